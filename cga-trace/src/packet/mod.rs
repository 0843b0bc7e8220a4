//! Ray packets: four neighbouring camera rays, the four shadow rays from their hits towards
//! one light, and their mirror bounces, on four f64 lanes ([`F64x4`]). A back end with
//! packets ([`Packets`]) meets its primitives in lanes — the sparse back end on the
//! generated types instantiated on lanes (`packet/sparse.rs`), the plain one by the textbook
//! formulas (`packet/plain.rs`) — with the same operations as its scalar path, so the same
//! bits; other shapes are met one lane at a time through their own code.
//!
//! The shading is the one ray's code run on four lanes ([`crate::shade`], through
//! [`RayLanes`] for packets); the secondary rays run in lanes too; normals and keeping the
//! nearest crossing stay per lane (they branch). A scene
//! whose rays do not come four to a row (a crop narrower than four, the last pixels of a
//! row) uses the scalar path for the remainder.

mod plain;
mod sparse;

use crate::backend::Backend;
use crate::camera::Camera;
use crate::lanes::{RayLanes, lanes3, mirrored};
use crate::ray::Ray;
use crate::render::{Layers, RayCounts, Renderer, sample_offset, sum_layers};
use crate::shapes::{Crossing, ShadingPoint};
use cga_core::euclid::{E3, dot, sub};
use cga_core::simd::F64x4;
#[cfg(target_arch = "x86_64")]
use cga_core::simd::avx2;

