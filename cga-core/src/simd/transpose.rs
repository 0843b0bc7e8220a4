//! Transposes between values as they lie in memory (rows: one value's coefficients, in
//! field order, since the generated types are `#[repr(C)]`) and lanes (columns: one
//! coefficient of every value), read and written in place: four f64 or eight f32 rows with
//! AVX, eight f64 or sixteen f32 rows with AVX-512.
//!
//! Each transposed register passes through an empty `asm!` that LLVM cannot look into:
//! given the lanes of a transpose, it otherwise folds the shuffles into scalar loads and
//! stores and computes the whole operation in scalar code.

/// 4 × 4 transposes with AVX, between four values' coefficients in memory (rows) and one
/// lane per value (columns): a block of four coefficients is read as 128-bit halves joined
/// by `vinsertf128` and paired by `vunpcklpd`/`vunpckhpd` (full-width loads and `vperm2f128`
/// were slower), and written back by the same unpacks and `vperm2f128`; a pair left over
/// takes 128-bit halves, a single one is gathered.
pub mod avx {
    use super::super::F64x4;
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

/// 8-row transposes with AVX-512: a block of eight coefficients is an 8 × 8 transpose
/// (`vunpcklpd`/`vunpckhpd`, two-source `vpermt2pd`, `vshuff64x2`: 24 shuffles, its own
/// inverse), a block of four joins rows `k` and `k + 4` in one register (`vinsertf64x4`
/// on the way in, an ordinary and a masked store on the way out, which is 10 % faster for
/// a rotor product than extracting the upper half) and transposes the halves as two
/// 4 × 4s, a pair joins four rows' pairs (`vinsertf64x2`) and splits them by two
/// `vpermt2pd`, and a single coefficient is gathered and scattered one by one.
pub mod avx512 {
    use super::super::F64x8;
    use core::arch::x86_64::*;

    /// `v`, which LLVM may not look into (see the module's notes).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn opaque(mut v: __m512d) -> __m512d {
        // SAFETY: an empty sequence: it reads, writes and clobbers nothing but `v`'s register.
        unsafe { core::arch::asm!("/* {0} */", inout(zmm_reg) v, options(pure, nomem, nostack, preserves_flags)) };
        v
    }

