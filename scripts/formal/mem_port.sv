// Formal wrapper of the chip's memory port (module `top$mem_port` of rtl/chip_e8m15_k6.v,
// src/rtl/memory_port.rs's MemoryPort), for Yosys (read_verilog -formal) and yosys-smtbmc;
// scripts/formal.sh runs it. formal.sh reads the chip's Verilog unchanged, keeps only
// `top$mem_port` and its sub-modules (`hierarchy -top`), renames it `mem_port` and ties the
// `f_*` wires below to the port's registers (Yosys `connect` after `flatten`): the tag
// ring's, the node-word FIFOs' and the ask list's counts, pointers and rows, the pair
// counters (seq_head, seq_tail), the triangle words' pending flags and the last pair's
// words (na_word, nb_word).
//
// One solver step is one rising edge; every input is free (the D_CNTR side, the memory's
// ready and responses, even responses nobody asked for) except `port_out`, `pf_on`,
// `slot_bits` and `map`, registers of the chip: anyconsts.
//
// The wrapper counts requests accepted (mem_req_valid && mem_req_ready, the port's
// `accept`) minus responses taken (`resp`), and keeps its own FIFO of the accepted
// requests' destinations (req_dst: 0 A's node, 1 B's node, 2 A's triangle, 3 B's).
//   COUNT (k-induction): accept = mem_req_valid && mem_req_ready; requests outstanding =
//     accepted - answered, never more than port_out + 1 nor 16; `outstanding` = any;
//     a request is accepted only with at most port_out outstanding; a response is taken
//     (`resp`) only while one is outstanding, never from a memory response without one.
//   ORDER (k-induction, k = 1): each response is routed (`resp_dst`) to the destination of
//     the oldest request not yet answered: every accepted request answered once, in
//     request order; at most one triangle word per triangle destination outstanding, its
//     pending flag (`ta_pend`, `tb_pend`) set exactly then. The invariant: the tag ring's
//     count, pointers and live rows equal the wrapper's FIFO.
//   COVER: 16 outstanding (port_out = 15), a response and a request at one edge, a
//     spurious memory response ignored, responses to all four destinations.
//   WORDS (k-induction, k = 1): the node-word FIFOs under D_CNTR's rules: an issue takes a
//     side's word only while its FIFO is not empty, and a side is never answered a 17th
//     word (assumed: D_CNTR owes at most 16 per side). wa (A's words) holds the words
//     answered to A's node requests and not yet taken, at most 16, `wa_empty` exactly when
//     none; a tracked word (any side, any value, the response the solver picks) is the DOP
//     unit's word of that side (`na_in`, `nb_in`) at the issue that takes it, after exactly
//     the words answered before it, and the word of every later pair that shares it;
//     likewise wb.
//   ASK (k-induction, k = 1; formal.sh --all, about 2 minutes of CPU): the ask list under
//     D_CNTR's rule that it never holds more than 32 words (assumed): at most 32, tail =
//     head + count, the pairs issued and popped counted (seq_head, seq_tail); no node word
//     requested from an empty list; a tracked fetched word of a pop (A0 B0 A1 B1 of the pop
//     the solver picks) is requested after exactly the words asked before it, once, with
//     its side, at its record's address (map 0), at prefetch 0 only while its pair is the
//     current one, and offered whenever it is at the head and may go.
// Not proven: the two rules assumed (D_CNTR's). Proving them here would tie the word FIFOs
// to the ask list (each side's owed words = its words over the ask list's 32 rows +
// requested + in its FIFO): z3 gave no answer to that k = 1 induction step within 10
// minutes (nor BMC past step 4 within 4; ABC's pdr none within 10 minutes, 2 busy cores).
// Simulation checks them: each chip's queries under Verilator, every accepted memory
// request and result against the cycle model's (scripts/run-chip.sh).

