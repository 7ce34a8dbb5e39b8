// Formal wrapper of the D_CNTR pair queue, rtl/pair_queue_n4.v (16 entries of 67 bits),
// for Yosys (read_verilog -formal) and yosys-smtbmc; scripts/formal.sh runs it.
//
// The exported module is instantiated unchanged; formal.sh renames its `top` to
// `pair_queue` (Yosys `rename`). One step of the solver is one rising edge of `clock`
// (the design has no other clock; the flow drops the clock input), every input of
// `wrapper` is free in every step, and the initial state is the registers' initial
// values (an empty FIFO, as after a clear), the RAM banks' contents arbitrary.
//
// The wrapper holds a reference model of the spec (src/rtl/d_cntr/pair_queue.rs, PairQueue's doc;
// golden src/cycle/d_cntr.rs, QueueModel): the count, max_count and overflow, the order
// latched by clear, and one tracked entry (the "any-constant entry": the value f_data is
// an anyconst, pushed at most once, in a step the solver picks) with the number of entries
// that leave before it (FIFO: those ahead of it; LIFO: those above it).
//
// Property groups, one per define (formal.sh builds one SMT2 file per group):
//   BOUNDS  count, flags, max_count, overflow against the model     (k-induction)
//   STEP    one-step rules: count changes by stored pushes - pop;
//           LIFO top after a push is the last stored pushed entry     (k-induction)
//   ORDER   the tracked entry: shown on top_data exactly when every entry that must
//           leave before it has left, removed by exactly one pop, never seen again,
//           in FIFO and LIFO order                                    (BMC)
//   COVER   full, overflow, a stored push2, the tracked entry out after 3 earlier ones

`ifdef ORDER
`define ORDER_OR_COVER
`endif
`ifdef COVER
`define ORDER_OR_COVER
`endif

