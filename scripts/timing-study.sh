#!/usr/bin/env bash
# The timing study: each exported unit's minimum clock
# period and area against the OSU 0.18 um standard cells, pre-layout.
#
# Needs: yosys, OpenSTA (`sta`) and the OSU 0.18 liberty
#   apt-get install -y yosys opensta qflow-tech-osu018
# (LIB defaults to /usr/share/qflow/tech/osu018/osu018_stdcells.lib; set LIB to use another).
#
# Per unit rtl/<unit>.v (top module `top`), flat or hierarchical (--hier):
#   yosys: read_verilog; synth -top top -flatten; dfflibmap -liberty LIB; abc -liberty LIB
#          -script ABC_SCRIPT (Yosys's default mapping, then ABC's `buffer -p; upsize; dnsize`);
#          opt_clean; stat -liberty LIB (cells, area in um^2); write_verilog -noattr
#   fanout: scripts/verilog/fanout.py puts a BUFX4 tree on every net with more than FANOUT
#          (16) loads (register outputs, which ABC does not buffer); a sub-module's input port
#          counts the loads it drives inside (at most FANOUT), so nets that cross module
#          boundaries are repaired in a hierarchical netlist too; its buffers are in the
#          netlist STA times, not in `cells`/`area_um2` (at most 2.3% more cells: fp_mul_b32)
#   hier:  as scripts/synth.sh, every module that instantiates others is kept
#          (`setattr -mod -set keep_hierarchy 1 t:* t:$* %d %m`), so each distinct one (the
#          DOPTRF lane, an FP adder, T.CHECK, ...) is mapped by ABC once, however often it is
#          used; leaf modules (registers, helpers) are flattened into their parents. The
#          mapped modules are then flattened (Yosys `flatten`, no re-mapping; flow `hier+flat`)
#          into the netlist OpenSTA times, so the fanout repair also sees the nets that cross
#          module boundaries. Above FLATTEN_MAX cells (default 650000; the k = 24 DOP unit's
#          620k took Yosys 4 GB and 11 minutes) OpenSTA links the hierarchical netlist instead
#          (`link_design top`, flow `hier`): every path is still timed, across boundaries too,
#          and fanout.py repairs a net that leaves its module in the module that drives it.
#          ABC does not optimize across a kept boundary.
#   bbox:  (--bbox) a chip timed as its glue around black boxes, for the k = 24 chips (3.3-3.6 M
#          cells) that the hier flow cannot synthesize in the machine's budget.
#          scripts/verilog/bbox.py walks the chip's instance tree from `top`; a module becomes a
#          black box when its design is that of an exported unit with a row in --out
#          (TRI_UNIT, the DOP unit or its DOPTRF lanes: equal canonical hashes, whatever the
#          chip's deduplicated module names), or when it is a rust-hdl RAM (D_CNTR's queue banks,
#          the node-word FIFO, the triangle cache's ids and words), which is timed first as a
#          unit of its own, flat, by this script (target/timing/ram_<hash>/, rows kept in
#          target/timing/parts.csv and reused): flip-flops and a read multiplexer, as in the whole
#          chip's netlist. The rest (D_CNTR, the memory port, the cache's control, KLMSEL where
#          the DOP unit has no row, the result port) is synthesized as `hier`, flattened, and
#          timed by OpenSTA with one liberty cell per black box (WORK/bbox.lib):
#            measured: each input's setup = the black box's in_path_ns + its flip-flops' setup
#            (min_period_ns - path_ns), a RAM's per address bit and per other port (timed from
#            that pin alone: target/timing/ram_<hash>/pins.txt); each output's clock-to-output
#            = its out_path_ns; the black box's own register-to-register period = its row's
#            min_period_ns;
#            assumed: a unit's worst input's and output's figure holds for every input and
#            output (pessimistic); an input loads its driver like one BUFX4 input; an output
#            drives its load like a DFFPOSX1's Q; ABC does not optimize across a black
#            box's boundary;
#            checked: no black box has a path from an input to an output in the same clock
#            (scripts/verilog/comb-paths.sh; a unit that has one is refused, to be left in the
#            glue with --glue).
#          The row: min_period_ns = the largest of the glue's worst register/black-box path
#          and the black boxes' own periods (its stage named `<module>(<unit>).<stage>` when a
#          black box's); cells and area add the black boxes' rows per instance; stage_ns lists
#          the black boxes first. Checked on chip_e8m15_k6 against its whole-chip `hier` row
#          (scripts/README.md). With --bbox a chip's work directory holds glue.v, stubs.v,
#          parts.csv (which module is which black box, timed by which row) and bbox.lib;
#          --sta-only re-times its glue netlist with the black boxes' cells made again.
#   each flip-flop instance is renamed after the register net it drives (`s3_nm.q[0]` ->
#   `s3_nm__q_0_`), so a path's start and end name their pipeline stage (rust-hdl: `sK_*`);
#   (hier: after flattening, `doptrf$4.add_2.s1_small.q[0]` -> `doptrf_4__add_2__s1_small__q_0`)
#   sta:   ideal clock of 10 ns on `clock`; the worst register-to-register setup path
#          (report_checks -from [all_registers -clock_pins] -to [all_registers -data_pins]):
#          path_ns = its data arrival (clk-to-q + logic);
#          min_period = 10 - slack = clk-to-q + logic + setup; fmax = 1000 / min_period
#          and the worst such path into each register block (`stage_ns`, `<block>:<ns>`);
#          in_path_ns / out_path_ns: data arrival of the worst input->register and
#          register->output paths (inputs arrive at 0 ns, outputs required at the edge):
#          logic at a unit's ports, which adds to the register driving it in a design
#          (fp_scale's shift sits between its inputs and its output register)
# Writes (updates: rows of units not measured now are kept) the CSV
#   unit,format,rounding,cells,area_um2,path_ns,min_period_ns,fmax_mhz,startpoint,endpoint,slow_stage,in_path_ns,out_path_ns,stage_ns,flow,rtl_sha256
# (flow: flat | hier | hier+flat | bbox; rtl_sha256: sha256sum of the rtl/<unit>.v measured, which
# scripts/check-timing-fresh.sh compares with rtl/ in CI)
# and prints, per format / DOP rounding configuration, the period of its slowest measured unit
# (also written to docs/figures/timing_config.csv, next to --out).
# Work files: target/timing/<unit>/ (netlist.v, stat.txt, sta.tcl, sta.txt, yosys.log).
#
# Usage: scripts/timing-study.sh [--units PATTERNS | --configs-only] [--hier PATTERNS] [--bbox PATTERNS] [--glue PATTERNS] [--out FILE] [--timeout SECONDS]
#   --units    space-separated shell globs on the unit name (default: every rtl/*.v); e.g.
#              --units 'fp_* doptrf_*' for the small ones (seconds to minutes each)
#   --hier     the units synthesized hierarchically (default 'dop_unit_* tcheck_* tri_unit_* chip_*':
#              flat, ABC does not finish them in 20 minutes / 4.7 GB)
#   --bbox     the units timed by the bbox flow (default none), e.g.
#              --units 'chip_b32_k24 chip_e8m15_b32_k24' --bbox 'chip_*'
#              (needs the rows of the units it black-boxes in --out)
#   --glue     units the bbox flow leaves in the glue, not black-boxed (default none): small
#              control units, so that their paths are timed pin to pin, not by the unit's worst
#              input and output figures applied to every pin; e.g. WSCG'03's chip:
#              --units chip_wscg03_b32_k24 --bbox 'chip_*' --glue 'sequencer memory_controller_* tri_input_*'
#   --rtl      the directory of the units' Verilog (default rtl/; the bbox flow's RAM parts)
#   --configs-only  measure nothing: rewrite timing_config.csv from the rows of --out
#   --sta-only re-time the netlists of an earlier run (target/timing/<unit>/netlist_raw.v)
#   --out      default docs/figures/timing.csv
#   --timeout  per unit, Yosys + STA (default 1200 s); a unit that times out is reported, not written
#   MEM_KB     virtual memory limit per tool run (ulimit -v; default 8000000 = 8 GB)
set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
LIB=${LIB:-/usr/share/qflow/tech/osu018/osu018_stdcells.lib}
PY=${PYTHON:-python3}
UNITS='*'
HIER='dop_unit_* tcheck_* tri_unit_* chip_*'
BBOX=
RTL=$ROOT/rtl
PARTS_CSV=$ROOT/target/timing/parts.csv
MEM_KB=${MEM_KB:-8000000}
STA_ONLY=
FLATTEN_MAX=${FLATTEN_MAX:-650000}
# ABC: Yosys's default script for a liberty, then buffering (incl. of ABC's inputs, -p) and gate sizing
ABC_SCRIPT='strash; &get -n; &fraig -x; &put; scorr; dc2; dretime; strash; &get -n; &dch -f; &nf; &put; buffer -p; upsize; dnsize'
FANOUT=${FANOUT:-16}
OUT=$ROOT/docs/figures/timing.csv
TIMEOUT=1200
usage() { sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    --units) UNITS=$2; shift 2 ;;
    --hier) HIER=$2; shift 2 ;;
    --bbox) BBOX=$2; shift 2 ;;
    --glue) export BBOX_GLUE=$2; shift 2 ;;
    --rtl) RTL=$(cd "$2" && pwd); shift 2 ;;
    --configs-only) UNITS=; shift ;;
    --sta-only) STA_ONLY=1; shift ;;
    --out) OUT=$2; shift 2 ;;
    --timeout) TIMEOUT=$2; shift 2 ;;
    -h|--help) usage ;;
    *) echo "timing-study.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done
