//! Folded T.CHECK: T.CHECK's operations on a few shared FP units, one triangle
//! pair every `ii` clocks, built from a [`Plan`](crate::fold::plan::Plan) (the modulo
//! schedule of T.CHECK's dataflow graph, `crate::fold`). The same plan drives the
//! simulation (`update`, an interpreter of the plan's tables) and the Verilog (a custom
//! module body generated from the same tables): registers are rust-hdl `DFF`s, the units
//! `FpMul`, `FpAdd`, `FpScale` and `Sign`, so every value is rounded as in `TCheck`.

/// A value a block's logic reads in simulation and its Verilog is generated from, with no
/// signals of its own (rust-hdl visits nothing in it).
#[derive(Clone, Debug)]
pub struct Fixed<T>(pub std::sync::Arc<T>);

impl<T> rust_hdl::prelude::Logic for Fixed<T> {
    fn update(&mut self) {}
}

impl<T> rust_hdl::prelude::Block for Fixed<T> {
    fn connect_all(&mut self) {}
    fn update_all(&mut self) {}
    fn has_changed(&self) -> bool {
        false
    }
    fn accept(&self, _name: &str, _probe: &mut dyn rust_hdl::prelude::Probe) {}
}

pub use kept::KeptDff;
mod kept {
    use super::Fixed;
    use rust_hdl::prelude::*;

    /// rust-hdl's `DFF`, its Verilog marked `(* keep *)` when `keep` holds: a register that
    /// synthesis must not merge with an identical one (the copies of a value's chain under
    /// [`Binding::PerReader`](crate::fold::plan::Binding::PerReader)). Otherwise its Verilog
    /// is `DFF`'s, byte for byte.
    #[derive(Clone, Debug, LogicBlock)]
    pub struct KeptDff<T: Synth> {
        pub d: Signal<In, T>,
        pub q: Signal<Out, T>,
        pub clock: Signal<In, Clock>,
        keep: Fixed<bool>,
    }

    impl<T: Synth> KeptDff<T> {
        pub fn new(keep: bool) -> Self {
            Self {
                d: Default::default(),
                q: Default::default(),
                clock: Default::default(),
                keep: Fixed(std::sync::Arc::new(keep)),
            }
        }
    }

    impl<T: Synth> Logic for KeptDff<T> {
        fn update(&mut self) {
            if self.clock.pos_edge() {
                self.q.next = self.d.val()
            }
        }
        fn connect(&mut self) {
            self.q.connect();
        }
        fn hdl(&self) -> Verilog {
            match DFF::<T>::default().hdl() {
                Verilog::Custom(v) if *self.keep.0 => Verilog::Custom(v.replace(
                    "always @(posedge clock)",
                    "(* keep *) always @(posedge clock)",
                )),
                v => v,
            }
        }
    }
}

/// The Verilog expression of a word register read with its modifiers (`regs$r$q`, sign
/// cleared, or doubled: one more in the exponent field unless it is 0 or all ones).
pub(crate) fn read_verilog(r: &crate::fold::plan::Read, w: usize, e: usize, f: usize) -> String {
    let q = format!("regs${}$q", r.reg);
    if r.abs {
        format!("{{1'b0, {q}[{}:0]}}", w - 2)
    } else if r.dbl {
        let x = format!("{q}[{}:{f}]", w - 2);
        format!(
            "((({x} != {e}'d0) && ({x} != {e}'d{})) ? {q} + {w}'d{} : {q})",
            (1u64 << e) - 1,
            1u64 << f
        )
    } else {
        q
    }
}

/// The module body (after rust-hdl's declarations and instances) of a folded T.CHECK:
/// the counter, every register's input, every unit's operand multiplexers (a `case` on
/// the counter), the signs' inputs and the output registers. `units` names the unit
/// vectors per class (`Class::ALL` order).
pub(crate) fn body_verilog(
    p: &crate::fold::plan::Plan,
    w: usize,
    ew: usize,
    f: usize,
    units: [&str; 7],
) -> String {
    let mut v = String::new();
    registers_verilog(&mut v, p, units);
    operands_verilog(&mut v, p, w, ew, f, units);
    outputs_verilog(&mut v, p);
    v
}

/// The control counter, which names a pair's slot in every `case` of the body.
const COUNTER: &str = "counter$q";

