//! WSCG'03's Memory Controller driven as the clocked chip drives it
//! ([`memory_controller_traffic`]: the inputs it had in every clock of whole queries, on a
//! memory of a few clocks' latency with requests overlapped); its records and triangle
//! words as memory words ([`record_word`], [`response`]); the RTL's ports as the model's
//! ([`set_mc_inputs`], [`mc_outputs_match`]).

use super::tri_unit::{tri_word, TRI_WORD_BITS};
use super::{bus, FORMAT};
use crate::chip::layout::Dst;
use crate::cycle::wscg03::memory_controller::{
    Ask, Fields, Images, McIn, McOut, MemoryController, Record,
};
use crate::harness::chip_io::{bits, put, Word};
use crate::rtl::b32::MemoryController as Rtl;
use rust_hdl::prelude::*;

/// Bits of a record (a memory word: two node words, padded to 256 bytes) and of a node
/// word (k = 24, binary32).
pub const RECORD_BITS: usize = 2048;
const NODE_BITS: usize = crate::chip::layout::node_bits(24, 32);

/// A record as the memory holds it: slot s's node word from bit `s NODE_BITS`: the leaf
/// bit, the distances, the two fields (`chip_io`'s node word).
pub fn record_word(r: &Record) -> Word {
    let mut w = vec![0; RECORD_BITS / 64];
    for (s, n) in r.iter().enumerate() {
        let at = s * NODE_BITS;
        put(&mut w, at, 1, n.fields.leaf as u64);
        for (i, &d) in n.dop.iter().enumerate() {
            put(&mut w, at + 1 + 32 * i, 32, FORMAT.to_bits(d));
        }
        put(&mut w, at + 769, 32, n.fields.f[0] as u64);
        put(&mut w, at + 801, 32, n.fields.f[1] as u64);
    }
    w
}

/// The memory's word for a response to a request of destination `d` and record `r`: a node
/// record of `img`, or the test's triangle word named by its record.
pub fn response(img: &Images, (d, r): (Dst, u32)) -> Word {
    let mut w = vec![0; RECORD_BITS / 64];
    match d {
        Dst::NodeA | Dst::NodeB => return record_word(&img.records[d as usize][r as usize]),
        Dst::TriA | Dst::TriB => {
            let t = tri_word(d == Dst::TriB, r as u16);
            w[..t.len()].copy_from_slice(&t);
        }
    }
    w
}

/// Whole queries' Memory Controller traffic: each clocked-chip query's memory, requests
/// outstanding at most, and inputs in every clock.
pub struct McTraffic {
    pub queries: Vec<(Images, usize, Vec<McIn>)>,
}

/// The Memory Controller's inputs in two queries of soups (60 against 80 triangles, all
/// pairs; 120 against 80, the first hit) on WSCG'03's chip clocked register by register,
/// on an ideal memory of 5 clocks' latency with 4 requests outstanding.
pub fn memory_controller_traffic() -> McTraffic {
    use crate::chip::memory::{MemTiming, Memory};
    use crate::pose::Pose;
    let p = crate::chip::params::Params {
        outstanding: 4,
        memory: Memory::Ideal(MemTiming {
            latency: 5,
            interval: 1,
            bus_bits: None,
        }),
        ..crate::chip::params::Params::RTL
    };
    let mut queries = vec![];
    for (na, nb, seed, first, pose) in [
        (60, 80, 7, false, Pose::new(5.0, 10.0, 0.0, 0.3, 0.2, 0.1)),
        (
            120,
            80,
            3,
            true,
            Pose::new(-35.0, 80.0, 5.0, 0.2, -0.1, 0.05),
        ),
    ] {
        let soup = |n, s| crate::mesh::soup(n, s).triangles_f64();
        let cfg = crate::chip::config::ChipConfig::default();
        let chip = crate::query::Chip::new(&soup(na, seed), &soup(nb, seed + 1), cfg)
            .expect("a soup is a valid object");
        let img = crate::cycle::wscg03::clocked::images(&chip);
        let setup = chip.setup(&pose);
        let ins = crate::cycle::wscg03::clocked::memory_controller_inputs(
            &chip,
            &img,
            &setup,
            first,
            &p,
            1 << 24,
        )
        .expect("the query finishes");
        queries.push((img, p.outstanding as usize, ins));
    }
    McTraffic { queries }
}

/// Drives one clock's inputs: `i`, the memory `img` (its bases; `resp`, the response's
/// word), at most `outstanding` requests.
pub fn set_mc_inputs(uut: &mut Rtl, img: &Images, outstanding: usize, i: &McIn, resp: &Word) {
    let (load, set, pair, id) = match i.push {
        Some(Ask::Load { set, id, n }) => (true, set, n == 2, id),
        Some(Ask::Aligned { set, id }) => (false, set, false, id),
        None => (false, 0, false, 0),
    };
    uut.clear.next = false;
    uut.halt.next = i.halt;
    uut.push.next = i.push.is_some();
    uut.push_load.next = load;
    uut.push_set.next = set == 1;
    uut.push_pair.next = pair;
    uut.push_id.next = (id as u64).into();
    uut.need_a.next = i.need[0];
    uut.need_b.next = i.need[1];
    uut.ta_id.next = (i.ids[0] as u64).into();
    uut.tb_id.next = (i.ids[1] as u64).into();
    uut.base_na.next = (img.bases[0] as u64).into();
    uut.base_nb.next = (img.bases[1] as u64).into();
    uut.base_ta.next = (img.bases[2] as u64).into();
    uut.base_tb.next = (img.bases[3] as u64).into();
    uut.port_out.next = (outstanding as u64 - 1).into();
    uut.mem_req_ready.next = i.mem_ready;
    uut.mem_resp_valid.next = i.resp;
    uut.mem_resp_data.next = bits(resp);
    uut.busy.next = (i.busy[0] as u64 | (i.busy[1] as u64) << 1).into();
}

