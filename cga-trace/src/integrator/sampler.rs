//! Pixels and their samples: where each sample falls ([`sample_offset`]), the camera rays
//! through them, one pixel at a time or four neighbours of a row as a packet, and the mean
//! over samples (as [`Keep`] keeps them).

#[cfg(target_arch = "x86_64")]
use super::avx::Ymm;
use super::keep::{Keep, Taken};
use super::{Aov, RayCounts, Renderer};
use crate::backend::{Backend, Packet, RayLanes, lanes3};
use crate::camera::Lens;
use crate::hash::{self, hash, permute};
use crate::ray::Ray;
use cga_core::simd::Lane;
#[cfg(target_arch = "x86_64")]
use cga_core::simd::avx2;
use cga_core::{Real, Select};
use core::f64::consts::FRAC_PI_4;

impl<B: Backend> Renderer<'_, B> {
    /// One pixel: the shaded colour or an AOV, with no coverage (over a transparent background
    /// too, a sample that meets nothing counts what it would see, as over a colour:
    /// [`Renderer::render_window`] gives the coverage).
    pub fn pixel(&self, i: u32, j: u32, aov: Aov) -> [f64; 3] {
        let mut cast = RayCounts::default();
        let colour = self.pixel_counted::<Taken>(i, j, aov, &mut cast);
        self.count(&cast);
        colour
    }

    /// One pixel, averaged over the scene's `spp` samples ([`sample_offset`]; the centre
    /// alone for one sample) as `K` keeps them; the background where the camera forms no ray.
    pub(super) fn pixel_counted<K: Keep>(&self, i: u32, j: u32, aov: Aov, cast: &mut RayCounts) -> K::Pixel {
        self.pixels::<Ray<B::Carrier>, 1, K>(i, j, aov, cast).map_or(K::empty(self.scene.settings.background), |[c]| c)
    }

    /// `W` neighbouring pixels of a row, `(i₀ + k, j)`, each averaged over the scene's `spp`
    /// samples as `K` keeps them, sample `s` of the `W` pixels cast as one set of rays in
    /// lanes; `None` where the camera forms no ray (nothing is counted then).
    #[inline(always)]
    pub(crate) fn pixels<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        i0: u32,
        j: u32,
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[K::Pixel; W]> {
        let mut taken = [K::default(); W];
        self.take::<R, W, K>(i0, j, aov, Stage::All, &mut taken, cast)?;
        Some(taken.map(|t| t.pixel()))
    }

    /// Adds to `taken` the samples `stage` names of the `W` pixels `(i₀ + k, j)`, in sample
    /// order; `None` where the camera forms no ray (nothing is counted then). One sample a
    /// pixel is the pixel's centre.
    #[inline(always)]
    pub(crate) fn take<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        i0: u32,
        j: u32,
        aov: Aov,
        stage: Stage<W>,
        taken: &mut [K; W],
        cast: &mut RayCounts,
    ) -> Option<()> {
        let spp = self.scene.settings.spp.max(1);
        let mut counted = RayCounts::default();
        let samples = 0..spp;
        match stage {
            _ if spp == 1 => {
                if !matches!(stage, Stage::Rest(..)) {
                    let u = core::array::from_fn(|k| f64::from(i0 + k as u32) + 0.5);
                    self.add::<R, W, K>(taken, (i0, j, 0), (u, [f64::from(j) + 0.5; W]), aov, &mut counted)?;
                }
            }
            Stage::All => {
                for s in samples {
                    self.add::<R, W, K>(taken, (i0, j, s), offsets(i0, j, s), aov, &mut counted)?;
                }
            }
            Stage::First(n) => {
                for s in samples.take(n) {
                    self.add::<R, W, K>(taken, (i0, j, s), offsets(i0, j, s), aov, &mut counted)?;
                }
            }
            Stage::Rest(n, more) if more.iter().all(|&m| m) => {
                for s in samples.skip(n) {
                    self.add::<R, W, K>(taken, (i0, j, s), offsets(i0, j, s), aov, &mut counted)?;
                }
            }
            Stage::Rest(n, more) => {
                // The lanes that go on do so one ray at a time: the same bits as in a packet.
                for k in (0..W).filter(|&k| more[k]) {
                    let mut one = [taken[k]];
                    self.take::<Ray<B::Carrier>, 1, K>(
                        i0 + k as u32,
                        j,
                        aov,
                        Stage::Rest(n, [true]),
                        &mut one,
                        &mut counted,
                    )?;
                    taken[k] = one[0];
                }
            }
        }
        cast.add(&counted);
        Some(())
    }

    /// The values of `W` samples of any pixels, `[i, j, s]` each (the centre where the scene
    /// takes one sample a pixel), as `K` gives one sample's: their colours (or AOVs), with their
    /// coverage over a transparent background; `None` where the camera forms no ray (nothing
    /// is counted then).
    #[inline(always)]
    pub(super) fn listed<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        samples: [[u32; 3]; W],
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[K::Pixel; W]> {
        let (u, v, keys) = self.placed(samples);
        self.points::<R, W, K>(u, v, keys, aov, cast)
    }

    /// Where the samples `[i, j, s]` fall, and their keys.
    fn placed<const W: usize>(&self, samples: [[u32; 3]; W]) -> ([f64; W], [f64; W], [SampleKey; W]) {
        let spp = self.scene.settings.spp.max(1);
        let (mut u, mut v) = ([0.0; W], [0.0; W]);
        for (k, &[i, j, s]) in samples.iter().enumerate() {
            let (du, dv) = if spp == 1 { (0.5, 0.5) } else { sample_offset(i, j, s) };
            (u[k], v[k]) = (f64::from(i) + du, f64::from(j) + dv);
        }
        (u, v, samples.map(|[i, j, s]| SampleKey::new(i, j, s, spp)))
    }

    /// The values of `W` samples seen at continuous pixel coordinates `(u_k, v_k)`, each
    /// drawing its lens and light points by `keys[k]`, as `K` gives one sample's; `None`
    /// where the camera forms no ray (nothing is counted then).
    #[inline(always)]
    pub(super) fn points<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        u: [f64; W],
        v: [f64; W],
        keys: [SampleKey; W],
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[K::Pixel; W]> {
        let mut counted = RayCounts::default();
        let (colours, coverage) = self.samples::<R, W, K>(u, v, keys, aov, &mut counted)?;
        cast.add(&counted);
        Some(K::samples(colours, coverage))
    }

    /// [`Renderer::points`] of the shaded picture four at a time through packets.
    pub(super) fn points4<K: Keep>(
        &self,
        u: [f64; 4],
        v: [f64; 4],
        keys: [SampleKey; 4],
        cast: &mut RayCounts,
    ) -> Option<[K::Pixel; 4]> {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 && avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.points4_avx2::<K>(u, v, keys, cast) };
        }
        self.points::<Packet<B>, 4, K>(u, v, keys, Aov::Shaded, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn points4_avx2<K: Keep>(
        &self,
        u: [f64; 4],
        v: [f64; 4],
        keys: [SampleKey; 4],
        cast: &mut RayCounts,
    ) -> Option<[K::Pixel; 4]> {
        self.points::<Packet<B, Ymm>, 4, K>(u, v, keys, Aov::Shaded, cast)
    }

    /// [`Renderer::listed`] four at a time through packets ([`Renderer::points4`]).
    pub(super) fn listed4<K: Keep>(&self, samples: [[u32; 3]; 4], cast: &mut RayCounts) -> Option<[K::Pixel; 4]> {
        let (u, v, keys) = self.placed(samples);
        self.points4::<K>(u, v, keys, cast)
    }

    /// Sample `s` of the `W` pixels `(i₀ + k, j)`, seen at `(u_k, v_k)`, added to `taken`.
    /// A method, not a closure: a closure is not compiled for the caller's AVX2.
    #[inline(always)]
    fn add<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        taken: &mut [K; W],
        (i0, j, s): (u32, u32, u32),
        (u, v): ([f64; W], [f64; W]),
        aov: Aov,
        counted: &mut RayCounts,
    ) -> Option<()> {
        let spp = self.scene.settings.spp.max(1);
        let keys = core::array::from_fn(|k| SampleKey::new(i0 + k as u32, j, s, spp));
        let (colours, coverage) = self.samples::<R, W, K>(u, v, keys, aov, counted)?;
        for ((taken, c), coverage) in taken.iter_mut().zip(colours).zip(coverage) {
            taken.add(c, coverage);
        }
        Some(())
    }

    /// The colours (or AOVs, lane by lane) seen at continuous pixel coordinates
    /// `(u_k, v_k)` by the samples `keys`, and the fraction of each one's camera rays that met
    /// anything where `K` keeps it (an AOV's rays count as met: AOV pictures are opaque); a
    /// miss adds nothing to a colour `K` keeps the coverage of, as the environment it would
    /// show is not there. Through a thin lens, each sample is the mean of the scene's
    /// `blur_samples` rays ([`SampleKey::lens_ray`]).
    #[inline(always)]
    fn samples<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        u: [f64; W],
        v: [f64; W],
        keys: [SampleKey; W],
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<([[f64; 3]; W], [f64; W])> {
        if aov != Aov::Shaded {
            let mut out = [[0.0; 3]; W];
            for l in 0..W {
                let ray: Ray<B::Carrier> = self.camera_rays::<Ray<B::Carrier>, 1>([u[l]], [v[l]], &[keys[l]])?;
                cast.primary += 1;
                out[l] = self.aov(&ray, aov);
            }
            return Some((out, [1.0; W]));
        }
        let m = match self.scene.camera.lens {
            Lens::Thin { .. } => self.scene.settings.blur_samples.max(1),
            _ => 1,
        };
        let (mut sum, mut coverage) = ([[0.0; 3]; W], [0.0; W]);
        for r in 0..m {
            let keys = if m == 1 { keys } else { keys.map(|k| k.lens_ray(r, m)) };
            let rays = self.camera_rays::<R, W>(u, v, &keys)?;
            cast.primary += W as u64;
            let (colours, met) = self.trace_met::<R, W, K>(rays, 0, &keys, cast);
            for l in 0..W {
                if met[l] || !K::COVERS {
                    sum[l] = [sum[l][0] + colours[l][0], sum[l][1] + colours[l][1], sum[l][2] + colours[l][2]];
                }
                coverage[l] += f64::from(u8::from(met[l]));
            }
        }
        if m > 1 {
            let scale = 1.0 / f64::from(m);
            sum = sum.map(|c| c.map(|x| x * scale));
            coverage = coverage.map(|c| c * scale);
        }
        Some((sum, coverage))
    }

    /// The camera rays through `(u_k, v_k)`: eq. 2's pinhole rays as the back end forms them,
    /// or the lens's ([`Camera::lens_ray`](crate::camera::Camera::lens_ray)) from each
    /// sample's lens point.
    #[inline(always)]
    fn camera_rays<R: RayLanes<B, W>, const W: usize>(
        &self,
        u: [f64; W],
        v: [f64; W],
        keys: &[SampleKey; W],
    ) -> Option<R> {
        let camera = &self.scene.camera;
        if camera.lens == Lens::Pinhole {
            return R::camera(camera, u, v);
        }
        let points: [(f64, f64); W] = core::array::from_fn(|l| keys[l].point(Dimension::Lens, 0, 1));
        let (a, b) = disk::<R::T>((R::T::from_fn(|l| points[l].0), R::T::from_fn(|l| points[l].1)));
        let mut rays = [([0.0; 3], [0.0; 3]); W];
        for l in 0..W {
            rays[l] = camera.lens_ray(u[l], v[l], (a.lane(l), b.lane(l)))?;
        }
        Some(R::cast(lanes3(rays.map(|r| r.0)), lanes3(rays.map(|r| r.1))))
    }

    /// Four neighbouring pixels of a row, `(i₀ + k, j)`, through packets, sample by sample
    /// (sample `s` of the four pixels is one packet) — the camera rays, the mirror bounces of
    /// those that hit mirrors (lanes whose ray has ended ride along, inactive), and at every
    /// hit the shadow rays towards each light; `None` where a camera ray cannot be formed
    /// (the scalar path then says why; nothing is counted). Each lane gets the bits
    /// [`Renderer::pixel`] gives its pixel: the same samples, meets, shading, sum from the
    /// deepest bounce up and mean over samples. Compiled for AVX2 and FMA where the CPU has
    /// them (the lanes then run in one register each).
    pub(super) fn pixels4<K: Keep>(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[K::Pixel; 4]> {
        let mut taken = [K::default(); 4];
        self.take4(i0, j, Stage::All, &mut taken, cast)?;
        Some(taken.map(|t| t.pixel()))
    }

    /// [`Renderer::take`] of four neighbouring pixels through packets ([`Renderer::pixels4`]).
    pub(super) fn take4<K: Keep>(
        &self,
        i0: u32,
        j: u32,
        stage: Stage<4>,
        taken: &mut [K; 4],
        cast: &mut RayCounts,
    ) -> Option<()> {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 && avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.take4_avx2(i0, j, stage, taken, cast) };
        }
        self.take::<Packet<B>, 4, K>(i0, j, Aov::Shaded, stage, taken, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn take4_avx2<K: Keep>(
        &self,
        i0: u32,
        j: u32,
        stage: Stage<4>,
        taken: &mut [K; 4],
        cast: &mut RayCounts,
    ) -> Option<()> {
        self.take::<Packet<B, Ymm>, 4, K>(i0, j, Aov::Shaded, stage, taken, cast)
    }
}

