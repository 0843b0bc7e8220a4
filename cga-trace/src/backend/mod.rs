//! Back ends: the same renderer over three kinds of geometry code, to compare them.
//!
//! - [`Sparse`] (the default): the generated grade-sparse types; meets as in
//!   [`crate::shapes`].
//! - [`Dense`]: the same algorithm with every product on the dense 32-coefficient
//!   [`Multivector`](cga_core::Multivector) — what a user of a dense CGA library writes.
//! - [`Plain`]: textbook Euclidean formulas with glam for spheres, planes, disks and
//!   triangles.
//!
//! The last two are comparison baselines: they specialise the primitives they know (by
//! downcasting) and hand every other shape — evolved surfaces, and any kind added later —
//! to its own sparse geometry, so a new shape needs nothing here.
//!
//! A back end turns rays into what it meets objects with (its carrier), one at a time or
//! four in lanes ([`Packet`]), prepares each scene object once, and intersects them and
//! gives their normals; the integrator ([`Renderer`](crate::Renderer)) is shared and
//! generic over the lanes ([`RayLanes`]).

mod dense;
mod lanes;
mod plain;
mod sparse;

use crate::camera::Camera;
use crate::frame::RANGE;
pub(crate) use crate::lanes::{array, lane, lanes3, mask_array};
use crate::ray::Ray;
use crate::scene::Scene;
use crate::shapes::{Crossing, Shape};
use cga_core::euclid::{E3, norm};
use cga_core::simd::Lane;
pub use dense::{Dense, DenseShape};
pub use lanes::{Crossings, Packet, RayLanes};
pub(crate) use lanes::{crossings, inside_rim};
pub use plain::{Plain, PlainShape};
pub use sparse::{Sparse, SparseShape};
use std::sync::Arc;

/// Geometry code the renderer runs on.
pub trait Backend: Send + Sync + 'static {
    /// What a ray carries to meet objects with.
    type Carrier: Copy + Send + Sync;
    /// A scene object, prepared once.
    type Shape: Clone + Send + Sync + 'static;
    /// Name, for reports.
    const NAME: &'static str;
    /// Which of the [`BackendKind`]s it is.
    const KIND: BackendKind;
    /// The ray from `origin` along the unit direction `dir` (the integrator's secondary rays,
    /// whose directions are unit by construction: not normalised again).
    fn ray(origin: E3, dir: E3) -> Ray<Self::Carrier>;
    /// The camera ray through pixel coordinates `(u, v)`.
    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray<Self::Carrier>>;
    /// A scene object in this back end's form.
    fn prepare(shape: &Arc<dyn Shape>) -> Self::Shape;
    /// The nearest crossing with `t_min < t < t_max`.
    fn intersect(shape: &Self::Shape, ray: &Ray<Self::Carrier>, t_min: f64, t_max: f64) -> Option<Crossing>;
    /// Whether the ray crosses the shape with `t_min < t < t_max` (a shadow ray's test): by
    /// default [`Backend::intersect`]`.is_some()`.
    fn occludes(shape: &Self::Shape, ray: &Ray<Self::Carrier>, t_min: f64, t_max: f64) -> bool {
        Self::intersect(shape, ray, t_min, t_max).is_some()
    }
    /// The unit normal at a crossing, facing the ray.
    fn normal(shape: &Self::Shape, ray: &Ray<Self::Carrier>, crossing: &Crossing) -> E3;
    /// Whether the renderer should trace this back end's rays four at a time ([`Packet`]):
    /// where it meets primitives in lanes ([`Backend::cross4`]).
    const PACKETS: bool = false;
    /// What four rays carry in lanes `L` (the sparse back end: their CGA lines).
    type CarrierLanes<L: Lane>: Copy;
    /// Four rays from origins along unit directions given in lanes (secondary rays), as
    /// [`Backend::ray`] makes each.
    fn packet<L: Lane>(origin: E3<L>, dir: E3<L>) -> Packet<Self, L>
    where
        Self: Sized;
    /// The camera rays through `(u_k, v_k)`, as [`Backend::camera_ray`] makes each; `None`
    /// where one cannot be formed, and for a back end without packets (the renderer then
    /// traces one ray at a time).
    fn camera_packet<L: Lane>(_camera: &Camera, _u: [f64; 4], _v: [f64; 4]) -> Option<Packet<Self, L>>
    where
        Self: Sized,
    {
        None
    }
    /// The crossings of the packet's rays with a shape within their ranges, as
    /// [`Backend::intersect`] finds each (by default one lane at a time).
    #[inline(always)]
    fn cross4<L: Lane>(shape: &Self::Shape, p: &Packet<Self, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings
    where
        Self: Sized,
    {
        core::array::from_fn(|l| Self::intersect(shape, &p.rays[l], t_min[l], t_max[l]))
    }
    /// Whether each of the packet's rays crosses the shape within its range, as
    /// [`Backend::occludes`] answers each (by default from [`Backend::cross4`]).
    #[inline(always)]
    fn occludes4<L: Lane>(shape: &Self::Shape, p: &Packet<Self, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> [bool; 4]
    where
        Self: Sized,
    {
        Self::cross4(shape, p, t_min, t_max).map(|c| c.is_some())
    }
    /// How far this back end's crossings of `shape` may lie from it ([`Shape::crossing_error`],
    /// which fits the null basis and plain vectors; a back end with other arithmetic says
    /// its own).
    fn crossing_error(shape: &dyn Shape) -> f64 {
        shape.crossing_error()
    }
    /// How many binary orders of magnitude an object's size may lie from the frame's unit
    /// for this back end to render it as it is ([`holds`]): the frame's own [`RANGE`] where
    /// the arithmetic is scale-free (the null basis, plain vectors).
    const SPAN: i32 = RANGE;
}

/// Whether back end `B` renders every object of `scene` as it is ([`Backend::SPAN`]): `Err`
/// says how far the objects' sizes (frame units: the larger of the distance from the camera
/// and the extent) spread from the frame's unit, where they are beyond it.
pub fn holds<B: Backend>(scene: &Scene) -> Result<(), String> {
    holds_bounds::<B>(scene.objects.iter().filter_map(|o| o.shape.bounds()))
}

/// [`holds`] for objects of these bounding spheres.
pub fn holds_bounds<B: Backend>(bounds: impl Iterator<Item = (E3, f64)>) -> Result<(), String> {
    let sizes = bounds.map(|(c, r)| norm(c).max(r));
    let (lo, hi) = sizes.fold((f64::INFINITY, 0.0f64), |(lo, hi), s| (lo.min(s), hi.max(s)));
    let limit = 2f64.powi(B::SPAN);
    if hi <= limit && (hi == 0.0 || lo >= 1.0 / limit) {
        return Ok(());
    }
    Err(format!(
        "the {} back end holds objects within 2^{} (about {:.0e}) of the scene's size either way; this scene's run from {lo:.1e} to {hi:.1e} of it (render it with --backend sparse)",
        B::NAME,
        B::SPAN,
        limit
    ))
}

/// Which back end renders (for the CLI and benches).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum BackendKind {
    /// Generated grade-sparse types.
    #[default]
    Sparse,
    /// The dense multivector.
    Dense,
    /// Plain vectors (glam).
    Plain,
}
