//! Point lights.

use crate::format::numbers;
use crate::scene::Invalid;
use cga_core::euclid::E3;
use serde::Deserialize;

/// A point light.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Light {
    /// Where it is.
    #[serde(deserialize_with = "numbers")]
    pub position: E3,
    /// Linear RGB intensity.
    #[serde(default = "white", deserialize_with = "numbers")]
    pub colour: [f64; 3],
}

fn white() -> [f64; 3] {
    [1.0; 3]
}

impl Light {
    /// Position and colour finite, colour non-negative.
    pub fn check(&self) -> Result<(), Invalid> {
        if !self.position.iter().chain(&self.colour).all(|x| x.is_finite()) || self.colour.iter().any(|&c| c < 0.0) {
            return Err(Invalid::Value("position and colour must be finite, colour ≥ 0"));
        }
        Ok(())
    }
}
