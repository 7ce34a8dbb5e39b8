//! Inputs nobody thought of: the mesh loaders (OBJ, STL, PLY), scene files and
//! poses, fed mutations of the vendored and bad inputs. Each must come back as a value or a
//! clear error: never a panic, a hang or an allocation the input's size does not justify.
//!
//! The mutations here are proptest's, blind but run by every `cargo test`: bytes flipped,
//! ranges cut, duplicated or truncated, and tokens that have broken parsers before (huge
//! counts and indices, NaN, overflowing exponents, NUL bytes, headers inside bodies) spliced
//! in at random places. Every failure proptest
//! finds is shrunk to a minimal input; add it to `vectors/bad-meshes/` (and the mesh error
//! tests) when it is fixed. `FUZZ_CASES=N` runs N cases per target (default: CI's bounded
//! run).
//!
//! The coverage-guided fuzzer (cargo-afl on stable Rust, `scripts/fuzz.sh`) runs outside
//! `cargo test`; its corpus and the crashes it found are replayed here.

#[path = "../fuzz/src/lib.rs"]
mod afl_targets;

use collision_chip::mesh;
use collision_chip::pose::Pose;
use collision_chip::scene::Scene;
use proptest::prelude::*;
use std::path::{Path, PathBuf};

const TOKENS: &[&str] = &[
    "-1",
    "0",
    "1",
    "4294967295",
    "4294967296",
    "18446744073709551616",
    "99999999999999999999999",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "1e309",
    "-1e-320",
    "1e-400",
    "0x10",
    "\n",
    " ",
    "\t",
    "\r\n",
    "/",
    "//",
    "\0",
    "\u{ff}",
    "#",
    "v 1 2 3\n",
    "f 1 2 3\n",
    "f -1 -2 -3\n",
    "vt 0 0\n",
    "f 1/1/1 2/2/2 3/3/3\n",
    "solid x\n",
    "facet normal 0 0 1\n",
    "outer loop\n",
    "vertex 1 2 3\n",
    "endloop\n",
    "endfacet\n",
    "endsolid\n",
    "ply\n",
    "format ascii 1.0\n",
    "format binary_little_endian 1.0\n",
    "format binary_big_endian 1.0\n",
    "element vertex 1000000000\n",
    "element face 4294967295\n",
    "property float x\n",
    "property list uchar int vertex_indices\n",
    "property list uint uint vertex_indices\n",
    "end_header\n",
    "= ",
    "[",
    "]",
    "{",
    "}",
    "\"",
    "'",
    "[[pose]]\n",
    "[sweep]\n",
    "orientations = 1000000\n",
    "distances = []\n",
    "k = 0\n",
    "latency = 4294967295\n",
    "queue_entries = 0\n",
    "tri_cache = 3\n",
];

/// One edit of a byte string.
#[derive(Clone, Debug)]
enum Edit {
    Flip(usize, u8),
    Cut(usize, usize),
    Dup(usize, usize),
    Token(usize, usize),
    Truncate(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(a, b)| Edit::Flip(a, b)),
        (any::<usize>(), 1usize..64).prop_map(|(a, n)| Edit::Cut(a, n)),
        (any::<usize>(), 1usize..64).prop_map(|(a, n)| Edit::Dup(a, n)),
        (any::<usize>(), 0..TOKENS.len()).prop_map(|(a, t)| Edit::Token(a, t)),
        any::<usize>().prop_map(Edit::Truncate),
    ]
}

