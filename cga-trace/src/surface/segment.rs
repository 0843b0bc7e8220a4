//! One segment of a spline surface: the circles `C_t = K⁻¹ X(t) / ‖…‖` of a Bézier curve
//! `X(t) = Σᵢ Bᵢ,d(t) Pᵢ` of degree `d ≤ 3` on the circles' coefficients, and the polynomial
//! whose roots include every `t` where a line meets `C_t`.
//!
//! The elimination behind [`TwoCircles::polynomial`](super::TwoCircles) carries over with
//! `Q(t) = ⟨−X X̃⟩₄` no longer a multiple of one 4-vector. With `S = ⟨−X X̃⟩₀` (degree
//! `2d`), `Q` (degree `2d`) and `q = Q²` (`4d`), the principal root is `K = s + Q/(2s)`,
//! `σ = s²` solving `σ² − Sσ + q/4 = 0`, and `K* X ∝ (2σ − Q) X`, so
//! `C_t ∨ L ∝ 2σA − B` with `A = X ∨ L` (degree `d`) and `B = ⟨Q X⟩₃ ∨ L` (`3d`). Its square
//! `4σ²a − 4σp + b` (`a = A²`, `p = A·B`, `b = B²`) becomes, with `σ² = Sσ − q/4`,
//! `σ D − N` for `D = 4(Sa − p)` (`4d`) and `N = qa − b` (`6d`). So `σ = N/D`, and putting it
//! back into `σ² − Sσ + q/4 = 0`:
//!
//! `R(t) = (N² − S N D + q D²/4) / (t²(1 − t)²)`, degree `12d − 4`
//!
//! The division is exact: the segment's ends are blades, so `Q = O(t)` and `O(1 − t)` there,
//! which makes `N`, `q` and every term of the numerator `O(t²)` and `O((1 − t)²)` (in the
//! scaled basis the factor drops two coefficients at each end). That is 8 for `d = 1`, the
//! degree of [`TwoCircles::polynomial`](super::TwoCircles), and 20 and 32 for quadratic and
//! cubic segments. Its extra roots —
//! the other branch `σ = (S − √(S² − q))/2`, and roots of `D = N = 0` — are rejected by the
//! caller's verification on `C_t` itself. Where `Q ≡ 0` (co-spherical controls) `R ≡ 0` and
//! `a` (degree `2d`) is used. Everything is built as convolutions in the scaled Bernstein
//! basis, in which the products of the controls' coefficients are exact sums.

use super::bernstein::{Bernstein, LARGEST_DEGREE, Scaled, binomial};
use super::family::{Circles, convolve as family_convolve};
use cga_core::{Circle, Dual, InterpolationError, Line, Real, ScalarQuadvector, Vector};
use smallvec::SmallVec;

/// The polynomial's capacity: degree 36, for cubic segments.
const CAPACITY: usize = LARGEST_DEGREE + 1;

/// Coefficient sequences in the scaled Bernstein basis, one blade per power.
type Blades<X> = SmallVec<[X; 10]>;

/// `X`, `⟨Q X⟩₃` (blades), `S` and `q` (coefficients) in the scaled basis.
pub(super) type Parts<'a, T> = (&'a [Circle<T>], &'a [Circle<T>], &'a [T], &'a [T]);

/// One Bézier segment of circles, with its per-surface constants.
#[derive(Clone, Debug)]
pub struct BezierSegment<T: Real> {
    /// `C(d, i) Pᵢ`: `X` in the scaled basis.
    x: Blades<Circle<T>>,
    /// `S(t) = ⟨−X X̃⟩₀`, degree `2d`.
    s: Scaled<T, CAPACITY>,
    /// `q(t) = Q²`, degree `4d`.
    q: Scaled<T, CAPACITY>,
    /// `⟨Q X⟩₃` in the scaled basis, degree `3d`.
    qx: Blades<Circle<T>>,
    /// `Q ≡ 0`: `K` is a scalar and `C_t ∝ X(t)`.
    cospherical: bool,
}

/// `Σ_{i+j=k} f(uᵢ, vⱼ)`: the product of two sequences in the scaled basis.
fn convolve<A: Copy, B: Copy, R: Copy + core::ops::Add<Output = R>>(
    u: &[A],
    v: &[B],
    zero: R,
    f: impl Fn(A, B) -> R,
) -> SmallVec<[R; 40]> {
    let mut out: SmallVec<[R; 40]> = SmallVec::from_elem(zero, u.len() + v.len() - 1);
    for (i, &a) in u.iter().enumerate() {
        for (j, &b) in v.iter().enumerate() {
            out[i + j] = out[i + j] + f(a, b);
        }
    }
    out
}

