//! Everyday constructors and read-backs of the spacetime algebra (`c = 1`, signature `(+, −,
//! −, −)`):
//!
//! - an event or four-vector `t γ0 + x γ1 + y γ2 + z γ3` ([`Vector::new`],
//!   [`Vector::components`]), its interval `v² = t² − x² − y² − z²`;
//! - the four-velocity `γ(1, v)` of a 3-velocity `|v| < 1`, and back;
//! - boosts `exp(−½φ n̂ · (e01, e02, e03)) = cosh(φ/2) − sinh(φ/2) n̂ · (e01, e02, e03)`, which
//!   take the observer `γ0` to `cosh φ γ0 + sinh φ n̂ · γ`: moving along `+n̂` at `tanh φ`
//!   (`e0k² = +1`, and `e0k γ0 = −γk`);
//! - rotations `cos(θ/2) + sin(θ/2) a · (e23, e31, e12)`, right-handed about `a` (`e31 =
//!   −e13`): the opposite sign to G(3)'s, as `γₖ² = −1` turns `γ1 e12 = −γ2`;
//! - the field `F = E + I B` on the relative vectors `σₖ = γₖ γ0` (`σₖ² = 1`, `(I σₖ)² = −1`):
//!   `Eₖ = ⟨F σₖ⟩₀`, `Bₖ = −⟨F I σₖ⟩₀`.

use super::{Bivector, Pseudoscalar, Rotor, Vector};
use crate::Real;

/// Why an STA constructor has no answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum StaError {
    /// A direction or axis of length zero.
    #[error("sta: a direction or axis of length zero")]
    ZeroVector,
    /// A speed `|v| ≥ 1` (or a vector not timelike and future-pointing, read back).
    #[error("sta: a speed of 1 or more, or a vector that is not timelike and future-pointing")]
    NotTimelike,
    /// An input or the result is not finite.
    #[error("sta: an input or the result is not finite")]
    NonFinite,
}

fn finite<T: Real, X>(x: X, values: &[T]) -> Result<X, StaError> {
    if values.iter().all(|v| v.is_finite()) { Ok(x) } else { Err(StaError::NonFinite) }
}

/// `(a / |a|, |a|)`, or `ZeroVector`.
fn unit<T: Real>(a: [T; 3]) -> Result<([T; 3], T), StaError> {
    finite((), &a)?;
    let u = cga_core::euclid::unit(a).ok_or(StaError::ZeroVector)?;
    Ok((u, cga_core::euclid::norm(a)))
}

/// `γₖ`, `k = 0..3`.
fn gamma<T: Real>(k: usize) -> Vector<T> {
    let mut c = [T::zero(); 4];
    c[k] = T::one();
    Vector::new(c)
}

/// `σₖ = γₖ γ0`, `k = 1..3`.
fn sigma<T: Real>(k: usize) -> Bivector<T> {
    let r: Rotor<T> = gamma::<T>(k) * gamma::<T>(0);
    Bivector::try_from(r).unwrap_or_else(|_| unreachable!("γₖ γ0 is a bivector"))
}

impl<T: Real> Vector<T> {
    /// `t γ0 + x γ1 + y γ2 + z γ3`.
    pub fn new([t, x, y, z]: [T; 4]) -> Self {
        Vector { e0: t, e1: x, e2: y, e3: z }
    }

    /// `[t, x, y, z]`.
    pub fn components(self) -> [T; 4] {
        [self.e0, self.e1, self.e2, self.e3]
    }

    /// The squared interval `v² = t² − x² − y² − z²`: positive timelike, negative spacelike.
    pub fn interval(self) -> T {
        self.e0 * self.e0 - self.e1 * self.e1 - self.e2 * self.e2 - self.e3 * self.e3
    }

    /// The four-velocity `γ(1, v)`, `γ = 1/√(1 − v²)`, of a 3-velocity (`c = 1`): `u² = 1`.
    /// `NotTimelike` for `|v| ≥ 1`, `NonFinite` for a non-finite input.
    pub fn from_velocity(v: [T; 3]) -> Result<Self, StaError> {
        finite((), &v)?;
        let v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if v2 >= T::one() {
            return Err(StaError::NotTimelike);
        }
        let g = T::one() / (T::one() - v2).sqrt();
        Ok(Vector::new([g, g * v[0], g * v[1], g * v[2]]))
    }

    /// The 3-velocity `(x, y, z) / t` of a future-pointing timelike vector. `NotTimelike`
    /// otherwise.
    pub fn velocity(self) -> Result<[T; 3], StaError> {
        finite((), &self.components())?;
        if self.e0 <= T::zero() || self.interval() <= T::zero() {
            return Err(StaError::NotTimelike);
        }
        let v = [self.e1 / self.e0, self.e2 / self.e0, self.e3 / self.e0];
        finite(v, &v)
    }
}

impl<T: Real> Rotor<T> {
    /// The boost with rapidity `φ` along `direction` (normalised here): `cosh(φ/2) −
    /// sinh(φ/2) n̂ · (e01, e02, e03)`, taking `γ0` to `cosh φ γ0 + sinh φ n̂ · γ` (velocity
    /// `tanh φ` along `+n̂`) by `R v R̃`. `ZeroVector`, `NonFinite` as named.
    pub fn boost(direction: [T; 3], rapidity: T) -> Result<Self, StaError> {
        let (n, _) = unit(direction)?;
        finite((), &[rapidity])?;
        let half = T::from_f64(0.5) * rapidity;
        let (c, s) = (half.cosh(), -half.sinh());
        let mut r = Rotor::zero();
        r.s = c;
        r.e01 = s * n[0];
        r.e02 = s * n[1];
        r.e03 = s * n[2];
        finite(r, &r.to_array())
    }

    /// The rotation by `angle` (right-handed) about `axis` (normalised here): `cos(θ/2) +
    /// sin(θ/2)(a₁ e23 + a₂ e31 + a₃ e12)` with `e31 = −e13`. `ZeroVector`, `NonFinite` as
    /// named.
    pub fn rotation(axis: [T; 3], angle: T) -> Result<Self, StaError> {
        let (a, _) = unit(axis)?;
        finite((), &[angle])?;
        let half = T::from_f64(0.5) * angle;
        let (c, s) = (half.cos(), half.sin());
        let mut r = Rotor::zero();
        r.s = c;
        r.e23 = s * a[0];
        r.e13 = -s * a[1];
        r.e12 = s * a[2];
        Ok(r)
    }
}

impl<T: Real> Bivector<T> {
    /// The field `F = E + I B`, `E = Eₖ σₖ`, `B = Bₖ σₖ`, `σₖ = γₖ γ0` (Doran and Lasenby's
    /// spelling), `I = e0123`.
    pub fn from_fields(e: [T; 3], b: [T; 3]) -> Self {
        let i = Pseudoscalar { e0123: T::one() };
        let mut f = Bivector::zero();
        for k in 0..3 {
            let s = sigma::<T>(k + 1);
            let is: Bivector<T> = i * s;
            f = f + s.scale(e[k]) + is.scale(b[k]);
        }
        f
    }

    /// `(E, B)`: `Eₖ = ⟨F σₖ⟩₀`, `Bₖ = −⟨F I σₖ⟩₀`.
    pub fn fields(self) -> ([T; 3], [T; 3]) {
        let i = Pseudoscalar { e0123: T::one() };
        let e = core::array::from_fn(|k| (self * sigma::<T>(k + 1)).s);
        let b = core::array::from_fn(|k| {
            let is: Bivector<T> = i * sigma::<T>(k + 1);
            -(self * is).s
        });
        (e, b)
    }
}
