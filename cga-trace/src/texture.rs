//! Textures: a colour that varies over a surface's own parameters `(u, v)`
//! ([`Shape::uv`]) in place of its material's one colour — a checker, stripes, a gradient,
//! noise, marble, bricks or an image — placed on the surface by a [`Placement`] (offset,
//! turn, scale, flip) and a repeat; and bumps, a texture's values read as heights that tilt
//! the normal shading sees ([`Bump`]).
//!
//! A lookup at `(u, v)` reads the pattern at `q = repeat ∘ placement(u, v)`
//! ([`Texture::coordinates`]). Every pattern is deterministic (noise from a seeded integer
//! hash, no state) and allocates nothing.

use crate::hash::hash;
use crate::light::orthonormal;
use crate::picture::Picture;
pub use crate::shapes::Unit;
use crate::shapes::{Crossing, Shape, largest};
use cga_core::euclid::{E3, add, scale, sub, unit};
use std::sync::Arc;

/// A texture: its pattern, placed on the surface's `(u, v)` by `place`, then repeated
/// `repeat[0]` times per unit of `u` and `repeat[1]` per unit of `v`; and, where it has one,
/// a bump.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// What it shows.
    pub pattern: Pattern,
    /// Cells (or copies of the image) per unit of `u` and of `v`, after the placement.
    pub repeat: [f64; 2],
    /// Where the pattern lies on the surface.
    pub place: Placement,
    /// Heights that tilt the shading normal, if any.
    pub bump: Option<Box<Bump>>,
}

/// Where a pattern lies on a surface: flipped, scaled, turned, then moved, in that order.
/// A lookup undoes them in turn, `q = F S⁻¹ R(−θ) ((u, v) − offset)` ([`Placement::apply`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// How much larger the pattern is along its own `u` and `v` (positive).
    pub scale: [f64; 2],
    /// How far it is turned, in degrees, counter-clockwise from `u` towards `v`.
    pub rotate: f64,
    /// Where its origin lies in the surface's `(u, v)`.
    pub offset: [f64; 2],
    /// Whether it is mirrored along `u` (`u ↦ −u`) and along `v`.
    pub flip: [bool; 2],
}

impl Default for Placement {
    /// As it is: no offset, turn, scale or flip.
    fn default() -> Self {
        Placement { scale: [1.0, 1.0], rotate: 0.0, offset: [0.0, 0.0], flip: [false, false] }
    }
}

impl Placement {
    /// The pattern's own coordinates of the surface's `(u, v)`: `q = F S⁻¹ R(−θ) ((u, v) −
    /// offset)`, `R(−θ)` the turn back by `rotate` (exact at multiples of 90°), `S` the
    /// scale and `F` the flips.
    pub fn apply(&self, [u, v]: [f64; 2]) -> [f64; 2] {
        let (du, dv) = (u - self.offset[0], v - self.offset[1]);
        let (c, s) = turn(self.rotate);
        let (a, b) = (c * du + s * dv, c * dv - s * du);
        let sign = |f: bool| if f { -1.0 } else { 1.0 };
        [sign(self.flip[0]) * a / self.scale[0], sign(self.flip[1]) * b / self.scale[1]]
    }

    /// The linear part of [`Placement::apply`], as rows: `∂q/∂(u, v)`.
    fn linear(&self) -> [[f64; 2]; 2] {
        let (c, s) = turn(self.rotate);
        let sign = |f: bool| if f { -1.0 } else { 1.0 };
        let (ku, kv) = (sign(self.flip[0]) / self.scale[0], sign(self.flip[1]) / self.scale[1]);
        [[ku * c, ku * s], [-kv * s, kv * c]]
    }
}

/// `(cos θ, sin θ)` for `θ` in degrees, exact at multiples of 90° (so that a quarter turn
/// swaps coordinates without rounding).
fn turn(degrees: f64) -> (f64, f64) {
    let d = degrees.rem_euclid(360.0);
    match d {
        0.0 => (1.0, 0.0),
        90.0 => (0.0, 1.0),
        180.0 => (-1.0, 0.0),
        270.0 => (0.0, -1.0),
        _ => {
            let (s, c) = d.to_radians().sin_cos();
            (c, s)
        }
    }
}

