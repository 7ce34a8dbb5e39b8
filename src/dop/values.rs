//! Values of one number format, held in the narrowest host float that holds each exactly:
//! f32 for every format of at most 8 exponent and 23 fraction bits (binary32 and the
//! reduced formats: their normals and subnormals are all f32s), f64 for the rest. The
//! host's DOP trees and triangle words are most of a query's memory (docs/reference/limits.md);
//! a value read back is the f64 it was stored as, bit for bit.

use crate::format::Format;

#[derive(Clone, Debug, PartialEq)]
pub enum Values {
    F32(Vec<f32>),
    F64(Vec<f64>),
}

impl Values {
    /// Empty, room for `capacity` values of `fmt`.
    pub fn new(fmt: Format, capacity: usize) -> Values {
        if fmt.exp_bits() <= 8 && fmt.frac_bits() <= 23 {
            Values::F32(Vec::with_capacity(capacity))
        } else {
            Values::F64(Vec::with_capacity(capacity))
        }
    }

    /// Appends `x`, a value of the format (so exact in the store's float).
    pub fn push(&mut self, x: f64) {
        match self {
            Values::F32(v) => {
                debug_assert!(x.is_nan() || x as f32 as f64 == x, "{x} is not an f32");
                v.push(x as f32)
            }
            Values::F64(v) => v.push(x),
        }
    }

    #[inline]
    pub fn get(&self, i: usize) -> f64 {
        match self {
            Values::F32(v) => v[i] as f64,
            Values::F64(v) => v[i],
        }
    }

    /// Values `at..at + out.len()` into `out`.
    #[inline]
    pub fn read(&self, at: usize, out: &mut [f64]) {
        let n = out.len();
        match self {
            Values::F32(v) => out
                .iter_mut()
                .zip(&v[at..at + n])
                .for_each(|(o, &x)| *o = x as f64),
            Values::F64(v) => out.copy_from_slice(&v[at..at + n]),
        }
    }

    /// [`prefetch`](super::prefetch) of values `at..`.
    #[inline]
    pub fn prefetch(&self, at: usize) {
        match self {
            Values::F32(v) => super::prefetch(v.as_ptr().wrapping_add(at)),
            Values::F64(v) => super::prefetch(v.as_ptr().wrapping_add(at)),
        }
    }

    /// Replaces value `i` by `x`, a value of the format.
    pub fn set(&mut self, i: usize, x: f64) {
        match self {
            Values::F32(v) => v[i] = x as f32,
            Values::F64(v) => v[i] = x,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// binary32's extremes (largest, smallest subnormal, infinity) come back bit for bit;
    /// a format with 9 exponent bits is held in f64.
    #[test]
    fn values_come_back_exactly() {
        let f = Format::BINARY32;
        let xs = [
            f.max_finite(),
            f.min_positive_subnormal(),
            -f.min_positive_normal(),
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.1f32 as f64,
        ];
        let mut v = Values::new(f, xs.len());
        xs.iter().for_each(|&x| v.push(x));
        assert!(matches!(v, Values::F32(_)));
        assert!(xs
            .iter()
            .enumerate()
            .all(|(i, &x)| v.get(i).to_bits() == x.to_bits()));
        let wide = Format::new(9, 23).unwrap();
        let mut w = Values::new(wide, 1);
        w.push(wide.min_positive_subnormal());
        assert_eq!(
            (matches!(w, Values::F64(_)), w.get(0)),
            (true, wide.min_positive_subnormal())
        );
    }
}
