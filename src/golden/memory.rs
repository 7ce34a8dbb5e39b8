//! The memory image the chip fetches, as values: per object, one node word per DOP-tree
//! node in its record and one triangle word per triangle (their bit layout and the layout of
//! the records are [`chip::layout`](crate::chip::layout)'s); and A's triangle cache.

use crate::chip::config::ChipConfig;
use crate::chip::layout::{node_ids, node_records, tri_records, Layout};
use crate::dop::tree::{DopTree, Tri};
use crate::format::{Format, Rounding};
use crate::golden::certificate::Certificate;
use crate::golden::host::{Affine, TriSide};
use nalgebra::{Matrix3, Vector3};

/// The triangle word of one leaf (DATE'05 §4.2: the triangle and its M_B), with the two
/// error words T.CHECK's certificate needs (docs/explanation/accuracy.md, "T.CHECK's certificate").
///
/// The ideal map is M_B* = [L* | -L* v0] with L* = [v1 - v0, v2 - v0, n]^-1 in exact
/// arithmetic on the f64 vertices, n being the host's f64 normal (v1 - v0) x (v2 - v0)
/// divided by the square root of its length, so that it is as long as the edges are (any
/// fixed vector off the plane defines a valid unit-triangle map, and T.CHECK's signs do not
/// depend on the scale of z). The stored entries are the host's f64 map rounded to nearest;
/// the f64 map is within `a_lin` (linear part) and `a_tr` (translation column) of M_B*.
///
/// Why n is scaled: the error of L is one bound for every entry, set by its largest row,
/// about 1 / (triangle size). With the unit normal, z's row of L is about 1 and z is the
/// distance from the plane, so the bound of z was some 1 / size times too wide: on
/// dragon-11k 3.1% of the triangle tests were uncertain at binary32, and 0.04% with n
/// scaled like the edges (`cargo run --release -- accuracy`, docs/explanation/accuracy.md).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TriWord {
    /// Vertices in the object's frame, rounded to nearest in the chip format.
    pub v: [[f64; 3]; 3],
    /// M_B: sends v0 to (0,0,0), v1 to (1,0,0), v2 to (0,1,0) and v0 + n to (0,0,1).
    pub m: Affine,
    /// alpha_m / g: M_B's own error (and the datapath's underflow), per unit of a frame's
    /// beta_m; at least the certificate's floor over the object's scale.
    pub alpha_m: f64,
    /// alpha_f / g: how M_B magnifies the frame's error and B's placement, per unit of
    /// beta_f.
    pub alpha_f: f64,
    /// The vertices are the input's exactly (no rounding error to account for).
    pub v_exact: bool,
    pub degenerate: bool,
    /// Host only, not in the memory word: lambda >= |L*|_inf (the placement bound's
    /// condition 4 lambda eta <= 1/2 is checked per pose against the largest).
    pub lambda: f64,
}

