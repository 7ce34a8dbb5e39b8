//! A's triangle cache (WSCG'03 §4.3), between the memory port's A triangle responses and
//! TRI_UNIT's A operands. Stamped out per triangle word by `tri_cache!` (the chip's `chip!`).

/// Stamps out `TriCache` in the calling module. Argument: `TW` triangle-word bits.
macro_rules! tri_cache {
    ($TW:tt) => {
        /// A's triangle cache: direct mapped, triangle id `t` in line `t & mask` with `t` as
        /// its tag, ids and words in RAMs of
        /// [`TRI_CACHE_LINES`](crate::chip::rtl::TRI_CACHE_LINES) lines, a valid bit per line.
        /// Golden: [`golden::memory::TriCache`](crate::golden::memory::TriCache) (one line:
        /// the single word held, as on B's side).
        ///
        /// The RAMs are read one clock ahead: at each edge, the line of `next_id` (the id
        /// the chip looks up at the next clock) is read, so that `hit`/`word` answer for `id`
        /// when `id` is the last clock's `next_id`. A fill at that edge of the line being read
        /// is not in the RAM's read data (a RAM reads the old word), so the last filled id and
        /// word are held beside it (`last_id`, `last_word`) and replace it (`byp`).
        ///
        /// Ports: in `clock`, `clear` (a start: no line valid), `mask[7]` (lines used less
        /// one, host register [`TRI_CACHE`](crate::chip::reg::TRI_CACHE)), `fill` (A's triangle word `fill_id[16]`,
        /// `fill_word[TW]` arrives from memory), `id[16]` (the leaf pair's A triangle),
        /// `next_id[16]`; out `hit` (`id`'s word is held), `word[TW]` (it, when `hit`).
        /// Proven in scripts/formal/tri_cache.sv.
        #[derive(LogicBlock)]
        pub struct TriCache {
            pub clock: Signal<In, Clock>,
            pub clear: Signal<In, Bit>,
            pub mask: Signal<In, Bits<7>>,
            pub fill: Signal<In, Bit>,
            pub fill_id: Signal<In, Bits<16>>,
            pub fill_word: Signal<In, Bits<$TW>>,
            pub id: Signal<In, Bits<16>>,
            pub next_id: Signal<In, Bits<16>>,
            pub hit: Signal<Out, Bit>,
            pub word: Signal<Out, Bits<$TW>>,
            valid: DFF<Bits<128>>,
            ids: RAM<Bits<16>, 7>,
            words: RAM<Bits<$TW>, 7>,
            byp: DFF<Bit>,
            last_id: DFF<Bits<16>>,
            last_word: DFF<Bits<$TW>>,
            line: Signal<Local, Bits<7>>,
            fill_line: Signal<Local, Bits<7>>,
            next_line: Signal<Local, Bits<7>>,
            held_id: Signal<Local, Bits<16>>,
            c_one128: Constant<Bits<128>>,
        }

        impl Logic for TriCache {
            #[hdl_gen]
            fn update(&mut self) {
                dff_setup!(self, clock, valid, byp, last_id, last_word);
                self.ids.read_clock.next = self.clock.val();
                self.ids.write_clock.next = self.clock.val();
                self.words.read_clock.next = self.clock.val();
                self.words.write_clock.next = self.clock.val();
                self.line.next = self.id.val().get_bits::<7>(0) & self.mask.val();
                self.fill_line.next = self.fill_id.val().get_bits::<7>(0) & self.mask.val();
                self.next_line.next = self.next_id.val().get_bits::<7>(0) & self.mask.val();
                // the line read at the last edge, or the word filled at that edge into it
                self.held_id.next = self.ids.read_data.val();
                self.word.next = self.words.read_data.val();
                if self.byp.q.val() {
                    self.held_id.next = self.last_id.q.val();
                    self.word.next = self.last_word.q.val();
                }
                self.hit.next = ((self.valid.q.val() & (self.c_one128.val() << self.line.val()))
                    != 0)
                    & (self.held_id.val() == self.id.val());
                self.ids.write_enable.next = self.fill.val();
                self.ids.write_address.next = self.fill_line.val();
                self.ids.write_data.next = self.fill_id.val();
                self.words.write_enable.next = self.fill.val();
                self.words.write_address.next = self.fill_line.val();
                self.words.write_data.next = self.fill_word.val();
                self.ids.read_address.next = self.next_line.val();
                self.words.read_address.next = self.next_line.val();
                self.byp.d.next = self.fill.val() & (self.fill_line.val() == self.next_line.val());
                if self.fill.val() {
                    self.valid.d.next =
                        self.valid.q.val() | (self.c_one128.val() << self.fill_line.val());
                    self.last_id.d.next = self.fill_id.val();
                    self.last_word.d.next = self.fill_word.val();
                }
                if self.clear.val() {
                    self.valid.d.next = 0.into();
                }
            }
        }

        impl TriCache {
            pub fn new() -> TriCache {
                TriCache {
                    clock: Default::default(),
                    clear: Default::default(),
                    mask: Default::default(),
                    fill: Default::default(),
                    fill_id: Default::default(),
                    fill_word: Default::default(),
                    id: Default::default(),
                    next_id: Default::default(),
                    hit: Default::default(),
                    word: Default::default(),
                    valid: Default::default(),
                    ids: Default::default(),
                    words: Default::default(),
                    byp: Default::default(),
                    last_id: Default::default(),
                    last_word: Default::default(),
                    line: Default::default(),
                    fill_line: Default::default(),
                    next_line: Default::default(),
                    held_id: Default::default(),
                    c_one128: Constant::new(1.into()),
                }
            }
        }

        impl Default for TriCache {
            fn default() -> Self {
                Self::new()
            }
        }
    };
}
pub(crate) use tri_cache;
