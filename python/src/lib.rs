//! `cga._cga`, the extension module of the Python package `cga`: a class for each of
//! cga-core's types (one value or a numpy-backed array of them, with the algebra's operators),
//! the geometry on them, pictures of objects (`draw`), and scenes rendered through cga-trace's
//! pipeline. Errors are Python
//! exceptions (`cga.ValueError` and its kinds), never a crash.

mod between;
mod cga2_sta;
mod classes;
mod draw;
mod errors;
mod figure;
mod fit;
mod geometry;
mod kernels;
mod pga;
mod render;
mod threads;
mod toolkit;
mod values;

use pyo3::prelude::*;

pub use classes::{Classes, add_algebra};

/// What `python_algebra!`'s expansion names, in the crate that invokes it.
#[doc(hidden)]
pub mod __private {
    pub use crate::classes::{
        Binary, Classes, Code, Product, Tables, Unary, any_values_of, array, binary, coefficients, floats, item, named,
        narrow, norm_squared, normalised, not_implemented, read, scalars, scaled, sum, unary, widen, widened,
        widened_single, wrap,
    };
    pub use crate::figure::png;
    pub use crate::values::{Algebra, Type, Values};
    pub use cga_core::{ProductKind, UnaryKind};
    pub use numpy::PyArrayDyn;
    pub use pyo3::IntoPyObjectExt;
    pub use pyo3::exceptions::PyTypeError;
    pub use pyo3::prelude::*;
}

/// The module: classes, functions, exceptions.
#[pymodule]
fn _cga(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    classes::register(m)?;
    pga::register(m)?;
    cga2_sta::register(m)?;
    m.add_class::<render::Scene>()?;
    m.add_class::<render::Picture>()?;
    m.add_class::<fit::Fit>()?;
    m.add_function(wrap_pyfunction!(geometry::up, m)?)?;
    m.add_function(wrap_pyfunction!(draw::draw, m)?)?;
    m.add_function(wrap_pyfunction!(geometry::down, m)?)?;
    m.add_function(wrap_pyfunction!(classes::kernels, m)?)?;
    m.add_function(wrap_pyfunction!(classes::wedge, m)?)?;
    m.add_function(wrap_pyfunction!(classes::registry_product, m)?)?;
    m.add_function(wrap_pyfunction!(render::_object_kinds, m)?)?;
    m.add("ValueError", py.get_type::<errors::ValueError>())?;
    m.add("ShapeError", py.get_type::<errors::ShapeError>())?;
    m.add("GeometryError", py.get_type::<errors::GeometryError>())?;
    m.add("SceneError", py.get_type::<errors::SceneError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
