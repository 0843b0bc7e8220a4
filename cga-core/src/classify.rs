//! What an arbitrary blade is: a round (real, imaginary or tangent), a flat or a direction,
//! and its Euclidean parameters (Dorst, Fontijne and Mann, *Geometric Algebra for Computer
//! Science*, ch. 14–15, in this crate's OPNS reading: `X ∧ ei = 0` for flats).
//!
//! For a blade `X` of grade `k` with `Π = X ∧ ei` and `w = ei ⌋ X`:
//! - `w = 0` and `Π = 0`: a direction (a free blade `E ∧ ei`, no position);
//! - `Π = 0`, `w ≠ 0`: a flat (flat point, line, plane) read by the flat's own read-back;
//! - `Π ≠ 0`: a round, with centre `down(X ei X)` and `r² = σ_k ⟨X X⟩₀ / ⟨Π Π⟩₀`,
//!   `σ_k = +1, +1, −1, +1` for `k = 1 … 4` (a point pair, circle, sphere of radius 1
//!   measured give 1): real for `r² > 0`, imaginary for `r² < 0`, tangent (a point with a
//!   direction) for `r² = 0` to rounding. Grade 1 reads as a dual sphere or plane (a
//!   conformal point is the tangent, zero-radius case).
//!
//! Zero to rounding means within `64 ε` of the size of the terms that cancel: for `⟨X X⟩₀`
//! the products of coefficients it sums (so a round is tangent by the same test at any size
//! and distance), for `Π` and the flat readings the largest coefficient.

use crate::conformal::{GeometryError, Result, down, ei};
use crate::euclid::{E3, norm, unit};
use crate::{
    Bivector, Circle, FlatPoint, GeometricProduct, LeftContraction, Line, Multivector, Plane, Real, Sphere, Vector,
};

/// Whether a round is real, imaginary or a tangent (zero radius).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reality {
    /// `r² > 0`.
    Real,
    /// `r² < 0` (an imaginary sphere, circle or point pair).
    Imaginary,
    /// `r² = 0` to rounding: a point with a direction (or a conformal point).
    Tangent,
}

/// What a blade is, with its Euclidean parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind<T: Real> {
    /// Every coefficient zero.
    Zero,
    /// A round: a dual sphere (grade 1), point pair (2), circle (3) or sphere (4), with its
    /// centre and signed squared radius.
    Round {
        /// The grade of the blade.
        grade: usize,
        /// Real, imaginary or tangent.
        reality: Reality,
        /// The centre `down(X ei X)`.
        centre: E3<T>,
        /// `r²`, negative for an imaginary round.
        radius_squared: T,
        /// The carrier's unit direction, `−(ei ⌋ X)` read in Euclidean terms: for a point pair
        /// `A ∧ B` its axis along `b − a`, for a circle `A ∧ B ∧ C` its normal
        /// `(b − a) × (c − a)` (so a tangent's direction too); zero for a sphere and grade 1.
        direction: E3<T>,
    },
    /// A flat point `x ∧ ei`.
    FlatPoint(E3<T>),
    /// A line: a point (nearest the origin) and a unit direction.
    Line {
        /// The point nearest the origin.
        point: E3<T>,
        /// The unit direction.
        direction: E3<T>,
    },
    /// A plane `n · x = δ`, or a dual plane (grade 1).
    Plane {
        /// The grade of the blade (1 for a dual plane `n + δ ei`).
        grade: usize,
        /// The unit normal.
        normal: E3<T>,
        /// The offset `δ`.
        offset: T,
    },
    /// A direction: `ei` itself (grade 1), or a free blade `E ∧ ei` whose Euclidean part `E`
    /// is a vector (grade 2, `direction` is it) or a bivector (grade 3, `direction` is its
    /// normal); no position.
    Direction {
        /// The grade of the blade.
        grade: usize,
        /// The unit Euclidean direction (zero for `ei`).
        direction: E3<T>,
    },
}

fn largest<T: Real>(c: &[T]) -> T {
    c.iter().fold(T::zero(), |m, x| m.max(x.abs()))
}

