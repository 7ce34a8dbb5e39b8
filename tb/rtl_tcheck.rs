//! T.CHECK in RTL (`collision_chip::rtl::{b32, e8m15}::TCheck`) against the golden
//! `golden::tcheck::{stage1, edges}`, bit for bit: s = (a + b) - r_z and its bound per edge,
//! the three-valued crossing per edge and the direction's verdict, in both directions of
//! TRI_UNIT (A vs U(B) with the vertex gap, B vs U(A) without), on every triangle pair of
//! the hard-case catalogue and on generated pairs (the hard-case families and general
//! pairs under general poses), binary32 and e8m15, one pair per clock through the 128-stage
//! pipeline. A T.CHECK with the wrong rounding is caught. A VCD under target/rtl-vcd/.

use collision_chip::config::ChipConfig;
use collision_chip::dop::tree::Tri;
use collision_chip::format::{Format, Rounding};
use collision_chip::hard_cases as hc;
use collision_chip::memory::TriWord;
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::rtl::tri_io::{tri_unit_directions, TCheckIn, TCheckOut};
use collision_chip::rtl::{b32, e8m15};
use nalgebra::Point3;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;

mod common;
use common::families::{any_case, general_pose};
use common::{run, Pipelined};

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
                self.e_lin.next = x.e_lin.into();
                self.e_tr.next = x.e_tr.into();
                self.l_norm.next = x.l_norm.into();
                self.f_lin.next = x.f_lin.into();
                self.f_tr.next = x.f_tr.into();
                self.eta.next = x.eta.into();
                self.gap_en.next = x.gap_en;
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
                    s_e: std::array::from_fn(|e| self.s_e[e].val().to_u64()),
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

/// Runs `f` on a thread with a stack big enough for a T.CHECK (built on the stack).
fn big_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new().stack_size(1 << 30).spawn(f).unwrap().join().unwrap()
}

/// The T.CHECK cases of a triangle pair set: both directions of every pair.
fn cases(f: Format, r: Rounding, pairs: &[(TriWord, TriWord, collision_chip::dop::HostSetup)]) -> Vec<(TCheckIn, TCheckOut)> {
    pairs.iter().flat_map(|(a, b, s)| tri_unit_directions(f, r, a, b, s)).collect()
}

/// Triangle pairs of a scene: every (a, b) of the two objects under the pose.
fn scene_pairs(f: Format, a: &[Tri], b: &[Tri], pose: &Pose) -> Vec<(TriWord, TriWord, collision_chip::dop::HostSetup)> {
    let chip = Chip::new(a, b, ChipConfig { format: f, ..Default::default() }).unwrap();
    let setup = chip.setup(pose);
    let mut out = vec![];
    for ta in &chip.a.tris {
        for tb in &chip.b.tris {
            out.push((ta.clone(), tb.clone(), setup.clone()));
        }
    }
    out
}

/// Runs `cases` through a fresh T.CHECK of the format with `rounding`; returns the
/// mismatches (described) and the number of cases.
fn mismatches(f: Format, rounding: Rounding, cases: Vec<(TCheckIn, TCheckOut)>) -> (Vec<String>, usize) {
    big_stack(move || {
        let ins: Vec<TCheckIn> = cases.iter().map(|c| c.0).collect();
        let outs = if f == Format::BINARY32 {
            let mut uut = b32::tcheck_top(rounding);
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
            .map(|(i, ((x, want), got))| format!("case {i}: {x:?}\n  golden {want:?}\n  rtl    {got:?}"))
            .collect();
        (bad, cases.len())
    })
}

fn assert_none(what: &str, (bad, n): (Vec<String>, usize)) {
    assert!(n > 0);
    assert!(bad.is_empty(), "{what}: {} of {n} T.CHECKs differ from the golden model; first:\n{}", bad.len(), bad[..bad.len().min(3)].join("\n"));
    eprintln!("{what}: {n} T.CHECKs equal to the golden model");
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
    assert_none("catalogue binary32", mismatches(Format::BINARY32, Rounding::NearestEven, catalogue_cases(Format::BINARY32)));
}

#[test]
fn tcheck_catalogue_e8m15() {
    assert_none("catalogue e8m15", mismatches(Format::REDUCED, Rounding::NearestEven, catalogue_cases(Format::REDUCED)));
}

/// Samples `n` values of `strat` (deterministic seed).
fn sample<T: std::fmt::Debug>(strat: impl Strategy<Value = T>, n: usize) -> Vec<T> {
    let mut runner = TestRunner::new_with_rng(Config::default(), proptest::test_runner::TestRng::deterministic_rng(proptest::test_runner::RngAlgorithm::ChaCha));
    (0..n).map(|_| strat.new_tree(&mut runner).unwrap().current()).collect()
}

fn tri() -> impl Strategy<Value = Tri> {
    prop::array::uniform3(prop::array::uniform3(-1.0..1.0f64)).prop_map(|t| t.map(|p| Point3::new(p[0], p[1], p[2])))
}

/// General rotations, translations up to 0.3: triangles of [-1, 1]^3 often cross.
fn near_pose() -> impl Strategy<Value = Pose> {
    (prop::array::uniform3(-180.0..180.0f64), prop::array::uniform3(-0.3..0.3f64)).prop_map(|(r, t)| Pose { rot_deg: r, t })
}

/// Generated T.CHECK cases: 60 hard cases of every family (`any_case`, all triangle pairs
/// of each case), 50 general triangle pairs under general poses and 100 under near poses.
fn generated_cases(f: Format) -> Vec<(TCheckIn, TCheckOut)> {
    let mut pairs = vec![];
    for case in sample(any_case(), 60) {
        pairs.extend(scene_pairs(f, &case.a, &case.b, &case.pose));
    }
    for (a, b, pose) in sample((tri(), tri(), general_pose()), 50).into_iter().chain(sample((tri(), tri(), near_pose()), 100)) {
        pairs.extend(scene_pairs(f, &[a], &[b], &pose));
    }
    cases(f, Rounding::NearestEven, &pairs)
}

/// The generated cases reach every verdict: hit, miss and unknown directions.
fn verdicts(cases: &[(TCheckIn, TCheckOut)]) -> [usize; 3] {
    let mut n = [0; 3];
    for (_, o) in cases {
        n[if o.hit { 0 } else if o.miss { 1 } else { 2 }] += 1;
    }
    n
}

#[test]
fn tcheck_generated_binary32() {
    let cases = generated_cases(Format::BINARY32);
    let v = verdicts(&cases);
    eprintln!("binary32 verdicts hit/miss/unknown: {v:?}");
    assert!(v.iter().all(|&n| n > 0), "{v:?}");
    assert_none("generated binary32", mismatches(Format::BINARY32, Rounding::NearestEven, cases));
}

#[test]
fn tcheck_generated_e8m15() {
    let cases = generated_cases(Format::REDUCED);
    let v = verdicts(&cases);
    eprintln!("e8m15 verdicts hit/miss/unknown: {v:?}");
    assert!(v.iter().all(|&n| n > 0), "{v:?}");
    assert_none("generated e8m15", mismatches(Format::REDUCED, Rounding::NearestEven, cases));
}

/// The comparison can fail: a T.CHECK rounding toward +inf differs from the nearest-even
/// golden model on the catalogue.
#[test]
fn tcheck_wrong_rounding_is_caught() {
    let (bad, n) = mismatches(Format::BINARY32, Rounding::TowardPositive, catalogue_cases(Format::BINARY32));
    assert!(!bad.is_empty(), "a toward-+inf T.CHECK matched the nearest-even golden model on all {n} cases");
}