/// [`body_verilog`]'s first part: `always @(*) begin`, the run flag, the counter, and the
/// inputs of the word registers (a unit's result from `units`) and of the side chains
/// (`v_exact`, `valid_in`, `tag`).
fn registers_verilog(v: &mut String, p: &crate::fold::plan::Plan, units: [&str; 7]) {
    use crate::fold::plan::Src;
    use std::fmt::Write;
    let c = COUNTER;
    let _ = writeln!(v, "always @(*) begin\n  run$clock = clock;\n  run$d = run$q | valid_in;\n  counter$clock = clock;");
    let _ = writeln!(
        v,
        "  counter$d = (!(run$q | valid_in) || {c} == 8'd{}) ? 8'd0 : {c} + 8'd1;",
        p.ii - 1
    );
    for i in 0..p.counter_copies() {
        let _ = writeln!(v, "  cnt${i}$clock = clock;\n  cnt${i}$d = counter$d;");
    }
    let inputs = input_names();
    for ch in &p.words {
        // a unit's result chains and an input word's count on their own copy of the counter
        let en = p
            .counter_copy(ch.src)
            .map_or(c.to_string(), |i| format!("cnt${i}$q"));
        for i in 0..ch.len {
            let r = ch.first + i;
            let src = match (i, ch.src) {
                (0, Src::Input(n)) => inputs[n].clone(),
                (0, Src::Unit(k, u)) => format!("{}${u}$y", units[k]),
                _ => format!("regs${}$q", r - 1),
            };
            let _ = writeln!(
                v,
                "  regs${r}$clock = clock;\n  regs${r}$d = ({en} == 8'd{}) ? {src} : regs${r}$q;",
                ch.slot
            );
        }
    }
    for (name, ch, port) in [
        ("exact", &p.exact, "v_exact"),
        ("valid", &p.valid, "valid_in"),
        ("tags", &p.tag, "tag"),
    ] {
        for i in 0..ch.len {
            let src = if i == 0 {
                port.to_string()
            } else {
                format!("{name}${}$q", i - 1)
            };
            let _ = writeln!(v, "  {name}${i}$clock = clock;\n  {name}${i}$d = ({c} == 8'd{}) ? {src} : {name}${i}$q;", ch.slot);
        }
    }
}

/// [`body_verilog`]'s operand multiplexers: per unit a `case` on the counter choosing its
/// operands in each slot it is issued (`units` names the unit vectors per class). With
/// operand registers the `case` sets them, on the unit's own copy of the counter, and they
/// drive the unit.
fn operands_verilog(
    v: &mut String,
    p: &crate::fold::plan::Plan,
    w: usize,
    ew: usize,
    f: usize,
    units: [&str; 7],
) {
    use std::fmt::Write;
    for (k, unit) in units.iter().enumerate() {
        for (u, slots) in p.issues[k].iter().enumerate() {
            let unit_port = format!("{unit}${u}");
            let scale = k >= 4;
            let _ = writeln!(v, "  {unit_port}$clock = clock;");
            if !scale {
                let _ = writeln!(v, "  {unit_port}$valid_in = 1'b0;");
            }
            let c = match p.operand_regs() {
                0 => COUNTER.to_string(),
                _ => operand_registers_verilog(v, p, k, u, &unit_port),
            };
            let n = |port: &str| operand_target(p, k, u, &unit_port, port);
            let _ = writeln!(v, "  case ({c})");
            for (slot, iss) in slots.iter().enumerate() {
                let Some(iss) = iss else { continue };
                let _ = write!(
                    v,
                    "    8'd{slot}: begin {} = {};",
                    n("a"),
                    read_verilog(&iss.a, w, ew, f)
                );
                if let Some(b) = &iss.b {
                    let _ = write!(v, " {} = {};", n("b"), read_verilog(b, w, ew, f));
                }
                if k == 2 || k == 3 {
                    let _ = write!(v, " {} = 1'b{};", n("sub"), iss.sub as u8);
                }
                if scale {
                    let sel = iss
                        .sel
                        .map_or("1'b0".to_string(), |r| format!("exact${r}$q"));
                    let _ = write!(v, " {} = {sel};", n("sel"));
                }
                let _ = writeln!(v, " end");
            }
            let _ = write!(v, "    default: begin {} = {w}'d0;", n("a"));
            let _ = write!(
                v,
                "{}",
                if scale {
                    format!(" {} = 1'b0;", n("sel"))
                } else {
                    format!(" {} = {w}'d0;", n("b"))
                }
            );
            if k == 2 || k == 3 {
                let _ = write!(v, " {} = 1'b0;", n("sub"));
            }
            let _ = writeln!(v, " end\n  endcase");
        }
    }
}

