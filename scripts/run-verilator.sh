#!/usr/bin/env bash
# Run one exported unit against its vectors in Verilator (--binary, -O3, C++ at -O0).
#
# Usage: scripts/run-verilator.sh <unit_file.v> <vectors.hex> [options] [+plusargs]
#   --latency N      pipeline latency (default: `// latency: N` line in the vector file)
#   --name UNIT      unit name (default: basename of unit_file); module `top` is renamed to it
#   --top MODULE     top module in unit_file (default: `top`, else UNIT)
#   --fields "a b y" field names (default: the vector file's header line)
#   --preload "en addr data"  preload field names (default: the `// preload:` line)
#   --clock/--in-valid/--out-valid NAME   port names (default clock, in_valid, out_valid)
#   --extra FILE.v   another Verilog source to compile with the unit (repeatable)
#   --trace          build with --trace, dump a VCD to target/verilog/verilator/<unit>/<unit>.vcd
#   --out DIR        build directory (default target/verilog/verilator/<unit>)
#   +bubble=K        an idle cycle (in_valid low) after every K cases
#   +max_print=N     mismatches printed (default 10)
# Environment: VERILATOR_WNO (default "-Wno-WIDTH -Wno-UNOPTFLAT", the warnings rust-hdl
#   output needs off: 32-bit literals, and the FP normalisers' chains of bit fields of one
#   signal, a scheduling note rather than a loop),
#   VERILATOR_FLAGS (extra flags for both the lint and the build).
# Lints the unit alone first (warnings are errors), then builds and runs the testbench.
# Prints the mismatches and `N passed, M failed`; exits non-zero on any failure.

set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
SIM=verilator
. "$SCRIPTS/verilog/common.sh"
need verilator verilator
parse_args "$@"

read -r -a WNO <<<"${VERILATOR_WNO--Wno-WIDTH -Wno-UNOPTFLAT}"
read -r -a XFLAGS <<<"${VERILATOR_FLAGS-}"
verilator --lint-only "${WNO[@]}" "${XFLAGS[@]}" --top-module "$UNIT" "$OUT/$UNIT.v" "${EXTRA[@]}"

# The C++ is compiled unoptimised (OPT_FAST=-O0): a unit's vectors run in well under a
# second either way, while -Os compiles TRI_UNIT's 150 MB of C++ in 11 CPU-minutes, -O0 in 6.
FLAGS=(--binary -O3 -MAKEFLAGS OPT_FAST=-O0 "${WNO[@]}" -Wno-STMTDLY "${XFLAGS[@]}" --top-module tb -Mdir "$OUT/obj"
       -j "$(nproc 2>/dev/null || echo 2)" -o "V$UNIT")
[ "$TRACE" = 1 ] && FLAGS+=(--trace -DTRACE)
# Rebuild from scratch when the flags change (e.g. --trace toggled).
echo "${FLAGS[*]}" > "$OUT/flags.new"
if ! cmp -s "$OUT/flags.new" "$OUT/flags" 2>/dev/null; then rm -rf "$OUT/obj"; fi
mv "$OUT/flags.new" "$OUT/flags"
verilator "${FLAGS[@]}" "$OUT/tb_$UNIT.v" "$OUT/$UNIT.v" "${EXTRA[@]}" > "$OUT/build.log" 2>&1 \
  || { cat "$OUT/build.log" >&2; echo "run-verilator.sh: $UNIT: build failed" >&2; exit 1; }
check_run "$OUT/obj/V$UNIT" "${PLUSARGS[@]}"
