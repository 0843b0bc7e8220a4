//! `Display` in Euclidean terms: a circle shows its centre, normal and radius, a line a
//! point and direction, a motor its rotation and translation. What has no Euclidean reading
//! (a general even element, a degenerate blade) shows its nonzero coefficients by blade.
//! A precision (`{:.3}`) applies to every number.

use crate::euclid::{E3, norm};
use crate::{
    Bivector, Blades, Circle, Dilator, Even, FlatPoint, Generator, Infinity, Line, Motor, Multivector, Odd, Plane,
    Pseudoscalar, Real, Rotor, Scalar, ScalarQuadvector, Sphere, Translator, Transversor, Vector, down,
};
use core::fmt::{Display, Formatter, Result};

/// A number, at the formatter's precision if it has one (`−0` shows as `0`).
fn num(f: &mut Formatter<'_>, x: f64) -> Result {
    let x = if x == 0.0 { 0.0 } else { x };
    match f.precision() {
        Some(p) => write!(f, "{x:.p$}"),
        None => write!(f, "{x}"),
    }
}

/// `(x, y, z)`.
fn triple<T: Real>(f: &mut Formatter<'_>, v: E3<T>) -> Result {
    f.write_str("(")?;
    for (k, x) in v.iter().enumerate() {
        if k > 0 {
            f.write_str(", ")?;
        }
        num(f, x.to_f64())?;
    }
    f.write_str(")")
}

/// `a e1 + b e23 − …`: the nonzero coefficients by blade name (`0` when there are none).
fn terms(f: &mut Formatter<'_>, names: &[&str], values: impl Iterator<Item = f64>) -> Result {
    let mut first = true;
    for (name, v) in names.iter().zip(values) {
        if v == 0.0 {
            continue;
        }
        let sign = if v < 0.0 { "−" } else { "+" };
        match (first, v < 0.0) {
            (true, true) => f.write_str("−")?,
            (true, false) => {}
            (false, _) => write!(f, " {sign} ")?,
        }
        num(f, v.abs())?;
        if *name != "s" && *name != "1" {
            write!(f, " {name}")?;
        }
        first = false;
    }
    if first { f.write_str("0") } else { Ok(()) }
}

/// The nonzero coefficients by blade name: every type's fallback when it has no Euclidean
/// reading, and the whole display of those that never have one.
trait Terms {
    fn terms(&self, f: &mut Formatter<'_>) -> Result;
}

impl<X: Blades<Coefficient: Real>> Terms for X {
    fn terms(&self, f: &mut Formatter<'_>) -> Result {
        terms(f, X::NAMES, self.coefficients().map(|x| x.to_f64()))
    }
}

macro_rules! by_terms {
    ($($ty:ident),*) => {$(
        impl<T: Real> Display for $ty<T> {
            /// The nonzero coefficients by blade name.
            fn fmt(&self, f: &mut Formatter<'_>) -> Result {
                self.terms(f)
            }
        }
    )*};
}

by_terms!(Scalar, Infinity, Pseudoscalar, ScalarQuadvector, Even, Odd, Transversor);

impl<T: Real> Display for Multivector<T> {
    /// The nonzero coefficients by orthonormal blade name.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        terms(f, &Self::BLADES, self.coeffs.iter().map(|x| x.to_f64()))
    }
}

impl<T: Real> Display for Vector<T> {
    /// `point (x, y, z)` for a null vector of nonzero weight, `dual sphere centre … radius …`
    /// or `dual plane normal … offset …` otherwise.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        let square = self.norm_squared().to_f64();
        let size = self.to_array().iter().fold(0.0f64, |m, x| m.max(x.to_f64().abs()));
        match down(*self).ok() {
            Some(x) if square.abs() <= 1e-12 * size * size => {
                f.write_str("point ")?;
                triple(f, x)
            }
            Some(x) => {
                f.write_str("dual sphere centre ")?;
                triple(f, x)?;
                let w = self.eo.to_f64();
                let r2 = square / (w * w);
                f.write_str(if r2 < 0.0 { ", imaginary radius " } else { ", radius " })?;
                num(f, r2.abs().sqrt())
            }
            None => match Plane::from_storage(&self.undual().to_storage()).normal_offset() {
                Ok((n, d)) => {
                    f.write_str("dual plane normal ")?;
                    triple(f, n.map(|x| -x))?;
                    f.write_str(", offset ")?;
                    num(f, -d.to_f64())
                }
                Err(_) => self.terms(f),
            },
        }
    }
}