impl TriWord {
    /// Built by the host in f64 from the input geometry, then rounded to the format.
    ///
    /// The bounds are a posteriori: with Res = L E* - I and rho >= |Res|_inf (computed in
    /// f64 plus its rounding error), L* = (I + Res)^-1 L, so |L - L*|_inf <= rho |L| / (1 - rho).
    /// A triangle with rho >= 1/2 (zero area, or too ill-conditioned for f64) is
    /// `degenerate`; so is one whose stored map overflows the format.
    /// `scale` is its object's [`object_scale`].
    pub fn new(t: &Tri, fmt: Format, scale: f64) -> TriWord {
        let rn = |x: f64| fmt.round(x, Rounding::NearestEven);
        let cert = Certificate::new(fmt, Rounding::NearestEven);
        let v = t.map(|p| [rn(p.x), rn(p.y), rn(p.z)]);
        let v_exact = t
            .iter()
            .zip(&v)
            .all(|(p, q)| p.x == q[0] && p.y == q[1] && p.z == q[2]);
        let bad = TriWord {
            v,
            m: [[0.0; 4]; 3],
            alpha_m: f64::INFINITY,
            alpha_f: f64::INFINITY,
            v_exact,
            degenerate: true,
            lambda: 0.0,
        };
        let e1 = t[1] - t[0];
        let e2 = t[2] - t[0];
        let n = e1.cross(&e2);
        let nn = n.norm();
        if !(nn > 0.0 && nn.is_finite()) {
            return bad;
        }
        let e = Matrix3::from_columns(&[e1, e2, n / nn.sqrt()]);
        let Some(l) = e.try_inverse().filter(|i| i.iter().all(|x| x.is_finite())) else {
            return bad;
        };
        let u = 2f64.powi(-53);
        // rho: |fl(L E) - I| plus the rounding of the product and of the differences in E.
        let res = l * e - Matrix3::identity();
        let mag = l.abs() * e.abs();
        let rho = (res.abs() + mag * (8.0 * u)).column_sum().max();
        if rho.is_nan() || rho >= 0.5 {
            return bad;
        }
        let l_inf = l.abs().column_sum().max();
        let e_lin = l_inf * rho / (1.0 - rho);
        let v0 = t[0].coords;
        let tr: Vector3<f64> = -(l * v0);
        // The stored words are the f64 ones rounded to nearest: relative error u1 (in the
        // certificate's g) or, below 2^emin, half the smallest subnormal.
        let a_lin = e_lin + cert.eta_s;
        // |tr - t*| <= |fl(-L v0) + L v0| + |L - L*| |v0|_1
        let derr = (tr.abs() + l.abs() * v0.abs()) * (4.0 * u);
        let a_tr = derr.max() + e_lin * v0.abs().sum() + cert.eta_s;
        let mut m = [[0.0; 4]; 3];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, x) in row.iter_mut().enumerate() {
                *x = rn(if c < 3 { l[(r, c)] } else { tr[r] });
            }
        }
        if !m.iter().flatten().all(|x| x.is_finite()) {
            return bad;
        }
        let u1 = cert.u1;
        // Lambda-hat (rows of the linear part) and T-hat (translation) bound |M_B*|.
        let lam_hat = (0..3)
            .map(|r| {
                (0..3)
                    .map(|c| (1.0 + u1) * m[r][c].abs() + a_lin)
                    .sum::<f64>()
            })
            .fold(0.0, f64::max);
        let t_hat = (0..3)
            .map(|r| (1.0 + u1) * m[r][3].abs() + a_tr)
            .fold(0.0, f64::max);
        let lambda = l_inf + e_lin;
        // Per unit of the frame's beta_m: M_B's own error, and the value datapath's
        // underflow (3 products on x, 3 more per coordinate, each at most the smallest
        // subnormal); per unit of beta_f: how M_B magnifies the frame's error and B's
        // placement (docs/explanation/accuracy.md). Each term in units of 1 / length, so that scaling
        // both objects by 2^s scales these words by 2^-s and the bounds not at all.
        let eta_r = fmt.min_positive_subnormal();
        let alpha_m = a_lin + a_tr / scale + 3.0 * eta_r + 6.0 * eta_r / scale;
        let alpha_f = lam_hat + 2.0 * lambda * (1.0 + 4.0 * t_hat) + 8.0 * lambda * lam_hat * scale;
        // g_v of exact vertices to nearest: the smallest g_v of the format. The floor
        // keeps every mapped vertex's magnitude at least F1 (beta_m >= scale / S_V, L1 >= S_V).
        let g = cert.g_v[1];
        TriWord {
            v,
            m,
            alpha_m: cert.word_up((alpha_m / g).max(cert.floor / scale)),
            alpha_f: cert.word_up(alpha_f / g),
            v_exact,
            degenerate: false,
            lambda,
        }
    }
}

