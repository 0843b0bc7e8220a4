//! Versors between frames and between objects (clifford's `orthoFrames2Versor`,
//! `tools.g3c.rotor_between_objects` and `motor_between_rounds`):
//! - [`Rotor::between_frames`], [`Motor::between_frames`]: the rotation (and motion) taking
//!   one orthonormal frame to another;
//! - [`VersorBetween::versor_to`]: the conformal versor `V = (1 + γ X₂ X₁) K^(−½)` with
//!   `V X₁ Ṽ = X₂`, for any two normalised objects of one kind (circles of different radii,
//!   spheres, point pairs, lines, planes);
//! - [`Motor::between_circles`], [`Motor::between_spheres`]: the rigid motion that lines
//!   up two rounds' carriers and centres (onto the other exactly when the radii agree).

use super::{VersorError, VersorResult};
use crate::euclid::{E3, cross, dot, sub};
use crate::{Bivector, Circle, Even, Line, Motor, Plane, Real, Rotor, ScalarProduct as _, ScalarQuadvector, Sphere};

/// A frame: an origin and three orthonormal axes (as rows), for [`Motor::between_frames`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<T> {
    /// Where the frame sits.
    pub origin: E3<T>,
    /// Its axes, orthonormal.
    pub axes: [E3<T>; 3],
}

/// The largest `|aᵢ·aⱼ − δᵢⱼ|` and the sign of `det[a₀ a₁ a₂]`; `NotAFrame` beyond `√ε`.
fn orthonormal<T: Real>(axes: &[E3<T>; 3]) -> VersorResult<bool> {
    let mut defect = T::zero();
    for i in 0..3 {
        for j in 0..3 {
            let target = if i == j { T::one() } else { T::zero() };
            let e = (dot(axes[i], axes[j]) - target).abs();
            defect = if e > defect || !e.is_finite() { e } else { defect };
        }
    }
    if !super::within(defect, T::epsilon().sqrt()) {
        return Err(VersorError::NotAFrame { defect: defect.to_f64() });
    }
    Ok(dot(cross(axes[0], axes[1]), axes[2]) > T::zero())
}

