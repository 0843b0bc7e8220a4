//! Plain-vector geometry with glam: the textbook formulas a tracer without CGA uses.
//! Ray–sphere: the quadratic `|o + t d − c|² = r²`; ray–plane: `t = (δ − n·o)/(n·d)`;
//! normals: `(x − c)/r` and `n`. Other shapes (evolved surfaces) use their own geometry.

use super::Backend;
use crate::camera::Camera;
use crate::ray::{Ray, in_range};
use crate::render::{RayCounts, Renderer};
use crate::shapes::{Crossing, DiskShape, PlaneShape, Shape, SphereShape, TriangleShape, facing, inside_triangle};
use cga_core::euclid::{E3, cross, unit};
use glam::DVec3;
use std::sync::Arc;

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
    /// Any other shape (an evolved surface, a kind added later): its own sparse geometry.
    Other(Arc<dyn Shape>),
}

impl Backend for Plain {
    type Carrier = ();
    type Shape = PlainShape;
    const NAME: &'static str = "plain";
    const PACKETS: bool = true;

    fn ray(origin: E3, dir: E3) -> Ray<()> {
        Ray { origin, dir, carrier: () }
    }

    fn camera_ray(camera: &Camera, u: f64, v: f64) -> Option<Ray<()>> {
        let [x, y, z] = camera.image_point(u, v);
        let [a, b, c] = camera.axes().map(DVec3::from);
        Some(Self::ray(camera.position(), unit((x * a + y * b + z * c).into())?))
    }

    fn prepare(shape: &Arc<dyn Shape>) -> PlainShape {
        let flat = |plane: &cga_core::Plane| plane.normal_offset().map_or((DVec3::Z, 0.0), |(n, d)| (n.into(), d));
        if let Some(s) = shape.downcast_ref::<SphereShape>() {
            PlainShape::Sphere { centre: s.centre.into(), radius: s.radius }
        } else if let Some(p) = shape.downcast_ref::<PlaneShape>() {
            let (normal, offset) = flat(&p.plane);
            PlainShape::Plane { normal, offset }
        } else if let Some(DiskShape { disk, .. }) = shape.downcast_ref::<DiskShape>() {
            let (normal, offset) = flat(&disk.plane);
            PlainShape::Disk { normal, offset, centre: disk.centre.into(), radius: disk.radius }
        } else if let Some(t) = shape.downcast_ref::<TriangleShape>() {
            let [a, b, c] = t.corners.map(DVec3::from);
            let normal = unit(cross((b - a).into(), (c - a).into())).map_or(DVec3::Z, DVec3::from);
            PlainShape::Triangle { normal, offset: normal.dot(a), corners: t.corners }
        } else {
            PlainShape::Other(shape.clone())
        }
    }

    #[inline]
    fn intersect(shape: &PlainShape, ray: &Ray<()>, t_min: f64, t_max: f64) -> Option<Crossing> {
        let (o, d) = (DVec3::from(ray.origin), DVec3::from(ray.dir));
        let on_plane = |n: DVec3, offset: f64| {
            let denom = n.dot(d);
            let t = (offset - n.dot(o)) / denom;
            (denom != 0.0 && t.is_finite() && in_range(t, t_min, t_max)).then_some(t)
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
                [-b - s, -b + s].into_iter().find(|&t| in_range(t, t_min, t_max))?
            }
            PlainShape::Plane { normal, offset } => on_plane(*normal, *offset)?,
            PlainShape::Disk { normal, offset, centre, radius } => {
                on_plane(*normal, *offset).filter(|&t| (o + t * d).distance_squared(*centre) <= radius * radius)?
            }
            PlainShape::Triangle { normal, offset, corners } => {
                on_plane(*normal, *offset).filter(|&t| inside_triangle((o + t * d).into(), corners))?
            }
            PlainShape::Other(shape) => return shape.intersect(&Ray::new(ray.origin, ray.dir)?, t_min, t_max),
        };
        Some(Crossing { t, point: (o + t * d).into(), alpha: None })
    }

    fn pixels4(renderer: &Renderer<'_, Plain>, i0: u32, j: u32, cast: &mut RayCounts) -> Option<[[f64; 3]; 4]> {
        renderer.pixels4(i0, j, cast)
    }

    fn normal(shape: &PlainShape, ray: &Ray<()>, crossing: &Crossing) -> E3 {
        let n = match shape {
            PlainShape::Sphere { centre, .. } => (DVec3::from(crossing.point) - *centre).normalize_or(DVec3::Z),
            PlainShape::Plane { normal, .. }
            | PlainShape::Disk { normal, .. }
            | PlainShape::Triangle { normal, .. } => *normal,
            PlainShape::Other(shape) => {
                return Ray::new(ray.origin, ray.dir).map_or([0.0, 0.0, 1.0], |r| shape.normal(&r, crossing));
            }
        };
        facing(n.into(), ray.dir)
    }
}
