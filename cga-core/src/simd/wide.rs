//! The lane types: [`F64x4`] and [`F64x8`] (f64 lanes), [`F32x8`] and [`F32x16`] (f32
//! lanes), each a [`Real`] and a [`Select`](crate::Select), written once by one macro.
//!
//! The lanes are a plain array that LLVM vectorises, not a SIMD crate's type: `wide` (tried
//! first) picks its width when it is compiled, so under run-time dispatch it stays at two
//! SSE2 registers. Arithmetic, `sqrt`, `abs` and `max` are lane-wise; the order is the
//! product order (`a < b` when every lane is), so code that branches on a comparison takes a
//! branch only when all lanes agree.

use crate::{Real, Select};
use core::cmp::Ordering;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// A lane type the generated types run on in [`super::run`]: so many f64 or f32 lanes, a
/// [`Select`] (lane-wise choice) and a [`Real`] (lane-wise arithmetic). Lanes are read and
/// built as f64, which holds every f32 exactly: f32 values go in and come out unchanged.
pub trait Lane: Select + Default {
    /// How many lanes.
    const LANES: usize;
    /// The lane `f(l)` in lane `l`.
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;
    /// Lane `l`.
    fn lane(self, l: usize) -> f64;
    /// Lane `l` of a mask.
    fn mask_lane(mask: Self::Mask, l: usize) -> bool;
}

/// One value is one lane: code written over lanes runs on a single ray or operand too.
impl Lane for f64 {
    const LANES: usize = 1;
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        f(0)
    }
    #[inline(always)]
    fn lane(self, _: usize) -> f64 {
        self
    }
    #[inline(always)]
    fn mask_lane(mask: bool, _: usize) -> bool {
        mask
    }
}

/// One f32 value is one lane.
impl Lane for f32 {
    const LANES: usize = 1;
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        f(0) as f32
    }
    #[inline(always)]
    fn lane(self, _: usize) -> f64 {
        self.into()
    }
    #[inline(always)]
    fn mask_lane(mask: bool, _: usize) -> bool {
        mask
    }
}

