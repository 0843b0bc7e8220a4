//! `type = "plane-patch"`: a disk of radius `size` of the plane through `point` with
//! `normal`, or through three `points` (about their centroid).

use super::drawn::{Draws, nonzero, read, sized};
use super::kind::{Kind, point, points, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use cga_core::Plane;

const TAKES: &str = "a plane patch takes `point` and `normal`, or `points` (three), and optionally `size` (its radius)";

pub(crate) const KIND: Kind =
    Kind { name: "plane-patch", fields: PlanePatch::FIELDS, takes: TAKES, read: read::<PlanePatch> };

spec!(PlanePatch { point: V3 => Point, normal: V3 => Direction, points: Vec<V3> => Points, size: Num => Length });

impl Draws for PlanePatch {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&self.size, &None, defaults)?;
        let (centre, normal) = match (point(&self.point), point(&self.normal), &self.points) {
            (Some(p), Some(n), None) => (p, nonzero(n)?),
            (None, None, Some(p)) => {
                let [a, b, c] = points("points", p)?;
                let (n, _) = Plane::through(a, b, c)?.normal_offset()?;
                ([0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0), n)
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        Ok(Drawing::PlanePatch { centre, normal, size: sizes.patch })
    }
}
