//! The family of circles `C_α` and the roots of `f(α) = (C_α ∨ L)²` for one line, generic
//! over the scalar (the renderer uses `f64`; the error report also runs `f32`).
//!
//! Three ways to find the roots, all returning candidate α that the caller verifies:
//! uniform sampling of `f` (the paper's baseline), sampling of `(f, f')` with the exact
//! slope (dual numbers) and safeguarded Newton, and the degree-8 polynomial (see
//! [`Family::polynomial`]) whose roots are isolated in the Bernstein basis.

use super::bernstein::{Bernstein, Roots, Scaled};
use super::newton::{Stop, safeguarded};
use cga_core::euclid::{E3, dot, norm, scale, sub};
use cga_core::{Circle, Dual, Interpolable, InterpolationError, Line, Pair, Real, ScalarQuadvector, Vector, down};
use smallvec::SmallVec;

/// `|f|` below this fraction of its sampled scale counts as zero: a tangential touch.
const TOUCH: f64 = 1e-12;
/// A root within this Newton step (in α) of α = 0 or 1 is looked for with `f` itself: rounding
/// decides which side of the end it falls, and verification whether the ray meets the edge.
const END_STEP: f64 = 1e-6;
/// How far from a candidate (in α) a touch of `f` is looked for when the kept crossing is
/// refined ([`Family::nearest`]).
const TOUCH_REACH: f64 = 1e-4;
/// `|f|` at or below this after Newton is a simple root placed to rounding (`f` is
/// dimensionless: the meet of a normalised circle and line).
const SIMPLE: f64 = 1e-13;
/// The α tolerance to which a polynomial's roots are refined where the crossing kept is then
/// placed on `f` itself ([`Finder::polishes`]): Newton's last, confirming step on the
/// polynomial is saved, and the Taylor step from `f`'s own slope ([`Family::nearest`]) takes
/// its place.
const CANDIDATE: f64 = 1e-10;

/// A one-parameter family of circles `C_α`, `α ∈ [0, 1]`: between two circles
/// ([`TwoCircles`]) or along one segment of a spline ([`BezierSegment`](super::BezierSegment)). It gives the circles
/// (on dual numbers too, for exact slopes) and a polynomial whose roots in [0, 1] include every
/// α at which a line meets `C_α`; [`Family`] finds and verifies the roots for any of them.
pub trait Circles<T: Real>: Clone + core::fmt::Debug {
    /// The polynomial's type (its capacity follows its degree).
    type Polynomial: RootPolynomial<T>;
    /// `C_α`.
    fn at(&self, alpha: T) -> Result<Circle<T>, InterpolationError>;
    /// `C_α` on dual numbers: `(C_α, dC_α/dα)` in one.
    fn at_dual(&self, alpha: Dual<T>) -> Result<Circle<Dual<T>>, InterpolationError>;
    /// A polynomial in α whose roots in [0, 1] include every root of `f(α) = (C_α ∨ L)²`.
    fn polynomial(&self, line: &Line<T>) -> Self::Polynomial;
    /// [`Circles::polynomial`] on `[lo, hi]`, reparametrised to [0, 1] (by default restricted
    /// by de Casteljau's algorithm).
    fn polynomial_on(&self, line: &Line<T>, lo: T, hi: T) -> Self::Polynomial {
        let poly = self.polynomial(line);
        if lo > T::zero() || hi < T::one() { poly.restrict(lo, hi) } else { poly }
    }
    /// The curvature of the surface at `x` on `C_α` ([`cga_core::curvature()`]), where the
    /// family knows it.
    fn curvature(&self, _alpha: T, _x: E3<T>) -> Option<cga_core::Curvature<T>> {
        None
    }
    /// Whether the polynomial costs more to build than to restrict (degree 20 or 32, a spline
    /// segment's): then it is built once over [0, 1] and restricted to each α-interval the
    /// cells leave ([`Family::roots_on`]), rather than built on each.
    const HIGH_DEGREE: bool = false;
}

/// What the root finder needs of a polynomial in the Bernstein basis, of any capacity.
pub trait RootPolynomial<T: Real>: Copy {
    /// The coefficients in use.
    fn coefficients(&self) -> &[T];
    /// The same polynomial on `[lo, hi]`, reparametrised to [0, 1].
    fn restrict(&self, lo: T, hi: T) -> Self;
    /// Every real root in `[lo, hi]`, touches where `|p| ≤ floor` ([`Bernstein::roots_above`]).
    fn roots_above(&self, lo: T, hi: T, tolerance: T, floor: T, out: &mut Roots<T>);
}

impl<T: Real, const N: usize> RootPolynomial<T> for Bernstein<T, N> {
    fn coefficients(&self) -> &[T] {
        Bernstein::coefficients(self)
    }
    fn restrict(&self, lo: T, hi: T) -> Self {
        Bernstein::restrict(self, lo, hi)
    }
    fn roots_above(&self, lo: T, hi: T, tolerance: T, floor: T, out: &mut Roots<T>) {
        Bernstein::roots_above(self, lo, hi, tolerance, floor, out)
    }
}

