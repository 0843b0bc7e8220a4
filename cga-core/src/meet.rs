//! Meets of a line (a ray's carrier) with the primitives, classified and read back as
//! Euclidean points, and reflections of a line in a plane or a sphere.
//!
//! All meets are regressive products `L ∨ X` (the `&` operator). A round meet gives a
//! point pair `P` whose square classifies the hit: `P² > 0` two points, `P² = 0` tangent,
//! `P² < 0` none (an imaginary pair).

use crate::conformal::{Disk, GeometryError, Result, down};
use crate::euclid::{E3, dot, norm, sub, tolerance};
use crate::{Bivector, Circle, FlatPoint, InnerProduct, LeftContraction, Line, Plane, Real, Sphere, Vector};

/// How a line meets a round, from the sign of the meet's square.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// Two points (`P² > 0`).
    Two,
    /// One double point (`P² ≈ 0` to rounding).
    Tangent,
    /// No real point (`P² < 0`).
    Miss,
}

/// The meet of a line and a sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundMeet<T = f64> {
    /// `L ∨ S`.
    pub pair: Bivector<T>,
    /// `P²`.
    pub square: T,
    /// The classification of `square`.
    pub hit: Hit,
}

impl<T: Real> RoundMeet<T> {
    /// Classify `P` by the sign of `P²`, counting `|P²|` below rounding of its terms as zero.
    pub fn new(pair: Bivector<T>) -> Self {
        let square = pair.inner(pair).s;
        let size: T = pair.to_array().iter().fold(T::zero(), |m, &x| m + x * x);
        let hit = if square.abs() <= tolerance(size) {
            Hit::Tangent
        } else if square > T::zero() {
            Hit::Two
        } else {
            Hit::Miss
        };
        RoundMeet { pair, square, hit }
    }

    /// The points of the meet ordered along `line`'s direction (a tangent gives the touching
    /// point twice), `None` for a miss.
    pub fn points(&self, line: &Line<T>) -> Option<[E3<T>; 2]> {
        self.points_along(line.direction().ok()?)
    }

    /// The points of the meet ordered along the direction `d` (the carrier's; it need not be
    /// unit), `None` for a miss: `A, B ∝ (P ∓ √P²)(ei ⌋ P)`, whose grade-1 parts are
    /// `P·(ei ⌋ P) ∓ √P² (ei ⌋ P)` (the inner product computes only that part).
    pub fn points_along(&self, d: E3<T>) -> Option<[E3<T>; 2]> {
        let e = crate::ei::<T>().lc(self.pair);
        let pe = self.pair | e;
        let [a, b] = match self.hit {
            Hit::Miss => return None,
            Hit::Two => {
                let s = self.square.sqrt();
                [down(pe - e.scale(s))?, down(pe + e.scale(s))?]
            }
            // The double point: √P² = 0 in the same formula.
            Hit::Tangent => {
                let p = down(pe)?;
                [p, p]
            }
        };
        Some(if dot(sub(b, a), d) < T::zero() { [b, a] } else { [a, b] })
    }
}

impl<T: Real> FlatPoint<T> {
    /// The Euclidean point of a flat point `λ(x ∧ ei + eo ∧ ei)`, `None` at infinity (a line
    /// parallel to the plane it met).
    pub fn point(&self) -> Option<E3<T>> {
        let x = [self.e1i, self.e2i, self.e3i];
        let inv = T::one() / self.eoi;
        let scale_ = x.iter().fold(T::zero(), |m, v| if v.abs() > m { v.abs() } else { m });
        (self.eoi.abs() > tolerance(scale_) && inv.is_finite()).then(|| x.map(|v| v * inv))
    }
}

impl<T: Real> Line<T> {
    /// `L ∨ S`, classified.
    #[inline]
    pub fn meet_sphere(&self, sphere: &Sphere<T>) -> RoundMeet<T> {
        RoundMeet::new(*self & *sphere)
    }

    /// The point where the line crosses `plane` (`L ∨ P`, a flat point `λ(x ∧ ei + eo ∧ ei)`),
    /// `None` when they are parallel.
    pub fn meet_plane(&self, plane: &Plane<T>) -> Option<E3<T>> {
        (*self & *plane).point()
    }

    /// The point where the line crosses `disk` (its plane, within the rim), if it does.
    pub fn meet_disk(&self, disk: &Disk<T>) -> Option<E3<T>> {
        let x = self.meet_plane(&disk.plane)?;
        (norm(sub(x, disk.centre)) <= disk.radius).then_some(x)
    }

    /// `C ∨ L`, a vector (dual sphere): its square is zero exactly when the line touches the
    /// circle, the condition `(C_α ∨ L)² = 0` of evolved-surface hits.
    #[inline]
    pub fn meet_circle(&self, circle: &Circle<T>) -> Vector<T> {
        *circle & *self
    }

    /// The line reflected in `plane`: `P L P`, directed away from the mirror (for a ray
    /// along `d` the result runs along `d − 2(d·n)n`). `L' − L` is then the normal line.
    #[inline]
    pub fn reflect_in_plane(&self, plane: &Plane<T>) -> Line<T> {
        Line::from_storage(&((*plane * *self) * *plane).to_storage())
    }

    /// The line reflected in `sphere` at the point `at` of the sphere: reflection in the
    /// tangent plane there. (Inversion `σ L σ` gives a circle tangent to this line at `at`.)
    pub fn reflect_in_sphere(&self, sphere: &Sphere<T>, at: E3<T>) -> Result<Line<T>> {
        let (centre, _) = sphere.centre_radius()?;
        let tangent = Plane::from_point_normal(at, sub(at, centre)).map_err(|_| GeometryError::Degenerate)?;
        Ok(self.reflect_in_plane(&tangent))
    }
}
