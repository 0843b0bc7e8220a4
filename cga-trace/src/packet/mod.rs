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
use crate::lanes::{RayLanes, lanes3};
use crate::ray::Ray;
use crate::render::{Aov, RayCounts, Renderer};
use crate::shapes::Crossing;
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
        self.pixels::<Packet<B>, 4>(i0, j, Aov::Shaded, cast)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn pixels4_avx2(&self, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        self.pixels::<Packet<B>, 4>(i0, j, Aov::Shaded, cast)
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
    fn camera(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Self> {
        B::camera_packet(camera, u, v)
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
