//! Conversions between Euclidean points and conformal ones: `[T; 3]` always, glam's `DVec3`
//! and `Vec3` behind the `glam` feature.

use crate::conformal::{GeometryError, down, up};
use crate::euclid::E3;
use crate::{Real, Vector};

impl<T: Real> From<E3<T>> for Vector<T> {
    /// `up(x)`: the conformal point of `x`.
    fn from(x: E3<T>) -> Self {
        up(x)
    }
}

impl<T: Real> Vector<T> {
    /// `down(X)`: the Euclidean point of a conformal point of any weight, `AtInfinity` when
    /// its weight `−X · ei` vanishes.
    pub fn to_point(self) -> Result<E3<T>, GeometryError> {
        down(self)
    }
}

#[cfg(feature = "glam")]
mod glam_vectors {
    use super::*;

    macro_rules! glam_point {
        ($vec:ty, $t:ty) => {
            impl From<$vec> for Vector<$t> {
                /// `up(x)`.
                fn from(x: $vec) -> Self {
                    up(x.to_array())
                }
            }

            impl TryFrom<Vector<$t>> for $vec {
                type Error = GeometryError;
                /// `down(X)`, `AtInfinity` for a point at infinity.
                fn try_from(x: Vector<$t>) -> Result<Self, GeometryError> {
                    x.to_point().map(<$vec>::from_array)
                }
            }
        };
    }

    glam_point!(glam::DVec3, f64);
    glam_point!(glam::Vec3, f32);
}

#[cfg(feature = "glam")]
mod glam_versors {
    use crate::versor::VersorError;
    use crate::{Motor, Rotor};
    use glam::{DAffine3, DMat3, DQuat, DVec3, Quat};

    macro_rules! glam_rotor {
        ($quat:ty, $t:ty) => {
            impl From<Rotor<$t>> for $quat {
                /// `R = cos(θ/2) − sin(θ/2) a I3` ↦ `(a sin(θ/2), cos(θ/2))`: `w = s`,
                /// `(x, y, z) = (−e23, e13, −e12)` (the same rotation, right-handed).
                fn from(r: Rotor<$t>) -> Self {
                    <$quat>::from_xyzw(-r.e23, r.e13, -r.e12, r.s)
                }
            }

            impl From<$quat> for Rotor<$t> {
                /// The inverse of `From<Rotor>`: `s = w`, `e23 = −x`, `e13 = y`, `e12 = −z`.
                fn from(q: $quat) -> Self {
                    Rotor { s: q.w, e12: -q.z, e13: q.y, e23: -q.x }
                }
            }
        };
    }

    glam_rotor!(DQuat, f64);
    glam_rotor!(Quat, f32);

    impl From<Motor<f64>> for (DQuat, DVec3) {
        /// A rigid motor `M = T R` as glam's rotation and translation (`x ↦ q x + t`).
        fn from(m: Motor<f64>) -> Self {
            (m.rotor().into(), DVec3::from_array(m.translation()))
        }
    }

    impl From<(DQuat, DVec3)> for Motor<f64> {
        /// `x ↦ q x + t` as `M = T_t R_q`.
        fn from((q, t): (DQuat, DVec3)) -> Self {
            Motor::from_rotor_translation(q.into(), t.to_array())
        }
    }

    impl From<Motor<f64>> for DAffine3 {
        /// A rigid motor as an affine map: the rotation matrix of its rotor and its
        /// translation (the matrix of [`Motor::transform_point`]).
        fn from(m: Motor<f64>) -> Self {
            let [c0, c1, c2] = m.rotation_matrix();
            DAffine3::from_mat3_translation(
                DMat3::from_cols(DVec3::from(c0), DVec3::from(c1), DVec3::from(c2)),
                DVec3::from(m.translation()),
            )
        }
    }

    impl TryFrom<DAffine3> for Motor<f64> {
        type Error = VersorError;
        /// A rigid affine map (orthonormal, determinant +1, to `rigid_tolerance`) as a
        /// motor; `NotRigid` with the defect `max |AᵀA − 1|` (or `|det − 1|`) otherwise.
        fn try_from(a: DAffine3) -> Result<Self, VersorError> {
            let m = a.matrix3;
            let gram = m.transpose() * m - DMat3::IDENTITY;
            let defect = gram.to_cols_array().iter().fold((m.determinant() - 1.0).abs(), |d, x| d.max(x.abs()));
            if !crate::versor::within(defect, 1e-9) {
                return Err(VersorError::NotRigid { defect });
            }
            Ok(Motor::from((DQuat::from_mat3(&m).normalize(), a.translation)))
        }
    }
}
