//! `type = "disk"`: `centre`, `normal` and `radius`, or the three `points` of its rim.

use super::kind::{At, Geometry, Kind, number, one, point, points, read, spec, spread};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use crate::shapes::DiskShape;
use cga_core::circumcircle;
use cga_core::euclid::E3;

const TAKES: &str = "a disk takes `centre`, `normal` and `radius`, or `points` (three)";

pub(crate) const KIND: Kind = Kind { name: "disk", fields: Disk::FIELDS, takes: TAKES, read: read::<Disk> };

spec!(Disk { centre: V3 => Point, normal: V3 => Direction, radius: Num => Length, points: Vec<V3> => Points });

impl Geometry for Disk {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        match (point(&self.centre), &self.points) {
            (Some(c), _) => Some((c, number(&self.radius).unwrap_or(0.0))),
            (None, Some(p)) => Some((p.get_ref().first()?.0, spread(p.get_ref()))),
            (None, None) => None,
        }
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (c, n, r) = match (point(&self.centre), point(&self.normal), number(&self.radius), &self.points) {
            (Some(c), Some(n), Some(r), None) => (c, n, r),
            (None, None, None, Some(p)) => {
                let [a, b, c] = points("points", p)?;
                circumcircle(a, b, c)?
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        let place = &at.place;
        Ok(one(DiskShape::new(place.point(c)?, place.direction(n), place.length(r))?))
    }
}