impl<T: Real> BezierSegment<T> {
    /// The segment of Bézier controls `controls` (2 to 4 circles, normalised and aligned, as
    /// [`cga_core::Spline::segment`] gives them).
    pub fn new(controls: &[Circle<T>]) -> Self {
        let d = controls.len() - 1;
        let x: Blades<Circle<T>> =
            controls.iter().enumerate().map(|(i, c)| c.scale(T::from_f64(binomial(d, i)))).collect();
        let neg = |a: Circle<T>, b: Circle<T>| -ScalarQuadvector::from_storage(&(a * b.reverse()).to_storage());
        let square = convolve(&x, &x, ScalarQuadvector::zero(), neg);
        let s = Scaled::new(&square.iter().map(|k| k.s).collect::<SmallVec<[T; 40]>>());
        let quad: SmallVec<[ScalarQuadvector<T>; 40]> =
            square.iter().map(|k| ScalarQuadvector { s: T::zero(), ..*k }).collect();
        let q = Scaled::new(&convolve(&quad, &quad, T::zero(), |a, b| (a.grade4() * b.grade4()).s));
        let qx: Blades<Circle<T>> =
            convolve(&quad, &x, Circle::zero(), |a, b| Circle::from_storage(&(a.grade4() * b).to_storage()))
                .into_iter()
                .collect();
        let largest = quad.iter().flat_map(|k| k.to_array()).fold(T::zero(), |m, v| m.max(v.abs()));
        BezierSegment { x, s, q, qx, cospherical: largest <= T::epsilon() }
    }
}

/// The largest degree of the sums `circle_at` evaluates: `q`, `4d`.
const WEIGHTS: usize = 13;

/// A scalar the circles of a segment are evaluated in: `T` itself, or dual numbers over it
/// for the slope. Sums of constant blades and coefficients with weights in `Self`: for dual
/// weights the constants are not lifted, which saves a third of the products.
pub(super) trait Weight<T: Real>: Real {
    /// `Σₖ cₖ wₖ`.
    fn blades(c: &[Circle<T>], w: &[Self]) -> Circle<Self>;
    /// `Σₖ cₖ wₖ`.
    fn scalars(c: &[T], w: &[Self]) -> Self;
}

impl<T: Real> Weight<T> for T {
    fn blades(c: &[Circle<T>], w: &[T]) -> Circle<T> {
        c.iter().zip(w).fold(Circle::zero(), |sum, (c, &w)| sum + *c * w)
    }
    fn scalars(c: &[T], w: &[T]) -> T {
        c.iter().zip(w).fold(T::zero(), |sum, (&c, &w)| sum + c * w)
    }
}

impl<T: Real> Weight<T> for Dual<T> {
    fn blades(c: &[Circle<T>], w: &[Dual<T>]) -> Circle<Dual<T>> {
        let re = c.iter().zip(w).fold(Circle::zero(), |sum, (c, w)| sum + *c * w.re);
        let du = c.iter().zip(w).fold(Circle::zero(), |sum, (c, w)| sum + *c * w.du);
        let (re, du) = (re.to_array(), du.to_array());
        Circle::from_array(core::array::from_fn(|k| Dual { re: re[k], du: du[k] }))
    }
    fn scalars(c: &[T], w: &[Dual<T>]) -> Dual<T> {
        let re = c.iter().zip(w).fold(T::zero(), |sum, (&c, w)| sum + c * w.re);
        let du = c.iter().zip(w).fold(T::zero(), |sum, (&c, w)| sum + c * w.du);
        Dual { re, du }
    }
}

/// The scaled Bernstein basis of degree `n` at `t`: `(1 − t)ⁿ⁻ᵏ tᵏ`, `k = 0 … n`; for the
/// degrees a segment evaluates, through loops of constant length (unrolled).
#[inline(always)]
pub(super) fn basis<U: Real>(t: U, n: usize) -> [U; WEIGHTS] {
    match n {
        2 => basis_of::<U, 2>(t),
        3 => basis_of::<U, 3>(t),
        4 => basis_of::<U, 4>(t),
        6 => basis_of::<U, 6>(t),
        8 => basis_of::<U, 8>(t),
        9 => basis_of::<U, 9>(t),
        12 => basis_of::<U, 12>(t),
        _ => basis_any(t, n),
    }
}

