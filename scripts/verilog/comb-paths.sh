#!/usr/bin/env bash
# The outputs of a design that an input reaches in the same clock: one line `<file>: <output>`
# per such output of each FILE's `top` (a Verilog file), nothing for a design whose every
# output comes from a register. Exit 1 if any has one, 2 if Yosys fails.
#
# The timing study's `--bbox` flow (scripts/timing-study.sh) refuses to make a black box of
# such a design: its liberty cell (scripts/verilog/bbox.py) has no input-to-output arc, so
# the chip's path through it would go untimed; leave it in the glue (`--glue`).
#
# How (Yosys, before any mapping: a few seconds, 90 s for a k = 24 TRI_UNIT): `proc; flatten`,
# then the output cone of every input (`%co*`), stopping at flip-flops (a memory's read
# port after `proc` is combinational, its registered data a flip-flop: a RAM's registered
# read stops there), intersected with the outputs.
#   Needs: yosys.   Cache: target/timing/comb/<sha256 of the file>.txt (the result per text).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
CACHE=$ROOT/target/timing/comb
mkdir -p "$CACHE"
FFS='$dff,$adff,$aldff,$dffsr,$dffe,$adffe,$aldffe,$dffsre,$sdff,$sdffe,$sdffce,$dlatch,$adlatch,$dlatchsr'
found=0
for f in "$@"; do
  c=$CACHE/$(sha256sum "$f" | cut -d' ' -f1).txt
  if [ ! -f "$c" ]; then
    yosys -q -p "read_verilog $f; hierarchy -top top; proc; flatten; opt_clean; select -set comb i:* %co*:-$FFS o:* %i; tee -q -o $c.tmp select -list @comb" >/dev/null 2>&1 \
      || { echo "comb-paths.sh: yosys failed on $f" >&2; exit 2; }
    mv "$c.tmp" "$c"
  fi
  while read -r o; do
    [ -n "$o" ] || continue
    echo "$f: ${o#top/}"
    found=1
  done < "$c"
done
exit $found