/// A texture's pattern. Procedural ones mix the material's colour `a` and their own `b` by
/// a value `t` in `[0, 1]` ([`Pattern::value`]): `(1 − t) a + t b`.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// The material's own colour (a texture that only bumps).
    Plain,
    /// Cells `⌊u⌋ + ⌊v⌋` even in the material's colour, odd in this one (`t` 0 or 1).
    Checker([f64; 3]),
    /// Bands `⌊u⌋` even in the material's colour, odd in this one.
    Stripes([f64; 3]),
    /// From the material's colour to this one along `u` or `v` over each unit, `t = u − ⌊u⌋`
    /// (a sawtooth: it starts again at each whole number).
    Gradient([f64; 3], Axis),
    /// Value noise summed over octaves ([`Noise::value`]): `t` the noise.
    Noise([f64; 3], Noise),
    /// Veins across `u` bent by noise: `t = ½ (1 + sin 2π (u + turbulence · n(q)))`, `n` the
    /// noise.
    Marble {
        /// The veins' colour.
        colour: [f64; 3],
        /// The noise that bends them.
        noise: Noise,
        /// How far it bends them, in units of `u` (0: straight bands).
        turbulence: f64,
    },
    /// Bricks of the material's colour in mortar of this colour: rows `brick[1]` high, each
    /// brick `brick[0]` long, every other row shifted by half a brick; the mortar `mortar`
    /// wide along each brick's lower and left edges (`t` 1 in the mortar).
    Bricks {
        /// The mortar's colour.
        colour: [f64; 3],
        /// A brick's length along `u` and height along `v`, mortar included.
        brick: [f64; 2],
        /// The mortar's width.
        mortar: f64,
    },
    /// An image over `[0, 1)²`: `u` across (wrapping), `v` down from the top (up from the
    /// bottom on a surface whose `v` runs up, [`Shape::v_up`]); `t` its luminance.
    Image(Arc<Picture>),
}

/// Which of a surface's parameters a gradient runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// `u`.
    U,
    /// `v`.
    V,
}

/// Seeded value noise over the pattern's `(u, v)`, summed over `octaves`: octave `k`
/// (from 0) at frequency `2^k` and weight `2^−k`, the sum divided by the weights' (so in
/// `[0, 1]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Noise {
    /// Which noise: each seed its own.
    pub seed: u32,
    /// Octaves summed, 1 to [`crate::limits::MAX_OCTAVES`].
    pub octaves: u32,
}

impl Default for Noise {
    /// Seed 0, four octaves.
    fn default() -> Self {
        Noise { seed: 0, octaves: 4 }
    }
}

impl Noise {
    /// `Σ_k 2^−k n_k(2^k q) / Σ_k 2^−k`, `n_k` the value noise of seed `seed + k`: each the
    /// lattice's hashed values in `[0, 1]` at the four corners of `q`'s cell, blended by
    /// `s(f) = 6f⁵ − 15f⁴ + 10f³` of `q`'s place in it (smooth to the second derivative).
    pub fn value(&self, [u, v]: [f64; 2]) -> f64 {
        let (mut sum, mut weight, mut total, mut frequency) = (0.0, 1.0, 0.0, 1.0);
        for k in 0..self.octaves {
            sum += weight * value_noise(self.seed.wrapping_add(k), [u * frequency, v * frequency]);
            total += weight;
            weight *= 0.5;
            frequency *= 2.0;
        }
        if total > 0.0 { (sum / total).clamp(0.0, 1.0) } else { 0.0 }
    }
}

/// One octave of value noise ([`Noise::value`]).
fn value_noise(seed: u32, [u, v]: [f64; 2]) -> f64 {
    let (i, j) = (u.floor(), v.floor());
    let (fu, fv) = (smooth(u - i), smooth(v - j));
    // Lattice coordinates as 32-bit integers: the noise repeats every 2³² cells.
    let (i, j) = ((i as i64) as u32, (j as i64) as u32);
    let at = |di: u32, dj: u32| {
        let h = hash(hash(hash(seed) ^ i.wrapping_add(di)) ^ j.wrapping_add(dj));
        f64::from(h) / f64::from(u32::MAX)
    };
    let bottom = at(0, 0) + fu * (at(1, 0) - at(0, 0));
    let top = at(0, 1) + fu * (at(1, 1) - at(0, 1));
    bottom + fv * (top - bottom)
}

/// `6f⁵ − 15f⁴ + 10f³`.
fn smooth(f: f64) -> f64 {
    f * f * f * (f * (f * 6.0 - 15.0) + 10.0)
}

