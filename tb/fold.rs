//! The folded T.CHECK: its one description of T.CHECK's operations
//! (`fold::ops::tcheck`) in f64 against the golden `golden::tcheck::{stage1, edges}` bit for
//! bit, and the folded RTL (`rtl::b32::TCheckFold`, built from the modulo schedule at II 16)
//! against the golden model in rust-hdl; a plan broken by hand (an operand multiplexer off
//! by one register) is caught.

use collision_chip::chip::config::ChipConfig;
use collision_chip::fold::ops::{tcheck, Eval, Inputs};
use collision_chip::fold::plan::Plan;
use collision_chip::format::{Format, Rounding};
use collision_chip::golden::certificate::Certificate;
use collision_chip::golden::host::HostSetup;
use collision_chip::golden::memory::TriWord;
use collision_chip::golden::tcheck as golden;
use collision_chip::harness::tri_io::{direction, TCheckIn, TCheckOut};
use collision_chip::pose::Pose;
use collision_chip::query::Chip;
use collision_chip::rtl::b32;
use nalgebra::Point3;
use rust_hdl::prelude::*;

/// One T.CHECK's inputs: the leaf, the frame map, its error words, the scale, the triangle.
type Dir = (TriWord, [[f64; 4]; 3], [f64; 2], f64, TriWord);

/// Every direction of every pair of two n-triangle soups under a pose where they meet, A
/// with a zero-area triangle more (as the exported vectors): (leaf, frame, its error words,
/// scale, triangle).
fn directions(f: Format, n: usize, pose: &Pose) -> Vec<Dir> {
    let mut a = collision_chip::mesh::soup(n, 21).triangles_f64();
    a.push([
        Point3::new(0.1, 0.2, 0.3),
        Point3::new(0.3, 0.4, 0.5),
        Point3::new(0.7, 0.8, 0.9),
    ]);
    let b = collision_chip::mesh::soup(n, 22).triangles_f64();
    let chip = Chip::new(
        &a,
        &b,
        ChipConfig {
            format: f.into(),
            ..Default::default()
        },
    )
    .unwrap();
    let setup: HostSetup = chip.setup(pose);
    let mut out = vec![];
    for ta in chip.a.tris() {
        for tb in chip.b.tris() {
            for (leaf, tri, ab) in [(tb, ta, true), (ta, tb, false)] {
                let (frame, beta, scale) = setup.tri_frame(ab);
                out.push((leaf, *frame, beta, scale, tri));
            }
        }
    }
    out
}

/// `fold::ops::tcheck` in the format's arithmetic gives golden T.CHECK's values and bounds
/// bit for bit, in both formats and roundings, on every direction of two soups under
/// several poses (one description of the operations, checked against the golden model).
#[test]
fn ops_equal_golden_tcheck() {
    let mut n = 0;
    for f in [Format::BINARY32, Format::REDUCED] {
        for r in [Rounding::NearestEven, Rounding::TowardPositive] {
            let cert = Certificate::new(f, r);
            for pose in [
                Pose::new(23.0, -61.0, 11.0, 0.05, -0.08, 0.03),
                Pose::new(-140.0, 33.0, 95.0, 0.2, 0.1, -0.1),
            ] {
                for (leaf, frame, beta, scale, tri) in directions(f, 10, &pose) {
                    let t = golden::edges(
                        f,
                        r,
                        &cert,
                        &golden::stage1(f, r, &leaf, &frame, beta, scale),
                        &tri,
                    );
                    let x = Inputs {
                        m: leaf.m,
                        alpha: [leaf.alpha_m, leaf.alpha_f],
                        frame,
                        beta,
                        scale,
                        v: tri.v,
                    };
                    let o = tcheck(&mut Eval::new(f, r, tri.v_exact), &x);
                    let bits = |v: &[f64]| v.iter().map(|&x| f.to_bits(x)).collect::<Vec<_>>();
                    let want = [
                        t.v.map(|p| p[2]),
                        t.e_z,
                        t.a,
                        t.b,
                        t.rz,
                        t.s,
                        t.a_bound,
                        t.b_bound,
                        t.rz_bound,
                        t.s_bound,
                    ]
                    .concat();
                    assert_eq!(bits(&o.all()), bits(&want), "{f} {r:?} {pose:?}");
                    n += 1;
                }
            }
        }
    }
    eprintln!("{n} directions equal");
    assert!(n > 1000, "{n} directions");
}