module wrapper (
    input wire clock,
    input wire clear,
    input wire go,
    input wire [23:0] base_na, input wire [23:0] base_nb,
    input wire [23:0] base_ta, input wire [23:0] base_tb,
    input wire pop,
    input wire [66:0] pop_entry,
    input wire [3:0] pop_fetch,
    input wire issue,
    input wire cur_fa, input wire cur_fb,
    input wire [2:0] cur_sa, input wire [2:0] cur_sb,
    input wire need_ta, input wire need_tb,
    input wire [31:0] leaf_tag,
    input wire mem_req_ready,
    input wire mem_resp_valid,
    input wire [553:0] mem_resp_data,
    input wire pick_word,          // WORDS: the tracked node word is this response's
    input wire pick_ask,           // ASK: the tracked ask-list word is this pop's ...
    input wire [1:0] which_ask     // ... A0, B0, A1 or B1
);
    wire [23:0] mem_req_addr;
    wire mem_req_valid, accept, resp, outstanding, wa_empty, wb_empty;
    wire [1:0] req_dst, resp_dst;
    wire [208:0] na_in, nb_in;

    (* anyconst *) reg [3:0] port_out;
    (* anyconst *) reg pf_on;
    (* anyconst *) reg [2:0] slot_bits;
    (* anyconst *) reg [19:0] map;

    mem_port dut (
        .clock(clock), .clear(clear), .go(go), .pf_on(pf_on), .slot_bits(slot_bits),
        .port_out(port_out), .base_na(base_na), .base_nb(base_nb), .base_ta(base_ta),
        .base_tb(base_tb), .map(map), .pop(pop), .pop_entry(pop_entry),
        .pop_fetch(pop_fetch), .issue(issue), .cur_fa(cur_fa), .cur_fb(cur_fb),
        .cur_sa(cur_sa), .cur_sb(cur_sb), .need_ta(need_ta), .need_tb(need_tb),
        .leaf_tag(leaf_tag), .mem_req_ready(mem_req_ready), .mem_resp_valid(mem_resp_valid),
        .mem_resp_data(mem_resp_data),
        .mem_req_valid(mem_req_valid), .mem_req_addr(mem_req_addr), .req_dst(req_dst),
        .accept(accept), .resp(resp), .resp_dst(resp_dst), .ta_req(), .tb_req(),
        .outstanding(outstanding), .na_in(na_in), .nb_in(nb_in), .wa_empty(wa_empty),
        .wb_empty(wb_empty)
    );

    // the port's registers (formal.sh: connect); rows are {row 15, ..., row 0}. Only a
    // proof's own: a kept wire keeps its registers in every solver step (the word rows
    // alone made COUNT's BMC five times slower)
    (* keep *) wire [4:0] f_tag_n;
