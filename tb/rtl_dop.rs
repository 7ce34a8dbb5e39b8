//! RTL DOP datapath (`collision_chip::rtl::{b32, e8m15}::{Doptrf, DopUnit6, DopUnit24}`)
//! against the golden model, bit for bit:
//!
//! * the DOPTRF lane against `golden::doptrf::lane` (s and flag) on proptest operands
//!   (zeros, infinities, NaN, subnormals, ties, near-cancellation of u + e), both formats,
//!   both roundings, one lane evaluation per clock, latency 15 checked on `valid_out`;
//! * the DOP unit against `golden::dop_unit::dop_overlap` on all node pairs of two real DOP
//!   trees (host setup loaded through the write port), and on random format values and
//!   random MUX controls; overlap and tag, one pair per clock;
//! * the folded DOP units (`DopUnit6Fold2` .. `DopUnit24Fold24`, a pair every ii clocks) the
//!   same way, the writer holding each pair until `in_ready` (with idle gaps now and then),
//!   the result `dop_fold_latency(ii)` clocks after the pair was taken.
//!
//! Also: a short VCD per block under `target/rtl-vcd/`, Verilog export with
//! (Verilog export and its checks: `harness::units`, scripts/check-rtl.sh.)

use collision_chip::chip::config::{ChipConfig, DopRounding};
use collision_chip::chip::rtl::dop_unit_name;
use collision_chip::dop::DopTree;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::host::HostSetup;
use collision_chip::golden::host::TriSide;
use collision_chip::golden::{dop_unit, doptrf};
use collision_chip::harness::chip_io::{dop_setup_words, dop_unit_setup_words};
use collision_chip::mesh::soup;
use collision_chip::pose::Pose;
use collision_chip::rtl::{b32, e8m10, e8m15};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use rust_hdl::prelude::*;
use std::time::Instant;

mod common;
use common::{operand, run, run_vcd, settle, vcd_outputs, vcd_path, Fmt, Pipelined};

const MODES: [Rounding; 2] = [Rounding::NearestEven, Rounding::TowardPositive];

/// The DOP units are large values (k = 24: about 2 MB, built on the stack): run their
/// tests in a thread with a big stack.
fn big_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap_or_else(|e| std::panic::resume_unwind(e));
}

// ---------------------------------------------------------------------------------------
// The lane.

/// One lane evaluation: d0 d1 d2, c0 c1 c2, c, e as bit patterns, and `round_up` (1:
/// TowardPositive, 0: NearestEven).
type LaneIn = [u64; 9];

/// A lane: inputs `LaneIn`, outputs (s, flag).
trait Lane: Pipelined<In = LaneIn, Out = (u64, bool)> {}
impl<T: Pipelined<In = LaneIn, Out = (u64, bool)>> Lane for T {}