/// Drives `uut` with one case every `ii` clocks (valid while the counter is 0) and collects
/// the results, each required `latency` clocks after its case (as the exported testbench
/// checks).
fn run_fold(
    uut: &mut b32::TCheckFold,
    ii: usize,
    latency: usize,
    ins: &[TCheckIn],
) -> Vec<TCheckOut> {
    let mut outs = vec![];
    for cyc in 0..ins.len() * ii + latency + 1 {
        let (valid, x) = match (cyc % ii == 0).then(|| ins.get(cyc / ii)).flatten() {
            Some(x) => (true, *x),
            None => (false, TCheckIn::default()),
        };
        for c in 0..4 {
            uut.m_0[c].next = x.m[c].into();
            uut.m_1[c].next = x.m[4 + c].into();
            uut.m_2[c].next = x.m[8 + c].into();
            uut.f_0[c].next = x.f[c].into();
            uut.f_1[c].next = x.f[4 + c].into();
            uut.f_2[c].next = x.f[8 + c].into();
        }
        (uut.alpha_m.next, uut.alpha_f.next) = (x.alpha_m.into(), x.alpha_f.into());
        (uut.beta_m.next, uut.beta_f.next, uut.scale.next) =
            (x.beta_m.into(), x.beta_f.into(), x.scale.into());
        for k in 0..3 {
            (uut.v_x[k].next, uut.v_y[k].next, uut.v_z[k].next) =
                (x.v[k][0].into(), x.v[k][1].into(), x.v[k][2].into());
        }
        (uut.v_exact.next, uut.tag.next, uut.valid_in.next) =
            (x.v_exact, ((cyc / ii) as u64).into(), valid);
        for high in [false, true] {
            uut.clock.next = Clock { clk: high };
            assert!(simulate(uut, 1000), "logic did not settle");
        }
        if uut.valid_out.val() {
            let k = outs.len();
            assert_eq!(
                (cyc + 1, uut.tag_out.val().to_u64()),
                (k * ii + latency, k as u64),
                "result {k} at the wrong edge or with the wrong tag"
            );
            outs.push(TCheckOut {
                s_x: std::array::from_fn(|e| uut.s_x[e].val().to_u64()),
                s_b: std::array::from_fn(|e| uut.s_b[e].val().to_u64()),
                cross_t: std::array::from_fn(|e| uut.cross_t[e].val()),
                cross_f: std::array::from_fn(|e| uut.cross_f[e].val()),
                hit: uut.hit.val(),
                miss: uut.miss.val(),
            });
        }
    }
    assert_eq!(outs.len(), ins.len(), "valid outputs lost");
    outs
}

/// A few directions with every verdict: surely crossing, surely missing and unknown.
fn few_cases(f: Format, r: Rounding) -> Vec<(TCheckIn, TCheckOut)> {
    let all: Vec<_> = directions(f, 12, &Pose::new(23.0, -61.0, 11.0, 0.05, -0.08, 0.03))
        .iter()
        .map(|(leaf, frame, beta, scale, tri)| direction(f, r, leaf, frame, *beta, *scale, tri))
        .collect();
    let mut pick = vec![];
    for verdict in [
        |o: &TCheckOut| o.hit,
        |o: &TCheckOut| o.miss,
        |o: &TCheckOut| !o.hit && !o.miss,
    ] {
        pick.extend(all.iter().filter(|(_, o)| verdict(o)).take(3).cloned());
    }
    assert_eq!(pick.len(), 9, "the scene has every verdict");
    pick
}

