//! `type = "torus"`: `centre`, `normal`, `radius` (of its core circle) and `tube`.

use super::kind::{At, Geometry, Kind, number, one, point, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use crate::shapes::TorusShape;
use cga_core::euclid::E3;

const TAKES: &str = "a torus takes `centre`, `normal`, `radius` (of its core circle) and `tube` (the tube's radius)";

pub(crate) const KIND: Kind = Kind { name: "torus", fields: Torus::FIELDS, takes: TAKES, read: read::<Torus> };

spec!(Torus { centre: V3 => Point, normal: V3 => Direction, radius: Num => Length, tube: Num => Length });

impl Geometry for Torus {
    /// It reaches its tube's radius beyond its core circle's.
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let reach = number(&self.radius).unwrap_or(0.0) + number(&self.tube).unwrap_or(0.0);
        Some((point(&self.centre)?, reach))
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (Some(c), Some(n), Some(r), Some(tube)) =
            (point(&self.centre), point(&self.normal), number(&self.radius), self.tube.as_ref())
        else {
            return Err(Invalid::Form(TAKES));
        };
        if !(tube.get_ref().0 > 0.0 && tube.get_ref().0.is_finite()) {
            return Err(Invalid::at("tube", tube.span(), Invalid::Value("the tube's radius must be positive")));
        }
        // Checked as given, before the frame scales it.
        TorusShape::new(c, n, r, tube.get_ref().0)?;
        let place = &at.place;
        let (c, n, r, tube) = (place.point(c)?, place.direction(n), place.length(r), place.length(tube.get_ref().0));
        Ok(one(TorusShape::new(c, n, r, tube)?))
    }
}