macro_rules! wide {
    ($(#[$doc:meta])* $t:ident, $(#[$mask_doc:meta])* $mask:ident, $e:ident, $bits:ident, $n:literal, [$($l:literal)*], $align:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        #[repr(C, align($align))]
        pub struct $t(pub [$e; $n]);

        impl $t {
            /// The lanes `[a₀, a₁, …]`.
            #[inline(always)]
            pub fn new(lanes: [$e; $n]) -> Self {
                $t(lanes)
            }

            /// The same value in every lane.
            #[inline(always)]
            pub fn splat(x: $e) -> Self {
                $t([x; $n])
            }

            /// The lanes as an array.
            #[inline(always)]
            pub fn to_array(self) -> [$e; $n] {
                self.0
            }

            /// `f` applied lane by lane.
            #[inline(always)]
            fn map(self, f: impl Fn($e) -> $e) -> Self {
                $t(self.0.map(f))
            }

            /// `f` of the two lanes `l`, lane by lane (written out lane by lane: the form
            /// LLVM turns into one vector instruction).
            #[inline(always)]
            fn zip(self, other: Self, f: impl Fn($e, $e) -> $e) -> Self {
                let (a, b) = (self.0, other.0);
                $t([$(f(a[$l], b[$l])),*])
            }

            /// Whether `f` holds in every lane (each lane compared, no early exit).
            #[inline(always)]
            fn every(self, other: Self, f: impl Fn($e, $e) -> bool) -> bool {
                let (a, b) = (self.0, other.0);
                true $(& f(a[$l], b[$l]))*
            }
        }

        impl Add for $t {
            type Output = $t;
            #[inline(always)]
            fn add(self, rhs: $t) -> $t {
                self.zip(rhs, |a, b| a + b)
            }
        }
        impl Sub for $t {
            type Output = $t;
            #[inline(always)]
            fn sub(self, rhs: $t) -> $t {
                self.zip(rhs, |a, b| a - b)
            }
        }
        impl Mul for $t {
            type Output = $t;
            #[inline(always)]
            fn mul(self, rhs: $t) -> $t {
                self.zip(rhs, |a, b| a * b)
            }
        }
        impl Div for $t {
            type Output = $t;
            #[inline(always)]
            fn div(self, rhs: $t) -> $t {
                self.zip(rhs, |a, b| a / b)
            }
        }
        impl Neg for $t {
            type Output = $t;
            #[inline(always)]
            fn neg(self) -> $t {
                self.map(|x| -x)
            }
        }

        /// The product order: `a < b` when every lane of `a` is below the same lane of `b`;
        /// lanes that disagree are unordered (`None`), so a comparison is true only for all.
        impl PartialOrd for $t {
            fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
                if self.every(*other, |x, y| x == y) {
                    Some(Ordering::Equal)
                } else if self.every(*other, |x, y| x <= y) {
                    Some(Ordering::Less)
                } else if self.every(*other, |x, y| x >= y) {
                    Some(Ordering::Greater)
                } else {
                    None
                }
            }

            /// Every lane `≤` (what `partial_cmp` gives, without branches).
            #[inline(always)]
            fn le(&self, other: &Self) -> bool {
                self.every(*other, |x, y| x <= y)
            }

            /// Every lane `≥` (what `partial_cmp` gives, without branches).
            #[inline(always)]
            fn ge(&self, other: &Self) -> bool {
                self.every(*other, |x, y| x >= y)
            }
        }

        impl Real for $t {
            /// Lane-wise maximum, `f64::max`'s (the other where one is NaN), with its one
            /// freedom fixed: of `±0` the first, as `vmaxpd` gives (`f64::max` may give
            /// either, and an optimised build did not give what a debug one does).
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                self.zip(other, |a, b| if a.is_nan() || b > a { b } else { a })
            }
            #[inline(always)]
            fn zero() -> Self {
                $t::splat(0.0)
            }
            #[inline(always)]
            fn one() -> Self {
                $t::splat(1.0)
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                $t::splat(Real::from_f64(x))
            }
            /// Lane 0 (a scalar view of many values has no better meaning; use `to_array`
            /// for the lanes).
            #[inline]
            fn to_f64(self) -> f64 {
                self.0[0].to_f64()
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                self.map($e::sqrt)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                self.map($e::abs)
            }
            /// Whether every lane is finite.
            #[inline(always)]
            fn is_finite(self) -> bool {
                let a = self.0;
                true $(& a[$l].is_finite())*
            }
            #[inline]
            fn epsilon() -> Self {
                $t::splat($e::EPSILON)
            }
            #[inline]
            fn sin(self) -> Self {
                self.map($e::sin)
            }
            #[inline]
            fn cos(self) -> Self {
                self.map($e::cos)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                self.zip(x, $e::atan2)
            }
            #[inline]
            fn exp(self) -> Self {
                self.map($e::exp)
            }
            #[inline]
            fn ln(self) -> Self {
                self.map($e::ln)
            }
            #[inline]
            fn sinh(self) -> Self {
                self.map($e::sinh)
            }
            #[inline]
            fn cosh(self) -> Self {
                self.map($e::cosh)
            }
            #[inline]
            fn ln_1p(self) -> Self {
                self.map($e::ln_1p)
            }
            #[inline]
            fn min_positive() -> Self {
                $t::splat($e::MIN_POSITIVE)
            }
            /// Lane by lane.
            #[inline]
            fn binade(self) -> Self {
                self.map(Real::binade)
            }
        }

        $(#[$mask_doc])*
        ///
        /// Each lane is all ones or all zeros, as a vector comparison leaves it, so that
        /// comparisons, `&`, `|`, `!` and [`Select::select`] stay in vector registers.
        #[derive(Clone, Copy, Default, PartialEq, Eq)]
        pub struct $mask([$bits; $n]);

        impl $mask {
            /// The mask with lane `l` set where `lanes[l]` is.
            #[inline(always)]
            pub fn new(lanes: [bool; $n]) -> Self {
                $mask(lanes.map(|b| (b as $bits).wrapping_neg()))
            }

            /// Whether lane `l` is set.
            #[inline(always)]
            pub fn lane(self, l: usize) -> bool {
                self.0[l] != 0
            }

            /// The lanes as truth values.
            #[inline(always)]
            pub fn to_array(self) -> [bool; $n] {
                self.0.map(|m| m != 0)
            }

            /// All ones where `f` of the lanes holds (written out lane by lane: the form
            /// LLVM turns into one vector comparison).
            #[inline(always)]
            fn compare(a: $t, b: $t, f: impl Fn($e, $e) -> bool) -> Self {
                let (a, b) = (a.0, b.0);
                $mask([$((f(a[$l], b[$l]) as $bits).wrapping_neg()),*])
            }
        }

        impl core::fmt::Debug for $mask {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_tuple(stringify!($mask)).field(&self.to_array()).finish()
            }
        }

        impl core::ops::BitAnd for $mask {
            type Output = $mask;
            #[inline(always)]
            fn bitand(self, rhs: $mask) -> $mask {
                let (a, b) = (self.0, rhs.0);
                $mask([$(a[$l] & b[$l]),*])
            }
        }
        impl core::ops::BitOr for $mask {
            type Output = $mask;
            #[inline(always)]
            fn bitor(self, rhs: $mask) -> $mask {
                let (a, b) = (self.0, rhs.0);
                $mask([$(a[$l] | b[$l]),*])
            }
        }
        impl core::ops::Not for $mask {
            type Output = $mask;
            #[inline(always)]
            fn not(self) -> $mask {
                let a = self.0;
                $mask([$(!a[$l]),*])
            }
        }

        impl Select for $t {
            type Mask = $mask;
            #[inline(always)]
            fn lt(self, other: Self) -> $mask {
                $mask::compare(self, other, |x, y| x < y)
            }
            #[inline(always)]
            fn le(self, other: Self) -> $mask {
                $mask::compare(self, other, |x, y| x <= y)
            }
            #[inline(always)]
            fn finite(self) -> $mask {
                $mask::compare(self.abs(), $t::splat($e::INFINITY), |x, inf| x < inf)
            }
            /// Bitwise: `(a & m) | (b & !m)` (LLVM's blend).
            #[inline(always)]
            fn select(mask: $mask, if_true: Self, if_false: Self) -> Self {
                let (m, a, b) = (mask.0, if_true.0, if_false.0);
                $t([$($e::from_bits((a[$l].to_bits() & m[$l]) | (b[$l].to_bits() & !m[$l]))),*])
            }
            #[inline(always)]
            fn any(mask: $mask) -> bool {
                let m = mask.0;
                (0 $(| m[$l])*) != 0
            }
            #[inline(always)]
            fn all(mask: $mask) -> bool {
                let m = mask.0;
                ($bits::MAX $(& m[$l])*) == $bits::MAX
            }
        }

        impl Lane for $t {
            const LANES: usize = $n;
            #[inline(always)]
            fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
                $t(core::array::from_fn(|l| Real::from_f64(f(l))))
            }
            #[inline(always)]
            fn lane(self, l: usize) -> f64 {
                self.0[l].to_f64()
            }
            #[inline(always)]
            fn mask_lane(mask: $mask, l: usize) -> bool {
                mask.lane(l)
            }
        }
    };
}

