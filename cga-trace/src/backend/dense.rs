//! The dense back end: the sparse back end's algorithm with every product computed on the
//! dense 32-coefficient multivector (table-driven, all 1024 blade pairs per product). Objects
//! are made from Euclidean data the same way (`up(x)` has no products); coefficients are read
//! back through the typed views, which only copy.

use super::{Backend, Packet};
use crate::camera::Camera;
use crate::ray::Ray;
use crate::shapes::{
    Crossing, DiskShape, PlaneShape, Shape, SphereShape, TriangleShape, facing, inside_triangle, point_in_range,
};
use cga_core::euclid::{E3, add, cross, dot, magnitude, norm, perpendicular, scale, sub, tolerance, unit};
use cga_core::simd::Lane;
use cga_core::{FlatPoint, LeftContraction, Line, Multivector, Scalar, Vector, down, ei, up};
use std::sync::Arc;

/// The dense back end.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dense;

/// A scene object as dense multivectors.
#[derive(Clone, Debug)]
pub enum DenseShape {
    /// An OPNS sphere, with its centre for the tangent plane.
    Sphere {
        /// The sphere.
        sphere: Multivector,
        /// Its centre.
        centre: E3,
    },
    /// An OPNS plane.
    Plane(Multivector),
    /// A disk: its plane, centre and radius.
    Disk {
        /// The plane.
        plane: Multivector,
        /// The rim's centre.
        centre: E3,
        /// The rim's radius.
        radius: f64,
    },
    /// A triangle: its plane and corners.
    Triangle {
        /// The plane.
        plane: Multivector,
        /// The corners.
        corners: [E3; 3],
    },
    /// Any other shape (an evolved surface, a kind added later): its own sparse geometry.
    Other(Arc<dyn Shape>),
}

fn dense_up(x: E3) -> Multivector {
    Multivector::from(up(x))
}

fn dense_ei() -> Multivector {
    Multivector::from(ei::<f64>())
}

/// `X / √|X X̃|`.
fn normalise(x: Multivector) -> Option<Multivector> {
    let s = Scalar::from_dense(&(x * x.reverse())).s;
    let inv = 1.0 / s.abs().sqrt();
    inv.is_finite().then(|| x.scale(inv))
}

/// `up(a) ∧ up(b) ∧ ei`, normalised.
fn line_through(a: E3, b: E3) -> Option<Multivector> {
    normalise((dense_up(a) ^ dense_up(b)) ^ dense_ei())
}

/// The plane through `p` with normal `n`, built as `Plane::from_point_normal` builds it.
fn plane_at(p: E3, n: E3) -> Option<Multivector> {
    let n = unit(n)?;
    let (u, s) = (perpendicular(n), magnitude(&[p]));
    let (b, c) = (add(p, scale(u, s)), add(p, scale(cross(n, u), s)));
    normalise(((dense_up(p) ^ dense_up(b)) ^ dense_up(c)) ^ dense_ei())
}

/// `|⟨X X̃⟩₀|`.
fn weight(x: &Multivector) -> f64 {
    Scalar::from_dense(&(*x * x.reverse())).s.abs()
}

/// Where the line meets a plane: the flat point `L ∨ P`, read as `Line::meet_plane` reads it.
fn meet_plane(line: &Multivector, plane: &Multivector) -> Option<E3> {
    FlatPoint::from_dense(&(*line & *plane)).point_with_weight((weight(line) * weight(plane)).sqrt())
}

/// The points where the line meets a sphere, in order along `dir`: `P = L ∨ S`, classified by
/// `P²`, read back as `(P ∓ √P²)(ei ⌋ P)` (as `RoundMeet` does, densely).
fn meet_sphere(line: &Multivector, sphere: &Multivector, dir: E3) -> Option<[E3; 2]> {
    let pair = *line & *sphere;
    let square = Scalar::from_dense(&(pair * pair)).s;
    let d = dense_ei().lc(pair);
    // Classified as `RoundMeet::new` classifies: |P²| against the operands' norms.
    let [a, b] = if square.abs() <= tolerance(weight(line) * weight(sphere)) {
        let p = down(Vector::from_dense(&(pair * d).grade(1))).ok()?;
        [p, p]
    } else if square > 0.0 {
        let (s, pd) = (square.sqrt(), (pair * d).grade(1));
        [down(Vector::from_dense(&(pd - d.scale(s)))).ok()?, down(Vector::from_dense(&(pd + d.scale(s)))).ok()?]
    } else {
        return None;
    };
    Some(if dot(sub(b, a), dir) < 0.0 { [b, a] } else { [a, b] })
}

impl Backend for Dense {
    type Carrier = Multivector;
    type Shape = DenseShape;
    const NAME: &'static str = "dense";
    const KIND: super::BackendKind = super::BackendKind::Dense;
    /// In the orthonormal basis a point's `eo` and `½|x|² ei` share the `e4`, `e5`
    /// coefficients (`½(|x|² ∓ 1)`), so objects of frame size `s` keep only `ε s²` (large)
    /// or `ε / s²` (small) of their geometry: 2²⁰ either way keeps it to about 2e-4.
    const SPAN: i32 = 20;

