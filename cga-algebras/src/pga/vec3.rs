//! Euclidean 3-vectors, for the read-backs and the distances.

use crate::Real;

pub(crate) fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `|a|`, scaled by the largest component so that it neither overflows nor underflows where
/// the components do not.
pub(crate) fn norm<T: Real>(a: [T; 3]) -> T {
    let m = a[0].abs().max(a[1].abs()).max(a[2].abs());
    if m == T::zero() || !m.is_finite() {
        return m;
    }
    let s = a.map(|c| c / m);
    m * dot(s, s).sqrt()
}

pub(crate) fn sub<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn scale<T: Real>(a: [T; 3], s: T) -> [T; 3] {
    a.map(|c| c * s)
}
