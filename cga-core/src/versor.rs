//! Rigid motions as versors: rotors, translators, motors, the exponential and logarithm of
//! their generators, and the rotor taking one line to another. Objects move by the sandwich
//! `X' = V X Ṽ` ([`crate::Sandwich`], generated for every type).
//!
//! Conventions (checked against `tests/golden/rotors.json`): `R = cos(θ/2) − sin(θ/2) a I3`
//! (`I3 = e123`, so the axis `e3` gives the plane `e12`) turns by `θ` right-handedly about
//! the unit axis `a`; `T = 1 − ½ t ei` shifts by `t`; `M = T R` turns, then shifts.

use crate::conformal::{GeometryError, Result};
use crate::euclid::{E3, norm, unit};
use crate::{Bivector, Line, Motor, Real, Rotor, ScalarQuadvector, Translator};

impl<T: Real> Rotor<T> {
    /// Rotation by `angle` (right-handed) about the axis `axis` through the origin.
    pub fn from_axis_angle(axis: E3<T>, angle: T) -> Result<Self> {
        let a = unit(axis).ok_or(GeometryError::ZeroVector)?;
        let half = angle * T::from_f64(0.5);
        let (c, s) = (half.cos(), half.sin());
        // a I3 = a1 e23 − a2 e13 + a3 e12.
        Ok(Rotor { s: c, e12: -s * a[2], e13: s * a[1], e23: -s * a[0] })
    }
}

impl<T: Real> Translator<T> {
    /// `1 − ½ t ei`: translation by `t`.
    pub fn from_vector(t: E3<T>) -> Self {
        let h = T::from_f64(-0.5);
        Translator { s: T::one(), e1i: h * t[0], e2i: h * t[1], e3i: h * t[2] }
    }
}

impl<T: Real> Motor<T> {
    /// `T R`: rotate by `R` about the origin, then translate by `T` (clifford's order).
    pub fn from_rotor_translator(r: Rotor<T>, t: Translator<T>) -> Self {
        t * r
    }

    /// The rotation part `R` of a rigid motor `M = T R`: its scalar and `e_jk` parts.
    #[inline]
    pub fn rotor(&self) -> Rotor<T> {
        Rotor { s: self.s, e12: self.e12, e13: self.e13, e23: self.e23 }
    }

    /// The translation `t` of a rigid motor `M = T R` with unit `R`: `M R̃ = T = 1 − ½ t ei`,
    /// so `t = −2 ⟨M R̃⟩_{e_k i}`. Exact in the coefficients: no conformal point is formed.
    pub fn translation(&self) -> E3<T> {
        let t = *self * self.rotor().reverse();
        let m = T::from_f64(-2.0);
        [m * t.e1i, m * t.e2i, m * t.e3i]
    }

    /// A direction moved by a rigid motor `M = T R` (unit `R`): `R d R̃` (translations do not
    /// move directions).
    pub fn move_direction(&self, d: E3<T>) -> E3<T> {
        use crate::Sandwich;
        let v = self.rotor().sandwich(crate::Vector { e1: d[0], e2: d[1], e3: d[2], eo: T::zero(), ei: T::zero() });
        [v.e1, v.e2, v.e3]
    }

    /// A point moved by a rigid motor `M = T R` (unit `R`): `R x R̃ + t`, the Euclidean part
    /// of `down(M up(x) M̃)` computed without `up(x)`, whose `½|x|²` would cost `ε |x|²` of
    /// the result (an object moved by 1e8 would lose its size) and overflow near 1e154.
    pub fn move_point(&self, x: E3<T>) -> E3<T> {
        let (r, t) = (self.move_direction(x), self.translation());
        [r[0] + t[0], r[1] + t[1], r[2] + t[2]]
    }

    /// `log M`: the generator `B` (rotation and translation parts only) with `exp(B) = M`,
    /// for a normalised motor whose rotation angle is below 2π (half-angle `φ < π`).
    /// Inverts the closed form of [`exp`]: `φ = atan2(|⟨M⟩_rot|, ⟨M⟩₀)`, the rotation part
    /// divided by `sin φ / φ`, the translation part with the `e123i` correction removed.
    pub fn log(self) -> Result<Bivector<T>> {
        let rot = [self.e12, self.e13, self.e23];
        let phi = norm(rot).atan2(self.s);
        let (c1, dc) = sinc_terms(phi);
        if c1 <= T::epsilon() {
            return Err(GeometryError::Degenerate);
        }
        let br = Bivector { e12: self.e12 / c1, e13: self.e13 / c1, e23: self.e23 / c1, ..Bivector::zero() };
        let eps = (self.e123i + self.e123i) / c1;
        let c2 = dc * eps;
        let corr = pseudo_infinity::<T>() * br;
        let bt = |m: T, k: T| (m - c2 * k) / c1;
        Ok(Bivector { e1i: bt(self.e1i, corr.e1i), e2i: bt(self.e2i, corr.e2i), e3i: bt(self.e3i, corr.e3i), ..br })
    }
}