missing=
command -v yosys >/dev/null || missing="$missing yosys"
command -v sta >/dev/null || missing="$missing opensta"
[ -f "$LIB" ] || missing="$missing qflow-tech-osu018"
if [ -n "$missing" ]; then
  echo "timing-study.sh: missing:$missing (apt-get install -y$missing; or set LIB=<liberty>)" >&2
  exit 127
fi

# One bounded tool run (time and virtual memory).
run() { (ulimit -v "$MEM_KB"; exec timeout "$TIMEOUT" "$@"); }
# bbox: the chip's black boxes (scripts/verilog/bbox.py split); its RAMs timed as units by this
# script (flat, target/timing/ram_<hash>/; rows kept in target/timing/parts.csv, so a RAM timed
# before on the same text is not timed again), then from each input pin alone (pins.txt: per
# address bit, per other port); then the black boxes' liberty cells.
bbox_parts() {
  local f=$1 w=$2 parts=$ROOT/target/timing/parts todo= r d
  "$PY" "$SCRIPTS/verilog/bbox.py" split "$f" "$OUT" "$RTL" "$w" "$parts" || return 1
  # a black box's cell has no input-to-output arc: refuse a box that has such a path
  local boxes
  boxes=$(awk -F, -v rtl="$RTL" -v parts="$parts" 'NR > 1 { print ($2 == "ram" ? parts : rtl) "/" $4 ".v" }' "$w/parts.csv" | sort -u)
  local rc=0
  # shellcheck disable=SC2086
  "$SCRIPTS/verilog/comb-paths.sh" $boxes > "$w/comb.txt" || rc=$?
  if [ $rc = 1 ]; then
    echo "timing-study.sh: $(basename "$f" .v): a black box's output follows its input in the same clock, which its liberty cell does not time; leave the unit in the glue (--glue 'UNIT ...'):" >&2
    sed 's/^/  /' "$w/comb.txt" >&2
  fi
  [ $rc = 0 ] || return 1
  for r in $(awk -F, 'NR > 1 && $2 == "ram" {print $4}' "$w/parts.csv" | sort -u); do
    grep -q "^$r,.*,$(sha256sum "$parts/$r.v" | cut -d' ' -f1)\$" "$PARTS_CSV" 2>/dev/null || todo="$todo $r"
  done
  if [ -n "$todo" ]; then
    "$SCRIPTS/timing-study.sh" --rtl "$parts" --units "$todo" --hier '' --out "$PARTS_CSV" --timeout "$TIMEOUT" || return 1
  fi
  for r in $(awk -F, 'NR > 1 && $2 == "ram" {print $4}' "$w/parts.csv" | sort -u); do
    d=$ROOT/target/timing/$r
    [ "$d/pins.txt" -nt "$d/netlist.v" ] && continue
    cat > "$d/pins.tcl" <<EOF
read_liberty $LIB
read_verilog $d/netlist.v
link_design top
create_clock -name clk -period 10 [get_ports clock]
set_input_delay 0 -clock clk [delete_from_list [all_inputs] [get_ports clock]]
set buses {}
foreach p [delete_from_list [all_inputs] [get_ports clock]] {
  set n [get_full_name \$p]
  regsub {\[[0-9]+\]\$} \$n {} bus
  if {[string match *address* \$n]} {
    puts "=== \$n"
    report_checks -path_delay max -digits 3 -from \$p -to [all_registers -data_pins] -format end
  } elseif {[lsearch \$buses \$bus] < 0} {
    lappend buses \$bus
    puts "=== \$bus"
    report_checks -path_delay max -digits 3 -from [get_ports \$bus*] -to [all_registers -data_pins] -format end
  }
}
EOF
    run sta -no_init -exit "$d/pins.tcl" > "$d/pins.txt" 2>&1 || { echo "timing-study.sh: $r: sta failed (see $d/pins.txt)" >&2; return 1; }
  done
  "$PY" "$SCRIPTS/verilog/bbox.py" lib "$w" "$OUT" "$PARTS_CSV" "$LIB" "$ROOT/target/timing"
}
FILES=()
for u in $UNITS; do
  for f in "$RTL"/$u.v; do [ -f "$f" ] && FILES+=("$f"); done
