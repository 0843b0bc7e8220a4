//! 3D projective geometric algebra G(3,0,1), in the conventions of bivector.net and kingdon:
//! `e0² = 0`, `e1² = e2² = e3² = 1`, the pseudoscalar `e0123`.
//!
//! - A plane `a x + b y + c z + d = 0` is the vector `a e1 + b e2 + c e3 + d e0`.
//! - Blades are spelled as bivector.net and klein spell them: `e31 = −e13`, `e021 = −e012`,
//!   `e032 = −e023`; each field is the coefficient of the blade as spelled.
//! - A point `(x, y, z)` is the trivector `e123 + x e032 + y e013 + z e021`: weight `e123`,
//!   position over it.
//! - A line is a bivector: `P & Q` (the join, regressive product) through two points,
//!   `p ^ q` (the meet, outer product) of two planes.
//! - `dual` is the right complement against `e0123`; `norm` (= `bulk_norm`) and
//!   `weight_norm` are the bulk and weight norms.
//! - A motor `[s, grade(2), e0123]` moves by `M X M̃` (`sandwich`); two planes' product
//!   `q p` reflects in `p` then `q`: a rotation about their line, or a translation by twice
//!   their distance when parallel.
//!
//! The toolkit, in klein's conventions (the same as kingdon's; `docs/PGA.md` tabulates the
//! signs and each peer's spelling), one file per subject in `pga/`:
//!
//! - constructors and read-backs ([`Plane::from_normal_distance`], [`Plane::through`],
//!   [`Line::through`], [`Line::from_point_direction`], [`Line::direction`],
//!   [`Line::moment`], [`Point::ideal`]);
//! - motors ([`Motor::rotor`], [`Motor::translator`], [`Motor::from_rotor_translator`],
//!   [`Motor::screw`], [`Motor::apply`]);
//! - closed-form [`Line::exp_motor`] and [`Motor::log`] of screws, [`Motor::sqrt`],
//!   [`Motor::pow`], [`Motor::interpolate`], [`Motor::renormalise`];
//! - distances, angles and projections ([`Point::distance_to_line`],
//!   [`Line::distance_to_line`], [`Line::project_onto_plane`], …).
//!
//! ```
//! use cga_algebras::pga::{Line, Motor, Point};
//! let axis = Line::through([1.0, 0.0, 0.0], [1.0, 0.0, 1.0])?; // along +z through (1, 0, 0)
//! let screw = Motor::screw(axis, std::f64::consts::PI, 2.0)?; // half turn, 2 along +z
//! let x = screw.apply(Point::at([0.0, 0.0, 0.0])).position().unwrap();
//! assert!((x[0] - 2.0).abs() < 1e-12 && x[1].abs() < 1e-12 && (x[2] - 2.0).abs() < 1e-12);
//! let half = screw.sqrt()?; // the quarter turn, 1 along +z
//! assert!((half * half - screw).to_array().iter().all(|c| c.abs() < 1e-12));
//! let generator = screw.log()?; // (−θ + δ I) L̂ / 2
//! assert!((generator.exp_motor()? - screw).to_array().iter().all(|c| c.abs() < 1e-12));
//! let mid = Motor::interpolate(&Motor::identity(), &screw, 0.5)?;
//! assert!((mid - half).to_array().iter().all(|c| c.abs() < 1e-12));
//! # Ok::<(), cga_algebras::pga::PgaError>(())
//! ```

use crate::Real;

mod construct;
mod error;
mod exp_log;
mod metric;
mod motor;

pub use error::PgaError;

cga_macros::algebra! {
    scalar = crate::Real;
    scalars = [f32, f64];
    lanes = cga_core::simd;
    prelude = f64;
    signature = (3, 0, 1);
    basis = [e0 = e4, e1, e2, e3];

    /// All 16 coefficients in the orthonormal basis `e1, e2, e3, e4 = e0`.
    dense Multivector;

    /// A scalar.
    type Scalar = [s];
    /// A plane `a e1 + b e2 + c e3 + d e0`: `a x + b y + c z + d = 0`. A versor too: it
    /// reflects by `p X p̃` (up to the grade sign).
    versor Plane = [grade(1)];
    /// A line: the join of two points or the meet of two planes; direction `e12, e31, e23`,
    /// moment `e01, e02, e03`.
    type Line = [e01, e02, e03, e12, e31, e23];
    /// A point `w (e123 + x e032 + y e013 + z e021)`.
    type Point = [e021, e013, e032, e123];
    /// The pseudoscalar `e0123`.
    type Pseudoscalar = [grade(4)];
    /// A motor (rotation, translation, screw): the even subalgebra.
    versor Motor = [s, e01, e02, e03, e12, e31, e23, e0123];
}

impl<T: Real> Plane<T> {
    /// The plane `a x + b y + c z + d = 0`.
    pub fn new(a: T, b: T, c: T, d: T) -> Self {
        Plane { e0: d, e1: a, e2: b, e3: c }
    }
}

impl<T: Real> Point<T> {
    /// The point `(x, y, z)`, of weight 1: `e123 + x e032 + y e013 + z e021`.
    pub fn at([x, y, z]: [T; 3]) -> Self {
        Point { e021: z, e013: y, e032: x, e123: T::one() }
    }

    /// Its Euclidean position `(e032, e013, e021) / e123`; `None` for an ideal point
    /// (a direction: `e123 = 0`) or where the division is not finite.
    pub fn position(self) -> Option<[T; 3]> {
        let w = self.e123;
        let x = [self.e032 / w, self.e013 / w, self.e021 / w];
        x.iter().all(|c| c.is_finite()).then_some(x)
    }

    /// The point's orthogonal projection onto `plane`: `(P · p) ∧ p`, the meet of the plane
    /// with the line through the point perpendicular to it.
    pub fn project_onto_plane(self, plane: Plane<T>) -> Point<T> {
        self.inner(plane) ^ plane
    }

    /// The point's orthogonal projection onto `line`: `(P · L) ∧ L`, the meet of the line
    /// with the plane through the point perpendicular to it.
    pub fn project_onto_line(self, line: Line<T>) -> Point<T> {
        self.inner(line) ^ line
    }
}
