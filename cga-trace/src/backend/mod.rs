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
//! A back end turns rays into what it meets objects with (its carrier), prepares each
//! scene object once, and intersects and shades them; the integrator
//! ([`Renderer`]) is shared.

mod dense;
mod plain;

use crate::camera::Camera;
use crate::frame::RANGE;
use crate::ray::Ray;
use crate::render::{RayCounts, Renderer};
use crate::scene::Scene;
use crate::shapes::{Crossing, DiskShape, PlaneShape, Shape, SphereShape, TriangleShape};
use cga_core::Line;
use cga_core::euclid::{E3, norm};
pub use dense::{Dense, DenseShape};
pub use plain::{Plain, PlainShape};
use std::sync::Arc;

/// Geometry code the renderer runs on.
pub trait Backend: Send + Sync + 'static {
    /// What a ray carries to meet objects with.
    type Carrier: Copy + Send + Sync;
    /// A scene object, prepared once.
    type Shape: Send + Sync;
    /// Name, for reports.
    const NAME: &'static str;
    /// The ray from `origin` along the unit direction `dir` (the integrator's secondary rays,
    /// whose directions are unit by construction: not normalised again).
    fn ray(origin: E3, dir: E3) -> Ray<Self::Carrier>;
    /// The camera ray through pixel coordinates `(u, v)`.
    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray<Self::Carrier>>;
    /// A scene object in this back end's form.
    fn prepare(shape: &Arc<dyn Shape>) -> Self::Shape;
    /// The nearest crossing with `t_min < t < t_max`.
    fn intersect(shape: &Self::Shape, ray: &Ray<Self::Carrier>, t_min: f64, t_max: f64) -> Option<Crossing>;
    /// The unit normal at a crossing, facing the ray.
    fn normal(shape: &Self::Shape, ray: &Ray<Self::Carrier>, crossing: &Crossing) -> E3;
    /// Whether the back end traces ray packets ([`crate::packet::Packets`]).
    const PACKETS: bool = false;
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
    /// Four neighbouring pixels `(i₀ + k, j)` of a renderer whose packets are on
    /// ([`crate::packet`]); `None` where the back end has none or a camera ray cannot be
    /// formed (the scalar path takes over).
    fn pixels4(_renderer: &Renderer<'_, Self>, _i0: u32, _j: u32, _cast: &mut RayCounts) -> Option<[[f64; 3]; 4]>
    where
        Self: Sized,
    {
        None
    }
}

/// Whether back end `B` renders every object of `scene` as it is ([`Backend::SPAN`]): `Err`
/// says how far the objects' sizes (frame units: the larger of the distance from the camera
/// and the extent) spread from the frame's unit, where they are beyond it.
pub fn holds<B: Backend>(scene: &Scene) -> Result<(), String> {
    let sizes = scene.objects.iter().filter_map(|o| o.shape.bounds()).map(|(c, r)| norm(c).max(r));
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

/// The generated grade-sparse types (the default back end).
#[derive(Clone, Copy, Debug, Default)]
pub struct Sparse;

/// A scene object for the sparse back end: the built-in primitives by value, so that their
/// meets are inlined into the integrator's loop (rather than a call through `dyn Shape` per
/// object and ray), any other shape through its trait.
#[derive(Clone, Debug)]
pub enum SparseShape {
    /// A sphere.
    Sphere(SphereShape),
    /// An infinite plane.
    Plane(PlaneShape),
    /// A disk.
    Disk(DiskShape),
    /// A triangle.
    Triangle(TriangleShape),
    /// Any other shape (evolved, spline and ruled surfaces, kinds added later).
    Other(Arc<dyn Shape>),
}

/// `$body` with `$s` bound to the shape inside a [`SparseShape`], whatever its kind.
macro_rules! each_kind {
    ($shape:expr, $s:ident => $body:expr) => {
        match $shape {
            SparseShape::Sphere($s) => $body,
            SparseShape::Plane($s) => $body,
            SparseShape::Disk($s) => $body,
            SparseShape::Triangle($s) => $body,
            SparseShape::Other($s) => $body,
        }
    };
}

impl Backend for Sparse {
    type Carrier = Line;
    type Shape = SparseShape;
    const NAME: &'static str = "sparse";
    const PACKETS: bool = true;

    fn ray(origin: E3, dir: E3) -> Ray {
        Ray::unit(origin, dir)
    }

    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray> {
        camera.ray(u, v)
    }

    fn prepare(shape: &Arc<dyn Shape>) -> SparseShape {
        let any: &dyn Shape = &**shape;
        if let Some(s) = any.downcast_ref::<SphereShape>() {
            SparseShape::Sphere(s.clone())
        } else if let Some(p) = any.downcast_ref::<PlaneShape>() {
            SparseShape::Plane(p.clone())
        } else if let Some(d) = any.downcast_ref::<DiskShape>() {
            SparseShape::Disk(d.clone())
        } else if let Some(t) = any.downcast_ref::<TriangleShape>() {
            SparseShape::Triangle(t.clone())
        } else {
            SparseShape::Other(shape.clone())
        }
    }

    #[inline(always)]
    fn intersect(shape: &SparseShape, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        each_kind!(shape, s => s.intersect(ray, t_min, t_max))
    }

    fn normal(shape: &SparseShape, ray: &Ray, crossing: &Crossing) -> E3 {
        each_kind!(shape, s => s.normal(ray, crossing))
    }

    fn pixels4(renderer: &Renderer<'_, Sparse>, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        renderer.pixels4(i0, j, cast)
    }
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