/// The circles `C_α = K⁻¹ X_α / ‖…‖`, `X_α = (1 − α) C1 + α C2`, with what the polynomial
/// formulation precomputes once per surface.
#[derive(Clone, Debug)]
pub struct TwoCircles<T: Real> {
    /// Normalised, aligned end circles.
    pub pair: Pair<Circle<T>>,
    /// `S(α) = ⟨−X X̃⟩₀ = S₀ (1 − α)² + S₁ α(1 − α) + S₂ α²`: `[S₀, S₁, S₂]`.
    s: [T; 3],
    /// `w = W²` for the constant 4-vector `W = ⟨−(C1 C̃2 + C2 C̃1)⟩₄`; `⟨−X X̃⟩₄ = α(1−α) W`.
    w: T,
    /// `⟨W C1⟩₃`, `⟨W C2⟩₃`.
    wc: [Circle<T>; 2],
    /// `C1, C2, ⟨W C1⟩₃, ⟨W C2⟩₃` over dual numbers, for the exact `f'`.
    lifted: [Circle<Dual<T>>; 4],
    /// `W = 0`: the circles are co-spherical, `K` is a scalar and `C_α ∝ X_α`.
    cospherical: bool,
}

/// The roots of `f(α) = (C_α ∨ L)²` for the circles of `C`, found by the method a [`Finder`]
/// names and verified on the circles themselves.
#[derive(Clone, Debug)]
pub struct Family<T: Real, C = TwoCircles<T>> {
    /// The circles.
    pub circles: C,
    _scalar: core::marker::PhantomData<T>,
}

/// Which root finder [`Family::roots`] runs over an α-interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Finder {
    /// `n` uniform samples of `f` per unit of α; sign changes bisected, local minima of `|f|`
    /// searched by golden section.
    Samples(usize),
    /// `n` uniform samples of `(f, f')` per interval; Newton; close root pairs split at the
    /// extremum of `f`.
    Slope(usize),
    /// Bernstein roots of the degree-8 polynomial, refined to this α tolerance.
    Polynomial(f64),
}

impl Finder {
    /// Whether candidates that fail verification are polished on `f` and tried again (see
    /// [`Family::nearest`]): for the polynomial refined to rounding level.
    pub fn polishes(self) -> bool {
        self == Finder::Polynomial(0.0)
    }
}

impl<T: Real> TwoCircles<T> {
    /// The family between normalised, aligned circles.
    pub fn new(pair: Pair<Circle<T>>) -> Self {
        let (c1, c2) = (pair.c1, pair.c2);
        let cross = -ScalarQuadvector::from_storage(&(c1 * c2.reverse() + c2 * c1.reverse()).to_storage());
        let s = [c1.neg_square().s, cross.s, c2.neg_square().s];
        let w4 = cross.grade4();
        let w = (w4 * w4).s;
        let wc = [Circle::from_storage(&(w4 * c1).to_storage()), Circle::from_storage(&(w4 * c2).to_storage())];
        let lifted = [c1.lift(), c2.lift(), wc[0].lift(), wc[1].lift()];
        let largest = w4.to_array().iter().fold(T::zero(), |m, x| m.max(x.abs()));
        TwoCircles { pair, s, w, wc, lifted, cospherical: largest <= T::epsilon() }
    }
}

/// `C_α` in closed form from what [`TwoCircles`] precomputes, in any scalar `U` (dual numbers
/// for the slope): `−X X̃ = S(α) + g W` with `g = α(1 − α)`, whose principal root is
/// `K = a + μW`, `2a² = S + √(S² − g² w)`, `μ = g / 2a` ([`ScalarQuadvector::try_sqrt`]'s
/// branches); then `C_α ∝ K* X = a X − μ ⟨W X⟩₃`, normalised, and `⟨W X⟩₃` is linear in α.
/// The same circle as the general projector ([`Pair::at`]) to rounding, without its products
/// — which were a sixth of a surface ray.
fn circle_at<U: Real>(
    [c1, c2, w1, w2]: [&Circle<U>; 4],
    s: [U; 3],
    w: U,
    alpha: U,
) -> Result<Circle<U>, InterpolationError> {
    let beta = U::one() - alpha;
    let g = alpha * beta;
    let big_s = s[0] * beta * beta + s[1] * g + s[2] * alpha * alpha;
    let q2 = g * g * w;
    let disc = big_s * big_s - q2;
    if disc < U::zero() || !disc.is_finite() {
        return Err(InterpolationError::NoRealRoot { alpha: alpha.to_f64(), s: big_s.to_f64(), q2: q2.to_f64() });
    }
    let singular = InterpolationError::Singular { alpha: alpha.to_f64() };
    let root = disc.sqrt();
    let plus = if big_s >= U::zero() { big_s + root } else { q2 / (big_s - root) };
    let a = (plus / U::from_f64(2.0)).sqrt();
    let mu = g / (a + a);
    if !(plus > U::zero() && mu.is_finite()) {
        return Err(singular);
    }
    let x = *c1 * beta + *c2 * alpha;
    let wx = *w1 * beta + *w2 * alpha;
    (x * a + wx * (-mu)).try_normalise().ok_or(singular)
}

impl<T: Real> Circles<T> for TwoCircles<T> {
    type Polynomial = Bernstein<T>;

    fn curvature(&self, alpha: T, x: E3<T>) -> Option<cga_core::Curvature<T>> {
        self.pair.curvature(alpha, x).ok()
    }

