#!/usr/bin/env bash
# The area study's Yosys cells (docs/explanation/accuracy-cost.md, "In time and area"): exports the
# DOP unit for every k (6, 14, 18, 24, 26), format (binary32, e8m15, e8m10) and DOP rounding, and
# TRI_UNIT per format, those of binary32 and e8m15 also folded (TRI_UNIT at a pair every 2 .. 32 clocks,
# the DOP unit at every k and interval the RTL stamps out) (`cchip export-verilog --area`),
# synthesizes each with scripts/synth.sh (hierarchical, Yosys' generic gates) and writes one
# row per unit: `unit,cells`.
# `cchip accuracy --area FILE` reads the file. CI re-synthesizes those of these units
# that are in rtl/ and fails if their cells differ from the file (then run this again).
#
# Usage: scripts/area-study.sh [--jobs N] [--out FILE] [--units PATTERNS]   (default: 2 jobs,
#        docs/figures/area_cells.csv; about 20 minutes on 2 cores, more with the folds)
#   --units  space-separated shell globs on the unit name: synthesize only these, keep the
#            file's other rows (e.g. --units 'tri_unit_fold* dop_unit_fold*')
set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
JOBS=2 OUT=$ROOT/docs/figures/area_cells.csv UNITS='*' 
while [ $# -gt 0 ]; do
  case $1 in
    --jobs) JOBS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --units) UNITS=$2; shift 2 ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) echo "area-study.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
dir=$ROOT/target/area
rm -rf "$dir"
(cd "$ROOT" && cargo run --release --locked -q -- export-verilog --area --out "$dir" >/dev/null)
# The units selected by --units (all by default).
files=()
set -f; pats=($UNITS); set +f   # the patterns as words, not globbed against the current directory
for pat in "${pats[@]}"; do
  for f in "$dir"/$pat.v; do [ -f "$f" ] && files+=("$f"); done
done
[ ${#files[@]} -gt 0 ] || { echo "area-study.sh: no unit of the study matches '$UNITS' (see $dir)" >&2; exit 2; }
# One Yosys per unit, JOBS at a time; each prints `<unit> cells: N` last.
printf '%s\n' "${files[@]}" | sort -u | xargs -P "$JOBS" -I{} sh -c '"$0" "$1" > "$1.synth" 2>&1 || { echo "area-study.sh: yosys failed on $1 (see $1.synth)" >&2; exit 1; }' "$SCRIPTS/synth.sh" {}
for f in $(printf '%s\n' "${files[@]}" | sort -u); do
  sed -n 's/^\([a-z0-9_]*\) cells: \([0-9]*\)$/\1,\2/p' "$f.synth" | tail -n 1
done > "$OUT.new"
rows=$(wc -l < "$OUT.new")
want=$(printf '%s\n' "${files[@]}" | sort -u | wc -l)
[ "$rows" = "$want" ] || { echo "area-study.sh: $rows cell counts for $want units (see $dir/*.synth)" >&2; rm -f "$OUT.new"; exit 1; }
# Merge: the units synthesized now replace their rows; the file's other rows stay when
# --units picked some (a full run writes only its own).
old=/dev/null
[ "$UNITS" != '*' ] && [ -f "$OUT" ] && old=$OUT
{
  echo "unit,cells"
  awk -F, 'NR == FNR { new[$1] = $0; next } FNR > 1 && !($1 in new) { print } END { for (u in new) print new[u] }' "$OUT.new" "$old" | sort
} > "$OUT.tmp"
rm -f "$OUT.new"
mv "$OUT.tmp" "$OUT"
echo "wrote $OUT ($rows units synthesized, $(($(wc -l < "$OUT") - 1)) rows)"