/// Where the `case` of unit `u` of class `k` (port prefix `unit`) puts operand `port`
/// (`a`, `b`, `sub`, `sel`): the unit's port, or with operand registers the register's input
/// (`op_sub$1$d`: the registers of each port numbered over the units that have it).
fn operand_target(
    p: &crate::fold::plan::Plan,
    k: usize,
    u: usize,
    unit: &str,
    port: &str,
) -> String {
    match p.operand_regs() {
        0 => format!("{unit}${port}"),
        _ => format!("op_{port}${}$d", p.operand_reg(k, u, port)),
    }
}

/// The operand registers of unit `u` of class `k` (port prefix `unit`): their clocks and the
/// unit's ports from them; returns the unit's copy of the counter its `case` selects on.
fn operand_registers_verilog(
    v: &mut String,
    p: &crate::fold::plan::Plan,
    k: usize,
    u: usize,
    unit: &str,
) -> String {
    use std::fmt::Write;
    for port in crate::fold::plan::Plan::operand_ports(k) {
        let r = format!("op_{port}${}", p.operand_reg(k, u, port));
        let _ = writeln!(v, "  {r}$clock = clock;\n  {unit}${port} = {r}$q;");
    }
    format!("cnt${}$q", p.operand_counter_copy(k, u))
}

/// [`body_verilog`]'s last part: the signs' inputs, the output registers taken at the
/// output slot, the outputs, and `end`.
fn outputs_verilog(v: &mut String, p: &crate::fold::plan::Plan) {
    use std::fmt::Write;
    let c = COUNTER;
    let o = &p.outputs;
    let take = format!("({c} == 8'd{})", p.out_slot);
    let (mut hit, mut miss) = (vec![], vec![]);
    for e in 0..3 {
        let q = (e + 1) % 3;
        let pairs = [
            (o.z[e], o.e_z[e]),
            (o.z[q], o.e_z[q]),
            (o.rz[e], o.rz_bound[e]),
            (o.a[e], o.a_bound[e]),
            (o.b[e], o.b_bound[e]),
            (o.s[e], o.s_bound[e]),
        ];
        for (i, (x, b)) in pairs.iter().enumerate() {
            let _ = writeln!(
                v,
                "  signs${}$x = regs${x}$q;\n  signs${}$e = regs${b}$q;",
                6 * e + i,
                6 * e + i
            );
        }
        // signs pz qz rz a b s; bit 0 positive, bit 1 negative
        let s = |i: usize, neg: bool| format!("signs${}$sgn[{}]", 6 * e + i, neg as u8);
        let up = [true, false, false, false, false, true]; // P below (negative), Q above, ...
        let t = |want_neg: [bool; 6]| (0..6).map(|i| s(i, want_neg[i])).collect::<Vec<_>>();
        let down = up.map(|x| !x);
        let ct = format!("(({}) | ({}))", t(up).join(" & "), t(down).join(" & "));
        let cf = format!("(({}) & ({}))", t(down).join(" | "), t(up).join(" | "));
        let _ = writeln!(
            v,
            "  out_s_x${e}$clock = clock;\n  out_s_x${e}$d = {take} ? regs${}$q : out_s_x${e}$q;",
            o.s[e]
        );
        let _ = writeln!(
            v,
            "  out_s_b${e}$clock = clock;\n  out_s_b${e}$d = {take} ? regs${}$q : out_s_b${e}$q;",
            o.s_bound[e]
        );
        let _ = writeln!(v, "  out_cross_t${e}$clock = clock;\n  out_cross_t${e}$d = {take} ? {ct} : out_cross_t${e}$q;");
        let _ = writeln!(v, "  out_cross_f${e}$clock = clock;\n  out_cross_f${e}$d = {take} ? {cf} : out_cross_f${e}$q;");
        hit.push(ct);
        miss.push(cf);
        let _ = writeln!(v, "  s_x${e} = out_s_x${e}$q;\n  s_b${e} = out_s_b${e}$q;\n  cross_t${e} = out_cross_t${e}$q;\n  cross_f${e} = out_cross_f${e}$q;");
    }
    let _ = writeln!(
        v,
        "  out_hit$clock = clock;\n  out_hit$d = {take} ? ({}) : out_hit$q;",
        hit.join(" | ")
    );
    let _ = writeln!(
        v,
        "  out_miss$clock = clock;\n  out_miss$d = {take} ? ({}) : out_miss$q;",
        miss.join(" & ")
    );
    let _ = writeln!(
        v,
        "  out_tag$clock = clock;\n  out_tag$d = {take} ? tags${}$q : out_tag$q;",
        p.side_out
    );
    let _ = writeln!(
        v,
        "  out_valid$clock = clock;\n  out_valid$d = {take} & valid${}$q;",
        p.side_out
    );
    let _ = writeln!(v, "  hit = out_hit$q;\n  miss = out_miss$q;\n  tag_out = out_tag$q;\n  valid_out = out_valid$q;\nend");
}

