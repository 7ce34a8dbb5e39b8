// Formal wrapper of the chip's memory port (module `top$mem_port` of rtl/chip_e8m15_k6.v,
// src/rtl: MemoryPort), for Yosys (read_verilog -formal) and yosys-smtbmc; scripts/formal.sh
// runs it. formal.sh reads the chip's Verilog unchanged, keeps only `top$mem_port` and its
// sub-modules (`hierarchy -top`), renames it `mem_port` and ties `f_tag_n` to the port's
// count of requests outstanding (`tag_n`, not an output; Yosys `connect` after `flatten`).
//
// One solver step is one rising edge; every input is free (the D_CNTR side, the memory's
// ready and responses, even responses nobody asked for) except `port_out`, a register
// of the chip: an anyconst.
//
// The wrapper counts requests accepted (mem_req_valid && mem_req_ready, the port's
// `accept`) minus responses taken (`resp`), and keeps its own FIFO of the accepted
// requests' destinations (req_dst).
//   COUNT (k-induction): accept = mem_req_valid && mem_req_ready; requests outstanding =
//     accepted - answered, never more than port_out + 1 nor 16; `outstanding` = any;
//     a request is accepted only with at most port_out outstanding; a response is taken
//     (`resp`) only while one is outstanding, never from a memory response without one.
//   ORDER (BMC): each response is routed (`resp_dst`) to the destination of the oldest
//     request not yet answered: every accepted request answered once, in request order.
//   COVER: 16 outstanding (port_out = 15), a response and a request at one edge, a
//     spurious memory response ignored, responses to all four destinations.

module wrapper (
    input wire clock,
    input wire clear,
    input wire go,
    input wire pf_on,
    input wire [23:0] base_na, input wire [23:0] base_nb,
    input wire [23:0] base_ta, input wire [23:0] base_tb,
    input wire pop,
    input wire [66:0] pop_entry,
    input wire [3:0] pop_fetch,
    input wire issue,
    input wire cur_fa, input wire cur_fb,
    input wire need_ta, input wire need_tb,
    input wire [31:0] leaf_tag,
    input wire mem_req_ready,
    input wire mem_resp_valid,
    input wire [553:0] mem_resp_data
);
    wire mem_req_valid, accept, resp, outstanding;
    wire [1:0] req_dst, resp_dst;

    mem_port dut (
        .clock(clock), .clear(clear), .go(go), .pf_on(pf_on), .port_out(port_out),
        .base_na(base_na), .base_nb(base_nb), .base_ta(base_ta), .base_tb(base_tb),
        .pop(pop), .pop_entry(pop_entry), .pop_fetch(pop_fetch), .issue(issue),
        .cur_fa(cur_fa), .cur_fb(cur_fb), .need_ta(need_ta), .need_tb(need_tb),
        .leaf_tag(leaf_tag), .mem_req_ready(mem_req_ready), .mem_resp_valid(mem_resp_valid),
        .mem_resp_data(mem_resp_data),
        .mem_req_valid(mem_req_valid), .mem_req_addr(), .req_dst(req_dst), .accept(accept),
        .resp(resp), .resp_dst(resp_dst), .ta_req(), .tb_req(), .outstanding(outstanding),
        .na_in(), .nb_in(), .wa_empty(), .wb_empty()
    );

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;
    (* anyconst *) reg [3:0] port_out;   // a register of the chip: constant here

    (* keep *) wire [4:0] f_tag_n;   // the port's tag_n (formal.sh: connect)

    // accepted - answered, and the accepted requests' destinations in order
    reg [5:0] m_n = 6'd0;
    reg [1:0] m_dst [0:31];
    reg [4:0] m_head = 5'd0, m_tail = 5'd0;
    always @(posedge clock) begin
        m_n <= m_n + accept - resp;
        if (accept) begin
            m_dst[m_tail] <= req_dst;
            m_tail <= m_tail + 1;
        end
        if (resp) m_head <= m_head + 1;
    end

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
    always @(*) begin
        if (resp) assert (resp_dst == m_dst[m_head]);          // routed in request order
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
