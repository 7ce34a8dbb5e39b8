#!/usr/bin/env bash
# Synthesize exported units with Yosys and report the cells per unit.
#
# Usage: scripts/synth.sh [--target generic|ice40|ecp5|xilinx] [--top MODULE] [--flat] <unit_file.v>...
#   --target T   generic (default): `synth -flatten` to Yosys' internal gate library;
#                ice40/ecp5/xilinx: the FPGA flow synth_<T> -flatten (xilinx: `-family xcup`,
#                AMD UltraScale+: LUT6, DSP48E2, RAMB18E2/36E2; all keep the hierarchy
#                described below unless --flat). FPGA targets add a line `<unit> resources:`
#                with LUTs, flip-flops, shift-register LUTs, DSP blocks and block RAMs.
#   --top MODULE top module in each file (default: `top` if present, else the file's basename)
#   --flat       flatten the whole unit (slow for the DOP units; the default is hierarchical)
# Hierarchical by default: every module that instantiates other modules (the unit, a DOP
# lane, an FP unit; the exported Verilog has one module per distinct block) gets
# keep_hierarchy and is synthesized once however often it is used; the leaf modules
# (registers, normaliser, rounder, ...) are flattened into it, so constants and unused
# outputs are optimized across them. `stat -top` adds up the hierarchy.
# For each unit (module `top` renamed to the file's basename, like the simulation flows):
# prints the `stat` tables and then one summary line `<unit> cells: N` (whole hierarchy).
# Logs in target/synth/<unit>.log. Exits non-zero if Yosys fails on any unit.

set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
PY=${PYTHON:-python3}
command -v yosys >/dev/null || { echo "synth.sh: yosys not found (apt-get install -y yosys)" >&2; exit 127; }

TARGET=generic TOP=() FILES=() FLAT=0
while [ $# -gt 0 ]; do
  case $1 in
    --target) TARGET=$2; shift 2 ;;
    --top) TOP=(--top "$2"); shift 2 ;;
    --flat) FLAT=1; shift ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) FILES+=("$1"); shift ;;
  esac
done
[ ${#FILES[@]} -gt 0 ] || { sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
case $TARGET in
  generic) SYNTH="synth -flatten" ;;
  ice40|ecp5) SYNTH="synth_$TARGET -flatten" ;;
  xilinx) SYNTH="synth_xilinx -family xcup -flatten" ;;
  *) echo "synth.sh: unknown target $TARGET" >&2; exit 2 ;;
esac
# Modules holding an instance of a module (cells whose type is not a Yosys `$` cell) keep
# their hierarchy; `flatten` (in synth -flatten) inlines everything else.
KEEP='setattr -mod -set keep_hierarchy 1 t:* t:$* %d %m;'
[ $FLAT = 1 ] && KEEP=

mkdir -p "$ROOT/target/synth"
status=0 SUMMARY=()
for f in "${FILES[@]}"; do
  unit=$(basename "$f" .v)
  out="$ROOT/target/synth/$unit"
  mkdir -p "$out"
  "$PY" "$SCRIPTS/verilog/prepare.py" --rename-only "$f" --out "$out" --name "$unit" "${TOP[@]}"
  log="$ROOT/target/synth/$unit.log"
  if ! yosys -l "$log" -q -p "read_verilog $out/$unit.v; hierarchy -check -top $unit; $KEEP $SYNTH -top $unit; check -assert; tee -o $out/stat.txt stat -top $unit" >/dev/null; then
    echo "synth.sh: $unit: yosys failed (log $log)" >&2; status=1; continue
  fi
  cat "$out/stat.txt"
  cells=$(grep -E '^\s+Number of cells:' "$out/stat.txt" | tail -n 1 | awk '{print $4}')
  echo "$unit cells: $cells"
  SUMMARY+=("$unit cells: $cells")
  if [ "$TARGET" != generic ]; then
    res=$("$PY" "$SCRIPTS/verilog/resources.py" "$out/stat.txt")
    echo "$unit resources: $res"
    SUMMARY+=("$unit resources: $res")
  fi
done
if [ ${#FILES[@]} -gt 1 ]; then printf '%s\n' "--- summary ($TARGET)" "${SUMMARY[@]}"; fi
exit $status
