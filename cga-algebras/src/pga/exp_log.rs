//! The exponential of any bivector (a screw generator) and the logarithm of any motor, in
//! closed form, by dual numbers: the pseudoscalar `I = e0123` squares to zero and commutes
//! with the even subalgebra, so `a + b I` behaves as the dual number `a + b ε`.
//!
//! A bivector `B = u + v` (`u` Euclidean, `v` ideal) has `B² = −a² + p I` with `a = |u|`:
//! `B = θ B̂` with the dual angle `θ = a + b I`, `p = −2 a b`, and `B̂² = −1`. So
//!
//! ```text
//! exp(B) = cos θ + (sin θ / θ) B
//!        = cos a + sinc(a) B + ½ p sinc(a) I + ½ p f(a) I u,   f(a) = (sin a − a cos a) / a³,
//! ```
//!
//! and for a unit motor `M = s + B_M + q I` (`M M̃ = 1`, the Study condition included),
//! `a = atan2(|u_M|, s)` and
//!
//! ```text
//! log(M) = (θ / sin θ) B_M = B_M / sinc(a) − q f(a) / sinc(a)³ · I u_M.
//! ```
//!
//! `sinc` and `f` are evaluated by their series near `a = 0` (a pure translation), where the
//! quotients cancel. The maps are klein's `kln::exp` / `kln::log` (`exp_log.hpp`), written here
//! from the dual-number derivation above (`tests/tests/algebra/pga_toolkit.rs` checks them on
//! kingdon's screws).

use super::error::{PgaError, finite};
use super::{GeometricProduct, Line, Motor, Pseudoscalar};
use crate::Real;
use cga_core::euclid::norm;
use cga_core::versor::sinc_terms;

/// The Euclidean part `u` of a line (`e12, e31, e23`).
fn euclidean<T: Real>(l: Line<T>) -> Line<T> {
    Line { e01: T::zero(), e02: T::zero(), e03: T::zero(), ..l }
}

impl<T: Real> Line<T> {
    /// `exp(B)` of any bivector `B`, a screw's generator included, in closed form (see the
    /// module's formula): `cos a + sinc(a) B + ½ p sinc(a) I + ½ p f(a) I u`, with `a = |u|`
    /// (`u` the Euclidean part) and `p I` the grade-4 part of `B²`. A line `L̂` (unit) times
    /// `−θ/2` gives the turn by `θ` about it; `(−θ + δ I) L̂ / 2` the screw of
    /// [`Motor::screw`]. klein: `kln::exp(line)`; kingdon: `B.exp()` (simple `B` only).
    /// The generated `Exp::exp` refuses a screw (`B ∧ B ≠ 0`); this one does not.
    /// `NonFinite` for a non-finite input.
    pub fn exp_motor(self) -> Result<Motor<T>, PgaError> {
        finite((), &self.to_array())?;
        let u = euclidean(self);
        let a = norm(self.direction());
        let p = self.gp(self).e0123;
        let half_p = T::from_f64(0.5) * p;
        // sinc_terms gives ½ f(a).
        let (sa, half_f) = sinc_terms(a);
        let iu: Line<T> = Pseudoscalar { e0123: p * half_f } * u;
        let m = Motor { s: a.cos(), e0123: half_p * sa, ..Motor::zero() } + Motor::from(self.scale(sa) + iu);
        finite(m, &m.to_array())
    }
}

impl<T: Real> Motor<T> {
    /// The principal logarithm of a motor, a screw's included, in closed form (see the
    /// module's formula): `B_M / sinc(a) − q f(a) / sinc(a)³ · I u_M` with `a = atan2(|u_M|,
    /// s) ∈ [0, π]`, after [`renormalise`](Self::renormalise); `exp_motor(log(M)) =
    /// M`. `log(M) = (−θ + δ I) L̂ / 2` for the screw by `θ` and `δ` about `L̂`; a pure
    /// translation `1 + v` gives `v`. klein: `kln::log(motor)`; kingdon has no `log`.
    /// `NotAMotor` for `⟨M M̃⟩₀ = 0`, `FullTurn` for `M = −1` exactly, up to a translation (every
    /// line's half turn twice), `NonFinite` for a non-finite input or result.
    pub fn log(self) -> Result<Line<T>, PgaError> {
        let m = self.renormalise()?;
        let b = Line { e01: m.e01, e02: m.e02, e03: m.e03, e12: m.e12, e31: m.e31, e23: m.e23 };
        let sin_a = norm(b.direction());
        if sin_a == T::zero() && m.s < T::zero() {
            return Err(PgaError::FullTurn);
        }
        let a = sin_a.atan2(m.s);
        let (sa, half_f) = sinc_terms(a);
        let iu: Line<T> = Pseudoscalar { e0123: -m.e0123 * (half_f + half_f) / (sa * sa * sa) } * euclidean(b);
        let l = b.scale(T::one() / sa) + iu;
        finite(l, &l.to_array())
    }

