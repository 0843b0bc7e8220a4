//! The plain back end's packets: spheres, planes and disks met by the textbook formulas of
//! [`Plain`] in lanes — the same operations in the same order as glam's, so the same bits;
//! other shapes one lane at a time.

use super::{Crossings, Packet, Packets, crossings, inside_rim, lane};
use crate::backend::{Backend, Plain, PlainShape};
use crate::camera::Camera;
use crate::lanes::lanes3;
use crate::ray::in_range;
use crate::shapes::Crossing;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use cga_core::simd::F64x4;
use glam::DVec3;

impl Packets for Plain {
    type CarrierLanes = ();

    #[inline(always)]
    fn packet(origin: [F64x4; 3], dir: [F64x4; 3]) -> Packet<Plain> {
        let rays = core::array::from_fn(|l| Plain::ray(lane(&origin, l), lane(&dir, l)));
        Packet { rays, origin, dir, carrier: () }
    }

    /// `unit(x a + y b + z c)` from the camera's position, `(x, y, z)` the image-plane point
    /// and `(a, b, c)` the camera's axes, as [`Plain::camera_ray`] computes it.
    #[inline(always)]
    fn camera_packet(camera: &Camera, u: [f64; 4], v: [f64; 4]) -> Option<Packet<Plain>> {
        let points: [F64x4; 3] = lanes3::<F64x4, 4>(core::array::from_fn(|k| camera.image_point(u[k], v[k])));
        let [a, b, c] = camera.axes();
        let d: [F64x4; 3] = core::array::from_fn(|k| {
            let axis = |e: E3| F64x4::splat(e[k]);
            points[0] * axis(a) + points[1] * axis(b) + points[2] * axis(c)
        });
        let inv = F64x4::splat(1.0) / norm(d);
        if !inv.to_array().iter().all(|i| i.is_finite() && *i > 0.0) {
            return None;
        }
        let dir = scale(d, inv);
        let origin = camera.position().map(F64x4::splat);
        Some(Self::packet(origin, dir))
    }

    #[inline(always)]
    fn cross4(shape: &PlainShape, p: &Packet<Plain>, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
        match shape {
            PlainShape::Sphere { centre, radius } => sphere4(p, *centre, *radius, t_min, t_max),
            PlainShape::Plane { normal, offset } => plane4(p, *normal, *offset, None, t_min, t_max),
            PlainShape::Disk { normal, offset, centre, radius } => {
                plane4(p, *normal, *offset, Some((*centre, *radius)), t_min, t_max)
            }
            _ => core::array::from_fn(|l| Plain::intersect(shape, &p.rays[l], t_min[l], t_max[l])),
        }
    }
}

/// `v` in lanes.
#[inline(always)]
fn splat3(v: DVec3) -> [F64x4; 3] {
    v.to_array().map(F64x4::splat)
}

/// The nearer root within range of `|o + t d − c|² = r²`: `t = −b ∓ √(b² − (|o − c|² − r²))`,
/// `b = (o − c)·d`.
#[inline(always)]
fn sphere4(p: &Packet<Plain>, centre: DVec3, radius: f64, t_min: &[f64; 4], t_max: &[f64; 4]) -> Crossings {
    let c = splat3(centre);
    let oc = sub(p.origin, c);
    let b = dot(oc, p.dir);
    let disc = b * b - (dot(oc, oc) - F64x4::splat(radius * radius));
    let d = disc.to_array();
    if d.iter().all(|&x| x < 0.0) {
        return [None; 4];
    }
    let s = F64x4::new(d.map(f64::sqrt));
    let (near, far) = (-b - s, -b + s);
    let range = (F64x4::new(*t_min), F64x4::new(*t_max));
    let (near_in, far_in) = (in_range(near, range.0, range.1).0, in_range(far, range.0, range.1).0);
    let (near, far) = (near.to_array(), far.to_array());
    let ok: [bool; 4] = core::array::from_fn(|l| (d[l] >= 0.0) & (near_in[l] | far_in[l]));
    if !ok.iter().any(|&o| o) {
        return [None; 4];
    }
    core::array::from_fn(|l| {
        ok[l].then(|| {
            let t = if near_in[l] { near[l] } else { far[l] };
            let point = core::array::from_fn(|k| p.origin[k].to_array()[l] + t * p.dir[k].to_array()[l]);
            Crossing { t, point, alpha: None }
        })
    })
}

/// `t = (δ − n·o)/(n·d)` on the plane `n·x = δ`, within range, and for a disk within the rim.
#[inline(always)]
fn plane4(
    p: &Packet<Plain>,
    normal: DVec3,
    offset: f64,
    rim: Option<(DVec3, f64)>,
    t_min: &[f64; 4],
    t_max: &[f64; 4],
) -> Crossings {
    let n = splat3(normal);
    let denom = dot(n, p.dir);
    let t = (F64x4::splat(offset) - dot(n, p.origin)) / denom;
    // `o + t d` (glam's `t * d` per coordinate: the same products).
    let x = add(p.origin, scale(p.dir, t));
    let inside = inside_rim(&x, rim.map(|(c, r)| (c.to_array(), r)));
    let (denom, t) = (denom.to_array(), t.to_array());
    let ok = core::array::from_fn(|l| {
        (denom[l] != 0.0) & t[l].is_finite() & (t[l] > t_min[l]) & (t[l] < t_max[l]) & inside[l]
    });
    crossings(ok, t, &x)
}