/// A bump: `heights`' values ([`Pattern::value`], in `[0, 1]`) read as a height field that
/// tilts the shading normal, `n′ = unit(n − s (∂h/∂q_u ê_u + ∂h/∂q_v ê_v))`, `s` the
/// `strength`, `q` the heights' pattern coordinates and `ê` the unit directions on the
/// surface along which `q_u` and `q_v` grow: a slope of `s` per cell of the pattern, whatever
/// the object's size. Only lights see it (diffuse and highlight); the surface itself, its
/// silhouette, mirror and refracted rays and the normal AOV keep the geometric normal.
#[derive(Clone, Debug, PartialEq)]
pub struct Bump {
    /// The heights, their placement and repeat (colours unused).
    pub heights: Texture,
    /// The slope a height of 1 across one cell stands for (negative: dents for bumps).
    pub strength: f64,
}

impl Texture {
    /// `pattern` as it is, once per unit of `u` and `v`, without a bump.
    pub fn new(pattern: Pattern) -> Self {
        Texture { pattern, repeat: [1.0, 1.0], place: Placement::default(), bump: None }
    }

    /// The texture repeated `repeat` times per unit of `u` and of `v`.
    pub fn repeat(self, repeat: [f64; 2]) -> Self {
        Texture { repeat, ..self }
    }

    /// The pattern `scale` times larger along its own `u` and `v`.
    pub fn scale(mut self, scale: [f64; 2]) -> Self {
        self.place.scale = scale;
        self
    }

    /// The pattern turned by `degrees`, counter-clockwise from `u` towards `v`.
    pub fn rotate(mut self, degrees: f64) -> Self {
        self.place.rotate = degrees;
        self
    }

    /// The pattern's origin moved to `offset` in the surface's `(u, v)`.
    pub fn offset(mut self, offset: [f64; 2]) -> Self {
        self.place.offset = offset;
        self
    }

    /// The pattern mirrored along `u` and/or `v`.
    pub fn flip(mut self, flip: [bool; 2]) -> Self {
        self.place.flip = flip;
        self
    }

    /// The texture with `bump`.
    pub fn bump(self, bump: Bump) -> Self {
        Texture { bump: Some(Box::new(bump)), ..self }
    }

    /// The pattern's coordinates at the surface's `(u, v)`: `q = repeat · placement(u, v)`
    /// ([`Placement::apply`]; an unmoved placement is skipped, so `q = repeat · (u, v)`).
    pub fn coordinates(&self, uv: [f64; 2]) -> [f64; 2] {
        let [u, v] = if self.place == Placement::default() { uv } else { self.place.apply(uv) };
        [u * self.repeat[0], v * self.repeat[1]]
    }

    /// The colour at `(u, v)` of a surface whose material's colour is `base`, `v` running down
    /// an image.
    pub fn colour(&self, base: [f64; 3], uv: [f64; 2]) -> [f64; 3] {
        self.colour_on(base, uv, false)
    }

    /// [`Texture::colour`] on a surface whose `v` runs up an image where `v_up`
    /// ([`Shape::v_up`]).
    pub fn colour_on(&self, base: [f64; 3], uv: [f64; 2], v_up: bool) -> [f64; 3] {
        let q = self.coordinates(uv);
        let odd = |x: f64| x.floor().rem_euclid(2.0) == 1.0;
        match &self.pattern {
            Pattern::Plain => base,
            Pattern::Checker(other) => {
                if odd(q[0]) != odd(q[1]) {
                    *other
                } else {
                    base
                }
            }
            Pattern::Stripes(other) => {
                if odd(q[0]) {
                    *other
                } else {
                    base
                }
            }
            Pattern::Image(picture) => image_at(picture, q, v_up),
            Pattern::Gradient(other, _)
            | Pattern::Noise(other, _)
            | Pattern::Marble { colour: other, .. }
            | Pattern::Bricks { colour: other, .. } => mix(base, *other, self.pattern.value(q, v_up)),
        }
    }

