//! `type = "sphere"`: `centre` and `radius`, or the four `points` it passes through.

use super::kind::{At, Geometry, Kind, one, point, points, read, spec, spread};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use crate::shapes::SphereShape;
use cga_core::circumsphere;
use cga_core::euclid::E3;

const TAKES: &str = "a sphere takes `centre` and `radius`, or `points` (four)";

pub(crate) const KIND: Kind = Kind { name: "sphere", fields: Sphere::FIELDS, takes: TAKES, read: read::<Sphere> };

spec!(Sphere { centre: V3 => Point, radius: Num => Length, points: Vec<V3> => Points });

impl Geometry for Sphere {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        match (&self.centre, &self.points) {
            (Some(c), _) => Some((c.get_ref().0, self.radius.as_ref().map_or(0.0, |r| r.get_ref().0))),
            (None, Some(p)) => Some((p.get_ref().first()?.0, spread(p.get_ref()))),
            (None, None) => None,
        }
    }

    /// `S = up(c) − ½ r² n∞`, its axes turned with it (a texture's).
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let radius = self.radius.as_ref().map(|r| r.get_ref().0);
        let (c, r) = match (point(&self.centre), radius, &self.points) {
            (Some(c), Some(r), None) => (c, r),
            (None, None, Some(p)) => {
                let [a, b, c, d] = points("points", p)?;
                let (c, r, _) = circumsphere(a, b, c, d)?;
                (c, r)
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        let place = &at.place;
        let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|a| place.direction(a));
        Ok(one(SphereShape::new(place.point(c)?, place.length(r))?.with_axes(axes)))
    }
}
