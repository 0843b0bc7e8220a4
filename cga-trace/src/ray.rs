//! Rays: a Euclidean origin and unit direction for ordering hits, and the CGA line they lie on
//! for meeting objects.

use cga_core::Line;
use cga_core::euclid::{E3, add, dot, scale, sub, unit};

/// A ray `o + t d`, `t > 0`, carried by the normalised line `L` from `o` along `d`.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: E3,
    /// Unit direction.
    pub dir: E3,
    /// The carrier `up(o) ∧ up(o + d) ∧ ei`, normalised.
    pub line: Line,
}

impl Ray {
    /// The ray from `origin` along `dir`; `None` for a zero or non-finite direction.
    pub fn new(origin: E3, dir: E3) -> Option<Self> {
        let dir = unit(dir)?;
        let line = Line::from_point_direction(origin, dir).ok()?;
        Some(Ray { origin, dir, line })
    }

    /// `o + t d`.
    pub fn at(&self, t: f64) -> E3 {
        add(self.origin, scale(self.dir, t))
    }

    /// The parameter of a point on the ray, `(x − o) · d`.
    pub fn t_of(&self, x: E3) -> f64 {
        dot(sub(x, self.origin), self.dir)
    }

    /// A secondary ray leaving a surface point `x` with unit normal `n` along `dir`: it starts
    /// `1e-6 (1 + |x|∞)` off the surface on the side it leaves to, so that rounding in the
    /// hit point cannot make it meet the surface it starts on.
    pub fn leaving(x: E3, n: E3, dir: E3) -> Option<Self> {
        let side = if dot(n, dir) >= 0.0 { 1.0 } else { -1.0 };
        let offset = 1e-6 * x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        Ray::new(add(x, scale(n, side * offset)), dir)
    }

    /// The ray from `origin` along the normalised line `line` (which must pass through it).
    pub fn from_line(origin: E3, line: Line) -> Option<Self> {
        Some(Ray { origin, dir: line.direction().ok()?, line })
    }
}