fn apply(mut b: Vec<u8>, edits: &[Edit]) -> Vec<u8> {
    for e in edits {
        let at = |a: usize, len: usize| if len == 0 { 0 } else { a % (len + 1) };
        match *e {
            Edit::Flip(a, v) if !b.is_empty() => {
                let i = a % b.len();
                b[i] = v;
            }
            Edit::Cut(a, n) => {
                let i = at(a, b.len());
                b.drain(i..(i + n).min(b.len()));
            }
            Edit::Dup(a, n) => {
                let i = at(a, b.len());
                let chunk = b[i..(i + n).min(b.len())].to_vec();
                b.splice(i..i, chunk);
            }
            Edit::Token(a, t) => {
                let i = at(a, b.len());
                b.splice(i..i, TOKENS[t].bytes());
            }
            Edit::Truncate(a) => b.truncate(at(a, b.len())),
            _ => {}
        }
    }
    b
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The seeds: every small bad mesh, and the head of each vendored mesh (a few hundred lines:
/// valid files of each format's shape).
fn mesh_seeds() -> Vec<(String, Vec<u8>)> {
    let mut seeds = vec![];
    for dir in ["vectors/bad-meshes", "vectors/meshes"] {
        let mut entries: Vec<_> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .collect();
        entries.sort();
        for p in entries.into_iter().filter(|p| p.is_file()) {
            let ext = p
                .extension()
                .map_or(String::new(), |e| e.to_string_lossy().into_owned());
            if !["obj", "stl", "ply"].contains(&ext.as_str()) {
                continue;
            }
            let mut b = std::fs::read(&p).unwrap();
            b.truncate(16 * 1024);
            seeds.push((ext, b));
        }
    }
    seeds
}

fn cases() -> u32 {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1500)
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: cases(),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// A loader's answer for a mutated file: a mesh of finite coordinates, or an error that
/// names the file.
fn check_load(path: &Path) -> Result<(), String> {
    match mesh::load(path) {
        Ok(m) => {
            let tris = m.triangles_f64();
            if tris
                .iter()
                .flatten()
                .all(|p| p.coords.iter().all(|x| x.is_finite()))
            {
                Ok(())
            } else {
                Err("a mesh with a non-finite coordinate was accepted".into())
            }
        }
        Err(e) => {
            let text = e.to_string();
            let name = path.file_name().unwrap().to_string_lossy();
            if text.contains(&*name) {
                Ok(())
            } else {
                Err(format!("the error does not name the file: {text}"))
            }
        }
    }
}

#[test]
fn mesh_loaders_take_any_bytes() {
    let seeds = mesh_seeds();
    assert!(seeds.len() > 20, "{} seeds", seeds.len());
    let dir = std::env::temp_dir().join(format!("cchip-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut runner = proptest::test_runner::TestRunner::new(config());
    let strategy = (0..seeds.len(), prop::collection::vec(edit(), 1..6));
    let result = runner.run(&strategy, |(s, edits)| {
        let (ext, bytes) = &seeds[s];
        let path = dir.join(format!("case.{ext}"));
        std::fs::write(&path, apply(bytes.clone(), &edits)).unwrap();
        check_load(&path).map_err(|e| TestCaseError::fail(format!("seed {s} (.{ext}): {e}")))
    });
    let _ = std::fs::remove_dir_all(&dir);
    result.unwrap();
}

#[test]
fn scene_files_take_any_text() {
    let mut seeds: Vec<Vec<u8>> = vec![];
    let mut entries: Vec<_> = std::fs::read_dir(root().join("vectors/scenes"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
    {
        seeds.push(std::fs::read(p).unwrap());
    }
    proptest!(config(), |(s in 0..seeds.len(), edits in prop::collection::vec(edit(), 1..6))| {
        let text = String::from_utf8_lossy(&apply(seeds[s].clone(), &edits)).into_owned();
        // a scene is checked whole before anything runs: a value or an error naming the file
        if let Err(e) = Scene::parse(&text, "fuzz.toml") {
            prop_assert!(e.starts_with("fuzz.toml"), "{e}");
        }
    });
}

/// The afl targets' corpus and the crashes afl found (`fuzz/corpus/TARGET/`,
/// `fuzz/regressions/TARGET/`), each through its target's own function: a value or an error,
/// within a few seconds. Cheap, and no afl needed (docs/explanation/testing.md, fuzzing).
#[test]
fn afl_corpus_and_regressions_replay() {
    let mut failed = vec![];
    let mut n = 0;
    for dir in ["fuzz/corpus", "fuzz/regressions"] {
        for target in afl_targets::TARGETS {
            let Ok(files) = std::fs::read_dir(root().join(dir).join(target)) else {
                continue;
            };
            for path in files.flatten().map(|e| e.path()) {
                let bytes = std::fs::read(&path).unwrap();
                let t0 = std::time::Instant::now();
                let run = std::panic::catch_unwind(|| afl_targets::run(target, &bytes));
                let took = t0.elapsed();
                if run.is_err() || took > std::time::Duration::from_secs(5) {
                    failed.push(format!("{} ({took:?})", path.display()));
                }
                n += 1;
            }
        }
    }
    assert!(n >= 10, "only {n} inputs replayed");
    assert!(failed.is_empty(), "panicked or ran too long: {failed:#?}");
}

/// The study's merge inputs afl found crashing (`fuzz/regressions/merge/`) are shard files
/// no study writes: each is refused with an error that names `--merge`, not merged into a
/// table. (The replay above catches a panic; a release build's arithmetic that wraps
/// instead of panicking would pass it and print wrong counts.)
#[test]
fn afl_merge_regressions_are_refused() {
    let dir = root().join("fuzz/regressions/merge");
    let mut n = 0;
    for path in std::fs::read_dir(&dir).unwrap().flatten().map(|e| e.path()) {
        let bytes = std::fs::read(&path).unwrap();
        match afl_targets::run("merge", &bytes) {
            Err(e) if e.starts_with("--merge: ") => n += 1,
            other => panic!("{}: {other:?}", path.display()),
        }
    }
    assert!(n >= 1, "no regression inputs in {}", dir.display());
}

#[test]
fn poses_take_any_text() {
    proptest!(config(), |(s in "[-+0-9.,eEnaifNI xX_]{0,48}")| {
        if let Ok(p) = Pose::parse(&s) {
            prop_assert!(p.rot_deg.iter().chain(&p.t).all(|x| x.is_finite()), "{s:?} gave {p:?}");
        }
    });
}

/// Arguments that have broken command lines before, spliced into `cchip`'s.
const ARGS: &[&str] = &[
    "--k",
    "0",
    "25",
    "-1",
    "4294967296",
    "--pose",
    "nan,0,0,0,0,0",
    "1e309,0,0,0,0,0",
    ",,,,,",
    "0,0,0",
    "--format",
    "e0m0",
    "e99m99",
    "reduced/binary32",
    "--preset",
    "date05",
    "wscg03",
    "--json",
    "--oracle",
    "sphere:0",
    "sphere:99999999",
    "soup:3:x",
    "--traversal",
    "list",
    "recursive",
    "--mode",
    "first",
    "--unit-cube",
    "--",
    "-",
    "",
    "\u{ff}",
    "query",
    "--explain",
    "--dot",
    "--help",
    "--tri-cache",
    "3",
    "--node-cache",
    "0",
    "--technology",
    "ecp5",
    "--architecture",
    "wscg03",
    "no/such/file.obj",
    "vectors/scenes",
];

/// Quick invocations: small queries and scenes explained, not run.
const INVOCATIONS: &[&[&str]] = &[
    &[
        "query",
        "--pose",
        "10,20,30,0.5,0,0",
        "sphere:20",
        "torus:20",
    ],
    &[
        "query",
        "--pose",
        "0,0,0,0,0,0",
        "--k",
        "6",
        "--format",
        "e8m15",
        "--mode",
        "first",
        "--json",
        "soup:8",
        "soup:8:2",
    ],
    &[
        "query",
        "--pose",
        "5,0,0,0.1,0,0",
        "--oracle",
        "--traversal",
        "fifo",
        "--tri-cache",
        "4",
        "teapot",
        "sphere:40",
    ],
    &["run", "--preset", "rtl", "--explain"],
    &[
        "run",
        "--technology",
        "paper",
        "--architecture",
        "wscg03",
        "--explain",
    ],
];

/// `cchip` started with `args` from the project root, its output to `stdout`, its errors
/// piped.
fn spawn_cchip(
    args: &[impl AsRef<std::ffi::OsStr>],
    stdout: std::process::Stdio,
) -> std::process::Child {
    std::process::Command::new(env!("CARGO_BIN_EXE_cchip"))
        .args(args)
        .current_dir(root())
        .stdout(stdout)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap()
}

/// `cchip` run with `args` from the project root: its exit code, or an error for a signal or a
/// run past `limit`.
fn cchip(args: &[String], limit: std::time::Duration) -> Result<(i32, String), String> {
    let mut child = spawn_cchip(args, std::process::Stdio::null());
    let t0 = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if t0.elapsed() > limit {
            child.kill().unwrap();
            return Err(format!("still running after {limit:?}"));
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    out.status
        .code()
        .map(|c| (c, err))
        .ok_or_else(|| format!("ended by a signal: {:?}", out.status))
}

/// `cchip`'s argument parsing and checks: mutated quick invocations end with
/// success or a clear error (exit code 2, no panic), never a hang. A `run` stays explained:
/// `--explain` is appended, so that no mutation starts the default scene's sweep.
#[test]
fn cchip_takes_any_arguments() {
    let config = ProptestConfig {
        cases: (cases() / 25).max(8),
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    let edit = prop_oneof![
        (any::<usize>(), 0..ARGS.len()).prop_map(|(i, a)| (0u8, i, a)),
        (any::<usize>(), 0..ARGS.len()).prop_map(|(i, a)| (1u8, i, a)),
        any::<usize>().prop_map(|i| (2u8, i, 0)),
    ];
    proptest!(config, |(s in 0..INVOCATIONS.len(), edits in prop::collection::vec(edit, 1..4))| {
        let mut args: Vec<String> = INVOCATIONS[s].iter().map(|a| a.to_string()).collect();
        for (op, i, a) in edits {
            let at = i % (args.len() + 1);
            match op {
                0 => args.insert(at, ARGS[a].into()),
                1 if at < args.len() => args[at] = ARGS[a].into(),
                _ if at < args.len() && args.len() > 1 => { args.remove(at); }
                _ => {}
            }
        }
        if args.first().is_some_and(|a| a == "run") {
            args.push("--explain".into());
        }
        let (code, err) = cchip(&args, std::time::Duration::from_secs(60)).map_err(|e| TestCaseError::fail(format!("{args:?}: {e}")))?;
        prop_assert!(code == 0 || (code == 2 && !err.contains("panicked")), "{args:?}: exit {code}\n{err}");
    });
}

/// A reader that goes away (`cchip ... | head -c 100`) ends `cchip` quietly, by SIGPIPE as
/// other Unix tools, not with a panic: the JSON of a bunny in contact with itself (about 110
/// KB with `--oracle`) overfills the pipe, so its write meets the closed end.
#[test]
fn cchip_ends_quietly_when_its_reader_goes_away() {
    use std::io::Read;
    let args = [
        "query",
        "bunny",
        "bunny",
        "--pose",
        "0,0,0,0.01,0,0",
        "--json",
        "--oracle",
    ];
    let mut child = spawn_cchip(&args, std::process::Stdio::piped());
    let mut head = [0u8; 100];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    #[cfg(unix)]
    let by_sigpipe =
        std::os::unix::process::ExitStatusExt::signal(&out.status) == Some(libc::SIGPIPE);
    #[cfg(not(unix))]
    let by_sigpipe = false;
    assert!(
        by_sigpipe || out.status.success(),
        "{args:?} | head -c 100: {:?}\n{err}",
        out.status
    );
    assert!(!err.contains("panicked"), "{err}");
}