/// `|x| ≤ 64 ε s`.
fn negligible<T: Real>(x: T, s: T) -> bool {
    x.abs() <= T::from_f64(64.0) * T::epsilon() * s
}

fn all_negligible<T: Real>(c: &[T], s: T) -> bool {
    c.iter().all(|x| negligible(*x, s))
}

/// The size of the terms that cancel in `⟨X X⟩₀`, a bound on its rounding: with `X` split
/// by whether its blades hold `eo` (`O`), `ei` (`I`), both or neither (`N`),
/// `⟨X X⟩₀ = ±|N|² − 2 O·I` term by term, so the terms are at most `|N|² + 2 |O| |I|`. Of
/// one unit whatever the blade's size and place (a round of radius `r` at `c` gives about
/// `w² (r² + |c|²)` for weight `w`), unlike the largest coefficient squared.
fn square_terms<T: Real>(names: &[&str], c: &[T]) -> T {
    let (mut n, mut o, mut i) = (T::zero(), T::zero(), T::zero());
    for (name, &x) in names.iter().zip(c) {
        match (name.contains('o'), name.contains('i')) {
            (true, false) => o = o + x * x,
            (false, true) => i = i + x * x,
            _ => n = n + x * x,
        }
    }
    n + T::from_f64(2.0) * (o * i).sqrt()
}

/// A round's centre and radius from `X`, `⟨X X⟩₀`, `⟨Π Π⟩₀` and `σ_k`; `terms` bounds the
/// rounding of `⟨X X⟩₀` ([`square_terms`]).
fn round<T: Real>(
    grade: usize,
    centre: Vector<T>,
    direction: E3<T>,
    xx: T,
    pp: T,
    sign: T,
    terms: T,
) -> Result<Kind<T>> {
    let centre = down(centre)?;
    let radius_squared = sign * xx / pp;
    let reality = if negligible(xx, terms) {
        Reality::Tangent
    } else if radius_squared > T::zero() {
        Reality::Real
    } else {
        Reality::Imaginary
    };
    let radius_squared = if reality == Reality::Tangent { T::zero() } else { radius_squared };
    Ok(Kind::Round { grade, reality, centre, radius_squared, direction })
}

impl<T: Real> Vector<T> {
    /// A grade-1 blade: a dual sphere (`Round`, a conformal point being its tangent,
    /// zero-radius case), a dual plane `n + δ ei`, or `ei` (a direction at infinity).
    pub fn classify(&self) -> Result<Kind<T>> {
        let size = largest(&self.to_array());
        if size == T::zero() {
            return Ok(Kind::Zero);
        }
        let w = self.eo; // −ei · X
        if negligible(w, size) {
            let n = [self.e1, self.e2, self.e3];
            return Ok(match unit(n) {
                Some(normal) if !all_negligible(&n, size) => {
                    Kind::Plane { grade: 1, normal, offset: self.ei / norm(n) }
                }
                _ => Kind::Direction { grade: 1, direction: [T::zero(); 3] },
            });
        }
        let pi = *self ^ ei::<T>();
        let terms = square_terms(&Self::BLADES, &self.to_array());
        round(1, *self, [T::zero(); 3], self.norm_squared(), pi.gp(pi).s, T::one(), terms)
    }
}

/// The flat reading of a grade-2 blade with `X ∧ ei = 0`: a flat point, or `t ∧ ei`.
fn flat_pair<T: Real>(x: &Bivector<T>, size: T) -> Kind<T> {
    let flat = FlatPoint::from_storage(&x.to_storage());
    match flat.point() {
        Some(p) if !negligible(flat.eoi, size) => Kind::FlatPoint(p),
        _ => Kind::Direction { grade: 2, direction: unit([flat.e1i, flat.e2i, flat.e3i]).unwrap_or([T::zero(); 3]) },
    }
}

/// The flat reading of a grade-3 blade: a line, or `B ∧ ei` (its normal).
fn flat_circle<T: Real>(x: &Circle<T>, _: T) -> Kind<T> {
    let line = Line::from_storage(&x.to_storage());
    match (line.point(), line.direction()) {
        (Ok(point), Ok(direction)) => Kind::Line { point, direction },
        _ => {
            Kind::Direction { grade: 3, direction: unit([line.e23i, -line.e13i, line.e12i]).unwrap_or([T::zero(); 3]) }
        }
    }
}

