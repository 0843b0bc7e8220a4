//! `type = "cylinder"`: its axis's ends `p1` and `p2`, `radius`, and `caps`: a cone of equal
//! radii.

use super::cone;
use super::kind::{At, Ends, Geometry, Kind, flag, number, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::Num;
use crate::invalid::Invalid;
use cga_core::euclid::E3;

const TAKES: &str =
    "a cylinder takes its axis's ends `p1` and `p2` (one point each), `radius`, and `caps` (default true)";

pub(crate) const KIND: Kind = Kind { name: "cylinder", fields: Cylinder::FIELDS, takes: TAKES, read: read::<Cylinder> };

spec!(Cylinder { p1: Ends => Point, p2: Ends => Point, radius: Num => Length, caps: bool => Other });

impl Geometry for Cylinder {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        cone::extent(&self.p1, &self.p2, number(&self.radius).unwrap_or(0.0))
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (Some(_), Some(_)) = (&self.p1, &self.p2) else { return Err(Invalid::Form(TAKES)) };
        let r = number(&self.radius).ok_or(Invalid::Form(TAKES))?;
        cone::build(TAKES, (&self.p1, r), (&self.p2, r), flag(&self.caps, true), at)
    }

    fn coincident(&self) -> &'static str {
        "p2"
    }
}
