//! The conformal embedding and the objects of CGA: construction from Euclidean data and
//! the inverse (Euclidean parameters of an object). Objects are OPNS blades, normalised
//! as clifford's `.normal()`: `X / √|⟨X X̃⟩₀|`.
//!
//! Orientation: an object built from points keeps the order of its points (`Line::through
//! (a, b)` points from `a` to `b`; `Plane::through(a, b, c)` has normal `(b−a)×(c−a)`);
//! objects built from parameters take the orientation of the same construction from points.

use crate::euclid::{E3, add, cross, dot, norm, rescaled_differences, scale, sub, tolerance, unit};
use crate::{Bivector, Circle, Infinity, LeftContraction, Line, Plane, Real, Select, Sphere, Vector};

/// Why an object cannot be built or read back.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GeometryError {
    /// Two of the given points are the same point.
    #[error("two of the points coincide")]
    CoincidentPoints,
    /// The points lie on one line, so they span no circle or plane.
    #[error("the points are collinear")]
    CollinearPoints,
    /// The points lie in one plane (or on one circle), so they span no sphere.
    #[error("the points are coplanar")]
    CoplanarPoints,
    /// A radius is zero or negative.
    #[error("the radius is not positive")]
    ZeroRadius,
    /// A direction or normal is the zero vector.
    #[error("the direction or normal is zero")]
    ZeroVector,
    /// The object is flat (or the point at infinity): it has no finite centre or radius.
    #[error("the object is flat or at infinity")]
    AtInfinity,
    /// A round (sphere, circle, point pair) of negative squared radius.
    #[error("the round is imaginary (negative squared radius)")]
    Imaginary,
    /// The blade is zero or null and cannot be normalised.
    #[error("the object is degenerate (zero or null)")]
    Degenerate,
    /// Two lines that neither meet nor are parallel: no plane holds both.
    #[error("the lines are skew: no plane holds both")]
    Skew,
    /// Mixed grades, or `X X̃` not a scalar: not the blade of any object.
    #[error("the multivector is not a blade (mixed grades, or X X̃ is not a scalar)")]
    NotABlade,
    /// A blade whose `eo` coefficients are nonzero but within rounding of its others: a
    /// round too large, or too far from the origin, for f64 to tell it from a
    /// flat: its `eo` parts are about `2/max(|c|, r)²` of its largest coefficient, so from
    /// about `√(2/(64 ε))` ≈ 1.2e7 coordinate units from the origin, or that large, whatever
    /// its size.
    #[error(
        "the blade's eo coefficients are within rounding of its others: f64 cannot tell this round from a flat (a round about 1.2e7 coordinate units or more from the origin, or as large): build it nearer the origin"
    )]
    Indistinct,
    /// An input is infinite or NaN.
    #[error("an input is not finite")]
    NonFinite,
    /// The inputs are finite but the object's coefficients are not: they grow like `|x|²`
    /// (or `|x|²/r`), so coordinates beyond about 1e154 (f64) overflow.
    #[error("the coordinates are too large for the conformal representation (its coefficients overflow)")]
    Overflow,
}

/// Shorthand for results of this module.
pub type Result<T, E = GeometryError> = core::result::Result<T, E>;

/// `up(x) = x + ½x² ei + eo`: the null vector of a Euclidean point, with `up(x) · ei = −1`.
/// Takes anything that converts into `[T; 3]` (an array, glam's `DVec3`/`Vec3`).
#[inline]
pub fn up<T: Real>(x: impl Into<E3<T>>) -> Vector<T> {
    let x: E3<T> = x.into();
    let half = T::from_f64(0.5);
    Vector { e1: x[0], e2: x[1], e3: x[2], eo: T::one(), ei: half * dot(x, x) }
}

/// `down(X) = x / (−X · ei)`: the Euclidean point of a (finite) point of any weight, at any
/// distance and any size f64 holds; `AtInfinity` only for the point at infinity (`X · ei = 0`
/// exactly) or a point too far for f64 (the quotient overflows). Only the `e1, e2, e3, eo`
/// parts are read. A weight that is the rounding of a zero (a meet that should have
/// been at infinity) gives a distant point: callers that know their scales test the weight
/// themselves ([`FlatPoint::point_with_weight`](crate::FlatPoint::point_with_weight)).
#[inline]
pub fn down<T: Real>(p: Vector<T>) -> Result<E3<T>> {
    let x = [p.e1, p.e2, p.e3];
    let weight = p.eo; // −X · ei
    let inv = T::one() / weight;
    let point = if inv.is_finite() { scale(x, inv) } else { x.map(|v| v / weight) };
    if weight != T::zero() && point.iter().all(|v| v.is_finite()) { Ok(point) } else { Err(GeometryError::AtInfinity) }
}

