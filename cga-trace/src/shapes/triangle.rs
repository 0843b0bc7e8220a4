//! A triangle: its plane met as a flat point, kept if inside the three edges.

use super::plane::{cross_plane, flat_normal};
use super::{Crossing, Shape, crossing_at, flat_error, point_in_range};
use crate::ray::Ray;
use cga_core::euclid::{E3, cross, dot, norm, scale, sub};
use cga_core::{GeometryError, Plane};

/// A triangle: its plane and corners.
#[derive(Clone, Debug)]
pub struct TriangleShape {
    /// The plane through the corners.
    pub plane: Plane,
    /// Corners, counter-clockwise seen from the normal.
    pub corners: [E3; 3],
    /// Its plane's unit normal.
    pub normal: E3,
}

impl TriangleShape {
    /// The triangle with these corners.
    pub fn new(corners: [E3; 3]) -> Result<Self, GeometryError> {
        let plane = Plane::through(corners[0], corners[1], corners[2])?;
        Ok(TriangleShape { normal: super::plane_normal(&plane), plane, corners })
    }
}

impl Shape for TriangleShape {
    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let x = cross_plane(ray, &self.plane)?;
        (point_in_range(ray, t_min, t_max)(&x) && inside_triangle(x, &self.corners)).then(|| crossing_at(ray, x))
    }

    fn normal(&self, ray: &Ray, _: &Crossing) -> E3 {
        flat_normal(ray, self.normal)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        let c = scale([0, 1, 2].map(|k| self.corners.iter().map(|x| x[k]).sum()), 1.0 / 3.0);
        Some((c, self.corners.iter().map(|&x| norm(sub(x, c))).fold(0.0, f64::max)))
    }

    /// The rounding of its plane's offset from the first corner, `64 ε Σ |n_k a_k|`.
    fn crossing_error(&self) -> f64 {
        flat_error(self.normal, self.corners[0])
    }

    /// A plane's meet and three edge tests cost more than a bounding-sphere test.
    fn cull(&self) -> bool {
        true
    }

    fn flat(&self) -> bool {
        true
    }
}

/// Whether `x` (on the triangle's plane) lies inside it: the same side of all three edges.
pub(crate) fn inside_triangle(x: E3, [a, b, c]: &[E3; 3]) -> bool {
    let n = cross(sub(*b, *a), sub(*c, *a));
    let side = |p: E3, q: E3| dot(cross(sub(q, p), sub(x, p)), n);
    let (s1, s2, s3) = (side(*a, *b), side(*b, *c), side(*c, *a));
    (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0)
}
