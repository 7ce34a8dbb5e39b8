//! The triangle datapath in RTL against the golden model, bit for bit.
//!
//! T.CHECK (`collision_chip::rtl::{b32, e8m15}::TCheck`) against the golden
//! `golden::tcheck::{stage1, edges}`, bit for bit: s = (a + b) - r_z and its bound per edge,
//! the three-valued crossing per edge and the direction's verdict, in both directions of
//! TRI_UNIT (A vs U(B), B vs U(A)), on every triangle pair of the hard-case catalogue and on
//! generated pairs (the hard-case families and general pairs under general poses), binary32
//! and e8m15, one pair per clock through the 52-stage pipeline. A T.CHECK with the wrong
//! rounding is caught.
//!
//! TRI_UNIT (`TriUnit`) against the golden `golden::tcheck::tri_unit`: the verdict
//! (intersecting, separate, uncertain) and the pair id of every pair, in order, on hard
//! cases of every kind of result and on generated pairs; a reader that stalls makes
//! `in_ready` fall and loses nothing; with a reader always ready, one result per clock after
//! `TriUnit::LATENCY`.

use collision_chip::chip::config::ChipConfig;
use collision_chip::chip::rtl::Depth;
use collision_chip::dop::tree::Tri;
use collision_chip::fold::plan::Binding;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::memory::TriWord;
use collision_chip::golden::tri_unit::tri_unit;
use collision_chip::golden::tri_unit::TriResult;
use collision_chip::hard_cases as hc;
use collision_chip::harness::tri_io::{
    tri_unit_directions, tri_unit_setup_words, LeafIn, TCheckIn, TCheckOut,
};
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::rtl::{b32, e8m10, e8m15};
use nalgebra::Point3;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;

mod common;
use common::families::{any_case, general_pose};
use common::{run, run_vcd, settle, Pipelined};

macro_rules! impl_tcheck {
    ($t:ty) => {
        impl Pipelined for $t {
            type In = TCheckIn;
            type Out = TCheckOut;
            const LATENCY: usize = <$t>::LATENCY;
            fn set(&mut self, x: TCheckIn, valid: bool) {
                for c in 0..4 {
                    self.m_0[c].next = x.m[c].into();
                    self.m_1[c].next = x.m[4 + c].into();
                    self.m_2[c].next = x.m[8 + c].into();
                    self.f_0[c].next = x.f[c].into();
                    self.f_1[c].next = x.f[4 + c].into();
                    self.f_2[c].next = x.f[8 + c].into();
                }
                self.alpha_m.next = x.alpha_m.into();
                self.alpha_f.next = x.alpha_f.into();
                self.beta_m.next = x.beta_m.into();
                self.beta_f.next = x.beta_f.into();
                self.scale.next = x.scale.into();
                for k in 0..3 {
                    self.v_x[k].next = x.v[k][0].into();
                    self.v_y[k].next = x.v[k][1].into();
                    self.v_z[k].next = x.v[k][2].into();
                }
                self.v_exact.next = x.v_exact;
                self.tag.next = 0.into();
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, TCheckOut) {
                let o = TCheckOut {
                    s_x: std::array::from_fn(|e| self.s_x[e].val().to_u64()),
                    s_b: std::array::from_fn(|e| self.s_b[e].val().to_u64()),
                    cross_t: std::array::from_fn(|e| self.cross_t[e].val()),
                    cross_f: std::array::from_fn(|e| self.cross_f[e].val()),
                    hit: self.hit.val(),
                    miss: self.miss.val(),
                };
                (self.valid_out.val(), o)
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    };
}

impl_tcheck!(b32::TCheck);
impl_tcheck!(e8m15::TCheck);
impl_tcheck!(e8m10::TCheck);

/// Runs `f` on a thread with a stack big enough for a T.CHECK (built on the stack).
fn big_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1 << 30)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap()
}

/// The T.CHECK cases of a triangle pair set: both directions of every pair.
fn cases(
    f: Format,
    r: Rounding,
    pairs: &[(TriWord, TriWord, collision_chip::golden::host::HostSetup)],
) -> Vec<(TCheckIn, TCheckOut)> {
    pairs
        .iter()
        .flat_map(|(a, b, s)| tri_unit_directions(f, r, a, b, s))
        .collect()
}

