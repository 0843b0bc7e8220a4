//! `type = "triangle"`: its three `corners`.

use super::kind::{At, Geometry, Kind, one, points, read, spec, spread};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::V3;
use crate::invalid::Invalid;
use crate::shapes::TriangleShape;
use cga_core::euclid::E3;

const TAKES: &str = "a triangle takes `corners` (three points)";

pub(crate) const KIND: Kind = Kind { name: "triangle", fields: Triangle::FIELDS, takes: TAKES, read: read::<Triangle> };

spec!(Triangle { corners: Vec<V3> => Points });

impl Geometry for Triangle {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let corners = self.corners.as_ref()?.get_ref();
        Some((corners.first()?.0, spread(corners)))
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let corners = self.corners.as_ref().ok_or(Invalid::Form(TAKES))?;
        let corners: [E3; 3] = points("corners", corners)?;
        // Checked as given: corners that coincide only after the move are a scale problem
        // (`Range`), not the user's.
        TriangleShape::new(corners)?;
        let [a, b, c] = corners.map(|x| at.place.point(x));
        Ok(one(TriangleShape::new([a?, b?, c?])?))
    }
}