/// `e123i`, which squares to zero and commutes with every motor.
fn pseudo_infinity<T: Real>() -> Motor<T> {
    Motor { e123i: T::one(), ..Motor::zero() }
}

/// `(sin φ / φ, −(φ cos φ − sin φ) / (2φ³))`, by series below `φ = ε^¼` where the closed
/// forms cancel.
fn sinc_terms<T: Real>(phi: T) -> (T, T) {
    let p2 = phi * phi;
    if phi.abs() < T::epsilon().sqrt().sqrt() {
        let c1 = T::one() - p2 / T::from_f64(6.0);
        let dc = T::from_f64(1.0 / 6.0) - p2 / T::from_f64(60.0);
        return (c1, dc);
    }
    let (s, c) = (phi.sin(), phi.cos());
    (s / phi, -(phi * c - s) / (T::from_f64(2.0) * p2 * phi))
}

/// Why an exponential is not a motor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum VersorError {
    /// The bivector has `e1o, e2o, e3o` or `eoi` parts: it generates more than a rigid motion.
    #[error("the bivector is not the generator of a rigid motion (it has eo parts)")]
    NotRigid,
    /// `1 + L2 L1` has no normalising square root (the lines are anti-parallel).
    #[error("no rotor takes the first line to the second this way (anti-parallel lines)")]
    NoRotor,
}

/// `exp(B)` for the generator `B` of a rigid motion (parts `e12, e13, e23, e1i, e2i, e3i`).
/// With `B² = −φ² + ε e123i` (`e123i` nilpotent and central here), the series sums to
/// `exp B = cos φ + (sin φ/2φ) ε e123i + (sin φ/φ) B − ((φ cos φ − sin φ)/2φ³) ε e123i B`.
/// `exp(−½θ a I3)` is the rotor of [`Rotor::from_axis_angle`]; `exp(−½ t ∧ ei)` the
/// translator by `t`.
pub fn exp<T: Real>(b: Bivector<T>) -> core::result::Result<Motor<T>, VersorError> {
    let scale_ = b.to_array().iter().fold(T::one(), |m, x| if x.abs() > m { x.abs() } else { m });
    let tol = T::from_f64(64.0) * T::epsilon() * scale_;
    if [b.e1o, b.e2o, b.e3o, b.eoi].iter().any(|x| x.abs() > tol) {
        return Err(VersorError::NotRigid);
    }
    let b = Motor { e12: b.e12, e13: b.e13, e23: b.e23, e1i: b.e1i, e2i: b.e2i, e3i: b.e3i, ..Motor::zero() };
    let sq = b * b;
    let phi = if sq.s < T::zero() { (-sq.s).sqrt() } else { T::zero() };
    let eps = sq.e123i;
    let (c1, dc) = sinc_terms(phi);
    let half_c1 = c1 * T::from_f64(0.5);
    let c2 = dc * eps;
    Ok(Motor { s: phi.cos(), e123i: half_c1 * eps, ..Motor::zero() }
        + b.scale(c1)
        + (pseudo_infinity::<T>() * b).scale(c2))
}

/// The rotor taking `l1` to `l2` (`R l1 R̃ = l2`) by the shortest motion:
/// `R = (1 + L2 L1) K^(−½)`, `K = (1 + L2 L1)(1 + L2 L1)~ = 2 + L2 L1 + L1 L2`, a scalar plus
/// `e123i`, inverted through its square root as in interpolation. Both lines normalised.
pub fn rotor_between_lines<T: Real>(l1: Line<T>, l2: Line<T>) -> core::result::Result<Motor<T>, VersorError> {
    let (l1, l2) = (l1.try_normalise().ok_or(VersorError::NoRotor)?, l2.try_normalise().ok_or(VersorError::NoRotor)?);
    let y = Motor { s: T::one(), ..Motor::zero() } + l2 * l1;
    let k = ScalarQuadvector::from_storage(&(y * y.reverse()).to_storage());
    let root = k.try_sqrt().ok_or(VersorError::NoRotor)?;
    let star = root.star();
    let inv = T::one() / (star * root).s;
    if !inv.is_finite() {
        return Err(VersorError::NoRotor);
    }
    Ok(Motor::from_storage(&(y * star).to_storage()).scale(inv))
}
