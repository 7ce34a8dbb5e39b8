//! Folded TRI_UNIT (DATE'05 §4.2): TRI_UNIT's function and ports with both
//! directions on one folded T.CHECK (`TCheckFold`), a pair taken every `ii` clocks. As in
//! `TCheckFold`, the simulation (`update`) and the Verilog (a custom module body, [`body_verilog`])
//! are two readings of the same wiring, checked separately (rust-hdl in tb/rtl_tri.rs, the
//! Verilog against its vectors).

use crate::fold::ops::Inputs;
use crate::rtl::tcheck_fold::input_names;

/// T.CHECK's input words ([`Inputs::from_words`]'s order).
pub(crate) const WORDS: usize = Inputs::<u64>::WORDS;

/// Frame registers: M_AB's 12 words, its error words and A's scale (write addresses 0 ..
/// 14), then M_BA's, B's (16 .. 30): T.CHECK's input words 14 .. 28 per direction.
pub(crate) const FRAME_REGS: usize = 30;

/// The write address of frame register `k`.
pub(crate) fn frame_addr(k: usize) -> usize {
    if k < 15 {
        k
    } else {
        k + 1
    }
}

/// The Verilog source of T.CHECK's input word `i` for direction `ba` (false: A's edges against
/// U(B), B's leaf and M_AB; true: B's edges against U(A), A's leaf and M_BA).
fn word_verilog(ba: bool, i: usize) -> String {
    let (leaf, tri) = if ba { ("a_", "b_") } else { ("b_", "a_") };
    match i {
        0..=13 => format!("{leaf}{}", input_names()[i]),
        14..=28 => format!("frame${}$q", 15 * ba as usize + i - 14),
        _ => format!("{tri}{}", input_names()[i]),
    }
}

/// The module body of a folded TRI_UNIT whose T.CHECK is folded for `half` (the pair
/// interval is 2 half) with latency `tc_latency`: the counter, the frame registers, the held
/// second direction, the T.CHECK's inputs, the first direction's verdict register, the
/// result FIFO's ports and its count (the logic `update` simulates). With `staged` (at FPGA
/// depth) the T.CHECK's inputs are registered (`tin`, `tin_bits`: `v_exact`, `valid_in`;
/// `tin_tag`), and the counter's two decodes that select them and enable the held direction
/// are registered flags (`flags`: counter not 0, counter at `half`), taken from its next value.
pub(crate) fn body_verilog(half: usize, tc_latency: usize, staged: bool) -> String {
    use std::fmt::Write;
    let ii = 2 * half;
    let full = 1usize << crate::chip::rtl::TRI_FIFO_BITS;
    let c = "counter$q";
    let take = format!("(in_valid && {c} == 8'd0 && count$q != 9'd{full})");
    let give = "(out_ready && !fifo$empty)";
    let (at0, phase) = match staged {
        false => (format!("({c} == 8'd0)"), format!("({c} == 8'd{half})")),
        true => ("!flags$0$q".to_string(), "flags$1$q".to_string()),
    };
    // a T.CHECK input: the port itself, or a register's input and the port from it
    let tc_in = |v: &mut String, port: &str, reg: &str, value: String| {
        let _ = match staged {
            false => writeln!(v, "  tc${port} = {value};"),
            true => writeln!(
                v,
                "  {reg}$clock = clock;\n  {reg}$d = {value};\n  tc${port} = {reg}$q;"
            ),
        };
    };
    let mut v = String::new();
    let _ = writeln!(
        v,
        "always @(*) begin\n  in_ready = ({c} == 8'd0) && (count$q != 9'd{full});"
    );
    let _ = writeln!(
        v,
        "  run$clock = clock;\n  run$d = run$q | {take};\n  counter$clock = clock;"
    );
    let _ = writeln!(
        v,
        "  counter$d = (!(run$q | {take}) || {c} == 8'd{}) ? 8'd0 : {c} + 8'd1;",
        ii - 1
    );
    if staged {
        let _ = writeln!(v, "  flags$0$clock = clock;\n  flags$0$d = counter$d != 8'd0;\n  flags$1$clock = clock;\n  flags$1$d = counter$d == 8'd{half};");
    }
    for k in 0..FRAME_REGS {
        let _ = writeln!(v, "  frame${k}$clock = clock;\n  frame${k}$d = (load_en && load_addr == 5'd{}) ? load_data : frame${k}$q;", frame_addr(k));
    }
    for (i, name) in input_names().iter().enumerate() {
        let _ = writeln!(
            v,
            "  held${i}$clock = clock;\n  held${i}$d = {at0} ? {} : held${i}$q;",
            word_verilog(true, i)
        );
        let value = format!("{phase} ? held${i}$q : {}", word_verilog(false, i));
        tc_in(&mut v, name, &format!("tin${i}"), value);
    }
    for (r, src) in [
        ("held_exact", "b_v_exact"),
        ("held_tag", "tag"),
        ("held_valid", take.as_str()),
    ] {
        let _ = writeln!(v, "  {r}$clock = clock;\n  {r}$d = {at0} ? {src} : {r}$q;");
    }
    let _ = writeln!(v, "  tc$clock = clock;");
    let exact = format!("{phase} ? held_exact$q : a_v_exact");
    tc_in(&mut v, "v_exact", "tin_bits$0", exact);
    let tag = format!("{phase} ? held_tag$q : {{30'd0, a_degenerate, b_degenerate}}");
    tc_in(&mut v, "tag", "tin_tag$0", tag);
    tc_in(
        &mut v,
        "valid_in",
        "tin_bits$1",
        format!("{phase} ? held_valid$q : {take}"),
    );
    // the verdicts come a clock later behind the input registers
    let tc_latency = tc_latency + staged as usize;
    let first = format!("(tc$valid_out && {c} == 8'd{})", tc_latency % ii);
    for (r, val) in [
        ("ab_t", "tc$hit & !tc$tag_out[0]"),
        ("ab_f", "tc$miss & !tc$tag_out[0]"),
        ("a_deg", "tc$tag_out[1]"),
    ] {
        let _ = writeln!(
            v,
            "  {r}$clock = clock;\n  {r}$d = {first} ? ({val}) : {r}$q;"
        );
    }
    let hit = "(ab_t$q | (tc$hit & !a_deg$q))";
    let _ = writeln!(
        v,
        "  fifo$clock = clock;\n  fifo$write = tc$valid_out && {c} == 8'd{};",
        (tc_latency + half) % ii
    );
    let _ = writeln!(
        v,
        "  fifo$data_in = {{tc$tag_out, {hit}, !{hit} & !(ab_f$q & tc$miss & !a_deg$q)}};"
    );
    let _ = writeln!(v, "  fifo$read = {give};\n  count$clock = clock;");
    let _ = writeln!(v, "  count$d = ({take} && !{give}) ? count$q + 9'd1 : ({give} && !{take}) ? count$q - 9'd1 : count$q;");
    let _ = writeln!(v, "  out_valid = !fifo$empty;\n  out_tag = fifo$data_out[33:2];\n  out_hit = fifo$data_out[1];\n  out_uncertain = fifo$data_out[0];\nend");
    v
}

