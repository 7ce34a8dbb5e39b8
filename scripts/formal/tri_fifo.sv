// Formal wrapper of TRI_UNIT's result FIFO (module `top$tri_unit$fifo` of
// rtl/chip_e8m15_k6.v: rust-hdl's synchronous FIFO, 256 entries of 34 bits, as
// src/rtl/tri_unit.rs declares it), for Yosys (read_verilog -formal) and yosys-smtbmc;
// scripts/formal.sh runs it. formal.sh reads the chip's Verilog unchanged, keeps only
// `top$tri_unit$fifo` and its sub-modules (`hierarchy -top`), renames it `tri_fifo` and ties
// the `f_*` wires below to its registers (Yosys `connect` after `flatten`): the write
// address, its copy one edge late (the read side's view) and the read address; for ORDER it
// also points a read port of the wrapper (`f_ram`) at the FIFO's RAM (Yosys `setparam` of
// the port's MEMID after `flatten`): the RAM stays one SMT array, read at the tracked row.
//
// One solver step is one rising edge. Every input is free: writes into a full FIFO and reads
// of an empty one too (the FIFO ignores them and raises its sticky flags). The wrapper
// counts the writes and reads the FIFO accepts, independently of it: a write while fewer
// than 256 entries are held, a read while an entry is readable. An entry becomes readable
// one edge after its write (the RAM's registered read): `m_last`.
//   COUNT (k-induction): entries held = accepted writes - accepted reads, at most 256, the
//     write and read addresses that far apart and the late copy one behind after a write;
//     `empty` (and `almost_empty`) exactly when no entry is readable, `full` exactly when
//     256 are held, `almost_full` exactly when 255 or more are readable; `overflow` and
//     `underflow` sticky, raised exactly by a write into a full FIFO and a read of an empty
//     one. Under TRI_UNIT's rules (an any-constant `f_chip` turns them on) neither is ever
//     raised: no result is lost and none read twice.
//   ORDER (k-induction, with COUNT): a tracked entry (the accepted write the solver picks,
//     any value) is shown on `data_out` whenever it is at the head and readable, leaves with
//     exactly one read, after exactly the entries accepted before it, unchanged. The
//     invariant: its RAM row holds it while it is held.
//   COVER: a write and a read at one edge, a read while the one entry held is not yet
//     readable, entries after an ignored read of an empty FIFO, a picked entry read after
//     two entries ahead of it, 3 entries readable.
// TRI_UNIT's rules, assumed where f_chip: it reads only while the FIFO is not empty (its
// `give = out_ready & ~fifo.empty`), and it writes only while fewer than 256 entries are
// held: T.CHECK's pipeline writes one result per pair taken, and TRI_UNIT takes a pair only
// while fewer than 256 are taken and not yet read (its `count`, in the pipeline or in the
// FIFO; `in_ready`), so a result leaving the pipeline finds room. The pipeline's one result
// per pair is not proven here; the Verilator cross-check compares every result of every
// query with the cycle model's (scripts/run-chip.sh).
// Not covered: a full FIFO (256 writes: a BMC 257 steps deep); COUNT proves `full` is the
// model's 256 entries held, which 256 accepted writes reach.