impl<T: Real> Rotor<T> {
    /// The rotor taking the orthonormal frame `from` to the orthonormal frame `to`
    /// (`R fromᵢ R̃ = toᵢ`), clifford's `orthoFrames2Versor(to, from)` for a rotation: the
    /// quaternion of the matrix `M = Σᵢ toᵢ fromᵢᵀ` by Shepperd's method (the largest of
    /// `1 + tr M`, `1 + 2Mₖₖ − tr M` under the root, so nothing cancels), as
    /// `R = w − x e23 + y e13 − z e12`, normalised. `NotAFrame` unless both are orthonormal
    /// to `√ε`; `Handedness` when one is right-handed and the other left-handed.
    ///
    /// ```
    /// use cga_core::Rotor;
    /// let from = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let to = [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]; // a quarter turn about z
    /// let r: Rotor = Rotor::between_frames(&from, &to)?;
    /// assert!((r.rotate(from[0])[1] - 1.0).abs() < 1e-15);
    /// # Ok::<(), cga_core::VersorError>(())
    /// ```
    pub fn between_frames(from: &[E3<T>; 3], to: &[E3<T>; 3]) -> VersorResult<Self> {
        if orthonormal(from)? != orthonormal(to)? {
            return Err(VersorError::Handedness);
        }
        let m: [[T; 3]; 3] = core::array::from_fn(|i| {
            core::array::from_fn(|j| (0..3).fold(T::zero(), |s, k| s + to[k][i] * from[k][j]))
        });
        let (one, quarter) = (T::one(), T::from_f64(0.25));
        let trace = m[0][0] + m[1][1] + m[2][2];
        let [w, x, y, z] = if trace > m[0][0] && trace > m[1][1] && trace > m[2][2] {
            let s = (one + trace).sqrt() * T::from_f64(2.0);
            [quarter * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s]
        } else if m[0][0] >= m[1][1] && m[0][0] >= m[2][2] {
            let s = (one + m[0][0] - m[1][1] - m[2][2]).sqrt() * T::from_f64(2.0);
            [(m[2][1] - m[1][2]) / s, quarter * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s]
        } else if m[1][1] >= m[2][2] {
            let s = (one + m[1][1] - m[0][0] - m[2][2]).sqrt() * T::from_f64(2.0);
            [(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, quarter * s, (m[1][2] + m[2][1]) / s]
        } else {
            let s = (one + m[2][2] - m[0][0] - m[1][1]).sqrt() * T::from_f64(2.0);
            [(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, quarter * s]
        };
        let r = Rotor { s: w, e12: -z, e13: y, e23: -x };
        r.try_normalise().ok_or(VersorError::NotAFrame { defect: f64::NAN })
    }

    /// The rotor taking the standard basis `e1, e2, e3` to the orthonormal frame `axes`
    /// (clifford's `orthoFrames2Versor(axes)`): [`Rotor::between_frames`] from the basis.
    pub fn from_frame(axes: &[E3<T>; 3]) -> VersorResult<Self> {
        let (o, i) = (T::zero(), T::one());
        Self::between_frames(&[[i, o, o], [o, i, o], [o, o, i]], axes)
    }
}

impl<T: Real> Motor<T> {
    /// The rigid motion taking the frame `from` to the frame `to`: its origin to theirs and
    /// its axes to theirs, `M = T_{o₂ − R o₁} R` with `R` = [`Rotor::between_frames`] of the
    /// axes (that rotor's errors).
    pub fn between_frames(from: &Frame<T>, to: &Frame<T>) -> VersorResult<Self> {
        let r = Rotor::between_frames(&from.axes, &to.axes)?;
        Ok(Motor::from_rotor_translation(r, sub(to.origin, r.rotate(from.origin))))
    }

    /// The rigid motion that takes circle `a`'s centre to `b`'s and its (oriented) normal to
    /// `b`'s by the shortest turn (clifford's `motor_between_rounds`: the rotor between the
    /// carrier planes, then the translation of the centres; the same motion):
    /// `M = T_{c₂ − R c₁} R`, `R` = [`Rotor::between`]`(n₁, n₂)`. It takes `a` onto `b` when
    /// their radii agree, else onto the circle of `a`'s radius concentric with `b` in its
    /// plane (for a versor onto `b` whatever the radii see [`VersorBetween::versor_to`]).
    /// `Antipodal` for opposite normals (every half turn about a diameter is as short),
    /// `ZeroAxis` for a degenerate circle.
    pub fn between_circles(a: &Circle<T>, b: &Circle<T>) -> VersorResult<Self> {
        let ((c1, n1, _), (c2, n2, _)) = (a.centre_normal_radius()?, b.centre_normal_radius()?);
        let r = Rotor::between(n1, n2)?;
        Ok(Motor::from_rotor_translation(r, sub(c2, r.rotate(c1))))
    }

    /// The translation taking sphere `a`'s centre to `b`'s, `M = T_{c₂ − c₁}` (clifford's
    /// `motor_between_rounds` for spheres): `a` onto `b` when their radii agree.
    /// `ZeroAxis` for a degenerate or flat sphere.
    pub fn between_spheres(a: &Sphere<T>, b: &Sphere<T>) -> VersorResult<Self> {
        let ((c1, _), (c2, _)) = (a.centre_radius()?, b.centre_radius()?);
        Ok(Motor::from_translation(sub(c2, c1)))
    }
}

/// The versor between two objects of one kind, and its action.
pub trait VersorBetween<T: Real>: Sized {
    /// The even versor `V` with `V X₁ Ṽ = X₂` for `X₁ = self`, `X₂ = other` (both
    /// normalised first): `Y = 1 + γ X₂ X₁`, `γ = X₁²` (`±1`), so that `Y X₁ = X₁ + X₂ = X₂ Y`;
    /// `K = Y Ỹ = 2 + γ (X₁ X₂ + X₂ X₁)` is a scalar plus 4-vector that commutes with `Y`,
    /// and `V = Y K^(−½)` (the principal Dorst–Valkenburg root, inverted through `K*`), so
    /// `V Ṽ = 1`. Where `K` has no such root but `−K` has (two disjoint spheres: their dual
    /// vectors' product is hyperbolic) `V = Y (−K)^(−½)` and `V Ṽ = −1`: `V X₁ V⁻¹ = X₂` still, while the plain
    /// sandwich `V X₁ Ṽ` is `−X₂`, the same sphere oppositely oriented (no versor with
    /// `V Ṽ = 1` takes such a sphere onto the other with its orientation). clifford's
    /// `rotor_between_objects`, which normalises the same way. For lines and planes `V` is a
    /// motor; for rounds of different sizes it scales too (a general conformal versor).
    /// `V` takes the normalised `X₁` to the normalised `X₂` (an `X₁` of another weight to
    /// `X₂` of that weight).
    /// `NoVersor` for opposite objects (`X₂ ≈ −X₁`) or where `K` has no real root;
    /// `ZeroAxis` for a zero or null object.
    fn versor_to(&self, other: &Self) -> VersorResult<Even<T>>;

    /// `V X V⁻¹ = V X Ṽ / ⟨V Ṽ⟩₀` for an even versor `V` (as [`VersorBetween::versor_to`]
    /// returns, `V Ṽ = ±1`), the parts of this type's grade kept.
    fn moved_by(&self, v: &Even<T>) -> Self;
}

macro_rules! versor_between {
    ($($ty:ident),*) => {$(
        impl<T: Real> VersorBetween<T> for $ty<T> {
            fn versor_to(&self, other: &Self) -> VersorResult<Even<T>> {
                let x1 = self.try_normalise().ok_or(VersorError::ZeroAxis)?;
                let x2 = other.try_normalise().ok_or(VersorError::ZeroAxis)?;
                let gamma = x1.scalar_product(x1);
                let gamma = if gamma < T::zero() { -T::one() } else { T::one() };
                let y = Even { s: T::one(), ..Even::zero() } + Even::from_storage(&(x2 * x1).to_storage()).scale(gamma);
                let k = ScalarQuadvector::from_storage(&(y * y.reverse()).to_storage());
                // K = s + Q has the principal root where 2a² = s + √(s² − Q²) is positive
                // beyond rounding; where it is not (Y Ỹ < 0: two disjoint spheres, whose
                // dual vectors' product is hyperbolic) V = Y (−K)^(−½), with V Ṽ = −1.
                let q = k.grade4();
                let q2 = (q * q).s;
                let disc = k.s * k.s - q2;
                let twice_a2 = k.s + if disc > T::zero() { disc.sqrt() } else { T::zero() };
                let size = k.s.abs() + q2.abs().sqrt();
                let k = if twice_a2 > T::from_f64(64.0) * T::epsilon() * size { k } else { -k };
                let root = k.try_sqrt().ok_or(VersorError::NoVersor)?;
                let star = root.star();
                let inv = T::one() / (star * root).s;
                if !inv.is_finite() || k.s == T::zero() {
                    return Err(VersorError::NoVersor);
                }
                Ok(Even::from_storage(&(y * star).to_storage()).scale(inv))
            }

            fn moved_by(&self, v: &Even<T>) -> Self {
                let norm = v.scalar_product(v.reverse());
                $ty::from_storage(&(*v * *self * v.reverse()).to_storage()).scale(T::one() / norm)
            }
        }
    )*};
}

versor_between!(Circle, Sphere, Bivector, Line, Plane);
