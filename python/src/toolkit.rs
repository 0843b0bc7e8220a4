//! cga-core's toolkit on the classes, row by row (one value or arrays, broadcast one against
//! many): what a blade is (`classify`), reflections and inversions, distances and angles
//! with Euclidean answers, and the versors' logarithm, exponential and interpolation. A row
//! that has no answer is refused by name and row (`GeometryError`).

use crate::classes::{
    Bivector, Circle, FlatPoint, Generator, Infinity, Line, Motor, Plane, Pseudoscalar, Rotor, Scalar, Sphere, Vector,
    values_of, wrap,
};
use crate::errors::GeometryError;
use crate::geometry::{Rows, build, numbers as params, points};
use crate::values::{Type, Values};
use crate::values::{at, length, row};
use cga_core::classify::{Kind, Reality};
use cga_core::euclid::E3;
use cga_core::{Reflect, classify_storage};
use pyo3::IntoPyObjectExt;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The common number of rows of two values (one broadcasts), and whether the answer is one.
fn rows(a: &Values, b: &Values) -> PyResult<(usize, bool)> {
    Ok((crate::values::broadcast(a, b)?, a.single && b.single))
}

/// The values of `obj` if it is of class `ty`.
fn of<'a>(obj: &'a Bound<'_, PyAny>, ty: &'static Type, what: &str) -> PyResult<&'a Values> {
    values_of(obj)
        .filter(|v| v.ty.name == ty.name)
        .ok_or_else(|| PyTypeError::new_err(format!("{what}: expected a {}", ty.name)))
}

/// Numbers `f(i)` for rows `0..n`: a float for one, an array of n for many.
fn numbers<E: std::fmt::Display>(
    py: Python<'_>,
    what: &str,
    n: usize,
    single: bool,
    f: impl Fn(usize) -> Result<f64, E>,
) -> PyResult<Py<PyAny>> {
    let out: Vec<f64> = (0..n)
        .map(|i| f(i).map_err(|e| GeometryError::new_err(format!("{what} (row {i}): {e}"))))
        .collect::<PyResult<_>>()?;
    if single { out[0].into_py_any(py) } else { numpy::PyArray1::from_vec(py, out).into_py_any(py) }
}

/// A Euclidean triple as a numpy array.
fn e3(py: Python<'_>, x: E3) -> PyResult<Py<PyAny>> {
    numpy::PyArray1::from_vec(py, x.to_vec()).into_py_any(py)
}

/// What row `i` of `v` is, as a dict: `kind` (`"zero"`, `"round"`, `"flat point"`, `"line"`,
/// `"plane"`, `"direction"`) and its Euclidean parameters.
fn kind(py: Python<'_>, v: &Values, i: usize) -> PyResult<Py<PyAny>> {
    let d = PyDict::new(py);
    let k =
        classify_storage(&v.storage(i)).map_err(|e| GeometryError::new_err(format!("{} (row {i}): {e}", v.ty.name)))?;
    match k {
        Kind::Zero => d.set_item("kind", "zero")?,
        Kind::Round { grade, reality, centre, radius_squared, direction } => {
            d.set_item("kind", "round")?;
            d.set_item("grade", grade)?;
            let reality = match reality {
                Reality::Real => "real",
                Reality::Imaginary => "imaginary",
                Reality::Tangent => "tangent",
            };
            d.set_item("reality", reality)?;
            d.set_item("centre", e3(py, centre)?)?;
            d.set_item("radius_squared", radius_squared)?;
            d.set_item("direction", e3(py, direction)?)?;
        }
        Kind::FlatPoint(x) => {
            d.set_item("kind", "flat point")?;
            d.set_item("point", e3(py, x)?)?;
        }
        Kind::Line { point, direction } => {
            d.set_item("kind", "line")?;
            d.set_item("point", e3(py, point)?)?;
            d.set_item("direction", e3(py, direction)?)?;
        }
        Kind::Plane { grade, normal, offset } => {
            d.set_item("kind", "plane")?;
            d.set_item("grade", grade)?;
            d.set_item("normal", e3(py, normal)?)?;
            d.set_item("offset", offset)?;
        }
        Kind::Direction { grade, direction } => {
            d.set_item("kind", "direction")?;
            d.set_item("grade", grade)?;
            d.set_item("direction", e3(py, direction)?)?;
        }
    }
    d.into_py_any(py)
}

