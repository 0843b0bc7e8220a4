//! 3D vector algebra G(3): `e1, e2, e3` orthonormal (`eᵢ² = +1`), the algebra of Euclidean
//! directions and rotations that clifford's `Cl(3)` and kingdon's `Algebra(3)` hold.
//!
//! - A rotor `exp(−½θ B) = cos(θ/2) − sin(θ/2) B` turns vectors by `R x R̃` (`sandwich`), by
//!   `θ` in the plane of the unit bivector `B` (about the axis `n`, `B = n I`, `I = e123`).
//! - `a ^ b` is the oriented plane of two vectors, `a * b = a · b + a ∧ b`.

use crate::Real;

cga_macros::algebra! {
    scalar = crate::Real;
    scalars = [f32, f64];
    lanes = cga_core::simd;
    prelude = f64;
    signature = (3, 0);

    /// All 8 coefficients.
    dense Multivector;

    /// A scalar.
    type Scalar = [s];
    /// A vector: a direction, or a reflection by its plane.
    versor Vector = [grade(1)];
    /// A bivector: an oriented plane, or a rotation's generator.
    type Bivector = [grade(2)];
    /// The pseudoscalar `e123`.
    type Pseudoscalar = [grade(3)];
    /// A rotor: a scalar and a bivector.
    versor Rotor = [s, grade(2)];
    /// Grades 1 and 3: the product of a vector and a rotor.
    versor Odd = [grade(1), grade(3)];
}

impl<T: Real> Rotor<T> {
    /// The rotation by `angle` about the unit `axis` `n`: `cos(θ/2) − sin(θ/2) n I` with
    /// `n I = n₁ e23 − n₂ e13 + n₃ e12`; `None` where the axis is zero or not finite.
    pub fn from_axis_angle(axis: [T; 3], angle: T) -> Option<Self> {
        let norm = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
        if norm <= T::zero() || !norm.is_finite() {
            return None;
        }
        let half = angle * T::from_f64(0.5);
        let s = half.sin() / norm;
        Some(Rotor { s: half.cos(), e23: -s * axis[0], e13: s * axis[1], e12: -s * axis[2] })
    }
}
