#!/usr/bin/env python3
"""Prepare one exported unit for simulation against its vectors.

Reads a rust-hdl export (`rtl/<unit>_<format>.v`, top module `top`) and its TestFloat-style
vector file (`vectors/<unit>_<format>.hex`) and writes, into an output directory:

  <unit>.v       the unit with module `top` renamed to `<unit>` and every `top$child` to
                 `<unit>$child`, so that several units can be compiled together and the
                 VCD scope is named after the unit;
  <unit>.mem     the vectors packed one case per line (one wide hex word: the 32-bit line
                 number of the case in the .hex file, then the fields in header order),
                 which `$readmemh` reads in both Icarus and Verilator;
  <unit>.pre.mem the preload cycles (`@` lines) packed the same way, {line, preload fields}
                 (only if the vector file has a `// preload:` section);
  tb_<unit>.v    the testbench for this unit (see scripts/README.md);
  <unit>.gtkw    a default GTKWave save file (inputs, outputs, valid) for the VCD;

Only the Python 3 standard library is used (python3 is a dependency of verilator and
yosys, so every machine with the tools has it). Errors in the vector file are reported
with file name and line number.
"""
import argparse
import os
import re
import sys

IDENT = r"[A-Za-z_][A-Za-z0-9_$]*"


def die(msg):
    print(f"prepare.py: error: {msg}", file=sys.stderr)
    sys.exit(2)


def strip_comments(src):
    src = re.sub(r"/\*.*?\*/", lambda m: " " * len(m.group(0)), src, flags=re.S)
    return re.sub(r"//[^\n]*", "", src)


def modules(src):
    """{name: body} for every module in the (comment-stripped) source."""
    out = {}
    for m in re.finditer(r"\bmodule\s+(" + IDENT + r")\s*(.*?)\bendmodule\b", src, flags=re.S):
        out[m.group(1)] = m.group(2)
    return out


def ports(body):
    """[(dir, name, width, signed)] in declaration order; non-ANSI (rust-hdl) or ANSI style."""
    found = []
    seen = set()
    decl = re.compile(
        r"\b(input|output|inout)\b\s*(?:wire|reg|logic)?\s*(signed\s+)?"
        r"(?:\[\s*(\d+)\s*:\s*(\d+)\s*\])?\s*((?:" + IDENT + r")(?:\s*,\s*(?!input|output|inout)" + IDENT + r")*)"
    )
    for m in decl.finditer(body):
        d, signed, hi, lo, names = m.groups()
        width = 1 if hi is None else abs(int(hi) - int(lo)) + 1
        for n in re.split(r"\s*,\s*", names.strip()):
            if n and n not in seen and n not in ("wire", "reg", "logic", "signed"):
                seen.add(n)
                found.append((d, n, width, bool(signed)))
    return found


def rename_modules(src, top, unit):
    """Rename module `top` to `unit` and `top$x` to `unit$x`, token by token."""
    names = set(re.findall(r"\bmodule\s+(" + IDENT + r")", src))
    ren = {n: unit + n[len(top):] for n in names if n == top or n.startswith(top + "$")}
    clash = [v for v in ren.values() if v in names and v not in ren]
    if clash:
        die(f"renaming {top} -> {unit} clashes with existing module(s) {clash}")
    tok = re.compile(r'(//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\])*")|(' + IDENT + r")", flags=re.S)
    return tok.sub(lambda m: m.group(0) if m.group(1) else ren.get(m.group(2), m.group(2)), src), ren