module wrapper (
    input wire clock,
    input wire write,
    input wire [33:0] data_in,
    input wire read,
    input wire pick          // ORDER: the tracked entry is this write's
);
    wire [33:0] data_out;
    wire empty, almost_empty, underflow, full, almost_full, overflow;

    tri_fifo dut (
        .clock(clock), .read(read), .data_out(data_out), .empty(empty),
        .almost_empty(almost_empty), .underflow(underflow), .write(write), .data_in(data_in),
        .full(full), .almost_full(almost_full), .overflow(overflow)
    );

    // the FIFO's registers (formal.sh: connect): write address, its late copy, read address
    (* keep *) wire [8:0] f_wr, f_wr_late, f_rd;

    (* anyconst *) reg f_chip;            // TRI_UNIT's rules on

    // ---- the model: entries held, readable, the flags' causes ----
    reg [8:0] m_n = 9'd0;                 // accepted writes - accepted reads
    reg m_last = 1'b0;                    // a write accepted at the last edge
    reg m_ovf = 1'b0, m_unf = 1'b0;
    wire [8:0] m_vis = m_n - m_last;      // readable entries
    wire m_wr = write && m_n != 9'd256;
    wire m_rd = read && m_vis != 9'd0;
    always @(posedge clock) begin
        m_n <= m_n + m_wr - m_rd;
        m_last <= m_wr;
        m_ovf <= m_ovf || (write && !m_wr);
        m_unf <= m_unf || (read && !m_rd);
    end

    always @(*)
        if (f_chip) begin
            if (read) assume (!empty);
            if (write) assume (m_n != 9'd256);
        end

`ifdef COUNT
    always @(*) begin
        assert (m_n <= 9'd256 && m_n >= m_last);
        assert (f_wr - f_rd == m_n);                    // 9-bit addresses, 256 rows
        assert (f_wr - f_wr_late == {8'd0, m_last});
        assert (empty == (m_vis == 9'd0) && almost_empty == empty);
        assert (full == (m_n == 9'd256));
        assert (almost_full == (m_vis >= 9'd255));
        assert (overflow == m_ovf && underflow == m_unf);
        if (f_chip) assert (!overflow && !underflow);
    end
`endif

`ifdef ORDER
    // the tracked entry; t_before = accepted entries that leave before it
    localparam [1:0] T_WAIT = 2'd0, T_IN = 2'd1, T_GONE = 2'd2;
    (* anyconst *) reg [33:0] f_val;
    reg [1:0] t_st = T_WAIT;
    reg [8:0] t_before = 9'd0;
    wire t_pick = t_st == T_WAIT && pick && m_wr;
    always @(*) if (t_pick) assume (data_in == f_val);
    always @(posedge clock)
        if (t_pick) begin
            t_st <= T_IN;
            t_before <= m_n - m_rd;
        end else if (t_st == T_IN && m_rd) begin
            if (t_before == 9'd0) t_st <= T_GONE;
            else t_before <= t_before - 9'd1;
        end
    // its row of the FIFO's RAM: f_ram has no contents of its own; formal.sh points this
    // read port at the FIFO's RAM (its MEMID), so that the row is read from the same array
    reg [33:0] f_ram [0:255];
    wire [33:0] t_held = f_ram[f_rd[7:0] + t_before[7:0]];
    always @(*)
        if (t_st == T_IN) begin
            assert (t_before < m_n);
            assert (t_held == f_val);
            if (t_before == 9'd0 && m_vis != 9'd0) assert (data_out == f_val);
        end
`endif

`ifdef COVER
    // the first picked write, and how many entries it had ahead of it
    reg c_in = 1'b0, c_out = 1'b0;
    reg [2:0] c_ahead = 3'd0, c_ahead0 = 3'd0;
    always @(posedge clock) begin
        if (pick && m_wr && !c_in) begin
            c_in <= 1'b1;
            c_ahead <= m_n - m_rd;
            c_ahead0 <= m_n - m_rd;
        end
        if (c_in && !c_out && m_rd) begin
            if (c_ahead == 3'd0) c_out <= 1'b1;
            else c_ahead <= c_ahead - 3'd1;
        end
    end
    always @(*) begin
        cover (m_wr && m_rd);                             // a write and a read at one edge
        cover (read && empty && m_n != 9'd0);             // written, not yet readable
        cover (underflow && !empty);                      // an ignored read, then entries
        cover (c_in && !c_out && m_rd && c_ahead == 3'd0 && c_ahead0 >= 3'd2);
        cover (m_n == 9'd3 && m_vis == 9'd3);
    end
`endif
endmodule
