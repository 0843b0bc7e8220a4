//! A torus: the points at distance `ρ` from a circle `C` (its core). A ray meets it where a
//! quartic vanishes; written about the ray's point nearest the centre and in units of the
//! bounding radius `R + ρ`, the quartic has no cubic term and every root lies in `[−1, 1]`,
//! where the roots are isolated between the critical points (those of the derivative, a
//! cubic, isolated the same way) and each is found by Newton steps kept inside its bracket.

use super::{Crossing, Shape, Unit, crossing_at, facing, largest, rounding};
use crate::light::orthonormal;
use crate::ray::{Ray, in_range};
use cga_core::euclid::{E3, add, dot, scale, sub, unit};
use cga_core::{Circle, GeometryError};

/// A torus about a circle of `centre`, unit `normal` and `radius` `R`, of tube radius `ρ`.
#[derive(Clone, Debug)]
pub struct TorusShape {
    /// The core circle, OPNS.
    pub core: Circle,
    /// Its centre.
    pub centre: E3,
    /// Its unit normal, the torus's axis.
    pub normal: E3,
    /// Its radius `R` (the major radius).
    pub radius: f64,
    /// The tube radius `ρ` (the minor radius).
    pub tube: f64,
}

impl TorusShape {
    /// The torus of tube radius `tube` about the circle of `centre`, `normal` and `radius`.
    /// `ZeroRadius` for a radius or tube that is not positive; `tube ≥ radius` (a horn or
    /// spindle torus, which meets its own axis) is allowed.
    pub fn new(centre: E3, normal: E3, radius: f64, tube: f64) -> Result<Self, GeometryError> {
        if !(radius > 0.0 && tube > 0.0) {
            return Err(if radius.is_finite() && tube.is_finite() {
                GeometryError::ZeroRadius
            } else {
                GeometryError::NonFinite
            });
        }
        let normal = unit(normal).ok_or(GeometryError::ZeroVector)?;
        let core = Circle::from_centre_normal_radius(centre, normal, radius)?;
        Ok(TorusShape { core, centre, normal, radius, tube })
    }

    /// The tube of radius `tube` about a real circle.
    pub fn about(circle: &Circle, tube: f64) -> Result<Self, GeometryError> {
        let (centre, normal, radius) = circle.centre_normal_radius()?;
        TorusShape::new(centre, normal, radius, tube)
    }

    /// The bounding radius `R + ρ`.
    fn extent(&self) -> f64 {
        self.radius + self.tube
    }

    /// The ray parameters where the ray's line crosses the torus, increasing: `t₀ + s (R + ρ)`
    /// for the roots `s` of `s⁴ + a s² + b s + c` (see [`depressed_quartic`]).
    fn crossings(&self, ray: &Ray) -> ([f64; 4], usize) {
        let k = self.extent();
        let rel = sub(ray.origin, self.centre);
        let t0 = -dot(rel, ray.dir);
        let q = scale(add(rel, scale(ray.dir, t0)), 1.0 / k);
        let q2 = dot(q, q);
        if q2 > 1.0 {
            return ([0.0; 4], 0);
        }
        let (r, rho) = (self.radius / k, self.tube / k);
        let (roots, n) = depressed_quartic(q2, dot(q, self.normal), dot(ray.dir, self.normal), r, rho);
        (roots.map(|s| t0 + s * k), n)
    }
}

