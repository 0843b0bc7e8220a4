//! Where a loop reads its operands: one array of values, or a tuple of arrays of one length
//! (columns), each element of a kernel's tuple input read from its own array in place, so
//! that operands kept apart are never copied into an array of tuples first.

use super::{Element, Lane, Lanes, Over};
#[cfg(target_arch = "x86_64")]
use super::{F32x8, F32x16, F64x4, F64x8};
use core::ops::Range;

/// The operands of [`run_columns`](super::run_columns): a slice `&[X]` (items `X`), or a
/// pair or triple of slices of one length (items `(A, B)`, `(A, B, C)`), row `i` of each
/// together making item `i`. Sealed: the loops read rows through it without bounds checks.
pub trait Columns: Copy + sealed::Sealed {
    /// One row's operands.
    type Item: Lanes;
    /// The rows: `None` where the arrays' lengths differ.
    fn rows(&self) -> Option<usize>;
    /// Row `i`, by value (`i` below [`rows`](Columns::rows)).
    fn row(&self, i: usize) -> Self::Item;
    /// The rows `range` (panics where they do not exist, as slicing does).
    fn part(self, range: Range<usize>) -> Self;
    /// Rows `first .. first + L::LANES` packed by value.
    fn pack_lanes<L: Lane>(&self, first: usize) -> Over<Self::Item, L>;
    /// Rows `first .. first + 4` by AVX transposes in place.
    ///
    /// # Safety
    /// The CPU must have AVX, and `first + 4` rows must exist.
    #[cfg(target_arch = "x86_64")]
    unsafe fn pack_rows(&self, first: usize) -> Over<Self::Item, F64x4>;
    /// Rows `first .. first + 8` by AVX-512 transposes in place.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `first + 8` rows must exist.
    #[cfg(target_arch = "x86_64")]
    unsafe fn pack_rows8(&self, first: usize) -> Over<Self::Item, F64x8>;
    /// Rows `first .. first + 8` (f32 values) by AVX transposes in place.
    ///
    /// # Safety
    /// The CPU must have AVX, and `first + 8` rows must exist.
    #[cfg(target_arch = "x86_64")]
    unsafe fn pack_rows_f32x8(&self, first: usize) -> Over<Self::Item, F32x8>;
    /// Rows `first .. first + 16` (f32 values) by AVX-512 transposes in place.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, and `first + 16` rows must exist.
    #[cfg(target_arch = "x86_64")]
    unsafe fn pack_rows16(&self, first: usize) -> Over<Self::Item, F32x16>;
}

mod sealed {
    pub trait Sealed {}
}

impl<X: Lanes> sealed::Sealed for &[X] {}

impl<X: Lanes> Columns for &[X] {
    type Item = X;
    #[inline(always)]
    fn rows(&self) -> Option<usize> {
        Some(self.len())
    }
    #[inline(always)]
    fn row(&self, i: usize) -> X {
        self[i]
    }
    #[inline(always)]
    fn part(self, range: Range<usize>) -> Self {
        &self[range]
    }
    #[inline(always)]
    fn pack_lanes<L: Lane>(&self, first: usize) -> Over<X, L> {
        X::pack_lanes::<L>(&self[first..first + L::LANES])
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows(&self, first: usize) -> Over<X, F64x4> {
        // SAFETY: the caller's CPU has AVX and rows `first .. first + 4` exist.
        unsafe { X::pack_rows([0, 1, 2, 3].map(|i| self.as_ptr().add(first + i))) }
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows8(&self, first: usize) -> Over<X, F64x8> {
        // SAFETY: the caller's CPU has AVX-512 and rows `first .. first + 8` exist.
        unsafe { X::pack_rows8(core::array::from_fn(|i| self.as_ptr().add(first + i))) }
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows_f32x8(&self, first: usize) -> Over<X, F32x8> {
        // SAFETY: the caller's CPU has AVX and rows `first .. first + 8` exist.
        unsafe { X::pack_rows_f32x8(core::array::from_fn(|i| self.as_ptr().add(first + i))) }
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn pack_rows16(&self, first: usize) -> Over<X, F32x16> {
        // SAFETY: the caller's CPU has AVX-512 and rows `first .. first + 16` exist.
        unsafe { X::pack_rows16(core::array::from_fn(|i| self.as_ptr().add(first + i))) }
    }
}

macro_rules! columns {
    ($($x:ident $k:tt),*) => {
        impl<E: Element, $($x: Lanes<Element = E>),*> sealed::Sealed for ($(&[$x],)*) {}

        /// Arrays of one length, each an element of the tuple (of one scalar).
        impl<E: Element, $($x: Lanes<Element = E>),*> Columns for ($(&[$x],)*) {
            type Item = ($($x,)*);
            #[inline(always)]
            fn rows(&self) -> Option<usize> {
                let n = self.0.len();
                [$(self.$k.len()),*].iter().all(|&m| m == n).then_some(n)
            }
            #[inline(always)]
            fn row(&self, i: usize) -> Self::Item {
                ($(self.$k[i],)*)
            }
            #[inline(always)]
            fn part(self, range: Range<usize>) -> Self {
                ($(&self.$k[range.clone()],)*)
            }
            #[inline(always)]
            fn pack_lanes<L: Lane>(&self, first: usize) -> Over<Self::Item, L> {
                ($(self.$k.pack_lanes::<L>(first),)*)
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows(&self, first: usize) -> Over<Self::Item, F64x4> {
                // SAFETY: the caller's, for every array (they have one length).
                unsafe { ($(self.$k.pack_rows(first),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows8(&self, first: usize) -> Over<Self::Item, F64x8> {
                // SAFETY: as in `pack_rows`.
                unsafe { ($(self.$k.pack_rows8(first),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows_f32x8(&self, first: usize) -> Over<Self::Item, F32x8> {
                // SAFETY: as in `pack_rows`.
                unsafe { ($(self.$k.pack_rows_f32x8(first),)*) }
            }
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            unsafe fn pack_rows16(&self, first: usize) -> Over<Self::Item, F32x16> {
                // SAFETY: as in `pack_rows`.
                unsafe { ($(self.$k.pack_rows16(first),)*) }
            }
        }
    };
}
columns!(A 0, B 1);
columns!(A 0, B 1, C 2);
