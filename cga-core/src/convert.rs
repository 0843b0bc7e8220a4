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