    /// The shading normal at a crossing of `shape` whose normal is `normal`: tilted by the
    /// texture's [`Bump`], `normal` itself without one. `lengths` is the world length of a
    /// frame unit (a plane's `(u, v)` are lengths in world units). The surface's gradients of
    /// `(u, v)` are read from `uv` one step along two tangents `t₁, t₂` ([`orthonormal`] to
    /// the normal), the step `2⁻²⁰` of the shape's bounding radius (of the point's distance
    /// from the camera, for an unbounded shape); a fraction's jump across its seam is taken
    /// the short way round. A swept surface's `α` is its crossing's own, kept by the steps:
    /// there the bump tilts the normal along the second parameter only.
    pub fn shading_normal(&self, shape: &dyn Shape, crossing: &Crossing, normal: E3, lengths: f64) -> E3 {
        let Some(bump) = &self.bump else { return normal };
        let Some((uv, unit_of)) = shape.uv(crossing) else { return normal };
        let size = shape.bounds().map_or_else(|| largest(crossing.point), |(_, r)| r);
        let step = if size > 0.0 && size.is_finite() { size * f64::powi(2.0, -20) } else { 1.0 };
        let (t1, t2) = orthonormal(normal);
        let units = |x: f64| if unit_of == Unit::Length { x * lengths } else { x };
        // ∂(u, v)/∂t₁ and ∂(u, v)/∂t₂, in the units the pattern reads.
        let slope = |t: E3| -> Option<[f64; 2]> {
            let moved = Crossing { point: add(crossing.point, scale(t, step)), ..*crossing };
            let (there, _) = shape.uv(&moved)?;
            let d = |k: usize| {
                let d = there[k] - uv[k];
                units(if unit_of == Unit::Fraction { d - d.round() } else { d }) / step
            };
            Some([d(0), d(1)])
        };
        let (Some(s1), Some(s2)) = (slope(t1), slope(t2)) else { return normal };
        let heights = &bump.heights;
        let m = heights.place.linear();
        // ∇q_k = Σ_j repeat_k m_kj ∇(u, v)_j on the surface.
        let grad = |k: usize| {
            let along = |s: [f64; 2]| heights.repeat[k] * (m[k][0] * s[0] + m[k][1] * s[1]);
            add(scale(t1, along(s1)), scale(t2, along(s2)))
        };
        let q = heights.coordinates(uv.map(units));
        let v_up = shape.v_up();
        let tilt = [0, 1].iter().fold([0.0; 3], |tilt, &k| {
            let Some(e) = unit(grad(k)) else { return tilt };
            add(tilt, scale(e, heights.pattern.slope(q, k, v_up)))
        });
        unit(sub(normal, scale(tilt, bump.strength))).unwrap_or(normal)
    }
}

/// The step of a procedural height's central difference in a pattern's coordinates: `1/64`
/// of a cell, so that the edges of a checker's, stripes' or bricks' cells show as bevels
/// `1/32` of a cell wide (a step's slope is nowhere else).
const DIFFERENCE: f64 = 1.0 / 64.0;

impl Pattern {
    /// The pattern's value `t` in `[0, 1]` at its coordinates `q`: the weight of its own
    /// colour against the material's, and a bump's height. 0 or 1 for a checker, stripes and
    /// bricks (1 in the mortar); the ramp of a gradient; the noise; marble's veins; an
    /// image's luminance `0.2126 r + 0.7152 g + 0.0722 b` (clamped); 0 for the plain pattern.
    pub fn value(&self, q: [f64; 2], v_up: bool) -> f64 {
        let odd = |x: f64| x.floor().rem_euclid(2.0) == 1.0;
        let one = |b: bool| if b { 1.0 } else { 0.0 };
        match self {
            Pattern::Plain => 0.0,
            Pattern::Checker(_) => one(odd(q[0]) != odd(q[1])),
            Pattern::Stripes(_) => one(odd(q[0])),
            Pattern::Gradient(_, axis) => {
                let x = q[usize::from(*axis == Axis::V)];
                x - x.floor()
            }
            Pattern::Noise(_, noise) => noise.value(q),
            Pattern::Marble { noise, turbulence, .. } => {
                let x = q[0] + turbulence * noise.value(q);
                (0.5 * (1.0 + (std::f64::consts::TAU * x).sin())).clamp(0.0, 1.0)
            }
            Pattern::Bricks { brick, mortar, .. } => one(in_mortar(q, *brick, *mortar)),
            Pattern::Image(picture) => {
                let [r, g, b] = image_at(picture, q, v_up);
                (0.2126 * r + 0.7152 * g + 0.0722 * b).clamp(0.0, 1.0)
            }
        }
    }

