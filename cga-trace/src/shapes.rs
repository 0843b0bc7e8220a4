//! The objects a scene holds and how a ray meets them. Every intersection is a CGA meet
//! with the ray's line; of its points the nearest with `t_min < t < t_max` counts (hits
//! behind the origin are dropped one by one, never the whole object). Primitives get their
//! normal from the reflected line, `N = L' − L`; evolved surfaces from eq. 6–11.

use crate::ray::Ray;
use crate::surface::EvolvedSurface;
use cga_core::euclid::{E3, cross, dot, norm, scale, sub, unit};
use cga_core::{Disk, Hit as MeetHit, Line, Plane, Sphere};

/// Where a ray meets an object.
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
    Evolved(Box<EvolvedSurface>),
}

impl Shape {
    /// The nearest hit with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let within = |t: f64| t > t_min && t < t_max;
        match self {
            Shape::Sphere { sphere, centre, .. } => {
                let meet = ray.line.meet_sphere(sphere);
                if meet.hit == MeetHit::Miss {
                    return None;
                }
                let point = meet.points(&ray.line)?.into_iter().find(|&x| within(ray.t_of(x)))?;
                let fallback = sub(point, *centre);
                let reflected = ray.line.reflect_in_sphere(sphere, point).ok();
                Some(primitive_hit(ray, point, reflected, fallback))
            }
            Shape::Plane(plane) => {
                let point = ray.line.meet_plane(plane).filter(|&x| within(ray.t_of(x)))?;
                Some(primitive_hit(ray, point, Some(ray.line.reflect_in_plane(plane)), plane_normal(plane)))
            }
            Shape::Disk(disk) => {
                let point = ray.line.meet_disk(disk).filter(|&x| within(ray.t_of(x)))?;
                let plane = &disk.plane;
                Some(primitive_hit(ray, point, Some(ray.line.reflect_in_plane(plane)), plane_normal(plane)))
            }
            Shape::Triangle { plane, corners } => {
                let point = ray.line.meet_plane(plane).filter(|&x| within(ray.t_of(x)))?;
                inside_triangle(point, corners).then_some(())?;
                Some(primitive_hit(ray, point, Some(ray.line.reflect_in_plane(plane)), plane_normal(plane)))
            }
            Shape::Evolved(surface) => surface.intersect(ray, t_min, t_max),
        }
    }

    /// A sphere `(centre, radius)` holding the shape, `None` when unbounded (a plane).
    pub fn bounds(&self) -> Option<(E3, f64)> {
        match self {
            Shape::Sphere { centre, radius, .. } => Some((*centre, *radius)),
            Shape::Plane(_) => None,
            Shape::Disk(disk) => disk.circle.centre_normal_radius().ok().map(|(c, _, r)| (c, r)),
            Shape::Triangle { corners, .. } => {
                let c = scale([0, 1, 2].map(|k| corners[0][k] + corners[1][k] + corners[2][k]), 1.0 / 3.0);
                Some((c, corners.iter().map(|&x| norm(sub(x, c))).fold(0.0, f64::max)))
            }
            Shape::Evolved(surface) => Some(surface.bounds()),
        }
    }
}

fn plane_normal(plane: &Plane) -> E3 {
    plane.normal_offset().map(|(n, _)| n).unwrap_or([0.0, 0.0, 1.0])
}

/// The hit at `point`, its normal the direction of `L' − L` (the reflected minus the incident
/// line), or of `fallback` where that vanishes (a grazing ray, `L' = L`); either way turned
/// to face the incoming ray.
fn primitive_hit(ray: &Ray, point: E3, reflected: Option<Line>, fallback: E3) -> Hit {
    let from_lines = reflected.and_then(|r| (r - ray.line).try_normalise()).and_then(|n| n.direction().ok());
    let n = from_lines.or_else(|| unit(fallback)).unwrap_or([0.0, 0.0, 1.0]);
    let normal = if dot(n, ray.dir) > 0.0 { n.map(|x| -x) } else { n };
    Hit { t: ray.t_of(point), point, normal, alpha: None }
}

/// Whether `x` (on the triangle's plane) lies inside it: the same side of all three edges.
fn inside_triangle(x: E3, [a, b, c]: &[E3; 3]) -> bool {
    let n = cross(sub(*b, *a), sub(*c, *a));
    let side = |p: E3, q: E3| dot(cross(sub(q, p), sub(x, p)), n);
    let (s1, s2, s3) = (side(*a, *b), side(*b, *c), side(*c, *a));
    (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0)
}
