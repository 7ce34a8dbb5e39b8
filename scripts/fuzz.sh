#!/usr/bin/env bash
# Coverage-guided fuzzing of the mesh loaders, the scene parser and the accuracy study's
# merge of shard files with cargo-afl (stable Rust): fuzz/ builds one program, `cchip-fuzz TARGET`, that runs each input the way `cchip`
# runs the same file (fuzz/src/lib.rs); afl-fuzz runs each target for SECONDS and this script
# fails if any input made it panic, abort or hang.
#
# Needs cargo-afl, which builds its own AFL++ from the source it ships (make and a C
# compiler; no network):
#   cargo install cargo-afl --locked
#
# Usage: scripts/fuzz.sh [--seconds N] [--jobs N] [--build-only] [TARGET ...]
#   TARGET        mesh_obj, mesh_stl, mesh_ply, scene, merge (default: all five)
#   --seconds N   afl-fuzz time per target (default 60)
#   --jobs N      targets fuzzed at a time (default 1; each takes a core)
#   --build-only  build the instrumented program and stop
# Seeds: fuzz/corpus/TARGET/, fuzz/regressions/TARGET/ and the project's own files of the
# kind (vectors/bad-meshes/*.EXT, vectors/scenes/*.toml; merge has its corpus alone: shard
# files of small studies, NUL between files). Everything else goes under
# target/afl/ (build, seeds, afl's output: out/TARGET/default/{crashes,hangs,queue}).
# A crash: reproduce it with `target/afl/release/cchip-fuzz TARGET < FILE`, shrink it with
# `cargo afl tmin -i FILE -o SMALL -- target/afl/release/cchip-fuzz TARGET`, fix its cause,
# and add SMALL to fuzz/regressions/TARGET/ (`cargo test --release --test fuzz_inputs`
# replays it). docs/explanation/testing.md, "Fuzzing"; scripts/README.md, "Fuzzing".
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$root/target/afl

seconds=60 jobs=1 build_only=0 targets=()
while [ $# -gt 0 ]; do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --build-only) build_only=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; exit 0 ;;
    mesh_obj|mesh_stl|mesh_ply|scene|merge) targets+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(mesh_obj mesh_stl mesh_ply scene merge)

cargo afl --version >/dev/null 2>&1 || {
  echo "fuzz.sh: cargo-afl not found (cargo install cargo-afl --locked)" >&2; exit 2; }

echo "== building the instrumented cchip-fuzz (cargo afl build --release)"
(cd fuzz && CARGO_TARGET_DIR=$out cargo afl build --release --locked -q)
bin=$out/release/cchip-fuzz
[ $build_only = 1 ] && { echo "$bin"; exit 0; }

# Where the project keeps files of each target's kind.
own_files() {
  case $1 in
    mesh_*) find "$root/vectors/bad-meshes" -maxdepth 1 -type f -name "*.${1#mesh_}" ;;
    scene) find "$root/vectors/scenes" -maxdepth 1 -type f -name '*.toml' ;;
  esac
}

fuzz_one() {
  local t=$1 seeds=$out/seeds/$1
  rm -rf "$seeds" "$out/out/$t"
  mkdir -p "$seeds" "$out/out"
  cp "$root/fuzz/corpus/$t"/* "$seeds"/
  [ -d "$root/fuzz/regressions/$t" ] && cp "$root/fuzz/regressions/$t"/* "$seeds"/
  own_files "$t" | xargs -I{} cp {} "$seeds"/
  # -V: stop after SECONDS; -t: ms per input before it counts as a hang (the targets do at
  # most a small query; 2 s leaves room on a busy machine); -m: MB of memory per run, so
  # that an allocation the input does not justify aborts the run as a crash.
  AFL_NO_UI=1 AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 \
    AFL_NO_AFFINITY=1 \
    cargo afl fuzz -V "$seconds" -t 2000 -m 4096 -i "$seeds" -o "$out/out/$t" -- "$bin" "$t" \
    >"$out/out/$t.log" 2>&1 || { tail -n 20 "$out/out/$t.log"; return 1; }
}

echo "== afl-fuzz: ${targets[*]}, $seconds s each, $jobs at a time (logs: target/afl/out/TARGET.log)"
failed=0
running=0
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  running=$((running + 1))
  if [ $running -ge "$jobs" ]; then wait -n || failed=1; running=$((running - 1)); fi
done
while [ $running -gt 0 ]; do wait -n || failed=1; running=$((running - 1)); done

bad=0
for t in "${targets[@]}"; do
  stats=$out/out/$t/default/fuzzer_stats
  [ -f "$stats" ] || { echo "$t: afl-fuzz left no statistics (target/afl/out/$t.log)"; bad=1; continue; }
  get() { awk -F' *: *' -v k="$1" '$1 == k { print $2 }' "$stats"; }
  found=$(find "$out/out/$t/default/crashes" "$out/out/$t/default/hangs" -type f ! -name README.txt | sort)
  printf '%-9s %4s s  %9s execs  %7s/s  corpus %5s  edges %s  crashes %s  hangs %s\n' \
    "$t" "$(get run_time)" "$(get execs_done)" "$(get execs_per_sec)" "$(get corpus_count)" \
    "$(get edges_found)" "$(get saved_crashes)" "$(get saved_hangs)"
  if [ -n "$found" ]; then echo "$found" | sed 's/^/  /'; bad=1; fi
done
if [ $failed = 1 ] || [ $bad = 1 ]; then
  echo "fuzz.sh: crashes, hangs or a failed run above (reproduce: $bin TARGET < FILE)" >&2
  exit 1
fi
echo "${#targets[@]} passed, 0 failed"
