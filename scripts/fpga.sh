#!/usr/bin/env bash
# FPGA numbers for exported units: Yosys `synth_ice40` (flat) and nextpnr-ice40 place and
# route on an iCE40 HX8K (ct256 package: 206 I/O, 7,680 logic cells, no DSP blocks, so the
# multipliers are logic). Prints one line per unit: logic cells, RAM blocks, I/O and the Fmax
# nextpnr's timing analysis reports, or why the unit does not fit.
#
# Usage: scripts/fpga.sh rtl/<unit>.v ...    (needs `apt-get install -y yosys nextpnr-ice40`)
# Logs and reports in target/fpga/<unit>/. Exits non-zero if a tool fails on a unit that fits.
#
# scripts/fpga.sh --ecp5 [--timeout SECONDS] [--placer P] [--no-tmdriv] [--seed N] rtl/<unit>.v ...
#   A Lattice LFE5U-85F instead (a whole chip fits: docs/guide/timing-and-fpga.md): the ECP5 flow of
#   scripts/timing-ecp5.sh (YoWASP Yosys, flat synth_ecp5; nextpnr-ecp5 out of context,
#   router2), its row into docs/figures/timing_ecp5.csv, and one line per unit: LUT4s,
#   flip-flops, MULT18X18D, DP16KD block RAMs and Fmax. Default timeout 14400 s per tool
#   (the k = 6 chip on both folded units: about 5 minutes of Yosys and 15-30 of nextpnr
#   here). Default placer: static (nextpnr's electrostatic placer; heap, timing-ecp5.sh's
#   default for single units, left the whole chip unroutable); --no-tmdriv places without
#   timing.
set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
PY=${PYTHON:-python3}
if [ "${1:-}" = --ecp5 ]; then
  shift; timeout=14400; place=(--placer static)
  while [ $# -gt 0 ]; do
    case $1 in
      --timeout) timeout=$2; shift 2 ;;
      --placer) place[1]=$2; shift 2 ;;
      --no-tmdriv) place+=(--no-tmdriv); shift ;;
      --seed) place+=(--seed "$2"); shift 2 ;;
      *) break ;;
    esac
  done
  [ $# -gt 0 ] || { sed -n '2,/^set/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2; exit 2; }
  units=$(for f in "$@"; do basename "$f" .v; done | tr '\n' ' ')
  rc=0; "$SCRIPTS/timing-ecp5.sh" --units "$units" --timeout "$timeout" "${place[@]}" || rc=$?
  "$PY" - "$ROOT/docs/figures/timing_ecp5.csv" $units <<'PYEOF'
import csv, sys
rows = {r["unit"]: r for r in csv.DictReader(open(sys.argv[1]))}
for u in sys.argv[2:]:
    r = rows.get(u)
    if r is None or r["status"] != "ok":
        print(f"{u}: {r['status'] if r else 'no row'} (see target/timing-ecp5/{u}/)")
        continue
    print(f"{u}: LFE5U-85F: LUT4 {r['luts']}/83640, FF {r['ffs']}/83640, MULT18X18D {r['dsps']}/156, "
          f"DP16KD {r['ebrs'] or '?'}/208, Fmax {r['fmax_mhz']} MHz ({r['period_ns']} ns), placer {r['placer']}")
PYEOF
  exit $rc
fi
for t in yosys nextpnr-ice40; do
  command -v $t >/dev/null || { echo "fpga.sh: $t not found (apt-get install -y yosys nextpnr-ice40)" >&2; exit 127; }
done
[ $# -gt 0 ] || { sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
status=0
for f in "$@"; do
  unit=$(basename "$f" .v)
  out=$ROOT/target/fpga/$unit
  mkdir -p "$out"
  "$PY" "$SCRIPTS/verilog/prepare.py" --rename-only "$f" --out "$out" --name "$unit"
  if ! yosys -q -l "$out/yosys.log" -p "read_verilog $out/$unit.v; synth_ice40 -top $unit -json $out/$unit.json" >/dev/null; then
    echo "$unit: yosys failed (log $out/yosys.log)"; status=1; continue
  fi
  if nextpnr-ice40 --hx8k --package ct256 --json "$out/$unit.json" --report "$out/report.json" --seed 1 >"$out/nextpnr.log" 2>&1; then
    "$PY" - "$unit" "$out/report.json" <<'PYEOF'
import json, sys
unit, path = sys.argv[1], sys.argv[2]
r = json.load(open(path))
u = r["utilization"]
use = lambda k: f"{u[k]['used']}/{u[k]['available']}" if k in u else "0"
fmax = min((c["achieved"] for c in r.get("fmax", {}).values()), default=None)
f = f"{fmax:.1f} MHz" if fmax else "- (no register-to-register path)"
print(f"{unit}: logic cells {use('ICESTORM_LC')}, RAM {use('ICESTORM_RAM')}, I/O {use('SB_IO')}, Fmax {f}")
PYEOF
  elif grep -qE "ERROR: Unable to (place|find a placement)" "$out/nextpnr.log"; then
    need() { sed -n "s/^Info:[[:space:]]*$1:[[:space:]]*\([0-9]*\)\/.*/\1/p" "$out/nextpnr.log" | head -n 1; }
    echo "$unit: does not fit the HX8K: needs $(need ICESTORM_LC) logic cells of 7680 and $(need SB_IO) I/O of the package's 206"
  else
    echo "$unit: nextpnr failed (log $out/nextpnr.log)"; status=1
  fi
done
exit $status
