#!/usr/bin/env bash
# Formal proofs of the chip's control blocks: the pair queue
# (rtl/pair_queue_n4.v), the result port, the memory port, A's triangle cache and TRI_UNIT's
# result FIFO (top$result, top$mem_port, top$tri_cache, top$tri_unit$fifo of
# rtl/chip_e8m15_k6.v); the wrappers in scripts/formal/ around the exported Verilog, unchanged, proven with Yosys and yosys-smtbmc (z3) or, where
# SMT BMC is too slow, Yosys's ABC (`bmc3`). Prints PASS/FAIL per proof (a group of
# properties, listed) and a last line `N passed, M failed`; exits non-zero on a failure.
#
# Needs: yosys (0.23; it ships yosys-smtbmc and yosys-abc) and z3. Debian 12:
#   apt-get install -y yosys z3
# It installs nothing. (Debian's boolector, 1.5.118 from 2012, cannot read yosys-smtbmc's
# SMT-LIB; without --unroll, z3 4.8.12 hangs on the queue's first step, so every SMT run
# uses --unroll.)
#
# Usage: scripts/formal.sh [--all] [--mutate] [proof ...]
#   (default: every proof of PROOFS; names as printed, e.g. pair_queue.bounds)
#   --all     also the proofs of SLOW_PROOFS (and, with --mutate, their SLOW_MUTANTS): each
#             takes over a minute of CPU, so CI leaves them out
#   --mutate  instead runs each hand mutation of MUTANTS below on a copy of the Verilog
#             (sed, under target/formal/mutants/) against the proof it must break, and
#             fails unless every mutant makes its proof fail with a counterexample from the
#             initial state (the failed assertion named on its line); a Yosys error, a solver
#             crash or an induction step failing alone kills no mutant (a control checks it).
# JOBS=N runs N at a time (default: the number of cores).
# Everything goes under target/formal/ (the SMT2/AIGER files, one log per run).
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$root/target/formal
mkdir -p "$out"

mutate=0 all=0
if [ "${1:-}" = "--all" ]; then all=1; shift; fi
if [ "${1:-}" = "--mutate" ]; then mutate=1; shift; fi
only=("$@")

for tool in yosys yosys-smtbmc yosys-abc z3; do
  command -v "$tool" >/dev/null || { echo "formal.sh: $tool not found (apt-get install -y yosys z3)" >&2; exit 2; }
done

