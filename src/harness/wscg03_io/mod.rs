//! WSCG'03's DOP Unit driven as its Stack Engine would drive it ([`dop_unit_traffic`]): a
//! random host setup in its MMM, tumbled sibling pairs loaded into either d' set while the
//! other set's d' meet aligned DOPs, bundle by bundle with idle clocks between, and what the
//! clocked model ([`ClockedDopUnit`]) answers every clock; the RTL's ports as the model's
//! ([`set_inputs`], [`outputs`]); the Stack Engine's lists driven as its sequencer would
//! drive them ([`list_traffic`]); the Triangle Unit's input stage ([`tri_unit`]); whole
//! queries' traffic of the Memory Controller and the sequencer ([`traffic`]); the chip's
//! core ([`chip_core`]) and the chip ([`chip`]) in RTL.

pub mod chip;
pub mod chip_core;
pub mod memory_controller;
pub mod sequencer;
pub mod tri_unit;

use crate::chip::config::ChipConfig;
use crate::cycle::wscg03::clocked::UnitInputs;
use crate::cycle::wscg03::dop_unit::{
    AlignedBundle, ClockIn, ClockOut, ClockedDopUnit, TumbledBundle,
};
use crate::format::{Format, Rounding};
use crate::golden::host::{HostSetup, TriSide};
use crate::golden::klmsel::opposite_lane;
use crate::rtl::b32::Wscg03DopUnit;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use std::collections::VecDeque;

/// WSCG'03's chip is binary32: eight distances on its 256-bit bus.
pub const FORMAT: Format = Format::BINARY32;

/// An aligned DOP compared: against which set, A's distances, the two tumbled siblings' DOPs
/// whose d' that set held, and the index (among all aligned bundles driven) of its last
/// bundle, whose verdicts are [`dop_overlap`](crate::golden::dop_unit::dop_overlap)'s.
pub struct AlignedDop {
    pub set: usize,
    pub e: Vec<f64>,
    pub d: [Vec<f64>; 2],
    pub last_bundle: usize,
}

/// A run of the DOP Unit: its setup (every lane rounding `rounding`), each clock's inputs and
/// the clocked model's outputs after it, the aligned DOPs.
pub struct DopTraffic {
    pub setup: HostSetup,
    pub rounding: Rounding,
    pub clocks: Vec<ClockIn>,
    pub outs: Vec<ClockOut>,
    pub dops: Vec<AlignedDop>,
}

/// A host setup of `k` lanes with random non-negative C and c (as the host sets C) and
/// random correspondences.
fn random_setup(rng: &mut impl Rng, k: usize) -> HostSetup {
    let fmt = FORMAT;
    let mut nonneg = || fmt.from_bits(super::units::operand(rng, fmt)).abs();
    let cmat = (0..k).map(|_| [nonneg(), nonneg(), nonneg()]).collect();
    let cvec = (0..k).map(|_| nonneg()).collect();
    let j = (0..k)
        .map(|_| [0; 3].map(|_| rng.random_range(0..k) as u8))
        .collect();
    let cfg = ChipConfig {
        k,
        format: fmt.into(),
        ..ChipConfig::default()
    };
    HostSetup {
        j,
        cmat,
        cvec,
        ..HostSetup::new(&cfg, &crate::pose::Pose::default(), 1.0, TriSide::UNUSED)
    }
}

/// Sets `e` so that each e_g meets minus the d' it is compared with, `dp[opp(g)]`, up to two
/// ulps above (no flag) or, at one lane in k on average, one ulp below (a flag): both
/// verdicts come out, decided in the last ulp.
pub(crate) fn near_flags(rng: &mut impl Rng, fmt: Format, dp: &[f64], e: &mut [f64]) {
    let k = e.len();
    for (g, x) in e.iter_mut().enumerate() {
        let mut y = -dp[opposite_lane(k, g)];
        if rng.random_range(0..k) == 0 {
            y = fmt.next_down(y);
        } else {
            for _ in 0..rng.random_range(0..3) {
                y = fmt.next_up(y);
            }
        }
        if !y.is_nan() {
            *x = y;
        }
    }
}