/// [`basis`] of degree `N`.
#[inline(always)]
fn basis_of<U: Real, const N: usize>(t: U) -> [U; WEIGHTS] {
    let u = U::one() - t;
    let mut w = [U::one(); WEIGHTS];
    let mut power = U::one();
    for slot in w[1..=N].iter_mut() {
        power = power * t;
        *slot = power;
    }
    let mut other = U::one();
    for slot in w[..N].iter_mut().rev() {
        other = other * u;
        *slot = *slot * other;
    }
    w
}

/// [`basis`] of any degree `n < WEIGHTS`.
fn basis_any<U: Real>(t: U, n: usize) -> [U; WEIGHTS] {
    let u = U::one() - t;
    let mut w = [U::one(); WEIGHTS];
    let mut power = U::one();
    for slot in w.iter_mut().take(n + 1).skip(1) {
        power = power * t;
        *slot = power;
    }
    let mut other = U::one();
    for k in (0..n).rev() {
        other = other * u;
        w[k] = w[k] * other;
    }
    w
}

/// `C_t` in closed form from what the segment precomputes, in any scalar `U` (dual numbers for
/// the slope): `−X X̃ = S + Q` has the principal root `K = s + Q/(2s)`, `σ = s²` the larger
/// root of `σ² − Sσ + q/4 = 0`, and `2s K* X = (2σ − Q) X`, so `C_t ∝ 2σ X − ⟨Q X⟩₃`,
/// normalised: `X` and `⟨Q X⟩₃` are Bézier sums of precomputed blades, `S` and `q = Q²`
/// polynomials. The same circle as the general projector ([`cga_core::project_at`]) to rounding,
/// without its products.
fn circle_at<T: Real, U: Weight<T>>(segment: &BezierSegment<T>, t: U) -> Result<Circle<U>, InterpolationError> {
    let d = segment.x.len() - 1;
    let two_sigma = segment.two_sigma(t)?;
    let singular = InterpolationError::Singular { alpha: t.to_f64() };
    let (x, qx) = (U::blades(&segment.x, &basis(t, d)), U::blades(&segment.qx, &basis(t, 3 * d)));
    (x * two_sigma + qx * (-U::one())).try_normalise().ok_or(singular)
}

impl<T: Real> BezierSegment<T> {
    /// `2σ(t)`, `σ` the larger root of `σ² − Sσ + q/4 = 0`, in any scalar `U` (dual numbers for
    /// the slope): `S + √(S² − q)`, or `q / (S − √(S² − q))` without cancellation when `S < 0`.
    pub(super) fn two_sigma<U: Weight<T>>(&self, t: U) -> Result<U, InterpolationError> {
        let d = self.x.len() - 1;
        let big_s = U::scalars(self.s.coefficients(), &basis(t, 2 * d));
        let q2 = U::scalars(self.q.coefficients(), &basis(t, 4 * d));
        let disc = big_s * big_s - q2;
        if disc < U::zero() || !disc.is_finite() {
            return Err(InterpolationError::NoRealRoot { alpha: t.to_f64(), s: big_s.to_f64(), q2: q2.to_f64() });
        }
        let root = disc.sqrt();
        let two_sigma = if big_s >= U::zero() { big_s + root } else { q2 / (big_s - root) };
        if two_sigma <= U::zero() || !two_sigma.is_finite() {
            return Err(InterpolationError::Singular { alpha: t.to_f64() });
        }
        Ok(two_sigma)
    }

    /// The Bézier degree `d`.
    pub(super) fn degree(&self) -> usize {
        self.x.len() - 1
    }

    /// Whether the controls are co-spherical (`Q ≡ 0`).
    pub(super) fn cospherical(&self) -> bool {
        self.cospherical
    }

    /// `X`, `⟨Q X⟩₃`, `S` and `q` in the scaled basis.
    pub(super) fn parts(&self) -> Parts<'_, T> {
        (&self.x, &self.qx, self.s.coefficients(), self.q.coefficients())
    }
}

impl<T: Real> Circles<T> for BezierSegment<T> {
    type Polynomial = Bernstein<T, CAPACITY>;
    const HIGH_DEGREE: bool = true;

