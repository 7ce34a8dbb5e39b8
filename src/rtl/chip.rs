//! The collision chip (DATE'05 Fig. 4): D_CNTR, the memory port, the DOP unit and
//! TRI_UNIT joined into one block that runs whole queries, stamped out per format by
//! `chip!`. Host side, memory model and drivers: [`chip_io`](crate::harness::chip_io); cycle
//! semantics: docs/explanation/architecture.md, "Cycle semantics".
//!
//! Its sub-blocks: D_CNTR with its pair queue ([`DCntr`](crate::rtl::d_cntr::DCntr),
//! rtl/d_cntr/), the memory port (`MemoryPort`, rtl/memory_port.rs), the DOP unit with the
//! side delay line of its pairs, TRI_UNIT and its result port
//! ([`ResultPort`](crate::rtl::tri_unit::ResultPort), rtl/tri_unit.rs). This file keeps what
//! joins them: the host registers, the leaf FIFO and register with the triangle words held
//! (A's in its triangle cache, `TriCache`, rtl/tri_cache.rs), the event counters (`EventCounter`, rtl/event_counter.rs) and the end of a query.

/// The chip kernel's part `Host` (in `chip!`), given the DOP and T.CHECK word widths and
/// then, from [`register_map!`](crate::chip::reg::register_map), the host registers'
/// addresses as literals.
macro_rules! host_kernel {
    ($WD:tt, $WT:tt;
     $(#[$tri_setup_doc:meta])* TRI_SETUP = $tri_setup:tt;
     $(#[$mode_doc:meta])* MODE = $mode:tt;
     $(#[$root_doc:meta])* ROOT = $root:tt;
     $(#[$base_na_doc:meta])* BASE_NA = $base_na:tt;
     $(#[$base_nb_doc:meta])* BASE_NB = $base_nb:tt;
     $(#[$base_ta_doc:meta])* BASE_TA = $base_ta:tt;
     $(#[$base_tb_doc:meta])* BASE_TB = $base_tb:tt;
     $(#[$port_doc:meta])* PORT = $port:tt;
     $(#[$tri_cache_doc:meta])* TRI_CACHE = $tri_cache:tt;
     $(#[$map_doc:meta])* MAP = $map:tt;) => {
        /// The host registers (chip::reg), the units' setup ports, and run or halt.
        struct Host;

        impl<const N: usize, const NP1: usize, const NM1: usize> $crate::rtl::kernel::Kernel<Host>
            for CollisionChip<N, NP1, NM1>
        {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(
                    self, clock, mode_lifo, mode_first, mode_rec, mode_slot, root, base_na,
                    base_nb, base_ta, base_tb, map
                );
                dff_setup!(
                    self,
                    clock,
                    port_pf,
                    port_out,
                    port_one,
                    port_credit,
                    run,
                    done_r,
                    push_root,
                    stop
                );
                dff_setup!(self, clock, leaf_count, leaf_valid, leaf_tag);
                dff_setup!(self, clock, tc_mask, tb_ok, tb_id, tb_word);
                clock!(
                    self, clock, d_cntr, mem_port, dop, side, leaf_fifo, tri_cache, tri_unit,
                    result
                );
                clock!(self, clock, cnt_dop, cnt_tri, cnt_nf, cnt_tf);
                // ---- host registers and the units' setup ports: the DOP unit's words below
                // 0x100, TRI_UNIT's from reg::TRI_SETUP (address bits 9:5 = 8)
                self.dop.load_en.next =
                    self.host_we.val() & (self.host_addr.val().get_bits::<2>(8) == 0);
                self.dop.load_addr.next = self.host_addr.val().get_bits::<8>(0);
                self.dop.load_data.next = self.host_data.val().get_bits::<$WD>(0);
                self.tri_unit.load_en.next =
                    self.host_we.val() & (self.host_addr.val().get_bits::<5>(5) == 8);
                self.tri_unit.load_addr.next = self.host_addr.val().get_bits::<5>(0);
                self.tri_unit.load_data.next = self.host_data.val().get_bits::<$WT>(0);
                if self.host_we.val() {
                    if self.host_addr.val() == $mode {
                        self.mode_lifo.d.next = self.host_data.val().get_bit(0);
                        self.mode_first.d.next = self.host_data.val().get_bit(1);
                        self.mode_rec.d.next = self.host_data.val().get_bit(2);
                        self.mode_slot.d.next = self.host_data.val().get_bits::<3>(3);
                    }
                    if self.host_addr.val() == $root {
                        self.root.d.next = self.host_data.val();
                    }
                    if self.host_addr.val() == $base_na {
                        self.base_na.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == $base_nb {
                        self.base_nb.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == $base_ta {
                        self.base_ta.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == $base_tb {
                        self.base_tb.d.next = self.host_data.val().get_bits::<24>(0);
                    }
                    if self.host_addr.val() == $port {
                        self.port_pf.d.next = self.host_data.val().get_bits::<4>(0);
                        self.port_out.d.next = self.host_data.val().get_bits::<4>(4);
                        self.port_one.d.next = self.host_data.val().get_bit(8);
                        self.port_credit.d.next = self.host_data.val().get_bits::<6>(9);
                    }
                    if self.host_addr.val() == $tri_cache {
                        self.tc_mask.d.next = self.host_data.val().get_bits::<7>(0);
                    }
                    if self.host_addr.val() == $map {
                        self.map.d.next = self.host_data.val().get_bits::<20>(0);
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
                self.halt.next = self.stop.q.val() | self.d_cntr.overflow.val();
                self.go.next = self.run.q.val() & !self.halt.val();
                self.start_q.next = self.start.val() & !self.run.q.val();
            }
        }
    };
}
pub(crate) use host_kernel;

/// Stamps out `CollisionChip<N, NP1, NM1>` in the calling module. Arguments: `K` the DOP's
/// k; `Dop = dop_new` its unit's type (its `LATENCY` sets the side delay line) and
/// constructor (`DopUnit6 = DopUnit6::new` for k = 6; its rounding is a setup word's), followed by
/// `=> in_ready` for a folded DOP unit whose `in_ready` gates D_CNTR's issue; `Tri = tri_new` TRI_UNIT's type and constructor from T.CHECK's
/// rounding (`TriUnit = TriUnit::new`, or a `TriUnitFold` on its plan: any block with
/// `TriUnit`'s ports, `tri_unit_ports!`, whose `in_ready` paces the leaf register); `WD` the
/// DOP format's word width, `WT` T.CHECK's, `WN` a node word's bits a plane (`WD`, or with
/// stored DOP precision the code's), `NW` node-word bits (`1 + K WN + 64`), `TW`
/// triangle-word bits (`23 WT + 2`), `MW` memory-word bits
/// ([`crate::chip::rtl::ChipKind::word_bits`]), `RW` the node record's bits (`SLOTS NW`, and
/// the shared fields with stored DOP precision), `SLOTS` its node words (2 on a chip that also
/// reads the `records` layout, else 1); then, with stored DOP precision, `coded X, SW`: the
/// exponent field's bits and the shared fields' (the DOP unit then a `DopUnitCoded24`).
macro_rules! chip {
    ($K:tt, $Dop:ident = $dop_new:expr $(=> $dop_ready:ident)?, $Tri:ident = $tri_new:expr, $WD:tt, $WT:tt, $WN:tt, $NW:tt, $TW:tt, $MW:tt, $RW:tt, $SLOTS:tt $(; coded $X:tt, $SW:tt)?) => {
        declare_sync_fifo!(LeafFifo, Bits<64>, $crate::chip::rtl::LEAF_FIFO, 1);
        $crate::rtl::memory_port::memory_port!($NW, $MW, $RW, $SLOTS $(, shared $SW)?);
        $crate::rtl::tri_cache::tri_cache!($TW);

        /// The chip's memory word bits (`mem_resp_data`).
        pub const CHIP_WORD_BITS: usize = $MW;
        /// The triangle word's bits (the low bits of a memory word; a triangle cache line).
        pub const TRI_WORD_BITS: usize = $TW;
        /// The node record's bits (the low bits of a memory word): one node word, or
        /// `SLOTS` and their shared fields.
        pub const RECORD_BITS: usize = $RW;
        /// Node words a record.
        pub const SLOTS: usize = $SLOTS;
        /// A node word's bits.
        pub const NODE_BITS: usize = $NW;

        /// The collision chip with a k-DOP: D_CNTR (DATE'05 §4.3) drives the DOP unit (Eq. 10)
        /// over pairs of node words from memory, overlapping leaf pairs go to TRI_UNIT
        /// (§4.2), and the host reads the intersecting and the uncertain triangle pairs.
        /// `2^N` queue entries (`NP1 = N + 1`, `NM1 = N - 1`).
        ///
        /// Ports (`W` = word width of the DOP unit's or TRI_UNIT's format, `MW` = memory word):
        ///
        /// * host registers: in `host_we`, `host_addr[10]`, `host_data[32]`, written on
        ///   the rising edge, at the addresses and with the fields of [`crate::chip::reg`]:
        ///   `0x000 + a` the DOP unit's setup word `a` (C, c, D.KLMSEL control, the DOP
        ///   unit's); [`TRI_SETUP`](crate::chip::reg::TRI_SETUP)` + a` TRI_UNIT's (frame
        ///   maps, bounds, eta, `TriUnit`); then [`MODE`](crate::chip::reg::MODE) (its
        ///   `records` bit only if `RW` is `2 NW`: node ids `2 record + slot`, a node record
        ///   two node words, a leaf's triangles fetched by their records),
        ///   [`ROOT`](crate::chip::reg::ROOT), the image's word addresses
        ///   [`BASE_NA`](crate::chip::reg::BASE_NA) to [`BASE_TB`](crate::chip::reg::BASE_TB),
        ///   the memory port [`PORT`](crate::chip::reg::PORT) (prefetch at most
        ///   [`PORT_PREFETCH`](crate::chip::rtl::PORT_PREFETCH); an issue every clock because
        ///   the queue's second write port takes a result's two child entries at once; reset:
        ///   one request, no prefetch, issues two clocks apart, credit 16), A's triangle cache
        ///   [`TRI_CACHE`](crate::chip::reg::TRI_CACHE) (a power of two up to
        ///   [`TRI_CACHE_LINES`](crate::chip::rtl::TRI_CACHE_LINES)) and the record map
        ///   [`MAP`](crate::chip::reg::MAP).
        /// * `start` (in): begins a query with the registers as written (ignored while
        ///   `busy`); `busy`, `done` (high from the query's end to the next start),
        ///   `overflow` (the pair queue was full when a child entry came: the query ended
        ///   early and its result is incomplete), `max_depth` (most entries queued),
        ///   counters `dop_tests`, `tri_tests`, `node_fetches`, `tri_fetches`.
        /// * memory: out `mem_req_valid`, `mem_req_addr[24]` (a word address), in
        ///   `mem_req_ready`; in `mem_resp_valid`, `mem_resp_data[MW]`: the words in
        ///   request order. At most [`PORT`](crate::chip::reg::PORT)`[7:4] + 1` requests are outstanding and the chip
        ///   takes every response at the rising edge it is valid (it has room for every word
        ///   it asks for, so the response has no ready).
        ///   Node word: bit 0 leaf, `d_i` at `1 + i W`, then two 32-bit fields (children,
        ///   or the triangle index and 0, `records`: its record); a node record: the node
        ///   word, or (`records`) slot 0's and slot 1's from bit `NW`; triangle word: v0, v1, v2 (x, y, z), M row-major,
        ///   alpha_m, alpha_f at `i W`, v_exact, degenerate ([`crate::golden::memory`]).
        /// * results (valid/ready): out `res_valid`, `res_tag[32]` (A's triangle in bits
        ///   15:0, B's in 31:16), `res_uncertain` (0: intersecting; 1: the host decides);
        ///   in `res_ready`. Separate pairs are not shown.
        ///
        /// Structure and timing, clock by clock: docs/explanation/architecture.md, "Cycle semantics".
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
            mode_rec: DFF<Bit>,
            mode_slot: DFF<Bits<3>>,
            id_mask: Signal<Local, Bits<16>>,
            c_ones16: Constant<Bits<16>>,
            root: DFF<Bits<32>>,
            base_na: DFF<Bits<24>>,
            base_nb: DFF<Bits<24>>,
            base_ta: DFF<Bits<24>>,
            base_tb: DFF<Bits<24>>,
            map: DFF<Bits<20>>,
            // ---- query state
            run: DFF<Bit>,
            done_r: DFF<Bit>,
            push_root: DFF<Bit>,
            stop: DFF<Bit>,
            halt: Signal<Local, Bit>,
            start_q: Signal<Local, Bit>,
            // ---- the memory port's limits (host register reg::PORT)
            port_pf: DFF<Bits<4>>,
            port_out: DFF<Bits<4>>,
            port_one: DFF<Bit>,
            port_credit: DFF<Bits<6>>,
            credit_lim: Signal<Local, Bits<6>>,
            c_credit: Constant<Bits<6>>,
            pf: Signal<Local, Bits<5>>,
            c_pf_max: Constant<Bits<5>>,
            go: Signal<Local, Bit>,
            // ---- D_CNTR (the pair queue, the pair buffer, issue, child entries) and the
            // memory port (the node words asked for and arrived, requests, responses)
            d_cntr: $crate::rtl::d_cntr::DCntr<N, NP1, NM1>,
            mem_port: MemoryPort,
            // ---- the DOP unit and what travels beside it
            dop: $Dop,
            side: $crate::rtl::delay::Delay<Bits<99>, { $Dop::LATENCY }>,
            // ---- leaf pairs waiting for TRI_UNIT, and the one being fetched
            leaf_fifo: LeafFifo,
            leaf_count: DFF<Bits<6>>,
            leaf_out: Signal<Local, Bit>,
            leaf_valid: DFF<Bit>,
            // A's and B's triangle index (bits 31:0, for results), A's and B's triangle word
            // as fetched (63:32, its record; or 31:0 in the `words` layout)
            leaf_tag: DFF<Bits<64>>,
            tri_ids: Signal<Local, Bits<32>>,
            next_tri_ids: Signal<Local, Bits<32>>,
            // A's triangle cache (WSCG'03 §4.3; rtl/tri_cache.rs), its lines used less one
            tc_mask: DFF<Bits<7>>,
            tri_cache: TriCache,
            tb_ok: DFF<Bit>,
            tb_id: DFF<Bits<16>>,
            tb_word: DFF<Bits<$TW>>,
            need_ta: Signal<Local, Bit>,
            need_tb: Signal<Local, Bit>,
            tri_unit: $Tri,
            tri_in: Signal<Local, Bit>,
            tri_take: Signal<Local, Bit>,
            // ---- results for the host
            result: $crate::rtl::tri_unit::ResultPort,
            // ---- end of query
            all_idle: Signal<Local, Bit>,
            halt_idle: Signal<Local, Bit>,
            // the event counters behind the ports dop_tests ... tri_fetches
            cnt_dop: $crate::rtl::event_counter::EventCounter,
            cnt_tri: $crate::rtl::event_counter::EventCounter,
            cnt_nf: $crate::rtl::event_counter::EventCounter,
            cnt_tf: $crate::rtl::event_counter::EventCounter,
        }

        impl<const N: usize, const NP1: usize, const NM1: usize> CollisionChip<N, NP1, NM1> {
            /// Queue entries.
            pub const CAPACITY: usize = 1 << N;

            /// T.CHECK rounds with `tri` (the DOP lanes as the host's setup words say).
            pub fn new(tri: Rounding) -> Self {
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
                    mode_rec: Default::default(),
                    mode_slot: Default::default(),
                    id_mask: Default::default(),
                    c_ones16: Constant::new(0xffffu64.into()),
                    root: Default::default(),
                    base_na: Default::default(),
                    base_nb: Default::default(),
                    base_ta: Default::default(),
                    base_tb: Default::default(),
                    map: Default::default(),
                    run: Default::default(),
                    done_r: Default::default(),
                    push_root: Default::default(),
                    stop: Default::default(),
                    halt: Default::default(),
                    start_q: Default::default(),
                    port_pf: Default::default(),
                    port_out: Default::default(),
                    port_one: Default::default(),
                    port_credit: Default::default(),
                    credit_lim: Default::default(),
                    c_credit: Constant::new(($crate::chip::rtl::CREDIT as u64).into()),
                    pf: Default::default(),
                    c_pf_max: Constant::new(($crate::chip::rtl::PORT_PREFETCH as u64).into()),
                    go: Default::default(),
                    d_cntr: Default::default(),
                    mem_port: MemoryPort::new(),
                    dop: ($dop_new)(),
                    side: Default::default(),
                    leaf_fifo: Default::default(),
                    leaf_count: Default::default(),
                    leaf_out: Default::default(),
                    leaf_valid: Default::default(),
                    leaf_tag: Default::default(),
                    tri_ids: Default::default(),
                    next_tri_ids: Default::default(),
                    tc_mask: Default::default(),
                    tri_cache: TriCache::new(),
                    tb_ok: Default::default(),
                    tb_id: Default::default(),
                    tb_word: Default::default(),
                    need_ta: Default::default(),
                    need_tb: Default::default(),
                    tri_unit: ($tri_new)(tri),
                    tri_in: Default::default(),
                    tri_take: Default::default(),
                    result: Default::default(),
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
            /// The values of the traversal signals [`crate::chip::probes::DATE05`] (in that
            /// order) as the logic shows them now: what the lockstep check compares and
            /// the traversal VCD shows (scripts/gtkw/chip_e8m15_k6.gtkw).
            pub fn probe(&self) -> Vec<u64> {
                let b = |x: bool| x as u64;
                let (dc, mp) = (&self.d_cntr, &self.mem_port);
                let r_tag = self.tri_unit.out_tag.val().to_u64();
                let l_tag = self.leaf_tag.q.val().to_u64();
                vec![
                    b(self.start.val()),
                    b(self.busy.val()),
                    b(self.done.val()),
                    b(self.overflow.val()),
                    b(self.halt.val()),
                    dc.count.val().to_u64(),
                    dc.max_count.val().to_u64(),
                    b(dc.push.val()),
                    b(dc.pop.val()),
                    b(dc.ent_valid.val()),
                    dc.cur_a.val().to_u64(),
                    dc.cur_b.val().to_u64(),
                    b(dc.need_na.val()),
                    b(dc.need_nb.val()),
                    b(dc.issue.val()),
                    dc.inflight.val().to_u64(),
                    b(self.mem_req_valid.val()),
                    b(self.mem_req_ready.val()),
                    self.mem_req_addr.val().to_u64(),
                    mp.req_dst.val().to_u64(),
                    b(mp.outstanding.val()),
                    b(self.mem_resp_valid.val()),
                    b(self.dop.valid_out.val()),
                    b(self.dop.overlap.val()),
                    dc.r_a.val().to_u64(),
                    dc.r_b.val().to_u64(),
                    b(dc.r_a_leaf.val()),
                    b(dc.r_b_leaf.val()),
                    b(dc.leaf_in.val()),
                    self.leaf_count.q.val().to_u64(),
                    b(self.leaf_valid.q.val()),
                    l_tag & 0xffff,
                    l_tag >> 16 & 0xffff,
                    b(self.tri_in.val()),
                    b(self.tri_unit.in_ready.val()),
                    b(self.tri_take.val()),
                    self.result.open.val().to_u64(),
                    b(self.tri_unit.out_valid.val()),
                    b(self.tri_unit.out_hit.val()),
                    b(self.tri_unit.out_uncertain.val()),
                    r_tag & 0xffff,
                    r_tag >> 16,
                    b(self.res_valid.val()),
                    b(self.res_uncertain.val()),
                    self.res_tag.val().to_u64() & 0xffff,
                    self.res_tag.val().to_u64() >> 16,
                    self.cnt_dop.count.val().to_u64(),
                    self.cnt_tri.count.val().to_u64(),
                    self.cnt_nf.count.val().to_u64(),
                    self.cnt_tf.count.val().to_u64(),
                ]
            }
        }

        $crate::rtl::kernel::kernel!([const N: usize, const NP1: usize, const NM1: usize] CollisionChip<N, NP1, NM1>: Host, Fetch, Datapath, TriOperands, Results);

        $crate::chip::reg::register_map!([$crate::rtl::chip::host_kernel] { $WD, $WT; });

        /// D_CNTR's ports, the leaf pair's triangle words, and the memory port that fetches the
        /// node and triangle words.
        struct Fetch;

        impl<const N: usize, const NP1: usize, const NM1: usize> $crate::rtl::kernel::Kernel<Fetch> for CollisionChip<N, NP1, NM1> {
            #[hdl_gen]
            fn update(&mut self) {
                // ---- D_CNTR: pops entries into its pair buffer, issues their pairs once the
                // memory port holds their node words, pushes the children of DOP results
                self.d_cntr.clear.next = self.start_q.val();
                self.d_cntr.lifo.next = self.mode_lifo.q.val();
                self.d_cntr.push_root.next = self.push_root.q.val();
                self.d_cntr.root.next = self.root.q.val();
                self.d_cntr.go.next = self.go.val();
                self.d_cntr.pf.next = self.pf.val();
                self.d_cntr.one.next = self.port_one.q.val();
                self.d_cntr.credit_lim.next = self.credit_lim.val();
                // a folded DOP unit takes a pair only while `in_ready`: D_CNTR issues none
                // otherwise (a credit limit of 0 blocks its issue and nothing else, so D_CNTR
                // keeps its ports and the unfolded chips their Verilog)
                $(if !self.dop.$dop_ready.val() {
                    self.d_cntr.credit_lim.next = 0.into();
                })?
                self.d_cntr.leaf_count.next = self.leaf_count.q.val();
                self.d_cntr.wa_empty.next = self.mem_port.wa_empty.val();
                self.d_cntr.wb_empty.next = self.mem_port.wb_empty.val();
                self.d_cntr.dop_valid.next = self.dop.valid_out.val();
                self.d_cntr.dop_overlap.next = self.dop.overlap.val();
                self.d_cntr.side.next = self.side.q.val();
                // a node id's record: the id without its slot field
                self.id_mask.next = self.c_ones16.val() << self.mode_slot.q.val();
                self.d_cntr.id_mask.next = self.id_mask.val();
                self.push_root.d.next = false;
                // the leaf pair's triangle words as fetched: by index, or (`records`) record
                self.tri_ids.next = self.leaf_tag.q.val().get_bits::<32>(0);
                if self.mode_rec.q.val() {
                    self.tri_ids.next = self.leaf_tag.q.val().get_bits::<32>(32);
                }
                // A's triangle word: from the cache, which read its line at the last edge
                self.tri_cache.clear.next = self.start_q.val();
                self.tri_cache.mask.next = self.tc_mask.q.val();
                self.tri_cache.id.next = self.tri_ids.val().get_bits::<16>(0);
                self.need_ta.next = self.go.val() & self.leaf_valid.q.val() & !self.tri_cache.hit.val();
                self.need_tb.next = self.go.val() & self.leaf_valid.q.val()
                    & !(self.tb_ok.q.val() & (self.tb_id.q.val() == self.tri_ids.val().get_bits::<16>(16)));
                // ---- the memory port: the node words D_CNTR's pops ask for, the triangle
                // words the leaf register needs
                self.mem_port.clear.next = self.start_q.val();
                self.mem_port.go.next = self.go.val();
                self.mem_port.pf_on.next = self.pf.val() != 0;
                self.mem_port.port_out.next = self.port_out.q.val();
                self.mem_port.base_na.next = self.base_na.q.val();
                self.mem_port.base_nb.next = self.base_nb.q.val();
                self.mem_port.base_ta.next = self.base_ta.q.val();
                self.mem_port.base_tb.next = self.base_tb.q.val();
                self.mem_port.map.next = self.map.q.val();
                self.mem_port.pop.next = self.d_cntr.pop.val();
                self.mem_port.pop_entry.next = self.d_cntr.pop_entry.val();
                self.mem_port.pop_fetch.next = self.d_cntr.pop_fetch.val();
                self.mem_port.issue.next = self.d_cntr.issue.val();
                self.mem_port.cur_fa.next = self.d_cntr.cur_fa.val();
                self.mem_port.cur_fb.next = self.d_cntr.cur_fb.val();
                self.mem_port.need_ta.next = self.need_ta.val();
                self.mem_port.need_tb.next = self.need_tb.val();
                self.mem_port.leaf_tag.next = self.tri_ids.val();
                self.mem_port.slot_bits.next = self.mode_slot.q.val();
                self.mem_port.cur_sa.next = bit_cast::<3, 16>(self.d_cntr.cur_a.val() & !self.id_mask.val());
                self.mem_port.cur_sb.next = bit_cast::<3, 16>(self.d_cntr.cur_b.val() & !self.id_mask.val());
                self.mem_port.mem_req_ready.next = self.mem_req_ready.val();
                self.mem_port.mem_resp_valid.next = self.mem_resp_valid.val();
                self.mem_port.mem_resp_data.next = self.mem_resp_data.val();
                self.mem_req_valid.next = self.mem_port.mem_req_valid.val();
                self.mem_req_addr.next = self.mem_port.mem_req_addr.val();
                self.cnt_tf.inc.next = self.mem_port.accept.val() & self.mem_port.req_dst.val().get_bit(1);
                self.cnt_nf.inc.next = self.mem_port.accept.val() & !self.mem_port.req_dst.val().get_bit(1);
                // a triangle word: A's fills its cache line, B's replaces the held one
                self.tri_cache.fill.next = self.mem_port.resp.val() & (self.mem_port.resp_dst.val() == 2);
                self.tri_cache.fill_id.next = self.mem_port.ta_req.val();
                self.tri_cache.fill_word.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                if self.mem_port.resp.val() {
                    if self.mem_port.resp_dst.val() == 3 {
                        self.tb_ok.d.next = true;
                        self.tb_id.d.next = self.mem_port.tb_req.val();
                        self.tb_word.d.next = self.mem_resp_data.val().get_bits::<$TW>(0);
                    }
                }
            }
        }

        /// The DOP unit fed from the node words, and the leaf pairs through their FIFO to the
        /// triangle words held for TRI_UNIT ([`tri_operands!`](crate::rtl::tri_unit::tri_operands)).
        struct Datapath;

        impl<const N: usize, const NP1: usize, const NM1: usize> $crate::rtl::kernel::Kernel<Datapath> for CollisionChip<N, NP1, NM1> {
            #[hdl_gen]
            fn update(&mut self) {
                // ---- the DOP unit: B's word as d, A's as e; beside it the pair, its leaf
                // bits and children (side word: a, b, flip, A's leaf bit and fields, B's)
                for i in 0..$K {
                    self.dop.d[i].next = self.mem_port.nb_in.val().get_bits::<$WN>(1 + i * $WN);
                    self.dop.e[i].next = self.mem_port.na_in.val().get_bits::<$WN>(1 + i * $WN);
                }
                // with stored DOP precision, the records' references and exponents
                $(for i in 0..$K {
                    self.dop.rd[i].next = self.mem_port.nb_sh.val().get_bits::<$WD>(i * $WD);
                    self.dop.re[i].next = self.mem_port.na_sh.val().get_bits::<$WD>(i * $WD);
                    self.dop.efd[i].next = self.mem_port.nb_sh.val().get_bits::<$X>($K * $WD + i * $X);
                    self.dop.efe[i].next = self.mem_port.na_sh.val().get_bits::<$X>($K * $WD + i * $X);
                })?
                self.dop.tag.next = self.d_cntr.cur_a.val();
                self.dop.valid_in.next = self.d_cntr.issue.val();
                self.side.d.next = bit_cast::<99, 16>(self.d_cntr.cur_a.val())
                    | (bit_cast::<99, 16>(self.d_cntr.cur_b.val()) << 16)
                    | (bit_cast::<99, 1>(self.d_cntr.cur_flip.val()) << 32)
                    | (bit_cast::<99, 1>(self.mem_port.na_in.val().get_bits::<1>(0)) << 33)
                    | (bit_cast::<99, 16>(self.mem_port.na_in.val().get_bits::<16>(1 + $K * $WN)) << 34)
                    | (bit_cast::<99, 16>(self.mem_port.na_in.val().get_bits::<16>(33 + $K * $WN)) << 50)
                    | (bit_cast::<99, 1>(self.mem_port.nb_in.val().get_bits::<1>(0)) << 66)
                    | (bit_cast::<99, 16>(self.mem_port.nb_in.val().get_bits::<16>(1 + $K * $WN)) << 67)
                    | (bit_cast::<99, 16>(self.mem_port.nb_in.val().get_bits::<16>(33 + $K * $WN)) << 83);
                self.cnt_dop.inc.next = self.d_cntr.issue.val();
                // ---- leaf pairs: FIFO, then one at a time its triangle words, then TRI_UNIT
                self.leaf_fifo.write.next = self.d_cntr.leaf_in.val();
                self.leaf_fifo.data_in.next = self.d_cntr.leaf_pair.val();
                self.tri_in.next = self.run.q.val() & !self.halt.val() & self.leaf_valid.q.val()
                    & !self.need_ta.val() & !self.need_tb.val();
                self.tri_take.next = self.tri_in.val() & self.tri_unit.in_ready.val();
                self.cnt_tri.inc.next = self.tri_take.val();
                // after a halt, waiting leaf pairs are dropped
                self.leaf_out.next = !self.leaf_fifo.empty.val()
                    & (self.halt.val() | (self.run.q.val() & (!self.leaf_valid.q.val() | self.tri_take.val())));
                self.leaf_fifo.read.next = self.leaf_out.val();
                if self.tri_take.val() {
                    self.leaf_valid.d.next = false;
                }
                if self.leaf_out.val() & !self.halt.val() {
                    self.leaf_valid.d.next = true;
                    self.leaf_tag.d.next = self.leaf_fifo.data_out.val();
                }
                if self.d_cntr.leaf_in.val() & !self.leaf_out.val() {
                    self.leaf_count.d.next = self.leaf_count.q.val() + 1;
                }
                if self.leaf_out.val() & !self.d_cntr.leaf_in.val() {
                    self.leaf_count.d.next = self.leaf_count.q.val() - 1;
                }
                // the cache reads the line of the next clock's leaf pair at this edge
                self.next_tri_ids.next = self.leaf_fifo.data_out.val().get_bits::<32>(0);
                if self.mode_rec.q.val() {
                    self.next_tri_ids.next = self.leaf_fifo.data_out.val().get_bits::<32>(32);
                }
                self.tri_cache.next_id.next = self.tri_ids.val().get_bits::<16>(0);
                if self.leaf_out.val() & !self.halt.val() {
                    self.tri_cache.next_id.next = self.next_tri_ids.val().get_bits::<16>(0);
                }
            }
        }

        $crate::rtl::tri_unit::tri_operands!(
            [const N: usize, const NP1: usize, const NM1: usize] CollisionChip<N, NP1, NM1>,
            TriOperands, tri_unit, $WT, [tri_cache.word.val()], [tb_word.q.val()],
            [leaf_tag.q.val().get_bits::<32>(0)], [tri_in.val()]
        );

        /// The result port, the end of a query, and the counters' ports.
        struct Results;

        impl<const N: usize, const NP1: usize, const NM1: usize> $crate::rtl::kernel::Kernel<Results> for CollisionChip<N, NP1, NM1> {
            #[hdl_gen]
            fn update(&mut self) {
                // ---- results: the result port shows the host the pairs it must see
                self.result.take.next = self.tri_take.val();
                self.result.out_valid.next = self.tri_unit.out_valid.val();
                self.result.out_hit.next = self.tri_unit.out_hit.val();
                self.result.out_uncertain.next = self.tri_unit.out_uncertain.val();
                self.result.out_tag.next = self.tri_unit.out_tag.val();
                self.result.res_ready.next = self.res_ready.val();
                self.tri_unit.out_ready.next = self.result.out_ready.val();
                self.res_valid.next = self.result.res_valid.val();
                self.res_tag.next = self.result.res_tag.val();
                self.res_uncertain.next = self.result.res_uncertain.val();
                if self.run.q.val() & self.mode_first.q.val() & self.result.sure_hit.val() {
                    self.stop.d.next = true;
                }
                // ---- end of query: nothing left to do (after a halt: nothing left in flight).
                // Leaf pairs by their count, not the FIFO's `empty`: a pair written at edge w
                // shows at the head only from cycle w + 2.
                self.halt_idle.next = (self.d_cntr.inflight.val() == 0) & !self.d_cntr.pend.val() & !self.mem_port.outstanding.val()
                    & (self.result.open.val() == 0) & !self.push_root.q.val() & (self.leaf_count.q.val() == 0);
                self.all_idle.next = self.halt_idle.val() & self.d_cntr.empty.val() & !self.d_cntr.ent_valid.val()
                    & !self.leaf_valid.q.val();
                if self.run.q.val() & (self.all_idle.val() | (self.halt.val() & self.halt_idle.val())) {
                    self.run.d.next = false;
                    self.done_r.d.next = true;
                }
                // a start (D_CNTR and the memory port clear themselves with `start_q`)
                if self.start_q.val() {
                    self.run.d.next = true;
                    self.done_r.d.next = false;
                    self.push_root.d.next = true;
                    self.stop.d.next = false;
                    self.leaf_valid.d.next = false;
                    self.tb_ok.d.next = false;
                }
                self.busy.next = self.run.q.val();
                self.done.next = self.done_r.q.val();
                self.overflow.next = self.d_cntr.overflow.val();
                self.max_depth.next = self.d_cntr.max_count.val();
                self.cnt_dop.clear.next = self.start_q.val();
                self.cnt_tri.clear.next = self.start_q.val();
                self.cnt_nf.clear.next = self.start_q.val();
                self.cnt_tf.clear.next = self.start_q.val();
                self.dop_tests.next = self.cnt_dop.count.val();
                self.tri_tests.next = self.cnt_tri.count.val();
                self.node_fetches.next = self.cnt_nf.count.val();
                self.tri_fetches.next = self.cnt_tf.count.val();
            }
        }

        /// A chip ready to simulate as a top-level block (inputs claimed, connected).
        /// Large (TRI_UNIT): build it on a thread with a big stack.
        pub fn chip_top<const N: usize, const NP1: usize, const NM1: usize>(tri: Rounding) -> CollisionChip<N, NP1, NM1> {
            top_level!(CollisionChip::<N, NP1, NM1>::new(tri); clock, host_we, host_addr, host_data, start,
                mem_req_ready, mem_resp_valid, mem_resp_data, res_ready)
        }
    };
}
pub(crate) use chip;
