#!/usr/bin/env python3
"""Black boxes for the timing study's `--bbox` flow (scripts/timing-study.sh): a chip too large to
synthesize whole in the machine's budget is timed as its glue logic around black boxes, each
black box carrying timing measured by the same flow on the same Verilog.

Walking the chip's instance tree from `top`, a module becomes a black box when
  - unit: its design is that of an exported unit with a row in timing.csv (but for the units
    matching the shell globs of BBOX_GLUE, which stay in the glue: small control units whose
    paths are timed pin to pin there, not by a unit's worst pin figure): compared by a
    canonical hash (module text with every module name replaced by the hash of its own
    design, so the chip's deduplicated module names do not matter), or
  - ram: it is a rust-hdl RAM (`reg [W:0] mem[N:0]`, registered read; Yosys maps it to
    flip-flops and a read multiplexer, as in the whole chip): it is written to
    PARTS/ram_<its canonical hash, 12 digits>.v (a `top` with one `clock` for its read and write
    clocks, as in the chip), which timing-study.sh times like a unit, once per distinct RAM.
Nothing below a black box is looked at.

  bbox.py split CHIP.v TIMING_CSV RTL_DIR WORK PARTS -> WORK/glue.v (the chip with the black boxes'
        definitions replaced by `(* blackbox *)` port lists named BB_<n>), WORK/stubs.v (those
        port lists), WORK/parts.csv (cell, kind, chip module, the unit whose row times it)
  bbox.py lib WORK TIMING_CSV PARTS_CSV LIB TIMING_DIR -> WORK/bbox.lib (one liberty cell per black
        box; a RAM's per-pin setups from TIMING_DIR/<part>/pins.txt, see below)
  bbox.py fold WORK TIMING_CSV PARTS_CSV ROWS   -> the chip's row (the last of ROWS, the glue's as
        timing-study.sh wrote it) with its black boxes folded in: cells and area add theirs
        (per instance in WORK/netlist.v); the period is the largest of the glue's and theirs,
        and names theirs where it is the largest; stage_ns lists them first (`<module>(<unit>):ns`)

The liberty cell of a black box (what is measured, what is assumed):
  - every input pin: a setup check against the rising clock of in_path_ns + setup, where
    in_path_ns is the unit's measured worst input-to-register arrival (inputs at 0 ns) and setup
    = min_period_ns - path_ns of its worst register-to-register path (its flip-flops' setup).
    A unit's worst input's figure is applied to every input (pessimistic). A RAM's are its own
    per address bit and per other port (pins.txt: timing-study.sh times each from that pin
    alone), since the queue pointer's late high bit meets only the last levels of the read
    multiplexer (the 512 x 67 queue bank: 1.15 ns for read_address[8] against 2.20 for the worst
    bit). Pin load: one BUFX4 input
    (assumed: a unit's input as the fanout repair buffers it).
  - every output pin: a clock-to-output arc of out_path_ns (measured: register to output,
    unloaded) plus what the load it drives adds to a DFFPOSX1's clock-to-Q beyond 5 fF
    (assumed: the output is driven like a flip-flop's Q, as a RAM's read data and most units'
    outputs are); the worst output's figure on every output.
  - inputs and outputs have no path between them in the same clock (the units' rows time
    none): timing-study.sh checks each black box with scripts/verilog/comb-paths.sh after
    `split`, and refuses one that has such a path.
  - the black box's own register-to-register period is its row's min_period_ns: the chip's
    period is the largest of the glue's and these.
"""
import csv
import fnmatch
import hashlib
import io
import os
import re
import sys

MODULE = re.compile(r'^module (\S+?)\(.*?^endmodule[^\n]*', re.S | re.M)
INSTANCE = re.compile(r'^\s+(top\$\S+)\s+\S+\(', re.M)
PORT = re.compile(r'^\s*(input|output)\s+(?:wire|reg)?\s*(?:\[(\d+):(\d+)\])?\s*(\S+);', re.M)
RAM = re.compile(r'reg\s*\[\d+:0\]\s*mem\[\d+:0\];')


