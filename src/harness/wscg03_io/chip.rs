//! WSCG'03's chip core in RTL (`rtl::wscg03::chip::ChipCore`) driven as the clocked chip
//! was in whole queries ([`traffic`](super::traffic): every clock from the first setup
//! word on), its memory's words by address, and its ports checked against the clocked
//! model's every clock ([`core_lockstep`]); the whole chip in RTL (`CollisionChip`) in
//! lockstep with the clocked chip on a query ([`cross_check`]).

use super::memory_controller::{response, RECORD_BITS};
use super::tri_unit::{tri_word, TRI_WORD_BITS};
use super::{Traffic, TrafficQuery};
use crate::chip::config::MemLayout;
use crate::chip::layout::Dst;
use crate::chip::params::Params;
use crate::chip::reg::{self, Mode, Order};
use crate::chip::rtl::{ChipKind, Depth};
use crate::cycle::drive::{run_query, ChipTrace, Lockstep, Reader, RequestLog};
use crate::cycle::wscg03::clocked::{self, CoreClock};
use crate::cycle::wscg03::memory_controller::Images;
use crate::golden::host::HostSetup;
use crate::harness::chip_io::{bits, drive, ChipQuery, PreparedQuery, QueryImage, RtlChip, Word};
use crate::rtl::wscg03::chip::ChipCore;
use rust_hdl::prelude::*;

/// The memory word at `addr` of the query `t`: a node record of A or B, or a triangle word
/// of A or B ([`response`]; the regions in memory order NA, TA, NB, TB).
pub fn word_at(t: &TrafficQuery, addr: u32) -> Word {
    let b = t.img.bases;
    let d = [Dst::TriB, Dst::NodeB, Dst::TriA, Dst::NodeA]
        .into_iter()
        .find(|&d| addr >= b[d as usize])
        .unwrap_or(Dst::NodeA);
    response(t, (d, addr - b[d as usize]))
}

/// Drives one clock's inputs (the response's word looked up in `t`).
fn set_core_inputs(uut: &mut ChipCore, t: &TrafficQuery, c: &CoreClock) {
    let i = &c.i;
    uut.host_we.next = i.host_we;
    uut.host_addr.next = (i.host_addr as u64 & 0x3ff).into();
    uut.host_data.next = (i.host_data as u64).into();
    uut.start.next = i.start;
    uut.mem_req_ready.next = i.mem_req_ready;
    uut.mem_resp_valid.next = i.mem_resp.is_some();
    let w = i
        .mem_resp
        .map_or(vec![0; RECORD_BITS / 64], |a| word_at(t, a));
    uut.mem_resp_data.next = bits(&w);
    uut.tri_ready.next = c.tri_ready;
    uut.tri_sure.next = c.tri_sure;
    uut.tri_idle.next = c.tri_idle;
}

/// What differs between the RTL's outputs in a clock and the model's (`None`: nothing).
fn core_differs(uut: &ChipCore, c: &CoreClock) -> Option<String> {
    let o = c.o.specified();
    let n32 = |x: u64| x & 0xffff_ffff;
    let got = [
        uut.busy.val() as u64,
        uut.done.val() as u64,
        uut.overflow.val() as u64,
        uut.max_depth.val().index() as u64,
        uut.dop_tests.val().index() as u64,
        uut.tri_tests.val().index() as u64,
        uut.node_fetches.val().index() as u64,
        uut.tri_fetches.val().index() as u64,
        uut.mem_req_valid.val() as u64,
        uut.mem_req_valid.val() as u64 * uut.mem_req_addr.val().index() as u64,
        uut.pair_valid.val() as u64,
        uut.pair_valid.val() as u64 * uut.pair_tag.val().index() as u64,
    ];
    let want = [
        o.busy as u64,
        o.done as u64,
        o.overflow as u64,
        o.max_depth,
        n32(o.dop_tests),
        n32(o.tri_tests),
        n32(o.node_fetches),
        n32(o.tri_fetches),
        o.mem_req_valid as u64,
        o.mem_req_addr as u64,
        c.pair.is_some() as u64,
        c.pair.map_or(0, |p| p.0 as u64),
    ];
    if got != want {
        return Some(format!("outputs {got:x?}, model {want:x?}"));
    }
    let word = |b, id| bits::<TRI_WORD_BITS>(&tri_word(b, id));
    match c.pair {
        Some((_, [a, b]))
            if uut.a_word.val() != word(false, a) || uut.b_word.val() != word(true, b) =>
        {
            Some(format!("the pair's words, model's ids {a} {b}"))
        }
        _ => None,
    }
}

