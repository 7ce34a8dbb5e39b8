//! T.CHECK (DATE'05 §4.2, Eqs. 8, 9, 11-13) and TRI_UNIT (two T.CHECKs).
//!
//! T.CHECK maps triangle A's vertices into the space where triangle B is the unit
//! triangle U = {(u, v, 0) : u, v >= 0, u + v <= 1} and tests A's three edges against U.
//! In pipeline order (column-vector convention, M_b = M_B . M_AB):
//! ```text
//! stage 1  Mb_ij = (m_i0 b_0j + m_i1 b_1j) + m_i2 b_2j                 j < 3   (Eq. 11)
//!          Mb_i3 = (m_i0 b_03 + m_i1 b_13) + (m_i2 b_23 + m_i3)                (Eq. 12)
//! stage 2  V'_i  = (Mb_i0 x + Mb_i1 y) + (Mb_i2 z + Mb_i3)                     (Eq. 13)
//! stage 3  per edge P->Q (V0V1, V1V2, V2V0):
//!          a = Px Qz - Qx Pz,  b = Py Qz - Qy Pz,  r_z = Qz - Pz              (Eq. 9)
//! stage 4  s = (a + b) - r_z
//! stage 5  crossing = (Pz <= 0 <= Qz and r_z > 0 and a >= 0 and b >= 0 and s <= 0)
//!                  or (Qz <= 0 <= Pz and r_z < 0 and a <= 0 and b <= 0 and s >= 0)
//! ```
//! where m = M_B (leaf of B) and b = M_AB (A's frame to B's frame). Derivation of stage 5:
//! the edge meets z = 0 at X = P + (-Pz / r_z)(Q - P), whose coordinates are
//! X = (a / r_z, b / r_z, 0); X is in U iff a/r_z >= 0, b/r_z >= 0, (a+b)/r_z <= 1, i.e.
//! Eq. 8 negated when r_z > 0 (P below, Q above) and the mirrored signs when r_z < 0 (the
//! "other criterion" of DATE'05 §3.3, which is the same test with P and Q swapped).
//! Two triangles in general position intersect iff an edge of one crosses the other, so
//! TRI_UNIT runs A's edges against U(B) and B's edges against U(A). A degenerate triangle
//! has no M_B: that direction is skipped (its edges are still tested against the other).

use crate::dop::host::{Affine, HostSetup};
use crate::format::{Format, Rounding};
use crate::memory::TriWord;

/// Every intermediate of one T.CHECK, for bit-exact comparison with the RTL.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    pub mb: Affine,
    pub v: [[f64; 3]; 3],
    pub a: [f64; 3],
    pub b: [f64; 3],
    pub rz: [f64; 3],
    pub s: [f64; 3],
    pub crossing: [bool; 3],
}

impl Trace {
    pub fn hit(&self) -> bool {
        self.crossing.iter().any(|&c| c)
    }
}

/// Stage 1: M_b = M_B . M_AB (Eqs. 11, 12), `m` the leaf's M_B, `b` the frame map.
pub fn stage1(f: Format, r: Rounding, m: &Affine, b: &Affine) -> Affine {
    let add = |x, y| f.add(x, y, r);
    let mul = |x, y| f.mul(x, y, r);
    let mut mb = [[0.0; 4]; 3];
    for i in 0..3 {
        for j in 0..3 {
            mb[i][j] = add(add(mul(m[i][0], b[0][j]), mul(m[i][1], b[1][j])), mul(m[i][2], b[2][j]));
        }
        mb[i][3] = add(
            add(mul(m[i][0], b[0][3]), mul(m[i][1], b[1][3])),
            add(mul(m[i][2], b[2][3]), m[i][3]),
        );
    }
    mb
}

