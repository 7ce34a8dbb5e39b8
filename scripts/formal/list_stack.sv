// Formal wrapper of WSCG'03's Stack Engine's lists, rtl/list_stack_a8.v (two SRAMs of 256
// node pointers, 32 levels; src/rtl/wscg03/stack_engine.rs, ListStack), for Yosys
// (read_verilog -formal) and yosys-smtbmc; scripts/formal.sh runs it and renames the
// exported `top` to `list_stack`.
//
// One solver step is one rising edge; every input is free in every step (any mix of
// clear, append, read and next_list); the initial state is the registers' initial values
// (level 0, every list empty), the SRAMs' contents arbitrary. The markers and the level
// register are tied by formal.sh (Yosys `connect`) to the f_* wires.
//
// Properties (define CHAIN; k-induction):
//   * the lists are contiguous: for every level j <= λ, side s: start_s[j+1] =
//     start_s[j] + len_s[j], and start_s[0] = 0, so the live lists never overlap;
//   * no list past its SRAM: start_s[j] + len_s[j] <= 256 for j <= λ + 1;
//   * the current list's read position within it; `remaining` its pointers not yet read
//     (0 while stepping up or done); `branch` the current level's branch bit; level λ + 1's
//     write addresses its lists' ends (start + len); level, busy, done the registers';
//   * overflow sticky until clear; a clear empties everything.
// COVER: level 3 reached, a right list read after stepping up, done after a descent, a
//   list of 2 read to its end (an overflow needs 257 appends: tb/wscg03.rs shows it).

module wrapper (
    input wire clock,
    input wire clear,
    input wire append,
    input wire wr_side,
    input wire [15:0] wr_ptr,
    input wire read,
    input wire next_list
);
    wire [4:0] level;
    wire branch, busy, done, rd_valid, overflow;
    wire [15:0] remaining, rd_ptr;

    list_stack dut (
        .clock(clock), .clear(clear), .append(append), .wr_side(wr_side), .wr_ptr(wr_ptr),
        .read(read), .next_list(next_list),
        .level(level), .branch(branch), .remaining(remaining), .busy(busy), .done(done),
        .rd_valid(rd_valid), .rd_ptr(rd_ptr), .overflow(overflow)
    );

    (* keep *) wire [4:0] f_lvl;
    (* keep *) wire [15:0] f_pos;
    (* keep *) wire f_up, f_done;
    (* keep *) wire [15:0] f_wa_l, f_wa_r;
    (* keep *) wire [31:0] f_br;
    (* keep *) wire [511:0] f_start_l, f_start_r, f_len_l, f_len_r;

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;

    function [15:0] at(input [511:0] v, input integer j);
        at = v[16 * j +: 16];
    endfunction

    wire [15:0] cur_len = f_br[f_lvl] ? at(f_len_r, f_lvl) : at(f_len_l, f_lvl);

`ifdef CHAIN
    integer j;
    always @(*) begin
        assert (at(f_start_l, 0) == 0 && at(f_start_r, 0) == 0);
        for (j = 0; j < 31; j = j + 1)
            if (j <= f_lvl) begin
                assert (at(f_start_l, j + 1) == at(f_start_l, j) + at(f_len_l, j));  // contiguous
                assert (at(f_start_r, j + 1) == at(f_start_r, j) + at(f_len_r, j));
            end
        for (j = 0; j < 32; j = j + 1)
            if (j <= f_lvl + 1) begin
                assert ({1'b0, at(f_start_l, j)} + at(f_len_l, j) <= 17'd256);    // within its SRAM
                assert ({1'b0, at(f_start_r, j)} + at(f_len_r, j) <= 17'd256);
            end
        assert (f_pos <= cur_len);                                                // read within the list
        assert (remaining == ((f_up || f_done) ? 16'd0 : cur_len - f_pos));
        assert (branch == f_br[f_lvl]);
        if (f_lvl != 31) begin                                                    // append here
            assert (f_wa_l == at(f_start_l, f_lvl + 1) + at(f_len_l, f_lvl + 1));
            assert (f_wa_r == at(f_start_r, f_lvl + 1) + at(f_len_r, f_lvl + 1));
        end
        assert (!(f_up && f_done));
        assert (level == f_lvl && busy == f_up && done == f_done);
        if (f_up || f_done) assert (f_pos == 0);
    end
    always @(posedge clock)
        if (f_past_valid) begin
            if ($past(overflow) && !$past(clear)) assert (overflow);               // sticky
            if ($past(clear))
                assert (level == 0 && !busy && !done && !overflow && remaining == 0 && !rd_valid);
        end
`endif

`ifdef COVER
    reg f_went_up = 1'b0, f_descended = 1'b0;
    always @(posedge clock) begin
        if (busy) f_went_up <= 1'b1;
        if (level != 0) f_descended <= 1'b1;
    end
    always @(*) begin
        cover (level == 5'd3);
        cover (f_went_up && !busy && branch && remaining != 0);
        cover (f_descended && done);
    end
    reg f_saw2 = 1'b0;
    always @(posedge clock) if (remaining == 16'd2 && level == 5'd1) f_saw2 <= 1'b1;
    always @(*) cover (f_saw2 && remaining == 16'd0 && rd_valid && level == 5'd1 && !busy);
`endif
endmodule
