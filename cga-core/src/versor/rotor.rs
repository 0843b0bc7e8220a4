//! Rotors `R = cos(θ/2) − sin(θ/2) a I3`: from an axis and angle, between two directions,
//! their logarithm and exponential, powers and spherical interpolation.

use super::{VersorError, VersorResult};
use crate::euclid::{E3, dot, norm, unit};
use crate::{Generator, Real, Rotor};

impl<T: Real> Rotor<T> {
    /// The identity rotation, `R = 1`.
    #[inline]
    pub fn identity() -> Self {
        Rotor { s: T::one(), ..Rotor::zero() }
    }

    /// Rotation by `angle` (right-handed) about the axis `axis` through the origin:
    /// `cos(θ/2) − sin(θ/2) â I3`. `ZeroVector` for a zero or non-finite axis.
    pub fn from_axis_angle(axis: E3<T>, angle: T) -> crate::conformal::Result<Self> {
        let a = unit(axis).ok_or(crate::GeometryError::ZeroVector)?;
        let half = angle * T::from_f64(0.5);
        let (c, s) = (half.cos(), half.sin());
        // a I3 = a1 e23 − a2 e13 + a3 e12.
        Ok(Rotor { s: c, e12: -s * a[2], e13: s * a[1], e23: -s * a[0] })
    }

    /// The shortest rotation taking the direction `a` to the direction `b` (any lengths):
    /// the turn by `θ = atan2(|â × b̂|, â · b̂)` about `â × b̂` (equal to `(1 + b̂ â)/|1 + b̂ â|`,
    /// written so that nothing cancels: near-opposite directions keep their small
    /// perpendicular part, which the sum `1 + b̂ â` would lose). The identity for equal
    /// directions; `Antipodal` when `b̂ = −â` to rounding (every perpendicular axis is as
    /// short), `ZeroAxis` for a zero or non-finite direction.
    pub fn between(a: E3<T>, b: E3<T>) -> VersorResult<Self> {
        let a = unit(a).ok_or(VersorError::ZeroAxis)?;
        let b = unit(b).ok_or(VersorError::ZeroAxis)?;
        let (w, c) = (crate::euclid::cross(a, b), dot(a, b));
        let s = norm(w);
        if s <= T::from_f64(8.0) * T::epsilon() && c < T::zero() {
            return Err(VersorError::Antipodal);
        }
        if s == T::zero() {
            return Ok(Self::identity());
        }
        Ok(Self::from_axis_angle(w, s.atan2(c))?)
    }

    /// `R x R̃` for a Euclidean direction or point `x` (rotors fix the origin).
    #[inline]
    pub fn rotate(&self, x: E3<T>) -> E3<T> {
        use crate::Sandwich;
        let v = self.sandwich(crate::Vector { e1: x[0], e2: x[1], e3: x[2], eo: T::zero(), ei: T::zero() });
        [v.e1, v.e2, v.e3]
    }

    /// The angle `θ ∈ [0, 2π)` and unit axis `a` of a unit rotor, `None` for the identity
    /// (`θ = 2 atan2(|⟨R⟩₂|, ⟨R⟩₀)`).
    pub fn angle_axis(&self) -> Option<(T, E3<T>)> {
        let axis = [-self.e23, self.e13, -self.e12];
        let s = norm(axis);
        let a = unit(axis)?;
        Some((T::from_f64(2.0) * s.atan2(self.s), a))
    }

    /// `|R R̃ − 1|`: how far the rotor is from unit norm.
    pub fn unit_defect(&self) -> T {
        (self.s * self.s + self.e12 * self.e12 + self.e13 * self.e13 + self.e23 * self.e23 - T::one()).abs()
    }

    /// `log R`: the generator `B = −½θ a I3` (rotation parts only) with `exp(B) = R`, for a
    /// unit rotor (`NotUnit` otherwise, naming the defect); `φ = θ/2 = atan2(|⟨R⟩₂|, ⟨R⟩₀)`
    /// in `[0, π]`, `B = ⟨R⟩₂ φ / sin φ`. `Antipodal` at `φ = π` (`R = −1`: a full turn about
    /// an undetermined axis; `−R`, the same rotation, has the logarithm 0).
    pub fn log(self) -> VersorResult<Generator<T>> {
        let defect = self.unit_defect();
        if !super::within(defect, super::rigid_tolerance::<T>()) {
            return Err(VersorError::NotUnit { defect: defect.to_f64() });
        }
        let phi = norm([self.e12, self.e13, self.e23]).atan2(self.s);
        let (c1, _) = super::sinc_terms(phi);
        if c1 <= T::epsilon() {
            return Err(VersorError::Antipodal);
        }
        let k = T::one() / c1;
        Ok(Generator { e12: self.e12 * k, e13: self.e13 * k, e23: self.e23 * k, ..Generator::zero() })
    }

    /// `exp(B) = cos φ + B sin φ / φ` (`φ = |B|`) for a generator with rotation parts only;
    /// `NotARotation` when it has translation parts (use [`crate::Motor::exp`]).
    pub fn exp(b: Generator<T>) -> VersorResult<Self> {
        let scale_ = b.to_array().iter().fold(T::one(), |m, x| m.max(x.abs()));
        let tol = T::from_f64(64.0) * T::epsilon() * scale_;
        if [b.e1i, b.e2i, b.e3i].iter().any(|x| !super::within(x.abs(), tol)) {
            return Err(VersorError::NotARotation);
        }
        let phi = norm([b.e12, b.e13, b.e23]);
        let (c1, _) = super::sinc_terms(phi);
        Ok(Rotor { s: phi.cos(), e12: b.e12 * c1, e13: b.e13 * c1, e23: b.e23 * c1 })
    }

    /// `R^t = exp(t log R)`: the rotation by `t θ` about the same axis (following `R`'s own
    /// sign: `R` and `−R` turn alike but their powers differ by a turn of `π t`).
    pub fn pow(self, t: T) -> VersorResult<Self> {
        let b = self.log()?;
        Self::exp(b.scale(t))
    }

    /// Spherical linear interpolation `exp(t log(R1 R̃0)) R0` along the shorter arc (`R1`'s
    /// sign chosen so that `⟨R1 R̃0⟩₀ ≥ 0`): constant angular velocity, `R0` at `t = 0` and
    /// `±R1` (the same rotation) at `t = 1`. `Antipodal` for a relative half turn, where both
    /// arcs are as short.
    pub fn interpolate(r0: &Self, r1: &Self, t: T) -> VersorResult<Self> {
        let mut delta = *r1 * r0.reverse();
        if delta.s < T::zero() {
            delta = -delta;
        }
        if delta.s <= T::from_f64(64.0) * T::epsilon() {
            return Err(VersorError::Antipodal);
        }
        Ok(delta.pow(t)? * *r0)
    }
}