    /// The indices that take lanes `0, 1` of each 128-bit half of `a` and `b` alternately:
    /// `[a₀ a₁ b₀ b₁ a₄ a₅ b₄ b₅]` (and with `ODD`, lanes `2, 3` and `6, 7`).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn pairs<const ODD: bool>() -> __m512i {
        if ODD { _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2) } else { _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0) }
    }

    /// The 8 × 8 transpose of `z` (rows to columns, and columns to rows).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn transpose8(z: [__m512d; 8]) -> [__m512d; 8] {
        // Unpacks pair rows 2k, 2k + 1 per coefficient: [r₀c₀ r₁c₀ r₀c₂ r₁c₂ r₀c₄ r₁c₄ r₀c₆ r₁c₆].
        let lo = [0, 2, 4, 6].map(|k| _mm512_unpacklo_pd(z[k], z[k + 1]));
        let hi = [0, 2, 4, 6].map(|k| _mm512_unpackhi_pd(z[k], z[k + 1]));
        // Two-source permutes join pairs of pairs: [r₀..r₃ c₀ | r₀..r₃ c₄] and so on.
        let quad = |a: __m512d, b: __m512d| {
            let (even, odd) = (pairs::<false>(), pairs::<true>());
            (_mm512_permutex2var_pd(a, even, b), _mm512_permutex2var_pd(a, odd, b))
        };
        let (c04_a, c26_a) = quad(lo[0], lo[1]);
        let (c15_a, c37_a) = quad(hi[0], hi[1]);
        let (c04_b, c26_b) = quad(lo[2], lo[3]);
        let (c15_b, c37_b) = quad(hi[2], hi[3]);
        // 256-bit halves join rows 0–3 and 4–7.
        let join = |a: __m512d, b: __m512d| {
            (_mm512_shuffle_f64x2::<0b01_00_01_00>(a, b), _mm512_shuffle_f64x2::<0b11_10_11_10>(a, b))
        };
        let (c0, c4) = join(c04_a, c04_b);
        let (c2, c6) = join(c26_a, c26_b);
        let (c1, c5) = join(c15_a, c15_b);
        let (c3, c7) = join(c37_a, c37_b);
        [c0, c1, c2, c3, c4, c5, c6, c7]
    }

    /// Rows `k` and `k + 4` of four coefficients each, as the halves of register `k`, to
    /// four columns, and back: its own inverse.
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn transpose4x2(z: [__m512d; 4]) -> [__m512d; 4] {
        // Within each half a 4 × 4: unpacks, then two-source permutes of pairs.
        let (t0, t1) = (_mm512_unpacklo_pd(z[0], z[1]), _mm512_unpackhi_pd(z[0], z[1]));
        let (t2, t3) = (_mm512_unpacklo_pd(z[2], z[3]), _mm512_unpackhi_pd(z[2], z[3]));
        let (even, odd) = (pairs::<false>(), pairs::<true>());
        [
            _mm512_permutex2var_pd(t0, even, t2),
            _mm512_permutex2var_pd(t1, even, t3),
            _mm512_permutex2var_pd(t0, odd, t2),
            _mm512_permutex2var_pd(t1, odd, t3),
        ]
    }

    /// `out[k]` holds coefficient `k` of the eight rows of `N` values each.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, each row must hold `N` values and `out` must be
    /// writable.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    pub unsafe fn pack<const N: usize>(rows: [*const f64; 8], out: *mut [F64x8; N]) {
        let out = out.cast::<f64>();
        let mut c = 0;
        // SAFETY: every load reads within a row, every store within `out`.
        unsafe {
            let store = |k: usize, v: __m512d| _mm512_storeu_pd(out.add(8 * k), opaque(v));
            while c + 8 <= N {
                let columns = transpose8(rows.map(|r| _mm512_loadu_pd(r.add(c))));
                columns.into_iter().enumerate().for_each(|(k, v)| store(c + k, v));
                c += 8;
            }
            if c + 4 <= N {
                // Masked loads put row k + 4 in the upper half without a shuffle: lanes
                // 4–7 read from 4 before its coefficient `c`, lanes 0–3 are not read.
                let half = |k: usize| {
                    let lo = _mm512_castpd256_pd512(_mm256_loadu_pd(rows[k].add(c)));
                    _mm512_insertf64x4::<1>(lo, _mm256_loadu_pd(rows[k + 4].add(c)))
                };
                let columns = transpose4x2([0, 1, 2, 3].map(half));
                columns.into_iter().enumerate().for_each(|(k, v)| store(c + k, v));
                c += 4;
            }
            if c + 2 <= N {
                let pair = |k: usize| _mm_loadu_pd(rows[k].add(c));
                let four = |k: usize| {
                    let v = _mm512_castpd128_pd512(pair(k));
                    let v = _mm512_insertf64x2::<1>(v, pair(k + 1));
                    let v = _mm512_insertf64x2::<2>(v, pair(k + 2));
                    _mm512_insertf64x2::<3>(v, pair(k + 3))
                };
                let (a, b) = (four(0), four(4));
                store(c, _mm512_permutex2var_pd(a, _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0), b));
                store(c + 1, _mm512_permutex2var_pd(a, _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1), b));
                c += 2;
            }
            if c < N {
                let r = rows.map(|r| *r.add(c));
                store(c, _mm512_set_pd(r[7], r[6], r[5], r[4], r[3], r[2], r[1], r[0]));
            }
        }
    }

    /// The inverse of [`pack`]: row `i` gets lane `i` of every `p[k]`.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, each row must hold `N` writable values.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    pub unsafe fn unpack<const N: usize>(p: *const [F64x8; N], rows: [*mut f64; 8]) {
        let p = p.cast::<f64>();
        let mut c = 0;
        // SAFETY: as in `pack`, with loads and stores exchanged; a masked store touches only
        // its enabled lanes, which lie within the row.
        unsafe {
            let load = |k: usize| opaque(_mm512_loadu_pd(p.add(8 * k)));
            while c + 8 <= N {
                let z = transpose8(core::array::from_fn(|k| load(c + k)));
                for (r, v) in rows.into_iter().zip(z) {
                    _mm512_storeu_pd(r.add(c), opaque(v));
                }
                c += 8;
            }
            if c + 4 <= N {
                // The upper half goes to row k + 4 by a masked store from 4 before its
                // coefficient `c` (lanes 0–3 are not written), without a shuffle; the
                // barrier keeps LLVM from recombining the shuffles with the stores.
                let z = transpose4x2([load(c), load(c + 1), load(c + 2), load(c + 3)]);
                for (k, v) in z.into_iter().enumerate() {
                    let v = opaque(v);
                    _mm256_storeu_pd(rows[k].add(c), _mm512_castpd512_pd256(v));
                    _mm512_mask_storeu_pd(rows[k + 4].add(c).wrapping_sub(4), 0xf0, v);
                }
                c += 4;
            }
            if c + 2 <= N {
                let (x, y) = (load(c), load(c + 1));
                let a = _mm512_permutex2var_pd(x, _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), y);
                let b = _mm512_permutex2var_pd(x, _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4), y);
                _mm_storeu_pd(rows[0].add(c), _mm512_castpd512_pd128(a));
                _mm_storeu_pd(rows[1].add(c), _mm512_extractf64x2_pd::<1>(a));
                _mm_storeu_pd(rows[2].add(c), _mm512_extractf64x2_pd::<2>(a));
                _mm_storeu_pd(rows[3].add(c), _mm512_extractf64x2_pd::<3>(a));
                _mm_storeu_pd(rows[4].add(c), _mm512_castpd512_pd128(b));
                _mm_storeu_pd(rows[5].add(c), _mm512_extractf64x2_pd::<1>(b));
                _mm_storeu_pd(rows[6].add(c), _mm512_extractf64x2_pd::<2>(b));
                _mm_storeu_pd(rows[7].add(c), _mm512_extractf64x2_pd::<3>(b));
                c += 2;
            }
            if c < N {
                let mut lanes = [0.0; 8];
                _mm512_storeu_pd(lanes.as_mut_ptr(), load(c));
                for (r, x) in rows.into_iter().zip(lanes) {
                    *r.add(c) = x;
                }
            }
        }
    }
}

