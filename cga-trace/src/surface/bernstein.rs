//! Polynomials in the Bernstein basis on [0, 1] — of degree ≤ 8 for the surface between two
//! circles, ≤ 36 for a cubic spline segment (`N`, the capacity, is a type parameter so the
//! common case keeps its small arrays) — and real-root isolation by subdivision.
//!
//! `p(t) = Σₖ cₖ C(n, k) (1 − t)ⁿ⁻ᵏ tᵏ`. The basis is the well-conditioned one on an
//! interval (Farouki–Rajan): coefficients bound the polynomial (convex hull), the number of
//! sign changes among them bounds the number of roots (Descartes' rule), and de Casteljau's
//! algorithm splits an interval without loss. Roots are isolated by splitting until an
//! interval's coefficients change sign at most once, then refined by Newton steps kept
//! inside the bracket — no companion-matrix eigenvalues.

use super::newton::{Stop, safeguarded};
use cga_core::Real;
use smallvec::SmallVec;

/// The largest degree of the two-circle polynomial (the default capacity is one more).
pub const MAX_DEGREE: usize = 8;

/// The largest degree any polynomial here may have: `12 d` for Bézier segments of degree
/// `d ≤ 3`.
pub const LARGEST_DEGREE: usize = 36;

/// How closely (in the interval's own parameter) an extremum that splits a pair of roots is
/// placed: moving it by δ changes `p` there by `p'' δ²/2`, far below the touch level at 1e-9,
/// and the roots on either side are refined on `p` itself.
const EXTREMUM: f64 = 1e-9;

/// A polynomial of degree `degree < N` in the Bernstein basis on [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bernstein<T, const N: usize = { MAX_DEGREE + 1 }> {
    /// `c₀ … c_degree`; entries above the degree are unused.
    pub c: [T; N],
    /// The degree.
    pub degree: usize,
}

/// Pascal's triangle to row 36 (exact in f64: the largest, `C(36, 18)`, is below 2⁵³).
const BINOMIALS: [[f64; LARGEST_DEGREE + 1]; LARGEST_DEGREE + 1] = {
    const M: usize = LARGEST_DEGREE + 1;
    let mut t = [[0.0; M]; M];
    let mut n = 0;
    while n < M {
        t[n][0] = 1.0;
        let mut k = 1;
        while k <= n {
            t[n][k] = t[n - 1][k - 1] + if k < n { t[n - 1][k] } else { 0.0 };
            k += 1;
        }
        n += 1;
    }
    t
};

/// `1 / C(n, k)`, rounded once (the same bits as dividing at run time).
const INVERSE_BINOMIALS: [[f64; LARGEST_DEGREE + 1]; LARGEST_DEGREE + 1] = {
    const M: usize = LARGEST_DEGREE + 1;
    let mut t = [[0.0; M]; M];
    let mut n = 0;
    while n < M {
        let mut k = 0;
        while k <= n {
            t[n][k] = 1.0 / BINOMIALS[n][k];
            k += 1;
        }
        n += 1;
    }
    t
};

/// `C(n, k)` for `n ≤ 36`.
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    BINOMIALS[n][k]
}

/// `1 / C(n, k)` for `n ≤ 36`.
pub(crate) fn inverse_binomial(n: usize, k: usize) -> f64 {
    INVERSE_BINOMIALS[n][k]
}

/// Roots found in one call: rarely more than a few.
pub type Roots<T> = SmallVec<[T; 8]>;

/// A polynomial in the scaled Bernstein (homogeneous) basis `(1 − t)ⁿ⁻ᵏ tᵏ`, coefficients
/// `C(n, k) cₖ`: products are plain convolutions, so polynomials are built in this form and
/// converted once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaled<T, const N: usize = { MAX_DEGREE + 1 }> {
    c: [T; N],
    degree: usize,
}

