#!/usr/bin/env bash
# Run one exported unit against its vectors in Icarus Verilog.
#
# Usage: scripts/run-icarus.sh <unit_file.v> <vectors.hex> [options] [+plusargs]
#   --latency N      pipeline latency (default: `// latency: N` line in the vector file)
#   --name UNIT      unit name (default: basename of unit_file); module `top` is renamed to it
#   --top MODULE     top module in unit_file (default: `top`, else UNIT)
#   --fields "a b y" field names (default: the vector file's header line)
#   --preload "en addr data"  preload field names (default: the `// preload:` line)
#   --clock/--in-valid/--out-valid NAME   port names (default clock, in_valid, out_valid)
#   --extra FILE.v   another Verilog source to compile with the unit (repeatable)
#   --trace          dump a VCD to target/verilog/icarus/<unit>/<unit>.vcd
#   --out DIR        build directory (default target/verilog/icarus/<unit>)
#   +bubble=K        an idle cycle (in_valid low) after every K cases
#   +max_print=N     mismatches printed (default 10)
# Prints the mismatches and `N passed, M failed`; exits non-zero on any failure.

set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
SIM=icarus
. "$SCRIPTS/verilog/common.sh"
need iverilog iverilog
need vvp iverilog
parse_args "$@"

DEFS=()
[ "$TRACE" = 1 ] && DEFS+=(-DTRACE)
iverilog -g2012 -Wall -Wno-timescale -Wno-implicit-dimensions "${DEFS[@]}" -s tb \
  -o "$OUT/sim.vvp" "$OUT/tb_$UNIT.v" "$OUT/$UNIT.v" "${EXTRA[@]}"
check_run vvp -n "$OUT/sim.vvp" "${PLUSARGS[@]}"
