//! What rays that leave the scene see: a gradient sky or an equirectangular image (an HDR
//! or EXR light probe, or any picture) around the world, in place of the background colour.
//! Reflections and refractions see it as camera rays do; it lights nothing directly.

use crate::picture::Picture;
use cga_core::euclid::E3;
use std::f64::consts::{PI, TAU};
use std::sync::Arc;

/// The world's surroundings, by direction (world axes, `+z` up).
#[derive(Clone, Debug, PartialEq)]
pub enum Environment {
    /// `horizon` along the horizon, blending linearly in the sine of the elevation to
    /// `zenith` straight up and `nadir` straight down.
    Gradient {
        /// Straight up.
        zenith: [f64; 3],
        /// At the horizon.
        horizon: [f64; 3],
        /// Straight down.
        nadir: [f64; 3],
    },
    /// An equirectangular image: longitude `φ = atan2(y, x) − turn` across
    /// (`u = ½ + φ/2π`), colatitude `θ = acos z` down (`v = θ/π`), times `strength`.
    Map {
        /// The image.
        picture: Arc<Picture>,
        /// Its turn about `+z` (radians).
        turn: f64,
        /// A factor on its values.
        strength: f64,
    },
}

impl Environment {
    /// What a ray leaving along the unit direction `d` sees.
    pub fn seen(&self, d: E3) -> [f64; 3] {
        match self {
            Environment::Gradient { zenith, horizon, nadir } => {
                let s = d[2].clamp(-1.0, 1.0);
                let towards = if s >= 0.0 { zenith } else { nadir };
                let w = s.abs();
                [0, 1, 2].map(|k| horizon[k] * (1.0 - w) + towards[k] * w)
            }
            Environment::Map { picture, turn, strength } => {
                let phi = d[1].atan2(d[0]) - turn;
                let theta = d[2].clamp(-1.0, 1.0).acos();
                picture.at(0.5 + phi / TAU, theta / PI).map(|c| c * strength)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_gradient_runs_from_nadir_through_horizon_to_zenith() {
        let sky = Environment::Gradient { zenith: [0.0, 0.0, 1.0], horizon: [1.0; 3], nadir: [0.0; 3] };
        assert_eq!(sky.seen([1.0, 0.0, 0.0]), [1.0; 3]);
        assert_eq!(sky.seen([0.0, 0.0, 1.0]), [0.0, 0.0, 1.0]);
        assert_eq!(sky.seen([0.0, 0.0, -1.0]), [0.0; 3]);
        let seen = sky.seen([0.0, 0.6, 0.8]);
        assert!((0..3).all(|k| (seen[k] - [0.2, 0.2, 1.0][k]).abs() < 1e-15), "{seen:?}");
    }

    #[test]
    fn a_map_is_read_at_longitude_and_colatitude() {
        // Four columns (longitudes −180°, −90°, 0°, 90° at their centres' left edges), two rows.
        let pixels = (0..8).map(|k| [k as f32, 0.0, 0.0]).collect();
        let picture = Arc::new(Picture { width: 4, height: 2, pixels });
        let map = Environment::Map { picture, turn: 0.0, strength: 2.0 };
        // Along +x: u = ½ (between columns 1 and 2), v = ½ (between the rows): the mean of
        // 1, 2, 5, 6 (3.5), doubled.
        assert_eq!(map.seen([1.0, 0.0, 0.0])[0], 7.0);
    }
}
