#!/usr/bin/env python3
"""The chip's throughput under each memory model (docs/explanation/architecture.md, "Throughput by memory
model"): DOP tests, triangle tests and memory words per clock, where the clocks went, page
hits, misses and bank conflicts, the bus's busy share (clocks carrying data / clocks) and the
node and triangle words (records) per query, on the default sweep of each mesh.

For every mesh and memory model it writes a scene (vectors/scenes/default.toml's sweep and
chip: k = 24, binary32, outward DOP rounding, LIFO, all pairs; `[memory]` set to the model), runs
`cchip run --json` on it (the cycle model, every pose) and prints one markdown row per
(mesh, model), summed over the poses whose root DOPs overlap (more than one DOP test).

Usage: scripts/memory-study.py [--meshes bunny dragon-11k] [--orientations 8] [--timing TOML]
                               [--chip TOML] [--cchip PATH]
  --timing  the scenes' [timing] table, e.g. 'issue_spacing = 1, outstanding = 16, credit = 48,
            prefetch = 14' (the memory port at full speed: docs/explanation/architecture.md, "With
            prefetch"; default: the RTL's parameters after reset)
  --chip    the scenes' [chip] table (default: preset "rtl", the papers' k = 24 binary32
            chip at the RTL's reset values, which --timing overrides), e.g. the RTL chip's
            'k = 6, format = "reduced", dop_rounding = "outward"', or the default's with
            WSCG'03's triangle cache: 'k = 24, format = "binary32", tri_cache = 128'
  --cchip   a built cchip binary (default: `cargo run --release -q --`)
Only the Python 3 standard library is used.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# name, [memory] table, what it stands for (a DDR's times in ns; the models count them in
# the chip's clocks at its period, which the scene's run reports: `memory_clocks`)
MODELS = [
    ("ideal, latency 1", 'model = "ideal"\nlatency = 1\ninterval = 1', "a word every clock, one clock after the request"),
    ("ideal, latency 8", 'model = "ideal"\nlatency = 8\ninterval = 1', "a request every clock, the word 8 clocks later"),
    ("DDR wscg03", 'model = "ddr"\npreset = "wscg03"', "WSCG'03: 4 banks, 4 KiB pages, 256-bit bus, bursts of 8 beats of 3.75 ns, hit 30 ns, miss 75 ns"),
    ("DDR date05", 'model = "ddr"\npreset = "date05"', "DATE'05's 756-bit DDR2 bus (DDR2-800 5-5-5 assumed: bursts of 4 beats of 1.25 ns, hit 17.5 ns, miss 42.5 ns)"),
]


def in_clocks(record):
    """The memory in the chip's clocks (the run's `memory_clocks`): the clocks the bus takes
    per memory word (one burst: a k = 24 binary32 node word or record fits one burst of
    either DDR; the ideal memory here moves a word a clock) and a text."""
    m = record["memory_clocks"]
    if "Ddr" in m:
        d = m["Ddr"]
        return d["burst_clocks"], f"at {record['period_ns']:.3f} ns: a burst {d['burst_clocks']}, a hit {d['hit']}, a miss {d['miss']} clocks"
    return 1, f"at {record['period_ns']:.3f} ns"

DEFAULT = os.path.join(ROOT, "vectors", "scenes", "default.toml")


def scene(mesh, orientations, timing, memory, chip):
    """The default scene (vectors/scenes/default.toml) on `mesh` with `orientations`, the
    given [timing] and [memory] (and [chip], if any), and only the cycle model's outputs."""
    with open(DEFAULT) as f:
        text = f.read()
    text = text[: text.index("[outputs]")]
    # the RTL's reset values under the scene's keys (the default scene's preset is date05's port)
    chip = chip or 'preset = "rtl"'
    text = re.sub(r"(?ms)^\[chip\]\n.*?\n\n", lambda _: f"[chip]\n{chip}\n\n", text, count=1)
    text = re.sub(r'(?m)^([ab]) = ".*"$', lambda m: f'{m.group(1)} = "{mesh}"', text)
    text = re.sub(r"(?m)^orientations = \d+$", f"orientations = {orientations}", text)
    return f"{text}[timing]\n{timing}\n\n[memory]\n{memory}\n\n[outputs]\ncycles = true\nmemory = true\n"