module wrapper (
    input wire clock,
    input wire clear,
    input wire lifo,
    input wire push,
    input wire [66:0] push_data,
    input wire push2,
    input wire [66:0] push2_data,
    input wire pop
);
    wire empty, full, overflow;
    wire [4:0] count, max_count;
    wire [66:0] top_data;

    pair_queue dut (
        .clock(clock), .clear(clear), .lifo(lifo),
        .push(push), .push_data(push_data), .push2(push2), .push2_data(push2_data),
        .pop(pop),
        .empty(empty), .full(full), .count(count), .max_count(max_count),
        .overflow(overflow), .top_data(top_data)
    );

    localparam [5:0] CAP = 6'd16;

    // Hidden state the outputs do not show, tied by formal.sh (Yosys `connect` after
    // `flatten`) to the DUT's register: the order latched by the last clear.
    (* keep *) wire f_order_lifo;

    reg f_past_valid = 1'b0;
    always @(posedge clock) f_past_valid <= 1'b1;

    // ---- the spec's count, max_count, overflow, order ----
    reg [5:0] m_count = 6'd0;
    reg [5:0] m_max = 6'd0;
    reg m_ovf = 1'b0;
    reg m_lifo = 1'b0;

    wire m_do_pop = pop && m_count != 0;
    wire [5:0] m_c0 = m_count - {5'd0, m_do_pop};
    // push first, then push2; each stored if there is room after the pop and the
    // earlier push of the cycle
    wire m_s1 = push && m_c0 < CAP;                        // push_data stored
    wire [5:0] m_c1 = m_c0 + {5'd0, m_s1};
    wire m_s2 = push2 && m_c1 < CAP;                       // push2_data stored
    wire [5:0] m_next = m_c1 + {5'd0, m_s2};
    wire m_lost = (push && !m_s1) || (push2 && !m_s2);

    always @(posedge clock) begin
        if (clear) begin
            m_count <= 0;
            m_max <= 0;
            m_ovf <= 0;
            m_lifo <= lifo;
        end else begin
            m_count <= m_next;
            if (m_next > m_max) m_max <= m_next;
            if (m_lost) m_ovf <= 1'b1;
        end
    end

`ifdef BOUNDS
    always @(*) begin
        assert (count <= 5'd16);                            // bounds
        assert ({1'b0, count} == m_count);                  // count model
        assert (empty == (count == 5'd0));                  // empty flag
        assert (full == (count == 5'd16));                  // full flag
        assert (max_count >= count);                        // max >= count
        assert ({1'b0, max_count} == m_max);                // max model
        assert (overflow == m_ovf);                         // overflow model
        if (empty) assert (top_data == 67'd0);              // 0 while empty
        assert (f_order_lifo == m_lifo);                    // order latched by clear
    end
    always @(posedge clock)
        if (f_past_valid && $past(overflow) && !$past(clear))
            assert (overflow);                              // overflow sticky until clear
`endif

`ifdef STEP
    // k-induction needs the model's count and order tied to the DUT's (asserted, not
    // assumed, so that a broken queue cannot make the group vacuous)
    always @(*) begin
        assert ({1'b0, count} == m_count);
        assert (f_order_lifo == m_lifo);
    end
    always @(posedge clock) begin
        if (f_past_valid && !$past(clear)) begin
            // not full / not empty cases: exactly push + push2 - pop
            if ($past(count) + $past(push) + $past(push2) <= 16 && !($past(pop) && $past(empty)))
                assert (count == $past(count) + $past(push) + $past(push2) - $past(pop));
            if ($past(pop) && $past(empty) && $past(!push && !push2))
                assert (count == 0);
            // LIFO: after a stored push, top_data is the last stored pushed entry
            if (m_lifo && $past(m_lifo)) begin
                if ($past(m_s2)) assert (top_data == $past(push2_data));
                else if ($past(m_s1)) assert (top_data == $past(push_data));
            end
            // FIFO: a push into an empty queue (or one emptied by this cycle's pop)
            // becomes the head
            if (!m_lifo && !$past(m_lifo) && $past(m_c0) == 0) begin
                if ($past(m_s1)) assert (top_data == $past(push_data));
                else if ($past(m_s2)) assert (top_data == $past(push2_data));
            end
        end
        if (f_past_valid && $past(clear)) begin
            assert (count == 0 && empty && !overflow && max_count == 0 && top_data == 0);
        end
    end
`endif

`ifdef ORDER_OR_COVER
    // ---- the tracked entry ----
    (* anyconst *) reg [66:0] f_data;
    localparam [1:0] T_WAIT = 2'd0, T_IN = 2'd1, T_OUT = 2'd2, T_GONE = 2'd3;
    reg [1:0] t_st = T_WAIT;
    reg [5:0] t_before = 6'd0;    // entries that leave before it (FIFO ahead, LIFO above)
    reg [5:0] t_popped = 6'd0;    // pops that removed it (must end at exactly 1)

    // Bit 66 tags the tracked entry: f_data has it set, every other pushed entry has
    // it clear (so "never seen again" is one bit for the solver, not a 67-bit
    // disequality per entry, which made the BMC blow up); the other 66 bits are free.
    wire p1 = push && push_data[66];
    wire p2 = push2 && push2_data[66];
    // f_data is written at most once, never in a clear cycle (a clear ignores pushes)
    always @(*) begin
        assume (f_data[66]);
        if (p1) assume (push_data == f_data);
        if (p2) assume (push2_data == f_data);
        assume (!(p1 && p2));
        if (t_st != T_WAIT || clear) assume (!p1 && !p2);
    end

    wire t_pop_it = m_do_pop && t_st == T_IN && t_before == 0;

    always @(posedge clock) begin
        if (t_pop_it) t_popped <= t_popped + 1;
        if (clear) begin
            if (t_st == T_IN) t_st <= T_GONE;
        end else if (t_st == T_WAIT) begin
            if (p1 && m_s1) begin
                t_st <= T_IN;
                t_before <= m_lifo ? {5'd0, m_s2} : m_c0;
            end else if (p2 && m_s2) begin
                t_st <= T_IN;
                t_before <= m_lifo ? 6'd0 : m_c1;
            end else if (p1 || p2) begin
                t_st <= T_GONE;   // dropped by an overflow
            end
        end else if (t_st == T_IN) begin
            if (t_pop_it) t_st <= T_OUT;
            else if (m_lifo) t_before <= t_before - {5'd0, m_do_pop} + {5'd0, m_s1} + {5'd0, m_s2};
            else t_before <= t_before - {5'd0, m_do_pop};
        end
    end
`endif

`ifdef ORDER
    always @(*) begin
        if (t_st == T_IN) begin
            assert (t_before < m_count);                          // still held
            if (t_before == 0) assert (top_data == f_data);       // shown when its turn comes
            else assert (!top_data[66]);                          // not before
        end else begin
            assert (!top_data[66]);                               // never before written, never again
        end
        assert (t_popped <= 1);                                   // removed at most once
        if (t_st == T_OUT) assert (t_popped == 1);                // exactly once
    end
`endif

`ifdef COVER
    always @(posedge clock) begin
        cover (full);
        cover (overflow);
        cover (f_past_valid && !$past(clear) && $past(push && push2) && count == $past(count) + 2);
        cover (f_past_valid && !$past(clear) && $past(push2 && !push) && !$past(pop) && count == $past(count) + 1);
        cover (!m_lifo && t_st == T_OUT && max_count >= 4 && $past(t_before) == 0 && f_past_valid);
        cover (m_lifo && t_st == T_OUT && max_count >= 4);
        cover (m_lifo && full && pop && push && push2);
    end
`endif
endmodule