/// [`down`] lane by lane ([`Select`]): the Euclidean point and where there is one (a weight
/// not zero and a finite quotient, as `down` decides it: where `1/w` overflows, the quotient
/// `x/w` itself). For one value the mask is `down(p).is_ok()`.
#[inline(always)]
pub fn down_lanes<T: Select>(p: Vector<T>) -> (E3<T>, T::Mask) {
    let x = [p.e1, p.e2, p.e3];
    let weight = p.eo; // −X · ei
    let inv = T::one() / weight;
    let finite = inv.finite();
    let point = if T::all(finite) { scale(x, inv) } else { x.map(|v| T::select(finite, v * inv, v / weight)) };
    let nonzero = weight.lt(T::zero()) | T::zero().lt(weight);
    (point, nonzero & point[0].finite() & point[1].finite() & point[2].finite())
}

/// `x` of a point of unit weight (`−X · ei = 1`: `up(x)`, and its image under any rigid
/// motor): the `e1, e2, e3` parts, no division and no check (for bulk work, where the
/// weight is known; [`down`] for any weight).
#[inline(always)]
pub fn down_unit<T: Real>(p: Vector<T>) -> E3<T> {
    [p.e1, p.e2, p.e3]
}

/// The point at infinity `ei`.
#[inline]
pub fn ei<T: Real>() -> Infinity<T> {
    Infinity { ei: T::one() }
}

/// The origin `eo = up(0)` (`eo · ei = −1`).
#[inline]
pub fn eo<T: Real>() -> Vector<T> {
    Vector { e1: T::zero(), e2: T::zero(), e3: T::zero(), eo: T::one(), ei: T::zero() }
}

fn finite<T: Real>(points: &[E3<T>]) -> Result<()> {
    if points.iter().flatten().all(|x| x.is_finite()) { Ok(()) } else { Err(GeometryError::NonFinite) }
}

/// Coincident points: within rounding (`64 ε`) of the largest coordinate, at any scale.
fn distinct<T: Real>(points: &[E3<T>]) -> Result<()> {
    finite(points)?;
    let tol = tolerance(points.iter().flatten().fold(T::zero(), |m, x| m.max(x.abs())));
    for (i, a) in points.iter().enumerate() {
        for b in &points[i + 1..] {
            if norm(sub(*a, *b)) <= tol {
                return Err(GeometryError::CoincidentPoints);
            }
        }
    }
    Ok(())
}

impl<T: Real> Line<T> {
    /// `up(a) ∧ up(b) ∧ ei`, normalised: the line through `a` and `b`, directed from `a` to `b`.
    ///
    /// Written down as [`Line::from_point_direction`]`(a, b − a)`, the same blade: the wedge
    /// of conformal points would square the coordinates (`½|a|²`), overflowing near 1e154 and
    /// cancelling to `ε |a|²` where the line's own coefficients are only of size `|a|`.
    pub fn through(a: E3<T>, b: E3<T>) -> Result<Self> {
        distinct(&[a, b])?;
        let d = sub(b, a);
        if !d.iter().all(|x| x.is_finite()) {
            return Err(GeometryError::Overflow);
        }
        let line = Self::from_point_direction(a, d)?;
        line.to_array().iter().all(|x| x.is_finite()).then_some(line).ok_or(GeometryError::Overflow)
    }

    /// [`Line::from_point_direction`]: the constructor a user looks for first.
    #[inline]
    pub fn new(point: E3<T>, direction: E3<T>) -> Result<Self> {
        Self::from_point_direction(point, direction)
    }

    /// The line through `p` with direction `d`, normalised: the same blade as
    /// `Line::through(p, p + d)` normalised, written down directly. For `L = up(a) ∧ up(b) ∧ ei`
    /// the `e_k o i` part is `(a − b)_k` and the `e_ij i` part the moment `a × b`; normalised,
    /// these are `−d̂` and `p × d̂` (six multiplications, one square root; no products of
    /// multivectors, as `up(x)` needs none).
    pub fn from_point_direction(p: E3<T>, d: E3<T>) -> Result<Self> {
        finite(&[p, d])?;
        let d = unit(d).ok_or(GeometryError::ZeroVector)?;
        Ok(Self::from_point_unit_direction(p, d))
    }

