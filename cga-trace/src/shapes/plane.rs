//! An infinite plane: met as the flat point `L ∨ Π`.

use super::Unit;
use super::{Crossing, Shape, crossing_at, facing, flat_error, plane_normal, point_in_range};
use crate::light::orthonormal;
use crate::ray::Ray;
use cga_core::euclid::{E3, dot, sub};
use cga_core::{GeometryError, Plane};

/// An infinite plane.
#[derive(Clone, Debug)]
pub struct PlaneShape {
    /// OPNS plane, normalised.
    pub plane: Plane,
    /// Its unit normal (the direction of every reflected line's `L' − L`).
    pub normal: E3,
    /// Its [crossing error](Shape::crossing_error): its offset's rounding.
    pub error: f64,
    /// The point it was placed through: where its texture's `(u, v)` are 0.
    pub anchor: E3,
}

impl PlaneShape {
    /// The plane through `point` with normal `normal`.
    pub fn new(point: E3, normal: E3) -> Result<Self, GeometryError> {
        let plane = Plane::from_point_normal(point, normal)?;
        let normal = plane_normal(&plane);
        Ok(PlaneShape { plane, normal, error: flat_error(normal, point), anchor: point })
    }
}

/// Where a normalised ray crosses a normalised plane (weight 1, as `Line::meet_plane`).
pub(super) fn cross_plane(ray: &Ray, plane: &Plane) -> Option<E3> {
    (ray.carrier & *plane).point()
}

/// The normal of a flat shape: from the line reflected in its plane.
pub(super) fn flat_normal(ray: &Ray, normal: E3) -> E3 {
    facing(normal, ray.dir)
}

impl Shape for PlaneShape {
    /// Lengths along the plane from its anchor, `u = (x − p)·a`, `v = (x − p)·b`, on the axes
    /// `(a, b)` [`orthonormal`] to its normal `n` (`a × b = n`: for `n = +z`, `a = +x` and
    /// `b = +y`; for a horizontal `n`, `b = +z`).
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let (a, b) = orthonormal(self.normal);
        let d = sub(c.point, self.anchor);
        Some(([dot(d, a), dot(d, b)], Unit::Length))
    }

    /// `a × b = n`: `v` runs up an image seen from the side the normal faces.
    fn v_up(&self) -> bool {
        true
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        cross_plane(ray, &self.plane).filter(point_in_range(ray, t_min, t_max)).map(|x| crossing_at(ray, x))
    }

    fn normal(&self, ray: &Ray, _: &Crossing) -> E3 {
        flat_normal(ray, self.normal)
    }

    /// The half-space behind its normal, `n · (x − p) ≤ 0` (POV-Ray's inside of a plane).
    fn closed(&self) -> bool {
        true
    }

    /// The line's part behind the plane: all of it, none, or from or up to its crossing.
    fn spans(&self, ray: &Ray) -> super::Spans {
        let (side, speed) = (dot(sub(ray.origin, self.anchor), self.normal), dot(ray.dir, self.normal));
        let cross = -side / speed;
        let span = match speed {
            s if s > 0.0 => Some((f64::NEG_INFINITY, cross)),
            s if s < 0.0 => Some((cross, f64::INFINITY)),
            _ => (side <= 0.0).then_some((f64::NEG_INFINITY, f64::INFINITY)),
        };
        span.into_iter().collect()
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        None
    }

    /// The rounding of its offset from the point it was given by, `64 ε Σ |n_k p_k|`.
    fn crossing_error(&self) -> f64 {
        self.error
    }

    fn flat(&self) -> bool {
        true
    }
}
