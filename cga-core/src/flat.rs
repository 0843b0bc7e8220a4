//! Flats in Euclidean terms — a point, a line or a plane — and the orthogonal projection of
//! any flat onto any flat.
//!
//! The blade formula `(A ⌋ B) B⁻¹` projects a flat `A` onto a flat `B` of the same or higher
//! grade, and vanishes where the image is smaller than `A` (two perpendicular lines) or where
//! `A` has the higher grade (a plane onto a line). [`Flat::project_onto`] gives the set that
//! the orthogonal projection onto `B` maps `A` to in every case: where the blade formula is
//! nonzero it is that flat (with `A`'s orientation, unit weight instead of `cos θ`), and where
//! it vanishes it is the point or line the blade cannot express. Each flat is read back
//! once and the rest is Euclid's, so the projection is as accurate as the read-backs.
//! [`Flat::reject_from`] gives the other part, `x − P(x)`, for which the blade formula
//! `(A ∧ B) B⁻¹` is zero for every pair of flats.

use crate::conformal::{GeometryError, Result, down};
use crate::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub};
use crate::{FlatPoint, Line, Plane, Real, Vector};

/// A flat, in Euclidean terms: what a projection of flats gives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Flat<T: Real = f64> {
    /// A point.
    Point(E3<T>),
    /// A line, normalised.
    Line(Line<T>),
    /// A plane, normalised.
    Plane(Plane<T>),
}

/// Objects that are flats: conformal points, flat points, lines, planes, Euclidean points.
pub trait AsFlat<T: Real> {
    /// The flat, read back: `AtInfinity` for a point or flat point at infinity, the
    /// read-back errors of lines and planes (`Degenerate`).
    fn flat(&self) -> Result<Flat<T>>;
}

impl<T: Real> AsFlat<T> for Flat<T> {
    fn flat(&self) -> Result<Flat<T>> {
        Ok(*self)
    }
}

impl<T: Real> AsFlat<T> for E3<T> {
    fn flat(&self) -> Result<Flat<T>> {
        Ok(Flat::Point(*self))
    }
}

impl<T: Real> AsFlat<T> for Vector<T> {
    /// The conformal point's Euclidean point (`down`).
    fn flat(&self) -> Result<Flat<T>> {
        Ok(Flat::Point(down(*self)?))
    }
}

impl<T: Real> AsFlat<T> for FlatPoint<T> {
    /// `x` of `λ(x ∧ ei + eo ∧ ei)`; `AtInfinity` for `λ` within rounding of 0.
    fn flat(&self) -> Result<Flat<T>> {
        let weight = norm([self.e1i, self.e2i, self.e3i]).max(self.eoi.abs());
        Ok(Flat::Point(self.point_with_weight(weight).ok_or(GeometryError::AtInfinity)?))
    }
}

impl<T: Real> AsFlat<T> for Line<T> {
    fn flat(&self) -> Result<Flat<T>> {
        Ok(Flat::Line(Line::from_point_direction(self.point()?, self.direction()?)?))
    }
}

impl<T: Real> AsFlat<T> for Plane<T> {
    fn flat(&self) -> Result<Flat<T>> {
        let (n, d) = self.normal_offset()?;
        Ok(Flat::Plane(Plane::from_point_normal(scale(n, d), n)?))
    }
}

/// A flat as a point and an orthonormal frame of its directions (`count` of them; a plane's
/// two are oriented so that `u × v` is its normal).
struct Frame<T> {
    point: E3<T>,
    dirs: [E3<T>; 2],
    count: usize,
}

impl<T: Real> Flat<T> {
    fn frame(&self) -> Result<Frame<T>> {
        let zero = [T::zero(); 3];
        Ok(match self {
            Flat::Point(x) => Frame { point: *x, dirs: [zero; 2], count: 0 },
            Flat::Line(l) => Frame { point: l.point()?, dirs: [l.direction()?, zero], count: 1 },
            Flat::Plane(p) => {
                let (n, d) = p.normal_offset()?;
                let u = perpendicular(n);
                Frame { point: scale(n, d), dirs: [u, cross(n, u)], count: 2 }
            }
        })
    }

