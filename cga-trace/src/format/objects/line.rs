//! `type = "line"`: the line through `point` along `direction`, drawn as a tube.

use super::drawn::{Draws, read, sized};
use super::kind::{Kind, point, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use cga_core::GeometryError;
use cga_core::euclid::unit;

const TAKES: &str = "a line takes `point` and `direction`, and optionally `tube` (its cylinder's radius)";

pub(crate) const KIND: Kind = Kind { name: "line", fields: LineSpec::FIELDS, takes: TAKES, read: read::<LineSpec> };

spec!(LineSpec { point: V3 => Point, direction: V3 => Direction, tube: Num => Length });

impl Draws for LineSpec {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&None, &self.tube, defaults)?;
        let (Some(point), Some(d)) = (point(&self.point), self.direction.as_ref()) else {
            return Err(Invalid::Form(TAKES));
        };
        let zero = || Invalid::at("direction", d.span(), GeometryError::ZeroVector.into());
        let direction = unit(d.get_ref().0).ok_or_else(zero)?;
        Ok(Drawing::Line { point, direction, tube: sizes.tube })
    }
}
