#!/usr/bin/env bash
# Runs every exported unit rtl/<unit>.v against vectors/<unit>.hex under Icarus Verilog and
# Verilator (the chips, rtl/chip_*.v: whole queries by scripts/run-chip.sh, each also
# compared on its memory requests; under Icarus only the short ones of ICARUS_CHIP_QUERIES,
# a list of `chip:query`; under Verilator every query with uninitialised bits zero, then
# those of X_CHIP_QUERIES once per seed of X_SEEDS with them random, default three seeds
# drawn at random and printed; a chip with no query in either list fails) and synthesizes each with
# Yosys (scripts/synth.sh), printing the cells per unit (and failing if
# docs/figures/area_cells.csv, the area study, disagrees).
# Exits non-zero on any mismatch, missing vector file, or synthesis failure.
# Usage: scripts/check-rtl.sh [--no-synth] [unit ...]    (default: every rtl/*.v)
# SYNTH_SKIP="unit ..." leaves units out of the Yosys step (their simulations still run).
# JOBS=N jobs at a time (default: the number of cores). Simulations and syntheses share the
# pool, the chips' long ones first (the k = 24 chip's Yosys run takes about 6 minutes, the
# k = 6 chip's Verilator build and queries about 7), so that the short ones fill in behind
# them; each writes its own directory under target/verilog/<simulator>/<unit>/ or
# target/synth/<unit>/.
set -euo pipefail
cd "$(dirname "$0")/.."