    fn at(&self, alpha: T) -> Result<Circle<T>, InterpolationError> {
        let [c1, c2] = [&self.pair.c1, &self.pair.c2];
        circle_at([c1, c2, &self.wc[0], &self.wc[1]], self.s, self.w, alpha)
    }

    fn at_dual(&self, alpha: Dual<T>) -> Result<Circle<Dual<T>>, InterpolationError> {
        let [c1, c2, w1, w2] = &self.lifted;
        circle_at([c1, c2, w1, w2], self.s.map(Dual::constant), Dual::constant(self.w), alpha)
    }

    /// A polynomial in α whose roots in [0, 1] include every root of `f`.
    ///
    /// With `K = s + μW` (`s² + μ²W² = S`, `2sμ = α(1−α) =: g`), `C_α ∝ K* X = (s − μW) X`,
    /// so `C_α ∨ L ∝ sA − μB` for `A = X ∨ L`, `B = ⟨W X⟩₃ ∨ L`, both linear in α. Its
    /// square times `σ = s²` is `σ²a − gσp + g²b/4` (`a = A²`, `p = A·B`, `b = B²`); using
    /// `σ² = Sσ − wg²/4` it vanishes when `σ P₁ + g²h/4 = 0`, `P₁ = Sa − gp`, `h = b − wa`.
    /// The principal root has `σ = (S + √(S² − wg²))/2`; isolating the radical and squaring
    /// leaves a factor `g²` (the ends, handled by `a` there), and dividing it out gives
    ///
    /// `R(α) = w P₁² + S P₁ h + g² h² / 4`, degree 8
    ///
    /// (the paper's polynomial has degree 12). Its extra roots — the other branch of the
    /// root, and `b = 0` at the ends — are rejected by the caller's verification. For
    /// co-spherical circles (`W = 0`) `R` vanishes identically and `a` (degree 2) is used.
    fn polynomial(&self, line: &Line<T>) -> Bernstein<T> {
        self.polynomial_on(line, T::zero(), T::one())
    }

    /// The same polynomial built on `[lo, hi]` directly: its quadratic factors (and
    /// `g = α(1 − α)`) restricted there by their blossoms, then multiplied out — cheaper than
    /// two de Casteljau splits of the degree-8 result, and no less accurate.
    fn polynomial_on(&self, line: &Line<T>, lo: T, hi: T) -> Bernstein<T> {
        let a_end = [line.meet_circle(&self.pair.c1), line.meet_circle(&self.pair.c2)];
        let product = |u: &[Vector<T>; 2], v: &[Vector<T>; 2]| {
            let dot = |x: &Vector<T>, y: &Vector<T>| (*x | *y).s;
            [dot(&u[0], &v[0]), dot(&u[0], &v[1]) + dot(&u[1], &v[0]), dot(&u[1], &v[1])]
        };
        let whole = lo == T::zero() && hi == T::one();
        let on = |q: [T; 3]| if whole { q } else { restrict_quadratic(q, lo, hi) };
        let a = on(product(&a_end, &a_end));
        if self.cospherical {
            return Scaled::<T>::new(&a).bernstein();
        }
        let b_end = [line.meet_circle(&self.wc[0]), line.meet_circle(&self.wc[1])];
        let (p, b) = (on(product(&a_end, &b_end)), on(product(&b_end, &b_end)));
        let (s, g) = (on(self.s), on([T::zero(), T::one(), T::zero()]));
        // Scaled-basis coefficients in arrays of their exact lengths: the products unroll
        // into registers.
        let (sa, gp): ([T; 5], [T; 5]) = (convolve(&s, &a), convolve(&g, &p));
        let p1: [T; 5] = core::array::from_fn(|k| sa[k] - gp[k]);
        let h: [T; 3] = core::array::from_fn(|k| b[k] + -self.w * a[k]);
        let p1p1: [T; 9] = convolve(&p1, &p1);
        let sp1: [T; 7] = convolve(&s, &p1);
        let sp1h: [T; 9] = convolve(&sp1, &h);
        let (gg, hh): ([T; 5], [T; 5]) = (convolve(&g, &g), convolve(&h, &h));
        let gghh: [T; 9] = convolve(&gg, &hh);
        let quarter = T::from_f64(0.25);
        let r: [T; 9] = core::array::from_fn(|k| (p1p1[k] * self.w + sp1h[k]) + quarter * gghh[k]);
        Scaled::<T>::new(&r).bernstein()
    }
}

/// A quadratic in the scaled Bernstein basis (`q₀ (1 − α)² + q₁ α(1 − α) + q₂ α²`) on
/// `[lo, hi]`, reparametrised to [0, 1]: its blossom at `(lo, lo)`, `(lo, hi)`, `(hi, hi)`.
fn restrict_quadratic<T: Real>(q: [T; 3], lo: T, hi: T) -> [T; 3] {
    let half = T::from_f64(0.5);
    let blossom = |u: T, v: T| {
        let (u1, v1) = (T::one() - u, T::one() - v);
        q[0] * u1 * v1 + half * q[1] * (u1 * v + u * v1) + q[2] * u * v
    };
    [blossom(lo, lo), T::from_f64(2.0) * blossom(lo, hi), blossom(hi, hi)]
}