# ---- proofs: name | wrapper | DUT Verilog | Yosys lines before write (after reading) | defines | engine | depth | what
# engine: ind = k-induction, depth k/b: yosys-smtbmc BMC to b >= k (the base case) and
#         yosys-smtbmc -i to k (the induction step),
#         bmc = yosys-smtbmc BMC to depth, cover = yosys-smtbmc -c (every cover reached
#         within depth), abc = yosys-abc bmc3 to depth (frames).
PQ_PREP='rename top pair_queue'
PQ_HIER='connect -set f_order_lifo dut.order_lifo$q'
RP_PREP='hierarchy -top \top$result; rename \top$result result_port'
PROOFS=(
  "pair_queue.bounds|pair_queue.sv|rtl/pair_queue_n4.v|BOUNDS|ind|4/20|count <= 16, count/max_count/overflow = the spec's model, empty = (count == 0), full = (count == 16), max_count >= count, overflow sticky until clear, top_data 0 while empty, order latched by clear"
  "pair_queue.step|pair_queue.sv|rtl/pair_queue_n4.v|BOUNDS STEP|ind|4/20|count changes by push + push2 - pop when nothing overflows and no empty pop; LIFO top_data after a push is the last stored pushed entry; FIFO a push into an empty queue becomes top_data; clear empties"
  "pair_queue.order|pair_queue.sv|rtl/pair_queue_n4.v|ORDER|abc|10|tracked (any-constant) entry, FIFO and LIFO: shown on top_data exactly when all entries that leave before it have left, removed by exactly one pop, never shown before it is pushed nor after it is popped"
  "pair_queue.cover|pair_queue.sv|rtl/pair_queue_n4.v|COVER|cover|14|reachable: full, overflow, two stored pushes in a cycle, a stored push2 alone, FIFO and LIFO tracked entry out with 4+ entries held at some point, LIFO full with pop+push+push2"
  "result_port.port|result_port.sv|rtl/chip_e8m15_k6.v|PORT|ind|2/20|open = taken - given (<= 511), give = offered and out_ready, a kept (hit/uncertain) result leaves exactly when the host reads it, shown with its tag and uncertain bit while offered, back-pressure on TRI_UNIT while the host is not ready, a separate result leaves at once unseen, sure_hit"
  "result_port.cover|result_port.sv|rtl/chip_e8m15_k6.v|COVER|cover|8|reachable: back-pressure for two edges, a take and a give at one edge, 3 pairs open, a separate result passing while the host is not ready, an uncertain result read"
  "mem_port.count|mem_port.sv|rtl/chip_e8m15_k6.v|COUNT|ind|2/20|accept = mem_req_valid && mem_req_ready; outstanding (tag_n) = accepted - answered, <= port_out + 1 and <= 16; outstanding flag; accept only with <= port_out outstanding; resp only while one is outstanding (spurious memory responses ignored), and always then"
  "mem_port.order|mem_port.sv|rtl/chip_e8m15_k6.v|ORDER|ind|1/4|each response routed (resp_dst) to the destination of the oldest unanswered accepted request (a FIFO model in the wrapper, which the tag ring holds); at most one triangle word outstanding per triangle destination, its pending flag set exactly then"
  "mem_port.words|mem_port.sv|rtl/chip_e8m15_k6.v|WORDS|ind|1/6|node-word FIFOs wa, wb under D_CNTR's rules (read only when not empty; never a 17th word, assumed): count = answered - taken (<= 16), empty flags, tail = head + count; a tracked word (either side, any value) is the DOP unit's word at the issue that takes it, after exactly the words answered before it, and of the later pairs that share it"
  "mem_port.cover|mem_port.sv|rtl/chip_e8m15_k6.v|COVER|cover|20|reachable: 16 outstanding, a request and a response at one edge, a spurious memory response ignored, responses to all four destinations"
  "tri_cache.cache|tri_cache.sv|rtl/chip_e8m15_k6.v|CACHE|bmc|5|tracked (any-constant) triangle id, any stale RAM contents, any mask: a hit only after its fill since the last clear, a hit returns its last fill's word (also through the bypass of a fill into the line being read), found while its line holds it"
  "tri_cache.cover|tri_cache.sv|rtl/chip_e8m15_k6.v|COVER|cover|8|reachable: a hit through the bypass, a hit from the RAM, a miss after another id took the line, a miss after a clear, the highest line"
  "tri_fifo.count|tri_fifo.sv|rtl/chip_e8m15_k6.v|COUNT|ind|1/12|any writes and reads: held = accepted writes - accepted reads (<= 256; a write accepted below 256, a read while one is readable, one edge after its write), addresses that far apart, empty/almost_empty = none readable, full = 256 held, almost_full = 255+ readable, overflow/underflow sticky and raised exactly by a write into a full FIFO/a read of an empty one; under TRI_UNIT's rules (assumed) never raised"
  "tri_fifo.order|tri_fifo.sv|rtl/chip_e8m15_k6.v|COUNT ORDER|ind|1/8|tracked (any-constant) accepted entry: its RAM row holds it while held, shown on data_out whenever at the head and readable, leaves with exactly one read after exactly the entries accepted before it"
  "list_stack.chain|list_stack.sv|rtl/list_stack_a8.v|CHAIN|ind|2/4|WSCG'03's Stack Engine's lists: start_s[j+1] = start_s[j] + len_s[j] for every level j <= λ and side (contiguous, the live lists never overlap), start_s[0] = 0, every list within its SRAM for j <= λ + 1, the read position within the current list, remaining = its pointers not read (0 while busy or done), branch = the current level's branch bit, level λ + 1's write addresses its lists' ends, overflow sticky until clear, clear empties"
  "tri_fifo.cover|tri_fifo.sv|rtl/chip_e8m15_k6.v|COVER|cover|8|reachable: a write and a read at one edge, a read while the one entry held is not yet readable, entries after an ignored read of an empty FIFO, an entry read after two ahead of it, 3 readable"
)