/// A tumbled DOP of `k` random distances, non-negative (a DOP that can overlap) two times
/// in three.
fn random_dop(rng: &mut impl Rng, k: usize) -> Vec<f64> {
    let nonneg = rng.random_range(0..3) != 2;
    (0..k)
        .map(|_| FORMAT.from_bits(super::units::operand(rng, FORMAT)))
        .map(|x| if nonneg { x.abs() } else { x })
        .collect()
}

/// A DOP's bundles of eight (zeros past its end).
fn bundles(d: &[f64]) -> Vec<[f64; 8]> {
    d.chunks(8)
        .map(|c| std::array::from_fn(|t| c.get(t).copied().unwrap_or(0.0)))
        .collect()
}

/// The driver's picture: which DOPs each set's input registers hold, and the load and the
/// aligned DOP in progress.
struct Driver {
    k: usize,
    held: [Option<[Vec<f64>; 2]>; 2],
    load: Option<(usize, VecDeque<TumbledBundle>)>,
    compare: Option<(usize, VecDeque<AlignedBundle>)>,
    bundles_driven: usize,
}

impl Driver {
    /// Starts loading set `s`: a new left DOP and, unless the set holds a pair and the
    /// group is a tumbled leaf alone (one time in five), a new right one.
    fn start_load(&mut self, rng: &mut impl Rng, s: usize) {
        let left = random_dop(rng, self.k);
        let alone = self.held[s].is_some() && rng.random_range(0..5) == 0;
        let right = match &self.held[s] {
            Some([_, r]) if alone => r.clone(),
            _ => random_dop(rng, self.k),
        };
        let mut queue = VecDeque::new();
        let sides: &[(usize, &Vec<f64>)] = if alone {
            &[(0, &left)]
        } else {
            &[(0, &left), (1, &right)]
        };
        for &(side, d) in sides {
            for (entry, data) in bundles(d).into_iter().enumerate() {
                queue.push_back(TumbledBundle {
                    set: s,
                    side,
                    entry,
                    last: false,
                    data,
                });
            }
        }
        queue.back_mut().expect("k > 0").last = true;
        self.held[s] = Some([left, right]);
        self.load = Some((s, queue));
    }

    /// Starts an aligned DOP against set `s`: random distances, or (two times in three) each
    /// a few ulps from a flag of one sibling's d'.
    fn start_compare(
        &mut self,
        rng: &mut impl Rng,
        s: usize,
        setup: &HostSetup,
        r: Rounding,
        dops: &mut Vec<AlignedDop>,
    ) {
        let fmt = FORMAT;
        let k = self.k;
        let d = self.held[s].clone().expect("a loaded set");
        let mut e: Vec<f64> = (0..k)
            .map(|_| fmt.from_bits(super::units::operand(rng, fmt)))
            .collect();
        if rng.random_range(0..3) != 0 {
            let base = &d[rng.random_range(0..2)];
            let dp: Vec<f64> = (0..k)
                .map(|i| crate::golden::dop_unit::dprime(fmt, r, setup, base, i))
                .collect();
            near_flags(rng, fmt, &dp, &mut e);
        }
        let b = bundles(&e);
        let n = b.len();
        let queue = b
            .into_iter()
            .enumerate()
            .map(|(entry, e)| AlignedBundle {
                set: s,
                entry,
                first: entry == 0,
                lanes: ((1u32 << (k - 8 * entry).min(8)) - 1) as u8,
                e,
            })
            .collect();
        dops.push(AlignedDop {
            set: s,
            e,
            d,
            last_bundle: self.bundles_driven + n - 1,
        });
        self.compare = Some((s, queue));
    }

