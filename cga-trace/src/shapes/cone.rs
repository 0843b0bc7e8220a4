//! A finite cone between two end disks, of radii `r1` at `p1` and `r2` at `p2` (a cylinder
//! when they are equal), with or without its end caps. The side is the quadric
//! `|x⊥|² = r(u)²`, `u` the coordinate along the axis and `r` linear in it, solved about the
//! ray's point nearest the axis's midpoint in units of the cone's size (the stable form of the
//! quadratic formula); the caps are the end planes within their radii.

use super::{Crossing, Shape, Unit, crossing_at, facing, largest, rounding};
use crate::light::orthonormal;
use crate::ray::{Ray, in_range};
use cga_core::GeometryError;
use cga_core::euclid::{E3, add, dot, norm, scale, sub, unit};

/// A cone (or cylinder) about the segment from `p1` to `p2`.
#[derive(Clone, Debug)]
pub struct ConeShape {
    /// The midpoint of the axis.
    pub mid: E3,
    /// The unit axis, from `p1` to `p2`.
    pub axis: E3,
    /// Half the axis's length.
    pub half: f64,
    /// The radii at `p1` and `p2`.
    pub radii: [f64; 2],
    /// Whether the end disks are part of it.
    pub caps: bool,
}

impl ConeShape {
    /// The cone from `p1` (radius `r1`) to `p2` (radius `r2`), with its end disks if `caps`.
    /// `CoincidentPoints` when `p1 = p2`; `ZeroRadius` for a negative radius or both zero.
    pub fn new(p1: E3, r1: f64, p2: E3, r2: f64, caps: bool) -> Result<Self, GeometryError> {
        if !p1.iter().chain(&p2).chain(&[r1, r2]).all(|x| x.is_finite()) {
            return Err(GeometryError::NonFinite);
        }
        if r1 < 0.0 || r2 < 0.0 || (r1 == 0.0 && r2 == 0.0) {
            return Err(GeometryError::ZeroRadius);
        }
        let d = sub(p2, p1);
        let axis = unit(d).ok_or(GeometryError::CoincidentPoints)?;
        let mid = [0, 1, 2].map(|k| 0.5 * (p1[k] + p2[k]));
        Ok(ConeShape { mid, axis, half: 0.5 * norm(d), radii: [r1, r2], caps })
    }

    /// The cylinder of `radius` from `p1` to `p2`.
    pub fn cylinder(p1: E3, p2: E3, radius: f64, caps: bool) -> Result<Self, GeometryError> {
        ConeShape::new(p1, radius, p2, radius, caps)
    }

    /// The size the equations are written in: half the axis plus the larger radius.
    fn size(&self) -> f64 {
        self.half + self.radii[0].max(self.radii[1])
    }

    /// `(r(u), dr/du)` with `u` along the axis from the midpoint, in units of `size`.
    fn radius_law(&self, size: f64) -> (f64, f64) {
        let mean = 0.5 * (self.radii[0] + self.radii[1]) / size;
        (mean, (self.radii[1] - self.radii[0]) / (2.0 * self.half))
    }

    /// A point's coordinate along the axis from the midpoint, its part across the axis, and
    /// whether it lies on a cap: nearer a cap's plane than the side.
    fn place(&self, point: E3) -> (f64, E3, bool) {
        let rel = sub(point, self.mid);
        let u = dot(rel, self.axis);
        let perp = sub(rel, scale(self.axis, u));
        let (mean, slope) = self.radius_law(1.0);
        let side_gap = (norm(perp) - (mean + slope * u)).abs() / (1.0 + slope * slope).sqrt();
        let cap_gap = if self.caps { (u.abs() - self.half).abs() } else { f64::INFINITY };
        (u, perp, cap_gap < side_gap)
    }

    /// The ray parameters where the ray's line crosses the side and the caps (unsorted).
    fn crossings(&self, ray: &Ray) -> ([f64; 4], usize) {
        let size = self.size();
        let rel = sub(ray.origin, self.mid);
        let t0 = -dot(rel, ray.dir);
        let q = scale(add(rel, scale(ray.dir, t0)), 1.0 / size);
        let (qa, da) = (dot(q, self.axis), dot(ray.dir, self.axis));
        let h = self.half / size;
        let (mean, slope) = self.radius_law(size);
        let radius_at = |u: f64| mean + slope * u;
        let p = sub(q, scale(self.axis, qa));
        let e = sub(ray.dir, scale(self.axis, da));
        // |p + s e|² = (r(qa) + slope da s)²
        let r0 = radius_at(qa);
        let a = dot(e, e) - slope * slope * da * da;
        let b = 2.0 * (dot(p, e) - slope * da * r0);
        let c = dot(p, p) - r0 * r0;
        let mut out = [0.0; 4];
        let mut n = 0;
        let mut keep = |s: f64| {
            if n < 4 {
                out[n] = t0 + s * size;
                n += 1;
            }
        };
        let on_side = |s: f64| {
            let u = qa + s * da;
            u.abs() <= h && radius_at(u) >= 0.0
        };
        for s in quadratic_roots(a, b, c).into_iter().flatten() {
            if on_side(s) {
                keep(s);
            }
        }
        if self.caps && da != 0.0 {
            for (end, r) in [(-h, self.radii[0] / size), (h, self.radii[1] / size)] {
                let s = (end - qa) / da;
                let x = add(p, scale(e, s));
                if r > 0.0 && dot(x, x) <= r * r {
                    keep(s);
                }
            }
        }
        (out, n)
    }
}