`ifdef ORDER
    (* keep *) wire [3:0] f_tag_head, f_tag_tail;
    (* keep *) wire [31:0] f_tags;
    (* keep *) wire f_ta_pend, f_tb_pend;
`endif
`ifdef WORDS
    (* keep *) wire [4:0] f_wa_n, f_wb_n;
    (* keep *) wire [3:0] f_wa_head, f_wa_tail, f_wb_head, f_wb_tail;
    (* keep *) wire [16*209-1:0] f_wa, f_wb;
    (* keep *) wire [208:0] f_na_word, f_nb_word;
`endif
`ifdef ASK
    (* keep *) wire [5:0] f_ask_n;
    (* keep *) wire [4:0] f_ask_head, f_ask_tail, f_seq_head, f_seq_tail;
    (* keep *) wire [32*22-1:0] f_ask;
`endif

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;

    // accepted - answered, and the accepted requests' destinations in order (16 rows: the
    // count is at most 16, COUNT)
    reg [5:0] m_n = 6'd0;
    reg [1:0] m_dst [0:15];
    reg [3:0] m_head = 4'd0, m_tail = 4'd0;
    always @(posedge clock) begin
        m_n <= m_n + accept - resp;
        if (accept) begin
            m_dst[m_tail] <= req_dst;
            m_tail <= m_tail + 1;
        end
        if (resp) m_head <= m_head + 1;
    end
    // row i of the ring holds a request not yet answered
    function live_tag(input [3:0] i);
        live_tag = {2'd0, i - m_head} < m_n;
    endfunction

`ifdef COUNT
    always @(*) begin
        assert (accept == (mem_req_valid && mem_req_ready));
        assert ({1'b0, f_tag_n} == m_n);                      // outstanding = accepted - answered
        assert (m_n <= {2'd0, port_out} + 6'd1);              // never more than port_out + 1
        assert (m_n <= 6'd16);                                // nor 16
        assert (outstanding == (m_n != 0));
        if (accept) assert (m_n <= {2'd0, port_out});         // credit: one more only with room
        if (resp) assert (m_n != 0);                          // no response without a request
        if (mem_resp_valid && m_n != 0) assert (resp);        // a response to a request is taken
    end
`endif

`ifdef ORDER
    // requests outstanding per triangle destination
    reg [4:0] c_tag2, c_tag3;
    always @(*) begin : per_dst
        integer r;
        c_tag2 = 0; c_tag3 = 0;
        for (r = 0; r < 16; r = r + 1)
            if (live_tag(r)) begin
                if (m_dst[r] == 2'd2) c_tag2 = c_tag2 + 1;
                if (m_dst[r] == 2'd3) c_tag3 = c_tag3 + 1;
            end
    end
    always @(*) begin : order
        integer r;
        // the tag ring holds the model's destinations (the induction's invariant)
        assert ({1'b0, f_tag_n} == m_n && m_n <= 6'd16);
        assert (m_tail == m_head + m_n[3:0]);
        assert (f_tag_head == m_head && f_tag_tail == m_tail);
        for (r = 0; r < 16; r = r + 1)
            if (live_tag(r)) assert (f_tags[2 * r +: 2] == m_dst[r]);
        if (resp) assert (resp_dst == m_dst[m_head]);          // routed in request order
        assert (c_tag2 <= 1 && c_tag3 <= 1);                  // one triangle word per side
        assert (f_ta_pend == (c_tag2 != 0) && f_tb_pend == (c_tag3 != 0));
    end
`endif

`ifdef WORDS
    // the node-word FIFOs under D_CNTR's rules: an issue takes a side's word only while that
    // FIFO is not empty (need_na, need_nb), and a side is never answered a 17th word (D_CNTR
    // owes at most 16 per side: assumed here, not proven)
    wire take_a = issue && cur_fa, take_b = issue && cur_fb;
    wire resp_a = resp && resp_dst == 2'd0, resp_b = resp && resp_dst == 2'd1;
    reg [4:0] m_wa = 5'd0, m_wb = 5'd0;   // words answered, not yet taken
    always @(posedge clock)
        if (clear) begin
            m_wa <= 0; m_wb <= 0;
        end else begin
            m_wa <= m_wa + resp_a - take_a;
            m_wb <= m_wb + resp_b - take_b;
        end
    always @(*) begin
        if (take_a) assume (!wa_empty);
        if (take_b) assume (!wb_empty);
        if (resp_a && !take_a) assume (m_wa != 5'd16);
        if (resp_b && !take_b) assume (m_wb != 5'd16);
        assert (f_wa_n == m_wa && f_wb_n == m_wb && m_wa <= 5'd16 && m_wb <= 5'd16);
        assert (wa_empty == (m_wa == 0) && wb_empty == (m_wb == 0));
        assert (f_wa_tail == f_wa_head + f_wa_n[3:0] && f_wb_tail == f_wb_head + f_wb_n[3:0]);
    end

    // the tracked node word: on side f_side (0: A's FIFO wa and na_in, 1: B's), the response
    // the solver picks (pick_word); w_before = words that leave that FIFO before it
    localparam [1:0] T_WAIT = 2'd0, T_IN = 2'd1, T_OUT = 2'd2, T_GONE = 2'd3;
    (* anyconst *) reg f_side;
    (* anyconst *) reg [208:0] f_word;
    reg [1:0] w_st = T_WAIT;
    reg [4:0] w_before = 5'd0;
    wire w_in = f_side ? resp_b : resp_a;
    wire w_take = f_side ? take_b : take_a;
    wire w_cur = f_side ? cur_fb : cur_fa;
    wire [4:0] w_n = f_side ? m_wb : m_wa;
    wire [3:0] w_row = (f_side ? f_wb_head : f_wa_head) + w_before[3:0];
    wire [208:0] w_dop = f_side ? nb_in : na_in;          // the DOP unit's word of that side
    wire [208:0] w_last = f_side ? f_nb_word : f_na_word;  // the last pair's
    always @(*)
        if (w_in && pick_word && w_st == T_WAIT) assume (mem_resp_data[208:0] == f_word);
    always @(posedge clock)
        if (w_st == T_WAIT && w_in && pick_word && !clear) begin
            w_st <= T_IN;
            w_before <= w_n - w_take;
        end else if (w_st == T_IN && clear) begin
            w_st <= T_GONE;
        end else if (w_st == T_IN && w_take) begin
            if (w_before == 0) w_st <= T_OUT;
            else w_before <= w_before - 1;
        end else if (w_st == T_OUT && w_take) begin
            w_st <= T_GONE;                       // a later pair takes its own word
        end
    always @(*) begin : words
        integer r;
        if (w_st == T_IN) begin
            assert (w_before < w_n);
            for (r = 0; r < 16; r = r + 1)        // a row per case: no shifter
                if (w_row == r) assert ((f_side ? f_wb[209 * r +: 209] : f_wa[209 * r +: 209]) == f_word);
            if (w_before == 0 && w_cur) assert (w_dop == f_word);     // its turn: in order
        end
        if (w_st == T_OUT) begin
            assert (w_last == f_word);
            if (!w_cur) assert (w_dop == f_word);                     // shared by later pairs
        end
    end
`endif

`ifdef ASK
    // the ask list under D_CNTR's rule that it never holds more than 32 words (assumed); the
    // pairs issued and popped (mod 32), against the port's seq_head and seq_tail
    wire take_ask = accept && !req_dst[1];
    wire [5:0] ask_new = {5'd0, pop_fetch[0]} + pop_fetch[1] + pop_fetch[2] + pop_fetch[3];
    reg [4:0] m_seq_head = 5'd0, m_seq_tail = 5'd0;
    always @(posedge clock)
        if (clear) begin
            m_seq_head <= 0; m_seq_tail <= 0;
        end else begin
            if (issue) m_seq_head <= m_seq_head + 1;
            if (pop) m_seq_tail <= m_seq_tail + 5'd1 + pop_entry[66];
        end
    always @(*) begin
        if (pop) assume ({1'b0, f_ask_n} + ask_new <= 7'd32 + take_ask);
        assert (f_ask_n <= 6'd32 && f_ask_tail == f_ask_head + f_ask_n[4:0]);
        assert (f_seq_head == m_seq_head && f_seq_tail == m_seq_tail);
        if (take_ask) assert (f_ask_n != 0);                  // none from an empty list
    end

    // the tracked word: word which_ask (A0 B0 A1 B1) of the pop the solver picks, as
    // {pair number mod 32, B, id}; a_before = words requested before it
    localparam [1:0] T_WAIT = 2'd0, T_IN = 2'd1, T_OUT = 2'd2;
    reg [1:0] a_st = T_WAIT;
    reg [5:0] a_before = 6'd0;
    reg [21:0] a_word = 22'd0;
    wire [2:0] off1 = {2'd0, pop_fetch[0]};
    wire [2:0] off2 = off1 + pop_fetch[1];
    wire [2:0] off3 = off2 + pop_fetch[2];
    wire [2:0] a_off = which_ask == 0 ? 3'd0 : which_ask == 1 ? off1 : which_ask == 2 ? off2 : off3;
    wire [15:0] a_id = which_ask == 0 ? pop_entry[15:0] : which_ask == 1 ? pop_entry[31:16]
                     : which_ask == 2 ? pop_entry[48:33] : pop_entry[64:49];
    wire a_sel = a_st == T_WAIT && pop && !clear && pick_ask && pop_fetch[which_ask];
    wire [4:0] a_row = f_ask_head + a_before[4:0];
    wire [15:0] a_rec = a_word[15:0] >> slot_bits;
    always @(posedge clock)
        if (a_sel) begin
            a_st <= T_IN;
            a_word <= {m_seq_tail + which_ask[1], which_ask[0], a_id};
            a_before <= f_ask_n + a_off - take_ask;
        end else if (a_st == T_IN && clear) begin
            a_st <= T_OUT;
        end else if (a_st == T_IN && take_ask) begin
            if (a_before == 0) a_st <= T_OUT;
            else a_before <= a_before - 1;
        end
    always @(*) begin : ask
        integer r;
        if (a_st == T_IN) begin
            assert (a_before < f_ask_n);
            for (r = 0; r < 32; r = r + 1)        // a row per case: no shifter
                if (a_row == r) assert (f_ask[22 * r +: 22] == a_word);
            if (a_before == 0 && take_ask) begin                        // its turn: in order
                assert (req_dst == {1'b0, a_word[16]});
                if (!pf_on) assert (a_word[21:17] == m_seq_head);       // prefetch 0
                if (map == 0) assert (mem_req_addr == (a_word[16] ? base_nb : base_na) + a_rec);
            end
            // at the head, allowed, no triangle word asked, the port not full: offered
            if (a_before == 0 && go && (pf_on || a_word[21:17] == m_seq_head)
                && f_tag_n <= {1'b0, port_out} && !need_ta && !need_tb)
                assert (mem_req_valid && req_dst == {1'b0, a_word[16]});
        end
    end
`endif

`ifdef COVER
    reg [3:0] f_seen = 4'd0;
    always @(posedge clock) if (resp) f_seen[resp_dst] <= 1'b1;
    always @(posedge clock) begin
        cover (m_n == 16);
        cover (accept && resp && m_n >= 2);
        cover (mem_resp_valid && !resp);
        cover (f_seen == 4'hf);
    end
`endif
endmodule
