//! WSCG'03's chip core in RTL (`rtl::wscg03::chip::ChipCore`) driven as the clocked chip
//! was in whole queries ([`traffic`](super::traffic): every clock from the first setup
//! word on), its memory's words by address, and its ports checked against the clocked
//! model's every clock ([`core_lockstep`]).

use super::memory_controller::{response, RECORD_BITS};
use super::tri_unit::{tri_word, TRI_WORD_BITS};
use super::{Traffic, TrafficQuery};
use crate::chip::layout::Dst;
use crate::cycle::wscg03::clocked::CoreClock;
use crate::harness::chip_io::{bits, Word};
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