/// `x y` for polynomials in the scaled Bernstein basis: a convolution, `C = A + B − 1`
/// coefficients, as `Σⱼ yⱼ (x shifted by j)` over the shorter factor `y`.
///
/// The longer factor is read from a zero-padded copy, so that every pass adds a whole
/// product `c[0..C]` in place: the sum `c[i..i + B] += xᵢ y` instead made each pass read
/// what the one before had just stored one slot over, and a load that partly overlaps a
/// store cannot take its value from the store buffer (a stall per pass; it was the hottest
/// instruction of a spline ray).
#[inline(always)]
pub(super) fn convolve<T: Real, const A: usize, const B: usize, const C: usize>(x: &[T; A], y: &[T; B]) -> [T; C] {
    const { assert!(C + 1 == A + B, "the product has A + B − 1 coefficients") };
    if A < B {
        return convolve(y, x);
    }
    // `x` with B − 1 zeros on each side; C + B − 1 ≤ PADDED for the degrees here (A ≤ 25).
    const PADDED: usize = 64;
    const { assert!(A + 2 * B <= PADDED + 2, "within the padded copy") };
    let mut padded = [T::zero(); PADDED];
    padded[B - 1..B - 1 + A].copy_from_slice(x);
    let mut c = [T::zero(); C];
    for (j, &yj) in y.iter().enumerate() {
        let shifted = &padded[B - 1 - j..B - 1 - j + C];
        for (slot, &v) in c.iter_mut().zip(shifted) {
            *slot = *slot + yj * v;
        }
    }
    c
}

impl<T: Real> Family<T> {
    /// The family between normalised, aligned circles.
    pub fn new(pair: Pair<Circle<T>>) -> Self {
        Family::of(TwoCircles::new(pair))
    }

    /// The end circles.
    pub fn pair(&self) -> &Pair<Circle<T>> {
        &self.circles.pair
    }

    /// The same family in another scalar type (through `f64`).
    pub fn cast<U: Real>(&self) -> Family<U> {
        let convert = |c: &Circle<T>| Circle::from_array(c.to_array().map(|x| U::from_f64(x.to_f64())));
        Family::new(Pair { c1: convert(&self.pair().c1), c2: convert(&self.pair().c2) })
    }

    /// The polynomial of [`TwoCircles::polynomial`] (degree 8).
    pub fn polynomial(&self, line: &Line<T>) -> Bernstein<T> {
        self.circles.polynomial(line)
    }
}

impl<T: Real, C: Circles<T>> Family<T, C> {
    /// The root finders over `circles`.
    pub fn of(circles: C) -> Self {
        Family { circles, _scalar: core::marker::PhantomData }
    }

    /// `C_α`.
    pub fn at(&self, alpha: T) -> Result<Circle<T>, InterpolationError> {
        self.circles.at(alpha)
    }

    /// `f(α) = (C_α ∨ L)²`; `None` where the interpolation fails.
    pub fn f(&self, line: &Line<T>, alpha: T) -> Option<T> {
        let c = self.circles.at(alpha).ok()?;
        Some(line.meet_circle(&c).norm_squared())
    }

    /// `(f, f')` at α, exact: the interpolation and meet run on dual numbers.
    pub fn f_and_slope(&self, line: &Line<Dual<T>>, alpha: T) -> Option<(T, T)> {
        let c = self.circles.at_dual(Dual::variable(alpha)).ok()?;
        let f = line.meet_circle(&c).norm_squared();
        Some((f.re, f.du))
    }

    /// Candidate α in `[lo, hi]` by `finder`, appended to `out` in increasing order.
    pub fn roots(&self, line: &Line<T>, finder: Finder, lo: f64, hi: f64, out: &mut Roots<T>) {
        let (lo, hi) = (T::from_f64(lo), T::from_f64(hi));
        match finder {
            Finder::Samples(n) => self.sampled(line, lo, hi, n.max(2), out),
            Finder::Slope(n) => self.sampled_with_slope(&line.lift(), lo, hi, n.max(2), out),
            Finder::Polynomial(tolerance) => {
                let restricted = self.circles.polynomial_on(line, lo, hi);
                let scale = largest(restricted.coefficients());
                self.polynomial_roots(line, &restricted, (lo, hi), scale, tolerance, out);
            }
        }
    }

    /// The polynomial's candidate α on each of `intervals` (increasing, disjoint, within
    /// [0, 1]): the polynomial built once over [0, 1], restricted to each interval by de
    /// Casteljau's algorithm, and its roots there isolated — for a spline segment, whose
    /// polynomial of degree 20 or 32 costs more to build than to restrict, and which the cells
    /// leave a few short intervals of.
    pub fn roots_on(
        &self,
        line: &Line<T>,
        tolerance: f64,
        intervals: impl IntoIterator<Item = (f64, f64)>,
        out: &mut Roots<T>,
    ) {
        // Built at the first interval: a ray the cells leave none costs nothing.
        let mut whole = None;
        for (lo, hi) in intervals {
            let (whole, scale) = *whole.get_or_insert_with(|| {
                let p = self.circles.polynomial(line);
                (p, largest(p.coefficients()))
            });
            let (lo, hi) = (T::from_f64(lo), T::from_f64(hi));
            let restricted = if lo > T::zero() || hi < T::one() { whole.restrict(lo, hi) } else { whole };
            self.polynomial_roots(line, &restricted, (lo, hi), scale, tolerance, out);
        }
    }

