//! An infinite plane: met as the flat point `L ∨ Π`.

use super::{Crossing, Shape, crossing_at, mirror_normal, within};
use crate::ray::Ray;
use cga_core::euclid::E3;
use cga_core::{GeometryError, Plane};

/// An infinite plane.
#[derive(Clone, Debug)]
pub struct PlaneShape {
    /// OPNS plane, normalised.
    pub plane: Plane,
}

impl PlaneShape {
    /// The plane through `point` with normal `normal`.
    pub fn new(point: E3, normal: E3) -> Result<Self, GeometryError> {
        Ok(PlaneShape { plane: Plane::from_point_normal(point, normal)? })
    }
}

/// Where a normalised ray crosses a normalised plane (weight 1, as `Line::meet_plane`).
pub(super) fn cross_plane(ray: &Ray, plane: &Plane) -> Option<E3> {
    (ray.line & *plane).point()
}

/// The normal of a flat shape: from the line reflected in its plane.
pub(super) fn flat_normal(ray: &Ray, plane: &Plane) -> E3 {
    mirror_normal(ray, Some(*plane), plane.normal_offset().map_or([0.0, 0.0, 1.0], |(n, _)| n))
}

impl Shape for PlaneShape {
    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        cross_plane(ray, &self.plane).filter(within(ray, t_min, t_max)).map(|x| crossing_at(ray, x))
    }

    fn normal(&self, ray: &Ray, _: &Crossing) -> E3 {
        flat_normal(ray, &self.plane)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        None
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}
