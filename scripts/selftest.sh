#!/usr/bin/env bash
# Self-test of the Verilog flows on hand-written demo units in rust-hdl's style
# (scripts/verilog/selftest/selftest_add8.v: 8-bit adder with carry, latency 2, valid in/out;
# selftest_kadd8.v: a register file k[0..3] preloaded through load_en/load_addr/load_data, then
# y$0 = a$0 + k[sel], y$1 = a$1 + k[sel ^ 1], latency 2, valid in/out).
#
# The chip flow (scripts/run-chip.sh, verilog/chip_tb.v) on a stand-in chip
# (scripts/verilog/selftest/selftest_chip.v: one request, one result, and a register read
# that the Verilog never initialises).
#
# Usage: scripts/selftest.sh
# Runs Icarus and Verilator on the demo vectors (back to back, then with bubbles), checks that
# a corrupted vector file (a wrong case, a wrong preload value) makes both fail with a non-zero
# exit, that a unit raising out_valid during the preload phase fails, that malformed preload
# sections are rejected by prepare.py naming file and line, and synthesizes the units with
# Yosys, and checks that the timing study's black-box check (verilog/comb-paths.sh) passes the
# adder and finds a path from in_valid to out_valid added to it. Then the chip flow: the stand-in passes its query with that register initialised,
# and fails it under Icarus (four-state: x) and under Verilator with random uninitialised
# bits (--x-seeds) while Verilator's zeros hide the flaw; a wrong counter, a wrong memory
# address and a simulator that exits non-zero after a correct trace each fail too.
# Exits 0 only if every step behaved as expected. Takes about a minute (Verilator builds).

set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
D=$SCRIPTS/verilog/selftest
UNIT_FILE=$D/selftest_add8.v
VEC=$D/selftest_add8.hex
KUNIT=$D/selftest_kadd8.v
KVEC=$D/selftest_kadd8.hex
TMP=$ROOT/target/verilog/selftest
mkdir -p "$TMP"

echo "== tools"
iverilog -V 2>/dev/null | head -n 1
verilator --version
yosys -V

CHIP=$D/selftest_chip.v
step() { echo; echo "== $*"; }
fails=0
expect_ok() { if "$@"; then :; else echo "selftest: UNEXPECTED FAILURE: $*" >&2; fails=$((fails + 1)); fi; }
expect_fail() {
  if "$@" > "$TMP/neg.log" 2>&1; then
    cat "$TMP/neg.log"; echo "selftest: corrupted vectors were NOT caught: $*" >&2; fails=$((fails + 1))
  else
    local rc=$?
    grep -E 'MISMATCH|SPURIOUS|: FAIL|passed,' "$TMP/neg.log"
    echo "(exit $rc, as expected)"
  fi
}

# expect_fail_with <text> <command ...>: fails, and its output contains <text> (the reason).
expect_fail_with() {
  local want=$1; shift
  expect_fail "$@"
  grep -qF -- "$want" "$TMP/neg.log" || { cat "$TMP/neg.log"; echo "selftest: the failure does not say '$want'" >&2; fails=$((fails + 1)); }
}

# prepare.py must reject a malformed vector file (exit 2) with a message containing $1.
expect_error() {
  local want=$1; shift
  if "${PYTHON:-python3}" "$SCRIPTS/verilog/prepare.py" "$@" --out "$TMP/err" > "$TMP/err.log" 2>&1; then
    echo "selftest: malformed vectors were NOT rejected: $*" >&2; fails=$((fails + 1))
  elif ! grep -qF -- "$want" "$TMP/err.log"; then
    cat "$TMP/err.log"; echo "selftest: expected an error containing '$want'" >&2; fails=$((fails + 1))
  else
    grep error "$TMP/err.log"
  fi
}

# A corrupted copy: one expected sum off by one (line 10) and one carry flipped (line 6).
"${PYTHON:-python3}" - "$VEC" "$TMP/selftest_add8.hex" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
f = lines[9].split(); f[2] = "%02x" % ((int(f[2], 16) + 1) % 256); lines[9] = " ".join(f)
f = lines[5].split(); f[3] = "0" if f[3] == "1" else "1"; lines[5] = " ".join(f)
open(sys.argv[2], "w").write("\n".join(lines))
PY
cmp -s "$VEC" "$TMP/selftest_add8.hex" && { echo "selftest: corruption did not change the file" >&2; exit 1; }