/// Triangle pairs of a scene: every (a, b) of the two objects under the pose.
fn scene_pairs(
    f: Format,
    a: &[Tri],
    b: &[Tri],
    pose: &Pose,
) -> Vec<(TriWord, TriWord, collision_chip::golden::host::HostSetup)> {
    let chip = Chip::new(
        a,
        b,
        ChipConfig {
            format: f.into(),
            ..Default::default()
        },
    )
    .unwrap();
    let setup = chip.setup(pose);
    let mut out = vec![];
    for ta in chip.a.tris() {
        for tb in chip.b.tris() {
            out.push((ta, tb, setup.clone()));
        }
    }
    out
}

/// Runs `cases` through a fresh T.CHECK of the format with `rounding`; returns the
/// mismatches (described) and the number of cases.
fn mismatches(
    f: Format,
    rounding: Rounding,
    cases: Vec<(TCheckIn, TCheckOut)>,
) -> (Vec<String>, usize) {
    big_stack(move || {
        let ins: Vec<TCheckIn> = cases.iter().map(|c| c.0).collect();
        let outs = if f == Format::BINARY32 {
            let mut uut = b32::tcheck_top(rounding);
            run(&mut uut, &ins)
        } else if f == Format::E8M10 {
            let mut uut = e8m10::tcheck_top(rounding);
            run(&mut uut, &ins)
        } else {
            let mut uut = e8m15::tcheck_top(rounding);
            run(&mut uut, &ins)
        };
        let bad = cases
            .iter()
            .zip(&outs)
            .enumerate()
            .filter(|(_, ((_, want), got))| want != *got)
            .map(|(i, ((x, want), got))| {
                format!("case {i}: {x:?}\n  golden {want:?}\n  rtl    {got:?}")
            })
            .collect();
        (bad, cases.len())
    })
}

/// Fails with the first mismatches if there are any; `unit` names what was counted.
fn assert_none(what: &str, unit: &str, (bad, n): (Vec<String>, usize)) {
    assert!(n > 0);
    assert!(
        bad.is_empty(),
        "{what}: {} problems in {n} {unit}; first:\n{}",
        bad.len(),
        bad[..bad.len().min(5)].join("\n")
    );
    eprintln!("{what}: {n} {unit} equal to the golden model");
}

fn catalogue_cases(f: Format) -> Vec<(TCheckIn, TCheckOut)> {
    let mut pairs = vec![];
    for case in hc::load_catalogue().unwrap() {
        pairs.extend(scene_pairs(f, &case.a, &case.b, &case.pose));
    }
    cases(f, Rounding::NearestEven, &pairs)
}

#[test]
fn tcheck_catalogue_binary32() {
    assert_none(
        "catalogue binary32",
        "T.CHECKs",
        mismatches(
            Format::BINARY32,
            Rounding::NearestEven,
            catalogue_cases(Format::BINARY32),
        ),
    );
}

#[test]
fn tcheck_catalogue_e8m15() {
    assert_none(
        "catalogue e8m15",
        "T.CHECKs",
        mismatches(
            Format::REDUCED,
            Rounding::NearestEven,
            catalogue_cases(Format::REDUCED),
        ),
    );
}

/// Samples `n` values of `strat` (deterministic seed).
fn sample<T: std::fmt::Debug>(strat: impl Strategy<Value = T>, n: usize) -> Vec<T> {
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        proptest::test_runner::TestRng::deterministic_rng(
            proptest::test_runner::RngAlgorithm::ChaCha,
        ),
    );
    (0..n)
        .map(|_| strat.new_tree(&mut runner).unwrap().current())
        .collect()
}

fn tri() -> impl Strategy<Value = Tri> {
    prop::array::uniform3(prop::array::uniform3(-1.0..1.0f64))
        .prop_map(|t| t.map(|p| Point3::new(p[0], p[1], p[2])))
}