/// The input word ports in [`Inputs::from_words`](crate::fold::ops::Inputs::from_words)'s
/// order, as the Verilog names them.
pub(crate) fn input_names() -> Vec<String> {
    let mut n = vec![];
    for r in 0..3 {
        n.extend((0..4).map(|c| format!("m_{r}${c}")));
    }
    n.extend(["alpha_m", "alpha_f"].map(String::from));
    for r in 0..3 {
        n.extend((0..4).map(|c| format!("f_{r}${c}")));
    }
    n.extend(["beta_m", "beta_f", "scale"].map(String::from));
    for k in 0..3 {
        n.extend(["v_x", "v_y", "v_z"].map(|a| format!("{a}${k}")));
    }
    n
}

/// Stamps out `TCheckFold` in the calling module (after `tcheck!`: it uses `Sign`, `FpMul`,
/// `FpAdd`, `FpScale`, `FORMAT`), or with `fpga` first `TCheckFoldFpga`, the same on
/// `FpMulFpga` and `FpAddFpga` (for a plan at FPGA depth). Arguments: `W`, `WM1` = W-1, `E`,
/// `F`.
macro_rules! tcheck_fold {
    ($W:tt, $WM1:tt, $E:tt, $F:tt) => {
        $crate::rtl::tcheck_fold::tcheck_fold!(@block TCheckFold, FpMul, FpAdd, $W, $WM1, $E, $F);
        $crate::rtl::tcheck_fold::tcheck_fold!(@logic TCheckFold, $W, $WM1, $E, $F);
        $crate::rtl::tcheck_fold::tcheck_fold!(@top $W);
    };
    (fpga $W:tt, $WM1:tt, $E:tt, $F:tt) => {
        $crate::rtl::tcheck_fold::tcheck_fold!(@block TCheckFoldFpga, FpMulFpga, FpAddFpga, $W, $WM1, $E, $F);
        $crate::rtl::tcheck_fold::tcheck_fold!(@logic TCheckFoldFpga, $W, $WM1, $E, $F);
    };
    (@block $Name:ident, $Mul:ident, $Add:ident, $W:tt, $WM1:tt, $E:tt, $F:tt) => {
        $crate::rtl::tcheck::tcheck_ports! {
            $W,
            /// T.CHECK folded onto shared units by a [`Plan`](crate::fold::plan::Plan): one
            /// triangle pair every `ii` clocks, taken while the control counter is 0 (it stays 0
            /// until the first pair, then runs: pairs come ii, 2 ii, ... clocks after it), its results at the outputs `latency` clocks
            /// later with `valid_out` high for one clock (docs/explanation/architecture.md, "Folded
            /// T.CHECK"). Bit for bit [`TCheck`]'s values and verdicts. Ports: [`TCheck`]'s. At FPGA depth
            /// (`TCheckFoldFpga`, a plan of `Depth::Fpga`) its operands are registered, each unit
            /// selecting them on its own copy of the counter.
            $Name {
                plan: $crate::rtl::tcheck_fold::Fixed<$crate::fold::plan::Plan>,
                // the counter starts with the first pair (`run`), then runs freely
                run: DFF<Bit>,
                counter: DFF<Bits<8>>,
                regs: Vec<$crate::rtl::tcheck_fold::KeptDff<Bits<$W>>>,
                exact: Vec<DFF<Bit>>,
                valid: Vec<DFF<Bit>>,
                tags: Vec<DFF<Bits<32>>>,
                // at FPGA depth (`Plan::operand_regs`), else none: copies of the counter
                // (`Plan::counter_copies`) and each unit's operand registers (`b` of the
                // multipliers and adders, `sub` of the adders, `sel` of the constant
                // multipliers, each numbered over those units)
                cnt: Vec<$crate::rtl::tcheck_fold::KeptDff<Bits<8>>>,
                op_a: Vec<DFF<Bits<$W>>>,
                op_b: Vec<DFF<Bits<$W>>>,
                op_sub: Vec<DFF<Bit>>,
                op_sel: Vec<DFF<Bit>>,
                // the units per class (Class::ALL order)
                mul_v: Vec<$Mul>,
                mul_up: Vec<$Mul>,
                add_v: Vec<$Add>,
                add_up: Vec<$Add>,
                scale_e: Vec<FpScale>,
                scale_z: Vec<FpScale>,
                scale_s: Vec<FpScale>,
                // per edge the signs of Pz, Qz, r_z, a, b, s
                signs: Vec<Sign>,
            }
        }

        impl $Name {
            /// The unit vectors' names per class (the Verilog's instance prefixes).
            const UNITS: [&'static str; 7] = ["mul_v", "mul_up", "add_v", "add_up", "scale_e", "scale_z", "scale_s"];

            /// A folded T.CHECK built from `plan`, its value datapath rounding with `rounding`.
            pub fn new(plan: $crate::fold::plan::Plan, rounding: Rounding) -> Self {
                assert!(
                    plan.depth.fp_mul_latency() == $Mul::LATENCY && plan.depth.fp_add_latency() == $Add::LATENCY,
                    "a plan at {:?} depth builds on that depth's units", plan.depth
                );
                let cert = $crate::golden::certificate::Certificate::new(FORMAT, rounding);
                let up = Rounding::TowardPositive;
                let u = plan.units;
                $crate::rtl::tcheck::tcheck_new! { Self {
                    run: Default::default(),
                    counter: Default::default(),
                    cnt: (0..plan.counter_copies()).map(|_| $crate::rtl::tcheck_fold::KeptDff::new(true)).collect(),
                    op_a: (0..plan.operand_reg_count("a")).map(|_| Default::default()).collect(),
                    op_b: (0..plan.operand_reg_count("b")).map(|_| Default::default()).collect(),
                    op_sub: (0..plan.operand_reg_count("sub")).map(|_| Default::default()).collect(),
                    op_sel: (0..plan.operand_reg_count("sel")).map(|_| Default::default()).collect(),
                    regs: (0..plan.word_regs()).map(|_| $crate::rtl::tcheck_fold::KeptDff::new(plan.binding == $crate::fold::plan::Binding::PerReader)).collect(),
                    exact: (0..plan.exact.len).map(|_| Default::default()).collect(),
                    valid: (0..plan.valid.len).map(|_| Default::default()).collect(),
                    tags: (0..plan.tag.len).map(|_| Default::default()).collect(),
                    mul_v: (0..u[0]).map(|_| $Mul::new(rounding)).collect(),
                    mul_up: (0..u[1]).map(|_| $Mul::new(up)).collect(),
                    add_v: (0..u[2]).map(|_| $Add::new(rounding)).collect(),
                    add_up: (0..u[3]).map(|_| $Add::new(up)).collect(),
                    scale_e: (0..u[4]).map(|_| FpScale::new(cert.c_e[0], cert.c_e[1])).collect(),
                    scale_z: (0..u[5]).map(|_| FpScale::new(cert.c_z[0], cert.c_z[1])).collect(),
                    scale_s: (0..u[6]).map(|_| FpScale::new(cert.c_s, cert.c_s)).collect(),
                    signs: (0..18).map(|_| Sign::new()).collect(),
                    plan: $crate::rtl::tcheck_fold::Fixed(std::sync::Arc::new(plan)),
                } }
            }

            /// The input word `i` ([`Inputs::from_words`](crate::fold::ops::Inputs::from_words)'s order).
            fn input_word(&self, i: usize) -> u64 {
                let x = match i {
                    0..=11 => [&self.m_0, &self.m_1, &self.m_2][i / 4][i % 4].val(),
                    12 => self.alpha_m.val(),
                    13 => self.alpha_f.val(),
                    14..=25 => [&self.f_0, &self.f_1, &self.f_2][(i - 14) / 4][(i - 14) % 4].val(),
                    26 => self.beta_m.val(),
                    27 => self.beta_f.val(),
                    28 => self.scale.val(),
                    _ => [&self.v_x, &self.v_y, &self.v_z][(i - 29) % 3][(i - 29) / 3].val(),
                };
                x.to_u64()
            }

            /// The input word port `i` ([`Inputs::from_words`](crate::fold::ops::Inputs::from_words)'s
            /// order), for a block that drives this one (the folded TRI_UNIT).
            fn input_mut(&mut self, i: usize) -> &mut Signal<In, Bits<$W>> {
                match i {
                    0..=11 => {
                        let row = match i / 4 {
                            0 => &mut self.m_0,
                            1 => &mut self.m_1,
                            _ => &mut self.m_2,
                        };
                        &mut row[i % 4]
                    }
                    12 => &mut self.alpha_m,
                    13 => &mut self.alpha_f,
                    14..=25 => {
                        let row = match (i - 14) / 4 {
                            0 => &mut self.f_0,
                            1 => &mut self.f_1,
                            _ => &mut self.f_2,
                        };
                        &mut row[(i - 14) % 4]
                    }
                    26 => &mut self.beta_m,
                    27 => &mut self.beta_f,
                    28 => &mut self.scale,
                    _ => {
                        let axis = match (i - 29) % 3 {
                            0 => &mut self.v_x,
                            1 => &mut self.v_y,
                            _ => &mut self.v_z,
                        };
                        &mut axis[(i - 29) / 3]
                    }
                }
            }

            /// The output of unit `u` of class `k`.
            fn unit_y(&self, k: usize, u: usize) -> u64 {
                match k {
                    0 => self.mul_v[u].y.val(),
                    1 => self.mul_up[u].y.val(),
                    2 => self.add_v[u].y.val(),
                    3 => self.add_up[u].y.val(),
                    4 => self.scale_e[u].y.val(),
                    5 => self.scale_z[u].y.val(),
                    _ => self.scale_s[u].y.val(),
                }
                .to_u64()
            }

            /// A word register read with its modifiers.
            fn read(&self, r: &$crate::fold::plan::Read) -> u64 {
                let q = self.regs[r.reg].q.val().to_u64();
                let e = (q >> $F) & ((1 << $E) - 1);
                if r.abs {
                    q & ((1u64 << $WM1) - 1)
                } else if r.dbl && e != 0 && e != (1 << $E) - 1 {
                    q + (1u64 << $F)
                } else {
                    q
                }
            }

            /// Issues to unit `u` of class `k` its operands, `sub` and `sel`: straight to the
            /// unit, or into its operand registers and the unit from them.
            fn issue_registered(&mut self, k: usize, u: usize, a: u64, b: u64, sub: bool, sel: bool) {
                if self.plan.0.operand_regs() == 0 {
                    return self.issue(k, u, a, b, sub, sel);
                }
                let clock = self.clock.val();
                let i = self.plan.0.operand_reg(k, u, "a");
                let r = &mut self.op_a[i];
                (r.clock.next, r.d.next) = (clock, a.into());
                let (a2, mut b2, mut sub2, mut sel2) = (r.q.val().to_u64(), 0, false, false);
                if k < 4 {
                    let i = self.plan.0.operand_reg(k, u, "b");
                    let r = &mut self.op_b[i];
                    (r.clock.next, r.d.next) = (clock, b.into());
                    b2 = r.q.val().to_u64();
                }
                if k == 2 || k == 3 {
                    let i = self.plan.0.operand_reg(k, u, "sub");
                    let r = &mut self.op_sub[i];
                    (r.clock.next, r.d.next) = (clock, sub);
                    sub2 = r.q.val();
                }
                if k >= 4 {
                    let i = self.plan.0.operand_reg(k, u, "sel");
                    let r = &mut self.op_sel[i];
                    (r.clock.next, r.d.next) = (clock, sel);
                    sel2 = r.q.val();
                }
                self.issue(k, u, a2, b2, sub2, sel2)
            }

            /// Drives unit `u` of class `k`: operands, `sub`, `sel`.
            fn issue(&mut self, k: usize, u: usize, a: u64, b: u64, sub: bool, sel: bool) {
                let clock = self.clock.val();
                match k {
                    0 | 1 => {
                        let m = if k == 0 { &mut self.mul_v[u] } else { &mut self.mul_up[u] };
                        (m.clock.next, m.a.next, m.b.next, m.valid_in.next) = (clock, a.into(), b.into(), false);
                    }
                    2 | 3 => {
                        let m = if k == 2 { &mut self.add_v[u] } else { &mut self.add_up[u] };
                        (m.clock.next, m.a.next, m.b.next, m.sub.next, m.valid_in.next) = (clock, a.into(), b.into(), sub, false);
                    }
                    _ => {
                        let m = match k {
                            4 => &mut self.scale_e[u],
                            5 => &mut self.scale_z[u],
                            _ => &mut self.scale_s[u],
                        };
                        (m.clock.next, m.a.next, m.sel.next) = (clock, a.into(), sel);
                    }
                }
            }

            /// Verilog of the folded T.CHECK's own logic (its registers and units are
            /// rust-hdl's instances).
            fn body(&self) -> String {
                $crate::rtl::tcheck_fold::body_verilog(&self.plan.0, $W, $E, $F, Self::UNITS)
            }
        }
    };
    (@logic $Name:ident, $W:tt, $WM1:tt, $E:tt, $F:tt) => {
        impl Logic for $Name {
            fn update(&mut self) {
                use $crate::fold::plan::Src;
                let p = self.plan.0.clone();
                let clock = self.clock.val();
                let c = self.counter.q.val().to_u64() as usize;
                let run = self.run.q.val() | self.valid_in.val();
                (self.run.clock.next, self.run.d.next) = (clock, run);
                self.counter.clock.next = clock;
                self.counter.d.next = (if run { ((c + 1) % p.ii) as u64 } else { 0 }).into();
                for r in &mut self.cnt {
                    (r.clock.next, r.d.next) = (clock, self.counter.d.next);
                }
                for ch in &p.words {
                    for i in 0..ch.len {
                        let r = ch.first + i;
                        let d = match (c == ch.slot, i, ch.src) {
                            (false, _, _) => self.regs[r].q.val(),
                            (true, 0, Src::Input(n)) => self.input_word(n).into(),
                            (true, 0, Src::Unit(k, u)) => self.unit_y(k, u).into(),
                            _ => self.regs[r - 1].q.val(),
                        };
                        (self.regs[r].clock.next, self.regs[r].d.next) = (clock, d);
                    }
                }
                for i in 0..p.exact.len {
                    let src = if i == 0 { self.v_exact.val() } else { self.exact[i - 1].q.val() };
                    let d = if c == p.exact.slot { src } else { self.exact[i].q.val() };
                    (self.exact[i].clock.next, self.exact[i].d.next) = (clock, d);
                }
                for i in 0..p.valid.len {
                    let src = if i == 0 { self.valid_in.val() } else { self.valid[i - 1].q.val() };
                    let d = if c == p.valid.slot { src } else { self.valid[i].q.val() };
                    (self.valid[i].clock.next, self.valid[i].d.next) = (clock, d);
                }
                for i in 0..p.tag.len {
                    let src = if i == 0 { self.tag.val() } else { self.tags[i - 1].q.val() };
                    let d = if c == p.tag.slot { src } else { self.tags[i].q.val() };
                    (self.tags[i].clock.next, self.tags[i].d.next) = (clock, d);
                }
                for k in 0..7 {
                    for u in 0..p.units[k] {
                        let (a, b, sub, sel) = match &p.issues[k][u][c] {
                            Some(iss) => (self.read(&iss.a), iss.b.map_or(0, |b| self.read(&b)), iss.sub, iss.sel.is_some_and(|r| self.exact[r].q.val())),
                            None => (0, 0, false, false),
                        };
                        self.issue_registered(k, u, a, b, sub, sel);
                    }
                }
                let o = &p.outputs;
                let take = c == p.out_slot;
                let (mut hit, mut miss) = (false, true);
                for e in 0..3 {
                    let q = (e + 1) % 3;
                    let pairs = [(o.z[e], o.e_z[e]), (o.z[q], o.e_z[q]), (o.rz[e], o.rz_bound[e]), (o.a[e], o.a_bound[e]), (o.b[e], o.b_bound[e]), (o.s[e], o.s_bound[e])];
                    let mut pos = [false; 6];
                    let mut neg = [false; 6];
                    for (i, (x, b)) in pairs.iter().enumerate() {
                        let s = &mut self.signs[6 * e + i];
                        (s.x.next, s.e.next) = (self.regs[*x].q.val(), self.regs[*b].q.val());
                        (pos[i], neg[i]) = (s.sgn.val().get_bit(0), s.sgn.val().get_bit(1));
                    }
                    // P below, Q above | the mirror (Pz, Qz, r_z, a, b, s)
                    let ct = (neg[0] & pos[1] & pos[2] & pos[3] & pos[4] & neg[5]) | (pos[0] & neg[1] & neg[2] & neg[3] & neg[4] & pos[5]);
                    let cf = (pos[0] | neg[1] | neg[2] | neg[3] | neg[4] | pos[5]) & (neg[0] | pos[1] | pos[2] | pos[3] | pos[4] | neg[5]);
                    (hit, miss) = (hit | ct, miss & cf);
                    let (sx, sb) = (self.regs[o.s[e]].q.val(), self.regs[o.s_bound[e]].q.val());
                    for (r, v) in [(&mut self.out_s_x[e], sx), (&mut self.out_s_b[e], sb)] {
                        (r.clock.next, r.d.next) = (clock, if take { v } else { r.q.val() });
                    }
                    for (r, v) in [(&mut self.out_cross_t[e], ct), (&mut self.out_cross_f[e], cf)] {
                        (r.clock.next, r.d.next) = (clock, if take { v } else { r.q.val() });
                    }
                    self.s_x[e].next = self.out_s_x[e].q.val();
                    self.s_b[e].next = self.out_s_b[e].q.val();
                    self.cross_t[e].next = self.out_cross_t[e].q.val();
                    self.cross_f[e].next = self.out_cross_f[e].q.val();
                }
                for (r, v) in [(&mut self.out_hit, hit), (&mut self.out_miss, miss)] {
                    (r.clock.next, r.d.next) = (clock, if take { v } else { r.q.val() });
                }
                let t = if take { self.tags[p.side_out].q.val() } else { self.out_tag.q.val() };
                (self.out_tag.clock.next, self.out_tag.d.next) = (clock, t);
                (self.out_valid.clock.next, self.out_valid.d.next) = (clock, take & self.valid[p.side_out].q.val());
                self.hit.next = self.out_hit.q.val();
                self.miss.next = self.out_miss.q.val();
                self.tag_out.next = self.out_tag.q.val();
                self.valid_out.next = self.out_valid.q.val();
            }

            fn connect(&mut self) {
                (self.run.clock.connect(), self.run.d.connect());
                self.counter.clock.connect();
                self.counter.d.connect();
                for r in &mut self.cnt {
                    (r.clock.connect(), r.d.connect());
                }
                for r in self.op_a.iter_mut().chain(&mut self.op_b) {
                    (r.clock.connect(), r.d.connect());
                }
                for r in self.op_sub.iter_mut().chain(&mut self.op_sel) {
                    (r.clock.connect(), r.d.connect());
                }
                for r in &mut self.regs {
                    (r.clock.connect(), r.d.connect());
                }
                for r in self.exact.iter_mut().chain(&mut self.valid) {
                    (r.clock.connect(), r.d.connect());
                }
                for r in &mut self.tags {
                    (r.clock.connect(), r.d.connect());
                }
                for m in self.mul_v.iter_mut().chain(&mut self.mul_up) {
                    (m.clock.connect(), m.a.connect(), m.b.connect(), m.valid_in.connect());
                }
                for m in self.add_v.iter_mut().chain(&mut self.add_up) {
                    (m.clock.connect(), m.a.connect(), m.b.connect(), m.sub.connect(), m.valid_in.connect());
                }
                for m in self.scale_e.iter_mut().chain(&mut self.scale_z).chain(&mut self.scale_s) {
                    (m.clock.connect(), m.a.connect(), m.sel.connect());
                }
                for s in &mut self.signs {
                    (s.x.connect(), s.e.connect());
                }
                for e in 0..3 {
                    for r in [&mut self.out_s_x[e], &mut self.out_s_b[e]] {
                        (r.clock.connect(), r.d.connect());
                    }
                    for r in [&mut self.out_cross_t[e], &mut self.out_cross_f[e]] {
                        (r.clock.connect(), r.d.connect());
                    }
                    (self.s_x[e].connect(), self.s_b[e].connect(), self.cross_t[e].connect(), self.cross_f[e].connect());
                }
                for r in [&mut self.out_hit, &mut self.out_miss, &mut self.out_valid] {
                    (r.clock.connect(), r.d.connect());
                }
                (self.out_tag.clock.connect(), self.out_tag.d.connect());
                (self.hit.connect(), self.miss.connect(), self.tag_out.connect(), self.valid_out.connect());
            }

            fn hdl(&self) -> Verilog {
                Verilog::Custom(self.body())
            }
        }
    };
    (@top $W:tt) => {
        /// A folded T.CHECK built from `plan` ([`crate::fold::tcheck_plan`]), ready to
        /// simulate as a top-level block (inputs claimed, connected).
        pub fn tcheck_fold_top(plan: $crate::fold::plan::Plan, rounding: Rounding) -> TCheckFold {
            let mut uut = TCheckFold::new(plan, rounding);
            for c in 0..4 {
                uut.m_0[c].connect();
                uut.m_1[c].connect();
                uut.m_2[c].connect();
                uut.f_0[c].connect();
                uut.f_1[c].connect();
                uut.f_2[c].connect();
            }
            for k in 0..3 {
                uut.v_x[k].connect();
                uut.v_y[k].connect();
                uut.v_z[k].connect();
            }
            top_level!(uut; clock, alpha_m, alpha_f, beta_m, beta_f, scale, v_exact, tag, valid_in)
        }

        /// Verilog of the folded T.CHECK (top module `top`).
        pub fn verilog_tcheck_fold(ii: usize, rounding: Rounding) -> String {
            let plan = $crate::fold::tcheck_plan(ii, $crate::fold::plan::Binding::Shared, $crate::chip::rtl::Depth::Asic).expect("T.CHECK schedules at every II >= 1");
            generate_verilog(&tcheck_fold_top(plan, rounding))
        }
    };
}
pub(crate) use tcheck_fold;
