//! `_cga.pga_toolkit`: cga-algebras' PGA toolkit (`pga/*.rs`: motors, screws, closed-form
//! `exp`/`log`/`sqrt`/`pow`, interpolation, normalisation, constructors, distances, angles) on rows of
//! coefficients, for `cga.pga`'s wrappers. Each function takes one row (shape `(k,)`) or `n`
//! rows (`(n, k)`) per argument, broadcast one against many, runs the Rust function on every
//! row (so an array gives the bits of one value at a time) and refuses a row that has no
//! answer by row and name (`GeometryError`, with `PgaError`'s words).

use crate::errors::{GeometryError, ShapeError, ValueError};
use crate::geometry::{Rows, finite};
use cga_algebras::pga::{Line, Motor, PgaError, Plane, Point};
use numpy::{AllowTypeChange, PyArray1, PyArray2, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::IntoPyObjectExt;
use pyo3::prelude::*;

/// Rows of `K` numbers: shape `(K,)` (single) or `(n, K)`; `K = 1` also takes a number or `(n,)`.
pub(crate) fn rows<const K: usize>(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Rows<[f64; K]>> {
    let array = obj
        .extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>()
        .map_err(|_| ShapeError::new_err(format!("{name}: expected numbers of shape ({K},) or (n, {K})")))?;
    let flat: Vec<f64> = array.as_array().iter().copied().collect();
    let single = match array.shape() {
        [] if K == 1 => true,
        [_] if K == 1 => false,
        [k] if *k == K => true,
        [_, k] if *k == K => false,
        shape => return Err(ShapeError::new_err(format!("{name}: shape {shape:?}; give ({K},) or (n, {K})"))),
    };
    finite(name, &flat)?;
    Ok(Rows { rows: flat.chunks(K).map(|c| core::array::from_fn(|i| c[i])).collect(), single })
}

/// The common row count of broadcast arguments (`lens`: each one's rows), and whether all are single.
pub(crate) fn broadcast(lens: &[(usize, bool)]) -> PyResult<(usize, bool)> {
    let n = lens.iter().filter(|(_, s)| !s).map(|(n, _)| *n).max().unwrap_or(1);
    if lens.iter().any(|&(m, s)| !s && m != n) {
        return Err(ShapeError::new_err(format!("arrays of different lengths: {lens:?}")));
    }
    Ok((n, lens.iter().all(|(_, s)| *s)))
}

/// The results as a `(K,)` or `(n, K)` array, the first failure refused by row.
pub(crate) fn output<const K: usize, E: std::fmt::Display>(
    py: Python<'_>,
    what: &str,
    (n, single): (usize, bool),
    f: impl Fn(usize) -> Result<[f64; K], E>,
) -> PyResult<Py<PyAny>> {
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        out.push(f(i).map_err(|e| {
            let at = if single { String::new() } else { format!(" (row {i})") };
            GeometryError::new_err(format!("{what}{at}: {e}"))
        })?);
    }
    if single {
        PyArray1::from_vec(py, out[0].to_vec()).into_py_any(py)
    } else {
        PyArray2::from_vec2(py, &out.iter().map(|r| r.to_vec()).collect::<Vec<_>>())?.into_py_any(py)
    }
}

/// Scalars as `(1,)` rows, out as a number or `(n,)`.
fn numbers(
    py: Python<'_>,
    what: &str,
    shape: (usize, bool),
    f: impl Fn(usize) -> Result<f64, PgaError>,
) -> PyResult<Py<PyAny>> {
    let a = output(py, what, shape, |i| f(i).map(|x| [x]))?;
    let a = a.bind(py).call_method1("reshape", (if shape.1 { vec![] } else { vec![shape.0] },))?;
    if shape.1 { a.call_method0("item")?.into_py_any(py) } else { a.into_py_any(py) }
}

#[pyfunction]
fn rotor(py: Python<'_>, axis: &Bound<'_, PyAny>, angle: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (a, t) = (rows::<3>("axis", axis)?, rows::<1>("angle", angle)?);
    let shape = broadcast(&[(a.rows.len(), a.single), (t.rows.len(), t.single)])?;
    output(py, "rotor", shape, |i| Motor::rotor(a.at(i), t.at(i)[0]).map(Motor::to_array))
}

#[pyfunction]
fn translator(py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let t = rows::<3>("t", t)?;
    let shape = broadcast(&[(t.rows.len(), t.single)])?;
    output(py, "translator", shape, |i| Motor::translator(t.at(i)).map(Motor::to_array))
}

#[pyfunction]
fn screw(
    py: Python<'_>,
    line: &Bound<'_, PyAny>,
    angle: &Bound<'_, PyAny>,
    distance: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let (l, a, d) = (rows::<6>("line", line)?, rows::<1>("angle", angle)?, rows::<1>("distance", distance)?);
    let shape = broadcast(&[(l.rows.len(), l.single), (a.rows.len(), a.single), (d.rows.len(), d.single)])?;
    output(py, "screw", shape, |i| Motor::screw(Line::from_array(l.at(i)), a.at(i)[0], d.at(i)[0]).map(Motor::to_array))
}

#[pyfunction]
fn exp(py: Python<'_>, line: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let l = rows::<6>("line", line)?;
    let shape = broadcast(&[(l.rows.len(), l.single)])?;
    output(py, "exp", shape, |i| Line::from_array(l.at(i)).exp_motor().map(Motor::to_array))
}

#[pyfunction]
fn log(py: Python<'_>, motor: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let m = rows::<8>("motor", motor)?;
    let shape = broadcast(&[(m.rows.len(), m.single)])?;
    output(py, "log", shape, |i| Motor::from_array(m.at(i)).log().map(Line::to_array))
}

#[pyfunction]
fn sqrt(py: Python<'_>, motor: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let m = rows::<8>("motor", motor)?;
    let shape = broadcast(&[(m.rows.len(), m.single)])?;
    output(py, "sqrt", shape, |i| Motor::from_array(m.at(i)).sqrt().map(Motor::to_array))
}

#[pyfunction]
fn normalise(py: Python<'_>, motor: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let m = rows::<8>("motor", motor)?;
    let shape = broadcast(&[(m.rows.len(), m.single)])?;
    output(py, "normalise", shape, |i| Motor::from_array(m.at(i)).renormalise().map(Motor::to_array))
}

#[pyfunction]
fn interpolate(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    t: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let (a, b, t) = (rows::<8>("a", a)?, rows::<8>("b", b)?, rows::<1>("t", t)?);
    let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single), (t.rows.len(), t.single)])?;
    output(py, "interpolate", shape, |i| {
        Motor::interpolate(&Motor::from_array(a.at(i)), &Motor::from_array(b.at(i)), t.at(i)[0]).map(Motor::to_array)
    })
}

