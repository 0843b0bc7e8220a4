//! A disk: its plane met as a flat point, kept if within the rim.

use super::Unit;
use super::plane::{cross_plane, flat_normal};
use super::{Crossing, Shape, crossing_at, flat_error, point_in_range};
use crate::light::orthonormal;
use crate::ray::Ray;
use cga_core::euclid::{E3, dot, sub};
use cga_core::{Disk, GeometryError};

/// A disk: a circle, its plane, its exact centre and radius.
#[derive(Clone, Debug)]
pub struct DiskShape {
    /// The disk.
    pub disk: Disk,
    /// Its plane's unit normal.
    pub normal: E3,
}

impl DiskShape {
    /// The disk of `centre`, `normal` and `radius`.
    pub fn new(centre: E3, normal: E3, radius: f64) -> Result<Self, GeometryError> {
        let disk = Disk::from_centre_normal_radius(centre, normal, radius)?;
        Ok(DiskShape { normal: super::plane_normal(&disk.plane), disk })
    }
}

impl Shape for DiskShape {
    /// The angle about its centre as a fraction of a turn (from the first axis
    /// [`orthonormal`] to its normal), and the distance from the centre over the radius.
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let (a, b) = orthonormal(self.normal);
        let d = sub(c.point, self.disk.centre);
        let u = 0.5 + dot(d, b).atan2(dot(d, a)) / std::f64::consts::TAU;
        Some(([u, dot(d, d).sqrt() / self.disk.radius], Unit::Fraction))
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let d = &self.disk;
        let x = cross_plane(ray, &d.plane)?;
        // Squared distances: no square root per ray.
        let v = sub(x, d.centre);
        (point_in_range(ray, t_min, t_max)(&x) && dot(v, v) <= d.radius * d.radius).then(|| crossing_at(ray, x))
    }

    fn normal(&self, ray: &Ray, _: &Crossing) -> E3 {
        flat_normal(ray, self.normal)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some((self.disk.centre, self.disk.radius))
    }

    /// The rounding of its plane's offset from the centre, `64 ε Σ |n_k c_k|`.
    fn crossing_error(&self) -> f64 {
        flat_error(self.normal, self.disk.centre)
    }

    /// A plane's meet and a rim test cost more than a bounding-sphere test.
    fn cull(&self) -> bool {
        true
    }

    fn flat(&self) -> bool {
        true
    }
}
