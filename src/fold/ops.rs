//! T.CHECK's floating-point operations written once, over any arithmetic ([`Arith`]): in
//! f64 ([`Eval`]) it is golden [`stage1`](crate::golden::tcheck::stage1) then
//! [`edges`](crate::golden::tcheck::edges), bit for bit (checked in `tb/fold.rs`); traced
//! ([`super::graph`]) it is the dataflow graph the folded RTL is scheduled from.

use crate::format::{Format, Rounding, ScaleConst};
use crate::golden::certificate::Certificate;

/// The rounding of an operation: the value datapath's (the triangle rounding) or upward
/// (the certificate's magnitudes and bounds).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Rnd {
    Value,
    Up,
}

/// The certificate's constant a magnitude is multiplied by: `c_e` and `c_z` per vertex
/// kind (rounded or exact vertices, the pair's `v_exact` bit), `c_s` one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Const {
    Ce,
    Cz,
    Cs,
}

/// The arithmetic T.CHECK is written in.
pub trait Arith {
    type V: Copy;
    fn mul(&mut self, a: Self::V, b: Self::V, r: Rnd) -> Self::V;
    fn add(&mut self, a: Self::V, b: Self::V, r: Rnd) -> Self::V;
    fn sub(&mut self, a: Self::V, b: Self::V, r: Rnd) -> Self::V;
    /// `|a| c` rounded upward, at least 2^emin ([`Format::scale_up`]).
    fn scale(&mut self, a: Self::V, c: Const) -> Self::V;
    /// `|a|`: the sign bit cleared (free in hardware).
    fn abs(&mut self, a: Self::V) -> Self::V;
    /// `2 a`, exact for the `a` it is used on (0, infinite or at least 2^emin, far below
    /// the largest value): one more in the exponent field.
    fn dbl(&mut self, a: Self::V) -> Self::V;
}

/// T.CHECK's word inputs: B's leaf (`m` = M_B, `alpha` its error words), the frame map
/// (`frame`, `beta`), the scale S of the vertices' object and the vertices `v[k][i]`.
#[derive(Clone, Copy, Debug)]
pub struct Inputs<V> {
    pub m: [[V; 4]; 3],
    pub alpha: [V; 2],
    pub frame: [[V; 4]; 3],
    pub beta: [V; 2],
    pub scale: V,
    pub v: [[V; 3]; 3],
}

impl<V: Copy> Inputs<V> {
    /// The number of input words, in the order of the fields.
    pub const WORDS: usize = 12 + 2 + 12 + 2 + 1 + 9;

    /// An input set from its words: `m` row-major, `alpha`, `frame` row-major, `beta`,
    /// `scale`, `v` vertex-major.
    pub fn from_words(w: impl Fn(usize) -> V) -> Self {
        Inputs {
            m: std::array::from_fn(|i| std::array::from_fn(|j| w(4 * i + j))),
            alpha: [w(12), w(13)],
            frame: std::array::from_fn(|i| std::array::from_fn(|j| w(14 + 4 * i + j))),
            beta: [w(26), w(27)],
            scale: w(28),
            v: std::array::from_fn(|k| std::array::from_fn(|i| w(29 + 3 * k + i))),
        }
    }
}

/// What T.CHECK's signs are decided from: per vertex z and its bound E_z, per edge (V0V1,
/// V1V2, V2V0) a, b, r_z, s and their bounds.
#[derive(Clone, Copy, Debug)]
pub struct Outputs<V> {
    pub z: [V; 3],
    pub e_z: [V; 3],
    pub a: [V; 3],
    pub b: [V; 3],
    pub rz: [V; 3],
    pub s: [V; 3],
    pub a_bound: [V; 3],
    pub b_bound: [V; 3],
    pub rz_bound: [V; 3],
    pub s_bound: [V; 3],
}

impl<V: Copy> Outputs<V> {
    /// Every output, in a fixed order (per field, per index).
    pub fn all(&self) -> Vec<V> {
        [
            self.z,
            self.e_z,
            self.a,
            self.b,
            self.rz,
            self.s,
            self.a_bound,
            self.b_bound,
            self.rz_bound,
            self.s_bound,
        ]
        .concat()
    }