wide!(
    /// Four f64 lanes, a [`Real`] whose arithmetic is lane-wise: AVX2's width, the packets'.
    F64x4,
    /// A truth value per lane of an [`F64x4`] ([`Select`]).
    Mask4,
    f64,
    u64,
    4,
    [0 1 2 3],
    32
);
wide!(
    /// Eight f64 lanes, a [`Real`] whose arithmetic is lane-wise: AVX-512's width, what
    /// [`super::run`] uses where the CPU has it.
    F64x8,
    /// A truth value per lane of an [`F64x8`] ([`Select`]).
    Mask8,
    f64,
    u64,
    8,
    [0 1 2 3 4 5 6 7],
    64
);
wide!(
    /// Eight f32 lanes, a [`Real`] whose arithmetic is lane-wise: one AVX2 register, what
    /// [`super::run`] uses for f32 values where the CPU has AVX2.
    F32x8,
    /// A truth value per lane of an [`F32x8`] ([`Select`]).
    Mask32x8,
    f32,
    u32,
    8,
    [0 1 2 3 4 5 6 7],
    32
);
wide!(
    /// Sixteen f32 lanes, a [`Real`] whose arithmetic is lane-wise: one AVX-512 register,
    /// what [`super::run`] uses for f32 values where the CPU has AVX-512.
    F32x16,
    /// A truth value per lane of an [`F32x16`] ([`Select`]).
    Mask32x16,
    f32,
    u32,
    16,
    [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15],
    64
);
