//! Pixels and their samples: where each sample falls ([`sample_offset`]), the camera rays
//! through them, one pixel at a time or four neighbours of a row as a packet, and the mean
//! over samples.

use super::{Aov, RayCounts, Renderer};
use crate::backend::{Backend, Packet, RayLanes};
use crate::ray::Ray;
#[cfg(target_arch = "x86_64")]
use cga_core::simd::avx2;

impl<B: Backend> Renderer<'_, B> {
    /// One pixel: the shaded colour or an AOV.
    pub fn pixel(&self, i: u32, j: u32, aov: Aov) -> [f64; 3] {
        let mut cast = RayCounts::default();
        let colour = self.pixel_counted(i, j, aov, &mut cast);
        self.count(&cast);
        colour
    }

    /// One pixel, averaged over the scene's `spp` samples ([`sample_offset`]; the centre
    /// alone for one sample); the background where the camera forms no ray.
    pub(super) fn pixel_counted(&self, i: u32, j: u32, aov: Aov, cast: &mut RayCounts) -> [f64; 3] {
        self.pixels::<Ray<B::Carrier>, 1>(i, j, aov, cast).map_or(self.scene.settings.background, |[c]| c)
    }

    /// `W` neighbouring pixels of a row, `(i₀ + k, j)`, each averaged over the scene's
    /// `spp` samples, sample `s` of the `W` pixels cast as one set of rays in lanes; `None`
    /// where the camera forms no ray (nothing is counted then).
    #[inline(always)]
    pub(crate) fn pixels<R: RayLanes<B, W>, const W: usize>(
        &self,
        i0: u32,
        j: u32,
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[[f64; 3]; W]> {
        let spp = self.scene.settings.spp.max(1);
        let mut counted = RayCounts::default();
        let colours = if spp == 1 {
            let u = core::array::from_fn(|k| f64::from(i0 + k as u32) + 0.5);
            self.samples::<R, W>(u, [f64::from(j) + 0.5; W], aov, &mut counted)?
        } else {
            let mut sum = [[0.0; 3]; W];
            for s in 0..spp {
                let (mut u, mut v) = ([0.0; W], [0.0; W]);
                for k in 0..W {
                    let (du, dv) = sample_offset(i0 + k as u32, j, s);
                    (u[k], v[k]) = (f64::from(i0 + k as u32) + du, f64::from(j) + dv);
                }
                let colours = self.samples::<R, W>(u, v, aov, &mut counted)?;
                for (sum, c) in sum.iter_mut().zip(colours) {
                    *sum = [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]];
                }
            }
            let n = f64::from(spp);
            for c in &mut sum {
                *c = [c[0] / n, c[1] / n, c[2] / n];
            }
            sum
        };
        cast.add(&counted);
        Some(colours)
    }

    /// The colours (or AOVs, lane by lane) seen at continuous pixel coordinates
    /// `(u_k, v_k)`.
    #[inline(always)]
    fn samples<R: RayLanes<B, W>, const W: usize>(
        &self,
        u: [f64; W],
        v: [f64; W],
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[[f64; 3]; W]> {
        if aov != Aov::Shaded {
            let mut out = [[0.0; 3]; W];
            for l in 0..W {
                let ray = B::camera_ray(&self.scene.camera, u[l], v[l])?;
                cast.primary += 1;
                out[l] = self.aov(&ray, aov);
            }
            return Some(out);
        }
        let rays = R::camera(&self.scene.camera, u, v)?;
        cast.primary += W as u64;
        Some(self.trace_lanes(rays, 0, cast))
    }

    /// Four neighbouring pixels of a row, `(i₀ + k, j)`, through packets, sample by sample
    /// (sample `s` of the four pixels is one packet) — the camera rays, the mirror bounces of
    /// those that hit mirrors (lanes whose ray has ended ride along, inactive), and at every
    /// hit the shadow rays towards each light; `None` where a camera ray cannot be formed
    /// (the scalar path then says why; nothing is counted). Each lane gets the bits
    /// [`Renderer::pixel`] gives its pixel: the same samples, meets, shading, sum from the
    /// deepest bounce up and mean over samples. Compiled for AVX2 and FMA where the CPU has
    /// them (the lanes then run in one register each).
    pub(super) fn pixels4(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.pixels4_avx2(i0, j, cast) };
        }
        self.pixels::<Packet<B>, 4>(i0, j, Aov::Shaded, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn pixels4_avx2(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        self.pixels::<Packet<B>, 4>(i0, j, Aov::Shaded, cast)
    }
}

/// Where sample `s` of pixel `(i, j)` falls, as an offset in `[0, 1)²` from the pixel's
/// corner: the first two dimensions of the Sobol' sequence (a (0, 2)-sequence: every prefix
/// of `2^k` samples has one in each of the `2^k` elementary boxes of every shape), with the
/// digits of each coordinate scrambled by a hash of the pixel (random digit scrambling keeps
/// that stratification and decorrelates neighbouring pixels). Deterministic: the same for
/// any thread count or crop.
pub fn sample_offset(i: u32, j: u32, s: u32) -> (f64, f64) {
    let pixel = hash(i ^ hash(j ^ 0x9e37_79b9));
    let x = s.reverse_bits() ^ hash(pixel ^ 0x68bc_21eb);
    let y = sobol_second(s) ^ hash(pixel ^ 0x02e5_be93);
    let unit = |bits: u32| f64::from(bits) / 4_294_967_296.0;
    (unit(x), unit(y))
}

/// The second dimension of the Sobol' sequence (primitive polynomial `x + 1`): direction
/// numbers `v₀ = 2³¹`, `v_k = v_{k−1} ⊕ (v_{k−1} >> 1)`, XORed over the bits of `s`.
fn sobol_second(mut s: u32) -> u32 {
    let (mut v, mut y) = (1u32 << 31, 0);
    while s != 0 {
        if s & 1 == 1 {
            y ^= v;
        }
        s >>= 1;
        v ^= v >> 1;
    }
    y
}

/// A 32-bit integer hash with good avalanche (two multiply–xorshift rounds).
fn hash(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^ (x >> 16)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_are_stratified_in_every_elementary_box() {
        // 16 samples: one in each of the 16 cells of the 16×1, 8×2, 4×4, 2×8, 1×16 grids.
        for (i, j) in [(0, 0), (7, 3), (1000, 20)] {
            let points: Vec<_> = (0..16).map(|s| sample_offset(i, j, s)).collect();
            for k in 0..=4 {
                let (nx, ny) = (1u32 << k, 1u32 << (4 - k));
                let mut seen = [false; 16];
                for &(x, y) in &points {
                    assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                    let cell = (x * f64::from(nx)) as u32 * ny + (y * f64::from(ny)) as u32;
                    assert!(!std::mem::replace(&mut seen[cell as usize], true), "pixel ({i}, {j}), {nx}×{ny}");
                }
            }
        }
        assert_ne!(sample_offset(0, 0, 0), sample_offset(1, 0, 0), "pixels are decorrelated");
    }
}