/// 16-row transposes of f32 values with AVX-512: a block of eight coefficients puts rows
/// `j` and `j + 8` in the halves of register `j` and transposes each half as an 8 × 8
/// (`vunpcklps`/`vunpckhps`, `vunpcklpd`/`vunpckhpd` on pairs, two-source `vpermt2ps` for
/// the 128-bit quarters: 24 shuffles, its own inverse); a block of four puts rows `j`,
/// `j + 4`, `j + 8`, `j + 12` in the quarters of register `j` and transposes each quarter as
/// a 4 × 4 (8 shuffles, its own inverse), written back by masked stores without a shuffle;
/// a pair is read as one f64 per row and split by two `vpermt2ps`; a single coefficient is
/// gathered and scattered one by one.
pub mod avx512_f32 {
    use super::super::F32x16;
    use core::arch::x86_64::*;

    /// `v`, which LLVM may not look into (see the module's notes).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn opaque(mut v: __m512) -> __m512 {
        // SAFETY: an empty sequence: it reads, writes and clobbers nothing but `v`'s register.
        unsafe { core::arch::asm!("/* {0} */", inout(zmm_reg) v, options(pure, nomem, nostack, preserves_flags)) };
        v
    }

    /// Within each 128-bit quarter, the 4 × 4 transpose of the four registers' quarters.
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn transpose4(z: [__m512; 4]) -> [__m512; 4] {
        let (t0, t1) = (_mm512_unpacklo_ps(z[0], z[1]), _mm512_unpackhi_ps(z[0], z[1]));
        let (t2, t3) = (_mm512_unpacklo_ps(z[2], z[3]), _mm512_unpackhi_ps(z[2], z[3]));
        let pairs = |a: __m512, b: __m512| {
            let (a, b) = (_mm512_castps_pd(a), _mm512_castps_pd(b));
            (_mm512_castpd_ps(_mm512_unpacklo_pd(a, b)), _mm512_castpd_ps(_mm512_unpackhi_pd(a, b)))
        };
        let ((c0, c1), (c2, c3)) = (pairs(t0, t2), pairs(t1, t3));
        [c0, c1, c2, c3]
    }

    /// Within each 256-bit half, the 8 × 8 transpose of the eight registers' halves.
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn transpose8(z: [__m512; 8]) -> [__m512; 8] {
        // 4 × 4s within quarters: registers 0–3 and 4–7 each give four columns of four rows.
        let a = transpose4([z[0], z[1], z[2], z[3]]);
        let b = transpose4([z[4], z[5], z[6], z[7]]);
        // Quarters of `a` (rows 0–3 and 8–11) and `b` (rows 4–7 and 12–15) interleaved:
        // coefficient k from quarters 0 and 2, coefficient k + 4 from quarters 1 and 3.
        let low = _mm512_set_epi32(27, 26, 25, 24, 11, 10, 9, 8, 19, 18, 17, 16, 3, 2, 1, 0);
        let high = _mm512_set_epi32(31, 30, 29, 28, 15, 14, 13, 12, 23, 22, 21, 20, 7, 6, 5, 4);
        let join = |k: usize, index: __m512i| _mm512_permutex2var_ps(a[k], index, b[k]);
        [
            join(0, low),
            join(1, low),
            join(2, low),
            join(3, low),
            join(0, high),
            join(1, high),
            join(2, high),
            join(3, high),
        ]
    }

    /// Coefficients `c .. c + 8` of the sixteen rows into `out[c ..]`.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ; the rows must hold them, `out` must be writable.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn pack8(rows: [*const f32; 16], c: usize, out: *mut f32) {
        // SAFETY: the caller's.
        unsafe {
            let half = |j: usize| {
                let lo = _mm512_castps256_ps512(_mm256_loadu_ps(rows[j].add(c)));
                _mm512_insertf32x8::<1>(lo, _mm256_loadu_ps(rows[j + 8].add(c)))
            };
            for (k, v) in transpose8([half(0), half(1), half(2), half(3), half(4), half(5), half(6), half(7)])
                .into_iter()
                .enumerate()
            {
                _mm512_storeu_ps(out.add(16 * (c + k)), opaque(v));
            }
        }
    }

    /// Coefficients `c .. c + 4` of rows `j`, `j + 4`, `j + 8` and `j + 12`, one to a
    /// quarter.
    ///
    /// # Safety
    /// As for [`pack8`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn quarters(rows: [*const f32; 16], j: usize, c: usize) -> __m512 {
        // SAFETY: the caller's.
        unsafe {
            let v = _mm512_castps128_ps512(_mm_loadu_ps(rows[j].add(c)));
            let v = _mm512_insertf32x4::<1>(v, _mm_loadu_ps(rows[j + 4].add(c)));
            let v = _mm512_insertf32x4::<2>(v, _mm_loadu_ps(rows[j + 8].add(c)));
            _mm512_insertf32x4::<3>(v, _mm_loadu_ps(rows[j + 12].add(c)))
        }
    }

    /// Coefficients `c .. c + 4` of the sixteen rows into `out[c ..]`.
    ///
    /// # Safety
    /// As for [`pack8`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn pack4(rows: [*const f32; 16], c: usize, out: *mut f32) {
        // SAFETY: the caller's.
        unsafe {
            for (k, v) in
                transpose4([quarters(rows, 0, c), quarters(rows, 1, c), quarters(rows, 2, c), quarters(rows, 3, c)])
                    .into_iter()
                    .enumerate()
            {
                _mm512_storeu_ps(out.add(16 * (c + k)), opaque(v));
            }
        }
    }

    /// Coefficients `c, c + 1` of the sixteen rows into `out[c ..]`: a row's pair read as
    /// one f64, eight rows to a register, then split into even and odd lanes.
    ///
    /// # Safety
    /// As for [`pack8`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn pack2(rows: [*const f32; 16], c: usize, out: *mut f32) {
        // SAFETY: the caller's.
        unsafe {
            let pairs: [f64; 16] = core::array::from_fn(|j| rows[j].add(c).cast::<f64>().read_unaligned());
            let (a, b) = (_mm512_loadu_ps(pairs.as_ptr().cast()), _mm512_loadu_ps(pairs[8..].as_ptr().cast()));
            let even = _mm512_set_epi32(30, 28, 26, 24, 22, 20, 18, 16, 14, 12, 10, 8, 6, 4, 2, 0);
            let odd = _mm512_set_epi32(31, 29, 27, 25, 23, 21, 19, 17, 15, 13, 11, 9, 7, 5, 3, 1);
            _mm512_storeu_ps(out.add(16 * c), opaque(_mm512_permutex2var_ps(a, even, b)));
            _mm512_storeu_ps(out.add(16 * c + 16), opaque(_mm512_permutex2var_ps(a, odd, b)));
        }
    }

    /// `out[k]` holds coefficient `k` of the sixteen rows of `N` values each.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, each row must hold `N` values and `out` must be
    /// writable.
    #[inline(always)]
    pub unsafe fn pack<const N: usize>(rows: [*const f32; 16], out: *mut [F32x16; N]) {
        let out = out.cast::<f32>();
        let mut c = 0;
        // SAFETY: every load reads within a row, every store within `out`.
        unsafe {
            while c + 8 <= N {
                pack8(rows, c, out);
                c += 8;
            }
            if c + 4 <= N {
                pack4(rows, c, out);
                c += 4;
            }
            if c + 2 <= N {
                pack2(rows, c, out);
                c += 2;
            }
            if c < N {
                for (j, r) in rows.into_iter().enumerate() {
                    *out.add(16 * c + j) = *r.add(c);
                }
            }
        }
    }

    /// Coefficients `c .. c + 8` of `p` back to the sixteen rows.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ; `p` must hold them and the rows be writable.
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn unpack8(p: *const f32, c: usize, rows: [*mut f32; 16]) {
        // SAFETY: the caller's; a masked store writes only its enabled lanes, in the row.
        unsafe {
            let load = |k: usize| opaque(_mm512_loadu_ps(p.add(16 * (c + k))));
            let z = transpose8([load(0), load(1), load(2), load(3), load(4), load(5), load(6), load(7)]);
            for (j, v) in z.into_iter().enumerate() {
                let v = opaque(v);
                _mm256_storeu_ps(rows[j].add(c), _mm512_castps512_ps256(v));
                _mm512_mask_storeu_ps(rows[j + 8].add(c).wrapping_sub(8), 0xff00, v);
            }
        }
    }

    /// Coefficients `c .. c + 4` of `p` back to the sixteen rows: quarter `q` of register
    /// `j` to row `j + 4q`.
    ///
    /// # Safety
    /// As for [`unpack8`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn unpack4(p: *const f32, c: usize, rows: [*mut f32; 16]) {
        // SAFETY: the caller's.
        unsafe {
            let load = |k: usize| opaque(_mm512_loadu_ps(p.add(16 * (c + k))));
            let z = transpose4([load(0), load(1), load(2), load(3)]);
            for (j, v) in z.into_iter().enumerate() {
                let v = opaque(v);
                _mm_storeu_ps(rows[j].add(c), _mm512_castps512_ps128(v));
                _mm512_mask_storeu_ps(rows[j + 4].add(c).wrapping_sub(4), 0x00f0, v);
                _mm512_mask_storeu_ps(rows[j + 8].add(c).wrapping_sub(8), 0x0f00, v);
                _mm512_mask_storeu_ps(rows[j + 12].add(c).wrapping_sub(12), 0xf000, v);
            }
        }
    }

    /// Coefficients `c, c + 1` of `p` back to the sixteen rows, as one f64 a row.
    ///
    /// # Safety
    /// As for [`unpack8`].
    #[inline]
    #[target_feature(enable = "avx512f,avx512dq")]
    unsafe fn unpack2(p: *const f32, c: usize, rows: [*mut f32; 16]) {
        // SAFETY: the caller's.
        unsafe {
            let (x, y) = (opaque(_mm512_loadu_ps(p.add(16 * c))), opaque(_mm512_loadu_ps(p.add(16 * c + 16))));
            let lo = _mm512_set_epi32(23, 7, 22, 6, 21, 5, 20, 4, 19, 3, 18, 2, 17, 1, 16, 0);
            let hi = _mm512_set_epi32(31, 15, 30, 14, 29, 13, 28, 12, 27, 11, 26, 10, 25, 9, 24, 8);
            let mut pairs = [0.0f64; 16];
            _mm512_storeu_ps(pairs.as_mut_ptr().cast(), _mm512_permutex2var_ps(x, lo, y));
            _mm512_storeu_ps(pairs[8..].as_mut_ptr().cast(), _mm512_permutex2var_ps(x, hi, y));
            for (r, pair) in rows.into_iter().zip(pairs) {
                r.add(c).cast::<f64>().write_unaligned(pair);
            }
        }
    }

    /// The inverse of [`pack`]: row `i` gets lane `i` of every `p[k]`.
    ///
    /// # Safety
    /// The CPU must have AVX-512 F and DQ, each row must hold `N` writable values.
    #[inline(always)]
    pub unsafe fn unpack<const N: usize>(p: *const [F32x16; N], rows: [*mut f32; 16]) {
        let p = p.cast::<f32>();
        let mut c = 0;
        // SAFETY: as in `pack`, with loads and stores exchanged.
        unsafe {
            while c + 8 <= N {
                unpack8(p, c, rows);
                c += 8;
            }
            if c + 4 <= N {
                unpack4(p, c, rows);
                c += 4;
            }
            if c + 2 <= N {
                unpack2(p, c, rows);
                c += 2;
            }
            if c < N {
                for (j, r) in rows.into_iter().enumerate() {
                    *r.add(c) = *p.add(16 * c + j);
                }
            }
        }
    }
}