/// The roots in `[−1, 1]` of `f(s) = (s² + A)² − 4R² (|q|² + s² − (a + b s)²)`, `A = |q|² + R²
/// − ρ²`, `a = q·n`, `b = d·n`: the torus `(|p|² + R² − ρ²)² = 4R² (|p|² − (p·n)²)` on the
/// line `p = q + s d` with `q ⊥ d`, lengths in units of `R + ρ` (so `|q| ≤ 1` and every root
/// is in `[−1, 1]`, searched with a margin). Expanded, `s⁴ + (2A − 4R²(1 − b²)) s² + 8R²ab s + A² − 4R²(|q|² − a²)`.
/// Roots of even multiplicity (a ray grazing the torus) are not reported.
fn depressed_quartic(q2: f64, a: f64, b: f64, r: f64, rho: f64) -> ([f64; 4], usize) {
    let big_a = q2 + r * r - rho * rho;
    let r4 = 4.0 * r * r;
    let p2 = 2.0 * big_a - r4 * (1.0 - b * b);
    let p1 = 2.0 * r4 * a * b;
    let p0 = big_a * big_a - r4 * (q2 - a * a);
    let f = move |s: f64| ((s * s + p2) * s + p1) * s + p0;
    let df = move |s: f64| (4.0 * s * s + 2.0 * p2) * s + p1;
    let ddf = move |s: f64| 12.0 * s * s + 2.0 * p2;
    // Every root is in [−1, 1]; a little beyond, f > 0 (outside the torus), so that a root at
    // ±1 itself (a ray through the outer equator) keeps its sign change whatever the rounding.
    const REACH: f64 = 1.0 + 1.0 / 1024.0;
    // f'' vanishes at ±√(−p₂/6): f' is monotone between those; its roots split f likewise.
    // Fixed arrays: this runs per ray.
    let mut cuts = Bounds::new(-REACH);
    if p2 < 0.0 {
        let c = (-p2 / 6.0).sqrt();
        [-c, c].into_iter().filter(|c| c.abs() < REACH).for_each(|c| cuts.push(c));
    }
    cuts.push(REACH);
    let mut critical = Bounds::new(-REACH);
    cuts.windows().filter_map(|(lo, hi)| bracketed_root(df, ddf, lo, hi)).for_each(|c| critical.push(c));
    critical.push(REACH);
    let mut roots = [0.0; 4];
    let mut n = 0;
    for (lo, hi) in critical.windows() {
        if let Some(s) = bracketed_root(f, df, lo, hi).filter(|_| n < 4) {
            roots[n] = s;
            n += 1;
        }
    }
    (roots, n)
}

/// Up to five increasing points splitting `[−1, 1]` (with its margin) into intervals.
struct Bounds {
    at: [f64; 5],
    len: usize,
}

impl Bounds {
    fn new(first: f64) -> Self {
        Bounds { at: [first; 5], len: 1 }
    }

    fn push(&mut self, x: f64) {
        if self.len < self.at.len() {
            self.at[self.len] = x;
            self.len += 1;
        }
    }

    /// Consecutive pairs.
    fn windows(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.at[..self.len].windows(2).map(|w| (w[0], w[1]))
    }
}

