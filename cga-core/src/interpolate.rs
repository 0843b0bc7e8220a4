//! Interpolation of objects through the square-root projector (the paper's eq. 3–5).
//!
//! For normalised blades `C1`, `C2` of one kind (circles, point pairs, lines, planes,
//! spheres), `X = (1 − α) C1 + α C2` is not a blade in general. Its projection onto the
//! blades is `C = K⁻¹ X` with `K = √(−X X̃)`, a scalar plus 4-vector, and
//! `K⁻¹ = K* / (K* K)`, `K* = ⟨K⟩₀ − ⟨K⟩₄` (so `K* K = ⟨K⟩₀² − ⟨K⟩₄²` is a scalar).
//! Then `C C̃ = K⁻¹ X X̃ K⁻¹ = −1`: the result is normalised as clifford normalises.
//!
//! Parameter convention: `α = 0` gives `C1`, `α = 1` gives `C2` (clifford's and the golden
//! files'); the paper writes `α C1 + (1 − α) C2`, the same surface with `α` reversed.

use crate::euclid::{E3, norm, sub};
use crate::{Bivector, Circle, Dual, Line, Plane, Real, ScalarQuadvector, Sphere};
use core::ops::{Add, Mul, Neg};

/// Why an interpolation has no blade.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum InterpolationError {
    /// `−X X̃ = s + Q` has no real square root: `s² − Q² < 0`, or both branches of `⟨K⟩₀²`
    /// are negative. The sum passes through an object with no real projection.
    #[error("−X X̃ has no real square root at α = {alpha} (s = {s}, Q² = {q2})")]
    NoRealRoot {
        /// Where it happened.
        alpha: f64,
        /// `⟨−X X̃⟩₀`.
        s: f64,
        /// `⟨−X X̃⟩₄²`.
        q2: f64,
    },
    /// `K* K = 0`, or the projected blade is null: the interpolant is degenerate there
    /// (for instance `X = 0` when `C2 = −C1` is not aligned, or a zero-radius round).
    #[error("the projector is singular at α = {alpha}")]
    Singular {
        /// Where it happened.
        alpha: f64,
    },
    /// The interpolation leaves through infinity: two disjoint spheres, aligned, pass
    /// through a plane at `alpha` (their centres run off to infinity on either side of it;
    /// with the other sign the spheres in between are imaginary). No real, bounded path of
    /// this pencil joins them; `Pair::new_unchecked` interpolates anyway.
    #[error("the interpolation passes through a plane at α = {alpha} (disjoint spheres): no bounded path joins them")]
    ThroughInfinity {
        /// Where the interpolant is a plane.
        alpha: f64,
    },
    /// An endpoint is zero or null: it cannot be normalised.
    #[error("an endpoint is zero or null")]
    Degenerate,
    /// [`average_objects`] of no objects.
    #[error("no objects to average")]
    NoObjects,
    /// [`average_objects_weighted`]: the weights are not one per object, not all finite, or
    /// sum to zero.
    #[error("{weights} weights for {objects} objects, or weights not finite or summing to zero")]
    Weights {
        /// The objects' count.
        objects: usize,
        /// The weights' count.
        weights: usize,
    },
    /// f64 (or the scalar in use) cannot deliver the interpolation to the accuracy [`Pair`]
    /// promises ([`accuracy`]): `estimate` is the relative error to expect (see
    /// [`Pair::condition`]). Move the objects to a frame near them (translate by minus their
    /// mean centre) and interpolate there.
    #[error(
        "ill-conditioned: expected relative error {estimate:.1e} (the objects lie far from the \
         origin, or differ greatly in size, for this precision: interpolate them in a local frame)"
    )]
    IllConditioned {
        /// The expected relative error.
        estimate: f64,
    },
}

/// The accuracy checked interpolations promise: `10⁻⁶` relative in f64, `√ε` for coarser
/// scalars (`3.5·10⁻⁴` in f32). [`Pair::new`] and [`Pair::normal`](crate::NormalParts)
/// refuse configurations whose estimated error exceeds it.
pub fn accuracy<T: Real>() -> f64 {
    T::epsilon().to_f64().sqrt().max(1e-6)
}