done
[ ${#FILES[@]} -gt 0 ] || [ -z "$UNITS" ] || { echo "timing-study.sh: no rtl/<unit>.v matches '$UNITS'" >&2; exit 2; }
case $OUT in /*) ;; *) OUT=$PWD/$OUT ;; esac
mkdir -p "$ROOT/target/timing" "$(dirname "$OUT")"
NEW=$(mktemp "$ROOT/target/timing/rows.XXXXXX")
trap 'rm -f "$NEW"' EXIT
status=0
for f in ${FILES[@]+"${FILES[@]}"}; do
  unit=$(basename "$f" .v)
  w=$ROOT/target/timing/$unit
  t0=$(date +%s)
  flow=flat; keep=; stubs=; src=$f
  for h in $HIER; do case $unit in $h) flow=hier; keep='hierarchy -check -top top; setattr -mod -set keep_hierarchy 1 t:* t:$* %d %m;' ;; esac; done
  for h in $BBOX; do case $unit in $h) flow=bbox; src=$w/glue.v; stubs="read_verilog -lib $w/stubs.v;" ;; esac; done
  if [ $flow = bbox ]; then
    [ -n "$STA_ONLY" ] || { rm -rf "$w"; mkdir -p "$w"; }
    bbox_parts "$f" "$w" || { status=1; continue; }
  fi
  if [ -n "$STA_ONLY" ]; then
    [ -f "$w/netlist_raw.v" ] && [ -f "$w/stat.txt" ] || { echo "timing-study.sh: $unit: --sta-only needs $w/netlist_raw.v (run without it first)" >&2; status=1; continue; }
  else
    [ $flow = bbox ] || { rm -rf "$w"; mkdir -p "$w"; }
    echo "$ABC_SCRIPT" > "$w/abc.script"
    if ! run yosys -q -l "$w/yosys.log" -p "read_verilog $src; $keep synth -top top -flatten; dfflibmap -liberty $LIB; abc -liberty $LIB -script $w/abc.script; opt_clean; tee -q -o $w/stat.txt stat -top top -liberty $LIB; write_verilog -noattr $w/netlist_raw.v" >/dev/null 2>&1; then
      echo "timing-study.sh: $unit: yosys failed or timed out after ${TIMEOUT}s (log $w/yosys.log)" >&2
      status=1; continue
    fi
  fi
  # hier: the mapped modules flattened into one netlist (no re-mapping), so that the fanout
  # repair below sees the nets that cross module boundaries too
  # (Yosys needs about 6.5 KB per cell for this: up to FLATTEN_MAX cells; a larger unit is timed
  # hierarchical, flow `hier`)
  mapped=$w/netlist_raw.v
  cells=$(grep -E 'Number of cells:' "$w/stat.txt" | tail -n 1 | tr -dc 0-9)
  if [ $flow != flat ] && [ "$cells" -le "$FLATTEN_MAX" ]; then
    [ $flow = bbox ] || flow=hier+flat
    mapped=$w/netlist_flat.v
    if ! run yosys -q -l "$w/flatten.log" -p "read_liberty -lib $LIB; $stubs read_verilog $w/netlist_raw.v; hierarchy -top top; flatten; opt_clean; write_verilog -noattr $mapped" >/dev/null 2>&1; then
      echo "timing-study.sh: $unit: flattening the mapped netlist failed (log $w/flatten.log)" >&2
      status=1; continue
    fi
  fi
  # Flip-flops named after the net their Q drives.
  "$PY" - "$mapped" "$w/netlist_named.v" <<'PY'
import re, sys
src = open(sys.argv[1]).read()
used = set()
def name(m):
    cell, inst, body = m.group(1), m.group(2), m.group(3)
    q = re.search(r'\.Q\((.*?)\)\s*[,)]?', body, re.S)
    net = q.group(1).strip() if q else ''
    if not net or net.lstrip('\\').startswith('_'):
        return m.group(0)
    net = net.lstrip('\\')
    new = re.sub(r'[^A-Za-z0-9_]+', '_', net.replace('.', '__')).strip('_')
    while new in used:
        new += '_'
    used.add(new)
    return f'{cell} {new} ({body}'
out = re.sub(r'^(\s*DFF\w*|\s*LATCH)\s+(\S+)\s+\((.*?\);)', name, src, flags=re.S | re.M)
open(sys.argv[2], 'w').write(out)
PY
  "$PY" "$SCRIPTS/verilog/fanout.py" "$w/netlist_named.v" "$w/netlist.v" "$FANOUT" 2>> "$w/yosys.log"
  # bbox: the black boxes' liberty cells; the worst path between registers and black boxes is
  # the worst constrained path while the ports are unconstrained (no input/output delay yet)
  if [ $flow = bbox ]; then
    bblib="read_liberty $w/bbox.lib"; worst='report_checks -path_delay max -format full_clock -digits 3'
    ends='report_checks -path_delay max -digits 3 -group_count 1000000 -endpoint_count 1 -format end'
  else
    bblib=; worst='report_checks -path_delay max -format full_clock -digits 3 -from [all_registers -clock_pins] -to [all_registers -data_pins]'
    ends='report_checks -path_delay max -digits 3 -from [all_registers -clock_pins] -to [all_registers -data_pins] -group_count 1000000 -endpoint_count 1 -format end'
  fi
  cat > "$w/sta.tcl" <<EOF
read_liberty $LIB
$bblib
read_verilog $w/netlist.v
link_design top
create_clock -name clk -period 10 [get_ports clock]
puts "=== worst"
$worst
puts "=== endpoints"
$ends
set_input_delay 0 -clock clk [delete_from_list [all_inputs] [get_ports clock]]
set_output_delay 0 -clock clk [all_outputs]
puts "=== in"
report_checks -path_delay max -digits 3 -from [delete_from_list [all_inputs] [get_ports clock]] -to [all_registers -data_pins]
puts "=== out"
report_checks -path_delay max -digits 3 -from [all_registers -clock_pins] -to [all_outputs]
EOF
  if ! run sta -no_init -exit "$w/sta.tcl" > "$w/sta.txt" 2>&1; then
    echo "timing-study.sh: $unit: sta failed (see $w/sta.txt)" >&2; status=1; continue
  fi
  t1=$(date +%s)
  sha=$(sha256sum "$f" | cut -d' ' -f1)
  "$PY" - "$unit" "$w/stat.txt" "$w/sta.txt" "$flow,$sha" >> "$NEW" <<'PY'
import re, sys
unit, stat, sta, tail = sys.argv[1:5]
st = open(stat).read()
cells = int(re.findall(r'Number of cells:\s+(\d+)', st)[-1])
area = float(re.findall(r'Chip area for (?:top )?module .*?:\s+([\d.]+)', st)[-1])
# hier: OpenSTA names instances by path (`doptrf\$4/add_2/s1_small__q_0`): write them as flat ones
def flat(tok):
    inst, pin = re.fullmatch(r'(.*?)(/[A-Z]+\d*)?', tok.replace('\\', '')).groups()
    return inst.replace('$', '_').replace('/', '__') + (pin or '')
txt = re.sub(r'\S*[$/]\S*', lambda m: flat(m.group()), open(sta).read())
worst, rest = txt.split('=== endpoints')
ends, rest = rest.split('=== in')
inp, outp = rest.split('=== out')
def arrival(t):
    m = re.search(r'(-?[\d.]+)\s+data arrival time', t)
    return f'{float(m.group(1)):.3f}' if m else ''
io = f'{arrival(inp)},{arrival(outp)}'
sp = re.search(r'Startpoint: (\S+)', worst); ep = re.search(r'Endpoint: (\S+)', worst)
slack = re.search(r'(-?[\d.]+)\s+slack', worst)
arr = re.search(r'(-?[\d.]+)\s+data arrival time', worst)
parts = unit.split('_')
fmt = '/'.join(p for p in parts if re.fullmatch(r'b32|e\d+m\d+', p)) or '-'  # chip_e8m15_b32_k24: e8m15/b32
rnd = next((p for p in parts if p in ('rne', 'ru', 'rd', 'rz')), '-')
def block(inst):
    # register block: the instance name up to its `__q_N_` / `_N_` bit suffix (`d_cntr__queue__...`
    # is a module named q..., not a suffix)
    q = re.fullmatch(r'(.*)__q(_\d+_?)?', inst)
    b = q.group(1) if q else re.sub(r'_\d+$', '', inst)
    segs = b.split('__')
    m = re.match(r'(s\d+)_', segs[-1])
    if m: segs[-1] = m.group(1)
    return '.'.join(segs)
if not slack:  # no register-to-register path (combinational unit)
    print(f'{unit},{fmt},{rnd},{cells},{area:.0f},,,,-,-,-,{io},-,{tail}'); sys.exit()
STAGES = 200
period = 10 - float(slack.group(1))
stages = {}
for m in re.finditer(r'^(\S+)/D \(\S+\)\s+(-?[\d.]+)\s+(-?[\d.]+)\s+(-?[\d.]+)', ends, re.M):
    b = block(m.group(1)); p = 10 - float(m.group(4))
    stages[b] = max(stages.get(b, 0), p)
order = sorted(stages.items(), key=lambda kv: -kv[1])
sn = ' '.join(f'{b}:{p:.2f}' for b, p in order[:STAGES])  # a chip has tens of thousands of blocks
print(f'{unit},{fmt},{rnd},{cells},{area:.0f},{float(arr.group(1)):.3f},{period:.3f},{1000/period:.1f},'
      f'{sp.group(1)},{ep.group(1)},{block(ep.group(1))},{io},{sn},{tail}')
PY
  [ $flow != bbox ] || "$PY" "$SCRIPTS/verilog/bbox.py" fold "$w" "$OUT" "$PARTS_CSV" "$NEW"
  echo "$(tail -n 1 "$NEW" | cut -d, -f1,4-8,11)  ($((t1 - t0)) s)" >&2
done

# Merge into OUT (replace measured units' rows), then the configurations.
CONF=$(dirname "$OUT")/timing_config.csv
"$PY" - "$OUT" "$NEW" "$CONF" <<'PY'
import csv, os, re, sys
csv.field_size_limit(sys.maxsize)  # a chip's stage_ns lists thousands of register blocks
out, new, conf = sys.argv[1:4]
head = 'unit,format,rounding,cells,area_um2,path_ns,min_period_ns,fmax_mhz,startpoint,endpoint,slow_stage,in_path_ns,out_path_ns,stage_ns,flow,rtl_sha256'.split(',')
rows = {}
if os.path.exists(out):
    for r in csv.DictReader(open(out)): rows[r['unit']] = r
for r in csv.DictReader(open(new), fieldnames=head): rows[r['unit']] = r
rows = [rows[k] for k in sorted(rows)]
with open(out, 'w', newline='') as f:
    w = csv.DictWriter(f, head, lineterminator='\n'); w.writeheader(); w.writerows(rows)
# A configuration = number format x DOP rounding. Its units: those of that format and
# rounding, those of that format without a rounding (fp_scale), the triangle datapath of that
# format (T.CHECK / TRI_UNIT: round to nearest even in every configuration) and the
# format-free ones (pair queue); a folded unit (`_fold<ii>`) only in a chip folded alike. A chip (chip_<dop format>[_<triangle format>]_k<k>) is a
# configuration of its own: its period is that of its own netlist, where every stage, the
# control and the paths between units are timed together; its units' rows (DOP format rounding
# outward, as every chip's lanes: src/chip/rtl.rs; T.CHECK / TRI_UNIT of the triangle
# format; the pair queue) are listed and their slowest given as datapath_* for comparison.
timed = [r for r in rows if r['min_period_ns']]
chip = lambda r: r['unit'].startswith('chip_')
configs = sorted({(r['format'], r['rounding']) for r in timed
                  if r['format'] != '-' and r['rounding'] != '-'
                  and not r['unit'].startswith(('tcheck', 'tri_unit'))})
fold = lambda name: (re.search(r'_fold(\d+)', name) or [None, None])[1]
def member(r, fmt, rnd, tri_fmt=None, k=None, ii=None):
    if chip(r) or (k and r['unit'].startswith('dop_unit_') and f'_k{k}_' not in r['unit']): return False
    if fold(r['unit']) != ii: return False  # a folded unit (tri_unit_fold16_*) is in its folded chips only
    if '_fpga' in r['unit']: return False  # the units at FPGA depth (fp_add_fpga_*) are in no ASIC configuration
    if r['unit'].startswith(('fp_cmp', 'compare_bank', 'dotadd', 'dprime', 'wscg03', 'list_stack', 'tri_input', 'memory_controller', 'sequencer')): return False  # WSCG'03's units: in no DATE'05 chip
    if r['format'] == '-': return True
    if r['unit'].startswith(('tcheck', 'tri_unit')): return r['format'] == (tri_fmt or fmt)
    return r['format'] == fmt and r['rounding'] in (rnd, '-')
def config_row(name, fmt, rnd, m, own=None):
    m = sorted(m, key=lambda r: -float(r['min_period_ns']))
    s = own or m[0]
    d = next((r for r in m if r['format'] != '-'), None)
    i = max((r for r in m if r.get('in_path_ns') and r['format'] != '-'), key=lambda r: float(r['in_path_ns']), default=None)
    return dict(format=fmt, rounding=rnd, min_period_ns=s['min_period_ns'], fmax_mhz=s['fmax_mhz'],
                slowest_unit=s['unit'], slow_stage=s['slow_stage'],
                datapath_period_ns=d['min_period_ns'] if d else '', datapath_unit=d['unit'] if d else '-',
                datapath_stage=d['slow_stage'] if d else '-',
                in_path_ns=i['in_path_ns'] if i else '', in_path_unit=i['unit'] if i else '-',
                units=' '.join(r['unit'] for r in m), config=name)
ch = ('format,rounding,min_period_ns,fmax_mhz,slowest_unit,slow_stage,'
      'datapath_period_ns,datapath_unit,datapath_stage,in_path_ns,in_path_unit,units,config').split(',')
crow = [config_row(f'{fmt} {rnd}', fmt, rnd, [r for r in timed if member(r, fmt, rnd)]) for fmt, rnd in configs]
for c in (r for r in timed if chip(r)):
    dop, tri = (c['format'].split('/') + [None])[:2]
    k = re.search(r'_k(\d+)', c['unit']).group(1)
    crow.append(config_row(c['unit'], c['format'], 'ru', [r for r in timed if member(r, dop, 'ru', tri, k, fold(c['unit']))], c))
with open(conf, 'w', newline='') as f:
    w = csv.DictWriter(f, ch, lineterminator='\n'); w.writeheader(); w.writerows(crow)
fmt = '{:<24} {:>7} {:>11} {:>10} {:>8} {:>8}  {}'
print(fmt.format('unit', 'cells', 'area_um2', 'period_ns', 'fmax', 'in_path', 'slowest reg-to-reg path into'))
for r in rows:
    print(fmt.format(r['unit'], r['cells'], r['area_um2'], r['min_period_ns'] or '-', r['fmax_mhz'] or '-',
                     r.get('in_path_ns') or '-', r['slow_stage']))
print('\nper configuration (format, DOP rounding; a chip): the period of its slowest measured unit (reg-to-reg)')
for c in crow:
    print(f"{c['config']:<20} {c['min_period_ns']:>7} ns {c['fmax_mhz']:>6} MHz: "
          f"{c['slowest_unit']}, path into {c['slow_stage']}; slowest datapath unit "
          f"{c['datapath_unit']} {c['datapath_period_ns']} ns into {c['datapath_stage']}; "
          f"worst datapath input-to-register logic {c['in_path_ns']} ns ({c['in_path_unit']}, its stage 1: "
          f"in a design it follows another unit's register, so add that clock-to-Q and a setup)")
print(f'\nwrote {out} and {conf}')
PY
exit $status