/// The folded unit built from `plan` against the golden outputs of `cases`: the mismatches.
fn mismatches(plan: Plan, cases: Vec<(TCheckIn, TCheckOut)>) -> Vec<String> {
    std::thread::Builder::new()
        .stack_size(1 << 28)
        .spawn(move || {
            let (ii, latency) = (plan.ii, plan.latency);
            let mut uut = b32::tcheck_fold_top(plan, Rounding::NearestEven);
            let ins: Vec<TCheckIn> = cases.iter().map(|c| c.0).collect();
            let outs = run_fold(&mut uut, ii, latency, &ins);
            cases
                .iter()
                .zip(&outs)
                .enumerate()
                .filter(|(_, ((_, w), g))| w != *g)
                .map(|(i, ((_, w), g))| format!("case {i}: golden {w:?}\n  rtl {g:?}"))
                .collect()
        })
        .unwrap()
        .join()
        .unwrap()
}

/// The folded T.CHECK at II 16 equals the golden model on every direction of the scene.
#[test]
fn fold16_equals_golden() {
    let (f, r) = (Format::BINARY32, Rounding::NearestEven);
    let cases: Vec<_> = directions(f, 12, &Pose::new(23.0, -61.0, 11.0, 0.05, -0.08, 0.03))
        .iter()
        .map(|(leaf, frame, beta, scale, tri)| direction(f, r, leaf, frame, *beta, *scale, tri))
        .collect();
    let n = cases.len();
    eprintln!("{n} directions at II 16");
    let bad = mismatches(
        collision_chip::fold::tcheck_plan(
            16,
            collision_chip::fold::plan::Binding::Shared,
            collision_chip::chip::rtl::Depth::Asic,
        )
        .unwrap(),
        cases,
    );
    assert!(
        bad.is_empty(),
        "{} of {n} differ:\n{}",
        bad.len(),
        bad[..bad.len().min(5)].join("\n")
    );
}

/// The same generator at every other II of the fold study equals the golden model on directions
/// of every verdict, and so does each II with its registers bound per reader.
#[test]
fn every_ii_equals_golden() {
    use collision_chip::fold::plan::Binding::{PerReader, Shared};
    let plans = [1, 2, 4, 8, 32]
        .map(|ii| (ii, Shared))
        .into_iter()
        .chain([1, 2, 4, 8, 16, 32].map(|ii| (ii, PerReader)));
    for (ii, binding) in plans {
        let bad = mismatches(
            collision_chip::fold::tcheck_plan(ii, binding, collision_chip::chip::rtl::Depth::Asic)
                .unwrap(),
            few_cases(Format::BINARY32, Rounding::NearestEven),
        );
        assert!(bad.is_empty(), "II {ii} {binding:?}: {}", bad.join("\n"));
    }
}

/// A plan broken by hand is caught: one operand multiplexer input moved to the next
/// register (a stage-1 product reading a neighbouring word).
#[test]
fn fold16_broken_mux_is_caught() {
    let mut plan = collision_chip::fold::tcheck_plan(
        16,
        collision_chip::fold::plan::Binding::Shared,
        collision_chip::chip::rtl::Depth::Asic,
    )
    .unwrap();
    let iss = plan.issues[0][0].iter_mut().flatten().next().unwrap();
    iss.a.reg += 1;
    let bad = mismatches(plan, few_cases(Format::BINARY32, Rounding::NearestEven));
    assert!(
        !bad.is_empty(),
        "an operand off by one register went unnoticed"
    );
}

/// Not a check: writes the folded TRI_UNIT's Verilog at every even II of the fold study for
/// synthesis (the time-against-area rows of docs/explanation/architecture.md, "Folded TRI_UNIT"; only
/// ii = 16 is exported): `cargo test --release --test fold -- --ignored
/// tri_unit_fold_verilog`, then `nice scripts/synth.sh target/fold-area/*.v`.
#[test]
#[ignore]
fn tri_unit_fold_verilog() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fold-area");
    std::fs::create_dir_all(&dir).unwrap();
    for ii in [2, 4, 8, 16, 32] {
        let v = std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn(move || b32::verilog_tri_unit_fold(ii, Rounding::NearestEven).unwrap())
            .unwrap()
            .join()
            .unwrap();
        let p = dir.join(format!("tri_unit_fold{ii}_b32_rne.v"));
        std::fs::write(&p, collision_chip::harness::verilog::dedup_modules(&v)).unwrap();
        eprintln!("wrote {}", p.display());
    }
}
