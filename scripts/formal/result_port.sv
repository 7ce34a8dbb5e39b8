// Formal wrapper of the chip's result port (module `top$result` of rtl/chip_e8m15_k6.v,
// src/rtl/tri_unit.rs's ResultPort), for Yosys (read_verilog -formal) and yosys-smtbmc;
// scripts/formal.sh runs it. formal.sh reads the chip's Verilog unchanged, keeps only
// `top$result` and its register (`hierarchy -top`) and renames it `result_port`.
//
// One solver step is one rising edge; the inputs are free except for the environment's
// rules (the chip's): TRI_UNIT gives a result only for a pair taken at an earlier edge
// (out_valid only while the model's count of open pairs is > 0), and it holds a result
// and its fields while out_ready is low (ready/valid); at most 511 pairs are open (the
// 9-bit `open`; TRI_UNIT's FIFO holds far fewer).
//
// Properties (define PORT; k-induction):
//   * open = pairs taken - results given (a wider counter in the wrapper);
//   * a result leaves (give) only when TRI_UNIT offers one (out_valid) and out_ready;
//   * a kept result (hit or uncertain) leaves exactly when the host reads it:
//     give && keep <-> res_valid && res_ready; it is shown (res_valid) while offered,
//     with TRI_UNIT's tag and uncertain bit; it holds TRI_UNIT (out_ready low) while
//     the host is not ready;
//   * a separate result (neither) leaves at once, never shown to the host;
//   * sure_hit = offered, hit, not uncertain.
// COVER: back-pressure for two edges, a take and a give at one edge, 3 pairs open,
// a separate result passing while the host is not ready.

module wrapper (
    input wire clock,
    input wire take,
    input wire out_valid,
    input wire out_hit,
    input wire out_uncertain,
    input wire [31:0] out_tag,
    input wire res_ready
);
    wire out_ready, res_valid, res_uncertain, give, sure_hit;
    wire [31:0] res_tag;
    wire [8:0] open;

    result_port dut (
        .clock(clock), .take(take), .out_valid(out_valid), .out_hit(out_hit),
        .out_uncertain(out_uncertain), .out_tag(out_tag), .res_ready(res_ready),
        .out_ready(out_ready), .res_valid(res_valid), .res_tag(res_tag),
        .res_uncertain(res_uncertain), .give(give), .sure_hit(sure_hit), .open(open)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;

    // pairs taken - results given, counted independently of the DUT
    reg [15:0] m_open = 16'd0;
    wire m_give = out_valid && out_ready;
    always @(posedge clock) m_open <= m_open + take - m_give;

    wire keep = out_hit || out_uncertain;

    // ---- the environment (TRI_UNIT and the chip around the port) ----
    always @(*) begin
        if (m_open == 0) assume (!out_valid);       // no result without an open pair
        if (m_open >= 16'd511) assume (!take);      // open fits in 9 bits
    end
    always @(posedge clock)
        if (f_past_valid && $past(out_valid && !out_ready)) begin
            // ready/valid: an offered result stays, unchanged, until it leaves
            assume (out_valid);
            assume (out_hit == $past(out_hit) && out_uncertain == $past(out_uncertain));
            assume (out_tag == $past(out_tag));
        end

`ifdef PORT
    always @(*) begin
        assert ({7'd0, open} == m_open);                                   // open = taken - given
        assert (m_open <= 16'd511);
        assert (give == (out_valid && out_ready));                         // leaves only when offered and ready
        assert ((give && keep) == (res_valid && res_ready));               // a kept result leaves exactly when read
        assert (res_valid == (out_valid && keep));                         // shown while offered
        if (res_valid) assert (res_tag == out_tag && res_uncertain == out_uncertain);
        if (res_valid && !res_ready) assert (!out_ready);                  // back-pressure
        if (out_valid && !keep) assert (give && !res_valid);               // a separate result leaves unseen
        assert (sure_hit == (out_valid && out_hit && !out_uncertain));
    end
`endif

`ifdef COVER
    always @(posedge clock) begin
        cover (f_past_valid && $past(res_valid && !res_ready) && res_valid && !res_ready);
        cover (take && give);
        cover (open == 9'd3);
        cover (out_valid && !keep && !res_ready && give);
        cover (res_valid && res_ready && out_uncertain);
    end
`endif
endmodule
