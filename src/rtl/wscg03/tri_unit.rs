//! WSCG'03's Triangle Unit (§4.3, Fig. 6) in RTL: its input stage (`TriInput`), which holds
//! the triangle words, A's in the triangle cache (`TriCache`, rtl/tri_cache.rs) and the
//! tumbled pair's in a two-entry SRAM, and asks for the ones it lacks. Its arithmetic is
//! TRI_UNIT's (rtl/tri_unit.rs), the same T.CHECKs as DATE'05's chip. Stamped out per
//! triangle word by `tri_input!` (after `chip!`, which stamps `TriCache`).

/// Stamps out `TriInput` in the calling module. Argument: `TW` triangle-word bits.
macro_rules! tri_input {
    ($TW:tt) => {
        /// WSCG'03's Triangle Unit's input stage (§4.3): a leaf pair from the Stack Engine
        /// waits in the leaf register until its triangle words are held, A's in A's triangle
        /// cache (`TriCache`, its lines used less one `mask`), B's in one of two entries
        /// (`b_ok`, `b_id`, `b_word`: the tumbled pair's leaves; a fill goes into the entry of
        /// the leaf's side, a lookup matches either), then moves with them into the pair
        /// register (`pair_valid`, `pair_tag`, `a_word`, `b_word`) that TRI_UNIT reads. A word
        /// it lacks is asked for (`need_a`, `need_b`, with the leaf's ids `ta_id`, `tb_id`):
        /// the Stack Engine's interrupt, while the Memory Controller fetches it (`fill_a` or
        /// `fill_b`, word `fill_id`). Its clocked model is
        /// [`ClockedTriInput`](crate::cycle::wscg03::tri_unit::ClockedTriInput), equal on every
        /// port every clock (tb/wscg03.rs).
        ///
        /// One clock: the leaf pair moves on (`go`) if both words are held and the pair
        /// register is empty or taken (`tri_ready`: TRI_UNIT's `in_ready`); a new leaf pair
        /// (`leaf_in`, `leaf_ids` = A's id | B's id << 16, `leaf_tag`, `leaf_side`) is taken if
        /// `leaf_ready` (the leaf register is empty or moves on). `halt` (first hit) drops the
        /// leaf and the pair registers and takes nothing; `clear` (a start) empties them, the
        /// cache and B's entries. Outputs other than `leaf_ready`, `need_a`, `need_b` and
        /// `pair_valid` are registers; those four also read `halt` and `tri_ready`.
        ///
        /// Ports: in `clock`, `clear`, `mask[7]`, `halt`, `leaf_in`, `leaf_ids[32]`,
        /// `leaf_tag[32]`, `leaf_side`, `fill_a`, `fill_b`, `fill_id[16]`, `fill_word[TW]`,
        /// `tri_ready`; out `leaf_ready`, `need_a`, `need_b`, `ta_id[16]`, `tb_id[16]`,
        /// `pair_valid`, `pair_tag[32]`, `a_word[TW]`, `b_word[TW]`, `busy` (a leaf or a
        /// pair held).
        #[derive(LogicBlock)]
        pub struct TriInput {
            pub clock: Signal<In, Clock>,
            pub clear: Signal<In, Bit>,
            pub mask: Signal<In, Bits<7>>,
            pub halt: Signal<In, Bit>,
            pub leaf_in: Signal<In, Bit>,
            pub leaf_ids: Signal<In, Bits<32>>,
            pub leaf_tag: Signal<In, Bits<32>>,
            pub leaf_side: Signal<In, Bit>,
            pub fill_a: Signal<In, Bit>,
            pub fill_b: Signal<In, Bit>,
            pub fill_id: Signal<In, Bits<16>>,
            pub fill_word: Signal<In, Bits<$TW>>,
            pub tri_ready: Signal<In, Bit>,
            pub leaf_ready: Signal<Out, Bit>,
            pub need_a: Signal<Out, Bit>,
            pub need_b: Signal<Out, Bit>,
            pub ta_id: Signal<Out, Bits<16>>,
            pub tb_id: Signal<Out, Bits<16>>,
            pub pair_valid: Signal<Out, Bit>,
            pub pair_tag: Signal<Out, Bits<32>>,
            pub a_word: Signal<Out, Bits<$TW>>,
            pub b_word: Signal<Out, Bits<$TW>>,
            pub busy: Signal<Out, Bit>,
            cache: TriCache,
            leaf_v: DFF<Bit>,
            leaf_id: DFF<Bits<32>>,
            leaf_t: DFF<Bits<32>>,
            side: DFF<Bit>,
            b_ok0: DFF<Bit>,
            b_ok1: DFF<Bit>,
            b_id0: DFF<Bits<16>>,
            b_id1: DFF<Bits<16>>,
            b_word0: DFF<Bits<$TW>>,
            b_word1: DFF<Bits<$TW>>,
            pair_v: DFF<Bit>,
            pair_t: DFF<Bits<32>>,
            pair_a: DFF<Bits<$TW>>,
            pair_b: DFF<Bits<$TW>>,
            live: Signal<Local, Bit>,
            hit_b0: Signal<Local, Bit>,
            hit_b1: Signal<Local, Bit>,
            go: Signal<Local, Bit>,
            load: Signal<Local, Bit>,
        }

        impl Logic for TriInput {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, leaf_v, leaf_id, leaf_t, side, b_ok0, b_ok1, b_id0, b_id1);
                dff_setup!(self, clock, b_word0, b_word1, pair_v, pair_t, pair_a, pair_b);
                clock!(self, clock, cache);
                // the leaf pair's words: A's from the cache (its line read at the last edge)
                self.live.next = self.leaf_v.q.val() & !self.halt.val();
                self.cache.clear.next = self.clear.val();
                self.cache.mask.next = self.mask.val();
                self.cache.id.next = self.leaf_id.q.val().get_bits::<16>(0);
                self.hit_b0.next = self.b_ok0.q.val() & (self.b_id0.q.val() == self.leaf_id.q.val().get_bits::<16>(16));
                self.hit_b1.next = self.b_ok1.q.val() & (self.b_id1.q.val() == self.leaf_id.q.val().get_bits::<16>(16));
                self.need_a.next = self.live.val() & !self.cache.hit.val();
                self.need_b.next = self.live.val() & !(self.hit_b0.val() | self.hit_b1.val());
                self.go.next = self.live.val() & self.cache.hit.val() & (self.hit_b0.val() | self.hit_b1.val())
                    & (!self.pair_v.q.val() | self.tri_ready.val());
                self.leaf_ready.next = !self.halt.val() & (!self.leaf_v.q.val() | self.go.val());
                self.load.next = self.leaf_in.val() & self.leaf_ready.val();
                // the cache reads the line of the next clock's leaf pair at this edge (one
                // assignment per branch: a default then an override glitches `next_id`, and
                // with the cache's `word` glitching back Icarus never settles)
                if self.load.val() {
                    self.cache.next_id.next = self.leaf_ids.val().get_bits::<16>(0);
                } else {
                    self.cache.next_id.next = self.leaf_id.q.val().get_bits::<16>(0);
                }
                // a word from memory: A's fills its cache line, B's the entry of the leaf's side
                self.cache.fill.next = self.fill_a.val();
                self.cache.fill_id.next = self.fill_id.val();
                self.cache.fill_word.next = self.fill_word.val();
                if self.fill_b.val() & !self.side.q.val() {
                    self.b_ok0.d.next = true;
                    self.b_id0.d.next = self.fill_id.val();
                    self.b_word0.d.next = self.fill_word.val();
                }
                if self.fill_b.val() & self.side.q.val() {
                    self.b_ok1.d.next = true;
                    self.b_id1.d.next = self.fill_id.val();
                    self.b_word1.d.next = self.fill_word.val();
                }
                // the pair register: taken by TRI_UNIT, refilled by the leaf pair
                if self.pair_v.q.val() & self.tri_ready.val() {
                    self.pair_v.d.next = false;
                }
                if self.go.val() {
                    self.leaf_v.d.next = false;
                    self.pair_v.d.next = true;
                    self.pair_t.d.next = self.leaf_t.q.val();
                    self.pair_a.d.next = self.cache.word.val();
                    self.pair_b.d.next = self.b_word1.q.val();
                    if self.hit_b0.val() {
                        self.pair_b.d.next = self.b_word0.q.val();
                    }
                }
                if self.load.val() {
                    self.leaf_v.d.next = true;
                    self.leaf_id.d.next = self.leaf_ids.val();
                    self.leaf_t.d.next = self.leaf_tag.val();
                    self.side.d.next = self.leaf_side.val();
                }
                if self.halt.val() | self.clear.val() {
                    self.leaf_v.d.next = false;
                    self.pair_v.d.next = false;
                }
                if self.clear.val() {
                    self.b_ok0.d.next = false;
                    self.b_ok1.d.next = false;
                }
                self.ta_id.next = self.leaf_id.q.val().get_bits::<16>(0);
                self.tb_id.next = self.leaf_id.q.val().get_bits::<16>(16);
                self.pair_valid.next = self.pair_v.q.val() & !self.halt.val();
                self.pair_tag.next = self.pair_t.q.val();
                self.a_word.next = self.pair_a.q.val();
                self.b_word.next = self.pair_b.q.val();
                self.busy.next = self.leaf_v.q.val() | self.pair_v.q.val();
            }
        }

        impl Default for TriInput {
            fn default() -> Self {
                TriInput {
                    clock: Default::default(),
                    clear: Default::default(),
                    mask: Default::default(),
                    halt: Default::default(),
                    leaf_in: Default::default(),
                    leaf_ids: Default::default(),
                    leaf_tag: Default::default(),
                    leaf_side: Default::default(),
                    fill_a: Default::default(),
                    fill_b: Default::default(),
                    fill_id: Default::default(),
                    fill_word: Default::default(),
                    tri_ready: Default::default(),
                    leaf_ready: Default::default(),
                    need_a: Default::default(),
                    need_b: Default::default(),
                    ta_id: Default::default(),
                    tb_id: Default::default(),
                    pair_valid: Default::default(),
                    pair_tag: Default::default(),
                    a_word: Default::default(),
                    b_word: Default::default(),
                    busy: Default::default(),
                    cache: TriCache::new(),
                    leaf_v: Default::default(),
                    leaf_id: Default::default(),
                    leaf_t: Default::default(),
                    side: Default::default(),
                    b_ok0: Default::default(),
                    b_ok1: Default::default(),
                    b_id0: Default::default(),
                    b_id1: Default::default(),
                    b_word0: Default::default(),
                    b_word1: Default::default(),
                    pair_v: Default::default(),
                    pair_t: Default::default(),
                    pair_a: Default::default(),
                    pair_b: Default::default(),
                    live: Default::default(),
                    hit_b0: Default::default(),
                    hit_b1: Default::default(),
                    go: Default::default(),
                    load: Default::default(),
                }
            }
        }

        /// The input stage ready to simulate as a top-level block.
        pub fn tri_input_top() -> TriInput {
            top_level!(TriInput::default(); clock, clear, mask, halt, leaf_in, leaf_ids, leaf_tag,
                leaf_side, fill_a, fill_b, fill_id, fill_word, tri_ready)
        }

        /// Verilog of [`tri_input_top`] (top module `top`).
        pub fn verilog_tri_input() -> String {
            generate_verilog(&tri_input_top())
        }
    };
}
pub(crate) use tri_input;
