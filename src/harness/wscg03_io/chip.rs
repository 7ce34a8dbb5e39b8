//! WSCG'03's chip in RTL (`rtl::wscg03::chip::CollisionChip`) as DATE'05's chips are run:
//! behind [`RtlPorts`](crate::harness::chip_io::RtlPorts), its memory image and host writes
//! from DATE'05's image builder ([`query_image`]), in lockstep with the clocked chip on a
//! query ([`cross_check`]), the clocked chip's traces of the RTL set's WSCG'03 queries
//! ([`model_trace`]), its Verilog ([`verilog`]).

use crate::chip::config::MemLayout;
use crate::chip::memory::{MemTiming, Memory};
use crate::chip::params::Params;
use crate::chip::reg::{self, Mode, Order};
use crate::chip::rtl::ChipKind;
use crate::cycle::drive::{request_line, run_query, ChipTrace, Lockstep, Reader, VcdFile, Watch};
use crate::cycle::wscg03::clocked;
use crate::cycle::wscg03::memory_controller::Images;
use crate::cycle::VcdOut;
use crate::golden::host::HostSetup;
use crate::harness::chip_io::{drive, ChipQuery, PreparedQuery, QueryImage, RtlChip};
use rust_hdl::prelude::*;

crate::harness::chip_io::rtl_ports!(
    [] crate::rtl::wscg03::chip::CollisionChip, 2048, ChipKind::K24B32,
    crate::chip::probes::WSCG03, Self::probe
);

/// The memory and host writes of `chip`'s query (B placed by `setup`, all pairs or the
/// first hit: `first`) on WSCG'03's RTL chip, on `p`'s memory: the clocked model's records
/// ([`clocked::images`]) and DATE'05's image of them ([`QueryImage`] in the `records` layout: node
/// records and triangle words as the chip reads them), the DOP Unit's and TRI_UNIT's setup
/// words, then the chip's registers ([`clocked::writes`]).
pub fn query_image(
    chip: &crate::query::Chip,
    setup: &HostSetup,
    first: bool,
    p: &Params,
) -> Result<(Images, QueryImage), String> {
    let cfg = chip.cfg;
    if cfg.layout != MemLayout::Records || !crate::chip::rtl::wscg03_builds(&cfg) {
        return Err(format!(
            "WSCG'03's RTL chip is binary32 with k = 24, T.CHECK to nearest-even and the records layout; this query has k = {}, format {}, layout {:?}: use the wscg03 preset's k = 24 and format = \"binary32\", or drop cross_check",
            cfg.k, cfg.format, cfg.layout
        ));
    }
    let img = clocked::images(chip);
    let mode = if first { Mode::First } else { Mode::All };
    // records in order, whatever the memory: no record map over DDR banks, as DATE'05's
    // image builder lays them out on DDR
    let in_order = Params {
        memory: Memory::Ideal(MemTiming::default()),
        ..*p
    };
    let mut image = QueryImage::new(
        ChipKind::K24B32,
        &chip.a,
        &chip.b,
        setup,
        Order::Fifo,
        mode,
        &in_order,
        &cfg,
    )?;
    let setup_word = |a: u32| a < 0x100 || a >> 5 == reg::TRI_SETUP >> 5;
    image.writes.retain(|w| setup_word(w.0));
    image.writes.extend(clocked::writes(chip, &img, first, p));
    Ok((img, image))
}

/// Runs one query (as [`query_image`]) on WSCG'03's rust-hdl chip in lockstep with its
/// clocked model (on a thread with the big stack the RTL needs): every output and every
/// specified traversal signal ([`WSCG03`](crate::chip::probes::WSCG03)) equal after every
/// clock; the RTL's signals into `vcd`, if any. Errors name the cycle and the first
/// difference.
pub fn cross_check(
    chip: &crate::query::Chip,
    setup: &HostSetup,
    (first, p): (bool, &Params),
    max_cycles: u64,
    vcd: Option<&std::path::Path>,
) -> Result<ChipTrace, String> {
    let open = |v| VcdOut(v, &[], 0..u64::MAX).open(&crate::chip::probes::WSCG03);
    let mut w = vcd.map(open).transpose()?;
    let mut observe = |t, v| VcdFile::observe(&mut w, t, v);
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
                run_query(&mut ls, &image.writes, &d, true, &mut observe, false).map_err(|e| e.0)
            })
            .map_err(|e| format!("cannot start the RTL simulation thread: {e}"))?
            .join()
            .map_err(|_| "the RTL simulation thread panicked".to_string())?
    })
}

/// The clocked chip's run of a WSCG'03 query of the RTL set (`q`, prepared as `prep`),
/// driven as the Verilog testbench drives the exported chip (its writes, its memory, its
/// reader): the trace and the memory requests taken ([`request_line`]).
pub fn model_trace(
    q: &ChipQuery,
    prep: &PreparedQuery,
    max_cycles: u64,
) -> Result<(ChipTrace, String), String> {
    let p = q.params();
    let setup = prep.chip.setup(&q.pose);
    let img = clocked::images(&prep.chip);
    let mut text = String::new();
    let see = |t, o: &_, i: &_| text.extend(request_line(t, o, i));
    let mut c = Watch::new(clocked::Chip::new(&prep.chip, &img, &setup, &p)?, see);
    let d = drive(&prep.image, p.memory_clocks()?, q.reader, max_cycles);
    let w = &prep.image.writes;
    let tr = run_query(&mut c, w, &d, false, |_, _| Ok(()), false).map_err(|e| e.0)?;
    Ok((tr, text))
}

/// The chip's Verilog (top module `top`), identical modules merged.
pub fn verilog() -> String {
    crate::harness::chip_io::big_stack(|| {
        let chip = crate::rtl::wscg03::chip::chip_top();
        crate::harness::verilog::dedup_modules(&generate_verilog(&chip))
    })
}
