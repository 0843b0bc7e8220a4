//! The renderer's world frame: camera-relative and of unit scale.
//!
//! Conformal coefficients grow like `|x|²`, so a scene placed a thousand units from the
//! origin loses six digits in every blade, and tolerances written for unit-sized scenes
//! misjudge tiny or huge ones. A scene is therefore read into a frame whose origin is the
//! camera and whose unit is a power of two close to the scene's size: `x ↦ (x − o) / s`.
//! Every shape, light and ray lives in this frame, so what holds for a scene near the origin
//! at unit size holds for any placement and any scale, and for every shape added later,
//! since a shape never sees world coordinates. Dividing by a power of two is exact, and
//! the subtraction loses no more than the input's own rounding (`ε |x|`, as plain vectors).
//! Only the distances that carry units out of the frame — light attenuation — are scaled
//! back to world units.

use cga_core::euclid::{E3, norm, sub};

/// `x ↦ (x − origin) / scale`: world coordinates to the renderer's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The frame's origin in world coordinates (the camera's position).
    pub origin: E3,
    /// World length of the frame's unit: a power of two.
    pub scale: f64,
}

impl Default for Frame {
    /// The identity: world coordinates as they are.
    fn default() -> Self {
        Frame { origin: [0.0; 3], scale: 1.0 }
    }
}

impl Frame {
    /// The frame at `origin` whose unit is the power of two nearest the median distance from
    /// `origin` to `anchors` (the scene's object and light positions), or 1 when there are
    /// none: a size the scene scales with, chosen so that the change of unit is exact.
    pub fn around(origin: E3, anchors: impl IntoIterator<Item = E3>) -> Self {
        let mut distances: Vec<f64> =
            anchors.into_iter().map(|x| norm(sub(x, origin))).filter(|d| d.is_finite() && *d > 0.0).collect();
        distances.sort_by(f64::total_cmp);
        let size = distances.get(distances.len() / 2).copied().unwrap_or(1.0);
        // 2^round(log2 size), clamped so that neither the scale nor its inverse overflows.
        let scale = 2f64.powi(size.log2().round().clamp(-1000.0, 1000.0) as i32);
        Frame { origin, scale }
    }

    /// A world point in the frame.
    #[inline]
    pub fn point(&self, x: E3) -> E3 {
        sub(x, self.origin).map(|v| v / self.scale)
    }

    /// A world length in the frame.
    #[inline]
    pub fn length(&self, l: f64) -> f64 {
        l / self.scale
    }

    /// A point of the frame in world coordinates.
    #[inline]
    pub fn world_point(&self, x: E3) -> E3 {
        [0, 1, 2].map(|k| x[k] * self.scale + self.origin[k])
    }

    /// A length of the frame in world units.
    #[inline]
    pub fn world_length(&self, l: f64) -> f64 {
        l * self.scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_is_a_power_of_two_near_the_median_distance() {
        let f = Frame::around([1.0, 0.0, 0.0], [[4.0, 0.0, 0.0], [1.0, 12.0, 0.0], [1.0, 0.0, 1e9]]);
        assert_eq!(f.scale, 16.0); // median distance 12
        assert_eq!(f.point([9.0, 0.0, 0.0]), [0.5, 0.0, 0.0]);
        assert_eq!(f.world_point(f.point([5.0, -3.0, 2.0])), [5.0, -3.0, 2.0]);
        assert_eq!(Frame::around([0.0; 3], []).scale, 1.0);
    }
}
