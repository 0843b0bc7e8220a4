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

/// A classified meet: of a line and a sphere (`M` a point pair `L ∨ S`, the default) or of
/// a line and a circle (`M` the vector `C ∨ L`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundMeet<M = Bivector<f64>, T = f64> {
    /// The meet: `L ∨ S` or `C ∨ L`.
    pub pair: M,
    /// `P²`.
    pub square: T,
    /// The classification of `square`.
    pub hit: Hit,
}

impl<T: Real> RoundMeet<Bivector<T>, T> {
    /// Classify the meet `P = L ∨ S` of a line and a sphere whose norms multiply to
    /// `weight = |⟨L L̃⟩₀ ⟨S S̃⟩₀|` (1 when both are normalised).
    ///
    /// For a normalised line at distance `d` from the centre of a normalised sphere of
    /// radius `r`, `P² = (r² − d²) / r²` exactly: a number that does not change when the
    /// configuration is translated, rotated or uniformly scaled. The meet is
    /// [`Hit::Tangent`] when `|P²| ≤ 64 ε · weight`, that is when `|d − r| ≤ 32 ε r` (the
    /// pair's two points within `16 √ε r` of each other); [`Hit::Two`] or [`Hit::Miss`] by
    /// its sign otherwise.
    ///
    /// Rounding: the null-basis coefficients of a sphere of centre `c` grow like `|c|²/r`,
    /// and `P²` computed from them carries an error of about `3 ε (1 + ρ)²`, `ρ = |c| / r`
    /// (measured in `tests/tests/geometry/precision.rs` over distances 1 … 1e6 and radii 1e-4 … 1e4). So
    /// the classification agrees with the Euclidean one (`d < r` two points, `d > r` none)
    /// everywhere outside the band `|d − r| ≤ (32 + 4 (1 + ρ)²) ε r`. Build objects near the
    /// origin of their coordinates (a renderer's camera-relative frame, or the object's own)
    /// to keep `ρ` small.
    pub fn new(pair: Bivector<T>, weight: T) -> Self {
        let square = pair.inner(pair).s;
        let hit = if square.abs() <= tolerance(weight) {
            Hit::Tangent
        } else if square > T::zero() {
            Hit::Two
        } else {
            Hit::Miss
        };
        RoundMeet { pair, square, hit }
    }

    /// The points of the meet ordered along `line`'s direction (a tangent gives the touching
    /// point twice); `Imaginary` for a miss (the pair is imaginary).
    pub fn points(&self, line: &Line<T>) -> Result<[E3<T>; 2]> {
        self.points_along(line.direction()?)
    }

    /// The points of the meet ordered along the direction `d` (the carrier's; it need not be
    /// unit), `Imaginary` for a miss: `A, B ∝ (P ∓ √P²)(ei ⌋ P)`, whose grade-1 parts are
    /// `P·(ei ⌋ P) ∓ √P² (ei ⌋ P)` (the inner product computes only that part).
    pub fn points_along(&self, d: E3<T>) -> Result<[E3<T>; 2]> {
        let e = crate::ei::<T>().lc(self.pair);
        let pe = self.pair | e;
        let [a, b] = match self.hit {
            Hit::Miss => return Err(GeometryError::Imaginary),
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
        Ok(if dot(sub(b, a), d) < T::zero() { [b, a] } else { [a, b] })
    }
}

impl<T: Real> FlatPoint<T> {
    /// The Euclidean point of a flat point `λ(x ∧ ei + eo ∧ ei)`, `None` at infinity (`λ = 0`)
    /// or when `|λ| ≤ 64 ε weight`. For the meet `L ∨ Π` of a line and a plane whose norms
    /// multiply to `weight = √|⟨L L̃⟩₀ ⟨Π Π̃⟩₀|`, `λ = ±weight · (d · n)`: the test is then
    /// `|d · n| ≤ 64 ε` for the unit direction `d` and unit normal `n`, an angle, which no
    /// translation or scaling changes (a line that close to parallel meets the plane more than
    /// 1/(64 ε) times its distance from it away).
    pub fn point_with_weight(&self, weight: T) -> Option<E3<T>> {
        let inv = T::one() / self.eoi;
        (self.eoi.abs() > tolerance(weight) && inv.is_finite()).then(|| [self.e1i, self.e2i, self.e3i].map(|v| v * inv))
    }

