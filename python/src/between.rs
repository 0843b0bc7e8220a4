//! Versors between frames and between objects (cga-core's `versor/between.rs`, clifford's
//! `orthoFrames2Versor`, `rotor_between_objects` and `motor_between_rounds`), row by row:
//! `Rotor.between_frames`, `Rotor.from_frame`, `Motor.between_frames`,
//! `Motor.between_circles`, `Motor.between_spheres`, and `X.versor_to(Y)` with its action
//! `X.moved_by(V)` on circles, spheres, point pairs, lines and planes. A row with no such
//! versor is refused by name and row (`GeometryError`).

use crate::classes::{Bivector, Circle, Even, Line, Motor, Plane, Rotor, Sphere};
use crate::errors::ShapeError;
use crate::geometry::{Rows, build, finite, points};
use crate::values::{at, broadcast, length};
use cga_core::VersorBetween;
use cga_core::euclid::E3;
use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// Frames: three orthonormal axes as the rows of a `(3, 3)` array, or `(n, 3, 3)` for n.
fn frames(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Rows<[E3; 3]>> {
    let array = obj.extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>().map_err(|_| {
        ShapeError::new_err(format!("{name}: expected a frame (its axes as the rows of a (3, 3) array) or (n, 3, 3)"))
    })?;
    let single = match array.shape() {
        [3, 3] => true,
        [_, 3, 3] => false,
        shape => return Err(ShapeError::new_err(format!("{name}: shape {shape:?}; give (3, 3) or (n, 3, 3)"))),
    };
    let flat: Vec<f64> = array.as_array().iter().copied().collect();
    finite(name, &flat)?;
    let rows = flat.chunks(9).map(|f| [[f[0], f[1], f[2]], [f[3], f[4], f[5]], [f[6], f[7], f[8]]]).collect();
    Ok(Rows { rows, single })
}

#[pymethods]
impl Rotor {
    /// The rotors taking the orthonormal frames `frm` to `to` (`R frmᵢ R̃ = toᵢ`, each a
    /// (3, 3) array of axes as rows, or (n, 3, 3)): clifford's `orthoFrames2Versor(to, frm)`,
    /// by Shepperd's method on `Σᵢ toᵢ frmᵢᵀ`. Frames not orthonormal to `√ε`, or of
    /// opposite handedness, raise GeometryError.
    #[staticmethod]
    fn between_frames(frm: &Bound<'_, PyAny>, to: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (a, b) = (frames("frm", frm)?, frames("to", to)?);
        let n = length(&[a.rows.len(), b.rows.len()])?;
        Ok(Rotor(build(Self::ty(), n, a.single && b.single, |i| {
            cga_core::Rotor::between_frames(&a.at(i), &b.at(i)).map(|r| r.to_storage())
        })?))
    }

    /// The rotors taking `e1, e2, e3` to the orthonormal frames `axes` ((3, 3) or
    /// (n, 3, 3), axes as rows): clifford's `orthoFrames2Versor(axes)`.
    #[staticmethod]
    fn from_frame(axes: &Bound<'_, PyAny>) -> PyResult<Self> {
        let a = frames("axes", axes)?;
        Ok(Rotor(build(Self::ty(), a.rows.len(), a.single, |i| {
            cga_core::Rotor::from_frame(&a.at(i)).map(|r| r.to_storage())
        })?))
    }
}

#[pymethods]
impl Motor {
    /// The rigid motions taking the frame at `frm_origin` with axes `frm_axes` to the frame
    /// at `to_origin` with axes `to_axes`: `M = T_{o₂ − R o₁} R`, `R` =
    /// `Rotor.between_frames(frm_axes, to_axes)` (its errors). Origins (3,) or (n, 3), axes
    /// (3, 3) or (n, 3, 3), broadcast.
    #[staticmethod]
    fn between_frames(
        frm_origin: &Bound<'_, PyAny>,
        frm_axes: &Bound<'_, PyAny>,
        to_origin: &Bound<'_, PyAny>,
        to_axes: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let (o1, a1) = (points("frm_origin", frm_origin)?, frames("frm_axes", frm_axes)?);
        let (o2, a2) = (points("to_origin", to_origin)?, frames("to_axes", to_axes)?);
        let n = length(&[o1.rows.len(), a1.rows.len(), o2.rows.len(), a2.rows.len()])?;
        let single = o1.single && a1.single && o2.single && a2.single;
        Ok(Motor(build(Self::ty(), n, single, |i| {
            let frm = cga_core::Frame { origin: o1.at(i), axes: a1.at(i) };
            let to = cga_core::Frame { origin: o2.at(i), axes: a2.at(i) };
            cga_core::Motor::between_frames(&frm, &to).map(|m| m.to_storage())
        })?))
    }

    /// The rigid motions taking circle `a`'s centre to `b`'s and its normal to `b`'s by the
    /// shortest turn (clifford's `motor_between_rounds` of circles): `a` onto `b` where the
    /// radii agree. Opposite normals or a degenerate circle raise GeometryError.
    #[staticmethod]
    fn between_circles(a: &Circle, b: &Circle) -> PyResult<Self> {
        let (a, b) = (&a.0, &b.0);
        let n = broadcast(a, b)?;
        Ok(Motor(build(Self::ty(), n, a.single && b.single, |i| {
            let (x, y) = (Circle::typed(a, at(a, i)), Circle::typed(b, at(b, i)));
            cga_core::Motor::between_circles(&x, &y).map(|m| m.to_storage())
        })?))
    }

    /// The translations taking sphere `a`'s centre to `b`'s (clifford's
    /// `motor_between_rounds` of spheres): `a` onto `b` where the radii agree.
    #[staticmethod]
    fn between_spheres(a: &Sphere, b: &Sphere) -> PyResult<Self> {
        let (a, b) = (&a.0, &b.0);
        let n = broadcast(a, b)?;
        Ok(Motor(build(Self::ty(), n, a.single && b.single, |i| {
            let (x, y) = (Sphere::typed(a, at(a, i)), Sphere::typed(b, at(b, i)));
            cga_core::Motor::between_spheres(&x, &y).map(|m| m.to_storage())
        })?))
    }
}

macro_rules! versor_to {
    ($($class:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// The even versors `V` with `V X₁ V⁻¹ = X₂` from these objects to `other`'s
            /// (both normalised; cga-core's `VersorBetween::versor_to`, clifford's
            /// `rotor_between_objects`): `V = (1 + γ X₂ X₁) K^(−½)`, `γ = X₁²`,
            /// `K = 2 + γ (X₁ X₂ + X₂ X₁)`; `V Ṽ = ±1`. A motor for lines and planes, a
            /// conformal versor (scaling too) for rounds of different sizes. Opposite
            /// objects, or a `K` with no real root, raise GeometryError.
            fn versor_to(&self, other: &Self) -> PyResult<Even> {
                let (a, b) = (&self.0, &other.0);
                let n = broadcast(a, b)?;
                Ok(Even(build(Even::ty(), n, a.single && b.single, |i| {
                    let (x, y) = ($class::typed(a, at(a, i)), $class::typed(b, at(b, i)));
                    x.versor_to(&y).map(|v| v.to_storage())
                })?))
            }

            /// These objects moved by the even versors `v` (as `versor_to` gives them):
            /// `V X V⁻¹ = V X Ṽ / ⟨V Ṽ⟩₀`, this class's grade kept.
            fn moved_by(&self, v: &Even) -> PyResult<Self> {
                let (a, b) = (&self.0, &v.0);
                let n = broadcast(a, b)?;
                Ok($class(build(Self::ty(), n, a.single && b.single, |i| {
                    let moved = $class::typed(a, at(a, i)).moved_by(&Even::typed(b, at(b, i)));
                    Ok::<_, String>(moved.to_storage())
                })?))
            }
        }
    )*};
}

versor_to!(Circle, Sphere, Bivector, Line, Plane);