/// The flat reading of a grade-4 blade: a plane, or `e123 ∧ ei`.
fn flat_sphere<T: Real>(x: &Sphere<T>, _: T) -> Kind<T> {
    match Plane::from_storage(&x.to_storage()).normal_offset() {
        Ok((normal, offset)) => Kind::Plane { grade: 4, normal, offset },
        Err(_) => Kind::Direction { grade: 4, direction: [T::zero(); 3] },
    }
}

/// A point pair's unit axis: the Euclidean part of `−(ei ⌋ X)`, `b − a` for `X = A ∧ B`
/// (`ei ⌋ (A ∧ B) = −B + A` for normalised points).
fn pair_axis<T: Real>(x: &Bivector<T>) -> E3<T> {
    let w = ei::<T>().lc(*x);
    unit([-w.e1, -w.e2, -w.e3]).unwrap_or([T::zero(); 3])
}

/// A circle's unit normal: the Euclidean bivector of `−(ei ⌋ X)`, `(b − a) ∧ (c − a)` for
/// `X = A ∧ B ∧ C`, read as the vector `(b − a) × (c − a)` it is the dual of.
fn circle_normal<T: Real>(x: &Circle<T>) -> E3<T> {
    let w = ei::<T>().lc(*x);
    unit([-w.e23, w.e13, -w.e12]).unwrap_or([T::zero(); 3])
}

/// A sphere has no direction.
fn no_direction<T: Real>(_: &Sphere<T>) -> E3<T> {
    [T::zero(); 3]
}

/// `classify` for the blades of grade 2 … 4: zero, the flat reading when `X ∧ ei = 0`, else
/// a round with centre `down(X ei X)` and `r² = σ_k ⟨X X⟩₀ / ⟨Π Π⟩₀`.
macro_rules! classify_round {
    ($($ty:ident: $grade:literal, $sign:literal, $flat:ident, $direction:ident, $doc:literal;)*) => {$(
        impl<T: Real> $ty<T> {
            #[doc = $doc]
            pub fn classify(&self) -> Result<Kind<T>> {
                let size = largest(&self.to_array());
                if size == T::zero() {
                    return Ok(Kind::Zero);
                }
                let pi = *self ^ ei::<T>();
                if all_negligible(&pi.to_array(), size) {
                    return Ok($flat(self, size));
                }
                let centre = self.gp(ei::<T>()).gp(*self).grade1();
                let terms = square_terms(&Self::BLADES, &self.to_array());
                round($grade, centre, $direction(self), self.gp(*self).s, pi.gp(pi).s, T::from_f64($sign), terms)
            }
        }
    )*};
}

classify_round! {
    Bivector: 2, 1.0, flat_pair, pair_axis, "A grade-2 blade: a point pair (real, imaginary or tangent), a flat point, or a direction `t ∧ ei`.";
    Circle: 3, -1.0, flat_circle, circle_normal, "A grade-3 blade: a circle (real, imaginary or tangent), a line, or a direction `B ∧ ei` (`direction` the normal of the bivector `B`).";
    Sphere: 4, 1.0, flat_sphere, no_direction, "A grade-4 blade: a sphere (real, imaginary or tangent), a plane, or the direction `e123 ∧ ei`.";
}

/// The flats' own types, read as their grade's general type reads them.
macro_rules! classify_as {
    ($($ty:ident as $general:ident),*) => {$(
        impl<T: Real> $ty<T> {
            #[doc = concat!("The kind of this blade, as [`", stringify!($general), "::classify`] reads it (a ", stringify!($ty), " may also hold a direction, or zero).")]
            pub fn classify(&self) -> Result<Kind<T>> {
                $general::from_storage(&self.to_storage()).classify()
            }
        }
    )*};
}

classify_as!(FlatPoint as Bivector, Line as Circle, Plane as Sphere);

