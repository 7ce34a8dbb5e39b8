#!/usr/bin/env bash
# Runs an exported collision chip on its queries of vectors/chip/ in Verilator (or
# Icarus) and compares each trace — results with their cycles, the cycle count, overflow,
# maximum queue depth and counters — with the rust-hdl chip's (vectors/chip/<query>.expect).
#
# Usage: scripts/run-chip.sh [--sim verilator|icarus] [--chip rtl/chip_e8m15_k6.v] [--bless]
#                            [--requests] [--x-seeds "S ..."] [--vectors DIR] [query ...]
#        scripts/run-chip.sh --build-only [--chip FILE]
#   (default: Verilator, every query of vectors/chip/queries.txt whose last column names
#   the chip, e.g. chip_b32_k24 for --chip rtl/chip_b32_k24.v)
# Each query also compares the memory requests the testbench accepted (cycle and word address)
# with the cycle model's, target/chip-expect/<query>.requests (written by `cargo test
# --release --test cycle_chip`), where that file exists; --requests makes a missing one a
# failure.
# --x-seeds "S ...": Verilator only, each query once per seed S with every register and memory
#   bit that the Verilog does not initialise random (+verilator+rand+reset+2
#   +verilator+seed+S; the build has --x-assign unique --x-initial unique), instead of once
#   with them zero: a result that depends on an uninitialised bit differs between seeds.
#   Icarus needs none: it is four-state, and such a bit prints as x.
# --vectors DIR: the queries, their files and expected traces and requests from DIR instead
#   of vectors/chip/ and target/chip-expect/ (scripts/selftest.sh's stand-in chip).
# RUN_CHIP_SED (environment): a sed script applied to a copy of the chip's Verilog, which is
#   built and run instead (under target/verilog/<sim>/<chip>-sed/, the chip's own build kept):
#   a chip made to diverge on purpose, to show that a check catches it (.ci/run does so for
#   `cross_check = "verilog"`, which builds through --build-only). An error if it changes nothing.
# --build-only: build the Verilator binary (target/verilog/verilator/<chip>/obj/Vchip) and print
#   its path. The build is kept and reused while the testbench, the chip's Verilog and the
#   flags are unchanged (`cchip run` builds it this way for cross_check = "verilog").
# --bless: compare each trace with the cycle model's instead (target/chip-expect/<query>.expect,
#   written by `CCHIP_BLESS=1 cargo test --release --test cycle_chip`) and, where the two agree,
#   copy it to vectors/chip/<query>.expect: an expected trace is written only when the
#   exported Verilog and the cycle model agree on it.
# The testbench is scripts/verilog/chip_tb.v (its memory word width MW taken from the
# chip's mem_resp_data port); builds and logs in target/verilog/<sim>/<chip>/.
# Prints `<query>: pass (<cycles> cycles)` or the diff, then `N passed, M failed`; exits
# non-zero on any failure, the simulator's own non-zero exit included. Icarus runs the chip at a few clocks per second (a query takes
# minutes); Verilator builds it once in about 6 minutes and then runs thousands of clocks a second.

