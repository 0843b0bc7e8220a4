//! Meets with Euclidean answers: where two objects (or three planes) cross, classified,
//! as points, lines and circles. Each object's parameters are read back once and the
//! crossing is Euclid's (so a meet is as accurate as the read-backs, and a miss is named,
//! never a NaN). The classifications use tolerances relative to the sizes that decide
//! them: two spheres touch when `|d − (r1 + r2)|` or `|d − |r1 − r2||` is within rounding
//! of `r1 + r2 + d`.

use crate::conformal::{GeometryError, Result};
use crate::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use crate::measure::Nearest;
use crate::{Bivector, Circle, Line, Plane, Real, Sphere};

/// What a meet is, in Euclidean terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Meet<T: Real = f64> {
    /// The objects do not meet.
    Miss,
    /// One point where they touch (tangent) or cross once (a line and a plane).
    Point(E3<T>),
    /// Two points (a line through a sphere or a circle; a circle through a plane).
    Points([E3<T>; 2]),
    /// A line (two planes).
    Line(Line<T>),
    /// A circle: centre, unit normal, radius (two spheres; a sphere and a plane).
    Circle {
        /// The centre.
        centre: E3<T>,
        /// The unit normal.
        normal: E3<T>,
        /// The radius.
        radius: T,
    },
    /// The objects coincide, or one lies in the other (a line in a plane, a circle in a
    /// plane, the same sphere): they meet everywhere on the smaller.
    Contained,
}

/// `|x| ≤ 16 ε s`: zero at the scale `s`.
fn negligible<T: Real>(x: T, s: T) -> bool {
    x.abs() <= T::from_f64(16.0) * T::epsilon() * s
}

/// Where a line at distance `h` from a centre `foot`, direction `d`, crosses a round of
/// radius `r`: `foot ± √(r² − h²) d`, tangent within rounding.
fn chord<T: Real>(foot: E3<T>, d: E3<T>, h: T, r: T) -> Meet<T> {
    let (a, b) = (r - h, r + h);
    if negligible(a, r + h) {
        return Meet::Point(foot);
    }
    if a < T::zero() {
        return Meet::Miss;
    }
    let half = (a * b).sqrt();
    Meet::Points([sub(foot, scale(d, half)), add(foot, scale(d, half))])
}

impl<T: Real> Line<T> {
    /// The line's crossings with a sphere, ordered along the line: two points, a tangent
    /// point, or a miss.
    pub fn intersect_sphere(&self, sphere: &Sphere<T>) -> Result<Meet<T>> {
        let ((c, r), d) = (sphere.centre_radius()?, self.direction()?);
        let foot = self.nearest_point(c)?;
        Ok(chord(foot, d, norm(sub(c, foot)), r))
    }

    /// The line's crossing with a plane: a point, a miss (parallel) or `Contained`.
    pub fn intersect_plane(&self, plane: &Plane<T>) -> Result<Meet<T>> {
        let (p, d, (n, off)) = (self.point()?, self.direction()?, plane.normal_offset()?);
        let (along, gap) = (dot(d, n), off - dot(n, p));
        let size = norm(p).max(off.abs());
        if negligible(along, T::one()) {
            return Ok(if negligible(gap, size) { Meet::Contained } else { Meet::Miss });
        }
        Ok(Meet::Point(add(p, scale(d, gap / along))))
    }

    /// The line's crossings with a circle: in the circle's plane, the chord's two points or a
    /// tangent point (ordered along the line); out of it, the point where the line pierces
    /// the plane if it lies on the circle. A miss otherwise.
    pub fn intersect_circle(&self, circle: &Circle<T>) -> Result<Meet<T>> {
        let (c, n, r) = circle.centre_normal_radius()?;
        let plane = Plane::from_point_normal(c, n)?;
        match self.intersect_plane(&plane)? {
            Meet::Contained => {
                let d = self.direction()?;
                let foot = self.nearest_point(c)?;
                Ok(chord(foot, d, norm(sub(c, foot)), r))
            }
            Meet::Point(x) => {
                let off = norm(sub(x, c)) - r;
                Ok(if negligible(off, r + norm(sub(x, c))) { Meet::Point(x) } else { Meet::Miss })
            }
            other => Ok(other),
        }
    }
}