impl<T: Real> Display for FlatPoint<T> {
    /// `flat point (x, y, z)`, or its coefficients at infinity.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match self.point() {
            Some(x) => {
                f.write_str("flat point ")?;
                triple(f, x)
            }
            None => self.terms(f),
        }
    }
}

impl<T: Real> Display for Bivector<T> {
    /// `point pair (a) (b)`, `tangent point (x)` or `imaginary point pair`, else coefficients.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match self.end_points() {
            Ok([a, b]) => {
                f.write_str("point pair ")?;
                triple(f, a)?;
                f.write_str(" ")?;
                triple(f, b)
            }
            Err(crate::GeometryError::Imaginary) => {
                f.write_str("imaginary point pair: ")?;
                self.terms(f)
            }
            Err(_) => self.terms(f),
        }
    }
}

impl<T: Real> Display for Line<T> {
    /// `line through (p) along (d)`, `p` the point nearest the origin.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match (self.point(), self.direction()) {
            (Ok(p), Ok(d)) => {
                f.write_str("line through ")?;
                triple(f, p)?;
                f.write_str(" along ")?;
                triple(f, d)
            }
            _ => self.terms(f),
        }
    }
}

impl<T: Real> Display for Plane<T> {
    /// `plane normal (n) offset δ` (`n · x = δ` on the plane).
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match self.normal_offset() {
            Ok((n, d)) => {
                f.write_str("plane normal ")?;
                triple(f, n)?;
                f.write_str(" offset ")?;
                num(f, d.to_f64())
            }
            Err(_) => self.terms(f),
        }
    }
}

impl<T: Real> Display for Circle<T> {
    /// `circle centre (c) normal (n) radius r`; a circle of infinite radius is a line.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match self.centre_normal_radius() {
            Ok((c, n, r)) => {
                f.write_str("circle centre ")?;
                triple(f, c)?;
                f.write_str(" normal ")?;
                triple(f, n)?;
                f.write_str(" radius ")?;
                num(f, r.to_f64())
            }
            // A circle of infinite radius: the line it is, when it has a direction.
            Err(crate::GeometryError::AtInfinity) => match Line::from_storage(&self.to_storage()) {
                line if line.direction().is_ok() => Display::fmt(&line, f),
                _ => self.terms(f),
            },
            Err(_) => self.terms(f),
        }
    }
}

impl<T: Real> Display for Sphere<T> {
    /// `sphere centre (c) radius r`, or the plane it is when flat.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match self.centre_radius() {
            Ok((c, r)) => {
                f.write_str("sphere centre ")?;
                triple(f, c)?;
                f.write_str(" radius ")?;
                num(f, r.to_f64())
            }
            Err(crate::GeometryError::AtInfinity) => Display::fmt(&Plane::from_storage(&self.to_storage()), f),
            Err(_) => self.terms(f),
        }
    }
}

/// `(angle in degrees, unit axis)` of a rotor `cos θ/2 − sin θ/2 a I3`, or `None` for the
/// identity.
fn rotation<T: Real>(r: &Rotor<T>) -> Option<(f64, E3)> {
    // a I3 = a1 e23 − a2 e13 + a3 e12, so the axis is (−e23, e13, −e12) / sin θ/2.
    let axis = [-r.e23.to_f64(), r.e13.to_f64(), -r.e12.to_f64()];
    let s = norm(axis);
    (s > 0.0).then(|| (2.0 * s.atan2(r.s.to_f64()).to_degrees(), axis.map(|x| x / s)))
}

impl<T: Real> Display for Rotor<T> {
    /// `rotation θ° about (a)`, or `identity`.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        match rotation(self) {
            Some((angle, axis)) => {
                f.write_str("rotation ")?;
                num(f, angle)?;
                f.write_str("° about ")?;
                triple(f, axis)
            }
            None => f.write_str("identity"),
        }
    }
}

impl<T: Real> Display for Translator<T> {
    /// `translation (t)`.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        f.write_str("translation ")?;
        let w = self.s.to_f64();
        triple(f, [self.e1i, self.e2i, self.e3i].map(|x| -2.0 * x.to_f64() / w))
    }
}

impl<T: Real> Display for Motor<T> {
    /// `rotation θ° about (a), then translation (t)`: `M = T R`, read as `R`'s turn and the
    /// image of the origin.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        let r = Rotor { s: self.s, e12: self.e12, e13: self.e13, e23: self.e23 };
        let t = down(crate::Sandwich::sandwich(*self, crate::up([T::zero(); 3]))).ok();
        if let Some((angle, axis)) = rotation(&r) {
            f.write_str("rotation ")?;
            num(f, angle)?;
            f.write_str("° about ")?;
            triple(f, axis)?;
            f.write_str(", then ")?;
        }
        match t {
            Some(t) => {
                f.write_str("translation ")?;
                triple(f, t)
            }
            None => self.terms(f),
        }
    }
}

