//! WSCG'03's Stack Engine's sequencer driven as the clocked chip drives it
//! ([`traffic`](super::traffic): the inputs it had in every clock of whole queries), the
//! clocked model's outputs each clock ([`seq_clocks`]), the RTL's ports as the model's
//! ([`set_seq_inputs`], [`seq_outputs_match`]) and its vectors.

use super::Traffic;
use crate::chip::rtl::LIST_LEVELS;
use crate::cycle::wscg03::memory_controller::{Ask, Fields};
use crate::cycle::wscg03::sequencer::{SeqIn, Sequencer};
use crate::cycle::wscg03::stack_engine::ListCmd;
use crate::cycle::wscg03::tri_unit::LeafPair;
use crate::rtl::wscg03::sequencer::Sequencer as Rtl;
use rust_hdl::prelude::*;

/// One clock of the traffic: `clear` (a clock between queries, `halt` high, nothing else
/// driven), the inputs, and the model's outputs: the lists' command, the ask, the leaf
/// pair offered, and after the last edge `idle` and its counters.
pub struct SeqClock {
    pub clear: bool,
    pub i: SeqIn,
    pub cmd: ListCmd,
    pub ask: Option<Ask>,
    pub offer: Option<LeafPair>,
    pub idle: bool,
    pub lists: u64,
    pub dop_tests: u64,
}

/// The traffic's clocks with the clocked model's outputs: each query on a model of its
/// own, a `clear` clock before each (whose outputs are the last query's, or reset's).
pub fn seq_clocks(tr: &Traffic) -> Vec<SeqClock> {
    let mut out = vec![];
    let mut last = (true, 0, 0);
    for ins in tr.queries.iter().map(|t| &t.ins) {
        let i = SeqIn {
            halt: true,
            ..SeqIn::default()
        };
        let (idle, lists, dop_tests) = last;
        out.push(SeqClock {
            clear: true,
            i,
            cmd: ListCmd::default(),
            ask: None,
            offer: None,
            idle,
            lists,
            dop_tests,
        });
        let mut model = Sequencer::new(LIST_LEVELS);
        for i in &ins.seq {
            let (ask, offer, idle) = (model.ask(i), model.offer(i.halt), model.idle());
            let (lists, dop_tests) = (model.lists, model.dop_tests);
            let cmd = model.step(i);
            out.push(SeqClock {
                clear: false,
                i: i.clone(),
                cmd,
                ask,
                offer,
                idle,
                lists,
                dop_tests,
            });
        }
        last = (model.idle(), model.lists, model.dop_tests);
    }
    out
}

/// A node word's fields as the ports carry them (`id`, leaf, f0, f1; zeros if none).
fn fields(f: Option<&Fields>) -> (u64, bool, u64, u64) {
    f.map_or((0, false, 0, 0), |f| {
        (f.id as u64, f.leaf, f.f[0] as u64, f.f[1] as u64)
    })
}

/// The ports' values of one clock's inputs, in the vectors' order: `clear`, `halt`,
/// `level`, `branch`, `remaining`, `ls_busy`, `ls_done`, `rd_valid`, `rd_ptr`,
/// `flags_valid`, `overlap`, `room`, `a_valid`, `al_valid`, `al_id`, `al_leaf`, `al_f0`,
/// `al_f1`, `ld_valid`, `ld_set`, `ld_pair`, `ld_id`, `ld_leaf0`, `ld_leaf1`, `ld_f00`,
/// `ld_f01`, `ld_f10`, `ld_f11`, `leaf_ready`.
fn inputs(c: &SeqClock) -> [u64; 29] {
    let (i, ls) = (&c.i, &c.i.ls);
    let al = fields(i.aligned.flatten().as_ref());
    let m = i.loaded.as_ref().map_or(&[][..], |l| &l.1[..]);
    let (m0, m1) = (fields(m.first()), fields(m.get(1)));
    [
        c.clear as u64,
        i.halt as u64,
        ls.level as u64,
        ls.branch as u64,
        ls.remaining as u64,
        ls.busy as u64,
        ls.done as u64,
        ls.rd.is_some() as u64,
        ls.rd.unwrap_or(0) as u64,
        i.flags_valid as u64,
        i.overlap[0] as u64 | (i.overlap[1] as u64) << 1,
        i.room as u64,
        i.aligned.is_some() as u64,
        i.aligned.flatten().is_some() as u64,
        al.0,
        al.1 as u64,
        al.2,
        al.3,
        i.loaded.is_some() as u64,
        i.loaded.as_ref().map_or(0, |l| l.0 as u64),
        (m.len() == 2) as u64,
        m0.0,
        m0.1 as u64,
        m1.1 as u64,
        m0.2,
        m0.3,
        m1.2,
        m1.3,
        i.leaf_ready as u64,
    ]
}

