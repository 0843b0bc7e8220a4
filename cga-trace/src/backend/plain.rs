//! Plain-vector geometry with glam: the textbook formulas a tracer without CGA uses.
//! Ray–sphere: the quadratic `|o + t d − c|² = r²`; ray–plane: `t = (δ − n·o)/(n·d)`;
//! normals: `(x − c)/r` and `n`. Packets meet spheres, planes and disks by the same formulas
//! in lanes, the same operations in the same order as glam's, so the same bits. Other shapes
//! (evolved surfaces) use their own geometry, one lane at a time.

use super::{Backend, Crossings, Packet, array, crossings, inside_rim, lanes3, mask_array};
use crate::camera::Camera;
use crate::ray::{Ray, in_range};
use crate::shapes::{
    Crossing, DiskShape, MeshShape, PlaneShape, Shape, SphereShape, TriangleShape, facing, inside_triangle,
};
use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::simd::Lane;
use core::any::Any;
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
    /// A mesh: its own hierarchy and triangle test (packets through it together).
    Mesh(Arc<MeshShape>),
    /// Any other shape (an evolved surface, a kind added later): its own sparse geometry.
    Other(Arc<dyn Shape>),
}

impl Backend for Plain {
    type Carrier = ();
    type Shape = PlainShape;
    const NAME: &'static str = "plain";
    const KIND: super::BackendKind = super::BackendKind::Plain;
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
        } else if let Ok(mesh) = (shape.clone() as Arc<dyn Any + Send + Sync>).downcast::<MeshShape>() {
            PlainShape::Mesh(mesh)
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
            PlainShape::Mesh(mesh) => return mesh.nearest(ray.origin, ray.dir, t_min, t_max),
            PlainShape::Other(shape) => return shape.intersect(&Ray::new(ray.origin, ray.dir)?, t_min, t_max),
        };
        Some(Crossing { t, point: (o + t * d).into(), alpha: None, part: 0 })
    }

    fn occludes(shape: &PlainShape, ray: &Ray<()>, t_min: f64, t_max: f64) -> bool {
        match shape {
            PlainShape::Mesh(mesh) => mesh.blocks(ray.origin, ray.dir, t_min, t_max),
            _ => Plain::intersect(shape, ray, t_min, t_max).is_some(),
        }
    }

    fn normal(shape: &PlainShape, ray: &Ray<()>, crossing: &Crossing) -> E3 {
        let n = match shape {
            PlainShape::Sphere { centre, .. } => (DVec3::from(crossing.point) - *centre).normalize_or(DVec3::Z),
            PlainShape::Plane { normal, .. }
            | PlainShape::Disk { normal, .. }
            | PlainShape::Triangle { normal, .. } => *normal,
            PlainShape::Mesh(mesh) => {
                return Ray::new(ray.origin, ray.dir).map_or([0.0, 0.0, 1.0], |r| mesh.normal(&r, crossing));
            }
            PlainShape::Other(shape) => {
                return Ray::new(ray.origin, ray.dir).map_or([0.0, 0.0, 1.0], |r| shape.normal(&r, crossing));
            }
        };
        facing(n.into(), ray.dir)
    }

    type CarrierLanes<L: Lane> = ();

    #[inline(always)]
    fn packet<L: Lane>(origin: E3<L>, dir: E3<L>) -> Packet<Plain, L> {
        Packet::per_lane(origin, dir, ())
    }

    /// `unit(x a + y b + z c)` from the camera's position, `(x, y, z)` the image-plane point
    /// and `(a, b, c)` the camera's axes, as [`Plain::camera_ray`] computes it.
    #[inline(always)]
    fn camera_packet<L: Lane>(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Packet<Plain, L>> {
        let points: E3<L> = lanes3::<L, 4>(core::array::from_fn(|k| camera.image_point(u[k], v[k])));
        let [a, b, c] = camera.axes();
        let along = |k: usize| {
            let axis = |e: E3| L::from_f64(e[k]);
            points[0] * axis(a) + points[1] * axis(b) + points[2] * axis(c)
        };
        // Written out (as lanes3): `from_fn` over lanes may stay out of line, without AVX.
        let d: E3<L> = [along(0), along(1), along(2)];
        let inv = L::one() / norm(d);
        if !array(inv).iter().all(|i| i.is_finite() && *i > 0.0) {
            return None;
        }
        let dir = scale(d, inv);
        let origin = camera.position().map(L::from_f64);
        Some(Self::packet(origin, dir))
    }

    #[inline(always)]
    fn cross4<L: Lane>(shape: &PlainShape, p: &Packet<Plain, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        match shape {
            PlainShape::Sphere { centre, radius } => sphere4(p, *centre, *radius, t_min, t_max),
            PlainShape::Plane { normal, offset } => plane4(p, *normal, *offset, None, t_min, t_max),
            PlainShape::Disk { normal, offset, centre, radius } => {
                plane4(p, *normal, *offset, Some((*centre, *radius)), t_min, t_max)
            }
            PlainShape::Mesh(mesh) => mesh.intersect4::<L>(p.origins_dirs(), t_min, t_max),
            _ => core::array::from_fn(|l| Plain::intersect(shape, &p.rays[l], t_min[l], t_max[l])),
        }
    }

    #[inline(always)]
    fn occludes4<L: Lane>(shape: &PlainShape, p: &Packet<Plain, L>, t_min: &[f64; 4], t_max: &[f64; 4]) -> [bool; 4] {
        match shape {
            PlainShape::Mesh(mesh) => mesh.occludes4::<L>(p.origins_dirs(), t_min, t_max),
            _ => Plain::cross4(shape, p, t_min, t_max).map(|c| c.is_some()),
        }
    }
}

