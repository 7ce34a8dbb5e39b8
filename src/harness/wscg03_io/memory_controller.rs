//! WSCG'03's Memory Controller driven as the clocked chip drives it
//! ([`traffic`](super::traffic): the inputs it had in every clock of whole queries, on a
//! memory of a few clocks' latency with requests overlapped); the memory's words
//! ([`response`]); the RTL's ports as the model's
//! ([`set_mc_inputs`], [`mc_outputs_match`]).

use super::tri_unit::{tri_word, TRI_WORD_BITS};
use super::{bus, Traffic, TrafficQuery, FORMAT};
use crate::chip::layout::Dst;
use crate::cycle::wscg03::memory_controller::{Ask, Fields, Images, McIn, McOut, MemoryController};
use crate::harness::chip_io::{bits, Word};
use crate::rtl::b32::MemoryController as Rtl;
use rust_hdl::prelude::*;

/// Bits of a record (a memory word: two node words, padded to 256 bytes; k = 24, binary32).
pub const RECORD_BITS: usize = crate::chip::layout::record_bits(24, 32, 32);

/// The memory's word for a response to a request of destination `d` and record `r` in the
/// query `t`: a node record as DATE'05's image builds it (`t.words`, at the model's
/// address), or the test's triangle word named by its record.
pub fn response(t: &TrafficQuery, (d, r): (Dst, u32)) -> Word {
    match d {
        Dst::NodeA | Dst::NodeB => t.words[(t.img.bases[d as usize] + r) as usize].clone(),
        Dst::TriA | Dst::TriB => {
            let mut w = vec![0; RECORD_BITS / 64];
            let tw = tri_word(d == Dst::TriB, r as u16);
            w[..tw.len()].copy_from_slice(&tw);
            w
        }
    }
}

/// One clock of the traffic: its query, `clear` (a clock between queries, nothing else
/// driven), the inputs and the response's word, the model's outputs and its ask list's
/// room after the last edge.
pub struct McClock {
    pub query: usize,
    pub clear: bool,
    pub i: McIn,
    pub resp: Word,
    pub o: McOut,
    pub room: usize,
    pub pending: bool,
}

/// The traffic's clocks with the clocked model's outputs: each query on a model of its
/// own, a `clear` clock before each.
pub fn mc_clocks(tr: &Traffic) -> Vec<McClock> {
    let mut out = vec![];
    for (q, t) in tr.queries.iter().enumerate() {
        let mut model = MemoryController::new(&t.img, t.img.bases, t.outstanding);
        out.push(McClock {
            query: q,
            clear: true,
            i: McIn::default(),
            resp: vec![0; RECORD_BITS / 64],
            o: McOut::default(),
            room: model.room(),
            pending: false,
        });
        for i in &t.ins.mc {
            let resp = match model.next_response().filter(|_| i.resp) {
                Some(tag) => response(t, tag),
                None => vec![0; RECORD_BITS / 64],
            };
            let (room, pending) = (model.room(), model.outstanding() > 0);
            let o = model.step(i);
            out.push(McClock {
                query: q,
                clear: false,
                i: *i,
                resp,
                o,
                room,
                pending,
            });
        }
    }
    out
}

/// Drives one clock's inputs: `i`, the memory `img` (its bases; `resp`, the response's
/// word), at most `outstanding` requests; `clear` low.
pub fn set_mc_inputs(uut: &mut Rtl, img: &Images, outstanding: usize, i: &McIn, resp: &Word) {
    let (load, set, pair, id) = Ask::ports(i.push);
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
        && uut.req_tri.val() == o.req_tri
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

/// Runs the traffic's clocks through the RTL: the clocks it ran as the model, or the first
/// clock whose outputs differ, with the model's.
pub fn mc_lockstep(tr: &Traffic) -> Result<usize, String> {
    let mut uut = crate::rtl::b32::memory_controller_top();
    let clocks = mc_clocks(tr);
    for (n, c) in clocks.iter().enumerate() {
        let t = &tr.queries[c.query];
        set_mc_inputs(&mut uut, &t.img, t.outstanding, &c.i, &c.resp);
        uut.clear.next = c.clear;
        uut.clock.next = Clock { clk: false };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {n}: logic did not settle"));
        }
        if !mc_outputs_match(&uut, &c.o, c.room, &c.resp) || uut.pending.val() != c.pending {
            return Err(format!("clock {n}: {:?} -> {:?}", c.i, c.o));
        }
        uut.clock.next = Clock { clk: true };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {n}: logic did not settle"));
        }
    }
    Ok(clocks.len())
}

/// A word of `n` bits as hex, most significant digit first.
fn hex(w: &[u64], n: usize) -> String {
    let full: String = w.iter().rev().map(|l| format!("{l:016x}")).collect();
    full[full.len() - n.div_ceil(4)..].to_string()
}