impl<T: Real> Display for Generator<T> {
    /// The screw that `exp(B)` is: `generator of rotation θ° about the line through (p)
    /// along (a), pitch h per radian`, or `generator of translation (t)`.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        let screw = self.screw();
        if screw.angle.to_f64() > 0.0 {
            f.write_str("generator of rotation ")?;
            num(f, screw.angle.to_f64().to_degrees())?;
            f.write_str("° about the line through ")?;
            triple(f, screw.point)?;
            f.write_str(" along ")?;
            triple(f, screw.axis)?;
            f.write_str(", pitch ")?;
            num(f, screw.pitch.to_f64())
        } else {
            f.write_str("generator of translation ")?;
            triple(f, screw.translation)
        }
    }
}

impl<T: Real> Display for Dilator<T> {
    /// `dilation by s about (c)`, or the coefficients when it is not one.
    fn fmt(&self, f: &mut Formatter<'_>) -> Result {
        let (s, sh) = (self.factor().to_f64(), self.eoi.to_f64());
        if s > 0.0 && s.is_finite() && sh != 0.0 {
            f.write_str("dilation by ")?;
            num(f, s)?;
            f.write_str(" about ")?;
            triple(f, [self.e1i, self.e2i, self.e3i].map(|x| x.to_f64() / sh))
        } else if sh == 0.0 && self.s.to_f64() != 0.0 {
            f.write_str("translation ")?;
            let w = self.s.to_f64();
            triple(f, [self.e1i, self.e2i, self.e3i].map(|x| -2.0 * x.to_f64() / w))
        } else {
            self.terms(f)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn objects_show_what_they_are() {
        let c: Circle = Circle::from_centre_normal_radius([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 0.5).unwrap();
        assert_eq!(format!("{c:.3}"), "circle centre (1.000, 2.000, 3.000) normal (0.000, 0.000, 1.000) radius 0.500");
        let s: Sphere = Sphere::from_centre_radius([0.0, -1.0, 0.0], 2.0).unwrap();
        assert_eq!(format!("{s:.2}"), "sphere centre (0.00, -1.00, 0.00) radius 2.00");
        let l: Line = Line::through([0.0, 0.0, 1.0], [1.0, 0.0, 1.0]).unwrap();
        assert_eq!(format!("{l:.1}"), "line through (0.0, 0.0, 1.0) along (1.0, 0.0, 0.0)");
        let p: Plane = Plane::from_point_normal([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]).unwrap();
        assert_eq!(format!("{p:.1}"), "plane normal (0.0, 0.0, 1.0) offset 2.0");
        assert_eq!(format!("{:.1}", crate::up([1.0, 2.0, 3.0])), "point (1.0, 2.0, 3.0)");
        let pair: Bivector = Bivector::from_points([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
        assert_eq!(format!("{pair:.1}"), "point pair (0.0, 0.0, 0.0) (1.0, 0.0, 0.0)");
        let turn: Rotor = Rotor::from_axis_angle([0.0, 0.0, 1.0], core::f64::consts::FRAC_PI_2).unwrap();
        assert_eq!(format!("{turn:.1}"), "rotation 90.0° about (0.0, 0.0, 1.0)");
        let shift: Translator = Translator::from_vector([2.0, 0.0, -1.0]);
        assert_eq!(format!("{shift:.1}"), "translation (2.0, 0.0, -1.0)");
        let m = Motor::from_rotor_translator(turn, shift);
        assert_eq!(format!("{m:.1}"), "rotation 90.0° about (0.0, 0.0, 1.0), then translation (2.0, 0.0, -1.0)");
        let e = Even::<f64> { s: 1.5, e12: -2.0, ..Even::zero() };
        assert_eq!(format!("{e}"), "1.5 − 2 e12");
    }

    #[test]
    fn debug_shows_the_nonzero_coefficients() {
        let e = Even::<f64> { s: 1.5, e12: -2.0, ..Even::zero() };
        assert_eq!(format!("{e:?}"), "Even { s: 1.5, e12: -2.0 }");
        assert_eq!(format!("{:?}", Scalar::<f64>::zero()), "Scalar { s: 0.0 }");
        let l: Line = Line::through([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
        assert_eq!(format!("{l:?}"), "Line { e1oi: -1.0 }");
    }
}