/// `v` in lanes.
#[inline(always)]
fn splat3<L: Lane>(v: DVec3) -> E3<L> {
    v.to_array().map(L::from_f64)
}

/// The nearer root within range of `|o + t d − c|² = r²`: `t = −b ∓ √(b² − (|o − c|² − r²))`,
/// `b = (o − c)·d`.
#[inline(always)]
fn sphere4<L: Lane>(p: &Packet<Plain, L>, centre: DVec3, radius: f64, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
    let c = splat3(centre);
    let oc = sub(p.origin, c);
    let b = dot(oc, p.dir);
    let disc = b * b - (dot(oc, oc) - L::from_f64(radius * radius));
    let d = array(disc);
    if d.iter().all(|&x| x < 0.0) {
        return [None; 4];
    }
    let s = L::from_fn(|l| d[l].sqrt());
    let (near, far) = (-b - s, -b + s);
    let range = (L::from_fn(|l| t_min[l]), L::from_fn(|l| t_max[l]));
    let (near_in, far_in) =
        (mask_array::<L>(in_range(near, range.0, range.1)), mask_array::<L>(in_range(far, range.0, range.1)));
    let (near, far) = (array(near), array(far));
    let ok: [bool; 4] = core::array::from_fn(|l| (d[l] >= 0.0) & (near_in[l] | far_in[l]));
    if !ok.iter().any(|&o| o) {
        return [None; 4];
    }
    core::array::from_fn(|l| {
        ok[l].then(|| {
            let t = if near_in[l] { near[l] } else { far[l] };
            let point = core::array::from_fn(|k| p.origin[k].lane(l) + t * p.dir[k].lane(l));
            Crossing { t, point, alpha: None, part: 0 }
        })
    })
}

/// `t = (δ − n·o)/(n·d)` on the plane `n·x = δ`, within range, and for a disk within the rim.
#[inline(always)]
fn plane4<L: Lane>(
    p: &Packet<Plain, L>,
    normal: DVec3,
    offset: f64,
    rim: Option<(DVec3, f64)>,
    t_min: &[f64; 4],
    t_max: &[f64; 4],
) -> Crossings {
    let n = splat3(normal);
    let denom = dot(n, p.dir);
    let t = (L::from_f64(offset) - dot(n, p.origin)) / denom;
    // `o + t d` (glam's `t * d` per coordinate: the same products).
    let x = add(p.origin, scale(p.dir, t));
    let inside = inside_rim(&x, rim.map(|(c, r)| (c.to_array(), r)));
    let (denom, t) = (array(denom), array(t));
    let ok = core::array::from_fn(|l| {
        (denom[l] != 0.0) & t[l].is_finite() & (t[l] > t_min[l]) & (t[l] < t_max[l]) & inside[l]
    });
    crossings(ok, t, &x)
}
