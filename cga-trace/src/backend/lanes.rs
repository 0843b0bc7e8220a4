//! Rays in lanes, for code written once for one ray and for a packet of four:
//! [`RayLanes`], which a [`Ray`] is with one lane and a [`Packet`] with four, and the
//! helpers back ends meet packets with.

use super::Backend;
use crate::camera::Camera;
use crate::lanes::{array, lane};
use crate::ray::Ray;
use crate::shapes::Crossing;
use cga_core::euclid::{E3, dot, sub};
use cga_core::simd::{F64x4, Lane};

/// `W` rays in lanes of `Self::T`: what the shading casts its shadow rays as.
pub trait RayLanes<B: Backend, const W: usize>: Sized {
    /// The lanes: `f64` for one ray, four lanes (`F64x4`, or one AVX register) for four.
    type T: Lane;
    /// The rays' origins.
    fn origin(&self) -> E3<Self::T>;
    /// Their unit directions.
    fn dir(&self) -> E3<Self::T>;
    /// Rays from `origin` along unit directions `dir` (secondary rays), as [`Backend::ray`]
    /// makes each.
    fn cast(origin: E3<Self::T>, dir: E3<Self::T>) -> Self;
    /// The camera rays through continuous pixel coordinates `(u_l, v_l)`, as
    /// [`Backend::camera_ray`] makes each; `None` where one cannot be formed.
    fn camera(camera: &Camera, u: [f64; W], v: [f64; W]) -> Option<Self>;
    /// Lane `l`'s ray (for what runs per lane: a BVH's traversal, bounding spheres, normals).
    fn ray(&self, l: usize) -> &Ray<B::Carrier>;
    /// The crossings of the rays with `shape` within their ranges, as [`Backend::intersect`]
    /// finds each; a lane with `t_max = −∞` finds nothing.
    fn cross(&self, shape: &B::Shape, t_min: &[f64; W], t_max: &[f64; W]) -> [Option<Crossing>; W];
    /// Whether each ray crosses `shape` within its range, as [`Backend::occludes`] answers
    /// each; a lane with `t_max = −∞` is never blocked.
    fn occluded_by(&self, shape: &B::Shape, t_min: &[f64; W], t_max: &[f64; W]) -> [bool; W];
}

impl<B: Backend> RayLanes<B, 1> for Ray<B::Carrier> {
    type T = f64;
    #[inline(always)]
    fn origin(&self) -> E3 {
        self.origin
    }
    #[inline(always)]
    fn dir(&self) -> E3 {
        self.dir
    }
    #[inline(always)]
    fn cast(origin: E3, dir: E3) -> Self {
        B::ray(origin, dir)
    }
    #[inline(always)]
    fn camera(camera: &Camera, u: [f64; 1], v: [f64; 1]) -> Option<Self> {
        B::camera_ray(camera, u[0], v[0])
    }
    #[inline(always)]
    fn ray(&self, _: usize) -> &Ray<B::Carrier> {
        self
    }
    #[inline(always)]
    fn cross(&self, shape: &B::Shape, t_min: &[f64; 1], t_max: &[f64; 1]) -> [Option<Crossing>; 1] {
        [B::intersect(shape, self, t_min[0], t_max[0])]
    }
    #[inline(always)]
    fn occluded_by(&self, shape: &B::Shape, t_min: &[f64; 1], t_max: &[f64; 1]) -> [bool; 1] {
        [B::occludes(shape, self, t_min[0], t_max[0])]
    }
}

/// A crossing per lane, `None` where the lane's ray misses.
pub type Crossings = [Option<Crossing>; 4];

/// Four rays, lane `k` being ray `k`, in lanes of `L` (four of them).
pub struct Packet<B: Backend, L: Lane = F64x4> {
    /// The scalar rays (for the per-lane steps).
    pub rays: [Ray<B::Carrier>; 4],
    /// Their origins in lanes.
    pub origin: E3<L>,
    /// Their unit directions in lanes.
    pub dir: E3<L>,
    /// Their carriers in lanes (the sparse back end: their lines).
    pub carrier: B::CarrierLanes<L>,
}

impl<B: Backend, L: Lane> Packet<B, L> {
    /// Four rays from origins along unit directions in lanes, each made by [`Backend::ray`],
    /// with `carrier` (for a back end whose rays carry nothing in lanes).
    #[inline(always)]
    pub fn per_lane(origin: E3<L>, dir: E3<L>, carrier: B::CarrierLanes<L>) -> Self {
        let rays = core::array::from_fn(|l| B::ray(lane(&origin, l), lane(&dir, l)));
        Packet { rays, origin, dir, carrier }
    }

    /// Each ray's origin and unit direction.
    #[inline(always)]
    pub fn origins_dirs(&self) -> [(E3, E3); 4] {
        self.rays.each_ref().map(|r| (r.origin, r.dir))
    }
}

/// Which lanes' points lie on a disk of rim `(c, r)`, `|x − c|² ≤ r²`; all lanes where
/// there is no rim (a plane).
#[inline(always)]
pub(crate) fn inside_rim<L: Lane>(x: &E3<L>, rim: Option<(E3, f64)>) -> [bool; 4] {
    match rim {
        None => [true; 4],
        Some((c, r)) => {
            let d = sub(*x, c.map(L::from_f64));
            array(dot(d, d)).map(|q| q <= r * r)
        }
    }
}

/// The crossings at `t` and points `x` of the lanes that are `ok`, the others `None`.
#[inline(always)]
pub(crate) fn crossings<L: Lane>(ok: [bool; 4], t: [f64; 4], x: &E3<L>) -> Crossings {
    if !ok.iter().any(|&b| b) {
        return [None; 4];
    }
    core::array::from_fn(|l| ok[l].then(|| Crossing { t: t[l], point: lane(x, l), alpha: None, part: 0 }))
}

/// Four rays in lanes.
impl<B: Backend, L: Lane> RayLanes<B, 4> for Packet<B, L> {
    type T = L;
    #[inline(always)]
    fn origin(&self) -> E3<L> {
        self.origin
    }
    #[inline(always)]
    fn dir(&self) -> E3<L> {
        self.dir
    }
    #[inline(always)]
    fn cast(origin: E3<L>, dir: E3<L>) -> Self {
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
    #[inline(always)]
    fn occluded_by(&self, shape: &B::Shape, t_min: &[f64; 4], t_max: &[f64; 4]) -> [bool; 4] {
        B::occludes4(shape, self, t_min, t_max)
    }
}