/// The ports' values of one clock's outputs, in the vectors' order: `append`, `wr_side`,
/// `wr_ptr`, `read`, `next_list`, `push`, `push_load`, `push_set`, `push_pair`, `push_id`,
/// `leaf_valid`, `leaf_ida`, `leaf_idb`, `leaf_tag`, `leaf_side`, `idle`, `lists`,
/// `dop_tests` (0 where not valid; the counters modulo 2^32).
fn outputs(c: &SeqClock) -> [u64; 18] {
    let (ap, (side, ptr)) = (c.cmd.append.is_some(), c.cmd.append.unwrap_or((0, 0)));
    let (load, set, pair, id) = Ask::ports(c.ask);
    let l = c.offer.unwrap_or_default();
    [
        ap as u64,
        side as u64,
        ptr as u64,
        c.cmd.read as u64,
        c.cmd.next_list as u64,
        c.ask.is_some() as u64,
        load as u64,
        set as u64,
        pair as u64,
        id as u64 & 0xffff,
        c.offer.is_some() as u64,
        l.ids[0] as u64,
        l.ids[1] as u64,
        l.tag as u64,
        l.side as u64,
        c.idle as u64,
        c.lists & 0xffff_ffff,
        c.dop_tests & 0xffff_ffff,
    ]
}

/// Drives one clock's inputs.
pub fn set_seq_inputs(uut: &mut Rtl, c: &SeqClock) {
    let v = inputs(c);
    let b = |x: u64| x != 0;
    uut.clear.next = b(v[0]);
    uut.halt.next = b(v[1]);
    uut.level.next = v[2].into();
    uut.branch.next = b(v[3]);
    uut.remaining.next = v[4].into();
    uut.ls_busy.next = b(v[5]);
    uut.ls_done.next = b(v[6]);
    uut.rd_valid.next = b(v[7]);
    uut.rd_ptr.next = v[8].into();
    uut.flags_valid.next = b(v[9]);
    uut.overlap.next = v[10].into();
    uut.room.next = v[11].into();
    uut.a_valid.next = b(v[12]);
    uut.al_valid.next = b(v[13]);
    uut.al_id.next = v[14].into();
    uut.al_leaf.next = b(v[15]);
    uut.al_f0.next = v[16].into();
    uut.al_f1.next = v[17].into();
    uut.ld_valid.next = b(v[18]);
    uut.ld_set.next = b(v[19]);
    uut.ld_pair.next = b(v[20]);
    uut.ld_id.next = v[21].into();
    uut.ld_leaf0.next = b(v[22]);
    uut.ld_leaf1.next = b(v[23]);
    uut.ld_f00.next = v[24].into();
    uut.ld_f01.next = v[25].into();
    uut.ld_f10.next = v[26].into();
    uut.ld_f11.next = v[27].into();
    uut.leaf_ready.next = b(v[28]);
}

