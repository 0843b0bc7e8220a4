//! Projections, distances and angles, in Euclidean terms: the nearest point of an object
//! to a point, the distance of a point from an object, the closest points of two lines,
//! and the angles between lines and planes. Each object's Euclidean parameters are read
//! once (its read-back) and the rest is Euclid's formula, so nothing costs more digits
//! than the read-back does (`ε ρ` for flats, `ε ρ²` for rounds: docs/STABILITY.md).

use crate::conformal::{GeometryError, Result, down};
use crate::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use crate::{Bivector, Circle, Line, Plane, Real, Sphere, Vector};

/// `|a − b|`, the distance of two Euclidean points (rescaled: no overflow or underflow
/// for any finite input). For conformal points, `√(−2 X·Y)` holds for unit weights; this
/// is that without the cancellation.
pub fn distance<T: Real>(a: E3<T>, b: E3<T>) -> T {
    norm(sub(a, b))
}

/// Objects that have a nearest point to any Euclidean point.
pub trait Nearest<T: Real> {
    /// The point of the object nearest `x` (the orthogonal projection onto a flat, the
    /// radial one onto a round). An error where it is not unique: `Degenerate` at a sphere's
    /// or circle's centre or on a circle's axis, and the object's own read-back errors.
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>>;

    /// `x − nearest(x)`: the rejection, the offset of `x` from the object.
    fn rejection(&self, x: E3<T>) -> Result<E3<T>> {
        Ok(sub(x, self.nearest_point(x)?))
    }

    /// `|x − nearest(x)|`: the distance of `x` from the object (unsigned).
    fn distance_to(&self, x: E3<T>) -> Result<T> {
        Ok(norm(self.rejection(x)?))
    }

    /// Whether `x` lies on the object: `|x − nearest(x)| ≤ 64 ε (|x| + |nearest(x)|)`, within
    /// rounding of the coordinates that decide it (so the answer is the same wherever the
    /// pair is moved or however it is scaled). Spheres and circles answer `false` at their
    /// centre and axis, where the nearest point is not unique.
    fn contains(&self, x: E3<T>) -> Result<bool> {
        self.contains_within(x, T::zero())
    }

    /// [`Nearest::contains`] with `slack` added to the tolerance: for a point known only to
    /// within `slack` (a point pair's end far from the origin, [`Bivector::intersect`]).
    fn contains_within(&self, x: E3<T>, slack: T) -> Result<bool> {
        Ok(on(x, self.nearest_point(x)?, slack))
    }
}

/// `|x − y| ≤ 64 ε (|x| + |y|) + slack`: `x` is its nearest point `y` to rounding.
fn on<T: Real>(x: E3<T>, y: E3<T>, slack: T) -> bool {
    distance(x, y) <= T::from_f64(64.0) * T::epsilon() * (norm(x) + norm(y)) + slack
}

/// [`Nearest::contains_within`] for rounds: `false` where every point is nearest
/// (`Degenerate` from a valid object).
fn on_round<T: Real>(x: E3<T>, nearest: Result<E3<T>>, valid: Result<()>, slack: T) -> Result<bool> {
    match nearest {
        Err(GeometryError::Degenerate) => valid.map(|()| false),
        y => Ok(on(x, y?, slack)),
    }
}

impl<T: Real> Nearest<T> for Line<T> {
    /// `p + ((x − p)·d) d` for the line's point `p` and unit direction `d`.
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>> {
        let (p, d) = (self.point()?, self.direction()?);
        Ok(add(p, scale(d, dot(sub(x, p), d))))
    }
}

impl<T: Real> Nearest<T> for Plane<T> {
    /// `x − (n·x − δ) n` for the plane `n·x = δ`.
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>> {
        let (n, d) = self.normal_offset()?;
        Ok(sub(x, scale(n, dot(n, x) - d)))
    }
}

impl<T: Real> Nearest<T> for Sphere<T> {
    /// `c + r (x − c)/|x − c|`; `Degenerate` at the centre, where every point is nearest.
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>> {
        let (c, r) = self.centre_radius()?;
        let u = unit(sub(x, c)).ok_or(GeometryError::Degenerate)?;
        Ok(add(c, scale(u, r)))
    }

    fn contains_within(&self, x: E3<T>, slack: T) -> Result<bool> {
        on_round(x, self.nearest_point(x), self.centre_radius().map(|_| ()), slack)
    }
}

