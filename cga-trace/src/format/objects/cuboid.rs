//! `type = "box"`: its opposite corners `min` and `max` (turned with the object's motor).

use super::kind::{At, Geometry, Kind, one, point, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::V3;
use crate::invalid::Invalid;
use crate::shapes::BoxShape;
use cga_core::GeometryError;
use cga_core::euclid::{E3, norm, sub};

const TAKES: &str = "a box takes its opposite corners `min` and `max` (turn it with `motor` or `transform`)";

pub(crate) const KIND: Kind = Kind { name: "box", fields: Cuboid::FIELDS, takes: TAKES, read: read::<Cuboid> };

spec!(Cuboid { min: V3 => Point, max: V3 => Point });

impl Geometry for Cuboid {
    /// Its centre, and half its diagonal.
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let (lo, hi) = (point(&self.min)?, point(&self.max)?);
        Some(([0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k])), 0.5 * norm(sub(hi, lo))))
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (Some(lo), Some(hi)) = (point(&self.min), self.max.as_ref()) else { return Err(Invalid::Form(TAKES)) };
        let box_ = BoxShape::between(lo, hi.get_ref().0).map_err(|e| match e {
            GeometryError::ZeroRadius => {
                Invalid::at("max", hi.span(), Invalid::Value("`max` must exceed `min` on every axis"))
            }
            e => e.into(),
        })?;
        let place = &at.place;
        let axes = box_.axes.map(|a| place.direction(a));
        let half = box_.half.map(|h| place.length(h));
        Ok(one(BoxShape::new(half, place.point(box_.centre)?, axes)?))
    }
}
