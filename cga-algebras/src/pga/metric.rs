//! Distances, angles and projections, each a product of the objects read as a Euclidean
//! length: for weight-1 points `P`, `Q` and unit planes and lines,
//!
//! - `|P Q| = |direction(P & Q)|` (the join's direction is `q − p`);
//! - point to plane: `p & P = a x + b y + c z + d`, signed, positive on the normal's side;
//! - point to line: `|normal(P & L)|`, the plane through both;
//! - line to line: `|L₁ & L₂| / |d₁ × d₂|` for skew lines (`L₁ & L₂ = d₁ · m₂ + d₂ · m₁`, the
//!   signed volume they span), `|m₁ − m₂|` for parallel unit lines;
//! - projections: `(X · Y) Y`-type products, as klein's `kln::project`.

use super::error::{PgaError, finite};
use super::{InnerProduct, Line, Plane, Point};
use crate::Real;
use cga_core::euclid::{cross, dot, norm, sub};

/// `|w|`, or `IdealPoint` for `w = 0`.
fn weight<T: Real>(p: Point<T>) -> Result<T, PgaError> {
    finite((), &p.to_array())?;
    if p.e123 == T::zero() { Err(PgaError::IdealPoint) } else { Ok(p.e123.abs()) }
}

/// `|d|` of a line, or `IdealLine` for `d = 0`.
fn line_weight<T: Real>(l: Line<T>) -> Result<T, PgaError> {
    finite((), &l.to_array())?;
    let w = norm(l.direction());
    if w == T::zero() { Err(PgaError::IdealLine) } else { Ok(w) }
}

/// `|n|` of a plane, or `IdealPlane` for `n = 0`.
fn plane_weight<T: Real>(p: Plane<T>) -> Result<T, PgaError> {
    finite((), &p.to_array())?;
    let w = norm([p.e1, p.e2, p.e3]);
    if w == T::zero() { Err(PgaError::IdealPlane) } else { Ok(w) }
}

/// The angle `atan2(|a × b|, a · b) ∈ [0, π]` between two vectors (no `acos`: exact near 0
/// and π).
fn angle<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    norm(cross(a, b)).atan2(dot(a, b))
}

impl<T: Real> Point<T> {
    /// The Euclidean distance `|direction(P & Q)| / |w_P w_Q|` to `other` (klein: `(a &
    /// b).norm()`; kingdon: `(P & Q).norm()` for weight-1 points). `IdealPoint` for a point at
    /// infinity, `NonFinite` for a non-finite input or result.
    pub fn distance_to_point(self, other: Point<T>) -> Result<T, PgaError> {
        let w = weight(self)? * weight(other)?;
        let d = norm((self & other).direction()) / w;
        finite(d, &[d])
    }

    /// The signed distance `(p & P) / (|n| w)` to `plane`, `a x + b y + c z + d` for a unit
    /// normal: positive on the side the normal `(a, b, c)` points to. klein: `plane & point`
    /// is its negative, `point & plane` it (see `docs/PGA.md`); kingdon: `p & P` (`P & p` is
    /// its negative). `IdealPoint`, `IdealPlane`, `NonFinite` as their names say.
    pub fn distance_to_plane(self, plane: Plane<T>) -> Result<T, PgaError> {
        let w = self.e123;
        weight(self)?;
        let d = (plane & self).s / (plane_weight(plane)? * w);
        finite(d, &[d])
    }

    /// The distance `|n(P & L)| / (|w| |d|)` to `line`: the plane through the point and the
    /// line has a normal as long as the distance times their weights. `IdealPoint`,
    /// `IdealLine`, `NonFinite` as their names say.
    pub fn distance_to_line(self, line: Line<T>) -> Result<T, PgaError> {
        let w = weight(self)? * line_weight(line)?;
        let p = self & line;
        let d = norm([p.e1, p.e2, p.e3]) / w;
        finite(d, &[d])
    }
}

impl<T: Real> Line<T> {
    /// The distance between two lines: `|L₁ & L₂| / |d₁ × d₂|` for skew or crossing lines
    /// (`L₁ & L₂ = d₁ · m₂ + d₂ · m₁`, the signed volume they span), and `|m̂₁ − m̂₂|` of the
    /// unit moments of parallel lines (directions made to agree), where `|d̂₁ × d̂₂| ≤ √ε`.
    /// `IdealLine` for a line at infinity, `NonFinite` for a non-finite input or result.
    pub fn distance_to_line(self, other: Line<T>) -> Result<T, PgaError> {
        let (w1, w2) = (line_weight(self)?, line_weight(other)?);
        let (d1, d2) = (self.direction(), other.direction());
        let sin = norm(cross(d1, d2)) / (w1 * w2);
        let d = if sin > T::epsilon().sqrt() {
            (self & other).s.abs() / (w1 * w2 * sin)
        } else {
            let k = if dot(d1, d2) < T::zero() { -T::one() / w2 } else { T::one() / w2 };
            let m1 = self.moment().map(|c| c / w1);
            let m2 = other.moment().map(|c| c * k);
            norm(sub(m1, m2))
        };
        finite(d, &[d])
    }

    /// The angle in `[0, π]` between the lines' directions, `atan2(|d₁ × d₂|, d₁ · d₂)`
    /// (klein, kingdon: `acos` of the unit lines' `L₁ · L₂`, up to its sign). `IdealLine`
    /// for a line at infinity.
    pub fn angle_to_line(self, other: Line<T>) -> Result<T, PgaError> {
        line_weight(self)?;
        line_weight(other)?;
        Ok(angle(self.direction(), other.direction()))
    }

    /// The angle in `[0, π/2]` between the line and the plane, `atan2(|d · n|, |d × n|)`:
    /// zero for a line parallel to the plane. `IdealLine`, `IdealPlane` as their names say.
    pub fn angle_to_plane(self, plane: Plane<T>) -> Result<T, PgaError> {
        line_weight(self)?;
        plane_weight(plane)?;
        let (d, n) = (self.direction(), [plane.e1, plane.e2, plane.e3]);
        Ok(dot(d, n).abs().atan2(norm(cross(d, n))))
    }

    /// The line's orthogonal projection onto `plane`, `(L · p) ∧ p` (klein: `kln::project(l,
    /// p)`): the meet of the plane with the plane through the line perpendicular to it, of
    /// the same orientation as the line. A line perpendicular to the plane has none: the
    /// result is zero.
    pub fn project_onto_plane(self, plane: Plane<T>) -> Line<T> {
        self.inner(plane) ^ plane
    }

    /// The line through `point` parallel to the line, `(L · P) · P` (klein:
    /// `kln::project(l, a)`), of the line's orientation.
    pub fn project_onto_point(self, point: Point<T>) -> Line<T> {
        self.inner(point).inner(point).scale(-T::one())
    }
}

impl<T: Real> Plane<T> {
    /// The angle in `[0, π]` between the planes' normals, `atan2(|n₁ × n₂|, n₁ · n₂)`
    /// (klein, kingdon: `acos(p · q)` of unit planes). `IdealPlane` for a plane at infinity.
    pub fn angle_to_plane(self, other: Plane<T>) -> Result<T, PgaError> {
        plane_weight(self)?;
        plane_weight(other)?;
        Ok(angle([self.e1, self.e2, self.e3], [other.e1, other.e2, other.e3]))
    }

    /// The plane through `point` parallel to this one, `(p · P) P` (klein: `kln::project(p,
    /// a)`), of this plane's orientation.
    pub fn project_onto_point(self, point: Point<T>) -> Plane<T> {
        self.inner(point).inner(point).scale(-T::one())
    }
}
