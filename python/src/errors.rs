//! The exceptions of `cga` (`cga._errors`, defined in Python so that every extension built on
//! this crate raises the same classes): every one a `ValueError` (a bad value, never a
//! crash), named by what went wrong, with the Rust error's words.

use pyo3::import_exception;

import_exception!(cga._errors, ValueError);
import_exception!(cga._errors, ShapeError);
import_exception!(cga._errors, GeometryError);
import_exception!(cga._errors, SceneError);
