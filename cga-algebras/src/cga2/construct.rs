//! Circles, lines and point pairs of the plane from points, and their Euclidean read-backs;
//! rotors and translators.
//!
//! - `Circle::through(a, b, c) = A ∧ B ∧ C` (`X = up(x)`); a line is `A ∧ B ∧ ei`.
//! - A circle's dual `σ = C*` is the vector `w (c + ½(c² − r²) ei + eo)`: its centre is
//!   `(σ₁, σ₂) / w`, its radius `√(σ²) / |w|` (`σ² = w² r²`), with `w = −σ · ei`, the `eo`
//!   coefficient; a line has `w = 0`.
//! - A point pair `T = A ∧ B` has the ends `(T ∓ √(T²)) (−ei ⌋ T)⁻¹` (Dorst, Fontijne and
//!   Mann, *Geometric Algebra for Computer Science*, §14.2): `T² = (A · B)²` is `¼|a − b|⁴`.

use super::error::{Cga2Error, finite};
use super::{Circle, GeometricProduct, LeftContraction, Motor, Multivector, PointPair, Rotor, Vector};
use crate::Real;

/// `ei`, the point at infinity.
fn ei<T: Real>() -> Vector<T> {
    Vector { e1: T::zero(), e2: T::zero(), eo: T::zero(), ei: T::one() }
}

/// `Σ |c|`, the size a rounding test compares to.
fn size<T: Real>(c: &[T]) -> T {
    c.iter().fold(T::zero(), |s, &x| s + x.abs())
}

impl<T: Real> Circle<T> {
    /// The circle through three points, `up(a) ∧ up(b) ∧ up(c)` (counter-clockwise `a → b →
    /// c` gives one orientation, clockwise the other). `CoincidentPoints` when two coincide,
    /// `Collinear` when the three lie on a line (within `64 ε` of the points' scale; use
    /// [`line_through`](Self::line_through)), `NonFinite` for a non-finite input.
    pub fn through(a: [T; 2], b: [T; 2], c: [T; 2]) -> Result<Self, Cga2Error> {
        finite((), &[a, b, c].concat())?;
        if a == b || b == c || a == c {
            return Err(Cga2Error::CoincidentPoints);
        }
        // (b − a) × (c − a), against the product of the sides' lengths.
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
        let cross = u[0] * v[1] - u[1] * v[0];
        let scale = (u[0] * u[0] + u[1] * u[1]).sqrt() * (v[0] * v[0] + v[1] * v[1]).sqrt();
        if cross.abs() <= T::from_f64(64.0) * T::epsilon() * scale {
            return Err(Cga2Error::Collinear);
        }
        let circle = Vector::up(a) ^ Vector::up(b) ^ Vector::up(c);
        finite(circle, &circle.to_array())
    }

    /// The line through two points, `up(p) ∧ up(q) ∧ ei`, directed from `p` to `q`.
    /// `CoincidentPoints` for `p = q`, `NonFinite` for a non-finite input.
    pub fn line_through(p: [T; 2], q: [T; 2]) -> Result<Self, Cga2Error> {
        finite((), &[p, q].concat())?;
        if p == q {
            return Err(Cga2Error::CoincidentPoints);
        }
        let line = Vector::up(p) ^ Vector::up(q) ^ ei();
        finite(line, &line.to_array())
    }

    /// Whether it is a line: `C ∧ ei = 0` to rounding (its dual has no `eo`).
    pub fn is_line(self) -> bool {
        let sigma = self.dual();
        sigma.eo.abs() <= T::from_f64(64.0) * T::epsilon() * size(&sigma.to_array())
    }

    /// The centre and radius: `c = (σ₁, σ₂) / w`, `r = √(σ²) / |w|`, of the dual `σ = C*`
    /// (see the module). `IsLine` for a line, `Imaginary` for `σ² < 0` (an imaginary circle),
    /// `Degenerate` for zero, `NonFinite` otherwise where it is not finite.
    pub fn centre_radius(self) -> Result<([T; 2], T), Cga2Error> {
        finite((), &self.to_array())?;
        let sigma = self.dual();
        if sigma.to_array().iter().all(|&c| c == T::zero()) {
            return Err(Cga2Error::Degenerate);
        }
        if self.is_line() {
            return Err(Cga2Error::IsLine);
        }
        let w = sigma.eo;
        let centre = [sigma.e1 / w, sigma.e2 / w];
        let s2 = sigma.norm_squared() / (w * w);
        if s2 < T::zero() {
            return Err(Cga2Error::Imaginary);
        }
        let r = s2.sqrt();
        finite((centre, r), &[centre[0], centre[1], r])
    }

