//! WSCG'03's Triangle Unit's input stage driven as the chip drives it
//! ([`tri_input_traffic`]): leaf pairs of a tumbled pair's two leaves against A's triangles,
//! the words it lacks fetched after a random latency, TRI_UNIT taking pairs now and then,
//! halts and starts; what the clocked model ([`ClockedTriInput`]) answers every clock; the
//! RTL's ports as the model's ([`set_tri_inputs`], [`tri_outputs_match`]).

use crate::cycle::wscg03::tri_unit::{ClockedTriInput, LeafPair, TriInputIn, TriInputOut};
use crate::rtl::b32::TriInput;
use rand::{Rng, SeedableRng};
use std::fmt::Write;

/// Bits of a binary32 triangle word (`chip::layout::tri_bits(32)`).
pub const TRI_WORD_BITS: usize = crate::chip::layout::tri_bits(32);
const LIMBS: usize = TRI_WORD_BITS.div_ceil(64);

/// The test's triangle word `id` of A (`b` false) or B: bits drawn from the id, so that a
/// word shown names the word it is.
pub fn tri_word(b: bool, id: u16) -> Vec<u64> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64((b as u64) << 16 | id as u64);
    let mut w: Vec<u64> = (0..LIMBS).map(|_| rng.random()).collect();
    w[LIMBS - 1] &= (1 << (TRI_WORD_BITS % 64)) - 1;
    w
}

/// A word named by its id, as the pair register holds it (`None`: never loaded, zeros).
fn word_of(b: bool, id: Option<u16>) -> Vec<u64> {
    id.map_or(vec![0; LIMBS], |id| tri_word(b, id))
}

/// A run of the input stage: each clock's inputs and the model's outputs in it, and the
/// pairs TRI_UNIT took (tag, the ids of the words it read, the clock).
pub struct TriInputTraffic {
    pub ins: Vec<TriInputIn>,
    pub outs: Vec<TriInputOut>,
    pub taken: Vec<(u32, [Option<u16>; 2], usize)>,
    /// Every leaf pair offered, by tag: its ids, the clock it was first offered.
    pub offered: Vec<([u16; 2], usize)>,
}

/// A word asked for: its id, the clock it arrives.
type Fetch = Option<(u16, usize)>;

/// `clocks` clocks of the input stage drawn from `seed`: leaf pairs (A's triangle from 60,
/// often one of the last few; B's one of the tumbled group's one or two leaves, the group
/// new every dozen pairs or so), each offered until taken; a word it lacks asked for the
/// clock after it shows `need` and answered 1 to 8 clocks later, one word a clock; TRI_UNIT
/// ready every third clock but now and then; now and then a halt (a first hit: it holds
/// until the next start), or a start with A's cache at 128, 32 or 8 lines.
pub fn tri_input_traffic(seed: u64, clocks: usize) -> TriInputTraffic {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut model = ClockedTriInput::default();
    let mut tr = TriInputTraffic {
        ins: vec![],
        outs: vec![],
        taken: vec![],
        offered: vec![],
    };
    let (mut mask, mut group, mut recent) = (127u8, vec![0u16, 1], vec![0u16]);
    let (mut offer, mut fetch): (Option<LeafPair>, [Fetch; 2]) = (None, [None; 2]);
    let (mut last, mut filled, mut halted) = (TriInputOut::default(), None, false);
    for c in 0..clocks {
        let mut i = TriInputIn {
            mask,
            tri_ready: c % 3 == 0 && rng.random_bool(0.9),
            ..Default::default()
        };
        halted |= rng.random_bool(1.0 / 250.0);
        if rng.random_bool(match halted {
            true => 1.0 / 20.0,
            false => 1.0 / 800.0,
        }) {
            mask = [127, 31, 7][rng.random_range(0..3)];
            (i.clear, i.mask, halted) = (true, mask, false);
        }
        i.halt = halted;
        if rng.random_bool(1.0 / 12.0) {
            let n = rng.random_range(1..=2);
            group = (0..n).map(|_| rng.random_range(0..24)).collect();
        }
        if offer.is_none() && rng.random_bool(0.6) {
            let side = rng.random_range(0..group.len());
            let ta = match rng.random_bool(0.5) {
                true => recent[rng.random_range(0..recent.len())],
                false => rng.random_range(0..60),
            };
            recent.push(ta);
            if recent.len() > 6 {
                recent.remove(0);
            }
            let (ids, tag) = ([ta, group[side]], tr.offered.len() as u32);
            tr.offered.push((ids, c));
            offer = Some(LeafPair { ids, tag, side });
        }
        i.leaf = offer;
        // the memory: asks for what the last clock lacked, answers what is due
        // (the last clock's `need` is stale for a word that arrived in it)
        let due = (0..2).find(|&d| fetch[d].is_some_and(|(_, t)| t <= c));
        for (d, f) in fetch.iter_mut().enumerate() {
            if last.need[d] && f.is_none() && filled != Some(d) {
                *f = Some((last.ids[d], c + rng.random_range(1..=8)));
            }
        }
        if let Some(d) = due {
            i.fill = Some((d == 1, fetch[d].take().unwrap().0));
        }
        filled = due;
        let o = model.step(&i);
        if o.leaf_ready {
            offer = None;
        }
        if o.pair_valid && i.tri_ready {
            tr.taken.push((o.pair_tag, o.words, c));
        }
        tr.ins.push(i);
        tr.outs.push(o);
        last = o;
    }
    tr
}

