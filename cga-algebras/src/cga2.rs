//! 2D conformal geometric algebra G(3,1): the plane's points as null vectors
//! `X = x + ½x² ei + eo`, with `eo = ½(e4 − e3)`, `ei = e3 + e4` (`e3² = 1`, `e4² = −1`,
//! `eo · ei = −1`), as cga-core does in 3D.
//!
//! - `X1 ∧ X2` is a point pair, `X1 ∧ X2 ∧ X3` the circle (or line, with `ei`) through three
//!   points; a point `X` lies on a circle `C` when `X ∧ C = 0`.
//! - Rotors `exp(−½θ e12)` and translators `1 − ½ t ei` move by `V X Ṽ` (`sandwich`).
//!
//! The everyday calls (docs/PGA.md's "2D CGA and STA" gives kingdon's spelling beside
//! each): `Vector::up(x)` and `down()`; `Circle::through(a, b, c)`,
//! `Circle::line_through(p, q)` (a line is a circle through `ei`), `is_line`,
//! `centre_radius`, `line_point_direction`; `PointPair::through(a, b)` and `ends()`; rotors
//! `Rotor::from_angle(θ)`, motors `Motor::translator(t)` and `Motor::rotation_about(c, θ)`.
//! Two circles or lines meet in a point pair, their regressive product `c1 & c2`, read by
//! `ends()` (`Imaginary` where they miss); a pair's ends are `(T ∓ √T²)(−ei ⌋ T)⁻¹`, the
//! order of the wedge `up(a) ∧ up(b)`.
//!
//! ```
//! use cga_algebras::cga2::prelude::*;
//! let circle = Circle::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]).unwrap();
//! let line = Circle::line_through([-2.0, 0.5], [2.0, 0.5]).unwrap();
//! let [a, b] = (line & circle).ends().unwrap();
//! let x = 0.75f64.sqrt();
//! assert!(a.iter().zip(b).all(|(p, q)| (p.abs() - q.abs()).abs() < 1e-12));
//! assert!(((a[0].abs() - x).abs() < 1e-12) && ((a[1] - 0.5).abs() < 1e-12));
//! ```

use crate::Real;

mod construct;
mod error;

pub use error::Cga2Error;

cga_macros::algebra! {
    scalar = crate::Real;
    scalars = [f32, f64];
    lanes = cga_core::simd;
    prelude = f64;
    signature = (3, 1);
    basis = [e1, e2, eo = 0.5 * (e4 - e3), ei = e3 + e4];

    /// All 16 coefficients in the orthonormal basis `e1..e4`.
    dense Multivector;

    /// A scalar.
    type Scalar = [s];
    /// A conformal point, a dual circle or a dual line.
    versor Vector = [grade(1)];
    /// A point pair `X1 ∧ X2`.
    type PointPair = [grade(2)];
    /// A circle `X1 ∧ X2 ∧ X3`, or a line `X1 ∧ X2 ∧ ei`.
    type Circle = [grade(3)];
    /// The pseudoscalar.
    type Pseudoscalar = [grade(4)];
    /// A rotation about the origin.
    versor Rotor = [s, e12];
    /// A rigid motion of the plane.
    versor Motor = [s, e12, e1i, e2i];
    /// The even subalgebra.
    versor Even = [s, grade(2), grade(4)];
}

impl<T: Real> Vector<T> {
    /// `up(x) = x + ½x² ei + eo`.
    pub fn up([x, y]: [T; 2]) -> Self {
        let half = T::from_f64(0.5);
        Vector { e1: x, e2: y, eo: T::one(), ei: half * (x * x + y * y) }
    }

    /// The Euclidean point of a conformal point, `x / (−X · ei)`; `None` where the weight
    /// `−X · ei = eo`'s coefficient is zero or the division not finite.
    pub fn down(self) -> Option<[T; 2]> {
        let x = [self.e1 / self.eo, self.e2 / self.eo];
        x.iter().all(|c| c.is_finite()).then_some(x)
    }
}