set -euo pipefail
cd "$(dirname "$0")/.."
sim=verilator chip=rtl/chip_e8m15_k6.v queries=() bless=0 build_only=0 need_requests=0 seeds=("") vec=vectors/chip ref=target/chip-expect
while [ $# -gt 0 ]; do
  case $1 in
    --sim) sim=$2; shift 2 ;;
    --chip) chip=$2; shift 2 ;;
    --bless) bless=1; shift ;;
    --build-only) build_only=1; shift ;;
    --requests) need_requests=1; shift ;;
    --vectors) vec=$2; ref=$2; shift 2 ;;
    --x-seeds) read -ra seeds <<<"$2"; [ ${#seeds[@]} -gt 0 ] || { echo "run-chip.sh: --x-seeds needs seeds" >&2; exit 2; }; shift 2 ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) queries+=("$1"); shift ;;
  esac
done
[ -f "$chip" ] || { echo "run-chip.sh: no such file: $chip (run: cargo run --release -- export-verilog)" >&2; exit 2; }
[ -z "${seeds[0]}" ] || [ "$sim" = verilator ] || { echo "run-chip.sh: --x-seeds is for Verilator (Icarus is four-state: an uninitialised bit is x)" >&2; exit 2; }
name=$(basename "$chip" .v)
out=target/verilog/$sim/$name
if [ -n "${RUN_CHIP_SED:-}" ]; then
  out=$out-sed
  mkdir -p "$out"
  sed "$RUN_CHIP_SED" "$chip" >"$out/sed.v"
  cmp -s "$chip" "$out/sed.v" && { echo "run-chip.sh: RUN_CHIP_SED changed nothing in $chip" >&2; exit 2; }
  chip=$out/sed.v
  echo "run-chip.sh: $chip is $name changed by RUN_CHIP_SED" >&2
fi
[ ${#queries[@]} -gt 0 ] || mapfile -t queries < <(awk -v c="$name" '$5 == c { print $1 }' "$vec/queries.txt")
mw=$(sed -nE 's/^ *input wire +\[([0-9]+):0\] mem_resp_data;$/\1/p' "$chip" | head -n 1)
[ -n "$mw" ] || { echo "run-chip.sh: $chip has no mem_resp_data input port" >&2; exit 2; }
mw=$((mw + 1))
mkdir -p "$out"
case $sim in
  verilator)
    command -v verilator >/dev/null || { echo "run-chip.sh: verilator not found (apt-get install -y verilator)" >&2; exit 127; }
    # Hierarchical: the DOP lane and T.CHECK are verilated and compiled once each as
    # hier_blocks (the k = 24 chip has 24 identical lanes), not inlined at every instance:
    # the k = 24 binary32 chip builds in about 6 minutes instead of more than 30. That
    # needs plain identifiers (rust-hdl's `a$b` names become `a_S_b` in the copy built
    # here), MW written into the testbench (a -G would reach the blocks too) and our own
    # main(), scripts/verilog/tb_main.cpp. The C++ is compiled at -O1 (CHIP_OPT_FAST): on
    # 2 cores the k = 6 chip builds in 5.5 minutes and runs about 4,000 clocks per second,
    # at -O0 in 2 minutes but at 570 (its 16 queries and CI's Verilog scenes are 440,000
    # clocks). rust-hdl output needs -Wno-WIDTH (32-bit literals); the FP normalisers trip
    # UNOPTFLAT; Verilator's front end lints the chip as it builds it. A chip with a folded
    # TRI_UNIT has no tc_ab (its one T.CHECK, `tc`, is instantiated once): a block the chip
    # lacks is left out.
    hier='top$dop$doptrf$0 top$tri_unit$tc_ab'
    opt=${CHIP_OPT_FAST:--O1}
    # --x-assign/--x-initial unique: what the Verilog leaves uninitialised is zero unless
    # +verilator+rand+reset+2 asks for random bits at run time (--x-seeds)
    flags=(--hierarchical --cc --timing --build -O3 -MAKEFLAGS "OPT_FAST=$opt" -Wno-WIDTH -Wno-UNOPTFLAT -Wno-STMTDLY
           --x-assign unique --x-initial unique --top-module tb)
    stamp=$( (verilator --version; echo "${flags[*]} $hier $mw"; cat scripts/verilog/chip_tb.v scripts/verilog/tb_main.cpp "$chip") | sha256sum)
    if [ -x "$out/obj/Vchip" ] && [ "$(cat "$out/stamp" 2>/dev/null)" = "$stamp" ]; then
      echo "run-chip.sh: $out/obj/Vchip is up to date" >&2
    else
      rm -rf "$out/stamp" "$out/obj"
      sed "s/^  parameter MW = [0-9]*;/  parameter MW = $mw;/" scripts/verilog/chip_tb.v >"$out/tb.v"
      python3 - "$chip" "$out/chip.v" $hier <<'PY'
import re, sys
src, dst, blocks = sys.argv[1], sys.argv[2], sys.argv[3:]
v = open(src).read()
for b in blocks:
    if "module " + b + "(" not in v:
        continue
    head = v.index("module " + b + "(")
    end = v.index(");", head) + 2
    v = v[:end] + "\n/*verilator hier_block*/" + v[end:]
open(dst, "w").write(re.sub(r"(?<=\w)\$", "_S_", v))
PY
      inc=$(verilator --getenv VERILATOR_ROOT)/include
      # the hier_blocks' libraries (none for a chip without the blocks)
      blocks() { local f; for f in "$out"/obj/V*/lib*.a; do [ -e "$f" ] && echo "$f"; done; }
      { verilator "${flags[@]}" -Mdir "$out/obj" -j "$(nproc 2>/dev/null || echo 2)" "$out/tb.v" "$out/chip.v" \
          && g++ -std=gnu++20 -fcoroutines "$opt" -DVL_TIME_CONTEXT -I"$out/obj" -I"$inc" -I"$inc/vltstd" \
            scripts/verilog/tb_main.cpp "$inc/verilated.cpp" "$inc/verilated_timing.cpp" "$inc/verilated_threads.cpp" \
            "$out/obj/Vtb__ALL.a" $(blocks) -pthread -latomic -o "$out/obj/Vchip"; } >"$out/build.log" 2>&1 \
        || { cat "$out/build.log" >&2; echo "run-chip.sh: Verilator build failed" >&2; exit 1; }
      echo "$stamp" >"$out/stamp"
    fi
    [ $build_only = 1 ] && { echo "$out/obj/Vchip"; exit 0; }
    run() { "$out/obj/Vchip" "$@"; } ;;
  icarus)
    [ $build_only = 1 ] && { echo "run-chip.sh: --build-only builds the Verilator binary" >&2; exit 2; }
    command -v iverilog >/dev/null || { echo "run-chip.sh: iverilog not found (apt-get install -y iverilog)" >&2; exit 127; }
    iverilog -g2012 -s tb -Ptb.MW="$mw" -o "$out/chip.vvp" scripts/verilog/chip_tb.v "$chip"
    run() { vvp -n "$out/chip.vvp" "$@"; } ;;
  *) echo "run-chip.sh: unknown simulator $sim" >&2; exit 2 ;;
esac
pass=0 fail=0
for q in "${queries[@]}"; do
  read -r _ latency interval reader _ < <(grep "^$q " "$vec/queries.txt") \
    || { echo "$q: not in $vec/queries.txt"; fail=$((fail + 1)); continue; }
  want=$vec/$q.expect
  [ $bless = 1 ] && want=$ref/$q.expect
  want_req=$ref/$q.requests
  for seed in "${seeds[@]}"; do
    name=$q x=() # a seed: every uninitialised bit random
    [ -n "$seed" ] && { name="$q (x seed $seed)"; x=(+verilator+rand+reset+2 "+verilator+seed+$seed"); }
    got=$out/$q${seed:+.x$seed}
    status=0; rm -f "$got.diff"
    run +mem="$vec/$q.mem" +host="$vec/$q.host" +latency="$latency" +interval="$interval" \
      +reader="${reader:-1}" +max_cycles=2000000 +requests "${x[@]}" >"$got.log" 2>&1 || status=$?
    grep -E '^(result|done|timeout)' "$got.log" >"$got.trace" || true
    grep '^request ' "$got.log" >"$got.requests" || true
    why=""
    if [ "$status" != 0 ]; then why="the simulator exited with $status ($got.log)"
    elif ! diff -u "$want" "$got.trace" >"$got.diff"; then why="expected $want, got $got.trace"
    elif [ -f "$want_req" ]; then
      diff -u "$want_req" "$got.requests" >"$got.diff" || why="memory requests: expected $want_req, got $got.requests"
    elif [ $need_requests = 1 ]; then why="no $want_req (run: cargo test --release --test cycle_chip every_checked_in_trace)"
    fi
    if [ -z "$why" ]; then
      echo "$name: pass ($(sed -n 's/^done \([0-9]*\) .*/\1/p' "$got.trace") cycles$([ -f "$want_req" ] && echo ", $(wc -l <"$got.requests") requests"))"
      [ $bless = 1 ] && cp "$want" "vectors/chip/$q.expect"
      pass=$((pass + 1))
    else
      echo "$name: FAIL ($why)"; [ -s "$got.diff" ] && head -n 20 "$got.diff"
      fail=$((fail + 1))
    fi
  done
done
echo "$pass passed, $fail failed"
[ $fail = 0 ] && [ $pass -gt 0 ]
