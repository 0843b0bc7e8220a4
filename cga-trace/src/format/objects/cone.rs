//! `type = "cone"`: its axis's ends `p1` and `p2`, their radii `r1` and `r2`, and `caps`;
//! and what a cylinder (`cylinder.rs`, one radius) shares with it.

use super::kind::{At, Ends, Geometry, Kind, ends, flag, number, one, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::Num;
use crate::invalid::Invalid;
use crate::shapes::ConeShape;
use cga_core::euclid::{E3, norm, sub};
use toml::Spanned;

const TAKES: &str =
    "a cone takes its axis's ends `p1` and `p2` (one point each), their radii `r1` and `r2`, and `caps` (default true)";

pub(crate) const KIND: Kind = Kind { name: "cone", fields: Cone::FIELDS, takes: TAKES, read: read::<Cone> };

spec!(Cone { p1: Ends => Point, r1: Num => Length, p2: Ends => Point, r2: Num => Length, caps: bool => Other });

impl Geometry for Cone {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let radius = number(&self.r1).unwrap_or(0.0).max(number(&self.r2).unwrap_or(0.0));
        extent(&self.p1, &self.p2, radius)
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (Some(r1), Some(r2)) = (number(&self.r1), number(&self.r2)) else { return Err(Invalid::Form(TAKES)) };
        build(TAKES, (&self.p1, r1), (&self.p2, r2), flag(&self.caps, true), at)
    }

    fn coincident(&self) -> &'static str {
        "p2"
    }
}

/// From the first end, as far as the other end and the widest radius reach.
pub(super) fn extent(p1: &Option<Spanned<Ends>>, p2: &Option<Spanned<Ends>>, radius: f64) -> Option<(E3, f64)> {
    let (a, b) = (p1.as_ref()?.get_ref().points().first()?.0, p2.as_ref()?.get_ref().points().first()?.0);
    Some((a, norm(sub(b, a)) + radius.max(0.0)))
}

/// The cone between the ends (one point each) of radii `r1` and `r2`, checked as given, then
/// placed.
pub(super) fn build(
    takes: &'static str,
    (p1, r1): (&Option<Spanned<Ends>>, f64),
    (p2, r2): (&Option<Spanned<Ends>>, f64),
    caps: bool,
    at: &At,
) -> Result<Parts, Invalid> {
    let (Some(a), Some(b)) = (p1, p2) else { return Err(Invalid::Form(takes)) };
    let ([a], [b]) = (ends("p1", a)?, ends("p2", b)?);
    ConeShape::new(a, r1, b, r2, caps)?;
    let place = &at.place;
    let (a, b) = (place.point(a)?, place.point(b)?);
    Ok(one(ConeShape::new(a, place.length(r1), b, place.length(r2), caps)?))
}
