//! A sphere: met as the point pair `L ∨ S`, classified by its square.

use super::{Crossing, Shape, crossing_at, facing, largest, point_in_range, rounding};
use crate::ray::Ray;
use cga_core::euclid::{E3, scale, sub, unit};
use cga_core::{GeometryError, Hit, RoundMeet, Sphere};

/// A sphere, with its centre and radius (for bounds and normals).
#[derive(Clone, Debug)]
pub struct SphereShape {
    /// OPNS sphere, normalised.
    pub sphere: Sphere,
    /// Centre.
    pub centre: E3,
    /// Radius.
    pub radius: f64,
}

impl SphereShape {
    /// The sphere of `centre` and `radius`.
    pub fn new(centre: E3, radius: f64) -> Result<Self, GeometryError> {
        Ok(SphereShape { sphere: Sphere::from_centre_radius(centre, radius)?, centre, radius })
    }
}

impl Shape for SphereShape {
    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        // Rays and spheres are normalised, so the meet is classified with weight 1, as
        // `Line::meet_sphere` would after computing the two norms.
        let meet = RoundMeet::new(ray.line & self.sphere, 1.0);
        if meet.hit == Hit::Miss {
            return None;
        }
        let point = meet.points_along(ray.dir).ok()?.into_iter().find(point_in_range(ray, t_min, t_max))?;
        Some(crossing_at(ray, point))
    }

    /// From the line reflected in the tangent plane at the crossing.
    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        // The tangent plane's normal (see `plane_normal`): `(x − c)/r`.
        let n = scale(sub(crossing.point, self.centre), 1.0 / self.radius);
        facing(unit(n).unwrap_or([0.0, 0.0, 1.0]), ray.dir)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some((self.centre, self.radius))
    }

    /// `64 ε r (1 + ρ)²`, `ρ = |c|/r`: the meet's points carry the null basis's `ε ρ²` of
    /// the radius (`RoundMeet::new`; measured at 3 ε (1 + ρ)² in `tests/tests/precision.rs`).
    fn crossing_error(&self) -> f64 {
        let one_plus_rho = 1.0 + largest(self.centre) / self.radius;
        rounding(self.radius * one_plus_rho * one_plus_rho)
    }
}
