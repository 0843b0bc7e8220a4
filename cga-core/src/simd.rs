//! Four f64 lanes as a scalar: every generated type, product and sandwich runs on four
//! independent operands at once, `Line<F64x4>` being a packet of four lines in
//! structure-of-arrays form.
//!
//! Arithmetic, `sqrt`, `abs` and `max` are lane-wise; the order is the product order
//! (`a < b` when every lane is), so code that branches on a comparison takes a branch only
//! when all four lanes agree. Three ways to run an operation over many operands:
//!
//! - [`run_packed`]: over packets (`&[Line<F64x4>]`…), the form a ray tracer keeps its
//!   packets in — the fastest;
//! - [`run`]: over slices of ordinary values, transposed into lanes four at a time and
//!   back, in place (with AVX: about 1 ns per operation for the six of
//!   benches/README.md, faster than one at a time for each);
//! - [`map`]: the same with a closure (run as a [`Kernel`]).
//!
//! `run` and `run_packed` take the operation as a [`Kernel`] (`map` makes one of its
//! closure) and compile it twice, for the baseline (SSE2) and for AVX2 + FMA, choosing at
//! run time: no `target-cpu` flag is needed and the binary runs on any x86-64. The lanes are a plain `[f64; 4]` that LLVM
//! vectorises, not a SIMD crate's type: `wide` (tried first) picks its width when it is
//! compiled, so under run-time dispatch it stays at two SSE2 registers.
//!
//! ```
//! use cga_core::simd::{F64x4, map};
//! use cga_core::{Line, PointPair, Sphere};
//! let sphere = Sphere::from_centre_radius([0.0, 0.0, 0.0], 1.0).unwrap();
//! let line = |k: usize| Line::through([k as f64 * 0.1, 0.0, -3.0], [0.0, 0.0, 3.0]).unwrap();
//! let input: Vec<(Line, Sphere)> = (0..10).map(|k| (line(k), sphere)).collect();
//! let mut pairs = vec![PointPair::zero(); 10];
//! map(&input, &mut pairs, |(l, s): (Line<F64x4>, Sphere<F64x4>)| l & s);
//! assert_eq!(pairs[7], line(7) & sphere); // the same bits as one at a time
//! ```

use crate::Real;
use core::cmp::Ordering;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// Four f64 lanes, a [`Real`] whose arithmetic is lane-wise.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(32))]
pub struct F64x4(pub [f64; 4]);

impl F64x4 {
    /// The lanes `[a₀, a₁, a₂, a₃]`.
    #[inline(always)]
    pub fn new(lanes: [f64; 4]) -> Self {
        F64x4(lanes)
    }

    /// The same value in every lane.
    #[inline(always)]
    pub fn splat(x: f64) -> Self {
        F64x4([x; 4])
    }

    /// The lanes as an array.
    #[inline(always)]
    pub fn to_array(self) -> [f64; 4] {
        self.0
    }

    /// `f` applied lane by lane (for what `wide` has no vector form of).
    #[inline]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        F64x4::new(self.to_array().map(f))
    }
}

macro_rules! lane_wise {
    ($($trait:ident $method:ident),*) => {$(
        impl $trait for F64x4 {
            type Output = F64x4;
            #[inline(always)]
            fn $method(self, rhs: F64x4) -> F64x4 {
                let (a, b) = (self.0, rhs.0);
                F64x4([a[0].$method(b[0]), a[1].$method(b[1]), a[2].$method(b[2]), a[3].$method(b[3])])
            }
        }
    )*};
}
lane_wise!(Add add, Sub sub, Mul mul, Div div);

impl Neg for F64x4 {
    type Output = F64x4;
    #[inline(always)]
    fn neg(self) -> F64x4 {
        F64x4(self.0.map(|x| -x))
    }
}

/// The product order: `a < b` when every lane of `a` is below the same lane of `b`; lanes
/// that disagree are unordered (`None`), so a comparison is true only for all four.
impl PartialOrd for F64x4 {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        let (a, b) = (self.to_array(), other.to_array());
        let all = |f: fn(&f64, &f64) -> bool| a.iter().zip(&b).all(|(x, y)| f(x, y));
        if all(|x, y| x == y) {
            Some(Ordering::Equal)
        } else if all(|x, y| x <= y) {
            Some(Ordering::Less)
        } else if all(|x, y| x >= y) {
            Some(Ordering::Greater)
        } else {
            None
        }
    }

    /// Every lane `≤` (what `partial_cmp` gives, in four comparisons without branches).
    #[inline(always)]
    fn le(&self, other: &Self) -> bool {
        let (a, b) = (self.0, other.0);
        (a[0] <= b[0]) & (a[1] <= b[1]) & (a[2] <= b[2]) & (a[3] <= b[3])
    }

    /// Every lane `≥` (what `partial_cmp` gives, in four comparisons without branches).
    #[inline(always)]
    fn ge(&self, other: &Self) -> bool {
        let (a, b) = (self.0, other.0);
        (a[0] >= b[0]) & (a[1] >= b[1]) & (a[2] >= b[2]) & (a[3] >= b[3])
    }
}