/// Everything the chip reads about one object.
#[derive(Clone, Debug)]
pub struct ObjectImage {
    pub tree: DopTree,
    /// [`object_scale`] of its triangles in T.CHECK's format.
    pub scale: f64,
    /// T.CHECK's format, the triangle words'.
    tri_format: Format,
    /// The largest [`TriWord::lambda`] of the object's triangles.
    lambda_max: f64,
    /// The record of each node in the configuration's layout
    /// ([`node_records`]).
    pub records: Vec<u32>,
    /// The id the chip knows each node by ([`node_ids`]).
    pub ids: Vec<u32>,
    /// The record of each triangle ([`tri_records`]).
    pub tri_records: Vec<u32>,
}

impl ObjectImage {
    /// `tris` must not be empty (mesh loaders reject empty meshes); the tree keeps them,
    /// the image's [`geometry`](ObjectImage::geometry).
    pub fn build(tris: Vec<Tri>, cfg: &ChipConfig) -> ObjectImage {
        let fmt = cfg.format.tri;
        let scale = object_scale(&tris, fmt);
        let lambda_max = tris
            .iter()
            .map(|t| TriWord::new(t, fmt, scale).lambda)
            .fold(0.0, f64::max);
        let tree = DopTree::of(tris, cfg);
        let (children, leaves) = (tree.children(), tree.leaf_tris());
        let levels = Layout::new(cfg).levels;
        let (records, ids, tri_records) = (
            node_records(cfg.layout, levels, &children),
            node_ids(cfg.layout, levels, &children),
            tri_records(cfg.layout, &leaves),
        );
        ObjectImage {
            tree,
            scale,
            tri_format: fmt,
            lambda_max,
            records,
            ids,
            tri_records,
        }
    }

    /// Triangle `t`'s word. Made from the f64 triangle when read, as the host made it
    /// for the memory image: a word per triangle held would be most of a large object's
    /// memory (docs/reference/limits.md).
    pub fn tri(&self, t: u32) -> TriWord {
        TriWord::new(&self.geometry()[t as usize], self.tri_format, self.scale)
    }

    /// Triangles of the object.
    pub fn tri_count(&self) -> usize {
        self.geometry().len()
    }

    /// Every triangle word, by triangle index.
    pub fn tris(&self) -> impl Iterator<Item = TriWord> + '_ {
        (0..self.tri_count() as u32).map(|t| self.tri(t))
    }

    /// The host's f64 triangles, by triangle index: the input the exact oracle judges, and
    /// what the triangle words are made from when read ([`ObjectImage::tri`]).
    pub fn geometry(&self) -> &[Tri] {
        self.tree.tris()
    }

    /// The record holding node `n`.
    pub fn record(&self, n: u32) -> u32 {
        self.records[n as usize]
    }

    /// The record holding triangle `t`'s word.
    pub fn tri_record(&self, t: u32) -> u32 {
        self.tri_records[t as usize]
    }

    /// Node records in the image (the last node's record is the last).
    pub fn node_records(&self) -> u32 {
        self.records.iter().max().map_or(0, |r| r + 1)
    }

    /// What T.CHECK's error words need of A (`self`) and B for
    /// [`HostSetup::new`](crate::golden::host::HostSetup::new).
    pub fn tri_side(&self, b: &ObjectImage) -> TriSide {
        TriSide {
            scale: [self.scale, b.scale],
            lambda_max_b: b.lambda_max,
        }
    }

    /// Bytes of this object's image in memory.
    pub fn bytes(&self, layout: &Layout) -> u64 {
        let [node, tri] = layout.record_bytes();
        self.node_records() as u64 * node + self.tri_count() as u64 * tri
    }
}

/// Record numbers of A's and B's first node and triangle records in the memory image of `a`
/// and `b` (by [`Dst`](crate::chip::layout::Dst), [`image_bases`](crate::chip::layout::image_bases)).
pub fn image_bases(a: &ObjectImage, b: &ObjectImage) -> [u32; 4] {
    crate::chip::layout::image_bases(a.node_records(), a.tri_count() as u32, b.node_records())
}