impl<T: Real, const N: usize> Scaled<T, N> {
    /// The polynomial with scaled coefficients `c` (`C(n, k) cₖ` of the Bernstein ones).
    pub fn new(c: &[T]) -> Self {
        assert!(!c.is_empty() && c.len() <= N, "degree below the capacity");
        let mut all = [T::zero(); N];
        all[..c.len()].copy_from_slice(c);
        Scaled { c: all, degree: c.len() - 1 }
    }

    /// The degree.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The scaled coefficients in use, `C(n, k) cₖ`.
    pub fn coefficients(&self) -> &[T] {
        &self.c[..=self.degree]
    }

    /// `(1 − t) a + t b`.
    pub fn linear(a: T, b: T) -> Self {
        let mut c = [T::zero(); N];
        (c[0], c[1]) = (a, b);
        Scaled { c, degree: 1 }
    }

    /// `a (1 − t)² + b (1 − t) t + c t²`.
    pub fn quadratic(a: T, b: T, c: T) -> Self {
        let mut all = [T::zero(); N];
        (all[0], all[1], all[2]) = (a, b, c);
        Scaled { c: all, degree: 2 }
    }

    /// `p q`.
    pub fn mul(&self, q: &Self) -> Self {
        let degree = self.degree + q.degree;
        assert!(degree < N, "product degree above the capacity");
        let mut c = [T::zero(); N];
        for i in 0..=self.degree {
            for j in 0..=q.degree {
                c[i + j] = c[i + j] + self.c[i] * q.c[j];
            }
        }
        Scaled { c, degree }
    }

    /// `p²`, each off-diagonal product formed once.
    pub fn square(&self) -> Self {
        let degree = 2 * self.degree;
        assert!(degree < N, "product degree above the capacity");
        let mut c = [T::zero(); N];
        let two = T::from_f64(2.0);
        for i in 0..=self.degree {
            c[2 * i] = c[2 * i] + self.c[i] * self.c[i];
            for j in i + 1..=self.degree {
                c[i + j] = c[i + j] + two * (self.c[i] * self.c[j]);
            }
        }
        Scaled { c, degree }
    }

    /// `p + s q`, of equal degrees.
    pub fn add_scaled(&self, s: T, q: &Self) -> Self {
        assert_eq!(self.degree, q.degree, "equal degrees");
        let mut c = self.c;
        for (a, b) in c.iter_mut().zip(q.c) {
            *a = *a + s * b;
        }
        Scaled { c, degree: self.degree }
    }

    /// `s p`.
    pub fn scale(&self, s: T) -> Self {
        Scaled { c: self.c.map(|x| x * s), degree: self.degree }
    }

    /// `(1 − t) t p`: in this basis a shift of the coefficients, no arithmetic.
    pub fn times_g(&self) -> Self {
        assert!(self.degree + 2 < N, "product degree above the capacity");
        let mut c = [T::zero(); N];
        c[1..self.degree + 2].copy_from_slice(&self.c[..=self.degree]);
        Scaled { c, degree: self.degree + 2 }
    }

    /// `p / (t (1 − t))ᵏ` for a polynomial with that factor: its first and last `k`
    /// coefficients in this basis are zero (to rounding) and are dropped (the inverse of
    /// [`Scaled::times_g`]).
    pub fn divide_g(&self, k: usize) -> Self {
        assert!(self.degree >= 2 * k, "degree at least 2k");
        Scaled::new(&self.c[k..=self.degree - k])
    }

    /// In the Bernstein basis: `cₖ / C(n, k)`.
    pub fn bernstein(&self) -> Bernstein<T, N> {
        let mut c = self.c;
        let inverse = &INVERSE_BINOMIALS[self.degree][..=self.degree];
        for (x, &w) in c.iter_mut().zip(inverse) {
            *x = *x * T::from_f64(w);
        }
        Bernstein { c, degree: self.degree }
    }
}