    /// `∂t/∂q_k` at `q` by a central difference: of a pixel for an image, of [`DIFFERENCE`]
    /// for the others.
    fn slope(&self, q: [f64; 2], k: usize, v_up: bool) -> f64 {
        let step = match self {
            Pattern::Image(p) => 1.0 / f64::from(if k == 0 { p.width } else { p.height }),
            _ => DIFFERENCE,
        };
        let at = |d: f64| {
            let mut p = q;
            p[k] += d;
            self.value(p, v_up)
        };
        (at(step) - at(-step)) / (2.0 * step)
    }
}

/// An image's colour at `q`: `u` across, `v` down from the top, or up from the bottom where
/// `v_up`, each wrapping.
fn image_at(picture: &Picture, [u, v]: [f64; 2], v_up: bool) -> [f64; 3] {
    let v = if v_up { -v } else { v };
    picture.at(u, v - v.floor())
}

/// Whether `q` lies in bricks' mortar: the row `⌊v/h⌋`, odd rows shifted by half a brick,
/// the mortar the first `mortar` of each brick along `u` and of each row along `v`.
fn in_mortar([u, v]: [f64; 2], [w, h]: [f64; 2], mortar: f64) -> bool {
    let row = (v / h).floor();
    let u = if row.rem_euclid(2.0) == 1.0 { u + 0.5 * w } else { u };
    let (x, y) = (u - (u / w).floor() * w, v - row * h);
    x < mortar || y < mortar
}