/// General rotations, translations up to 0.3: triangles of [-1, 1]^3 often cross.
fn near_pose() -> impl Strategy<Value = Pose> {
    (
        prop::array::uniform3(-180.0..180.0f64),
        prop::array::uniform3(-0.3..0.3f64),
    )
        .prop_map(|(r, t)| Pose { rot_deg: r, t })
}

/// Generated T.CHECK cases: 24 hard cases of every family (`any_case`, all triangle pairs
/// of each case), 20 general triangle pairs under general poses and 40 under near poses.
/// (rust-hdl runs about 14 T.CHECK pairs a second; the volume is the exported Verilog's,
/// vectors/tcheck_*.hex under Verilator and Icarus in CI.)
fn generated_cases(f: Format) -> Vec<(TCheckIn, TCheckOut)> {
    let mut pairs = vec![];
    for case in sample(any_case(), 24) {
        pairs.extend(scene_pairs(f, &case.a, &case.b, &case.pose));
    }
    for (a, b, pose) in sample((tri(), tri(), general_pose()), 20)
        .into_iter()
        .chain(sample((tri(), tri(), near_pose()), 40))
    {
        pairs.extend(scene_pairs(f, &[a], &[b], &pose));
    }
    cases(f, Rounding::NearestEven, &pairs)
}

/// The generated cases reach every verdict: hit, miss and unknown directions.
fn verdicts(cases: &[(TCheckIn, TCheckOut)]) -> [usize; 3] {
    let mut n = [0; 3];
    for (_, o) in cases {
        n[if o.hit {
            0
        } else if o.miss {
            1
        } else {
            2
        }] += 1;
    }
    n
}

#[test]
fn tcheck_generated_binary32() {
    let cases = generated_cases(Format::BINARY32);
    let v = verdicts(&cases);
    eprintln!("binary32 verdicts hit/miss/unknown: {v:?}");
    assert!(v.iter().all(|&n| n > 0), "{v:?}");
    assert_none(
        "generated binary32",
        "T.CHECKs",
        mismatches(Format::BINARY32, Rounding::NearestEven, cases),
    );
}

#[test]
fn tcheck_generated_e8m15() {
    let cases = generated_cases(Format::REDUCED);
    let v = verdicts(&cases);
    eprintln!("e8m15 verdicts hit/miss/unknown: {v:?}");
    assert!(v.iter().all(|&n| n > 0), "{v:?}");
    assert_none(
        "generated e8m15",
        "T.CHECKs",
        mismatches(Format::REDUCED, Rounding::NearestEven, cases),
    );
}

#[test]
fn tcheck_catalogue_e8m10() {
    assert_none(
        "catalogue e8m10",
        "T.CHECKs",
        mismatches(
            Format::E8M10,
            Rounding::NearestEven,
            catalogue_cases(Format::E8M10),
        ),
    );
}

/// The comparison can fail: a T.CHECK rounding toward +inf differs from the nearest-even
/// golden model on the catalogue.
#[test]
fn tcheck_wrong_rounding_is_caught() {
    let (bad, n) = mismatches(
        Format::BINARY32,
        Rounding::TowardPositive,
        catalogue_cases(Format::BINARY32),
    );
    assert!(
        !bad.is_empty(),
        "a toward-+inf T.CHECK matched the nearest-even golden model on all {n} cases"
    );
}

// ---------------------------------------------------------------------------------------
// TRI_UNIT
// ---------------------------------------------------------------------------------------

/// TRI_UNIT's ports as the driver sees them.
trait TriUnitSim: Block {
    /// Pair in to result out, with a reader always ready.
    fn latency(&self) -> usize;
    /// Clocks between pairs taken (1: one per clock).
    fn interval(&self) -> usize;
    fn set_load(&mut self, en: bool, addr: u64, data: u64);
    fn set_pair(&mut self, a: &LeafIn, b: &LeafIn, tag: u32, valid: bool);
    fn set_out_ready(&mut self, ready: bool);
    fn in_ready(&self) -> bool;
    /// `(out_valid, (tag, verdict))`.
    fn result(&self) -> (bool, (u32, TriResult));
    fn clock(&mut self, high: bool);
}