/// Which of a pixel's samples to take.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Stage<const W: usize> {
    /// All of them.
    All,
    /// The first `n`.
    First(usize),
    /// Those after the first `n`, for the lanes marked.
    Rest(usize, [bool; W]),
}

/// Sample `s` of the `W` pixels `(i₀ + k, j)`: their continuous pixel coordinates.
#[inline(always)]
fn offsets<const W: usize>(i0: u32, j: u32, s: u32) -> ([f64; W], [f64; W]) {
    let (mut u, mut v) = ([0.0; W], [0.0; W]);
    for k in 0..W {
        let (du, dv) = sample_offset(i0 + k as u32, j, s);
        (u[k], v[k]) = (f64::from(i0 + k as u32) + du, f64::from(j) + dv);
    }
    (u, v)
}

/// Where sample `s` of pixel `(i, j)` falls, as an offset in `[0, 1)²` from the pixel's
/// corner: the first two dimensions of the Sobol' sequence (a (0, 2)-sequence: every prefix
/// of `2^k` samples has one in each of the `2^k` elementary boxes of every shape), with the
/// digits of each coordinate scrambled by a hash of the pixel (random digit scrambling keeps
/// that stratification and decorrelates neighbouring pixels). Deterministic: the same for
/// any thread count or crop.
pub fn sample_offset(i: u32, j: u32, s: u32) -> (f64, f64) {
    let pixel = hash::pixel(i, j, 0x9e37_79b9);
    let x = s.reverse_bits() ^ hash(pixel ^ 0x68bc_21eb);
    let y = sobol_second(s) ^ hash(pixel ^ 0x02e5_be93);
    let unit = |bits: u32| f64::from(bits) / 4_294_967_296.0;
    (unit(x), unit(y))
}