    /// The next bundle of the load or the aligned DOP in progress (or none this clock: the
    /// memory is late).
    fn next<T>(rng: &mut impl Rng, job: &mut Option<(usize, VecDeque<T>)>, p: f64) -> Option<T> {
        let (_, q) = job.as_mut()?;
        let b = rng.random_bool(p).then(|| q.pop_front()).flatten();
        if q.is_empty() {
            *job = None;
        }
        b
    }
}

/// `clocks` clocks of the DOP Unit of `k` directions, every lane rounding `r`, drawn from
/// `seed`: loads start now and then into a set that is neither busy nor being compared
/// with; aligned DOPs start against a loaded set that is neither busy nor being loaded;
/// both run concurrently, a bundle on most clocks. The driver reads the model's `busy`.
pub fn dop_unit_traffic(k: usize, r: Rounding, seed: u64, clocks: usize) -> DopTraffic {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let setup = random_setup(&mut rng, k);
    let mut model = ClockedDopUnit::new(FORMAT, r, &setup);
    let mut drv = Driver {
        k,
        held: [None, None],
        load: None,
        compare: None,
        bundles_driven: 0,
    };
    let (mut ins, mut outs, mut dops) = (vec![], vec![], vec![]);
    let mut busy = [false; 2];
    for _ in 0..clocks {
        if drv.load.is_none() && rng.random_bool(0.1) {
            let comparing = drv.compare.as_ref().map(|c| c.0);
            let free: Vec<usize> = (0..2)
                .filter(|&s| !busy[s] && comparing != Some(s))
                .collect();
            if let Some(&s) = free.get(rng.random_range(0..free.len().max(1))) {
                drv.start_load(&mut rng, s);
            }
        }
        let t = Driver::next(&mut rng, &mut drv.load, 0.8);
        if drv.compare.is_none() && rng.random_bool(0.5) {
            let loading = drv.load.as_ref().map(|l| l.0).or(t.as_ref().map(|t| t.set));
            let ready: Vec<usize> = (0..2)
                .filter(|&s| drv.held[s].is_some() && !busy[s] && loading != Some(s))
                .collect();
            if let Some(&s) = ready.get(rng.random_range(0..ready.len().max(1))) {
                drv.start_compare(&mut rng, s, &setup, r, &mut dops);
            }
        }
        let a = Driver::next(&mut rng, &mut drv.compare, 0.85);
        drv.bundles_driven += a.is_some() as usize;
        let inp = ClockIn { t, a };
        let out = model.step(&inp);
        busy = out.busy;
        ins.push(inp);
        outs.push(out);
    }
    DopTraffic {
        setup,
        rounding: r,
        clocks: ins,
        outs,
        dops,
    }
}

/// Eight format values as a 256-bit bus word (slot t in bits 32 t ..).
fn bus(xs: &[f64; 8]) -> Bits<256> {
    let mut w = Bits::<256>::default();
    for (t, &x) in xs.iter().enumerate() {
        w.set_bits::<32>(32 * t, FORMAT.to_bits(x).into());
    }
    w
}

/// Drives one clock's inputs (the MMM's port idle).
pub fn set_inputs<const K: usize>(uut: &mut Wscg03DopUnit<K>, inp: &ClockIn) {
    uut.load_en.next = false;
    uut.t_valid.next = inp.t.is_some();
    if let Some(t) = &inp.t {
        uut.t_set.next = (t.set as u64).into();
        uut.t_side.next = t.side == 1;
        uut.t_entry.next = (t.entry as u64).into();
        uut.t_last.next = t.last;
        uut.t_data.next = bus(&t.data);
    }
    uut.a_valid.next = inp.a.is_some();
    if let Some(a) = &inp.a {
        uut.a_set.next = (a.set as u64).into();
        uut.a_entry.next = (a.entry as u64).into();
        uut.a_first.next = a.first;
        uut.a_lanes.next = (a.lanes as u64).into();
        uut.e.next = bus(&a.e);
    }
}

