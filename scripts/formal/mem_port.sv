// Formal wrapper of the chip's memory port (module `top$mem_port` of rtl/chip_e8m15_k6.v,
// src/rtl/memory_port.rs's MemoryPort), for Yosys (read_verilog -formal) and yosys-smtbmc;
// scripts/formal.sh runs it. formal.sh reads the chip's Verilog unchanged, keeps only
// `top$mem_port` and its sub-modules (`hierarchy -top`), renames it `mem_port` and ties the
// `f_*` wires below to the port's registers (Yosys `connect` after `flatten`): the tag
// ring's count, pointers and rows and the triangle words' pending flags.
//
// One solver step is one rising edge; every input is free (the D_CNTR side, the memory's
// ready and responses, even responses nobody asked for) except `port_out`, `pf_on`,
// `records` and `map`, registers of the chip: anyconsts.
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
// Not proven: the node-word FIFOs (wa, wb) and the ask list. Their properties (each word
// answered reaches the DOP unit at its issue, in order; each fetched word of a pop is
// requested once, in order, at its address) need D_CNTR's rules as assumptions and a count
// over the ask list's 32 rows; z3 gave no answer to that induction step within 10 minutes
// nor BMC to depth 5 within 4 (ABC's pdr none within 10 minutes). They are checked by
// simulation: every accepted memory request of each chip's queries against the cycle
// model's (scripts/run-chip.sh).

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
    input wire cur_sa, input wire cur_sb,
    input wire need_ta, input wire need_tb,
    input wire [31:0] leaf_tag,
    input wire mem_req_ready,
    input wire mem_resp_valid,
    input wire [553:0] mem_resp_data
);
    wire mem_req_valid, accept, resp, outstanding;
    wire [1:0] req_dst, resp_dst;

    (* anyconst *) reg [3:0] port_out;
    (* anyconst *) reg pf_on;
    (* anyconst *) reg records;
    (* anyconst *) reg [19:0] map;

    mem_port dut (
        .clock(clock), .clear(clear), .go(go), .pf_on(pf_on), .records(records),
        .port_out(port_out), .base_na(base_na), .base_nb(base_nb), .base_ta(base_ta),
        .base_tb(base_tb), .map(map), .pop(pop), .pop_entry(pop_entry),
        .pop_fetch(pop_fetch), .issue(issue), .cur_fa(cur_fa), .cur_fb(cur_fb),
        .cur_sa(cur_sa), .cur_sb(cur_sb), .need_ta(need_ta), .need_tb(need_tb),
        .leaf_tag(leaf_tag), .mem_req_ready(mem_req_ready), .mem_resp_valid(mem_resp_valid),
        .mem_resp_data(mem_resp_data),
        .mem_req_valid(mem_req_valid), .mem_req_addr(), .req_dst(req_dst),
        .accept(accept), .resp(resp), .resp_dst(resp_dst), .ta_req(), .tb_req(),
        .outstanding(outstanding), .na_in(), .nb_in(), .wa_empty(), .wb_empty()
    );

    // the port's registers (formal.sh: connect); rows are {row 15, ..., row 0}
    (* keep *) wire [4:0] f_tag_n;
    (* keep *) wire [3:0] f_tag_head, f_tag_tail;
    (* keep *) wire [31:0] f_tags;
    (* keep *) wire f_ta_pend, f_tb_pend;

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