    /// A sphere's coefficients in the orthonormal basis are of size `max(1, |c|², r²)/r`, each
    /// rounded: its crossings lie within `64 ε` of that (more than the null basis's
    /// `64 ε r (1 + ρ)²` where the sphere and its distance are both below the unit).
    fn crossing_error(shape: &dyn Shape) -> f64 {
        let own = shape.crossing_error();
        match shape.downcast_ref::<SphereShape>() {
            Some(s) => {
                let c = norm(s.centre);
                own.max(tolerance((1.0f64).max(c * c).max(s.radius * s.radius) / s.radius))
            }
            None => own,
        }
    }

    fn ray(origin: E3, dir: E3) -> Ray<Multivector> {
        // Through `o` and `o + |o|∞ d`: two points as far apart as the origin is large, so
        // that the line is as well conditioned as the sparse one (`d` is unit and finite, `o`
        // finite: the points are distinct and the line exists).
        let line = line_through(origin, add(origin, scale(dir, magnitude(&[origin])))).unwrap_or_default();
        Ray { origin, dir, carrier: line }
    }

    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray<Multivector>> {
        let pose = Multivector::from(camera.pose);
        let p = pose.sandwich(&dense_up(camera.image_point(u, v)));
        let line = normalise((Multivector::from(camera.cam()) ^ p) ^ dense_ei())?;
        let dir = Line::from_dense(&line).direction().ok()?;
        Some(Ray { origin: camera.position(), dir, carrier: line })
    }

    fn prepare(shape: &Arc<dyn Shape>) -> DenseShape {
        if let Some(s) = shape.downcast_ref::<SphereShape>() {
            DenseShape::Sphere { sphere: s.sphere.into(), centre: s.centre }
        } else if let Some(p) = shape.downcast_ref::<PlaneShape>() {
            DenseShape::Plane(p.plane.into())
        } else if let Some(DiskShape { disk, .. }) = shape.downcast_ref::<DiskShape>() {
            DenseShape::Disk { plane: disk.plane.into(), centre: disk.centre, radius: disk.radius }
        } else if let Some(t) = shape.downcast_ref::<TriangleShape>() {
            DenseShape::Triangle { plane: t.plane.into(), corners: t.corners }
        } else {
            DenseShape::Other(shape.clone())
        }
    }

    fn intersect(shape: &DenseShape, ray: &Ray<Multivector>, t_min: f64, t_max: f64) -> Option<Crossing> {
        let in_range = point_in_range(ray, t_min, t_max);
        let point = match shape {
            DenseShape::Sphere { sphere, .. } => {
                meet_sphere(&ray.carrier, sphere, ray.dir)?.into_iter().find(in_range)?
            }
            DenseShape::Plane(plane) => meet_plane(&ray.carrier, plane).filter(in_range)?,
            DenseShape::Disk { plane, centre, radius } => {
                meet_plane(&ray.carrier, plane).filter(|x| in_range(x) && norm(sub(*x, *centre)) <= *radius)?
            }
            DenseShape::Triangle { plane, corners } => {
                meet_plane(&ray.carrier, plane).filter(|x| in_range(x) && inside_triangle(*x, corners))?
            }
            DenseShape::Other(shape) => return shape.intersect(&Ray::new(ray.origin, ray.dir)?, t_min, t_max),
        };
        Some(Crossing { t: ray.t_of(point), point, alpha: None, part: 0 })
    }

    fn normal(shape: &DenseShape, ray: &Ray<Multivector>, crossing: &Crossing) -> E3 {
        let x = crossing.point;
        let (mirror, fallback) = match shape {
            DenseShape::Sphere { centre, .. } => (plane_at(x, sub(x, *centre)), sub(x, *centre)),
            DenseShape::Plane(plane) | DenseShape::Disk { plane, .. } | DenseShape::Triangle { plane, .. } => {
                // The plane's normal from its dual, −λ(n + δ ei), as `Plane::normal_offset`.
                let dual = Vector::from_dense(&plane.dual());
                (Some(*plane), [-dual.e1, -dual.e2, -dual.e3])
            }
            DenseShape::Other(shape) => {
                return Ray::new(ray.origin, ray.dir).map_or([0.0, 0.0, 1.0], |r| shape.normal(&r, crossing));
            }
        };
        // L' − L, the reflected minus the incident line, is the normal line.
        let from_lines = mirror
            .and_then(|m| normalise((m * ray.carrier) * m - ray.carrier))
            .and_then(|n| Line::from_dense(&n).direction().ok());
        facing(from_lines.or_else(|| unit(fallback)).unwrap_or([0.0, 0.0, 1.0]), ray.dir)
    }

    type CarrierLanes<L: Lane> = ();

    #[inline(always)]
    fn packet<L: Lane>(origin: E3<L>, dir: E3<L>) -> Packet<Dense, L> {
        Packet::per_lane(origin, dir, ())
    }
}