    /// The candidate α of `restricted`, the polynomial on `[lo, hi]` reparametrised to [0, 1]:
    /// its roots there, touches where it comes within [`TOUCH`] `scale` of zero (`scale` the
    /// largest coefficient of the polynomial it was restricted from, whose rounding it
    /// carries: relative to its own, a touch found on a wide interval was lost on a short
    /// one), and roots within rounding of α = 0 or 1 placed by `f` itself. (The
    /// crossing finally kept is placed on `f` itself, [`Family::nearest`]: refining every root
    /// of a spline segment's polynomial up front cost a fifth of its rays' time for nothing.)
    fn polynomial_roots(
        &self,
        line: &Line<T>,
        restricted: &C::Polynomial,
        (lo, hi): (T, T),
        scale: T,
        tolerance: f64,
        out: &mut Roots<T>,
    ) {
        // A root within rounding of α = 0 or 1 (a ray through an end circle) can fall just
        // outside [0, 1] in R; a short Newton step from the end tells, and f itself then
        // places the root. (Slopes in α: the restricted parameter runs 1/(hi − lo) times
        // faster.)
        let c = restricted.coefficients();
        let n = T::from_f64((c.len() - 1) as f64) / (hi - lo);
        let near = |value: T, slope: T| value.abs() <= T::from_f64(END_STEP) * (n * slope).abs();
        let (first, last) = (c[0], c[c.len() - 1]);
        let start_at_zero = lo == T::zero() && c.len() > 1 && near(first, c[1] - first);
        let start_at_one = hi == T::one() && c.len() > 1 && near(last, last - c[c.len() - 2]);
        let tolerance = if Finder::Polynomial(tolerance).polishes() { CANDIDATE } else { tolerance };
        restricted.roots_above(lo, hi, T::from_f64(tolerance), T::from_f64(TOUCH) * scale, out);
        for (near_end, end) in [(start_at_zero, T::zero()), (start_at_one, T::one())] {
            // Kept only if it stays by the end: a polish that wanders off converges (slowly,
            // if to a touch) on a root the polynomial reports itself.
            let polished = if near_end { self.polish(&line.lift(), end) } else { continue };
            if (polished - end).abs() <= T::from_f64(END_STEP) {
                out.push(polished);
            }
        }
    }

    /// Every α in `[lo, hi]` where `f` changes sign or `|f|` has a local minimum reaching
    /// rounding level, from `n + 1` samples; sign changes bisected, minima golden-sectioned.
    fn sampled(&self, line: &Line<T>, lo: T, hi: T, n: usize, out: &mut Roots<T>) {
        let at = |k: usize| lo + (hi - lo) * T::from_f64(k as f64 / n as f64);
        let mut scale = T::zero();
        let mut touches: SmallVec<[(T, T); 4]> = SmallVec::new();
        let (mut prev, mut cur) = (None, self.f(line, lo));
        for k in 0..=n {
            let next = if k < n { self.f(line, at(k + 1)) } else { None };
            if let Some(fk) = cur {
                scale = scale.max(fk.abs());
                if fk == T::zero() {
                    out.push(at(k));
                } else {
                    if let Some(fn_) = next
                        && fn_ != T::zero()
                        && (fk > T::zero()) != (fn_ > T::zero())
                    {
                        out.push(self.bisect(line, at(k), at(k + 1), fk));
                    }
                    // A local minimum of |f| (the ends included) without a sign change.
                    let no_lower =
                        |v: Option<T>| v.is_none_or(|v| v.abs() >= fk.abs() && (v > T::zero()) == (fk > T::zero()));
                    if no_lower(prev) && no_lower(next) {
                        let alpha = self.minimise_abs(line, at(k.saturating_sub(1)), at((k + 1).min(n)));
                        if let Some(f) = self.f(line, alpha) {
                            touches.push((alpha, f.abs()));
                        }
                    }
                }
            }
            (prev, cur) = (cur, next);
        }
        // A touch is real only where |f| reaches rounding level: a near miss has a small but
        // clearly nonzero minimum.
        out.extend(touches.into_iter().filter(|t| t.1 <= T::from_f64(TOUCH) * scale).map(|t| t.0));
    }

    /// The root of `f` in `[lo, hi]`, where `f(lo) = f_lo` and `f(hi)` differ in sign.
    fn bisect(&self, line: &Line<T>, mut lo: T, mut hi: T, mut f_lo: T) -> T {
        let half = T::from_f64(0.5);
        for _ in 0..64 {
            let mid = half * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            match self.f(line, mid) {
                Some(fm) if fm == T::zero() => return mid,
                Some(fm) if (fm > T::zero()) == (f_lo > T::zero()) => {
                    lo = mid;
                    f_lo = fm;
                }
                _ => hi = mid,
            }
        }
        half * (lo + hi)
    }