impl Real for F64x4 {
    /// Lane-wise maximum.
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        let (a, b) = (self.0, other.0);
        F64x4([a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2]), a[3].max(b[3])])
    }
    #[inline(always)]
    fn zero() -> Self {
        F64x4::splat(0.0)
    }
    #[inline(always)]
    fn one() -> Self {
        F64x4::splat(1.0)
    }
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        F64x4::splat(x)
    }
    /// Lane 0 (a scalar view of four values has no better meaning; use
    /// [`F64x4::to_array`] for the lanes).
    #[inline]
    fn to_f64(self) -> f64 {
        self.to_array()[0]
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        F64x4(self.0.map(f64::sqrt))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F64x4(self.0.map(f64::abs))
    }
    /// Whether every lane is finite.
    #[inline(always)]
    fn is_finite(self) -> bool {
        let a = self.0;
        a[0].is_finite() & a[1].is_finite() & a[2].is_finite() & a[3].is_finite()
    }
    #[inline]
    fn epsilon() -> Self {
        F64x4::splat(f64::EPSILON)
    }
    #[inline]
    fn sin(self) -> Self {
        self.map(f64::sin)
    }
    #[inline]
    fn cos(self) -> Self {
        self.map(f64::cos)
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        let (y, x) = (self.to_array(), x.to_array());
        F64x4::new([0, 1, 2, 3].map(|k| y[k].atan2(x[k])))
    }
    #[inline]
    fn min_positive() -> Self {
        F64x4::splat(f64::MIN_POSITIVE)
    }
    /// Lane by lane.
    #[inline]
    fn binade(self) -> Self {
        self.map(Real::binade)
    }
}

/// A truth value per lane of an [`F64x4`] ([`Select`](crate::Select)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mask4(pub [bool; 4]);

macro_rules! mask_op {
    ($($trait:ident $method:ident $op:tt),*) => {$(
        impl core::ops::$trait for Mask4 {
            type Output = Mask4;
            #[inline(always)]
            fn $method(self, rhs: Mask4) -> Mask4 {
                let (a, b) = (self.0, rhs.0);
                Mask4([a[0] $op b[0], a[1] $op b[1], a[2] $op b[2], a[3] $op b[3]])
            }
        }
    )*};
}
mask_op!(BitAnd bitand &, BitOr bitor |);

impl core::ops::Not for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn not(self) -> Mask4 {
        Mask4(self.0.map(|x| !x))
    }
}

impl crate::Select for F64x4 {
    type Mask = Mask4;
    #[inline(always)]
    fn lt(self, other: Self) -> Mask4 {
        let (a, b) = (self.0, other.0);
        Mask4([a[0] < b[0], a[1] < b[1], a[2] < b[2], a[3] < b[3]])
    }
    #[inline(always)]
    fn le(self, other: Self) -> Mask4 {
        let (a, b) = (self.0, other.0);
        Mask4([a[0] <= b[0], a[1] <= b[1], a[2] <= b[2], a[3] <= b[3]])
    }
    #[inline(always)]
    fn finite(self) -> Mask4 {
        Mask4(self.0.map(f64::is_finite))
    }
    #[inline(always)]
    fn select(mask: Mask4, if_true: Self, if_false: Self) -> Self {
        let (m, a, b) = (mask.0, if_true.0, if_false.0);
        F64x4([0, 1, 2, 3].map(|l| if m[l] { a[l] } else { b[l] }))
    }
    #[inline(always)]
    fn any(mask: Mask4) -> bool {
        let m = mask.0;
        m[0] | m[1] | m[2] | m[3]
    }
    #[inline(always)]
    fn all(mask: Mask4) -> bool {
        let m = mask.0;
        m[0] & m[1] & m[2] & m[3]
    }
}

/// A generated type that packs four of itself into one of four lanes, field by field.
pub trait Lanes: Copy {
    /// The same type over [`F64x4`].
    type Packed: Copy;
    /// `[x₀, x₁, x₂, x₃]` as one value whose lane `k` is `x_k`.
    fn pack(x: [Self; 4]) -> Self::Packed;
    /// The inverse of [`Lanes::pack`].
    fn unpack(p: Self::Packed) -> [Self; 4];
    /// [`Lanes::pack`] of the values at `rows`, read in place by AVX shuffles where the
    /// type allows (the same values).
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to four values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows(rows: [*const Self; 4]) -> Self::Packed {
        // SAFETY: the caller's pointers are valid.
        Self::pack(rows.map(|r| unsafe { *r }))
    }
    /// [`Lanes::unpack`] into the values at `rows`, written in place by AVX shuffles where
    /// the type allows.
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to four writable values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn unpack_rows(p: Self::Packed, rows: [*mut Self; 4]) {
        for (r, v) in rows.into_iter().zip(Self::unpack(p)) {
            // SAFETY: the caller's pointers are valid.
            unsafe { *r = v };
        }
    }
}

