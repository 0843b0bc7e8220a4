//! A `[[lights]]` table read and checked into a [`Light`] in the scene's frame.

use super::given::first_given;
use super::numbers::{Num, V3};
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::light::{Light, Source as Emitter};
use crate::limits::MAX_LIGHT_SAMPLES;
use cga_core::GeometryError;
use cga_core::euclid::{E3, norm, sub};
use serde::Deserialize;
use std::ops::Range;
use toml::Spanned;

/// A `[[lights]]` table: `position` (a point light), `direction` (a directional light: the
/// way its light travels), or both (a spot light shining along `direction`, full within
/// `radius` degrees of it and dark beyond `falloff`, as POV-Ray's `spotlight`), and a colour.
/// With `position`, `sphere = r` makes it a sphere of light of radius `r`, and `disk = r`
/// with `normal` a disk of light: area lights, `samples` of whose points light each hit.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LightSpec {
    position: Option<Spanned<V3>>,
    direction: Option<Spanned<V3>>,
    radius: Option<Spanned<Num>>,
    falloff: Option<Spanned<Num>>,
    colour: Option<Spanned<V3>>,
    sphere: Option<Spanned<Num>>,
    disk: Option<Spanned<Num>>,
    normal: Option<Spanned<V3>>,
    samples: Option<Spanned<u32>>,
}

/// Points of an area light that light each hit where a file gives no `samples`.
const AREA_SAMPLES: u32 = 16;

/// POV-Ray's spot light angles where a file gives none: full light within 30° of the axis,
/// none beyond 45°.
const SPOT_RADIUS: f64 = 30.0;
const SPOT_FALLOFF: f64 = 45.0;

impl LightSpec {
    /// The light in `frame`: colour non-negative; a point light's position one the frame
    /// holds; a directional light's direction not zero; a spot light's angles with
    /// `0 ≤ radius ≤ falloff ≤ 90` degrees.
    pub(crate) fn build(self, frame: &Frame) -> Result<Light, Invalid> {
        let colour = self.colour.as_ref().map_or([1.0; 3], |c| c.get_ref().0);
        if let Some(c) = self.colour.as_ref().filter(|_| colour.iter().any(|&c| c < 0.0)) {
            return Err(Invalid::at("colour", c.span(), Invalid::Value("a light's colour must be ≥ 0")));
        }
        if let Some(area) = self.area(frame)? {
            return Ok(Light { source: area, colour });
        }
        if (self.position.is_none() || self.direction.is_none())
            && let Some(a) = self.radius.as_ref().or(self.falloff.as_ref())
        {
            let why = Invalid::Value("`radius` and `falloff` are a spot light's: give it `position` and `direction`");
            return Err(Invalid::at(if self.radius.is_some() { "radius" } else { "falloff" }, a.span(), why));
        }
        let source = match (self.position, self.direction) {
            (Some(p), None) => Emitter::Point(light_position(&p, frame)?),
            (None, Some(d)) => {
                let unit = cga_core::euclid::unit(d.get_ref().0);
                Emitter::Directional(unit.ok_or(Invalid::at(
                    "direction",
                    d.span(),
                    GeometryError::ZeroVector.into(),
                ))?)
            }
            (Some(p), Some(d)) => {
                let position = light_position(&p, frame)?;
                let axis = cga_core::euclid::unit(d.get_ref().0);
                let axis = axis.ok_or(Invalid::at("direction", d.span(), GeometryError::ZeroVector.into()))?;
                let angle = |a: &Option<Spanned<Num>>, default| a.as_ref().map_or(default, |a| a.get_ref().0);
                let (radius, falloff) = (angle(&self.radius, SPOT_RADIUS), angle(&self.falloff, SPOT_FALLOFF));
                if !(0.0 < falloff && falloff <= 90.0 && 0.0 <= radius && radius <= falloff) {
                    // The radius when it is out of range or past the falloff, else the falloff.
                    let radius_wrong = self.radius.is_some() && !(0.0 <= radius && radius <= falloff && radius <= 90.0);
                    let (field, given) =
                        if radius_wrong { ("radius", &self.radius) } else { ("falloff", &self.falloff) };
                    let span = given.as_ref().or(self.radius.as_ref()).map_or(p.span(), |a| a.span());
                    let why = Invalid::Value("a spot light needs 0 ≤ radius ≤ falloff ≤ 90 degrees, falloff > 0");
                    return Err(Invalid::at(field, span, why));
                }
                let (cos_radius, cos_falloff) = (radius.to_radians().cos(), falloff.to_radians().cos());
                // A hard edge where the angles agree.
                let inverse_width = 1.0 / (cos_radius - cos_falloff).max(1e-12);
                Emitter::Spot { position, axis, cos_falloff, inverse_width }
            }
            (None, None) => {
                return Err(Invalid::Form(
                    "a light takes `position` (a point light), `direction` (a directional light), or both (a spot light)",
                ));
            }
        };
        Ok(Light { source, colour })
    }
}

