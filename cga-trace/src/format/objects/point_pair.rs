//! `type = "point-pair"`: balls at its two `points`, and with `segment = true` the segment
//! between them as a tube.

use super::drawn::{Draws, read, sized};
use super::kind::{Kind, flag, points, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use cga_core::GeometryError;
use cga_core::euclid::{E3, norm, sub};

const TAKES: &str =
    "a point pair takes `points` (two), optionally `size`, and `segment = true` (with its `tube`) to draw the segment";

pub(crate) const KIND: Kind =
    Kind { name: "point-pair", fields: PointPair::FIELDS, takes: TAKES, read: read::<PointPair> };

spec!(PointPair { points: Vec<V3> => Points, size: Num => Length, segment: bool => Other, tube: Num => Length });

impl Draws for PointPair {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&self.size, &self.tube, defaults)?;
        let p = self.points.as_ref().ok_or(Invalid::Form(TAKES))?;
        let [a, b]: [E3; 2] = points("points", p)?;
        if norm(sub(a, b)) == 0.0 {
            return Err(GeometryError::CoincidentPoints.into());
        }
        let segment = flag(&self.segment, false).then_some(sizes.tube);
        Ok(Drawing::PointPair { points: [a, b], size: sizes.size, segment })
    }
}
