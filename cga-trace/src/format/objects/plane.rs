//! `type = "plane"`: a `point` and `normal`, or three `points` on it.

use super::kind::{At, Geometry, Kind, one, point, points, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::V3;
use crate::invalid::Invalid;
use crate::shapes::PlaneShape;
use cga_core::Plane;
use cga_core::euclid::{E3, dot, unit};

const TAKES: &str = "a plane takes `point` and `normal`, or `points` (three)";

pub(crate) const KIND: Kind = Kind { name: "plane", fields: PlaneSpec::FIELDS, takes: TAKES, read: read::<PlaneSpec> };

spec!(PlaneSpec { point: V3 => Point, normal: V3 => Direction, points: Vec<V3> => Points });

impl Geometry for PlaneSpec {
    /// The point of the plane nearest the origin, `n (n · p)`, where the normal is given; it
    /// reaches everywhere.
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let p = point(&self.point).or_else(|| Some(self.points.as_ref()?.get_ref().first()?.0))?;
        let foot = |n: E3| n.map(|x| x * dot(n, p));
        Some((point(&self.normal).and_then(unit).map_or(p, foot), f64::INFINITY))
    }

    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let (p, n) = match (point(&self.point), point(&self.normal), &self.points) {
            (Some(p), Some(n), None) => (p, n),
            (None, None, Some(p)) => {
                let [a, b, c] = points("points", p)?;
                let (n, _) = Plane::through(a, b, c)?.normal_offset()?;
                (a, n)
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        let (foot, n) = at.place.plane(p, n)?;
        // The texture's origin is the point given, where the frame holds it.
        let anchor = at.place.point(p).unwrap_or(foot);
        Ok(one(PlaneShape { anchor, ..PlaneShape::new(foot, n)? }))
    }
}
