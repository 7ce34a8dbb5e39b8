//! WSCG'03's Memory Controller (§4.4) in RTL: the ask list of the Stack Engine's
//! sequencer, the requests to memory, the node records arrived and the stream of DOPs into
//! the DOP Unit. Stamped out per memory word by `memory_controller!` (binary32, k = 24: a
//! DOP is three 256-bit bundles).

/// Stamps out `MemoryController` in the calling module. Arguments: `MW` memory-word bits
/// (a record: slot 0's node word, slot 1's from bit `NW`), `NW` node-word bits, `TW`
/// triangle-word bits, `F0` the bit of a node word's first 32-bit field (1 + k W).
macro_rules! memory_controller {
    ($MW:tt, $NW:tt, $TW:tt, $F0:tt) => {
        /// WSCG'03's Memory Controller (§4.4). Its clocked model is
        /// [`MemoryController`](crate::cycle::wscg03::memory_controller::MemoryController),
        /// equal on every port every clock (tb/wscg03.rs).
        ///
        /// * The ask list (`ask_e`, [`MC_ASKS`](crate::chip::rtl::MC_ASKS) entries, the head
        ///   in entry 0, shifted down as it goes): `push` writes `{load, set, pair, fetch,
        ///   id}`: a load of B's node `push_id` (and its sibling, `push_pair`) or the
        ///   aligned node `push_id`, against d' set `push_set`, at the record `id >> 1` of
        ///   B's or A's node region (its address added when it is requested, so that no
        ///   adder follows the sequencer's push). An aligned node in the record of the
        ///   aligned node before it (`last_al`, no load between) does not fetch it again
        ///   (`fetch` low).
        /// * Requests (`mem_req_valid`, `mem_req_addr`), while at most `port_out` are
        ///   outstanding: A's triangle word (`need_a`, record `ta_id`) unless one is
        ///   outstanding, B's (`need_b`, `tb_id`), else the first ask not requested, while
        ///   the records held and in flight are fewer than
        ///   [`MC_RECORDS`](crate::chip::rtl::MC_RECORDS) (`req_tri`: a triangle word's).
        ///   Taken with `mem_req_ready`; the
        ///   destination and record join the tag ring (`tag_d`, `tag_r`).
        /// * A response (`mem_resp_valid`) belongs to the oldest tag: a triangle word goes to
        ///   the Triangle Unit's input stage (`fill_a`/`fill_b`, `fill_id`, `fill_word`), a
        ///   node record into the records held (`held0`, `held1`).
        /// * The head ask streams a bundle a clock (unless `halt`; its first once its record
        ///   is held and its set not `busy`): a load's `t_*` (side 0, then 1 if a pair;
        ///   `ld_*`: the set and the members' fields, with the first bundle), an aligned
        ///   node's `a_*` and `e` (`al_*`: its fields, with the last). Its first bundle moves
        ///   a fetched record from `held0` into `cur`, which the asks after it read.
        ///   Fields: `id[16]`, `leaf`, the two 32-bit fields; outputs not valid are 0.
        ///
        /// `clear` (a start, with no request outstanding: `pending` low) empties the ask
        /// list and the records. Outputs are read before the clock's edge (they read this
        /// clock's inputs); `room` is the ask list's free entries.
        #[derive(LogicBlock)]
        pub struct MemoryController {
            pub clock: Signal<In, Clock>,
            pub clear: Signal<In, Bit>,
            pub halt: Signal<In, Bit>,
            pub push: Signal<In, Bit>,
            pub push_load: Signal<In, Bit>,
            pub push_set: Signal<In, Bit>,
            pub push_pair: Signal<In, Bit>,
            pub push_id: Signal<In, Bits<16>>,
            pub need_a: Signal<In, Bit>,
            pub need_b: Signal<In, Bit>,
            pub ta_id: Signal<In, Bits<16>>,
            pub tb_id: Signal<In, Bits<16>>,
            pub base_na: Signal<In, Bits<24>>,
            pub base_nb: Signal<In, Bits<24>>,
            pub base_ta: Signal<In, Bits<24>>,
            pub base_tb: Signal<In, Bits<24>>,
            pub port_out: Signal<In, Bits<4>>,
            pub mem_req_ready: Signal<In, Bit>,
            pub mem_resp_valid: Signal<In, Bit>,
            pub mem_resp_data: Signal<In, Bits<$MW>>,
            pub busy: Signal<In, Bits<2>>,
            pub room: Signal<Out, Bits<4>>,
            pub pending: Signal<Out, Bit>,
            pub mem_req_valid: Signal<Out, Bit>,
            pub mem_req_addr: Signal<Out, Bits<24>>,
            pub req_tri: Signal<Out, Bit>,
            pub fill_a: Signal<Out, Bit>,
            pub fill_b: Signal<Out, Bit>,
            pub fill_id: Signal<Out, Bits<16>>,
            pub fill_word: Signal<Out, Bits<$TW>>,
            pub t_valid: Signal<Out, Bit>,
            pub t_set: Signal<Out, Bit>,
            pub t_side: Signal<Out, Bit>,
            pub t_entry: Signal<Out, Bits<2>>,
            pub t_last: Signal<Out, Bit>,
            pub t_data: Signal<Out, Bits<256>>,
            pub a_valid: Signal<Out, Bit>,
            pub a_first: Signal<Out, Bit>,
            pub a_set: Signal<Out, Bit>,
            pub a_entry: Signal<Out, Bits<2>>,
            pub e: Signal<Out, Bits<256>>,
            pub al_valid: Signal<Out, Bit>,
            pub al_id: Signal<Out, Bits<16>>,
            pub al_leaf: Signal<Out, Bit>,
            pub al_f0: Signal<Out, Bits<32>>,
            pub al_f1: Signal<Out, Bits<32>>,
            pub ld_valid: Signal<Out, Bit>,
            pub ld_set: Signal<Out, Bit>,
            pub ld_pair: Signal<Out, Bit>,
            pub ld_id: Signal<Out, Bits<16>>,
            pub ld_leaf0: Signal<Out, Bit>,
            pub ld_leaf1: Signal<Out, Bit>,
            pub ld_f00: Signal<Out, Bits<32>>,
            pub ld_f01: Signal<Out, Bits<32>>,
            pub ld_f10: Signal<Out, Bits<32>>,
            pub ld_f11: Signal<Out, Bits<32>>,
            idx8: [Constant<Bits<4>>; 8],
            asks: Constant<Bits<4>>,
            idx16: [Constant<Bits<4>>; 16],
            // the ask list: bit 0 load, 1 set, 2 pair, 3 fetch, 4.. id, 20.. address
            ask_e: [DFF<Bits<20>>; 8],
            ask_req: [DFF<Bit>; 8],
            ask_n: DFF<Bits<4>>,
            last_al: DFF<Bits<16>>,
            last_al_v: DFF<Bit>,
            // the requests outstanding: destination (0 A's node, 1 B's, 2 A's triangle,
            // 3 B's) and record, oldest at `tag_head`
            tag_d: [DFF<Bits<2>>; 16],
            tag_r: [DFF<Bits<16>>; 16],
            tag_head: DFF<Bits<4>>,
            tag_n: DFF<Bits<5>>,
            ta_out: DFF<Bit>,
            tb_out: DFF<Bit>,
            node_inf: DFF<Bits<2>>,
            // the records held (held0 first), the one streamed, the head ask's bundles
            held0: DFF<Bits<$MW>>,
            held1: DFF<Bits<$MW>>,
            held_n: DFF<Bits<2>>,
            cur: DFF<Bits<$MW>>,
            beat: DFF<Bits<3>>,
            c_e0: Signal<Local, Bits<20>>,
            c_load: Signal<Local, Bit>,
            c_set: Signal<Local, Bit>,
            c_pair: Signal<Local, Bit>,
            c_fetch: Signal<Local, Bit>,
            c_id: Signal<Local, Bits<16>>,
            c_first: Signal<Local, Bit>,
            c_rec: Signal<Local, Bits<$MW>>,
            c_ok: Signal<Local, Bit>,
            c_side: Signal<Local, Bit>,
            c_entry: Signal<Local, Bits<3>>,
            c_slot: Signal<Local, Bit>,
            c_word: Signal<Local, Bits<$NW>>,
            c_w0: Signal<Local, Bits<$NW>>,
            c_w1: Signal<Local, Bits<$NW>>,
            c_bundle: Signal<Local, Bits<256>>,
            c_last: Signal<Local, Bit>,
            c_pop: Signal<Local, Bit>,
            c_take: Signal<Local, Bit>,
            c_rq_found: Signal<Local, Bit>,
            c_rq_idx: Signal<Local, Bits<4>>,
            c_rq_e: Signal<Local, Bits<20>>,
            c_rq_base: Signal<Local, Bits<24>>,
            c_tag_ok: Signal<Local, Bit>,
            c_req_ta: Signal<Local, Bit>,
            c_req_tb: Signal<Local, Bit>,
            c_req_node: Signal<Local, Bit>,
            c_accept: Signal<Local, Bit>,
            c_acc_d: Signal<Local, Bits<2>>,
            c_acc_r: Signal<Local, Bits<16>>,
            c_hd_d: Signal<Local, Bits<2>>,
            c_hd_r: Signal<Local, Bits<16>>,
            c_resp_node: Signal<Local, Bit>,
            c_push_rec: Signal<Local, Bits<16>>,
            c_push_fetch: Signal<Local, Bit>,
            c_push_at: Signal<Local, Bits<4>>,
            c_tag_at: Signal<Local, Bits<4>>,
        }

        /// The kernel, part 1: the head ask's bundle, the request, the response.
        struct McStream;

        impl crate::rtl::kernel::Kernel<McStream> for MemoryController {
            #[hdl_gen]
            fn update(&mut self) {
                // the head ask and the record it reads
                self.c_e0.next = self.ask_e[0].q.val();
                self.c_load.next = self.c_e0.val().get_bit(0);
                self.c_set.next = self.c_e0.val().get_bit(1);
                self.c_pair.next = self.c_e0.val().get_bit(2);
                self.c_fetch.next = self.c_e0.val().get_bit(3);
                self.c_id.next = self.c_e0.val().get_bits::<16>(4);
                self.c_first.next = self.beat.q.val() == 0;
                if self.c_first.val() & self.c_fetch.val() {
                    self.c_rec.next = self.held0.q.val();
                } else {
                    self.c_rec.next = self.cur.q.val();
                }
                self.c_ok.next = (self.ask_n.q.val() != 0)
                    & !self.halt.val()
                    & !(self.c_first.val() & self.c_fetch.val() & (self.held_n.q.val() == 0))
                    & !(self.c_first.val() & (self.busy.val().get_bit(0) & !self.c_set.val()))
                    & !(self.c_first.val() & (self.busy.val().get_bit(1) & self.c_set.val()));
                // a load's side 1 is beats 3 to 5; the node word of the bundle's slot
                self.c_side.next = self.c_load.val() & (self.beat.q.val() > 2);
                if self.c_side.val() {
                    self.c_entry.next = self.beat.q.val() - 3;
                } else {
                    self.c_entry.next = self.beat.q.val();
                }
                if self.c_load.val() & self.c_pair.val() {
                    self.c_slot.next = self.c_side.val();
                } else {
                    self.c_slot.next = self.c_id.val().get_bit(0);
                }
                self.c_w0.next = self.c_rec.val().get_bits::<$NW>(0);
                self.c_w1.next = self.c_rec.val().get_bits::<$NW>($NW);
                if self.c_slot.val() {
                    self.c_word.next = self.c_w1.val();
                } else {
                    self.c_word.next = self.c_w0.val();
                }
                if self.c_entry.val() == 0 {
                    self.c_bundle.next = self.c_word.val().get_bits::<256>(1);
                } else if self.c_entry.val() == 1 {
                    self.c_bundle.next = self.c_word.val().get_bits::<256>(257);
                } else {
                    self.c_bundle.next = self.c_word.val().get_bits::<256>(513);
                }
                if self.c_load.val() & self.c_pair.val() {
                    self.c_last.next = self.beat.q.val() == 5;
                } else {
                    self.c_last.next = self.beat.q.val() == 2;
                }
                self.c_pop.next = self.c_ok.val() & self.c_last.val();
                self.c_take.next = self.c_ok.val() & self.c_first.val() & self.c_fetch.val();
                // the first ask not requested (the lowest entry wins)
                self.c_rq_found.next = false;
                self.c_rq_idx.next = 0.into();
                self.c_rq_e.next = 0.into();
                for j in 0..8 {
                    if (self.idx8[7 - j].val() < self.ask_n.q.val()) & !self.ask_req[7 - j].q.val() {
                        self.c_rq_found.next = true;
                        self.c_rq_idx.next = self.idx8[7 - j].val();
                        self.c_rq_e.next = self.ask_e[7 - j].q.val();
                    }
                }
                self.c_rq_base.next = self.base_na.val();
                if self.c_rq_e.val().get_bit(0) {
                    self.c_rq_base.next = self.base_nb.val();
                }
                self.c_tag_ok.next = self.tag_n.q.val() <= bit_cast::<5, 4>(self.port_out.val());
                self.c_req_ta.next = self.c_tag_ok.val() & self.need_a.val() & !self.ta_out.q.val();
                self.c_req_tb.next = self.c_tag_ok.val() & self.need_b.val() & !self.tb_out.q.val()
                    & !self.c_req_ta.val();
                self.c_req_node.next = self.c_tag_ok.val() & !self.c_req_ta.val() & !self.c_req_tb.val()
                    & self.c_rq_found.val()
                    & (bit_cast::<3, 2>(self.held_n.q.val()) + bit_cast::<3, 2>(self.node_inf.q.val()) < 2);
                self.mem_req_valid.next = self.c_req_ta.val() | self.c_req_tb.val() | self.c_req_node.val();
                self.req_tri.next = self.c_req_ta.val() | self.c_req_tb.val();
                self.c_accept.next = self.mem_req_valid.val() & self.mem_req_ready.val();
                if self.c_req_ta.val() {
                    self.mem_req_addr.next = self.base_ta.val() + bit_cast::<24, 16>(self.ta_id.val());
                    self.c_acc_d.next = 2.into();
                    self.c_acc_r.next = self.ta_id.val();
                } else if self.c_req_tb.val() {
                    self.mem_req_addr.next = self.base_tb.val() + bit_cast::<24, 16>(self.tb_id.val());
                    self.c_acc_d.next = 3.into();
                    self.c_acc_r.next = self.tb_id.val();
                } else if self.c_req_node.val() {
                    self.mem_req_addr.next =
                        self.c_rq_base.val() + bit_cast::<24, 16>(self.c_rq_e.val().get_bits::<16>(4) >> 1);
                    self.c_acc_d.next = bit_cast::<2, 1>(self.c_rq_e.val().get_bits::<1>(0));
                    self.c_acc_r.next = self.c_rq_e.val().get_bits::<16>(4) >> 1;
                } else {
                    self.mem_req_addr.next = 0.into();
                    self.c_acc_d.next = 0.into();
                    self.c_acc_r.next = 0.into();
                }
                // the response: the oldest tag's
                self.c_hd_d.next = 0.into();
                self.c_hd_r.next = 0.into();
                for j in 0..16 {
                    if self.tag_head.q.val() == self.idx16[j].val() {
                        self.c_hd_d.next = self.tag_d[j].q.val();
                        self.c_hd_r.next = self.tag_r[j].q.val();
                    }
                }
                self.c_resp_node.next = self.mem_resp_valid.val() & !self.c_hd_d.val().get_bit(1);
                self.fill_a.next = self.mem_resp_valid.val() & (self.c_hd_d.val() == 2);
                self.fill_b.next = self.mem_resp_valid.val() & (self.c_hd_d.val() == 3);
                self.fill_id.next = 0.into();
                self.fill_word.next = 0.into();
                if self.fill_a.val() | self.fill_b.val() {
                    self.fill_id.next = self.c_hd_r.val();
                    self.fill_word.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                }
            }
        }

        /// Part 2: the outputs to the DOP Unit and the sequencer; the edge.
        struct McEdge;

        impl crate::rtl::kernel::Kernel<McEdge> for MemoryController {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, ask_n, last_al, last_al_v, tag_head, tag_n, ta_out, tb_out);
                dff_setup!(self, clock, node_inf, held0, held1, held_n, cur, beat);
                self.t_valid.next = self.c_ok.val() & self.c_load.val();
                self.a_valid.next = self.c_ok.val() & !self.c_load.val();
                self.al_valid.next = self.a_valid.val() & self.c_last.val();
                self.ld_valid.next = self.t_valid.val() & self.c_first.val();
                self.t_set.next = self.t_valid.val() & self.c_set.val();
                self.t_side.next = self.t_valid.val() & self.c_side.val();
                self.t_last.next = self.t_valid.val() & self.c_last.val();
                self.a_first.next = self.a_valid.val() & self.c_first.val();
                self.a_set.next = self.a_valid.val() & self.c_set.val();
                self.t_entry.next = 0.into();
                self.t_data.next = 0.into();
                self.a_entry.next = 0.into();
                self.e.next = 0.into();
                if self.t_valid.val() {
                    self.t_entry.next = self.c_entry.val().get_bits::<2>(0);
                    self.t_data.next = self.c_bundle.val();
                }
                if self.a_valid.val() {
                    self.a_entry.next = self.c_entry.val().get_bits::<2>(0);
                    self.e.next = self.c_bundle.val();
                }
                self.al_id.next = 0.into();
                self.al_leaf.next = false;
                self.al_f0.next = 0.into();
                self.al_f1.next = 0.into();
                if self.al_valid.val() {
                    self.al_id.next = self.c_id.val();
                    self.al_leaf.next = self.c_word.val().get_bit(0);
                    self.al_f0.next = self.c_word.val().get_bits::<32>($F0);
                    self.al_f1.next = self.c_word.val().get_bits::<32>($F0 + 32);
                }
                self.ld_set.next = self.ld_valid.val() & self.c_set.val();
                self.ld_pair.next = self.ld_valid.val() & self.c_pair.val();
                self.ld_id.next = 0.into();
                self.ld_leaf0.next = false;
                self.ld_leaf1.next = false;
                self.ld_f00.next = 0.into();
                self.ld_f01.next = 0.into();
                self.ld_f10.next = 0.into();
                self.ld_f11.next = 0.into();
                if self.ld_valid.val() {
                    // member 0: the word in the bundle's slot (slot 0 of a pair)
                    self.ld_id.next = self.c_id.val();
                    self.ld_leaf0.next = self.c_word.val().get_bit(0);
                    self.ld_f00.next = self.c_word.val().get_bits::<32>($F0);
                    self.ld_f01.next = self.c_word.val().get_bits::<32>($F0 + 32);
                }
                if self.ld_pair.val() {
                    self.ld_leaf1.next = self.c_w1.val().get_bit(0);
                    self.ld_f10.next = self.c_w1.val().get_bits::<32>($F0);
                    self.ld_f11.next = self.c_w1.val().get_bits::<32>($F0 + 32);
                }
                self.room.next = self.asks.val() - self.ask_n.q.val();
                self.pending.next = self.tag_n.q.val() != 0;
                // the head ask's beats; the record it takes
                if self.c_ok.val() {
                    self.beat.d.next = self.beat.q.val() + 1;
                }
                if self.c_pop.val() {
                    self.beat.d.next = 0.into();
                }
                if self.c_take.val() {
                    self.cur.d.next = self.held0.q.val();
                    self.held0.d.next = self.held1.q.val();
                }
                // a node record arrives: behind the records still held
                if self.c_resp_node.val() {
                    if (self.held_n.q.val() == 0) | ((self.held_n.q.val() == 1) & self.c_take.val()) {
                        self.held0.d.next = self.mem_resp_data.val();
                    } else {
                        self.held1.d.next = self.mem_resp_data.val();
                    }
                }
                self.held_n.d.next = self.held_n.q.val() + bit_cast::<2, 1>(self.c_resp_node.val().into())
                    - bit_cast::<2, 1>(self.c_take.val().into());
                self.node_inf.d.next = self.node_inf.q.val()
                    + bit_cast::<2, 1>((self.c_accept.val() & self.c_req_node.val()).into())
                    - bit_cast::<2, 1>(self.c_resp_node.val().into());
            }
        }

        /// Part 3: the ask list, the tags.
        struct McLists;

        impl crate::rtl::kernel::Kernel<McLists> for MemoryController {
            #[hdl_gen]
            fn update(&mut self) {
                // the ask pushed: whether it fetches its record
                self.c_push_rec.next = self.push_id.val() >> 1;
                self.c_push_fetch.next = self.push_load.val() | !self.last_al_v.q.val()
                    | (self.last_al.q.val() != self.c_push_rec.val());
                if self.push.val() & !self.push_load.val() {
                    self.last_al_v.d.next = true;
                    self.last_al.d.next = self.c_push_rec.val();
                }
                if self.push.val() & self.push_load.val() {
                    self.last_al_v.d.next = false;
                }
                self.c_push_at.next = self.ask_n.q.val() - bit_cast::<4, 1>(self.c_pop.val().into());
                self.ask_n.d.next = self.c_push_at.val() + bit_cast::<4, 1>(self.push.val().into());
                for j in 0..8 {
                    self.ask_e[j].clock.next = self.clock.val();
                    self.ask_req[j].clock.next = self.clock.val();
                    self.ask_e[j].d.next = self.ask_e[j].q.val();
                    self.ask_req[j].d.next = self.ask_req[j].q.val()
                        | (self.c_accept.val() & self.c_req_node.val() & (self.c_rq_idx.val() == self.idx8[j].val()));
                }
                // the head gone: every entry one down
                for j in 1..8 {
                    if self.c_pop.val() {
                        self.ask_e[j - 1].d.next = self.ask_e[j].q.val();
                        self.ask_req[j - 1].d.next = self.ask_req[j].q.val()
                            | (self.c_accept.val() & self.c_req_node.val() & (self.c_rq_idx.val() == self.idx8[j].val()));
                    }
                }
                for j in 0..8 {
                    if self.push.val() & (self.c_push_at.val() == self.idx8[j].val()) {
                        self.ask_e[j].d.next = bit_cast::<20, 1>(self.push_load.val().into())
                            | (bit_cast::<20, 1>(self.push_set.val().into()) << 1)
                            | (bit_cast::<20, 1>(self.push_pair.val().into()) << 2)
                            | (bit_cast::<20, 1>(self.c_push_fetch.val().into()) << 3)
                            | (bit_cast::<20, 16>(self.push_id.val()) << 4);
                        self.ask_req[j].d.next = !self.c_push_fetch.val();
                    }
                }
                // the tags: one joins at an accept, the oldest leaves with a response
                self.c_tag_at.next = (self.tag_head.q.val() + self.tag_n.q.val().get_bits::<4>(0));
                for j in 0..16 {
                    self.tag_d[j].clock.next = self.clock.val();
                    self.tag_r[j].clock.next = self.clock.val();
                    self.tag_d[j].d.next = self.tag_d[j].q.val();
                    self.tag_r[j].d.next = self.tag_r[j].q.val();
                    if self.c_accept.val() & (self.c_tag_at.val() == self.idx16[j].val()) {
                        self.tag_d[j].d.next = self.c_acc_d.val();
                        self.tag_r[j].d.next = self.c_acc_r.val();
                    }
                }
                self.tag_n.d.next = self.tag_n.q.val() + bit_cast::<5, 1>(self.c_accept.val().into())
                    - bit_cast::<5, 1>(self.mem_resp_valid.val().into());
                if self.mem_resp_valid.val() {
                    self.tag_head.d.next = self.tag_head.q.val() + 1;
                }
                if self.c_accept.val() & self.c_req_ta.val() {
                    self.ta_out.d.next = true;
                }
                if self.fill_a.val() {
                    self.ta_out.d.next = false;
                }
                if self.c_accept.val() & self.c_req_tb.val() {
                    self.tb_out.d.next = true;
                }
                if self.fill_b.val() {
                    self.tb_out.d.next = false;
                }
                if self.clear.val() {
                    self.ask_n.d.next = 0.into();
                    self.held_n.d.next = 0.into();
                    self.beat.d.next = 0.into();
                    self.last_al_v.d.next = false;
                }
            }
        }

        crate::rtl::kernel::kernel!([] MemoryController: McStream, McEdge, McLists);

        impl Default for MemoryController {
            fn default() -> Self {
                MemoryController {
                    clock: Default::default(),
                    clear: Default::default(),
                    halt: Default::default(),
                    push: Default::default(),
                    push_load: Default::default(),
                    push_set: Default::default(),
                    push_pair: Default::default(),
                    push_id: Default::default(),
                    need_a: Default::default(),
                    need_b: Default::default(),
                    ta_id: Default::default(),
                    tb_id: Default::default(),
                    base_na: Default::default(),
                    base_nb: Default::default(),
                    base_ta: Default::default(),
                    base_tb: Default::default(),
                    port_out: Default::default(),
                    mem_req_ready: Default::default(),
                    mem_resp_valid: Default::default(),
                    mem_resp_data: Default::default(),
                    busy: Default::default(),
                    room: Default::default(),
                    pending: Default::default(),
                    mem_req_valid: Default::default(),
                    mem_req_addr: Default::default(),
                    req_tri: Default::default(),
                    fill_a: Default::default(),
                    fill_b: Default::default(),
                    fill_id: Default::default(),
                    fill_word: Default::default(),
                    t_valid: Default::default(),
                    t_set: Default::default(),
                    t_side: Default::default(),
                    t_entry: Default::default(),
                    t_last: Default::default(),
                    t_data: Default::default(),
                    a_valid: Default::default(),
                    a_first: Default::default(),
                    a_set: Default::default(),
                    a_entry: Default::default(),
                    e: Default::default(),
                    al_valid: Default::default(),
                    al_id: Default::default(),
                    al_leaf: Default::default(),
                    al_f0: Default::default(),
                    al_f1: Default::default(),
                    ld_valid: Default::default(),
                    ld_set: Default::default(),
                    ld_pair: Default::default(),
                    ld_id: Default::default(),
                    ld_leaf0: Default::default(),
                    ld_leaf1: Default::default(),
                    ld_f00: Default::default(),
                    ld_f01: Default::default(),
                    ld_f10: Default::default(),
                    ld_f11: Default::default(),
                    idx8: std::array::from_fn(|j| Constant::new((j as u64).into())),
                    asks: Constant::new((crate::chip::rtl::MC_ASKS as u64).into()),
                    idx16: std::array::from_fn(|j| Constant::new((j as u64).into())),
                    ask_e: Default::default(),
                    ask_req: Default::default(),
                    ask_n: Default::default(),
                    last_al: Default::default(),
                    last_al_v: Default::default(),
                    tag_d: Default::default(),
                    tag_r: Default::default(),
                    tag_head: Default::default(),
                    tag_n: Default::default(),
                    ta_out: Default::default(),
                    tb_out: Default::default(),
                    node_inf: Default::default(),
                    held0: Default::default(),
                    held1: Default::default(),
                    held_n: Default::default(),
                    cur: Default::default(),
                    beat: Default::default(),
                    c_e0: Default::default(),
                    c_load: Default::default(),
                    c_set: Default::default(),
                    c_pair: Default::default(),
                    c_fetch: Default::default(),
                    c_id: Default::default(),
                    c_first: Default::default(),
                    c_rec: Default::default(),
                    c_ok: Default::default(),
                    c_side: Default::default(),
                    c_entry: Default::default(),
                    c_slot: Default::default(),
                    c_word: Default::default(),
                    c_w0: Default::default(),
                    c_w1: Default::default(),
                    c_bundle: Default::default(),
                    c_last: Default::default(),
                    c_pop: Default::default(),
                    c_take: Default::default(),
                    c_rq_found: Default::default(),
                    c_rq_idx: Default::default(),
                    c_rq_e: Default::default(),
                    c_rq_base: Default::default(),
                    c_tag_ok: Default::default(),
                    c_req_ta: Default::default(),
                    c_req_tb: Default::default(),
                    c_req_node: Default::default(),
                    c_accept: Default::default(),
                    c_acc_d: Default::default(),
                    c_acc_r: Default::default(),
                    c_hd_d: Default::default(),
                    c_hd_r: Default::default(),
                    c_resp_node: Default::default(),
                    c_push_rec: Default::default(),
                    c_push_fetch: Default::default(),
                    c_push_at: Default::default(),
                    c_tag_at: Default::default(),
                }
            }
        }

        /// The Memory Controller ready to simulate as a top-level block.
        pub fn memory_controller_top() -> MemoryController {
            top_level!(MemoryController::default(); clock, clear, halt, push, push_load,
                push_set, push_pair, push_id, need_a, need_b, ta_id, tb_id, base_na, base_nb,
                base_ta, base_tb, port_out, mem_req_ready, mem_resp_valid, mem_resp_data, busy)
        }

        /// Verilog of [`memory_controller_top`] (top module `top`).
        pub fn verilog_memory_controller() -> String {
            generate_verilog(&memory_controller_top())
        }
    };
}
pub(crate) use memory_controller;