    /// The set the orthogonal projection onto `onto` maps this flat to: with `q` a point of
    /// `onto` and `P(v) = Σ (v·b) b` over its orthonormal directions `b`, the flat through
    /// `q + P(p − q)` spanned by `P(a)` for this flat's directions `a`. Its dimension is the
    /// rank of those images (directions shorter than `16 ε` count as zero, the tolerance of
    /// [`Line::project_onto_plane`]): a line onto a plane is a line (a point, its foot, when
    /// the line is along the normal), a line onto a line is that line (the foot of the
    /// closest points when they are perpendicular), a plane onto a line is the line (the
    /// point where the line pierces the plane when it is along the normal), a plane onto a
    /// plane is that plane (their line of intersection when perpendicular), and anything
    /// onto a point is the point. Orientation: a flat onto one of its own dimension keeps
    /// the sign of `(A ⌋ B) B⁻¹` (a line `P(d)`, a plane the normal `P(u) × P(v) = (n·n₂) n₂`);
    /// a plane onto the whole of a line gives the line as it is, and onto a perpendicular
    /// plane their line directed along `n × n₂` (as [`Plane::intersect_plane`]).
    pub fn project_onto<B: AsFlat<T>>(&self, onto: &B) -> Result<Flat<T>> {
        let target = onto.flat()?;
        let (a, b) = (self.frame()?, target.frame()?);
        let along = |v: E3<T>| (0..b.count).fold([T::zero(); 3], |s, k| add(s, scale(b.dirs[k], dot(v, b.dirs[k]))));
        let point = add(b.point, along(sub(a.point, b.point)));
        let small = T::from_f64(16.0) * T::epsilon();
        let images = [along(a.dirs[0]), along(a.dirs[1])];
        if a.count == 2 {
            let normal = cross(images[0], images[1]);
            if norm(normal) > small {
                return Ok(Flat::Plane(Plane::from_point_normal(point, normal)?));
            }
            if b.count == 2 {
                // Perpendicular planes: their line, directed as their meet (`n₁ × n₂`).
                let along = cross(cross(a.dirs[0], a.dirs[1]), cross(b.dirs[0], b.dirs[1]));
                return Ok(Flat::Line(Line::from_point_direction(point, along)?));
            }
        }
        let by_length = |x: &E3<T>, y: &E3<T>| norm(*x).partial_cmp(&norm(*y)).unwrap_or(core::cmp::Ordering::Equal);
        let longest = images[..a.count].iter().copied().max_by(by_length).filter(|d| norm(*d) > small);
        Ok(match longest {
            None => Flat::Point(point),
            // A plane onto the whole of a line.
            Some(_) if a.count > b.count => target,
            Some(d) => Flat::Line(Line::from_point_direction(point, d)?),
        })
    }

    /// The rejection of this flat from the flat `from`, the part of it perpendicular to
    /// `from`: the image of the flat under `x ↦ x − P(x)`, where `P` is the orthogonal
    /// projection onto `from` ([`Flat::project_onto`]), so that every point of this flat is
    /// `P(x) + R(x)` with `P(x)` in the projection and `R(x)` in the rejection. As
    /// [`Vector::reject_from`] gives a point's offset vector `x − P(x)`, the rejection lives
    /// in offsets: with `q` a point of `from`, it is `x − q` projected onto the orthogonal
    /// complement of `from`'s directions through the origin (the plane normal to a line,
    /// the line along a plane's normal, all of space for a point). A line crossing a plane
    /// rejects to the line along the normal through the origin, a line parallel to it to
    /// the one offset vector; a flat parallel to `from` rejects to a point. (The blade
    /// formula `(A ∧ B) B⁻¹` vanishes for every pair of flats, both holding `∞`.)
    pub fn reject_from<B: AsFlat<T>>(&self, from: &B) -> Result<Flat<T>> {
        let target = from.flat()?;
        let b = target.frame()?;
        let origin = [T::zero(); 3];
        let moved = self.translated(sub(origin, b.point))?;
        match target {
            Flat::Point(_) => Ok(moved),
            Flat::Line(_) => moved.project_onto(&Flat::Plane(Plane::from_point_normal(origin, b.dirs[0])?)),
            Flat::Plane(_) => {
                moved.project_onto(&Flat::Line(Line::from_point_direction(origin, cross(b.dirs[0], b.dirs[1]))?))
            }
        }
    }

    /// The flat moved by the vector `t`.
    fn translated(&self, t: E3<T>) -> Result<Flat<T>> {
        Ok(match self {
            Flat::Point(x) => Flat::Point(add(*x, t)),
            Flat::Line(l) => Flat::Line(Line::from_point_direction(add(l.point()?, t), l.direction()?)?),
            Flat::Plane(p) => {
                let (n, d) = p.normal_offset()?;
                Flat::Plane(Plane::from_point_normal(add(scale(n, d), t), n)?)
            }
        })
    }

    /// The flat's dimension: 0, 1 or 2.
    pub fn dimension(&self) -> usize {
        match self {
            Flat::Point(_) => 0,
            Flat::Line(_) => 1,
            Flat::Plane(_) => 2,
        }
    }
}

macro_rules! project_flats {
    ($($ty:ident),*) => {$(
        impl<T: Real> $ty<T> {
            /// The orthogonal projection of this flat onto the flat `onto` (a point, line
            /// or plane), as [`Flat::project_onto`]: `(A ⌋ B) B⁻¹` where that is nonzero,
            /// and the smaller image it cannot express where it vanishes.
            pub fn project_flat_onto<B: AsFlat<T>>(&self, onto: &B) -> Result<Flat<T>> {
                self.flat()?.project_onto(onto)
            }

            /// The rejection of this flat from the flat `from` (a point, line or plane), as
            /// [`Flat::reject_from`]: the image under `x ↦ x − P(x)`, `P` the orthogonal
            /// projection onto `from`.
            pub fn reject_flat_from<B: AsFlat<T>>(&self, from: &B) -> Result<Flat<T>> {
                self.flat()?.reject_from(from)
            }
        }
    )*};
}
project_flats!(Line, Plane, FlatPoint);

