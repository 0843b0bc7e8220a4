//! An object's `clip`: the region it is cut to, in its own coordinates (moved with it, as
//! POV-Ray's `clipped_by`): any of `plane = { point, normal }` (the half-space behind the
//! normal is kept), `sphere = { centre, radius }` and `box = { min, max }` (their insides
//! kept), all of them where several are given; `capped = true` closes the cut with the
//! region's own surface (a closed object's solid intersected with the region), `false`
//! (default) leaves it open.

use crate::format::numbers::{Num, V3};
use crate::format::transform::Placement;
use crate::invalid::Invalid;
use crate::shapes::{BoxShape, PlaneShape, Shape, SphereShape};
use serde::Deserialize;
use std::sync::Arc;

/// Said of a capped clip on an object that bounds no solid.
pub(crate) const CAPPED_OPEN: &str = "a capped clip needs a closed object (a sphere, box, capped cylinder or cone, torus, closed mesh, evolved or spline surface with `caps = true`, or csg): `capped = false` cuts any";

/// An object's `clip` table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ClipSpec {
    plane: Option<PlaneCut>,
    sphere: Option<SphereCut>,
    #[serde(rename = "box")]
    cuboid: Option<BoxCut>,
    capped: Option<bool>,
}

/// `plane = { point, normal }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PlaneCut {
    point: V3,
    normal: V3,
}

/// `sphere = { centre, radius }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SphereCut {
    centre: V3,
    radius: Num,
}

/// `box = { min, max }`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BoxCut {
    min: V3,
    max: V3,
}

impl ClipSpec {
    /// Whether the cut is closed.
    pub(crate) fn capped(&self) -> bool {
        self.capped.unwrap_or(false)
    }

    /// The region's closed shapes, placed as the object is.
    pub(crate) fn region(&self, place: &Placement) -> Result<Vec<Arc<dyn Shape>>, Invalid> {
        let mut region: Vec<Arc<dyn Shape>> = Vec::new();
        if let Some(p) = &self.plane {
            region.push(Arc::new(PlaneShape::new(place.point(p.point.0)?, place.direction(p.normal.0))?));
        }
        if let Some(s) = &self.sphere {
            region.push(Arc::new(SphereShape::new(place.point(s.centre.0)?, place.length(s.radius.0))?));
        }
        if let Some(b) = &self.cuboid {
            let half = [0, 1, 2].map(|k| 0.5 * (b.max.0[k] - b.min.0[k]));
            let centre = [0, 1, 2].map(|k| 0.5 * (b.max.0[k] + b.min.0[k]));
            let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|a| place.direction(a));
            region.push(Arc::new(BoxShape::new(half.map(|h| place.length(h)), place.point(centre)?, axes)?));
        }
        if region.is_empty() {
            return Err(Invalid::Form(
                "a clip takes `plane = { point, normal }`, `sphere = { centre, radius }` or `box = { min, max }` (and `capped`)",
            ));
        }
        Ok(region)
    }
}