    fn at(&self, t: T) -> Result<Circle<T>, InterpolationError> {
        circle_at(self, t)
    }

    fn at_dual(&self, t: Dual<T>) -> Result<Circle<Dual<T>>, InterpolationError> {
        circle_at(self, t)
    }

    /// `R(t)` of the module docs (degree `12d − 4`), or `a` for
    /// co-spherical controls.
    fn polynomial(&self, line: &Line<T>) -> Self::Polynomial {
        let a_seq: SmallVec<[Vector<T>; 4]> = self.x.iter().map(|c| line.meet_circle(c)).collect();
        if self.cospherical {
            return Scaled::new(&self_convolve(&a_seq, dot)).bernstein();
        }
        let b_seq: SmallVec<[Vector<T>; 10]> = self.qx.iter().map(|c| line.meet_circle(c)).collect();
        // Arrays of the exact lengths for the two degrees a spline makes (the products unroll
        // into registers); sequences of any length otherwise.
        let (s, q) = (self.s.coefficients(), self.q.coefficients());
        let r = match self.x.len() - 1 {
            2 => Scaled::new(&eliminate::<T, 3, 7, 5, 9, 13, 25, 17>(&a_seq, &b_seq, s, q)),
            3 => Scaled::new(&eliminate::<T, 4, 10, 7, 13, 19, 37, 25>(&a_seq, &b_seq, s, q)),
            _ => self.eliminate_any(&a_seq, &b_seq),
        };
        // The ends are blades: Q = O(t) there, so R = O(t²) (and O((1 − t)²)); the factor,
        // exact in exact arithmetic, is divided out, or its rounding would hide roots near
        // the ends from the isolation.
        r.divide_g(2).bernstein()
    }
}

/// `u · v`, the scalar product of two vectors.
fn dot<T: Real>(u: Vector<T>, v: Vector<T>) -> T {
    (u | v).s
}

impl<T: Real> BezierSegment<T> {
    /// [`eliminate`] on sequences of any length (a segment of degree 1).
    fn eliminate_any(&self, a_seq: &[Vector<T>], b_seq: &[Vector<T>]) -> Scaled<T, CAPACITY> {
        let a = Scaled::new(&self_convolve(a_seq, dot));
        let p = Scaled::new(&convolve(a_seq, b_seq, T::zero(), dot));
        let b = Scaled::new(&self_convolve(b_seq, dot));
        let n = self.q.mul(&a).add_scaled(-T::one(), &b);
        let d = self.s.mul(&a).add_scaled(-T::one(), &p).scale(T::from_f64(4.0));
        let r = n.mul(&n.add_scaled(-T::one(), &self.s.mul(&d)));
        r.add_scaled(T::from_f64(0.25), &self.q.mul(&d.square()))
    }
}

/// `t²(1 − t)² R` of the module docs in the scaled basis, from the meets `A = X ∨ L`
/// (`VA = d + 1` blades) and `B = ⟨Q X⟩₃ ∨ L` (`VB = 3d + 1`) and the segment's `S` (`SA = 2d + 1`
/// coefficients) and `q` (`P = 4d + 1`): `N² − S N D + q D²/4 = N (N − S D) + q D²/4`
/// (`R1 = 12d + 1`; `DD = 8d + 1` for `D²`) of [`numerators`], a third fewer products than as
/// written.
#[allow(clippy::many_single_char_names)]
fn eliminate<
    T: Real,
    const VA: usize,
    const VB: usize,
    const SA: usize,
    const P: usize,
    const BB: usize,
    const R1: usize,
    const DD: usize,
>(
    a_seq: &[Vector<T>],
    b_seq: &[Vector<T>],
    s: &[T],
    q: &[T],
) -> [T; R1] {
    let (n, d) = numerators::<T, VA, VB, SA, P, BB>(a_seq, b_seq, s, q);
    let s: [T; SA] = core::array::from_fn(|k| s[k]);
    let q: [T; P] = core::array::from_fn(|k| q[k]);
    let sd: [T; BB] = family_convolve(&s, &d);
    let m: [T; BB] = core::array::from_fn(|k| n[k] - sd[k]);
    let nm: [T; R1] = family_convolve(&n, &m);
    let dd: [T; DD] = family_convolve(&d, &d);
    let qdd: [T; R1] = family_convolve(&q, &dd);
    core::array::from_fn(|k| nm[k] + T::from_f64(0.25) * qdd[k])
}

