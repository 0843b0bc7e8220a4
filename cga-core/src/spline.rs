//! Blades interpolated through `N ≥ 2` control blades — the paper's Fig. 3 surfaces through
//! several circles, and the splines of circles its references build: a curve on the blades'
//! coefficients, each of its points projected back onto the blades by the square-root
//! projector ([`project_at`], eq. 4–5).
//!
//! Every [`Joining`] is a chain of Bézier segments of degree `d ≤ 3` on the coefficients,
//! consecutive segments sharing an end: `X(α) = Σᵢ Bᵢ,d(t) Pⱼd₊ᵢ` on segment `j` of `m`,
//! `t = α m − j`, `Bᵢ,d` the Bernstein polynomials, and `C_α = K⁻¹ X(α) / ‖…‖`. The
//! parameter `α ∈ [0, 1]` runs over the whole curve; the controls are normalised and each
//! aligned to the one before ([`align`]), as [`Pair`](crate::Pair) does for two.
//!
//! Kochanek–Bartels segments are cubic Hermite segments through consecutive controls `Pᵢ`,
//! written as Bézier segments `Pᵢ, Pᵢ + dᵢ⁺/3, Pᵢ₊₁ − dᵢ₊₁⁻/3, Pᵢ₊₁` with the tangents
//! `dᵢ⁺ = ½(1−τ)[(1+β)(1+γ)(Pᵢ − Pᵢ₋₁) + (1−β)(1−γ)(Pᵢ₊₁ − Pᵢ)]` leaving `Pᵢ` and
//! `dᵢ⁻ = ½(1−τ)[(1+β)(1−γ)(Pᵢ − Pᵢ₋₁) + (1−β)(1+γ)(Pᵢ₊₁ − Pᵢ)]` arriving (`τ` tension, `β`
//! bias, `γ` continuity; all zero is Catmull–Rom, `dᵢ = (Pᵢ₊₁ − Pᵢ₋₁)/2`), with the missing
//! neighbours of the ends reflected, `P₋₁ = 2P₀ − P₁`.

use crate::euclid::norm;
use crate::interpolate::{Interpolable, InterpolationError, accuracy, align, project_at};
use crate::{Dual, Real};

/// How a [`Spline`] joins its controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Joining {
    /// Consecutive controls joined two by two: the two-blade interpolation of
    /// [`Pair`](crate::Pair) on each span, with knots at every control.
    Linear,
    /// Quadratic Bézier segments over `N = 2m + 1` controls: through controls `0, 2, 4, …`,
    /// drawn towards the odd ones.
    Quadratic,
    /// Cubic Bézier segments over `N = 3m + 1` controls: through controls `0, 3, 6, …`.
    Cubic,
    /// Through every control (a Kochanek–Bartels spline; all three zero is Catmull–Rom),
    /// each parameter in `[−1, 1]`.
    KochanekBartels {
        /// `τ`: 1 stops at each control, −1 overshoots.
        tension: f64,
        /// `β`: leans each tangent towards the previous (1) or the next (−1) span.
        bias: f64,
        /// `γ`: 0 keeps the curve C¹ at the controls; otherwise a corner.
        continuity: f64,
    },
}

impl Joining {
    /// Catmull–Rom: Kochanek–Bartels with `τ = β = γ = 0`.
    pub const CATMULL_ROM: Joining = Joining::KochanekBartels { tension: 0.0, bias: 0.0, continuity: 0.0 };

    /// The Bézier degree of the segments.
    pub fn degree(self) -> usize {
        match self {
            Joining::Linear => 1,
            Joining::Quadratic => 2,
            Joining::Cubic | Joining::KochanekBartels { .. } => 3,
        }
    }
}

/// Why controls make no spline.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SplineError {
    /// The wrong number of controls for the joining.
    #[error("{found} control objects: {needs}")]
    Count {
        /// What the joining takes.
        needs: &'static str,
        /// How many were given.
        found: usize,
    },
    /// A Kochanek–Bartels parameter outside `[−1, 1]`.
    #[error("tension, bias and continuity must lie in [-1, 1]")]
    Parameters,
    /// A control cannot be normalised, or the curve cannot be delivered to
    /// [`accuracy`] ([`Spline::condition`]).
    #[error(transparent)]
    Interpolation(#[from] InterpolationError),
}