/// What a sample's further points are drawn for: each its own scramble of the sequence.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Dimension {
    /// The point on a thin lens.
    Lens = 1,
    /// The point on an area light.
    Light = 2,
}

/// Which sample of which pixel a ray serves: what places its lens and light points.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct SampleKey {
    /// The pixel.
    i: u32,
    j: u32,
    /// The sample's number, and how many the pixel takes.
    index: u32,
    count: u32,
}

impl SampleKey {
    /// Sample `s` of `count` of pixel `(i, j)` (hashed only where a point is drawn).
    #[inline(always)]
    pub(crate) fn new(i: u32, j: u32, s: u32, count: u32) -> Self {
        SampleKey { i, j, index: s, count }
    }

    /// Camera ray `r` of the `m` that this sample averages through a thin lens: sample
    /// `s m + r` of the pixel's `count · m`, so that the lens (and light) points of all the
    /// pixel's rays are stratified together.
    #[inline(always)]
    pub(crate) fn lens_ray(self, r: u32, m: u32) -> Self {
        SampleKey { index: self.index * m + r, count: self.count * m, ..self }
    }

    /// Point `k` of `n` in `[0, 1)²` that this sample takes for `dimension`: of the pixel's
    /// `count · n` points of that dimension, number `π(s) n + k` — the first two dimensions
    /// of the Sobol' sequence with their digits scrambled by a hash of the pixel and the
    /// dimension, `π` a permutation of the samples by the same hash (Kensler's), so that the
    /// points of every dimension are stratified over the pixel's samples and uncorrelated with
    /// where in the pixel each sample falls (pbrt's padded Sobol' sampler).
    pub(crate) fn point(&self, dimension: Dimension, k: u32, n: u32) -> (f64, f64) {
        self.points(dimension, n).at(k)
    }

