//! `type = "spline"`: the surface through a list of `circles`, joined by `joining` (two by
//! two, Bézier segments, Catmull–Rom or Kochanek–Bartels with `tension`, `bias` and
//! `continuity`), with `caps`, the disks of its end circles.

use super::circles::{self, CircleSpec};
use super::kind::{At, Geometry, Kind, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::Num;
use crate::invalid::Invalid;
use cga_core::euclid::E3;
use serde::Deserialize;
use toml::Spanned;

const TAKES: &str = "a spline surface takes `circles`, `joining`, for joining = \"kochanek-bartels\" `tension`, `bias`, `continuity`, and `caps` (the end circles' disks, default false)";

pub(crate) const KIND: Kind = Kind { name: "spline", fields: Spline::FIELDS, takes: TAKES, read: read::<Spline> };

spec!(Spline {
    circles: Vec<Spanned<CircleSpec>> => Circles,
    joining: JoiningSpec => Other,
    tension: Num => Other,
    bias: Num => Other,
    continuity: Num => Other,
    caps: bool => Other,
});

/// How a spline surface joins its circles (`joining = "…"`).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum JoiningSpec {
    /// Consecutive circles joined two by two.
    #[default]
    Linear,
    /// Quadratic Bézier segments (2m + 1 circles).
    Quadratic,
    /// Cubic Bézier segments (3m + 1 circles).
    Cubic,
    /// Through every circle, C¹.
    CatmullRom,
    /// Through every circle, with `tension`, `bias`, `continuity`.
    KochanekBartels,
}

impl Geometry for Spline {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        circles::extent(self.circles.as_ref()?.get_ref().iter().map(Spanned::get_ref))
    }

    #[cfg(feature = "evolved")]
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        use super::circles::capped;
        use super::kind::flag;
        let surface = std::sync::Arc::new(self.surface(at)?);
        let ends = self.circles.as_ref().and_then(|c| Some([c.get_ref().first()?, c.get_ref().last()?]));
        Ok((capped(surface, ends.ok_or(Invalid::Form(TAKES))?, flag(&self.caps, false), at)?, None))
    }

    #[cfg(not(feature = "evolved"))]
    fn build(&self, _: &At) -> Result<Parts, Invalid> {
        Err(Invalid::NoEvolved)
    }

    /// With `caps`, its surface and end disks close a solid.
    fn closed(&self, _: &Assets) -> Result<bool, Invalid> {
        Ok(super::kind::flag(&self.caps, false))
    }
}

#[cfg(feature = "evolved")]
impl Spline {
    /// The surface through its circles, each moved by its own transform and then by the
    /// object's.
    fn surface(&self, at: &At) -> Result<crate::surface::SplineSurface, Invalid> {
        use super::circles::circle;
        use super::kind::{Fields, number};
        use cga_core::Joining;
        let circles = self.circles.as_ref().ok_or(Invalid::Form(TAKES))?;
        let joining = self.joining.as_ref().map_or(JoiningSpec::Linear, |j| *j.get_ref());
        if joining != JoiningSpec::KochanekBartels
            && let Some((field, span)) =
                ["tension", "bias", "continuity"].into_iter().find_map(|f| Some((f, self.span(f)?)))
        {
            return Err(Invalid::at(
                field,
                span,
                Invalid::Value("tension, bias and continuity need joining = \"kochanek-bartels\""),
            ));
        }
        let joining = match joining {
            JoiningSpec::Linear => Joining::Linear,
            JoiningSpec::Quadratic => Joining::Quadratic,
            JoiningSpec::Cubic => Joining::Cubic,
            JoiningSpec::CatmullRom => Joining::CATMULL_ROM,
            JoiningSpec::KochanekBartels => Joining::KochanekBartels {
                tension: number(&self.tension).unwrap_or(0.0),
                bias: number(&self.bias).unwrap_or(0.0),
                continuity: number(&self.continuity).unwrap_or(0.0),
            },
        };
        let mut built = Vec::with_capacity(circles.get_ref().len());
        for (k, c) in circles.get_ref().iter().enumerate() {
            let reason = |e| {
                Invalid::at("circles", c.span(), Invalid::Indexed { what: "circle", index: k + 1, reason: Box::new(e) })
            };
            built.push(circle(c.get_ref(), &at.place).map_err(reason)?);
        }
        Ok(crate::surface::SplineSurface::new(&built, joining, at.method)?)
    }
}