def run(cmd, scene):
    out = subprocess.run(cmd + ["run", "--json", scene], cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"memory-study.py: {' '.join(cmd)} run {scene} failed:\n{out.stderr}")
    return json.loads(out.stdout)


def row(mesh, name, records):
    """The table's row of one mesh and memory, and the memory in the chip's clocks."""
    c = [r["cycles"] for r in records if r.get("cycles") and r["cycles"]["dop_tests"] > 1]
    if not c:
        return f"| {mesh} | {name} | no overlapping pose |", ""
    bus_clocks, clocks_text = in_clocks(c[0])
    if any("tri_fetches_a" not in x.get("stats", {}) for x in c):
        sys.exit("memory-study.py: this study reads DATE'05's chip's counters, and the scenes ran another "
                 "chip (the wscg03 preset selects WSCG'03's): add architecture = \"date05\" to --chip")
    clocks = sum(x["cycles"] for x in c)
    st = lambda k: sum(x["stats"][k] for x in c)
    mem = lambda k: sum(x["memory"][k] for x in c)
    words = mem("node_words") + mem("tri_words")
    pages = mem("page_hits") + mem("page_misses")
    page_hit = f"{100 * mem('page_hits') / pages:.0f}%" if pages else "-"
    tri_tests = sum(x["tri_tests"] for x in c)
    # A's triangle words held when a leaf pair needs them: the triangle cache's hit rate
    a_hit = f"{100 * (1 - st('tri_fetches_a') / tri_tests):.1f}%" if tri_tests else "-"
    return (
        f"| {mesh} | {name} | {len(c)} | {clocks / len(c):,.0f} | {sum(x['dop_tests'] for x in c) / clocks:.3f} | "
        f"{sum(x['tri_tests'] for x in c) / clocks:.3f} | {words / clocks:.3f} | {100 * st('issue') / clocks:.1f} | "
        f"{100 * st('stall_memory') / clocks:.1f} | {100 * st('stall_spacing') / clocks:.1f} | "
        f"{100 * (st('stall_credit') + st('back_pressure')) / clocks:.1f} | {mem('bytes') / len(c) / 1024:,.0f} | "
        f"{page_hit} | {mem('page_misses')} | {mem('bank_conflicts')} | {a_hit} | {100 * words * bus_clocks / clocks:.0f}% | "
        f"{mem('node_words') / len(c):,.0f} | {mem('tri_words') / len(c):,.0f} |",
        clocks_text,
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--meshes", nargs="+", default=["bunny", "dragon-11k"])
    ap.add_argument("--orientations", type=int, default=8)
    ap.add_argument("--timing", default="", help="the scenes' [timing] entries, comma separated")
    ap.add_argument("--chip", default="", help="the scenes' [chip] entries, comma separated (default: the default scene's)")
    ap.add_argument("--cchip", help="a built cchip binary (default: cargo run --release -q --)")
    a = ap.parse_args()
    cmd = [a.cchip] if a.cchip else ["cargo", "run", "--release", "-q", "--"]
    print("| mesh | memory | poses | clocks | DOP tests/clock | tri tests/clock | words/clock | issue% | memory% "
          "| spacing% | credit+bkpres% | KiB/query | page hits | page misses | bank conflicts | A tri hits | bus busy | node words/query "
          "| tri words/query |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    clocks = {}
    with tempfile.TemporaryDirectory() as tmp:
        for mesh in a.meshes:
            for name, memory, _ in MODELS:
                path = os.path.join(tmp, f"{mesh}-{name.replace(' ', '').replace(',', '-')}.toml")
                with open(path, "w") as f:
                    lines = lambda t: "\n".join(x.strip() for x in t.split(","))
                    f.write(scene(mesh, a.orientations, lines(a.timing), memory, lines(a.chip) if a.chip else ""))
                line, clocks[name] = row(mesh, name, run(cmd, path))
                print(line, flush=True)
    print()
    for name, _, what in MODELS:
        print(f"- {name}: {what}; {clocks.get(name) or 'no overlapping pose'}")


if __name__ == "__main__":
    main()