impl LightSpec {
    /// The area light the table gives (`sphere` or `disk`), checked: a `position`, a radius
    /// `> 0` that the frame holds, a disk's non-zero `normal`, `1 ..= MAX_LIGHT_SAMPLES`
    /// samples; `None` for the other lights (which take none of these fields).
    fn area(&self, frame: &Frame) -> Result<Option<Emitter>, Invalid> {
        let at = |field, span: Range<usize>, why| Invalid::at(field, span, Invalid::Value(why));
        let radius = match (&self.sphere, &self.disk) {
            (Some(_), Some(d)) => return Err(at("disk", d.span(), "give `sphere` or `disk`, not both")),
            (Some(r), None) | (None, Some(r)) => r,
            (None, None) => {
                let stray = first_given(&[("normal", &self.normal), ("samples", &self.samples)]);
                return match stray {
                    Some((field, span)) => {
                        Err(at(field, span, "`normal` and `samples` are an area light's: give it `sphere` or `disk`"))
                    }
                    None => Ok(None),
                };
            }
        };
        let field = if self.sphere.is_some() { "sphere" } else { "disk" };
        let Some(p) = &self.position else {
            return Err(at(field, radius.span(), "an area light needs its centre as `position`"));
        };
        let spot = first_given(&[("direction", &self.direction), ("radius", &self.radius), ("falloff", &self.falloff)]);
        if let Some((field, span)) = spot {
            return Err(at(
                field,
                span,
                "an area light takes `position`, `sphere` or `disk` (its radius), `normal` (a disk's) and `samples`, not a spot light's `direction`, `radius` or `falloff`",
            ));
        }
        let r = frame.length(radius.get_ref().0);
        if !(r > 0.0 && Frame::holds(r)) {
            return Err(at(field, radius.span(), "an area light's radius must be > 0 and within the scene's range"));
        }
        let samples = self.samples.as_ref().map_or(AREA_SAMPLES, |n| *n.get_ref());
        if !(1..=MAX_LIGHT_SAMPLES).contains(&samples) {
            let span = self.samples.as_ref().expect("given").span();
            let why = Invalid::Limit {
                what: "samples of an area light",
                found: u64::from(samples),
                limit: u64::from(MAX_LIGHT_SAMPLES),
            };
            return Err(Invalid::at(
                "samples",
                span,
                if samples == 0 { Invalid::Value("an area light needs at least 1 sample") } else { why },
            ));
        }
        let centre = light_position(p, frame)?;
        Ok(Some(match (self.sphere.is_some(), &self.normal) {
            (true, None) => Emitter::Sphere { centre, radius: r, samples },
            (true, Some(n)) => return Err(at("normal", n.span(), "a sphere of light takes no `normal` (a disk does)")),
            (false, Some(n)) => {
                let normal = cga_core::euclid::unit(n.get_ref().0);
                let normal = normal.ok_or(Invalid::at("normal", n.span(), GeometryError::ZeroVector.into()))?;
                Emitter::Disk { centre, normal, radius: r, samples }
            }
            (false, None) => return Err(at("disk", radius.span(), "a disk of light needs its `normal`")),
        }))
    }
}

/// A point or spot light's position in `frame`. A light forms no conformal products: any
/// distance whose norm f64 holds (with room for the distances from points of the scene)
/// will do.
fn light_position(p: &Spanned<V3>, frame: &Frame) -> Result<E3, Invalid> {
    let x = frame.point(p.get_ref().0);
    let d = norm(x);
    if d.is_nan() || d > 1e300 {
        let why = format!(
            "the light is {:.1e} from the camera, more than f64 holds in units of the scene's size ({:.1e}): give it as `direction` (a light that far is a directional light)",
            norm(sub(p.get_ref().0, frame.origin)),
            frame.scale
        );
        return Err(Invalid::at("position", p.span(), Invalid::Range(why)));
    }
    Ok(x)
}