/// An object's scale S for T.CHECK's certificate: the power of two at or above its largest
/// |coordinate|, kept within the normal range of `fmt` (down to 2^emin, up to 2^-2 of its
/// largest value). The input-error terms are measured against `|x| + |y| + |z| + S`, so
/// that they scale with the objects (docs/explanation/accuracy.md).
pub fn object_scale(tris: &[Tri], fmt: Format) -> f64 {
    let x = tris
        .iter()
        .flatten()
        .map(|p| p.coords.amax())
        .fold(0.0, f64::max);
    let s = if x > 0.0 {
        2f64.powi(x.log2().ceil() as i32)
    } else {
        1.0
    };
    s.clamp(
        fmt.min_positive_normal(),
        2f64.powi(fmt.max_finite().log2().floor() as i32 - 2),
    )
}

/// Values of one object made when read (a node's DOP, a triangle's word), the last ones
/// read held direct-mapped by index in [`HELD_LINES`] lines: software only (the chip reads
/// the record), so that a node or triangle met several times in a row is made once. The
/// lines are allocated at the first read; [`Held::of`] hands them to the next query, whose
/// object may be another.
pub struct Held<T> {
    /// Per line, the object's number and the index held, `object << 32 | n` (`u64::MAX`:
    /// none; indices are below 2^31).
    tags: Vec<u64>,
    values: Vec<T>,
    object: u32,
}

impl<T> Default for Held<T> {
    fn default() -> Self {
        Held {
            tags: vec![],
            values: vec![],
            object: 0,
        }
    }
}

pub const HELD_LINES: usize = 1024;

impl<T: Copy + Default> Held<T> {
    /// The value of `n`, made by `make` unless held.
    #[inline]
    pub fn get(&mut self, n: u32, make: impl FnOnce() -> T) -> &T {
        self.get_in(n, |line| *line = make())
    }

    /// The value of `n`, written into its line by `make` unless held (no copy of a large
    /// value).
    #[inline]
    pub fn get_in(&mut self, n: u32, make: impl FnOnce(&mut T)) -> &T {
        let (i, tag) = self.line(n);
        if self.values.is_empty() {
            self.values = vec![T::default(); HELD_LINES];
            self.tags = vec![u64::MAX; HELD_LINES];
        }
        if self.tags[i] != tag {
            self.tags[i] = tag;
            make(&mut self.values[i]);
        }
        &self.values[i]
    }

    /// Whether the value of `n` is held.
    #[inline]
    pub fn holds(&self, n: u32) -> bool {
        let (i, tag) = self.line(n);
        self.tags.get(i) == Some(&tag)
    }

    /// The line of `n` and the tag it holds while `n`'s value is there.
    #[inline]
    fn line(&self, n: u32) -> (usize, u64) {
        (
            n as usize % HELD_LINES,
            (self.object as u64) << 32 | n as u64,
        )
    }

    /// The lines for the values of the object numbered `object` (its tree's
    /// [`DopTree::id`]): what they held of it stays (its values do not change), any other
    /// object's is not found.
    pub fn of(mut self, object: u32) -> Held<T> {
        self.object = object;
        self
    }
}

/// WSCG'03 §4.3's triangle cache on the aligned side (object A; on B's side the same kind,
/// [`ChipConfig::tri_cache_b`]): direct mapped, triangle word t in line `t mod lines` with
/// its index as the tag (`lines` a power of two, [`ChipConfig::tri_cache`]). One line is the
/// single word held that the RTL chips have on B's side: a word is fetched again only if the
/// previous leaf pair had another triangle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TriCache {
    tags: Vec<Option<u32>>,
}

impl TriCache {
    /// An empty cache; `lines` must pass [`ChipConfig::check`](crate::chip::config::ChipConfig::check).
    pub fn new(lines: u32) -> TriCache {
        TriCache {
            tags: vec![None; lines as usize],
        }
    }

