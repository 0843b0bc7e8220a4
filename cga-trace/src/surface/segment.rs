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
use super::family::Circles;
use cga_core::{
    Circle, Dual, Interpolable, InterpolationError, Line, Real, ScalarQuadvector, Vector, bezier, project_at,
};
use smallvec::SmallVec;

/// The polynomial's capacity: degree 36, for cubic segments.
const CAPACITY: usize = LARGEST_DEGREE + 1;

/// Coefficient sequences in the scaled Bernstein basis, one blade per power.
type Blades<X> = SmallVec<[X; 10]>;

/// One Bézier segment of circles, with its per-surface constants.
#[derive(Clone, Debug)]
pub struct BezierSegment<T: Real> {
    /// The Bézier controls `Pᵢ` (2 to 4).
    controls: SmallVec<[Circle<T>; 4]>,
    /// The same over dual numbers.
    lifted: SmallVec<[Circle<Dual<T>>; 4]>,
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
        BezierSegment {
            controls: controls.iter().copied().collect(),
            lifted: controls.iter().map(|c| c.lift()).collect(),
            x,
            s,
            q,
            qx,
            cospherical: largest <= T::epsilon(),
        }
    }
}

impl<T: Real> Circles<T> for BezierSegment<T> {
    type Polynomial = Bernstein<T, CAPACITY>;
    const REFINE: bool = true;

    fn at(&self, t: T) -> Result<Circle<T>, InterpolationError> {
        project_at(bezier(&self.controls, t), t)
    }

    fn at_dual(&self, t: Dual<T>) -> Result<Circle<Dual<T>>, InterpolationError> {
        project_at(bezier(&self.lifted, t), t)
    }

    /// `R(t)` of the module docs (degree `12d − 4`), or `a` for
    /// co-spherical controls.
    fn polynomial(&self, line: &Line<T>) -> Self::Polynomial {
        let dot = |u: Vector<T>, v: Vector<T>| (u | v).s;
        let a_seq: SmallVec<[Vector<T>; 4]> = self.x.iter().map(|c| line.meet_circle(c)).collect();
        let a = Scaled::new(&convolve(&a_seq, &a_seq, T::zero(), dot));
        if self.cospherical {
            return a.bernstein();
        }
        let b_seq: SmallVec<[Vector<T>; 10]> = self.qx.iter().map(|c| line.meet_circle(c)).collect();
        let p = Scaled::new(&convolve(&a_seq, &b_seq, T::zero(), dot));
        let b = Scaled::new(&convolve(&b_seq, &b_seq, T::zero(), dot));
        let n = self.q.mul(&a).add_scaled(-T::one(), &b);
        let d = self.s.mul(&a).add_scaled(-T::one(), &p).scale(T::from_f64(4.0));
        let r = n.mul(&n).add_scaled(-T::one(), &self.s.mul(&n).mul(&d));
        // The ends are blades: Q = O(t) there, so R = O(t²) (and O((1 − t)²)); the factor,
        // exact in exact arithmetic, is divided out, or its rounding would hide roots near
        // the ends from the isolation.
        r.add_scaled(T::from_f64(0.25), &self.q.mul(&d).mul(&d)).divide_g(2).bernstein()
    }
}