/// `N = q a − b` (`BB = 6d + 1` coefficients) and `D = 4(S a − p)` (`P = 4d + 1`) in the scaled
/// basis, from the meets `A = X ∨ L` (`VA = d + 1` blades) and `B = ⟨Q X⟩₃ ∨ L`
/// (`VB = 3d + 1`) and the segment's `S` (`SA = 2d + 1`) and `q` (`P`), with `a = A²`,
/// `p = A·B`, `b = B²`: the crossing condition is `σ D − N = 0` (module docs).
#[allow(clippy::many_single_char_names)]
#[inline(always)]
pub(super) fn numerators<
    T: Real,
    const VA: usize,
    const VB: usize,
    const SA: usize,
    const P: usize,
    const BB: usize,
>(
    a_seq: &[Vector<T>],
    b_seq: &[Vector<T>],
    s: &[T],
    q: &[T],
) -> ([T; BB], [T; P]) {
    let a_seq: [Vector<T>; VA] = filled(Vector::zero(), |k| a_seq[k]);
    let b_seq: [Vector<T>; VB] = filled(Vector::zero(), |k| b_seq[k]);
    let p = filled(T::zero(), |k| pairs(&a_seq, &b_seq, k));
    from_products::<T, SA, P, BB>(squares(&a_seq), p, squares(&b_seq), s, q)
}

/// `N = q a − b` and `D = 4(S a − p)` from the products `a`, `p`, `b` of the meets.
#[inline(always)]
fn from_products<T: Real, const SA: usize, const P: usize, const BB: usize>(
    a: [T; SA],
    p: [T; P],
    b: [T; BB],
    s: &[T],
    q: &[T],
) -> ([T; BB], [T; P]) {
    let s: [T; SA] = filled(T::zero(), |k| s[k]);
    let q: [T; P] = filled(T::zero(), |k| q[k]);
    let qa: [T; BB] = family_convolve(&q, &a);
    let n: [T; BB] = filled(T::zero(), |k| qa[k] - b[k]);
    let sa: [T; P] = family_convolve(&s, &a);
    let d: [T; P] = filled(T::zero(), |k| T::from_f64(4.0) * (sa[k] - p[k]));
    (n, d)
}

/// The symmetric bilinear form `β` with `β(x, x) =` [`numerators`]`(x)`: `N` and `D` with `a`,
/// `p`, `b` the products `A₁·A₂`, `½(A₁·B₂ + A₂·B₁)`, `B₁·B₂` of two lines' meets `(A₁, B₁)` and
/// `(A₂, B₂)`. The meets are linear in the line, `X ∨ Σ lⱼEⱼ = Σ lⱼ (X ∨ Eⱼ)`, so `N` and `D`
/// are quadratic forms in its six coefficients: `Σⱼ lⱼ² β(Eⱼ, Eⱼ) + Σ_{j<k} 2 lⱼlₖ β(Eⱼ, Eₖ)`.
#[allow(clippy::many_single_char_names)]
pub(super) fn numerators_between<
    T: Real,
    const VA: usize,
    const VB: usize,
    const SA: usize,
    const P: usize,
    const BB: usize,
>(
    (a1, b1): (&[Vector<T>], &[Vector<T>]),
    (a2, b2): (&[Vector<T>], &[Vector<T>]),
    s: &[T],
    q: &[T],
) -> ([T; BB], [T; P]) {
    let (a1, a2): ([Vector<T>; VA], [Vector<T>; VA]) =
        (filled(Vector::zero(), |k| a1[k]), filled(Vector::zero(), |k| a2[k]));
    let (b1, b2): ([Vector<T>; VB], [Vector<T>; VB]) =
        (filled(Vector::zero(), |k| b1[k]), filled(Vector::zero(), |k| b2[k]));
    let half = T::from_f64(0.5);
    let a = filled(T::zero(), |k| pairs(&a1, &a2, k));
    let p = filled(T::zero(), |k| half * (pairs(&a1, &b2, k) + pairs(&a2, &b1, k)));
    from_products::<T, SA, P, BB>(a, p, filled(T::zero(), |k| pairs(&b1, &b2, k)), s, q)
}