impl<T: Real> ScalarQuadvector<T> {
    /// `K* = ⟨K⟩₀ − ⟨K⟩₄`.
    #[inline]
    pub fn star(self) -> Self {
        Self {
            s: self.s,
            e123o: -self.e123o,
            e123i: -self.e123i,
            e12oi: -self.e12oi,
            e13oi: -self.e13oi,
            e23oi: -self.e23oi,
        }
    }

    /// Both real square roots with a positive scalar part (Dorst–Valkenburg): for
    /// `S = s + Q`, `√S = a + Q/(2a)` with `a² = (s ± √(s² − Q²))/2`, since `Q²` is a scalar.
    /// `[principal, other]`; the negatives are roots too. The principal (`+`) branch is the
    /// one continuous with `√s` as `Q → 0` for `s > 0`, so `√1 = 1`: interpolating between
    /// equal blades gives that blade. A branch is `None` where its `a²` is not positive.
    pub fn sqrt_roots(self) -> [Option<Self>; 2] {
        let Some((q, q2, plus, root)) = self.branches() else { return [None, None] };
        // The other branch: (s + √disc)(s − √disc) = Q², so 2a₋² = Q² / 2a₊² where s ≥ 0,
        // and 2a₊² = Q² / 2a₋² where s < 0; each computed without cancellation.
        let minus = if self.s >= T::zero() { q2 / plus } else { self.s - root };
        [Self::root(q, plus), Self::root(q, minus)]
    }

    /// The principal square root (see [`ScalarQuadvector::sqrt_roots`]), if it is real;
    /// only that branch is computed.
    #[inline]
    pub fn try_sqrt(self) -> Option<Self> {
        let (q, _, plus, _) = self.branches()?;
        Self::root(q, plus)
    }

    /// `(Q, Q², 2a₊², √(s² − Q²))`, with `2a₊² = s + √(s² − Q²)` written as
    /// `Q² / (s − √…)` when `s < 0`; `None` when `s² < Q²`.
    #[inline]
    fn branches(self) -> Option<(Sphere<T>, T, T, T)> {
        let q = self.grade4();
        let q2 = (q * q).s;
        let disc = self.s * self.s - q2;
        if disc < T::zero() || !disc.is_finite() {
            return None;
        }
        let root = disc.sqrt();
        let plus = if self.s >= T::zero() { self.s + root } else { q2 / (self.s - root) };
        Some((q, q2, plus, root))
    }

    /// `a + Q/(2a)` for `2a² = twice_a2`, if that is positive.
    #[inline]
    fn root(q: Sphere<T>, twice_a2: T) -> Option<Self> {
        let a = (twice_a2 / T::from_f64(2.0)).sqrt();
        let inv = T::one() / (a + a);
        (twice_a2 > T::zero() && inv.is_finite()).then(|| Self::from(q.scale(inv)) + Self { s: a, ..Self::zero() })
    }
}

/// Blades that interpolate through the projector: [`Circle`], [`Bivector`] (point pairs),
/// [`Line`], [`Plane`], [`Sphere`]. The interpolation's machinery, named for what it does
/// there (none of it is a geometric projection: for those see [`crate::Nearest`]).
pub trait Interpolable<T: Real>: Copy + Add<Output = Self> + Mul<T, Output = Self> + Neg<Output = Self> {
    /// The same blade over dual numbers.
    type Lifted: Interpolable<Dual<T>>;
    /// As a constant dual blade.
    fn lift(self) -> Self::Lifted;
    /// (value, derivative) of a dual blade.
    fn split(lifted: Self::Lifted) -> (Self, Self);
    /// `−X X̃`: a scalar plus 4-vector for a sum of blades of one grade (the grade-2 part
    /// vanishes identically and is dropped).
    fn neg_square(self) -> ScalarQuadvector<T>;
    /// `K⁻¹ X = K* X / (K* K)`, the parts of this type's grade kept; `None` when singular.
    fn apply_projector(self, k: ScalarQuadvector<T>) -> Option<Self>;
    /// `⟨A B̃⟩₀`.
    fn reverse_product(self, other: Self) -> T;
    /// `A / √|⟨A Ã⟩₀|`, `None` for a null or zero blade.
    fn try_normalised(self) -> Option<Self>;
    /// For a round (circle, point pair, sphere): its centre and size (radius, or half the
    /// pair's distance), to estimate conditioning; `None` for flats, whose coefficients grow
    /// only linearly with distance.
    fn centre_size(self) -> Option<(E3<T>, T)>;
    /// Where the interpolation `(1 − α) C1 + α C2` of two aligned blades of this kind leaves
    /// the kind through infinity, if it does for `α` in `(0, 1)`: two spheres whose duals'
    /// weights `λ1, λ2` differ in sign (disjoint spheres, once aligned) pass through a
    /// plane at `α = λ1/(λ1 − λ2)`, where the centre runs off to infinity; `None` for the
    /// other kinds.
    fn through_infinity(self, other: Self) -> Option<T>;
}

