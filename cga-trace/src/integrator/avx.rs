//! [`Ymm`]: four f64 lanes held in one AVX register, the lane type of the packets traced
//! by [`Renderer::pixels4`](super::Renderer) where the CPU has AVX2.
//!
//! Every operation is one AVX instruction on the whole register, so the packet code stays in
//! vector form; on [`F64x4`]'s plain arrays LLVM scalarises the packets' values and then
//! re-vectorises parts of them, some across lanes and some across a multivector's
//! components, with shuffles in between. The arithmetic is IEEE's, lane by lane, as
//! [`F64x4`]'s: the same bits (no fused operations are formed from intrinsics).
//!
//! Sound only where the CPU has AVX: the type is private to the crate and named only in the
//! function compiled for AVX2 and FMA that [`Renderer::pixels4`](super::Renderer) calls after
//! checking the CPU, into which every operation is inlined.

use cga_core::simd::{F64x4, Lane};
use cga_core::{Real, Select};
use core::arch::x86_64::{
    __m256d, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_UNORD_Q, _mm256_add_pd, _mm256_and_pd, _mm256_andnot_pd, _mm256_blendv_pd,
    _mm256_cmp_pd, _mm256_div_pd, _mm256_max_pd, _mm256_movemask_pd, _mm256_mul_pd, _mm256_or_pd, _mm256_set1_pd,
    _mm256_setr_pd, _mm256_sqrt_pd, _mm256_sub_pd, _mm256_xor_pd,
};
use core::cmp::Ordering;
use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// Four f64 lanes in one AVX register.
#[derive(Clone, Copy)]
pub(crate) struct Ymm(__m256d);

/// A truth value per lane of a [`Ymm`]: all ones or all zeros, as `vcmppd` leaves it.
#[derive(Clone, Copy)]
pub(crate) struct YmmMask(__m256d);

/// `$intrinsic` on the registers, inlined into the caller (which is compiled for AVX2).
macro_rules! avx {
    ($call:expr) => {
        // SAFETY: reached only from code run on a CPU with AVX (the module's invariant).
        unsafe { $call }
    };
}

impl Ymm {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Ymm(avx!(_mm256_set1_pd(x)))
    }

    #[inline(always)]
    fn to_array(self) -> [f64; 4] {
        // SAFETY: `__m256d` is four f64s.
        unsafe { core::mem::transmute::<__m256d, [f64; 4]>(self.0) }
    }

    /// Built in registers (`vunpcklpd`, `vinsertf128`, or one broadcast where the lanes are
    /// one value).
    #[inline(always)]
    fn from_array(a: [f64; 4]) -> Self {
        Ymm(avx!(_mm256_setr_pd(a[0], a[1], a[2], a[3])))
    }

    /// The lanes as [`F64x4`], for what is done lane by lane (the transcendental functions).
    #[inline(always)]
    fn wide(self) -> F64x4 {
        F64x4::new(self.to_array())
    }

    /// `f` of the lanes as [`F64x4`] computes it.
    #[inline(always)]
    fn via(self, f: impl Fn(F64x4) -> F64x4) -> Self {
        Ymm::from_array(f(self.wide()).to_array())
    }

    #[inline(always)]
    fn compare<const OP: i32>(self, other: Self) -> YmmMask {
        YmmMask(avx!(_mm256_cmp_pd::<OP>(self.0, other.0)))
    }
}

impl Default for Ymm {
    #[inline(always)]
    fn default() -> Self {
        Ymm::splat(0.0)
    }
}

impl core::fmt::Debug for Ymm {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_tuple("Ymm").field(&self.to_array()).finish()
    }
}

impl PartialEq for Ymm {
    fn eq(&self, other: &Self) -> bool {
        self.to_array() == other.to_array()
    }
}

/// [`F64x4`]'s product order: ordered only where every lane agrees.
impl PartialOrd for Ymm {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.wide().partial_cmp(&other.wide())
    }
}