/// `[f(0), …, f(N − 1)]`, written in a loop that inlines (`core::array::from_fn` was left out
/// of line here, a call per element).
#[inline(always)]
pub(super) fn filled<X: Copy, const N: usize>(zero: X, f: impl Fn(usize) -> X) -> [X; N] {
    let mut out = [zero; N];
    for (k, slot) in out.iter_mut().enumerate() {
        *slot = f(k);
    }
    out
}

/// `Σ_{i+j=k} uᵢ · uⱼ` for every `k`, each pair `i < j` formed once.
#[inline(always)]
fn squares<T: Real, const U: usize, const K: usize>(u: &[Vector<T>; U]) -> [T; K] {
    const { assert!(K + 1 == 2 * U, "the square has 2U − 1 coefficients") };
    let mut out = [T::zero(); K];
    let two = T::from_f64(2.0);
    for i in 0..U {
        out[2 * i] = out[2 * i] + dot(u[i], u[i]);
        for j in i + 1..U {
            out[i + j] = out[i + j] + two * dot(u[i], u[j]);
        }
    }
    out
}

/// `Σ_{i+j=k} uᵢ · vⱼ`.
#[inline(always)]
fn pairs<T: Real, const U: usize, const V: usize>(u: &[Vector<T>; U], v: &[Vector<T>; V], k: usize) -> T {
    let mut sum = T::zero();
    for (i, ui) in u.iter().enumerate().take(k + 1) {
        if k - i < V {
            sum = sum + dot(*ui, v[k - i]);
        }
    }
    sum
}

/// `Σ_{i+j=k} f(uᵢ, uⱼ)` for a symmetric `f`: the square of a sequence in the scaled basis,
/// each off-diagonal pair formed once.
fn self_convolve<A: Copy, R: Real>(u: &[A], f: impl Fn(A, A) -> R) -> SmallVec<[R; 40]> {
    let mut out: SmallVec<[R; 40]> = SmallVec::from_elem(R::zero(), 2 * u.len() - 1);
    let two = R::from_f64(2.0);
    for (i, &a) in u.iter().enumerate() {
        out[2 * i] = out[2 * i] + f(a, a);
        for (j, &b) in u.iter().enumerate().skip(i + 1) {
            out[i + j] = out[i + j] + two * f(a, b);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_core::{Interpolable, Joining, Spline, bezier, project_at};

    /// The closed form of `C_t` and its slope are the general projector's on the Bézier sum,
    /// for quadratic and cubic segments of the Fig. 3 circles.
    #[test]
    fn closed_form_circles_are_the_projector_s() {
        let circles = [
            ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0),
            ([1.2, 0.0, 1.8], [0.4, 0.0, 1.0], 0.9),
            ([-0.3, 0.3, 3.6], [-0.4, 0.2, 1.0], 1.7),
            ([0.4, 0.0, 5.6], [0.0, 0.3, 1.0], 0.8),
        ];
        let circles: Vec<Circle> =
            circles.iter().map(|&(c, n, r)| Circle::from_centre_normal_radius(c, n, r).unwrap()).collect();
        for joining in [Joining::Quadratic, Joining::Cubic, Joining::CATMULL_ROM] {
            let used =
                if joining == Joining::Quadratic { vec![circles[0], circles[1], circles[3]] } else { circles.clone() };
            let spline = Spline::new(&used, joining).unwrap();
            for j in 0..spline.segments() {
                let controls = spline.segment(j);
                let segment = BezierSegment::new(controls);
                for k in 0..=64 {
                    let t = f64::from(k) / 64.0;
                    let want = project_at(bezier(controls, t), t).unwrap().to_array();
                    let got = segment.at(t).unwrap().to_array();
                    let off = want.iter().zip(got).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
                    assert!(off < 1e-12, "{joining:?} segment {j}, t = {t}: {off:e}");
                    // The slope against the projector's on dual numbers.
                    let lifted: Vec<Circle<Dual<f64>>> = controls.iter().map(|c| c.lift()).collect();
                    let want = project_at(bezier(&lifted, Dual::variable(t)), Dual::variable(t)).unwrap().to_array();
                    let dual = segment.at_dual(Dual::variable(t)).unwrap().to_array();
                    let off = dual.iter().zip(&want).map(|(d, w)| (d.du - w.du).abs()).fold(0.0, f64::max);
                    let size = want.iter().fold(1.0f64, |m, w| m.max(w.du.abs()));
                    assert!(off < 1e-12 * size, "{joining:?} segment {j}, t = {t}: slope off by {off:e} of {size}");
                }
            }
        }
    }
}