/// Stages 2-5 on the output `mb` of stage 1 and the triangle `v`.
pub fn edges(f: Format, r: Rounding, mb: &Affine, v: &[[f64; 3]; 3]) -> Trace {
    let add = |x, y| f.add(x, y, r);
    let sub = |x, y| f.sub(x, y, r);
    let mul = |x, y| f.mul(x, y, r);
    let mut vt = [[0.0; 3]; 3];
    for (p, out) in v.iter().zip(vt.iter_mut()) {
        for i in 0..3 {
            out[i] = add(add(mul(mb[i][0], p[0]), mul(mb[i][1], p[1])), add(mul(mb[i][2], p[2]), mb[i][3]));
        }
    }
    let (mut a, mut bb, mut rz, mut s, mut crossing) = ([0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3], [false; 3]);
    for e in 0..3 {
        let (p, q) = (vt[e], vt[(e + 1) % 3]);
        a[e] = sub(mul(p[0], q[2]), mul(q[0], p[2]));
        bb[e] = sub(mul(p[1], q[2]), mul(q[1], p[2]));
        rz[e] = sub(q[2], p[2]);
        s[e] = sub(add(a[e], bb[e]), rz[e]);
        let up = p[2] <= 0.0 && q[2] >= 0.0 && rz[e] > 0.0 && a[e] >= 0.0 && bb[e] >= 0.0 && s[e] <= 0.0;
        let down = q[2] <= 0.0 && p[2] >= 0.0 && rz[e] < 0.0 && a[e] <= 0.0 && bb[e] <= 0.0 && s[e] >= 0.0;
        crossing[e] = up || down;
    }
    Trace { mb: *mb, v: vt, a, b: bb, rz, s, crossing }
}

/// One T.CHECK: the edges of triangle `v` (in its own object's frame) against the unit
/// triangle of the other object's leaf, whose map is `m_leaf`; `m_frame` maps `v`'s frame
/// into the leaf's frame.
pub fn tcheck(f: Format, r: Rounding, m_leaf: &Affine, m_frame: &Affine, v: &[[f64; 3]; 3]) -> Trace {
    edges(f, r, &stage1(f, r, m_leaf, m_frame), v)
}

/// TRI_UNIT: A's edges against U(B), then B's edges against U(A).
pub fn tri_unit(f: Format, r: Rounding, a: &TriWord, b: &TriWord, setup: &HostSetup) -> bool {
    (!b.degenerate && tcheck(f, r, &b.m, &setup.m_ab, &a.v).hit())
        || (!a.degenerate && tcheck(f, r, &a.m, &setup.m_ba, &b.v).hit())
}

/// TRI_UNIT during one query: stage 1 depends on one leaf and the pose only, so its
/// output is kept per leaf (the same values; [`tri_unit`] bit for bit, tested).
pub struct TriUnit<'a> {
    f: Format,
    r: Rounding,
    setup: &'a HostSetup,
    /// Per triangle of B: M_B(b) . M_AB; per triangle of A: M_A(a) . M_BA.
    mb_b: StageOneCache,
    mb_a: StageOneCache,
}

struct StageOneCache {
    slot: Vec<u32>,
    values: Vec<Affine>,
}

impl StageOneCache {
    fn get(&mut self, t: u32, compute: impl FnOnce() -> Affine) -> &Affine {
        let mut s = self.slot[t as usize];
        if s == u32::MAX {
            s = self.values.len() as u32;
            self.slot[t as usize] = s;
            self.values.push(compute());
        }
        &self.values[s as usize]
    }
}

impl<'a> TriUnit<'a> {
    pub fn new(f: Format, r: Rounding, setup: &'a HostSetup, tris_a: usize, tris_b: usize) -> Self {
        let cache = |n| StageOneCache { slot: vec![u32::MAX; n], values: vec![] };
        TriUnit { f, r, setup, mb_b: cache(tris_b), mb_a: cache(tris_a) }
    }

    /// Do triangle `ta` of A (word `a`) and `tb` of B (word `b`) intersect?
    pub fn test(&mut self, ta: u32, a: &TriWord, tb: u32, b: &TriWord) -> bool {
        let (f, r, setup) = (self.f, self.r, self.setup);
        if !b.degenerate {
            let mb = self.mb_b.get(tb, || stage1(f, r, &b.m, &setup.m_ab));
            if edges(f, r, mb, &a.v).hit() {
                return true;
            }
        }
        !a.degenerate && edges(f, r, self.mb_a.get(ta, || stage1(f, r, &a.m, &setup.m_ba)), &b.v).hit()
    }
}
