//! The objects a scene holds and how a ray meets them. Every intersection is a CGA meet
//! with the ray's line; of its points the nearest with `t_min < t < t_max` counts (hits
//! behind the origin are dropped one by one, never the whole object). Finding a crossing
//! and shading it are separate: shadow rays only need the crossing, so the normal — from
//! the reflected line `N = L' − L` for primitives, from eq. 6–11 for evolved surfaces —
//! is computed only for the hit that is shaded.

use crate::ray::Ray;
#[cfg(feature = "evolved")]
use crate::surface::EvolvedSurface;
use cga_core::euclid::{E3, cross, dot, norm, scale, sub, unit};
use cga_core::{Disk, Hit as MeetHit, Plane, RoundMeet, Sphere};

/// Where a ray crosses an object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Ray parameter.
    pub t: f64,
    /// The point.
    pub point: E3,
    /// For an evolved surface, the α of the circle hit.
    pub alpha: Option<f64>,
}

/// A crossing with its normal, ready to shade.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter.
    pub t: f64,
    /// The point.
    pub point: E3,
    /// Unit normal, facing the side the ray came from (surfaces are two-sided).
    pub normal: E3,
    /// For an evolved surface, the α of the circle hit.
    pub alpha: Option<f64>,
}

/// A scene object's geometry.
#[derive(Clone, Debug)]
pub enum Shape {
    /// A sphere (with its centre and radius, for bounds).
    Sphere {
        /// OPNS sphere.
        sphere: Sphere,
        /// Centre.
        centre: E3,
        /// Radius.
        radius: f64,
    },
    /// An infinite plane.
    Plane(Plane),
    /// A disk: a circle and its plane.
    Disk(Disk),
    /// A triangle: its plane and corners.
    Triangle {
        /// The plane through the corners.
        plane: Plane,
        /// Corners, counter-clockwise seen from the normal.
        corners: [E3; 3],
    },
    /// A surface swept between two circles.
    #[cfg(feature = "evolved")]
    Evolved(Box<EvolvedSurface>),
}

impl Shape {
    /// The nearest crossing with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let within = |x: &E3| {
            let t = ray.t_of(*x);
            t > t_min && t < t_max
        };
        // Rays and objects are normalised (unit direction; spheres and planes built so), so the
        // meets are classified with weight 1, as `Line::meet_sphere` and `meet_plane` would
        // after computing the two norms.
        let flat = |plane: &Plane| (ray.line & *plane).point();
        let point = match self {
            Shape::Sphere { sphere, .. } => {
                let meet = RoundMeet::new(ray.line & *sphere, 1.0);
                if meet.hit == MeetHit::Miss {
                    return None;
                }
                meet.points_along(ray.dir)?.into_iter().find(within)?
            }
            Shape::Plane(plane) => flat(plane).filter(within)?,
            Shape::Disk(disk) => {
                flat(&disk.plane).filter(|x| within(x) && norm(sub(*x, disk.centre)) <= disk.radius)?
            }
            Shape::Triangle { plane, corners } => flat(plane).filter(|x| within(x) && inside_triangle(*x, corners))?,
            #[cfg(feature = "evolved")]
            Shape::Evolved(surface) => return surface.intersect(ray, t_min, t_max),
        };
        Some(Crossing { t: ray.t_of(point), point, alpha: None })
    }

    /// The unit normal at a crossing of `ray`, facing the ray. For primitives the direction
    /// of `L' − L`, the reflected minus the incident line (a sphere reflects in its tangent
    /// plane there), or of the geometric normal where that vanishes (a grazing ray, `L' = L`).
    pub fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let x = crossing.point;
        let (mirror, fallback) = match self {
            Shape::Sphere { centre, .. } => (Plane::from_point_normal(x, sub(x, *centre)).ok(), sub(x, *centre)),
            Shape::Plane(plane) | Shape::Disk(Disk { plane, .. }) | Shape::Triangle { plane, .. } => {
                (Some(*plane), plane.normal_offset().map_or([0.0, 0.0, 1.0], |(n, _)| n))
            }
            #[cfg(feature = "evolved")]
            Shape::Evolved(surface) => return facing(surface.normal(crossing), ray.dir),
        };
        // Only the direction of L' − L is needed: no normalisation.
        let from_lines = mirror.and_then(|m| (ray.line.reflect_in_plane(&m) - ray.line).direction().ok());
        facing(from_lines.or_else(|| unit(fallback)).unwrap_or([0.0, 0.0, 1.0]), ray.dir)
    }

    /// The nearest crossing and its normal.
    pub fn hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let c = self.intersect(ray, t_min, t_max)?;
        Some(Hit { t: c.t, point: c.point, normal: self.normal(ray, &c), alpha: c.alpha })
    }

    /// A sphere `(centre, radius)` holding the shape, `None` when unbounded (a plane).
    pub fn bounds(&self) -> Option<(E3, f64)> {
        match self {
            Shape::Sphere { centre, radius, .. } => Some((*centre, *radius)),
            Shape::Plane(_) => None,
            Shape::Disk(disk) => Some((disk.centre, disk.radius)),
            Shape::Triangle { corners, .. } => {
                let c = scale([0, 1, 2].map(|k| corners[0][k] + corners[1][k] + corners[2][k]), 1.0 / 3.0);
                Some((c, corners.iter().map(|&x| norm(sub(x, c))).fold(0.0, f64::max)))
            }
            #[cfg(feature = "evolved")]
            Shape::Evolved(surface) => Some(surface.bounds()),
        }
    }
}

/// `n` turned to face against `dir`.
pub(crate) fn facing(n: E3, dir: E3) -> E3 {
    if dot(n, dir) > 0.0 { n.map(|x| -x) } else { n }
}

/// Whether `x` (on the triangle's plane) lies inside it: the same side of all three edges.
pub(crate) fn inside_triangle(x: E3, [a, b, c]: &[E3; 3]) -> bool {
    let n = cross(sub(*b, *a), sub(*c, *a));
    let side = |p: E3, q: E3| dot(cross(sub(q, p), sub(x, p)), n);
    let (s1, s2, s3) = (side(*a, *b), side(*b, *c), side(*c, *a));
    (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0)
}
