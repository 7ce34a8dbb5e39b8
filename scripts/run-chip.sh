#!/usr/bin/env bash
# Runs an exported collision chip on its queries of vectors/chip/ in Verilator (or
# Icarus) and compares each trace — results with their cycles, the cycle count, overflow,
# maximum queue depth and counters — with the rust-hdl chip's (vectors/chip/<query>.expect).
#
# Usage: scripts/run-chip.sh [--sim verilator|icarus] [--chip rtl/chip_e8m15_k6.v] [--bless] [query ...]
#        scripts/run-chip.sh --build-only [--chip FILE]
#   (default: Verilator, every query of vectors/chip/queries.txt whose last column names
#   the chip, e.g. chip_b32_k24 for --chip rtl/chip_b32_k24.v)
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
# non-zero on any failure. Icarus runs the chip at a few clocks per second (a query takes
# minutes); Verilator builds it once in about 6 minutes and then runs thousands of clocks a second.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=verilator chip=rtl/chip_e8m15_k6.v queries=() bless=0 build_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --sim) sim=$2; shift 2 ;;
    --chip) chip=$2; shift 2 ;;
    --bless) bless=1; shift ;;
    --build-only) build_only=1; shift ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) queries+=("$1"); shift ;;
  esac
done
[ -f "$chip" ] || { echo "run-chip.sh: no such file: $chip (run: cargo run --release -- export-verilog)" >&2; exit 2; }
name=$(basename "$chip" .v)
[ ${#queries[@]} -gt 0 ] || mapfile -t queries < <(awk -v c="$name" '$5 == c { print $1 }' vectors/chip/queries.txt)
mw=$(sed -nE 's/^ *input wire +\[([0-9]+):0\] mem_resp_data;$/\1/p' "$chip" | head -n 1)
[ -n "$mw" ] || { echo "run-chip.sh: $chip has no mem_resp_data input port" >&2; exit 2; }
mw=$((mw + 1))
out=target/verilog/$sim/$name
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
    flags=(--hierarchical --cc --timing --build -O3 -MAKEFLAGS "OPT_FAST=$opt" -Wno-WIDTH -Wno-UNOPTFLAT -Wno-STMTDLY --top-module tb)
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
      { verilator "${flags[@]}" -Mdir "$out/obj" -j "$(nproc 2>/dev/null || echo 2)" "$out/tb.v" "$out/chip.v" \
          && g++ -std=gnu++20 -fcoroutines "$opt" -DVL_TIME_CONTEXT -I"$out/obj" -I"$inc" -I"$inc/vltstd" \
            scripts/verilog/tb_main.cpp "$inc/verilated.cpp" "$inc/verilated_timing.cpp" "$inc/verilated_threads.cpp" \
            "$out/obj/Vtb__ALL.a" "$out"/obj/V*/lib*.a -pthread -latomic -o "$out/obj/Vchip"; } >"$out/build.log" 2>&1 \
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
  read -r _ latency interval reader _ < <(grep "^$q " vectors/chip/queries.txt) \
    || { echo "$q: not in vectors/chip/queries.txt"; fail=$((fail + 1)); continue; }
  run +mem="vectors/chip/$q.mem" +host="vectors/chip/$q.host" +latency="$latency" +interval="$interval" \
    +reader="${reader:-1}" +max_cycles=2000000 \
    | grep -E '^(result|done|timeout)' >"$out/$q.trace" || true
  want=vectors/chip/$q.expect
  [ $bless = 1 ] && want=target/chip-expect/$q.expect
  if diff -u "$want" "$out/$q.trace" >"$out/$q.diff"; then
    echo "$q: pass ($(sed -n 's/^done \([0-9]*\) .*/\1/p' "$out/$q.trace") cycles)"
    [ $bless = 1 ] && cp "$want" "vectors/chip/$q.expect"
    pass=$((pass + 1))
  else
    echo "$q: FAIL (expected $want, got $out/$q.trace)"; head -n 20 "$out/$q.diff"
    fail=$((fail + 1))
  fi
done
echo "$pass passed, $fail failed"
[ $fail = 0 ] && [ $pass -gt 0 ]
