//! The `[render]` table and an object's `material` as scene files write them: every field
//! optional but a material's `colour`, numbers checked as they are read ([`super::numbers`]),
//! and what is not given taken from the domain's defaults ([`Settings::default`],
//! [`Material::new`]), so that no default is written twice.

use super::numbers::{numbers, some_number, some_numbers};
use crate::limits::MAX_BLUR_SAMPLES;
use crate::material::Material;
use crate::settings::{Adaptive, AdaptiveMethod, Background, Encoding, Reflection, Settings, ToneMap};
use crate::surface::Method;
use serde::Deserialize;
use serde::de::{Deserializer, Error, MapAccess, Visitor};
use std::fmt;

/// A `[render]` table.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SettingsSpec {
    max_depth: Option<u32>,
    spp: Option<u32>,
    adaptive: Option<AdaptiveSpec>,
    blur_samples: Option<BlurSpec>,
    background: Option<BackgroundSpec>,
    #[serde(default, deserialize_with = "some_number")]
    ambient: Option<f64>,
    #[serde(default, deserialize_with = "some_number")]
    shadow_transmission: Option<f64>,
    shadows: Option<bool>,
    #[serde(default, deserialize_with = "some_numbers")]
    attenuation: Option<[f64; 3]>,
    encoding: Option<EncodingSpec>,
    #[serde(default, deserialize_with = "some_number")]
    exposure: Option<f64>,
    tone_map: Option<ToneMapSpec>,
    reflection: Option<ReflectionSpec>,
    surface_method: Option<Method>,
}

/// `adaptive = 0.3` (the threshold, the first samples [`Adaptive::MIN_SPP`]) or
/// `adaptive = { threshold = 0.3, min_spp = 8, method = "samples" }` (`method = "corners"`:
/// POV-Ray's method 2, [`AdaptiveMethod`]), checked as read.
#[derive(Clone, Copy, Debug)]
struct AdaptiveSpec(Adaptive);

impl<'de> Deserialize<'de> for AdaptiveSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Spec;
        impl<'de> Visitor<'de> for Spec {
            type Value = Adaptive;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(
                    "a contrast threshold (a number such as 0.3) or { threshold = 0.3, min_spp = 4, method = \"samples\" or \"corners\" }",
                )
            }
            fn visit_f64<E: Error>(self, threshold: f64) -> Result<Adaptive, E> {
                Ok(Adaptive::threshold(threshold))
            }
            fn visit_i64<E: Error>(self, threshold: i64) -> Result<Adaptive, E> {
                Ok(Adaptive::threshold(threshold as f64))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Adaptive, A::Error> {
                let (mut threshold, mut min_spp, mut method) = (None, None, AdaptiveMethod::Samples);
                while let Some(key) = map.next_key::<String>()? {
                    match key.as_str() {
                        "threshold" => threshold = Some(map.next_value::<f64>()?),
                        "min_spp" => min_spp = Some(map.next_value::<u32>()?),
                        "method" => method = map.next_value::<MethodSpec>()?.0,
                        other => return Err(A::Error::unknown_field(other, &["threshold", "min_spp", "method"])),
                    }
                }
                let threshold = threshold.ok_or_else(|| A::Error::missing_field("threshold"))?;
                Ok(Adaptive { threshold, min_spp: min_spp.unwrap_or(Adaptive::MIN_SPP), method })
            }
        }
        let a = d.deserialize_any(Spec)?;
        a.check().map_err(D::Error::custom)?;
        Ok(AdaptiveSpec(a))
    }
}

/// `blur_samples = M`, checked as read (so that an error names its line).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(try_from = "u32")]
struct BlurSpec(u32);

impl TryFrom<u32> for BlurSpec {
    type Error = &'static str;
    fn try_from(m: u32) -> Result<Self, Self::Error> {
        match m {
            1..=MAX_BLUR_SAMPLES => Ok(BlurSpec(m)),
            _ => Err("blur_samples (lens rays a sample) must be 1 to 256"),
        }
    }
}

/// `method = "samples"` or `"corners"` of `adaptive`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(try_from = "String")]
struct MethodSpec(AdaptiveMethod);

impl TryFrom<String> for MethodSpec {
    type Error = String;
    fn try_from(name: String) -> Result<Self, String> {
        match name.as_str() {
            "samples" => Ok(MethodSpec(AdaptiveMethod::Samples)),
            "corners" => Ok(MethodSpec(AdaptiveMethod::Corners)),
            other => Err(format!("adaptive method `{other}`: give \"samples\" or \"corners\" (POV-Ray's method 2)")),
        }
    }
}