/// A back end's geometry for packets: its rays four at a time and its meets in lanes.
pub trait Packets: Backend {
    /// What four rays carry in lanes (the sparse back end: their CGA lines).
    type CarrierLanes: Copy;
    /// Four rays from origins along unit directions given in lanes (secondary rays), as
    /// [`Backend::ray`] makes each.
    fn packet(origin: [F64x4; 3], dir: [F64x4; 3]) -> Packet<Self>
    where
        Self: Sized;
    /// The camera rays through `(u_k, v_k)`, as [`Backend::camera_ray`] makes each; `None`
    /// where one cannot be formed (the scalar path then says why).
    fn camera_packet(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Packet<Self>>
    where
        Self: Sized;
    /// The crossings of the packet's rays with a shape within their ranges, as
    /// [`Backend::intersect`] finds each.
    fn cross4(shape: &Self::Shape, p: &Packet<Self>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings
    where
        Self: Sized;
}

/// A crossing per lane, `None` where the lane's ray misses.
pub type Crossings = [Option<Crossing>; 4];

/// Four rays, lane `k` being ray `k`.
pub struct Packet<B: Packets> {
    /// The scalar rays (for the per-lane steps).
    pub rays: [Ray<B::Carrier>; 4],
    /// Their origins in lanes.
    pub origin: [F64x4; 3],
    /// Their unit directions in lanes.
    pub dir: [F64x4; 3],
    /// Their carriers in lanes (the sparse back end: their lines).
    pub carrier: B::CarrierLanes,
}

impl<B: Packets> Packet<B> {
    /// Four rays whose carriers are already in lanes.
    #[inline(always)]
    pub fn with_carrier(rays: [Ray<B::Carrier>; 4], carrier: B::CarrierLanes) -> Self {
        let lanes = |f: fn(&Ray<B::Carrier>) -> E3| lanes3(rays.each_ref().map(f));
        Packet { origin: lanes(|r| r.origin), dir: lanes(|r| r.dir), rays, carrier }
    }
}

/// Lane `l` of a point in lanes.
#[inline(always)]
fn lane(x: &[F64x4; 3], l: usize) -> E3 {
    [x[0].to_array()[l], x[1].to_array()[l], x[2].to_array()[l]]
}

/// Which lanes' points lie on a disk of rim `(c, r)`, `|x − c|² ≤ r²`; all lanes where
/// there is no rim (a plane).
#[inline(always)]
fn inside_rim(x: &[F64x4; 3], rim: Option<(E3, f64)>) -> [bool; 4] {
    rim.map_or([true; 4], |(c, r)| {
        let d = sub(*x, c.map(F64x4::splat));
        dot(d, d).to_array().map(|q| q <= r * r)
    })
}

/// The crossings at `t` and points `x` of the lanes that are `ok`, the others `None`.
#[inline(always)]
fn crossings(ok: [bool; 4], t: [f64; 4], x: &[F64x4; 3]) -> Crossings {
    if !ok.iter().any(|&b| b) {
        return [None; 4];
    }
    core::array::from_fn(|l| ok[l].then(|| Crossing { t: t[l], point: lane(x, l), alpha: None }))
}

impl<'a, B: Packets> Renderer<'a, B> {
    /// Four neighbouring pixels of a row, `(i₀ + k, j)`, through packets, sample by sample
    /// (sample `s` of the four pixels is one packet) — the camera rays, the mirror bounces of
    /// those that hit mirrors (lanes whose ray has ended ride along, inactive), and at every
    /// hit the shadow rays towards each light; `None` where a camera ray cannot be formed
    /// (the scalar path then says why; nothing is counted). Each lane gets the bits
    /// [`Renderer::pixel`] gives its pixel: the same samples, meets, shading, sum from the
    /// deepest bounce up and mean over samples. Compiled for AVX2 and FMA where the CPU has
    /// them (the lanes then run in one register each).
    pub fn pixels4(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.pixels4_avx2(i0, j, cast) };
        }
        self.pixels4_lanes(i0, j, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn pixels4_avx2(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        self.pixels4_lanes(i0, j, cast)
    }

    #[inline(always)]
    fn pixels4_lanes(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        let spp = self.scene.settings.spp.max(1);
        let pixels = [0, 1, 2, 3].map(|k| i0 + k);
        let mut counted = RayCounts::default();
        if spp == 1 {
            let centre = |i: u32| f64::from(i) + 0.5;
            let colours = self.samples4(pixels.map(centre), [centre(j); 4], &mut counted)?;
            cast.add(&counted);
            return Some(colours);
        }
        // As `Renderer::pixel` sums them: sample by sample, then divided by their number.
        let mut sum = [[0.0; 3]; 4];
        for s in 0..spp {
            let offsets = pixels.map(|i| sample_offset(i, j, s));
            let u = core::array::from_fn(|k| f64::from(pixels[k]) + offsets[k].0);
            let v = offsets.map(|o| f64::from(j) + o.1);
            let colours = self.samples4(u, v, &mut counted)?;
            for (sum, c) in sum.iter_mut().zip(colours) {
                *sum = [0, 1, 2].map(|k| sum[k] + c[k]);
            }
        }
        cast.add(&counted);
        Some(sum.map(|c| c.map(|x| x / f64::from(spp))))
    }

    /// The colours seen at continuous pixel coordinates `(u_k, v_k)`, one packet.
    #[inline(always)]
    fn samples4(&self, u: [f64; 4], v: [f64; 4], cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        let (camera, settings) = (&self.scene.camera, &self.scene.settings);
        let mut packet = B::camera_packet(camera, u, v)?;
        cast.primary += 4;
        let mut active = [true; 4];
        let mut deepest = [settings.background; 4];
        let mut layers: [Layers; 4] = Default::default();
        let mut depth = 0;
        while active.iter().any(|&a| a) {
            // An inactive lane's range is empty: it finds nothing.
            let nearest =
                self.crossings(&packet, 0.0, active.map(|a| if a { f64::INFINITY } else { f64::NEG_INFINITY }));
            let hits: [Option<(ShadingPoint, usize)>; 4] = core::array::from_fn(|l| {
                nearest[l].map(|(c, k)| {
                    let normal = B::normal(&self.shapes[k], &packet.rays[l], &c);
                    (ShadingPoint { t: c.t, point: c.point, normal, alpha: c.alpha }, k)
                })
            });
            let errors = nearest.map(|n| n.map_or(0.0, |(_, k)| self.errors[k]));
            let local = self.shade(&packet, &hits, cast);
            let mut bounce = [false; 4];
            for l in 0..4 {
                if !active[l] {
                    continue;
                }
                let Some((_, k)) = hits[l] else {
                    (deepest[l], active[l]) = (settings.background, false);
                    continue;
                };
                let kr = self.scene.objects[k].material.kr;
                if !(kr > 0.0 && depth < settings.max_depth) {
                    (deepest[l], active[l]) = (local[l], false);
                    continue;
                }
                cast.reflection += 1;
                layers[l].push((local[l], kr));
                bounce[l] = true;
            }
            if bounce.iter().any(|&b| b) {
                packet = mirrored(&packet, &hits, &errors, &bounce);
            }
            depth += 1;
        }
        Some(core::array::from_fn(|l| sum_layers(&layers[l], deepest[l])))
    }
}

/// Four rays in lanes, for the shading ([`crate::shade`]).
impl<B: Packets> RayLanes<B, 4> for Packet<B> {
    type T = F64x4;
    #[inline(always)]
    fn origin(&self) -> E3<F64x4> {
        self.origin
    }
    #[inline(always)]
    fn dir(&self) -> E3<F64x4> {
        self.dir
    }
    #[inline(always)]
    fn cast(origin: E3<F64x4>, dir: E3<F64x4>) -> Self {
        B::packet(origin, dir)
    }
    #[inline(always)]
    fn ray(&self, l: usize) -> &Ray<B::Carrier> {
        &self.rays[l]
    }
    #[inline(always)]
    fn cross(&self, shape: &B::Shape, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        B::cross4(shape, self, t_min, t_max)
    }
}
