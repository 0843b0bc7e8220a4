//! The object kinds that draw a CGA object (`point`, `point-pair`, `line`, `circle`,
//! `plane-patch`, `blade`): their fields read into a [`Drawing`], which [`super::marks`] turns
//! into shapes. A `blade` is given by its coefficients under blade names, in the null
//! basis (`e1 … e3`, `eo`, `ei`: `e1o`, `e12i`, `e123oi`, …) or the orthonormal one (`e4`,
//! `e5`: `e14`, `e1235`, …), and drawn as cga-core's classification says it is.

use super::blade::{BladeSpec, describe};
use super::numbers::V3;
use super::{Kind, ObjectSpec, points};
use crate::drawing::{Drawing, Sizes};
use crate::invalid::Invalid;
use cga_core::euclid::{E3, norm, sub, unit};
use cga_core::{GeometryError, Plane, circumcircle};
use toml::Spanned;

impl ObjectSpec {
    /// Whether the object draws a CGA object (the kinds of this module).
    pub(crate) fn draws(&self) -> bool {
        matches!(self.kind, Kind::Point | Kind::PointPair | Kind::Line | Kind::Circle | Kind::PlanePatch | Kind::Blade)
    }

    /// For the kinds that draw a CGA object: a point of it and its extent, in world
    /// coordinates before its motor (`None` inside for a direction, which has no place, or
    /// for fields that make no object: building it says why).
    pub(crate) fn drawn_extent(&self) -> Option<Option<(E3, f64)>> {
        if !self.draws() {
            return None;
        }
        let zero = Sizes::ZERO;
        Some(match self.drawing(&zero) {
            Ok(d) if self.kind != Kind::Blade || !matches!(d, Drawing::Arrow { .. }) => Some(d.extent()),
            // An arrow of a blade: a tangent has a place, a direction none.
            Ok(Drawing::Arrow { at, .. }) if self.tangent() => Some((at, 0.0)),
            _ => None,
        })
    }

    /// Whether a `blade` is a tangent (a round of zero radius), not a direction.
    fn tangent(&self) -> bool {
        let kind = self.blade.as_ref().and_then(|b| b.get_ref().kind().ok());
        matches!(kind, Some(cga_core::Kind::Round { .. }))
    }

    /// What the object draws, in world coordinates before its motor, its marks sized by the
    /// object's `size` and `tube` where given, else by `defaults`.
    pub(crate) fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let form = || Invalid::Form(self.kind.takes().1);
        let v = |x: &Option<Spanned<V3>>| x.as_ref().map(|x| x.get_ref().0);
        let length = |field: &'static str, x: &Option<Spanned<super::numbers::Num>>, default: f64| match x {
            // Numbers are finite where they are read.
            Some(l) if l.get_ref().0 <= 0.0 => {
                Err(Invalid::at(field, l.span(), Invalid::Value("a size must be positive")))
            }
            Some(l) => Ok(l.get_ref().0),
            None => Ok(default),
        };
        let size = length("size", &self.size, defaults.size)?;
        let sizes = Sizes {
            size,
            tube: length("tube", &self.tube, defaults.tube)?,
            patch: length("size", &self.size, defaults.patch)?,
            ..*defaults
        };
        let segment = self.segment.as_ref().is_some_and(|s| *s.get_ref());
        let (point, normal, centre) = (v(&self.point), v(&self.normal), v(&self.centre));
        let radius = self.radius.as_ref().map(|r| r.get_ref().0);
        let nonzero = |d: E3| unit(d).ok_or(Invalid::Geometry(GeometryError::ZeroVector));
        Ok(match self.kind {
            Kind::Point => Drawing::Point { at: point.ok_or_else(form)?, size },
            Kind::PointPair => {
                let p = self.points.as_ref().ok_or_else(form)?;
                let [a, b]: [E3; 2] = points("points", p)?;
                if norm(sub(a, b)) == 0.0 {
                    return Err(GeometryError::CoincidentPoints.into());
                }
                Drawing::PointPair { points: [a, b], size, segment: segment.then_some(sizes.tube) }
            }
            Kind::Line => {
                let (Some(point), Some(d)) = (point, self.direction.as_ref()) else { return Err(form()) };
                let direction =
                    unit(d.get_ref().0).ok_or(Invalid::at("direction", d.span(), GeometryError::ZeroVector.into()))?;
                Drawing::Line { point, direction, tube: sizes.tube }
            }
            Kind::Circle => {
                let (c, n, r) = match (centre, normal, radius, &self.points, &self.blade) {
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
                    _ => return Err(form()),
                };
                Drawing::Circle { centre: c, normal: n, radius: r, tube: sizes.tube, dashed: false }
            }
            Kind::PlanePatch => {
                let (p, n) = match (point, normal, &self.points) {
                    (Some(p), Some(n), None) => (p, nonzero(n)?),
                    (None, None, Some(p)) => {
                        let [a, b, c] = points("points", p)?;
                        let (n, _) = Plane::through(a, b, c)?.normal_offset()?;
                        ([0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0), n)
                    }
                    _ => return Err(form()),
                };
                Drawing::PlanePatch { centre: p, normal: n, size: sizes.patch }
            }
            Kind::Blade => {
                let b = self.blade.as_ref().ok_or_else(form)?;
                if matches!(b.get_ref(), BladeSpec::Circle(_)) {
                    return Err(Invalid::at("blade", b.span(), Invalid::Value("give a blade's coefficients by name")));
                }
                let on = |e| Invalid::at("blade", b.span(), e);
                let kind = b.get_ref().kind().map_err(on)?;
                Drawing::of(kind, &sizes, segment).map_err(|e| on(e.into()))?
            }
            _ => return Err(form()),
        })
    }
}
