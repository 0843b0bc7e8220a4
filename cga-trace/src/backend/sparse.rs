//! The generated grade-sparse types: rays carry their CGA lines, and the built-in
//! primitives are met as [`crate::shapes`] meets them — in packets on the generated types
//! instantiated on four f64 lanes, operation for operation, so the same bits; other shapes
//! one lane at a time through their own code.

use super::{Backend, Crossings, Packet, array, crossings, inside_rim, lane, mask_array};
use crate::camera::Camera;
use crate::ray::Ray;
use crate::shapes::{Crossing, DiskShape, MeshShape, PlaneShape, Shape, SphereShape, TriangleShape, sphere_crossing};
use cga_core::euclid::{E3, dot, sub, tolerance};
use cga_core::simd::{Lane, Lanes};
use cga_core::{Line, Plane, Sphere};
use core::any::Any;
use std::sync::Arc;

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
    /// A mesh (packets go through its hierarchy together).
    Mesh(Arc<MeshShape>),
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
            SparseShape::Mesh($s) => $body,
            SparseShape::Other($s) => $body,
        }
    };
}

impl Backend for Sparse {
    type Carrier = Line;
    type Shape = SparseShape;
    const NAME: &'static str = "sparse";
    const KIND: super::BackendKind = super::BackendKind::Sparse;
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
        } else if let Ok(mesh) = (shape.clone() as Arc<dyn Any + Send + Sync>).downcast::<MeshShape>() {
            SparseShape::Mesh(mesh)
        } else {
            SparseShape::Other(shape.clone())
        }
    }

    #[inline(always)]
    fn intersect(shape: &SparseShape, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        each_kind!(shape, s => s.intersect(ray, t_min, t_max))
    }

    #[inline(always)]
    fn occludes(shape: &SparseShape, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        each_kind!(shape, s => s.occludes(ray, t_min, t_max))
    }

    fn normal(shape: &SparseShape, ray: &Ray, crossing: &Crossing) -> E3 {
        each_kind!(shape, s => s.normal(ray, crossing))
    }

    type CarrierLanes<L: Lane> = Line<L>;

    #[inline(always)]
    fn packet<L: Lane>(origin: E3<L>, dir: E3<L>) -> Packet<Sparse, L> {
        let line = Line::from_point_unit_direction(origin, dir);
        let mut lines = [Line::zero(); 4];
        Line::unpack_lanes(line, &mut lines);
        let rays = core::array::from_fn(|l| Ray { origin: lane(&origin, l), dir: lane(&dir, l), carrier: lines[l] });
        Packet { rays, origin, dir, carrier: line }
    }

    #[inline(always)]
    fn camera_packet<L: Lane>(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Packet<Sparse, L>> {
        let (rays, carrier, dir) = camera.rays4(u, v)?;
        // The lanes as computed, not gathered back from the rays.
        Some(Packet { rays, origin: camera.position().map(L::from_f64), dir, carrier })
    }

    #[inline(always)]
    fn cross4<L: Lane>(shape: &SparseShape, p: &Packet<Sparse, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        match shape {
            SparseShape::Sphere(s) => meet_sphere(p, &s.sphere.cast(), t_min, t_max),
            SparseShape::Plane(s) => meet_plane(p, &s.plane.cast(), None, t_min, t_max),
            SparseShape::Disk(d) => {
                let rim = Some((d.disk.centre, d.disk.radius));
                meet_plane(p, &d.disk.plane.cast(), rim, t_min, t_max)
            }
            SparseShape::Mesh(m) => m.intersect4::<L>(p.origins_dirs(), t_min, t_max),
            _ => core::array::from_fn(|l| Sparse::intersect(shape, &p.rays[l], t_min[l], t_max[l])),
        }
    }

    #[inline(always)]
    fn occludes4<L: Lane>(shape: &SparseShape, p: &Packet<Sparse, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> [bool; 4] {
        match shape {
            SparseShape::Mesh(m) => m.occludes4::<L>(p.origins_dirs(), t_min, t_max),
            SparseShape::Other(s) => core::array::from_fn(|l| s.occludes(&p.rays[l], t_min[l], t_max[l])),
            _ => Sparse::cross4(shape, p, t_min, t_max).map(|c| c.is_some()),
        }
    }
}

/// `(x − o) · d` per lane, as [`Ray::t_of`] computes it.
fn t_of4<L: Lane>(p: &Packet<Sparse, L>, x: E3<L>) -> L {
    dot(sub(x, p.origin), p.dir)
}

/// `L ∨ S` in lanes: [`sphere_crossing`], which [`SphereShape::intersect`](crate::shapes::SphereShape)
/// runs for one ray.
#[inline(always)]
fn meet_sphere<L: Lane>(p: &Packet<Sparse, L>, sphere: &Sphere<L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
    let range = (L::from_fn(|l| t_min[l]), L::from_fn(|l| t_max[l]));
    let c = sphere_crossing(&p.carrier, sphere, (p.origin, p.dir), range);
    if !L::any(c.found) {
        return [None; 4];
    }
    let [a, b] = &c.points;
    let (ta, tb) = (array(c.t[0]), array(c.t[1]));
    let (found, second) = (mask_array::<L>(c.found), mask_array::<L>(c.second));
    core::array::from_fn(|l| {
        found[l].then(|| {
            let (t, x) = if second[l] { (tb[l], b) } else { (ta[l], a) };
            Crossing { t, point: lane(x, l), alpha: None, part: 0 }
        })
    })
}

/// `L ∨ Π` in lanes, as the plane and disk shapes meet it: the flat point's point where
/// its weight is not zero to rounding, within range, and for a disk within the rim.
#[inline(always)]
fn meet_plane<L: Lane>(
    p: &Packet<Sparse, L>,
    plane: &Plane<L>,
    rim: Option<(E3, f64)>,
    t_min: &[f64; 4],
    t_max: &[f64; 4],
) -> Crossings {
    let flat = p.carrier & *plane;
    let inv = L::one() / flat.eoi;
    let x = [flat.e1i * inv, flat.e2i * inv, flat.e3i * inv];
    let t = array(t_of4(p, x));
    let (w, inv) = (array(flat.eoi), array(inv));
    let (inside, tol) = (inside_rim(&x, rim), tolerance(1.0));
    let ok = core::array::from_fn(|l| {
        (w[l].abs() > tol) & inv[l].is_finite() & (t[l] > t_min[l]) & (t[l] < t_max[l]) & inside[l]
    });
    crossings(ok, t, &x)
}
