//! The objects a scene holds and how a ray meets them, one module per kind of shape. Every
//! intersection is a CGA meet with the ray's line; of its points the nearest with
//! `t_min < t < t_max` counts (hits behind the origin are dropped one by one, never the whole
//! object). Finding a crossing and shading it are separate: shadow rays only need the
//! crossing, so the normal — from the reflected line `N = L' − L` for primitives, from
//! eq. 6–11 for evolved surfaces — is computed only for the hit that is shaded.
//!
//! A shape owns everything about itself ([`Shape`]): its intersection, its normal, its
//! bounds and whether a ray should test them first. Adding a kind of shape is a module
//! here (or, like [`crate::surface`], beside) and its entry in the scene format
//! ([`crate::format`]); see ARCHITECTURE.md, "Adding a shape".

mod body;
mod cone;
mod csg;
mod cuboid;
mod disk;
mod mesh;
mod plane;
mod sphere;
mod torus;
mod triangle;

use crate::ray::{Ray, in_range};
pub use body::Body;
use cga_core::Plane;
use cga_core::euclid::{E3, dot};
pub use cone::ConeShape;
use core::any::Any;
use core::fmt::Debug;
pub use csg::{Clipped, Csg, CsgError, CsgPart, MAX_CROSSINGS, Node, Operation, Spans, spans_by_crossings};
pub use cuboid::BoxShape;
pub use disk::DiskShape;
pub use mesh::MeshShape;
pub use plane::PlaneShape;
pub use sphere::SphereShape;
pub(crate) use sphere::sphere_crossing;
pub use torus::TorusShape;
pub(crate) use triangle::inside_triangle;
pub use triangle::{Shading, TriangleShape};

/// What a surface's parameters are: fractions (angles over a turn, α, barycentric
/// coordinates) or lengths (frame units, which the renderer turns into world units, so that
/// a floor's checker has the same size at any scale).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Dimensionless.
    Fraction,
    /// A length.
    Length,
}

/// Where a ray crosses an object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Ray parameter.
    pub t: f64,
    /// The point.
    pub point: E3,
    /// For an evolved surface, the α of the circle hit.
    pub alpha: Option<f64>,
    /// Which piece of a shape made of several the crossing lies on (a body's part, a mesh's
    /// triangle); 0 for a shape of one piece.
    pub part: u32,
}

/// A crossing with its normal, ready to shade.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingPoint {
    /// Ray parameter.
    pub t: f64,
    /// The point.
    pub point: E3,
    /// Unit normal, facing the side the ray came from (surfaces are two-sided).
    pub normal: E3,
    /// For an evolved surface, the α of the circle hit.
    pub alpha: Option<f64>,
    /// The piece of the shape it lies on ([`Crossing::part`]).
    pub part: u32,
}

impl ShadingPoint {
    /// The crossing it shades.
    pub fn crossing(&self) -> Crossing {
        Crossing { t: self.t, point: self.point, alpha: self.alpha, part: self.part }
    }

    /// The crossing `c` with its normal.
    pub fn at(c: Crossing, normal: E3) -> Self {
        ShadingPoint { t: c.t, point: c.point, normal, alpha: c.alpha, part: c.part }
    }
}

/// A scene object's geometry: how rays meet it (with the generated sparse types), its
/// normal, its bounds. Everything about a kind of shape is in its implementation.
pub trait Shape: Send + Sync + Debug + Any {
    /// The nearest crossing with `t_min < t < t_max`.
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing>;

    /// Whether the ray crosses the shape with `t_min < t < t_max` (a shadow ray's test):
    /// `intersect(…).is_some()`, which a shape may answer sooner (at the first crossing it
    /// finds rather than the nearest).
    fn occludes(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.intersect(ray, t_min, t_max).is_some()
    }

    /// The unit normal at a crossing of `ray`, facing the ray.
    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3;

    /// The unit normal of the plane the shape lies in, for a flat shape whose shading
    /// normal may differ from it (a mesh's triangle, whose corner normals are blended):
    /// light crossing a dielectric's surface bends at the surface itself, so refraction and
    /// which side of a solid a ray is on read this, never the shading normal. `None` where
    /// [`Shape::normal`] is the surface's own.
    fn facet(&self, _crossing: &Crossing) -> Option<E3> {
        None
    }

    /// A sphere `(centre, radius)` holding the shape, `None` when unbounded (a plane).
    fn bounds(&self) -> Option<(E3, f64)>;

    /// How far (frame units) a crossing the shape reports may lie from its true surface,
    /// beside the rounding of the crossing's own coordinates and of its ray's origin (which
    /// the integrator adds, [`crate::ray::offset`]): a bound from the shape's own sizes — its
    /// extent and its distance from the frame's origin, the camera — so relative to the
    /// shape, never to a global unit. No ray counts a crossing of the shape nearer than this
    /// (a camera standing on it, a ray leaving it), and secondary rays start a multiple of it
    /// off the surface.
    fn crossing_error(&self) -> f64;

    /// Whether a ray should test [`Shape::bounds`] before the shape itself: where the
    /// shape's own test costs more than a sphere's (a sphere's does not; an evolved surface
    /// culls itself).
    fn cull(&self) -> bool {
        false
    }

    /// Whether the shape lies in a plane, so that no ray leaving it meets it again
    /// (secondary rays start off the surface on the side they leave to): its own shadow
    /// rays skip it.
    fn flat(&self) -> bool {
        false
    }

