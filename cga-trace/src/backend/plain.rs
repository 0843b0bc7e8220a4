//! Plain-vector geometry with glam: the textbook formulas a tracer without CGA uses.
//! Ray–sphere: the quadratic `|o + t d − c|² = r²`; ray–plane: `t = (δ − n·o)/(n·d)`;
//! normals: `(x − c)/r` and `n`. Evolved surfaces reuse cga-core.

use super::Backend;
use crate::camera::Camera;
use crate::ray::Ray;
use crate::shapes::{Crossing, Shape, facing, inside_triangle};
#[cfg(feature = "evolved")]
use crate::surface::EvolvedSurface;
use cga_core::euclid::{E3, cross, unit};
use glam::DVec3;

/// The plain-vector back end.
#[derive(Clone, Copy, Debug, Default)]
pub struct Plain;

/// A scene object as plain vectors.
#[derive(Clone, Debug)]
pub enum PlainShape {
    /// Centre and radius.
    Sphere {
        /// Centre.
        centre: DVec3,
        /// Radius.
        radius: f64,
    },
    /// `n · x = δ`.
    Plane {
        /// Unit normal.
        normal: DVec3,
        /// Offset δ.
        offset: f64,
    },
    /// A disk in the plane `n · x = δ`.
    Disk {
        /// Unit normal.
        normal: DVec3,
        /// Offset δ.
        offset: f64,
        /// Centre.
        centre: DVec3,
        /// Radius.
        radius: f64,
    },
    /// A triangle in the plane `n · x = δ`.
    Triangle {
        /// Unit normal.
        normal: DVec3,
        /// Offset δ.
        offset: f64,
        /// Corners.
        corners: [E3; 3],
    },
    /// An evolved surface (cga-core).
    #[cfg(feature = "evolved")]
    Evolved(Box<EvolvedSurface>),
}

impl Backend for Plain {
    type Carrier = ();
    type Shape = PlainShape;
    const NAME: &'static str = "plain";

    fn ray(origin: E3, dir: E3) -> Option<Ray<()>> {
        Some(Ray { origin, dir: unit(dir)?, line: () })
    }

    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray<()>> {
        let [x, y, z] = camera.image_point(u, v);
        let [a, b, c] = camera.axes().map(DVec3::from);
        Self::ray(camera.position(), (x * a + y * b + z * c).into())
    }

    fn prepare(shape: &Shape) -> PlainShape {
        let flat = |plane: &cga_core::Plane| plane.normal_offset().map_or((DVec3::Z, 0.0), |(n, d)| (n.into(), d));
        match shape {
            Shape::Sphere { centre, radius, .. } => PlainShape::Sphere { centre: (*centre).into(), radius: *radius },
            Shape::Plane(plane) => {
                let (normal, offset) = flat(plane);
                PlainShape::Plane { normal, offset }
            }
            Shape::Disk(disk) => {
                let (normal, offset) = flat(&disk.plane);
                PlainShape::Disk { normal, offset, centre: disk.centre.into(), radius: disk.radius }
            }
            Shape::Triangle { corners, .. } => {
                let [a, b, c] = corners.map(DVec3::from);
                let normal = unit(cross((b - a).into(), (c - a).into())).map_or(DVec3::Z, DVec3::from);
                PlainShape::Triangle { normal, offset: normal.dot(a), corners: *corners }
            }
            #[cfg(feature = "evolved")]
            Shape::Evolved(surface) => PlainShape::Evolved(surface.clone()),
        }
    }

    fn intersect(shape: &PlainShape, ray: &Ray<()>, t_min: f64, t_max: f64) -> Option<Crossing> {
        let (o, d) = (DVec3::from(ray.origin), DVec3::from(ray.dir));
        let within = |t: f64| t > t_min && t < t_max;
        let on_plane = |n: DVec3, offset: f64| {
            let denom = n.dot(d);
            let t = (offset - n.dot(o)) / denom;
            (denom != 0.0 && t.is_finite() && within(t)).then_some(t)
        };
        let t = match shape {
            PlainShape::Sphere { centre, radius } => {
                let oc = o - *centre;
                let b = oc.dot(d);
                let disc = b * b - (oc.length_squared() - radius * radius);
                if disc < 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                [-b - s, -b + s].into_iter().find(|&t| within(t))?
            }
            PlainShape::Plane { normal, offset } => on_plane(*normal, *offset)?,
            PlainShape::Disk { normal, offset, centre, radius } => {
                on_plane(*normal, *offset).filter(|&t| (o + t * d).distance(*centre) <= *radius)?
            }
            PlainShape::Triangle { normal, offset, corners } => {
                on_plane(*normal, *offset).filter(|&t| inside_triangle((o + t * d).into(), corners))?
            }
            #[cfg(feature = "evolved")]
            PlainShape::Evolved(surface) => return surface.intersect(ray, t_min, t_max),
        };
        Some(Crossing { t, point: (o + t * d).into(), alpha: None })
    }

    fn normal(shape: &PlainShape, ray: &Ray<()>, crossing: &Crossing) -> E3 {
        let n = match shape {
            PlainShape::Sphere { centre, .. } => (DVec3::from(crossing.point) - *centre).normalize_or(DVec3::Z),
            PlainShape::Plane { normal, .. }
            | PlainShape::Disk { normal, .. }
            | PlainShape::Triangle { normal, .. } => *normal,
            #[cfg(feature = "evolved")]
            PlainShape::Evolved(surface) => return facing(surface.normal(crossing), ray.dir),
        };
        facing(n.into(), ray.dir)
    }
}
