//! Materials: a surface's colour and Blinn–Phong coefficients (the paper's eq. 12).

use crate::format::{number, numbers};
use crate::scene::Invalid;
use serde::Deserialize;

/// Surface colour and Blinn–Phong coefficients.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Linear RGB in [0, 1].
    #[serde(deserialize_with = "numbers")]
    pub colour: [f64; 3],
    /// Ambient coefficient `k_a`.
    #[serde(default = "half", deserialize_with = "number")]
    pub ka: f64,
    /// Diffuse coefficient `k_d`.
    #[serde(default = "one", deserialize_with = "number")]
    pub kd: f64,
    /// Specular coefficient `k_s`.
    #[serde(default = "one", deserialize_with = "number")]
    pub ks: f64,
    /// Specular exponent `q`.
    #[serde(default = "hundred", deserialize_with = "number")]
    pub q: f64,
    /// Mirror reflection `k_r`.
    #[serde(default, deserialize_with = "number")]
    pub kr: f64,
}

pub(crate) fn half() -> f64 {
    0.5
}
pub(crate) fn one() -> f64 {
    1.0
}
pub(crate) fn hundred() -> f64 {
    100.0
}

impl Material {
    /// Every value finite and non-negative.
    pub fn check(&self) -> Result<(), Invalid> {
        let all = self.colour.iter().chain([&self.ka, &self.kd, &self.ks, &self.q, &self.kr]);
        if all.clone().any(|x| !x.is_finite() || *x < 0.0) {
            return Err(Invalid::Value("material values must be finite and ≥ 0"));
        }
        Ok(())
    }
}