synth=1
if [ "${1:-}" = "--no-synth" ]; then synth=0; shift; fi
if [ $# -gt 0 ]; then units=("$@"); else units=(); for f in rtl/*.v; do units+=("$(basename "$f" .v)"); done; fi
# Largest Verilog first within the chips and within the units: the longest builds (TRI_UNIT's
# Verilator build takes some 200 s, a small unit's a few) start early, the short ones fill in.
mapfile -t units < <(for u in "${units[@]}"; do echo "$(stat -c %s "rtl/$u.v" 2>/dev/null || echo 0) $u"; done | sort -k1,1nr -k2 | cut -d' ' -f2)

# The pipelined units name their valid ports valid_in / valid_out; units with a ready/valid
# handshake (TRI_UNIT) in_valid / out_valid, the run scripts' defaults. The warnings that
# rust-hdl's output needs off are run-verilator.sh's default (VERILATOR_WNO).
jobs_max=${JOBS:-$(nproc 2>/dev/null || echo 2)}
out_dir=$(mktemp -d)
trap 'rm -rf "$out_dir"' EXIT

# Each chip's queries under Icarus (four-state: an uninitialised bit prints as x; a few
# clocks per second, so the root query only) and, with random uninitialised bits under
# Verilator, queries with triangle tests and results (and, on the k = 6 chip, a FIFO
# traversal that wraps the pair queue's ring of 1,024 entries: the k = 24 chips share its
# Verilog), each once per seed.
ICARUS_CHIP_QUERIES=${ICARUS_CHIP_QUERIES-chip_e8m15_k6:apart_lifo_first chip_b32_k24:k24_apart_lifo_first chip_e8m15_b32_k24:k24r_apart_lifo_first chip_e8m15_k24:k24e_apart_lifo_first chip_e8m10_k24:k24m10_apart_lifo_first chip_e8m15_k6_fold16:fold16_apart_lifo_first chip_e8m15_k6_dop6_tri32:dop6tri32_apart_lifo_first chip_e8m15_k6_dop6_tri32_fpga:dop6tri32fpga_apart_lifo_first chip_b32_k24_q4:k24q4_apart_lifo_first chip_wscg03_b32_k24:w3_apart_first}
X_CHIP_QUERIES=${X_CHIP_QUERIES-chip_e8m15_k6:big_sphere_fifo_prefetch chip_b32_k24:k24_big_sphere_fifo_cache chip_e8m15_b32_k24:k24r_big_sphere_fifo_prefetch chip_e8m15_k24:k24e_rne_patch_fifo_all chip_e8m10_k24:k24m10_rne_patch_fifo_all chip_e8m15_k6_fold16:fold16_patch_fifo_all chip_e8m15_k6_dop6_tri32:dop6tri32_patch_fifo_all chip_e8m15_k6_dop6_tri32_fpga:dop6tri32fpga_patch_fifo_all chip_b32_k24_q4:k24q4_big_sphere_fifo_cache chip_wscg03_b32_k24:w3_big_sphere_all_cache}
X_SEEDS=${X_SEEDS:-$((RANDOM + 1)) $((RANDOM + 1)) $((RANDOM + 1))}

chip_queries() { # <chip> <list of chip:query>: the chip's queries in the list
  local cq
  for cq in $2; do [ "${cq%%:*}" = "$1" ] && echo "${cq#*:}"; done
}

run_one() { # unit simulator (its wall time, build and run, into $out_dir/<unit>.<sim>.t)
  local u=$1 sim=$2 ports=() t0=$SECONDS
  trap 'echo $((SECONDS - t0)) >"$out_dir/$u.$sim.t"' RETURN
  if [[ $u == chip_* ]]; then # whole queries (scripts/run-chip.sh); Icarus only the short ones
    local status=0 qs=() xs=() o=$out_dir/$u.$sim.out
    mapfile -t xs < <(chip_queries "$u" "$X_CHIP_QUERIES")
    if [ "$sim" = icarus ]; then
      mapfile -t qs < <(chip_queries "$u" "$ICARUS_CHIP_QUERIES")
      [ ${#qs[@]} -gt 0 ] || { echo "no Icarus query for $u in ICARUS_CHIP_QUERIES" >"$o"; echo 1 >"$out_dir/$u.$sim.rc"; return; }
    fi
    scripts/run-chip.sh --sim "$sim" --chip "rtl/$u.v" --requests "${qs[@]}" >"$o" 2>&1 || status=$?
    if [ "$sim" = verilator ]; then
      if [ ${#xs[@]} -eq 0 ]; then echo "no X-randomized query for $u in X_CHIP_QUERIES" >>"$o"; status=1
      else
        echo "x seeds: $X_SEEDS" >>"$o"
        scripts/run-chip.sh --sim verilator --chip "rtl/$u.v" --requests --x-seeds "$X_SEEDS" "${xs[@]}" >>"$o" 2>&1 || status=$?
      fi
    fi
    echo "$status" >"$out_dir/$u.$sim.rc"
    return
  fi
  # the top module's own port list (sub-modules such as TRI_UNIT's T.CHECKs have valid_in too)
  if grep -m1 '^module top(' "rtl/$u.v" | grep -Eq '[(,]valid_in[,)]'; then ports=(--in-valid valid_in --out-valid valid_out); fi
  local status=0
  "scripts/run-$sim.sh" "rtl/$u.v" "vectors/$u.hex" "${ports[@]}" >"$out_dir/$u.$sim.out" 2>&1 || status=$?
  echo "$status" >"$out_dir/$u.$sim.rc"
}

run_synth() { # unit (its cells line and stat tables into $out_dir/<unit>.synth.out)
  local u=$1 t0=$SECONDS status=0
  scripts/synth.sh "rtl/$u.v" >"$out_dir/$u.synth.out" 2>&1 || status=$?
  echo "$status" >"$out_dir/$u.synth.rc"
  echo $((SECONDS - t0)) >"$out_dir/$u.synth.t"
}

fail=0
summary=()
jobs_list=() # `unit kind`, the chips first (longest), then the units, each largest first
for pass in chips units; do
  for u in "${units[@]}"; do
    [[ $u == chip_* ]] && [ $pass = units ] && continue
    [[ $u != chip_* ]] && [ $pass = chips ] && continue
    [[ $u == chip_* ]] && vec=vectors/chip/queries.txt || vec=vectors/$u.hex
    if [ ! -f "$vec" ]; then echo "missing $vec for rtl/$u.v (run: cargo run --release -- vectors)"; fail=1; continue; fi
    [ $synth = 1 ] && [[ " ${SYNTH_SKIP:-} " != *" $u "* ]] && jobs_list+=("$u synth")
    jobs_list+=("$u verilator" "$u icarus")
  done
done
for job in "${jobs_list[@]}"; do
  read -r u kind <<<"$job"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
  if [ "$kind" = synth ]; then run_synth "$u" & else run_one "$u" "$kind" & fi
done
wait
cells=()
for job in "${jobs_list[@]}"; do
  read -r u kind <<<"$job"
  out=$(cat "$out_dir/$u.$kind.out"); status=$(cat "$out_dir/$u.$kind.rc"); t=$(cat "$out_dir/$u.$kind.t")
  if [ "$kind" = synth ]; then
    line=$(grep -E "^$u cells: [0-9]+\$" <<<"$out" || true)
    if [ "$status" = 0 ] && [ -n "$line" ]; then cells+=("$line"); summary+=("$u yosys: ${line#* cells: } cells ($t s)")
    else summary+=("$u yosys: FAILED ($(tail -n 1 <<<"$out"))"); fail=1; fi
    continue
  fi
  # a chip under Verilator: its queries, then those with random uninitialised bits
  line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' <<<"$out" | paste -sd';' - | sed 's/;/; x-random: /' || true)
  seeds=$(sed -n 's/^x seeds: //p' <<<"$out")
  if [ "$status" = 0 ] && [ -n "$line" ] && ! grep -Eq '[1-9][0-9]* failed' <<<"$line" && ! grep -Eq '(^|; x-random: )0 passed' <<<"$line"; then
    summary+=("$u $kind: $line${seeds:+ (seeds $seeds)} ($t s)")
  else
    summary+=("$u $kind: FAILED ($(tail -n 1 <<<"$out"))"); fail=1
  fi
done
printf '%s\n' "${summary[@]}"
if [ ${#cells[@]} -gt 0 ]; then
  printf '%s\n' "${cells[@]}"
  # The area study's cells (scripts/area-study.sh) must be these for the units in both.
  area=docs/figures/area_cells.csv
  for c in "${cells[@]}"; do
    read -r u _ n <<<"$c"
    want=$(sed -n "s/^$u,//p" "$area")
    if [ -n "$want" ] && [ "$want" != "$n" ]; then
      echo "$area is stale: $u has $n cells, the file says $want: run scripts/area-study.sh" >&2; fail=1
    fi
  done
fi
exit $fail