/// `background = [r, g, b]` (linear RGB, checked as read) or `background = "transparent"`.
#[derive(Clone, Copy, Debug)]
struct BackgroundSpec(Background);

impl<'de> Deserialize<'de> for BackgroundSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Spec;
        impl<'de> Visitor<'de> for Spec {
            type Value = Background;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a linear RGB colour [r, g, b] or \"transparent\"")
            }
            fn visit_str<E: Error>(self, v: &str) -> Result<Background, E> {
                match v {
                    "transparent" => Ok(Background::Transparent),
                    _ => Err(E::invalid_value(serde::de::Unexpected::Str(v), &self)),
                }
            }
            // The colour's own checks and messages (`expected 3 numbers, found 4`).
            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, seq: A) -> Result<Background, A::Error> {
                numbers(serde::de::value::SeqAccessDeserializer::new(seq)).map(Background::Colour)
            }
        }
        d.deserialize_any(Spec).map(BackgroundSpec)
    }
}

/// `reflection = "additive" | "conserving"`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "lowercase")]
enum ReflectionSpec {
    Additive,
    Conserving,
}

/// `tone_map = "none" | "filmic"`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "lowercase")]
enum ToneMapSpec {
    None,
    Filmic,
}

/// `encoding = "srgb" | "linear"`.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(rename_all = "lowercase")]
enum EncodingSpec {
    Srgb,
    Linear,
}

impl From<SettingsSpec> for Settings {
    fn from(s: SettingsSpec) -> Settings {
        let d = Settings::default();
        let mut settings = Settings {
            max_depth: s.max_depth.unwrap_or(d.max_depth),
            spp: s.spp.unwrap_or(d.spp),
            adaptive: s.adaptive.map(|a| a.0).or(d.adaptive),
            blur_samples: s.blur_samples.map_or(d.blur_samples, |b| b.0),
            background: d.background,
            transparent: d.transparent,
            ambient: s.ambient.unwrap_or(d.ambient),
            shadow_transmission: s.shadow_transmission.unwrap_or(d.shadow_transmission),
            shadows: s.shadows.unwrap_or(d.shadows),
            attenuation: s.attenuation.unwrap_or(d.attenuation),
            encoding: match s.encoding {
                Some(EncodingSpec::Srgb) => Encoding::Srgb,
                Some(EncodingSpec::Linear) => Encoding::Linear,
                None => d.encoding,
            },
            exposure: s.exposure.unwrap_or(d.exposure),
            tone_map: match s.tone_map {
                Some(ToneMapSpec::None) => ToneMap::None,
                Some(ToneMapSpec::Filmic) => ToneMap::Filmic,
                None => d.tone_map,
            },
            reflection: match s.reflection {
                Some(ReflectionSpec::Additive) => Reflection::Additive,
                Some(ReflectionSpec::Conserving) => Reflection::Conserving,
                None => d.reflection,
            },
            surface_method: s.surface_method.unwrap_or(d.surface_method),
        };
        if let Some(BackgroundSpec(background)) = s.background {
            settings.set_background(background);
        }
        settings
    }
}

/// An object's `material`: `colour` and any of `ka`, `kd`, `ks`, `q`, `kr`, `ior`,
/// `absorption`, `texture`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct MaterialSpec {
    #[serde(deserialize_with = "numbers")]
    colour: [f64; 3],
    #[serde(default, deserialize_with = "some_number")]
    ka: Option<f64>,
    #[serde(default, deserialize_with = "some_number")]
    kd: Option<f64>,
    #[serde(default, deserialize_with = "some_number")]
    ks: Option<f64>,
    #[serde(default, deserialize_with = "some_number")]
    q: Option<f64>,
    #[serde(default, deserialize_with = "some_number")]
    kr: Option<f64>,
    /// A dielectric's index of refraction (glass 1.5, water 1.33).
    #[serde(default, deserialize_with = "some_number")]
    ior: Option<f64>,
    /// A dielectric's absorption per world unit, per channel.
    #[serde(default, deserialize_with = "some_numbers")]
    absorption: Option<[f64; 3]>,
    /// A texture in place of `colour`.
    #[serde(default)]
    pub texture: Option<toml::Spanned<TextureSpec>>,
    /// A texture's values as heights that tilt the shading normal, with its `strength`.
    #[serde(default)]
    pub bump: Option<toml::Spanned<TextureSpec>>,
}