macro_rules! impl_lane {
    ($t:ty) => {
        impl Pipelined for $t {
            type In = LaneIn;
            type Out = (u64, bool);
            const LATENCY: usize = <$t>::LATENCY;
            fn set(&mut self, x: LaneIn, valid: bool) {
                self.d0.next = x[0].into();
                self.d1.next = x[1].into();
                self.d2.next = x[2].into();
                self.c0.next = x[3].into();
                self.c1.next = x[4].into();
                self.c2.next = x[5].into();
                self.c.next = x[6].into();
                self.e.next = x[7].into();
                self.round_up.next = x[8] == 1;
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, (u64, bool)) {
                (
                    self.valid_out.val(),
                    (self.s.val().to_u64(), self.flag.val()),
                )
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    };
}
impl_lane!(b32::Doptrf);
impl_lane!(e8m15::Doptrf);
impl_lane!(e8m10::Doptrf);
impl_lane!(b32::DoptrfFpga);
impl_lane!(e8m15::DoptrfFpga);
impl_lane!(e8m10::DoptrfFpga);

/// A case's rounding (its `round_up`).
fn rounding(x: &LaneIn) -> Rounding {
    MODES[x[8] as usize]
}

fn golden_lane(fmt: Format, x: &LaneIn) -> (u64, bool) {
    let r = rounding(x);
    let v: Vec<f64> = x[..8].iter().map(|&b| fmt.from_bits(b)).collect();
    let s = doptrf::lane(fmt, r, [v[0], v[1], v[2]], [v[3], v[4], v[5]], v[6], v[7]);
    (fmt.to_bits(s), s < 0.0)
}

fn check_lane<L: Lane>(uut: &mut L, fmt: Format, cases: &[LaneIn]) -> Result<(), TestCaseError> {
    let outs = run(uut, cases);
    let w = fmt.width() as usize / 4;
    for (x, &(s, flag)) in cases.iter().zip(&outs) {
        let (gs, gf) = golden_lane(fmt, x);
        prop_assert!(
            s == gs && flag == gf,
            "{} {:?}: in {:0w$x?}: rtl s={:0w$x} flag={}, golden s={:0w$x} flag={}",
            fmt,
            rounding(x),
            x,
            s,
            flag,
            gs,
            gf,
            w = w
        );
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Operand generators (bit patterns of a format with `e` exponent and `f` fraction bits).

/// A lane case in rounding `r`: independent operands, or C >= 0 (as the host sets it) with e
/// chosen near -u (the flag's boundary: s is zero, a few ulps either side, or a tie).
fn lane_case(fmt: Format, r: Rounding) -> BoxedStrategy<LaneIn> {
    let t = Fmt::of(fmt);
    let pos = move |x: u64| x & ((1u64 << (t.e + t.f)) - 1);
    let up = (r == Rounding::TowardPositive) as u64;
    let with_r = move |x: [u64; 8]| std::array::from_fn(|i| if i < 8 { x[i] } else { up });
    prop_oneof![
        1 => prop::array::uniform8(operand(t)).prop_map(with_r),
        2 => (prop::array::uniform8(operand(t)), any::<bool>(), -3i64..4)
            .prop_map(move |(mut x, cpos, delta)| {
                if cpos {
                    x[3] = pos(x[3]);
                    x[4] = pos(x[4]);
                    x[5] = pos(x[5]);
                }
                let v: Vec<f64> = x.iter().map(|&b| fmt.from_bits(b)).collect();
                let u = doptrf::transformed(fmt, r, [v[0], v[1], v[2]], [v[3], v[4], v[5]], v[6]);
                if u.is_finite() {
                    // e = -u, moved by delta ulps (sign-magnitude bit patterns)
                    let nb = fmt.to_bits(-u) as i64;
                    let mag = (nb & ((1i64 << (t.e + t.f)) - 1)) + delta;
                    if mag >= 0 && mag < ((t.ones() as i64) << t.f) {
                        x[7] = (nb as u64 & (1u64 << (t.e + t.f))) | mag as u64;
                    }
                }
                with_r(x)
            }),
    ]
    .boxed()
}

const LANE_CASES: u32 = 4;
const LANE_BATCH: usize = 500;

/// Batches of cases in both roundings, mixed case by case (the rounding travels with its
/// case through the lane's stages).
fn prop_lane<L: Lane>(make: impl Fn() -> L, fmt: Format, name: &str) {
    {
        let both = prop_oneof![lane_case(fmt, MODES[0]), lane_case(fmt, MODES[1])];
        let strat = prop::collection::vec(both, LANE_BATCH);
        let mut runner = TestRunner::new(Config {
            cases: LANE_CASES,
            failure_persistence: None,
            ..Config::default()
        });
        let n = std::cell::Cell::new(0usize);
        let start = Instant::now();
        let res = runner.run(&strat, |cases| {
            let mut uut = make();
            check_lane(&mut uut, fmt, &cases)?;
            n.set(n.get() + cases.len());
            Ok(())
        });
        if let Err(e) = res {
            panic!("{}", e);
        }
        let dt = start.elapsed().as_secs_f64();
        println!(
            "{name} {fmt}: {} lane evaluations ok, {:.0} cycles/s",
            n.get(),
            n.get() as f64 / dt
        );
    }
}

/// Every special operand in every position (`round_up` 0), the other operands moderate.
fn special_cases(fmt: Format) -> Vec<LaneIn> {
    let t = Fmt::of(fmt);
    let one = t.pack(false, t.bias(), 0);
    let base: LaneIn = [
        one,
        t.pack(false, t.bias() + 1, 1),
        t.pack(true, t.bias(), 3),
        one,
        one,
        one,
        t.pack(true, t.bias() + 2, 0),
        one,
        0,
    ];
    let mut cases = vec![];
    for pos in 0..8 {
        for &s in &t.specials() {
            let mut x = base;
            x[pos] = s;
            cases.push(x);
        }
    }
    cases
}

/// [`special_cases`] in both roundings.
fn specials_lane<L: Lane>(make: impl Fn() -> L, fmt: Format) {
    let cases = special_cases(fmt);
    for up in [0, 1] {
        let cases: Vec<LaneIn> = cases
            .iter()
            .map(|x| std::array::from_fn(|i| if i < 8 { x[i] } else { up }))
            .collect();
        let mut uut = make();
        check_lane(&mut uut, fmt, &cases).unwrap_or_else(|e| panic!("{}", e));
        println!(
            "Doptrf {fmt} {:?}: {} special cases ok",
            MODES[up as usize],
            cases.len()
        );
    }
}

#[test]
fn lane_b32_random() {
    prop_lane(b32::doptrf_top, Format::BINARY32, "Doptrf");
}

#[test]
fn lane_e8m15_random() {
    prop_lane(e8m15::doptrf_top, Format::REDUCED, "Doptrf");
}

#[test]
fn lane_e8m10_random() {
    prop_lane(e8m10::doptrf_top, Format::E8M10, "Doptrf");
}

/// The lanes at FPGA depth: the same values, 26 clocks.
#[test]
fn lane_fpga_depth() {
    prop_lane(b32::doptrf_fpga_top, Format::BINARY32, "DoptrfFpga");
    prop_lane(e8m15::doptrf_fpga_top, Format::REDUCED, "DoptrfFpga");
    prop_lane(e8m10::doptrf_fpga_top, Format::E8M10, "DoptrfFpga");
    specials_lane(b32::doptrf_fpga_top, Format::BINARY32);
    specials_lane(e8m15::doptrf_fpga_top, Format::REDUCED);
    specials_lane(e8m10::doptrf_fpga_top, Format::E8M10);
}

#[test]
fn lane_specials() {
    specials_lane(b32::doptrf_top, Format::BINARY32);
    specials_lane(e8m15::doptrf_top, Format::REDUCED);
    specials_lane(e8m10::doptrf_top, Format::E8M10);
}

/// The testbench sees a wrong lane: cases checked in the other rounding than they ran fail.
#[test]
fn lane_testbench_detects_mismatch() {
    use proptest::strategy::ValueTree;
    let mut runner = TestRunner::deterministic();
    let cases = prop::collection::vec(lane_case(Format::BINARY32, Rounding::TowardPositive), 200)
        .new_tree(&mut runner)
        .unwrap()
        .current();
    let outs = run(&mut b32::doptrf_top(), &cases);
    let flipped = cases.iter().map(|x| {
        golden_lane(
            Format::BINARY32,
            &[x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], 1 - x[8]],
        )
    });
    assert!(outs.iter().zip(flipped).any(|(o, g)| *o != g));
}

// ---------------------------------------------------------------------------------------
// The DOP unit.

/// One node pair: B's DOP d, A's DOP e (bit patterns), a tag.
struct Pair {
    d: Vec<u64>,
    e: Vec<u64>,
    tag: u16,
}

// The ports of the stamped DOP units as integers: the trait of harness::sim (also used by benches/rtl_sim.rs).
use collision_chip::harness::sim::DopUnitSim as Unit;

/// A probe called after every half cycle (for VCD dumps).
type Probe<'a, U> = &'a mut dyn FnMut(&U);

fn cycle<U: Unit>(uut: &mut U, probe: &mut Option<Probe<U>>) {
    for high in [false, true] {
        uut.set_clock(high);
        settle(uut);
        if let Some(p) = probe {
            p(uut);
        }
    }
}

/// Idle cycles the writer leaves after taken pair `i`: none for most, a few now and then
/// (a folded unit's counter runs on meanwhile, and the next pair waits for `in_ready`).
fn gap(i: usize) -> usize {
    if i % 7 == 6 {
        i % 5
    } else {
        0
    }
}

/// Loads the setup, streams `pairs`, flushes; returns (overlap, tag) in order (latency
/// checked) and the number of cycles of the pair stream. A writer holds each pair with
/// `valid_in` high until `in_ready` takes it (a folded unit sees the next pair on its ports
/// during the passes of the one taken), then leaves [`gap`] idle cycles.
fn run_unit<U: Unit>(
    uut: &mut U,
    words: &[(u64, u64)],
    pairs: &[Pair],
    mut probe: Option<Probe<U>>,
) -> (Vec<(bool, u16)>, usize) {
    let k = U::K;
    let latency = U::LATENCY;
    let zero = vec![0u64; k];
    for &(a, d) in words {
        uut.set_load(true, a, d);
        uut.set_pair(&zero, &zero, 0, false);
        cycle(uut, &mut probe);
    }
    uut.set_load(false, 0, 0);
    let n = pairs.len();
    let mut outs = Vec::with_capacity(n);
    // the cycles the pairs were taken in; the next pair is driven from cycle `from`
    let (mut taken, mut from) = (vec![], 0);
    let mut cyc = 0;
    while outs.len() < n {
        let p = pairs.get(taken.len()).filter(|_| cyc >= from);
        match p {
            Some(p) => uut.set_pair(&p.d, &p.e, p.tag, true),
            None => uut.set_pair(&zero, &zero, 0, false),
        }
        if p.is_some() && uut.in_ready() {
            from = cyc + 1 + gap(taken.len());
            taken.push(cyc);
        }
        cycle(uut, &mut probe);
        let (v, ov, tag) = uut.out();
        if v {
            let i = outs.len();
            assert!(
                i < taken.len() && cyc + 1 == taken[i] + latency,
                "unit output {i} at the wrong edge ({cyc})"
            );
            outs.push((ov, tag));
        }
        if let Some(&t) = taken.get(outs.len()) {
            assert!(cyc + 1 < t + latency, "unit output {} lost", outs.len());
        }
        cyc += 1;
    }
    (outs, cyc)
}

/// All node pairs of two soup trees under a pose, against `dop_overlap`. Returns
/// (pairs, overlaps, cycles/s).
fn unit_trees<U: Unit>(
    make: impl Fn() -> U,
    fmt: Format,
    r: Rounding,
    n_tris: usize,
    pose: Pose,
) -> (usize, usize, f64) {
    let k = U::K;
    let cfg = ChipConfig {
        k,
        format: fmt.into(),
        dop_rounding: if r == Rounding::TowardPositive {
            DopRounding::Outward
        } else {
            DopRounding::NearestEven
        },
        ..ChipConfig::default()
    };
    let ta = DopTree::build(&soup(n_tris, 1).triangles_f64(), &cfg);
    let tb = DopTree::build(&soup(n_tris, 2).triangles_f64(), &cfg);
    let setup = HostSetup::new(&cfg, &pose, tb.coord_bound(), TriSide::UNUSED);
    let words = dop_unit_setup_words(fmt, r, &setup);
    let mut pairs = vec![];
    let mut want = vec![];
    for na in 0..ta.len() as u32 {
        for nb in 0..tb.len() as u32 {
            let (d, e) = (tb.dop(nb), ta.dop(na));
            pairs.push(Pair {
                d: d.iter().map(|&x| fmt.to_bits(x)).collect(),
                e: e.iter().map(|&x| fmt.to_bits(x)).collect(),
                tag: (pairs.len() as u16).wrapping_mul(40503) ^ 0x5a5a,
            });
            want.push(dop_unit::dop_overlap(fmt, r, &setup, &d, &e));
        }
    }
    let mut uut = make();
    let start = Instant::now();
    let (outs, cycles) = run_unit(&mut uut, &words, &pairs, None);
    let rate = (cycles + words.len()) as f64 / start.elapsed().as_secs_f64();
    for (i, ((ov, tag), p)) in outs.iter().zip(&pairs).enumerate() {
        assert_eq!(*tag, p.tag, "k={k} {fmt} {r:?}: pair {i}: tag");
        assert_eq!(
            *ov, want[i],
            "k={k} {fmt} {r:?}: pair {i}: overlap (rtl {ov}, golden {})",
            want[i]
        );
    }
    let overlaps = want.iter().filter(|&&o| o).count();
    (pairs.len(), overlaps, rate)
}

fn unit_trees_all<U: Unit>(make: impl Fn() -> U + Copy, fmt: Format, n_tris: usize) {
    for r in MODES {
        for pose in [
            Pose::new(10.0, 20.0, 30.0, 0.3, 0.1, 0.0),
            Pose::new(-35.0, 80.0, 5.0, 1.2, -0.4, 0.2),
        ] {
            let (n, ov, rate) = unit_trees(make, fmt, r, n_tris, pose);
            println!("DopUnit k={} interval {} {fmt} {r:?} pose {pose:?}: {n} node pairs ok ({ov} overlap), {rate:.0} cycles/s", U::K, U::INTERVAL);
            assert!(ov > 0 && ov < n, "the pose should give both verdicts");
        }
    }
}

#[test]
fn unit_k24_b32_trees() {
    big_stack(|| {
        unit_trees_all(b32::dop_unit24_top, Format::BINARY32, 8);
    });
}

#[test]
fn unit_k24_e8m15_trees() {
    big_stack(|| {
        unit_trees_all(e8m15::dop_unit24_top, Format::REDUCED, 8);
    });
}

#[test]
fn unit_k6_trees() {
    big_stack(|| {
        unit_trees_all(b32::dop_unit6_top, Format::BINARY32, 16);
        unit_trees_all(e8m15::dop_unit6_top, Format::REDUCED, 16);
    });
}

/// The folded DOP units (k = 6 on 3, 2 and 1 lanes) on all node pairs of the trees, both
/// roundings.
#[test]
fn fold_k6_trees() {
    big_stack(|| {
        unit_trees_all(e8m15::dop_unit6_fold2_top, Format::REDUCED, 16);
        unit_trees_all(e8m15::dop_unit6_fold3_top, Format::REDUCED, 16);
        unit_trees_all(e8m15::dop_unit6_fold6_top, Format::REDUCED, 16);
        unit_trees_all(e8m15::dop_unit6_fold6_fpga_top, Format::REDUCED, 16);
        unit_trees_all(b32::dop_unit6_fold3_top, Format::BINARY32, 8);
    });
}

/// The folded k = 24 units, every interval stamped out, on the trees (binary32) and on random
/// values (e8m15).
#[test]
fn fold_k24() {
    big_stack(|| {
        unit_trees_all(b32::dop_unit24_fold4_top, Format::BINARY32, 4);
        unit_trees_all(b32::dop_unit24_fold8_top, Format::BINARY32, 4);
        unit_trees_all(b32::dop_unit24_fold24_top, Format::BINARY32, 4);
        unit_random(e8m15::dop_unit24_fold6_top, Format::REDUCED, 30, 8);
        unit_random(e8m15::dop_unit24_fold12_top, Format::REDUCED, 30, 9);
    });
}

/// Random format values everywhere (C of either sign, specials) and random MUX controls.
/// A host setup of `k` lanes with C and c from the bit patterns `cm` (3k) and `cv` (k), and
/// correspondences drawn from the same bits (any normal of the k).
fn random_setup(fmt: Format, k: usize, cm: &[u64], cv: &[u64]) -> HostSetup {
    HostSetup {
        j: (0..k)
            .map(|i| [0, 1, 2].map(|l| ((cm[3 * i + l] ^ cv[i] >> l) % k as u64) as u8))
            .collect(),
        cmat: (0..k)
            .map(|i| [0, 1, 2].map(|l| fmt.from_bits(cm[3 * i + l])))
            .collect(),
        cvec: cv.iter().map(|&b| fmt.from_bits(b)).collect(),
        ..HostSetup::new(
            &ChipConfig {
                k,
                format: fmt.into(),
                ..ChipConfig::default()
            },
            &Pose::default(),
            1.0,
            TriSide::UNUSED,
        )
    }
}

fn unit_random<U: Unit>(make: impl Fn() -> U, fmt: Format, n_pairs: usize, seed: u64) {
    use proptest::strategy::ValueTree;
    let k = U::K;
    let t = Fmt::of(fmt);
    let mut runner = TestRunner::new_with_rng(
        Config::default(),
        proptest::test_runner::TestRng::from_seed(
            proptest::test_runner::RngAlgorithm::ChaCha,
            &[seed as u8; 32],
        ),
    );
    let mut draw = |n: usize| {
        prop::collection::vec(operand(t), n)
            .new_tree(&mut runner)
            .unwrap()
            .current()
    };
    let sign = 1u64 << (t.e + t.f);
    for (r, nonneg) in [
        (MODES[0], false),
        (MODES[0], true),
        (MODES[1], false),
        (MODES[1], true),
    ] {
        // C and c of random sign, or non-negative (as the host sets C)
        let clear = |v: Vec<u64>| {
            if nonneg {
                v.into_iter().map(|x| x & !sign).collect()
            } else {
                v
            }
        };
        let setup = random_setup(fmt, k, &clear(draw(3 * k)), &clear(draw(k)));
        let words = dop_setup_words(fmt, r, &setup.j, &setup.cmat, &setup.cvec);
        let mut pairs = vec![];
        let mut want = vec![];
        for p in 0..n_pairs {
            let mut d = draw(k);
            let e = draw(k);
            let mut e = e;
            // non-negative d (and e): pairs that overlap
            if p % 3 != 2 {
                d.iter_mut().for_each(|x| *x &= !sign);
            }
            if p % 3 == 0 {
                e.iter_mut().for_each(|x| *x &= !sign);
            }
            let df: Vec<f64> = d.iter().map(|&b| fmt.from_bits(b)).collect();
            let ef: Vec<f64> = e.iter().map(|&b| fmt.from_bits(b)).collect();
            want.push(dop_unit::dop_overlap(fmt, r, &setup, &df, &ef));
            pairs.push(Pair {
                d,
                e,
                tag: p as u16,
            });
        }
        let mut uut = make();
        let (outs, _) = run_unit(&mut uut, &words, &pairs, None);
        for (i, (ov, tag)) in outs.iter().enumerate() {
            assert_eq!(*tag, i as u16);
            assert_eq!(*ov, want[i], "k={k} {fmt} {r:?} random pair {i}: overlap");
        }
        let ov = want.iter().filter(|&&o| o).count();
        println!(
            "DopUnit k={k} {fmt} {r:?} C, c {}: {n_pairs} random pairs ok ({ov} overlap)",
            if nonneg { ">= 0" } else { "any sign" }
        );
    }
}

#[test]
fn unit_random_values() {
    big_stack(|| {
        unit_random(b32::dop_unit6_top, Format::BINARY32, 300, 1);
        unit_random(e8m15::dop_unit6_top, Format::REDUCED, 300, 2);
        unit_random(b32::dop_unit24_top, Format::BINARY32, 100, 3);
        unit_random(e8m15::dop_unit24_top, Format::REDUCED, 100, 4);
        // the other k of the area study, one format each
        unit_random(e8m15::dop_unit14_top, Format::REDUCED, 40, 5);
        unit_random(b32::dop_unit18_top, Format::BINARY32, 40, 6);
        unit_random(e8m15::dop_unit26_top, Format::REDUCED, 40, 7);
        // folded: a pair every 2, 3, 6 clocks
        unit_random(b32::dop_unit6_fold2_top, Format::BINARY32, 100, 10);
        unit_random(e8m15::dop_unit6_fold3_top, Format::REDUCED, 100, 11);
        unit_random(e8m15::dop_unit6_fold6_top, Format::REDUCED, 100, 12);
    });
}

// ---------------------------------------------------------------------------------------
// VCD and Verilog.

/// rust-hdl names the VCD root `uut`; name it after the block.
fn write_vcd(name: &str, root: &str, buf: Vec<u8>) {
    let text = String::from_utf8(buf).unwrap().replacen(
        "$scope module uut $end",
        &format!("$scope module {root} $end"),
        1,
    );
    let path = vcd_path(name);
    std::fs::write(&path, text).unwrap();
    println!("wrote {}", path.display());
}

/// Short traced runs for GTKWave: a DOPTRF lane and the k = 24 DOP unit, their results the
/// golden model's, and the VCDs' `s` and `overlap` at each `valid_out` those results.
#[test]
fn vcd_traces() {
    big_stack(|| {
        // the lane: a few binary32 cases, rounding up and to nearest by turns
        let f = Format::BINARY32;
        let b = |x: f64| f.to_bits(x);
        let cases: Vec<LaneIn> = vec![
            [
                b(1.0),
                b(2.0),
                b(3.0),
                b(0.5),
                b(0.25),
                b(0.125),
                b(-1.0),
                b(-0.5),
                1,
            ],
            [
                b(1.5),
                b(-2.0),
                b(0.1),
                b(0.7),
                b(0.2),
                b(0.1),
                b(0.3),
                b(-3.0),
                0,
            ],
            [
                b(f64::INFINITY),
                b(1.0),
                b(1.0),
                b(0.0),
                b(1.0),
                b(1.0),
                b(0.0),
                b(0.0),
                1,
            ],
            [
                b(1e-40),
                b(1e-40),
                b(1.0),
                b(1.0),
                b(1.0),
                b(0.0),
                b(0.0),
                b(-2e-40),
                0,
            ],
        ];
        let outs = run_vcd(&mut b32::doptrf_top(), &cases, "doptrf_b32", "doptrf");
        let want: Vec<(u64, bool)> = cases.iter().map(|x| golden_lane(f, x)).collect();
        assert_eq!(outs, want);
        assert_eq!(
            vcd_outputs(&vcd_path("doptrf_b32"), "doptrf", "valid_out", "s"),
            want.iter().map(|w| w.0).collect::<Vec<_>>(),
            "doptrf_b32.vcd: s at valid_out"
        );

        // the DOP unit (k = 24): a pose, a few node pairs of two small trees
        let cfg = ChipConfig::default();
        let ta = DopTree::build(&soup(4, 1).triangles_f64(), &cfg);
        let tb = DopTree::build(&soup(4, 2).triangles_f64(), &cfg);
        let setup = HostSetup::new(
            &cfg,
            &Pose::new(10.0, 20.0, 30.0, 0.3, 0.1, 0.0),
            tb.coord_bound(),
            TriSide::UNUSED,
        );
        let words = dop_unit_setup_words(f, Rounding::TowardPositive, &setup);
        let nodes: Vec<(u32, u32)> = (0..ta.len() as u32)
            .flat_map(|na| (0..tb.len() as u32).map(move |nb| (na, nb)))
            .take(12)
            .collect();
        let pairs: Vec<Pair> = nodes
            .iter()
            .enumerate()
            .map(|(i, &(na, nb))| Pair {
                d: tb.dop(nb).iter().map(|&x| f.to_bits(x)).collect(),
                e: ta.dop(na).iter().map(|&x| f.to_bits(x)).collect(),
                tag: i as u16,
            })
            .collect();
        let want: Vec<bool> = nodes
            .iter()
            .map(|&(na, nb)| {
                dop_unit::dop_overlap(
                    f,
                    Rounding::TowardPositive,
                    &setup,
                    &tb.dop(nb),
                    &ta.dop(na),
                )
            })
            .collect();
        let mut uut = b32::dop_unit24_top();
        let mut buf = vec![];
        {
            let vcd = std::cell::RefCell::new(Some(write_vcd_dump(
                write_vcd_header(&mut buf, &uut),
                &uut,
            )));
            let mut time = 0u64;
            let mut probe = |u: &b32::DopUnit24| {
                let mut v = vcd.borrow_mut();
                let w = v.take().unwrap();
                let mut w = w;
                w.timestamp(time).unwrap();
                *v = Some(write_vcd_change(w, u));
                time += 5;
            };
            let (outs, _) = run_unit(&mut uut, &words, &pairs, Some(&mut probe));
            assert_eq!(outs.iter().map(|o| o.0).collect::<Vec<_>>(), want);
        }
        write_vcd("dop_unit_b32", "dop_unit", buf);
        let shown: Vec<bool> = vcd_outputs(
            &vcd_path("dop_unit_b32"),
            "dop_unit",
            "valid_out",
            "overlap",
        )
        .iter()
        .map(|&v| v == 1)
        .collect();
        assert_eq!(shown, want, "dop_unit_b32.vcd: overlap at valid_out");
    });
}

/// The rust-hdl DOP units run the same golden vector files that Icarus and Verilator run
/// (`vectors/dop_unit_*.hex`, regenerated from the golden model here), with no mismatch.
#[test]
fn dop_units_pass_their_exported_vectors() {
    use collision_chip::harness::{sim, units};
    big_stack(|| {
        let text = |name: &str| {
            units::all()
                .into_iter()
                .find(|u| u.name == name)
                .expect("exported unit")
                .vectors()
        };
        let v6 = sim::parse_dop_vectors(&text("dop_unit_k6_e8m15"), e8m15::WIDTH).unwrap();
        let run6 = sim::run_dop_vectors(&mut e8m15::dop_unit6_top(), &v6).unwrap();
        assert_eq!(run6.mismatches(&v6).count(), 0);
        let v24 = sim::parse_dop_vectors(&text("dop_unit_k24_b32"), b32::WIDTH).unwrap();
        let run24 = sim::run_dop_vectors(&mut b32::dop_unit24_top(), &v24).unwrap();
        assert_eq!(run24.mismatches(&v24).count(), 0);
        assert!(v6.cases.len() > 900 && v24.cases.len() > 200);
        // the folded units: the same pairs, a pair every 2, 3, 6 clocks
        let fold = |ii: usize| {
            sim::parse_dop_vectors(
                &text(&dop_unit_name(6, Format::REDUCED, ii as u32)),
                e8m15::WIDTH,
            )
            .unwrap()
        };
        let (v2, v3, v6f) = (fold(2), fold(3), fold(6));
        assert_eq!((v2.interval, v2.cases.len()), (2, v6.cases.len()));
        assert_eq!(
            sim::run_dop_vectors(&mut e8m15::dop_unit6_fold2_top(), &v2)
                .unwrap()
                .mismatches(&v2)
                .count(),
            0
        );
        assert_eq!(
            sim::run_dop_vectors(&mut e8m15::dop_unit6_fold3_top(), &v3)
                .unwrap()
                .mismatches(&v3)
                .count(),
            0
        );
        assert_eq!(
            sim::run_dop_vectors(&mut e8m15::dop_unit6_fold6_top(), &v6f)
                .unwrap()
                .mismatches(&v6f)
                .count(),
            0
        );
    });
}

/// Not a check: writes the folded k = 24 DOP units' Verilog (binary32; none is
/// exported) for synthesis (docs/explanation/architecture.md, "Folded DOP unit"): `cargo test --release
/// --test rtl_dop -- --ignored dop_unit_fold_verilog`, then `nice scripts/synth.sh --target
/// ecp5 target/fold-area/dop_unit_fold*_k24_b32.v`.
#[test]
#[ignore]
fn dop_unit_fold_verilog() {
    use collision_chip::harness::{units, verilog::dedup_modules};
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fold-area");
    std::fs::create_dir_all(&dir).unwrap();
    for ii in [4, 8, 12, 24] {
        let f = Format::BINARY32;
        let v = std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn(move || units::dop_unit_fold_verilog(ii, 24, f).unwrap())
            .unwrap()
            .join()
            .unwrap();
        let p = dir.join(format!("{}.v", dop_unit_name(24, f, ii as u32)));
        std::fs::write(&p, dedup_modules(&v)).unwrap();
        eprintln!("wrote {}", p.display());
    }
}

// ---------------------------------------------------------------------------------------
// WSCG'03's DOP Unit: the compare bank.

/// A DOP's bundles of `(d', e)` pairs ([`compare_bundles`]) for the left and the right sibling.
///
/// [`compare_bundles`]: collision_chip::golden::dop_unit::compare_bundles
type Bundles = [Vec<Vec<(f64, f64)>>; 2];

/// Drives WSCG'03's compare bank (`b32::CompareBank`) with the bundles of each
/// `(left, right)` list of `(d', e)` pairs (masked lanes -1, which would flag), an idle
/// clock after every third DOP; returns the verdicts after each DOP's last bundle.
fn run_compare_bank(uut: &mut b32::CompareBank, dops: &[Bundles]) -> Vec<[bool; 2]> {
    let fmt = Format::BINARY32;
    let word = |xs: &[(f64, f64)], side: usize| {
        let mut w = Bits::<256>::default();
        // lanes past the DOP's end: -1 against -1, which would flag
        for t in 0..8 {
            let x = xs
                .get(t)
                .map_or(fmt.to_bits(-1.0), |p| fmt.to_bits([p.0, p.1][side]));
            for i in 0..32 {
                w = w.replace_bit(32 * t + i, x >> i & 1 == 1);
            }
        }
        w
    };
    let mut beats = vec![];
    for (n, [l, r]) in dops.iter().enumerate() {
        for (b, (bl, br)) in l.iter().zip(r).enumerate() {
            beats.push(Some((
                b == 0,
                b + 1 == l.len(),
                bl.len(),
                word(bl, 1),
                word(bl, 0),
                word(br, 0),
            )));
        }
        if n % 3 == 2 {
            beats.push(None);
        }
    }
    let mut lasts = std::collections::VecDeque::new();
    let mut out = vec![];
    for cyc in 0..beats.len() + b32::CompareBank::LATENCY + 1 {
        let beat = beats.get(cyc).copied().flatten();
        uut.valid_in.next = beat.is_some();
        if let Some((first, last, n, e, dl, dr)) = beat {
            uut.first.next = first;
            uut.lanes.next = ((1u64 << n) - 1).into();
            (uut.e.next, uut.dl.next, uut.dr.next) = (e, dl, dr);
            lasts.push_back(last);
        }
        for high in [false, true] {
            uut.clock.next = Clock { clk: high };
            settle(uut);
        }
        if uut.valid_out.val() && lasts.pop_front().unwrap() {
            out.push([uut.overlap_l.val(), uut.overlap_r.val()]);
        }
    }
    out
}

/// WSCG'03's compare bank gives the DOP unit's verdict: for random host setups (C, c >= 0,
/// random correspondences) in both roundings, k = 6, 14, 24 and 26, each sibling's d' is
/// the golden lanes' `transformed`, held in the d' memory's order (`compare_bundles`), and
/// the bank's verdicts after the last bundle are `dop_overlap`'s for the left and the right
/// sibling against A's DOP. And the test sees a bank that drops the last bundle's flags.
/// (By hand: a bank that ignored `lanes` failed it.)
#[test]
fn compare_bank_b32_dop_overlap() {
    use collision_chip::golden::dop_unit::compare_bundles;
    use proptest::strategy::ValueTree;
    let fmt = Format::BINARY32;
    let t = Fmt::of(fmt);
    let sign = 1u64 << (t.e + t.f);
    let mut runner = TestRunner::deterministic();
    let mut draw = |n: usize| {
        prop::collection::vec(operand(t), n)
            .new_tree(&mut runner)
            .unwrap()
            .current()
    };
    let (mut total, mut overlaps, mut noticed) = (0, 0, false);
    for (k, r) in [6, 14, 24, 26]
        .into_iter()
        .flat_map(|k| MODES.map(|r| (k, r)))
    {
        let nonneg = |v: Vec<u64>| -> Vec<u64> { v.into_iter().map(|x| x & !sign).collect() };
        let setup = random_setup(fmt, k, &nonneg(draw(3 * k)), &nonneg(draw(k)));
        let mut dops = vec![];
        let mut want = vec![];
        for p in 0..60 {
            // non-negative distances (DOPs that overlap) in two of three pairs
            let mut dop = |nonneg: bool| -> Vec<f64> {
                draw(k)
                    .into_iter()
                    .map(|x| fmt.from_bits(if nonneg { x & !sign } else { x }))
                    .collect()
            };
            let (dl, dr, e) = (dop(p % 3 != 2), dop(p % 3 == 0), dop(p % 3 != 2));
            let dp = |d: &[f64]| -> Vec<f64> {
                (0..k)
                    .map(|i| dop_unit::dprime(fmt, r, &setup, d, i))
                    .collect()
            };
            dops.push([
                compare_bundles(&dp(&dl), &e, 8),
                compare_bundles(&dp(&dr), &e, 8),
            ]);
            want.push([&dl, &dr].map(|d| dop_unit::dop_overlap(fmt, r, &setup, d, &e)));
        }
        let mut uut = b32::compare_bank_top();
        let got = run_compare_bank(&mut uut, &dops);
        assert_eq!(got, want, "k = {k} {r:?}");
        // a bank that missed the last bundle (the verdicts after the one before it)
        let short: Vec<_> = dops
            .iter()
            .filter(|[l, _]| l.len() > 1)
            .map(|[l, r]| [l[..l.len() - 1].to_vec(), r[..r.len() - 1].to_vec()])
            .collect();
        if !short.is_empty() {
            let mut uut = b32::compare_bank_top();
            let cut = run_compare_bank(&mut uut, &short);
            let full: Vec<_> = dops
                .iter()
                .zip(&want)
                .filter(|([l, _], _)| l.len() > 1)
                .map(|(_, w)| *w)
                .collect();
            noticed |= cut != full;
        }
        total += want.len();
        overlaps += want.iter().flatten().filter(|&&o| o).count();
    }
    assert!(noticed, "a bank without the last bundle went unnoticed");
    println!(
        "CompareBank b32: {total} DOPs against both siblings ok ({overlaps} of {} overlap)",
        2 * total
    );
}

// ---------------------------------------------------------------------------------------
// WSCG'03's DOP Unit: the DOTADD unit.

macro_rules! impl_dotadd {
    ($($m:ident),*) => {$(
        impl Pipelined for $m::Dotadd {
            type In = LaneIn;
            type Out = u64;
            const LATENCY: usize = $m::Dotadd::LATENCY;
            fn set(&mut self, x: LaneIn, valid: bool) {
                self.d0.next = x[0].into();
                self.d1.next = x[1].into();
                self.d2.next = x[2].into();
                self.c0.next = x[3].into();
                self.c1.next = x[4].into();
                self.c2.next = x[5].into();
                self.c.next = x[6].into();
                self.round_up.next = x[8] == 1;
                self.valid_in.next = valid;
            }
            fn out(&self) -> (bool, u64) {
                (self.valid_out.val(), self.u.val().to_u64())
            }
            fn clock(&mut self, high: bool) {
                self.clock.next = Clock { clk: high };
            }
        }
    )*};
}
impl_dotadd!(b32, e8m15, e8m10);

/// The DOTADD unit (`Dotadd`) against the golden `transformed`, bit for bit, in every format:
/// the lane's random cases in both roundings (`lane_case`: its `e` unused) and its special
/// cases (`special_cases`) in both, one per clock, latency checked on `valid_out`. And the test
/// sees a unit that would round every operation to nearest even.
#[test]
fn dotadd_all_formats() {
    fn check<U: Pipelined<In = LaneIn, Out = u64>>(mut uut: U, fmt: Format) {
        use proptest::strategy::ValueTree;
        let both = prop_oneof![lane_case(fmt, MODES[0]), lane_case(fmt, MODES[1])];
        let mut cases = prop::collection::vec(both, 2000)
            .new_tree(&mut TestRunner::deterministic())
            .unwrap()
            .current();
        for up in [0, 1] {
            cases.extend(special_cases(fmt).into_iter().map(|mut x| {
                x[8] = up;
                x
            }));
        }
        let golden = |x: &LaneIn, r: Rounding| {
            let v: Vec<f64> = x[..7].iter().map(|&b| fmt.from_bits(b)).collect();
            fmt.to_bits(doptrf::transformed(
                fmt,
                r,
                [v[0], v[1], v[2]],
                [v[3], v[4], v[5]],
                v[6],
            ))
        };
        let got = run(&mut uut, &cases);
        let bad: Vec<_> = cases
            .iter()
            .zip(&got)
            .filter(|&(x, &u)| u != golden(x, rounding(x)))
            .collect();
        assert!(
            bad.is_empty(),
            "{fmt}: {} mismatches, first {:x?}",
            bad.len(),
            &bad[..bad.len().min(3)]
        );
        let nearest = cases
            .iter()
            .zip(&got)
            .any(|(x, &u)| u != golden(x, Rounding::NearestEven));
        assert!(
            nearest,
            "{fmt}: a unit rounding to nearest even only went unnoticed"
        );
        println!("Dotadd {fmt}: {} transforms ok", cases.len());
    }
    check(b32::dotadd_top(), Format::BINARY32);
    check(e8m15::dotadd_top(), Format::REDUCED);
    check(e8m10::dotadd_top(), Format::E8M10);
}

// ---------------------------------------------------------------------------------------
// WSCG'03's DOP Unit: the d' memory.

/// Writes the d' of `dops` (left, right; one lane per clock in lane order, as the DOTADD
/// units make them) into sets 0, 1, 0, ... of the d' memory (`b32::DprimeMemory`) of `k`
/// directions; after each DOP's writes reads back its set's entries, then the other set's;
/// returns them per DOP (left and right, eight slots of bit patterns each).
fn dprime_run(k: usize, dops: &[[Vec<f64>; 2]]) -> Vec<Vec<[[u64; 8]; 2]>> {
    let fmt = Format::BINARY32;
    let mut uut = b32::dprime_memory_top(k);
    let entries = k.div_ceil(8);
    let clock = |uut: &mut b32::DprimeMemory| {
        for high in [false, true] {
            uut.clock.next = Clock { clk: high };
            settle(uut);
        }
    };
    let slots = |w: Bits<256>| -> [u64; 8] {
        std::array::from_fn(|t| (0..32).fold(0, |a, i| a | (w.get_bit(32 * t + i) as u64) << i))
    };
    let mut out = vec![];
    for (n, [l, r]) in dops.iter().enumerate() {
        let set = (n % 2) as u64;
        for i in 0..k {
            uut.wr_valid.next = true;
            uut.wr_set.next = set.into();
            uut.wr_lane.next = (i as u64).into();
            uut.wr_l.next = fmt.to_bits(l[i]).into();
            uut.wr_r.next = fmt.to_bits(r[i]).into();
            clock(&mut uut);
        }
        uut.wr_valid.next = false;
        let mut read = vec![];
        // an entry is on the outputs right after the edge that took its address; this
        // set's entries, then the other set's
        for (sel, e) in [set, 1 - set]
            .into_iter()
            .flat_map(|s| (0..entries).map(move |e| (s, e)))
        {
            uut.rd_set.next = sel.into();
            uut.rd_entry.next = (e as u64).into();
            clock(&mut uut);
            read.push([slots(uut.dl.val()), slots(uut.dr.val())]);
        }
        out.push(read);
    }
    out
}

/// The d' memory holds each sibling's d' in the order of A's distances: its entries, read
/// back after the DOTADD units' lane order, are `compare_bundles`' d' (k = 6, 14, 24, 26;
/// four DOPs each, in alternate sets, so that a write into one set must leave the other).
/// And the test sees a memory that stored lane i at position i.
#[test]
fn dprime_memory_b32_order() {
    use collision_chip::golden::dop_unit::compare_bundles;
    use proptest::strategy::ValueTree;
    let fmt = Format::BINARY32;
    let t = Fmt::of(fmt);
    let mut runner = TestRunner::deterministic();
    for k in [6, 14, 24, 26] {
        let mut draw = || -> Vec<f64> {
            prop::collection::vec(operand(t), k)
                .new_tree(&mut runner)
                .unwrap()
                .current()
                .into_iter()
                .map(|b| fmt.from_bits(b))
                .collect()
        };
        let dops: Vec<[Vec<f64>; 2]> = (0..4).map(|_| [draw(), draw()]).collect();
        let got = dprime_run(k, &dops);
        let e = vec![0.0; k];
        let entries = |dp: &[f64]| -> Vec<Vec<u64>> {
            compare_bundles(dp, &e, 8)
                .iter()
                .map(|b| b.iter().map(|&(d, _)| fmt.to_bits(d)).collect())
                .collect()
        };
        let m = k.div_ceil(8);
        for (n, (dop, read)) in dops.iter().zip(&got).enumerate() {
            for s in 0..2 {
                let want = entries(&dop[s]);
                let have = |read: &[[[u64; 8]; 2]]| -> Vec<Vec<u64>> {
                    read.iter()
                        .zip(&want)
                        .map(|(r, w)| r[s][..w.len()].to_vec())
                        .collect()
                };
                // the other set still holds the DOP before
                if n > 0 {
                    let before = entries(&dops[n - 1][s]);
                    let other: Vec<Vec<u64>> = read[m..]
                        .iter()
                        .zip(&before)
                        .map(|(r, w)| r[s][..w.len()].to_vec())
                        .collect();
                    assert_eq!(other, before, "k = {k}, DOP {n}, side {s}: the other set");
                }
                let have = have(&read[..m]);
                assert_eq!(have, want, "k = {k}, DOP {n}, side {s}");
                let flat: Vec<u64> = dop[s].iter().map(|&d| fmt.to_bits(d)).collect();
                let in_order: Vec<Vec<u64>> = flat.chunks(8).map(|c| c.to_vec()).collect();
                assert_ne!(have, in_order, "k = {k}: lane i at position i would pass");
            }
        }
    }
    println!("DprimeMemory b32: d' of k = 6, 14, 24, 26 in the compare units' order");
}

// ---------------------------------------------------------------------------------------
// WSCG'03's DOP Unit: the whole unit, against its clocked model and the golden verdicts.

/// One clock of WSCG'03's DOP Unit.
fn clock_wscg03<const K: usize>(uut: &mut b32::Wscg03DopUnit<K>) {
    for high in [false, true] {
        uut.clock.next = Clock { clk: high };
        settle(uut);
    }
}

/// Runs `traffic` on the RTL: its MMM loaded through the setup port, then every clock's
/// inputs; checks every output after every clock against the clocked model's. Returns the
/// verdicts after each aligned DOP's last bundle.
fn run_wscg03_dop_unit<const K: usize>(
    traffic: &collision_chip::harness::wscg03_io::DopTraffic,
) -> Vec<[bool; 2]> {
    use collision_chip::harness::wscg03_io::{outputs, set_inputs, FORMAT};
    let mut uut = b32::wscg03_dop_unit_top::<K>();
    for (a, d) in dop_unit_setup_words(FORMAT, traffic.rounding, &traffic.setup) {
        set_inputs(&mut uut, &Default::default());
        uut.load_en.next = true;
        uut.load_addr.next = a.into();
        uut.load_data.next = d.into();
        clock_wscg03(&mut uut);
    }
    let mut verdicts = vec![];
    for (c, (inp, want)) in traffic.clocks.iter().zip(&traffic.outs).enumerate() {
        set_inputs(&mut uut, inp);
        clock_wscg03(&mut uut);
        let got = outputs(&uut);
        assert_eq!(got, *want, "k = {K}: clock {c} after the MMM");
        if got.flags_valid {
            verdicts.push(got.overlap);
        }
    }
    traffic
        .dops
        .iter()
        .filter_map(|d| verdicts.get(d.last_bundle).copied())
        .collect()
}

/// WSCG'03's DOP Unit (`b32::Wscg03DopUnit`) equals its clocked model
/// (`cycle::wscg03::dop_unit::ClockedDopUnit`) on every port every clock, under traffic as
/// the Stack Engine makes it (`harness::wscg03_io::dop_unit_traffic`: loads into one set while
/// the other set's d' meet aligned DOPs, a tumbled leaf alone now and then, idle clocks) for
/// k = 6, 14, 24 and 26 in both roundings; after each aligned DOP's last bundle the verdicts
/// are `dop_overlap`'s for the left and the right sibling. And a set's d' are in the memory
/// `wscg03_transform_clocks(k)` clocks after its last bundle.
#[test]
fn wscg03_dop_unit_b32_lockstep() {
    use collision_chip::chip::rtl::wscg03_transform_clocks;
    use collision_chip::cycle::wscg03::dop_unit::{ClockIn, TumbledBundle};
    use collision_chip::harness::wscg03_io::{dop_unit_traffic, FORMAT};
    fn check<const K: usize>(seed: u64) -> (usize, usize) {
        let (mut dops, mut overlaps) = (0, 0);
        for r in MODES {
            let traffic = dop_unit_traffic(K, r, seed, 1500);
            let got = run_wscg03_dop_unit::<K>(&traffic);
            let want: Vec<[bool; 2]> = traffic
                .dops
                .iter()
                .take(got.len())
                .map(|d| {
                    d.d.clone()
                        .map(|side| dop_unit::dop_overlap(FORMAT, r, &traffic.setup, &side, &d.e))
                })
                .collect();
            assert_eq!(got, want, "k = {K} {r:?}: verdicts");
            assert!(
                got.len() + 3 >= traffic.dops.len() && got.len() > 40,
                "k = {K}: {} of {} aligned DOPs",
                got.len(),
                traffic.dops.len()
            );
            dops += got.len();
            overlaps += got.iter().flatten().filter(|&&o| o).count();
        }
        // one pair from reset: busy from its first bundle to its transform's last write
        let mut traffic = dop_unit_traffic(K, MODES[0], seed, 0);
        let m = K.div_ceil(8);
        let mut load: Vec<ClockIn> = (0..2 * m)
            .map(|b| ClockIn {
                t: Some(TumbledBundle {
                    set: 0,
                    side: b / m,
                    entry: b % m,
                    last: b + 1 == 2 * m,
                    data: [1.0; 8],
                }),
                a: None,
            })
            .collect();
        load.resize(2 * m + wscg03_transform_clocks(K) + 2, ClockIn::default());
        let mut model = collision_chip::cycle::wscg03::dop_unit::ClockedDopUnit::new(
            FORMAT,
            MODES[0],
            &traffic.setup,
        );
        traffic.outs = load.iter().map(|c| model.step(c)).collect();
        traffic.clocks = load;
        run_wscg03_dop_unit::<K>(&traffic);
        // outs[c] is the state in clock c + 1; the last bundle is in clock 2 m - 1
        let free = traffic.outs.iter().rposition(|o| o.busy[0]).unwrap() + 2;
        assert_eq!(free - (2 * m - 1), wscg03_transform_clocks(K), "k = {K}");
        (dops, overlaps)
    }
    big_stack(|| {
        let runs = [
            check::<6>(1),
            check::<14>(2),
            check::<24>(3),
            check::<26>(4),
        ];
        let dops: usize = runs.iter().map(|r| r.0).sum();
        let overlaps: usize = runs.iter().map(|r| r.1).sum();
        assert!(overlaps > dops / 4 && overlaps < 2 * dops - dops / 4);
        println!("Wscg03DopUnit b32: {dops} aligned DOPs against both siblings, every clock as the model ({overlaps} of {} overlap)", 2 * dops);
    });
}