/// The outputs as the model's.
pub fn outputs<const K: usize>(uut: &Wscg03DopUnit<K>) -> ClockOut {
    let busy = uut.busy.val();
    ClockOut {
        busy: [busy.get_bit(0), busy.get_bit(1)],
        overlap: [uut.overlap_l.val(), uut.overlap_r.val()],
        flags_valid: uut.flags_valid.val(),
    }
}

use crate::cycle::wscg03::stack_engine::{appended, expand, ListCmd, ListOut, ListStack};
use crate::dop::DopTree;

/// A query's run of the Stack Engine's lists: each clock's command and the clocked model's
/// outputs after it, and the lists in the order they were read.
pub struct ListTraffic {
    pub cmds: Vec<ListCmd>,
    pub outs: Vec<ListOut>,
    pub lists: Vec<Vec<u32>>,
}

/// The Stack Engine's lists (the clocked [`ListStack`], SRAMs of 2^`sram_bits` pointers)
/// driven as its sequencer would on
/// the query of trees `a` (aligned) and `b` (tumbled) with DOP verdicts `overlap(n, x)`:
/// the root's pointer onto level 1, then per list its pointers read one a clock while
/// earlier ones' appends (one a clock) are pending, each read pointer tested against the
/// list's tumbled group (the group one level up's member `branch`, expanded), the list done
/// when every append has gone; idle while the lists step up. At most `max_clocks` clocks.
pub fn list_traffic(
    sram_bits: usize,
    a: &DopTree,
    b: &DopTree,
    overlap: &mut dyn FnMut(u32, u32) -> bool,
    max_clocks: usize,
) -> ListTraffic {
    let mut model = ListStack::new(sram_bits);
    let root = DopTree::ROOT;
    // the tumbled group per level (level 0's one member stands for the root's list)
    let mut groups: Vec<Vec<u32>> = vec![vec![root]];
    let mut pending: VecDeque<(usize, u16)> = VecDeque::from([(0, root as u16)]);
    let (mut cmds, mut outs, mut lists): (_, _, Vec<Vec<u32>>) = (vec![], vec![], vec![]);
    let (mut out, mut reads_out, mut started) = (ListOut::default(), 0u16, false);
    while cmds.len() < max_clocks && !out.done {
        if let Some(n) = out.rd {
            let group = &groups[out.level];
            if let Some(l) = lists.last_mut() {
                l.push(n as u32);
            }
            for (m, &x) in group.iter().enumerate() {
                if overlap(n as u32, x) {
                    pending.extend(
                        appended(a, b, n as u32, x)
                            .into_iter()
                            .map(|p| (m, p as u16)),
                    );
                }
            }
            reads_out -= 1;
        }
        let mut cmd = ListCmd {
            append: pending.pop_front(),
            ..ListCmd::default()
        };
        if !out.busy && started {
            cmd.read = out.remaining > reads_out && pending.len() < 4;
            reads_out += cmd.read as u16;
        }
        // the list is done: every pointer read, tested and its appends gone
        let list_done = out.remaining == 0 && reads_out == 0 && cmd.append.is_none();
        if !out.busy && list_done && (started || cmds.len() == 1) {
            cmd.next_list = true;
        }
        let before = (out.level, out.branch, out.busy);
        out = model.step(&cmd);
        cmds.push(cmd);
        outs.push(out);
        let entered = (out.level, out.branch, out.busy) != before;
        if entered && !out.busy && !out.done && out.level > 0 {
            let parent = if out.level == 1 {
                root
            } else {
                groups[out.level - 1][out.branch]
            };
            let g = if out.level == 1 {
                vec![root]
            } else {
                expand(b, parent)
            };
            groups.truncate(out.level);
            groups.push(g);
            lists.push(vec![]);
            started = true;
        }
    }
    ListTraffic { cmds, outs, lists }
}