impl<T: Real, const N: usize> Bernstein<T, N> {
    /// The polynomial with Bernstein coefficients `c`.
    pub fn new(c: &[T]) -> Self {
        assert!(!c.is_empty() && c.len() <= N, "degree below the capacity");
        let mut all = [T::zero(); N];
        all[..c.len()].copy_from_slice(c);
        Bernstein { c: all, degree: c.len() - 1 }
    }

    /// The coefficients in use.
    pub fn coefficients(&self) -> &[T] {
        &self.c[..=self.degree]
    }

    /// `p(t)`: [`Bernstein::eval_with_slope`]'s value, the same operations, without the
    /// slope's chain (Newton on a spline segment's `F` evaluates `N` and `D` so at every step).
    #[inline]
    pub fn eval(&self, t: T) -> T {
        let (n, c) = (self.degree, self.coefficients());
        match t {
            t if t == T::zero() => c[0],
            t if t == T::one() => c[n],
            t if t > T::from_f64(0.5) => horner_value(n, |j| c[n - j], (T::one() - t) / t, t),
            t => horner_value(n, |j| c[j], t / (T::one() - t), T::one() - t),
        }
    }

    /// `(p(t), p'(t))` by Horner's rule from the nearer end (Schumaker–Volk): for `t ≤ ½`,
    /// `p(t) = (1 − t)ⁿ Σ C(n, k) cₖ sᵏ` with `s = t / (1 − t) ≤ 1`, and for `t > ½` the same
    /// from `cₙ` with `s = (1 − t) / t`; `p' = n Σ (cₖ₊₁ − cₖ) Bₖⁿ⁻¹(t)` the same way. Its
    /// error bound is de Casteljau's, `O(n ε) Σ |cₖ| Bₖ(t)`, at `O(n)` operations instead of
    /// `O(n²)` — two independent chains of `n` multiply-adds (root refinement runs on it).
    pub fn eval_with_slope(&self, t: T) -> (T, T) {
        let (n, c) = (self.degree, self.coefficients());
        if n == 0 {
            return (c[0], T::zero());
        }
        let u = T::one() - t;
        // One loop per end (no branch per term, no copy of the coefficients).
        if t > T::from_f64(0.5) {
            let (value, slope) = horner(n, |j| c[n - j], u / t, t);
            (value, -slope)
        } else {
            horner(n, |j| c[j], t / u, u)
        }
    }

    /// `Σ |cₖ| Bₖ(t)`: the scale of `p(t)`'s rounding (de Casteljau's and Horner's error bound
    /// is `O(n ε)` times it), by Horner's rule from the nearer end as in
    /// [`Bernstein::eval_with_slope`].
    pub fn magnitude(&self, t: T) -> T {
        let (n, c) = (self.degree, self.coefficients());
        let u = T::one() - t;
        if t > T::from_f64(0.5) {
            horner_value(n, |j| c[n - j].abs(), u / t, t)
        } else {
            horner_value(n, |j| c[j].abs(), t / u, u)
        }
    }

    /// The same polynomial on `[0, s]` and `[s, 1]`, each reparametrised to [0, 1].
    pub fn split(&self, s: T) -> (Self, Self) {
        let n = self.degree;
        let (mut left, mut right) = (self.c, self.c);
        let mut b = self.c;
        let u = T::one() - s;
        left[0] = b[0];
        right[n] = b[n];
        for r in 1..=n {
            // Row r of de Casteljau's triangle from row r − 1, in place; slicing the row first
            // lets the compiler drop the bounds checks of the inner loop.
            let m = n - r + 1;
            let row = &mut b[..=m];
            for k in 0..m {
                row[k] = u * row[k] + s * row[k + 1];
            }
            left[r] = row[0];
            right[n - r] = row[m - 1];
        }
        (Bernstein { c: left, degree: n }, Bernstein { c: right, degree: n })
    }