    fn line(&self, t: u32) -> usize {
        t as usize & (self.tags.len() - 1)
    }

    /// Whether triangle word `t` is held.
    pub fn holds(&self, t: u32) -> bool {
        self.tags[self.line(t)] == Some(t)
    }

    /// Word `t` arrived: it replaces its line.
    pub fn fill(&mut self, t: u32) {
        let l = self.line(t);
        self.tags[l] = Some(t);
    }

    /// A use of word `t`: true if it had to be fetched (a miss, which fills the line).
    pub fn fetch(&mut self, t: u32) -> bool {
        let miss = !self.holds(t);
        self.fill(t);
        miss
    }

    /// Every line empty (a query's start).
    pub fn clear(&mut self) {
        self.tags.fill(None);
    }
}

/// The node records held for the DOP unit, per object: the `lines` records used last (least
/// recently used replaced), looked up as D_CNTR's pairs leave the queue, in order. One line
/// is the RTL chips' single record held (a pair repeats the previous pair's word). A record
/// enters its line as its pair issues, so every hit's data is there at its pair's issue: the
/// pairs popped before it have issued before it, and those after it write after it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NodeCache {
    lines: usize,
    /// Most recently used last.
    tags: Vec<u32>,
}

impl NodeCache {
    /// `lines` from [`ChipConfig::node_cache`](crate::chip::config::ChipConfig::node_cache).
    pub fn new(lines: u32) -> NodeCache {
        NodeCache {
            lines: lines as usize,
            tags: Vec::with_capacity(lines as usize),
        }
    }

    /// A use of record `r`: true if it had to be fetched (a miss, which replaces the least
    /// recently used line). A use of the most recent line (most of them: D_CNTR's
    /// consecutive pairs share a node) changes nothing; otherwise the lines from `r`'s (or
    /// the least recent) on move down one and `r` goes last.
    #[inline]
    pub fn fetch(&mut self, r: u32) -> bool {
        if self.tags.last() == Some(&r) {
            return false;
        }
        let hit = self.tags.iter().position(|&t| t == r);
        let from = match hit {
            Some(i) => i,
            None if self.tags.len() == self.lines => 0,
            None => {
                self.tags.push(r);
                return true;
            }
        };
        // (a one-line cache, the default, has nothing to move)
        if from + 1 < self.tags.len() {
            self.tags[from..].rotate_left(1);
        }
        *self.tags.last_mut().expect("a full or hit cache has lines") = r;
        hit.is_none()
    }

