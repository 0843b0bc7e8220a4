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
    /// `eˣ`.
    fn exp(self) -> Self;
    /// `ln x`, the natural logarithm.
    fn ln(self) -> Self;
    /// `sinh x`. The default sums `x + x³/3! + … + x¹³/13!` for `|x| < ½` (where
    /// `(eˣ − e⁻ˣ)/2` would cancel; the next term is below `2⁻⁵⁴ |x|`) and takes
    /// `(eˣ − e⁻ˣ)/2` above.
    #[inline]
    fn sinh(self) -> Self {
        let half = Self::from_f64(0.5);
        if self.abs() < half {
            let x2 = self * self;
            let mut term = self;
            let mut sum = self;
            for k in [2.0, 4.0, 6.0, 8.0, 10.0, 12.0] {
                term = term * x2 / Self::from_f64(k * (k + 1.0));
                sum = sum + term;
            }
            sum
        } else {
            let e = self.exp();
            (e - Self::one() / e) * half
        }
    }
    /// `cosh x = (eˣ + e⁻ˣ)/2` (no cancellation: both terms are positive).
    #[inline]
    fn cosh(self) -> Self {
        let e = self.exp();
        (e + Self::one() / e) * Self::from_f64(0.5)
    }
    /// `ln(1 + x)`, accurate for small `x`: with `u = 1 + x` rounded, `ln u · x / (u − 1)`
    /// (Goldberg's correction: the rounding of `u` cancels in the quotient), `x` when `u = 1`.
    #[inline]
    fn ln_1p(self) -> Self {
        let u = Self::one() + self;
        if u == Self::one() { self } else { u.ln() * self / (u - Self::one()) }
    }
    /// The smallest positive normal number of the type's precision (below it, products lose
    /// digits to underflow).
    #[inline]
    fn min_positive() -> Self {
        Self::from_f64(f64::MIN_POSITIVE)
    }
    /// `2^e` for the binary exponent `e` of `self` (`|self| = m 2^e`, `1 ≤ m < 2`), or 1 for
    /// zero and non-finite values: a scale that brings `self` near 1 exactly, since dividing
    /// by a power of two only changes the exponent. The default is 1 (no rescaling), which
    /// is always correct but leaves types without it the range of their squares.
    #[inline]
    fn binade(self) -> Self {
        Self::one()
    }
}

/// `2^e` for the exponent of a finite nonzero `x` (subnormals included), 1 otherwise.
fn binade_f64(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 1.0;
    }
    let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if exponent == 0 {
        // Subnormal: scale up by 2^54 first (exactly), then back.
        return binade_f64(x * 2f64.powi(54)) * 2f64.powi(-54);
    }
    f64::from_bits(((exponent as u64) << 52) & 0x7ff0_0000_0000_0000)
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
            #[inline]
            fn exp(self) -> Self { <$t>::exp(self) }
            #[inline]
            fn ln(self) -> Self { <$t>::ln(self) }
            #[inline]
            fn sinh(self) -> Self { <$t>::sinh(self) }
            #[inline]
            fn cosh(self) -> Self { <$t>::cosh(self) }
            #[inline]
            fn ln_1p(self) -> Self { <$t>::ln_1p(self) }
            #[inline]
            fn min_positive() -> Self { <$t>::MIN_POSITIVE }
            #[inline]
            // f32 exponents are those of the f64 it widens to (exact both ways).
            fn binade(self) -> Self { binade_f64(self as f64) as $t }
        }
    )*};
}

impl_real!(f32, f64);

/// Comparisons and choices made lane by lane: what code written once for one value and for a
/// packet of lanes ([`crate::simd::F64x4`]) needs where the lanes' paths may differ. For one
/// value a mask is a `bool` and [`Select::select`] is `if`; for lanes it is a truth value per
/// lane and the choice is made in each (no branch). [`Real`]'s own comparisons hold only where
/// every lane agrees; these do not.
pub trait Select: Real {
    /// One truth value per lane (`bool` for one value).
    type Mask: Copy
        + core::ops::BitAnd<Output = Self::Mask>
        + core::ops::BitOr<Output = Self::Mask>
        + core::ops::Not<Output = Self::Mask>;
    /// `self < other`, lane by lane (false where either is NaN).
    fn lt(self, other: Self) -> Self::Mask;
    /// `self ≤ other`, lane by lane (false where either is NaN).
    fn le(self, other: Self) -> Self::Mask;
    /// Neither infinite nor NaN, lane by lane.
    fn finite(self) -> Self::Mask;
    /// `if_true` where `mask` holds, `if_false` elsewhere, lane by lane.
    fn select(mask: Self::Mask, if_true: Self, if_false: Self) -> Self;
    /// Whether `mask` holds in any lane.
    fn any(mask: Self::Mask) -> bool;
    /// Whether `mask` holds in every lane.
    fn all(mask: Self::Mask) -> bool;

    /// The smaller of the two, lane by lane, as `f64::min` takes it: `other` where `self` is
    /// NaN.
    #[inline(always)]
    fn min_lanes(self, other: Self) -> Self {
        Self::select(self.lt(other), self, other)
    }

    /// The larger of the two, lane by lane, as `f64::max` takes it: `other` where `self` is
    /// NaN.
    #[inline(always)]
    fn max_lanes(self, other: Self) -> Self {
        Self::select(other.lt(self), self, other)
    }
}

macro_rules! impl_select {
    ($($t:ty),*) => {$(
        impl Select for $t {
            type Mask = bool;
            #[inline(always)]
            fn lt(self, other: Self) -> bool { self < other }
            #[inline(always)]
            fn le(self, other: Self) -> bool { self <= other }
            #[inline(always)]
            fn finite(self) -> bool { <$t>::is_finite(self) }
            #[inline(always)]
            fn select(mask: bool, if_true: Self, if_false: Self) -> Self { if mask { if_true } else { if_false } }
            #[inline(always)]
            fn any(mask: bool) -> bool { mask }
            #[inline(always)]
            fn all(mask: bool) -> bool { mask }
        }
    )*};
}

impl_select!(f32, f64);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_value_selects_as_if_does() {
        assert_eq!(f64::select(1.0.lt(2.0), 3.0, 4.0), 3.0);
        assert_eq!(f64::select(f64::NAN.le(0.0), 3.0, 4.0), 4.0);
        assert_eq!((f64::NAN.min_lanes(1.0), 0.5f64.min_lanes(1.0), 2.0f64.min_lanes(1.0)), (1.0, 0.5, 1.0));
        assert_eq!((f64::NAN.max_lanes(0.0), (-0.5f64).max_lanes(0.0), 2.0f64.max_lanes(0.0)), (0.0, 0.0, 2.0));
        assert!(!Select::finite(f64::INFINITY) && Select::finite(1.0f32));
    }

    #[test]
    fn binades_are_the_powers_of_two_below() {
        for x in [1.0, 1.5, 3.0, 1e-300, 5e-324, 1e300, -6.0, f64::MAX] {
            let b = Real::binade(x);
            assert!(b.is_finite() && b > 0.0 && b.log2().fract() == 0.0, "{x:e}: {b:e}");
            assert!((1.0..2.0).contains(&(x.abs() / b)), "{x:e}: {b:e}");
        }
        assert_eq!((Real::binade(0.0f64), Real::binade(f64::NAN)), (1.0, 1.0));
        assert_eq!(Real::binade(12.0f32), 8.0);
        assert_eq!(<f32 as Real>::min_positive(), f32::MIN_POSITIVE);
    }
}
