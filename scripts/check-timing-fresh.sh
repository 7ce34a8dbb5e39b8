#!/usr/bin/env bash
# Are the checked-in timing tables measured on the current rtl/? Cheap (no EDA tool runs):
# each row's `rtl_sha256` must be the sha256sum of rtl/<unit>.v and a row's unit must still be
# exported, and every exported unit has a row in docs/figures/timing.csv (the ECP5 table,
# docs/figures/timing_ecp5.csv, has rows only for the units it measures).
# Also: every chip's row in timing.csv is set by a datapath unit (its slow stage in the DOP unit
# or TRI_UNIT), so that a format or a rounding, not the control, sets a chip's clock (a chip at
# FPGA depth, `_fpga`, aside: its units are cut for an FPGA).
# Usage: scripts/check-timing-fresh.sh [TABLE ...]   (default: the two tables; what CI runs)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
[ $# -gt 0 ] || set -- docs/figures/timing.csv docs/figures/timing_ecp5.csv
python3 - "$@" <<'PY'
import csv, glob, hashlib, os, sys
rtl = {os.path.basename(f)[:-2]: hashlib.sha256(open(f, 'rb').read()).hexdigest()
       for f in glob.glob('rtl/*.v')}
bad = []
for table in sys.argv[1:]:
    rows = list(csv.DictReader(open(table)))
    if not rows or 'rtl_sha256' not in rows[0]:
        bad.append(f'{table}: no rtl_sha256 column')
        continue
    seen = set()
    for line, r in enumerate(rows, 2):
        u = r['unit']
        seen.add(u)
        if u not in rtl:
            bad.append(f'{table}:{line}: {u}: rtl/{u}.v is no longer exported: delete the row')
        elif r['rtl_sha256'] != rtl[u]:
            bad.append(f'{table}:{line}: {u}: measured on another rtl/{u}.v (sha256 {r["rtl_sha256"][:12]}.., '
                       f'now {rtl[u][:12]}..)')
        # a chip's clock is its datapath's: the slow stage in its DOP unit or TRI_UNIT (WSCG'03's
        # chip: in its core, `core.dop`), not in the glue (D_CNTR, the memory port, the counters;
        # WSCG'03's Stack Engine and Memory Controller), whose paths are cut to be shorter.
        # Not for a chip at FPGA depth (`_fpga`): its units are cut for an FPGA's stages, and
        # on these cells they are faster than the glue the other chips share.
        stage = r.get('slow_stage', '')
        if table.endswith('/timing.csv') and u.startswith('chip_') and not u.endswith('_fpga') \
                and not stage.startswith(('tri_unit', 'dop', 'core.dop')):
            bad.append(f'{table}:{line}: {u}: its period is set by {stage}, not by its DOP unit or TRI_UNIT: '
                       f'cut that glue path (docs/explanation/architecture.md, "Clock period")')
    missing = sorted(set(rtl) - seen)
    if missing and table.endswith('/timing.csv'):
        bad.append(f'{table}: not measured (no row): {" ".join(missing)}')
for b in bad:
    print(b, file=sys.stderr)
if bad:
    print('stale timing tables: re-run scripts/timing-study.sh --units "<unit> ..." '
          '(scripts/timing-ecp5.sh --units "<unit> ..." for timing_ecp5.csv); scripts/README.md', file=sys.stderr)
    sys.exit(1)
print(f'timing tables fresh: {", ".join(sys.argv[1:])} ({len(rtl)} units in rtl/)')
PY