/// 8-row transposes of f32 values with AVX: a block of eight coefficients is the 8 × 8
/// transpose (`vunpcklps`/`vunpckhps`, `vunpcklpd`/`vunpckhpd` on pairs, `vperm2f128` for
/// the halves: 24 shuffles, its own inverse); a block of four puts rows `j` and `j + 4` in
/// the halves of register `j` and transposes each half as a 4 × 4 (8 shuffles, its own
/// inverse); a pair is read as one f64 per row (rows 0, 1, 4, 5 in one register, 2, 3, 6, 7
/// in the other) and split into its two coefficients by one `vshufps` each; a single
/// coefficient is gathered and scattered one by one.
pub mod avx_f32 {
    use super::super::F32x8;
    use core::arch::x86_64::*;

    /// `v`, which LLVM may not look into (see the module's notes).
    #[inline]
    #[target_feature(enable = "avx")]
    fn opaque(mut v: __m256) -> __m256 {
        // SAFETY: an empty sequence: it reads, writes and clobbers nothing but `v`'s register.
        unsafe { core::arch::asm!("/* {0} */", inout(ymm_reg) v, options(pure, nomem, nostack, preserves_flags)) };
        v
    }

    /// Within each 128-bit half, the 4 × 4 transpose of the four registers' halves.
    #[inline]
    #[target_feature(enable = "avx")]
    fn transpose4(z: [__m256; 4]) -> [__m256; 4] {
        let (t0, t1) = (_mm256_unpacklo_ps(z[0], z[1]), _mm256_unpackhi_ps(z[0], z[1]));
        let (t2, t3) = (_mm256_unpacklo_ps(z[2], z[3]), _mm256_unpackhi_ps(z[2], z[3]));
        let (a, b, c, d) = (_mm256_castps_pd(t0), _mm256_castps_pd(t1), _mm256_castps_pd(t2), _mm256_castps_pd(t3));
        [
            _mm256_castpd_ps(_mm256_unpacklo_pd(a, c)),
            _mm256_castpd_ps(_mm256_unpackhi_pd(a, c)),
            _mm256_castpd_ps(_mm256_unpacklo_pd(b, d)),
            _mm256_castpd_ps(_mm256_unpackhi_pd(b, d)),
        ]
    }