macro_rules! interpolable {
    ($($ty:ident => $reach:expr, $agree:expr);*) => {$(
        impl<T: Real> Interpolable<T> for $ty<T> {
            type Lifted = $ty<Dual<T>>;
            #[inline]
            fn lift(self) -> Self::Lifted {
                $ty::from_array(self.to_array().map(Dual::constant))
            }
            #[inline]
            fn split(lifted: Self::Lifted) -> (Self, Self) {
                let c = lifted.to_array();
                ($ty::from_array(c.map(|d| d.re)), $ty::from_array(c.map(|d| d.du)))
            }
            #[inline]
            fn neg_square(self) -> ScalarQuadvector<T> {
                -ScalarQuadvector::from_storage(&(self * self.reverse()).to_storage())
            }
            #[inline]
            fn apply_projector(self, k: ScalarQuadvector<T>) -> Option<Self> {
                let star = k.star();
                let inv = T::one() / (star * k).s;
                inv.is_finite().then(|| $ty::from_storage(&(star * self).to_storage()).scale(inv))
            }
            #[inline]
            fn reverse_product(self, other: Self) -> T {
                ScalarQuadvector::from_storage(&(self * other.reverse()).to_storage()).s
            }
            #[inline]
            fn try_normalised(self) -> Option<Self> {
                self.try_normalise()
            }
            fn centre_size(self) -> Option<(E3<T>, T)> {
                let reach: fn($ty<T>) -> Option<(E3<T>, T)> = $reach;
                reach(self)
            }
            fn through_infinity(self, other: Self) -> Option<T> {
                let at: fn($ty<T>, $ty<T>) -> Option<T> = $agree;
                at(self, other)
            }
        }
    )*};
}

interpolable!(
    Circle => |c| c.centre_normal_radius().ok().map(|(c, _, r)| (c, r)), |_, _| None;
    Bivector => |p| {
        let [a, b] = p.end_points().ok()?;
        let half = T::from_f64(0.5);
        Some(([0, 1, 2].map(|k| half * (a[k] + b[k])), half * norm(sub(b, a))))
    }, |_, _| None;
    Line => |_| None, |_, _| None;
    Plane => |_| None, |_, _| None;
    Sphere => |s| s.centre_radius().ok(), |a, b| {
        // The dual weights λ of λ(up(c) − ½r² ei).
        let (w1, w2) = (a.dual().eo, b.dual().eo);
        ((w1 < T::zero()) != (w2 < T::zero()) && w1 != T::zero() && w2 != T::zero()).then(|| w1 / (w1 - w2))
    }
);

/// `C2` or `−C2`, whichever is oriented like `C1`: the sign of `⟨C1 C̃2⟩₀` must be that of
/// `⟨C1 C̃1⟩₀`. Without this, `C2 ≈ −C1` makes `X` pass through zero. Where `⟨C1 C̃2⟩₀` is zero
/// to rounding (perpendicular point pairs or lines, say) its sign says nothing — rounding
/// would choose between two different interpolations, and moving or scaling the objects
/// could choose the other — so `C2` is kept the way it was given.
#[inline]
pub fn align<T: Real, X: Interpolable<T>>(c1: X, c2: X) -> X {
    let (own, cross) = (c1.reverse_product(c1), c1.reverse_product(c2));
    let undecided = cross.abs() <= T::from_f64(64.0) * T::epsilon() * (own * c2.reverse_product(c2)).abs().sqrt();
    if !undecided && (own < T::zero()) != (cross < T::zero()) { -c2 } else { c2 }
}