    /// [`Line::from_point_direction`] for a direction already of unit length and finite
    /// input, unchecked: `−d` and `p × d` (for the rays of a renderer, made by the million).
    #[inline(always)]
    pub fn from_point_unit_direction(p: E3<T>, d: E3<T>) -> Self {
        let m = cross(p, d);
        Line { e12i: m[2], e13i: -m[1], e23i: m[0], e1oi: -d[0], e2oi: -d[1], e3oi: -d[2] }
    }

    /// Unit direction: for `L = up(a) ∧ up(b) ∧ ei`, the `e_k o i` part is `(a − b)_k`,
    /// so the direction is `b − a` normalised.
    pub fn direction(&self) -> Result<E3<T>> {
        unit([-self.e1oi, -self.e2oi, -self.e3oi]).ok_or(GeometryError::Degenerate)
    }

    /// The point of the line nearest the origin, `d × m / |d|²`, with `d` the direction
    /// part and `m` the moment `a × b` read from the `e_ij i` part.
    pub fn point(&self) -> Result<E3<T>> {
        let d = [-self.e1oi, -self.e2oi, -self.e3oi];
        let m = [self.e23i, -self.e13i, self.e12i];
        let inv = T::one() / dot(d, d);
        if !inv.is_finite() {
            return Err(GeometryError::Degenerate);
        }
        Ok(scale(cross(d, m), inv))
    }
}

impl<T: Real> Plane<T> {
    /// `up(a) ∧ up(b) ∧ up(c) ∧ ei`, normalised: normal `(b − a) × (c − a)`.
    pub fn through(a: E3<T>, b: E3<T>, c: E3<T>) -> Result<Self> {
        distinct(&[a, b, c])?;
        // The differences scaled near 1 (exactly): the test below is scale-free, its products not.
        let ([_, u, v], _) = rescaled_differences([a, b, c]);
        let n = cross(u, v);
        if !n.iter().all(|x| x.is_finite()) {
            return Err(GeometryError::Overflow);
        }
        // Collinear: the sine of the angle at `a` is below rounding (a scale-free test).
        if norm(n) <= tolerance(norm(u) * norm(v)) {
            return Err(GeometryError::CollinearPoints);
        }
        // The same blade as the wedge of conformal points, written down without squaring them.
        Self::from_point_normal(a, n)
    }

    /// [`Plane::from_point_normal`]: the constructor a user looks for first.
    #[inline]
    pub fn new(point: E3<T>, normal: E3<T>) -> Result<Self> {
        Self::from_point_normal(point, normal)
    }

    /// The plane through `p` with normal `n`, normalised: the blade `Plane::through` gives for
    /// three points spanning it counter-clockwise about `n`, written down from its dual
    /// `P I5⁻¹ = −(n̂ + δ ei)`, `δ = n̂ · p` (no products).
    pub fn from_point_normal(p: E3<T>, n: E3<T>) -> Result<Self> {
        finite(&[p, n])?;
        let n = unit(n).ok_or(GeometryError::ZeroVector)?;
        let dual = Vector { e1: -n[0], e2: -n[1], e3: -n[2], eo: T::zero(), ei: -dot(n, p) };
        Ok(Plane::from_storage(&dual.undual().to_storage()))
    }

    /// `(n, δ)`: unit normal and signed distance from the origin, `n · x = δ` on the plane.
    /// The dual `P I5⁻¹ = −λ (n + δ ei)` with `λ > 0`.
    pub fn normal_offset(&self) -> Result<(E3<T>, T)> {
        let dual = self.dual();
        let v = [-dual.e1, -dual.e2, -dual.e3];
        let len = norm(v);
        let n = unit(v).ok_or(GeometryError::Degenerate)?;
        Ok((n, -dual.ei / len))
    }
}

impl<T: Real> Sphere<T> {
    /// `up(a) ∧ up(b) ∧ up(c) ∧ up(d)`, normalised.
    ///
    /// Written as [`Sphere::from_centre_radius`] of the circumsphere, from the differences
    /// `u = b − a`, `v = c − a`, `w = d − a`: centre
    /// `a + (|u|² v × w + |v|² w × u + |w|² u × v) / (2 u · (v × w))`, radius its distance
    /// from `a`, and the wedge's orientation, the sign of `−u · (v × w)`. Coplanar points
    /// (`|u · (v × w)|` below rounding of `|u| |v| |w|`) span no sphere. Accurate to `ε ρ²`
    /// where the wedge loses `ε ρ³`.
    pub fn through(a: E3<T>, b: E3<T>, c: E3<T>, d: E3<T>) -> Result<Self> {
        let (centre, radius, positive) = circumsphere(a, b, c, d)?;
        let sphere = Self::from_centre_radius(centre, radius)?;
        Ok(if positive { -sphere } else { sphere })
    }

