//! Transposes between values as they lie in memory (rows: one value's coefficients, in
//! field order, since the generated types are `#[repr(C)]`) and lanes (columns: one
//! coefficient of every value), read and written in place: four rows with AVX, eight with
//! AVX-512.
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