    /// Every root of `f` in `[lo, hi]` from `n + 1` samples of `(f, f')`: sign changes of `f`
    /// are refined by Newton; where `f` keeps its sign but `f'` turns towards zero between
    /// two samples, the extremum is found by bisection on `f'`, and if `f` crosses zero
    /// there both roots are bracketed (a pair of roots closer than the sample spacing), or
    /// if it only reaches zero, the touch is kept.
    fn sampled_with_slope(&self, line: &Line<Dual<T>>, lo: T, hi: T, n: usize, out: &mut Roots<T>) {
        let at = |k: usize| lo + (hi - lo) * T::from_f64(k as f64 / n as f64);
        let mut scale = T::zero();
        let mut touches: SmallVec<[(T, T); 4]> = SmallVec::new();
        let mut cur = self.f_and_slope(line, lo);
        for k in 0..=n {
            let next = if k < n { self.f_and_slope(line, at(k + 1)) } else { None };
            let (Some((fk, dk)), pair) = (cur, next) else {
                cur = next;
                continue;
            };
            scale = scale.max(fk.abs());
            cur = next;
            if fk == T::zero() {
                out.push(at(k));
                continue;
            }
            if k == 0 || k == n {
                // A ray through an end circle: a touch there, or a root within a short
                // Newton step of the end, which f then places (it may lie just outside).
                if fk.abs() <= T::from_f64(END_STEP) * dk.abs() {
                    out.push(self.polish(line, at(k)));
                } else {
                    touches.push((at(k), fk.abs()));
                }
            }
            let Some((fn_, dn)) = pair else { continue };
            let positive = fk > T::zero();
            if fn_ != T::zero() && positive != (fn_ > T::zero()) {
                out.push(self.newton(line, at(k), at(k + 1), fk));
                continue;
            }
            // f keeps its sign; does it turn back towards zero in between?
            let zero = T::zero();
            let towards_zero = if positive { dk < zero && dn > zero } else { dk > zero && dn < zero };
            if !towards_zero {
                continue;
            }
            let (a, b) = (at(k), at(k + 1));
            let e = self.extremum(line, a, b, dk);
            let Some((fe, _)) = self.f_and_slope(line, e) else { continue };
            if fe != zero && (fe > zero) != positive {
                out.push(self.newton(line, a, e, fk));
                out.push(self.newton(line, e, b, fe));
            }
            // A double root that rounding split into two, or lifted off zero.
            touches.push((e, fe.abs()));
        }
        out.extend(touches.into_iter().filter(|t| t.1 <= T::from_f64(TOUCH) * scale).map(|t| t.0));
    }

    /// Up to two Newton steps on `f` from α, each taken only if shorter than `END_STEP`, and
    /// kept only if `|f|` falls (at a double root rounding can make a step worse).
    fn polish_near(&self, line: &Line<Dual<T>>, alpha: T) -> T {
        self.polish_near_f(line, alpha).0
    }

    /// [`Family::polish_near`], and `|f|` where it ends (infinite if `f` has no value there).
    fn polish_near_f(&self, line: &Line<Dual<T>>, alpha: T) -> (T, T) {
        let Some((mut f, mut slope)) = self.f_and_slope(line, alpha) else {
            return (alpha, T::from_f64(f64::INFINITY));
        };
        let mut best = alpha;
        for _ in 0..2 {
            let step = f / slope;
            // (A NaN step is not short either.)
            let short = step.abs() <= T::from_f64(END_STEP);
            if !short || f == T::zero() {
                break;
            }
            let next = clamp_unit(best - step);
            let Some((f_next, slope_next)) = self.f_and_slope(line, next) else { break };
            if f_next.abs() >= f.abs() {
                break;
            }
            (best, f, slope) = (next, f_next, slope_next);
        }
        (best, f.abs())
    }

    /// A root placed to rounding: Newton on `f` ([`Family::polish_near`]), and where that
    /// leaves `|f|` above rounding — a touch, where Newton converges only linearly — the
    /// extremum of `f` nearby ([`Family::touch_near`]).
    fn refine(&self, line: &Line<Dual<T>>, alpha: T) -> T {
        let (alpha, f) = self.polish_near_f(line, alpha);
        if f <= T::from_f64(SIMPLE) { alpha } else { self.touch_near(line, alpha) }
    }

    /// Newton steps on `f` from α, kept in [0, 1], until a step is below rounding (at most
    /// 12: from an end, a root within `END_STEP` converges quadratically well before).
    fn polish(&self, line: &Line<Dual<T>>, mut alpha: T) -> T {
        for _ in 0..12 {
            let Some((f, slope)) = self.f_and_slope(line, alpha) else { break };
            let next = alpha - f / slope;
            if !next.is_finite() {
                break;
            }
            let next = clamp_unit(next);
            let settled = (next - alpha).abs() <= T::from_f64(4.0) * T::epsilon();
            alpha = next;
            if settled {
                break;
            }
        }
        alpha
    }

    /// A touch of `f` (a double root: `f'` changes sign) within `TOUCH_REACH` of α, found by
    /// bisection on `f'`, if `|f|` is smaller there. A double root of a high-degree
    /// polynomial is placed only to about the square root of its rounding; `f'` places it to
    /// rounding.
    fn touch_near(&self, line: &Line<Dual<T>>, alpha: T) -> T {
        let reach = T::from_f64(TOUCH_REACH);
        let (lo, hi) = (clamp_unit(alpha - reach), clamp_unit(alpha + reach));
        let (Some((f, _)), Some((_, d_lo)), Some((_, d_hi))) =
            (self.f_and_slope(line, alpha), self.f_and_slope(line, lo), self.f_and_slope(line, hi))
        else {
            return alpha;
        };
        if f == T::zero() || (d_lo > T::zero()) == (d_hi > T::zero()) {
            return alpha;
        }
        let e = self.extremum(line, lo, hi, d_lo);
        match self.f_and_slope(line, e) {
            Some((fe, _)) if fe.abs() < f.abs() => e,
            _ => alpha,
        }
    }