impl<T: Real> Line<T> {
    /// Where two lines meet: their crossing point, `Contained` for the same line, a miss for
    /// skew or parallel lines. From the closest points ([`Line::closest_points`]): the lines
    /// cross when those lie within rounding of their distance from the origin
    /// (`64 ε max(|a|, |b|)`, as [`Line::join_line`] decides), and the point returned is
    /// their midpoint.
    pub fn intersect_line(&self, other: &Line<T>) -> Result<Meet<T>> {
        let k = self.closest_points(other)?;
        let size = norm(k.on_self).max(norm(k.on_other));
        let touching = k.distance <= T::from_f64(64.0) * T::epsilon() * size;
        Ok(match (k.parallel, touching) {
            (true, true) => Meet::Contained,
            (false, true) => Meet::Point(scale(add(k.on_self, k.on_other), T::from_f64(0.5))),
            _ => Meet::Miss,
        })
    }
}

impl<T: Real> Bivector<T> {
    /// Where a point pair meets an object (a sphere, plane, line, circle, another pair or a
    /// conformal point): those of its two points that lie on the object, `Points` in the
    /// pair's order when both do. A point pair is two points, so its meet with anything is a
    /// subset of them; the blade meet `P ∨ X` is not (it has grade `2 + k − 5`). "On" is
    /// [`Nearest::contains_within`] with the pair's own uncertainty as slack: its ends, read
    /// back from the blade, are good to `ε ρ² r` (half-distance `r`, centre `c`,
    /// `ρ = |c|/r`, docs/STABILITY.md), so the slack is `64 ε (1 + ρ)² r`. An imaginary pair
    /// has no real points: a miss. A tangent pair is `Degenerate`, as its read-back
    /// ([`Bivector::end_points`]).
    pub fn intersect<O: Nearest<T>>(&self, object: &O) -> Result<Meet<T>> {
        let [a, b] = match self.end_points() {
            Err(GeometryError::Imaginary) => return Ok(Meet::Miss),
            points => points?,
        };
        let half = T::from_f64(0.5);
        let r = half * norm(sub(a, b));
        let rho = half * norm(add(a, b)) / r;
        let slack = T::from_f64(64.0) * T::epsilon() * (T::one() + rho) * (T::one() + rho) * r;
        Ok(match (object.contains_within(a, slack)?, object.contains_within(b, slack)?) {
            (true, true) => Meet::Points([a, b]),
            (true, false) => Meet::Point(a),
            (false, true) => Meet::Point(b),
            (false, false) => Meet::Miss,
        })
    }
}

impl<T: Real> Plane<T> {
    /// The line where two planes cross, directed along `n1 × n2`; `Miss` for parallel
    /// planes, `Contained` for the same plane.
    pub fn intersect_plane(&self, other: &Plane<T>) -> Result<Meet<T>> {
        let ((n1, d1), (n2, d2)) = (self.normal_offset()?, other.normal_offset()?);
        let dir = cross(n1, n2);
        if negligible(norm(dir), T::one()) {
            let same = negligible(d1 - d2 * dot(n1, n2), d1.abs().max(d2.abs()));
            return Ok(if same { Meet::Contained } else { Meet::Miss });
        }
        // The point of the line nearest the origin: (d1 n2 × dir + d2 dir × n1)/|dir|².
        let k = T::one() / dot(dir, dir);
        let p = scale(add(scale(cross(n2, dir), d1), scale(cross(dir, n1), d2)), k);
        Ok(Meet::Line(Line::from_point_direction(p, dir)?))
    }

    /// The circle where a plane cuts a sphere (normal the plane's), a tangent point, or a
    /// miss.
    pub fn intersect_sphere(&self, sphere: &Sphere<T>) -> Result<Meet<T>> {
        let ((c, r), (n, _)) = (sphere.centre_radius()?, self.normal_offset()?);
        let foot = self.nearest_point(c)?;
        let h = norm(sub(c, foot));
        Ok(match chord(foot, n, h, r) {
            Meet::Points([a, _]) => Meet::Circle { centre: foot, normal: n, radius: norm(sub(a, foot)) },
            other => other,
        })
    }

    /// The two points where a circle pierces a plane, a tangent point, a miss, or
    /// `Contained` for a circle in the plane.
    pub fn intersect_circle(&self, circle: &Circle<T>) -> Result<Meet<T>> {
        let (c, n, _) = circle.centre_normal_radius()?;
        let carrier = Plane::from_point_normal(c, n)?;
        match carrier.intersect_plane(self)? {
            Meet::Line(line) => line.intersect_circle(circle),
            Meet::Contained => Ok(Meet::Contained),
            _ => Ok(Meet::Miss),
        }
    }