/// A node word's fields as vector fields: id, leaf, f0, f1.
fn fields_hex(f: Option<Fields>) -> String {
    let (id, leaf, f0, f1) = fields(f);
    format!("{id:04x} {} {f0:08x} {f1:08x}", leaf as u8)
}

/// A bundle of eight distances as hex (zeros if none).
fn bus_hex(d: Option<&[f64; 8]>) -> String {
    (0..8)
        .rev()
        .map(|t| format!("{:08x}", d.map_or(0, |d| FORMAT.to_bits(d[t]))))
        .collect()
}

/// One clock's inputs as vector fields.
fn inputs_hex(c: &McClock, img: &Images, outstanding: usize) -> String {
    let i = &c.i;
    let (load, set, pair, id) = Ask::ports(i.push);
    let (load, pair) = (load as u8, pair as u8);
    let b = img.bases;
    format!(
        "{} {} {} {load} {set} {pair} {id:04x} {} {} {:04x} {:04x} {:06x} {:06x} {:06x} {:06x} {:x} {} {} {} {}",
        c.clear as u8,
        i.halt as u8,
        i.push.is_some() as u8,
        i.need[0] as u8,
        i.need[1] as u8,
        i.ids[0],
        i.ids[1],
        b[0],
        b[1],
        b[2],
        b[3],
        outstanding - 1,
        i.mem_ready as u8,
        i.resp as u8,
        hex(&c.resp, RECORD_BITS),
        i.busy[0] as u8 | (i.busy[1] as u8) << 1,
    )
}

/// One clock's outputs as vector fields.
fn outputs_hex(c: &McClock) -> String {
    let o = &c.o;
    let (t, a) = (o.dop_in.t.as_ref(), o.dop_in.a.as_ref());
    let (fa, fb, fid) = o
        .fill
        .map_or((0, 0, 0), |(b, id)| ((!b) as u8, b as u8, id));
    let fw = match o.fill {
        Some(_) => hex(&c.resp, TRI_WORD_BITS),
        None => "0".repeat(TRI_WORD_BITS.div_ceil(4)),
    };
    let m = o.loaded.as_ref().map_or(&[][..], |l| &l.1[..]);
    let (m0, m1) = (fields(m.first().copied()), fields(m.get(1).copied()));
    format!(
        "{:x} {} {} {:06x} {} {fa} {fb} {fid:04x} {fw} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {:04x} {} {} {:08x} {:08x} {:08x} {:08x}",
        c.room,
        c.pending as u8,
        o.req.is_some() as u8,
        o.req.unwrap_or(0),
        o.req_tri as u8,
        t.is_some() as u8,
        t.map_or(0, |t| t.set),
        t.map_or(0, |t| t.side),
        t.map_or(0, |t| t.entry),
        t.is_some_and(|t| t.last) as u8,
        bus_hex(t.map(|t| &t.data)),
        a.is_some() as u8,
        a.is_some_and(|a| a.first) as u8,
        a.map_or(0, |a| a.set),
        a.map_or(0, |a| a.entry),
        bus_hex(a.map(|a| &a.e)),
        o.aligned.is_some() as u8,
        fields_hex(o.aligned),
        o.loaded.is_some() as u8,
        o.loaded.as_ref().map_or(0, |l| l.0),
        (m.len() == 2) as u8,
        m0.0,
        m0.1 as u8,
        m1.1 as u8,
        m0.2,
        m0.3,
        m1.2,
        m1.3,
    )
}

/// Vectors of the Memory Controller, a clock per line (latency 0: the outputs in that
/// clock, before its rising edge): [`traffic`](super::traffic)'s clocks
/// ([`mc_clocks`]) and the clocked model's outputs.
pub fn memory_controller_vectors() -> String {
    use std::fmt::Write;
    let tr = super::traffic();
    let mut out = String::new();
    let _ = writeln!(out, "// clear halt push push_load push_set push_pair push_id need_a need_b ta_id tb_id base_na base_nb base_ta base_tb port_out mem_req_ready mem_resp_valid mem_resp_data busy room pending mem_req_valid mem_req_addr req_tri fill_a fill_b fill_id fill_word t_valid t_set t_side t_entry t_last t_data a_valid a_first a_set a_entry e al_valid al_id al_leaf al_f0 al_f1 ld_valid ld_set ld_pair ld_id ld_leaf0 ld_leaf1 ld_f00 ld_f01 ld_f10 ld_f11");
    let _ = writeln!(out, "// latency: 0");
    let _ = writeln!(out, "// memory_controller_b32: WSCG'03's Memory Controller, one line per clock: inputs, then the outputs in that clock (before its rising edge); the inputs the clocked chip gave it in two whole queries; golden: cycle::wscg03::memory_controller::MemoryController");
    for c in mc_clocks(&tr) {
        let t = &tr.queries[c.query];
        let _ = writeln!(
            out,
            "{} {}",
            inputs_hex(&c, &t.img, t.outstanding),
            outputs_hex(&c)
        );
    }
    out
}
