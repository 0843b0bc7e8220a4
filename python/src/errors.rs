//! The exceptions of `cga`: every one a `ValueError` (a bad value, never a crash), named by
//! what went wrong, with the Rust error's words.

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;

create_exception!(cga, ValueError, PyValueError, "A value the operation cannot take (a base of every cga error).");
create_exception!(cga, ShapeError, ValueError, "An array of the wrong shape, or two arrays of different lengths.");
create_exception!(
    cga,
    GeometryError,
    ValueError,
    "Geometry that makes no object: a zero radius, collinear points, a null blade."
);
create_exception!(cga, SceneError, ValueError, "A scene file or a picture's options that cannot be rendered.");