    /// The `n` points this sample takes for `dimension` ([`SampleKey::point`]), their
    /// hashes and permutation found once: an area light asks for all of them at each hit.
    #[inline(always)]
    pub(crate) fn points(&self, dimension: Dimension, n: u32) -> Points {
        let pixel = hash::pixel(self.i, self.j, 0x85eb_ca6b);
        let seed = hash(pixel ^ (dimension as u32).wrapping_mul(0x9e37_79b9));
        Points {
            first: permute(self.index, self.count.max(1), seed).wrapping_mul(n),
            x: hash(seed ^ 0x68bc_21eb),
            y: hash(seed ^ 0x02e5_be93),
        }
    }
}

/// A sample's points of one dimension ([`SampleKey::points`]): the number of its first in
/// the pixel's sequence, and the scrambles of the two coordinates.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Points {
    first: u32,
    x: u32,
    y: u32,
}

impl Points {
    /// Point `k` ([`SampleKey::point`]).
    #[inline(always)]
    pub(crate) fn at(&self, k: u32) -> (f64, f64) {
        let s = self.first.wrapping_add(k);
        let unit = |bits: u32| f64::from(bits) / 4_294_967_296.0;
        (unit(s.reverse_bits() ^ self.x), unit(sobol_second(s) ^ self.y))
    }
}

