//! A sphere: met as the point pair `L ∨ S`, classified by its square.

use super::Unit;
use super::{Crossing, Shape, facing, largest, rounding};
use crate::ray::{Ray, in_range};
use cga_core::euclid::{E3, dot, scale, sub, tolerance, unit};
use cga_core::{GeometryError, InnerProduct, LeftContraction, Line, Select, Sphere, down_lanes, ei};

/// A sphere, with its centre and radius (for bounds and normals).
#[derive(Clone, Debug)]
pub struct SphereShape {
    /// OPNS sphere, normalised.
    pub sphere: Sphere,
    /// Centre.
    pub centre: E3,
    /// Radius.
    pub radius: f64,
    /// Its own x, y and z axes (orthonormal): a texture's longitude is measured about z from
    /// x, so that the texture turns with the sphere.
    pub axes: [E3; 3],
}

impl SphereShape {
    /// The sphere of `centre` and `radius`, its axes the frame's.
    pub fn new(centre: E3, radius: f64) -> Result<Self, GeometryError> {
        let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        Ok(SphereShape { sphere: Sphere::from_centre_radius(centre, radius)?, centre, radius, axes })
    }

    /// The sphere with its own `axes` (the frame's turned by the object's motor).
    pub fn with_axes(self, axes: [E3; 3]) -> Self {
        SphereShape { axes, ..self }
    }
}

/// Where a ray's line `L` (normalised, from `origin` along the unit `dir`) crosses a
/// normalised sphere `S` within `(t_min, t_max)`. The meet `P = L ∨ S` is classified by its
/// square as [`cga_core::RoundMeet::new`] does with weight 1 (a tangent within `64 ε`), its
/// points `P·e ∓ √(P²) e` with `e = ei ⌋ P` read by [`down_lanes`], and the first in range
/// along the ray is the one to keep ([`SphereCrossing`]). Lane by lane for a packet
/// ([`Select`]): one ray and four take the same steps, so the same bits.
#[inline(always)]
pub(crate) fn sphere_crossing<T: Select>(
    line: &Line<T>,
    sphere: &Sphere<T>,
    (origin, dir): (E3<T>, E3<T>),
    (t_min, t_max): (T, T),
) -> SphereCrossing<T> {
    let zero = T::zero();
    let pair = *line & *sphere;
    let square = pair.inner(pair).s;
    let tangent = square.abs().le(tolerance(T::one()));
    let hit = tangent | zero.lt(square);
    let none = SphereCrossing { points: [[zero; 3]; 2], t: [zero; 2], second: hit, found: hit };
    if !T::any(hit) {
        return none;
    }
    let e = ei::<T>().lc(pair);
    let pe = pair | e;
    // The double point of a tangent meet: `√P² = 0` in the same formula.
    let s = T::select(tangent, zero, square.sqrt());
    let ((a, a_ok), (b, b_ok)) = (down_lanes(pe - e.scale(s)), down_lanes(pe + e.scale(s)));
    let t_of = |x: E3<T>| dot(sub(x, origin), dir);
    let t = [t_of(a), t_of(b)];
    let (a_in, b_in) = (in_range(t[0], t_min, t_max), in_range(t[1], t_min, t_max));
    let found = hit & a_ok & b_ok & (a_in | b_in);
    // Along the ray `b` comes first where `(b − a)·d < 0`; the first point in range is kept.
    let b_first = dot(sub(b, a), dir).lt(zero);
    SphereCrossing { points: [a, b], t, second: (b_first & b_in) | (!b_first & !a_in), found }
}

/// What [`sphere_crossing`] finds: the meet's two points and their ray parameters, whether
/// the second is the one kept, and whether there is one at all (lane by lane).
pub(crate) struct SphereCrossing<T: Select> {
    /// `P·e − √(P²) e` and `P·e + √(P²) e`, read as Euclidean points.
    pub points: [E3<T>; 2],
    /// Their ray parameters.
    pub t: [T; 2],
    /// The second point is the one kept.
    pub second: T::Mask,
    /// There is a crossing in range.
    pub found: T::Mask,
}

impl Shape for SphereShape {
    /// Longitude and colatitude about its own z axis as fractions: `u = ½ + atan2(y, x)/2π`,
    /// `v = acos(z/r)/π` (0 at the top), `(x, y, z)` the hit from the centre on its own axes.
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let d = sub(c.point, self.centre);
        let [x, y, z] = self.axes.map(|a| dot(d, a));
        let r = (x * x + y * y + z * z).sqrt();
        let u = 0.5 + y.atan2(x) / std::f64::consts::TAU;
        Some(([u, (z / r).clamp(-1.0, 1.0).acos() / std::f64::consts::PI], Unit::Fraction))
    }

    #[inline]
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let c = sphere_crossing(&ray.carrier, &self.sphere, (ray.origin, ray.dir), (t_min, t_max));
        let (t, point) = if c.second { (c.t[1], c.points[1]) } else { (c.t[0], c.points[0]) };
        c.found.then_some(Crossing { t, point, alpha: None, part: 0 })
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

    fn closed(&self) -> bool {
        true
    }

    /// `|o + t d − c|² = r²` between its roots (the larger in magnitude directly, the other
    /// from their product: no cancellation); none where the line only touches or misses.
    fn spans(&self, ray: &Ray) -> super::Spans {
        let oc = sub(ray.origin, self.centre);
        let (b, cc) = (dot(oc, ray.dir), dot(oc, oc) - self.radius * self.radius);
        let disc = b * b - cc;
        let mut spans = super::Spans::new();
        if disc > 0.0 {
            let far = if b > 0.0 { -b - disc.sqrt() } else { -b + disc.sqrt() };
            let near = if far != 0.0 { cc / far } else { 0.0 };
            spans.push((near.min(far), near.max(far)));
        }
        spans
    }

    /// `64 ε r (1 + ρ)²`, `ρ = |c|/r`: the meet's points carry the null basis's `ε ρ²` of
    /// the radius (`RoundMeet::new`; measured at 3 ε (1 + ρ)² in `tests/tests/geometry/precision.rs`).
    fn crossing_error(&self) -> f64 {
        let one_plus_rho = 1.0 + largest(self.centre) / self.radius;
        rounding(self.radius * one_plus_rho * one_plus_rho)
    }
}
