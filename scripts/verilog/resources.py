#!/usr/bin/env python3
"""FPGA resources of a unit from Yosys `stat -top` (scripts/synth.sh --target ice40|ecp5|xilinx):
the whole hierarchy's cell counts (the table after `=== design hierarchy ===`, or the only
table of a flat run) summed by kind. Prints one line: LUTs (LUT1..LUT6, SB_LUT4 / LUT4),
flip-flops (FD*, SB_DFF*, TRELLIS_FF), shift-register LUTs (SRL*), DSP blocks (DSP48*,
MULT18X18D, SB_MAC16) and block RAMs (RAMB18*/RAMB36* counted as 36 Kb halves: RAMB18 = 0.5,
DP16KD, SB_RAM40_4K).

Usage: scripts/verilog/resources.py STAT_TXT
"""
import re
import sys

KINDS = [  # (label, pattern on the cell type, weight)
    ("LUT", r"LUT[1-6]|SB_LUT4", 1),
    ("FF", r"FD\w*|SB_DFF\w*|TRELLIS_FF", 1),
    ("SRL", r"SRL\w+", 1),
    ("DSP", r"DSP48\w*|MULT18X18D|SB_MAC16", 1),
    ("BRAM36", r"RAMB36\w*|DP16KD|SB_RAM40_4K", 1),
    ("BRAM36", r"RAMB18\w*", 0.5),
]


def main(path):
    text = open(path).read()
    i = text.rfind("=== design hierarchy ===")
    table = text[i:] if i >= 0 else text
    count = {}
    for cell, n in re.findall(r"^\s+([A-Za-z]\w*)\s+(\d+)\s*$", table, re.M):
        for label, pat, w in KINDS:
            if re.fullmatch(pat, cell):
                count[label] = count.get(label, 0) + w * int(n)
    labels = list(dict.fromkeys(label for label, _, _ in KINDS))
    print(", ".join(f"{label} {count.get(label, 0):,g}" for label in labels))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
