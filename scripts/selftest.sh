#!/usr/bin/env bash
# Self-test of the Verilog flows on a hand-written demo unit in rust-hdl's style
# (scripts/verilog/selftest/selftest_add8.v: 8-bit adder with carry, latency 2, valid in/out).
#
# Usage: scripts/selftest.sh
# Runs Icarus and Verilator on the demo vectors (back to back, then with bubbles), checks that
# a corrupted vector file makes both fail with a non-zero exit, and synthesizes the unit with
# Yosys. Exits 0 only if every step behaved as expected. Takes a few seconds.

set -euo pipefail
SCRIPTS=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$SCRIPTS/.." && pwd)
D=$SCRIPTS/verilog/selftest
UNIT_FILE=$D/selftest_add8.v
VEC=$D/selftest_add8.hex
TMP=$ROOT/target/verilog/selftest
mkdir -p "$TMP"

echo "== tools"
iverilog -V 2>/dev/null | head -n 1
verilator --version
yosys -V

step() { echo; echo "== $*"; }
fails=0
expect_ok() { if "$@"; then :; else echo "selftest: UNEXPECTED FAILURE: $*" >&2; fails=$((fails + 1)); fi; }
expect_fail() {
  if "$@" > "$TMP/neg.log" 2>&1; then
    cat "$TMP/neg.log"; echo "selftest: corrupted vectors were NOT caught: $*" >&2; fails=$((fails + 1))
  else
    local rc=$?
    grep -E 'MISMATCH|passed,' "$TMP/neg.log"
    echo "(exit $rc, as expected)"
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

step "Yosys synth"
expect_ok "$SCRIPTS/synth.sh" "$UNIT_FILE"

echo
if [ "$fails" = 0 ]; then
  echo "selftest: OK (Icarus, Verilator, Yosys; corrupted vectors caught)"
else
  echo "selftest: $fails step(s) FAILED" >&2
  exit 1
fi
