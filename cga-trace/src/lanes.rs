//! Rays and their hits in lanes, for code written once for one ray and for a packet of
//! four: [`RayLanes`] (a [`Ray`] is one lane, a [`Packet`](crate::packet::Packet) four),
//! what one light gives the hits (`lit`), and the mirror bounce (`mirrored`).

use crate::backend::Backend;
use crate::camera::Camera;
use crate::light::{Light, lights};
use crate::material::{Material, shine};
use crate::ray::{Ray, leaving_origin, mirror};
use crate::shapes::{Crossing, ShadingPoint};
use cga_core::euclid::{E3, add, dot};
use cga_core::simd::Lane;

/// `W` rays in lanes of `Self::T`: what the shading casts its shadow rays as.
pub trait RayLanes<B: Backend, const W: usize>: Sized {
    /// The lanes: `f64` for one ray, `F64x4` for four.
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
}

/// The mirror bounces of the lanes that `bounce` at their hits (object index per lane), each
/// off its object's crossing error `errors` ([`mirror`] in lanes: the reflected direction,
/// starting off the surface); the other lanes keep their ray (a zero normal reflects nothing).
#[inline(always)]
pub(crate) fn mirrored<B: Backend, R: RayLanes<B, W>, const W: usize>(
    rays: &R,
    hits: &[Option<(ShadingPoint, usize)>; W],
    errors: &[f64; W],
    bounce: &[bool; W],
) -> R {
    let at = |l: usize| match hits[l] {
        Some((hit, _)) if bounce[l] => (hit.point, hit.normal),
        _ => (rays.ray(l).origin, [0.0; 3]),
    };
    let x: E3<R::T> = lanes3::<R::T, W>(core::array::from_fn(|l| at(l).0));
    let n: E3<R::T> = lanes3::<R::T, W>(core::array::from_fn(|l| at(l).1));
    let (origin, r) = mirror(rays.dir(), rays.origin(), x, n, R::T::from_fn(|l| errors[l]));
    R::cast(origin, r)
}

/// Points (or vectors), one per lane, as three coordinates in lanes.
#[inline(always)]
pub(crate) fn lanes3<T: Lane, const W: usize>(v: [E3; W]) -> E3<T> {
    core::array::from_fn(|k| T::from_fn(|l| v[l][k]))
}

/// What one light gives hits in lanes before shadowing.
pub(crate) struct Lit<T, const W: usize> {
    /// Which lanes it lights: a hit, the light ahead of it and in front of the surface for
    /// the diffuse or the specular term.
    pub lit: [bool; W],
    /// Unit direction to the light.
    pub l: E3<T>,
    /// Distance to it (frame units; ∞ for a directional light).
    pub distance: T,
    /// `n · l`.
    pub diffuse: T,
    /// `max(n · h, 0)^q`.
    pub specular: T,
    /// Where the shadow rays towards it start ([`leaving_origin`]).
    pub shadow_origin: E3<T>,
}

/// The unshadowed terms of `light` at hits `x` (unit normals `n`, materials `m`, `hit` where
/// a lane has one) seen from `v`, shadow rays starting `offset` off the surfaces; `None`
/// where it lights no lane.
#[inline(always)]
pub(crate) fn lit<T: Lane, const W: usize>(
    light: &Light,
    (x, n, v): (E3<T>, E3<T>, E3<T>),
    m: &[&Material; W],
    hit: &[bool; W],
    offset: T,
) -> Option<Lit<T, W>> {
    // One square root for the distance and the direction.
    let (l, distance) = light.toward(x);
    let diffuse = dot(n, l);
    let specular = shine(m, n, add(l, v));
    let lighting = lights(distance, diffuse, specular);
    let lit: [bool; W] = core::array::from_fn(|k| hit[k] && T::mask_lane(lighting, k));
    let shadow_origin = leaving_origin(x, n, diffuse, offset);
    lit.iter().any(|&b| b).then_some(Lit { lit, l, distance, diffuse, specular, shadow_origin })
}
