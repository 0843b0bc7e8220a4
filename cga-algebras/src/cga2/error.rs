//! The one error type of 2D CGA's constructors and read-backs.

/// Why a 2D CGA constructor or read-back has no answer; never a non-finite value instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cga2Error {
    /// Two of the points coincide: no circle, line or pair through them.
    CoincidentPoints,
    /// Three points on one line: a line, not a circle (`Circle::line_through` makes it).
    Collinear,
    /// A line (a circle through `ei`) where a centre and radius are needed.
    IsLine,
    /// A circle or pair of imaginary radius (`r² < 0`): no real points.
    Imaginary,
    /// A zero value, or one that is not the kind of object asked for.
    Degenerate,
    /// An input or the result is not finite.
    NonFinite,
}

impl core::fmt::Display for Cga2Error {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            Cga2Error::CoincidentPoints => "cga2: two of the points coincide",
            Cga2Error::Collinear => "cga2: the three points are collinear: a line, not a circle",
            Cga2Error::IsLine => "cga2: a line has no centre or radius",
            Cga2Error::Imaginary => "cga2: an imaginary circle or pair (r² < 0) has no real points",
            Cga2Error::Degenerate => "cga2: zero, or not the object asked for",
            Cga2Error::NonFinite => "cga2: an input or the result is not finite",
        })
    }
}

impl std::error::Error for Cga2Error {}

/// `Ok(x)` when every value is finite, `Err(NonFinite)` otherwise.
pub(crate) fn finite<T: crate::Real, X>(x: X, values: &[T]) -> Result<X, Cga2Error> {
    if values.iter().all(|v| v.is_finite()) { Ok(x) } else { Err(Cga2Error::NonFinite) }
}
