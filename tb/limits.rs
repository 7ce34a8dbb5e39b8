//! The memory limit is kept. `cchip run` refuses objects whose setup would
//! not fit before it builds anything, and its estimate is an upper bound of the peak it
//! reaches (measured as the child process's maximum resident set). And bad input, as a new
//! user gives it, gets a clear error (exit 2) before work, never a panic or an abort. And the
//! software's time a scene reports is warm in a fresh process, its first pose's too.

use std::process::Command;

/// Two 200k-triangle objects on the papers' chip, one overlapping pose, every output that
/// builds state per triangle (cycles, accuracy).
fn scene(dir: &std::path::Path) -> std::path::PathBuf {
    let path = dir.join("limits.toml");
    let text = "[objects]\na = \"sphere:200000\"\nb = \"torus:200000\"\nunit_cube = true\n[chip]\npreset = \"date05\"\n[[pose]]\nrot_deg = [10, 20, 30]\nt = [1.0, 0, 0]\n[outputs]\naccuracy = true\ncycles = true\n";
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(&path, text).unwrap();
    path
}

fn tmp() -> std::path::PathBuf {
    std::env::temp_dir().join(format!("cchip-limits-{}", std::process::id()))
}

#[test]
fn too_little_memory_is_refused_before_work() {
    let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args(["run"])
        .arg(scene(&tmp()))
        .env("CCHIP_MAX_MEMORY_MB", "100")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("need about")
            && err.contains("100 MB available")
            && err.contains("CCHIP_MAX_MEMORY_MB"),
        "{err}"
    );
}

