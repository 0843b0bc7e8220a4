//! Planes, lines and points from Euclidean data, and their Euclidean read-backs.
//!
//! - A plane `a e1 + b e2 + c e3 + d e0` is `a x + b y + c z + d = 0`: normal `(a, b, c)`.
//! - A line `m₁ e01 + m₂ e02 + m₃ e03 + d₁ e23 + d₂ e31 + d₃ e12` has direction `d` and
//!   moment `m = p × d` about the origin (`p` any of its points): its Plücker coordinates
//!   `(d, m)`. The join `P & Q` of the points `p`, `q` (weight 1) has direction `q − p`.
//! - A point `w (e123 + x e032 + y e013 + z e021)`; `w = 0` is the point at infinity in the
//!   direction `(e032, e013, e021)`.

use super::error::{PgaError, finite};
use super::{Line, Plane, Point};
use crate::Real;
use cga_core::euclid::{cross, dot, norm, scale};

impl<T: Real> Plane<T> {
    /// The plane of the points `x` with `n̂ · x = d`, `n̂ = n / |n|`: `n̂₁ e1 + n̂₂ e2 + n̂₃ e3
    /// − d e0` (Hessian normal form: `d` the signed distance from the origin along `n`).
    /// klein: `kln::plane(a, b, c, −d)` with `(a, b, c)` unit; kingdon: `alg.vector(e1=a,
    /// e2=b, e3=c, e0=−d)`. `ZeroVector` for `n = 0`, `NonFinite` for a non-finite input.
    pub fn from_normal_distance(n: [T; 3], d: T) -> Result<Self, PgaError> {
        finite((), &[n[0], n[1], n[2], d])?;
        let len = norm(n);
        if len == T::zero() {
            return Err(PgaError::ZeroVector);
        }
        let [a, b, c] = scale(n, T::one() / len);
        Ok(Plane::new(a, b, c, -d))
    }

    /// The plane through three points, `A & B & C` (the join): its normal is
    /// `(b − a) × (c − a)` (the points counter-clockwise seen from the side it points to).
    /// `CoincidentPoints` when the points are collinear (the normal is zero), `NonFinite` for
    /// a non-finite input.
    pub fn through(a: [T; 3], b: [T; 3], c: [T; 3]) -> Result<Self, PgaError> {
        finite((), &[a, b, c].concat())?;
        let plane = Point::at(a) & Point::at(b) & Point::at(c);
        if plane.e1 == T::zero() && plane.e2 == T::zero() && plane.e3 == T::zero() {
            return Err(PgaError::CoincidentPoints);
        }
        Ok(plane)
    }

    /// The unit normal `n̂ = (e1, e2, e3) / |(e1, e2, e3)|` and the signed distance `d = −e0 / |(e1,
    /// e2, e3)|` of the origin's foot: the plane is `n̂ · x = d`. `IdealPlane` for the plane at
    /// infinity, `NonFinite` otherwise where it is not finite.
    pub fn normal_distance(self) -> Result<([T; 3], T), PgaError> {
        let n = [self.e1, self.e2, self.e3];
        finite((), &[self.e0, n[0], n[1], n[2]])?;
        let len = norm(n);
        if len == T::zero() {
            return Err(PgaError::IdealPlane);
        }
        let inv = T::one() / len;
        finite((scale(n, inv), -self.e0 * inv), &[inv])
    }
}

impl<T: Real> Line<T> {
    /// The line through `p` and `q`, directed from `p` to `q`: the join `P & Q` of the
    /// points of weight 1, with direction `q − p` and moment `p × q` (klein: `p & q`; kingdon:
    /// `P & Q`, the same coefficients). `CoincidentPoints` for `p = q`, `NonFinite` for a
    /// non-finite input.
    pub fn through(p: [T; 3], q: [T; 3]) -> Result<Self, PgaError> {
        finite((), &[p, q].concat())?;
        if p == q {
            return Err(PgaError::CoincidentPoints);
        }
        let line = Point::at(p) & Point::at(q);
        finite(line, &line.to_array())
    }