    /// [`Sphere::from_centre_radius`]: the constructor a user looks for first.
    #[inline]
    pub fn new(centre: E3<T>, radius: T) -> Result<Self> {
        Self::from_centre_radius(centre, radius)
    }

    /// The sphere of centre `c` and radius `r`: `undual(σ)` with the dual sphere
    /// `σ = (up(c) − ½r² ei) / r`, normalised by construction (`σ² = 1`): dividing by the
    /// known `r` rather than by the computed `√|σ²|` avoids the cancellation `c² − (c² − r²)`
    /// in `σ²`, which would cost `ε (|c|/r)²` a second time.
    pub fn from_centre_radius(c: E3<T>, r: T) -> Result<Self> {
        Ok(Self::dual_of_centre_radius(c, r)?.undual())
    }

    /// The dual sphere `σ = (up(c) − ½r² ei) / r` of [`Sphere::from_centre_radius`].
    fn dual_of_centre_radius(c: E3<T>, r: T) -> Result<Vector<T>> {
        finite(&[c, [r, r, r]])?;
        if r <= T::zero() {
            return Err(GeometryError::ZeroRadius);
        }
        let mut dual = up(c);
        dual.ei = dual.ei - T::from_f64(0.5) * r * r;
        let dual = dual.scale(T::one() / r);
        // ½|c|²/r overflows long before the input does (|c| ≈ 1e154, or r tiny).
        dual.to_array().iter().all(|x| x.is_finite()).then_some(dual).ok_or(GeometryError::Overflow)
    }

    /// `(centre, radius)` from the dual `σ = S I5⁻¹ = λ(up(c) − ½r² ei)`: `c = σ₁₂₃/λ`,
    /// `r² = σ²/λ²` with `λ = σ_eo`.
    pub fn centre_radius(&self) -> Result<(E3<T>, T)> {
        round_centre_radius(self.dual())
    }
}

/// Centre and radius of a dual sphere `λ(up(c) − ½r² ei)`.
fn round_centre_radius<T: Real>(sigma: Vector<T>) -> Result<(E3<T>, T)> {
    let centre = down(sigma)?;
    let s2 = sigma.norm_squared(); // σ · σ = ⟨σ σ̃⟩₀ for a vector
    if s2 < T::zero() {
        return Err(GeometryError::Imaginary);
    }
    // `√(σ²)/|λ|`, not `√(σ²/λ²)`: λ = 1/r for a unit σ, whose square overflows for r below
    // 1e-154 (and r² underflows).
    Ok((centre, s2.sqrt() / sigma.eo.abs()))
}

/// The sphere through four points in Euclidean terms: its centre, its radius, and whether
/// `u · (v × w) > 0` for the differences `u = b − a`, `v = c − a`, `w = d − a` (the wedge
/// `up(a) ∧ up(b) ∧ up(c) ∧ up(d)` is then the negative of the sphere built from centre and
/// radius). Centre `a + (|u|² v × w + |v|² w × u + |w|² u × v) / (2 u · (v × w))`, computed on
/// the differences scaled near 1 by a power of two, so for points of any size; coplanar
/// points (`|u · (v × w)|` below rounding of `|u| |v| |w|`) span no sphere.
pub fn circumsphere<T: Real>(a: E3<T>, b: E3<T>, c: E3<T>, d: E3<T>) -> Result<(E3<T>, T, bool)> {
    distinct(&[a, b, c, d])?;
    let ([_, u, v, w], k) = rescaled_differences([a, b, c, d]);
    let volume = dot(u, cross(v, w));
    if volume.abs() <= tolerance(norm(u) * norm(v) * norm(w)) {
        return Err(GeometryError::CoplanarPoints);
    }
    let sum = add(add(scale(cross(v, w), dot(u, u)), scale(cross(w, u), dot(v, v))), scale(cross(u, v), dot(w, w)));
    let offset = scale(sum, k / (T::from_f64(2.0) * volume));
    let centre = add(a, offset);
    if !centre.iter().chain(&offset).all(|x| x.is_finite()) {
        return Err(GeometryError::Overflow);
    }
    Ok((centre, norm(offset), volume > T::zero()))
}

