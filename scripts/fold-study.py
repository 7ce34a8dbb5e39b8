#!/usr/bin/env python3
"""What area costs in time (docs/explanation/accuracy-cost.md, "What area costs in time"): the default
sweep (vectors/scenes/default.toml: two bunnies, 40 poses, the date05 preset) on the cycle
model with TRI_UNIT folded for each pair interval ii ([timing] tri_interval; 1: unfolded), on
each memory: the preset's (DATE'05's DDR2) and the ideal one (a word every clock, one clock
after the request). One `cchip run --json` per (memory, ii); prints one markdown row each:
TRI_UNIT's Yosys cells at that ii, clocks per query (mean over the 40 poses), the slow-down
against ii = 1, triangle tests per clock, the clocks a leaf pair waited at TRI_UNIT's input
(`back_pressure`: its rhythm or its full FIFO), and the time per query at the scene's clock
(the configuration's measured period, docs/figures/timing_config.csv: the unfolded chip's; the
folded TRI_UNIT's period is not measured).

Usage: scripts/fold-study.py [--cchip PATH]
  --cchip   a built cchip binary (default: `cargo run --release -q --`)
Only the Python 3 standard library is used.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = os.path.join(ROOT, "vectors", "scenes", "default.toml")

INTERVALS = [1, 2, 4, 8, 16, 32]

# TRI_UNIT's Yosys cells (binary32, nearest-even): ii = 1 the unfolded TriUnit, else
# TriUnitFold; the area study's file (scripts/area-study.sh)
AREA = os.path.join(ROOT, "docs", "figures", "area_cells.csv")


def cells():
    """TRI_UNIT's cells by interval, from the area study's file."""
    with open(AREA) as f:
        rows = {r["unit"]: int(r["cells"]) for r in csv.DictReader(f)}
    name = lambda ii: "tri_unit_b32_rne" if ii == 1 else f"tri_unit_fold{ii}_b32_rne"
    missing = [name(ii) for ii in INTERVALS if name(ii) not in rows]
    if missing:
        sys.exit(f"fold-study.py: {AREA} has no row for {', '.join(missing)}: run scripts/area-study.sh --units 'tri_unit*'")
    return {ii: rows[name(ii)] for ii in INTERVALS}

# name, [memory] table (None: the preset's)
MEMORIES = [
    ("DDR date05 (the preset's)", None),
    ("ideal, latency 1", 'model = "ideal"\nlatency = 1\ninterval = 1'),
]


def scene(ii, memory):
    """The default scene with TRI_UNIT's interval `ii`, `memory`, and only the cycle model's
    outputs."""
    with open(DEFAULT) as f:
        text = f.read()
    text = text[: text.index("[outputs]")]
    text += f"[timing]\ntri_interval = {ii}\n\n"
    if memory:
        text += f"[memory]\n{memory}\n\n"
    return text + "[outputs]\ncycles = true\n"


def run(cmd, ii, memory):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, f"fold{ii}.toml")
        with open(path, "w") as f:
            f.write(scene(ii, memory))
        out = subprocess.run(cmd + ["run", "--json", path], cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"fold-study.py: {' '.join(cmd)} run (tri_interval {ii}) failed:\n{out.stderr}")
    return [r["cycles"] for r in json.loads(out.stdout)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cchip", help="a built cchip binary")
    a = ap.parse_args()
    cmd = [a.cchip] if a.cchip else ["cargo", "run", "--release", "-q", "--"]
    area = cells()
    print("| memory | ii | TRI_UNIT cells | clocks / query | x ii = 1 | tri tests / clock | waits at TRI_UNIT / clock | time / query |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, memory in MEMORIES:
        base = None
        for ii in INTERVALS:
            c = run(cmd, ii, memory)
            clocks = sum(x["cycles"] for x in c)
            tri = sum(x["tri_tests"] for x in c)
            waits = sum(x["stats"]["back_pressure"] for x in c)
            periods = {x["period_ns"] for x in c}
            base = base or clocks
            per = clocks / len(c)
            time = " / ".join(f"{per * p / 1000:.2f} us at {p} ns" for p in sorted(periods))
            print(f"| {name} | {ii} | {area[ii]:,} | {per:,.0f} | {clocks / base:.3f} | {tri / clocks:.4f} | {waits / clocks:.3f} | {time} |")


if __name__ == "__main__":
    main()
