//! The chip's memory port (DATE'05 Fig. 4, between D_CNTR and the memory): the node words
//! D_CNTR's popped pairs ask for, the requests to memory, and the responses routed to the
//! node-word FIFOs in front of the DOP unit or to the triangle words held for TRI_UNIT.
//! Stamped out per node word by `memory_port!` (the chip's `chip!`).

/// Stamps out `MemoryPort` in the calling module. Arguments: `NW` node-word bits, `MW`
/// memory-word bits (`mem_resp_data`), `RW` node-record bits (its low `RW` bits: one node
/// word, or on a chip that reads the `records` layout `SLOTS` node words and, with stored
/// DOP precision, `SW` bits of shared fields after them), `SLOTS` node words a record.
macro_rules! memory_port {
    ($NW:tt, $MW:tt, $RW:tt, $SLOTS:tt $(, shared $SW:tt)?) => {
        /// The memory port: up to [`PORT`](crate::chip::reg::PORT)`[7:4] + 1` requests outstanding, answered in request
        /// order. Golden: [`cycle::memory_port::MemPort`](crate::cycle::memory_port::MemPort) (the
        /// requests outstanding, whose destinations here are the tag ring `tags`) and the
        /// node-word lists of [`cycle::chip`](crate::cycle::chip) (`to_ask`, `words`); cycle
        /// semantics: docs/explanation/architecture.md, "Cycle semantics" (Node words, Memory requests).
        ///
        /// * The ask list (`ask_w`, [`ASK_LIST`](crate::chip::rtl::ASK_LIST) words `{pair number
        ///   mod 32, B, id}`): a `pop` of D_CNTR appends the node words its pairs fetch
        ///   (`pop_fetch`: A0 B0 A1 B1), in pair order; `seq_head` is the number of the pair
        ///   at the DOP unit's input (an `issue` moves it on), so that at prefetch 0 (`pf_on`
        ///   low) only the current pair's words are asked for.
        /// * Requests, by priority: A's triangle word (`need_ta`, unless one is outstanding),
        ///   B's (`need_tb`), the node word at the head of the ask list; while fewer than
        ///   `port_out + 1` are outstanding and `go`. Addresses: of the record (a node's id,
        ///   `records`: `id >> slot_bits`; the triangle's `leaf_tag` field, where the chip puts the
        ///   records in the `records` layout) in the destination's region, whose first word is
        ///   its base, placed by `map` (register [`MAP`](crate::chip::reg::MAP), shifts and
        ///   masks: [`RecordMap::addr`](crate::chip::layout::RecordMap::addr); 0: base plus
        ///   record). A request is taken (`accept`) with `mem_req_ready`; its destination
        ///   `req_dst` (0 A's node, 1 B's node, 2 A's triangle, 3 B's triangle) joins the tag
        ///   ring, a triangle id its pending register (`ta_req`, `tb_req`).
        /// * A response (`mem_resp_valid`, `resp` while a request is outstanding) belongs to
        ///   the oldest tag (`resp_dst`): a node word goes into its FIFO (`wa`: A's, the DOP
        ///   unit's e; `wb`: B's, d; [`PAIR_BUF`](crate::chip::rtl::PAIR_BUF) words each); a
        ///   triangle word is the chip's to hold (`resp`, `resp_dst`, `ta_req`, `tb_req`).
        /// * The DOP unit's words of the current pair (`na_in`, `nb_in`): of the record at the
        ///   FIFO's head if the pair fetches it (`cur_fa`, `cur_fb`), else of the last pair's
        ///   (`na_word`, `nb_word`), the node word in the pair's slot (`cur_sa`, `cur_sb`:
        ///   `records`, slot s from bit `s NW`; else 0, the record is the word), and with
        ///   stored DOP precision the record's shared fields (`na_sh`, `nb_sh`, from bit
        ///   `SLOTS NW`); an `issue` takes the fetched heads.
        ///   `wa_empty`, `wb_empty`: D_CNTR's pair waits for a word.
        ///
        /// `clear` (a start) empties the ask list and the FIFOs; requests outstanding
        /// finish as they would.
        #[derive(LogicBlock)]
        pub struct MemoryPort {
            pub clock: Signal<In, Clock>,
            pub clear: Signal<In, Bit>,
            pub go: Signal<In, Bit>,
            pub pf_on: Signal<In, Bit>,
            pub slot_bits: Signal<In, Bits<3>>,
            pub port_out: Signal<In, Bits<4>>,
            pub base_na: Signal<In, Bits<24>>,
            pub base_nb: Signal<In, Bits<24>>,
            pub base_ta: Signal<In, Bits<24>>,
            pub base_tb: Signal<In, Bits<24>>,
            pub map: Signal<In, Bits<20>>,
            pub pop: Signal<In, Bit>,
            pub pop_entry: Signal<In, Bits<67>>,
            pub pop_fetch: Signal<In, Bits<4>>,
            pub issue: Signal<In, Bit>,
            pub cur_fa: Signal<In, Bit>,
            pub cur_fb: Signal<In, Bit>,
            pub cur_sa: Signal<In, Bits<3>>,
            pub cur_sb: Signal<In, Bits<3>>,
            pub need_ta: Signal<In, Bit>,
            pub need_tb: Signal<In, Bit>,
            pub leaf_tag: Signal<In, Bits<32>>,
            pub mem_req_ready: Signal<In, Bit>,
            pub mem_resp_valid: Signal<In, Bit>,
            pub mem_resp_data: Signal<In, Bits<$MW>>,
            pub mem_req_valid: Signal<Out, Bit>,
            pub mem_req_addr: Signal<Out, Bits<24>>,
            pub req_dst: Signal<Out, Bits<2>>,
            pub accept: Signal<Out, Bit>,
            pub resp: Signal<Out, Bit>,
            pub resp_dst: Signal<Out, Bits<2>>,
            pub ta_req: Signal<Out, Bits<16>>,
            pub tb_req: Signal<Out, Bits<16>>,
            pub outstanding: Signal<Out, Bit>,
            pub na_in: Signal<Out, Bits<$NW>>,
            pub nb_in: Signal<Out, Bits<$NW>>,
            $(pub na_sh: Signal<Out, Bits<$SW>>,
            pub nb_sh: Signal<Out, Bits<$SW>>,)?
            pub wa_empty: Signal<Out, Bit>,
            pub wb_empty: Signal<Out, Bit>,
            // ---- node words to ask for, in pair order: {pair number mod 32, B, id}
            // (four write ports: a popped entry's words; not a RegRing)
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
            ask_take: Signal<Local, Bit>,
            top_two: Signal<Local, Bit>,
            put0: Signal<Local, Bits<32>>,
            put1: Signal<Local, Bits<32>>,
            put2: Signal<Local, Bits<32>>,
            put3: Signal<Local, Bits<32>>,
            // ---- node records arrived, per destination in request order (A's: e, B's: d),
            // and the records of the last pair issued
            wa: $crate::rtl::reg_ring::RegRing<$RW, { $crate::chip::rtl::PAIR_BUF }>,
            wa_head: DFF<Bits<4>>,
            wa_tail: DFF<Bits<4>>,
            wa_n: DFF<Bits<5>>,
            wb: $crate::rtl::reg_ring::RegRing<$RW, { $crate::chip::rtl::PAIR_BUF }>,
            wb_head: DFF<Bits<4>>,
            wb_tail: DFF<Bits<4>>,
            wb_n: DFF<Bits<5>>,
            na_word: DFF<Bits<$RW>>,
            nb_word: DFF<Bits<$RW>>,
            rec_a: Signal<Local, Bits<$RW>>,
            rec_b: Signal<Local, Bits<$RW>>,
            sa_dec: Signal<Local, Bits<8>>,
            sb_dec: Signal<Local, Bits<8>>,
            // ---- the destinations of the requests outstanding, in order, and the triangle
            // word asked for per triangle destination (one at a time)
            tags: $crate::rtl::reg_ring::RegRing<2, { $crate::chip::rtl::PORT_OUTSTANDING }>,
            tag_head: DFF<Bits<4>>,
            tag_tail: DFF<Bits<4>>,
            tag_n: DFF<Bits<5>>,
            ta_pend: DFF<Bit>,
            ta_req_r: DFF<Bits<16>>,
            tb_pend: DFF<Bit>,
            tb_req_r: DFF<Bits<16>>,
            port_free: Signal<Local, Bit>,
            req: Signal<Local, Bit>,
            req_id: Signal<Local, Bits<16>>,
            ask_rec: Signal<Local, Bits<16>>,
            req_addr: Signal<Local, Bits<24>>,
            req_base: Signal<Local, Bits<24>>,
            req_rec: Signal<Local, Bits<24>>,
            map_ln: Signal<Local, Bits<5>>,
            map_lp: Signal<Local, Bits<5>>,
            map_lb: Signal<Local, Bits<5>>,
            c_one24: Constant<Bits<24>>,
            c_one16: Constant<Bits<16>>,
            c_one32: Constant<Bits<32>>,
            c_one8: Constant<Bits<8>>,
        }

        impl MemoryPort {
            pub fn new() -> Self {
                use $crate::rtl::reg_ring::array_init;
                Self {
                    clock: Default::default(),
                    clear: Default::default(),
                    go: Default::default(),
                    pf_on: Default::default(),
                    slot_bits: Default::default(),
                    port_out: Default::default(),
                    base_na: Default::default(),
                    base_nb: Default::default(),
                    base_ta: Default::default(),
                    base_tb: Default::default(),
                    map: Default::default(),
                    pop: Default::default(),
                    pop_entry: Default::default(),
                    pop_fetch: Default::default(),
                    issue: Default::default(),
                    cur_fa: Default::default(),
                    cur_fb: Default::default(),
                    cur_sa: Default::default(),
                    cur_sb: Default::default(),
                    need_ta: Default::default(),
                    need_tb: Default::default(),
                    leaf_tag: Default::default(),
                    mem_req_ready: Default::default(),
                    mem_resp_valid: Default::default(),
                    mem_resp_data: Default::default(),
                    mem_req_valid: Default::default(),
                    mem_req_addr: Default::default(),
                    req_dst: Default::default(),
                    accept: Default::default(),
                    resp: Default::default(),
                    resp_dst: Default::default(),
                    ta_req: Default::default(),
                    tb_req: Default::default(),
                    outstanding: Default::default(),
                    na_in: Default::default(),
                    nb_in: Default::default(),
                    $(na_sh: <Signal<Out, Bits<$SW>>>::default(),
                    nb_sh: Default::default(),)?
                    wa_empty: Default::default(),
                    wb_empty: Default::default(),
                    ask_w: array_init(),
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
                    ask_take: Default::default(),
                    top_two: Default::default(),
                    put0: Default::default(),
                    put1: Default::default(),
                    put2: Default::default(),
                    put3: Default::default(),
                    wa: Default::default(),
                    wa_head: Default::default(),
                    wa_tail: Default::default(),
                    wa_n: Default::default(),
                    wb: Default::default(),
                    wb_head: Default::default(),
                    wb_tail: Default::default(),
                    wb_n: Default::default(),
                    na_word: Default::default(),
                    nb_word: Default::default(),
                    rec_a: Default::default(),
                    rec_b: Default::default(),
                    sa_dec: Default::default(),
                    sb_dec: Default::default(),
                    tags: Default::default(),
                    tag_head: Default::default(),
                    tag_tail: Default::default(),
                    tag_n: Default::default(),
                    ta_pend: Default::default(),
                    ta_req_r: Default::default(),
                    tb_pend: Default::default(),
                    tb_req_r: Default::default(),
                    port_free: Default::default(),
                    req: Default::default(),
                    req_id: Default::default(),
                    ask_rec: Default::default(),
                    req_addr: Default::default(),
                    req_base: Default::default(),
                    req_rec: Default::default(),
                    map_ln: Default::default(),
                    map_lp: Default::default(),
                    map_lb: Default::default(),
                    c_one24: Constant::new(1.into()),
                    c_one16: Constant::new(1.into()),
                    c_one32: Constant::new(1.into()),
                    c_one8: Constant::new(1.into()),
                }
            }
        }

        impl Default for MemoryPort {
            fn default() -> Self {
                Self::new()
            }
        }

        $crate::rtl::kernel::kernel!([] MemoryPort: Words, Requests, Responses, Asks);

        /// The current pair's node words, from the records at the heads of the word FIFOs.
        struct Words;

        // The slot loop `1..SLOTS` is empty on a chip of one node word a record (no Verilog);
        // rust-hdl's generated methods repeat it.
        #[allow(clippy::reversed_empty_ranges)]
        impl $crate::rtl::kernel::Kernel<Words> for MemoryPort {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, ask_head, ask_tail, ask_n, seq_head, seq_tail);
                dff_setup!(
                    self, clock, wa_head, wa_tail, wa_n, wb_head, wb_tail, wb_n, na_word, nb_word
                );
                dff_setup!(
                    self, clock, tag_head, tag_tail, tag_n, ta_pend, ta_req_r, tb_pend, tb_req_r
                );
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    self.ask_w[i].clock.next = self.clock.val();
                    self.ask_w[i].d.next = self.ask_w[i].q.val();
                }
                clock!(self, clock, wa, wb, tags);
                // ---- the current pair's node words: of the records at the FIFO heads, or of
                // the last pair's, in the pair's slot (slot s from bit s NW)
                self.wa.rsel.next = self.c_one16.val() << self.wa_head.q.val();
                self.wb.rsel.next = self.c_one16.val() << self.wb_head.q.val();
                self.rec_a.next = self.na_word.q.val();
                if self.cur_fa.val() {
                    self.rec_a.next = self.wa.rdata.val();
                }
                self.rec_b.next = self.nb_word.q.val();
                if self.cur_fb.val() {
                    self.rec_b.next = self.wb.rdata.val();
                }
                self.sa_dec.next = self.c_one8.val() << self.cur_sa.val();
                self.sb_dec.next = self.c_one8.val() << self.cur_sb.val();
                self.na_in.next = self.rec_a.val().get_bits::<$NW>(0);
                self.nb_in.next = self.rec_b.val().get_bits::<$NW>(0);
                for s in 1..$SLOTS {
                    if self.sa_dec.val().get_bit(s) {
                        self.na_in.next = self.rec_a.val().get_bits::<$NW>(s * $NW);
                    }
                    if self.sb_dec.val().get_bit(s) {
                        self.nb_in.next = self.rec_b.val().get_bits::<$NW>(s * $NW);
                    }
                }
                $(self.na_sh.next = self.rec_a.val().get_bits::<$SW>($SLOTS * $NW);
                self.nb_sh.next = self.rec_b.val().get_bits::<$SW>($SLOTS * $NW);)?
                self.wa_empty.next = self.wa_n.q.val() == 0;
                self.wb_empty.next = self.wb_n.q.val() == 0;
                // ---- requests: triangle words first (one outstanding per destination), then
            }
        }

        /// The next request to memory (triangle words first, then the ask list's node words) and
        /// the tag ring that matches each response to its request.
        struct Requests;

        impl $crate::rtl::kernel::Kernel<Requests> for MemoryPort {
            #[hdl_gen]
            fn update(&mut self) {
                // the node word at the head of the ask list (at prefetch 0 only the current
                // pair's), while fewer than port_out + 1 are outstanding
                self.ask_dec.next = self.c_one32.val() << self.ask_head.q.val();
                self.ask_front.next = 0.into();
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    if self.ask_dec.val().get_bit(i) {
                        self.ask_front.next = self.ask_w[i].q.val();
                    }
                }
                self.ask_ok.next = self.go.val()
                    & (self.ask_n.q.val() != 0)
                    & (self.pf_on.val()
                        | (self.ask_front.val().get_bits::<5>(17) == self.seq_head.q.val()));
                self.port_free.next = self.tag_n.q.val() <= bit_cast::<5, 4>(self.port_out.val());
                self.req_dst.next = bit_cast::<2, 1>(self.ask_front.val().get_bits::<1>(16));
                self.req_id.next = self.ask_front.val().get_bits::<16>(0);
                self.ask_rec.next = self.ask_front.val().get_bits::<16>(0) >> self.slot_bits.val();
                self.req_base.next = self.base_na.val();
                if self.ask_front.val().get_bit(16) {
                    self.req_base.next = self.base_nb.val();
                }
                self.req_rec.next = bit_cast::<24, 16>(self.ask_rec.val());
                self.req.next = self.port_free.val() & self.ask_ok.val();
                if self.need_tb.val() & !self.tb_pend.q.val() {
                    self.req_dst.next = 3.into();
                    self.req_id.next = self.leaf_tag.val().get_bits::<16>(16);
                    self.req_base.next = self.base_tb.val();
                    self.req_rec.next = bit_cast::<24, 16>(self.leaf_tag.val().get_bits::<16>(16));
                    self.req.next = self.port_free.val();
                }
                if self.need_ta.val() & !self.ta_pend.q.val() {
                    self.req_dst.next = 2.into();
                    self.req_id.next = self.leaf_tag.val().get_bits::<16>(0);
                    self.req_base.next = self.base_ta.val();
                    self.req_rec.next = bit_cast::<24, 16>(self.leaf_tag.val().get_bits::<16>(0));
                    self.req.next = self.port_free.val();
                }
                // the record's word: row above the bank field, the bank within the
                // region's, the column below (`map`: the log2 of the region's banks, by
                // destination, of a page's records, of the banks)
                self.map_ln.next = bit_cast::<5, 3>(self.map.val().get_bits::<3>(0));
                if self.req_dst.val() == 1 {
                    self.map_ln.next = bit_cast::<5, 3>(self.map.val().get_bits::<3>(3));
                }
                if self.req_dst.val() == 2 {
                    self.map_ln.next = bit_cast::<5, 3>(self.map.val().get_bits::<3>(6));
                }
                if self.req_dst.val() == 3 {
                    self.map_ln.next = bit_cast::<5, 3>(self.map.val().get_bits::<3>(9));
                }
                self.map_lp.next = bit_cast::<5, 4>(self.map.val().get_bits::<4>(12));
                self.map_lb.next = bit_cast::<5, 4>(self.map.val().get_bits::<4>(16));
                self.req_addr.next = self.req_base.val()
                    + ((self.req_rec.val() >> (self.map_ln.val() + self.map_lp.val()))
                        << (self.map_lb.val() + self.map_lp.val()))
                    + ((self.req_rec.val() & ((self.c_one24.val() << self.map_ln.val()) - 1))
                        << self.map_lp.val())
                    + ((self.req_rec.val() >> self.map_ln.val())
                        & ((self.c_one24.val() << self.map_lp.val()) - 1));
                self.mem_req_valid.next = self.req.val();
                self.mem_req_addr.next = self.req_addr.val();
                self.accept.next = self.req.val() & self.mem_req_ready.val();
                // ---- the tag ring: a request taken joins it, a response leaves its head
                self.tags.rsel.next = self.c_one16.val() << self.tag_head.q.val();
                self.resp_dst.next = self.tags.rdata.val();
                self.tags.wsel.next = 0.into();
                if self.accept.val() {
                    self.tags.wsel.next = self.c_one16.val() << self.tag_tail.q.val();
                }
                self.tags.wdata.next = self.req_dst.val();
                self.resp.next = self.mem_resp_valid.val() & (self.tag_n.q.val() != 0);
                if self.accept.val() {
                    self.tag_tail.d.next = self.tag_tail.q.val() + 1;
                    if !self.req_dst.val().get_bit(1) {
                        self.ask_head.d.next = self.ask_head.q.val() + 1;
                    }
                    if self.req_dst.val() == 2 {
                        self.ta_pend.d.next = true;
                        self.ta_req_r.d.next = self.req_id.val();
                    }
                    if self.req_dst.val() == 3 {
                        self.tb_pend.d.next = true;
                        self.tb_req_r.d.next = self.req_id.val();
                    }
                }
                if self.accept.val() & !self.resp.val() {
                    self.tag_n.d.next = self.tag_n.q.val() + 1;
                }
                if self.resp.val() & !self.accept.val() {
                    self.tag_n.d.next = self.tag_n.q.val() - 1;
                }
                // ---- a response: node words into their FIFO (a triangle word is the chip's)
            }
        }

        /// A response's node word into its FIFO, and an issue taking the pair's words out.
        struct Responses;

        impl $crate::rtl::kernel::Kernel<Responses> for MemoryPort {
            #[hdl_gen]
            fn update(&mut self) {
                self.wa.wsel.next = 0.into();
                if self.resp.val() & (self.resp_dst.val() == 0) {
                    self.wa.wsel.next = self.c_one16.val() << self.wa_tail.q.val();
                }
                self.wa.wdata.next = self.mem_resp_data.val().get_bits::<$RW>(0);
                self.wb.wsel.next = 0.into();
                if self.resp.val() & (self.resp_dst.val() == 1) {
                    self.wb.wsel.next = self.c_one16.val() << self.wb_tail.q.val();
                }
                self.wb.wdata.next = self.mem_resp_data.val().get_bits::<$RW>(0);
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
                    }
                    if self.resp_dst.val() == 3 {
                        self.tb_pend.d.next = false;
                    }
                }
                // ---- an issue takes the pair's fetched words from their FIFOs
                if self.issue.val() {
                    self.seq_head.d.next = self.seq_head.q.val() + 1;
                    if self.cur_fa.val() {
                        self.na_word.d.next = self.wa.rdata.val();
                        self.wa_head.d.next = self.wa_head.q.val() + 1;
                    }
                    if self.cur_fb.val() {
                        self.nb_word.d.next = self.wb.rdata.val();
                        self.wb_head.d.next = self.wb_head.q.val() + 1;
                    }
                }
                self.wa_n.d.next = self.wa_n.q.val()
                    + bit_cast::<5, 1>((self.resp.val() & (self.resp_dst.val() == 0)).into())
                    - bit_cast::<5, 1>((self.issue.val() & self.cur_fa.val()).into());
                self.wb_n.d.next = self.wb_n.q.val()
                    + bit_cast::<5, 1>((self.resp.val() & (self.resp_dst.val() == 1)).into())
                    - bit_cast::<5, 1>((self.issue.val() & self.cur_fb.val()).into());
                // ---- a pop: its node words join the ask list in pair order (A0 B0 A1 B1, the
            }
        }

        /// A pop's node words joining the ask list, and the start.
        struct Asks;

        impl $crate::rtl::kernel::Kernel<Asks> for MemoryPort {
            #[hdl_gen]
            fn update(&mut self) {
                // fetched ones), each with its pair's number
                self.top_two.next = self.pop_entry.val().get_bit(66);
                if self.pop.val() {
                    self.seq_tail.d.next =
                        self.seq_tail.q.val() + 1 + bit_cast::<5, 1>(self.top_two.val().into());
                }
                self.seq_tail1.next = self.seq_tail.q.val() + 1;
                self.ask_off1.next = bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(0));
                self.ask_off2.next =
                    self.ask_off1.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(1));
                self.ask_off3.next =
                    self.ask_off2.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(2));
                self.ask_new.next =
                    self.ask_off3.val() + bit_cast::<5, 1>(self.pop_fetch.val().get_bits::<1>(3));
                self.put0.next = self.c_one32.val() << self.ask_tail.q.val();
                self.put1.next =
                    self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off1.val());
                self.put2.next =
                    self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off2.val());
                self.put3.next =
                    self.c_one32.val() << (self.ask_tail.q.val() + self.ask_off3.val());
                for i in 0..$crate::chip::rtl::ASK_LIST {
                    if self.pop.val() & self.pop_fetch.val().get_bit(0) & self.put0.val().get_bit(i)
                    {
                        self.ask_w[i].d.next =
                            bit_cast::<22, 16>(self.pop_entry.val().get_bits::<16>(0))
                                | (bit_cast::<22, 5>(self.seq_tail.q.val()) << 17);
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(1) & self.put1.val().get_bit(i)
                    {
                        self.ask_w[i].d.next =
                            bit_cast::<22, 16>(self.pop_entry.val().get_bits::<16>(16))
                                | (bit_cast::<22, 5>(self.seq_tail.q.val()) << 17)
                                | self.c_ask_b.val();
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(2) & self.put2.val().get_bit(i)
                    {
                        self.ask_w[i].d.next =
                            bit_cast::<22, 16>(self.pop_entry.val().get_bits::<16>(33))
                                | (bit_cast::<22, 5>(self.seq_tail1.val()) << 17);
                    }
                    if self.pop.val() & self.pop_fetch.val().get_bit(3) & self.put3.val().get_bit(i)
                    {
                        self.ask_w[i].d.next =
                            bit_cast::<22, 16>(self.pop_entry.val().get_bits::<16>(49))
                                | (bit_cast::<22, 5>(self.seq_tail1.val()) << 17)
                                | self.c_ask_b.val();
                    }
                }
                self.ask_take.next = self.accept.val() & !self.req_dst.val().get_bit(1);
                self.ask_n.d.next =
                    self.ask_n.q.val() - bit_cast::<6, 1>(self.ask_take.val().into());
                if self.pop.val() {
                    self.ask_tail.d.next = self.ask_tail.q.val() + self.ask_new.val();
                    self.ask_n.d.next = self.ask_n.q.val()
                        - bit_cast::<6, 1>(self.ask_take.val().into())
                        + bit_cast::<6, 5>(self.ask_new.val());
                }
                // ---- a start: the ask list and the node-word FIFOs empty
                if self.clear.val() {
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
                }
                self.ta_req.next = self.ta_req_r.q.val();
                self.tb_req.next = self.tb_req_r.q.val();
                self.outstanding.next = self.tag_n.q.val() != 0;
            }
        }
    };
}
pub(crate) use memory_port;