/// What each value is (cga-core's `classify`), a dict for one value and a list of them for
/// an array; refused where a value is no blade.
fn classify(py: Python<'_>, v: &Values) -> PyResult<Py<PyAny>> {
    if v.single {
        return kind(py, v, 0);
    }
    let all: Vec<Py<PyAny>> = (0..v.n).map(|i| kind(py, v, i)).collect::<PyResult<_>>()?;
    all.into_py_any(py)
}

/// Reflections and inversions of the classes cga-core reflects.
macro_rules! reflect {
    ($($class:ident => $inverted:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// The mirror image in `plane` (`(−1)^k π X π`, the same class).
            fn reflect_in(&self, py: Python<'_>, plane: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                let (v, p) = (&self.0, of(plane, Plane::ty(), "plane")?);
                let (n, single) = rows(v, p)?;
                let out = build(Self::ty(), n, single, |i| {
                    Self::typed(v, at(v, i)).reflect_in(&Plane::typed(p, at(p, i))).map(|x| x.to_storage())
                })?;
                wrap(py, out)
            }

            /// The image under inversion in `sphere` (`(−1)^k σ X σ⁻¹`): a line or plane not
            /// through the centre becomes a circle or sphere.
            fn invert_in(&self, py: Python<'_>, sphere: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                let (v, s) = (&self.0, of(sphere, Sphere::ty(), "sphere")?);
                let (n, single) = rows(v, s)?;
                let out = build($inverted::ty(), n, single, |i| {
                    let image: cga_core::$inverted<f64> = Self::typed(v, at(v, i)).invert_in(&Sphere::typed(s, at(s, i)))?;
                    Ok::<_, cga_core::GeometryError>(image.to_storage())
                })?;
                wrap(py, out)
            }

            /// The half turn about `line` (the reflection in a line, orientation kept).
            fn reflect_in_line(&self, py: Python<'_>, line: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                let (v, l) = (&self.0, of(line, Line::ty(), "line")?);
                let (n, single) = rows(v, l)?;
                let out = build(Self::ty(), n, single, |i| {
                    Self::typed(v, at(v, i)).reflect_in_line(&Line::typed(l, at(l, i))).map(|x| x.to_storage())
                })?;
                wrap(py, out)
            }

            /// The point reflection `x ↦ 2c − x` through `c` ((3,) or (n, 3)).
            fn reflect_in_point(&self, py: Python<'_>, c: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                let v = &self.0;
                let Rows { rows: cs, single: one } = points("c", c)?;
                let n = length(&[v.n, cs.len()])?;
                let out = build(Self::ty(), n, v.single && one, |i| {
                    Ok::<_, String>(Self::typed(v, at(v, i)).reflect_in_point(cs[row(cs.len(), i)]).to_storage())
                })?;
                wrap(py, out)
            }
        }
    )*};
}

reflect!(Vector => Vector, Bivector => Bivector, Line => Circle, Circle => Circle, Plane => Sphere, Sphere => Sphere);

#[pymethods]
impl Line {
    /// `|(x − p) × d|`: the distance of points `x` from the line(s).
    fn distance_to(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let v = &self.0;
        let Rows { rows: xs, single: one } = points("x", x)?;
        let n = length(&[v.n, xs.len()])?;
        numbers(py, "Line", n, v.single && one, |i| Self::typed(v, at(v, i)).distance_to(xs[row(xs.len(), i)]))
    }

