//! T.CHECK's certificate constants (docs/explanation/accuracy.md, "T.CHECK's certificate"): the
//! error factors of the values T.CHECK computes and the constants the chip multiplies
//! their magnitudes by. The host's error words (per leaf and per pose) use them too.

use crate::format::{Format, Rounding, ScaleConst};

/// The constants of T.CHECK's certificate for a value format and rounding
/// (docs/explanation/accuracy.md, "T.CHECK's certificate"). `g_v` is the mapped vertices' error
/// factor (f64, exact to 2^-50); `c_*` are the constants the chip multiplies magnitudes
/// by, each the smallest [`ScaleConst`] at least its target (times 1 + 2^-40), indexed
/// like `g_v` by whether the vertices are exact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Certificate {
    /// The format and rounding of the chip's values.
    pub f: Format,
    pub r: Rounding,
    /// Unit roundoff of the value datapath: 2^-(F+1) to nearest, 2^-F directed.
    pub u: f64,
    /// The host's rounding of the words it writes (M_B, the frame maps, the vertices; to
    /// nearest): relative error `u1` of a normal result, absolute `eta_s` (half the smallest
    /// subnormal) below 2^emin.
    pub u1: f64,
    pub eta_s: f64,
    /// Mapped vertex coordinates: |V - V*| <= g_v M_V, for vertices the host rounded (`[0]`)
    /// or exact ones (`[1]`).
    pub g_v: [f64; 2],
    /// E = c_e M >= g_v M: a mapped coordinate's bound (z's).
    pub c_e: [ScaleConst; 2],
    /// E' = c_z M >= g_v M + u (1 + u) |z| for z (r_z's rounding).
    pub c_z: [ScaleConst; 2],
    /// c_s >= 2u + u^2: the rounding of a product and the difference after it, per unit
    /// of the operands' magnitudes (in G = E_z + c_s |z|, which carries a's and b's), and of
    /// s's two additions per unit of |a| + |b| + |r_z|.
    pub c_s: ScaleConst,
    /// F1: a power of two that every mapped vertex's magnitude is at least (the host's
    /// alpha_m is floored so): (g_v F1)^2 >= the largest underflow error of a product.
    pub floor: f64,
}

impl Certificate {
    /// Computed once per format and rounding and thread (the host asks for it at every
    /// pose; finding the scale constants takes microseconds).
    pub fn new(f: Format, r: Rounding) -> Certificate {
        thread_local! {
            static KNOWN: std::cell::RefCell<Vec<(Rounding, Certificate)>> = const { std::cell::RefCell::new(Vec::new()) };
        }
        KNOWN.with_borrow_mut(
            |known| match known.iter().find(|(_, c)| c.r == r && c.f == f) {
                Some((_, c)) => *c,
                None => {
                    let c = Certificate::compute(f, r);
                    known.push((r, c));
                    c
                }
            },
        )
    }

    fn compute(f: Format, r: Rounding) -> Certificate {
        let half = 2f64.powi(-(f.frac_bits() as i32) - 1);
        let nearest = r == Rounding::NearestEven;
        let u = if nearest { half } else { 2.0 * half };
        let u1 = half / (1.0 - half);
        // A product's absolute error below 2^emin: half the smallest subnormal to nearest.
        let eta = f.min_positive_subnormal() * if nearest { 0.5 } else { 1.0 };
        let g_v = [u1, 0.0].map(|gx| 6.0 * u + ((1.0 + u1) * (1.0 + u1) * (1.0 + gx) - 1.0));
        let floor = 2f64.powi((eta.sqrt() / g_v[1]).log2().ceil() as i32);
        let c = |x: f64| f.scale_const_at_least(x * (1.0 + 2f64.powi(-40)));
        let (c2, c1) = (2.0 * u + u * u, u + u * u);
        Certificate {
            f,
            r,
            u,
            u1,
            eta_s: f.min_positive_subnormal() / 2.0,
            g_v,
            c_e: g_v.map(c),
            c_z: g_v.map(|g| c(g + c1)),
            c_s: c(c2),
            floor,
        }
    }

    /// A word of the certificate from its f64 value x (computed to within 2^-50 of the
    /// quantity it stands for): x (1 + 2^-40) rounded up in the format.
    pub fn word_up(&self, x: f64) -> f64 {
        self.f
            .round(x * (1.0 + 2f64.powi(-40)), Rounding::TowardPositive)
    }
}
