#!/usr/bin/env python3
"""Fanout repair of a mapped Yosys netlist for the timing study (scripts/timing-study.sh).

ABC maps and buffers the logic between registers, but a register's output is an input of
ABC's network, so a flip-flop (DFFPOSX1, the only size in OSU 0.18) may be left driving
hundreds of gates: the pair queue's `order_lifo` drove 254 with 3.65 pF, 3.4 ns of the
flip-flop's clock-to-Q alone. Every placement tool repairs this (OpenROAD `repair_design`,
not in plain OpenSTA); this does the same minimal thing before STA: in each module, every net
(but the clock) with more than FANOUT standard-cell input pins gets a tree of BUFX4 cells,
FANOUT loads each. Loads through a sub-module port stay on the net (the sub-module's own
nets are repaired inside it).

Usage: fanout.py IN.v OUT.v [FANOUT]   (prints how many nets and buffers to stderr)
"""
import re
import sys

OUTPUT_PINS = {'Y', 'Q', 'YC', 'YS'}
PIN = re.compile(r'\.(\w+)\(([^(){},]*?)\s*\)')
CELL = re.compile(r'^\s+([A-Z][A-Z0-9]*X\d|DFF\w*|LATCH)\s+(\S+)\s+\((.*?)\);', re.S | re.M)


def load_pins(module):
    """(start, end, net) of every standard-cell input pin connection of one module."""
    pins = []
    for cell in CELL.finditer(module):
        for pin in PIN.finditer(cell.group(3)):
            if pin.group(1) not in OUTPUT_PINS:
                off = cell.start(3)
                pins.append((off + pin.start(2), off + pin.end(2), pin.group(2).strip()))
    return pins


def repair(module, fanout, counter):
    """The module's text with buffer trees on its high-fanout nets; counter = [nets, buffers]."""
    by_net = {}
    for start, end, net in load_pins(module):
        if net != 'clock' and not net.startswith("1'"):
            by_net.setdefault(net, []).append((start, end))
    edits, cells = [], []
    for net, loads in by_net.items():
        if len(loads) <= fanout:
            continue
        counter[0] += 1
        targets = [('pin', span) for span in loads]
        while len(targets) > fanout:
            groups = [targets[i:i + fanout] for i in range(0, len(targets), fanout)]
            targets = []
            for group in groups:
                counter[1] += 1
                y = f'_fo{counter[1]}_'
                cells.append([y, None])
                for kind, what in group:
                    if kind == 'pin':
                        edits.append((what, y))
                    else:
                        cells[what][1] = y
                targets.append(('buf', len(cells) - 1))
        for kind, what in targets:
            if kind == 'pin':
                edits.append((what, net))
            else:
                cells[what][1] = net
    out, last = [], 0
    for (start, end), net in sorted(edits):
        out += [module[last:start], net + (' ' if net.startswith('\\') else '')]
        last = end
    out.append(module[last:])
    text = ''.join(out)
    decl = ''.join(f'  wire {y};\n  BUFX4 {y}b (.A({a}{" " if a.startswith(chr(92)) else ""}), .Y({y}));\n'
                   for y, a in cells)
    return text[:text.rindex('endmodule')] + decl + 'endmodule'


def main():
    src, dst = sys.argv[1], sys.argv[2]
    fanout = int(sys.argv[3]) if len(sys.argv) > 3 else 16
    counter = [0, 0]
    parts = re.split(r'(?m)^(?=module )', open(src).read())
    text = ''.join(repair(p, fanout, counter) + p[p.rindex('endmodule') + 9:] if 'endmodule' in p else p
                   for p in parts)
    open(dst, 'w').write(text)
    print(f'fanout.py: {counter[0]} nets with more than {fanout} loads, {counter[1]} BUFX4 inserted',
          file=sys.stderr)


if __name__ == '__main__':
    main()