/// `C_α = K⁻¹ X / √|⟨…⟩₀|` for `X = (1 − α) C1 + α C2`, `K` the principal root of `−X X̃`.
/// The inputs are used as given (normalise and [`align`] them first: [`Pair::new`] does).
/// The final renormalisation only removes rounding: `K⁻¹ X` is normalised exactly.
pub fn interpolate<T: Real, X: Interpolable<T>>(c1: X, c2: X, alpha: T) -> Result<X, InterpolationError> {
    project_at(c1 * (T::one() - alpha) + c2 * alpha, alpha)
}

/// The square-root projector (eq. 4–5) of any sum `X` of blades of one kind:
/// `C = K⁻¹ X / √|⟨…⟩₀|`, `K` the principal root of `−X X̃`. `alpha` only labels errors (the
/// parameter at which `X` was formed).
pub fn project_at<T: Real, X: Interpolable<T>>(x: X, alpha: T) -> Result<X, InterpolationError> {
    let sq = x.neg_square();
    let singular = || InterpolationError::Singular { alpha: alpha.to_f64() };
    let k = match sq.try_sqrt() {
        Some(k) => k,
        // X = 0 (unaligned opposite blades): the root exists, it is zero.
        None if sq == ScalarQuadvector::zero() => return Err(singular()),
        None => {
            let q = sq.grade4();
            return Err(InterpolationError::NoRealRoot {
                alpha: alpha.to_f64(),
                s: sq.s.to_f64(),
                q2: (q * q).s.to_f64(),
            });
        }
    };
    x.apply_projector(k).ok_or_else(singular)?.try_normalised().ok_or_else(singular)
}

/// Two normalised blades of one kind, the second aligned to the first: the endpoints of an
/// interpolation, prepared once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair<X> {
    /// `α = 0`.
    pub c1: X,
    /// `α = 1`, oriented like `c1`.
    pub c2: X,
}

impl<X> Pair<X> {
    /// Normalise both and align `c2` to `c1`, checking that the interpolation can be
    /// delivered to [`accuracy`]: `Degenerate` if either is null or zero, `IllConditioned`
    /// when [`Pair::condition`] exceeds it (rounds far from the origin for their size, or of
    /// very different sizes). [`Pair::new_unchecked`] skips the check.
    pub fn new<T: Real>(c1: X, c2: X) -> Result<Self, InterpolationError>
    where
        X: Interpolable<T>,
    {
        let pair = Self::new_unchecked(c1, c2)?;
        if let Some(alpha) = pair.c1.through_infinity(pair.c2) {
            return Err(InterpolationError::ThroughInfinity { alpha: alpha.to_f64() });
        }
        let estimate = pair.condition();
        if estimate.is_nan() || estimate > accuracy::<T>() {
            return Err(InterpolationError::IllConditioned { estimate });
        }
        Ok(pair)
    }

    /// Normalise both and align `c2` to `c1`, without the conditioning check.
    pub fn new_unchecked<T: Real>(c1: X, c2: X) -> Result<Self, InterpolationError>
    where
        X: Interpolable<T>,
    {
        let c1 = c1.try_normalised().ok_or(InterpolationError::Degenerate)?;
        let c2 = align(c1, c2.try_normalised().ok_or(InterpolationError::Degenerate)?);
        Ok(Pair { c1, c2 })
    }