/// The operators `$trait` of `$t` (a register newtype), each one intrinsic.
macro_rules! binary {
    ($t:ident: $($trait:ident $method:ident $intrinsic:ident),*) => {$(
        impl $trait for $t {
            type Output = $t;
            #[inline(always)]
            fn $method(self, rhs: $t) -> $t {
                $t(avx!($intrinsic(self.0, rhs.0)))
            }
        }
    )*};
}
binary!(Ymm: Add add _mm256_add_pd, Sub sub _mm256_sub_pd, Mul mul _mm256_mul_pd, Div div _mm256_div_pd);

impl Neg for Ymm {
    type Output = Ymm;
    /// The sign bit flipped, as `-x` is for one f64.
    #[inline(always)]
    fn neg(self) -> Ymm {
        Ymm(avx!(_mm256_xor_pd(self.0, Ymm::splat(-0.0).0)))
    }
}

impl Real for Ymm {
    /// `f64::max` lane by lane: the larger, the other where one is NaN (`vmaxpd` returns its
    /// second operand where either is NaN; the lanes where `self` is NaN take `other`).
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        let larger = avx!(_mm256_max_pd(other.0, self.0));
        let nan = self.compare::<_CMP_UNORD_Q>(self);
        Ymm(avx!(_mm256_blendv_pd(larger, other.0, nan.0)))
    }
    #[inline(always)]
    fn zero() -> Self {
        Ymm::splat(0.0)
    }
    #[inline(always)]
    fn one() -> Self {
        Ymm::splat(1.0)
    }
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        Ymm::splat(x)
    }
    /// Lane 0, as [`F64x4`] gives it.
    #[inline]
    fn to_f64(self) -> f64 {
        self.to_array()[0]
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Ymm(avx!(_mm256_sqrt_pd(self.0)))
    }
    /// The sign bit cleared.
    #[inline(always)]
    fn abs(self) -> Self {
        Ymm(avx!(_mm256_andnot_pd(Ymm::splat(-0.0).0, self.0)))
    }
    /// Whether every lane is finite.
    #[inline(always)]
    fn is_finite(self) -> bool {
        Ymm::all(self.finite())
    }
    #[inline]
    fn epsilon() -> Self {
        Ymm::splat(f64::EPSILON)
    }
    #[inline]
    fn sin(self) -> Self {
        self.via(F64x4::sin)
    }
    #[inline]
    fn cos(self) -> Self {
        self.via(F64x4::cos)
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        Ymm::from_array(self.wide().atan2(x.wide()).to_array())
    }
    #[inline]
    fn exp(self) -> Self {
        self.via(F64x4::exp)
    }
    #[inline]
    fn ln(self) -> Self {
        self.via(F64x4::ln)
    }
    #[inline]
    fn sinh(self) -> Self {
        self.via(F64x4::sinh)
    }
    #[inline]
    fn cosh(self) -> Self {
        self.via(F64x4::cosh)
    }
    #[inline]
    fn ln_1p(self) -> Self {
        self.via(F64x4::ln_1p)
    }
    #[inline]
    fn min_positive() -> Self {
        Ymm::splat(f64::MIN_POSITIVE)
    }
    #[inline]
    fn binade(self) -> Self {
        self.via(F64x4::binade)
    }
}

binary!(YmmMask: BitAnd bitand _mm256_and_pd, BitOr bitor _mm256_or_pd);

impl Not for YmmMask {
    type Output = YmmMask;
    #[inline(always)]
    fn not(self) -> YmmMask {
        // All ones is a NaN's bits: made by a comparison that always holds.
        let ones = Ymm::splat(0.0).compare::<{ core::arch::x86_64::_CMP_TRUE_UQ }>(Ymm::splat(0.0));
        YmmMask(avx!(_mm256_xor_pd(self.0, ones.0)))
    }
}