# proofs run only with --all (over a minute of CPU each)
SLOW_PROOFS=(
  "list_stack.cover|list_stack.sv|rtl/list_stack_a8.v|COVER|cover|7|reachable: level 3, a right list read after stepping up, done after a descent, a list of 2 read to its end"
  "mem_port.ask|mem_port.sv|rtl/chip_e8m15_k6.v|ASK|ind|1/4|ask list (at most 32 words, assumed): a tracked fetched word of a pop (A0 B0 A1 B1) requested once, after exactly the words asked before it, with its side, at its record's address (map 0), at prefetch 0 only for the current pair, offered whenever at the head and allowed; no node request from an empty list"
)

# ---- mutants: name | proof it must break | DUT Verilog | sed script (applied to a copy)
# A mutant is killed only by a counterexample from the initial state; a control (control_*)
# breaks the Verilog instead and must fail without one (not counted as a kill).
MUTANTS=(
  "s2_room_off_by_one|pair_queue.bounds|rtl/pair_queue_n4.v|s/s2 = two \& ((do_pop \& nfull) | spare);/s2 = two \& ((do_pop \& nfull) | nfull);/"
  "full_flag_at_15|pair_queue.bounds|rtl/pair_queue_n4.v|s/full = cnt\$q == c_cap;/full = cnt\$q == c_cap - 5'h1;/"
  "max_count_lags|pair_queue.bounds|rtl/pair_queue_n4.v|s/if (cnt_n > max_r\$q) begin/if (cnt_n > max_r\$q + 5'h1) begin/"
  "overflow_not_sticky|pair_queue.bounds|rtl/pair_queue_n4.v|s/ovf_r\$d = ovf_r\$q;/ovf_r\$d = 1'b0;/"
  "overflow_on_one_push|pair_queue.bounds|rtl/pair_queue_n4.v|s/if ((any \& ~s1) | (two \& ~s2)) begin/if ((any \& ~s1)) begin/"
  "lifo_push2_top_is_push|pair_queue.step|rtl/pair_queue_n4.v|/if (order_lifo\$q) begin/,/else begin/s/top_r\$d = push2_data;/top_r\$d = e1;/"
  "fifo_rd_ptr_stuck|pair_queue.order|rtl/pair_queue_n4.v|s/rd_n = rd_ptr\$q + 32'h1;/rd_n = rd_ptr\$q;/"
  "no_bypass|pair_queue.order|rtl/pair_queue_n4.v|s/byp\$d = (we_a \& hit_a) | (we_b \& hit_b);/byp\$d = 1'b0;/"
  "result_hides_uncertain|result_port.port|rtl/chip_e8m15_k6.v|s/keep = out_hit | out_uncertain;/keep = out_hit;/"
  "result_open_no_decrement|result_port.port|rtl/chip_e8m15_k6.v|s/open_r\$d = open_r\$q - 32'h1;/open_r\$d = open_r\$q;/"
  "result_separate_waits|result_port.port|rtl/chip_e8m15_k6.v|s/give = out_valid \& (res_ready | ~keep);/give = out_valid \& res_ready;/"
  "mem_credit_off_by_one|mem_port.count|rtl/chip_e8m15_k6.v|s/port_free = tag_n\$q <= ((port_out) \& 5'h1f);/port_free = tag_n\$q <= ((port_out) \& 5'h1f) + 5'h1;/"
  "mem_resp_unguarded|mem_port.count|rtl/chip_e8m15_k6.v|s/resp = mem_resp_valid \& (tag_n\$q != 32'h0);/resp = mem_resp_valid;/"
  "mem_tag_head_stuck|mem_port.order|rtl/chip_e8m15_k6.v|s/tag_head\$d = tag_head\$q + 32'h1;/tag_head\$d = tag_head\$q;/"
  "mem_tag_written_at_head|mem_port.order|rtl/chip_e8m15_k6.v|s/tags\$wsel = c_one16 << tag_tail\$q;/tags\$wsel = c_one16 << tag_head\$q;/"
  "mem_ta_pend_not_cleared|mem_port.order|rtl/chip_e8m15_k6.v|s/ta_pend\$d = 1'b0;/ta_pend\$d = ta_pend\$q;/"
  "mem_wa_head_stuck|mem_port.words|rtl/chip_e8m15_k6.v|s/wa_head\$d = wa_head\$q + 32'h1;/wa_head\$d = wa_head\$q;/"
  "mem_na_word_not_latched|mem_port.words|rtl/chip_e8m15_k6.v|s/na_word\$d = wa\$rdata;/na_word\$d = na_word\$q;/"
  "cache_no_bypass|tri_cache.cache|rtl/chip_e8m15_k6.v|s/byp\$d = fill \& (fill_line == next_line);/byp\$d = 1'b0;/"
  "cache_valid_not_cleared|tri_cache.cache|rtl/chip_e8m15_k6.v|/if (clear) begin/,/end/s/valid\$d = 32'h0;/valid\$d = valid\$q;/"
  "cache_hit_ignores_id|tri_cache.cache|rtl/chip_e8m15_k6.v|s/hit = ((valid\$q \& (c_one128 << line)) != 32'h0) \& (held_id == id);/hit = ((valid\$q \& (c_one128 << line)) != 32'h0);/"
  "tri_fifo_read_when_empty|tri_fifo.count|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.read_logic(/,/^endmodule/s/if (read \& ~is_empty) begin/if (read) begin/"
  "tri_fifo_underflow_not_sticky|tri_fifo.count|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.read_logic(/,/^endmodule/s/dff_underflow\$d = dff_underflow\$q | (is_empty \& read);/dff_underflow\$d = is_empty \& read;/"
  "tri_fifo_overflow_on_any_write|tri_fifo.count|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.write_logic(/,/^endmodule/s/dff_overflow\$d = dff_overflow\$q | (is_full \& write);/dff_overflow\$d = dff_overflow\$q | write;/"
  "tri_fifo_head_not_advanced|tri_fifo.order|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.read_logic(/,/^endmodule/s/ram_read_address = (((read_address\$q + 32'h1) \& fifo_address_mask) \& 8'hff);/ram_read_address = ((read_address\$q \& fifo_address_mask) \& 8'hff);/"
  "tri_fifo_written_a_row_late|tri_fifo.order|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.write_logic(/,/^endmodule/s/ram_write_address = ((write_address\$q \& fifo_address_mask) \& 8'hff);/ram_write_address = (((write_address\$q + 9'h1) \& fifo_address_mask) \& 8'hff);/"
  "tri_fifo_entry_changed|tri_fifo.order|rtl/chip_e8m15_k6.v|/^module top.tri_unit.fifo.write_logic(/,/^endmodule/s/ram_write_data = data_in;/ram_write_data = data_in ^ 34'h1;/"
  "lifo_pop_no_wr_ptr_dec|pair_queue.order|rtl/pair_queue_n4.v|s/wr_n = wr_ptr\$q - 32'h1;/wr_n = wr_ptr\$q;/"
  "list_open_without_len|list_stack.chain|rtl/list_stack_a8.v|s/c_open_l = wa_l\$q;/c_open_l = c_ns_l;/"
  "list_read_past_end|list_stack.chain|rtl/list_stack_a8.v|s/c_read = read \& c_idle \& (rem\$q != 32'h0);/c_read = read \& c_idle;/"
  "list_read_keeps_remaining|list_stack.chain|rtl/list_stack_a8.v|s/rem\$d = rem\$q - 32'h1;/rem\$d = rem\$q;/"
  "list_desc_branch_left|list_stack.chain|rtl/list_stack_a8.v|s/cur_b\$d = c_desc_b;/cur_b\$d = 1'b0;/"
  "list_append_keeps_address|list_stack.chain|rtl/list_stack_a8.v|s/wa_l\$d = wa_l\$q + 32'h1;/wa_l\$d = wa_l\$q;/"
  "control_syntax_error|pair_queue.bounds|rtl/pair_queue_n4.v|0,/^endmodule/s//endmodul/"
)