macro_rules! impl_tri_unit {
    ($t:ty, $latency:expr, $interval:expr) => {
        impl TriUnitSim for $t {
            fn latency(&self) -> usize {
                let f: fn(&$t) -> usize = $latency;
                f(self)
            }
            fn interval(&self) -> usize {
                let f: fn(&$t) -> usize = $interval;
                f(self)
            }
            fn set_load(&mut self, en: bool, addr: u64, data: u64) {
                self.load_en.next = en;
                self.load_addr.next = addr.into();
                self.load_data.next = data.into();
            }
            fn set_pair(&mut self, a: &LeafIn, b: &LeafIn, tag: u32, valid: bool) {
                for c in 0..4 {
                    self.a_m_0[c].next = a.m[c].into();
                    self.a_m_1[c].next = a.m[4 + c].into();
                    self.a_m_2[c].next = a.m[8 + c].into();
                    self.b_m_0[c].next = b.m[c].into();
                    self.b_m_1[c].next = b.m[4 + c].into();
                    self.b_m_2[c].next = b.m[8 + c].into();
                }
                for k in 0..3 {
                    self.a_v_x[k].next = a.v[k][0].into();
                    self.a_v_y[k].next = a.v[k][1].into();
                    self.a_v_z[k].next = a.v[k][2].into();
                    self.b_v_x[k].next = b.v[k][0].into();
                    self.b_v_y[k].next = b.v[k][1].into();
                    self.b_v_z[k].next = b.v[k][2].into();
                }
                self.a_alpha_m.next = a.alpha_m.into();
                self.a_alpha_f.next = a.alpha_f.into();
                self.a_v_exact.next = a.v_exact;
                self.a_degenerate.next = a.degenerate;
                self.b_alpha_m.next = b.alpha_m.into();
                self.b_alpha_f.next = b.alpha_f.into();
                self.b_v_exact.next = b.v_exact;
                self.b_degenerate.next = b.degenerate;
                self.tag.next = (tag as u64).into();
                self.in_valid.next = valid;
            }
            fn set_out_ready(&mut self, ready: bool) {
                self.out_ready.next = ready;
            }
            fn in_ready(&self) -> bool {
                self.in_ready.val()
            }
            fn result(&self) -> (bool, (u32, TriResult)) {
                let r = TriResult {
                    hit: self.out_hit.val(),
                    uncertain: self.out_uncertain.val(),
                };
                (
                    self.out_valid.val(),
                    (self.out_tag.val().to_u64() as u32, r),
                )
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    };
}

impl_tri_unit!(b32::TriUnit, |_| b32::TriUnit::LATENCY, |_| 1);
impl_tri_unit!(e8m15::TriUnit, |_| e8m15::TriUnit::LATENCY, |_| 1);
impl_tri_unit!(
    b32::TriUnitFold,
    b32::TriUnitFold::latency,
    b32::TriUnitFold::interval
);
impl_tri_unit!(
    e8m15::TriUnitFold,
    e8m15::TriUnitFold::latency,
    e8m15::TriUnitFold::interval
);
impl_tri_unit!(
    e8m15::TriUnitFoldFpga,
    e8m15::TriUnitFoldFpga::latency,
    e8m15::TriUnitFoldFpga::interval
);

/// TRI_UNIT work: setup writes and pairs in the order the host issues them (the frame
/// registers are read when a pair is taken, so a new pose's setup may follow pairs still
/// in flight), and the golden verdict of every pair (tag = pair index).
#[derive(Default)]
struct TriJob {
    steps: Vec<Step>,
    golden: Vec<TriResult>,
}

// most steps are pairs: boxing the large variant would save no memory
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy)]
enum Step {
    Load(u64, u64),
    Pair(LeafIn, LeafIn),
}

/// What the driver saw: results `(tag, verdict)` in output order, the clocks from taking
/// the first pair to reading the first result, whether `in_ready` was ever low, the cycles
/// pairs were taken in.
struct TriRun {
    results: Vec<(u32, TriResult)>,
    first_latency: Option<usize>,
    stalled: bool,
    taken: Vec<usize>,
}

