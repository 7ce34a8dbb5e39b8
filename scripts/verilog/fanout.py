#!/usr/bin/env python3
"""Fanout repair of a mapped Yosys netlist for the timing study (scripts/timing-study.sh).

ABC maps and buffers the logic between registers, but a register's output is an input of
ABC's network, so a flip-flop (DFFPOSX1, the only size in OSU 0.18) may be left driving
hundreds of gates: the pair queue's `order_lifo` drove 254 with 3.65 pF, 3.4 ns of the
flip-flop's clock-to-Q alone. Every placement tool repairs this (OpenROAD `repair_design`,
not in plain OpenSTA); this does the same minimal thing before STA: in each module, every net
(but the clock) with more than FANOUT loads gets a tree of BUFX4 cells, FANOUT loads each.

A load is a standard-cell input pin (weight 1) or a sub-module's input port bit, weighted
by the loads that bit drives inside the sub-module once that module is repaired (at most
FANOUT): so in a hierarchical netlist a net that crosses module boundaries is buffered in
the module that drives it, as in a flat one. Nets joined by `assign` are one net. A
black box's input pin (the bbox flow's cells) is not a load.

Usage: fanout.py IN.v OUT.v [FANOUT]   (prints how many nets and buffers to stderr)
       fanout.py --selftest                (checks the repair on small netlists; CI runs it)
"""
import re
import sys

OUTPUT_PINS = {'Y', 'Q', 'YC', 'YS'}
PIN = re.compile(r'\.(\w+)\(([^(){},]*?)\s*\)')
CELL = re.compile(r'^\s+([A-Z][A-Z0-9]*X\d|DFF\w*|LATCH)\s+(\S+)\s+\((.*?)\);', re.S | re.M)
INST = re.compile(r'^\s+(\\\S+|[A-Za-z_][\w$]*)\s+(\\\S+|[A-Za-z_][\w$]*)\s*\((.*?)\);', re.S | re.M)
DECL = re.compile(r'^\s+(input|output|inout|wire)\s+(?:\[(\d+):(\d+)\]\s+)?(\\\S+|[A-Za-z_][\w$]*)\s*;', re.M)
ASSIGN = re.compile(r'^\s+assign\s+(.*?)\s*=\s*(.*?);', re.S | re.M)
CONN = re.compile(r'\.(\\\S+|[A-Za-z_][\w$]*)\s*\(')
TERM = re.compile(r"\s*(?:(\d+)'[hbdo]([0-9a-fA-FxXzZ_]+)|(\\\S+|[A-Za-z_][\w$]*)\s*(?:\[(\d+)(?::(\d+))?\])?)\s*")


def bits(expr, ranges):
    """The bits of a connection expression, most significant first: a net bit's key
    (`name[i]`, or `name` for a scalar) or None for a constant bit."""
    expr = expr.strip()
    if expr.startswith('{'):
        out = []
        for part in split_concat(expr[1:expr.rindex('}')]):
            out += bits(part, ranges)
        return out
    m = TERM.fullmatch(expr)
    if not m:
        return []
    if m.group(1):
        return [None] * int(m.group(1))
    name, hi, lo = m.group(3), m.group(4), m.group(5)
    if hi is not None:
        lo = hi if lo is None else lo
        step = -1 if int(hi) >= int(lo) else 1
        return [f'{name}[{i}]' for i in range(int(hi), int(lo) + step, step)]
    r = ranges.get(name)
    if r is None:
        return [name]
    step = -1 if r[0] >= r[1] else 1
    return [f'{name}[{i}]' for i in range(r[0], r[1] + step, step)]


def split_concat(text):
    """The comma-separated parts of a concatenation's inside (nested braces kept whole)."""
    parts, depth, last = [], 0, 0
    for i, c in enumerate(text):
        depth += (c == '{') - (c == '}')
        if c == ',' and depth == 0:
            parts.append(text[last:i])
            last = i + 1
    parts.append(text[last:])
    return [p for p in parts if p.strip()]


def key_of_pin(text):
    """A standard-cell pin's net (`\\a.q [3]` -> `\\a.q[3]`)."""
    m = TERM.fullmatch(text.strip())
    if not m or m.group(1):
        return None
    return m.group(3) + (f'[{m.group(4)}]' if m.group(4) is not None else '')


