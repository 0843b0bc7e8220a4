//! The generator `B = −½(θ a I3 + t ∧ ei)` of a rigid motion, read as a screw: an axis
//! line, an angle and a pitch.

use crate::euclid::{E3, cross, dot, norm, scale, unit};
use crate::{Generator, Line, Real};

/// A screw motion's parts: a turn by `angle` about the line through `point` with unit
/// direction `axis`, and an advance of `pitch · angle` along it; with `angle = 0`, the
/// translation `translation` alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Screw<T> {
    /// The turn `θ ≥ 0` in radians (zero for a translation).
    pub angle: T,
    /// The axis direction (unit), or the translation's direction when `angle = 0`.
    pub axis: E3<T>,
    /// The point of the axis nearest the origin (the origin for a translation).
    pub point: E3<T>,
    /// Advance along the axis per radian (for `angle = 0`, zero: see `translation`).
    pub pitch: T,
    /// The translation of a pure translation (zero otherwise).
    pub translation: E3<T>,
}

impl<T: Real> Generator<T> {
    /// `−½ θ â I3`: the generator of the turn by `angle` about `axis` through the origin
    /// (`None` for a zero axis).
    pub fn rotation(axis: E3<T>, angle: T) -> Option<Self> {
        let a = unit(axis)?;
        let h = angle * T::from_f64(-0.5);
        // a I3 = a1 e23 − a2 e13 + a3 e12.
        Some(Generator { e12: h * a[2], e13: -h * a[1], e23: h * a[0], ..Generator::zero() })
    }

    /// `−½ t ∧ ei`: the generator of the translation by `t`.
    pub fn translation(t: E3<T>) -> Self {
        let h = T::from_f64(-0.5);
        Generator { e1i: h * t[0], e2i: h * t[1], e3i: h * t[2], ..Generator::zero() }
    }

    /// The turn vector `ω = θ a`, read from `−½ θ a I3`: `(−2 e23, 2 e13, −2 e12)`.
    pub fn angular(&self) -> E3<T> {
        let two = T::from_f64(2.0);
        [-two * self.e23, two * self.e13, -two * self.e12]
    }

    /// The velocity `v` of the origin, read from `−½ v ∧ ei`: `−2 (e1i, e2i, e3i)`.
    pub fn linear(&self) -> E3<T> {
        let m = T::from_f64(-2.0);
        [m * self.e1i, m * self.e2i, m * self.e3i]
    }

    /// The screw of `exp(B)` (Chasles): with `ω` the turn and `v` the origin's velocity,
    /// the point moves by `ω × x + v`; its axis has direction `ω̂`, passes through
    /// `p = ω × v / |ω|²`, and the pitch is `ω · v / |ω|²` per radian. With `ω = 0` the
    /// motion is the translation `v`.
    pub fn screw(&self) -> Screw<T> {
        let (w, v) = (self.angular(), self.linear());
        let zero = [T::zero(); 3];
        match unit(w) {
            Some(axis) if norm(w) > T::zero() => {
                let (angle, w2) = (norm(w), dot(w, w));
                let k = T::one() / w2;
                let point = if k.is_finite() { scale(cross(w, v), k) } else { zero };
                let pitch = if k.is_finite() { dot(w, v) * k } else { T::zero() };
                Screw { angle, axis, point, pitch, translation: zero }
            }
            _ => {
                Screw { angle: T::zero(), axis: unit(v).unwrap_or(zero), point: zero, pitch: T::zero(), translation: v }
            }
        }
    }

    /// The screw's axis as a line (`None` for a translation, which has none).
    pub fn axis_line(&self) -> Option<Line<T>> {
        let s = self.screw();
        (s.angle > T::zero()).then(|| Line::from_point_unit_direction(s.point, s.axis))
    }
}
