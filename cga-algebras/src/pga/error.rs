//! The one error type of the PGA toolkit: what a constructor, read-back or motor function
//! refuses, by name.

/// Why a PGA constructor, read-back or motor function has no answer. Every fallible function
/// of [`crate::pga`]'s toolkit returns it rather than a non-finite value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PgaError {
    /// A rotation axis, normal or direction of length zero.
    #[error("pga: an axis, normal or direction of length zero")]
    ZeroVector,
    /// Two points that coincide (or are not both finite points): no line through them.
    #[error("pga: the two points coincide (or one is at infinity); no line joins them")]
    CoincidentPoints,
    /// A point at infinity (`e123 = 0`) where a position is needed.
    #[error("pga: a point at infinity (e123 = 0) has no position")]
    IdealPoint,
    /// A line at infinity (direction zero) where a direction or distance is needed.
    #[error("pga: a line at infinity has no direction")]
    IdealLine,
    /// A plane at infinity (`e1 = e2 = e3 = 0`) where a normal is needed.
    #[error("pga: a plane at infinity has no normal")]
    IdealPlane,
    /// A motor with `⟨M M̃⟩₀ = 0`: zero, or a sum of ideal terms only.
    #[error("pga: ⟨M M̃⟩₀ = 0: not a motor")]
    NotAMotor,
    /// A motor with no principal logarithm or square root: a full turn `−1` (times a
    /// translation), whose rotation axis is undetermined.
    #[error("pga: a full turn (M = −1 up to a translation) has no principal logarithm or square root")]
    FullTurn,
    /// An input or the result is not finite.
    #[error("pga: an input or the result is not finite")]
    NonFinite,
}

/// `Ok(x)` when every value is finite, `Err(NonFinite)` otherwise.
pub(crate) fn finite<T: crate::Real, X>(x: X, values: &[T]) -> Result<X, PgaError> {
    if values.iter().all(|v| v.is_finite()) { Ok(x) } else { Err(PgaError::NonFinite) }
}