/// 4 × 4 transposes with AVX, between four values' coefficients in memory (rows) and one
/// lane per value (columns): a block of four coefficients is read as 128-bit halves joined
/// by `vinsertf128` and paired by `vunpcklpd`/`vunpckhpd` (full-width loads and `vperm2f128`
/// were slower), and written back by the same unpacks and `vperm2f128`; a pair left over
/// takes 128-bit halves, a single one is gathered.
#[cfg(target_arch = "x86_64")]
mod transpose {
    use super::F64x4;
    use core::arch::x86_64::*;

    /// `v`, which LLVM may not look into: given the lanes of a transpose, it otherwise folds
    /// the shuffles into scalar loads and stores and computes the whole operation in scalar
    /// code.
    #[inline]
    #[target_feature(enable = "avx")]
    fn opaque(mut v: __m256d) -> __m256d {
        // SAFETY: an empty sequence: it reads, writes and clobbers nothing but `v`'s register.
        unsafe { core::arch::asm!("/* {0} */", inout(ymm_reg) v, options(pure, nomem, nostack, preserves_flags)) };
        v
    }

    /// `out[k]` holds coefficient `k` of the four rows of `N` values each.
    ///
    /// # Safety
    /// The CPU must have AVX, each row must hold `N` values and `out` must be writable.
    #[inline]
    #[target_feature(enable = "avx")]
    pub unsafe fn pack<const N: usize>(rows: [*const f64; 4], out: *mut [F64x4; N]) {
        let out = out.cast::<f64>();
        let mut c = 0;
        // SAFETY: every load reads within a row, every store within `out` (unaligned
        // accesses throughout).
        unsafe {
            while c + 4 <= N {
                // Halves of rows 0 and 2, 1 and 3 joined by 128-bit inserts (loads), then
                // paired by unpacks: no lane-crossing shuffle.
                let join = |a: usize, k: usize| {
                    let lo = _mm256_castpd128_pd256(_mm_loadu_pd(rows[a].add(c + k)));
                    _mm256_insertf128_pd::<1>(lo, _mm_loadu_pd(rows[a + 2].add(c + k)))
                };
                let (x, y, z, w) = (join(0, 0), join(1, 0), join(0, 2), join(1, 2));
                let lanes = [
                    _mm256_unpacklo_pd(x, y),
                    _mm256_unpackhi_pd(x, y),
                    _mm256_unpacklo_pd(z, w),
                    _mm256_unpackhi_pd(z, w),
                ];
                for (k, v) in lanes.into_iter().enumerate() {
                    _mm256_storeu_pd(out.add(4 * (c + k)), opaque(v));
                }
                c += 4;
            }
            if c + 2 <= N {
                let half = |i: usize| _mm_loadu_pd(rows[i].add(c));
                let x = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(half(0)), half(2));
                let y = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(half(1)), half(3));
                _mm256_storeu_pd(out.add(4 * c), opaque(_mm256_unpacklo_pd(x, y)));
                _mm256_storeu_pd(out.add(4 * c + 4), opaque(_mm256_unpackhi_pd(x, y)));
                c += 2;
            }
            if c < N {
                let v = _mm256_set_pd(*rows[3].add(c), *rows[2].add(c), *rows[1].add(c), *rows[0].add(c));
                _mm256_storeu_pd(out.add(4 * c), opaque(v));
            }
        }
    }

    /// The inverse of [`pack`]: row `i` gets lane `i` of every `p[k]`.
    ///
    /// # Safety
    /// The CPU must have AVX, each row must hold `N` writable values.
    #[inline]
    #[target_feature(enable = "avx")]
    pub unsafe fn unpack<const N: usize>(p: *const [F64x4; N], rows: [*mut f64; 4]) {
        let p = p.cast::<f64>();
        let mut c = 0;
        // SAFETY: as in `pack`, with loads and stores exchanged.
        unsafe {
            while c + 4 <= N {
                // Unpacks pair coefficients `c, c + 1` and `c + 2, c + 3` per lane (each
                // 128-bit half one row's pair), `vperm2f128` joins a row's two pairs: a
                // 256-bit store per row (faster than two 128-bit halves for 10-coefficient
                // results, the same for 4).
                let [p0, p1, p2, p3] = [0, 1, 2, 3].map(|k| opaque(_mm256_loadu_pd(p.add(4 * (c + k)))));
                let (a, b) = (_mm256_unpacklo_pd(p0, p1), _mm256_unpackhi_pd(p0, p1));
                let (x, y) = (_mm256_unpacklo_pd(p2, p3), _mm256_unpackhi_pd(p2, p3));
                _mm256_storeu_pd(rows[0].add(c), _mm256_permute2f128_pd::<0x20>(a, x));
                _mm256_storeu_pd(rows[1].add(c), _mm256_permute2f128_pd::<0x20>(b, y));
                _mm256_storeu_pd(rows[2].add(c), _mm256_permute2f128_pd::<0x31>(a, x));
                _mm256_storeu_pd(rows[3].add(c), _mm256_permute2f128_pd::<0x31>(b, y));
                c += 4;
            }
            if c + 2 <= N {
                let (x, y) = (opaque(_mm256_loadu_pd(p.add(4 * c))), opaque(_mm256_loadu_pd(p.add(4 * c + 4))));
                let (u, v) = (_mm256_unpacklo_pd(x, y), _mm256_unpackhi_pd(x, y));
                _mm_storeu_pd(rows[0].add(c), _mm256_castpd256_pd128(u));
                _mm_storeu_pd(rows[1].add(c), _mm256_castpd256_pd128(v));
                _mm_storeu_pd(rows[2].add(c), _mm256_extractf128_pd::<1>(u));
                _mm_storeu_pd(rows[3].add(c), _mm256_extractf128_pd::<1>(v));
                c += 2;
            }
            if c < N {
                let v = opaque(_mm256_loadu_pd(p.add(4 * c)));
                let (lo, hi) = (_mm256_castpd256_pd128(v), _mm256_extractf128_pd::<1>(v));
                _mm_storel_pd(rows[0].add(c), lo);
                _mm_storeh_pd(rows[1].add(c), lo);
                _mm_storel_pd(rows[2].add(c), hi);
                _mm_storeh_pd(rows[3].add(c), hi);
            }
        }
    }
}

