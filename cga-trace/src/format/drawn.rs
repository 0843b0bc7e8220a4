//! The object kinds that draw a CGA object (`point`, `point-pair`, `line`, `circle`,
//! `plane-patch`, `blade`): their fields read into a [`Drawing`], which the figure module
//! turns into shapes. A `blade` is given by its coefficients under blade names, in the null
//! basis (`e1 … e3`, `eo`, `ei`: `e1o`, `e12i`, `e123oi`, …) or the orthonormal one (`e4`,
//! `e5`: `e14`, `e1235`, …), and drawn as cga-core's classification says it is.

use super::numbers::{Nums, V3};
use super::{Kind, ObjectSpec, points};
use crate::figure::{DrawError, Drawing, Sizes};
use crate::invalid::Invalid;
use cga_core::euclid::{E3, norm, sub, unit};
use cga_core::{GeometryError, Multivector, Plane, Real, circumcircle, classify_storage};
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A blade's coefficients: by name (`{ e1 = 1.0, eo = 1.0 }`), or for a circle the ten
/// orthonormal grade-3 coefficients in the order of [`CIRCLE_ORDER`].
#[derive(Deserialize)]
#[serde(
    untagged,
    expecting = "a table of coefficients by blade name ({ e12 = 1.0, e3i = 2.0 }), or for a circle ten numbers"
)]
pub(crate) enum BladeSpec {
    Circle(Nums<10>),
    Named(BTreeMap<String, super::numbers::Num>),
}

/// The orthonormal grade-3 blades, in the order circles give them as a list.
pub(crate) const CIRCLE_ORDER: [&str; 10] =
    ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"];

/// Coefficients past this many names are refused before any is read (a blade has 32).
const MAX_NAMES: usize = 32;

/// The storage index of a null-basis blade name (`s` or `1` for the scalar).
fn storage_index(name: &str) -> Option<usize> {
    let name = if name == "1" { "s" } else { name };
    crate::figure::null_basis_names().iter().position(|n| *n == name)
}

/// Which basis a name is written in: null (`o`, `i`), orthonormal (`4`, `5`) or either
/// (only `e1`, `e2`, `e3`).
fn basis_of(name: &str) -> (bool, bool) {
    (name.contains(['o', 'i']), name.contains(['4', '5']))
}

impl BladeSpec {
    /// The null-basis coefficients (`to_storage` order), scaled by a power of two to a
    /// largest coefficient near 1 (a blade and its multiples are one object; so coefficients
    /// of any size square without overflow). Orthonormal names are converted; null-basis
    /// ones are kept as given (the orthonormal basis would lose the small `eo` coefficients
    /// beside `|c|²`-sized `ei` ones of an object far from the origin).
    pub(crate) fn storage(&self) -> Result<[f64; 32], Invalid> {
        let mut storage = [0.0; 32];
        let mut ortho = [0.0; 32];
        let (mut null_named, mut ortho_named) = (None, None);
        match self {
            BladeSpec::Circle(c) => {
                for (name, value) in CIRCLE_ORDER.iter().zip(c.0) {
                    let k = Multivector::<f64>::BLADES.iter().position(|x| x == name).expect("a blade name");
                    ortho[k] = value;
                }
                ortho_named = Some("e123");
            }
            BladeSpec::Named(named) => {
                if named.len() > MAX_NAMES {
                    return Err(Invalid::Limit {
                        what: "blade coefficients",
                        found: named.len() as u64,
                        limit: MAX_NAMES as u64,
                    });
                }
                for (name, value) in named {
                    let (null, orthonormal) = basis_of(name);
                    if null {
                        null_named = Some(name.as_str());
                    }
                    if orthonormal {
                        ortho_named = Some(name.as_str());
                    }
                    match (storage_index(name), Multivector::<f64>::BLADES.iter().position(|x| x == name)) {
                        (Some(k), _) if !orthonormal => storage[k] = value.0,
                        (_, Some(k)) => ortho[k] = value.0,
                        _ => return Err(Invalid::Name(name.escape_debug().to_string())),
                    }
                }
            }
        }
        if let (Some(a), Some(b)) = (null_named, ortho_named) {
            return Err(Invalid::Mixed(a.to_string(), b.to_string()));
        }
        if ortho_named.is_some() {
            storage = Multivector { coeffs: ortho }.to_storage();
        }
        let largest = storage.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if largest > 0.0 {
            let unit = Real::binade(largest);
            storage.iter_mut().for_each(|x| *x /= unit);
        }
        Ok(storage)
    }
}

impl From<DrawError> for Invalid {
    fn from(e: DrawError) -> Invalid {
        Invalid::Draw(e)
    }
}

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
        let kind = self.blade.as_ref().and_then(|b| b.get_ref().storage().ok()).and_then(|c| classify_storage(&c).ok());
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
                        let kind = classify_storage(&b.get_ref().storage().map_err(on)?).map_err(|e| on(e.into()))?;
                        return match Drawing::of(kind, &sizes, false)? {
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
                let kind = classify_storage(&b.get_ref().storage().map_err(on)?).map_err(|e| on(e.into()))?;
                Drawing::of(kind, &sizes, segment).map_err(|e| on(e.into()))?
            }
            _ => return Err(form()),
        })
    }
}

/// What a classified blade is, in a word or two.
fn describe(kind: cga_core::Kind<f64>) -> &'static str {
    use cga_core::Kind as K;
    match kind {
        K::Zero => "zero",
        K::Round { grade: 1 | 4, .. } => "a sphere",
        K::Round { grade: 2, .. } => "a point pair",
        K::Round { .. } => "a tangent",
        K::FlatPoint(_) => "a flat point",
        K::Line { .. } => "a line",
        K::Plane { .. } => "a plane",
        K::Direction { .. } => "a direction",
    }
}