impl<T: Real> Multivector<T> {
    /// The kind of a dense blade: `NotABlade` unless it is of one grade from 1 to 4 with
    /// `X X̃` a scalar (to rounding), then as the typed `classify` of that grade. The dense
    /// type keeps the orthonormal basis, whose `e4`, `e5` coefficients mix the `eo` and `ei`
    /// ones: far from the origin (`|c|²`-sized beside `r`-sized) the small ones are lost in
    /// it; [`classify_storage`] reads a blade from null-basis coefficients as given.
    pub fn classify(&self) -> Result<Kind<T>> {
        if largest(&self.coeffs) == T::zero() {
            return Ok(Kind::Zero);
        }
        let k = blade_grade(&self.to_storage())?;
        match k {
            1 => Vector::from_dense(self).classify(),
            2 => Bivector::from_dense(self).classify(),
            3 => Circle::from_dense(self).classify(),
            _ => Sphere::from_dense(self).classify(),
        }
    }
}

/// The grade (1 … 4) of a blade given by its null-basis coefficients: `NotABlade` unless
/// they are of one grade (to rounding) with `X X̃` a scalar.
fn blade_grade<T: Real>(c: &[T; 32]) -> Result<usize> {
    let size = largest(c);
    let present = |index: &[usize]| index.iter().any(|&k| !negligible(c[k], size));
    let grades = [
        present(&[0]),
        present(&Vector::<T>::STORAGE_INDEX),
        present(&Bivector::<T>::STORAGE_INDEX),
        present(&Circle::<T>::STORAGE_INDEX),
        present(&Sphere::<T>::STORAGE_INDEX),
        present(&crate::Pseudoscalar::<T>::STORAGE_INDEX),
    ];
    let mut given = (0..=5).filter(|&k| grades[k]);
    let (Some(k @ 1..=4), None) = (given.next(), given.next()) else { return Err(GeometryError::NotABlade) };
    // A blade squares to a scalar; the dense square is exact enough for this test (its
    // rounding is relative to the largest coefficient, as the test is).
    let x = Multivector::from_storage(c);
    let square = (x * x.reverse()).to_storage();
    if !all_negligible(&square[1..], size * size) {
        return Err(GeometryError::NotABlade);
    }
    Ok(k)
}

/// The kind of a blade given by its null-basis coefficients (`to_storage` order), read as
/// given by the typed `classify` of its grade (see [`Multivector::classify`] for the
/// conditions). Coefficients given in the null basis carry a flat's zero `eo` parts exactly
/// (no flat gains them in a product with flats or motors), so a blade with nonzero `eo`
/// parts that the typed test reads as a flat (its `eo` parts within rounding of the rest:
/// the test is relative to the largest coefficient, so a round some 1.2e7 coordinate units from
/// the origin) is refused as [`GeometryError::Indistinct`] rather than drawn as a flat.
pub fn classify_storage<T: Real>(c: &[T; 32]) -> Result<Kind<T>> {
    if largest(c) == T::zero() {
        return Ok(Kind::Zero);
    }
    let k = blade_grade(c)?;
    let (names, index): (&[&str], &[usize]) = match k {
        1 => (&Vector::<T>::BLADES, &Vector::<T>::STORAGE_INDEX),
        2 => (&Bivector::<T>::BLADES, &Bivector::<T>::STORAGE_INDEX),
        3 => (&Circle::<T>::BLADES, &Circle::<T>::STORAGE_INDEX),
        _ => (&Sphere::<T>::BLADES, &Sphere::<T>::STORAGE_INDEX),
    };
    let round = names.iter().zip(index).any(|(n, &i)| n.contains('o') && !n.contains('i') && c[i] != T::zero());
    let kind = match k {
        1 => Vector::from_storage(c).classify(),
        2 => Bivector::from_storage(c).classify(),
        3 => Circle::from_storage(c).classify(),
        _ => Sphere::from_storage(c).classify(),
    }?;
    match kind {
        Kind::FlatPoint(_) | Kind::Line { .. } | Kind::Plane { .. } | Kind::Direction { .. } if round => {
            Err(GeometryError::Indistinct)
        }
        kind => Ok(kind),
    }
}
