//! Euclidean 3-vectors as `[T; 3]`, generic over the scalar like everything else here
//! (glam's `DVec3` converts with `to_array`/`from_array`).

use crate::Real;

/// A Euclidean point or vector.
pub type E3<T = f64> = [T; 3];

/// `a + b`.
#[inline(always)]
pub fn add<T: Real>(a: E3<T>, b: E3<T>) -> E3<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a − b`.
#[inline(always)]
pub fn sub<T: Real>(a: E3<T>, b: E3<T>) -> E3<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s a`.
#[inline(always)]
pub fn scale<T: Real>(a: E3<T>, s: T) -> E3<T> {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `a · b`.
#[inline(always)]
pub fn dot<T: Real>(a: E3<T>, b: E3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
#[inline(always)]
pub fn cross<T: Real>(a: E3<T>, b: E3<T>) -> E3<T> {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The mirror image of direction `d` in a plane of unit normal `n`: `d − 2(d·n)n`.
#[inline(always)]
pub fn reflect<T: Real>(d: E3<T>, n: E3<T>) -> E3<T> {
    sub(d, scale(n, T::from_f64(2.0) * dot(d, n)))
}

/// `|a|`, without overflow or underflow: `√(a·a)` where the squares keep every digit (`a·a`
/// finite and at least the smallest normal number over ε), otherwise `2^e √((a/2^e)·(a/2^e))`
/// with `2^e` the binade of the largest component (exact scalings, so the two agree bit for
/// bit wherever both apply: lanes of a packet take either path alike).
#[inline(always)]
pub fn norm<T: Real>(a: E3<T>) -> T {
    let s = dot(a, a);
    if s.is_finite() && s >= T::min_positive() / T::epsilon() { s.sqrt() } else { norm_rescaled(a) }
}

/// [`norm`] of a vector whose squares leave the normal range: out of line, so that the
/// common case stays a dot product and a square root wherever it is inlined.
#[cold]
#[inline(never)]
fn norm_rescaled<T: Real>(a: E3<T>) -> T {
    let largest = a.iter().fold(T::zero(), |m, x| m.max(x.abs()));
    let k = largest.binade();
    let b = a.map(|x| x / k);
    dot(b, b).sqrt() * k
}

/// `a / |a|`, or `None` for a zero or non-finite vector. Vectors whose length overflows or
/// underflows its reciprocal (components beyond about 1e308 or below 1e-308 in f64) are
/// rescaled by their largest component first.
pub fn unit<T: Real>(a: E3<T>) -> Option<E3<T>> {
    let inv = T::one() / norm(a);
    if inv.is_finite() && inv > T::zero() {
        return Some(scale(a, inv));
    }
    let largest = a.iter().fold(T::zero(), |m, x| m.max(x.abs()));
    let b = scale(a, T::one() / largest);
    let inv = T::one() / norm(b);
    (largest.is_finite() && largest > T::zero() && inv.is_finite() && inv > T::zero()).then(|| scale(b, inv))
}

/// The differences `points[k] − points[0]` scaled by a power of two that brings the largest
/// near 1, and that power: Euclidean constructions of degree three and four in the
/// differences (circumcentres, volumes) then neither overflow nor underflow for points of
/// any size f64 holds, and scaling back is exact.
pub fn rescaled_differences<T: Real, const N: usize>(points: [E3<T>; N]) -> ([E3<T>; N], T) {
    let d = points.map(|p| sub(p, points[0]));
    let largest = d.iter().flatten().fold(T::zero(), |m, x| m.max(x.abs()));
    let k = largest.binade();
    (d.map(|v| v.map(|x| x / k)), k)
}

/// The largest `|a_i|` over several vectors, at least 1: the scale tolerances are relative to.
pub fn magnitude<T: Real>(points: &[E3<T>]) -> T {
    points.iter().flatten().fold(T::one(), |m, x| if x.abs() > m { x.abs() } else { m })
}

/// A tolerance `64 ε s` for quantities of size `s`.
pub fn tolerance<T: Real>(s: T) -> T {
    T::from_f64(64.0) * T::epsilon() * s
}

/// Some unit vector perpendicular to unit `n`.
pub fn perpendicular<T: Real>(n: E3<T>) -> E3<T> {
    // Cross with the axis least aligned with n, so the result is never tiny.
    let a = n.map(|x| x.abs());
    let axis = if a[0] <= a[1] && a[0] <= a[2] {
        [T::one(), T::zero(), T::zero()]
    } else if a[1] <= a[2] {
        [T::zero(), T::one(), T::zero()]
    } else {
        [T::zero(), T::zero(), T::one()]
    };
    let p = cross(n, axis);
    scale(p, T::one() / norm(p))
}

/// The distance of `x` from the circle of centre `c`, unit normal `n` and radius `r`, in
/// radii: `√(h² + (ρ − r)²) / r`, `h` the height of `x` above the circle's plane and `ρ` its
/// distance from the axis.
pub fn circle_distance<T: Real>(x: E3<T>, (c, n, r): (E3<T>, E3<T>, T)) -> T {
    let d = sub(x, c);
    let along = dot(d, n);
    let across = norm(sub(d, scale(n, along)));
    (along * along + (across - r) * (across - r)).sqrt() / r
}
