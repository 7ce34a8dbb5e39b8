#!/usr/bin/env bash
# The area study's Yosys cells (docs/ACCURACY.md, "What accuracy costs in area"): exports the
# DOP unit for every k (6, 14, 18, 24, 26), format (binary32, e8m15) and DOP rounding, and
# TRI_UNIT per format (`cchip export-verilog --area`), synthesizes each with scripts/synth.sh
# (hierarchical, Yosys' generic gates) and writes one row per unit: `unit,cells`.
# `cchip accuracy --area FILE` reads the file. CI re-synthesizes the four of these units
# that are in rtl/ and fails if their cells differ from the file (then run this again).
#
# Usage: scripts/area-study.sh [--jobs N] [--out FILE]   (default: 2 jobs,
#        docs/figures/area_cells.csv; about 20 minutes on 2 cores)
set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
JOBS=2 OUT=$ROOT/docs/figures/area_cells.csv
while [ $# -gt 0 ]; do
  case $1 in
    --jobs) JOBS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) echo "area-study.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
dir=$ROOT/target/area
rm -rf "$dir"
(cd "$ROOT" && cargo run --release --locked -q -- export-verilog --area --out "$dir" >/dev/null)
# One Yosys per unit, JOBS at a time; each prints `<unit> cells: N` last.
ls "$dir"/*.v | xargs -P "$JOBS" -I{} sh -c '"$0" "$1" > "$1.synth" 2>&1 || { echo "area-study.sh: yosys failed on $1 (see $1.synth)" >&2; exit 1; }' "$SCRIPTS/synth.sh" {}
{
  echo "unit,cells"
  for f in "$dir"/*.v.synth; do
    sed -n 's/^\([a-z0-9_]*\) cells: \([0-9]*\)$/\1,\2/p' "$f" | tail -n 1
  done
} > "$OUT.tmp"
rows=$(($(wc -l < "$OUT.tmp") - 1))
want=$(ls "$dir"/*.v | wc -l)
[ "$rows" = "$want" ] || { echo "area-study.sh: $rows cell counts for $want units (see $dir/*.synth)" >&2; exit 1; }
mv "$OUT.tmp" "$OUT"
echo "wrote $OUT ($rows units)"
