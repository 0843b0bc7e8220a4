//! The generated grade-sparse types: rays carry their CGA lines, and the built-in
//! primitives are met as [`crate::shapes`] meets them — in packets on the generated types
//! instantiated on four f64 lanes, operation for operation, so the same bits; other shapes
//! one lane at a time through their own code.

use super::{Backend, Crossings, Packet, crossings, inside_rim, lane};
use crate::camera::Camera;
use crate::ray::Ray;
use crate::shapes::{Crossing, DiskShape, PlaneShape, Shape, SphereShape, TriangleShape, sphere_crossing};
use cga_core::euclid::{E3, dot, sub, tolerance};
use cga_core::simd::{F64x4, Lanes};
use cga_core::{Line, Plane, Select, Sphere};
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

    type CarrierLanes = Line<F64x4>;

    #[inline(always)]
    fn packet(origin: [F64x4; 3], dir: [F64x4; 3]) -> Packet<Sparse> {
        let line = Line::from_point_unit_direction(origin, dir);
        let lines = Line::unpack(line);
        let rays = core::array::from_fn(|l| Ray { origin: lane(&origin, l), dir: lane(&dir, l), carrier: lines[l] });
        Packet { rays, origin, dir, carrier: line }
    }

    #[inline(always)]
    fn camera_packet(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Packet<Sparse>> {
        let (rays, line) = camera.rays4(u, v)?;
        Some(Packet::with_carrier(rays, line))
    }

    #[inline(always)]
    fn cross4(shape: &SparseShape, p: &Packet<Sparse>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        match shape {
            SparseShape::Sphere(s) => meet_sphere(p, &Sphere::pack([s.sphere; 4]), t_min, t_max),
            SparseShape::Plane(s) => meet_plane(p, &Plane::pack([s.plane; 4]), None, t_min, t_max),
            SparseShape::Disk(d) => {
                let rim = Some((d.disk.centre, d.disk.radius));
                meet_plane(p, &Plane::pack([d.disk.plane; 4]), rim, t_min, t_max)
            }
            _ => core::array::from_fn(|l| Sparse::intersect(shape, &p.rays[l], t_min[l], t_max[l])),
        }
    }
}

/// `(x − o) · d` per lane, as [`Ray::t_of`] computes it.
fn t_of4(p: &Packet<Sparse>, x: [F64x4; 3]) -> F64x4 {
    dot(sub(x, p.origin), p.dir)
}

/// `L ∨ S` in lanes: [`sphere_crossing`], which [`SphereShape::intersect`](crate::shapes::SphereShape)
/// runs for one ray.
#[inline(always)]
fn meet_sphere(p: &Packet<Sparse>, sphere: &Sphere<F64x4>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
    let range = (F64x4::new(*t_min), F64x4::new(*t_max));
    let c = sphere_crossing(&p.carrier, sphere, (p.origin, p.dir), range);
    if !F64x4::any(c.found) {
        return [None; 4];
    }
    let [a, b] = &c.points;
    let (ta, tb) = (c.t[0].to_array(), c.t[1].to_array());
    core::array::from_fn(|l| {
        c.found.0[l].then(|| {
            let (t, x) = if c.second.0[l] { (tb[l], b) } else { (ta[l], a) };
            Crossing { t, point: lane(x, l), alpha: None }
        })
    })
}

/// `L ∨ Π` in lanes, as the plane and disk shapes meet it: the flat point's point where
/// its weight is not zero to rounding, within range, and for a disk within the rim.
#[inline(always)]
fn meet_plane(
    p: &Packet<Sparse>,
    plane: &Plane<F64x4>,
    rim: Option<(E3, f64)>,
    t_min: &[f64; 4],
    t_max: &[f64; 4],
) -> Crossings {
    let flat = p.carrier & *plane;
    let inv = F64x4::splat(1.0) / flat.eoi;
    let x = [flat.e1i * inv, flat.e2i * inv, flat.e3i * inv];
    let t = t_of4(p, x).to_array();
    let (w, inv) = (flat.eoi.to_array(), inv.to_array());
    let (inside, tol) = (inside_rim(&x, rim), tolerance(1.0));
    let ok = core::array::from_fn(|l| {
        (w[l].abs() > tol) & inv[l].is_finite() & (t[l] > t_min[l]) & (t[l] < t_max[l]) & inside[l]
    });
    crossings(ok, t, &x)
}