impl<T: Real> Nearest<T> for Circle<T> {
    /// `c + r ŷ` with `y` the offset `x − c` projected into the circle's plane; `Degenerate`
    /// on the axis, where every point of the circle is nearest.
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>> {
        let (c, n, r) = self.centre_normal_radius()?;
        let v = sub(x, c);
        let y = sub(v, scale(n, dot(v, n)));
        let u = unit(y).ok_or(GeometryError::Degenerate)?;
        if norm(y) <= T::from_f64(16.0) * T::epsilon() * norm(v) {
            return Err(GeometryError::Degenerate);
        }
        Ok(add(c, scale(u, r)))
    }

    fn contains_within(&self, x: E3<T>, slack: T) -> Result<bool> {
        on_round(x, self.nearest_point(x), self.centre_normal_radius().map(|_| ()), slack)
    }
}

impl<T: Real> Nearest<T> for Bivector<T> {
    /// The nearer of the pair's two points (the first on a tie); the pair's own
    /// read-back errors (`Imaginary`, `Degenerate`).
    fn nearest_point(&self, x: E3<T>) -> Result<E3<T>> {
        let [a, b] = self.end_points()?;
        Ok(if distance(x, b) < distance(x, a) { b } else { a })
    }
}

impl<T: Real> Nearest<T> for Vector<T> {
    /// A conformal point is its own nearest point (`down`).
    fn nearest_point(&self, _: E3<T>) -> Result<E3<T>> {
        down(*self)
    }
}

impl<T: Real> Vector<T> {
    /// The Euclidean point of `object` nearest this conformal point: `down(X)` projected
    /// ([`Nearest::nearest_point`]). `AtInfinity` for a point at infinity.
    pub fn project_onto<O: Nearest<T>>(&self, object: &O) -> Result<E3<T>> {
        object.nearest_point(down(*self)?)
    }

    /// `down(X) − project_onto(object)`: the rejection of the point from the object.
    pub fn reject_from<O: Nearest<T>>(&self, object: &O) -> Result<E3<T>> {
        object.rejection(down(*self)?)
    }
}

impl<T: Real> Line<T> {
    /// `|(x − p) × d|`, the distance of the point `x` from the line (`Degenerate` for a
    /// degenerate line).
    pub fn distance_to(&self, x: E3<T>) -> Result<T> {
        let (p, d) = (self.point()?, self.direction()?);
        Ok(norm(cross(sub(x, p), d)))
    }

    /// The closest points of two lines and their distance. For skew or crossing lines the
    /// points are unique: with `w = p2 − p1`, `n = d1 × d2`,
    /// `t1 = (w × d2)·n / |n|²`, `t2 = (w × d1)·n / |n|²`. For parallel lines (`|n|` within
    /// rounding of 0) every pair at the same height is closest: `Closest::parallel` is set and
    /// the points are `p1` and its foot on the other line.
    pub fn closest_points(&self, other: &Line<T>) -> Result<Closest<T>> {
        let (p1, d1, p2, d2) = (self.point()?, self.direction()?, other.point()?, other.direction()?);
        let w = sub(p2, p1);
        let n = cross(d1, d2);
        let n2 = dot(n, n);
        if norm(n) <= T::from_f64(16.0) * T::epsilon() {
            let foot = add(p2, scale(d2, dot(sub(p1, p2), d2)));
            return Ok(Closest { on_self: p1, on_other: foot, distance: distance(p1, foot), parallel: true });
        }
        let t1 = dot(cross(w, d2), n) / n2;
        let t2 = dot(cross(w, d1), n) / n2;
        let (a, b) = (add(p1, scale(d1, t1)), add(p2, scale(d2, t2)));
        Ok(Closest { on_self: a, on_other: b, distance: distance(a, b), parallel: false })
    }

    /// The angle between the two lines' directions, in `[0, π]` (`atan2(|d1 × d2|, d1·d2)`,
    /// accurate at every angle, unlike `acos`).
    pub fn angle_to(&self, other: &Line<T>) -> Result<T> {
        let (a, b) = (self.direction()?, other.direction()?);
        Ok(norm(cross(a, b)).atan2(dot(a, b)))
    }

    /// The angle between the line and a plane, in `[0, π/2]`: `atan2(|d·n|, |d × n|)` (0 for
    /// a line in or parallel to the plane, π/2 for one along the normal).
    pub fn angle_to_plane(&self, plane: &Plane<T>) -> Result<T> {
        let (d, (n, _)) = (self.direction()?, plane.normal_offset()?);
        Ok(dot(d, n).abs().atan2(norm(cross(d, n))))
    }

    /// The line projected onto a plane: the foot of its point and its direction with the
    /// normal part removed (`(L·Π) Π⁻¹`, in Euclidean terms). `Degenerate` for a line along
    /// the normal, whose projection is a point ([`Nearest::nearest_point`] of the plane).
    pub fn project_onto_plane(&self, plane: &Plane<T>) -> Result<Line<T>> {
        let (p, d, (n, _)) = (self.point()?, self.direction()?, plane.normal_offset()?);
        let along = sub(d, scale(n, dot(d, n)));
        if norm(along) <= T::from_f64(16.0) * T::epsilon() {
            return Err(GeometryError::Degenerate);
        }
        Line::from_point_direction(plane.nearest_point(p)?, along)
    }
}

