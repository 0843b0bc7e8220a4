//! The geometry on the classes: conformal points (`up`, `down`), objects from Euclidean data
//! and their read-backs, versors from axes, angles and vectors, and their motions. Each takes
//! one value or arrays (broadcast, one against many) and runs cga-core's own constructors row
//! by row, so an array gives the bits of one value at a time; a row that makes no object is
//! refused by name and row (`GeometryError`).

use crate::classes::{Circle, Line, Motor, Plane, Rotor, Sphere, Translator, Vector, floats, values_of};
use crate::errors::{GeometryError, ShapeError, ValueError};
use crate::values::{Type, Values, at, length};
use cga_core::euclid::E3;
use numpy::{AllowTypeChange, PyArrayLikeDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::IntoPyObjectExt;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

/// Rows of an argument: points `(3,)`/`(n, 3)` or numbers (a float or `(n,)`).
pub(crate) struct Rows<T> {
    pub(crate) rows: Vec<T>,
    pub(crate) single: bool,
}

impl<T: Copy> Rows<T> {
    pub(crate) fn at(&self, i: usize) -> T {
        if self.rows.len() == 1 { self.rows[0] } else { self.rows[i] }
    }
}

/// Points: shape `(3,)` or `(n, 3)`, finite.
pub(crate) fn points(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Rows<E3>> {
    let array = obj
        .extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>()
        .map_err(|_| ShapeError::new_err(format!("{name}: expected a point [x, y, z] or an array of shape (n, 3)")))?;
    let flat: Vec<f64> = array.as_array().iter().copied().collect();
    let single = match array.shape() {
        [3] => true,
        [_, 3] => false,
        shape => return Err(ShapeError::new_err(format!("{name}: shape {shape:?}; give (3,) or (n, 3)"))),
    };
    finite(name, &flat)?;
    Ok(Rows { rows: flat.chunks(3).map(|c| [c[0], c[1], c[2]]).collect(), single })
}

/// Numbers: a float or shape `(n,)`, finite.
pub(crate) fn numbers(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Rows<f64>> {
    let array = obj
        .extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>()
        .map_err(|_| ShapeError::new_err(format!("{name}: expected a number or an array of shape (n,)")))?;
    let single = match array.shape() {
        [] => true,
        [_] => false,
        shape => return Err(ShapeError::new_err(format!("{name}: shape {shape:?}; give a number or (n,)"))),
    };
    let rows: Vec<f64> = array.as_array().iter().copied().collect();
    finite(name, &rows)?;
    Ok(Rows { rows, single })
}

/// Refuses NaN and ±∞, naming the argument.
pub(crate) fn finite(name: &str, x: &[f64]) -> PyResult<()> {
    match x.iter().find(|v| !v.is_finite()) {
        Some(v) => Err(ValueError::new_err(format!("{name}: {v} (every number must be finite)"))),
        None => Ok(()),
    }
}

/// Values of `ty` from `f(i)` (storage-basis values) for rows `0..n`, the first failure
/// refused by row.
pub(crate) fn build<E: std::fmt::Display>(
    ty: &'static Type,
    n: usize,
    single: bool,
    f: impl Fn(usize) -> Result<[f64; 32], E>,
) -> PyResult<Values> {
    let mut data = Vec::with_capacity(n * ty.storage.len());
    for i in 0..n {
        let s = f(i).map_err(|e| {
            let at = if single { String::new() } else { format!(" (row {i})") };
            GeometryError::new_err(format!("{}{at}: {e}", ty.name))
        })?;
        data.extend(ty.storage.iter().map(|&at| s[at]));
    }
    Ok(Values { ty, data, n, single })
}

/// `f(i)` for each row of `v`, the first failure refused by row.
fn each<R, E: std::fmt::Display>(v: &Values, f: impl Fn(usize) -> Result<R, E>) -> PyResult<Vec<R>> {
    (0..v.n).map(|i| f(i).map_err(|e| GeometryError::new_err(format!("{} (row {i}): {e}", v.ty.name)))).collect()
}

/// Points as a numpy array: `(3,)` for one, `(n, 3)` for many.
fn e3s(py: Python<'_>, single: bool, rows: Vec<E3>) -> PyResult<Py<PyAny>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    let a = numpy::PyArray1::from_vec(py, flat);
    if single { a.reshape([3])?.into_py_any(py) } else { a.reshape([rows.len(), 3])?.into_py_any(py) }
}

/// The values of `obj` (a class of the bindings), for functions that take any.
fn values<'a>(obj: &'a Bound<'_, PyAny>) -> PyResult<&'a Values> {
    values_of(obj).ok_or_else(|| {
        PyTypeError::new_err(format!(
            "expected a cga value, got {}",
            obj.get_type().name().map(|n| n.to_string()).unwrap_or_default()
        ))
    })
}

/// `up(x) = x + ½x² ei + eo`: conformal points of Euclidean ones, shape (3,) or (n, 3).
#[pyfunction]
pub fn up(x: &Bound<'_, PyAny>) -> PyResult<Vector> {
    let p = points("x", x)?;
    let n = p.rows.len();
    Ok(Vector(build(Vector::ty(), n, p.single, |i| Ok::<_, String>(cga_core::up(p.at(i)).to_storage()))?))
}

/// The Euclidean points of conformal ones (weight divided out): shape (3,) or (n, 3); a
/// point of zero weight (a direction, or not a point) is refused.
#[pyfunction]
pub fn down(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let v = values(x)?;
    if v.ty.name != "Vector" {
        return Err(PyTypeError::new_err(format!("down takes a Vector (a conformal point), not a {}", v.ty.name)));
    }
    let out = each(v, |i| cga_core::down(Vector::typed(v, i)))?;
    e3s(py, v.single, out)
}

#[pymethods]
impl Sphere {
    /// Spheres of `centre` (3,)/(n, 3) and `radius` (a number or (n,)).
    #[staticmethod]
    fn from_centre_radius(centre: &Bound<'_, PyAny>, radius: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (c, r) = (points("centre", centre)?, numbers("radius", radius)?);
        let n = length(&[c.rows.len(), r.rows.len()])?;
        let single = c.single && r.single;
        Ok(Sphere(build(Self::ty(), n, single, |i| {
            cga_core::Sphere::from_centre_radius(c.at(i), r.at(i)).map(|s| s.to_storage())
        })?))
    }

    /// The spheres through four points each.
    #[staticmethod]
    fn through(
        a: &Bound<'_, PyAny>,
        b: &Bound<'_, PyAny>,
        c: &Bound<'_, PyAny>,
        d: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let p = [points("a", a)?, points("b", b)?, points("c", c)?, points("d", d)?];
        let n = length(&p.each_ref().map(|x| x.rows.len()))?;
        let single = p.iter().all(|x| x.single);
        Ok(Sphere(build(Self::ty(), n, single, |i| {
            cga_core::Sphere::through(p[0].at(i), p[1].at(i), p[2].at(i), p[3].at(i)).map(|s| s.to_storage())
        })?))
    }

    /// `(centre, radius)`: shape (3,) and a float for one sphere, (n, 3) and (n,) for many.
    fn centre_radius(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, Py<PyAny>)> {
        let v = &self.0;
        let (centres, radii): (Vec<E3>, Vec<f64>) = each(v, |i| Self::typed(v, i).centre_radius())?.into_iter().unzip();
        Ok((e3s(py, v.single, centres)?, floats(py, v, radii)?))
    }
}

#[pymethods]
impl Plane {
    /// Planes through `point` with `normal` (each (3,) or (n, 3)).
    #[staticmethod]
    fn from_point_normal(point: &Bound<'_, PyAny>, normal: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (p, q) = (points("point", point)?, points("normal", normal)?);
        let n = length(&[p.rows.len(), q.rows.len()])?;
        Ok(Plane(build(Self::ty(), n, p.single && q.single, |i| {
            cga_core::Plane::from_point_normal(p.at(i), q.at(i)).map(|x| x.to_storage())
        })?))
    }

    /// The planes through three points each.
    #[staticmethod]
    fn through(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>) -> PyResult<Self> {
        let p = [points("a", a)?, points("b", b)?, points("c", c)?];
        let n = length(&p.each_ref().map(|x| x.rows.len()))?;
        let single = p.iter().all(|x| x.single);
        Ok(Plane(build(Self::ty(), n, single, |i| {
            cga_core::Plane::through(p[0].at(i), p[1].at(i), p[2].at(i)).map(|x| x.to_storage())
        })?))
    }

    /// `(normal, offset)`: the unit normal and the distance of the plane from the origin along it.
    fn normal_offset(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, Py<PyAny>)> {
        let v = &self.0;
        let (normals, offsets): (Vec<E3>, Vec<f64>) =
            each(v, |i| Self::typed(v, i).normal_offset())?.into_iter().unzip();
        Ok((e3s(py, v.single, normals)?, floats(py, v, offsets)?))
    }
}

#[pymethods]
impl Line {
    /// The lines from `a` to `b` (each (3,) or (n, 3)).
    #[staticmethod]
    fn through(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (p, q) = (points("a", a)?, points("b", b)?);
        let n = length(&[p.rows.len(), q.rows.len()])?;
        Ok(Line(build(Self::ty(), n, p.single && q.single, |i| {
            cga_core::Line::through(p.at(i), q.at(i)).map(|x| x.to_storage())
        })?))
    }

    /// The lines through `point` along `direction`.
    #[staticmethod]
    fn from_point_direction(point: &Bound<'_, PyAny>, direction: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (p, d) = (points("point", point)?, points("direction", direction)?);
        let n = length(&[p.rows.len(), d.rows.len()])?;
        Ok(Line(build(Self::ty(), n, p.single && d.single, |i| {
            cga_core::Line::from_point_direction(p.at(i), d.at(i)).map(|x| x.to_storage())
        })?))
    }

    /// The direction (the weight's length: `b − a` for a line through `a` and `b`).
    fn direction(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let v = &self.0;
        e3s(py, v.single, each(v, |i| Self::typed(v, i).direction())?)
    }

    /// The point of the line nearest the origin.
    fn point(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let v = &self.0;
        e3s(py, v.single, each(v, |i| Self::typed(v, i).point())?)
    }
}

#[pymethods]
impl Circle {
    /// The circles through three points each (oriented from `a` to `b` to `c`).
    #[staticmethod]
    fn through(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>) -> PyResult<Self> {
        let p = [points("a", a)?, points("b", b)?, points("c", c)?];
        let n = length(&p.each_ref().map(|x| x.rows.len()))?;
        let single = p.iter().all(|x| x.single);
        Ok(Circle(build(Self::ty(), n, single, |i| {
            cga_core::Circle::through(p[0].at(i), p[1].at(i), p[2].at(i)).map(|x| x.to_storage())
        })?))
    }

    /// Circles of `centre`, `normal` (each (3,) or (n, 3)) and `radius` (a number or (n,)).
    #[staticmethod]
    fn from_centre_normal_radius(
        centre: &Bound<'_, PyAny>,
        normal: &Bound<'_, PyAny>,
        radius: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let (c, m, r) = (points("centre", centre)?, points("normal", normal)?, numbers("radius", radius)?);
        let n = length(&[c.rows.len(), m.rows.len(), r.rows.len()])?;
        let single = c.single && m.single && r.single;
        Ok(Circle(build(Self::ty(), n, single, |i| {
            cga_core::Circle::from_centre_normal_radius(c.at(i), m.at(i), r.at(i)).map(|x| x.to_storage())
        })?))
    }

    /// `(centre, normal, radius)`.
    fn centre_normal_radius(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
        let v = &self.0;
        let parts = each(v, |i| Self::typed(v, i).centre_normal_radius())?;
        let centres = parts.iter().map(|p| p.0).collect();
        let normals = parts.iter().map(|p| p.1).collect();
        let radii = parts.iter().map(|p| p.2).collect();
        Ok((e3s(py, v.single, centres)?, e3s(py, v.single, normals)?, floats(py, v, radii)?))
    }
}

#[pymethods]
impl Rotor {
    /// Rotors turning by `angle` (radians; a number or (n,)) right-handedly about `axis`.
    #[staticmethod]
    fn from_axis_angle(axis: &Bound<'_, PyAny>, angle: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (a, t) = (points("axis", axis)?, numbers("angle", angle)?);
        let n = length(&[a.rows.len(), t.rows.len()])?;
        Ok(Rotor(build(Self::ty(), n, a.single && t.single, |i| {
            cga_core::Rotor::from_axis_angle(a.at(i), t.at(i)).map(|x| x.to_storage())
        })?))
    }
}

#[pymethods]
impl Translator {
    /// Translators by `t` ((3,) or (n, 3)).
    #[staticmethod]
    fn from_vector(t: &Bound<'_, PyAny>) -> PyResult<Self> {
        let v = points("t", t)?;
        Ok(Translator(build(Self::ty(), v.rows.len(), v.single, |i| {
            Ok::<_, String>(cga_core::Translator::from_vector(v.at(i)).to_storage())
        })?))
    }
}

#[pymethods]
impl Motor {
    /// The motors turning by `rotor`, then shifting by `t`: `M = T R`.
    #[staticmethod]
    fn from_rotor_translation(rotor: &Rotor, t: &Bound<'_, PyAny>) -> PyResult<Self> {
        let v = points("t", t)?;
        let r = &rotor.0;
        let n = length(&[r.n, v.rows.len()])?;
        Ok(Motor(build(Self::ty(), n, r.single && v.single, |i| {
            let rot = Rotor::typed(r, at(r, i));
            Ok::<_, String>(cga_core::Motor::from_rotor_translation(rot, v.at(i)).to_storage())
        })?))
    }

    /// Euclidean points moved by the motor(s): `x ↦ R x R̃ + t`, on the points' own data.
    fn move_point(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let p = points("x", x)?;
        let m = &self.0;
        let n = length(&[m.n, p.rows.len()])?;
        let out: Vec<E3> = (0..n).map(|i| Self::typed(m, at(m, i)).move_point(p.at(i))).collect();
        e3s(py, m.single && p.single, out)
    }
}
