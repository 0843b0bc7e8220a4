//! What an image shows: the shaded colour or, per first hit, a normal, α, curvature or
//! coverage (the values; `trace.rs` finds them along a ray).

use crate::settings::Settings;
use cga_core::euclid::{E3, dot};

/// What an image shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum Aov {
    /// The shaded image.
    #[default]
    Shaded,
    /// False-colour normals of the first hit, `(n + 1) / 2`.
    Normal,
    /// The α of evolved-surface hits, blue (α = 0) to red (α = 1); black elsewhere.
    Alpha,
    /// Gaussian curvature `K` of swept surfaces (1/length², world units), false colour.
    Gaussian,
    /// Mean curvature `H`, positive where the surface bulges towards the viewer (1/length),
    /// false colour.
    Mean,
    /// The larger principal curvature `k₁` (normal towards the viewer), false colour.
    K1,
    /// The smaller principal curvature `k₂`, false colour.
    K2,
    /// The angle (degrees) between `L_C` and the nearest principal direction: the paper's
    /// postulate holds where it is 0.
    Postulate,
    /// The fraction of a pixel's samples whose camera ray meets something, in grey (white
    /// where all do): what a transparent background's alpha channel holds.
    Coverage,
}

impl Aov {
    /// Whether a picture of this AOV under `settings` carries its coverage: the shaded one over
    /// a transparent background (other AOVs are opaque).
    pub fn covered(self, settings: &Settings) -> bool {
        self == Aov::Shaded && settings.transparent
    }

    /// Whether the AOV is a scalar shown in false colour ([`crate::colour`]).
    pub fn is_scalar(self) -> bool {
        matches!(self, Aov::Gaussian | Aov::Mean | Aov::K1 | Aov::K2 | Aov::Postulate)
    }

    /// The scalar this AOV shows at a hit of curvature `k` seen along `dir`, in world units
    /// (`scale`: the frame's unit in world lengths).
    pub(super) fn value(self, k: &cga_core::Curvature, dir: E3, scale: f64) -> f64 {
        // Curvatures positive where the surface bulges towards the viewer (a sphere seen from
        // outside), whichever way the surface's own normal `ν` points: with `ν` towards the
        // viewer a sphere has `H = −1/R` (`x_αα · ν < 0`), so the value is `−H` then.
        let sign = if dot(k.normal, dir) > 0.0 { 1.0 } else { -1.0 };
        let (a, b) = (sign * k.k[0] / scale, sign * k.k[1] / scale);
        match self {
            Aov::Gaussian => k.gaussian / (scale * scale),
            Aov::Mean => sign * k.mean / scale,
            Aov::K1 => a.max(b),
            Aov::K2 => a.min(b),
            _ => k.circle_angle().to_degrees(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curvatures_are_positive_where_the_surface_bulges_towards_the_viewer() {
        // A sphere of radius 2 seen from outside along −x at (2, 0, 0): the curvature module's
        // convention gives H = −1/R with the outward normal, +1/R with the inward one.
        for (normal, mean) in [([1.0, 0.0, 0.0], -0.5), ([-1.0, 0.0, 0.0], 0.5)] {
            let k = cga_core::Curvature {
                normal,
                k: [mean; 2],
                directions: [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                gaussian: 0.25,
                mean,
                circle_tangent: [0.0, 1.0, 0.0],
                condition: 0.0,
            };
            for aov in [Aov::Mean, Aov::K1, Aov::K2] {
                assert_eq!(aov.value(&k, [-1.0, 0.0, 0.0], 1.0), 0.5, "{aov:?}");
            }
            assert_eq!(Aov::Gaussian.value(&k, [-1.0, 0.0, 0.0], 2.0), 0.0625, "world units");
        }
    }
}
