//! `type = "point"`: a ball of radius `size` at `point`.

use super::drawn::{Draws, read, sized};
use super::kind::{Kind, point, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;

const TAKES: &str = "a point takes `point` and optionally `size` (its ball's radius)";

pub(crate) const KIND: Kind = Kind { name: "point", fields: PointSpec::FIELDS, takes: TAKES, read: read::<PointSpec> };

spec!(PointSpec { point: V3 => Point, size: Num => Length });

impl Draws for PointSpec {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&self.size, &None, defaults)?;
        Ok(Drawing::Point { at: point(&self.point).ok_or(Invalid::Form(TAKES))?, size: sizes.size })
    }
}
