//! Textures: a colour that varies over a surface's own parameters `(u, v)`
//! ([`Shape::uv`](crate::shapes::Shape::uv)) — a checker or stripes of two colours, or an
//! image — in place of its material's one colour.

use crate::picture::Picture;
pub use crate::shapes::Unit;
use std::sync::Arc;

/// A texture: its pattern, repeated `repeat[0]` times per unit of `u` and `repeat[1]` per
/// unit of `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// What it shows.
    pub pattern: Pattern,
    /// Cells (or copies of the image) per unit of `u` and of `v`.
    pub repeat: [f64; 2],
}

/// A texture's pattern.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// Cells `⌊u⌋ + ⌊v⌋` even in the material's colour, odd in this one.
    Checker([f64; 3]),
    /// Bands `⌊u⌋` even in the material's colour, odd in this one.
    Stripes([f64; 3]),
    /// An image over `[0, 1)²`: `u` across (wrapping), `v` down from the top.
    Image(Arc<Picture>),
}

impl Texture {
    /// The colour at `(u, v)` of a surface whose material's colour is `base`.
    pub fn colour(&self, base: [f64; 3], [u, v]: [f64; 2]) -> [f64; 3] {
        let (u, v) = (u * self.repeat[0], v * self.repeat[1]);
        let odd = |x: f64| x.floor().rem_euclid(2.0) == 1.0;
        match &self.pattern {
            Pattern::Checker(other) => {
                if odd(u) != odd(v) {
                    *other
                } else {
                    base
                }
            }
            Pattern::Stripes(other) => {
                if odd(u) {
                    *other
                } else {
                    base
                }
            }
            Pattern::Image(picture) => picture.at(u, v - v.floor()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checkers_and_stripes_alternate_by_cell() {
        let (a, b) = ([1.0; 3], [0.0; 3]);
        let checker = Texture { pattern: Pattern::Checker(b), repeat: [2.0, 2.0] };
        assert_eq!(checker.colour(a, [0.1, 0.1]), a);
        assert_eq!(checker.colour(a, [0.6, 0.1]), b);
        assert_eq!(checker.colour(a, [0.6, 0.6]), a);
        assert_eq!(checker.colour(a, [-0.1, 0.1]), b, "cells continue below 0");
        let stripes = Texture { pattern: Pattern::Stripes(b), repeat: [1.0, 1.0] };
        assert_eq!((stripes.colour(a, [0.5, 7.3]), stripes.colour(a, [1.5, 0.0])), (a, b));
    }
}