    /// A line's point nearest the origin and its unit direction (`p → q` for
    /// [`line_through`](Self::line_through)`(p, q)`). The dual of a line is `n + δ ei`, `n`
    /// its normal and `δ` the distance of the origin along `n`: the point is `δ n̂ / |n|`,
    /// the direction `n` turned by a quarter turn. `Degenerate` for a circle or zero.
    pub fn line_point_direction(self) -> Result<([T; 2], [T; 2]), Cga2Error> {
        finite((), &self.to_array())?;
        let sigma = self.dual();
        let n = [sigma.e1, sigma.e2];
        let len = (n[0] * n[0] + n[1] * n[1]).sqrt();
        if !self.is_line() || len == T::zero() {
            return Err(Cga2Error::Degenerate);
        }
        let u = [n[0] / len, n[1] / len];
        let delta = sigma.ei / len;
        // The sign of the turn that makes `line_through(p, q)` point from p to q.
        let out = ([u[0] * delta, u[1] * delta], [-u[1], u[0]]);
        finite(out, &[out.0[0], out.0[1]])
    }
}

impl<T: Real> PointPair<T> {
    /// The pair's two ends, `(T ∓ √(T²)) (−ei ⌋ T)⁻¹` (see the module): for `up(a) ∧ up(b)`
    /// the ends are `[a, b]`. `Imaginary` for `T² < 0` (an imaginary pair), `Degenerate`
    /// where `T² = 0` (a tangent, one point twice) or `−ei ⌋ T = 0` (a flat point or zero),
    /// `NonFinite` for a non-finite input or result.
    pub fn ends(self) -> Result<[[T; 2]; 2], Cga2Error> {
        finite((), &self.to_array())?;
        let t2 = self.dense().gp(self.dense()).coeffs[0];
        if t2 < T::zero() {
            return Err(Cga2Error::Imaginary);
        }
        let v: Vector<T> = -(ei::<T>().lc(self));
        let vv = v.norm_squared();
        if t2 == T::zero() || vv == T::zero() {
            return Err(Cga2Error::Degenerate);
        }
        let root = t2.sqrt();
        let inv = Multivector::from_storage(&(v / vv).to_storage());
        let end = |sign: T| -> Result<[T; 2], Cga2Error> {
            let mut t = self.dense();
            t.coeffs[0] = -sign * root;
            let x = Vector::from_storage(&t.gp(inv).grade(1).to_storage());
            x.down().ok_or(Cga2Error::NonFinite)
        };
        Ok([end(T::one())?, end(-T::one())?])
    }

    /// The point pair `up(a) ∧ up(b)`. `CoincidentPoints` for `a = b`, `NonFinite` for a
    /// non-finite input.
    pub fn through(a: [T; 2], b: [T; 2]) -> Result<Self, Cga2Error> {
        finite((), &[a, b].concat())?;
        if a == b {
            return Err(Cga2Error::CoincidentPoints);
        }
        Ok(Vector::up(a) ^ Vector::up(b))
    }

    fn dense(self) -> Multivector<T> {
        Multivector::from_storage(&self.to_storage())
    }
}

impl<T: Real> Rotor<T> {
    /// The turn by `angle` (radians, counter-clockwise) about the origin: `exp(−½θ e12) =
    /// cos(θ/2) − sin(θ/2) e12` (kingdon: `(-θ/2 * e12).exp()`).
    pub fn from_angle(angle: T) -> Self {
        let half = T::from_f64(0.5) * angle;
        Rotor { s: half.cos(), e12: -half.sin() }
    }

    /// The angle it turns by, `2 atan2(−e12, s)`, in `(−2π, 2π]`.
    pub fn angle(self) -> T {
        T::from_f64(2.0) * (-self.e12).atan2(self.s)
    }
}

impl<T: Real> Motor<T> {
    /// The translation by `t`: `1 − ½(t₁ e1i + t₂ e2i)` (`e1i = e1 ∧ ei`), moving points by
    /// `+t` (kingdon: `1 - 0.5 * (t1 * e1 + t2 * e2) * ei`).
    pub fn translator(t: [T; 2]) -> Self {
        let h = -T::from_f64(0.5);
        Motor { s: T::one(), e12: T::zero(), e1i: h * t[0], e2i: h * t[1] }
    }

    /// The turn by `angle` (counter-clockwise) about `centre`: `T R T̃` with `R` the turn
    /// about the origin and `T` the translation by `centre`.
    pub fn rotation_about(centre: [T; 2], angle: T) -> Self {
        let (t, r) = (Motor::translator(centre), Motor::from(Rotor::from_angle(angle)));
        t * r * t.reverse()
    }
}