/// Shirley and Chiu's concentric map from the unit square onto the unit disk, lane by lane:
/// strata stay compact and areas keep their proportions. With `a = 2x − 1`, `b = 2y − 1`:
/// `r (cos φ, sin φ)` for `r = a`, `φ = π/4 · b/a` where `|a| > |b|`, else `r (sin φ, cos φ)`
/// for `r = b`, `φ = π/4 · a/b` (the angle `π/2 − φ`). One lane and four take the same steps
/// ([`sin_cos_quarter`], no library call), so a packet's lens and light points are the bits of
/// one ray at a time.
#[inline(always)]
pub(crate) fn disk<T: Select>((x, y): (T, T)) -> (T, T) {
    let (two, one) = (T::from_f64(2.0), T::one());
    let (a, b) = (two * x - one, two * y - one);
    let wide = b.abs().lt(a.abs());
    let (r, across) = (T::select(wide, a, b), T::select(wide, b, a));
    // r = 0 only at the centre, where `across` is 0 too.
    let phi = T::from_f64(FRAC_PI_4) * (across / T::select(T::zero().lt(r.abs()), r, one));
    let (s, c) = sin_cos_quarter(phi);
    (T::select(wide, r * c, r * s), T::select(wide, r * s, r * c))
}

/// `(sin φ, cos φ)` for `|φ| ≤ π/4` by their Taylor series to `φ¹⁵` and `φ¹⁶` (the first
/// term left out is under `(π/4)¹⁷/17! < 5·10⁻¹⁷`, half an ulp of 0.7), in Horner's form in `φ²`:
/// within a few ulps of the library's, and the same steps in every lane.
#[inline(always)]
pub(crate) fn sin_cos_quarter<T: Real>(phi: T) -> (T, T) {
    const SIN: [f64; 7] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
    ];
    const COS: [f64; 8] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
    ];
    let z = phi * phi;
    let horner = |c: &[f64]| c.iter().rev().fold(T::zero(), |p, &k| p * z + T::from_f64(k));
    (phi + phi * z * horner(&SIN), T::one() + z * horner(&COS))
}