/// Stamps out `TriUnitFold` in the calling module (after `tri_unit!` and `tcheck_fold!`: it
/// uses `TCheckFold`, `TriFifo`, `TRI_FIFO_BITS`), or with `fpga` first `TriUnitFoldFpga`
/// on `TCheckFoldFpga` (for a plan at FPGA depth). Argument: `W` word width.
macro_rules! tri_unit_fold {
    ($W:tt) => {
        $crate::rtl::tri_unit_fold::tri_unit_fold!(@unit TriUnitFold, TCheckFold, tri_unit_fold_top, $W);
        /// Verilog of the TRI_UNIT folded for a pair every `ii` clocks (top module `top`); Err
        /// for an `ii` it cannot be folded to ([`crate::fold::tri_unit_plan`]).
        pub fn verilog_tri_unit_fold(ii: usize, rounding: Rounding) -> Result<String, String> {
            Ok(generate_verilog(&tri_unit_fold_top($crate::fold::tri_unit_plan(ii, $crate::fold::plan::Binding::Shared, $crate::chip::rtl::Depth::Asic)?, rounding)))
        }
    };
    (fpga $W:tt) => {
        $crate::rtl::tri_unit_fold::tri_unit_fold!(@unit TriUnitFoldFpga, TCheckFoldFpga, tri_unit_fold_fpga_top, $W);
        /// Verilog of the TRI_UNIT folded for a pair every `ii` clocks at FPGA depth, its
        /// registers per reader (top module `top`); Err for an `ii` it cannot be folded to.
        pub fn verilog_tri_unit_fold_fpga(ii: usize, rounding: Rounding) -> Result<String, String> {
            let plan = $crate::fold::tri_unit_plan(ii, $crate::fold::plan::Binding::PerReader, $crate::chip::rtl::Depth::Fpga)?;
            Ok(generate_verilog(&tri_unit_fold_fpga_top(plan, rounding)))
        }
    };
    (@unit $Name:ident, $TCheck:ident, $top:ident, $W:tt) => {
        $crate::rtl::tri_unit::tri_unit_ports! {
            $W,
            /// TRI_UNIT folded (docs/explanation/architecture.md, "Folded TRI_UNIT"): [`TriUnit`]'s ports and
            /// verdicts, bit for bit golden [`tri_unit`](crate::golden::tri_unit::tri_unit), with
            /// both directions on one [`TCheckFold`] folded for ii / 2 (its plan,
            /// [`crate::fold::tri_unit_plan`]). A control counter runs 0 .. ii-1 from the first
            /// pair taken; `in_ready` is high while it is 0 and the result FIFO has room, so a pair
            /// is taken at most every ii clocks (a writer holds `in_valid` until `in_ready`).
            /// Taken at counter 0: A's edges against U(B) (B's leaf, M_AB) enter the T.CHECK at
            /// once, and B's edges against U(A) (A's leaf, M_BA), held in registers with the
            /// pair's tag and B's `v_exact`, at counter ii / 2. The first direction's T.CHECK tag
            /// carries the pair's degenerate flags; its masked verdict waits in `ab_t`, `ab_f`
            /// for the second's, and their Kleene OR enters the result FIFO
            /// ([`crate::fold::tri_unit_latency`] after the pair, with the FIFO's two registers).
            /// The frame registers are read when the pair is taken, as in [`TriUnit`].
            $Name {
                // the counter starts with the first pair (`run`), then runs freely
                run: DFF<Bit>,
                counter: DFF<Bits<8>>,
                // per-query registers (`frame_addr`)
                frame: Vec<DFF<Bits<$W>>>,
                // the second direction's T.CHECK inputs, held from counter 0 to ii / 2
                held: Vec<DFF<Bits<$W>>>,
                held_exact: DFF<Bit>,
                held_tag: DFF<Bits<32>>,
                held_valid: DFF<Bit>,
                // at FPGA depth (`Plan::operand_regs`), else none: the T.CHECK's inputs
                // registered (`tin_bits`: `v_exact`, `valid_in`) and the counter's decodes as
                // flags (not 0; at ii / 2)
                tin: Vec<DFF<Bits<$W>>>,
                tin_bits: Vec<DFF<Bit>>,
                tin_tag: Vec<DFF<Bits<32>>>,
                flags: Vec<DFF<Bit>>,
                tc: $TCheck,
                // the first direction's verdict (masked by B's degenerate flag) and A's flag
                ab_t: DFF<Bit>,
                ab_f: DFF<Bit>,
                a_deg: DFF<Bit>,
                fifo: TriFifo,
                // pairs taken and not yet read out
                count: DFF<Bits<9>>,
            }
        }

        impl $Name {
            /// Result FIFO entries: pairs taken and not yet read out.
            pub const FIFO_DEPTH: usize = 1 << TRI_FIFO_BITS;

            /// A folded TRI_UNIT on a T.CHECK built from `plan` ([`crate::fold::tri_unit_plan`]),
            /// its value datapath rounding with `rounding`.
            pub fn new(plan: $crate::fold::plan::Plan, rounding: Rounding) -> Self {
                let staged = plan.operand_regs();
                $crate::rtl::tri_unit::tri_unit_new! { Self {
                    run: Default::default(),
                    counter: Default::default(),
                    frame: (0..$crate::rtl::tri_unit_fold::FRAME_REGS).map(|_| Default::default()).collect(),
                    held: (0..$crate::rtl::tri_unit_fold::WORDS).map(|_| Default::default()).collect(),
                    held_exact: Default::default(),
                    held_tag: Default::default(),
                    held_valid: Default::default(),
                    tin: (0..staged * $crate::rtl::tri_unit_fold::WORDS).map(|_| Default::default()).collect(),
                    tin_bits: (0..2 * staged).map(|_| Default::default()).collect(),
                    tin_tag: (0..staged).map(|_| Default::default()).collect(),
                    flags: (0..2 * staged).map(|_| Default::default()).collect(),
                    tc: $TCheck::new(plan, rounding),
                    ab_t: Default::default(),
                    ab_f: Default::default(),
                    a_deg: Default::default(),
                    fifo: Default::default(),
                    count: Default::default(),
                } }
            }

            /// Pair in to result visible at the output, with a reader always ready.
            pub fn latency(&self) -> usize {
                $crate::fold::tri_unit_latency(&self.tc.plan.0)
            }

            /// Clocks between pairs taken.
            pub fn interval(&self) -> usize {
                2 * self.tc.plan.0.ii
            }

            /// Word `i` of a leaf's map on the ports (M row-major, then alpha_m, alpha_f).
            fn leaf_word(&self, a: bool, i: usize) -> u64 {
                let (m, alpha) = if a {
                    ([&self.a_m_0, &self.a_m_1, &self.a_m_2], [&self.a_alpha_m, &self.a_alpha_f])
                } else {
                    ([&self.b_m_0, &self.b_m_1, &self.b_m_2], [&self.b_alpha_m, &self.b_alpha_f])
                };
                (if i < 12 { m[i / 4][i % 4].val() } else { alpha[i - 12].val() }).to_u64()
            }

            /// Word `j` = 3 k + c of a triangle's vertices on the ports (vertex k, coordinate c).
            fn vertex_word(&self, a: bool, j: usize) -> u64 {
                let v = if a { [&self.a_v_x, &self.a_v_y, &self.a_v_z] } else { [&self.b_v_x, &self.b_v_y, &self.b_v_z] };
                v[j % 3][j / 3].val().to_u64()
            }

            /// T.CHECK's input word `i` for direction `ba` (`word_verilog`'s source).
            fn word(&self, ba: bool, i: usize) -> u64 {
                match i {
                    0..=13 => self.leaf_word(ba, i),
                    14..=28 => self.frame[15 * ba as usize + i - 14].q.val().to_u64(),
                    _ => self.vertex_word(!ba, i - 29),
                }
            }
        }

        impl Logic for $Name {
            fn update(&mut self) {
                use $crate::rtl::tri_unit_fold::{frame_addr, WORDS};
                let (half, tc_latency) = (self.tc.plan.0.ii, self.tc.plan.0.latency);
                let ii = 2 * half;
                let clock = self.clock.val();
                let c = self.counter.q.val().to_u64() as usize;
                let ready = c == 0 && self.count.q.val().to_u64() != Self::FIFO_DEPTH as u64;
                let take = self.in_valid.val() & ready;
                self.in_ready.next = ready;
                let run = self.run.q.val() | take;
                (self.run.clock.next, self.run.d.next) = (clock, run);
                self.counter.clock.next = clock;
                let next = if run { (c + 1) % ii } else { 0 };
                self.counter.d.next = (next as u64).into();
                let staged = !self.flags.is_empty();
                for (r, v) in self.flags.iter_mut().zip([next != 0, next == half]) {
                    (r.clock.next, r.d.next) = (clock, v);
                }
                // ---- per-query registers: hold, or load through the write port
                let (en, addr, data) = (self.load_en.val(), self.load_addr.val().to_u64() as usize, self.load_data.val());
                for (k, r) in self.frame.iter_mut().enumerate() {
                    let d = if en && addr == frame_addr(k) { data } else { r.q.val() };
                    (r.clock.next, r.d.next) = (clock, d);
                }
                // ---- the T.CHECK: A's edges at counter 0, B's (held) at ii / 2
                let (c0, phase) = (c == 0, c == half);
                for i in 0..WORDS {
                    let (ba, ab) = (self.word(true, i), self.word(false, i));
                    let q = self.held[i].q.val();
                    (self.held[i].clock.next, self.held[i].d.next) = (clock, if c0 { ba.into() } else { q });
                    let v = if phase { q } else { ab.into() };
                    self.tc.input_mut(i).next = match self.tin.get_mut(i) {
                        Some(r) => {
                            (r.clock.next, r.d.next) = (clock, v);
                            r.q.val()
                        }
                        None => v,
                    };
                }
                let (ex, tg, vl) = (self.held_exact.q.val(), self.held_tag.q.val(), self.held_valid.q.val());
                (self.held_exact.clock.next, self.held_exact.d.next) = (clock, if c0 { self.b_v_exact.val() } else { ex });
                (self.held_tag.clock.next, self.held_tag.d.next) = (clock, if c0 { self.tag.val() } else { tg });
                (self.held_valid.clock.next, self.held_valid.d.next) = (clock, if c0 { take } else { vl });
                let deg = (self.a_degenerate.val() as u64) << 1 | self.b_degenerate.val() as u64;
                self.tc.clock.next = clock;
                let (ex, tg, vl) = if phase { (ex, tg, vl) } else { (self.a_v_exact.val(), deg.into(), take) };
                (self.tc.v_exact.next, self.tc.tag.next, self.tc.valid_in.next) = match staged {
                    false => (ex, tg, vl),
                    true => {
                        for (r, d) in self.tin_bits.iter_mut().zip([ex, vl]) {
                            (r.clock.next, r.d.next) = (clock, d);
                        }
                        (self.tin_tag[0].clock.next, self.tin_tag[0].d.next) = (clock, tg);
                        (self.tin_bits[0].q.val(), self.tin_tag[0].q.val(), self.tin_bits[1].q.val())
                    }
                };
                // the verdicts come a clock later behind the input registers
                let tc_latency = tc_latency + staged as usize;
                // ---- verdict: Kleene OR of the directions (a degenerate leaf: unknown)
                let (vo, hit, miss, tag) = (self.tc.valid_out.val(), self.tc.hit.val(), self.tc.miss.val(), self.tc.tag_out.val());
                let first = vo && c == tc_latency % ii;
                let b_deg = tag.get_bit(0);
                for (r, v) in [(&mut self.ab_t, hit & !b_deg), (&mut self.ab_f, miss & !b_deg), (&mut self.a_deg, tag.get_bit(1))] {
                    (r.clock.next, r.d.next) = (clock, if first { v } else { r.q.val() });
                }
                let a_deg = self.a_deg.q.val();
                let t = self.ab_t.q.val() | (hit & !a_deg);
                let f = self.ab_f.q.val() & miss & !a_deg;
                self.fifo.clock.next = clock;
                self.fifo.write.next = vo && c == (tc_latency + half) % ii;
                self.fifo.data_in.next = (tag.to_u64() << 2 | (t as u64) << 1 | (!t & !f) as u64).into();
                // ---- back-pressure: take a pair only while the FIFO has room for it
                let give = self.out_ready.val() & !self.fifo.empty.val();
                self.fifo.read.next = give;
                let n = self.count.q.val();
                let d = if take && !give { n + 1 } else if give && !take { n - 1 } else { n };
                (self.count.clock.next, self.count.d.next) = (clock, d);
                let out = self.fifo.data_out.val();
                self.out_valid.next = !self.fifo.empty.val();
                self.out_tag.next = out.get_bits::<32>(2);
                self.out_hit.next = out.get_bit(1);
                self.out_uncertain.next = out.get_bit(0);
            }

            fn connect(&mut self) {
                for r in [&mut self.run, &mut self.held_exact, &mut self.held_valid, &mut self.ab_t, &mut self.ab_f, &mut self.a_deg] {
                    (r.clock.connect(), r.d.connect());
                }
                for r in self.frame.iter_mut().chain(&mut self.held).chain(&mut self.tin) {
                    (r.clock.connect(), r.d.connect());
                }
                for r in self.tin_bits.iter_mut().chain(&mut self.flags) {
                    (r.clock.connect(), r.d.connect());
                }
                for r in &mut self.tin_tag {
                    (r.clock.connect(), r.d.connect());
                }
                (self.counter.clock.connect(), self.counter.d.connect());
                (self.held_tag.clock.connect(), self.held_tag.d.connect());
                (self.count.clock.connect(), self.count.d.connect());
                for i in 0..$crate::rtl::tri_unit_fold::WORDS {
                    self.tc.input_mut(i).connect();
                }
                (self.tc.clock.connect(), self.tc.v_exact.connect(), self.tc.tag.connect(), self.tc.valid_in.connect());
                (self.fifo.clock.connect(), self.fifo.write.connect(), self.fifo.data_in.connect(), self.fifo.read.connect());
                (self.in_ready.connect(), self.out_valid.connect(), self.out_tag.connect(), self.out_hit.connect(), self.out_uncertain.connect());
            }

            fn hdl(&self) -> Verilog {
                let p = &self.tc.plan.0;
                Verilog::Custom($crate::rtl::tri_unit_fold::body_verilog(p.ii, p.latency, p.operand_regs() > 0))
            }
        }

        /// A folded TRI_UNIT on a T.CHECK built from `plan` ([`crate::fold::tri_unit_plan`]),
        /// ready to simulate as a top-level block (inputs claimed, connected).
        pub fn $top(plan: $crate::fold::plan::Plan, rounding: Rounding) -> $Name {
            $crate::rtl::tri_unit::tri_unit_top_level!($Name::new(plan, rounding))
        }
    };
}
pub(crate) use tri_unit_fold;