macro_rules! lanes {
    ($($t:ident),*) => {$(
        impl Lanes for crate::$t<f64> {
            type Packed = crate::$t<F64x4>;
            #[inline(always)]
            fn pack(x: [Self; 4]) -> Self::Packed {
                let a = x.map(|v| v.to_array());
                crate::$t::from_array(core::array::from_fn(|k| F64x4::new([a[0][k], a[1][k], a[2][k], a[3][k]])))
            }
            #[inline(always)]
            fn unpack(p: Self::Packed) -> [Self; 4] {
                let a = p.to_array().map(F64x4::to_array);
                core::array::from_fn(|lane| crate::$t::from_array(core::array::from_fn(|k| a[k][lane])))
            }
            // The generated types are `#[repr(C)]` structs of their coefficients in field
            // order: a value is `[T; N]` in memory, a packed one `[F64x4; N]`.
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows(rows: [*const Self; 4]) -> Self::Packed {
                let mut out = core::mem::MaybeUninit::<Self::Packed>::uninit();
                // SAFETY: the caller's CPU has AVX and its rows are valid; `pack` writes
                // every coefficient of `out`.
                unsafe {
                    transpose::pack::<{ crate::$t::<f64>::BLADES.len() }>(rows.map(|r| r.cast()), out.as_mut_ptr().cast());
                    out.assume_init()
                }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows(p: Self::Packed, rows: [*mut Self; 4]) {
                // SAFETY: as in `pack_rows`.
                unsafe {
                    transpose::unpack::<{ crate::$t::<f64>::BLADES.len() }>((&raw const p).cast(), rows.map(|r| r.cast()))
                }
            }
        }
    )*};
}
lanes!(
    Scalar,
    Infinity,
    Vector,
    Bivector,
    FlatPoint,
    Line,
    Circle,
    Plane,
    Sphere,
    Pseudoscalar,
    ScalarQuadvector,
    Rotor,
    Translator,
    Motor,
    Dilator,
    Transversor,
    Generator,
    Even,
    Odd
);

macro_rules! tuple_lanes {
    ($($x:ident $k:tt),*) => {
        /// Tuples pack element by element.
        impl<$($x: Lanes),*> Lanes for ($($x,)*) {
            type Packed = ($($x::Packed,)*);
            #[inline(always)]
            fn pack(x: [Self; 4]) -> Self::Packed {
                ($($x::pack(x.map(|t| t.$k)),)*)
            }
            #[inline(always)]
            fn unpack(p: Self::Packed) -> [Self; 4] {
                let parts = ($($x::unpack(p.$k),)*);
                core::array::from_fn(|lane| ($(parts.$k[lane],)*))
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows(rows: [*const Self; 4]) -> Self::Packed {
                // SAFETY: the caller's CPU has AVX and its pointers are valid.
                unsafe { ($($x::pack_rows(rows.map(|r| &raw const (*r).$k)),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows(p: Self::Packed, rows: [*mut Self; 4]) {
                // SAFETY: as in `pack_rows`.
                unsafe { $($x::unpack_rows(p.$k, rows.map(|r| &raw mut (*r).$k));)* }
            }
        }
    };
}
tuple_lanes!(A 0, B 1);
tuple_lanes!(A 0, B 1, C 2);

/// `out[k] = f(input[k])` for every `k`, four at a time on [`F64x4`] lanes (a tail of
/// fewer than four is padded with copies of the last input): [`run`] with the closure as
/// its kernel, so dispatched to AVX2 and FMA the same way, with the same bits. The closure
/// is called from the AVX2 loop; LLVM inlines it there as it inlines any small function
/// with one caller, and where it declines (a body of several hundred instructions) a
/// [`Kernel`], whose `apply` is `#[inline(always)]`, is the sure way. `None`, and nothing
/// written, where the lengths differ.
#[inline]
pub fn map<I: Lanes, R: Lanes>(input: &[I], out: &mut [R], f: impl Fn(I::Packed) -> R::Packed) -> Option<()> {
    run(&Closure(f, core::marker::PhantomData), input, out)
}

/// A closure as a [`Kernel`] ([`map`]).
struct Closure<I, R, F>(F, core::marker::PhantomData<fn(I) -> R>);

impl<I: Lanes, R: Lanes, F: Fn(I::Packed) -> R::Packed> Kernel for Closure<I, R, F> {
    type Input = I;
    type Output = R;
    #[inline(always)]
    fn apply(&self, x: I::Packed) -> R::Packed {
        (self.0)(x)
    }
}

/// The loop of [`map`], lengths already checked.
#[inline(always)]
fn map_lanes<I: Lanes, R: Lanes>(input: &[I], out: &mut [R], f: &impl Fn(I::Packed) -> R::Packed) {
    let whole = input.len() / 4 * 4;
    for (x, out) in input.chunks_exact(4).zip(out.chunks_exact_mut(4)) {
        out.copy_from_slice(&R::unpack(f(I::pack([x[0], x[1], x[2], x[3]]))));
        not_across_iterations();
    }
    if whole < input.len() {
        let last = input.len() - 1;
        let lanes = R::unpack(f(I::pack([0, 1, 2, 3].map(|k| input[(whole + k).min(last)]))));
        out[whole..].copy_from_slice(&lanes[..input.len() - whole]);
    }
}

/// One operation on packets of four, named so that [`run`] can compile it for the CPU it
/// finds: a closure handed to a function compiled for AVX2 is a call LLVM may decline to
/// inline (it did, for every product bigger than a rotor's), and a call out of the
/// AVX2 function runs baseline code; a trait method marked `#[inline(always)]` is inlined.
/// A kernel may carry state known only at run time (a motor, a sphere): `apply` takes
/// `&self`, and [`splat`] puts a value into every lane.
///
/// ```
/// use cga_core::simd::{F64x4, Kernel, run};
/// use cga_core::{Line, PointPair, Sphere};
/// struct Meet;
/// impl Kernel for Meet {
///     type Input = (Line, Sphere);
///     type Output = PointPair;
///     #[inline(always)]
///     fn apply(&self, (l, s): (Line<F64x4>, Sphere<F64x4>)) -> PointPair<F64x4> {
///         l & s
///     }
/// }
/// let line = Line::through([0.5, 0.0, -3.0], [0.5, 0.0, 3.0]).unwrap();
/// let input = vec![(line, Sphere::from_centre_radius([0.0; 3], 1.0).unwrap()); 6];
/// let mut out = vec![PointPair::zero(); 6];
/// run(&Meet, &input, &mut out).unwrap();
/// assert_eq!(out[5], line & input[5].1);
///
/// // A kernel with state: one sphere, given at run time, met by many lines.
/// use cga_core::simd::splat;
/// struct MeetSphere(Sphere<F64x4>);
/// impl Kernel for MeetSphere {
///     type Input = Line;
///     type Output = PointPair;
///     #[inline(always)]
///     fn apply(&self, l: Line<F64x4>) -> PointPair<F64x4> {
///         l & self.0
///     }
/// }
/// let sphere = Sphere::from_centre_radius([0.0; 3], 1.0).unwrap();
/// let lines = vec![line; 6];
/// run(&MeetSphere(splat(sphere)), &lines, &mut out).unwrap();
/// assert_eq!(out[3], line & sphere);
/// ```
pub trait Kernel {
    /// What one operation takes (a type, or a tuple of types).
    type Input: Lanes;
    /// What it gives.
    type Output: Lanes;
    /// The operation on four operands at once.
    fn apply(&self, x: <Self::Input as Lanes>::Packed) -> <Self::Output as Lanes>::Packed;
}

/// `x` in every lane: a value of any generated type as a packet of four copies (a kernel's
/// run-time state, such as the motor every point is moved by).
#[inline]
pub fn splat<X: Lanes>(x: X) -> X::Packed {
    X::pack([x; 4])
}

/// `out[k] = K(input[k])` for every `k`, four at a time, compiled for AVX2 and FMA where the
/// CPU has them (detected once, at run time: the build stays baseline x86-64) and for the
/// baseline otherwise. The results are the same bits either way (no multiply–add is
/// contracted). `None`, and nothing written, where the lengths differ.
pub fn run<K: Kernel>(kernel: &K, input: &[K::Input], out: &mut [K::Output]) -> Option<()> {
    if input.len() != out.len() {
        return None;
    }
    #[cfg(target_arch = "x86_64")]
    if avx2() {
        // SAFETY: the CPU has the features `run_avx2` is compiled for.
        unsafe { run_avx2(kernel, input, out) };
        return Some(());
    }
    map_lanes(input, out, &|x| kernel.apply(x));
    Some(())
}

/// [`run`]'s loop compiled with AVX2 and FMA enabled.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn run_avx2<K: Kernel>(kernel: &K, input: &[K::Input], out: &mut [K::Output]) {
    // `K::apply` is a function item marked `#[inline(always)]`: inlined, so compiled for AVX2;
    // the values go into and out of lanes by AVX transposes, in place.
    let whole = input.len() / 4 * 4;
    for (x, y) in input[..whole].chunks_exact(4).zip(out[..whole].chunks_exact_mut(4)) {
        let rows = y.as_mut_ptr();
        // SAFETY: the CPU has AVX2 (so AVX); the rows are the chunks' four values.
        unsafe {
            let lanes = K::Input::pack_rows([0, 1, 2, 3].map(|i| &raw const x[i]));
            K::Output::unpack_rows(kernel.apply(lanes), [0, 1, 2, 3].map(|i| rows.add(i)));
        }
        not_across_iterations();
    }
    map_lanes(&input[whole..], &mut out[whole..], &|x| kernel.apply(x))
}

/// [`run`] on operands already in lanes (packets, as a ray tracer keeps them: no packing),
/// `out[k] = K(input[k])`; dispatched to AVX2 and FMA the same way. `None`, and nothing
/// written, where the lengths differ.
pub fn run_packed<K: Kernel>(kernel: &K, input: &[Packed<K::Input>], out: &mut [Packed<K::Output>]) -> Option<()> {
    if input.len() != out.len() {
        return None;
    }
    #[cfg(target_arch = "x86_64")]
    if avx2() {
        // SAFETY: the CPU has the features `run_packed_avx2` is compiled for.
        unsafe { run_packed_avx2(kernel, input, out) };
        return Some(());
    }
    packed_loop(kernel, input, out);
    Some(())
}

/// Whether this CPU has AVX2 and FMA, which the dispatched loops here (and callers' own,
/// such as a ray tracer's packet loops) are compiled for; detected once (`std` caches it).
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn avx2() -> bool {
    std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")
}

/// The packed form of a [`Lanes`] type.
pub type Packed<X> = <X as Lanes>::Packed;

/// [`run_packed`]'s loop compiled with AVX2 and FMA enabled.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn run_packed_avx2<K: Kernel>(kernel: &K, input: &[Packed<K::Input>], out: &mut [Packed<K::Output>]) {
    packed_loop(kernel, input, out)
}

#[inline(always)]
fn packed_loop<K: Kernel>(kernel: &K, input: &[Packed<K::Input>], out: &mut [Packed<K::Output>]) {
    for (o, &x) in out.iter_mut().zip(input) {
        *o = kernel.apply(x);
        not_across_iterations();
    }
}

/// An empty instruction sequence LLVM cannot see through: it keeps the loop vectoriser from
/// vectorising a loop of packet operations a second time, across iterations, which it
/// otherwise does with per-lane loads and shuffles (2–3× slower than the packets alone).
#[inline(always)]
fn not_across_iterations() {
    #[cfg(any(target_arch = "x86_64", target_arch = "x86", target_arch = "aarch64"))]
    // SAFETY: an empty sequence: it reads, writes and clobbers nothing.
    unsafe {
        core::arch::asm!("", options(nomem, nostack, preserves_flags))
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_select_each_as_one_value_does() {
        use crate::Select;
        let (a, b) = ([1.0, f64::NAN, 3.0, -0.5], [2.0, 0.0, 3.0, f64::INFINITY]);
        let (x, y) = (F64x4(a), F64x4(b));
        for l in 0..4 {
            assert_eq!(x.lt(y).0[l], a[l].lt(b[l]));
            assert_eq!(x.le(y).0[l], a[l].le(b[l]));
            assert_eq!(y.finite().0[l], Select::finite(b[l]));
            assert_eq!(F64x4::select(x.lt(y), x, y).0[l].to_bits(), f64::select(a[l] < b[l], a[l], b[l]).to_bits());
            assert_eq!(x.min_lanes(y).0[l].to_bits(), a[l].min(b[l]).to_bits());
            assert_eq!(x.max_lanes(y).0[l].to_bits(), a[l].max(b[l]).to_bits());
        }
        assert!(F64x4::any(x.lt(y)) && !F64x4::all(x.lt(y)) && F64x4::all(!Mask4::default()));
    }

    #[test]
    fn down_in_lanes_is_down_in_each_lane() {
        use crate::{Select, Vector, down, down_lanes};
        // Ordinary weights, zero, a weight whose inverse overflows, a NaN, a quotient that
        // overflows, and a negative weight.
        let cases = [
            Vector { e1: 1.0, e2: -2.0, e3: 3.0, eo: 2.0, ei: 0.0 },
            Vector { e1: 1.0, e2: 0.0, e3: 0.0, eo: 0.0, ei: 1.0 },
            Vector { e1: 1e-310, e2: 2e-310, e3: 0.0, eo: 1e-310, ei: 0.0 },
            Vector { e1: 1.0, e2: 0.0, e3: 0.0, eo: f64::NAN, ei: 0.0 },
            Vector { e1: 1e300, e2: 0.0, e3: 0.0, eo: 1e-300, ei: 0.0 },
            Vector { e1: 4.0, e2: 6.0, e3: 8.0, eo: -2.0, ei: 0.0 },
            Vector { e1: 3.0, e2: 1.0, e3: 2.0, eo: 0.5, ei: 0.0 },
            Vector { e1: 3.0, e2: 1.0, e3: 2.0, eo: 1.0, ei: 0.0 },
        ];
        for four in cases.chunks(4) {
            let (points, ok) = down_lanes(Vector::pack([four[0], four[1], four[2], four[3]]));
            for (l, v) in four.iter().enumerate() {
                let (point, valid) = down_lanes(*v);
                assert_eq!(valid, down(*v).is_ok(), "{v:?}");
                assert_eq!(ok.0[l], valid, "lane {l}: {v:?}");
                if let Ok(want) = down(*v) {
                    assert_eq!(point.map(f64::to_bits), want.map(f64::to_bits));
                    assert_eq!(points.map(|c| c.0[l].to_bits()), want.map(f64::to_bits), "lane {l}");
                }
            }
            assert_eq!(F64x4::any(ok), ok.0.iter().any(|&b| b));
        }
    }
    use crate::{Circle, Even, Line, Motor, Rotor, Sandwich, Sphere, Translator, Vector, up};

    struct Sandwiched;
    impl Kernel for Sandwiched {
        type Input = (Motor, Vector);
        type Output = Vector;
        #[inline(always)]
        fn apply(&self, (m, x): (Motor<F64x4>, Vector<F64x4>)) -> Vector<F64x4> {
            m.sandwich(x)
        }
    }

    /// A motor given at run time, in every lane.
    struct MoveBy(Motor<F64x4>);
    impl Kernel for MoveBy {
        type Input = Vector;
        type Output = Vector;
        #[inline(always)]
        fn apply(&self, x: Vector<F64x4>) -> Vector<F64x4> {
            self.0.sandwich(x)
        }
    }

    #[test]
    fn kernels_carry_run_time_state_and_give_the_bits_of_one_at_a_time() {
        let m: Motor =
            Motor::from_rotor_translation(Rotor::from_axis_angle([1.0, 2.0, 3.0], 0.7).unwrap(), [1.0, -2.0, 0.5]);
        let points: Vec<Vector> = (0..11).map(|k| up([k as f64, 0.5 * k as f64, -1.0])).collect();
        let mut out = vec![Vector::zero(); points.len()];
        run(&MoveBy(splat(m)), &points, &mut out).unwrap();
        for (x, y) in points.iter().zip(&out) {
            assert_eq!(*y, m.sandwich(*x));
        }
    }

    struct Product;
    impl Kernel for Product {
        type Input = (Circle, Circle);
        type Output = Even;
        #[inline(always)]
        fn apply(&self, (a, b): (Circle<F64x4>, Circle<F64x4>)) -> Even<F64x4> {
            a * b
        }
    }

    fn point(k: usize, seed: f64) -> Vector {
        let t = seed + k as f64;
        up([3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5])
    }

    fn motor(k: usize) -> Motor {
        let r = Rotor::from_axis_angle([0.6, -0.48, 0.64], 0.1 * k as f64).unwrap();
        Motor::from_rotor_translator(r, Translator::from_vector([k as f64, -2.0, 0.5]))
    }

    /// `pack_rows`/`unpack_rows` (AVX transposes in place) against `pack`/`unpack`, for
    /// types of every size of block and remainder (1, 4, 5, 6, 8, 10 and 16 coefficients).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn transposes_in_place_agree_with_packing() {
        fn check<X: Lanes + PartialEq + core::fmt::Debug>(values: [X; 4], blank: X)
        where
            X::Packed: PartialEq + core::fmt::Debug,
        {
            // SAFETY: run only where the CPU has AVX; the pointers are to `values` and `back`.
            unsafe {
                let packed = X::pack_rows(values.each_ref().map(|v| v as *const X));
                assert_eq!(packed, X::pack(values));
                let mut back = [blank; 4];
                X::unpack_rows(packed, back.each_mut().map(|v| v as *mut X));
                assert_eq!(back, values);
            }
        }
        if !std::is_x86_feature_detected!("avx") {
            return;
        }
        // Distinct values in every coefficient of every lane.
        macro_rules! values {
            ($t:ident, $seed:expr) => {
                core::array::from_fn::<crate::$t, 4, _>(|l| {
                    crate::$t::from_array(core::array::from_fn(|k| (100 * l + k) as f64 + $seed))
                })
            };
        }
        macro_rules! each {
            ($($t:ident),*) => {$(
                check(values!($t, 0.5), crate::$t::zero());
            )*};
        }
        each!(Scalar, Plane, Vector, Line, Motor, Circle, Even);
        let (rotors, points) = (values!(Rotor, 0.25), values!(Vector, 0.75));
        check(core::array::from_fn(|l| (rotors[l], points[l])), (crate::Rotor::zero(), Vector::zero()));
    }

    #[test]
    fn every_path_gives_the_bits_of_one_at_a_time() {
        for n in [0, 1, 3, 4, 5, 8, 11] {
            let moved: Vec<_> = (0..n).map(|k| (motor(k), point(k, 0.0))).collect();
            let want: Vec<Vector> = moved.iter().map(|&(m, x)| m.sandwich(x)).collect();
            let mut got = vec![Vector::zero(); n];
            run(&Sandwiched, &moved, &mut got).unwrap();
            assert_eq!(got, want, "run, n = {n}");
            got.fill(Vector::zero());
            map_lanes(&moved, &mut got, &|x| Sandwiched.apply(x));
            assert_eq!(got, want, "baseline, n = {n}");
            got.fill(Vector::zero());
            map(&moved, &mut got, |(m, x): (Motor<F64x4>, Vector<F64x4>)| m.sandwich(x)).unwrap();
            assert_eq!(got, want, "map, n = {n}");

            let circles: Vec<(Circle, Circle)> = (0..n)
                .map(|k| {
                    ((point(k, 0.0) ^ point(k, 1.0)) ^ point(k, 2.0), (point(k, 3.0) ^ point(k, 4.0)) ^ point(k, 5.0))
                })
                .collect();
            let packets: Vec<_> =
                circles.chunks_exact(4).map(|c| <(Circle, Circle)>::pack([c[0], c[1], c[2], c[3]])).collect();
            let mut out = vec![Even::<F64x4>::zero(); packets.len()];
            run_packed(&Product, &packets, &mut out).unwrap();
            for (k, &(a, b)) in circles.iter().enumerate().take(packets.len() * 4) {
                assert_eq!(Even::unpack(out[k / 4])[k % 4], a * b, "packets, n = {n}");
            }
        }
    }

    #[test]
    fn lengths_must_agree() {
        let input = vec![(motor(1), point(1, 0.0)); 3];
        let mut out = vec![Vector::zero(); 2];
        assert_eq!(run(&Sandwiched, &input, &mut out), None);
        assert_eq!(map(&input, &mut out, |(m, x): (Motor<F64x4>, Vector<F64x4>)| m.sandwich(x)), None);
        assert_eq!(out, vec![Vector::zero(); 2], "nothing written");
        let mut packed = vec![Vector::<F64x4>::zero(); 1];
        assert_eq!(run_packed(&Sandwiched, &[], &mut packed), None);
    }

    #[test]
    fn lanes_are_ordered_only_when_all_agree() {
        let (a, b) = (F64x4::new([1.0, 2.0, 3.0, 4.0]), F64x4::new([2.0, 3.0, 4.0, 5.0]));
        assert!(a < b);
        assert!(b > a);
        assert_ne!(a, b);
        let mixed = F64x4::new([0.0, 5.0, 3.0, 4.0]);
        assert_eq!(a.partial_cmp(&mixed), None);
        assert_eq!(Real::max(a, mixed).to_array(), [1.0, 5.0, 3.0, 4.0]);
        assert!(F64x4::splat(1.0).is_finite() && !F64x4::new([1.0, f64::NAN, 1.0, 1.0]).is_finite());
        assert_eq!((-a).to_array(), [-1.0, -2.0, -3.0, -4.0]);
        assert_eq!(Real::sqrt(F64x4::new([4.0, 9.0, 16.0, 0.25])).to_array(), [2.0, 3.0, 4.0, 0.5]);
        let (l, s) =
            (Line::through([0.0; 3], [1.0, 0.0, 0.0]).unwrap(), Sphere::from_centre_radius([0.0; 3], 1.0).unwrap());
        assert_eq!(crate::PointPair::unpack(Line::pack([l; 4]) & Sphere::pack([s; 4]))[2], l & s);
    }
}