/// The real roots of `a s² + b s + c`, by the stable form `q = −(b + sign(b) √Δ)/2`,
/// `s = q/a, c/q` (no cancellation); the one root of `b s + c` when `a = 0`.
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    if a == 0.0 {
        return [(b != 0.0).then(|| -c / b), None];
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return [None, None];
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return [Some(0.0), None];
    }
    [Some(q / a), Some(c / q)]
}

impl Shape for ConeShape {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let (ts, n) = self.crossings(ray);
        let t = ts[..n].iter().copied().filter(|&t| in_range(t, t_min, t_max)).min_by(f64::total_cmp)?;
        Some(crossing_at(ray, ray.at(t)))
    }

    /// On a cap, the axis; on the side, `x⊥/|x⊥| − r′ a` normalised (the gradient of
    /// `|x⊥| − r(u)`): whichever surface the point is nearer to.
    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let (_, perp, cap) = self.place(crossing.point);
        let n = if cap {
            self.axis
        } else {
            let radial = unit(perp).unwrap_or(self.axis);
            unit(sub(radial, scale(self.axis, self.radius_law(1.0).1))).unwrap_or(self.axis)
        };
        facing(n, ray.dir)
    }

    /// On the side, the angle about the axis as a fraction of a turn, `u = ½ + atan2(x·b,
    /// x·a)/2π` (`(a, b)` [`orthonormal`] to the axis: counter-clockwise seen from `p2`, as a
    /// sphere's longitude about its z), and the place along the axis down from `p2`, `v = ½ −
    /// (x·axis)/(2h)` (0 at `p2`, 1 at `p1`; `x` from the midpoint, `2h` the axis's length):
    /// seen from outside with `p2` up, an image reads as drawn. On a cap, a disk's: the same
    /// angle, and `r/R` out from the axis.
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let (along, perp, cap) = self.place(c.point);
        let (a, b) = orthonormal(self.axis);
        let angle = 0.5 + dot(perp, b).atan2(dot(perp, a)) / std::f64::consts::TAU;
        // A cap of radius 0 (a cone's tip, met by rounding) is a point: r/R is 0 there.
        let radius = self.radii[usize::from(along > 0.0)];
        let v = match cap {
            true if radius > 0.0 => (norm(perp) / radius).min(1.0),
            true => 0.0,
            false => 0.5 - along / (2.0 * self.half),
        };
        Some(([angle, v], Unit::Fraction))
    }

    /// With its caps, the solid between them.
    fn closed(&self) -> bool {
        self.caps
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        let r = self.radii[0].max(self.radii[1]);
        Some((self.mid, (self.half * self.half + r * r).sqrt()))
    }

    /// The rounding of its size and of its midpoint's place, `64 ε (4 s + |m|)`.
    fn crossing_error(&self) -> f64 {
        rounding(4.0 * self.size() + largest(self.mid))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A point classed on the cap of radius 0 (a cone's tip) has finite `(u, v)`.
    #[test]
    fn the_tip_of_a_cone_has_finite_texture_coordinates() {
        let c = ConeShape::new([0.0, 0.0, 0.0], 0.8, [0.0, 0.0, 2.0], 0.0, true).unwrap();
        for z in [2.0, 2.0 - 1e-17, 2.0 + 1e-15] {
            let crossing = Crossing { t: 0.0, point: [0.0, 0.0, z], alpha: None, part: 0 };
            let ([u, v], _) = c.uv(&crossing).unwrap();
            assert!(u.is_finite() && v.is_finite(), "{u} {v} at z = {z}");
        }
    }

    /// A ray across a cylinder's axis meets its side at `±r`; along the axis, its caps.
    #[test]
    fn a_cylinder_is_met_at_its_side_and_its_caps() {
        let c = ConeShape::cylinder([0.0, 0.0, -1.0], [0.0, 0.0, 3.0], 0.5, true).unwrap();
        let across = Ray::new([-4.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
        let hit = c.hit(&across, 0.0, f64::INFINITY).unwrap();
        assert_eq!((hit.t, hit.normal), (3.5, [-1.0, 0.0, 0.0]));
        let along = Ray::new([0.1, 0.0, -5.0], [0.0, 0.0, 1.0]).unwrap();
        let cap = c.hit(&along, 0.0, f64::INFINITY).unwrap();
        assert_eq!((cap.t, cap.normal), (4.0, [0.0, 0.0, -1.0]));
        let open = ConeShape::cylinder([0.0, 0.0, -1.0], [0.0, 0.0, 3.0], 0.5, false).unwrap();
        assert!(open.intersect(&along, 0.0, f64::INFINITY).is_none(), "no caps: the ray runs inside");
        // A cone of apex (0, 0, 2) and base radius 1 at z = 0: the ray along x at z = 1 meets
        // it at x = −0.5.
        let cone = ConeShape::new([0.0, 0.0, 0.0], 1.0, [0.0, 0.0, 2.0], 0.0, true).unwrap();
        let hit = cone.hit(&Ray::new([-3.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap(), 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 2.5).abs() <= 1e-15, "{hit:?}");
        let s = 1.0 / 5f64.sqrt();
        assert!(norm(sub(hit.normal, [-2.0 * s, 0.0, s])) <= 1e-15, "{:?}", hit.normal);
        assert_eq!(ConeShape::new([0.0; 3], 1.0, [0.0; 3], 1.0, true).unwrap_err(), GeometryError::CoincidentPoints);
        assert_eq!(ConeShape::new([0.0; 3], 0.0, [1.0; 3], 0.0, true).unwrap_err(), GeometryError::ZeroRadius);
    }
}