    /// The 8 × 8 transpose: 4 × 4s within halves, then the halves exchanged.
    #[inline]
    #[target_feature(enable = "avx")]
    fn transpose8(z: [__m256; 8]) -> [__m256; 8] {
        let a = transpose4([z[0], z[1], z[2], z[3]]);
        let b = transpose4([z[4], z[5], z[6], z[7]]);
        [
            _mm256_permute2f128_ps::<0x20>(a[0], b[0]),
            _mm256_permute2f128_ps::<0x20>(a[1], b[1]),
            _mm256_permute2f128_ps::<0x20>(a[2], b[2]),
            _mm256_permute2f128_ps::<0x20>(a[3], b[3]),
            _mm256_permute2f128_ps::<0x31>(a[0], b[0]),
            _mm256_permute2f128_ps::<0x31>(a[1], b[1]),
            _mm256_permute2f128_ps::<0x31>(a[2], b[2]),
            _mm256_permute2f128_ps::<0x31>(a[3], b[3]),
        ]
    }

    /// Coefficients `c .. c + 4` of rows `j` and `j + 4`, one to a half.
    ///
    /// # Safety
    /// The CPU must have AVX; the rows must hold them.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn halves(rows: [*const f32; 8], j: usize, c: usize) -> __m256 {
        // SAFETY: the caller's.
        unsafe {
            let v = _mm256_castps128_ps256(_mm_loadu_ps(rows[j].add(c)));
            _mm256_insertf128_ps::<1>(v, _mm_loadu_ps(rows[j + 4].add(c)))
        }
    }

    /// Coefficients `c .. c + 8`, `c .. c + 4` or `c, c + 1` of the eight rows into
    /// `out[c ..]`, by the widest block that fits in `n` coefficients from `c`.
    ///
    /// # Safety
    /// The CPU must have AVX; the rows must hold `c + n` values, `out` must be writable.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn pack_block(rows: [*const f32; 8], c: usize, n: usize, out: *mut f32) -> usize {
        // SAFETY: the caller's.
        unsafe {
            let store = |k: usize, v: __m256| _mm256_storeu_ps(out.add(8 * k), opaque(v));
            if n >= 8 {
                let load = |j: usize| _mm256_loadu_ps(rows[j].add(c));
                let z = transpose8([load(0), load(1), load(2), load(3), load(4), load(5), load(6), load(7)]);
                for (k, v) in z.into_iter().enumerate() {
                    store(c + k, v);
                }
                8
            } else if n >= 4 {
                let z = transpose4([halves(rows, 0, c), halves(rows, 1, c), halves(rows, 2, c), halves(rows, 3, c)]);
                for (k, v) in z.into_iter().enumerate() {
                    store(c + k, v);
                }
                4
            } else if n >= 2 {
                // Rows 0–3 and 4–7 as f64 pairs, then even and odd lanes.
                let pair = |j: usize| rows[j].add(c).cast::<f64>().read_unaligned();
                let a = _mm256_castpd_ps(_mm256_set_pd(pair(5), pair(4), pair(1), pair(0)));
                let b = _mm256_castpd_ps(_mm256_set_pd(pair(7), pair(6), pair(3), pair(2)));
                // [r0 r1 r2 r3 | r4 r5 r6 r7] of coefficient c, then of c + 1.
                store(c, _mm256_shuffle_ps::<0b10_00_10_00>(a, b));
                store(c + 1, _mm256_shuffle_ps::<0b11_01_11_01>(a, b));
                2
            } else {
                let v: [f32; 8] = core::array::from_fn(|j| *rows[j].add(c));
                store(c, _mm256_loadu_ps(v.as_ptr()));
                1
            }
        }
    }

    /// `out[k]` holds coefficient `k` of the eight rows of `N` values each.
    ///
    /// # Safety
    /// The CPU must have AVX, each row must hold `N` values and `out` must be writable.
    #[inline(always)]
    pub unsafe fn pack<const N: usize>(rows: [*const f32; 8], out: *mut [F32x8; N]) {
        let mut c = 0;
        while c < N {
            // SAFETY: the caller's.
            c += unsafe { pack_block(rows, c, N - c, out.cast()) };
        }
    }

    /// The inverse of [`pack_block`]: coefficients from `c` of `p` back to the eight rows.
    ///
    /// # Safety
    /// The CPU must have AVX; `p` must hold them and the rows be writable.
    #[inline]
    #[target_feature(enable = "avx")]
    unsafe fn unpack_block(p: *const f32, c: usize, n: usize, rows: [*mut f32; 8]) -> usize {
        // SAFETY: the caller's.
        unsafe {
            let load = |k: usize| opaque(_mm256_loadu_ps(p.add(8 * (c + k))));
            if n >= 8 {
                let z = transpose8([load(0), load(1), load(2), load(3), load(4), load(5), load(6), load(7)]);
                for (r, v) in rows.into_iter().zip(z) {
                    _mm256_storeu_ps(r.add(c), v);
                }
                8
            } else if n >= 4 {
                let z = transpose4([load(0), load(1), load(2), load(3)]);
                for (j, v) in z.into_iter().enumerate() {
                    _mm_storeu_ps(rows[j].add(c), _mm256_castps256_ps128(v));
                    _mm_storeu_ps(rows[j + 4].add(c), _mm256_extractf128_ps::<1>(v));
                }
                4
            } else if n >= 2 {
                let (x, y) = (load(0), load(1));
                let (lo, hi) = (_mm256_unpacklo_ps(x, y), _mm256_unpackhi_ps(x, y));
                // lo: pairs of rows 0, 1 | 4, 5; hi: rows 2, 3 | 6, 7.
                let mut pairs = [0.0f64; 8];
                _mm256_storeu_ps(pairs.as_mut_ptr().cast(), lo);
                _mm256_storeu_ps(pairs[4..].as_mut_ptr().cast(), hi);
                for (r, k) in rows.into_iter().zip([0, 1, 4, 5, 2, 3, 6, 7]) {
                    r.add(c).cast::<f64>().write_unaligned(pairs[k]);
                }
                2
            } else {
                let mut lanes = [0.0f32; 8];
                _mm256_storeu_ps(lanes.as_mut_ptr(), load(0));
                for (r, x) in rows.into_iter().zip(lanes) {
                    *r.add(c) = x;
                }
                1
            }
        }
    }

    /// The inverse of [`pack`]: row `i` gets lane `i` of every `p[k]`.
    ///
    /// # Safety
    /// The CPU must have AVX, each row must hold `N` writable values.
    #[inline(always)]
    pub unsafe fn unpack<const N: usize>(p: *const [F32x8; N], rows: [*mut f32; 8]) {
        let mut c = 0;
        while c < N {
            // SAFETY: the caller's.
            c += unsafe { unpack_block(p.cast(), c, N - c, rows) };
        }
    }
}