/// A material's `texture` (or `bump`): a `pattern` (`"checker"`, `"stripes"`, `"gradient"`,
/// `"noise"`, `"marble"`, `"bricks"`) with the second `colour`, or an `image` file; its
/// placement (`scale`, `rotate`, `offset`, `flip`) and `repeat = [u, v]` (default 1, 1) cells
/// or copies per unit of the surface's `(u, v)`; the patterns' own parameters (`along`,
/// `turbulence`, `octaves`, `seed`, `brick`, `mortar`); a bump's `strength`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct TextureSpec {
    pub pattern: Option<toml::Spanned<PatternSpec>>,
    #[serde(default, deserialize_with = "some_numbers")]
    pub colour: Option<[f64; 3]>,
    pub image: Option<toml::Spanned<String>>,
    #[serde(default, deserialize_with = "some_numbers")]
    pub repeat: Option<[f64; 2]>,
    /// How much larger the pattern is along `u` and `v`.
    #[serde(default, deserialize_with = "some_numbers")]
    pub scale: Option<[f64; 2]>,
    /// Degrees, counter-clockwise from `u` towards `v`.
    #[serde(default, deserialize_with = "some_number")]
    pub rotate: Option<f64>,
    /// Where the pattern's origin lies in `(u, v)`.
    #[serde(default, deserialize_with = "some_numbers")]
    pub offset: Option<[f64; 2]>,
    /// Which parameters it is mirrored along.
    pub flip: Option<FlipSpec>,
    /// A gradient's direction.
    pub along: Option<AxisSpec>,
    /// How far noise bends marble's veins.
    #[serde(default, deserialize_with = "some_number")]
    pub turbulence: Option<f64>,
    /// Octaves of noise or marble.
    pub octaves: Option<u32>,
    /// Which noise.
    pub seed: Option<u32>,
    /// A brick's length and height.
    #[serde(default, deserialize_with = "some_numbers")]
    pub brick: Option<[f64; 2]>,
    /// Bricks' mortar width.
    #[serde(default, deserialize_with = "some_number")]
    pub mortar: Option<f64>,
    /// A bump's slope per unit of height and cell.
    #[serde(default, deserialize_with = "some_number")]
    pub strength: Option<f64>,
}

/// A texture's `pattern`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum PatternSpec {
    /// Cells of two colours.
    Checker,
    /// Bands of two colours along `u`.
    Stripes,
    /// From one colour to the other along `u` or `v`.
    Gradient,
    /// Value noise.
    Noise,
    /// Veins bent by noise.
    Marble,
    /// Bricks in mortar.
    Bricks,
}

/// A texture's `flip`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
pub(crate) enum FlipSpec {
    /// `u ↦ −u`.
    #[serde(rename = "u")]
    U,
    /// `v ↦ −v`.
    #[serde(rename = "v")]
    V,
    /// Both.
    #[serde(rename = "uv")]
    Both,
}

/// A gradient's `along`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
pub(crate) enum AxisSpec {
    /// Along `u`.
    #[serde(rename = "u")]
    U,
    /// Along `v`.
    #[serde(rename = "v")]
    V,
}

/// An object's `material`: a table, or the name of one of the file's `[materials.NAME]`
/// tables.
#[derive(Clone, Debug)]
pub(crate) enum MaterialRef {
    /// `material = "gold"`.
    Named(String),
    /// `material = { colour = … }`.
    Given(Box<MaterialSpec>),
}

impl<'de> Deserialize<'de> for MaterialRef {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Either;
        impl<'de> serde::de::Visitor<'de> for Either {
            type Value = MaterialRef;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a material table ({ colour = [r, g, b], … }) or the name of a [materials.NAME] table")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<MaterialRef, E> {
                Ok(MaterialRef::Named(name.to_string()))
            }
            // A table keeps its own fields' errors (a serde untagged enum would lose them).
            fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<MaterialRef, A::Error> {
                MaterialSpec::deserialize(serde::de::value::MapAccessDeserializer::new(map))
                    .map(|m| MaterialRef::Given(Box::new(m)))
            }
        }
        d.deserialize_any(Either)
    }
}

impl From<&MaterialSpec> for Material {
    fn from(s: &MaterialSpec) -> Material {
        let d = Material::new(s.colour);
        Material {
            colour: s.colour,
            ka: s.ka.unwrap_or(d.ka),
            kd: s.kd.unwrap_or(d.kd),
            ks: s.ks.unwrap_or(d.ks),
            q: s.q.unwrap_or(d.q),
            kr: s.kr.unwrap_or(d.kr),
            ior: s.ior.unwrap_or(d.ior),
            absorption: s.absorption.unwrap_or(d.absorption),
        }
    }
}
