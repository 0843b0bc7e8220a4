//! Reflections and inversions of any object: in a plane, a sphere, a point or a line.
//!
//! A unit dual plane `π = n + δ ei` (`π² = 1`) reflects a vector by `−π X π`; a dual sphere
//! `σ = up(c) − ½r² ei` inverts one by `−σ X σ / σ²`. Sandwiches are outermorphisms, so an
//! object `X = X1 ∧ … ∧ Xk` of grade `k`, built from points (and `ei`, which both fix up to
//! weight), goes to `(−1)^k V X V⁻¹`: the image of each of its points, wedged in the same
//! order. Points keep a positive weight (`|x − c|²/r²`… times theirs, for an inversion), and
//! objects the orientation that their points' images give them.

use crate::conformal::{GeometryError, Result};
use crate::euclid::{E3, add, scale, sub};
use crate::{Bivector, Circle, Line, Motor, Plane, Real, Rotor, Sandwich, Sphere, Translator, Vector};

/// Reflections and inversions, for every object type (points, point pairs, lines, circles,
/// planes, spheres).
pub trait Reflect<T: Real>: Sized + Copy {
    /// The type of an inversion's image: a line becomes a circle, a plane a sphere.
    type Inverted;

    /// `(−1)^k π X π` for the unit dual plane `π` of `plane`: the mirror image in the plane,
    /// the same type (a reflected line is a line). `Degenerate` for a zero plane.
    fn reflect_in(&self, plane: &Plane<T>) -> Result<Self>;

    /// `(−1)^k σ X σ⁻¹` for the dual sphere `σ` of `sphere`: the image under
    /// `x ↦ c + r² (x − c)/|x − c|²`; lines and planes not through `c` become circles and
    /// spheres. `Degenerate` for a sphere of zero radius; `AtInfinity` for a point at the
    /// centre (its image is the point at infinity).
    fn invert_in(&self, sphere: &Sphere<T>) -> Result<Self::Inverted>;

    /// The point reflection `x ↦ 2c − x` (a half turn about any line through `c` followed
    /// by the reflection in the plane through `c` perpendicular to it).
    fn reflect_in_point(&self, c: E3<T>) -> Self;

    /// The reflection in a line, `x ↦ 2 proj(x) − x`: the half turn about it (a motor, so
    /// orientation is kept). `Degenerate` for a degenerate line.
    fn reflect_in_line(&self, line: &Line<T>) -> Result<Self>;
}

/// The unit dual plane `n + δ ei` of a plane.
fn dual_plane<T: Real>(plane: &Plane<T>) -> Result<Vector<T>> {
    let (n, d) = plane.normal_offset()?;
    Ok(Vector { e1: n[0], e2: n[1], e3: n[2], eo: T::zero(), ei: d })
}

/// `σ⁻¹ = σ/σ²` for the dual sphere `σ` of `sphere` (any weight: `σ⁻¹ X σ⁻¹ σ²` is
/// `σ X σ⁻¹`, and the scale of `σ` cancels). `Degenerate` for a sphere of zero radius.
fn dual_sphere<T: Real>(sphere: &Sphere<T>) -> Result<Vector<T>> {
    let sigma = sphere.dual();
    let inv = sigma.scale(T::one() / sigma.norm_squared());
    let finite = inv.to_array().iter().all(|x| x.is_finite());
    if !finite || sigma.norm_squared() == T::zero() {
        return Err(GeometryError::Degenerate);
    }
    Ok(inv)
}

/// A point of nonzero weight sent to a vector of zero weight went to infinity.
fn point_to_infinity<T: Real>(x: &Vector<T>, image: &Vector<T>) -> Result<()> {
    // A point (null, `|X²|` within rounding of `2|eo ei| + |x|²`), not a dual sphere through
    // the centre, whose image is legitimately a plane.
    let size = (x.eo * x.ei).abs() * T::from_f64(2.0) + x.e1 * x.e1 + x.e2 * x.e2 + x.e3 * x.e3;
    let null = x.norm_squared().abs() <= T::from_f64(64.0) * T::epsilon() * size;
    let largest = image.to_array().iter().fold(T::zero(), |m, c| m.max(c.abs()));
    if x.eo != T::zero() && null && image.eo.abs() <= T::from_f64(64.0) * T::epsilon() * largest {
        return Err(GeometryError::AtInfinity);
    }
    Ok(())
}