    /// `(on_self, on_other, distance)`: the closest points of two lines and their distance
    /// (for parallel lines, one closest pair of many).
    fn closest_points(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<(Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
        let (v, w) = (&self.0, of(other, Line::ty(), "other")?);
        let (n, single) = rows(v, w)?;
        let all: Vec<_> = (0..n)
            .map(|i| {
                Self::typed(v, at(v, i))
                    .closest_points(&Self::typed(w, at(w, i)))
                    .map_err(|e| GeometryError::new_err(format!("Line (row {i}): {e}")))
            })
            .collect::<PyResult<_>>()?;
        let pts = |f: fn(&cga_core::Closest<f64>) -> E3| points_out(py, all.iter().map(f).collect(), single);
        let d = numbers(py, "Line", n, single, |i| Ok::<_, String>(all[i].distance))?;
        Ok((pts(|c| c.on_self)?, pts(|c| c.on_other)?, d))
    }

    /// The angle between the lines' directions, in `[0, π]`.
    fn angle_to(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let (v, w) = (&self.0, of(other, Line::ty(), "other")?);
        let (n, single) = rows(v, w)?;
        numbers(py, "Line", n, single, |i| Self::typed(v, at(v, i)).angle_to(&Self::typed(w, at(w, i))))
    }
}

#[pymethods]
impl Plane {
    /// `n·x − δ`: signed distances of points `x`, positive on the normal's side.
    fn signed_distance(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let v = &self.0;
        let Rows { rows: xs, single: one } = points("x", x)?;
        let n = length(&[v.n, xs.len()])?;
        numbers(py, "Plane", n, v.single && one, |i| Self::typed(v, at(v, i)).signed_distance(xs[row(xs.len(), i)]))
    }

    /// The angle between the planes' normals, in `[0, π]`.
    fn angle_to(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let (v, w) = (&self.0, of(other, Plane::ty(), "other")?);
        let (n, single) = rows(v, w)?;
        numbers(py, "Plane", n, single, |i| Self::typed(v, at(v, i)).angle_to(&Self::typed(w, at(w, i))))
    }
}

#[pymethods]
impl Sphere {
    /// `|x − c| − r`: signed distances of points `x`, negative inside.
    fn signed_distance(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let v = &self.0;
        let Rows { rows: xs, single: one } = points("x", x)?;
        let n = length(&[v.n, xs.len()])?;
        numbers(py, "Sphere", n, v.single && one, |i| Self::typed(v, at(v, i)).signed_distance(xs[row(xs.len(), i)]))
    }
}

/// Logarithm, exponential and interpolation of a versor class.
macro_rules! versor {
    ($($class:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// The generator `B` with `exp(B)` this versor (the principal logarithm).
            fn log(&self) -> PyResult<Generator> {
                let v = &self.0;
                Ok(Generator(build(Generator::ty(), v.n, v.single, |i| {
                    Self::typed(v, i).log().map(|b| b.to_storage())
                })?))
            }

            /// `exp(B)` of generators (a `Generator`, one or an array).
            #[staticmethod]
            fn exp(b: &Generator) -> PyResult<Self> {
                let v = &b.0;
                Ok($class(build(Self::ty(), v.n, v.single, |i| {
                    exp_of::<cga_core::$class<f64>>(Generator::typed(v, i))
                })?))
            }

            /// `V(t)`: the screw (or rotation) from `a` at `t = 0` to `b` at `t = 1`, at
            /// constant velocity; `t` a number or an array of n.
            #[staticmethod]
            fn interpolate(a: &Self, b: &Self, t: &Bound<'_, PyAny>) -> PyResult<Self> {
                let (va, vb) = (&a.0, &b.0);
                let Rows { rows: ts, single: one } = params("t", t)?;
                let n = length(&[va.n, vb.n, ts.len()])?;
                Ok($class(build(Self::ty(), n, va.single && vb.single && one, |i| {
                    let (x, y) = (Self::typed(va, at(va, i)), Self::typed(vb, at(vb, i)));
                    cga_core::$class::interpolate(&x, &y, ts[row(ts.len(), i)]).map(|x| x.to_storage())
                })?))
            }
        }
    )*};
}