#[cfg(test)]
mod tests {
    use super::*;

    fn line(p: E3<f64>, d: E3<f64>) -> Line {
        Line::from_point_direction(p, d).unwrap()
    }

    fn plane(p: E3<f64>, n: E3<f64>) -> Plane {
        Plane::from_point_normal(p, n).unwrap()
    }

    #[test]
    fn perpendicular_flats_project_to_the_smaller_image() {
        // Two perpendicular lines: the foot of the closest points.
        let got =
            line([0.0, 0.0, 5.0], [1.0, 0.0, 0.0]).project_flat_onto(&line([0.0, 2.0, 0.0], [0.0, 0.0, 1.0])).unwrap();
        assert_eq!(got, Flat::Point([0.0, 2.0, 5.0]));
        // A plane onto a line along its normal: where the line pierces it.
        let got = plane([0.0, 0.0, 3.0], [0.0, 0.0, 1.0])
            .project_flat_onto(&line([1.0, 1.0, 0.0], [0.0, 0.0, -1.0]))
            .unwrap();
        assert_eq!(got, Flat::Point([1.0, 1.0, 3.0]));
        // Perpendicular planes: their line of intersection.
        let Flat::Line(l) = plane([0.0, 0.0, 3.0], [0.0, 0.0, 1.0])
            .project_flat_onto(&plane([2.0, 0.0, 0.0], [1.0, 0.0, 0.0]))
            .unwrap()
        else {
            panic!("a line")
        };
        assert_eq!(l.point().unwrap(), [2.0, 0.0, 3.0]);
        assert_eq!(l.direction().unwrap()[1].abs(), 1.0);
    }

    #[test]
    fn oblique_flats_keep_their_orientation() {
        let onto = line([0.0, 1.0, 0.0], [1.0, 0.0, 0.0]);
        let Flat::Line(l) = line([0.0, 0.0, 2.0], [-1.0, 1.0, 1.0]).project_flat_onto(&onto).unwrap() else {
            panic!("a line")
        };
        assert_eq!((l.point().unwrap(), l.direction().unwrap()), ([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]));
        let Flat::Plane(p) =
            plane([0.0, 0.0, 1.0], [0.0, -1.0, -1.0]).project_flat_onto(&plane([0.0; 3], [0.0, 0.0, 1.0])).unwrap()
        else {
            panic!("a plane")
        };
        assert_eq!(p.normal_offset().unwrap(), ([0.0, 0.0, -1.0], 0.0));
    }

    #[test]
    fn rejections_are_the_offsets_perpendicular_to_the_target() {
        let plane_z = plane([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]);
        // A line crossing a plane: every offset along the normal, a line through the origin.
        let Flat::Line(l) = line([1.0, 2.0, 0.0], [1.0, 0.0, 1.0]).reject_flat_from(&plane_z).unwrap() else {
            panic!("a line")
        };
        assert_eq!((l.point().unwrap(), l.direction().unwrap().map(f64::abs)), ([0.0; 3], [0.0, 0.0, 1.0]));
        // A line parallel to the plane: its one offset.
        let Flat::Point(x) = line([1.0, 2.0, 5.0], [1.0, 1.0, 0.0]).reject_flat_from(&plane_z).unwrap() else {
            panic!("a point")
        };
        assert!(crate::distance(x, [0.0, 0.0, 3.0]) < 1e-15, "{x:?}");
        // A plane from a line in it: the plane's offsets from the line, normal to the line.
        let Flat::Line(l) = plane_z.reject_flat_from(&line([0.0, 1.0, 2.0], [1.0, 0.0, 0.0])).unwrap() else {
            panic!("a line")
        };
        assert_eq!((l.point().unwrap(), l.direction().unwrap().map(f64::abs)), ([0.0; 3], [0.0, 1.0, 0.0]));
        // From a point: the flat moved by minus the point.
        let got = line([1.0, 2.0, 3.0], [0.0, 1.0, 0.0]).reject_flat_from(&[1.0, 0.0, 3.0]).unwrap();
        assert_eq!(got, Flat::Line(line([0.0, 0.0, 0.0], [0.0, 1.0, 0.0])));
    }

    #[test]
    fn a_flat_point_at_infinity_is_refused() {
        let direction = FlatPoint { e1i: 1.0, e2i: 0.0, e3i: 0.0, eoi: 0.0 };
        assert_eq!(direction.flat(), Err(GeometryError::AtInfinity));
    }
}