#[pyfunction]
fn pow(py: Python<'_>, motor: &Bound<'_, PyAny>, t: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (m, t) = (rows::<8>("motor", motor)?, rows::<1>("t", t)?);
    let shape = broadcast(&[(m.rows.len(), m.single), (t.rows.len(), t.single)])?;
    output(py, "pow", shape, |i| Motor::from_array(m.at(i)).pow(t.at(i)[0]).map(Motor::to_array))
}

#[pyfunction]
fn from_line_pitch(
    py: Python<'_>,
    line: &Bound<'_, PyAny>,
    angle: &Bound<'_, PyAny>,
    pitch: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let (l, a, p) = (rows::<6>("line", line)?, rows::<1>("angle", angle)?, rows::<1>("pitch", pitch)?);
    let shape = broadcast(&[(l.rows.len(), l.single), (a.rows.len(), a.single), (p.rows.len(), p.single)])?;
    output(py, "from_line_pitch", shape, |i| {
        Motor::from_line_pitch(Line::from_array(l.at(i)), a.at(i)[0], p.at(i)[0]).map(Motor::to_array)
    })
}

/// A motor's rotor (8 coefficients) and translation (3) side by side in one row of 11.
#[pyfunction]
fn rotor_translation(py: Python<'_>, motor: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let m = rows::<8>("motor", motor)?;
    let shape = broadcast(&[(m.rows.len(), m.single)])?;
    output(py, "rotor_translation", shape, |i| {
        let (r, t) = Motor::from_array(m.at(i)).rotor_translation()?;
        let r = r.to_array();
        Ok::<[f64; 11], PgaError>(core::array::from_fn(|k| if k < 8 { r[k] } else { t[k - 8] }))
    })
}

