//! Render settings: depth, background, ambient light, shadows, attenuation, output
//! encoding, and how evolved surfaces are intersected.

use crate::scene::Invalid;
use crate::surface::Method;
use serde::Deserialize;

/// How the output PNG encodes linear values.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, Default, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Encoding {
    /// The sRGB transfer curve (the default).
    #[default]
    Srgb,
    /// Clipped linear values, as the original renderer writes them.
    Linear,
}

/// Global render settings.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    /// Reflection recursion depth.
    #[serde(default = "five")]
    pub max_depth: u32,
    /// Colour of rays that hit nothing.
    #[serde(default)]
    pub background: [f64; 3],
    /// Ambient light intensity (times `k_a` and the colour).
    #[serde(default = "ambient")]
    pub ambient: f64,
    /// Fraction of a light's diffuse and specular that passes a blocker (0: hard shadows).
    #[serde(default)]
    pub shadow_transmission: f64,
    /// Whether shadow rays are cast at all (`false`: every light reaches every point).
    #[serde(default = "yes")]
    pub shadows: bool,
    /// `f_att = min(1, 1 / (c0 + c1 d + c2 d²))`, `d` the distance to the light.
    #[serde(default = "no_attenuation")]
    pub attenuation: [f64; 3],
    /// PNG encoding.
    #[serde(default)]
    pub encoding: Encoding,
    /// How rays meet evolved surfaces (default: hybrid — the α-tree culls, the degree-8
    /// polynomial finds the roots; docs/SURFACE.md).
    #[serde(default)]
    pub surface_method: Method,
}

fn yes() -> bool {
    true
}
pub(crate) fn five() -> u32 {
    5
}
fn ambient() -> f64 {
    0.3
}
fn no_attenuation() -> [f64; 3] {
    [1.0, 0.0, 0.0]
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_depth: five(),
            background: [0.0; 3],
            ambient: ambient(),
            shadow_transmission: 0.0,
            shadows: true,
            attenuation: no_attenuation(),
            encoding: Encoding::Srgb,
            surface_method: Method::default(),
        }
    }
}

impl Settings {
    /// Values finite and in range, and a usable surface method.
    pub fn check(&self) -> Result<(), Invalid> {
        let s = self;
        let finite = s
            .background
            .iter()
            .chain(&s.attenuation)
            .chain([&s.ambient, &s.shadow_transmission])
            .all(|x| x.is_finite());
        if !finite {
            return Err(Invalid::Value("values must be finite"));
        }
        if !(0.0..=1.0).contains(&s.shadow_transmission) {
            return Err(Invalid::Value("shadow_transmission must lie in [0, 1]"));
        }
        if s.attenuation.iter().any(|&c| c < 0.0) || s.attenuation.iter().all(|&c| c == 0.0) {
            return Err(Invalid::Value("attenuation coefficients must be ≥ 0 and not all zero"));
        }
        s.surface_method.check().map_err(Invalid::SurfaceMethod)
    }
}
