#!/usr/bin/env bash
# Runs every exported unit rtl/<unit>.v against vectors/<unit>.hex under Icarus Verilog and
# Verilator, then synthesizes all of them with Yosys and prints the cells per unit.
# Exits non-zero on any mismatch, missing vector file, or synthesis failure.
# Usage: scripts/check-rtl.sh [--no-synth] [unit ...]    (default: every rtl/*.v)
# SYNTH_SKIP="unit ..." leaves units out of the Yosys step (their simulations still run).
set -euo pipefail
cd "$(dirname "$0")/.."

synth=1
if [ "${1:-}" = "--no-synth" ]; then synth=0; shift; fi
if [ $# -gt 0 ]; then units=("$@"); else units=(); for f in rtl/*.v; do units+=("$(basename "$f" .v)"); done; fi

# The exported units name their valid ports valid_in / valid_out. rust-hdl's output needs
# -Wno-WIDTH (32-bit literals); the adders' normaliser is a chain of bit fields of one
# signal, which Verilator reports as UNOPTFLAT (a scheduling note, not a loop: Icarus and
# the vectors agree).
ports=(--in-valid valid_in --out-valid valid_out)
export VERILATOR_WNO="${VERILATOR_WNO:--Wno-WIDTH -Wno-UNOPTFLAT}"
fail=0
summary=()
for u in "${units[@]}"; do
  v="vectors/$u.hex"
  if [ ! -f "$v" ]; then echo "missing $v for rtl/$u.v (run: cargo run --release -- vectors)"; fail=1; continue; fi
  for sim in icarus verilator; do
    if out=$("scripts/run-$sim.sh" "rtl/$u.v" "$v" "${ports[@]}" 2>&1); then status=0; else status=$?; fi
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' <<<"$out" | tail -n 1 || true)
    if [ $status = 0 ] && [[ "$line" =~ ^[0-9]+\ passed,\ 0\ failed$ ]]; then
      summary+=("$u $sim: $line")
    else
      summary+=("$u $sim: FAILED (${line:-$(tail -n 1 <<<"$out")})"); fail=1
    fi
  done
done
printf '%s\n' "${summary[@]}"
if [ $synth = 1 ]; then
  files=(); for u in "${units[@]}"; do [[ " ${SYNTH_SKIP:-} " == *" $u "* ]] || files+=("rtl/$u.v"); done
  if ! synth_out=$(scripts/synth.sh "${files[@]}" 2>&1); then echo "$synth_out" | tail -n 20; fail=1; fi
  grep -E '^[a-z0-9_]+ cells: [0-9]+$' <<<"$synth_out" | sort -u
fi
exit $fail