    /// Where `f'` changes sign in `[lo, hi]` (`f'(lo) = d_lo`), by bisection.
    fn extremum(&self, line: &Line<Dual<T>>, mut lo: T, mut hi: T, d_lo: T) -> T {
        let half = T::from_f64(0.5);
        for _ in 0..60 {
            let mid = half * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            match self.f_and_slope(line, mid) {
                Some((_, d)) if (d > T::zero()) == (d_lo > T::zero()) => lo = mid,
                _ => hi = mid,
            }
        }
        half * (lo + hi)
    }

    /// The root of `f` in `[lo, hi]` (`f(lo) = f_lo`, `f(hi)` of the other sign): Newton
    /// steps with the exact slope, replaced by bisection whenever one would leave the bracket.
    fn newton(&self, line: &Line<Dual<T>>, lo: T, hi: T, f_lo: T) -> T {
        let eps = T::epsilon();
        let stop = Stop { noise: T::zero(), absolute: eps + eps, relative: T::from_f64(4.0) * eps, iterations: 64 };
        safeguarded(
            |x| self.f_and_slope(line, x),
            |_| T::zero(),
            (lo, hi),
            f_lo > T::zero(),
            T::from_f64(0.5) * (lo + hi),
            stop,
        )
    }

    /// The α minimising `|f|` on `[lo, hi]` (golden-section search).
    fn minimise_abs(&self, line: &Line<T>, mut lo: T, mut hi: T) -> T {
        let g = T::from_f64(0.5 * (5f64.sqrt() - 1.0));
        let h = |a: T| self.f(line, a).map(T::abs);
        let h = |a: T| h(a).unwrap_or(T::from_f64(f64::MAX));
        let (mut a, mut b) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (mut ha, mut hb) = (h(a), h(b));
        for _ in 0..80 {
            if ha < hb {
                hi = b;
                (b, hb) = (a, ha);
                a = hi - g * (hi - lo);
                ha = h(a);
            } else {
                lo = a;
                (a, ha) = (b, hb);
                b = lo + g * (hi - lo);
                hb = h(b);
            }
        }
        let mid = T::from_f64(0.5) * (lo + hi);
        let ends = [(lo, h(lo)), (hi, h(hi)), (mid, h(mid))];
        ends.into_iter().fold((lo, T::from_f64(f64::MAX)), |best, e| if e.1 < best.1 { e } else { best }).0
    }

    /// The nearest verified crossing `(t, point, α)` with `t_min < t < t_max` of the ray
    /// `origin + t dir` (unit `dir`, carried by `line`) among the candidate α.
    ///
    /// With `polish`, the crossing is placed to rounding on `f` itself: a root of the
    /// polynomial `R` carries `R`'s conditioning, not `f`'s. Each candidate is then verified on
    /// `C_α` from one evaluation on dual numbers, which also gives `f`, `f'` and `dC/dα`; the
    /// kept crossing takes its Newton step `δ = f/f'` from those when `|δ| ≤ 1e-8` (the
    /// circle moved to `C − δ dC/dα`, exact to `δ²`), and by Newton on `f` otherwise. A
    /// candidate that fails verification is moved by up to two Newton steps on `f` and tried
    /// again: near-degenerate circles can put `R`'s root just outside the verification's
    /// tolerance. Steps longer than 1e-6 mean `R`'s root is not one of `f`'s (the other branch
    /// of the square root), and it stays rejected.
    #[allow(clippy::type_complexity)]
    pub fn nearest(
        &self,
        ray: (E3<T>, E3<T>, &Line<T>),
        alphas: &[T],
        t_min: T,
        t_max: T,
        polish: bool,
    ) -> Option<(T, E3<T>, T)> {
        let in_range = |x: &E3<T>| {
            let t = dot(sub(*x, ray.0), ray.1);
            (t > t_min && t < t_max).then_some(t)
        };
        if !polish {
            let mut best: Option<(T, E3<T>, T)> = None;
            for &alpha in alphas {
                for x in self.verified(alpha, ray) {
                    match in_range(&x) {
                        Some(t) if best.is_none_or(|b| t < b.0) => best = Some((t, x, alpha)),
                        _ => {}
                    }
                }
            }
            return best;
        }
        let line = ray.2.lift();
        // (t, point, α, whether α was polished)
        let mut best: Option<(T, E3<T>, T, bool)> = None;
        for &alpha in alphas {
            let mut points = self.verified(alpha, ray);
            let (mut alpha, mut polished) = (alpha, false);
            if points.is_empty() {
                let moved = self.polish_near(&line, alpha);
                if moved != alpha {
                    (alpha, polished) = (moved, true);
                    points = self.verified(alpha, ray);
                }
            }
            for x in points {
                match in_range(&x) {
                    Some(t) if best.as_ref().is_none_or(|b| t < b.0) => best = Some((t, x, alpha, polished)),
                    _ => {}
                }
            }
        }
        let (t, x, alpha, polished) = best?;
        // The slope on dual numbers only for the crossing kept (its circle's real part is
        // the circle verified).
        let slope = if polished { None } else { self.slope(&line, alpha) };
        let step = slope.as_ref().map(|s| (s.f / s.df, s));
        let (refined, circle) = match step {
            Some((delta, s))
                if delta.abs() <= T::from_f64(TAYLOR_STEP) && (alpha - delta) == clamp_unit(alpha - delta) =>
            {
                (alpha - delta, Ok(s.circle + s.circle_slope * (-delta)))
            }
            _ => {
                let refined = self.refine(&line, alpha);
                (refined, self.circles.at(refined))
            }
        };
        let distance = |y: &E3<T>| norm(sub(*y, x));
        let nearest = circle
            .map_or_else(|_| SmallVec::new(), |c| hit_points(&c, ray))
            .into_iter()
            .min_by(|a, b| distance(a).to_f64().total_cmp(&distance(b).to_f64()));
        if let Some(y) = nearest {
            let t2 = dot(sub(y, ray.0), ray.1);
            if t2 > t_min && t2 < t_max && (t2 - t).abs() <= T::from_f64(1e-6) * (t.abs() + norm(sub(x, ray.0))) {
                return Some((t2, y, refined));
            }
        }
        Some((t, x, alpha))
    }

