//! Curvature of surfaces swept by circles — the paper's future work — from the CGA normal of
//! eq. 6–11 and its exact derivatives.
//!
//! At a point `x₀` of `C_{α₀}`, the surface is parametrised near `x₀` by `(α, s)`:
//! `x(α, s) = c + r (cos s e + sin s (n × e))`, `(c, n, r)` the centre, normal and radius of
//! `C_α` and `e` the in-plane direction of `x₀ − c` (so `x(α₀, 0) = x₀` and `s` runs along the
//! circle). The unit normal `ν(α, s)` is the direction of `N = ⟨L_T L_C I5⟩₃`, built from
//! `Ω = C Ċ`. Its derivatives need `Ω̇`, hence `C̈`: the whole construction runs on dual
//! numbers over the dual numbers that give `Ċ`, so every derivative is exact. Then, with
//! `I = [[E, F], [F, G]]` (`E = x_α·x_α`, `F = x_α·x_s`, `G = x_s·x_s`) and
//! `II = [[L, M], [M, N]]` (`L = −x_α·ν_α`, `M = −x_s·ν_α`, `N = −x_s·ν_s`, Weingarten),
//!
//! - Gaussian curvature `K = (LN − M²)/(EG − F²)`,
//! - mean curvature `H = (EN − 2FM + GL) / (2(EG − F²))` (its sign follows `ν`),
//! - principal curvatures `k₁,₂ = H ± √(H² − K)` and their directions, the eigenvectors of
//!   the shape operator `I⁻¹ II` mapped to space by `(a, b) ↦ a x_α + b x_s`.
//!
//! The paper postulates that `L_C` (the circle's tangent, `x_s`) and `L_T` are principal
//! directions; [`Curvature::circle_angle`] measures how far `L_C` is from the nearest one.

use crate::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use crate::evolved::NormalParts;
use crate::interpolate::{Interpolable, InterpolationError, Pair};
use crate::spline::Spline;
use crate::{Circle, Dual, Real};

/// A one-parameter family of circles with exact derivatives (two circles, or a spline).
pub trait CircleFamily<T: Real> {
    /// The same family over dual numbers.
    type Lifted: CircleFamily<Dual<T>>;
    /// The family with dual-number coefficients (constant parts).
    fn lift(&self) -> Self::Lifted;
    /// `(C_α, dC_α/dα)`.
    fn with_derivative(&self, alpha: T) -> Result<(Circle<T>, Circle<T>), InterpolationError>;
}

impl<T: Real> CircleFamily<T> for Pair<Circle<T>> {
    type Lifted = Pair<Circle<Dual<T>>>;
    fn lift(&self) -> Self::Lifted {
        Pair { c1: self.c1.lift(), c2: self.c2.lift() }
    }
    fn with_derivative(&self, alpha: T) -> Result<(Circle<T>, Circle<T>), InterpolationError> {
        Pair::with_derivative(self, alpha)
    }
}

impl<T: Real> CircleFamily<T> for Spline<Circle<T>> {
    type Lifted = Spline<Circle<Dual<T>>>;
    fn lift(&self) -> Self::Lifted {
        self.map(|c| c.lift())
    }
    fn with_derivative(&self, alpha: T) -> Result<(Circle<T>, Circle<T>), InterpolationError> {
        Spline::with_derivative(self, alpha)
    }
}

/// Why a curvature cannot be computed.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum CurvatureError {
    /// No circle at this α.
    #[error(transparent)]
    Interpolation(#[from] InterpolationError),
    /// The point is the circle's centre, or the circle is degenerate.
    #[error("the point does not determine a position on the circle")]
    NotOnCircle,
    /// The surface is singular there: `N = 0`, or `x_α ∥ x_s`.
    #[error("the surface is singular at this point (no normal or no tangent plane)")]
    Singular,
}

