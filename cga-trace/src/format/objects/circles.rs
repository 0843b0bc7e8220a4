//! The circles that evolved and spline surfaces sweep: a circle table read and placed, and
//! the disks that cap a surface's ends.

use crate::format::numbers::{Num, Nums, V3};
use crate::format::transform::Step;
use cga_core::euclid::{E3, norm, sub};
use serde::Deserialize;
use toml::Spanned;

#[cfg(feature = "evolved")]
pub(crate) use placed::{capped, circle};

/// A circle: Euclidean, through three points, or the original renderer's grade-3
/// coefficients in the orthonormal basis (order e123, e124, e125, e134, e135, e145, e234,
/// e235, e245, e345); optionally moved.
// Still read without the `evolved` feature, so that such objects get a clear error.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct CircleSpec {
    centre: Option<V3>,
    normal: Option<V3>,
    radius: Option<Num>,
    points: Option<Spanned<Vec<V3>>>,
    blade: Option<Nums<10>>,
    motor: Option<Spanned<Nums<8>>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
}

impl CircleSpec {
    /// Its centre and radius where given as such (a blade's or three points' are known only
    /// once built).
    pub(crate) fn centre_radius(&self) -> Option<(E3, f64)> {
        self.centre.map(|x| (x.0, self.radius.map_or(0.0, |r| r.0)))
    }
}

/// The sphere about the first circle's centre holding them all, where each is given by
/// centre and radius.
pub(crate) fn extent<'a>(mut circles: impl Iterator<Item = &'a CircleSpec>) -> Option<(E3, f64)> {
    let (x, r) = circles.next()?.centre_radius()?;
    let far = circles.filter_map(CircleSpec::centre_radius).map(|(y, r)| r + norm(sub(x, y)));
    Some((x, far.fold(r, f64::max)))
}

/// Circles placed in the frame (only evolved surfaces place them).
#[cfg(feature = "evolved")]
mod placed {
    use crate::format::blade;
    use crate::format::objects::circles::CircleSpec;
    use crate::format::objects::kind::{At, points};
    use crate::format::transform::{Placement, world_motor};
    use crate::invalid::Invalid;
    use crate::shapes::{DiskShape, Shape};
    use cga_core::euclid::E3;
    use cga_core::{Circle, GeometryError, circumcircle};
    use std::sync::Arc;
    use toml::Spanned;

    /// The centre, normal and radius of a circle, moved by its own transform and then by the
    /// object's `place` (its motor and the frame). A blade is read in world coordinates (where
    /// the file gives it): its coefficients carry the circle no better than `ε (|c|/r)²` there,
    /// which is what the file holds.
    pub(crate) fn circle(spec: &CircleSpec, place: &Placement) -> Result<(E3, E3, f64), Invalid> {
        let (c, n, r) = match (spec.blade, spec.centre, spec.normal, spec.radius, &spec.points) {
            (Some(b), None, None, None, None) => {
                let c = Circle::from_dense(&blade::circle_blade(b.0))
                    .try_normalise()
                    .ok_or(Invalid::Value("the blade is zero or null"))?;
                c.centre_normal_radius()?
            }
            (None, Some(c), Some(n), Some(r), None) => {
                // A zero radius or normal (numbers are finite) is named here, before the frame or
                // a motor acts on it.
                if r.0 <= 0.0 {
                    return Err(GeometryError::ZeroRadius.into());
                }
                cga_core::euclid::unit(n.0).ok_or(GeometryError::ZeroVector)?;
                (c.0, n.0, r.0)
            }
            (None, None, None, None, Some(p)) => {
                let [a, b, c] = points("points", p)?;
                circumcircle(a, b, c)?
            }
            _ => return Err(Invalid::Form("give `blade`, or `centre`, `normal` and `radius`, or `points` (three)")),
        };
        // Its own transform, then the object's placement.
        let own = world_motor(spec.motor.as_ref(), spec.transform.as_ref())?;
        let (c, n) = match own {
            Some(m) => (m.move_point(c), m.move_direction(n)),
            None => (c, n),
        };
        Ok((place.point(c)?, place.direction(n), place.length(r)))
    }

    /// A swept surface and, with `caps`, the disks of its end circles (errors at `caps`).
    pub(crate) fn capped(
        surface: Arc<dyn Shape>,
        ends: [&Spanned<CircleSpec>; 2],
        caps: bool,
        at: &At,
    ) -> Result<Vec<Arc<dyn Shape>>, Invalid> {
        let mut shapes = vec![surface];
        if caps {
            for end in ends {
                let (c, n, r) = circle(end.get_ref(), &at.place).map_err(|e| Invalid::at("caps", end.span(), e))?;
                shapes.push(Arc::new(DiskShape::new(c, n, r)?));
            }
        }
        Ok(shapes)
    }
}