impl Select for Ymm {
    type Mask = YmmMask;
    #[inline(always)]
    fn lt(self, other: Self) -> YmmMask {
        self.compare::<_CMP_LT_OQ>(other)
    }
    #[inline(always)]
    fn le(self, other: Self) -> YmmMask {
        self.compare::<_CMP_LE_OQ>(other)
    }
    /// `|x| < ∞`: false for infinities and NaN.
    #[inline(always)]
    fn finite(self) -> YmmMask {
        self.abs().compare::<_CMP_LT_OQ>(Ymm::splat(f64::INFINITY))
    }
    #[inline(always)]
    fn select(mask: YmmMask, if_true: Self, if_false: Self) -> Self {
        Ymm(avx!(_mm256_blendv_pd(if_false.0, if_true.0, mask.0)))
    }
    #[inline(always)]
    fn any(mask: YmmMask) -> bool {
        avx!(_mm256_movemask_pd(mask.0)) != 0
    }
    #[inline(always)]
    fn all(mask: YmmMask) -> bool {
        avx!(_mm256_movemask_pd(mask.0)) == 0b1111
    }
}

impl Lane for Ymm {
    const LANES: usize = 4;
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        // Written out: `core::array::from_fn` may stay out of line, compiled without AVX.
        Ymm::from_array([f(0), f(1), f(2), f(3)])
    }
    #[inline(always)]
    fn lane(self, l: usize) -> f64 {
        self.to_array()[l]
    }
    #[inline(always)]
    fn mask_lane(mask: YmmMask, l: usize) -> bool {
        avx!(_mm256_movemask_pd(mask.0)) >> l & 1 == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation gives [`F64x4`]'s bits, lane by lane (NaN's as NaN), on values that
    /// probe the edges: signed zeros, infinities, NaN, subnormals.
    #[test]
    fn every_operation_gives_the_bits_of_f64x4() {
        if !cga_core::simd::avx2() {
            return;
        }
        let values = [0.0, -0.0, 1.5, -2.25, f64::INFINITY, f64::NEG_INFINITY, f64::NAN, 5e-324, 1e308, -3.0];
        // A NaN's sign and payload are not the language's to keep (an optimised build may
        // swap a commutative operation's operands): any NaN is the same here.
        let bits = |x: [f64; 4]| x.map(|v| if v.is_nan() { f64::NAN.to_bits() } else { v.to_bits() });
        for (i, &a0) in values.iter().enumerate() {
            for &b0 in &values {
                let a = [a0, b0, values[(i + 3) % values.len()], -a0];
                let b = [b0, a0, -b0, values[(i + 7) % values.len()]];
                let (x, y) = (Ymm::from_array(a), Ymm::from_array(b));
                let (p, q) = (F64x4::new(a), F64x4::new(b));
                for (ours, theirs) in [
                    (x + y, p + q),
                    (x - y, p - q),
                    (x * y, p * q),
                    (x / y, p / q),
                    (-x, -p),
                    (x.sqrt(), p.sqrt()),
                    (x.abs(), p.abs()),
                    (x.max(y), p.max(q)),
                    (Ymm::select(x.lt(y), x, y), F64x4::select(p.lt(q), p, q)),
                    (Ymm::select(!x.le(y) | y.finite(), x, y), F64x4::select(!p.le(q) | q.finite(), p, q)),
                    (Ymm::select(x.finite() & y.lt(x), x, y), F64x4::select(p.finite() & q.lt(p), p, q)),
                ] {
                    assert_eq!(bits(ours.to_array()), bits(theirs.to_array()), "{a:?} {b:?}");
                }
                let masks = [(x.lt(y), p.lt(q)), (x.le(y), p.le(q)), (x.finite(), p.finite())];
                for (ours, theirs) in masks {
                    assert_eq!(Ymm::any(ours), F64x4::any(theirs));
                    assert_eq!(Ymm::all(ours), F64x4::all(theirs));
                    for l in 0..4 {
                        assert_eq!(Ymm::mask_lane(ours, l), F64x4::mask_lane(theirs, l));
                    }
                }
                assert_eq!(x.partial_cmp(&y), p.partial_cmp(&q));
                assert_eq!(x.is_finite(), p.is_finite());
            }
        }
    }
}