/// The second dimension of the Sobol' sequence (primitive polynomial `x + 1`): direction
/// numbers `v₀ = 2³¹`, `v_k = v_{k−1} ⊕ (v_{k−1} >> 1)`, XORed over the bits of `s`. Bit `31 − i`
/// of `v_k` is `C(k, i) mod 2`, which is 1 where the bits of `i` are among those of `k`
/// (Lucas), so bit `31 − i` of the result is the XOR of the bits `k ⊇ i` of `s`: the superset
/// transform over the five bits of a bit's position, five shifts and masks, then a reversal.
/// No branch on the bits of `s` (which a loop over them mispredicts).
fn sobol_second(s: u32) -> u32 {
    let mut w = s;
    for (shift, mask) in [(1, 0x5555_5555u32), (2, 0x3333_3333), (4, 0x0f0f_0f0f), (8, 0x00ff_00ff), (16, 0x0000_ffff)]
    {
        w ^= (w >> shift) & mask;
    }
    w.reverse_bits()
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

    #[test]
    fn lens_and_light_points_are_stratified_and_shuffled() {
        for n in [1, 4, 16, 100] {
            let mut seen: Vec<u32> = (0..n).map(|s| permute(s, n, 0x1234_5678)).collect();
            seen.sort();
            assert_eq!(seen, (0..n).collect::<Vec<_>>(), "a permutation of 0..{n}");
        }
        // 16 samples: their lens points one in each of 4×4 cells; not in pixel order.
        let points: Vec<_> = (0..16).map(|s| SampleKey::new(3, 5, s, 16).point(Dimension::Lens, 0, 1)).collect();
        let mut cells: Vec<u32> = points.iter().map(|&(x, y)| (x * 4.0) as u32 * 4 + (y * 4.0) as u32).collect();
        cells.sort();
        assert_eq!(cells, (0..16).collect::<Vec<_>>());
        let offsets: Vec<_> = (0..16).map(|s| sample_offset(3, 5, s)).collect();
        let order = |p: &[(f64, f64)]| p.iter().map(|&(x, _)| (x * 16.0) as u32).collect::<Vec<_>>();
        assert_ne!(order(&points), order(&offsets), "lens points are not tied to pixel offsets");
        // The disk map keeps area: the mean squared radius of a fine grid is ½.
        let grid = (0..64).flat_map(|a| (0..64).map(move |b| ((a as f64 + 0.5) / 64.0, (b as f64 + 0.5) / 64.0)));
        let mean = grid.map(disk::<f64>).map(|(x, y)| x * x + y * y).sum::<f64>() / 4096.0;
        assert!((mean - 0.5).abs() < 1e-3, "{mean}");
    }

    #[test]
    fn the_disk_map_is_shirley_and_chius_and_the_same_in_every_lane() {
        use cga_core::simd::{F64x4, Lane};
        let library = |(x, y): (f64, f64)| {
            let (a, b) = (2.0 * x - 1.0, 2.0 * y - 1.0);
            if a == 0.0 && b == 0.0 {
                return (0.0, 0.0);
            }
            let (r, theta) =
                if a.abs() > b.abs() { (a, FRAC_PI_4 * (b / a)) } else { (b, FRAC_PI_4 * 2.0 - FRAC_PI_4 * (a / b)) };
            (r * theta.cos(), r * theta.sin())
        };
        let grid: Vec<(f64, f64)> =
            (0..=40).flat_map(|a| (0..=40).map(move |b| (f64::from(a) / 40.0, f64::from(b) / 40.0))).collect();
        for chunk in grid.chunks_exact(4) {
            let lanes = disk((F64x4::from_fn(|l| chunk[l].0), F64x4::from_fn(|l| chunk[l].1)));
            for (l, &p) in chunk.iter().enumerate() {
                let (got, want) = (disk(p), library(p));
                assert!((got.0 - want.0).abs() <= 4e-16 && (got.1 - want.1).abs() <= 4e-16, "{p:?}: {got:?} {want:?}");
                assert_eq!((lanes.0.lane(l), lanes.1.lane(l)), got, "lane {l} of {p:?}");
            }
        }
        assert_eq!(disk((0.5, 0.5)), (0.0, 0.0));
        for k in 0..=1000 {
            let phi = FRAC_PI_4 * (f64::from(k) / 500.0 - 1.0);
            let (s, c) = sin_cos_quarter(phi);
            assert!((s - phi.sin()).abs() <= 2e-16 && (c - phi.cos()).abs() <= 2e-16, "{phi}");
        }
    }

    #[test]
    fn sobol_second_is_the_xor_of_its_direction_numbers() {
        let by_loop = |mut s: u32| {
            let (mut v, mut y) = (1u32 << 31, 0);
            while s != 0 {
                if s & 1 == 1 {
                    y ^= v;
                }
                s >>= 1;
                v ^= v >> 1;
            }
            y
        };
        let mut x = 0x1234_5678u32;
        for s in (0..4096).chain([u32::MAX, 1 << 31, 0x8000_0001]).chain((0..4096).map(|_| {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x
        })) {
            assert_eq!(sobol_second(s), by_loop(s), "s = {s:#x}");
        }
    }
}
