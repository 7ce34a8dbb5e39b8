//! The collision chip (DATE'05 Fig. 4): D_CNTR, the memory port, the DOP unit and
//! TRI_UNIT joined into one block that runs whole queries, stamped out per format by
//! `chip!`. Host side, memory model and drivers: [`chip_io`](crate::harness::chip_io); cycle
//! semantics: docs/ARCHITECTURE.md, "Cycle semantics".

/// Stamps out `CollisionChip<N, NP1, NM1>` in the calling module (which must also hold the
/// DOP unit `Dop` and `TriUnit`). Arguments: `K` the DOP's k, `Dop` its unit (`DopUnit6`
/// for k = 6), `WD` the DOP format's word width, `WT` T.CHECK's, `NW` node-word bits
/// (`1 + K WD + 64`), `TW` triangle-word bits (`23 WT + 2`), `MW` memory-word bits (the
/// wider of the two: [`crate::chip::layout::Layout`]).
macro_rules! chip {
    ($K:tt, $Dop:ident, $WD:tt, $WT:tt, $NW:tt, $TW:tt, $MW:tt) => {
        declare_sync_fifo!(LeafFifo, Bits<32>, $crate::chip::rtl::LEAF_FIFO, 1);

        /// The chip's memory word bits (`mem_resp_data`).
        pub const CHIP_WORD_BITS: usize = $MW;
        /// The triangle word's bits (the low bits of a memory word; a triangle cache line).
        pub const TRI_WORD_BITS: usize = $TW;

        /// The collision chip with a k-DOP: D_CNTR (DATE'05 §4.3) drives the DOP unit (Eq. 10)
        /// over pairs of node words from memory, overlapping leaf pairs go to TRI_UNIT
        /// (§4.2), and the host reads the intersecting and the uncertain triangle pairs.
        /// `2^N` queue entries (`NP1 = N + 1`, `NM1 = N - 1`).
        ///
        /// Ports (`W` = word width of the DOP unit's or TRI_UNIT's format, `MW` = memory word):
        ///
        /// * host registers: in `host_we`, `host_addr[10]`, `host_data[32]`, written on
        ///   the rising edge. `0x000 + a`: the DOP unit's setup word `a` (C, c, D.KLMSEL
        ///   control, the DOP unit's); `0x100 + a`: TRI_UNIT's (frame maps, bounds, eta,
        ///   [`TriUnit`]); `0x120`: mode, bit 0 LIFO, bit 1 first hit; `0x121`: the root
        ///   pair, A's node in bits 15:0, B's in 31:16; `0x122 .. 0x125`: the word
        ///   addresses of A's node 0, B's node 0, A's triangle 0, B's triangle 0; `0x126`:
        ///   the memory port, bits 3:0 the node pairs prefetched (at most
        ///   [`PORT_PREFETCH`](crate::chip::rtl::PORT_PREFETCH)), 7:4 the requests outstanding at
        ///   most, less one, 8 an issue every clock (the queue's second write port takes a
        ///   result's two child entries at once), 14:9 the credit of DOP tests in flight
        ///   plus waiting leaf pairs (0: [`CREDIT`](crate::chip::rtl::CREDIT)); reset: 0, one
        ///   request, no prefetch,
        ///   issues two clocks apart, credit 16; `0x127`: A's triangle cache, bits 6:0 its
        ///   lines less one (a power of two up to
        ///   [`TRI_CACHE_LINES`](crate::chip::rtl::TRI_CACHE_LINES); reset: 0, one line).
        /// * `start` (in): begins a query with the registers as written (ignored while
        ///   `busy`); `busy`, `done` (high from the query's end to the next start),
        ///   `overflow` (the pair queue was full when a child entry came: the query ended
        ///   early and its result is incomplete), `max_depth` (most entries queued),
        ///   counters `dop_tests`, `tri_tests`, `node_fetches`, `tri_fetches`.
        /// * memory: out `mem_req_valid`, `mem_req_addr[24]` (a word address), in
        ///   `mem_req_ready`; in `mem_resp_valid`, `mem_resp_data[MW]`: the words in
        ///   request order. At most `0x126[7:4] + 1` requests are outstanding and the chip
        ///   takes every response at the rising edge it is valid (it has room for every word
        ///   it asks for, so the response has no ready).
        ///   Node word: bit 0 leaf, `d_i` at `1 + i W`, then two 32-bit fields (children,
        ///   or the triangle index and 0); triangle word: v0, v1, v2 (x, y, z), M row-major,
        ///   alpha_m, alpha_f at `i W`, v_exact, degenerate ([`crate::golden::memory`]).
        /// * results (valid/ready): out `res_valid`, `res_tag[32]` (A's triangle in bits
        ///   15:0, B's in 31:16), `res_uncertain` (0: intersecting; 1: the host decides);
        ///   in `res_ready`. Separate pairs are not shown.
        ///
        /// Structure and timing, clock by clock: docs/ARCHITECTURE.md, "Cycle semantics".
        #[derive(LogicBlock)]
        pub struct CollisionChip<const N: usize, const NP1: usize, const NM1: usize> {
            pub clock: Signal<In, Clock>,
            pub host_we: Signal<In, Bit>,
            pub host_addr: Signal<In, Bits<10>>,
            pub host_data: Signal<In, Bits<32>>,
            pub start: Signal<In, Bit>,
            pub busy: Signal<Out, Bit>,
            pub done: Signal<Out, Bit>,
            pub overflow: Signal<Out, Bit>,
            pub max_depth: Signal<Out, Bits<NP1>>,
            pub dop_tests: Signal<Out, Bits<32>>,
            pub tri_tests: Signal<Out, Bits<32>>,
            pub node_fetches: Signal<Out, Bits<32>>,
            pub tri_fetches: Signal<Out, Bits<32>>,
            pub mem_req_valid: Signal<Out, Bit>,
            pub mem_req_addr: Signal<Out, Bits<24>>,
            pub mem_req_ready: Signal<In, Bit>,
            pub mem_resp_valid: Signal<In, Bit>,
            pub mem_resp_data: Signal<In, Bits<$MW>>,
            pub res_valid: Signal<Out, Bit>,
            pub res_tag: Signal<Out, Bits<32>>,
            pub res_uncertain: Signal<Out, Bit>,
            pub res_ready: Signal<In, Bit>,
            // ---- host registers
            mode_lifo: DFF<Bit>,
            mode_first: DFF<Bit>,
            root: DFF<Bits<32>>,
            base_na: DFF<Bits<24>>,
            base_nb: DFF<Bits<24>>,
            base_ta: DFF<Bits<24>>,
            base_tb: DFF<Bits<24>>,
            // ---- query state
            run: DFF<Bit>,
            done_r: DFF<Bit>,
            push_root: DFF<Bit>,
            stop: DFF<Bit>,
            halt: Signal<Local, Bit>,
            // ---- the memory port's limits (host register 0x126)
            port_pf: DFF<Bits<4>>,
            port_out: DFF<Bits<4>>,
            port_one: DFF<Bit>,
            port_credit: DFF<Bits<6>>,
            credit_lim: Signal<Local, Bits<6>>,
            c_credit: Constant<Bits<6>>,
            pf: Signal<Local, Bits<5>>,
            c_pf_max: Constant<Bits<5>>,
            go: Signal<Local, Bit>,
            // ---- D_CNTR: the pair queue, and the pair buffer of entries popped ahead
            // (a ring of PAIR_BUF entries, each with its pairs' fetch bits A0 B0 A1 B1)
            queue: $crate::rtl::d_cntr::PairQueue<N, NP1, NM1>,
            ahd_ent: [DFF<Bits<67>>; $crate::chip::rtl::PAIR_BUF],
            ahd_fetch: [DFF<Bits<4>>; $crate::chip::rtl::PAIR_BUF],
            ahd_head: DFF<Bits<4>>,
            ahd_tail: DFF<Bits<4>>,
            ahd_pairs: DFF<Bits<5>>,
            ent_second: DFF<Bit>,
            head_dec: Signal<Local, Bits<16>>,
            tail_dec: Signal<Local, Bits<16>>,
            head_ent: Signal<Local, Bits<67>>,
            head_fetch: Signal<Local, Bits<4>>,
            ent_valid: Signal<Local, Bit>,
            cur_a: Signal<Local, Bits<16>>,
            cur_b: Signal<Local, Bits<16>>,
            cur_flip: Signal<Local, Bits<1>>,
            cur_fa: Signal<Local, Bit>,
            cur_fb: Signal<Local, Bit>,
            ent_last: Signal<Local, Bit>,
            room: Signal<Local, Bit>,
            pop: Signal<Local, Bit>,
            child_push: Signal<Local, Bit>,
            // the popped entry's node ids, fetch bits and pair count; the last pair's ids
            top: Signal<Local, Bits<67>>,
            top_two: Signal<Local, Bit>,
            pop_fetch: Signal<Local, Bits<4>>,
            fetch_a0: Signal<Local, Bit>,
            fetch_b0: Signal<Local, Bit>,
            fetch_a1: Signal<Local, Bit>,
            fetch_b1: Signal<Local, Bit>,
            ask_take: Signal<Local, Bit>,
            last_ok: DFF<Bit>,
            last_a: DFF<Bits<16>>,
            last_b: DFF<Bits<16>>,
            // ---- node words to ask for, in pair order: {pair number mod 32, B, id}
            ask_w: [DFF<Bits<22>>; $crate::chip::rtl::ASK_LIST],
            ask_head: DFF<Bits<5>>,
            ask_tail: DFF<Bits<5>>,
            ask_n: DFF<Bits<6>>,
            seq_head: DFF<Bits<5>>,
            seq_tail: DFF<Bits<5>>,
            seq_tail1: Signal<Local, Bits<5>>,
            c_ask_b: Constant<Bits<22>>,
            ask_dec: Signal<Local, Bits<32>>,
            ask_front: Signal<Local, Bits<22>>,
            ask_ok: Signal<Local, Bit>,
            ask_off1: Signal<Local, Bits<5>>,
            ask_off2: Signal<Local, Bits<5>>,
            ask_off3: Signal<Local, Bits<5>>,
            ask_new: Signal<Local, Bits<5>>,
            put0: Signal<Local, Bits<32>>,
            put1: Signal<Local, Bits<32>>,
            put2: Signal<Local, Bits<32>>,
            put3: Signal<Local, Bits<32>>,
            // ---- node words arrived, per destination in request order (A's: e, B's: d),
            // and the words of the last pair issued
            wa: [DFF<Bits<$NW>>; $crate::chip::rtl::PAIR_BUF],
            wa_head: DFF<Bits<4>>,
            wa_tail: DFF<Bits<4>>,
            wa_n: DFF<Bits<5>>,
            wb: [DFF<Bits<$NW>>; $crate::chip::rtl::PAIR_BUF],
            wb_head: DFF<Bits<4>>,
            wb_tail: DFF<Bits<4>>,
            wb_n: DFF<Bits<5>>,
            wa_hdec: Signal<Local, Bits<16>>,
            wa_tdec: Signal<Local, Bits<16>>,
            wb_hdec: Signal<Local, Bits<16>>,
            wb_tdec: Signal<Local, Bits<16>>,
            wa_front: Signal<Local, Bits<$NW>>,
            wb_front: Signal<Local, Bits<$NW>>,
            na_word: DFF<Bits<$NW>>,
            nb_word: DFF<Bits<$NW>>,
            na_in: Signal<Local, Bits<$NW>>,
            nb_in: Signal<Local, Bits<$NW>>,
            need_na: Signal<Local, Bit>,
            need_nb: Signal<Local, Bit>,
            // ---- the memory port: the destinations of the requests outstanding, in order,
            // and the triangle word asked for per triangle destination (one at a time)
            tags: [DFF<Bits<2>>; $crate::chip::rtl::PORT_OUTSTANDING],
            tag_head: DFF<Bits<4>>,
            tag_tail: DFF<Bits<4>>,
            tag_n: DFF<Bits<5>>,
            tag_hdec: Signal<Local, Bits<16>>,
            tag_tdec: Signal<Local, Bits<16>>,
            ta_pend: DFF<Bit>,
            ta_req: DFF<Bits<16>>,
            tb_pend: DFF<Bit>,
            tb_req: DFF<Bits<16>>,
            port_free: Signal<Local, Bit>,
            resp: Signal<Local, Bit>,
            resp_dst: Signal<Local, Bits<2>>,
            req: Signal<Local, Bit>,
            req_dst: Signal<Local, Bits<2>>,
            req_id: Signal<Local, Bits<16>>,
            req_addr: Signal<Local, Bits<24>>,
            accept: Signal<Local, Bit>,
            c_one16: Constant<Bits<16>>,
            c_one32: Constant<Bits<32>>,
            // ---- the DOP unit and what travels beside it
            dop: $Dop,
            side: $crate::rtl::delay::Delay<Bits<99>, { $crate::chip::rtl::DOP_LATENCY }>,
            issue: Signal<Local, Bit>,
            last_issue: DFF<Bit>,
            inflight: DFF<Bits<5>>,
            credit: Signal<Local, Bits<6>>,
            // ---- a DOP result: its pair and nodes, the child entries
            r_a: Signal<Local, Bits<16>>,
            r_b: Signal<Local, Bits<16>>,
            r_flip: Signal<Local, Bit>,
            r_a_leaf: Signal<Local, Bit>,
            r_a0: Signal<Local, Bits<16>>,
            r_a1: Signal<Local, Bits<16>>,
            r_b_leaf: Signal<Local, Bit>,
            r_b0: Signal<Local, Bits<16>>,
            r_b1: Signal<Local, Bits<16>>,
            r_hit: Signal<Local, Bit>,
            xa: Signal<Local, Bits<16>>,
            xb: Signal<Local, Bits<16>>,
            ya: Signal<Local, Bits<16>>,
            yb: Signal<Local, Bits<16>>,
            p0a: Signal<Local, Bits<16>>,
            p0b: Signal<Local, Bits<16>>,
            p1a: Signal<Local, Bits<16>>,
            p1b: Signal<Local, Bits<16>>,
            e0: Signal<Local, Bits<67>>,
            e1: Signal<Local, Bits<67>>,
            c_two: Constant<Bits<67>>,
            pend: DFF<Bit>,
            pend_data: DFF<Bits<67>>,
            // ---- leaf pairs waiting for TRI_UNIT, and the one being fetched
            leaf_fifo: LeafFifo,
            leaf_count: DFF<Bits<6>>,
            leaf_in: Signal<Local, Bit>,
            leaf_out: Signal<Local, Bit>,
            leaf_valid: DFF<Bit>,
            leaf_tag: DFF<Bits<32>>,
            // A's triangle cache (WSCG'03 §4.3): line `id & mask` holds word `id`; ids and
            // words in RAMs read one clock ahead (the next leaf pair's line), the last filled
            // word beside them for a fill of the line being read (`tc_byp`)
            tc_mask: DFF<Bits<7>>,
            ta_valid: DFF<Bits<128>>,
            tc_id: RAM<Bits<16>, 7>,
            tc_word: RAM<Bits<$TW>, 7>,
            tc_byp: DFF<Bit>,
            tc_line: Signal<Local, Bits<7>>,
            tc_next: Signal<Local, Bits<7>>,
            tc_wr: Signal<Local, Bits<7>>,
            tc_fill: Signal<Local, Bit>,
            c_one128: Constant<Bits<128>>,
            ta_ok: Signal<Local, Bit>,
            ta_id: DFF<Bits<16>>,
            ta_word: DFF<Bits<$TW>>,
            ta_held_id: Signal<Local, Bits<16>>,
            ta_held: Signal<Local, Bits<$TW>>,
            tb_ok: DFF<Bit>,
            tb_id: DFF<Bits<16>>,
            tb_word: DFF<Bits<$TW>>,
            need_ta: Signal<Local, Bit>,
            need_tb: Signal<Local, Bit>,
            tri_unit: TriUnit,
            tri_in: Signal<Local, Bit>,
            tri_take: Signal<Local, Bit>,
            tri_give: Signal<Local, Bit>,
            tri_open: DFF<Bits<9>>,
            keep: Signal<Local, Bit>,
            // ---- end of query
            all_idle: Signal<Local, Bit>,
            halt_idle: Signal<Local, Bit>,
            cnt_dop: DFF<Bits<32>>,
            cnt_tri: DFF<Bits<32>>,
            cnt_nf: DFF<Bits<32>>,
            cnt_tf: DFF<Bits<32>>,
        }

        impl<const N: usize, const NP1: usize, const NM1: usize> CollisionChip<N, NP1, NM1> {
            /// Queue entries.
            pub const CAPACITY: usize = 1 << N;

            /// DOP lanes round with `dop`, T.CHECK with `tri`.
            pub fn new(dop: Rounding, tri: Rounding) -> Self {
                Self {
                    clock: Default::default(),
                    host_we: Default::default(),
                    host_addr: Default::default(),
                    host_data: Default::default(),
                    start: Default::default(),
                    busy: Default::default(),
                    done: Default::default(),
                    overflow: Default::default(),
                    max_depth: Default::default(),
                    dop_tests: Default::default(),
                    tri_tests: Default::default(),
                    node_fetches: Default::default(),
                    tri_fetches: Default::default(),
                    mem_req_valid: Default::default(),
                    mem_req_addr: Default::default(),
                    mem_req_ready: Default::default(),
                    mem_resp_valid: Default::default(),
                    mem_resp_data: Default::default(),
                    res_valid: Default::default(),
                    res_tag: Default::default(),
                    res_uncertain: Default::default(),
                    res_ready: Default::default(),
                    mode_lifo: Default::default(),
                    mode_first: Default::default(),
                    root: Default::default(),
                    base_na: Default::default(),
                    base_nb: Default::default(),
                    base_ta: Default::default(),
                    base_tb: Default::default(),
                    run: Default::default(),
                    done_r: Default::default(),
                    push_root: Default::default(),
                    stop: Default::default(),
                    halt: Default::default(),
                    port_pf: Default::default(),
                    port_out: Default::default(),
                    port_one: Default::default(),
                    port_credit: Default::default(),
                    credit_lim: Default::default(),
                    c_credit: Constant::new(($crate::chip::rtl::CREDIT as u64).into()),
                    pf: Default::default(),
                    c_pf_max: Constant::new(($crate::chip::rtl::PORT_PREFETCH as u64).into()),
                    go: Default::default(),
                    queue: Default::default(),
                    ahd_ent: std::array::from_fn(|_| Default::default()),
                    ahd_fetch: std::array::from_fn(|_| Default::default()),
                    ahd_head: Default::default(),
                    ahd_tail: Default::default(),
                    ahd_pairs: Default::default(),
                    ent_second: Default::default(),
                    head_dec: Default::default(),
                    tail_dec: Default::default(),
                    head_ent: Default::default(),
                    head_fetch: Default::default(),
                    ent_valid: Default::default(),
                    cur_a: Default::default(),
                    cur_b: Default::default(),
                    cur_flip: Default::default(),
                    cur_fa: Default::default(),
                    cur_fb: Default::default(),
                    ent_last: Default::default(),
                    room: Default::default(),
                    pop: Default::default(),
                    child_push: Default::default(),
                    top: Default::default(),
                    top_two: Default::default(),
                    pop_fetch: Default::default(),
                    fetch_a0: Default::default(),
                    fetch_b0: Default::default(),
                    fetch_a1: Default::default(),
                    fetch_b1: Default::default(),
                    ask_take: Default::default(),
                    last_ok: Default::default(),
                    last_a: Default::default(),
                    last_b: Default::default(),
                    ask_w: std::array::from_fn(|_| Default::default()),
                    ask_head: Default::default(),
                    ask_tail: Default::default(),
                    ask_n: Default::default(),
                    seq_head: Default::default(),
                    seq_tail: Default::default(),
                    seq_tail1: Default::default(),
                    c_ask_b: Constant::new((1u64 << 16).into()),
                    ask_dec: Default::default(),
                    ask_front: Default::default(),
                    ask_ok: Default::default(),
                    ask_off1: Default::default(),
                    ask_off2: Default::default(),
                    ask_off3: Default::default(),
                    ask_new: Default::default(),
                    put0: Default::default(),
                    put1: Default::default(),
                    put2: Default::default(),
                    put3: Default::default(),
                    wa: std::array::from_fn(|_| Default::default()),
                    wa_head: Default::default(),
                    wa_tail: Default::default(),
                    wa_n: Default::default(),
                    wb: std::array::from_fn(|_| Default::default()),
                    wb_head: Default::default(),
                    wb_tail: Default::default(),
                    wb_n: Default::default(),
                    wa_hdec: Default::default(),
                    wa_tdec: Default::default(),
                    wb_hdec: Default::default(),
                    wb_tdec: Default::default(),
                    wa_front: Default::default(),
                    wb_front: Default::default(),
                    na_word: Default::default(),
                    nb_word: Default::default(),
                    na_in: Default::default(),
                    nb_in: Default::default(),
                    need_na: Default::default(),
                    need_nb: Default::default(),
                    tags: std::array::from_fn(|_| Default::default()),
                    tag_head: Default::default(),
                    tag_tail: Default::default(),
                    tag_n: Default::default(),
                    tag_hdec: Default::default(),
                    tag_tdec: Default::default(),
                    ta_pend: Default::default(),
                    ta_req: Default::default(),
                    tb_pend: Default::default(),
                    tb_req: Default::default(),
                    port_free: Default::default(),
                    resp: Default::default(),
                    resp_dst: Default::default(),
                    req: Default::default(),
                    req_dst: Default::default(),
                    req_id: Default::default(),
                    req_addr: Default::default(),
                    accept: Default::default(),
                    c_one16: Constant::new(1.into()),
                    c_one32: Constant::new(1.into()),
                    dop: $Dop::new(dop),
                    side: Default::default(),
                    issue: Default::default(),
                    last_issue: Default::default(),
                    inflight: Default::default(),
                    credit: Default::default(),
                    r_a: Default::default(),
                    r_b: Default::default(),
                    r_flip: Default::default(),
                    r_a_leaf: Default::default(),
                    r_a0: Default::default(),
                    r_a1: Default::default(),
                    r_b_leaf: Default::default(),
                    r_b0: Default::default(),
                    r_b1: Default::default(),
                    r_hit: Default::default(),
                    xa: Default::default(),
                    xb: Default::default(),
                    ya: Default::default(),
                    yb: Default::default(),
                    p0a: Default::default(),
                    p0b: Default::default(),
                    p1a: Default::default(),
                    p1b: Default::default(),
                    e0: Default::default(),
                    e1: Default::default(),
                    c_two: Constant::new(Bits::<67>::default().replace_bit(65, true).replace_bit(66, true)),
                    pend: Default::default(),
                    pend_data: Default::default(),
                    leaf_fifo: Default::default(),
                    leaf_count: Default::default(),
                    leaf_in: Default::default(),
                    leaf_out: Default::default(),
                    leaf_valid: Default::default(),
                    leaf_tag: Default::default(),
                    tc_mask: Default::default(),
                    ta_valid: Default::default(),
                    tc_id: Default::default(),
                    tc_word: Default::default(),
                    tc_byp: Default::default(),
                    tc_line: Default::default(),
                    tc_next: Default::default(),
                    tc_wr: Default::default(),
                    tc_fill: Default::default(),
                    c_one128: Constant::new(1.into()),
                    ta_ok: Default::default(),
                    ta_id: Default::default(),
                    ta_word: Default::default(),
                    ta_held_id: Default::default(),
                    ta_held: Default::default(),
                    tb_ok: Default::default(),
                    tb_id: Default::default(),
                    tb_word: Default::default(),
                    need_ta: Default::default(),
                    need_tb: Default::default(),
                    tri_unit: TriUnit::new(tri),
                    tri_in: Default::default(),
                    tri_take: Default::default(),
                    tri_give: Default::default(),
                    tri_open: Default::default(),
                    keep: Default::default(),
                    all_idle: Default::default(),
                    halt_idle: Default::default(),
                    cnt_dop: Default::default(),
                    cnt_tri: Default::default(),
                    cnt_nf: Default::default(),
                    cnt_tf: Default::default(),
                }
            }
        }

        impl<const N: usize, const NP1: usize, const NM1: usize> CollisionChip<N, NP1, NM1> {
            /// The values of the traversal signals [`crate::chip::probes::PROBES`] (in that
            /// order) as the logic shows them now: what the lockstep check compares and
            /// the traversal VCD shows (scripts/gtkw/chip_e8m15_k6.gtkw).
            pub fn probe(&self) -> Vec<u64> {
                let b = |x: bool| x as u64;
                let r_tag = self.tri_unit.out_tag.val().to_u64();
                let l_tag = self.leaf_tag.q.val().to_u64();
                vec![
                    b(self.start.val()),
                    b(self.busy.val()),
                    b(self.done.val()),
                    b(self.overflow.val()),
                    b(self.halt.val()),
                    self.queue.count.val().to_u64(),
                    self.queue.max_count.val().to_u64(),
                    b(self.queue.push.val()),
                    b(self.pop.val()),
                    b(self.ent_valid.val()),
                    self.cur_a.val().to_u64(),
                    self.cur_b.val().to_u64(),
                    b(self.need_na.val()),
                    b(self.need_nb.val()),
                    b(self.issue.val()),
                    self.inflight.q.val().to_u64(),
                    b(self.mem_req_valid.val()),
                    b(self.mem_req_ready.val()),
                    self.mem_req_addr.val().to_u64(),
                    self.req_dst.val().to_u64(),
                    b(self.tag_n.q.val() != 0),
                    b(self.mem_resp_valid.val()),
                    b(self.dop.valid_out.val()),
                    b(self.dop.overlap.val()),
                    self.r_a.val().to_u64(),
                    self.r_b.val().to_u64(),
                    b(self.r_a_leaf.val()),
                    b(self.r_b_leaf.val()),
                    b(self.leaf_in.val()),
                    self.leaf_count.q.val().to_u64(),
                    b(self.leaf_valid.q.val()),
                    l_tag & 0xffff,
                    l_tag >> 16,
                    b(self.tri_in.val()),
                    b(self.tri_unit.in_ready.val()),
                    b(self.tri_take.val()),
                    self.tri_open.q.val().to_u64(),
                    b(self.tri_unit.out_valid.val()),
                    b(self.tri_unit.out_hit.val()),
                    b(self.tri_unit.out_uncertain.val()),
                    r_tag & 0xffff,
                    r_tag >> 16,
                    b(self.res_valid.val()),
                    b(self.res_uncertain.val()),
                    self.res_tag.val().to_u64() & 0xffff,
                    self.res_tag.val().to_u64() >> 16,
                    self.cnt_dop.q.val().to_u64(),
                    self.cnt_tri.q.val().to_u64(),
                    self.cnt_nf.q.val().to_u64(),
                    self.cnt_tf.q.val().to_u64(),
                ]
            }
        }

        impl<const N: usize, const NP1: usize, const NM1: usize> Logic for CollisionChip<N, NP1, NM1> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, mode_lifo, mode_first, root, base_na, base_nb, base_ta, base_tb);
                dff_setup!(self, clock, port_pf, port_out, port_one, port_credit, run, done_r, push_root, stop);
                dff_setup!(self, clock, ahd_head, ahd_tail, ahd_pairs, ent_second, last_ok, last_a, last_b);
                dff_setup!(self, clock, ask_head, ask_tail, ask_n, seq_head, seq_tail);
                dff_setup!(self, clock, wa_head, wa_tail, wa_n, wb_head, wb_tail, wb_n, na_word, nb_word);
                dff_setup!(self, clock, tag_head, tag_tail, tag_n, ta_pend, ta_req, tb_pend, tb_req);
                for i in 0..$crate::chip::rtl::PAIR_BUF {
                    self.ahd_ent[i].clock.next = self.clock.val();
                    self.ahd_ent[i].d.next = self.ahd_ent[i].q.val();
                    self.ahd_fetch[i].clock.next = self.clock.val();
                    self.ahd_fetch[i].d.next = self.ahd_fetch[i].q.val();
                    self.wa[i].clock.next = self.clock.val();
                    self.wa[i].d.next = self.wa[i].q.val();
                    self.wb[i].clock.next = self.clock.val();
                    self.wb[i].d.next = self.wb[i].q.val();
                }
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    self.ask_w[i].clock.next = self.clock.val();
                    self.ask_w[i].d.next = self.ask_w[i].q.val();
                }
                for i in 0..$crate::chip::rtl::PORT_OUTSTANDING {
                    self.tags[i].clock.next = self.clock.val();
                    self.tags[i].d.next = self.tags[i].q.val();
                }
                dff_setup!(self, clock, last_issue, inflight, pend, pend_data, leaf_count, leaf_valid, leaf_tag);
                dff_setup!(self, clock, tc_mask, ta_valid, tc_byp, ta_id, ta_word, tb_ok, tb_id, tb_word, tri_open);
                self.tc_id.read_clock.next = self.clock.val();
                self.tc_id.write_clock.next = self.clock.val();
                self.tc_word.read_clock.next = self.clock.val();
                self.tc_word.write_clock.next = self.clock.val();
                dff_setup!(self, clock, cnt_dop, cnt_tri, cnt_nf, cnt_tf);
                clock!(self, clock, queue, dop, side, leaf_fifo, tri_unit);
                // ---- host registers and the units' setup ports
                self.dop.load_en.next = self.host_we.val() & (self.host_addr.val().get_bits::<2>(8) == 0);
                self.dop.load_addr.next = self.host_addr.val().get_bits::<8>(0);
                self.dop.load_data.next = self.host_data.val().get_bits::<$WD>(0);
                self.tri_unit.load_en.next = self.host_we.val() & (self.host_addr.val().get_bits::<5>(5) == 8);
                self.tri_unit.load_addr.next = self.host_addr.val().get_bits::<5>(0);
                self.tri_unit.load_data.next = self.host_data.val().get_bits::<$WT>(0);
                if self.host_we.val() {
                    if self.host_addr.val() == 0x120 {
                        self.mode_lifo.d.next = self.host_data.val().get_bit(0);
                        self.mode_first.d.next = self.host_data.val().get_bit(1);
                    }
                    if self.host_addr.val() == 0x121 {
                        self.root.d.next = self.host_data.val();
                    }
                    if self.host_addr.val() == 0x122 {
                        self.base_na.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == 0x123 {
                        self.base_nb.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == 0x124 {
                        self.base_ta.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == 0x125 {
                        self.base_tb.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == 0x126 {
                        self.port_pf.d.next = self.host_data.val().get_bits::<4>(0);
                        self.port_out.d.next = self.host_data.val().get_bits::<4>(4);
                        self.port_one.d.next = self.host_data.val().get_bit(8);
                        self.port_credit.d.next = self.host_data.val().get_bits::<6>(9);
                    }
                    if self.host_addr.val() == 0x127 {
                        self.tc_mask.d.next = self.host_data.val().get_bits::<7>(0);
                    }
                }
                self.pf.next = bit_cast::<5, 4>(self.port_pf.q.val());
                if bit_cast::<5, 4>(self.port_pf.q.val()) > self.c_pf_max.val() {
                    self.pf.next = self.c_pf_max.val();
                }
                self.credit_lim.next = self.port_credit.q.val();
                if self.port_credit.q.val() == 0 {
                    self.credit_lim.next = self.c_credit.val();
                }
                // A first hit or an overflow stops the traversal; what is in flight drains.
                self.halt.next = self.stop.q.val() | self.queue.overflow.val();
                self.go.next = self.run.q.val() & !self.halt.val();
                // ---- D_CNTR: the head entry of the pair buffer and its current pair (entry
                // word: cycle::d_cntr; fetch bits: which node words the pair takes from the
                // word FIFOs, the others are the last pair's)
                self.head_dec.next = self.c_one16.val() << self.ahd_head.q.val();
                self.tail_dec.next = self.c_one16.val() << self.ahd_tail.q.val();
                self.head_ent.next = 0.into();
                self.head_fetch.next = 0.into();
                for i in 0..$crate::chip::rtl::PAIR_BUF {
                    if self.head_dec.val().get_bit(i) {
                        self.head_ent.next = self.ahd_ent[i].q.val();
                        self.head_fetch.next = self.ahd_fetch[i].q.val();
                    }
                }
                self.ent_valid.next = self.ahd_pairs.q.val() != 0;
                self.cur_a.next = self.head_ent.val().get_bits::<16>(0);
                self.cur_b.next = self.head_ent.val().get_bits::<16>(16);
                self.cur_flip.next = self.head_ent.val().get_bits::<1>(32);
                self.cur_fa.next = self.head_fetch.val().get_bit(0);
                self.cur_fb.next = self.head_fetch.val().get_bit(1);
                if self.ent_second.q.val() {
                    self.cur_a.next = self.head_ent.val().get_bits::<16>(33);
                    self.cur_b.next = self.head_ent.val().get_bits::<16>(49);
                    self.cur_flip.next = self.head_ent.val().get_bits::<1>(65);
                    self.cur_fa.next = self.head_fetch.val().get_bit(2);
                    self.cur_fb.next = self.head_fetch.val().get_bit(3);
                }
                self.ent_last.next = self.ent_second.q.val() | !self.head_ent.val().get_bit(66);
                // the pair's node words: from the FIFO heads, or the last pair's
                self.wa_hdec.next = self.c_one16.val() << self.wa_head.q.val();
                self.wa_tdec.next = self.c_one16.val() << self.wa_tail.q.val();
                self.wb_hdec.next = self.c_one16.val() << self.wb_head.q.val();
                self.wb_tdec.next = self.c_one16.val() << self.wb_tail.q.val();
                self.wa_front.next = 0.into();
                self.wb_front.next = 0.into();
                for i in 0..$crate::chip::rtl::PAIR_BUF {
                    if self.wa_hdec.val().get_bit(i) {
                        self.wa_front.next = self.wa[i].q.val();
                    }
                    if self.wb_hdec.val().get_bit(i) {
                        self.wb_front.next = self.wb[i].q.val();
                    }
                }
                self.na_in.next = self.na_word.q.val();
                if self.cur_fa.val() {
                    self.na_in.next = self.wa_front.val();
                }
                self.nb_in.next = self.nb_word.q.val();
                if self.cur_fb.val() {
                    self.nb_in.next = self.wb_front.val();
                }
                self.need_na.next = self.go.val() & self.ent_valid.val() & self.cur_fa.val() & (self.wa_n.q.val() == 0);
                self.need_nb.next = self.go.val() & self.ent_valid.val() & self.cur_fb.val() & (self.wb_n.q.val() == 0);
                // A's triangle word: its line's id and word, read at the last edge for this
                // leaf pair, or filled at that edge; an A response fills line `tc_wr`
                self.tc_line.next = self.leaf_tag.q.val().get_bits::<7>(0) & self.tc_mask.q.val();
                self.tc_wr.next = self.ta_req.q.val().get_bits::<7>(0) & self.tc_mask.q.val();
                self.ta_ok.next = (self.ta_valid.q.val() & (self.c_one128.val() << self.tc_line.val())) != 0;
                self.ta_held_id.next = self.tc_id.read_data.val();
                self.ta_held.next = self.tc_word.read_data.val();
                if self.tc_byp.q.val() {
                    self.ta_held_id.next = self.ta_id.q.val();
                    self.ta_held.next = self.ta_word.q.val();
                }
                self.need_ta.next = self.go.val() & self.leaf_valid.q.val()
                    & !(self.ta_ok.val() & (self.ta_held_id.val() == self.leaf_tag.q.val().get_bits::<16>(0)));
                self.need_tb.next = self.go.val() & self.leaf_valid.q.val()
                    & !(self.tb_ok.q.val() & (self.tb_id.q.val() == self.leaf_tag.q.val().get_bits::<16>(16)));
                // ---- memory requests: triangle words first (one outstanding per
                // destination), then the node word at the head of the ask list (at prefetch
                // 0 only the current pair's), while fewer than 0x126[7:4] + 1 are outstanding
                self.ask_dec.next = self.c_one32.val() << self.ask_head.q.val();
                self.ask_front.next = 0.into();
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    if self.ask_dec.val().get_bit(i) {
                        self.ask_front.next = self.ask_w[i].q.val();
                    }
                }
                self.ask_ok.next = self.go.val() & (self.ask_n.q.val() != 0)
                    & ((self.pf.val() != 0) | (self.ask_front.val().get_bits::<5>(17) == self.seq_head.q.val()));
                self.port_free.next = self.tag_n.q.val() <= bit_cast::<5, 4>(self.port_out.q.val());
                self.req_dst.next = bit_cast::<2, 1>(self.ask_front.val().get_bits::<1>(16));
                self.req_id.next = self.ask_front.val().get_bits::<16>(0);
                self.req_addr.next = self.base_na.q.val() + bit_cast::<24, 16>(self.ask_front.val().get_bits::<16>(0));
                if self.ask_front.val().get_bit(16) {
                    self.req_addr.next = self.base_nb.q.val() + bit_cast::<24, 16>(self.ask_front.val().get_bits::<16>(0));
                }
                self.req.next = self.port_free.val() & self.ask_ok.val();
                if self.need_tb.val() & !self.tb_pend.q.val() {
                    self.req_dst.next = 3.into();
                    self.req_id.next = self.leaf_tag.q.val().get_bits::<16>(16);
                    self.req_addr.next = self.base_tb.q.val() + bit_cast::<24, 16>(self.leaf_tag.q.val().get_bits::<16>(16));
                    self.req.next = self.port_free.val();
                }
                if self.need_ta.val() & !self.ta_pend.q.val() {
                    self.req_dst.next = 2.into();
                    self.req_id.next = self.leaf_tag.q.val().get_bits::<16>(0);
                    self.req_addr.next = self.base_ta.q.val() + bit_cast::<24, 16>(self.leaf_tag.q.val().get_bits::<16>(0));
                    self.req.next = self.port_free.val();
                }
                self.mem_req_valid.next = self.req.val();
                self.mem_req_addr.next = self.req_addr.val();
                self.accept.next = self.req.val() & self.mem_req_ready.val();
                self.tag_hdec.next = self.c_one16.val() << self.tag_head.q.val();
                self.tag_tdec.next = self.c_one16.val() << self.tag_tail.q.val();
                self.resp_dst.next = 0.into();
                for i in 0..$crate::chip::rtl::PORT_OUTSTANDING {
                    if self.tag_hdec.val().get_bit(i) {
                        self.resp_dst.next = self.tags[i].q.val();
                    }
                    if self.accept.val() & self.tag_tdec.val().get_bit(i) {
                        self.tags[i].d.next = self.req_dst.val();
                    }
                }
                self.resp.next = self.mem_resp_valid.val() & (self.tag_n.q.val() != 0);
                if self.accept.val() {
                    self.tag_tail.d.next = self.tag_tail.q.val() + 1;
                    if self.req_dst.val().get_bit(1) {
                        self.cnt_tf.d.next = self.cnt_tf.q.val() + 1;
                    } else {
                        self.cnt_nf.d.next = self.cnt_nf.q.val() + 1;
                        self.ask_head.d.next = self.ask_head.q.val() + 1;
                    }
                    if self.req_dst.val() == 2 {
                        self.ta_pend.d.next = true;
                        self.ta_req.d.next = self.req_id.val();
                    }
                    if self.req_dst.val() == 3 {
                        self.tb_pend.d.next = true;
                        self.tb_req.d.next = self.req_id.val();
                    }
                }
                if self.accept.val() & !self.resp.val() {
                    self.tag_n.d.next = self.tag_n.q.val() + 1;
                }
                if self.resp.val() & !self.accept.val() {
                    self.tag_n.d.next = self.tag_n.q.val() - 1;
                }
                // a response: node words into their FIFO, a triangle word replaces the held one
                for i in 0..$crate::chip::rtl::PAIR_BUF {
                    if self.resp.val() & (self.resp_dst.val() == 0) & self.wa_tdec.val().get_bit(i) {
                        self.wa[i].d.next = self.mem_resp_data.val().get_bits::<$NW>(0);
                    }
                    if self.resp.val() & (self.resp_dst.val() == 1) & self.wb_tdec.val().get_bit(i) {
                        self.wb[i].d.next = self.mem_resp_data.val().get_bits::<$NW>(0);
                    }
                }
                if self.resp.val() {
                    self.tag_head.d.next = self.tag_head.q.val() + 1;
                    if self.resp_dst.val() == 0 {
                        self.wa_tail.d.next = self.wa_tail.q.val() + 1;
                    }
                    if self.resp_dst.val() == 1 {
                        self.wb_tail.d.next = self.wb_tail.q.val() + 1;
                    }
                    if self.resp_dst.val() == 2 {
                        self.ta_pend.d.next = false;
                        self.ta_valid.d.next = self.ta_valid.q.val() | (self.c_one128.val() << self.tc_wr.val());
                        self.ta_id.d.next = self.ta_req.q.val();
                        self.ta_word.d.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                    }
                    if self.resp_dst.val() == 3 {
                        self.tb_pend.d.next = false;
                        self.tb_ok.d.next = true;
                        self.tb_id.d.next = self.tb_req.q.val();
                        self.tb_word.d.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                    }
                }
                // ---- issue a pair to the DOP unit once both words are held. Issues are at
                // least two clocks apart (so child entries can be pushed one per clock)
                // unless 0x126[8] (the queue's second write port takes both in one clock),
                // and every test in flight has a place in the leaf FIFO.
                self.credit.next = bit_cast::<6, 5>(self.inflight.q.val()) + self.leaf_count.q.val();
                self.issue.next = self.go.val() & self.ent_valid.val()
                    & !self.need_na.val() & !self.need_nb.val() & !(self.last_issue.q.val() & !self.port_one.q.val())
                    & (self.credit.val() < self.credit_lim.val());
                self.last_issue.d.next = self.issue.val();
                for i in 0..$K {
                    self.dop.d[i].next = self.nb_in.val().get_bits::<$WD>(1 + i * $WD);
                    self.dop.e[i].next = self.na_in.val().get_bits::<$WD>(1 + i * $WD);
                }
                self.dop.tag.next = self.cur_a.val();
                self.dop.valid_in.next = self.issue.val();
                // side word: a, b, flip, A's leaf bit and fields, B's leaf bit and fields
                self.side.d.next = bit_cast::<99, 16>(self.cur_a.val())
                    | (bit_cast::<99, 16>(self.cur_b.val()) << 16)
                    | (bit_cast::<99, 1>(self.cur_flip.val()) << 32)
                    | (bit_cast::<99, 1>(self.na_in.val().get_bits::<1>(0)) << 33)
                    | (bit_cast::<99, 16>(self.na_in.val().get_bits::<16>(1 + $K * $WD)) << 34)
                    | (bit_cast::<99, 16>(self.na_in.val().get_bits::<16>(33 + $K * $WD)) << 50)
                    | (bit_cast::<99, 1>(self.nb_in.val().get_bits::<1>(0)) << 66)
                    | (bit_cast::<99, 16>(self.nb_in.val().get_bits::<16>(1 + $K * $WD)) << 67)
                    | (bit_cast::<99, 16>(self.nb_in.val().get_bits::<16>(33 + $K * $WD)) << 83);
                // an issue takes the pair's fetched words from their FIFOs and moves to the
                // entry's second pair, or to the next entry
                if self.issue.val() {
                    self.cnt_dop.d.next = self.cnt_dop.q.val() + 1;
                    self.seq_head.d.next = self.seq_head.q.val() + 1;
                    self.ent_second.d.next = true;
                    if self.ent_last.val() {
                        self.ent_second.d.next = false;
                        self.ahd_head.d.next = self.ahd_head.q.val() + 1;
                    }
                    if self.cur_fa.val() {
                        self.na_word.d.next = self.wa_front.val();
                        self.wa_head.d.next = self.wa_head.q.val() + 1;
                    }
                    if self.cur_fb.val() {
                        self.nb_word.d.next = self.wb_front.val();
                        self.wb_head.d.next = self.wb_head.q.val() + 1;
                    }
                }
                self.wa_n.d.next = self.wa_n.q.val() + bit_cast::<5, 1>((self.resp.val() & (self.resp_dst.val() == 0)).into())
                    - bit_cast::<5, 1>((self.issue.val() & self.cur_fa.val()).into());
                self.wb_n.d.next = self.wb_n.q.val() + bit_cast::<5, 1>((self.resp.val() & (self.resp_dst.val() == 1)).into())
                    - bit_cast::<5, 1>((self.issue.val() & self.cur_fb.val()).into());
                // ---- a DOP result: child entries (DOP-sharing order), or a leaf pair
                self.r_a.next = self.side.q.val().get_bits::<16>(0);
                self.r_b.next = self.side.q.val().get_bits::<16>(16);
                self.r_flip.next = self.side.q.val().get_bit(32);
                self.r_a_leaf.next = self.side.q.val().get_bit(33);
                self.r_a0.next = self.side.q.val().get_bits::<16>(34);
                self.r_a1.next = self.side.q.val().get_bits::<16>(50);
                self.r_b_leaf.next = self.side.q.val().get_bit(66);
                self.r_b0.next = self.side.q.val().get_bits::<16>(67);
                self.r_b1.next = self.side.q.val().get_bits::<16>(83);
                self.r_hit.next = self.dop.valid_out.val() & self.dop.overlap.val();
                // ---- pop the next entry when the current one is done (or issues its last pair);
                // in LIFO order not while a child entry is pushed, so that the children are
                // on top when popped, the first child first (depth first as far as the DOP
                // pipeline allows)
                self.child_push.next = self.pend.q.val() | (self.r_hit.val() & !(self.r_a_leaf.val() & self.r_b_leaf.val()));
                // ... while the pair buffer, once this clock's issue has left, holds at most
                // `prefetch` pairs (0: the entry is popped as its last pair issues)
                self.room.next = (self.ahd_pairs.q.val() - bit_cast::<5, 1>(self.issue.val().into())) <= self.pf.val();
                self.pop.next = self.go.val() & !self.queue.empty.val() & self.room.val()
                    & !(self.mode_lifo.q.val() & self.child_push.val());
                self.queue.pop.next = self.pop.val();
                // the popped entry's pairs fetch the node words the pair before did not use
                self.top.next = self.queue.top_data.val();
                self.top_two.next = self.top.val().get_bit(66);
                // (one bit each: a `!` inside a wider Verilog expression would invert the
                // zero-extended bits too)
                self.fetch_a0.next = !(self.last_ok.q.val() & (self.last_a.q.val() == self.top.val().get_bits::<16>(0)));
                self.fetch_b0.next = !(self.last_ok.q.val() & (self.last_b.q.val() == self.top.val().get_bits::<16>(16)));
                self.fetch_a1.next = self.top_two.val() & (self.top.val().get_bits::<16>(33) != self.top.val().get_bits::<16>(0));
                self.fetch_b1.next = self.top_two.val() & (self.top.val().get_bits::<16>(49) != self.top.val().get_bits::<16>(16));
                self.pop_fetch.next = bit_cast::<4, 1>(self.fetch_a0.val().into())
                    | (bit_cast::<4, 1>(self.fetch_b0.val().into()) << 1)
                    | (bit_cast::<4, 1>(self.fetch_a1.val().into()) << 2)
                    | (bit_cast::<4, 1>(self.fetch_b1.val().into()) << 3);
                for i in 0..$crate::chip::rtl::PAIR_BUF {
                    if self.pop.val() & self.tail_dec.val().get_bit(i) {
                        self.ahd_ent[i].d.next = self.top.val();
                        self.ahd_fetch[i].d.next = self.pop_fetch.val();
                    }
                }
                self.ahd_pairs.d.next = self.ahd_pairs.q.val() - bit_cast::<5, 1>(self.issue.val().into());
                if self.pop.val() {
                    self.ahd_tail.d.next = self.ahd_tail.q.val() + 1;
                    self.ahd_pairs.d.next = self.ahd_pairs.q.val() - bit_cast::<5, 1>(self.issue.val().into())
                        + 1 + bit_cast::<5, 1>(self.top_two.val().into());
                    self.seq_tail.d.next = self.seq_tail.q.val() + 1 + bit_cast::<5, 1>(self.top_two.val().into());
                    self.last_ok.d.next = true;
                    self.last_a.d.next = self.top.val().get_bits::<16>(0);
                    self.last_b.d.next = self.top.val().get_bits::<16>(16);
                    if self.top_two.val() {
                        self.last_a.d.next = self.top.val().get_bits::<16>(33);
                        self.last_b.d.next = self.top.val().get_bits::<16>(49);
                    }
                }
                // ... and its node words join the ask list in pair order (A0 B0 A1 B1, the
                // fetched ones), each with its pair's number
                self.seq_tail1.next = self.seq_tail.q.val() + 1;
                self.ask_off1.next = bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(0));
                self.ask_off2.next = self.ask_off1.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(1));
                self.ask_off3.next = self.ask_off2.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(2));
                self.ask_new.next = self.ask_off3.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(3));
                self.put0.next = self.c_one32.val() << self.ask_tail.q.val();
                self.put1.next = self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off1.val());
                self.put2.next = self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off2.val());
                self.put3.next = self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off3.val());
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    if self.pop.val() & self.pop_fetch.val().get_bit(0) & self.put0.val().get_bit(i) {
                        self.ask_w[i].d.next = bit_cast::<22, 16>(self.top.val().get_bits::<16>(0))
                            | (bit_cast::<22, 5>(self.seq_tail.q.val()) << 17);
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(1) & self.put1.val().get_bit(i) {
                        self.ask_w[i].d.next = bit_cast::<22, 16>(self.top.val().get_bits::<16>(16))
                            | (bit_cast::<22, 5>(self.seq_tail.q.val()) << 17) | self.c_ask_b.val();
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(2) & self.put2.val().get_bit(i) {
                        self.ask_w[i].d.next = bit_cast::<22, 16>(self.top.val().get_bits::<16>(33))
                            | (bit_cast::<22, 5>(self.seq_tail1.val()) << 17);
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(3) & self.put3.val().get_bit(i) {
                        self.ask_w[i].d.next = bit_cast::<22, 16>(self.top.val().get_bits::<16>(49))
                            | (bit_cast::<22, 5>(self.seq_tail1.val()) << 17) | self.c_ask_b.val();
                    }
                }
                self.ask_take.next = self.accept.val() & !self.req_dst.val().get_bit(1);
                self.ask_n.d.next = self.ask_n.q.val() - bit_cast::<6, 1>(self.ask_take.val().into());
                if self.pop.val() {
                    self.ask_tail.d.next = self.ask_tail.q.val() + self.ask_new.val();
                    self.ask_n.d.next = self.ask_n.q.val() - bit_cast::<6, 1>(self.ask_take.val().into())
                        + bit_cast::<6, 5>(self.ask_new.val());
                }
                // (xa, xb): A's children, (ya, yb): B's, in the pair's flip order
                self.xa.next = self.r_a0.val();
                self.xb.next = self.r_a1.val();
                self.ya.next = self.r_b0.val();
                self.yb.next = self.r_b1.val();
                if self.r_flip.val() {
                    self.xa.next = self.r_a1.val();
                    self.xb.next = self.r_a0.val();
                    self.ya.next = self.r_b1.val();
                    self.yb.next = self.r_b0.val();
                }
                // entry 0's pairs (p0a, p0b), (p1a, p1b); entry 1 only for inner/inner
                // inner/inner: [(xa, b0), (xa, b1)], [(xb, b1), (xb, b0)]
                self.p0a.next = self.xa.val();
                self.p0b.next = self.r_b0.val();
                self.p1a.next = self.xa.val();
                self.p1b.next = self.r_b1.val();
                if self.r_b_leaf.val() {
                    // inner/leaf: [(xa, b), (xb, b)]
                    self.p0b.next = self.r_b.val();
                    self.p1a.next = self.xb.val();
                    self.p1b.next = self.r_b.val();
                }
                if self.r_a_leaf.val() {
                    // leaf/inner: [(a, ya), (a, yb)]
                    self.p0a.next = self.r_a.val();
                    self.p0b.next = self.ya.val();
                    self.p1a.next = self.r_a.val();
                    self.p1b.next = self.yb.val();
                }
                self.e0.next = self.c_two.val() | bit_cast::<67, 16>(self.p0a.val())
                    | (bit_cast::<67, 16>(self.p0b.val()) << 16)
                    | (bit_cast::<67, 16>(self.p1a.val()) << 33)
                    | (bit_cast::<67, 16>(self.p1b.val()) << 49);
                self.e1.next = self.c_two.val() | bit_cast::<67, 16>(self.xb.val())
                    | (bit_cast::<67, 16>(self.r_b1.val()) << 16)
                    | (bit_cast::<67, 16>(self.xb.val()) << 33)
                    | (bit_cast::<67, 16>(self.r_b0.val()) << 49);
                self.queue.clear.next = self.start.val() & !self.run.q.val();
                self.queue.lifo.next = self.mode_lifo.q.val();
                self.queue.push.next = false;
                self.queue.push_data.next = self.e0.val();
                self.queue.push2.next = false;
                self.queue.push2_data.next = self.e1.val();
                self.pend.d.next = false;
                if self.pend.q.val() {
                    self.queue.push.next = true;
                    self.queue.push_data.next = self.pend_data.q.val();
                }
                self.leaf_in.next = self.r_hit.val() & self.r_a_leaf.val() & self.r_b_leaf.val();
                if self.r_hit.val() & !(self.r_a_leaf.val() & self.r_b_leaf.val()) {
                    self.queue.push.next = true;
                    if self.r_a_leaf.val() | self.r_b_leaf.val() {
                        self.queue.push_data.next = self.e0.val();
                    } else {
                        // two entries, in one clock (second write port) or one per clock;
                        // LIFO pushes the second first, so that the first is popped first
                        self.queue.push2.next = self.port_one.q.val();
                        self.pend.d.next = !self.port_one.q.val();
                        if self.mode_lifo.q.val() {
                            self.queue.push_data.next = self.e1.val();
                            self.queue.push2_data.next = self.e0.val();
                            self.pend_data.d.next = self.e0.val();
                        } else {
                            self.queue.push_data.next = self.e0.val();
                            self.pend_data.d.next = self.e1.val();
                        }
                    }
                }
                if self.push_root.q.val() {
                    self.queue.push.next = true;
                    self.queue.push_data.next = bit_cast::<67, 32>(self.root.q.val());
                }
                self.push_root.d.next = false;
                self.inflight.d.next = self.inflight.q.val();
                if self.issue.val() & !self.dop.valid_out.val() {
                    self.inflight.d.next = self.inflight.q.val() + 1;
                }
                if self.dop.valid_out.val() & !self.issue.val() {
                    self.inflight.d.next = self.inflight.q.val() - 1;
                }
                // ---- leaf pairs: FIFO, then one at a time its triangle words, then TRI_UNIT
                self.leaf_fifo.write.next = self.leaf_in.val();
                self.leaf_fifo.data_in.next = bit_cast::<32, 16>(self.r_a0.val()) | (bit_cast::<32, 16>(self.r_b0.val()) << 16);
                self.tri_in.next = self.run.q.val() & !self.halt.val() & self.leaf_valid.q.val()
                    & !self.need_ta.val() & !self.need_tb.val();
                self.tri_take.next = self.tri_in.val() & self.tri_unit.in_ready.val();
                // after a halt, waiting leaf pairs are dropped
                self.leaf_out.next = !self.leaf_fifo.empty.val()
                    & (self.halt.val() | (self.run.q.val() & (!self.leaf_valid.q.val() | self.tri_take.val())));
                self.leaf_fifo.read.next = self.leaf_out.val();
                if self.tri_take.val() {
                    self.leaf_valid.d.next = false;
                    self.cnt_tri.d.next = self.cnt_tri.q.val() + 1;
                }
                if self.leaf_out.val() & !self.halt.val() {
                    self.leaf_valid.d.next = true;
                    self.leaf_tag.d.next = self.leaf_fifo.data_out.val();
                }
                if self.leaf_in.val() & !self.leaf_out.val() {
                    self.leaf_count.d.next = self.leaf_count.q.val() + 1;
                }
                if self.leaf_out.val() & !self.leaf_in.val() {
                    self.leaf_count.d.next = self.leaf_count.q.val() - 1;
                }
                // A's triangle cache: a response for A fills line `tc_wr`; the line of the
                // next clock's leaf pair is read at this edge
                self.tc_fill.next = self.resp.val() & (self.resp_dst.val() == 2);
                self.tc_id.write_enable.next = self.tc_fill.val();
                self.tc_id.write_address.next = self.tc_wr.val();
                self.tc_id.write_data.next = self.ta_req.q.val();
                self.tc_word.write_enable.next = self.tc_fill.val();
                self.tc_word.write_address.next = self.tc_wr.val();
                self.tc_word.write_data.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                self.tc_next.next = self.tc_line.val();
                if self.leaf_out.val() & !self.halt.val() {
                    self.tc_next.next = self.leaf_fifo.data_out.val().get_bits::<7>(0) & self.tc_mask.q.val();
                }
                self.tc_id.read_address.next = self.tc_next.val();
                self.tc_word.read_address.next = self.tc_next.val();
                self.tc_byp.d.next = self.tc_fill.val() & (self.tc_wr.val() == self.tc_next.val());
                // TRI_UNIT's ports from the held triangle words (crate::golden::memory::TriWord order)
                for k in 0..3 {
                    self.tri_unit.a_v_x[k].next = self.ta_held.val().get_bits::<$WT>(3 * k * $WT);
                    self.tri_unit.a_v_y[k].next = self.ta_held.val().get_bits::<$WT>((3 * k + 1) * $WT);
                    self.tri_unit.a_v_z[k].next = self.ta_held.val().get_bits::<$WT>((3 * k + 2) * $WT);
                    self.tri_unit.b_v_x[k].next = self.tb_word.q.val().get_bits::<$WT>(3 * k * $WT);
                    self.tri_unit.b_v_y[k].next = self.tb_word.q.val().get_bits::<$WT>((3 * k + 1) * $WT);
                    self.tri_unit.b_v_z[k].next = self.tb_word.q.val().get_bits::<$WT>((3 * k + 2) * $WT);
                }
                for c in 0..4 {
                    self.tri_unit.a_m_0[c].next = self.ta_held.val().get_bits::<$WT>((9 + c) * $WT);
                    self.tri_unit.a_m_1[c].next = self.ta_held.val().get_bits::<$WT>((13 + c) * $WT);
                    self.tri_unit.a_m_2[c].next = self.ta_held.val().get_bits::<$WT>((17 + c) * $WT);
                    self.tri_unit.b_m_0[c].next = self.tb_word.q.val().get_bits::<$WT>((9 + c) * $WT);
                    self.tri_unit.b_m_1[c].next = self.tb_word.q.val().get_bits::<$WT>((13 + c) * $WT);
                    self.tri_unit.b_m_2[c].next = self.tb_word.q.val().get_bits::<$WT>((17 + c) * $WT);
                }
                self.tri_unit.a_alpha_m.next = self.ta_held.val().get_bits::<$WT>(21 * $WT);
                self.tri_unit.a_alpha_f.next = self.ta_held.val().get_bits::<$WT>(22 * $WT);
                self.tri_unit.a_v_exact.next = self.ta_held.val().get_bit(23 * $WT);
                self.tri_unit.a_degenerate.next = self.ta_held.val().get_bit(23 * $WT + 1);
                self.tri_unit.b_alpha_m.next = self.tb_word.q.val().get_bits::<$WT>(21 * $WT);
                self.tri_unit.b_alpha_f.next = self.tb_word.q.val().get_bits::<$WT>(22 * $WT);
                self.tri_unit.b_v_exact.next = self.tb_word.q.val().get_bit(23 * $WT);
                self.tri_unit.b_degenerate.next = self.tb_word.q.val().get_bit(23 * $WT + 1);
                self.tri_unit.tag.next = self.leaf_tag.q.val();
                self.tri_unit.in_valid.next = self.tri_in.val();
                // ---- results: separate pairs leave TRI_UNIT unseen, the others wait for the host
                self.keep.next = self.tri_unit.out_hit.val() | self.tri_unit.out_uncertain.val();
                self.res_valid.next = self.tri_unit.out_valid.val() & self.keep.val();
                self.res_tag.next = self.tri_unit.out_tag.val();
                self.res_uncertain.next = self.tri_unit.out_uncertain.val();
                self.tri_unit.out_ready.next = self.res_ready.val() | !self.keep.val();
                self.tri_give.next = self.tri_unit.out_valid.val() & (self.res_ready.val() | !self.keep.val());
                if self.tri_take.val() & !self.tri_give.val() {
                    self.tri_open.d.next = self.tri_open.q.val() + 1;
                }
                if self.tri_give.val() & !self.tri_take.val() {
                    self.tri_open.d.next = self.tri_open.q.val() - 1;
                }
                if self.run.q.val() & self.mode_first.q.val() & self.tri_unit.out_valid.val()
                    & self.tri_unit.out_hit.val() & !self.tri_unit.out_uncertain.val()
                {
                    self.stop.d.next = true;
                }
                // ---- end of query: nothing left to do (after a halt: nothing left in flight).
                // Leaf pairs by their count, not the FIFO's `empty`: a pair written at edge w
                // shows at the head only from cycle w + 2.
                self.halt_idle.next = (self.inflight.q.val() == 0) & !self.pend.q.val() & (self.tag_n.q.val() == 0)
                    & (self.tri_open.q.val() == 0) & !self.push_root.q.val() & (self.leaf_count.q.val() == 0);
                self.all_idle.next = self.halt_idle.val() & self.queue.empty.val() & !self.ent_valid.val()
                    & !self.leaf_valid.q.val();
                if self.run.q.val() & (self.all_idle.val() | (self.halt.val() & self.halt_idle.val())) {
                    self.run.d.next = false;
                    self.done_r.d.next = true;
                }
                if self.start.val() & !self.run.q.val() {
                    self.run.d.next = true;
                    self.done_r.d.next = false;
                    self.push_root.d.next = true;
                    self.stop.d.next = false;
                    self.leaf_valid.d.next = false;
                    // the pair buffer, the ask list and the node-word FIFOs start empty
                    self.ahd_head.d.next = 0.into();
                    self.ahd_tail.d.next = 0.into();
                    self.ahd_pairs.d.next = 0.into();
                    self.ent_second.d.next = false;
                    self.last_ok.d.next = false;
                    self.ask_head.d.next = 0.into();
                    self.ask_tail.d.next = 0.into();
                    self.ask_n.d.next = 0.into();
                    self.seq_head.d.next = 0.into();
                    self.seq_tail.d.next = 0.into();
                    self.wa_head.d.next = 0.into();
                    self.wa_tail.d.next = 0.into();
                    self.wa_n.d.next = 0.into();
                    self.wb_head.d.next = 0.into();
                    self.wb_tail.d.next = 0.into();
                    self.wb_n.d.next = 0.into();
                    self.ta_valid.d.next = 0.into();
                    self.tb_ok.d.next = false;
                    self.cnt_dop.d.next = 0.into();
                    self.cnt_tri.d.next = 0.into();
                    self.cnt_nf.d.next = 0.into();
                    self.cnt_tf.d.next = 0.into();
                }
                self.busy.next = self.run.q.val();
                self.done.next = self.done_r.q.val();
                self.overflow.next = self.queue.overflow.val();
                self.max_depth.next = self.queue.max_count.val();
                self.dop_tests.next = self.cnt_dop.q.val();
                self.tri_tests.next = self.cnt_tri.q.val();
                self.node_fetches.next = self.cnt_nf.q.val();
                self.tri_fetches.next = self.cnt_tf.q.val();
            }
        }

        /// A chip ready to simulate as a top-level block (inputs claimed, connected).
        /// Large (TRI_UNIT): build it on a thread with a big stack.
        pub fn chip_top<const N: usize, const NP1: usize, const NM1: usize>(dop: Rounding, tri: Rounding) -> CollisionChip<N, NP1, NM1> {
            top_level!(CollisionChip::<N, NP1, NM1>::new(dop, tri); clock, host_we, host_addr, host_data, start,
                mem_req_ready, mem_resp_valid, mem_resp_data, res_ready)
        }
    };
}
pub(crate) use chip;