def parse_vectors(path):
    """(comments, latency, interval, cases, preload_header, preloads) of a vector file.

    comments: the bodies of the `//`/`#` lines before the first case (header candidates);
    cases, preloads: [(line number, tokens)]; preload_header: (line number, names) of the
    `// preload: ...` line or None. Preload (`@`) lines after the first case are an error."""
    comments = []
    latency = None
    interval = 1
    cases = []
    pre_header = None
    preloads = []
    try:
        f = open(path)
    except OSError as e:
        die(str(e))
    with f:
        for no, line in enumerate(f, 1):
            s = line.strip()
            if not s:
                continue
            if s.startswith("//") or s.startswith("#"):
                body = s.lstrip("/#").strip()
                m = re.match(r"latency\s*[:=]\s*(\d+)\s*$", body)
                mi = re.match(r"interval\s*[:=]\s*(\d+)\s*$", body)
                mp = re.match(r"preload\s*:(.*)$", body)
                if m:
                    latency = int(m.group(1))
                elif mi:
                    interval = int(mi.group(1))
                    if interval < 1:
                        die(f"{path}:{no}: `// interval:` must be at least 1")
                elif mp:
                    if cases:
                        die(f"{path}:{no}: `// preload:` header after the first case (line {cases[0][0]})")
                    if pre_header is not None:
                        die(f"{path}:{no}: second `// preload:` header (the first is line {pre_header[0]})")
                    names = [t for t in re.split(r"[\s,]+", mp.group(1)) if t]
                    if not names:
                        die(f"{path}:{no}: `// preload:` header names no ports")
                    pre_header = (no, names)
                elif body and not cases:
                    comments.append(body)
                continue
            toks = s.split("//")[0].split()
            if s.startswith("@"):
                if cases:
                    die(f"{path}:{no}: preload line after the first case (line {cases[0][0]}); "
                        f"preload lines must come before every case")
                toks = s[1:].split("//")[0].split()
                preloads.append((no, toks))
            else:
                cases.append((no, toks))
    return comments, latency, interval, cases, pre_header, preloads


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("unit_file")
    ap.add_argument("vectors", nargs="?")
    ap.add_argument("--rename-only", action="store_true", help="only write <out>/<unit>.v (for synthesis)")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--name", help="unit name (default: basename of unit_file)")
    ap.add_argument("--top", help="top module in unit_file (default: `top` if present, else the unit name)")
    ap.add_argument("--latency", type=int, help="pipeline latency in cycles (default: `// latency: N` in the vector file)")
    ap.add_argument("--clock", default="clock")
    ap.add_argument("--in-valid", default="in_valid")
    ap.add_argument("--out-valid", default="out_valid")
    ap.add_argument("--fields", help="field names, space separated (default: the vector file's header)")
    ap.add_argument("--preload", help="preload field names, space separated (default: the vector file's "
                    "`// preload:` line)")
    ap.add_argument("--sim", choices=["icarus", "verilator"], default="icarus",
                    help="VCD scope root for the .gtkw: icarus `tb.`, verilator `TOP.tb.`")
    ap.add_argument("--gtkw", help="curated save file (default: scripts/gtkw/<unit>.gtkw if it exists)")
    ap.add_argument("--vcd", help="VCD path the testbench dumps to when compiled with +define+TRACE")
    a = ap.parse_args()

    unit = a.name or os.path.splitext(os.path.basename(a.unit_file))[0]
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", unit):
        die(f"unit name {unit!r} is not a plain Verilog identifier (use --name)")
    try:
        raw = open(a.unit_file).read()
    except OSError as e:
        die(str(e))
    mods = modules(strip_comments(raw))
    if not mods:
        die(f"{a.unit_file}: no module found")
    top = a.top or ("top" if "top" in mods else unit)
    if top not in mods:
        die(f"{a.unit_file}: no module {top!r} (modules: {', '.join(sorted(mods))}); use --top")
    if a.rename_only:
        os.makedirs(a.out, exist_ok=True)
        renamed, _ = rename_modules(raw, top, unit)
        with open(os.path.join(a.out, unit + ".v"), "w") as f:
            f.write(f"// Generated by scripts/verilog/prepare.py from {a.unit_file}: module {top} -> {unit}\n")
            f.write(renamed)
        return
    plist = ports(mods[top])
    if not plist:
        die(f"{a.unit_file}: module {top} has no ports")
    pmap = {n: (d, w, s) for d, n, w, s in plist}
    if a.clock not in pmap or pmap[a.clock][0] != "input":
        die(f"{a.unit_file}: module {top} has no input {a.clock!r} (use --clock)")

    if not a.vectors:
        die("no vector file given")
    comments, hlat, interval, cases, pre_header, preloads = parse_vectors(a.vectors)
    latency = a.latency if a.latency is not None else hlat
    if latency is None:
        die(f"{a.vectors}: no latency: pass --latency N or put a line `// latency: N` in the vector file")
    if latency < 0:
        die("latency must be >= 0")
    if a.fields:
        fields = a.fields.split()
    else:
        # The header: the first comment line before the first case whose words are all ports.
        fields = None
        for c in comments:
            toks = [t for t in re.split(r"[\s,]+", c) if t and t not in ("->", "|", "=", ":")]
            if toks and all(t in pmap for t in toks):
                fields = toks
                break
        if fields is None:
            die(f"{a.vectors}: no header line `// <field> <field> ...` naming ports of {top} "
                f"(ports: {' '.join(n for _, n, _, _ in plist)}); or pass --fields")
    for fld in fields:
        if fld not in pmap:
            die(f"{a.vectors}: header field {fld!r} is not a port of {top} "
                f"(ports: {' '.join(n for _, n, _, _ in plist)})")
        if fld in (a.clock, a.in_valid, a.out_valid):
            die(f"{a.vectors}: field {fld!r} is driven/checked by the testbench itself; drop it from the header")
        if pmap[fld][0] == "inout":
            die(f"port {fld!r} is inout: not supported")
    ins = [f for f in fields if pmap[f][0] == "input"]
    # Preload fields: inputs driven for one cycle per `@` line before the first case.
    if a.preload is not None:
        pfields = a.preload.split()
        pwhere = "--preload"
    elif pre_header is not None:
        pfields = pre_header[1]
        pwhere = f"{a.vectors}:{pre_header[0]}"
    else:
        pfields = []
        pwhere = None
    if preloads and not pfields:
        die(f"{a.vectors}:{preloads[0][0]}: preload line (`@ ...`) but no `// preload: <ports>` header "
            f"(or --preload)")
    for fld in pfields:
        if fld not in pmap:
            die(f"{pwhere}: preload field {fld!r} is not a port of {top} "
                f"(ports: {' '.join(n for _, n, _, _ in plist)})")
        if fld in (a.clock, a.in_valid, a.out_valid):
            die(f"{pwhere}: preload field {fld!r} is driven/checked by the testbench itself")
        if pmap[fld][0] != "input":
            die(f"{pwhere}: preload field {fld!r} is an {pmap[fld][0]}, not an input")
        if fld in fields:
            die(f"{pwhere}: preload field {fld!r} is also a case field; a port is either preloaded or "
                f"driven by the cases")
        if pfields.count(fld) > 1:
            die(f"{pwhere}: preload field {fld!r} named twice")
    if pfields and not preloads:
        print(f"prepare.py: warning: {a.vectors}: no preload lines (`@ ...`): "
              f"{' '.join(pfields)} stay 0", file=sys.stderr)
    outs = [f for f in fields if pmap[f][0] == "output"]
    if not outs:
        die(f"{a.vectors}: no output field in the header")
    has_iv = a.in_valid in pmap and pmap[a.in_valid][0] == "input"
    has_ov = a.out_valid in pmap and pmap[a.out_valid][0] == "output"
    tied = [n for d, n, w, s in plist
            if d == "input" and n not in ins and n not in pfields and n not in (a.clock, a.in_valid)]
    unchecked = [n for d, n, w, s in plist if d == "output" and n not in outs and n != a.out_valid]
    for n in tied:
        print(f"prepare.py: warning: input {n} is not in the vectors: tied to 0", file=sys.stderr)
    if unchecked:
        # An unchecked output would let a wrong unit pass: name every output in the header.
        die(f"{a.vectors}: output(s) {' '.join(unchecked)} of {top} not in the header, so never checked; "
            f"add them to the vector file's header")
    if not has_iv:
        print(f"prepare.py: warning: no input {a.in_valid}: not driven", file=sys.stderr)
    if not has_ov:
        print(f"prepare.py: warning: no output {a.out_valid}: valid not checked", file=sys.stderr)

    # Pack the vectors: {line[31:0], field0, field1, ...}, each field padded to whole hex digits;
    # the preload lines the same way into a second file, {line[31:0], pfield0, pfield1, ...}.
    digits = {f: (pmap[f][1] + 3) // 4 for f in fields + pfields}

    def pack(lines, flds, what):
        out = []
        for no, toks in lines:
            if len(toks) != len(flds):
                die(f"{a.vectors}:{no}: {len(toks)} {what}fields, expected {len(flds)} ({' '.join(flds)})")
            for fld, t in zip(flds, toks):
                if not re.fullmatch(r"[0-9a-fA-F]+", t):
                    die(f"{a.vectors}:{no}: {what}field {fld} = {t!r} is not hex")
                if len(t) != digits[fld]:
                    die(f"{a.vectors}:{no}: {what}field {fld} = {t!r} has {len(t)} hex digits, "
                        f"expected {digits[fld]} (port width {pmap[fld][1]})")
                if int(t, 16) >> pmap[fld][1]:
                    die(f"{a.vectors}:{no}: {what}field {fld} = {t!r} does not fit {pmap[fld][1]} bits")
            out.append(f"{no:08x}" + "".join(t.lower() for t in toks))
        return out

    words = pack(cases, fields, "")
    pwords = pack(preloads, pfields, "preload ")
    if not words:
        die(f"{a.vectors}: no cases")

    os.makedirs(a.out, exist_ok=True)
    renamed, ren = rename_modules(raw, top, unit)
    with open(os.path.join(a.out, unit + ".v"), "w") as f:
        f.write(f"// Generated by scripts/verilog/prepare.py from {a.unit_file}: module {top} -> {unit}\n")
        f.write(renamed)
    mem_path = os.path.join(a.out, unit + ".mem")
    with open(mem_path, "w") as f:
        f.write(f"// {a.vectors}: line {' '.join(fields)} (packed)\n")
        f.write("\n".join(words) + "\n")
    pmem_path = os.path.join(a.out, unit + ".pre.mem")
    if pwords:
        with open(pmem_path, "w") as f:
            f.write(f"// {a.vectors}: line {' '.join(pfields)} (packed preload cycles)\n")
            f.write("\n".join(pwords) + "\n")
    elif os.path.exists(pmem_path):
        os.remove(pmem_path)

    # Field layout in the packed word (MSB first).
    layout = []  # (name, hi, lo) within the word; word width = 32 + sum(4 * digits)
    total = 32 + sum(4 * digits[f] for f in fields)
    pos = total - 32
    for fld in fields:
        pos -= 4 * digits[fld]
        layout.append((fld, pos + pmap[fld][1] - 1, pos))
    ptotal = 32 + sum(4 * digits[f] for f in pfields)
    playout = []
    pos = ptotal - 32
    for fld in pfields:
        pos -= 4 * digits[fld]
        playout.append((fld, pos + pmap[fld][1] - 1, pos))

    def decl(n):
        w = pmap[n][1]
        return f"[{w - 1}:0] " if w > 1 else ""

    L = []
    w = L.append
    w(f"// Generated by scripts/verilog/prepare.py: testbench for {unit} ({a.unit_file})")
    w(f"// vectors {a.vectors}: {len(words)} cases, fields {' '.join(fields)}; latency {latency}")
    if pfields:
        w(f"// preload: {len(pwords)} cycles before the first case ({a.in_valid} low), fields {' '.join(pfields)}; "
          f"0 afterwards")
    w("// Plusargs: +bubble=K (an idle cycle after every K cases; 0 = none), +max_print=N (mismatches printed, default 10)")
    w("`timescale 1ns/1ps")
    w("module tb;")
    w(f"  localparam integer NCASES = {len(words)};")
    w(f"  localparam integer LATENCY = {latency};")
    w(f"  localparam integer INTERVAL = {interval}; // a case only in cycles t = 0 mod INTERVAL")
    w(f"  localparam integer WORD = {total};")
    w("  reg [WORD-1:0] vec [0:NCASES-1];")
    w(f"  localparam integer NPRE = {len(pwords)};")
    if pwords:
        w(f"  localparam integer PWORD = {ptotal};")
        w("  reg [PWORD-1:0] pvec [0:NPRE-1];")
        w("  reg [PWORD-1:0] pcur;")
    w(f"  reg {a.clock} = 1'b0;")
    for n in ins + pfields + tied:
        w(f"  reg {decl(n)}{n} = 0;")
    if has_iv:
        w(f"  reg {decl(a.in_valid)}{a.in_valid} = 0;")
    for n in outs + unchecked:
        w(f"  wire {decl(n)}{n};")
    if has_ov:
        w(f"  wire {decl(a.out_valid)}{a.out_valid};")
    conns = [a.clock] + ins + pfields + tied + ([a.in_valid] if has_iv else []) + outs + unchecked + ([a.out_valid] if has_ov else [])
    order = [n for _, n, _, _ in plist if n in conns]
    w(f"  {unit} {unit} (")
    w(",\n".join(f"    .{n}({n})" for n in order))
    w("  );")
    w("  always #5 " + a.clock + " = ~" + a.clock + ";")
    w("")
    w("  // sched[t % (LATENCY+1)]: case driven at cycle t, or -1 for an idle cycle")
    w("  integer sched [0:LATENCY];")
    w("  integer t, k, next, pnext, due, passed, failed, bubble, since, max_print, printed, tail;")
    w("  reg ok;")
    w("  reg [WORD-1:0] cur;")
    w("  initial begin")
    w(f"    $readmemh(\"{os.path.abspath(mem_path)}\", vec);")
    if pwords:
        w(f"    $readmemh(\"{os.path.abspath(pmem_path)}\", pvec);")
    w("`ifdef TRACE")
    vcd = a.vcd or os.path.join(os.path.abspath(a.out), unit + ".vcd")
    w(f"    $dumpfile(\"{vcd}\");")
    w("    $dumpvars(0, tb);")
    w("`endif")
    w("    if (!$value$plusargs(\"bubble=%d\", bubble)) bubble = 0;")
    w("    if (!$value$plusargs(\"max_print=%d\", max_print)) max_print = 10;")
    w("    passed = 0; failed = 0; printed = 0; next = 0; pnext = 0; since = 0;")
    w("    for (k = 0; k <= LATENCY; k = k + 1) sched[k] = -1;")
    w("    t = 0;")
    w("    // one cycle per iteration: drive at the falling edge, check just after (before the next rising edge)")
    w("    tail = 0;")
    w("    while (pnext < NPRE || next < NCASES || tail <= LATENCY) begin")
    w(f"      @(negedge {a.clock});")
    if pwords:
        w("      if (pnext < NPRE) begin")
        w(f"        // preload cycle: one `@` line of the vector file, {a.in_valid} low, nothing due")
        w("        pcur = pvec[pnext];")
        for fld, hi, lo in playout:
            w(f"        {fld} = pcur[{hi}:{lo}];")
        if has_iv:
            w(f"        {a.in_valid} = 1'b0;")
        w("        sched[t % (LATENCY+1)] = -1;")
        w("        pnext = pnext + 1;")
        w("      end else begin")
    body_start = len(L)
    for fld in pfields:
        w(f"      {fld} = 0;")
    w("      if (next < NCASES && !(bubble > 0 && since == bubble) && t % INTERVAL == 0) begin")
    w("        cur = vec[next];")
    for fld, hi, lo in layout:
        if fld in ins:
            w(f"        {fld} = cur[{hi}:{lo}];")
    if has_iv:
        w(f"        {a.in_valid} = 1'b1;")
    w("        sched[t % (LATENCY+1)] = next;")
    w("        next = next + 1; since = since + 1;")
    w("      end else begin")
    if has_iv:
        w(f"        {a.in_valid} = 1'b0;")
    w("        sched[t % (LATENCY+1)] = -1;")
    w("        since = 0;")
    w("        if (next >= NCASES) tail = tail + 1;")
    w("      end")
    if pwords:
        L[body_start:] = ["  " + x for x in L[body_start:]]
        w("      end")
    w("      #1;")
    w("      begin")
    w("        due = (t >= LATENCY) ? sched[(t - LATENCY) % (LATENCY+1)] : -1;")
    w("        if (due >= 0) begin")
    w("          cur = vec[due];")
    checks = []
    if has_ov:
        checks.append(f"({a.out_valid} === 1'b1)")
    for fld, hi, lo in layout:
        if fld in outs:
            checks.append(f"({fld} === cur[{hi}:{lo}])")
    w("          ok = " + " && ".join(checks) + ";")
    w("          if (ok) passed = passed + 1;")
    w("          else begin")
    w("            failed = failed + 1;")
    w("            if (printed < max_print) begin")
    fmt_in = " ".join(f"{f}=%h" for f in ins)
    fmt_out = " ".join(f"{f}=%h (expected %h)" for f in outs)
    args_in = ", ".join(f"cur[{hi}:{lo}]" for f, hi, lo in layout if f in ins)
    args_out = ", ".join(f"{f}, cur[{hi}:{lo}]" for f, hi, lo in layout if f in outs)
    vfmt = f" {a.out_valid}=%b" if has_ov else ""
    vargs = f", {a.out_valid}" if has_ov else ""
    allargs = ", ".join(x for x in [args_in, args_out] if x)
    w(f"              $display(\"MISMATCH case %0d (line %0d, cycle %0d): {fmt_in} -> {fmt_out}{vfmt}\",")
    w(f"                       due, cur[WORD-1:WORD-32], t, {allargs}{vargs});")
    w("              printed = printed + 1;")
    w("            end")
    w("          end")
    if has_ov:
        w(f"        end else if ({a.out_valid} !== 1'b0) begin")
        w("          failed = failed + 1;")
        w("          if (printed < max_print) begin")
        w(f"            $display(\"SPURIOUS {a.out_valid}=%b at cycle %0d (no case due)\", {a.out_valid}, t);")
        w("            printed = printed + 1;")
        w("          end")
    w("        end")
    w("      end")
    w("      t = t + 1;")
    w("    end")
    w("    if (failed > max_print) $display(\"(%0d more mismatches not printed)\", failed - printed);")
    w("    $display(\"%0d passed, %0d failed\", passed, failed);")
    w("`ifdef TRACE")
    w("    $dumpflush;")
    w("`endif")
    w("    if (failed != 0) begin")
    w("`ifdef VERILATOR")
    w("      $c(\"std::exit(1);\");")
    w("`else")
    w("      $fatal(1, \"vectors failed\");")
    w("`endif")
    w("    end")
    w("    $finish;")
    w("  end")
    w("endmodule")

    # GTKWave save file next to the VCD: the curated scripts/gtkw/<unit>.gtkw (written with
    # `tb.<unit>.` paths) with its dumpfile and, for Verilator, the `TOP.` root fixed; else a
    # default one grouping the unit's inputs, outputs and the testbench's progress counters.
    root = "TOP.tb." if a.sim == "verilator" else "tb."
    curated = a.gtkw or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "gtkw", unit + ".gtkw")
    if os.path.exists(curated):
        src = open(curated).read()
        src = re.sub(r"^\[dumpfile\].*$", f'[dumpfile] "{vcd}"', src, flags=re.M)
        if a.sim == "verilator":
            src = re.sub(r"^(tb\.)", "TOP.tb.", src, flags=re.M)
            src = re.sub(r"^(\[treeopen\]\s*)tb\.", r"\1TOP.tb.", src, flags=re.M)
        gtkw = src
    else:
        def sig(n, scope=unit):
            w_ = pmap[n][1] if n in pmap else 32
            path = f"{root}{scope}.{n}" if scope else f"{root}{n}"
            fmt = "@28" if w_ == 1 else "@22"
            return [fmt, path + (f"[{w_ - 1}:0]" if w_ > 1 else "")]
        g = [f"[*] default save file for {unit}, written by scripts/verilog/prepare.py",
             f'[dumpfile] "{vcd}"', "[timestart] 0", "[size] 1400 700", "[signals_width] 260",
             f"[treeopen] {root}", f"[treeopen] {root}{unit}.", "@800200", "-Inputs"]
        for n in [a.clock] + ([a.in_valid] if has_iv else []) + pfields + ins:
            g += sig(n)
        g += ["@1000200", "-Inputs", "@800200", "-Outputs"]
        for n in ([a.out_valid] if has_ov else []) + outs:
            g += sig(n)
        g += ["@1000200", "-Outputs", "@c00200", "-Testbench"]
        rng = "[31:0]" if a.sim == "verilator" else ""  # Icarus dumps `integer` without a range
        g += ["@24"] + [f"{root}{n}{rng}" for n in ("t", "due", "passed", "failed")]
        g += ["@1000200", "-Testbench"]
        gtkw = "\n".join(g) + "\n"
    with open(os.path.join(a.out, unit + ".gtkw"), "w") as f:
        f.write(gtkw)
    with open(os.path.join(a.out, f"tb_{unit}.v"), "w") as f:
        f.write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