/// Blades through `N ≥ 2` controls: a chain of Bézier segments on the coefficients, projected.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline<X> {
    /// The controls, normalised and aligned.
    knots: Vec<X>,
    /// The Bézier controls, segment after segment: segment `j` is `controls[j d ..= j d + d]`.
    controls: Vec<X>,
    /// `d`.
    degree: usize,
}

impl<X> Spline<X> {
    /// The spline through (or drawn by) `controls`, joined as `joining` says; each control
    /// normalised and aligned to the one before. Refused if the count does not suit the
    /// joining, a control is null, or [`Spline::condition`] exceeds [`accuracy`].
    pub fn new<T: Real>(controls: &[X], joining: Joining) -> Result<Self, SplineError>
    where
        X: Interpolable<T>,
    {
        let spline = Self::new_unchecked(controls, joining)?;
        let estimate = spline.condition();
        if estimate.is_nan() || estimate > accuracy::<T>() {
            return Err(InterpolationError::IllConditioned { estimate }.into());
        }
        Ok(spline)
    }

    /// [`Spline::new`] without the conditioning check.
    pub fn new_unchecked<T: Real>(controls: &[X], joining: Joining) -> Result<Self, SplineError>
    where
        X: Interpolable<T>,
    {
        let n = controls.len();
        let count = |needs| Err(SplineError::Count { needs, found: n });
        match joining {
            _ if n < 2 => return count("a spline needs at least 2"),
            Joining::Quadratic if n.is_multiple_of(2) => {
                return count("quadratic Bézier segments need 2m + 1 (3, 5, 7, …)");
            }
            Joining::Cubic if n % 3 != 1 => return count("cubic Bézier segments need 3m + 1 (4, 7, 10, …)"),
            Joining::KochanekBartels { tension, bias, continuity }
                if ![tension, bias, continuity].iter().all(|p| (-1.0..=1.0).contains(p)) =>
            {
                return Err(SplineError::Parameters);
            }
            _ => {}
        }
        let mut knots: Vec<X> = Vec::with_capacity(n);
        for c in controls {
            let c = c.try_normalised().ok_or(InterpolationError::Degenerate)?;
            knots.push(match knots.last() {
                Some(&previous) => align(previous, c),
                None => c,
            });
        }
        let controls = match joining {
            Joining::KochanekBartels { tension, bias, continuity } => hermite(&knots, tension, bias, continuity),
            _ => knots.clone(),
        };
        Ok(Spline { knots, controls, degree: joining.degree() })
    }

    /// The same spline with every control mapped by `f` (to another scalar type, say).
    pub fn map<Y>(&self, f: impl Fn(X) -> Y) -> Spline<Y>
    where
        X: Copy,
    {
        Spline {
            knots: self.knots.iter().map(|x| f(*x)).collect(),
            controls: self.controls.iter().map(|x| f(*x)).collect(),
            degree: self.degree,
        }
    }

    /// The controls as given, normalised and aligned.
    pub fn knots(&self) -> &[X] {
        &self.knots
    }

    /// The number of Bézier segments, `m`.
    pub fn segments(&self) -> usize {
        (self.controls.len() - 1) / self.degree
    }

    /// The Bézier degree `d` of the segments.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The Bézier controls of segment `j` (`d + 1` blades).
    pub fn segment(&self, j: usize) -> &[X] {
        &self.controls[j * self.degree..=j * self.degree + self.degree]
    }

    /// The segment holding `α` and the parameter in it, `t = α m − j ∈ [0, 1]` (α = 1 is the
    /// end of the last segment; α outside `[0, 1]` extends the first or last).
    pub fn locate<T: Real>(&self, alpha: T) -> (usize, T) {
        let m = self.segments();
        let u = alpha * T::from_f64(m as f64);
        let j = (u.to_f64().floor().max(0.0) as usize).min(m - 1);
        (j, u - T::from_f64(j as f64))
    }

    /// `X(α)`, the point of the coefficient curve (before projection).
    pub fn coefficients_at<T: Real>(&self, alpha: T) -> X
    where
        X: Interpolable<T>,
    {
        let (j, t) = self.locate(alpha);
        bezier(self.segment(j), t)
    }