    /// Every line empty (a query's start).
    pub fn clear(&mut self) {
        self.tags.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Hand-derived: 0 and 4 share a line of 4 (each evicts the other; the last 0 finds its
    /// line as the third use left it), 1 and 5 another; 8 lines hold all four.
    #[test]
    fn tri_cache_by_hand() {
        let misses = |lines: u32| {
            let mut c = TriCache::new(lines);
            [0, 4, 0, 1, 5, 1, 0].map(|t| c.fetch(t) as u32)
        };
        assert_eq!(misses(1), [1, 1, 1, 1, 1, 1, 1]);
        assert_eq!(misses(4), [1, 1, 1, 1, 1, 1, 0]);
        assert_eq!(misses(8), [1, 1, 0, 1, 1, 0, 0]);
        let check = |tri_cache| {
            crate::chip::config::ChipConfig {
                tri_cache,
                ..Default::default()
            }
            .check()
        };
        assert!(check(128).is_ok() && check(1).is_ok());
        assert!(check(0).is_err() && check(96).is_err() && check(2048).is_err());
    }

    /// Every T.CHECK format a configuration accepts has room for an object scale (a 2-bit
    /// exponent has none: `object_scale` would clamp between 1.0 and 0.5), and the
    /// configurations that have none are refused with what to write.
    #[test]
    fn every_accepted_format_has_an_object_scale() {
        use crate::chip::config::{ChipConfig, Formats};
        let tri: Tri = [
            nalgebra::Point3::new(0.0, 0.0, 0.0),
            nalgebra::Point3::new(3.0, 0.0, 0.0),
            nalgebra::Point3::new(0.0, 1e-3, 0.0),
        ];
        let mut refused = vec![];
        for (e, m) in (2..=9).flat_map(|e| (1..=24).map(move |m| (e, m))) {
            let f = Format::new(e, m).unwrap();
            for format in [
                Formats::from(f),
                Formats {
                    dop: Format::BINARY32,
                    tri: f,
                },
                Formats {
                    dop: f,
                    tri: Format::BINARY32,
                },
            ] {
                match (ChipConfig {
                    format,
                    ..Default::default()
                })
                .check()
                {
                    Ok(()) => assert!(object_scale(&[tri], format.tri) > 0.0),
                    Err(e) => refused.push((format.to_string(), e)),
                }
            }
        }
        assert_eq!(refused.len(), 2 * 24, "{refused:?}");
        assert!(
            refused
                .iter()
                .all(|(f, _)| f.ends_with(|c: char| c.is_ascii_digit())
                    && f.rsplit('/').next().unwrap().starts_with("e2m")),
            "{refused:?}"
        );
        let (_, e) = &refused[0];
        assert!(
            e.contains("at least 3 exponent bits") && e.contains("e3m1"),
            "{e}"
        );
    }

    proptest! {
        /// Another formulation: a use misses iff the last earlier use of a triangle in the
        /// same line (t mod lines) was of another triangle, or there was none.
        #[test]
        fn tri_cache_is_direct_mapped(uses in prop::collection::vec(0u32..64, 0..200), bits in 0u32..7) {
            let lines = 1u32 << bits;
            let mut c = TriCache::new(lines);
            for (i, &t) in uses.iter().enumerate() {
                let last = uses[..i].iter().rev().find(|&&u| u % lines == t % lines);
                prop_assert_eq!(c.fetch(t), last != Some(&t), "use {} of {:?}, {} lines", i, uses, lines);
            }
        }
    }

    /// Hand-derived: with 2 lines, 1 2 1 3 evicts 2 (least recently used), so 2 misses
    /// again and evicts 1; with 1 line, every change of record misses.
    #[test]
    fn node_cache_by_hand() {
        let misses = |lines: u32| {
            let mut c = NodeCache::new(lines);
            [1, 2, 1, 3, 2, 1, 1].map(|r| c.fetch(r) as u32)
        };
        assert_eq!(misses(1), [1, 1, 1, 1, 1, 1, 0]);
        assert_eq!(misses(2), [1, 1, 0, 1, 1, 1, 0]);
        assert_eq!(misses(3), [1, 1, 0, 1, 0, 0, 0]);
    }

    /// Hand-derived: a value held is not made again until its line holds another index, or
    /// the lines serve another object; they serve the first object again as they left it.
    #[test]
    fn held_lines_are_per_object() {
        let mut h = Held::default().of(1);
        assert_eq!((*h.get(5, || 1), *h.get(5, || 2)), (1, 1));
        assert_eq!(
            (*h.get(5 + HELD_LINES as u32, || 3), *h.get(5, || 4)),
            (3, 4)
        );
        let mut h = h.of(2);
        assert_eq!((*h.get(5, || 6), *h.get(5, || 7)), (6, 6));
        let mut h = h.of(1);
        assert_eq!((*h.get(6, || 8), *h.get(5, || 9)), (8, 9));
        let mut h = h.of(1);
        assert_eq!(*h.get(6, || 10), 8);
    }

    #[test]
    fn word_sizes_of_the_default_chip() {
        // binary32, k = 24: 1 + 24 * 32 + 64 = 833 bits; 23 * 32 + 2 = 738 bits.
        let l = Layout::new(&ChipConfig::default());
        assert_eq!((l.node_bits, l.node_bytes()), (833, 105));
        assert_eq!((l.tri_bits, l.tri_bytes()), (738, 93));
    }
}