/// Drives one clock's command into the RTL lists.
pub fn set_list_inputs<const A: usize>(
    uut: &mut crate::rtl::wscg03::stack_engine::ListStack<A>,
    c: &ListCmd,
) {
    uut.clear.next = c.clear;
    uut.append.next = c.append.is_some();
    let (side, ptr) = c.append.unwrap_or((0, 0));
    uut.wr_side.next = side == 1;
    uut.wr_ptr.next = (ptr as u64).into();
    uut.read.next = c.read;
    uut.next_list.next = c.next_list;
}

/// The RTL lists' outputs as the model's.
pub fn list_outputs<const A: usize>(
    uut: &crate::rtl::wscg03::stack_engine::ListStack<A>,
) -> ListOut {
    ListOut {
        level: uut.level.val().index(),
        branch: uut.branch.val() as usize,
        remaining: uut.remaining.val().index() as u16,
        busy: uut.busy.val(),
        done: uut.done.val(),
        rd: uut.rd_valid.val().then(|| uut.rd_ptr.val().index() as u16),
        overflow: uut.overflow.val(),
    }
}

/// SRAM address bits of the exported lists (`list_stack_a8`) and their tests.
pub const LIST_TEST_BITS: usize = 8;

/// The commands that test the Stack Engine's lists (SRAMs of 2^[`LIST_TEST_BITS`]
/// pointers): whole queries of two soups (20 and 120 triangles, DOP verdicts of the
/// default chip), each followed by a `clear`; 260 appends onto level 1's left list (past
/// the SRAM: overflow), down and 20 reads, a `clear`; one
/// pointer a level down past the last level (overflow), then idle clocks while the lists
/// step up to done.
pub fn list_commands() -> Vec<ListCmd> {
    use crate::golden::dop_unit::TransformCache;
    use crate::pose::Pose;
    let mut cmds = vec![];
    let clear = ListCmd {
        clear: true,
        ..ListCmd::default()
    };
    for (n, seed, pose) in [
        (20, 1, Pose::new(10.0, 20.0, 30.0, 0.1, 0.0, 0.0)),
        (120, 3, Pose::new(-35.0, 80.0, 5.0, 0.2, -0.1, 0.05)),
    ] {
        let soup = |s| crate::mesh::soup(n, s).triangles_f64();
        let chip = crate::query::Chip::new(&soup(seed), &soup(seed + 1), ChipConfig::default())
            .expect("a soup is a valid object");
        let setup = chip.setup(&pose);
        let (a, b, cfg) = (&chip.a.tree, &chip.b.tree, &chip.cfg);
        let mut cache = TransformCache::new(cfg.format.dop, cfg.dop_rounding.op(), &setup, a, b);
        cmds.extend(
            list_traffic(
                LIST_TEST_BITS,
                a,
                b,
                &mut |n, x| cache.overlap(x, n),
                1 << 20,
            )
            .cmds,
        );
        cmds.push(clear);
    }
    let cmd = |append: Option<(usize, u16)>, read: bool, next_list: bool| ListCmd {
        append,
        read,
        next_list,
        ..ListCmd::default()
    };
    cmds.extend((0..(1u16 << LIST_TEST_BITS) + 4).map(|p| cmd(Some((0, p)), false, false)));
    cmds.push(cmd(None, false, true));
    cmds.extend((0..20).map(|_| cmd(None, true, false)));
    cmds.push(clear);
    for p in 0..34u16 {
        cmds.push(cmd(Some(((p % 2) as usize, p)), false, false));
        cmds.push(cmd(None, true, true));
    }
    cmds.extend((0..70).map(|_| ListCmd::default()));
    cmds
}

