//! `type = "circle"`: a circle by `centre`, `normal` and `radius`, through three `points`,
//! or as a `blade`, drawn as a torus of radius `tube`.

use super::drawn::{Draws, nonzero, read, sized};
use super::kind::{Kind, number, point, points, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::blade::{BladeSpec, describe};
use crate::format::numbers::{Num, V3};
use crate::invalid::Invalid;
use cga_core::{GeometryError, circumcircle};

const TAKES: &str =
    "a circle takes `centre`, `normal` and `radius`, or `points` (three), or `blade`; optionally `tube`";

pub(crate) const KIND: Kind =
    Kind { name: "circle", fields: CircleDrawn::FIELDS, takes: TAKES, read: read::<CircleDrawn> };

spec!(CircleDrawn {
    centre: V3 => Point,
    normal: V3 => Direction,
    radius: Num => Length,
    points: Vec<V3> => Points,
    blade: BladeSpec => Blade,
    tube: Num => Length,
});

impl Draws for CircleDrawn {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&None, &self.tube, defaults)?;
        let given = (point(&self.centre), point(&self.normal), number(&self.radius), &self.points, &self.blade);
        let (centre, normal, radius) = match given {
            (Some(c), Some(n), Some(r), None, None) if r > 0.0 => (c, nonzero(n)?, r),
            (Some(_), Some(_), Some(_), None, None) => return Err(GeometryError::ZeroRadius.into()),
            (None, None, None, Some(p), None) => {
                let [a, b, c] = points("points", p)?;
                circumcircle(a, b, c)?
            }
            (None, None, None, None, Some(b)) => {
                let on = |e| Invalid::at("blade", b.span(), e);
                let kind = b.get_ref().kind().map_err(on)?;
                return match Drawing::of(kind, &sizes, false).map_err(|e| on(e.into()))? {
                    d @ Drawing::Circle { .. } => Ok(d),
                    _ => Err(Invalid::at("blade", b.span(), Invalid::NotA("circle", describe(kind)))),
                };
            }
            _ => return Err(Invalid::Form(TAKES)),
        };
        Ok(Drawing::Circle { centre, normal, radius, tube: sizes.tube, dashed: false })
    }
}