/// A node word's fields as the RTL's ports give them (`id`, leaf, f0, f1; zeros if none).
fn fields(f: Option<Fields>) -> (usize, bool, usize, usize) {
    f.map_or((0, false, 0, 0), |f| {
        (f.id as usize, f.leaf, f.f[0] as usize, f.f[1] as usize)
    })
}

/// Whether the RTL's outputs in a clock are the model's `o` (`room` after the last edge,
/// `resp` the response's word).
pub fn mc_outputs_match(uut: &Rtl, o: &McOut, room: usize, resp: &Word) -> bool {
    let t = o.dop_in.t.as_ref();
    let a = o.dop_in.a.as_ref();
    let (fa, fb, fid) = match o.fill {
        Some((b, id)) => (!b, b, id as usize),
        None => (false, false, 0),
    };
    let word = match o.fill {
        Some(_) => bits::<TRI_WORD_BITS>(&resp[..TRI_WORD_BITS.div_ceil(64)].to_vec()),
        None => 0.into(),
    };
    let (ld, m) = match &o.loaded {
        Some((set, m)) => (Some(*set), m.clone()),
        None => (None, vec![]),
    };
    let al = fields(o.aligned);
    let (m0, m1) = (fields(m.first().copied()), fields(m.get(1).copied()));
    uut.room.val().index() == room
        && uut.mem_req_valid.val() == o.req.is_some()
        && uut.mem_req_addr.val().index() == o.req.unwrap_or(0) as usize
        && (
            uut.fill_a.val(),
            uut.fill_b.val(),
            uut.fill_id.val().index(),
        ) == (fa, fb, fid)
        && uut.fill_word.val() == word
        && uut.t_valid.val() == t.is_some()
        && uut.t_set.val() == t.is_some_and(|t| t.set == 1)
        && uut.t_side.val() == t.is_some_and(|t| t.side == 1)
        && uut.t_entry.val().index() == t.map_or(0, |t| t.entry)
        && uut.t_last.val() == t.is_some_and(|t| t.last)
        && uut.t_data.val() == t.map_or(0.into(), |t| bus(&t.data))
        && uut.a_valid.val() == a.is_some()
        && uut.a_first.val() == a.is_some_and(|a| a.first)
        && uut.a_set.val() == a.is_some_and(|a| a.set == 1)
        && uut.a_entry.val().index() == a.map_or(0, |a| a.entry)
        && uut.e.val() == a.map_or(0.into(), |a| bus(&a.e))
        && uut.al_valid.val() == o.aligned.is_some()
        && (uut.al_id.val().index(), uut.al_leaf.val()) == (al.0, al.1)
        && (uut.al_f0.val().index(), uut.al_f1.val().index()) == (al.2, al.3)
        && uut.ld_valid.val() == ld.is_some()
        && uut.ld_set.val() == (ld == Some(1))
        && uut.ld_pair.val() == (m.len() == 2)
        && (uut.ld_id.val().index(), uut.ld_leaf0.val()) == (m0.0, m0.1)
        && (uut.ld_f00.val().index(), uut.ld_f01.val().index()) == (m0.2, m0.3)
        && uut.ld_leaf1.val() == m1.1
        && (uut.ld_f10.val().index(), uut.ld_f11.val().index()) == (m1.2, m1.3)
}

/// Runs `ins` through the model and the RTL, clock by clock: the first clock whose outputs
/// differ, with the model's, if any.
pub fn mc_lockstep(img: &Images, outstanding: usize, ins: &[McIn]) -> Result<usize, String> {
    let mut model = MemoryController::new(img, outstanding);
    let mut uut = crate::rtl::b32::memory_controller_top();
    for (c, i) in ins.iter().enumerate() {
        let resp = match model.next_response().filter(|_| i.resp) {
            Some(tag) => response(img, tag),
            None => vec![0; RECORD_BITS / 64],
        };
        let room = model.room();
        let o = model.step(i);
        set_mc_inputs(&mut uut, img, outstanding, i, &resp);
        uut.clock.next = Clock { clk: false };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {c}: logic did not settle"));
        }
        if !mc_outputs_match(&uut, &o, room, &resp) {
            return Err(format!("clock {c}: {i:?} -> {o:?}"));
        }
        uut.clock.next = Clock { clk: true };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {c}: logic did not settle"));
        }
    }
    Ok(ins.len())
}