/// Issues the steps (a setup write per clock with `in_valid` low; a pair with `in_valid`
/// high until taken) and reads results while `reader(cycle)` says the reader is ready;
/// handshakes are sampled before each rising edge.
fn drive<U: TriUnitSim>(uut: &mut U, job: &TriJob, reader: impl Fn(usize) -> bool) -> TriRun {
    let blank = LeafIn::default();
    let (mut step, mut tag, mut results, mut first_in, mut first_latency, mut stalled, mut taken) =
        (0, 0u32, vec![], None, None, false, vec![]);
    let limit = job.steps.len() * 4 * uut.interval() + 4 * uut.latency() + 1000;
    for cycle in 0..limit {
        if results.len() == job.golden.len() && step == job.steps.len() {
            break;
        }
        uut.set_load(false, 0, 0);
        uut.set_pair(&blank, &blank, 0, false);
        match job.steps.get(step) {
            Some(&Step::Load(addr, data)) => uut.set_load(true, addr, data),
            Some(Step::Pair(a, b)) => uut.set_pair(a, b, tag, true),
            None => {}
        }
        uut.set_out_ready(reader(cycle));
        settle(uut);
        match job.steps.get(step) {
            Some(Step::Load(..)) => step += 1,
            Some(Step::Pair(..)) if uut.in_ready() => {
                first_in.get_or_insert(cycle);
                taken.push(cycle);
                step += 1;
                tag += 1;
            }
            Some(Step::Pair(..)) => stalled = true,
            None => {}
        }
        let (v, r) = uut.result();
        if v && reader(cycle) {
            first_latency.get_or_insert(cycle - first_in.unwrap_or(0));
            results.push(r);
        }
        for high in [true, false] {
            uut.clock(high);
            settle(uut);
        }
    }
    TriRun {
        results,
        first_latency,
        stalled,
        taken,
    }
}

/// The host's steps for triangle pairs: a setup write for every frame register whose value
/// changes with the pair's pose, then the pair.
fn tri_job(
    f: Format,
    triples: &[(TriWord, TriWord, collision_chip::golden::host::HostSetup)],
) -> TriJob {
    let mut regs = std::collections::HashMap::new();
    let mut job = TriJob::default();
    for (a, b, s) in triples {
        for (addr, data) in tri_unit_setup_words(f, s) {
            if regs.insert(addr, data) != Some(data) {
                job.steps.push(Step::Load(addr, data));
            }
        }
        job.steps
            .push(Step::Pair(LeafIn::of(f, a), LeafIn::of(f, b)));
        job.golden.push(tri_unit(f, Rounding::NearestEven, a, b, s));
    }
    job
}

/// Runs `job` through a TRI_UNIT with a reader always ready; returns the mismatches and the
/// number of pairs.
fn tri_unit_mismatches(f: Format, job: TriJob) -> (Vec<String>, usize) {
    big_stack(move || {
        let bad = if f == Format::BINARY32 {
            run_mismatches(&mut b32::tri_unit_top(Rounding::NearestEven), &job)
        } else {
            run_mismatches(&mut e8m15::tri_unit_top(Rounding::NearestEven), &job)
        };
        (bad, job.golden.len())
    })
}

/// Runs `job` through `uut` with a reader always ready: the mismatches against the golden
/// verdicts, the first result's latency, and the rhythm (pairs taken `interval` clocks apart or
/// a multiple of it; one per clock: `in_ready` never low).
fn run_mismatches<U: TriUnitSim>(uut: &mut U, job: &TriJob) -> Vec<String> {
    let run = drive(uut, job, |_| true);
    let mut bad = vec![];
    let want: Vec<(u32, TriResult)> = job
        .golden
        .iter()
        .enumerate()
        .map(|(i, &r)| (i as u32, r))
        .collect();
    for (i, w) in want.iter().enumerate() {
        if run.results.get(i) != Some(w) {
            bad.push(format!(
                "pair {i}: golden {w:?}, rtl {:?}",
                run.results.get(i)
            ));
        }
    }
    if run.results.len() != want.len() {
        bad.push(format!(
            "{} results for {} pairs",
            run.results.len(),
            want.len()
        ));
    }
    if run.first_latency != Some(uut.latency()) {
        bad.push(format!(
            "first result {:?} clocks after the first pair, not {}",
            run.first_latency,
            uut.latency()
        ));
    }
    let ii = uut.interval();
    if ii == 1 && run.stalled {
        bad.push("in_ready fell with a reader always ready".into());
    }
    if let Some(w) = run.taken.windows(2).find(|w| (w[1] - w[0]) % ii != 0) {
        bad.push(format!(
            "pairs taken at cycles {} and {}, not a multiple of {ii} apart",
            w[0], w[1]
        ));
    }
    bad
}

