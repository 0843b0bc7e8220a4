//! A triangle: its plane met as a flat point, kept if inside the three edges.

use super::plane::{cross_plane, flat_normal};
use super::{Crossing, Shape, crossing_at, flat_error, point_in_range};
use crate::ray::Ray;
use cga_core::euclid::{E3, cross, dot, norm, scale, sub, unit};
use cga_core::{GeometryError, Plane};

/// A triangle: its plane and corners, and what a mesh gives at its corners.
#[derive(Clone, Debug)]
pub struct TriangleShape {
    /// The plane through the corners.
    pub plane: Plane,
    /// Corners, counter-clockwise seen from the normal.
    pub corners: [E3; 3],
    /// Its plane's unit normal.
    pub normal: E3,
    /// A mesh's normals and texture coordinates at the corners, where it gives them.
    pub shading: Option<Box<Shading>>,
}

/// What a mesh gives at a triangle's corners: unit normals, interpolated for smooth
/// shading (Phong), and texture coordinates, interpolated for textures.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shading {
    /// Unit normals at the corners.
    pub normals: Option<[E3; 3]>,
    /// Texture coordinates `(u, v)` at the corners.
    pub uvs: Option<[[f64; 2]; 3]>,
}

impl TriangleShape {
    /// The triangle with these corners.
    pub fn new(corners: [E3; 3]) -> Result<Self, GeometryError> {
        let plane = Plane::through(corners[0], corners[1], corners[2])?;
        Ok(TriangleShape { normal: super::plane_normal(&plane), plane, corners, shading: None })
    }

    /// The triangle with a mesh's corner normals and texture coordinates (none given,
    /// none kept; zero normals refused).
    pub fn with_shading(self, shading: Shading) -> Result<Self, GeometryError> {
        let normals = match shading.normals {
            Some([a, b, c]) => match (unit(a), unit(b), unit(c)) {
                (Some(a), Some(b), Some(c)) => Some([a, b, c]),
                _ => return Err(GeometryError::ZeroVector),
            },
            None => None,
        };
        let shading = Shading { normals, ..shading };
        let kept = (shading != Shading::default()).then(|| Box::new(shading));
        Ok(TriangleShape { shading: kept, ..self })
    }

    /// Barycentric coordinates `(u, v)` of `x` in its plane: `x = (1 − u − v) a + u b + v c`.
    fn barycentric(&self, x: E3) -> [f64; 2] {
        let [a, b, cc] = self.corners;
        let (e1, e2, d) = (sub(b, a), sub(cc, a), sub(x, a));
        let (d11, d12, d22) = (dot(e1, e1), dot(e1, e2), dot(e2, e2));
        let (p, q) = (dot(d, e1), dot(d, e2));
        let det = d11 * d22 - d12 * d12;
        [(d22 * p - d12 * q) / det, (d11 * q - d12 * p) / det]
    }
}

/// `(1 − u − v) a + u b + v c` for corner values of `N` numbers.
fn blend<const N: usize>([u, v]: [f64; 2], [a, b, c]: [[f64; N]; 3]) -> [f64; N] {
    std::array::from_fn(|k| (1.0 - u - v) * a[k] + u * b[k] + v * c[k])
}

impl Shape for TriangleShape {
    /// A mesh's texture coordinates, interpolated; else the barycentric coordinates `(u, v)`
    /// of the hit, `(1 − u − v) a + u b + v c` for the corners `a, b, c`.
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], super::Unit)> {
        let b = self.barycentric(c.point);
        let uv = self.shading.as_ref().and_then(|s| s.uvs).map_or(b, |uvs| blend(b, uvs));
        Some((uv, super::Unit::Fraction))
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let x = cross_plane(ray, &self.plane)?;
        (point_in_range(ray, t_min, t_max)(&x) && inside_triangle(x, &self.corners)).then(|| crossing_at(ray, x))
    }

    /// The plane's normal facing the ray; with a mesh's corner normals, their blend at the
    /// hit (Phong), turned to the side the plane's normal faces.
    fn normal(&self, ray: &Ray, c: &Crossing) -> E3 {
        let facing = flat_normal(ray, self.normal);
        let Some(normals) = self.shading.as_ref().and_then(|s| s.normals) else { return facing };
        match unit(blend(self.barycentric(c.point), normals)) {
            Some(n) if dot(n, facing) < 0.0 => scale(n, -1.0),
            Some(n) => n,
            None => facing,
        }
    }

    fn facet(&self, _: &Crossing) -> Option<E3> {
        self.shading.as_ref().and_then(|s| s.normals).map(|_| self.normal)
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