/// The circle through three points in Euclidean terms: centre
/// `a + (|u|² v × w + |v|² w × u) / (2|w|²)` for `u = b − a`, `v = c − a`, `w = u × v`, unit
/// normal along `w`, radius; on the differences scaled near 1 by a power of two, so for
/// points of any size. Coincident and collinear points are refused.
pub fn circumcircle<T: Real>(a: E3<T>, b: E3<T>, c: E3<T>) -> Result<(E3<T>, E3<T>, T)> {
    Plane::through(a, b, c)?; // rejects coincident and collinear points
    let ([_, u, v], k) = rescaled_differences([a, b, c]);
    let w = cross(u, v);
    let two_w2 = T::from_f64(2.0) * dot(w, w);
    let offset = scale(add(scale(cross(v, w), dot(u, u)), scale(cross(w, u), dot(v, v))), k / two_w2);
    let centre = add(a, offset);
    if !centre.iter().chain(&offset).all(|x| x.is_finite()) {
        return Err(GeometryError::Overflow);
    }
    Ok((centre, unit(w).ok_or(GeometryError::CollinearPoints)?, norm(offset)))
}

impl<T: Real> Circle<T> {
    /// `up(a) ∧ up(b) ∧ up(c)`, normalised: the circle through three points, its plane's
    /// normal `(b − a) × (c − a)`.
    ///
    /// Written as [`Circle::from_centre_normal_radius`] of the circumcircle, computed from the
    /// differences `u = b − a`, `v = c − a` (`w = u × v`): centre
    /// `a + (|u|² v × w + |v|² w × u) / (2|w|²)`, radius its distance from `a`, normal `w`.
    /// The same blade as the wedge, without the wedge's `ε ρ³` (it multiplies `½|a|²`-sized
    /// terms that cancel back to the circle's size): `ε ρ²`, `ρ = |centre|/radius`.
    pub fn through(a: E3<T>, b: E3<T>, c: E3<T>) -> Result<Self> {
        let (centre, normal, radius) = circumcircle(a, b, c)?;
        Self::from_centre_normal_radius(centre, normal, radius)
    }

    /// [`Circle::from_centre_normal_radius`]: the constructor a user looks for first.
    #[inline]
    pub fn new(centre: E3<T>, normal: E3<T>, radius: T) -> Result<Self> {
        Self::from_centre_normal_radius(centre, normal, radius)
    }

    /// The circle of centre `c`, plane normal `n` and radius `r`: the meet `S ∨ Π` of the
    /// sphere of centre `c` and radius `r` ([`Sphere::from_centre_radius`]) with the plane
    /// through `c` of normal `n` ([`Plane::from_point_normal`]), oriented as
    /// [`Circle::through`] orients three of its points counter-clockwise about `n`.
    ///
    /// Normalised by construction: the dual sphere and dual plane are unit (`σ² = π² = 1`)
    /// and orthogonal (`σ · π = 0`, the plane passes through the centre), so
    /// `(σ ∧ π)² = σ² π² − (σ · π)² = 1` with no division. The coefficients carry the
    /// circle to `ε (|c|/r)²` relative, the accuracy of the null-basis representation
    /// (built through three points it was `ε (|c|/r)³`).
    pub fn from_centre_normal_radius(c: E3<T>, n: E3<T>, r: T) -> Result<Self> {
        let sphere = Sphere::from_centre_radius(c, r)?;
        let plane = Plane::from_point_normal(c, n)?;
        let meet = sphere & plane;
        meet.to_array().iter().all(|x| x.is_finite()).then_some(-meet).ok_or(GeometryError::Overflow)
    }

    /// The plane of the circle, `C ∧ ei` (not normalised).
    pub fn carrier_plane(&self) -> Plane<T> {
        *self ^ ei()
    }

    /// `(centre, unit normal, radius)`: the centre is `down(C ei C)`, the normal that of
    /// the carrier plane `Π = C ∧ ei`, and `r² = −C² / Π²` (a real circle has `C² > 0`).
    /// `AtInfinity` for a line (`Π = 0`), `Imaginary` when `r² < 0`.
    pub fn centre_normal_radius(&self) -> Result<(E3<T>, E3<T>, T)> {
        let plane = self.carrier_plane();
        let (normal, _) = plane.normal_offset().map_err(|_| GeometryError::AtInfinity)?;
        let r2 = -(*self * *self).s / (plane * plane).s;
        if !r2.is_finite() {
            return Err(GeometryError::AtInfinity);
        }
        if r2 < T::zero() {
            return Err(GeometryError::Imaginary);
        }
        let centre = down(((*self * ei()) * *self).grade1())?;
        Ok((centre, normal, r2.sqrt()))
    }
}