    /// The relative error to expect of `C_α` (its centre, radius, normal) from rounding:
    /// `ε (1 + ρ)³`, `ρ = max(|c₁|/r₁, |c₂|/r₂)` for rounds of centres `cᵢ` and sizes `rᵢ`
    /// (each round's distance from the origin in units of its own size; 0 for flats, whose
    /// coefficients grow only linearly).
    ///
    /// Why: a round's null-basis coefficients grow like `ρ²` (as `|c|²/r` against `1/r`), and
    /// the projector's square `−X X̃` cancels them back to size 1. The sizes alone do not
    /// matter: a circle of radius 1e-8 at the origin beside a unit one interpolates to
    /// rounding. Measured (docs/STABILITY.md, `cargo test --test geometry precision:: -- --ignored
    /// --nocapture`): through this crate's constructors the normal's error stays 10× below
    /// the estimate and C_α's centre and radius 300× below; from correctly rounded blades
    /// (50-digit references, `tests/tests/geometry/far_reference.rs`) within it.
    pub fn condition<T: Real>(&self) -> f64
    where
        X: Interpolable<T>,
    {
        let (Some((a, r1)), Some((b, r2))) = (self.c1.centre_size(), self.c2.centre_size()) else { return 0.0 };
        let own = |c: crate::euclid::E3<T>, r: T| norm(c.map(|x| x.to_f64())) / r.to_f64();
        let rho = own(a, r1).max(own(b, r2));
        T::epsilon().to_f64() * (1.0 + rho).powi(3)
    }

    /// `C_α` (see [`interpolate`]).
    pub fn at<T: Real>(&self, alpha: T) -> Result<X, InterpolationError>
    where
        X: Interpolable<T>,
    {
        interpolate(self.c1, self.c2, alpha)
    }

    /// `(C_α, dC_α/dα)`, the derivative exact: the same code run on dual numbers.
    pub fn with_derivative<T: Real>(&self, alpha: T) -> Result<(X, X), InterpolationError>
    where
        X: Interpolable<T>,
    {
        let c = interpolate(self.c1.lift(), self.c2.lift(), Dual::variable(alpha))?;
        Ok(X::split(c))
    }
}

/// The average of objects of one kind (clifford.tools.g3c's `average_objects`; Hadfield
/// and Lasenby, "Direct linear interpolation of geometric objects", AGACSE 2018): each
/// normalised and [`align`]ed to the first, summed, `X = (1/n) Σ Cᵢ`, and projected back
/// onto the blades of that kind by the square-root projector `C = K⁻¹ X`,
/// `K = √(−X X̃)` (see [`project_at`]; errors are labelled `α = 0`), normalised.
///
/// For two objects this is [`interpolate`] at `α = ½`. Unlike clifford, which sums the
/// objects as given, the objects are oriented like the first before they are summed: an object and its
/// negative are the same object, so `[C, −C]` averages to `C` here (clifford's sum is zero
/// and its answer NaN).
///
/// `NoObjects` for an empty slice, `Degenerate` for a zero or null object; the projector's
/// own errors where the sum has no real blade nearby (objects far apart, disjoint spheres).
pub fn average_objects<T: Real, X: Interpolable<T>>(objects: &[X]) -> Result<X, InterpolationError> {
    let weights = vec![T::one(); objects.len()];
    average_objects_weighted(objects, &weights)
}

/// [`average_objects`] with weights: `X = Σ wᵢ Cᵢ / Σ wᵢ` of the normalised, aligned
/// objects, projected. `Weights` unless there is one finite weight per object and they do
/// not sum to zero.
pub fn average_objects_weighted<T: Real, X: Interpolable<T>>(
    objects: &[X],
    weights: &[T],
) -> Result<X, InterpolationError> {
    let Some(&first) = objects.first() else { return Err(InterpolationError::NoObjects) };
    let total = weights.iter().fold(T::zero(), |s, &w| s + w);
    if weights.len() != objects.len()
        || !weights.iter().all(|w| w.is_finite())
        || total == T::zero()
        || !total.is_finite()
    {
        return Err(InterpolationError::Weights { objects: objects.len(), weights: weights.len() });
    }
    let c1 = first.try_normalised().ok_or(InterpolationError::Degenerate)?;
    let mut sum = c1 * (weights[0] / total);
    for (&x, &w) in objects.iter().zip(weights).skip(1) {
        let c = align(c1, x.try_normalised().ok_or(InterpolationError::Degenerate)?);
        sum = sum + c * (w / total);
    }
    project_at(sum, T::zero())
}