/// `exp(B)` for a motor (any generator) or a rotor (a generator without translation part).
trait Exp: Sized {
    fn exp_of(b: cga_core::Generator<f64>) -> Result<[f64; 32], String>;
}

impl Exp for cga_core::Motor<f64> {
    fn exp_of(b: cga_core::Generator<f64>) -> Result<[f64; 32], String> {
        Ok(cga_core::Motor::exp(b).to_storage())
    }
}

impl Exp for cga_core::Rotor<f64> {
    fn exp_of(b: cga_core::Generator<f64>) -> Result<[f64; 32], String> {
        cga_core::Rotor::exp(b).map(|r| r.to_storage()).map_err(|e| e.to_string())
    }
}

/// `classify()` on every class.
macro_rules! classify {
    ($($class:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// What the value is, with its Euclidean parameters (cga-core's `classify`): a
            /// dict with `kind` (`"zero"`, `"round"`, `"flat point"`, `"line"`, `"plane"`,
            /// `"direction"`) and the parameters of that kind; a list of them for an array.
            fn classify(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                classify(py, &self.0)
            }
        }
    )*};
}

classify!(Vector, Bivector, FlatPoint, Line, Circle, Plane, Sphere, Infinity, Pseudoscalar, Scalar);

fn exp_of<X: Exp>(b: cga_core::Generator<f64>) -> Result<[f64; 32], String> {
    X::exp_of(b)
}

versor!(Motor, Rotor);

/// Points as a numpy array: (3,) for one, (n, 3) for many.
fn points_out(py: Python<'_>, all: Vec<E3>, single: bool) -> PyResult<Py<PyAny>> {
    use numpy::PyArrayMethods;
    let n = all.len();
    let a = numpy::PyArray1::from_vec(py, all.into_iter().flatten().collect());
    if single { a.reshape([3])?.into_py_any(py) } else { a.reshape([n, 3])?.into_py_any(py) }
}

/// Projections of points onto the classes that have a nearest point (cga-core's `Nearest`).
macro_rules! nearest {
    ($($class:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// The points of the object nearest `x` ((3,) or (n, 3)): the orthogonal projection
            /// onto a flat, the radial one onto a round, the nearer point of a pair; refused by
            /// row where it is not unique (a sphere's centre, a circle's axis).
            fn project(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                use cga_core::Nearest;
                let v = &self.0;
                let Rows { rows: xs, single: one } = points("x", x)?;
                let n = length(&[v.n, xs.len()])?;
                let all = (0..n)
                    .map(|i| {
                        Self::typed(v, at(v, i))
                            .nearest_point(xs[row(xs.len(), i)])
                            .map_err(|e| GeometryError::new_err(format!("{} (row {i}): {e}", v.ty.name)))
                    })
                    .collect::<PyResult<Vec<E3>>>()?;
                points_out(py, all, v.single && one)
            }
        }
    )*};
}

nearest!(Line, Plane, Sphere, Circle, Bivector);

#[pymethods]
impl Line {
    /// The line's orthogonal projection onto `plane` (a line in the plane); refused for a
    /// line along the plane's normal, whose projection is a point.
    fn project_onto_plane(&self, plane: &Bound<'_, PyAny>) -> PyResult<Line> {
        let (v, p) = (&self.0, of(plane, Plane::ty(), "plane")?);
        let (n, single) = rows(v, p)?;
        Ok(Line(build(Line::ty(), n, single, |i| {
            Self::typed(v, at(v, i)).project_onto_plane(&Plane::typed(p, at(p, i))).map(|l| l.to_storage())
        })?))
    }
}