    /// The point common to three planes, `(δ1 n2 × n3 + δ2 n3 × n1 + δ3 n1 × n2) / (n1 · n2 × n3)`;
    /// `Miss` when their normals are coplanar (they meet in a line or not at all).
    pub fn intersect_planes(a: &Plane<T>, b: &Plane<T>, c: &Plane<T>) -> Result<Meet<T>> {
        let ((n1, d1), (n2, d2), (n3, d3)) = (a.normal_offset()?, b.normal_offset()?, c.normal_offset()?);
        let det = dot(n1, cross(n2, n3));
        if negligible(det, T::one()) {
            return Ok(Meet::Miss);
        }
        let sum = add(add(scale(cross(n2, n3), d1), scale(cross(n3, n1), d2)), scale(cross(n1, n2), d3));
        Ok(Meet::Point(scale(sum, T::one() / det)))
    }
}

impl<T: Real> Sphere<T> {
    /// The circle where two spheres cross (normal from the first centre to the second), a
    /// tangent point, a miss, or `Contained` for the same sphere. With `d` the distance of
    /// the centres, the circle's plane lies `a = (d² + r1² − r2²)/2d` from the first centre
    /// and its radius is `√(r1² − a²)`, computed as `√((r1 − a)(r1 + a))`.
    pub fn intersect_sphere(&self, other: &Sphere<T>) -> Result<Meet<T>> {
        let ((c1, r1), (c2, r2)) = (self.centre_radius()?, other.centre_radius()?);
        let v = sub(c2, c1);
        let d = norm(v);
        let size = r1 + r2 + d;
        let Some(n) = unit(v).filter(|_| !negligible(d, size)) else {
            return Ok(if negligible(r1 - r2, size) { Meet::Contained } else { Meet::Miss });
        };
        Ok(match two_rounds(c1, n, r1, r2, d) {
            Rounds::Touch(x) => Meet::Point(x),
            Rounds::Apart => Meet::Miss,
            Rounds::Cross { foot, half } => Meet::Circle { centre: foot, normal: n, radius: half },
        })
    }
}

impl<T: Real> Circle<T> {
    /// Where two circles meet: two points, a tangent point, a miss, or `Contained` for the
    /// same circle. In one plane, by the chord of the two discs (`a = (d² + r1² − r2²)/2d`
    /// from the first centre, half-chord `√((r1 − a)(r1 + a))`, the points ordered along
    /// `n × (c2 − c1)`); in two planes, where the line the planes share meets both (ordered
    /// along `n1 × n2`).
    pub fn intersect_circle(&self, other: &Circle<T>) -> Result<Meet<T>> {
        let ((c1, n1, r1), (c2, n2, r2)) = (self.centre_normal_radius()?, other.centre_normal_radius()?);
        let (p1, p2) = (Plane::from_point_normal(c1, n1)?, Plane::from_point_normal(c2, n2)?);
        match p1.intersect_plane(&p2)? {
            Meet::Contained => Ok(coplanar_circles((c1, n1, r1), (c2, r2))),
            Meet::Line(line) => {
                let on_second = |x: E3<T>| negligible(norm(sub(x, c2)) - r2, r2 + norm(sub(x, c2)));
                Ok(match line.intersect_circle(self)? {
                    Meet::Points([a, b]) => match (on_second(a), on_second(b)) {
                        (true, true) => Meet::Points([a, b]),
                        (true, false) => Meet::Point(a),
                        (false, true) => Meet::Point(b),
                        _ => Meet::Miss,
                    },
                    Meet::Point(a) if on_second(a) => Meet::Point(a),
                    _ => Meet::Miss,
                })
            }
            _ => Ok(Meet::Miss),
        }
    }