    /// The line through `p` with direction `d` (not normalised): `(p × d) · (e01, e02, e03) +
    /// d · (e23, e31, e12)`. `ZeroVector` for `d = 0`, `NonFinite` for a non-finite input.
    pub fn from_point_direction(p: [T; 3], d: [T; 3]) -> Result<Self, PgaError> {
        finite((), &[p, d].concat())?;
        if d.iter().all(|&c| c == T::zero()) {
            return Err(PgaError::ZeroVector);
        }
        Ok(Line::from_plucker(d, cross(p, d)))
    }

    /// The line of Plücker coordinates direction `d` and moment `m` (`m = p × d` for a point
    /// `p` on it; `d · m = 0` for a line): `m · (e01, e02, e03) + d · (e23, e31, e12)`.
    /// `d = 0` is a line at infinity.
    pub fn from_plucker(d: [T; 3], m: [T; 3]) -> Self {
        Line { e01: m[0], e02: m[1], e03: m[2], e12: d[2], e31: d[1], e23: d[0] }
    }

    /// The direction `(e23, e31, e12)`, as long as the line's weight: `q − p` for `P & Q`.
    pub fn direction(self) -> [T; 3] {
        [self.e23, self.e31, self.e12]
    }

    /// The moment `(e01, e02, e03)` about the origin: `p × d` for any point `p` on the line
    /// and its [`direction`](Self::direction) `d`.
    pub fn moment(self) -> [T; 3] {
        [self.e01, self.e02, self.e03]
    }

    /// The line's point nearest the origin, `d × m / |d|²`, and its unit direction `d / |d|`.
    /// `IdealLine` for a line at infinity (`d = 0`), `NonFinite` otherwise where it is not
    /// finite.
    pub fn point_direction(self) -> Result<([T; 3], [T; 3]), PgaError> {
        let (d, m) = (self.direction(), self.moment());
        finite((), &self.to_array())?;
        let len = norm(d);
        if len == T::zero() {
            return Err(PgaError::IdealLine);
        }
        let u = scale(d, T::one() / len);
        let p = scale(cross(u, m), T::one() / len);
        finite((p, u), &[p, u].concat())
    }

    /// The line scaled to unit direction, `L / |d|`, so that `L² = −1` (klein:
    /// `l.normalize()`; kingdon: `L.normalized()`). `IdealLine` for a line at infinity.
    pub fn unit(self) -> Result<Self, PgaError> {
        finite((), &self.to_array())?;
        let len = norm(self.direction());
        if len == T::zero() {
            return Err(PgaError::IdealLine);
        }
        let unit = self.scale(T::one() / len);
        finite(unit, &unit.to_array())
    }

    /// `d · m`: zero exactly for a line (the Plücker condition, `L ∧ L = 0`); nonzero for a
    /// general bivector, the generator of a screw.
    pub fn plucker_defect(self) -> T {
        dot(self.direction(), self.moment())
    }
}

impl<T: Real> Point<T> {
    /// The point at infinity in the direction `d`: `d₁ e032 + d₂ e013 + d₃ e021` (klein:
    /// `kln::direction(x, y, z)`).
    pub fn ideal([x, y, z]: [T; 3]) -> Self {
        Point { e021: z, e013: y, e032: x, e123: T::zero() }
    }

    /// The point `(x, y, z)` of weight `w`: `w e123 + w x e032 + w y e013 + w z e021`.
    pub fn at_weight([x, y, z]: [T; 3], w: T) -> Self {
        Point { e021: w * z, e013: w * y, e032: w * x, e123: w }
    }

    /// Its position as [`position`](Self::position), or which error: `IdealPoint` for
    /// `e123 = 0`, `NonFinite` where the division is not finite.
    pub fn try_position(self) -> Result<[T; 3], PgaError> {
        if self.e123 == T::zero() {
            return Err(PgaError::IdealPoint);
        }
        self.position().ok_or(PgaError::NonFinite)
    }
}
