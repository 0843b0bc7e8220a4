//! [`Lanes`]: a generated type (or a tuple of them) over lanes, and the moves between
//! values and lanes.

use super::{Element, F32x8, F32x16, F64x4, F64x8, Lane};

/// A generated type (or a tuple of them) that runs on lanes, field by field:
/// `Line<f64>::Over<F64x4>` is `Line<F64x4>`, four lines in structure-of-arrays form.
pub trait Lanes: Copy {
    /// The scalar of the values (of every element, for a tuple), which picks the lanes
    /// [`run`](super::run) puts them in.
    type Element: Element;
    /// The same type over the lanes `L`.
    type Over<L: Lane>: Copy;
    /// The values of `x` (one per lane, `L::LANES` of them) as one value whose lane `k` is
    /// `x[k]`.
    fn pack_lanes<L: Lane>(x: &[Self]) -> Self::Over<L>;
    /// The inverse of [`Lanes::pack_lanes`]: lane `k` into `out[k]`.
    fn unpack_lanes<L: Lane>(p: Self::Over<L>, out: &mut [Self]);
    /// `x` in every lane ([`splat`]): [`Lanes::pack_lanes`] of `L::LANES` copies, which a
    /// type of coefficients does coefficient by coefficient instead (no copies to pack).
    #[inline(always)]
    fn splat_lanes<L: Lane>(x: Self) -> Self::Over<L> {
        Self::pack_lanes(&[x; 16][..L::LANES])
    }
    /// `[x₀, x₁, x₂, x₃]` as one value whose lane `k` is `x_k`.
    #[inline(always)]
    fn pack(x: [Self; 4]) -> Self::Over<F64x4> {
        Self::pack_lanes(&x)
    }
    /// The inverse of [`Lanes::pack`].
    #[inline(always)]
    fn unpack(p: Self::Over<F64x4>) -> [Self; 4] {
        let mut out = [Self::pack_filler(); 4];
        Self::unpack_lanes(p, &mut out);
        out
    }
    /// Some value of the type, to be overwritten ([`Lanes::unpack`]'s array).
    fn pack_filler() -> Self;
    /// [`Lanes::pack`] of the values at `rows`, read in place by AVX shuffles where the
    /// type allows (the same values).
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to four values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows(rows: [*const Self; 4]) -> Self::Over<F64x4> {
        // SAFETY: the caller's.
        unsafe { read_rows(rows) }
    }
    /// [`Lanes::unpack`] into the values at `rows`, written in place by AVX shuffles where
    /// the type allows.
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to four writable values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn unpack_rows(p: Self::Over<F64x4>, rows: [*mut Self; 4]) {
        // SAFETY: the caller's.
        unsafe { write_rows(p, rows) }
    }
    /// The eight values at `rows` in eight lanes, read in place by AVX-512 shuffles.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `rows` must point to eight values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows8(rows: [*const Self; 8]) -> Self::Over<F64x8> {
        // SAFETY: the caller's.
        unsafe { read_rows(rows) }
    }
    /// The inverse of [`Lanes::pack_rows8`], written in place.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `rows` must point to eight writable values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn unpack_rows8(p: Self::Over<F64x8>, rows: [*mut Self; 8]) {
        // SAFETY: the caller's.
        unsafe { write_rows(p, rows) }
    }
    /// The eight values at `rows` in eight f32 lanes, read in place by AVX shuffles where
    /// the type allows.
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to eight values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows_f32x8(rows: [*const Self; 8]) -> Self::Over<F32x8> {
        // SAFETY: the caller's.
        unsafe { read_rows(rows) }
    }
    /// The inverse of [`Lanes::pack_rows_f32x8`], written in place.
    ///
    /// # Safety
    /// The CPU must have AVX, and `rows` must point to eight writable values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn unpack_rows_f32x8(p: Self::Over<F32x8>, rows: [*mut Self; 8]) {
        // SAFETY: the caller's.
        unsafe { write_rows(p, rows) }
    }
    /// The sixteen values at `rows` in sixteen f32 lanes, read in place by AVX-512 shuffles
    /// where the type allows.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `rows` must point to sixteen values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows16(rows: [*const Self; 16]) -> Self::Over<F32x16> {
        // SAFETY: the caller's.
        unsafe { read_rows(rows) }
    }
    /// The inverse of [`Lanes::pack_rows16`], written in place.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `rows` must point to sixteen writable values.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn unpack_rows16(p: Self::Over<F32x16>, rows: [*mut Self; 16]) {
        // SAFETY: the caller's.
        unsafe { write_rows(p, rows) }
    }
}