def modules(path):
    return {m.group(1): m.group(0) for m in MODULE.finditer(open(path).read())}


def canon(mods):
    """module name -> hash of its design (names of it and of the modules it uses left out)."""
    memo = {}

    def h(name):
        if name not in memo:
            body = re.sub(r'//[^\n]*', '', mods[name]).replace(f'module {name}(', 'module (', 1)
            for child in sorted(set(INSTANCE.findall(body)), key=len, reverse=True):
                body = re.sub(rf'(?<![\w$]){re.escape(child)}(?=\s)', h(child), body)
            memo[name] = hashlib.sha256(body.encode()).hexdigest()
        return memo[name]
    return {n: h(n) for n in mods}


def ports(body):
    """[(direction, name, width)] in declaration order."""
    return [(d, n, int(hi) - int(lo) + 1 if hi else 1) for d, hi, lo, n in PORT.findall(body)]


def ram_part(name, body):
    """A RAM module as a unit: `top` drives its read and write clocks from one `clock`."""
    ps = [(d, n, w) for d, n, w in ports(body) if not n.endswith('_clock')]
    decl = ''.join(f'  {d} {"[%d:0] " % (w - 1) if w > 1 else ""}{n};\n' for d, n, w in ps)
    conn = ', '.join([f'.{n}({n})' for _, n, _ in ps] + ['.read_clock(clock)', '.write_clock(clock)'])
    return (body.replace(f'module {name}(', 'module ram(', 1) + '\n\n'
            + f'module top(clock, {", ".join(n for _, n, _ in ps)});\n  input clock;\n{decl}'
            + f'  ram ram({conn});\nendmodule\n')