# Preload variants of selftest_kadd8.hex (E = error cases, each a full copy with one change):
#   badpre:  k[1] preloaded with 23 instead of 22 (must fail in simulation);
#   E-late:  a preload line moved after the first case;  E-digits: a preload field with 3 digits;
#   E-nohdr: the `// preload:` header dropped;  E-both: `sel` both preloaded and a case field;
#   E-out:   an output preloaded.
# and a mutant unit whose out_valid is also high while load_en is (caught as SPURIOUS).
"${PYTHON:-python3}" - "$KVEC" "$KUNIT" "$TMP" <<'PY'
import sys, os
src, unit, tmp = sys.argv[1:]
lines = open(src).read().split("\n")
def write(name, ls):
    open(os.path.join(tmp, name), "w").write("\n".join(ls))
pre = [i for i, l in enumerate(lines) if l.startswith("@")]
first_case = pre[-1] + 1
i1 = [i for i in pre if lines[i].split()[2] == "01"][0]
bad = list(lines); bad[i1] = bad[i1].replace("@ 1 01 22", "@ 1 01 23"); assert bad != lines
write("badpre.hex", bad)
late = list(lines); late.insert(first_case + 3, late.pop(pre[0])); write("E-late.hex", late)
dig = list(lines); dig[pre[1]] = dig[pre[1]].replace("@ 1 01 22", "@ 1 001 22"); write("E-digits.hex", dig)
write("E-nohdr.hex", [l for l in lines if not l.startswith("// preload:")])
write("E-both.hex", [l.replace("// preload: load_en load_addr load_data", "// preload: load_en load_addr load_data sel") for l in lines])
write("E-out.hex", [l.replace("// preload: load_en load_addr load_data", "// preload: load_en load_addr load_data y$1") for l in lines])
v = open(unit).read()
assert "        out_valid = s2_v$q;" in v
open(os.path.join(tmp, "selftest_kadd8_ov.v"), "w").write(
    v.replace("        out_valid = s2_v$q;", "        out_valid = s2_v$q | load_en;"))
PY

step "Icarus: $VEC"
expect_ok "$SCRIPTS/run-icarus.sh" "$UNIT_FILE" "$VEC" --trace
step "Icarus with an idle cycle after every 3 cases"
expect_ok "$SCRIPTS/run-icarus.sh" "$UNIT_FILE" "$VEC" +bubble=3
step "Icarus, corrupted vectors (must fail)"
expect_fail "$SCRIPTS/run-icarus.sh" "$UNIT_FILE" "$TMP/selftest_add8.hex" --name selftest_add8
step "Icarus, wrong latency (must fail)"
expect_fail "$SCRIPTS/run-icarus.sh" "$UNIT_FILE" "$VEC" --latency 3

step "Verilator: $VEC"
expect_ok "$SCRIPTS/run-verilator.sh" "$UNIT_FILE" "$VEC" --trace
step "Verilator with an idle cycle after every 3 cases"
expect_ok "$SCRIPTS/run-verilator.sh" "$UNIT_FILE" "$VEC" --trace +bubble=3
step "Verilator, corrupted vectors (must fail)"
expect_fail "$SCRIPTS/run-verilator.sh" "$UNIT_FILE" "$TMP/selftest_add8.hex" --name selftest_add8 --trace

step "Icarus, preload: $KVEC"
expect_ok "$SCRIPTS/run-icarus.sh" "$KUNIT" "$KVEC" --trace
step "Icarus, preload, with an idle cycle after every 2 cases"
expect_ok "$SCRIPTS/run-icarus.sh" "$KUNIT" "$KVEC" +bubble=2
step "Icarus, wrong preload value (must fail)"
expect_fail "$SCRIPTS/run-icarus.sh" "$KUNIT" "$TMP/badpre.hex" --name selftest_kadd8
step "Icarus, out_valid high during the preload phase (must fail)"
expect_fail "$SCRIPTS/run-icarus.sh" "$TMP/selftest_kadd8_ov.v" "$KVEC" --name selftest_kadd8
step "Verilator, preload: $KVEC"
expect_ok "$SCRIPTS/run-verilator.sh" "$KUNIT" "$KVEC" --trace +bubble=2
step "Verilator, wrong preload value (must fail)"
expect_fail "$SCRIPTS/run-verilator.sh" "$KUNIT" "$TMP/badpre.hex" --name selftest_kadd8 --trace

step "prepare.py rejects malformed preload sections"
expect_error "E-late.hex:17: preload line after the first case (line 13)" "$KUNIT" "$TMP/E-late.hex"
expect_error "E-digits.hex:7: preload field load_addr = '001' has 3 hex digits" "$KUNIT" "$TMP/E-digits.hex"
expect_error "E-nohdr.hex:5: preload line" "$KUNIT" "$TMP/E-nohdr.hex"
expect_error "preload field 'sel' is also a case field" "$KUNIT" "$TMP/E-both.hex"
expect_error "preload field 'y\$1' is an output" "$KUNIT" "$TMP/E-out.hex"