    /// Every output mapped by `f`.
    pub fn map<U>(&self, mut f: impl FnMut(V) -> U) -> Outputs<U> {
        let mut m = |x: [V; 3]| x.map(&mut f);
        Outputs {
            z: m(self.z),
            e_z: m(self.e_z),
            a: m(self.a),
            b: m(self.b),
            rz: m(self.rz),
            s: m(self.s),
            a_bound: m(self.a_bound),
            b_bound: m(self.b_bound),
            rz_bound: m(self.rz_bound),
            s_bound: m(self.s_bound),
        }
    }
}

/// `(a0 b0 + a1 b1) + a2 b2`, or `(a0 b0 + a1 b1) + (a2 b2 + c)`: golden `dot`.
fn dot<A: Arith>(o: &mut A, r: Rnd, a: [A::V; 3], b: [A::V; 3], c: Option<A::V>) -> A::V {
    let p: [A::V; 3] = std::array::from_fn(|k| o.mul(a[k], b[k], r));
    let s01 = o.add(p[0], p[1], r);
    match c {
        None => o.add(s01, p[2], r),
        Some(c) => {
            let s2c = o.add(p[2], c, r);
            o.add(s01, s2c, r)
        }
    }
}

/// [`dot`] on absolute values, rounded upward: golden `dot_mag`.
fn dot_mag<A: Arith>(o: &mut A, a: [A::V; 3], b: [A::V; 3], c: Option<A::V>) -> A::V {
    let (a, b) = (a.map(|x| o.abs(x)), b.map(|x| o.abs(x)));
    let c = c.map(|x| o.abs(x));
    dot(o, Rnd::Up, a, b, c)
}

