//! Objects fitted to points by least squares (cga-core's `fit_sphere`, `fit_circle`,
//! `fit_plane`, `fit_line`): `Sphere.fit(points)` …, which `cga.fit_sphere` … name as
//! clifford.tools.g3c does, and with their stated error (`fit_sphere_with_error` …):
//! `Sphere.fit_with_error(points)` gives a `Fit` of the object and the points' distances from
//! it. Points are an array of shape (n, 3) (one object), (m, n, 3) (m objects, n points each),
//! or a `Vector` of conformal points (one object).

use crate::classes::{Circle, Line, Plane, Sphere, Vector, floats, values_of};
use crate::errors::{GeometryError, ShapeError};
use crate::geometry::build;
use cga_core::euclid::E3;
use numpy::{AllowTypeChange, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::IntoPyObjectExt;
use pyo3::prelude::*;
use pyo3::types::{PyIterator, PyTuple};

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

impl Sets {
    /// How many sets (one where there is a single set, even of no points).
    fn count(&self) -> usize {
        let m = self.points.len().checked_div(self.per).unwrap_or(0);
        m.max(usize::from(self.single))
    }

    /// Set `i`'s points.
    fn set(&self, i: usize) -> &[E3] {
        self.points.get(i * self.per..(i + 1) * self.per).unwrap_or(&[])
    }
}

/// An object fitted to points with its stated error (cga-core's `Fit`): `object`, and the
/// points' Euclidean distances `dᵢ` from it as `rms = √(mean dᵢ²)`, `max = max dᵢ` and
/// `sigma = rms √(n / (n − p))`, the noise's standard deviation estimated from `n` points and
/// the object's `p` parameters (sphere 4, circle 6, plane 3, line 4). Each is a float for one
/// set of points, an array of m for m sets. Unpacks as `object, rms, max, sigma = fit`.
#[pyclass(module = "cga", frozen, name = "Fit")]
pub struct Fit {
    /// The fitted object(s), as `fit` gives them.
    #[pyo3(get)]
    object: Py<PyAny>,
    /// The root-mean-square distance of the points from it.
    #[pyo3(get)]
    rms: Py<PyAny>,
    /// The largest distance of a point from it.
    #[pyo3(get)]
    max: Py<PyAny>,
    /// `rms √(n / (n − p))`: the noise's standard deviation, estimated.
    #[pyo3(get)]
    sigma: Py<PyAny>,
}

#[pymethods]
impl Fit {
    fn __iter__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyIterator>> {
        PyTuple::new(py, [&self.object, &self.rms, &self.max, &self.sigma])?.try_iter()
    }

    fn __len__(&self) -> usize {
        4
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let show = |x: &Py<PyAny>| x.bind(py).repr().map(|r| r.to_string());
        Ok(format!(
            "Fit(object={}, rms={}, max={}, sigma={})",
            show(&self.object)?,
            show(&self.rms)?,
            show(&self.max)?,
            show(&self.sigma)?
        ))
    }
}

macro_rules! fit {
    ($($class:ident $fit:ident $with_error:ident $what:literal),*) => {$(
        #[pymethods]
        impl $class {
            #[doc = concat!("The ", $what, " fitted to points by least squares (cga-core's `",
                stringify!($fit), "`; docs/COOKBOOK.md): one for points of shape (n, 3) or a ",
                "Vector of them, m for (m, n, 3). Too few points, or points that hold no ",
                "such object, raise GeometryError by name.")]
            #[staticmethod]
            fn fit(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Self> {
                let s = sets(points)?;
                let values = py.detach(|| {
                    build(Self::ty(), s.count(), s.single, |i| cga_core::$fit(s.set(i)).map(|x| x.to_storage()))
                })?;
                Ok($class(values))
            }

            #[doc = concat!("`fit` with its stated error (cga-core's `", stringify!($with_error),
                "`): a `Fit` of the ", $what, " and the points' distances from it (rms, max, ",
                "and sigma, the noise's standard deviation estimated). The same points and ",
                "errors as `fit`.")]
            #[staticmethod]
            fn fit_with_error(py: Python<'_>, points: &Bound<'_, PyAny>) -> PyResult<Fit> {
                let s = sets(points)?;
                let fits: Vec<_> = py.detach(|| (0..s.count()).map(|i| cga_core::$with_error(s.set(i))).collect());
                let values = build(Self::ty(), fits.len(), s.single, |i| {
                    fits[i].as_ref().map(|f| f.object.to_storage()).map_err(|e| e.to_string())
                })?;
                // Every row built, so every fit is Ok.
                let column = |part: fn(&cga_core::fit::Fit<_, f64>) -> f64| {
                    fits.iter().flatten().map(part).collect::<Vec<f64>>()
                };
                let (rms, max, sigma) = (column(|f| f.rms), column(|f| f.max), column(|f| f.sigma));
                Ok(Fit {
                    rms: floats(py, &values, rms)?,
                    max: floats(py, &values, max)?,
                    sigma: floats(py, &values, sigma)?,
                    object: $class(values).into_py_any(py)?,
                })
            }
        }
    )*};
}

fit!(
    Sphere fit_sphere fit_sphere_with_error "sphere",
    Circle fit_circle fit_circle_with_error "circle",
    Plane fit_plane fit_plane_with_error "plane",
    Line fit_line fit_line_with_error "line"
);