    /// Where a circle meets a sphere: the sphere cuts the circle's plane in a circle, met
    /// as [`Circle::intersect_circle`] in that plane; `Contained` for a circle on the sphere.
    pub fn intersect_sphere(&self, sphere: &Sphere<T>) -> Result<Meet<T>> {
        let (c, n, r) = self.centre_normal_radius()?;
        match Plane::from_point_normal(c, n)?.intersect_sphere(sphere)? {
            Meet::Circle { centre, radius, .. } => Ok(coplanar_circles((c, n, r), (centre, radius))),
            Meet::Point(x) => {
                let off = norm(sub(x, c)) - r;
                Ok(if negligible(off, r + norm(sub(x, c))) { Meet::Point(x) } else { Meet::Miss })
            }
            other => Ok(other),
        }
    }
}

/// Two circles in the plane of normal `n`: the first `(c1, r1)`, the second `(c2, r2)`.
fn coplanar_circles<T: Real>((c1, n, r1): (E3<T>, E3<T>, T), (c2, r2): (E3<T>, T)) -> Meet<T> {
    let v = sub(c2, c1);
    let d = norm(v);
    let size = r1 + r2 + d;
    let Some(u) = unit(v).filter(|_| !negligible(d, size)) else {
        return if negligible(r1 - r2, size) { Meet::Contained } else { Meet::Miss };
    };
    match two_rounds(c1, u, r1, r2, d) {
        Rounds::Touch(x) => Meet::Point(x),
        Rounds::Apart => Meet::Miss,
        Rounds::Cross { foot, half } => {
            let across = cross(n, u);
            Meet::Points([sub(foot, scale(across, half)), add(foot, scale(across, half))])
        }
    }
}

/// How two rounds of radii `r1`, `r2` whose centres lie `d` apart along the unit `u` from
/// `c1` meet: touching (at the point on the side the second lies), apart, or crossing
/// where the plane `a = (d² + r1² − r2²)/2d` from `c1` cuts them, with the half-chord
/// `√((r1 − a)(r1 + a))`. Touching within rounding of `r1 + r2 + d`.
enum Rounds<T> {
    Touch(E3<T>),
    Apart,
    Cross { foot: E3<T>, half: T },
}

fn two_rounds<T: Real>(c1: E3<T>, u: E3<T>, r1: T, r2: T, d: T) -> Rounds<T> {
    let size = r1 + r2 + d;
    let (outer, inner) = (d - (r1 + r2), d - (r1 - r2).abs());
    if negligible(outer, size) || negligible(inner, size) {
        // Outside each other, or the first around the second: the point toward the second.
        let a = if negligible(outer, size) || r1 > r2 { r1 } else { -r1 };
        return Rounds::Touch(add(c1, scale(u, a)));
    }
    if outer > T::zero() || inner < T::zero() {
        return Rounds::Apart;
    }
    let a = (d * d + (r1 - r2) * (r1 + r2)) / (d + d);
    Rounds::Cross { foot: add(c1, scale(u, a)), half: ((r1 - a) * (r1 + a)).sqrt() }
}

/// The meets named from the other side: the same answer whichever object is asked, in the
/// order and orientation the first method states (a line's points along the line; a circle
/// of a sphere and a plane normal to the plane).
impl<T: Real> Sphere<T> {
    /// Where a line crosses the sphere: [`Line::intersect_sphere`].
    pub fn intersect_line(&self, line: &Line<T>) -> Result<Meet<T>> {
        line.intersect_sphere(self)
    }

    /// The circle where a plane cuts the sphere (normal the plane's): [`Plane::intersect_sphere`].
    pub fn intersect_plane(&self, plane: &Plane<T>) -> Result<Meet<T>> {
        plane.intersect_sphere(self)
    }

    /// Where a circle meets the sphere: [`Circle::intersect_sphere`].
    pub fn intersect_circle(&self, circle: &Circle<T>) -> Result<Meet<T>> {
        circle.intersect_sphere(self)
    }
}

impl<T: Real> Plane<T> {
    /// Where a line crosses the plane: [`Line::intersect_plane`].
    pub fn intersect_line(&self, line: &Line<T>) -> Result<Meet<T>> {
        line.intersect_plane(self)
    }
}

impl<T: Real> Circle<T> {
    /// Where a line crosses the circle (points along the line): [`Line::intersect_circle`].
    pub fn intersect_line(&self, line: &Line<T>) -> Result<Meet<T>> {
        line.intersect_circle(self)
    }

    /// Where the circle pierces a plane: [`Plane::intersect_circle`].
    pub fn intersect_plane(&self, plane: &Plane<T>) -> Result<Meet<T>> {
        plane.intersect_circle(self)
    }
}