/// Drives one clock's inputs into the RTL input stage.
pub fn set_tri_inputs(uut: &mut TriInput, i: &TriInputIn) {
    let leaf = i.leaf.unwrap_or_default();
    let (b, id) = i.fill.unwrap_or_default();
    uut.clear.next = i.clear;
    uut.mask.next = (i.mask as u64).into();
    uut.halt.next = i.halt;
    uut.leaf_in.next = i.leaf.is_some();
    uut.leaf_ids.next = (leaf.ids[0] as u64 | (leaf.ids[1] as u64) << 16).into();
    uut.leaf_tag.next = (leaf.tag as u64).into();
    uut.leaf_side.next = leaf.side == 1;
    uut.fill_a.next = i.fill.is_some() && !b;
    uut.fill_b.next = i.fill.is_some() && b;
    uut.fill_id.next = (id as u64).into();
    uut.fill_word.next = crate::harness::chip_io::bits(&match i.fill {
        Some(_) => tri_word(b, id),
        None => vec![0; LIMBS],
    });
    uut.tri_ready.next = i.tri_ready;
}

/// Whether the RTL's outputs are the model's `o` (its words those of the ids `o` names).
pub fn tri_outputs_match(uut: &TriInput, o: &TriInputOut) -> bool {
    let word =
        |b: bool| crate::harness::chip_io::bits::<TRI_WORD_BITS>(&word_of(b, o.words[b as usize]));
    uut.leaf_ready.val() == o.leaf_ready
        && [uut.need_a.val(), uut.need_b.val()] == o.need
        && [uut.ta_id.val().index(), uut.tb_id.val().index()] == o.ids.map(|x| x as usize)
        && uut.pair_valid.val() == o.pair_valid
        && uut.pair_tag.val().index() == o.pair_tag as usize
        && uut.a_word.val() == word(false)
        && uut.b_word.val() == word(true)
        && uut.busy.val() == o.busy
}

/// A word as hex, most significant digit first.
fn hex(w: &[u64]) -> String {
    let digits = TRI_WORD_BITS.div_ceil(4);
    let full: String = w.iter().rev().map(|l| format!("{l:016x}")).collect();
    full[full.len() - digits..].to_string()
}

/// Vectors of the input stage, a clock per line (latency 0: the outputs in that clock,
/// before its rising edge): 3,000 clocks of [`tri_input_traffic`] and the clocked model's
/// outputs.
pub fn tri_input_vectors() -> String {
    let tr = tri_input_traffic(0x7e1, 3000);
    let mut out = String::new();
    let _ = writeln!(out, "// clear mask halt leaf_in leaf_ids leaf_tag leaf_side fill_a fill_b fill_id fill_word tri_ready leaf_ready need_a need_b ta_id tb_id pair_valid pair_tag a_word b_word busy");
    let _ = writeln!(out, "// latency: 0");
    let _ = writeln!(out, "// tri_input_b32: WSCG'03's Triangle Unit's input stage, one line per clock: inputs, then the outputs in that clock (before its rising edge); golden: cycle::wscg03::tri_unit::ClockedTriInput, the words named by their ids");
    for (i, o) in tr.ins.iter().zip(&tr.outs) {
        let l = i.leaf.unwrap_or_default();
        let (b, id) = i.fill.unwrap_or_default();
        let fw = i.fill.map_or(vec![0; LIMBS], |_| tri_word(b, id));
        let ids = l.ids[0] as u32 | (l.ids[1] as u32) << 16;
        let _ = writeln!(
            out,
            "{} {:02x} {} {} {ids:08x} {:08x} {} {} {} {id:04x} {} {} {} {} {} {:04x} {:04x} {} {:08x} {} {} {}",
            i.clear as u8,
            i.mask,
            i.halt as u8,
            i.leaf.is_some() as u8,
            l.tag,
            l.side,
            (i.fill.is_some() && !b) as u8,
            (i.fill.is_some() && b) as u8,
            hex(&fw),
            i.tri_ready as u8,
            o.leaf_ready as u8,
            o.need[0] as u8,
            o.need[1] as u8,
            o.ids[0],
            o.ids[1],
            o.pair_valid as u8,
            o.pair_tag,
            hex(&word_of(false, o.words[0])),
            hex(&word_of(true, o.words[1])),
            o.busy as u8,
        );
    }
    out
}