SLOW_MUTANTS=(
  "mem_ask_head_stuck|mem_port.ask|rtl/chip_e8m15_k6.v|s/ask_head\$d = ask_head\$q + 32'h1;/ask_head\$d = ask_head\$q;/"
)
if [ $all = 1 ]; then PROOFS+=("${SLOW_PROOFS[@]}"); MUTANTS+=("${SLOW_MUTANTS[@]}"); fi
MP_PREP='hierarchy -top \top$mem_port; rename \top$mem_port mem_port'
# mp_hier <proof>: the memory port's registers that proof's wrapper reads, tied to its f_*
# wires (a row i of w bits: f_x[w i +: w]); -nounset: `connect -set` would otherwise cut a
# wrapper wire's aliases (the 1-bit f_* that proc used as a mux select are left undriven,
# then free: a spurious counterexample)
mp_hier() {
  local r i regs="tag_n" s=""
  case $1 in
    mem_port.order) regs+=" tag_head tag_tail ta_pend tb_pend" ;;
    mem_port.words) regs+=" wa_n wa_head wa_tail wb_n wb_head wb_tail na_word nb_word" ;;
    mem_port.ask)   regs+=" ask_n ask_head ask_tail seq_head seq_tail" ;;
  esac
  for r in $regs; do s+="connect -nounset -set f_$r dut.$r\$q; "; done
  for ((i = 0; i < 16; i++)); do
    case $1 in
      mem_port.order) s+="connect -nounset -set f_tags[$((2 * i + 1)):$((2 * i))] dut.tags.row\$$i\$q; " ;;
      mem_port.words) s+="connect -nounset -set f_wa[$((209 * i + 208)):$((209 * i))] dut.wa.row\$$i\$q; "
                      s+="connect -nounset -set f_wb[$((209 * i + 208)):$((209 * i))] dut.wb.row\$$i\$q; " ;;
    esac
  done
  if [ "$1" = mem_port.ask ]; then
    for ((i = 0; i < 32; i++)); do s+="connect -nounset -set f_ask[$((22 * i + 21)):$((22 * i))] dut.ask_w\$$i\$q; "; done
  fi
  echo "$s"
}
TC_PREP='hierarchy -top \top$tri_cache; rename \top$tri_cache tri_cache'
TF_PREP='hierarchy -top \top$tri_unit$fifo; rename \top$tri_unit$fifo tri_fifo'
LS_PREP='rename top list_stack'
# ls_hier: the lists' level, position, step state, branch bits and markers tied to the
# wrapper's f_* wires (level j's 16-bit marker in f_x[16 j +: 16])
ls_hier() {
  local j s="connect -nounset -set f_lvl dut.lvl\$q; connect -nounset -set f_pos dut.pos\$q; "
  s+="connect -nounset -set f_wa_l dut.wa_l\$q; connect -nounset -set f_wa_r dut.wa_r\$q; "
  s+="connect -nounset -set f_up dut.up\$q; connect -nounset -set f_done dut.done_r\$q; "
  for ((j = 0; j < 32; j++)); do
    s+="connect -nounset -set f_br[$j] dut.br\$$j\$q; "
    for m in start_l start_r len_l len_r; do
      s+="connect -nounset -set f_$m[$((16 * j + 15)):$((16 * j))] dut.$m\$$j\$q; "
    done
  done
  echo "$s"
}
# tf_hier <proof>: the result FIFO's addresses tied to the wrapper's f_* wires; for ORDER also
# the wrapper's read port of f_ram pointed at the FIFO's RAM (its MEMID: one array, two ports)
tf_hier() {
  local s="connect -nounset -set f_wr dut.write_logic.write_address\$q; "
  s+="connect -nounset -set f_wr_late dut.write_logic.dff_write_address_delay\$q; "
  s+="connect -nounset -set f_rd dut.read_logic.read_address\$q; "
  [ "$1" = tri_fifo.order ] && s+='setparam -set MEMID "\dut.ram.mem" c:$memrd$\f_ram$*; '
  echo "$s"
}
prep_of() { case $1 in list_stack.*) echo "$LS_PREP";; pair_queue.*) echo "$PQ_PREP";; result_port.*) echo "$RP_PREP";; mem_port.*) echo "$MP_PREP";; tri_cache.*) echo "$TC_PREP";; tri_fifo.*) echo "$TF_PREP";; esac; }
hier_of() { case $1 in list_stack.chain) ls_hier;; pair_queue.*) echo "$PQ_HIER";; mem_port.*) mp_hier "$1";; tri_fifo.*) tf_hier "$1";; esac; }