/// The RTL's outputs in a clock, in [`outputs`]' order.
fn rtl_outputs(uut: &Rtl) -> [u64; 18] {
    let b = |x: bool| x as u64;
    [
        b(uut.append.val()),
        b(uut.wr_side.val()),
        uut.wr_ptr.val().index() as u64,
        b(uut.read.val()),
        b(uut.next_list.val()),
        b(uut.push.val()),
        b(uut.push_load.val()),
        b(uut.push_set.val()),
        b(uut.push_pair.val()),
        uut.push_id.val().index() as u64,
        b(uut.leaf_valid.val()),
        uut.leaf_ida.val().index() as u64,
        uut.leaf_idb.val().index() as u64,
        uut.leaf_tag.val().index() as u64,
        b(uut.leaf_side.val()),
        b(uut.idle.val()),
        uut.lists.val().index() as u64,
        uut.dop_tests.val().index() as u64,
    ]
}

/// Whether the RTL's outputs in a clock are the model's.
pub fn seq_outputs_match(uut: &Rtl, c: &SeqClock) -> bool {
    rtl_outputs(uut) == outputs(c)
}

/// Runs the traffic's clocks through the RTL: the clocks it ran as the model, or the first
/// clock whose outputs differ, with both.
pub fn seq_lockstep(tr: &Traffic) -> Result<usize, String> {
    let mut uut = crate::rtl::wscg03::sequencer::sequencer_top();
    let clocks = seq_clocks(tr);
    for (n, c) in clocks.iter().enumerate() {
        set_seq_inputs(&mut uut, c);
        uut.clock.next = Clock { clk: false };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {n}: logic did not settle"));
        }
        if !seq_outputs_match(&uut, c) {
            let (m, r) = (outputs(c), rtl_outputs(&uut));
            return Err(format!("clock {n}: {:?}\nmodel {m:x?}\nRTL   {r:x?}", c.i));
        }
        uut.clock.next = Clock { clk: true };
        if !simulate(&mut uut, 1000) {
            return Err(format!("clock {n}: logic did not settle"));
        }
    }
    Ok(clocks.len())
}

/// Vectors of the sequencer, a clock per line (latency 0: the outputs in that clock,
/// before its rising edge): [`seq_clocks`] of [`traffic`](super::traffic).
pub fn sequencer_vectors() -> String {
    use std::fmt::Write;
    let widths_in = [
        1, 1, 5, 1, 16, 1, 1, 1, 16, 1, 2, 4, 1, 1, 16, 1, 32, 32, 1, 1, 1, 16, 1, 1, 32, 32, 32,
        32, 1,
    ];
    let widths_out = [1, 1, 16, 1, 1, 1, 1, 1, 1, 16, 1, 16, 16, 32, 1, 1, 32, 32];
    let hex = |v: &[u64], w: &[usize]| -> Vec<String> {
        v.iter()
            .zip(w)
            .map(|(x, n)| format!("{x:0width$x}", width = n.div_ceil(4)))
            .collect()
    };
    let mut out = String::new();
    let _ = writeln!(out, "// clear halt level branch remaining ls_busy ls_done rd_valid rd_ptr flags_valid overlap room a_valid al_valid al_id al_leaf al_f0 al_f1 ld_valid ld_set ld_pair ld_id ld_leaf0 ld_leaf1 ld_f00 ld_f01 ld_f10 ld_f11 leaf_ready append wr_side wr_ptr read next_list push push_load push_set push_pair push_id leaf_valid leaf_ida leaf_idb leaf_tag leaf_side idle lists dop_tests");
    let _ = writeln!(out, "// latency: 0");
    let _ = writeln!(out, "// sequencer: WSCG'03's Stack Engine's sequencer, one line per clock: inputs, then the outputs in that clock (before its rising edge); the inputs the clocked chip gave it in two whole queries; golden: cycle::wscg03::sequencer::Sequencer");
    for c in seq_clocks(&super::traffic()) {
        let mut f = hex(&inputs(&c), &widths_in);
        f.extend(hex(&outputs(&c), &widths_out));
        let _ = writeln!(out, "{}", f.join(" "));
    }
    out
}