    /// `Mᵗ = exp(t log M)`: the motor a fraction `t` of the way along `M`'s screw (klein:
    /// `kln::exp(t * kln::log(m))`). Errors as [`log`](Self::log).
    pub fn pow(self, t: T) -> Result<Self, PgaError> {
        finite((), &[t])?;
        self.log()?.scale(t).exp_motor()
    }

    /// The square root: `(1 + M) / |1 + M|`, normalised as a motor (the dual number `|1 +
    /// M|` removed, the Study condition kept), of the unit motor `M`; `√M √M = M`, half its
    /// screw. klein: `kln::sqrt(m)` (the same formula); kingdon: `M.sqrt()`, which divides by
    /// the real part of `|1 + M|` only, so agrees for rotations and translations but not for
    /// screws. `FullTurn` for `M = −1` up to a translation, `NotAMotor`, `NonFinite` as
    /// [`renormalise`](Self::renormalise).
    pub fn sqrt(self) -> Result<Self, PgaError> {
        let m = self.renormalise()?;
        let one_plus = Motor { s: m.s + T::one(), ..m };
        match one_plus.renormalise() {
            Err(PgaError::NotAMotor) => Err(PgaError::FullTurn),
            r => r,
        }
    }

    /// The motor a fraction `t` of the way from `a` to `b` along the screw that joins them:
    /// `(b ã)ᵗ a`, with `b ã` taken with a nonnegative scalar part (`M` and `−M` move alike:
    /// the shorter of the two screws). `t = 0` gives `a`, `t = 1` gives `±b`, `t = ½` gives
    /// `√(b ã) a`. klein: `kln::exp(t * kln::log(b * ~a)) * a`; kingdon: `(b * ~a).sqrt() *
    /// a` at `t = ½`. Errors as [`log`](Self::log), of `b ã`. By reference, as cga-core's
    /// `Motor::interpolate`.
    pub fn interpolate(a: &Motor<T>, b: &Motor<T>, t: T) -> Result<Self, PgaError> {
        let a = a.renormalise()?;
        let mut d = (b.renormalise()? * a.reverse()).renormalise()?;
        if d.s < T::zero() {
            d = -d;
        }
        let m = d.pow(t)? * a;
        finite(m, &m.to_array())
    }

    /// The motor normalised as a rigid motion: `M M̃ = 1` exactly, its grade-4 part (the
    /// Study condition) included, so that it is a motor `exp` and `log` take. A motor with a
    /// Study defect still moves points rigidly, but not by the screw its coefficients name:
    /// renormalising moves its image by about the size of the defect. With `M M̃ =
    /// n₀ + n₁ I` (a dual number), `M / √(n₀ + n₁ I) = M (1/√n₀ − n₁/(2 n₀^{3/2}) I)`. klein:
    /// `m.normalize()`; kingdon: `M.normalized()` (dividing by `M.norm()`, a Study number).
    /// The generated `normalise` divides by `√⟨M M̃⟩₀` alone and leaves the Study defect.
    /// `NotAMotor` for `⟨M M̃⟩₀ ≤ 0`, `NonFinite` for a non-finite input or result.
    pub fn renormalise(self) -> Result<Self, PgaError> {
        finite((), &self.to_array())?;
        let n = self.gp(self.reverse());
        let (n0, n1) = (n.s, n.e0123);
        if !n0.is_finite() || !n1.is_finite() {
            return Err(PgaError::NonFinite);
        }
        if n0 <= T::zero() {
            return Err(PgaError::NotAMotor);
        }
        let alpha = T::one() / n0.sqrt();
        let beta = -T::from_f64(0.5) * n1 * alpha * alpha * alpha;
        let m = self.scale(alpha) + self.gp(Pseudoscalar { e0123: beta });
        finite(m, &m.to_array())
    }
}
