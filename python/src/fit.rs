//! Objects fitted to points by least squares (cga-core's `fit_sphere`, `fit_circle`,
//! `fit_plane`, `fit_line`): `Sphere.fit(points)` …, which `cga.fit_sphere` … name as
//! clifford.tools.g3c does. Points are an array of shape (n, 3) (one object), (m, n, 3) (m
//! objects, n points each), or a `Vector` of conformal points (one object).

use crate::classes::{Circle, Line, Plane, Sphere, Vector, values_of};
use crate::errors::{GeometryError, ShapeError};
use crate::geometry::build;
use cga_core::euclid::E3;
use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// Point sets: every point, how many a set holds, and whether there is one set.
struct Sets {
    points: Vec<E3>,
    per: usize,
    single: bool,
}

/// The point sets `obj` gives, finite (a conformal point down to its Euclidean point).
fn sets(obj: &Bound<'_, PyAny>) -> PyResult<Sets> {
    if let Some(v) = values_of(obj) {
        if v.ty.name != "Vector" {
            return Err(ShapeError::new_err(format!(
                "points: expected conformal points (a Vector), not a {}",
                v.ty.name
            )));
        }
        let points = (0..v.n)
            .map(|i| {
                cga_core::down(Vector::typed(v, i))
                    .map_err(|e| GeometryError::new_err(format!("points (row {i}): {e}")))
            })
            .collect::<PyResult<Vec<E3>>>()?;
        return Ok(Sets { per: points.len(), points, single: true });
    }
    let array = obj.extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>().map_err(|_| {
        ShapeError::new_err("points: expected an array of shape (n, 3) or (m, n, 3), or a Vector of points")
    })?;
    let (per, single) = match *array.shape() {
        [n, 3] => (n, true),
        [_, n, 3] => (n, false),
        ref shape => return Err(ShapeError::new_err(format!("points: shape {shape:?}; give (n, 3) or (m, n, 3)"))),
    };
    let flat: Vec<f64> = array.as_array().iter().copied().collect();
    if let Some(x) = flat.iter().find(|x| !x.is_finite()) {
        return Err(crate::errors::ValueError::new_err(format!("points: {x} (every number must be finite)")));
    }
    Ok(Sets { points: flat.chunks(3).map(|c| [c[0], c[1], c[2]]).collect(), per, single })
}

macro_rules! fit {
    ($($class:ident $fit:ident $what:literal),*) => {$(
        #[pymethods]
        impl $class {
            #[doc = concat!("The ", $what, " fitted to points by least squares (cga-core's `",
                stringify!($fit), "`; docs/COOKBOOK.md): one for points of shape (n, 3) or a ",
                "Vector of them, m for (m, n, 3). Too few points, or points that hold no ",
                "such object, raise GeometryError by name.")]
            #[staticmethod]
            fn fit(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Self> {
                let s = sets(points)?;
                let m = if s.per == 0 { 0 } else { s.points.len() / s.per };
                let values = py.detach(|| {
                    build(Self::ty(), m.max(usize::from(s.single)), s.single, |i| {
                        let set = s.points.get(i * s.per..(i + 1) * s.per).unwrap_or(&[]);
                        cga_core::$fit(set).map(|x| x.to_storage())
                    })
                })?;
                Ok($class(values))
            }
        }
    )*};
}

fit!(Sphere fit_sphere "sphere", Circle fit_circle "circle", Plane fit_plane "plane", Line fit_line "line");