/// Hard cases that reach every kind of TRI_UNIT result: the first catalogue case that adds a
/// sure hit, a sure miss, an uncertain pair or a degenerate leaf, all its pairs, each case
/// under its own pose (the setup changes between pairs in flight). (rust-hdl runs TRI_UNIT
/// at about 5 clocks per second; the volume is T.CHECK's above, here and in the exported
/// Verilog, and the chip's, in the cycle model and under Verilator.)
fn catalogue_triples(
    f: Format,
) -> Vec<(TriWord, TriWord, collision_chip::golden::host::HostSetup)> {
    let mut seen = [false; 4];
    let mut out = vec![];
    for case in hc::load_catalogue().unwrap() {
        let triples = scene_pairs(f, &case.a, &case.b, &case.pose);
        let mut new = false;
        for (a, b, s) in &triples {
            let r = tri_unit(f, Rounding::NearestEven, a, b, s);
            let kind = if a.degenerate || b.degenerate {
                3
            } else if r.uncertain {
                2
            } else if r.hit {
                0
            } else {
                1
            };
            new |= !std::mem::replace(&mut seen[kind], true);
        }
        if new {
            out.extend(triples);
        }
    }
    assert_eq!(
        seen, [true; 4],
        "the catalogue lacks a hit, a miss, an uncertain pair or a degenerate leaf"
    );
    out
}

/// Triangle pairs of a random soup pair (`na` x `nb` triangles of [-1, 1]^3) under a near pose.
fn soup_triples(
    f: Format,
    na: usize,
    nb: usize,
) -> Vec<(TriWord, TriWord, collision_chip::golden::host::HostSetup)> {
    let tris = sample(prop::collection::vec(tri(), na + nb), 1)
        .pop()
        .unwrap();
    let pose = sample(near_pose(), 2).pop().unwrap();
    scene_pairs(f, &tris[..na], &tris[na..], &pose)
}

/// TRI_UNIT in e8m15 with a reader always ready: the hard cases and a 3 x 4 soup, every
/// verdict and pair id the golden model's, in order, one result per clock after
/// `TriUnit::LATENCY`, `in_ready` never low.
#[test]
fn tri_unit_e8m15() {
    let f = Format::REDUCED;
    let mut triples = catalogue_triples(f);
    triples.extend(soup_triples(f, 3, 4));
    assert_none(
        "TRI_UNIT e8m15",
        "pairs",
        tri_unit_mismatches(f, tri_job(f, &triples)),
    );
}

/// The folded TRI_UNIT (`TriUnitFold`, a pair every 16 clocks, both directions on one T.CHECK
/// folded for 8) with a reader always ready: the hard cases of every kind of result, each
/// under its own pose (the setup changes between pairs in flight), and a 4 x 5 soup, every verdict and pair id
/// the golden model's, in order; the first result `latency()` clocks after the first pair;
/// pairs taken 16 clocks apart (or a multiple: a setup write can make a pair miss its slot).
#[test]
fn tri_unit_fold16_binary32() {
    assert_none(
        "folded TRI_UNIT (II 16) binary32",
        "pairs",
        tri_unit_fold16_mismatches(Format::BINARY32),
    );
}

/// The same in e8m15 (`rtl::e8m15::TriUnitFold`, the TRI_UNIT of the chip
/// `chip_e8m15_k6_fold16`): the generator's schedule on e8m15's units, bit for bit golden.
#[test]
fn tri_unit_fold16_e8m15() {
    assert_none(
        "folded TRI_UNIT (II 16) e8m15",
        "pairs",
        tri_unit_fold16_mismatches(Format::REDUCED),
    );
}