/// The curvature of a swept surface at one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Curvature<T: Real = f64> {
    /// The unit normal `ν` the signs refer to.
    pub normal: E3<T>,
    /// Principal curvatures, `k₁ ≥ k₂`.
    pub k: [T; 2],
    /// Unit principal directions, of `k₁` and `k₂`.
    pub directions: [E3<T>; 2],
    /// Gaussian curvature `K = k₁ k₂`.
    pub gaussian: T,
    /// Mean curvature `H = (k₁ + k₂)/2`.
    pub mean: T,
    /// The circle's unit tangent at the point (the direction of `L_C`; for a ruled surface,
    /// the ruling's).
    pub circle_tangent: E3<T>,
    /// The scale of the relative error of `K`, `H` from rounding:
    /// `ε (1 + r²/|x_α|²) EG/(EG − F²)` — large where the parametrisation degenerates: near
    /// the points every circle of a pencil passes through (there `x_α → 0`), or where `x_α`
    /// turns along the circle. Measured errors stay within `1e-9 + 10³ condition` (the
    /// largest, 432 times it, on a sphere; `tests/tests/geometry/curvature.rs`).
    pub condition: f64,
}

impl<T: Real> Curvature<T> {
    /// The angle (radians, in `[0, π/4]` unless `k₁ = k₂`) between `L_C` (the circle's
    /// tangent) and the nearest principal direction: zero where the paper's postulate holds.
    pub fn circle_angle(&self) -> T {
        let angle = |d: E3<T>| {
            let c = dot(d, self.circle_tangent).abs();
            norm(cross(d, self.circle_tangent)).atan2(c)
        };
        let (a, b) = (angle(self.directions[0]), angle(self.directions[1]));
        if a < b { a } else { b }
    }
}

/// `k₁ − k₂` below this fraction of `|H|` is an umbilic: `√(H² − K)` of a rounding-level
/// difference is about `√ε |H|` (1.5e-8), so closer curvatures cannot be told apart.
const UMBILIC: f64 = 1e-6;

/// `x(α, s)` near `x₀` and the unit normal there, for `α`, `s` of any scalar (duals give the
/// derivatives).
fn point_and_normal<T: Real, F: CircleFamily<T>>(
    family: &F,
    x0: E3<f64>,
    alpha: T,
    s: T,
) -> Result<(E3<T>, E3<T>), CurvatureError> {
    let (circle, circle_dot) = family.with_derivative(alpha)?;
    let (c, n, r) = circle.centre_normal_radius().map_err(|_| CurvatureError::NotOnCircle)?;
    let x0 = x0.map(T::from_f64);
    let d = sub(x0, c);
    let e = unit(sub(d, scale(n, dot(d, n)))).ok_or(CurvatureError::NotOnCircle)?;
    let f = cross(n, e);
    let x = add(c, add(scale(e, r * s.cos()), scale(f, r * s.sin())));
    let normal =
        NormalParts::new(circle, circle_dot, x).normal_line.direction().map_err(|_| CurvatureError::Singular)?;
    Ok((x, normal))
}

/// The curvature at the point `x` of `C_α` of the surface `family` sweeps (module docs).
pub fn curvature<T: Real, F: CircleFamily<T>>(family: &F, alpha: T, x: E3<T>) -> Result<Curvature<T>, CurvatureError> {
    let lifted = family.lift();
    let x0 = x.map(|v| v.to_f64());
    let split = |v: E3<Dual<T>>| (v.map(|d| d.re), v.map(|d| d.du));
    // d/dα at s = 0, and d/ds at α.
    let (xa, na) = point_and_normal(&lifted, x0, Dual::variable(alpha), Dual::constant(T::zero()))?;
    let (xs, ns) = point_and_normal(&lifted, x0, Dual::constant(alpha), Dual::variable(T::zero()))?;
    let ((_, x_a), (nu, nu_a)) = (split(xa), split(na));
    let ((_, x_s), (_, nu_s)) = (split(xs), split(ns));
    let second = [-dot(x_a, nu_a), -dot(x_s, nu_a), -dot(x_s, nu_s)];
    let mut k = from_fundamental_forms(x_a, x_s, nu, second, unit(x_s).ok_or(CurvatureError::Singular)?)?;
    // x_s has length r: the α-speed against it.
    let speed = dot(x_a, x_a) / dot(x_s, x_s);
    k.condition *= 1.0 + 1.0 / speed.to_f64();
    Ok(k)
}

