//! `_cga.cga2_toolkit` and `_cga.sta_toolkit`: cga-algebras' everyday constructors and
//! read-backs of 2D CGA (`cga2/construct.rs`) and the spacetime algebra (`sta/construct.rs`)
//! on rows of numbers, for `cga.cga2`'s and `cga.sta`'s wrappers; rows as `_cga.pga_toolkit`
//! takes them (one `(k,)` or `n` rows `(n, k)`, broadcast), a row with no answer refused by
//! row and name (`GeometryError`).

use crate::pga::{broadcast, output, rows};
use cga_algebras::{cga2, sta};
use pyo3::prelude::*;

#[pyfunction]
fn circle_through(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let (a, b, c) = (rows::<2>("a", a)?, rows::<2>("b", b)?, rows::<2>("c", c)?);
    let shape = broadcast(&[(a.rows.len(), a.single), (b.rows.len(), b.single), (c.rows.len(), c.single)])?;
    output(py, "circle_through", shape, |i| {
        cga2::Circle::through(a.at(i), b.at(i), c.at(i)).map(cga2::Circle::to_array)
    })
}

#[pyfunction]
fn line_through(py: Python<'_>, p: &Bound<'_, PyAny>, q: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (p, q) = (rows::<2>("p", p)?, rows::<2>("q", q)?);
    let shape = broadcast(&[(p.rows.len(), p.single), (q.rows.len(), q.single)])?;
    output(py, "line_through", shape, |i| cga2::Circle::line_through(p.at(i), q.at(i)).map(cga2::Circle::to_array))
}

/// Rows `[cx, cy, r]`.
#[pyfunction]
fn centre_radius(py: Python<'_>, circle: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let c = rows::<4>("circle", circle)?;
    let shape = broadcast(&[(c.rows.len(), c.single)])?;
    output(py, "centre_radius", shape, |i| {
        cga2::Circle::from_array(c.at(i)).centre_radius().map(|(centre, r)| [centre[0], centre[1], r])
    })
}

/// Rows `[ax, ay, bx, by]`.
#[pyfunction]
fn ends(py: Python<'_>, pair: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let p = rows::<6>("pair", pair)?;
    let shape = broadcast(&[(p.rows.len(), p.single)])?;
    output(py, "ends", shape, |i| cga2::PointPair::from_array(p.at(i)).ends().map(|[a, b]| [a[0], a[1], b[0], b[1]]))
}

#[pyfunction]
fn boost(py: Python<'_>, direction: &Bound<'_, PyAny>, rapidity: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (d, r) = (rows::<3>("direction", direction)?, rows::<1>("rapidity", rapidity)?);
    let shape = broadcast(&[(d.rows.len(), d.single), (r.rows.len(), r.single)])?;
    output(py, "boost", shape, |i| sta::Rotor::boost(d.at(i), r.at(i)[0]).map(sta::Rotor::to_array))
}

#[pyfunction]
fn rotation(py: Python<'_>, axis: &Bound<'_, PyAny>, angle: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (a, t) = (rows::<3>("axis", axis)?, rows::<1>("angle", angle)?);
    let shape = broadcast(&[(a.rows.len(), a.single), (t.rows.len(), t.single)])?;
    output(py, "rotation", shape, |i| sta::Rotor::rotation(a.at(i), t.at(i)[0]).map(sta::Rotor::to_array))
}

#[pyfunction]
fn four_velocity(py: Python<'_>, v: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let v = rows::<3>("v", v)?;
    let shape = broadcast(&[(v.rows.len(), v.single)])?;
    output(py, "four_velocity", shape, |i| sta::Vector::from_velocity(v.at(i)).map(sta::Vector::to_array))
}

#[pyfunction]
fn velocity(py: Python<'_>, u: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let u = rows::<4>("u", u)?;
    let shape = broadcast(&[(u.rows.len(), u.single)])?;
    output(py, "velocity", shape, |i| sta::Vector::from_array(u.at(i)).velocity())
}

#[pyfunction]
fn field(py: Python<'_>, e: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let (e, b) = (rows::<3>("e", e)?, rows::<3>("b", b)?);
    let shape = broadcast(&[(e.rows.len(), e.single), (b.rows.len(), b.single)])?;
    output(py, "field", shape, |i| Ok::<_, sta::StaError>(sta::Bivector::from_fields(e.at(i), b.at(i)).to_array()))
}

/// Rows `[E1, E2, E3, B1, B2, B3]`.
#[pyfunction]
fn fields(py: Python<'_>, f: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let f = rows::<6>("f", f)?;
    let shape = broadcast(&[(f.rows.len(), f.single)])?;
    output(py, "fields", shape, |i| {
        let (e, b) = sta::Bivector::from_array(f.at(i)).fields();
        Ok::<_, sta::StaError>([e[0], e[1], e[2], b[0], b[1], b[2]])
    })
}

/// The submodules `_cga.cga2_toolkit` and `_cga.sta_toolkit`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let cga2 = PyModule::new(m.py(), "cga2_toolkit")?;
    cga2.add_function(wrap_pyfunction!(circle_through, &cga2)?)?;
    cga2.add_function(wrap_pyfunction!(line_through, &cga2)?)?;
    cga2.add_function(wrap_pyfunction!(centre_radius, &cga2)?)?;
    cga2.add_function(wrap_pyfunction!(ends, &cga2)?)?;
    m.add_submodule(&cga2)?;
    let sta = PyModule::new(m.py(), "sta_toolkit")?;
    sta.add_function(wrap_pyfunction!(boost, &sta)?)?;
    sta.add_function(wrap_pyfunction!(rotation, &sta)?)?;
    sta.add_function(wrap_pyfunction!(four_velocity, &sta)?)?;
    sta.add_function(wrap_pyfunction!(velocity, &sta)?)?;
    sta.add_function(wrap_pyfunction!(field, &sta)?)?;
    sta.add_function(wrap_pyfunction!(fields, &sta)?)?;
    m.add_submodule(&sta)
}