/// The hard cases and a 4 x 5 soup through the TRI_UNIT folded for a pair every 16 clocks
/// in `f`: the mismatches and the number of pairs.
fn tri_unit_fold16_mismatches(f: Format) -> (Vec<String>, usize) {
    let plan = collision_chip::fold::tri_unit_plan(16, Binding::Shared, Depth::Asic).unwrap();
    let job = tri_job(f, &fold_triples(f));
    let n = job.golden.len();
    let bad = big_stack(move || {
        if f == Format::BINARY32 {
            run_mismatches(
                &mut b32::tri_unit_fold_top(plan, Rounding::NearestEven),
                &job,
            )
        } else {
            run_mismatches(
                &mut e8m15::tri_unit_fold_top(plan, Rounding::NearestEven),
                &job,
            )
        }
    });
    (bad, n)
}

/// The hard cases and a 4 x 5 soup: the folded TRI_UNIT's test set.
fn fold_triples(f: Format) -> Vec<(TriWord, TriWord, collision_chip::golden::host::HostSetup)> {
    let mut triples = catalogue_triples(f);
    triples.extend(soup_triples(f, 4, 5));
    triples
}

/// The FPGA chip's TRI_UNIT (`rtl::e8m15::TriUnitFoldFpga`: a pair every 32 clocks, T.CHECK
/// at FPGA depth with its operands registered and its registers per reader) on the same
/// set: every verdict and pair id the golden model's, the first result `latency()` clocks
/// after the first pair.
#[test]
fn tri_unit_fold32_e8m15_fpga() {
    let f = Format::REDUCED;
    let plan = collision_chip::fold::tri_unit_plan(32, Binding::PerReader, Depth::Fpga).unwrap();
    let job = tri_job(f, &fold_triples(f));
    let n = job.golden.len();
    let bad = big_stack(move || {
        run_mismatches(
            &mut e8m15::tri_unit_fold_fpga_top(plan, Rounding::NearestEven),
            &job,
        )
    });
    assert_none(
        "folded TRI_UNIT (II 32) e8m15 at FPGA depth",
        "pairs",
        (bad, n),
    );
}

/// TRI_UNIT in binary32 under back pressure: the hard cases, then more soup pairs than the
/// result FIFO holds; the reader is away for the first 400 clocks, then ready three clocks
/// in four: the FIFO fills, `in_ready` falls, and every result still arrives, in order, equal
/// to the golden model's.
#[test]
fn tri_unit_binary32_back_pressure_loses_nothing() {
    let f = Format::BINARY32;
    let mut triples = catalogue_triples(f);
    let soup = soup_triples(f, 10, 10);
    triples.extend(
        soup.iter()
            .cloned()
            .cycle()
            .take(b32::TriUnit::FIFO_DEPTH + 20),
    );
    let job = tri_job(f, &triples);
    let golden = job.golden.clone();
    let run = big_stack(move || {
        let mut uut = b32::tri_unit_top(Rounding::NearestEven);
        drive(&mut uut, &job, |c| c >= 400 && c % 4 != 0)
    });
    assert!(run.stalled, "the FIFO never filled");
    let want: Vec<(u32, TriResult)> = golden
        .iter()
        .enumerate()
        .map(|(i, &r)| (i as u32, r))
        .collect();
    assert_eq!(run.results.len(), want.len(), "results lost");
    assert_eq!(run.results, want);
}

/// A traced T.CHECK run (binary32, the catalogue's first 16 directions) for GTKWave:
/// target/rtl-vcd/tcheck_b32.vcd, scopes named after the blocks (`tcheck.mb_0$3.p$2.mul`).
#[test]
fn tcheck_vcd_trace() {
    let cases: Vec<(TCheckIn, TCheckOut)> = catalogue_cases(Format::BINARY32)
        .into_iter()
        .take(16)
        .collect();
    let outs = big_stack(move || {
        let ins: Vec<TCheckIn> = cases.iter().map(|c| c.0).collect();
        let outs = run_vcd(
            &mut b32::tcheck_top(Rounding::NearestEven),
            &ins,
            "tcheck_b32",
            "tcheck",
        );
        (outs, cases)
    });
    for (got, (_, want)) in outs.0.iter().zip(&outs.1) {
        assert_eq!(got, want);
    }
}
