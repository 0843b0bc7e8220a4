//! The evolved surface swept by `C_α` between two circles, and its analytic normal
//! (the paper's eq. 6–11), with `Ċ = dC_α/dα` exact (dual numbers, see [`Pair::with_derivative`]).
//!
//! At a point `X` of `C_α`:
//! - `Ω = ⟨C Ċ⟩₂`, the "angular velocity" of the circles (`C Ċ` has no other part:
//!   `C² = 1` makes `Ċ C + C Ċ = 0`, which leaves grade 2 only);
//! - `Ẋ = X · Ω` (for a vector on the left the Hestenes inner product is `X ⌋ Ω`), the
//!   velocity of the point as the circle moves;
//! - `L_C = (X · C) ∧ ei`, the tangent line of the circle at `X`;
//! - `L_T = Ẋ ∧ X ∧ ei`, the line through `X` along `Ẋ`;
//! - `N = ⟨L_T L_C I5⟩₃`, the normal line at `X`, `I5 = e12345 = −e123oi`.
//!
//! `α` runs from `C1` (α = 0) to `C2` (α = 1). The paper's parameter runs the other way, so
//! its `Ċ`, `Ω`, `Ẋ`, `L_T` and `N` are the negatives of these (the golden files use it).

use crate::conformal::{GeometryError, ei, up};
use crate::euclid::{E3, circle_distance, cross, dot, norm, sub};
use crate::interpolate::{InterpolationError, Pair};
use crate::spline::Spline;
use crate::{Bivector, Circle, Line, Pseudoscalar, Real, Vector};

/// Why a normal cannot be computed.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum NormalError {
    /// No circle at this α.
    #[error(transparent)]
    Interpolation(#[from] InterpolationError),
    /// `N` has no direction: `L_T` is parallel to `L_C` (the point does not move off its
    /// circle, `Ẋ ∥` tangent) or `Ẋ = 0` (the circles do not move there).
    #[error("the normal line is degenerate: {0}")]
    Degenerate(#[from] GeometryError),
    /// The point is not on `C_α`: `distance` from it, relative to the radius, exceeds
    /// [`accuracy`](crate::interpolate::accuracy) (the normal of eq. 6–11 holds on the circle only).
    #[error("the point is {distance:.1e} radii off the circle C_α")]
    OffCircle {
        /// Distance from `C_α`, in radii.
        distance: f64,
    },
    /// The normal's direction cannot be delivered to [`accuracy`](crate::interpolate::accuracy):
    /// `estimate` (radians) is the error to expect. The circles are nearly identical, so
    /// `Ċ`, of size `Δ` (their relative difference), is rounding noise of size `ε/Δ`.
    #[error("ill-conditioned normal: expected angle error {estimate:.1e} rad (the circles are nearly identical)")]
    IllConditioned {
        /// The expected angle error in radians.
        estimate: f64,
    },
}

/// Every quantity of the normal computation, for inspection and testing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalParts<T: Real = f64> {
    /// `C_α`.
    pub circle: Circle<T>,
    /// `dC_α/dα`.
    pub circle_dot: Circle<T>,
    /// `X = up(x)`.
    pub point: Vector<T>,
    /// `Ω = ⟨C Ċ⟩₂`.
    pub omega: Bivector<T>,
    /// `Ẋ = X · Ω`.
    pub x_dot: Vector<T>,
    /// `L_C = (X · C) ∧ ei`.
    pub l_c: Line<T>,
    /// `L_T = Ẋ ∧ X ∧ ei`.
    pub l_t: Line<T>,
    /// `N = ⟨L_T L_C I5⟩₃`.
    pub normal_line: Line<T>,
}

impl<T: Real> NormalParts<T> {
    /// Eq. 6–11 from `C_α`, `Ċ_α` and the point `x` (which should lie on `C_α`), for any
    /// family of circles: two ([`Pair::normal_parts`]) or many ([`Spline::normal_parts`]).
    pub fn new(circle: Circle<T>, circle_dot: Circle<T>, x: E3<T>) -> Self {
        let omega = (circle * circle_dot).grade2();
        let point = up(x);
        let x_dot = point | omega;
        let l_c = (point | circle) ^ ei();
        let l_t = (x_dot ^ point) ^ ei();
        let i5 = Pseudoscalar { e123oi: -T::one() };
        let normal_line = Line::from_storage(&((l_t * l_c) * i5).to_storage());
        NormalParts { circle, circle_dot, point, omega, x_dot, l_c, l_t, normal_line }
    }