    /// [`FlatPoint::point_with_weight`] for the meet of a normalised line and plane (weight 1).
    pub fn point(&self) -> Option<E3<T>> {
        self.point_with_weight(T::one())
    }
}

impl<T: Real> Line<T> {
    /// `L ∨ S`, classified by a tolerance that no translation or scaling of the pair changes
    /// (see [`RoundMeet::new`] for the band within which rounding can misclassify).
    #[inline]
    pub fn meet_sphere(&self, sphere: &Sphere<T>) -> RoundMeet<Bivector<T>, T> {
        let weight = (self.norm_squared() * sphere.norm_squared()).abs();
        RoundMeet::new(*self & *sphere, weight)
    }

    /// The point where the line crosses `plane` (`L ∨ P`, a flat point `λ(x ∧ ei + eo ∧ ei)`),
    /// `None` when they are parallel to within `|d · n| ≤ 64 ε` (see
    /// [`FlatPoint::point_with_weight`]). The point itself is accurate to about
    /// `ε (|x| + δ/|d · n|)`: as a plain-vector ray–plane solve.
    pub fn meet_plane(&self, plane: &Plane<T>) -> Option<E3<T>> {
        let weight = (self.norm_squared() * plane.norm_squared()).abs().sqrt();
        (*self & *plane).point_with_weight(weight)
    }

    /// The point where the line crosses `disk` (its plane, within the rim), if it does. The
    /// rim test `|x − c| ≤ r` is Euclidean, on the disk's exact centre and radius; it can err
    /// only for points within the crossing's own rounding (`ε |x|`) of the rim.
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

    /// `C ∨ L`, classified: [`Hit::Two`] when the line passes through the disk the circle
    /// bounds, [`Hit::Tangent`] when it meets the circle itself, [`Hit::Miss`] otherwise.
    ///
    /// For normalised operands `(C ∨ L)² = sin²θ (x² − r²) / r²`, `x` the distance from the
    /// centre at which the line crosses the circle's plane and `θ` its angle with that
    /// plane: a number no translation or scaling changes. `Tangent` when its size is at most
    /// `64 ε` of the operands' norms, so the rim band is `|x − r| ≤ 32 ε r / sin²θ` plus
    /// rounding, `≈ 4 (1 + ρ)² ε r / sin²θ` (ρ = |c|/r, measured in `tests/tests/geometry/precision.rs`).
    /// A line in the circle's plane (`|sin θ| ≤ 64 ε`, where the square vanishes
    /// identically) is classified as it meets the circle's sphere there: two points, a
    /// touch, or none.
    pub fn meet_circle_classified(&self, circle: &Circle<T>) -> RoundMeet<Vector<T>, T> {
        let dual = self.meet_circle(circle);
        let line_weight = self.norm_squared().abs();
        let weight = line_weight * circle.norm_squared().abs();
        let square = dual.norm_squared();
        let plane = circle.carrier_plane().try_normalise();
        // `L ∨ Π` for the unit plane is a flat point of weight `±|L| sin θ`.
        let parallel = plane.is_none_or(|p| (*self & p).eoi.abs() <= tolerance(line_weight.sqrt()));
        let hit = if parallel {
            plane.and_then(|p| self.meet_circle_in_its_plane(circle, &p)).unwrap_or(Hit::Miss)
        } else if square.abs() <= tolerance(weight) {
            Hit::Tangent
        } else if square < T::zero() {
            Hit::Two
        } else {
            Hit::Miss
        };
        RoundMeet { pair: dual, square, hit }
    }

    /// For a line parallel to the circle's (unit) plane: how it meets the circle's sphere if
    /// it lies in the plane to within the meet's rounding `64 ε (1 + ρ)² r`, `None` if it
    /// lies off the plane (or the circle has no centre).
    fn meet_circle_in_its_plane(&self, circle: &Circle<T>, plane: &Plane<T>) -> Option<Hit> {
        let (c, _, r) = circle.centre_normal_radius().ok()?;
        let meet = self.meet_sphere(&Sphere::from_centre_radius(c, r).ok()?);
        let (n, delta) = plane.normal_offset().ok()?;
        let on_plane = |x: E3<T>| {
            let rho = T::one() + norm(c) / r;
            (dot(n, x) - delta).abs() <= tolerance(r * rho * rho)
        };
        match meet.points(self) {
            Ok([x, _]) => on_plane(x).then_some(meet.hit),
            Err(_) => Some(Hit::Miss),
        }
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