/// The values at `rows` packed by value: what the in-place transposes default to.
///
/// # Safety
/// `rows` must point to valid values.
#[inline(always)]
unsafe fn read_rows<X: Lanes, L: Lane, const N: usize>(rows: [*const X; N]) -> X::Over<L> {
    // SAFETY: the caller's pointers are valid.
    X::pack_lanes(&rows.map(|r| unsafe { *r }))
}

/// The inverse of [`read_rows`]: lane `k` written to `rows[k]`.
///
/// # Safety
/// `rows` must point to writable values.
#[inline(always)]
unsafe fn write_rows<X: Lanes, L: Lane, const N: usize>(p: X::Over<L>, rows: [*mut X; N]) {
    let mut values = [X::pack_filler(); N];
    X::unpack_lanes(p, &mut values);
    for (r, v) in rows.into_iter().zip(values) {
        // SAFETY: the caller's pointers are valid.
        unsafe { *r = v };
    }
}

/// `x` in every lane: a value of any generated type as the packet of `L::LANES` copies (a
/// kernel's run-time state, such as the motor every point is moved by).
#[inline(always)]
pub fn splat<X: Lanes, L: Lane>(x: X) -> X::Over<L> {
    X::splat_lanes(x)
}

/// `Lanes` for the named generated types over `f64` and `f32`: what `algebra!` emits for an algebra that
/// asks for it (`lanes = cga_core::simd;`), spelled through `$crate` so that it expands in any
/// crate.
#[doc(hidden)]
#[macro_export]
macro_rules! __simd_lanes {
    ($($t:ident),*) => {$(
        // The generated types are `#[repr(C)]` structs of their coefficients in field order:
        // a value is `[T; N]` in memory, a packed one `[F64x4; N]`.
        $crate::__simd_lanes!(@by_value $t f64 {
            $crate::__simd_lanes!(@rows $t avx F64x4 4 pack_rows unpack_rows);
            $crate::__simd_lanes!(@rows $t avx512 F64x8 8 pack_rows8 unpack_rows8);
        });
        $crate::__simd_lanes!(@by_value $t f32 {
            $crate::__simd_lanes!(@rows $t avx_f32 F32x8 8 pack_rows_f32x8 unpack_rows_f32x8);
            $crate::__simd_lanes!(@rows $t avx512_f32 F32x16 16 pack_rows16 unpack_rows16);
        });
    )*};
    // The transposes of `simd::transpose::$module` as `Lanes`' in-place moves on `$n` rows.
    (@rows $t:ident $module:ident $lanes:ident $n:literal $pack:ident $unpack:ident) => {
        #[cfg(target_arch = "x86_64")]
        #[inline(always)]
        unsafe fn $pack(rows: [*const Self; $n]) -> $t<$crate::simd::$lanes> {
            let mut out = core::mem::MaybeUninit::<$t<$crate::simd::$lanes>>::uninit();
            // SAFETY: the caller's CPU has the transposes' level and its rows are valid;
            // `pack` writes every coefficient of `out`.
            unsafe {
                $crate::simd::transpose::$module::pack::<{ Self::BLADES.len() }>(rows.map(|r| r.cast()), out.as_mut_ptr().cast());
                out.assume_init()
            }
        }
        #[cfg(target_arch = "x86_64")]
        #[inline(always)]
        unsafe fn $unpack(p: $t<$crate::simd::$lanes>, rows: [*mut Self; $n]) {
            // SAFETY: as in the pack.
            unsafe { $crate::simd::transpose::$module::unpack::<{ Self::BLADES.len() }>((&raw const p).cast(), rows.map(|r| r.cast())) }
        }
    };
    (@by_value $t:ident $e:ident { $($rows:tt)* }) => {
        impl $crate::simd::Lanes for $t<$e> {
            type Element = $e;
            type Over<L: $crate::simd::Lane> = $t<L>;
            #[inline(always)]
            fn pack_lanes<L: $crate::simd::Lane>(x: &[Self]) -> $t<L> {
                let a: [[$e; Self::BLADES.len()]; 16] = core::array::from_fn(|l| x.get(l).map_or([0.0; Self::BLADES.len()], |v| v.to_array()));
                $t::from_array(core::array::from_fn(|k| L::from_fn(|l| $crate::Real::to_f64(a[l][k]))))
            }
            #[inline(always)]
            fn splat_lanes<L: $crate::simd::Lane>(x: Self) -> $t<L> {
                let a = x.to_array();
                $t::from_array(core::array::from_fn(|k| L::from_fn(|_| $crate::Real::to_f64(a[k]))))
            }
            #[inline(always)]
            fn unpack_lanes<L: $crate::simd::Lane>(p: $t<L>, out: &mut [Self]) {
                let a = p.to_array();
                for (l, o) in out.iter_mut().enumerate().take(L::LANES) {
                    // Exact: the lanes hold values of `$e`.
                    *o = $t::from_array(core::array::from_fn(|k| <$e as $crate::Real>::from_f64(a[k].lane(l))));
                }
            }
            #[inline(always)]
            fn pack_filler() -> Self {
                $t::zero()
            }
            $($rows)*
        }
    };
}
macro_rules! tuple_lanes {
    ($($x:ident $k:tt),*) => {
        /// Tuples pack element by element.
        /// Of one scalar: each element goes into the same lanes.
        impl<E: Element, $($x: Lanes<Element = E>),*> Lanes for ($($x,)*) {
            type Element = E;
            type Over<L: Lane> = ($($x::Over<L>,)*);
            #[inline(always)]
            fn pack_lanes<L: Lane>(x: &[Self]) -> Self::Over<L> {
                ($({
                    let part: [$x; 16] = core::array::from_fn(|l| x.get(l).map_or($x::pack_filler(), |t| t.$k));
                    $x::pack_lanes::<L>(&part[..L::LANES])
                },)*)
            }
            #[inline(always)]
            fn unpack_lanes<L: Lane>(p: Self::Over<L>, out: &mut [Self]) {
                $({
                    let mut part = [$x::pack_filler(); 16];
                    $x::unpack_lanes::<L>(p.$k, &mut part[..L::LANES]);
                    for (o, v) in out.iter_mut().zip(part) {
                        o.$k = v;
                    }
                })*
            }
            #[inline(always)]
            fn splat_lanes<L: Lane>(x: Self) -> Self::Over<L> {
                ($($x::splat_lanes::<L>(x.$k),)*)
            }
            #[inline(always)]
            fn pack_filler() -> Self {
                ($($x::pack_filler(),)*)
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows(rows: [*const Self; 4]) -> Self::Over<F64x4> {
                // SAFETY: the caller's CPU has AVX and its pointers are valid.
                unsafe { ($($x::pack_rows(rows.map(|r| &raw const (*r).$k)),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows(p: Self::Over<F64x4>, rows: [*mut Self; 4]) {
                // SAFETY: as in `pack_rows`.
                unsafe { $($x::unpack_rows(p.$k, rows.map(|r| &raw mut (*r).$k));)* }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows8(rows: [*const Self; 8]) -> Self::Over<F64x8> {
                // SAFETY: the caller's CPU has AVX-512 and its pointers are valid.
                unsafe { ($($x::pack_rows8(rows.map(|r| &raw const (*r).$k)),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows8(p: Self::Over<F64x8>, rows: [*mut Self; 8]) {
                // SAFETY: as in `pack_rows8`.
                unsafe { $($x::unpack_rows8(p.$k, rows.map(|r| &raw mut (*r).$k));)* }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows_f32x8(rows: [*const Self; 8]) -> Self::Over<F32x8> {
                // SAFETY: the caller's CPU has AVX and its pointers are valid.
                unsafe { ($($x::pack_rows_f32x8(rows.map(|r| &raw const (*r).$k)),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows_f32x8(p: Self::Over<F32x8>, rows: [*mut Self; 8]) {
                // SAFETY: as in `pack_rows_f32x8`.
                unsafe { $($x::unpack_rows_f32x8(p.$k, rows.map(|r| &raw mut (*r).$k));)* }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows16(rows: [*const Self; 16]) -> Self::Over<F32x16> {
                // SAFETY: the caller's CPU has AVX-512 and its pointers are valid.
                unsafe { ($($x::pack_rows16(rows.map(|r| &raw const (*r).$k)),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn unpack_rows16(p: Self::Over<F32x16>, rows: [*mut Self; 16]) {
                // SAFETY: as in `pack_rows16`.
                unsafe { $($x::unpack_rows16(p.$k, rows.map(|r| &raw mut (*r).$k));)* }
            }
        }
    };
}
tuple_lanes!(A 0, B 1);
tuple_lanes!(A 0, B 1, C 2);