# The stand-in chip's query (vectors/chip's file formats, scripts/README.md): a register
# write, a memory of eight 32-bit words, the trace and request derived by hand in its
# header; and its variants: the register initialised (the correct chip), a DOP test too
# many, a request to word 6, and a fatal error at the end of the simulation.
Q=$TMP/chip
mkdir -p "$Q"
echo "selftest_query 1 1 1 selftest_chip" >"$Q/queries.txt"
echo "00000000001" >"$Q/selftest_query.host"
for i in 0 1 2 3 4 5 6 7; do printf '%08x\n' $((0x100 + i)); done >"$Q/selftest_query.mem"
printf 'result 3 1 2 0\ndone 3 overflow 0 max_depth 1 dop_tests 1 tri_tests 0 node_fetches 1 tri_fetches 0\n' >"$Q/selftest_query.expect"
echo "request 1 5" >"$Q/selftest_query.requests"
variant() { # <name> <sed script>: the stand-in with its register file initialised, changed
  mkdir -p "$TMP/$1"
  sed "s/^    reg \[31:0\] regs \[0:3\];/&\n    initial regs[3] = 32'h0;/; $2" "$CHIP" >"$TMP/$1/selftest_chip.v"
  cmp -s "$CHIP" "$TMP/$1/selftest_chip.v" && { echo "selftest: variant $1 is the stand-in unchanged" >&2; exit 1; }
  echo "$TMP/$1/selftest_chip.v"
}
# (Verilator's C++ at -O0: the stand-in builds in half the time)
chip() { CHIP_OPT_FAST=-O0 "$SCRIPTS/run-chip.sh" --vectors "$Q" --requests "$@"; }

step "chip flow, Icarus: the stand-in with its register initialised"
expect_ok chip --sim icarus --chip "$(variant init "")"
step "chip flow, Icarus: the stand-in reading its uninitialised register (must fail: x)"
expect_fail_with "overflow x" chip --sim icarus --chip "$CHIP"
step "chip flow, Icarus: a DOP test too many (must fail)"
expect_fail_with "dop_tests 2" chip --sim icarus --chip "$(variant count 's/assign dop_tests = fetched;/assign dop_tests = fetched + 32'"'"'h1;/')"
step "chip flow, Icarus: a request to the wrong word (must fail)"
expect_fail_with "memory requests" chip --sim icarus --chip "$(variant addr "s/assign mem_req_addr = 24'd5;/assign mem_req_addr = 24'd6;/")"
step "chip flow, Icarus: a fatal error after a correct trace (must fail)"
expect_fail_with "the simulator exited with" chip --sim icarus --chip "$(variant fatal 's/^endmodule/    final $fatal(1, "selftest: fatal at the end");\nendmodule/')"
step "chip flow, Verilator: the stand-in as is (zeros hide its uninitialised register)"
expect_ok chip --chip "$CHIP"
step "chip flow, Verilator with random uninitialised bits (must fail)"
expect_fail_with "overflow 1" chip --chip "$CHIP" --x-seeds "1 2 3"

step "Yosys synth"
expect_ok "$SCRIPTS/synth.sh" "$UNIT_FILE" "$KUNIT"

step "the bbox flow's check (comb-paths.sh): a registered unit has no input-to-output path"
expect_ok "$SCRIPTS/verilog/comb-paths.sh" "$UNIT_FILE"
step "the bbox flow's check: out_valid following in_valid in the same clock (must fail, naming it)"
mkdir -p "$TMP/comb"
sed 's/out_valid = s2_v\$q;/out_valid = s2_v$q \& in_valid;/' "$UNIT_FILE" > "$TMP/comb/selftest_add8.v"
rc=0; "$SCRIPTS/verilog/comb-paths.sh" "$TMP/comb/selftest_add8.v" > "$TMP/comb.log" 2>&1 || rc=$?
if [ $rc = 1 ] && grep -qF "selftest_add8.v: out_valid" "$TMP/comb.log"; then
  cat "$TMP/comb.log"; echo "(exit 1, as expected)"
else
  cat "$TMP/comb.log"; echo "selftest: comb-paths.sh did not find in_valid -> out_valid (exit $rc)" >&2; fails=$((fails + 1))
fi

echo
if [ "$fails" = 0 ]; then
  echo "selftest: OK (Icarus, Verilator, Yosys; preload; corrupted vectors caught; the chip flow's checks fail where they must; the black-box check finds a same-clock path)"
else
  echo "selftest: $fails step(s) FAILED" >&2
  exit 1
fi