    /// `C_α`, `dC/dα`, `f` and `f'` at α, from one evaluation on dual numbers.
    fn slope(&self, line: &Line<Dual<T>>, alpha: T) -> Option<Slope<T>> {
        let c = self.circles.at_dual(Dual::variable(alpha)).ok()?;
        let f = line.meet_circle(&c).norm_squared();
        let (circle, circle_slope) = Circle::split(c);
        Some(Slope { circle, circle_slope, f: f.re, df: f.du })
    }

    /// The verified points where the ray meets `C_α`.
    fn verified(&self, alpha: T, ray: (E3<T>, E3<T>, &Line<T>)) -> SmallVec<[E3<T>; 2]> {
        self.circles.at(alpha).map_or_else(|_| SmallVec::new(), |circle| hit_points(&circle, ray))
    }
}

/// A Newton step on `f` at most this long (in α) is taken from the derivatives already at
/// hand, the circle moved along its tangent: the error is of order δ², below rounding.
const TAYLOR_STEP: f64 = 1e-8;

/// What one evaluation on dual numbers gives at α ([`Family::slope`]).
#[derive(Clone, Copy, Debug)]
struct Slope<T: Real> {
    circle: Circle<T>,
    circle_slope: Circle<T>,
    f: T,
    df: T,
}

/// The largest magnitude among `c`.
fn largest<T: Real>(c: &[T]) -> T {
    c.iter().fold(T::zero(), |m, x| m.max(x.abs()))
}

/// `x` kept in [0, 1].
fn clamp_unit<T: Real>(x: T) -> T {
    if x < T::zero() {
        T::zero()
    } else if x > T::one() {
        T::one()
    } else {
        x
    }
}

/// Points where the ray's line meets `circle`, each checked to lie on both. The meet
/// `C ∨ L` is the touching point; where it fails the check — it vanishes with the line in the
/// circle's plane, and near that plane it is ill-conditioned (a ray within 1e-8 of a circle's
/// plane gave a point 3e-3 off at 160×120 in `surface.toml`) — the points where the line meets
/// the circle's sphere `|x − c| = r` are checked instead: well-conditioned unless the ray runs
/// along the circle's tangent, that is grazes the surface.
fn hit_points<T: Real>(circle: &Circle<T>, (origin, dir, line): (E3<T>, E3<T>, &Line<T>)) -> SmallVec<[E3<T>; 2]> {
    let mut points = SmallVec::new();
    let Ok((c, n, r)) = circle.centre_normal_radius() else { return points };
    // Relative to the circle, and to the distance the ray's line carries (its rounding).
    let eps = T::epsilon();
    let tol = T::from_f64(1e-6).max(T::from_f64(1e3) * eps) * r
        + T::from_f64(1e-9).max(T::from_f64(10.0) * eps) * norm(sub(origin, c));
    let on_both = |x: &E3<T>| {
        let d = sub(*x, c);
        let rel = sub(*x, origin);
        let to_line = norm(sub(rel, scale(dir, dot(rel, dir))));
        (norm(d) - r).abs() < tol && dot(d, n).abs() < tol && to_line < tol
    };
    points.extend(down(line.meet_circle(circle)).ok().filter(on_both));
    if points.is_empty() {
        // |o + t d − c|² = r², each root kept where it lies in the circle's plane.
        let oc = sub(origin, c);
        let (b, cc) = (dot(oc, dir), dot(oc, oc) - r * r);
        let disc = b * b - cc;
        if disc >= T::zero() {
            let s = disc.sqrt();
            // The root of larger magnitude directly, the other from their product: no
            // cancellation.
            let far = if b > T::zero() { -b - s } else { -b + s };
            let near = if far != T::zero() { cc / far } else { T::zero() };
            let mut ts = [near, far];
            ts.sort_by(|a, b| a.to_f64().total_cmp(&b.to_f64()));
            points.extend(ts.into_iter().map(|t| cga_core::euclid::add(origin, scale(dir, t))).filter(on_both));
        }
    }
    points
}
