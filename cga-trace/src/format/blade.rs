//! A `blade`'s coefficients: by blade name in the null basis (`e1 … e3`, `eo`, `ei`: `e1o`,
//! `e12i`, `e123oi`, …) or the orthonormal one (`e4`, `e5`: `e14`, `e1235`, …), or a circle's
//! ten orthonormal grade-3 coefficients, read into a dense multivector; and what cga-core's
//! classification calls it.

use super::numbers::Nums;
use crate::drawing::DrawError;
use crate::invalid::Invalid;
use cga_core::{Multivector, Real, classify_storage};
use serde::Deserialize;
use std::collections::BTreeMap;

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

/// The storage index of a null-basis blade name (`s` for the scalar).
fn storage_index(name: &str) -> Option<usize> {
    crate::drawing::null_basis_names().iter().position(|n| *n == name)
}

/// The dense (orthonormal-basis) index of a blade name.
fn ortho_index(name: &str) -> Option<usize> {
    Multivector::<f64>::BLADES.iter().position(|n| *n == name)
}

/// `coeffs` divided by the power of two nearest their largest magnitude: a blade and its
/// multiples are one object, and so coefficients of any size f64 holds square without
/// overflow or underflow.
pub(crate) fn scaled<const N: usize>(mut coeffs: [f64; N]) -> [f64; N] {
    let largest = coeffs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest > 0.0 {
        let unit = Real::binade(largest);
        coeffs.iter_mut().for_each(|x| *x /= unit);
    }
    coeffs
}

/// The dense multivector of a circle given as ten orthonormal grade-3 coefficients in
/// [`CIRCLE_ORDER`], [`scaled`].
pub(crate) fn circle_blade(c: [f64; 10]) -> Multivector<f64> {
    let mut coeffs = [0.0; 32];
    for (name, value) in CIRCLE_ORDER.iter().zip(scaled(c)) {
        coeffs[ortho_index(name).expect("a grade-3 blade")] = value;
    }
    Multivector { coeffs }
}

impl BladeSpec {
    /// What the blade is. Names in the null basis (any `eo`, `ei`) are read as given by
    /// `classify_storage` (the orthonormal basis would lose the small `eo` coefficients
    /// beside `|c|²`-sized `ei` ones of an object far from the origin); names in the
    /// orthonormal one (any `e4`, `e5`, or a circle's list) by the dense `classify`; names in
    /// neither (`s`, `e1`, `e12`, …) are the same blade in both. Mixing the two bases is an
    /// error.
    pub(crate) fn kind(&self) -> Result<cga_core::Kind<f64>, Invalid> {
        let named = match self {
            BladeSpec::Circle(c) => return Ok(circle_blade(c.0).classify()?),
            BladeSpec::Named(named) => named,
        };
        let null = named.keys().find(|n| n.contains(['o', 'i']));
        let ortho = named.keys().find(|n| n.contains(['4', '5']));
        if let (Some(a), Some(b)) = (null, ortho) {
            return Err(Invalid::Mixed(a.escape_debug().to_string(), b.escape_debug().to_string()));
        }
        let index = if ortho.is_some() { ortho_index } else { storage_index };
        let mut coeffs = [0.0; 32];
        for (name, value) in named {
            let k = index(name).ok_or_else(|| Invalid::Name(name.escape_debug().to_string()))?;
            coeffs[k] = value.0;
        }
        Ok(match ortho {
            Some(_) => Multivector { coeffs: scaled(coeffs) }.classify()?,
            None => classify_storage(&scaled(coeffs))?,
        })
    }
}

impl From<DrawError> for Invalid {
    fn from(e: DrawError) -> Invalid {
        Invalid::Draw(e)
    }
}

/// What a classified blade is, in a word or two.
pub(crate) fn describe(kind: cga_core::Kind<f64>) -> &'static str {
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