/// T.CHECK's operations in the golden model's order (`stage1`, then `edges_in` with every
/// edge computed): stage 1's M_b and its magnitude, A', then per vertex L1, A' L1, the
/// mapped coordinates with their magnitudes and the certificate's terms, then per edge the
/// values and bounds.
pub fn tcheck<A: Arith>(o: &mut A, x: &Inputs<A::V>) -> Outputs<A::V> {
    let up = Rnd::Up;
    // (arrays start filled with any value: V has no default)
    let (mut mb, mut mag) = ([[x.scale; 4]; 3], [[x.scale; 4]; 3]);
    for n in 0..12 {
        let (i, j) = (n / 4, n % 4);
        let row = [x.m[i][0], x.m[i][1], x.m[i][2]];
        let col = [x.frame[0][j], x.frame[1][j], x.frame[2][j]];
        let c = (j == 3).then_some(x.m[i][3]);
        mb[i][j] = dot(o, Rnd::Value, row, col, c);
        mag[i][j] = dot_mag(o, row, col, c);
    }
    let (am, af) = (
        o.mul(x.alpha[0], x.beta[0], up),
        o.mul(x.alpha[1], x.beta[1], up),
    );
    let a_err = o.add(am, af, up);
    let (mut v, mut e1) = ([[x.scale; 3]; 3], [[x.scale; 3]; 3]);
    let (mut e_z, mut g, mut h) = ([x.scale; 3], [x.scale; 3], [x.scale; 3]);
    for (k, p) in x.v.iter().enumerate() {
        let pa = p.map(|c| o.abs(c));
        let (lx, lz) = (o.add(pa[0], pa[1], up), o.add(pa[2], x.scale, up));
        let l1 = o.add(lx, lz, up);
        let err = o.mul(a_err, l1, up);
        let mut v_mag = [x.scale; 3];
        for i in 0..3 {
            v[k][i] = dot(
                o,
                Rnd::Value,
                [mb[i][0], mb[i][1], mb[i][2]],
                *p,
                Some(mb[i][3]),
            );
            let c = o.add(mag[i][3], err, up);
            v_mag[i] = dot_mag(o, [mag[i][0], mag[i][1], mag[i][2]], *p, Some(c));
            e1[k][i] = o.scale(v_mag[i], if i < 2 { Const::Ce } else { Const::Cz });
        }
        e_z[k] = o.scale(v_mag[2], Const::Ce);
        let cz = o.scale(v[k][2], Const::Cs);
        g[k] = o.add(e_z[k], cz, up);
        let (za, e2) = (o.abs(v[k][2]), o.dbl(e_z[k]));
        h[k] = o.add(za, e2, up);
    }
    let mut out = Outputs {
        z: [v[0][2], v[1][2], v[2][2]],
        e_z,
        a: e_z,
        b: e_z,
        rz: e_z,
        s: e_z,
        a_bound: e_z,
        b_bound: e_z,
        rz_bound: e_z,
        s_bound: e_z,
    };
    for e in 0..3 {
        let (p, q) = (e, (e + 1) % 3);
        let cross = |o: &mut A, i: usize| {
            let (t0, t1) = (
                o.mul(v[p][i], v[q][2], Rnd::Value),
                o.mul(v[q][i], v[p][2], Rnd::Value),
            );
            let x = o.sub(t0, t1, Rnd::Value);
            let (pa, qa) = (o.abs(v[p][i]), o.abs(v[q][i]));
            let (t0, t1) = (o.mul(e1[p][i], h[q], up), o.mul(pa, g[q], up));
            let pq = o.add(t0, t1, up);
            let (t0, t1) = (o.mul(e1[q][i], h[p], up), o.mul(qa, g[p], up));
            let qp = o.add(t0, t1, up);
            (x, o.add(pq, qp, up))
        };
        (out.a[e], out.a_bound[e]) = cross(o, 0);
        (out.b[e], out.b_bound[e]) = cross(o, 1);
        out.rz[e] = o.sub(v[q][2], v[p][2], Rnd::Value);
        out.rz_bound[e] = o.add(e1[q][2], e1[p][2], up);
        let ab = o.add(out.a[e], out.b[e], Rnd::Value);
        out.s[e] = o.sub(ab, out.rz[e], Rnd::Value);
        let (aa, ba, ra) = (o.abs(out.a[e]), o.abs(out.b[e]), o.abs(out.rz[e]));
        let sab = o.add(aa, ba, up);
        let sum = o.add(sab, ra, up);
        let s_round = o.scale(sum, Const::Cs);
        let bab = o.add(out.a_bound[e], out.b_bound[e], up);
        let brs = o.add(out.rz_bound[e], s_round, up);
        out.s_bound[e] = o.add(bab, brs, up);
    }
    out
}

/// The arithmetic in a format, bit for bit the golden model's (values as f64).
pub struct Eval {
    pub f: Format,
    pub r: Rounding,
    /// The constants `c_e`, `c_z` of the pair's vertex kind, and `c_s`.
    pub c: [ScaleConst; 3],
}

impl Eval {
    /// The golden arithmetic of a T.CHECK rounding with `r`, for vertices exact or not.
    pub fn new(f: Format, r: Rounding, v_exact: bool) -> Eval {
        let cert = Certificate::new(f, r);
        let x = v_exact as usize;
        Eval {
            f,
            r,
            c: [cert.c_e[x], cert.c_z[x], cert.c_s],
        }
    }

    fn rounding(&self, r: Rnd) -> Rounding {
        match r {
            Rnd::Value => self.r,
            Rnd::Up => Rounding::TowardPositive,
        }
    }
}

impl Arith for Eval {
    type V = f64;
    fn mul(&mut self, a: f64, b: f64, r: Rnd) -> f64 {
        self.f.mul(a, b, self.rounding(r))
    }
    fn add(&mut self, a: f64, b: f64, r: Rnd) -> f64 {
        self.f.add(a, b, self.rounding(r))
    }
    fn sub(&mut self, a: f64, b: f64, r: Rnd) -> f64 {
        self.f.sub(a, b, self.rounding(r))
    }
    fn scale(&mut self, a: f64, c: Const) -> f64 {
        self.f.scale_up(a, self.c[c as usize])
    }
    fn abs(&mut self, a: f64) -> f64 {
        a.abs()
    }
    fn dbl(&mut self, a: f64) -> f64 {
        2.0 * a
    }
}