/// Vectors of the Stack Engine's lists, a clock per line: [`list_commands`] and the
/// clocked model's outputs after each clock's rising edge.
pub fn list_stack_vectors() -> String {
    use std::fmt::Write;
    let mut model = ListStack::new(LIST_TEST_BITS);
    let mut out = String::new();
    let _ = writeln!(out, "// clear append wr_side wr_ptr read next_list level branch remaining busy done rd_valid rd_ptr overflow");
    let _ = writeln!(out, "// latency: 1");
    let _ = writeln!(out, "// list_stack_a8: WSCG'03's Stack Engine's lists, one line per clock: inputs, then the outputs after that clock's rising edge; golden: cycle::wscg03::stack_engine::ListStack");
    for c in list_commands() {
        let o = model.step(&c);
        let (side, ptr) = c.append.unwrap_or((0, 0));
        let b = |x: bool| x as u8;
        let _ = writeln!(
            out,
            "{} {} {side} {ptr:04x} {} {} {:02x} {} {:04x} {} {} {} {:04x} {}",
            b(c.clear),
            b(c.append.is_some()),
            b(c.read),
            b(c.next_list),
            o.level,
            o.branch,
            o.remaining,
            b(o.busy),
            b(o.done),
            b(o.rd.is_some()),
            o.rd.unwrap_or(0),
            b(o.overflow)
        );
    }
    out
}

/// Whole queries' traffic of WSCG'03's units, a [`TrafficQuery`] each.
pub struct Traffic {
    pub queries: Vec<TrafficQuery>,
}

/// One query of the traffic: the clocked chip's memory (`img`: its records, as the models
/// read them), the same memory's words as DATE'05's image builds them
/// ([`QueryImage`](crate::harness::chip_io::QueryImage) in the `records` layout of one
/// level), the requests outstanding at most, the units' inputs in every clock.
pub struct TrafficQuery {
    pub img: crate::cycle::wscg03::memory_controller::Images,
    pub words: Vec<crate::harness::chip_io::Word>,
    pub outstanding: usize,
    pub ins: UnitInputs,
}

/// The units' inputs (the DOP Unit's setup words written first) in two queries of soups (30 against 40 triangles, all
/// pairs; 120 against 80, the first hit) on WSCG'03's chip clocked register by register,
/// on an ideal memory of 5 clocks' latency with 4 requests outstanding.
pub fn traffic() -> Traffic {
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
        (30, 40, 7, false, Pose::new(5.0, 10.0, 0.0, 0.3, 0.2, 0.1)),
        (
            120,
            80,
            3,
            true,
            Pose::new(-35.0, 80.0, 5.0, 0.2, -0.1, 0.05),
        ),
    ] {
        let soup = |n, s| crate::mesh::soup(n, s).triangles_f64();
        let cfg = crate::chip::config::ChipConfig {
            layout: crate::chip::config::MemLayout::Records,
            ..Default::default()
        };
        let chip = crate::query::Chip::new(&soup(na, seed), &soup(nb, seed + 1), cfg)
            .expect("a soup is a valid object");
        let img = crate::cycle::wscg03::clocked::images(&chip);
        let setup = chip.setup(&pose);
        let kind = crate::chip::rtl::ChipKind::of(&cfg, p.dop_interval, p.tri_interval, p.depth)
            .expect("binary32, k = 24, in records: an RTL chip's configuration");
        let mode = crate::chip::reg::Mode::All;
        let image = crate::harness::chip_io::QueryImage::new(
            kind,
            &chip.a,
            &chip.b,
            &setup,
            crate::chip::reg::Order::Fifo,
            mode,
            &p,
            &cfg,
        )
        .expect("a soup fits the chip");
        // the DOP Unit's setup words, as DATE'05's chip is written them
        let dop_words: Vec<(u32, u32)> = image
            .writes
            .iter()
            .copied()
            .filter(|w| w.0 < 0x100)
            .collect();
        let ins = crate::cycle::wscg03::clocked::unit_inputs(
            &chip,
            &img,
            (&setup, &dop_words),
            first,
            &p,
            1 << 24,
        )
        .expect("the query finishes");
        queries.push(TrafficQuery {
            img,
            words: image.memory,
            outstanding: p.outstanding as usize,
            ins,
        });
    }
    Traffic { queries }
}