    /// The curvature of the surface at a crossing (in the scene's frame), for surfaces swept
    /// by circles; `None` for the others (flat or of constant curvature, not reported).
    fn curvature(&self, _crossing: &Crossing) -> Option<cga_core::Curvature> {
        None
    }

    /// The surface's own parameters `(u, v)` at a crossing, for textures
    /// ([`crate::texture`]), and what they measure; `None` where the shape has none.
    fn uv(&self, _crossing: &Crossing) -> Option<([f64; 2], Unit)> {
        None
    }

    /// Whether the shape's `(u, v)` turn about its normal `n` as a map's east and north do,
    /// `u × v = n` (a plane's): an image laid on them is read with `v` up (its bottom row at
    /// `v = 0`) so that, seen from the side `n` faces, it reads as drawn. `false` where `v`
    /// already runs down an image as down a page seen from outside (a sphere's colatitude, a
    /// box's faces, a mesh's coordinates as files count them).
    fn v_up(&self) -> bool {
        false
    }

    /// Whether the shape bounds a solid on its own, which CSG and clipping take: a sphere, a
    /// box, a capped cylinder or cone, a torus, a plane (the half-space behind its normal), a
    /// closed mesh ([`MeshShape`]) and surfaces that close one together ([`Body`]).
    fn closed(&self) -> bool {
        false
    }

    /// Where the ray's whole line lies inside the solid a [closed](Shape::closed) shape
    /// bounds: by default read off its crossings in turn ([`spans_by_crossings`]).
    fn spans(&self, ray: &Ray) -> Spans {
        spans_by_crossings(self, ray)
    }

    /// The crossing at parameter `t` of the ray's line, an end of one of its
    /// [spans](Shape::spans): by default the point there; a shape of several pieces says
    /// which piece it lies on (and a swept surface its α), so that its normal and `(u, v)`
    /// can be read there.
    fn crossing_on(&self, ray: &Ray, t: f64) -> Crossing {
        Crossing { t, point: ray.at(t), alpha: None, part: 0 }
    }

    /// The nearest crossing and its normal.
    fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<ShadingPoint> {
        let c = self.intersect(ray, t_min, t_max)?;
        Some(ShadingPoint::at(c, self.normal(ray, &c)))
    }
}

impl dyn Shape {
    /// The shape as a `S`, if it is one.
    pub fn downcast_ref<S: Shape>(&self) -> Option<&S> {
        (self as &dyn Any).downcast_ref()
    }
}

/// Whether a point of the ray lies in its range `(t_min, t_max)` ([`in_range`]).
pub(crate) fn point_in_range<C>(ray: &Ray<C>, t_min: f64, t_max: f64) -> impl Fn(&E3) -> bool + '_ {
    move |x| in_range(ray.t_of(*x), t_min, t_max)
}

/// The crossing at `point`.
fn crossing_at(ray: &Ray, point: E3) -> Crossing {
    Crossing { t: ray.t_of(point), point, alpha: None, part: 0 }
}

/// The unit normal from the reflected line, facing the ray: the direction of `L' − L` for
/// the mirror plane `Π` at the crossing (the paper's construction). Reflecting `L` in a
/// plane of unit normal `n` changes only the component of its direction along `n`
/// (`d' = d − 2(d·n)n`), so `L' − L` points along `±n`: the normal is `Π`'s own, read from
/// its dual's Euclidean part when the shape is made (for a sphere, the tangent plane's
/// `(x − c)/r`): the sandwich `Π L Π` per hit equals it to rounding (`tests/render.rs`
/// checks both agree) at the cost of a product per hit.
fn plane_normal(plane: &Plane) -> E3 {
    plane.normal_offset().map_or([0.0, 0.0, 1.0], |(n, _)| n)
}

/// `64 ε s`: the rounding of quantities of size `s`, the crossing error of shapes whose
/// crossings are accurate to their data's own rounding.
pub(crate) fn rounding(s: f64) -> f64 {
    cga_core::euclid::tolerance(s)
}

/// `|x|∞`.
pub(crate) fn largest(x: E3) -> f64 {
    x.iter().fold(0.0f64, |m, c| m.max(c.abs()))
}

/// The crossing error of a flat shape whose plane has unit normal `n` and was placed through
/// `p`: the rounding of its offset `δ = n · p`, `64 ε Σ |n_k p_k|` (exact for a plane along
/// the axes, `64 ε |p|` at worst). Its crossings lie on the plane to that and their own
/// rounding.
pub(crate) fn flat_error(n: E3, p: E3) -> f64 {
    rounding((0..3).map(|k| (n[k] * p[k]).abs()).sum())
}

/// `n` turned to face against `dir`.
pub(crate) fn facing(n: E3, dir: E3) -> E3 {
    if dot(n, dir) > 0.0 { n.map(|x| -x) } else { n }
}

/// What the shapes' unit tests share: rays and a seeded stream of numbers.
#[cfg(test)]
pub(crate) mod testing {
    use crate::ray::Ray;
    use cga_core::Line;
    use cga_core::euclid::{E3, unit};

    /// The ray from `o` along `d` (made unit).
    pub(crate) fn ray(o: E3, d: E3) -> Ray {
        let dir = unit(d).unwrap();
        Ray { origin: o, dir, carrier: Line::from_point_unit_direction(o, dir) }
    }

    /// A seeded stream of numbers in [−1, 1) (xorshift).
    pub(crate) fn stream(mut state: u64) -> impl FnMut() -> f64 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }
}
