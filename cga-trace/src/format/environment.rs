//! The `[environment]` table read and checked into an [`Environment`].

use super::Assets;
use super::given::first_given;
use super::numbers::{Num, V3};
use crate::environment::Environment;
use crate::invalid::Invalid;
use serde::Deserialize;
use std::ops::Range;
use toml::Spanned;

/// `[environment]`: a gradient (`zenith`, `horizon`, `nadir`; the horizon's colour where
/// one is left out) or an equirectangular `image` turned by `rotate` degrees about `+z` and
/// scaled by `strength`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct EnvironmentSpec {
    zenith: Option<Spanned<V3>>,
    horizon: Option<Spanned<V3>>,
    nadir: Option<Spanned<V3>>,
    image: Option<Spanned<String>>,
    rotate: Option<Spanned<Num>>,
    strength: Option<Spanned<Num>>,
}

impl EnvironmentSpec {
    /// The environment, checked: colours and strength ≥ 0; a gradient or an image, not both.
    pub(crate) fn build(&self, assets: &Assets) -> Result<Environment, Invalid> {
        let why = |field, span: Range<usize>, reason| Invalid::at(field, span, Invalid::Value(reason));
        let gradient = first_given(&[("zenith", &self.zenith), ("horizon", &self.horizon), ("nadir", &self.nadir)]);
        for (field, colour) in [("zenith", &self.zenith), ("horizon", &self.horizon), ("nadir", &self.nadir)] {
            if let Some(c) = colour.as_ref().filter(|c| c.get_ref().0.iter().any(|&x| x < 0.0)) {
                return Err(why(field, c.span(), "an environment's colours must be ≥ 0"));
            }
        }
        match (&self.image, gradient) {
            (Some(file), None) => {
                let strength = self.strength.as_ref().map_or(1.0, |s| s.get_ref().0);
                if strength < 0.0 {
                    return Err(why("strength", self.strength.as_ref().expect("given").span(), "must be ≥ 0"));
                }
                let turn = self.rotate.as_ref().map_or(0.0, |r| r.get_ref().0).to_radians();
                Ok(Environment::Map { picture: assets.image(file, "environment image")?, turn, strength })
            }
            (None, Some(_)) => {
                if let Some((field, span)) = first_given(&[("rotate", &self.rotate), ("strength", &self.strength)]) {
                    return Err(why(field, span, "`rotate` and `strength` are an image's: give `image`"));
                }
                let colour = |c: &Option<Spanned<V3>>| c.as_ref().map(|c| c.get_ref().0);
                let horizon =
                    colour(&self.horizon).or(colour(&self.zenith)).or(colour(&self.nadir)).unwrap_or([0.0; 3]);
                let (zenith, nadir) = (colour(&self.zenith).unwrap_or(horizon), colour(&self.nadir).unwrap_or(horizon));
                Ok(Environment::Gradient { zenith, horizon, nadir })
            }
            (Some(file), Some((field, _))) => Err(why(field, file.span(), "give a gradient or an `image`, not both")),
            (None, None) => {
                Err(Invalid::Form("an [environment] takes `zenith`, `horizon`, `nadir` (a gradient) or an `image`"))
            }
        }
    }
}
