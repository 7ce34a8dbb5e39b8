//! The collision chip (DATE'05 Fig. 4): D_CNTR, the memory port, the DOP unit and
//! TRI_UNIT joined into one block that runs whole queries, stamped out per format by
//! `chip!`. Host side, memory model and drivers: [`chip_io`](crate::harness::chip_io); cycle
//! semantics: docs/ARCHITECTURE.md, "Cycle semantics".

/// Stamps out `CollisionChip<N, NP1>` (k = 6) in the calling module (which must also hold
/// `DopUnit6` and `TriUnit`). Arguments: `W` word width, `NW` node-word bits
/// (`1 + 6 W + 64`), `MW` memory-word bits (the triangle word, `24 W + 2`).
macro_rules! chip {
    ($W:tt, $NW:tt, $MW:tt) => {
        declare_sync_fifo!(LeafFifo, Bits<32>, $crate::rtl::LEAF_FIFO, 1);

        /// The collision chip with k = 6: D_CNTR (DATE'05 §4.3) drives the DOP unit (Eq. 10)
        /// over pairs of node words from memory, overlapping leaf pairs go to TRI_UNIT
        /// (§4.2), and the host reads the intersecting and the uncertain triangle pairs.
        /// `2^N` queue entries (`NP1 = N + 1`).
        ///
        /// Ports (`W` = word width, `MW` = memory word):
        ///
        /// * host registers: in `host_we`, `host_addr[10]`, `host_data[32]`, written on
        ///   the rising edge. `0x000 + a`: the DOP unit's setup word `a` (C, c, D.KLMSEL
        ///   control, [`DopUnit6`]); `0x100 + a`: TRI_UNIT's (frame maps, bounds, eta,
        ///   [`TriUnit`]); `0x120`: mode, bit 0 LIFO, bit 1 first hit; `0x121`: the root
        ///   pair, A's node in bits 15:0, B's in 31:16; `0x122 .. 0x125`: the word
        ///   addresses of A's node 0, B's node 0, A's triangle 0, B's triangle 0.
        /// * `start` (in): begins a query with the registers as written (ignored while
        ///   `busy`); `busy`, `done` (high from the query's end to the next start),
        ///   `overflow` (the pair queue was full when a child entry came: the query ended
        ///   early and its result is incomplete), `max_depth` (most entries queued),
        ///   counters `dop_tests`, `tri_tests`, `node_fetches`, `tri_fetches`.
        /// * memory: out `mem_req_valid`, `mem_req_addr[24]` (a word address), in
        ///   `mem_req_ready`; in `mem_resp_valid`, `mem_resp_data[MW]`: the words in
        ///   request order. At most one request is outstanding and the chip takes every
        ///   response at the rising edge it is valid (so the response has no ready).
        ///   Node word: bit 0 leaf, `d_i` at `1 + i W`, then two 32-bit fields (children,
        ///   or the triangle index and 0); triangle word: v0, v1, v2 (x, y, z), M row-major,
        ///   e_lin, e_tr, l_norm at `i W`, v_exact, degenerate ([`crate::memory`]).
        /// * results (valid/ready): out `res_valid`, `res_tag[32]` (A's triangle in bits
        ///   15:0, B's in 31:16), `res_uncertain` (0: intersecting; 1: the host decides);
        ///   in `res_ready`. Separate pairs are not shown.
        ///
        /// Structure and timing, clock by clock: docs/ARCHITECTURE.md, "Cycle semantics".
        #[derive(LogicBlock)]
        pub struct CollisionChip<const N: usize, const NP1: usize> {
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
            // ---- D_CNTR: the pair queue and the entry being issued
            queue: $crate::rtl::d_cntr::PairQueue<N, NP1>,
            ent: DFF<Bits<67>>,
            ent_valid: DFF<Bit>,
            ent_second: DFF<Bit>,
            cur_a: Signal<Local, Bits<16>>,
            cur_b: Signal<Local, Bits<16>>,
            cur_flip: Signal<Local, Bits<1>>,
            ent_last: Signal<Local, Bit>,
            pop: Signal<Local, Bit>,
            child_push: Signal<Local, Bit>,
            // ---- node words held for the DOP unit (A's: e, B's: d)
            na_ok: DFF<Bit>,
            na_id: DFF<Bits<16>>,
            na_word: DFF<Bits<$NW>>,
            nb_ok: DFF<Bit>,
            nb_id: DFF<Bits<16>>,
            nb_word: DFF<Bits<$NW>>,
            need_na: Signal<Local, Bit>,
            need_nb: Signal<Local, Bit>,
            // ---- the memory port: one request outstanding, its destination and id
            outstanding: DFF<Bit>,
            dst: DFF<Bits<2>>,
            dst_id: DFF<Bits<16>>,
            req: Signal<Local, Bit>,
            req_dst: Signal<Local, Bits<2>>,
            req_id: Signal<Local, Bits<16>>,
            req_addr: Signal<Local, Bits<24>>,
            accept: Signal<Local, Bit>,
            // ---- the DOP unit and what travels beside it
            dop: DopUnit6,
            side: $crate::rtl::delay::Delay<Bits<99>, { $crate::rtl::DOP_LATENCY }>,
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
            leaf_count: DFF<Bits<5>>,
            leaf_in: Signal<Local, Bit>,
            leaf_out: Signal<Local, Bit>,
            leaf_valid: DFF<Bit>,
            leaf_tag: DFF<Bits<32>>,
            ta_ok: DFF<Bit>,
            ta_id: DFF<Bits<16>>,
            ta_word: DFF<Bits<$MW>>,
            tb_ok: DFF<Bit>,
            tb_id: DFF<Bits<16>>,
            tb_word: DFF<Bits<$MW>>,
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

        impl<const N: usize, const NP1: usize> CollisionChip<N, NP1> {
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
                    queue: Default::default(),
                    ent: Default::default(),
                    ent_valid: Default::default(),
                    ent_second: Default::default(),
                    cur_a: Default::default(),
                    cur_b: Default::default(),
                    cur_flip: Default::default(),
                    ent_last: Default::default(),
                    pop: Default::default(),
                    child_push: Default::default(),
                    na_ok: Default::default(),
                    na_id: Default::default(),
                    na_word: Default::default(),
                    nb_ok: Default::default(),
                    nb_id: Default::default(),
                    nb_word: Default::default(),
                    need_na: Default::default(),
                    need_nb: Default::default(),
                    outstanding: Default::default(),
                    dst: Default::default(),
                    dst_id: Default::default(),
                    req: Default::default(),
                    req_dst: Default::default(),
                    req_id: Default::default(),
                    req_addr: Default::default(),
                    accept: Default::default(),
                    dop: DopUnit6::new(dop),
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
                    ta_ok: Default::default(),
                    ta_id: Default::default(),
                    ta_word: Default::default(),
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

        impl<const N: usize, const NP1: usize> CollisionChip<N, NP1> {
            /// The values of the traversal signals [`crate::cycle::PROBES`] (in that
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
                    b(self.ent_valid.q.val()),
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
                    b(self.outstanding.q.val()),
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

        impl<const N: usize, const NP1: usize> Logic for CollisionChip<N, NP1> {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, mode_lifo, mode_first, root, base_na, base_nb, base_ta, base_tb);
                dff_setup!(self, clock, run, done_r, push_root, stop, ent, ent_valid, ent_second);
                dff_setup!(self, clock, na_ok, na_id, na_word, nb_ok, nb_id, nb_word, outstanding, dst, dst_id);
                dff_setup!(self, clock, last_issue, inflight, pend, pend_data, leaf_count, leaf_valid, leaf_tag);
                dff_setup!(self, clock, ta_ok, ta_id, ta_word, tb_ok, tb_id, tb_word, tri_open);
                dff_setup!(self, clock, cnt_dop, cnt_tri, cnt_nf, cnt_tf);
                clock!(self, clock, queue, dop, side, leaf_fifo, tri_unit);
                // ---- host registers and the units' setup ports
                self.dop.load_en.next = self.host_we.val() & (self.host_addr.val().get_bits::<2>(8) == 0);
                self.dop.load_addr.next = self.host_addr.val().get_bits::<8>(0);
                self.dop.load_data.next = self.host_data.val().get_bits::<$W>(0);
                self.tri_unit.load_en.next = self.host_we.val() & (self.host_addr.val().get_bits::<5>(5) == 8);
                self.tri_unit.load_addr.next = self.host_addr.val().get_bits::<5>(0);
                self.tri_unit.load_data.next = self.host_data.val().get_bits::<$W>(0);
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
                }
                // A first hit or an overflow stops the traversal; what is in flight drains.
                self.halt.next = self.stop.q.val() | self.queue.overflow.val();
                // ---- D_CNTR: the entry's current pair (entry word: cycle::d_cntr)
                self.cur_a.next = self.ent.q.val().get_bits::<16>(0);
                self.cur_b.next = self.ent.q.val().get_bits::<16>(16);
                self.cur_flip.next = self.ent.q.val().get_bits::<1>(32);
                if self.ent_second.q.val() {
                    self.cur_a.next = self.ent.q.val().get_bits::<16>(33);
                    self.cur_b.next = self.ent.q.val().get_bits::<16>(49);
                    self.cur_flip.next = self.ent.q.val().get_bits::<1>(65);
                }
                self.ent_last.next = self.ent_second.q.val() | !self.ent.q.val().get_bit(66);
                self.need_na.next = self.run.q.val() & !self.halt.val() & self.ent_valid.q.val()
                    & !(self.na_ok.q.val() & (self.na_id.q.val() == self.cur_a.val()));
                self.need_nb.next = self.run.q.val() & !self.halt.val() & self.ent_valid.q.val()
                    & !(self.nb_ok.q.val() & (self.nb_id.q.val() == self.cur_b.val()));
                self.need_ta.next = self.run.q.val() & !self.halt.val() & self.leaf_valid.q.val()
                    & !(self.ta_ok.q.val() & (self.ta_id.q.val() == self.leaf_tag.q.val().get_bits::<16>(0)));
                self.need_tb.next = self.run.q.val() & !self.halt.val() & self.leaf_valid.q.val()
                    & !(self.tb_ok.q.val() & (self.tb_id.q.val() == self.leaf_tag.q.val().get_bits::<16>(16)));
                // ---- memory requests, one at a time: triangle words first, then node words
                self.req_dst.next = 1.into();
                self.req_id.next = self.cur_b.val();
                self.req_addr.next = self.base_nb.q.val() + bit_cast::<24, 16>(self.cur_b.val());
                if self.need_na.val() {
                    self.req_dst.next = 0.into();
                    self.req_id.next = self.cur_a.val();
                    self.req_addr.next = self.base_na.q.val() + bit_cast::<24, 16>(self.cur_a.val());
                }
                if self.need_tb.val() {
                    self.req_dst.next = 3.into();
                    self.req_id.next = self.leaf_tag.q.val().get_bits::<16>(16);
                    self.req_addr.next = self.base_tb.q.val() + bit_cast::<24, 16>(self.leaf_tag.q.val().get_bits::<16>(16));
                }
                if self.need_ta.val() {
                    self.req_dst.next = 2.into();
                    self.req_id.next = self.leaf_tag.q.val().get_bits::<16>(0);
                    self.req_addr.next = self.base_ta.q.val() + bit_cast::<24, 16>(self.leaf_tag.q.val().get_bits::<16>(0));
                }
                self.req.next = !self.outstanding.q.val()
                    & (self.need_na.val() | self.need_nb.val() | self.need_ta.val() | self.need_tb.val());
                self.mem_req_valid.next = self.req.val();
                self.mem_req_addr.next = self.req_addr.val();
                self.accept.next = self.req.val() & self.mem_req_ready.val();
                if self.accept.val() {
                    self.outstanding.d.next = true;
                    self.dst.d.next = self.req_dst.val();
                    self.dst_id.d.next = self.req_id.val();
                    if self.req_dst.val().get_bit(1) {
                        self.cnt_tf.d.next = self.cnt_tf.q.val() + 1;
                    } else {
                        self.cnt_nf.d.next = self.cnt_nf.q.val() + 1;
                    }
                }
                if self.outstanding.q.val() & self.mem_resp_valid.val() {
                    self.outstanding.d.next = false;
                    if self.dst.q.val() == 0 {
                        self.na_ok.d.next = true;
                        self.na_id.d.next = self.dst_id.q.val();
                        self.na_word.d.next = self.mem_resp_data.val().get_bits::<$NW>(0);
                    }
                    if self.dst.q.val() == 1 {
                        self.nb_ok.d.next = true;
                        self.nb_id.d.next = self.dst_id.q.val();
                        self.nb_word.d.next = self.mem_resp_data.val().get_bits::<$NW>(0);
                    }
                    if self.dst.q.val() == 2 {
                        self.ta_ok.d.next = true;
                        self.ta_id.d.next = self.dst_id.q.val();
                        self.ta_word.d.next = self.mem_resp_data.val();
                    }
                    if self.dst.q.val() == 3 {
                        self.tb_ok.d.next = true;
                        self.tb_id.d.next = self.dst_id.q.val();
                        self.tb_word.d.next = self.mem_resp_data.val();
                    }
                }
                // ---- issue a pair to the DOP unit once both words are held. Issues are at
                // least two clocks apart (so child entries can be pushed one per clock), and
                // every test in flight has a place in the leaf FIFO.
                self.credit.next = bit_cast::<6, 5>(self.inflight.q.val()) + bit_cast::<6, 5>(self.leaf_count.q.val());
                self.issue.next = self.run.q.val() & !self.halt.val() & self.ent_valid.q.val()
                    & !self.need_na.val() & !self.need_nb.val() & !self.last_issue.q.val()
                    & (self.credit.val() < 16);
                self.last_issue.d.next = self.issue.val();
                for i in 0..6 {
                    self.dop.d[i].next = self.nb_word.q.val().get_bits::<$W>(1 + i * $W);
                    self.dop.e[i].next = self.na_word.q.val().get_bits::<$W>(1 + i * $W);
                }
                self.dop.tag.next = self.cur_a.val();
                self.dop.valid_in.next = self.issue.val();
                // side word: a, b, flip, A's leaf bit and fields, B's leaf bit and fields
                self.side.d.next = bit_cast::<99, 16>(self.cur_a.val())
                    | (bit_cast::<99, 16>(self.cur_b.val()) << 16)
                    | (bit_cast::<99, 1>(self.cur_flip.val()) << 32)
                    | (bit_cast::<99, 1>(self.na_word.q.val().get_bits::<1>(0)) << 33)
                    | (bit_cast::<99, 16>(self.na_word.q.val().get_bits::<16>(1 + 6 * $W)) << 34)
                    | (bit_cast::<99, 16>(self.na_word.q.val().get_bits::<16>(33 + 6 * $W)) << 50)
                    | (bit_cast::<99, 1>(self.nb_word.q.val().get_bits::<1>(0)) << 66)
                    | (bit_cast::<99, 16>(self.nb_word.q.val().get_bits::<16>(1 + 6 * $W)) << 67)
                    | (bit_cast::<99, 16>(self.nb_word.q.val().get_bits::<16>(33 + 6 * $W)) << 83);
                if self.issue.val() {
                    self.cnt_dop.d.next = self.cnt_dop.q.val() + 1;
                    self.ent_second.d.next = true;
                    if self.ent_last.val() {
                        self.ent_valid.d.next = false;
                    }
                }
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
                self.pop.next = self.run.q.val() & !self.halt.val() & !self.queue.empty.val()
                    & (!self.ent_valid.q.val() | (self.issue.val() & self.ent_last.val()))
                    & !(self.mode_lifo.q.val() & self.child_push.val());
                self.queue.pop.next = self.pop.val();
                if self.pop.val() {
                    self.ent.d.next = self.queue.top_data.val();
                    self.ent_valid.d.next = true;
                    self.ent_second.d.next = false;
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
                        // two entries, one per clock; LIFO pushes the second first, so that
                        // the first is popped first
                        self.pend.d.next = true;
                        if self.mode_lifo.q.val() {
                            self.queue.push_data.next = self.e1.val();
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
                // TRI_UNIT's ports from the held triangle words (crate::memory::TriWord order)
                for k in 0..3 {
                    self.tri_unit.a_v_x[k].next = self.ta_word.q.val().get_bits::<$W>(3 * k * $W);
                    self.tri_unit.a_v_y[k].next = self.ta_word.q.val().get_bits::<$W>((3 * k + 1) * $W);
                    self.tri_unit.a_v_z[k].next = self.ta_word.q.val().get_bits::<$W>((3 * k + 2) * $W);
                    self.tri_unit.b_v_x[k].next = self.tb_word.q.val().get_bits::<$W>(3 * k * $W);
                    self.tri_unit.b_v_y[k].next = self.tb_word.q.val().get_bits::<$W>((3 * k + 1) * $W);
                    self.tri_unit.b_v_z[k].next = self.tb_word.q.val().get_bits::<$W>((3 * k + 2) * $W);
                }
                for c in 0..4 {
                    self.tri_unit.a_m_0[c].next = self.ta_word.q.val().get_bits::<$W>((9 + c) * $W);
                    self.tri_unit.a_m_1[c].next = self.ta_word.q.val().get_bits::<$W>((13 + c) * $W);
                    self.tri_unit.a_m_2[c].next = self.ta_word.q.val().get_bits::<$W>((17 + c) * $W);
                    self.tri_unit.b_m_0[c].next = self.tb_word.q.val().get_bits::<$W>((9 + c) * $W);
                    self.tri_unit.b_m_1[c].next = self.tb_word.q.val().get_bits::<$W>((13 + c) * $W);
                    self.tri_unit.b_m_2[c].next = self.tb_word.q.val().get_bits::<$W>((17 + c) * $W);
                }
                self.tri_unit.a_e_lin.next = self.ta_word.q.val().get_bits::<$W>(21 * $W);
                self.tri_unit.a_e_tr.next = self.ta_word.q.val().get_bits::<$W>(22 * $W);
                self.tri_unit.a_l_norm.next = self.ta_word.q.val().get_bits::<$W>(23 * $W);
                self.tri_unit.a_v_exact.next = self.ta_word.q.val().get_bit(24 * $W);
                self.tri_unit.a_degenerate.next = self.ta_word.q.val().get_bit(24 * $W + 1);
                self.tri_unit.b_e_lin.next = self.tb_word.q.val().get_bits::<$W>(21 * $W);
                self.tri_unit.b_e_tr.next = self.tb_word.q.val().get_bits::<$W>(22 * $W);
                self.tri_unit.b_l_norm.next = self.tb_word.q.val().get_bits::<$W>(23 * $W);
                self.tri_unit.b_v_exact.next = self.tb_word.q.val().get_bit(24 * $W);
                self.tri_unit.b_degenerate.next = self.tb_word.q.val().get_bit(24 * $W + 1);
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
                self.halt_idle.next = (self.inflight.q.val() == 0) & !self.pend.q.val() & !self.outstanding.q.val()
                    & (self.tri_open.q.val() == 0) & !self.push_root.q.val() & (self.leaf_count.q.val() == 0);
                self.all_idle.next = self.halt_idle.val() & self.queue.empty.val() & !self.ent_valid.q.val()
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
                    self.ent_valid.d.next = false;
                    self.leaf_valid.d.next = false;
                    self.na_ok.d.next = false;
                    self.nb_ok.d.next = false;
                    self.ta_ok.d.next = false;
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
        pub fn chip_top<const N: usize, const NP1: usize>(dop: Rounding, tri: Rounding) -> CollisionChip<N, NP1> {
            top_level!(CollisionChip::<N, NP1>::new(dop, tri); clock, host_we, host_addr, host_data, start,
                mem_req_ready, mem_resp_valid, mem_resp_data, res_ready)
        }

        /// Verilog of the chip with `2^N` queue entries (top module `top`).
        pub fn verilog_chip<const N: usize, const NP1: usize>(dop: Rounding, tri: Rounding) -> String {
            generate_verilog(&chip_top::<N, NP1>(dop, tri))
        }
    };
}
pub(crate) use chip;