impl<T: Real> Bivector<T> {
    /// `up(a) ∧ up(b)`: the point pair of `a` and `b`.
    ///
    /// Built as the meet `L ∨ S` of the line from `a` to `b` and the sphere on their midpoint
    /// through both — unit by construction (`L` and `S` are) and then given the weight of
    /// the wedge, `|up(a) ∧ up(b)| = ½|a − b|²`, and its orientation (`ei ⌋ (A ∧ B) = A − B`).
    /// The wedge itself multiplies `½|a|²` by `½|b|²`-sized terms and cancels them back to
    /// `|a − b|²`, losing `ε ρ³` (`ρ = |a|/|a − b|`); this loses `ε ρ²`.
    pub fn from_points(a: E3<T>, b: E3<T>) -> Result<Self> {
        distinct(&[a, b])?;
        let half = T::from_f64(0.5);
        let d = sub(b, a);
        let mid = [0, 1, 2].map(|k| half * (a[k] + b[k]));
        let line = Line::from_point_direction(mid, d)?;
        let sphere = Sphere::from_centre_radius(mid, half * norm(d))?;
        let unit_pair = line & sphere;
        // Orientation: ei ⌋ P has Euclidean part a − b for P = up(a) ∧ up(b).
        let toward = crate::ei::<T>().lc(unit_pair);
        let sign = if dot([toward.e1, toward.e2, toward.e3], d) < T::zero() { T::one() } else { -T::one() };
        let pair = unit_pair.scale(sign * half * dot(d, d));
        pair.to_array().iter().all(|x| x.is_finite()).then_some(pair).ok_or(GeometryError::Overflow)
    }

    /// The two points of a real point pair `P = A ∧ B`, in that order:
    /// `A ∝ (P − √P²)(ei ⌋ P)`, `B ∝ (P + √P²)(ei ⌋ P)`. `Imaginary` when `P² < 0`,
    /// `Degenerate` when the two points coincide (`P² = 0`, a tangent).
    pub fn end_points(&self) -> Result<[E3<T>; 2]> {
        let sq = (*self * *self).s;
        if sq < T::zero() {
            return Err(GeometryError::Imaginary);
        }
        let s = sq.sqrt();
        let d = ei::<T>().lc(*self);
        let pd = (*self * d).grade1();
        let a = down(pd - d.scale(s)).map_err(|_| GeometryError::Degenerate)?;
        let b = down(pd + d.scale(s)).map_err(|_| GeometryError::Degenerate)?;
        if s <= T::zero() {
            return Err(GeometryError::Degenerate);
        }
        Ok([a, b])
    }
}

/// A disk: a circle and the plane it bounds a piece of, with the rim's centre and radius
/// read once (meets test every ray against them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk<T: Real = f64> {
    /// The rim.
    pub circle: Circle<T>,
    /// `C ∧ ei`, normalised.
    pub plane: Plane<T>,
    /// The rim's centre.
    pub centre: E3<T>,
    /// The rim's radius.
    pub radius: T,
}

impl<T: Real> Disk<T> {
    /// The disk bounded by `circle` (centre and radius read back from the blade, so to its
    /// accuracy; prefer [`Disk::from_centre_normal_radius`] when they are known).
    pub fn new(circle: Circle<T>) -> Result<Self> {
        let plane = circle.carrier_plane().try_normalise().ok_or(GeometryError::AtInfinity)?;
        let (centre, _, radius) = circle.centre_normal_radius()?;
        Ok(Disk { circle, plane, centre, radius })
    }

    /// The disk of centre `c`, normal `n` and radius `r`: the rim
    /// [`Circle::from_centre_normal_radius`], its carrier plane, and `c` and `r` kept
    /// exactly as given (the meets test every ray against them).
    pub fn from_centre_normal_radius(c: E3<T>, n: E3<T>, r: T) -> Result<Self> {
        let circle = Circle::from_centre_normal_radius(c, n, r)?;
        let plane = circle.carrier_plane().try_normalise().ok_or(GeometryError::AtInfinity)?;
        Ok(Disk { circle, plane, centre: c, radius: r })
    }
}