/// Runs the traffic's queries through the core, each on a core of its own: the clocks it
/// ran as the model, or the first that differs.
pub fn core_lockstep(tr: &Traffic) -> Result<usize, String> {
    let mut n = 0;
    for (q, tq) in tr.queries.iter().enumerate() {
        let mut uut = crate::rtl::wscg03::chip::chip_core_top();
        for (t, c) in tq.ins.core.iter().enumerate() {
            set_core_inputs(&mut uut, tq, c);
            uut.clock.next = Clock { clk: false };
            if !simulate(&mut uut, 1000) {
                return Err(format!("query {q}, clock {t}: logic did not settle"));
            }
            if let Some(d) = core_differs(&uut, c) {
                return Err(format!("query {q}, clock {t} ({:?}): {d}", c.i));
            }
            uut.clock.next = Clock { clk: true };
            if !simulate(&mut uut, 1000) {
                return Err(format!("query {q}, clock {t}: logic did not settle"));
            }
            n += 1;
        }
    }
    Ok(n)
}

crate::harness::chip_io::rtl_ports!(
    [] crate::rtl::wscg03::chip::CollisionChip, 2048, ChipKind::K24B32, |_: &Self| None
);

/// The memory and host writes of `chip`'s query (B placed by `setup`, all pairs or the
/// first hit: `first`) on WSCG'03's RTL chip, on `p`'s memory: the clocked model's records
/// ([`images`]) and DATE'05's image of them ([`QueryImage`] in the `records` layout: node
/// records and triangle words as the chip reads them), the DOP Unit's and TRI_UNIT's setup
/// words, then the chip's registers ([`clocked::writes`]).
pub fn query_image(
    chip: &crate::query::Chip,
    setup: &HostSetup,
    first: bool,
    p: &Params,
) -> Result<(Images, QueryImage), String> {
    let cfg = chip.cfg;
    if cfg.layout != MemLayout::Records
        || ChipKind::of(&cfg, 1, 1, Depth::Asic) != Some(ChipKind::K24B32)
    {
        return Err(format!(
            "WSCG'03's RTL chip is binary32 with k = 24, T.CHECK to nearest-even and the records layout; this query has k = {}, format {}, layout {:?}: set [chip] preset = \"wscg03\"",
            cfg.k, cfg.format, cfg.layout
        ));
    }
    let img = clocked::images(chip);
    let mode = if first { Mode::First } else { Mode::All };
    let mut image = QueryImage::new(
        ChipKind::K24B32,
        &chip.a,
        &chip.b,
        setup,
        Order::Fifo,
        mode,
        p,
        &cfg,
    )?;
    let setup_word = |a: u32| a < 0x100 || a >> 5 == reg::TRI_SETUP >> 5;
    image.writes.retain(|w| setup_word(w.0));
    image.writes.extend(clocked::writes(chip, &img, first, p));
    Ok((img, image))
}

/// Runs one query (as [`query_image`]) on WSCG'03's rust-hdl chip in lockstep with its
/// clocked model (on a thread with the big stack the RTL needs): every output equal after
/// every clock. Errors name the cycle and the first difference.
pub fn cross_check(
    chip: &crate::query::Chip,
    setup: &HostSetup,
    first: bool,
    p: &Params,
    max_cycles: u64,
) -> Result<ChipTrace, String> {
    let (img, image) = query_image(chip, setup, first, p)?;
    let d = drive(&image, p.memory_clocks()?, Reader::default(), max_cycles);
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn_scoped(s, || {
                let model = clocked::Chip::new(chip, &img, setup, p)?;
                let mut rtl = crate::rtl::wscg03::chip::chip_top();
                let mut ls = Lockstep::new(
                    RtlChip::new(&mut rtl, &image),
                    model,
                    ("rust-hdl", "clocked model"),
                );
                run_query(&mut ls, &image.writes, &d, true, |_, _| Ok(()), false).map_err(|e| e.0)
            })
            .map_err(|e| format!("cannot start the RTL simulation thread: {e}"))?
            .join()
            .map_err(|_| "the RTL simulation thread panicked".to_string())?
    })
}

/// The clocked chip's run of a WSCG'03 query of the RTL set (`q`, prepared as `prep`),
/// driven as the Verilog testbench drives the exported chip (its writes, its memory, its
/// reader): the trace and the memory requests taken ([`RequestLog`]).
pub fn model_trace(
    q: &ChipQuery,
    prep: &PreparedQuery,
    max_cycles: u64,
) -> Result<(ChipTrace, String), String> {
    let p = q.params();
    let setup = prep.chip.setup(&q.pose);
    let img = clocked::images(&prep.chip);
    let mut log = RequestLog::new(clocked::Chip::new(&prep.chip, &img, &setup, &p)?);
    let d = drive(&prep.image, p.memory_clocks()?, q.reader, max_cycles);
    let w = &prep.image.writes;
    let tr = run_query(&mut log, w, &d, false, |_, _| Ok(()), false).map_err(|e| e.0)?;
    Ok((tr, log.text))
}

/// The chip's Verilog (top module `top`), identical modules merged.
pub fn verilog() -> String {
    crate::harness::chip_io::big_stack(|| {
        let chip = crate::rtl::wscg03::chip::chip_top();
        crate::harness::verilog::dedup_modules(&generate_verilog(&chip))
    })
}