impl<T: Real> Plane<T> {
    /// `n·x − δ`: the signed distance of `x` from the plane, positive on the normal's side.
    pub fn signed_distance(&self, x: E3<T>) -> Result<T> {
        let (n, d) = self.normal_offset()?;
        Ok(dot(n, x) - d)
    }

    /// The angle between the two planes' normals, in `[0, π]`.
    pub fn angle_to(&self, other: &Plane<T>) -> Result<T> {
        let ((a, _), (b, _)) = (self.normal_offset()?, other.normal_offset()?);
        Ok(norm(cross(a, b)).atan2(dot(a, b)))
    }
}

impl<T: Real> Sphere<T> {
    /// `|x − c| − r`: the signed distance of `x` from the sphere, negative inside.
    pub fn signed_distance(&self, x: E3<T>) -> Result<T> {
        let (c, r) = self.centre_radius()?;
        Ok(distance(x, c) - r)
    }
}

impl<T: Real> Circle<T> {
    /// The plane of the circle, normalised, oriented by the circle's normal.
    pub fn plane(&self) -> Result<Plane<T>> {
        let (c, n, _) = self.centre_normal_radius()?;
        Plane::from_point_normal(c, n)
    }

    /// The sphere of which the circle is a great circle (centre the circle's, same radius),
    /// from the read-back: `Sphere::new(c, r)`, oriented as that constructor orients (the
    /// opposite of clifford's `circle_to_sphere`, which gives `−sphere(c, r)`).
    pub fn carrier_sphere(&self) -> Result<Sphere<T>> {
        let (c, _, r) = self.centre_normal_radius()?;
        Sphere::from_centre_radius(c, r)
    }

    /// The tangent line of the circle at (the point of the circle nearest) `x`, directed
    /// along `n × (x − c)` (counter-clockwise about the circle's normal; clifford's
    /// `(x ⌋ C) ∧ ei` runs the other way).
    pub fn tangent_at(&self, x: E3<T>) -> Result<Line<T>> {
        let (c, n, _) = self.centre_normal_radius()?;
        let on = self.nearest_point(x)?;
        Line::from_point_direction(on, cross(n, sub(on, c)))
    }
}

/// The closest points of two lines ([`Line::closest_points`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closest<T> {
    /// The point on the first line.
    pub on_self: E3<T>,
    /// The point on the second line.
    pub on_other: E3<T>,
    /// Their distance.
    pub distance: T,
    /// The closest pair is one of many: parallel lines, and for
    /// [`Circle::closest_points_to_line`] and [`Circle::closest_points_to_circle`] a line
    /// along the circle's axis, coaxial circles, or a closest point on the other circle's
    /// axis.
    pub parallel: bool,
}

impl<T: Real> Line<T> {
    /// The join of the line and a point off it: the plane through both, with normal
    /// `d × (x − p)` (`L ∧ X` normalised, from the Euclidean data). `CollinearPoints` for a
    /// point on the line (within rounding of `|x − p|`), where the join is the line itself. The
    /// joins of points alone are the constructors `Line::through`, `Plane::through`,
    /// `Circle::through` and `Sphere::through`.
    pub fn join_point(&self, x: E3<T>) -> Result<Plane<T>> {
        let (p, d) = (self.point()?, self.direction()?);
        let v = sub(x, p);
        let n = cross(d, v);
        if norm(n) <= T::from_f64(16.0) * T::epsilon() * norm(v) {
            return Err(GeometryError::CollinearPoints);
        }
        Plane::from_point_normal(x, n)
    }

    /// The join of two lines that meet or are parallel: the plane holding both (normal
    /// `d1 × d2` for crossing lines, through their crossing; through the first and the
    /// second's point for parallel ones). `Skew` for lines that do neither (their join is
    /// all of space), `CollinearPoints` for the same line. Crossing means closer than
    /// rounding of the crossing's distance from the origin.
    pub fn join_line(&self, other: &Line<T>) -> Result<Plane<T>> {
        let k = self.closest_points(other)?;
        if k.parallel {
            return self.join_point(other.point()?);
        }
        let size = norm(k.on_self).max(norm(k.on_other));
        if k.distance > T::from_f64(64.0) * T::epsilon() * size {
            return Err(GeometryError::Skew);
        }
        Plane::from_point_normal(k.on_self, cross(self.direction()?, other.direction()?))
    }
}
