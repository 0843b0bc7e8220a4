//! A user's own algebra in Python: the quaternions as G(0,2) (`e1² = e2² = −1`, so that
//! `i = e1`, `j = e2`, `k = e12` obey Hamilton's `i² = j² = k² = ijk = −1`), declared with
//! `algebra!` and bound by `cga_python::python_algebra!`: its classes take numpy arrays and
//! have the operators and methods of `cga`'s own, on the generated code.
//!
//! ```python
//! import quaternions as q
//! i, j = q.Vector([1.0, 0.0]), q.Vector([0.0, 1.0])
//! (i * j).array  # the Bivector k: [1.0]
//! ```

use pyo3::prelude::*;

/// The algebra, declared as any user declares one.
pub mod g02 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        scalars = [f64];
        lanes = cga_core::simd;
        signature = (0, 2);

        /// All 4 coefficients.
        dense Multivector;

        /// A scalar.
        type Scalar = [s];
        /// A pure quaternion of `i` and `j`.
        type Vector = [grade(1)];
        /// `k = e12`.
        type Bivector = [grade(2)];
        /// A quaternion `w + x i + y j + z k`; unit ones rotate.
        versor Quaternion = [s, e1, e2, e12];
    }
}

cga_python::python_algebra!(
    /// The quaternions' classes, in the Python module `quaternions`.
    classes, "quaternions", crate::g02; Scalar, Vector, Bivector, Quaternion; dense Multivector;
    covered by Scalar, Vector, Bivector
);

/// The extension module: the algebra's classes.
#[pymodule]
fn quaternions(m: &Bound<'_, PyModule>) -> PyResult<()> {
    cga_python::add_algebra(m, &classes::CLASSES)
}