# build <name> <wrapper> <dut.v> <defines> <engine> <dir>: writes <dir>/<name>.smt2 or .aig
build() {
  local name=$1 wrapper=$2 dut=$3 defs=$4 engine=$5 dir=$6 dflags="" d
  for d in $defs; do dflags+=" -D$d"; done
  local common="read_verilog $dut; $(prep_of "$name"); read_verilog -formal$dflags $root/scripts/formal/$wrapper; hierarchy -top wrapper; proc; flatten; $(hier_of "$name"); prep -top wrapper"
  if [ "$engine" = abc ]; then
    yosys -q -l "$dir/$name.yosys.log" -p "$common; memory_map; opt -fast; async2sync; chformal -assume -early; chformal -live -fair -cover -remove; opt_clean; setundef -anyseq; opt -keepdc -fast; delete -output; techmap; opt -fast; setundef -anyseq; dffunmap; aigmap; opt_clean; write_aiger -I -B -zinit -map $dir/$name.aim $dir/$name.aig" >/dev/null 2>&1
  else
    yosys -q -l "$dir/$name.yosys.log" -p "$common; async2sync; dffunmap; write_smt2 -wires $dir/$name.smt2" >/dev/null 2>&1
  fi
}

# prove <name> <wrapper> <dut.v> <defines> <engine> <depth> <dir>: 0 = proven; 1 = failed
# with a counterexample from the initial state (a failed assertion named in the log, or an
# unreached cover); 2 = failed without one (a Yosys error, a solver that crashed or gave no
# status, an induction step that fails while the base case holds). Only 1 kills a mutant.
prove() {
  local name=$1 wrapper=$2 dut=$3 defs=$4 engine=$5 depth=$6 dir=$7 log frame
  log=$dir/$name.log
  if ! build "$name" "$wrapper" "$dut" "$defs" "$engine" "$dir"; then
    echo "yosys failed: $dir/$name.yosys.log" >"$log"; return 2
  fi
  case $engine in
    ind)   # depth k/b: the base case (BMC to b >= k, deeper than needed so that a broken
           # design fails with a real trace, not only an induction step) then the step
           yosys-smtbmc -s z3 --unroll --noprogress -t "${depth#*/}" "$dir/$name.smt2" >"$log" 2>&1
           smt_status "$log" || return $?
           # a failed step alone starts from a state that may be unreachable: no counterexample
           yosys-smtbmc -s z3 --unroll --noprogress -i -t "${depth%/*}" "$dir/$name.smt2" >>"$log" 2>&1
           smt_status "$log" || return 2 ;;
    bmc)   yosys-smtbmc -s z3 --unroll --noprogress -t "$depth" "$dir/$name.smt2" >"$log" 2>&1
           smt_status "$log" ;;
    cover) yosys-smtbmc -s z3 --unroll --noprogress -c -t "$depth" "$dir/$name.smt2" >"$log" 2>&1
           smt_status "$log" ;;
    abc)   yosys-abc -c "read_aiger $dir/$name.aig; fold; strash; bmc3 -F $depth -v" >"$log" 2>&1
           # "No output asserted in N frames." = passed; "Output 0 ... was asserted in frame F"
           # = failed: replayed by yosys-smtbmc to F + 1 steps, which names the assertion
           grep -q "No output asserted in" "$log" && return 0
           frame=$(sed -nE 's/.*was asserted in frame ([0-9]+).*/\1/p' "$log" | head -n 1)
           [ -n "$frame" ] || return 2
           build "$name" "$wrapper" "$dut" "$defs" bmc "$dir" || { echo "yosys failed (replay): $dir/$name.yosys.log" >>"$log"; return 2; }
           yosys-smtbmc -s z3 --unroll --noprogress -t $((frame + 1)) "$dir/$name.smt2" >>"$log" 2>&1
           smt_status "$log"; [ $? = 1 ] && return 1
           echo "abc's counterexample in frame $frame not reproduced by yosys-smtbmc" >>"$log"; return 2 ;;
  esac
}