#[pymethods]
impl Motor {
    /// The C¹ spline of rigid motions through `poses` (a Motor array of n ≥ 2) at `u` in
    /// `[0, n − 1]` (pose k at u = k), a number or an array: cubic Bézier segments of screw
    /// interpolations whose velocities at the poses are Catmull–Rom's (cga-core's
    /// `MotorSpline`).
    #[staticmethod]
    fn spline(poses: &Self, u: &Bound<'_, PyAny>) -> PyResult<Self> {
        let v = &poses.0;
        let all: Vec<cga_core::Motor<f64>> = (0..v.n).map(|i| Self::typed(v, i)).collect();
        let spline =
            cga_core::MotorSpline::new(&all).map_err(|e| GeometryError::new_err(format!("Motor.spline: {e}")))?;
        let Rows { rows: us, single } = params("u", u)?;
        let last = (v.n - 1) as f64;
        if let Some(bad) = us.iter().find(|u| !(0.0..=last).contains(*u)) {
            return Err(crate::errors::ValueError::new_err(format!(
                "Motor.spline: u = {bad} is outside [0, {last}] (pose k at u = k)"
            )));
        }
        Ok(Motor(build(Self::ty(), us.len(), single, |i| spline.at(us[i]).map(|m| m.to_storage()))?))
    }
}

/// `(on_self, on_other, distance)` of rows of closest pairs, refused by name and row.
fn closest_out(
    py: Python<'_>,
    class: &str,
    all: Vec<Result<cga_core::Closest<f64>, cga_core::GeometryError>>,
    single: bool,
) -> PyResult<(Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
    let all: Vec<cga_core::Closest<f64>> = all
        .into_iter()
        .enumerate()
        .map(|(i, k)| k.map_err(|e| GeometryError::new_err(format!("{class} (row {i}): {e}"))))
        .collect::<PyResult<_>>()?;
    let pts = |f: fn(&cga_core::Closest<f64>) -> E3| points_out(py, all.iter().map(f).collect(), single);
    let d = numbers(py, class, all.len(), single, |i| Ok::<_, String>(all[i].distance))?;
    Ok((pts(|c| c.on_self)?, pts(|c| c.on_other)?, d))
}

#[pymethods]
impl Circle {
    /// `(on_self, on_other, distance)`: the closest points of the circle(s) and the line(s)
    /// (cga-core's `Circle::closest_points_to_line`: the global minimum over the circle, to
    /// rounding; for a line along the axis one pair of many).
    fn closest_points_to_line(
        &self,
        py: Python<'_>,
        line: &Bound<'_, PyAny>,
    ) -> PyResult<(Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
        let (v, w) = (&self.0, of(line, Line::ty(), "line")?);
        let (n, single) = rows(v, w)?;
        let all = (0..n).map(|i| Self::typed(v, at(v, i)).closest_points_to_line(&Line::typed(w, at(w, i)))).collect();
        closest_out(py, "Circle", all, single)
    }

    /// `(on_self, on_other, distance)`: the closest points of two circles (cga-core's
    /// `Circle::closest_points_to_circle`; for coaxial circles one pair of many).
    fn closest_points_to_circle(
        &self,
        py: Python<'_>,
        other: &Bound<'_, PyAny>,
    ) -> PyResult<(Py<PyAny>, Py<PyAny>, Py<PyAny>)> {
        let (v, w) = (&self.0, of(other, Circle::ty(), "other")?);
        let (n, single) = rows(v, w)?;
        let all =
            (0..n).map(|i| Self::typed(v, at(v, i)).closest_points_to_circle(&Self::typed(w, at(w, i)))).collect();
        closest_out(py, "Circle", all, single)
    }
}

macro_rules! average {
    ($($class:ident),*) => {$(
        #[pymethods]
        impl $class {
            /// The average of the rows as one object (cga-core's `average_objects`: each
            /// normalised and oriented like the first, summed, projected back onto the blades
            /// by the square-root projector; clifford.tools.g3c's `average_objects`).
            fn average(&self) -> PyResult<Self> {
                let v = &self.0;
                let all: Vec<_> = (0..v.n).map(|i| Self::typed(v, i)).collect();
                let mean = cga_core::average_objects(&all)
                    .map_err(|e| GeometryError::new_err(format!("{}.average: {e}", stringify!($class))))?;
                Ok($class(build(Self::ty(), 1, true, |_| Ok::<_, String>(mean.to_storage()))?))
            }
        }
    )*};
}

average!(Circle, Sphere, Plane, Line, Bivector);