    /// The same polynomial on `[lo, hi] ⊆ [0, 1]`, reparametrised to [0, 1].
    pub fn restrict(&self, lo: T, hi: T) -> Self {
        let right = if lo > T::zero() { self.split(lo).1 } else { *self };
        if hi >= T::one() { right } else { right.split((hi - lo) / (T::one() - lo)).0 }
    }

    /// Sign changes among the nonzero coefficients: an upper bound on the number of roots in
    /// (0, 1), exact when it is 0 or 1.
    pub fn sign_changes(&self) -> usize {
        let mut last = T::zero();
        let mut changes = 0;
        for &c in self.coefficients() {
            if c != T::zero() {
                if (c > T::zero()) != (last > T::zero()) && last != T::zero() {
                    changes += 1;
                }
                last = c;
            }
        }
        changes
    }

    /// Every real root in `[lo, hi]` (parameters of the original polynomial, `self` being
    /// its restriction to that interval), in increasing order, each refined to `tolerance`
    /// in α (to rounding level when it is 0).
    ///
    /// An interval whose coefficients change sign once holds one root. Where they change
    /// more often, or come within `touch` (relative to the largest) of zero, the slope `p'`
    /// decides: monotone, at most one root; one extremum `e`, found by refining `p'`, then
    /// a root on each side where `p(e)` has crossed zero — a pair of close roots — and a
    /// touch at `e` where `|p(e)| ≤ touch` (a double root: rounding may hide its sign change
    /// or split it in two);
    /// otherwise the interval is split.
    pub fn roots_in(&self, lo: T, hi: T, tolerance: T, touch: T, out: &mut Roots<T>) {
        self.roots_above(lo, hi, tolerance, touch * self.largest(), out);
    }

    /// The largest coefficient's magnitude: `|p| ≤` it on [0, 1].
    pub fn largest(&self) -> T {
        self.coefficients().iter().fold(T::zero(), |m, c| m.max(c.abs()))
    }

    /// [`Bernstein::roots_in`] with the touch level `floor` given in the polynomial's own units:
    /// for a restriction, its whole polynomial's (`touch` times the whole's largest
    /// coefficient), whose rounding the restriction carries however short the interval.
    pub fn roots_above(&self, lo: T, hi: T, tolerance: T, floor: T, out: &mut Roots<T>) {
        if self.c[0].abs() <= floor {
            out.push(lo);
        }
        self.isolate(lo, hi, tolerance, floor, 0, out);
        let last = self.c[self.degree];
        if last != T::zero() && last.abs() <= floor {
            out.push(hi);
        }
    }

