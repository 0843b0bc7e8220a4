//! Moving many points or objects by one motor: the rotation matrix is formed once, then
//! each point costs nine multiplications and nine additions, as an affine map does.

use super::{VersorError, VersorResult};
use crate::euclid::E3;
use crate::{Motor, Real, Sandwich};

impl<T: Real> Motor<T> {
    /// The columns of the rotation matrix of `R x R̃` for a unit rotor `R = w − (z e12 −
    /// y e13 + x e23)` read as the quaternion `(x, y, z, w)`: the images of `e1, e2, e3`.
    pub fn rotation_matrix(&self) -> [E3<T>; 3] {
        let (w, x, y, z) = (self.s, -self.e23, self.e13, -self.e12);
        let two = T::from_f64(2.0);
        let (xx, yy, zz) = (x * x, y * y, z * z);
        let (xy, xz, yz, wx, wy, wz) = (x * y, x * z, y * z, w * x, w * y, w * z);
        let one = T::one();
        [
            [one - two * (yy + zz), two * (xy + wz), two * (xz - wy)],
            [two * (xy - wz), one - two * (xx + zz), two * (yz + wx)],
            [two * (xz + wy), two * (yz - wx), one - two * (xx + yy)],
        ]
    }

    /// `R x R̃ + t` through the rotation matrix: the same arithmetic as
    /// [`Motor::transform_points`] (bit for bit), for one point.
    pub fn transform_point(&self, x: E3<T>) -> E3<T> {
        apply(&self.rotation_matrix(), &self.translation(), x)
    }

    /// Every point of `points` moved by this rigid motor into `out` (`R x + t`, the rotation
    /// matrix and translation formed once: nine multiply–adds a point, as
    /// `DAffine3::transform_point3`). `Lengths` when the slices differ in length.
    pub fn transform_points(&self, points: &[E3<T>], out: &mut [E3<T>]) -> VersorResult<()> {
        if points.len() != out.len() {
            return Err(VersorError::Lengths { input: points.len(), output: out.len() });
        }
        let (m, t) = (self.rotation_matrix(), self.translation());
        for (o, x) in out.iter_mut().zip(points) {
            *o = apply(&m, &t, *x);
        }
        Ok(())
    }

    /// Every object of `objects` (lines, planes, spheres, circles, …) moved by `M X M̃` into
    /// `out`. `Lengths` when the slices differ in length.
    pub fn transform_objects<X: Copy>(&self, objects: &[X], out: &mut [X]) -> VersorResult<()>
    where
        Self: Sandwich<X, Output = X>,
    {
        if objects.len() != out.len() {
            return Err(VersorError::Lengths { input: objects.len(), output: out.len() });
        }
        for (o, x) in out.iter_mut().zip(objects) {
            *o = self.sandwich(*x);
        }
        Ok(())
    }
}

/// `c0 x + c1 y + c2 z + t`, written out (the order glam's affine map uses).
#[inline(always)]
fn apply<T: Real>([c0, c1, c2]: &[E3<T>; 3], t: &E3<T>, [x, y, z]: E3<T>) -> E3<T> {
    [
        c0[0] * x + c1[0] * y + c2[0] * z + t[0],
        c0[1] * x + c1[1] * y + c2[1] * z + t[1],
        c0[2] * x + c1[2] * y + c2[2] * z + t[2],
    ]
}