def text_of(key):
    """A net bit's key written back as Verilog."""
    m = re.fullmatch(r'(.*?)\[(\d+)\]', key)
    name, idx = (m.group(1), m.group(2)) if m else (key, None)
    sep = ' ' if name.startswith('\\') else ''
    return f'{name}{sep}[{idx}]' if idx is not None else name + sep


def connections(body):
    """(port, start, end, expr) of each `.port(expr)` of an instance's body."""
    out, pos = [], 0
    while (m := CONN.search(body, pos)):
        depth, i = 1, m.end()
        while depth:
            depth += (body[i] == '(') - (body[i] == ')')
            i += 1
        out.append((m.group(1), m.end(), i - 1, body[m.end():i - 1]))
        pos = i
    return out


class Module:
    def __init__(self, text):
        self.text = text
        self.ranges = {m.group(4): (int(m.group(2)), int(m.group(3)))
                       for m in DECL.finditer(text) if m.group(2) is not None}
        self.ports = {m.group(4) for m in DECL.finditer(text) if m.group(1) in ('input', 'inout')}
        self.alias = {}

    def root(self, k):
        while self.alias.get(k, k) != k:
            k = self.alias[k]
        return k

    def join_assigns(self):
        for m in ASSIGN.finditer(self.text):
            lhs, rhs = bits(m.group(1), self.ranges), bits(m.group(2), self.ranges)
            if len(lhs) != len(rhs):
                continue
            for a, b in zip(lhs, rhs):
                if a and b and a != 'clock' and b != 'clock':
                    ra, rb = self.root(a), self.root(b)
                    if ra != rb:
                        self.alias[ra] = rb


def repair(mod, modules, fanout, counter, allw, weights):
    """The module's text with buffer trees on its high-fanout nets (counter = [nets, buffers]);
    fills weights[port bit] with the loads each input port bit presents to a parent (allw:
    every module's)."""
    text = mod.text
    mod.join_assigns()
    by_net = {}
    for cell in CELL.finditer(text):
        for pin in PIN.finditer(cell.group(3)):
            if pin.group(1) in OUTPUT_PINS:
                continue
            k = key_of_pin(pin.group(2))
            if k and k != 'clock':
                off = cell.start(3)
                by_net.setdefault(mod.root(k), []).append((('pin', (off + pin.start(2), off + pin.end(2))), 1))
    exprs = []  # (start, end, [bit keys], {bit position: new net})
    for inst in INST.finditer(text):
        sub = modules.get(inst.group(1))
        if sub is None:
            continue
        sub_w = weights_of(inst.group(1), modules, fanout, counter, allw)
        for port, start, end, expr in connections(inst.group(3)):
            if port not in sub.ports:
                continue
            port_bits = bits(port, sub.ranges)
            net_bits = bits(expr, mod.ranges)
            if len(port_bits) != len(net_bits):
                continue
            exprs.append((inst.start(3) + start, inst.start(3) + end, net_bits, {}))
            for pos, (pb, nb) in enumerate(zip(port_bits, net_bits)):
                w = sub_w.get(pb, 0)
                if nb and nb != 'clock' and w:
                    by_net.setdefault(mod.root(nb), []).append((('bit', (len(exprs) - 1, pos)), w))
    edits, cells = [], []
    tops = {}
    for net, loads in by_net.items():
        targets = loads
        if sum(w for _, w in loads) > fanout:
            counter[0] += 1
        while sum(w for _, w in targets) > fanout:
            groups, cur, cur_w = [], [], 0
            for t in targets:
                if cur and cur_w + t[1] > fanout:
                    groups.append(cur)
                    cur, cur_w = [], 0
                cur.append(t)
                cur_w += t[1]
            groups.append(cur)
            targets = []
            for group in groups:
                counter[1] += 1
                y = f'_fo{counter[1]}_'
                cells.append([y, None])
                for (kind, what), _ in group:
                    point(kind, what, y, edits, exprs, cells)
                targets.append((('buf', len(cells) - 1), 1))
        for (kind, what), _ in targets:
            if kind == 'buf':
                cells[what][1] = text_of(net)
        tops[net] = sum(w for _, w in targets)
    for start, end, net_bits, new in exprs:
        if new:
            parts = [new.get(i) or (text_of(b) if b else "1'hx") for i, b in enumerate(net_bits)]
            edits.append(((start, end), '{ ' + ', '.join(parts) + ' }'))
    for port in mod.ports:
        for b in bits(port, mod.ranges):
            weights[b] = max(1, tops.get(mod.root(b), 0))
    out, last = [], 0
    for (start, end), net in sorted(edits):
        out += [text[last:start], net + (' ' if net.startswith('\\') and not net.endswith(' ') else '')]
        last = end
    out.append(text[last:])
    text = ''.join(out)
    decl = ''.join(f'  wire {y};\n  BUFX4 {y}b (.A({a}{" " if a.startswith(chr(92)) and not a.endswith(" ") else ""}), .Y({y}));\n'
                   for y, a in cells)
    return text[:text.rindex('endmodule')] + decl + 'endmodule'