    /// The unit Euclidean normal at `x` (the point these parts were built for): the
    /// direction of `N`, once `x` is checked to lie on `C_α` within
    /// [`accuracy`](crate::interpolate::accuracy) radii (else `OffCircle`).
    pub fn unit_normal(&self, x: E3<T>) -> Result<E3<T>, NormalError> {
        let limit = crate::interpolate::accuracy::<T>();
        let distance = circle_distance(x, self.circle.centre_normal_radius()?).to_f64();
        if distance.is_nan() || distance > limit {
            return Err(NormalError::OffCircle { distance });
        }
        Ok(self.normal_line.direction()?)
    }
}

impl<T: Real> Pair<Circle<T>> {
    /// All of eq. 6–11 at parameter `α` and the point `x` (which should lie on `C_α`).
    pub fn normal_parts(&self, alpha: T, x: E3<T>) -> Result<NormalParts<T>, InterpolationError> {
        let (circle, circle_dot) = self.with_derivative(alpha)?;
        Ok(NormalParts::new(circle, circle_dot, x))
    }

    /// The unit Euclidean normal at `x` on `C_α`: the direction of `N` (its sign follows
    /// `N`'s orientation, which follows the circles': surfaces here are two-sided).
    ///
    /// Checked: `x` must lie on `C_α` (within [`accuracy`](crate::interpolate::accuracy)
    /// radii, else `OffCircle`), and the expected angle error
    /// `ε (1 + ρ)² / Δ + condition()` must stay below it (else `IllConditioned`), `Δ` the
    /// circles' relative difference `(|c₁ − c₂| + |r₁ − r₂| + r ∠(n₁, n₂)) / r`, `r` the
    /// smaller radius and `ρ` as in [`Pair::condition`].
    pub fn normal(&self, alpha: T, x: E3<T>) -> Result<E3<T>, NormalError> {
        checked_normal(self.normal_condition(), || self.normal_parts(alpha, x), x)
    }

    /// The expected angle error of [`Pair::normal`] (radians): see there.
    pub fn normal_condition(&self) -> f64 {
        let cnr = |c: &Circle<T>| {
            c.centre_normal_radius().map(|(c, n, r)| (c.map(|x| x.to_f64()), n.map(|x| x.to_f64()), r.to_f64()))
        };
        let (Ok((a, n1, r1)), Ok((b, n2, r2))) = (cnr(&self.c1), cnr(&self.c2)) else { return f64::INFINITY };
        let r = r1.min(r2);
        let turn = norm(cross(n1, n2)).atan2(dot(n1, n2).abs());
        let delta = (norm(sub(a, b)) + (r1 - r2).abs() + r * turn) / r;
        let rho = (norm(a) / r1).max(norm(b) / r2);
        T::epsilon().to_f64() * (1.0 + rho).powi(2) / delta + self.condition()
    }
}

impl<T: Real> Spline<Circle<T>> {
    /// All of eq. 6–11 at parameter `α` of the spline and the point `x` on `C_α`; `Ċ` is the
    /// derivative in the spline's own `α` (exact, dual numbers through the Bézier segment and
    /// the projector).
    pub fn normal_parts(&self, alpha: T, x: E3<T>) -> Result<NormalParts<T>, InterpolationError> {
        let (circle, circle_dot) = self.with_derivative(alpha)?;
        Ok(NormalParts::new(circle, circle_dot, x))
    }

    /// The unit Euclidean normal at `x` on `C_α`, checked as [`Pair::normal`] checks it
    /// (`OffCircle`; `IllConditioned` when [`Spline::condition`] exceeds the accuracy).
    pub fn normal(&self, alpha: T, x: E3<T>) -> Result<E3<T>, NormalError> {
        checked_normal(self.condition(), || self.normal_parts(alpha, x), x)
    }
}

/// The unit normal at `x` from `parts`, refused as `IllConditioned` when the expected error
/// `estimate` exceeds [`accuracy`](crate::interpolate::accuracy).
fn checked_normal<T: Real>(
    estimate: f64,
    parts: impl FnOnce() -> Result<NormalParts<T>, InterpolationError>,
    x: E3<T>,
) -> Result<E3<T>, NormalError> {
    if estimate.is_nan() || estimate > crate::interpolate::accuracy::<T>() {
        return Err(NormalError::IllConditioned { estimate });
    }
    parts()?.unit_normal(x)
}