# smt_status <log>: the last yosys-smtbmc run in <log> (its lines since the status line
# before): 0 = PASSED; 1 = FAILED on a named failed assertion or unreached cover (an induction
# step's failure is not one); 2 = anything else (a crash, no status)
smt_status() {
  local run
  run=$(awk 'after { buf = ""; after = 0 } { buf = buf $0 "\n"; if (/Status:/) after = 1 } END { printf "%s", buf }' "$1")
  case $(grep "Status:" <<<"$run" | tail -n 1) in
    *"Status: PASSED"*) return 0 ;;
    *"Status: FAILED"*) grep -qE "Assert failed|Unreached cover" <<<"$run" && ! grep -q "Temporal induction failed" <<<"$run" && return 1 ;;
  esac
  return 2
}

fail_detail() { # the failed assertion / unreached cover in a log, with its source line, or why there is none
  local l f n
  l=$(grep -m1 -E "Assert failed|Unreached cover" "$1" \
      || grep -m1 -E "yosys failed|not reproduced|was asserted in frame|Temporal induction failed|Traceback|ERROR|Error" "$1" \
      || echo "no status line from the solver: $1")
  l=$(sed 's/^## *[0-9:]* *//' <<<"$l")
  # Yosys names an assertion file:L0.C0-L1.C1 (L1 is the assert's own line)
  if [[ $l =~ ([^ :]+\.sv):[0-9]+\.[0-9]+-([0-9]+)\. ]]; then
    f=${BASH_REMATCH[1]}; n=${BASH_REMATCH[2]}
    l="$(basename "$f"):$n: $(sed -n "${n}p" "$f" | sed 's/^ *//; s/  */ /g')"
    grep -q "Temporal induction failed" "$1" && l="induction step: $l"
  fi
  echo "$l"
}