/// The root of `f` in `[lo, hi]` where `f` is monotone and changes sign: Newton steps from
/// the end nearer zero, each replaced by bisection when it leaves the bracket, until the
/// bracket holds no double between its ends. `None` without a sign change.
fn bracketed_root(f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Option<f64> {
    let (f_lo, f_hi) = (f(lo), f(hi));
    if f_lo == 0.0 {
        return Some(lo);
    }
    if f_hi == 0.0 {
        return Some(hi);
    }
    if (f_lo < 0.0) == (f_hi < 0.0) {
        return None;
    }
    let rising = f_lo < 0.0;
    let mut s = if f_lo.abs() < f_hi.abs() { lo } else { hi };
    for _ in 0..200 {
        let v = f(s);
        if v == 0.0 {
            return Some(s);
        }
        if (v < 0.0) == rising {
            lo = s;
        } else {
            hi = s;
        }
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let newton = s - v / df(s);
        s = if newton > lo && newton < hi { newton } else { mid };
        if s == lo || s == hi {
            s = mid;
        }
    }
    Some(if f(lo).abs() < f(hi).abs() { lo } else { hi })
}

impl Shape for TorusShape {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let (ts, n) = self.crossings(ray);
        let t = ts[..n].iter().copied().find(|&t| in_range(t, t_min, t_max))?;
        Some(crossing_at(ray, ray.at(t)))
    }

    /// Away from the nearest point `m` of the core circle: `x − m` over its length (the
    /// tangent plane at `x` is that of the sphere of radius `ρ` about `m`).
    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let p = sub(crossing.point, self.centre);
        let radial = sub(p, scale(self.normal, dot(p, self.normal)));
        // On the axis (a spindle torus's apex) every core point is nearest: the axis is the
        // normal there.
        let m = unit(radial).map_or(self.centre, |u| add(self.centre, scale(u, self.radius)));
        let n = unit(sub(crossing.point, m)).unwrap_or(self.normal);
        facing(n, ray.dir)
    }

    /// Two angles as fractions of a turn: about the axis, `u = ½ + atan2(x·b, x·a)/2π`
    /// (`(a, b)` [`orthonormal`] to the normal, as a cylinder's), and about the tube from its
    /// top outwards and down, `v = (¼ − φ/2π) mod 1`, `φ = atan2(h, ρ′)` with `h` the height
    /// over the core's plane and `ρ′` the distance from the axis less `R`: 0 on top, ¼ on the
    /// outer equator, ½ below, ¾ on the inner one (`v` runs down the outside, as down a page).
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let p = sub(c.point, self.centre);
        let h = dot(p, self.normal);
        let radial = sub(p, scale(self.normal, h));
        let (a, b) = orthonormal(self.normal);
        let turn = std::f64::consts::TAU;
        let u = 0.5 + dot(radial, b).atan2(dot(radial, a)) / turn;
        let out = dot(radial, radial).sqrt() - self.radius;
        Some(([u, (0.25 - h.atan2(out) / turn).rem_euclid(1.0)], Unit::Fraction))
    }

    fn closed(&self) -> bool {
        true
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some((self.centre, self.extent()))
    }

    /// `64 ε (R + ρ)²/ρ + 64 ε |c|`: the roots are found to the last bit of `s` in units of
    /// `R + ρ`, where the quartic's slope at a crossing scales with `ρ/(R + ρ)` (a thin tube
    /// has steep walls in `s` only at its own scale), plus the rounding of the centre.
    fn crossing_error(&self) -> f64 {
        let k = self.extent();
        rounding(k * k / self.tube + largest(self.centre))
    }

    /// A quartic costs more than a bounding-sphere test.
    fn cull(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Along the torus's plane through its centre a ray crosses at `±(R ± ρ)`.
    #[test]
    fn a_ray_through_the_centre_crosses_four_times() {
        let torus = TorusShape::new([1.0, 2.0, 3.0], [0.0, 0.0, 2.0], 3.0, 0.5).unwrap();
        let ray = Ray::new([-10.0, 2.0, 3.0], [1.0, 0.0, 0.0]).unwrap();
        let (t, n) = torus.crossings(&ray);
        assert_eq!(n, 4);
        let want = [7.5, 8.5, 13.5, 14.5];
        for k in 0..4 {
            assert!((t[k] - want[k]).abs() <= 4.0 * f64::EPSILON * 14.5, "{t:?}");
        }
        let hit = torus.hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.normal, [-1.0, 0.0, 0.0]);
    }

    #[test]
    fn bad_sizes_are_refused() {
        assert_eq!(TorusShape::new([0.0; 3], [0.0, 0.0, 1.0], 1.0, 0.0).unwrap_err(), GeometryError::ZeroRadius);
        assert_eq!(TorusShape::new([0.0; 3], [0.0, 0.0, 1.0], -1.0, 0.2).unwrap_err(), GeometryError::ZeroRadius);
        assert_eq!(TorusShape::new([0.0; 3], [0.0, 0.0, 0.0], 1.0, 0.2).unwrap_err(), GeometryError::ZeroVector);
        assert_eq!(TorusShape::new([0.0; 3], [0.0, 0.0, 1.0], f64::NAN, 0.2).unwrap_err(), GeometryError::NonFinite);
    }
}