    /// `C_α`, the projected blade.
    pub fn at<T: Real>(&self, alpha: T) -> Result<X, InterpolationError>
    where
        X: Interpolable<T>,
    {
        project_at(self.coefficients_at(alpha), alpha)
    }

    /// `(C_α, dC_α/dα)`, the derivative exact: the same code on dual numbers (only the
    /// segment's `d + 1` controls are lifted).
    pub fn with_derivative<T: Real>(&self, alpha: T) -> Result<(X, X), InterpolationError>
    where
        X: Interpolable<T>,
    {
        let (j, _) = self.locate(alpha);
        let m = Dual::constant(T::from_f64(self.segments() as f64));
        let t = Dual::variable(alpha) * m - Dual::constant(T::from_f64(j as f64));
        let p = self.segment(j);
        let x = match *p {
            [a, b] => bezier(&[a.lift(), b.lift()], t),
            [a, b, c] => bezier(&[a.lift(), b.lift(), c.lift()], t),
            _ => bezier(&[p[0].lift(), p[1].lift(), p[2].lift(), p[3].lift()], t),
        };
        let c = project_at(x, Dual::variable(alpha))?;
        Ok(X::split(c))
    }

    /// The relative error to expect of `C_α` from rounding, `ε (1 + ρ)³` with `ρ` the largest
    /// `|cᵢ|/rᵢ` of the controls (see [`Pair::condition`](crate::Pair::condition)).
    pub fn condition<T: Real>(&self) -> f64
    where
        X: Interpolable<T>,
    {
        let rho = (self.knots.iter().filter_map(|k| k.centre_size()))
            .map(|(c, r)| norm(c.map(|x| x.to_f64())) / r.to_f64())
            .fold(0.0, f64::max);
        T::epsilon().to_f64() * (1.0 + rho).powi(3)
    }
}

/// `Σᵢ Bᵢ,d(t) Pᵢ`, the Bézier curve of `d + 1 ≤ 4` controls at `t` (Bernstein weights
/// `(1 − t)^{d−i} tⁱ C(d, i)`); one control is returned as it is.
pub fn bezier<T: Real, X: Interpolable<T>>(p: &[X], t: T) -> X {
    let s = T::one() - t;
    let three = T::from_f64(3.0);
    match p {
        [a, b] => *a * s + *b * t,
        [a, b, c] => *a * (s * s) + *b * (T::from_f64(2.0) * s * t) + *c * (t * t),
        [a, b, c, d] => *a * (s * s * s) + *b * (three * s * s * t) + *c * (three * s * t * t) + *d * (t * t * t),
        // One control (a spline of one segment of degree 0 cannot be built).
        _ => p[0],
    }
}

/// The Bézier controls of the Kochanek–Bartels spline through `p` (see the module docs).
fn hermite<T: Real, X: Interpolable<T>>(p: &[X], tension: f64, bias: f64, continuity: f64) -> Vec<X> {
    let n = p.len();
    let k = |x: f64| T::from_f64(x);
    let (t, b, c) = (tension, bias, continuity);
    // P₋₁ = 2P₀ − P₁ and Pₙ = 2Pₙ₋₁ − Pₙ₋₂: the spans beyond the ends repeat the end spans.
    let span = |i: isize| -> X {
        let i = i.clamp(0, n as isize - 2) as usize;
        p[i + 1] + -p[i]
    };
    let third = 1.0 / 3.0;
    let leaving = |i: usize| {
        span(i as isize - 1) * k(0.5 * (1.0 - t) * (1.0 + b) * (1.0 + c) * third)
            + span(i as isize) * k(0.5 * (1.0 - t) * (1.0 - b) * (1.0 - c) * third)
    };
    let arriving = |i: usize| {
        span(i as isize - 1) * k(0.5 * (1.0 - t) * (1.0 + b) * (1.0 - c) * third)
            + span(i as isize) * k(0.5 * (1.0 - t) * (1.0 - b) * (1.0 + c) * third)
    };
    let mut out = Vec::with_capacity(3 * (n - 1) + 1);
    for i in 0..n - 1 {
        out.push(p[i]);
        out.push(p[i] + leaving(i));
        out.push(p[i + 1] + -arriving(i + 1));
    }
    out.push(p[n - 1]);
    out
}