/// The curvature at a point of any surface `x(u, v)` from its tangents `x_u`, `x_v`, unit
/// normal `ν`, and second fundamental form `[L, M, N]` (`L = x_uu · ν`, `M = x_uv · ν`,
/// `N = x_vv · ν`): `K = (LN − M²)/(EG − F²)`, `H = (EN − 2FM + GL)/(2(EG − F²))`, the principal
/// curvatures and directions from the shape operator `I⁻¹ II`; `tangent` is the direction
/// [`Curvature::circle_angle`] measures from (the circle's, or a ruled surface's ruling).
pub fn from_fundamental_forms<T: Real>(
    x_a: E3<T>,
    x_s: E3<T>,
    nu: E3<T>,
    [l, m, n]: [T; 3],
    tangent: E3<T>,
) -> Result<Curvature<T>, CurvatureError> {
    let (e, f, g) = (dot(x_a, x_a), dot(x_a, x_s), dot(x_s, x_s));
    let det = e * g - f * f;
    // (Written so that a NaN determinant is singular too.)
    if det.to_f64().is_nan() || det <= T::epsilon() * e * g {
        return Err(CurvatureError::Singular);
    }
    let gaussian = (l * n - m * m) / det;
    let two = T::from_f64(2.0);
    let mean = (e * n - two * f * m + g * l) / (two * det);
    let root = (mean * mean - gaussian).max(T::zero()).sqrt();
    let k = [mean + root, mean - root];
    // Shape operator S = I⁻¹ II; an eigenvector of k: (S − k) v = 0.
    let s = [[(g * l - f * m) / det, (g * m - f * n) / det], [(e * m - f * l) / det, (e * n - f * m) / det]];
    let direction = |k: T| -> E3<T> {
        let (a, b) = (s[0][0] - k, s[0][1]);
        let (c, d) = (s[1][0], s[1][1] - k);
        // Of the two rows, the longer gives the better-conditioned null vector.
        let (u, v) = if a * a + b * b >= c * c + d * d { (-b, a) } else { (-d, c) };
        let v3 = add(scale(x_a, u), scale(x_s, v));
        unit(v3).unwrap_or(tangent)
    };
    let mut directions = [direction(k[0]), direction(k[1])];
    if root <= T::from_f64(UMBILIC) * mean.abs() {
        // An umbilic: every direction is principal (k₁ and k₂ are known only to about √ε
        // there); report the tangent's and the one across.
        directions = [tangent, cross(nu, tangent)];
    }
    let condition = T::epsilon().to_f64() * (e * g / det).to_f64();
    Ok(Curvature { normal: nu, k, directions, gaussian, mean, circle_tangent: tangent, condition })
}

impl<T: Real> Pair<Circle<T>> {
    /// The curvature of the evolved surface at `x` on `C_α` ([`curvature`]): `K`, `H`, the
    /// principal curvatures and directions, from eq. 6–11's normal and its exact derivatives.
    pub fn curvature(&self, alpha: T, x: E3<T>) -> Result<Curvature<T>, CurvatureError> {
        curvature(self, alpha, x)
    }
}

impl<T: Real> Spline<Circle<T>> {
    /// The curvature of the spline surface at `x` on `C_α` ([`curvature`]).
    pub fn curvature(&self, alpha: T, x: E3<T>) -> Result<Curvature<T>, CurvatureError> {
        curvature(self, alpha, x)
    }
}
