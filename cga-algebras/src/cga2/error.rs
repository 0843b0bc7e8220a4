//! The one error type of 2D CGA's constructors and read-backs.

/// Why a 2D CGA constructor or read-back has no answer; never a non-finite value instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Cga2Error {
    /// Two of the points coincide: no circle, line or pair through them.
    #[error("cga2: two of the points coincide")]
    CoincidentPoints,
    /// Three points on one line: a line, not a circle (`Circle::line_through` makes it).
    #[error("cga2: the three points are collinear: a line, not a circle")]
    Collinear,
    /// A line (a circle through `ei`) where a centre and radius are needed.
    #[error("cga2: a line has no centre or radius")]
    IsLine,
    /// A circle or pair of imaginary radius (`r² < 0`): no real points.
    #[error("cga2: an imaginary circle or pair (r² < 0) has no real points")]
    Imaginary,
    /// A zero value, or one that is not the kind of object asked for.
    #[error("cga2: zero, or not the object asked for")]
    Degenerate,
    /// An input or the result is not finite.
    #[error("cga2: an input or the result is not finite")]
    NonFinite,
}

/// `Ok(x)` when every value is finite, `Err(NonFinite)` otherwise.
pub(crate) fn finite<T: crate::Real, X>(x: X, values: &[T]) -> Result<X, Cga2Error> {
    if values.iter().all(|v| v.is_finite()) { Ok(x) } else { Err(Cga2Error::NonFinite) }
}