    fn isolate(&self, lo: T, hi: T, tolerance: T, floor: T, depth: usize, out: &mut Roots<T>) {
        let n = self.degree;
        let changes = self.sign_changes();
        let near_zero = self.coefficients().iter().any(|c| c.abs() <= floor);
        let (first, last) = (self.c[0], self.c[n]);
        let opposite = first != T::zero() && last != T::zero() && (first > T::zero()) != (last > T::zero());
        let to_alpha = |t: T| lo + (hi - lo) * t;
        let tol = tolerance / (hi - lo);
        if changes == 0 && !near_zero {
            // No root in (lo, hi].
        } else if changes == 1 && opposite {
            out.push(to_alpha(self.refine(T::zero(), T::one(), tol)));
        } else {
            let slope = self.derivative();
            match slope.sign_changes() {
                0 if opposite => out.push(to_alpha(self.refine(T::zero(), T::one(), tol))),
                0 => {}
                1 if n >= 2 => {
                    let e = slope.refine(T::zero(), T::one(), T::from_f64(EXTREMUM));
                    let pe = self.eval(e);
                    let crossed = |end: T| pe != T::zero() && end != T::zero() && (pe > T::zero()) != (end > T::zero());
                    let (left, right) = (crossed(first), crossed(last));
                    if left || right {
                        // Each root's Newton iteration starts where the control polygon of
                        // its side crosses zero (the chord from the extremum, where p is
                        // flat, starts it far off).
                        let (below, above) = self.split(e);
                        if left {
                            let start = below.polygon_crossing().map(|r| e * r);
                            out.push(to_alpha(self.refine_from(T::zero(), e, tol, start)));
                        }
                        if right {
                            let start = above.polygon_crossing().map(|r| e + (T::one() - e) * r);
                            out.push(to_alpha(self.refine_from(e, T::one(), tol, start)));
                        }
                    }
                    // A double root that rounding split into two, or lifted off zero.
                    if pe.abs() <= floor {
                        out.push(to_alpha(e));
                    }
                }
                _ if hi - lo <= tolerance.max(T::epsilon() * T::from_f64(4.0)) || depth >= 60 => {
                    if changes > 0 {
                        out.push(T::from_f64(0.5) * (lo + hi));
                    }
                    return;
                }
                _ => {
                    let mid = T::from_f64(0.5) * (lo + hi);
                    let (left, right) = self.split(T::from_f64(0.5));
                    left.isolate(lo, mid, tolerance, floor, depth + 1, out);
                    right.isolate(mid, hi, tolerance, floor, depth + 1, out);
                    return;
                }
            }
        }
        if last == T::zero() {
            out.push(hi);
        }
    }

    /// `p'`, degree `n − 1`: coefficients `n (cₖ₊₁ − cₖ)`.
    pub fn derivative(&self) -> Self {
        let n = self.degree;
        let mut d = [T::zero(); N];
        for (k, slot) in d.iter_mut().enumerate().take(n) {
            *slot = T::from_f64(n as f64) * (self.c[k + 1] - self.c[k]);
        }
        Bernstein { c: d, degree: n.saturating_sub(1) }
    }

    /// The single root in `(a, b) ⊆ [0, 1]`, where `p(a)`, `p(b)` differ in sign: Newton
    /// steps with the exact slope, replaced by bisection whenever one leaves the bracket,
    /// until the bracket or the step is below `tolerance` (rounding level at least).
    pub(super) fn refine(&self, a: T, b: T, tolerance: T) -> T {
        // Over the whole interval the control polygon's crossing lies within O(1/n²) of the
        // root.
        let start = if a == T::zero() && b == T::one() { self.polygon_crossing() } else { None };
        self.refine_from(a, b, tolerance, start)
    }

    /// [`Bernstein::refine`] from `start` where given (inside the bracket), else where the
    /// chord crosses zero.
    fn refine_from(&self, a: T, b: T, tolerance: T, start: Option<T>) -> T {
        let (pa, pb) = (self.eval(a), self.eval(b));
        let positive_at_a = pa > T::zero();
        // Below this, |p| is rounding noise (de Casteljau is backward stable: the error is a
        // few ulps of the largest coefficient): further steps only wander.
        let largest = self.coefficients().iter().fold(T::zero(), |m, c| m.max(c.abs()));
        let noise = T::from_f64(16.0) * T::epsilon() * largest;
        let tolerance = tolerance.max(T::epsilon() * T::from_f64(4.0));
        let start = start.unwrap_or_else(|| a + (b - a) * pa / (pa - pb));
        let stop = Stop { noise, absolute: tolerance, relative: T::zero(), iterations: 100 };
        let noise_at = |t: T| T::from_f64(16.0) * T::epsilon() * self.magnitude(t);
        safeguarded(|t| Some(self.eval_with_slope(t)), noise_at, (a, b), positive_at_a, start, stop)
    }

    /// Where the control polygon `(k/n, cₖ)` first crosses zero.
    fn polygon_crossing(&self) -> Option<T> {
        let n = self.degree;
        (0..n).find_map(|k| {
            let (c0, c1) = (self.c[k], self.c[k + 1]);
            ((c0 > T::zero()) != (c1 > T::zero()) && c0 != c1)
                .then(|| (T::from_f64(k as f64) + c0 / (c0 - c1)) / T::from_f64(n as f64))
        })
    }
}