def split(chip, timing, rtl, work, parts):
    mods = modules(chip)
    ch = canon(mods)
    by_hash = {}
    for r in csv.DictReader(open(timing)):
        f = os.path.join(rtl, r['unit'] + '.v')
        if r['unit'].startswith('chip_') or not r['min_period_ns'] or not os.path.exists(f):
            continue
        if any(fnmatch.fnmatch(r['unit'], g) for g in os.environ.get('BBOX_GLUE', '').split()):
            continue
        by_hash.setdefault(canon(modules(f))['top'], r['unit'])
    boxes, todo, seen = {}, ['top'], set()
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        if name != 'top' and ch[name] in by_hash:
            boxes[name] = ('unit', by_hash[ch[name]])
        elif name != 'top' and RAM.search(mods[name]):
            boxes[name] = ('ram', None)
        else:
            todo += INSTANCE.findall(mods[name])
    os.makedirs(parts, exist_ok=True)
    os.makedirs(work, exist_ok=True)
    src = open(chip).read()
    stubs, rows = [], []
    for i, (name, (kind, unit)) in enumerate(sorted(boxes.items())):
        cell = f'BB_{i}'
        body = mods[name]
        if kind == 'ram':
            unit = 'ram_' + ch[name][:12]
            open(os.path.join(parts, unit + '.v'), 'w').write(ram_part(name, body))
        decl = ''.join(f'  {d} {"[%d:0] " % (w - 1) if w > 1 else ""}{n};\n' for d, n, w in ports(body))
        head = body[:body.index(')') + 1].replace(f'module {name}(', f'module {cell}(', 1)
        stub = f'(* blackbox *)\n{head};\n{decl}endmodule\n'
        stubs.append(stub)
        src = src.replace(body, stub)
        src = re.sub(rf'(?<![\w$]){re.escape(name)}(?=\s)', cell, src)
        rows.append(dict(cell=cell, kind=kind, module=name, unit=unit))
    open(os.path.join(work, 'glue.v'), 'w').write(src)
    open(os.path.join(work, 'stubs.v'), 'w').write(''.join(stubs))
    with open(os.path.join(work, 'parts.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, ['cell', 'kind', 'module', 'unit'], lineterminator='\n')
        w.writeheader()
        w.writerows(rows)
    for r in rows:
        print(f"bbox.py: {r['cell']} = {r['module']} ({r['kind']}: {r['unit']})", file=sys.stderr)


def drive(lib, table):
    """DFFPOSX1's clock-to-Q `table` (cell_rise, ...) at the fastest clock edge: (loads, values)."""
    text = open(lib).read()
    cell = text[text.index('cell (DFFPOSX1)'):]
    t = re.search(rf'{table}\(\w+\)\s*{{\s*index_1\s*\("([^"]*)"\);\s*index_2\s*\("[^"]*"\);\s*values\s*\((.*?)\);', cell[cell.index('pin(Q)'):], re.S)
    rows = re.findall(r'"([^"]*)"', t.group(2))
    return [float(x) for x in t.group(1).split(',')], [float(r.split(',')[0]) for r in rows]


def pin_setups(path):
    """{port or port bit: setup constraint in ns} from a pins.txt (`=== <name>` then
    OpenSTA's `-format end` report of the paths from it: 10 ns - its worst slack)."""
    if not os.path.exists(path):
        return {}
    out = {}
    for m in re.finditer(r'^=== (\S+)\n(.*?)(?=^=== |\Z)', open(path).read(), re.S | re.M):
        s = re.search(r'\s(-?[\d.]+)\s+\((?:MET|VIOLATED)\)', m.group(2))
        if s:
            out[m.group(1)] = 10 - float(s.group(1))
    return out


def setup_arc(clk, v):
    return (f' timing () {{ related_pin : "{clk}"; timing_type : setup_rising; '
            f'rise_constraint(scalar) {{ values ("{v:.4f}"); }} '
            f'fall_constraint(scalar) {{ values ("{v:.4f}"); }} }}')


def lib(work, timing, parts_rows, stdlib, timing_dir):
    rows = {r['unit']: r for r in csv.DictReader(open(timing))}
    rows.update({r['unit']: r for r in csv.DictReader(open(parts_rows))})
    cap = float(re.search(r'cell \(BUFX4\).*?pin\(A\)\s*{[^}]*?capacitance : ([\d.]+)', open(stdlib).read(), re.S).group(1))
    out = ['library (bbox) {', '  delay_model : table_lookup;', '  time_unit : "1ns";', '  voltage_unit : "1V";',
           '  current_unit : "1mA";', '  pulling_resistance_unit : "1kohm";', '  capacitive_load_unit (1,pf);',
           *(f'  {k}_pct_{e} : {v};' for k, v in (('input_threshold', 50), ('output_threshold', 50),
             ('slew_lower_threshold', 10), ('slew_upper_threshold', 90)) for e in ('rise', 'fall')),
           '  lu_table_template(bb_load) { variable_1 : total_output_net_capacitance; '
           'index_1 ("1, 2, 3, 4, 5"); }']
    widths = set()
    cells = []
    stubs = modules(os.path.join(work, 'stubs.v'))
    for p in csv.DictReader(open(os.path.join(work, 'parts.csv'))):
        r = rows[p['unit']]
        setup = float(r['min_period_ns']) - float(r['path_ns'])
        per_pin = pin_setups(os.path.join(timing_dir, p['unit'], 'pins.txt')) if p['kind'] == 'ram' else {}
        pins = []
        for d, n, w in ports(stubs[p['cell']]):
            kind = f'bus ("{n}") {{ bus_type : bb_w{w};' if w > 1 else f'pin ("{n}") {{'
            widths.add(w)
            if 'clock' in n:
                pins.append(f'    pin ("{n}") {{ direction : input; clock : true; capacitance : {cap}; }}')
                continue
            clk = 'write_clock' if n.startswith('write_') else ('read_clock' if p['kind'] == 'ram' else 'clock')
            if d == 'input':
                arc = ''
                if per_pin:
                    bits = [f' pin ("{n}[{i}]") {{{setup_arc(clk, per_pin[f"{n}[{i}]"])} }}'
                            for i in range(w) if f'{n}[{i}]' in per_pin]
                    arc = ''.join(bits) if bits else (setup_arc(clk, per_pin[n]) if n in per_pin else '')
                elif r['in_path_ns']:
                    arc = setup_arc(clk, float(r['in_path_ns']) + setup)
                pins.append(f'    {kind} direction : input; capacitance : {cap};{arc} }}')
            else:
                arc = ''
                if r['out_path_ns']:
                    o = float(r['out_path_ns'])
                    tabs = []
                    for t in ('cell_rise', 'cell_fall', 'rise_transition', 'fall_transition'):
                        loads, vals = drive(stdlib, t)
                        vs = [v - vals[0] + o for v in vals] if t.startswith('cell') else vals
                        tabs.append(f'{t}(bb_load) {{ index_1 ("{", ".join(map(str, loads))}"); '
                                    f'values ("{", ".join(f"{v:.4f}" for v in vs)}"); }}')
                    arc = (f' timing () {{ related_pin : "{clk}"; timing_type : rising_edge; '
                           + ' '.join(tabs) + ' }')
                pins.append(f'    {kind} direction : output;{arc} }}')
        cells.append(f'  cell ({p["cell"]}) {{\n    area : {float(r["area_um2"]):.0f};\n' + '\n'.join(pins) + '\n  }')
    out += [f'  type (bb_w{w}) {{ base_type : array; data_type : bit; bit_width : {w}; bit_from : {w - 1}; '
            f'bit_to : 0; downto : true; }}' for w in sorted(widths) if w > 1]
    out += cells + ['}']
    open(os.path.join(work, 'bbox.lib'), 'w').write('\n'.join(out) + '\n')


def fold(work, timing, parts_csv, rows_file):
    rows = {r['unit']: r for r in csv.DictReader(open(timing))}
    rows.update({r['unit']: r for r in csv.DictReader(open(parts_csv))})
    lines = open(rows_file).read().splitlines()
    head = next(csv.reader([open(timing).readline()]))
    row = dict(zip(head, next(csv.reader([lines[-1]]))))
    used = re.findall(r'^\s*(BB_\d+)\s', open(os.path.join(work, 'netlist.v')).read(), re.M)
    cells, area = int(row['cells']) - len(used), float(row['area_um2'])
    stages = []
    for p in csv.DictReader(open(os.path.join(work, 'parts.csv'))):
        r, n = rows[p['unit']], used.count(p['cell'])
        cells += n * int(r['cells'])
        area += n * float(r['area_um2'])
        mod = p['module'].replace('top$', '', 1).replace('$', '.')
        stages.append((float(r['min_period_ns']), f"{mod}({p['unit']}):{float(r['min_period_ns']):.2f}"))
        if float(r['min_period_ns']) > float(row['min_period_ns'] or 0):
            row.update(min_period_ns=r['min_period_ns'], fmax_mhz=r['fmax_mhz'], path_ns=r['path_ns'],
                       startpoint=f"{mod}({p['unit']}).{r['startpoint']}",
                       endpoint=f"{mod}({p['unit']}).{r['endpoint']}",
                       slow_stage=f"{mod}({p['unit']}).{r['slow_stage']}")
    row.update(cells=str(cells), area_um2=f'{area:.0f}',
               stage_ns=' '.join([t for _, t in sorted(stages, reverse=True)] + [row['stage_ns']]))
    out = io.StringIO()
    csv.writer(out, lineterminator='\n').writerow([row[h] for h in head])
    open(rows_file, 'w').write('\n'.join(lines[:-1] + [out.getvalue()]))


if __name__ == '__main__':
    if len(sys.argv) == 7 and sys.argv[1] == 'split':
        split(*sys.argv[2:])
    elif len(sys.argv) == 7 and sys.argv[1] == 'lib':
        lib(*sys.argv[2:])
    elif len(sys.argv) == 6 and sys.argv[1] == 'fold':
        fold(*sys.argv[2:])
    else:
        sys.exit(__doc__)