def point(kind, what, net, edits, exprs, cells):
    """Connects one load (a pin, a sub-module port bit, a buffer's input) to `net`."""
    if kind == 'pin':
        edits.append((what, net))
    elif kind == 'bit':
        exprs[what[0]][3][what[1]] = net
    else:
        cells[what][1] = net


def weights_of(name, modules, fanout, counter, weights):
    """Module `name` repaired (once) and the load weights of its input port bits."""
    if name not in weights:
        weights[name] = {}
        mod = modules[name]
        mod.text = repair(mod, modules, fanout, counter, weights, weights[name])
    return weights[name]


def repaired(text, fanout=16):
    """`text` repaired, and [nets, buffers]."""
    counter, modules, order = [0, 0], {}, []
    for p in re.split(r'(?m)^(?=module )', text):
        m = re.match(r'module\s+(\\\S+|[A-Za-z_][\w$]*)', p)
        if m and 'endmodule' in p:
            end = p.rindex('endmodule') + 9
            modules[m.group(1)] = Module(p[:end])
            order.append((m.group(1), p[end:]))
        else:
            order.append((None, p))
    weights = {}
    for name, _ in order:
        if name:
            weights_of(name, modules, fanout, counter, weights)
    return ''.join((modules[n].text if n else '') + rest for n, rest in order), counter


def selftest():
    """A flip-flop driving three instances of a module whose input drives 16 gates: 48 loads
    behind three ports, which a repair blind to the ports leaves on the flip-flop."""
    leaf = 'module \\sub (a, y);\n  input a;\n  output [15:0] y;\n' + ''.join(
        f'  INVX1 _{i}_ (.A(a), .Y(y[{i}]));\n' for i in range(16)) + 'endmodule\n'
    top = ('module top(clock, d, y0, y1, y2);\n  input clock;\n  input d;\n  wire q;\n'
           '  output [15:0] y0;\n  output [15:0] y1;\n  output [15:0] y2;\n'
           '  DFFPOSX1 _r_ (.CLK(clock), .D(d), .Q(q));\n'
           + ''.join(f'  \\sub  s{i} (\n    .a(q),\n    .y(y{i})\n  );\n' for i in range(3)) + 'endmodule\n')
    text, (nets, bufs) = repaired(leaf + top, fanout=16)
    # inside each sub nothing (16 loads); in top the flip-flop's net, 48 loads: 3 buffers
    assert (nets, bufs) == (1, 3), (nets, bufs)
    assert text.count('BUFX4') == 3 and '.a(_fo' in text.replace('{ ', '').replace(' }', ''), text
    # the same loads as gates of one flat module: the same three buffers
    flat = ('module top(clock, d);\n  input clock;\n  input d;\n  wire q;\n'
            '  DFFPOSX1 _r_ (.CLK(clock), .D(d), .Q(q));\n'
            + ''.join(f'  INVX1 _{i}_ (.A(q), .Y(_y{i}_));\n' for i in range(48)) + 'endmodule\n')
    assert repaired(flat)[1] == [1, 3]
    print('fanout.py: selftest passed')


def main():
    if sys.argv[1:] == ['--selftest']:
        return selftest()
    src, dst = sys.argv[1], sys.argv[2]
    fanout = int(sys.argv[3]) if len(sys.argv) > 3 else 16
    text, (nets, bufs) = repaired(open(src).read(), fanout)
    open(dst, 'w').write(text)
    print(f'fanout.py: {nets} nets with more than {fanout} loads, {bufs} BUFX4 inserted', file=sys.stderr)


if __name__ == '__main__':
    main()
