//! The scalar the generated types are generic over.

use core::fmt::Debug;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// A real number as the generated code needs it: field arithmetic, ordering, a square root.
///
/// Implemented for `f32`, `f64` and [`crate::Dual`] (exact first derivatives); implement
/// it for an instrumented or higher-precision type to run every generated product on it.
pub trait Real:
    Copy
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The larger of the two (`self` when they are equal or unordered).
    #[inline]
    fn max(self, other: Self) -> Self {
        if other > self { other } else { self }
    }
    /// Additive identity.
    fn zero() -> Self;
    /// Multiplicative identity.
    fn one() -> Self;
    /// A constant, rounded to this type.
    fn from_f64(x: f64) -> Self;
    /// The value as `f64` (for a dual number: its real part).
    fn to_f64(self) -> f64;
    /// `√x`.
    fn sqrt(self) -> Self;
    /// `|x|`.
    fn abs(self) -> Self;
    /// Neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// The machine epsilon of the type's precision (for a dual number: of its parts).
    fn epsilon() -> Self;
    /// `sin x`.
    fn sin(self) -> Self;
    /// `cos x`.
    fn cos(self) -> Self;
    /// The angle of the point `(x, self)`, in `(−π, π]`.
    fn atan2(self, x: Self) -> Self;
}

macro_rules! impl_real {
    ($($t:ty),*) => {$(
        impl Real for $t {
            #[inline]
            fn zero() -> Self { 0.0 }
            #[inline]
            fn one() -> Self { 1.0 }
            #[inline]
            fn from_f64(x: f64) -> Self { x as $t }
            #[inline]
            fn to_f64(self) -> f64 { self as f64 }
            #[inline]
            fn sqrt(self) -> Self { <$t>::sqrt(self) }
            #[inline]
            fn abs(self) -> Self { <$t>::abs(self) }
            #[inline]
            fn is_finite(self) -> bool { <$t>::is_finite(self) }
            #[inline]
            fn epsilon() -> Self { <$t>::EPSILON }
            #[inline]
            fn sin(self) -> Self { <$t>::sin(self) }
            #[inline]
            fn cos(self) -> Self { <$t>::cos(self) }
            #[inline]
            fn atan2(self, x: Self) -> Self { <$t>::atan2(self, x) }
        }
    )*};
}

impl_real!(f32, f64);
