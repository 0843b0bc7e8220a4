//! Render settings: depth, background (a colour, or transparent), ambient light, shadows,
//! attenuation, output encoding, and how evolved surfaces are intersected.

pub use crate::film::{Encoding, ToneMap};
use crate::invalid::Invalid;
use crate::limits::{MAX_BLUR_SAMPLES, MAX_DEPTH, MAX_SPP};
use crate::surface::Method;

/// How a hit's mirror reflection adds to its own colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Reflection {
    /// `I = I_local + k_r I_reflected`: the paper's eq. 12, which the reference images use
    /// (a mirror adds light on top of its own shading).
    #[default]
    Additive,
    /// `I = (1 − k_r) I_local + k_r I_reflected`: what a surface reflects it does not also
    /// shade, so no bounce makes more light than it receives.
    Conserving,
}

/// Adaptive anti-aliasing: `spp` becomes a maximum, spent where the picture changes. Two
/// methods ([`AdaptiveMethod`]): POV-Ray's method 1 and pbrt-v2's test together
/// ([`AdaptiveMethod::Samples`], the default), or POV-Ray's method 2 ([`AdaptiveMethod::Corners`]).
/// Both decide by POV-Ray's colour distance (`+A0.3`): `Σ_c (max_s d_c − min_s d_c)` over R, G,
/// B of the samples, `Σ_c |d_c(a) − d_c(b)|` between two values, of the values as a PNG of the
/// picture shows them, `d = clamp(T(2^exposure · colour), 0, 1)` with `T` its tone map.
/// Every sample is placed by its position alone: any thread count or crop gives the same
/// bytes. The shaded picture only; AOVs, and a picture through a shutter, take every sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptive {
    /// The contrast above which a pixel (or a square of one) takes more samples, in [0, 3]
    /// (POV-Ray's default is 0.3; 0: wherever its samples differ at all).
    pub threshold: f64,
    /// The samples every pixel takes first under [`AdaptiveMethod::Samples`], 1 to
    /// [`MAX_SPP`] (at least `spp`: nothing adapts; 1: POV-Ray's method 1, the neighbours
    /// alone decide). [`AdaptiveMethod::Corners`] does not use it.
    pub min_spp: u32,
    /// Where the samples go.
    pub method: AdaptiveMethod,
}

/// Where adaptive sampling puts a pixel's samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum AdaptiveMethod {
    /// Each pixel first takes `min_spp` of its stratified samples (a prefix of its sequence,
    /// spread over the pixel); it takes the rest only where their contrast, or the distance
    /// between its mean and a neighbour's (left, right, below, above), exceeds the threshold.
    /// A pixel's result depends on its own samples and its neighbours' first ones.
    #[default]
    Samples,
    /// POV-Ray's method 2 (`+AM2`): one ray at each pixel corner, shared by the four pixels
    /// that meet there (one ray a pixel where the picture is flat). A square whose four
    /// corners differ pairwise by more than the threshold is cut into four, tracing its edges'
    /// midpoints and centre, down to `⌊log₄ spp⌋` levels (`spp` 16: 4 × 4 squares a pixel,
    /// as POV-Ray's `+R3`); a square's value is the mean of its quarters' values, a square
    /// not cut the mean of its corners.
    Corners,
}

impl Adaptive {
    /// The first samples a pixel takes where a scene gives only the threshold: 4, one in each
    /// quarter of the pixel.
    pub const MIN_SPP: u32 = 4;

    /// POV-Ray's default threshold (`+A` alone), where only the first samples are given.
    pub const THRESHOLD: f64 = 0.3;

    /// The threshold with the default first samples.
    pub fn threshold(threshold: f64) -> Self {
        Adaptive { threshold, min_spp: Self::MIN_SPP, method: AdaptiveMethod::Samples }
    }

    /// Whether it takes fewer samples than every pixel's `spp`: `spp` above the first
    /// samples ([`AdaptiveMethod::Samples`]), or at least one cut of a pixel, `spp ≥ 4`
    /// ([`AdaptiveMethod::Corners`]).
    pub fn adapts(&self, spp: u32) -> bool {
        match self.method {
            AdaptiveMethod::Samples => spp > self.min_spp,
            AdaptiveMethod::Corners => spp >= 4,
        }
    }

    /// How many times [`AdaptiveMethod::Corners`] may cut a pixel's squares in four:
    /// `⌊log₄ spp⌋` (6 at [`MAX_SPP`]).
    pub fn levels(spp: u32) -> u32 {
        spp.max(1).ilog2() / 2
    }

    /// `threshold` finite in [0, 3], `min_spp` in 1 ..= [`MAX_SPP`].
    pub fn check(&self) -> Result<(), Invalid> {
        if !(0.0..=3.0).contains(&self.threshold) {
            return Err(Invalid::Value("the adaptive threshold must lie in [0, 3] (POV-Ray's default is 0.3)"));
        }
        if !(1..=MAX_SPP).contains(&self.min_spp) {
            return Err(Invalid::Value("adaptive min_spp must be 1 to 4096"));
        }
        Ok(())
    }
}