selected() { [ ${#only[@]} -eq 0 ] && return 0; local o; for o in "${only[@]}"; do [ "$o" = "$1" ] && return 0; done; return 1; }

# proof_job <proof line>: one proof, its PASS/FAIL line on stdout
proof_job() {
  local name wrapper dut defs engine depth what how t0=$SECONDS dir=$out/proofs
  IFS='|' read -r name wrapper dut defs engine depth what <<<"$1"
  case $engine in ind) how="k-induction, k = ${depth%/*}, base case BMC to ${depth#*/}";; bmc|abc) how="BMC to depth $depth ($engine)";; cover) how="cover within $depth steps";; esac
  if prove "$name" "$wrapper" "$root/$dut" "$defs" "$engine" "$depth" "$dir"; then
    echo "PASS $name ($how, $((SECONDS - t0)) s): $what"
  else
    echo "FAIL $name ($how, $((SECONDS - t0)) s): $(fail_detail "$dir/$name.log") [log: ${dir#$root/}/$name.log]"
  fi
}

# mutant_job <mutant line>: the mutant's copy of its Verilog against the proof it must break,
# killed only by a counterexample from the initial state (prove's 1); a control (control_*)
# must fail without one, which shows that such a failure is not counted.
mutant_job() {
  local mname proof dut script expect=cex name wrapper pdut defs engine depth what p t0 dir status
  IFS='|' read -r mname proof dut script <<<"$1"
  [[ $mname == control_* ]] && expect=error
  dir=$out/mutants/$mname; mkdir -p "$dir"
  cp "$root/$dut" "$dir/$(basename "$dut")"
  sed -i "$script" "$dir/$(basename "$dut")"
  if cmp -s "$root/$dut" "$dir/$(basename "$dut")"; then
    echo "FAIL mutant $mname: the sed changed nothing"; return
  fi
  for p in "${PROOFS[@]}"; do
    IFS='|' read -r name wrapper pdut defs engine depth what <<<"$p"
    [ "$name" = "$proof" ] || continue
    t0=$SECONDS status=0
    prove "$name" "$wrapper" "$dir/$(basename "$dut")" "$defs" "$engine" "$depth" "$dir" || status=$?
    local detail; detail=$(fail_detail "$dir/$name.log")
    case $expect:$status in
      cex:1)   echo "PASS mutant $mname: killed by a counterexample, $name fails ($((SECONDS - t0)) s): $detail" ;;
      cex:0)   echo "FAIL mutant $mname: $name still passes (mutant survived)" ;;
      cex:*)   echo "FAIL mutant $mname: $name fails without a counterexample, which kills nothing: $detail [log: ${dir#$root/}/$name.log]" ;;
      error:2) echo "PASS control $mname: $name fails without a counterexample, not counted as a kill: $detail" ;;
      error:*) echo "FAIL control $mname: $name gave status $status, not the error a broken build must give [log: ${dir#$root/}/$name.log]" ;;
    esac
    return
  done
  echo "FAIL mutant $mname: no proof named $proof"
}