/// `(1 − t) a + t b`, held between `a` and `b` channel by channel (`a` at 0, `b` at 1).
fn mix(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| ((1.0 - t) * a[k] + t * b[k]).clamp(a[k].min(b[k]), a[k].max(b[k])))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checkers_and_stripes_alternate_by_cell() {
        let (a, b) = ([1.0; 3], [0.0; 3]);
        let checker = Texture::new(Pattern::Checker(b)).repeat([2.0, 2.0]);
        assert_eq!(checker.colour(a, [0.1, 0.1]), a);
        assert_eq!(checker.colour(a, [0.6, 0.1]), b);
        assert_eq!(checker.colour(a, [0.6, 0.6]), a);
        assert_eq!(checker.colour(a, [-0.1, 0.1]), b, "cells continue below 0");
        let stripes = Texture::new(Pattern::Stripes(b));
        assert_eq!((stripes.colour(a, [0.5, 7.3]), stripes.colour(a, [1.5, 0.0])), (a, b));
    }

    /// Points off the cells' edges, in a few cells either side of 0.
    fn grid() -> impl Iterator<Item = [f64; 2]> {
        (-7..7).flat_map(|i| (-7..7).map(move |j| [0.37 * f64::from(i) + 0.011, 0.29 * f64::from(j) + 0.013]))
    }

    #[test]
    fn a_quarter_turn_swaps_the_coordinates_and_flips_and_offsets_move_them() {
        let (a, b) = ([1.0, 0.5, 0.2], [0.0, 0.1, 0.9]);
        let plain = Texture::new(Pattern::Checker(b)).repeat([3.0, 1.0]);
        // Turned by 90° the pattern's u runs along the surface's v: q = (v, −u) · repeat,
        // the transposed checker (its repeats swapped) read at (−u, v).
        let turned = plain.clone().rotate(90.0);
        let transposed = Texture::new(Pattern::Checker(b)).repeat([1.0, 3.0]);
        let stripes = Texture::new(Pattern::Stripes(b));
        for [u, v] in grid() {
            assert_eq!(turned.colour(a, [u, v]), plain.colour(a, [v, -u]), "({u}, {v})");
            assert_eq!(turned.colour(a, [u, v]), transposed.colour(a, [-u, v]), "({u}, {v})");
            // Stripes across u, turned a quarter, run across v.
            assert_eq!(stripes.clone().rotate(90.0).colour(a, [u, v]), stripes.colour(a, [v, 0.0]));
            assert_eq!(plain.clone().flip([true, false]).colour(a, [u, v]), plain.colour(a, [-u, v]));
            assert_eq!(plain.clone().flip([false, true]).colour(a, [u, v]), plain.colour(a, [u, -v]));
            assert_eq!(plain.clone().offset([0.25, -2.0]).colour(a, [u, v]), plain.colour(a, [u - 0.25, v + 2.0]));
            assert_eq!(plain.clone().scale([2.0, 4.0]).colour(a, [u, v]), plain.colour(a, [u / 2.0, v / 4.0]));
        }
        // A turn that is not a quarter moves cells off the axes.
        let eighth = plain.clone().rotate(45.0);
        assert!(grid().any(|uv| eighth.colour(a, uv) != plain.colour(a, uv)));
        assert_eq!(turn(-90.0), (0.0, -1.0));
        assert_eq!(turn(450.0), (0.0, 1.0));
    }

    #[test]
    fn the_placement_applies_offset_turn_scale_and_flip_in_that_order() {
        let place = Placement { scale: [2.0, 0.5], rotate: 90.0, offset: [1.0, 2.0], flip: [true, false] };
        // (3, 2) − (1, 2) = (2, 0); turned back by 90°: (0, −2); scaled: (0, −4); flipped u: (−0, −4).
        assert_eq!(place.apply([3.0, 2.0]), [0.0, -4.0]);
        let m = place.linear();
        let (p, e) = (place.apply([0.3, 0.7]), 1.0 / 1024.0);
        let (pu, pv) = (place.apply([0.3 + e, 0.7]), place.apply([0.3, 0.7 + e]));
        for k in 0..2 {
            assert!(((pu[k] - p[k]) / e - m[k][0]).abs() < 1e-9 && ((pv[k] - p[k]) / e - m[k][1]).abs() < 1e-9);
        }
    }

    #[test]
    fn procedural_patterns_are_deterministic_and_between_their_colours() {
        let (a, b) = ([0.9, 0.2, 0.4], [0.1, 0.6, 0.4]);
        let noise = Noise { seed: 7, octaves: 5 };
        let patterns = [
            Pattern::Gradient(b, Axis::U),
            Pattern::Gradient(b, Axis::V),
            Pattern::Noise(b, noise),
            Pattern::Marble { colour: b, noise, turbulence: 2.0 },
            Pattern::Bricks { colour: b, brick: [1.0, 0.5], mortar: 0.05 },
        ];
        for pattern in patterns {
            let texture = Texture::new(pattern.clone()).repeat([3.0, 2.0]);
            let again = Texture::new(pattern.clone()).repeat([3.0, 2.0]);
            let mut seen = Vec::new();
            for uv in grid() {
                let c = texture.colour(a, uv);
                assert_eq!(c, again.colour(a, uv), "{pattern:?} is deterministic");
                for k in 0..3 {
                    assert!(c[k] >= a[k].min(b[k]) && c[k] <= a[k].max(b[k]), "{pattern:?} at {uv:?}: {c:?}");
                }
                seen.push(c);
            }
            assert!(seen.iter().any(|c| *c != seen[0]), "{pattern:?} varies");
        }
        // Another seed is another noise; the noise spreads over its range.
        let other = Noise { seed: 8, ..noise };
        assert!(grid().any(|q| noise.value(q) != other.value(q)));
        let values: Vec<f64> = grid().map(|q| noise.value(q)).collect();
        let (lo, hi) = values.iter().fold((1.0f64, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
        assert!(lo < 0.4 && hi > 0.6, "{lo} … {hi}");
        // A gradient: the material's colour at 0, half way at ½.
        let gradient = Texture::new(Pattern::Gradient([1.0; 3], Axis::V));
        assert_eq!(gradient.colour([0.0; 3], [0.9, 0.0]), [0.0; 3]);
        assert_eq!(gradient.colour([0.0; 3], [0.9, 0.5]), [0.5; 3]);
        assert_eq!(gradient.colour([0.0; 3], [0.5, 0.25]), [0.25; 3]);
    }

    #[test]
    fn bricks_have_mortar_along_their_lower_and_left_edges_and_alternate_rows_shift() {
        let bricks = Pattern::Bricks { colour: [0.0; 3], brick: [1.0, 0.5], mortar: 0.1 };
        assert_eq!(bricks.value([0.5, 0.25], false), 0.0, "inside a brick");
        assert_eq!(bricks.value([0.05, 0.25], false), 1.0, "the joint at u = 0");
        assert_eq!(bricks.value([0.5, 0.05], false), 1.0, "the bed joint at v = 0");
        // The second row is shifted by half a brick: its joint is at u = ½.
        assert_eq!(bricks.value([0.05, 0.75], false), 0.0);
        assert_eq!(bricks.value([0.55, 0.75], false), 1.0);
    }
}
