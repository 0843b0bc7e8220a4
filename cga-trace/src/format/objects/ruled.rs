//! `type = "ruled"`: the surface ruled between two point pairs `p1` and `p2`, or between two
//! lines `l1` and `l2` within a `bound`ing sphere.

use super::kind::{At, Ends, Geometry, Kind, read, spec, spread};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use cga_core::euclid::E3;
use serde::Deserialize;

const TAKES: &str = "a ruled surface takes point pairs `p1` and `p2` (two points each), or lines `l1` and `l2` ({ point, direction }) and a `bound` ({ centre, radius })";

pub(crate) const KIND: Kind = Kind { name: "ruled", fields: Ruled::FIELDS, takes: TAKES, read: read::<Ruled> };

spec!(Ruled {
    p1: Ends => Points,
    p2: Ends => Points,
    l1: LineSpec => Line,
    l2: LineSpec => Line,
    bound: BoundSpec => Bound,
});

/// A line of a ruled surface: a point on it and its direction.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct LineSpec {
    point: V3,
    direction: V3,
}

/// A sphere bounding the rulings of a ruled surface of lines.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct BoundSpec {
    centre: V3,
    radius: Num,
}

impl Geometry for Ruled {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        match (&self.p1, &self.bound) {
            (Some(p), _) => Some((p.get_ref().points().first()?.0, spread(p.get_ref().points()))),
            (None, Some(b)) => Some((b.get_ref().centre.0, b.get_ref().radius.0)),
            (None, None) => None,
        }
    }

    /// The surface in a local frame at the mean of its defining points (or the bound's
    /// centre), moved into the scene's frame.
    #[cfg(feature = "evolved")]
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        use super::kind::{ends, one};
        use crate::surface::RuledSurface;
        use cga_core::euclid::sub;
        let place = &at.place;
        let surface = match (&self.p1, &self.p2, &self.l1, &self.l2, &self.bound) {
            (Some(p1), Some(p2), None, None, None) => {
                let (p1, p2): ([E3; 2], [E3; 2]) = (ends("p1", p1)?, ends("p2", p2)?);
                let (p1, p2) = ([place.point(p1[0])?, place.point(p1[1])?], [place.point(p2[0])?, place.point(p2[1])?]);
                let origin = [0, 1, 2].map(|k| (p1[0][k] + p1[1][k] + p2[0][k] + p2[1][k]) / 4.0);
                let local = |x: E3| sub(x, origin);
                RuledSurface::point_pairs(origin, p1.map(local), p2.map(local))?
            }
            (None, None, Some(l1), Some(l2), Some(bound)) => {
                let (l1, l2, b) = (l1.get_ref(), l2.get_ref(), bound.get_ref());
                let origin = place.point(b.centre.0)?;
                let line = |l: &LineSpec| -> Result<(E3, E3), Invalid> {
                    Ok((sub(place.point(l.point.0)?, origin), place.direction(l.direction.0)))
                };
                let radius = place.length(b.radius.0);
                if radius <= 0.0 {
                    let why = Invalid::Value("the bound's radius must be positive");
                    return Err(Invalid::at("bound", bound.span(), why));
                }
                RuledSurface::lines(origin, line(l1)?, line(l2)?, ([0.0; 3], radius))?
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        Ok(one(surface))
    }

    #[cfg(not(feature = "evolved"))]
    fn build(&self, _: &At) -> Result<Parts, Invalid> {
        Err(Invalid::NoEvolved)
    }
}
