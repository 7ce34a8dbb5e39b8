// Formal wrapper of A's triangle cache (module `top$tri_cache` of rtl/chip_e8m15_k6.v,
// src/rtl/tri_cache.rs's TriCache), for Yosys (read_verilog -formal) and yosys-smtbmc;
// scripts/formal.sh runs it. formal.sh reads the chip's Verilog unchanged, keeps only
// `top$tri_cache` and its registers and RAMs (`hierarchy -top`) and renames it `tri_cache`.
// The RAMs start with any contents (stale lines of earlier queries), the registers at 0.
//
// One solver step is one rising edge. The environment's rules (the chip's):
//   * the host writes the lines used (mask) between queries: one any-constant mask;
//   * the line looked up (`id`) is the one announced at the last edge (`next_id`), which
//     the chip guarantees by computing `next_id` from the same leaf register and FIFO head
//     that its leaf register loads at that edge.
// A reference model in the wrapper follows one any-constant triangle id X: whether it was
// filled since the last clear, the word of its last fill, and whether its line still holds
// it (no other id filled into that line since).
//
// Properties (define CACHE; bounded model checking, the RAMs' contents are not inductive):
//   * a hit for X only after a fill of X since the last clear (stale lines never hit);
//   * a hit for X returns the word of X's last fill (also when that fill was at the last
//     edge into the line being read: the bypass);
//   * X is found while its line holds it (no needless refetch).
// COVER: a hit through the bypass (fill of the line being read), a hit from the RAM two
// edges after its fill, a miss after another id took X's line, a clear between fill and
// lookup, the highest line used.

`ifndef TW
`define TW 554
`endif

module wrapper (
    input wire clock,
    input wire clear,
    input wire fill,
    input wire [15:0] fill_id,
    input wire [`TW-1:0] fill_word,
    input wire [15:0] id,
    input wire [15:0] next_id
);
    (* anyconst *) reg [6:0] mask;
    (* anyconst *) reg [15:0] x;
    wire hit;
    wire [`TW-1:0] word;

    tri_cache dut (
        .clock(clock), .clear(clear), .mask(mask), .fill(fill), .fill_id(fill_id),
        .fill_word(fill_word), .id(id), .next_id(next_id), .hit(hit), .word(word)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;

    // ---- the environment (combinational, so that it holds at the step that is checked) ----
    reg [15:0] p_next_id;
    always @(posedge clock) p_next_id <= next_id;
    always @(*)
        if (f_past_valid) assume ((id[6:0] & mask) == (p_next_id[6:0] & mask));

    // ---- the model of X ----
    wire [6:0] line_x = x[6:0] & mask;
    wire fill_x = fill && fill_id == x;
    wire fill_other = fill && fill_id != x && (fill_id[6:0] & mask) == line_x;
    reg m_filled = 1'b0, m_live = 1'b0;
    reg [`TW-1:0] m_word;
    always @(posedge clock) begin
        if (fill_x) m_word <= fill_word;
        if (fill_x) m_filled <= 1'b1;
        if (fill_x) m_live <= 1'b1;
        if (fill_other) m_live <= 1'b0;
        if (clear) begin m_filled <= 1'b0; m_live <= 1'b0; end
    end

`ifdef CACHE
    always @(*) begin
        if (hit && id == x) assert (m_filled);              // no stale hit
        if (hit && id == x) assert (word == m_word);        // the last fill's word
        if (f_past_valid && id == x && m_live) assert (hit); // found while held
    end
`endif

`ifdef COVER
    always @(posedge clock) begin
        cover (f_past_valid && $past(fill_x && (next_id[6:0] & mask) == line_x) && id == x && hit);
        cover (f_past_valid && !$past(fill) && id == x && hit);
        cover (f_past_valid && m_filled && !m_live && id == x && !hit);
        cover (f_past_valid && $past(clear) && $past(m_filled) && id == x && !hit);
        cover (mask == 7'h7f && line_x == 7'h7f && id == x && hit);
    end
`endif
endmodule