/// Objects other than points have no such case.
fn no_check<X, Y>(_: &X, _: &Y) -> Result<()> {
    Ok(())
}

/// The half turn about the line through `p` with unit direction `a`, exactly: `R = −a I3`
/// (no `cos(π/2)` rounding), `t = p − R p R̃ = 2 (p − (p·a) a)`.
fn half_turn<T: Real>(p: E3<T>, a: E3<T>) -> Motor<T> {
    let r = Rotor { s: T::zero(), e12: -a[2], e13: a[1], e23: -a[0] };
    Motor::from_rotor_translator(r, Translator::from_vector(sub(p, r.rotate(p))))
}

macro_rules! reflect {
    ($($ty:ident: $grade:literal, $check:ident);*) => {$(
        impl<T: Real> Reflect<T> for $ty<T> {
            type Inverted = <Vector<T> as Sandwich<$ty<T>>>::Output;

            fn reflect_in(&self, plane: &Plane<T>) -> Result<Self> {
                let pi = dual_plane(plane)?;
                // π has no eo part, so the image's blades outside this type are exactly 0.
                let image = $ty::from_storage(&pi.sandwich(*self).to_storage());
                Ok(if $grade % 2 == 1 { -image } else { image })
            }

            fn invert_in(&self, sphere: &Sphere<T>) -> Result<Self::Inverted> {
                let inv = dual_sphere(sphere)?;
                let image = inv.sandwich(*self).scale(T::one() / inv.norm_squared());
                let image = if $grade % 2 == 1 { -image } else { image };
                if !image.to_array().iter().all(|x| x.is_finite()) {
                    return Err(GeometryError::Overflow);
                }
                $check(self, &image)?;
                Ok(image)
            }

            fn reflect_in_point(&self, c: E3<T>) -> Self {
                let e3 = [T::zero(), T::zero(), T::one()];
                let turned = half_turn(c, e3).sandwich(*self);
                let turned = $ty::from_storage(&turned.to_storage());
                let pi = Vector { e1: T::zero(), e2: T::zero(), e3: T::one(), eo: T::zero(), ei: c[2] };
                let image = $ty::from_storage(&pi.sandwich(turned).to_storage());
                if $grade % 2 == 1 { -image } else { image }
            }

            fn reflect_in_line(&self, line: &Line<T>) -> Result<Self> {
                let (p, a) = (line.point()?, line.direction()?);
                Ok($ty::from_storage(&half_turn(p, a).sandwich(*self).to_storage()))
            }
        }
    )*};
}

reflect!(Vector: 1, point_to_infinity; Bivector: 2, no_check; Line: 3, no_check; Circle: 3, no_check; Plane: 4, no_check; Sphere: 4, no_check);

/// The inverse of the point `x` in the sphere of centre `c` and radius `r` (the sphere
/// given as a blade), as a Euclidean point: `c + r² (x − c)/|x − c|²`, computed from the
/// Euclidean data (no conformal coordinates of `x`, so no `ε |x|²` loss); the sphere's own
/// read-back costs `ε (|x| + |c|) ρ` (`ρ = |c|/r`). `AtInfinity` at the
/// centre, `Imaginary`/`Degenerate` for a sphere that is not real.
pub fn invert_point<T: Real>(x: E3<T>, sphere: &Sphere<T>) -> Result<E3<T>> {
    let (c, r) = sphere.centre_radius()?;
    let d = sub(x, c);
    let d2 = crate::euclid::dot(d, d);
    let k = r * r / d2;
    if d2 == T::zero() || !k.is_finite() {
        return Err(GeometryError::AtInfinity);
    }
    Ok(add(c, scale(d, k)))
}

/// The mirror image of the point `x` in a plane, `x − 2 (n·x − δ) n`, from Euclidean data.
pub fn reflect_point<T: Real>(x: E3<T>, plane: &Plane<T>) -> Result<E3<T>> {
    let (n, d) = plane.normal_offset()?;
    Ok(sub(x, scale(n, T::from_f64(2.0) * (crate::euclid::dot(n, x) - d))))
}