/// `(p, p')` of the Bernstein coefficients `e(0) … e(n)` (degree `n ≥ 1`, read from the
/// nearer end) at the point where `s = t/(1 − t)` (or its inverse) and `a = 1 − t` (or `t`):
/// `p = aⁿ Σ C(n, j) eⱼ sʲ`, `p' = n aⁿ⁻¹ Σ C(n − 1, j) (eⱼ₊₁ − eⱼ) sʲ`, two independent chains
/// of Horner's rule.
#[inline(always)]
fn horner<T: Real>(n: usize, e: impl Fn(usize) -> T, s: T, a: T) -> (T, T) {
    let (rows, lower) = (&BINOMIALS[n][..n], &BINOMIALS[n - 1][..n]);
    let mut value = e(n) * s + T::from_f64(rows[n - 1]) * e(n - 1);
    let mut slope = e(n) - e(n - 1);
    let mut power = T::one();
    for j in (0..n - 1).rev() {
        value = value * s + T::from_f64(rows[j]) * e(j);
        slope = slope * s + T::from_f64(lower[j]) * (e(j + 1) - e(j));
        power = power * a;
    }
    // power = aⁿ⁻¹.
    (value * (power * a), T::from_f64(n as f64) * slope * power)
}

/// `p = aⁿ Σ C(n, j) eⱼ sʲ` alone, as [`horner`].
#[inline(always)]
fn horner_value<T: Real>(n: usize, e: impl Fn(usize) -> T, s: T, a: T) -> T {
    let rows = &BINOMIALS[n];
    let (mut value, mut power) = (e(n), T::one());
    for j in (0..n).rev() {
        value = value * s + T::from_f64(rows[j]) * e(j);
        power = power * a;
    }
    value * power
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bernstein coefficients of `Π (t − rᵢ)` built factor by factor.
    fn from_roots(roots: &[f64]) -> Bernstein<f64> {
        from_roots_in(roots)
    }

    /// [`from_roots`] in a polynomial of capacity `N`.
    fn from_roots_in<const N: usize>(roots: &[f64]) -> Bernstein<f64, N> {
        let one = Scaled { c: [1.0; N], degree: 0 };
        roots.iter().fold(one, |p, &r| p.mul(&Scaled::linear(-r, 1.0 - r))).bernstein()
    }

    /// `p + e` (a constant adds to every Bernstein coefficient).
    fn plus(mut p: Bernstein<f64>, e: f64) -> Bernstein<f64> {
        p.c.iter_mut().take(p.degree + 1).for_each(|c| *c += e);
        p
    }

    #[test]
    fn eval_matches_the_product_form() {
        let roots = [0.1, 0.35, 0.5, 0.9, 1.7, -0.4];
        let p = from_roots(&roots);
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let want: f64 = roots.iter().map(|r| t - r).product();
            assert!((p.eval(t) - want).abs() < 1e-14, "t = {t}");
            let h = 1e-6;
            let fd = (p.eval(t + h) - p.eval(t - h)) / (2.0 * h);
            assert!((p.eval_with_slope(t).1 - fd).abs() < 1e-7);
        }
    }

    #[test]
    fn times_g_is_the_product_with_t_one_minus_t() {
        let p: Scaled<f64> = Scaled::quadratic(0.3, -1.2, 2.5).mul(&Scaled::linear(0.7, -0.4));
        let g = Scaled::quadratic(0.0, 1.0, 0.0);
        assert_eq!(p.times_g(), p.mul(&g));
    }

    #[test]
    fn split_and_restrict_reparametrise() {
        let p = from_roots(&[0.2, 0.6, 0.65, 1.3]);
        let (l, r) = p.split(0.3);
        let q = p.restrict(0.25, 0.75);
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!((l.eval(t) - p.eval(0.3 * t)).abs() < 1e-15);
            assert!((r.eval(t) - p.eval(0.3 + 0.7 * t)).abs() < 1e-15);
            assert!((q.eval(t) - p.eval(0.25 + 0.5 * t)).abs() < 1e-15);
        }
    }

    #[test]
    fn finds_every_root_in_the_interval_and_no_other() {
        let roots = [0.0, 0.2, 0.2 + 1e-7, 0.5, 0.77, 1.0, 1.2, -0.1];
        let p = from_roots(&roots);
        let mut out = Roots::new();
        p.roots_in(0.0, 1.0, 0.0, 1e-12, &mut out);
        // Roots 1e-7 apart are conditioned ~1e7 times worse than the others; the extremum
        // between them comes within the touch level, so it is a candidate too.
        let want = [(0.0, 1e-12), (0.2, 1e-9), (0.2 + 1e-7, 1e-9), (0.5, 1e-12), (0.77, 1e-12), (1.0, 1e-12)];
        for (root, tol) in want {
            assert!(out.iter().any(|r| (r - root).abs() < tol), "{root} missing from {out:?}");
        }
        assert!(out.iter().all(|r| want.iter().any(|w| (r - w.0).abs() < 1e-7)), "{out:?}");
        assert!(out.len() <= 7, "{out:?}");
    }

    #[test]
    fn a_double_root_is_found_once_within_tolerance() {
        let p = from_roots(&[0.4, 0.4, 0.9]);
        let mut out = Roots::new();
        p.roots_in(0.0, 1.0, 1e-9, 1e-12, &mut out);
        assert!(!out.is_empty() && out.iter().all(|r| (r - 0.4).abs() < 1e-6 || (r - 0.9).abs() < 1e-12), "{out:?}");
        let positive = plus(from_roots(&[0.4, 0.4]), 1e-3);
        let mut none = Roots::new();
        positive.roots_in(0.0, 1.0, 1e-9, 1e-12, &mut none);
        assert!(none.is_empty(), "{none:?}");
        // A double root that rounding has lifted just above zero is still found, accurately.
        let lifted = plus(from_roots(&[0.3, 0.3, 1.5]), 1e-17);
        let mut touch = Roots::new();
        lifted.roots_in(0.0, 1.0, 0.0, 1e-12, &mut touch);
        assert!(touch.len() == 1 && (touch[0] - 0.3).abs() < 1e-12, "{touch:?}");
    }
    /// A root where the coefficients are many decades below the largest (a segment's end, as
    /// fig3b's rim at 1280×960 has them: 1e-5 against 3e7) is placed to the rounding of its
    /// own neighbourhood, not to that of the largest coefficient — which let Newton stop
    /// 1e-6 off in α. For every degree of a segment's polynomial (8, 20, 32), at either end.
    #[test]
    fn a_root_among_tiny_coefficients_is_placed_to_its_own_rounding() {
        for degree in [8, 20, 32] {
            for k in 0..400 {
                let r = 1e-4 + 0.05 * f64::from(k) / 400.0;
                for (root, far) in [(r, -0.08), (1.0 - r, 1.08)] {
                    // (t − root) times a factor growing by many decades towards the other end.
                    let mut roots = vec![far; degree - 1];
                    roots.push(root);
                    let p = from_roots_in::<{ LARGEST_DEGREE + 1 }>(&roots);
                    let mut out = Roots::new();
                    p.roots_in(0.0, 1.0, 0.0, 1e-12, &mut out);
                    let found = out.iter().copied().min_by(|a, b| (a - root).abs().total_cmp(&(b - root).abs()));
                    let error = found.map_or(f64::INFINITY, |f| (f - root).abs());
                    assert!(error <= 1e-13, "degree {degree}, root {root}: {out:?}");
                }
            }
        }
    }
}