/// `angle(kind, a, b)`: `kind` one of `line_line`, `line_plane`, `plane_plane`.
#[pyfunction]
fn angle(py: Python<'_>, kind: &str, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    match kind {
        "line_line" => {
            let (a, b) = (rows::<6>("a", a)?, rows::<6>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "angle", shape, |i| Line::from_array(a.at(i)).angle_to_line(Line::from_array(b.at(i))))
        }
        "line_plane" => {
            let (a, b) = (rows::<6>("a", a)?, rows::<4>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "angle", shape, |i| Line::from_array(a.at(i)).angle_to_plane(Plane::from_array(b.at(i))))
        }
        "plane_plane" => {
            let (a, b) = (rows::<4>("a", a)?, rows::<4>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "angle", shape, |i| Plane::from_array(a.at(i)).angle_to_plane(Plane::from_array(b.at(i))))
        }
        _ => Err(ValueError::new_err(format!("angle: no angle of kind {kind:?}"))),
    }
}

#[pyfunction]
fn line_through(py: Python<'_>, p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (p, q) = (rows::<3>("p", p)?, rows::<3>("q", q)?);
    let shape = broadcast(&[(p.rows.len(), p.single), (q.rows.len(), q.single)])?;
    output(py, "line_through", shape, |i| Line::through(p.at(i), q.at(i)).map(Line::to_array))
}

#[pyfunction]
fn plane_from_normal_distance(py: Python<'_>, n: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (n, d) = (rows::<3>("n", n)?, rows::<1>("d", d)?);
    let shape = broadcast(&[(n.rows.len(), n.single), (d.rows.len(), d.single)])?;
    output(py, "plane_from_normal_distance", shape, |i| {
        Plane::from_normal_distance(n.at(i), d.at(i)[0]).map(Plane::to_array)
    })
}

/// `distance(kind, a, b)`: `kind` one of `point_point`, `point_plane`, `point_line`,
/// `line_line`; the rows are the classes' coefficients.
#[pyfunction]
fn distance(py: Python<'_>, kind: &str, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    match kind {
        "point_point" => {
            let (a, b) = (rows::<4>("a", a)?, rows::<4>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "distance", shape, |i| Point::from_array(a.at(i)).distance_to_point(Point::from_array(b.at(i))))
        }
        "point_plane" => {
            let (a, b) = (rows::<4>("a", a)?, rows::<4>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "distance", shape, |i| Point::from_array(a.at(i)).distance_to_plane(Plane::from_array(b.at(i))))
        }
        "point_line" => {
            let (a, b) = (rows::<4>("a", a)?, rows::<6>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "distance", shape, |i| Point::from_array(a.at(i)).distance_to_line(Line::from_array(b.at(i))))
        }
        "line_line" => {
            let (a, b) = (rows::<6>("a", a)?, rows::<6>("b", b)?);
            let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single)])?;
            numbers(py, "distance", shape, |i| Line::from_array(a.at(i)).distance_to_line(Line::from_array(b.at(i))))
        }
        _ => Err(ValueError::new_err(format!("distance: no distance of kind {kind:?}"))),
    }
}

/// The submodule `_cga.pga_toolkit`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let sub = PyModule::new(m.py(), "pga_toolkit")?;
    sub.add_function(wrap_pyfunction!(rotor, &sub)?)?;
    sub.add_function(wrap_pyfunction!(translator, &sub)?)?;
    sub.add_function(wrap_pyfunction!(screw, &sub)?)?;
    sub.add_function(wrap_pyfunction!(exp, &sub)?)?;
    sub.add_function(wrap_pyfunction!(log, &sub)?)?;
    sub.add_function(wrap_pyfunction!(sqrt, &sub)?)?;
    sub.add_function(wrap_pyfunction!(normalise, &sub)?)?;
    sub.add_function(wrap_pyfunction!(interpolate, &sub)?)?;
    sub.add_function(wrap_pyfunction!(line_through, &sub)?)?;
    sub.add_function(wrap_pyfunction!(plane_from_normal_distance, &sub)?)?;
    sub.add_function(wrap_pyfunction!(distance, &sub)?)?;
    sub.add_function(wrap_pyfunction!(pow, &sub)?)?;
    sub.add_function(wrap_pyfunction!(from_line_pitch, &sub)?)?;
    sub.add_function(wrap_pyfunction!(rotor_translation, &sub)?)?;
    sub.add_function(wrap_pyfunction!(angle, &sub)?)?;
    m.add_submodule(&sub)
}
