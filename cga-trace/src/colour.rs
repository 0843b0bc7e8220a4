//! False colour for scalar AOVs (curvatures, the postulate's angle): a perceptually uniform
//! colour map (viridis, from the `colorous` crate), a colour bar along the bottom of the
//! image, and the scale — quantity, unit, the values at the bar's ends — for a file beside it.

use crate::film::{Film, srgb_to_linear};
use crate::integrator::Aov;

/// What the colours of a false-colour image mean.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Scale {
    /// The quantity shown.
    pub quantity: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// The colour map (low to high).
    pub map: &'static str,
    /// The value at the low end (left of the bar); lower values are clipped to it.
    pub low: f64,
    /// The value at the high end (right of the bar).
    pub high: f64,
    /// Pixels with a value (on a swept surface).
    pub pixels: usize,
}

/// The linear RGB of viridis at `t ∈ [0, 1]` (the map is given in sRGB).
fn viridis(t: f64) -> [f64; 3] {
    let c = colorous::VIRIDIS.eval_continuous(t.clamp(0.0, 1.0));
    [c.r, c.g, c.b].map(srgb_to_linear)
}

/// The film of a scalar AOV in false colour, and its scale; `None` for other AOVs. The range
/// is the 2nd to 98th percentile of the values (symmetric about 0 when they change sign, so
/// that zero is the map's middle), `[0°, 45°]` for the postulate's angle; pixels without a
/// value are dark grey; the bottom rows are the colour bar.
pub fn false_colour(film: &Film, aov: Aov) -> Option<(Film, Scale)> {
    let (quantity, unit) = match aov {
        Aov::Gaussian => ("Gaussian curvature K", "1/length²"),
        Aov::Mean => ("mean curvature H (positive bulging towards the viewer)", "1/length"),
        Aov::K1 => ("larger principal curvature k1", "1/length"),
        Aov::K2 => ("smaller principal curvature k2", "1/length"),
        Aov::Postulate => ("angle between L_C and the nearest principal direction", "degrees"),
        _ => return None,
    };
    let value = |p: &[f64; 3]| (p[1] > 0.0).then(|| p[0] / p[1]);
    let mut values: Vec<f64> = film.pixels.iter().filter_map(value).filter(|v| v.is_finite()).collect();
    values.sort_by(f64::total_cmp);
    let (mut low, mut high) = match (aov, values.len()) {
        (Aov::Postulate, _) => (0.0, 45.0),
        (_, 0) => (0.0, 1.0),
        (_, n) => (values[n / 50], values[n - 1 - n / 50]),
    };
    if aov != Aov::Postulate && low < 0.0 && high > 0.0 {
        let m = (-low).max(high);
        (low, high) = (-m, m);
    }
    if high <= low {
        high = low + low.abs().max(1e-300);
    }
    let mut out = film.clone();
    for (p, o) in film.pixels.iter().zip(&mut out.pixels) {
        *o = match value(p) {
            Some(v) if v.is_finite() => viridis((v - low) / (high - low)),
            _ => [0.02; 3],
        };
    }
    // The colour bar: the bottom rows (the film's row 0 is the bottom).
    let (w, bar) = (film.width as usize, (film.height as usize / 20).max(2).min(film.height as usize));
    for j in 0..bar {
        for i in 0..w {
            out.pixels[j * w + i] = viridis((i as f64 + 0.5) / w as f64);
        }
    }
    Some((out, Scale { quantity, unit, map: "viridis", low, high, pixels: values.len() }))
}