/// What camera rays that meet nothing show, as a scene, the command line or a figure gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Background {
    /// A linear RGB colour (the picture is opaque).
    Colour([f64; 3]),
    /// Nothing: the picture carries each pixel's coverage (an alpha channel), and what
    /// reflected and refracted rays that leave the scene see is the environment, or black.
    Transparent,
}

/// Exposure, in stops, a scene or the command line may set: 2^±64 spans any range of
/// linear values a picture needs.
pub const MAX_EXPOSURE: f64 = 64.0;

/// Global render settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Reflection depth: bounces after the first hit (at most [`MAX_DEPTH`]).
    pub max_depth: u32,
    /// Samples per pixel, stratified over the pixel (at most [`MAX_SPP`]; 1: the centre); the
    /// most a pixel takes where `adaptive` is set.
    pub spp: u32,
    /// Adaptive anti-aliasing (`None`: every pixel takes `spp` samples).
    pub adaptive: Option<Adaptive>,
    /// Camera rays each sample averages through a thin lens, POV-Ray's `blur_samples`: ray
    /// `r` of `m` of sample `s` of `spp` takes lens point number `s m + r` of the pixel's
    /// `spp · m` stratified ones, so the lens is sampled `m` times as finely while adaptive
    /// sampling compares the samples' means (a blur's noise then no longer looks like an
    /// edge). 1 to [`MAX_BLUR_SAMPLES`]; a pinhole or orthographic camera, and an AOV, take
    /// one ray a sample.
    pub blur_samples: u32,
    /// Colour of rays that hit nothing (black where `transparent`).
    pub background: [f64; 3],
    /// Camera rays that meet nothing are transparent (`background = "transparent"`): the
    /// picture carries each pixel's coverage, the fraction of its samples whose camera ray met
    /// something, and its colours are premultiplied by it (misses add nothing).
    pub transparent: bool,
    /// Ambient light intensity (times `k_a` and the colour).
    pub ambient: f64,
    /// Fraction of a light's diffuse and specular that passes a blocker (0: hard shadows).
    pub shadow_transmission: f64,
    /// Whether shadow rays are cast at all (`false`: every light reaches every point).
    pub shadows: bool,
    /// `f_att = min(1, 1 / (c0 + c1 d + c2 d²))`, `d` the distance to the light.
    pub attenuation: [f64; 3],
    /// PNG encoding.
    pub encoding: Encoding,
    /// Exposure in stops for PNG output: linear values times `2^exposure` (EXR and HDR keep
    /// them as rendered).
    pub exposure: f64,
    /// The tone map of PNG output, after the exposure.
    pub tone_map: ToneMap,
    /// How mirror reflections add to a hit's colour.
    pub reflection: Reflection,
    /// How rays meet evolved surfaces (default: hybrid — α-cells cull, the degree-8
    /// polynomial finds the roots; docs/SURFACE.md).
    pub surface_method: Method,
}

/// What a scene gets where it sets nothing: 5 bounces, one sample per pixel (the centre), no
/// adaptive sampling, a black (opaque) background, ambient 0.3, hard shadows, no attenuation, sRGB,
/// the hybrid surface method.
impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_depth: 5,
            spp: 1,
            adaptive: None,
            blur_samples: 1,
            background: [0.0; 3],
            transparent: false,
            ambient: 0.3,
            shadow_transmission: 0.0,
            shadows: true,
            attenuation: [1.0, 0.0, 0.0],
            encoding: Encoding::Srgb,
            exposure: 0.0,
            tone_map: ToneMap::None,
            reflection: Reflection::Additive,
            surface_method: Method::default(),
        }
    }
}

impl Settings {
    /// The background as given: its colour, or transparent.
    pub fn background(&self) -> Background {
        if self.transparent { Background::Transparent } else { Background::Colour(self.background) }
    }

    /// The background set to `background`: a transparent one is black to the rays that leave
    /// the scene (where no environment is given), as nothing lies behind it.
    pub fn set_background(&mut self, background: Background) {
        (self.background, self.transparent) = match background {
            Background::Colour(c) => (c, false),
            Background::Transparent => ([0.0; 3], true),
        };
    }

    /// Values finite and in range, counts within [`crate::limits`], and a usable surface
    /// method.
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
        if s.max_depth > MAX_DEPTH {
            return Err(Invalid::Limit {
                what: "bounces (max_depth)",
                found: s.max_depth.into(),
                limit: MAX_DEPTH.into(),
            });
        }
        if !(1..=MAX_SPP).contains(&s.spp) {
            return Err(Invalid::Value("spp (samples per pixel) must be 1 to 4096"));
        }
        if !(1..=MAX_BLUR_SAMPLES).contains(&s.blur_samples) {
            return Err(Invalid::Value("blur_samples (lens rays a sample) must be 1 to 256"));
        }
        if let Some(a) = &s.adaptive {
            a.check()?;
        }
        if s.ambient < 0.0 || s.background.iter().any(|&c| c < 0.0) {
            return Err(Invalid::Value("ambient and background must be ≥ 0"));
        }
        if !s.exposure.is_finite() || s.exposure.abs() > MAX_EXPOSURE {
            return Err(Invalid::Value("exposure must lie in [-64, 64] stops"));
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