# JOBS=N proofs (or mutants) at a time (default: the number of cores), the slowest proof
# first (SLOW: its BMC took 205 of the proofs' 357 CPU seconds, 249 of 429 in another run),
# each one's line printed in the order of the lists once all are done.
jobs_max=${JOBS:-$(nproc 2>/dev/null || echo 2)}
SLOW=tri_cache.cache
res=$(mktemp -d)
trap 'rm -rf "$res"' EXIT
spawn() { # <index in its list> <job function> <line>
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n; done
  "$2" "$3" >"$res/$(printf %03d "$1")" &
}
mkdir -p "$out/proofs"
if [ $mutate = 0 ]; then
  order=()
  for i in "${!PROOFS[@]}"; do
    if [ "${PROOFS[$i]%%|*}" = "$SLOW" ]; then order=("$i" "${order[@]}"); else order+=("$i"); fi
  done
  for i in "${order[@]}"; do selected "${PROOFS[$i]%%|*}" && spawn "$i" proof_job "${PROOFS[$i]}"; done
else
  for i in "${!MUTANTS[@]}"; do selected "${MUTANTS[$i]%%|*}" && spawn "$i" mutant_job "${MUTANTS[$i]}"; done
fi
wait
passed=0; failed=0
for f in "$res"/*; do
  [ -e "$f" ] || continue
  cat "$f"
  if grep -q '^PASS' "$f"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
done

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