/// A value of an environment variable that is not what it takes is an error naming it, not
/// a limit quietly switched off (or wrapped to 0 MB).
#[test]
fn environment_values_are_checked() {
    let query = |var: &str, value: &str| {
        let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
            .args(["query", "sphere:12", "sphere:12", "--pose", "0,0,0,0,0,0"])
            .env(var, value)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    for v in ["2MB", "2.0", "-5", "abc", "", "17592186044416"] {
        let (rc, err) = query("CCHIP_MAX_MEMORY_MB", v);
        assert_eq!(rc, Some(2), "{v}: {err}");
        assert!(
            err.contains(&format!("CCHIP_MAX_MEMORY_MB={v:?}"))
                && err.contains("whole number of MB"),
            "{v}: {err}"
        );
    }
    assert_eq!(query("CCHIP_MAX_MEMORY_MB", " 64 ").0, Some(0));
    let (rc, err) = query("CCHIP_MAX_MEMORY_MB", "0");
    assert!(rc == Some(2) && err.contains("0 MB available"), "{err}");
    let (rc, err) = query("CCHIP_CHECK_FAST", "true");
    assert!(
        rc == Some(2) && err.contains("CCHIP_CHECK_FAST=\"true\": give 1 (on) or 0 (off)"),
        "{err}"
    );
    assert_eq!(query("CCHIP_CHECK_FAST", "0").0, Some(0));
}

#[cfg(target_os = "linux")]
#[test]
fn the_estimate_bounds_the_peak() {
    let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args(["run"])
        .arg(scene(&tmp()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: `ru` is a valid rusage for getrusage to write.
    assert_eq!(
        unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut ru) },
        0
    );
    let peak = ru.ru_maxrss as u64 * 1024; // kB on Linux
    let estimate = collision_chip::query::memory_estimate(200_000, 200_000, 24, false);
    // the process's own baseline (code, the vendored meshes) is not per triangle
    let baseline = 64 << 20;
    assert!(
        peak <= estimate + baseline,
        "peak {} MB > estimate {} MB + 64 MB",
        peak >> 20,
        estimate >> 20
    );
}

fn cchip(args: &[&str], dir: &std::path::Path) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Inputs that panicked, aborted or ran to an unlabelled answer: each an error naming what
/// to change.
#[test]
fn bad_input_is_refused_with_exit_2() {
    let dir = tmp().join("bad");
    std::fs::create_dir_all(&dir).unwrap();
    for format in ["e2m1", "binary32/e2m3"] {
        let (rc, err) = cchip(
            &[
                "query",
                "sphere:12",
                "sphere:12",
                "--pose",
                "0,0,0,0.5,0,0",
                "--k",
                "6",
                "--format",
                format,
            ],
            &dir,
        );
        assert!(
            rc == Some(2) && err.contains("at least 3 exponent bits"),
            "{format}: {rc:?} {err}"
        );
    }
    let shard = Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args([
            "accuracy",
            "--meshes",
            "sphere:12",
            "--k",
            "6",
            "--formats",
            "e8m15",
            "--distances",
            "1",
            "--orientations",
            "1",
            "--presets",
            "rtl",
            "--shard",
            "1/18446744073709551615",
        ])
        .output()
        .unwrap();
    assert!(
        shard.status.success(),
        "{}",
        String::from_utf8_lossy(&shard.stderr)
    );
    std::fs::write(dir.join("f.json"), &shard.stdout).unwrap();
    let (rc, err) = cchip(&["accuracy", "--merge", "f.json"], &dir);
    assert!(
        rc == Some(2) && err.contains("shard 2/18446744073709551615 is missing"),
        "{rc:?} {err}"
    );
    let scene = "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[[pose]]\nrot_deg = [0, 0, 0]\nt = [0, 0, 0]\n[outputs]\ncycles = true\n";
    for (name, extra, want) in [
        (
            "clock.toml",
            "[timing]\nclock_mhz = 1e-307\n",
            "clock_mhz must be from 0.001 to 100000 MHz",
        ),
        (
            "e8m24.toml",
            "[chip]\nformat = \"e8m24\"\n",
            "measures none of this configuration's DOP datapath's units",
        ),
        (
            "ddr.toml",
            "[chip]\npreset = \"date05\"\n[memory]\nmodel = \"ddr\"\nlatency = 3\n",
            "ddr.toml:13: [memory] latency belongs to the ideal memory",
        ),
    ] {
        std::fs::write(dir.join(name), format!("{scene}{extra}")).unwrap();
        for flag in ["--json", "--explain", "--dot"] {
            let (rc, err) = cchip(&["run", name, flag], &dir);
            assert!(
                rc == Some(2) && err.contains(want),
                "{name} {flag}: {rc:?} {err}"
            );
        }
    }
    // an output directory that cannot be one is refused before the run
    std::fs::write(dir.join("afile"), "").unwrap();
    let t0 = std::time::Instant::now();
    let (rc, err) = cchip(&["figures", "--out", "afile"], &dir);
    assert!(
        rc == Some(2)
            && err.contains("afile: cannot make the output directory")
            && t0.elapsed().as_secs() < 5,
        "{rc:?} {err}"
    );
    let (rc, err) = cchip(
        &["accuracy", "--meshes", "sphere:12", "--plot", "afile"],
        &dir,
    );
    assert!(
        rc == Some(2) && err.contains("afile: cannot make the output directory"),
        "{rc:?} {err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The help speaks to users: no Rust paths or rustdoc links.
#[test]
fn help_has_no_rustdoc() {
    for sub in [
        &[][..],
        &["query"],
        &["run"],
        &["accuracy"],
        &["figures"],
        &["export-verilog"],
        &["vectors"],
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
            .args(sub)
            .arg("--help")
            .output()
            .unwrap();
        let help = String::from_utf8_lossy(&out.stdout);
        for bad in ["[`", "`]", "::"] {
            assert!(!help.contains(bad), "{sub:?} --help has {bad}:\n{help}");
        }
    }
}

/// The same pose six times in a fresh `cchip` (as a user runs it: the process's first query
/// pays for its cold caches and first allocations) reports the same software time within
/// noise, the first row too: timed once, the first took 15 to 25 times the others (570 and
/// 354 us against 15-28 us for two 12-triangle spheres).
#[test]
fn the_software_time_is_warm() {
    let dir = tmp().join("warm");
    std::fs::create_dir_all(&dir).unwrap();
    let poses = "[[pose]]\nrot_deg = [10, 20, 30]\nt = [0.8, 0.1, 0]\n".repeat(6);
    std::fs::write(
        dir.join("six.toml"),
        format!(
            "[objects]\na = \"sphere:12\"\nb = \"sphere:12\"\n[outputs]\ncycles = true\n{poses}"
        ),
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args(["run", "six.toml", "--json"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let us: Vec<f64> = json
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["cycles"]["software_us"].as_f64().unwrap())
        .collect();
    let mut rest = us[1..].to_vec();
    rest.sort_by(f64::total_cmp);
    assert!(
        us.len() == 6 && us[0] < 3.0 * rest[2],
        "the first pose's software time is not warm: {us:?}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
