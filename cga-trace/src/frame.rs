//! The renderer's world frame: camera-relative and of the scene's scale.
//!
//! Conformal coefficients grow like `|x|²`, so a scene placed a thousand units from the
//! origin loses six digits in every blade. A scene is therefore read into a frame whose
//! origin is the camera and whose unit is a power of two near the scene's size:
//! `x ↦ (x − o) / s`. Every shape, light and ray lives in this frame, so a scene renders the
//! same wherever it sits, for every shape added later too, since a shape never sees world
//! coordinates. Dividing by a power of two is exact, and the subtraction loses no more than
//! the input's own rounding (`ε |x|`, as plain vectors). Only the distances that carry units
//! out of the frame — light attenuation, curvatures — are scaled back to world units.
//!
//! The unit does not decide any tolerance: rays ignore crossings and start secondary rays
//! by amounts relative to each hit's own size ([`crate::shapes::Shape::crossing_error`]).
//! It only keeps the numbers in range, so it follows what the picture shows — the median
//! size of the objects that cover at least a pixel (lights and sub-pixel objects do not set
//! it) — moved only as far as needed to keep every object within [`RANGE`] binary orders of
//! magnitude of it, where the products of up to four coordinates the shapes form stay far
//! inside f64's range.

use cga_core::euclid::{E3, norm, sub};

/// How many binary orders of magnitude an object's size (its distance from the camera, or
/// its extent if larger) may lie from the frame's unit: 2²⁰⁰ ≈ 1.6e60, so that products of
/// four coordinates (a triangle's edge tests, the square of a sphere's meet) stay below
/// 1e242, far from f64's 1.8e308, and above 1e-242.
pub const RANGE: i32 = 200;

/// Sizes that no one frame holds: the smallest and largest, in world units.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error(
    "the objects' sizes (distance from the camera, or extent if larger) run from {smallest:.1e} to {largest:.1e}: more than the 2^400 (about 2.6e120) f64 renders in one picture"
)]
pub struct Span {
    /// The smallest size.
    pub smallest: f64,
    /// The largest size.
    pub largest: f64,
}

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
    /// The frame at `origin` for objects of the given `sizes`, `(point, extent)` in world
    /// coordinates (an extent of ∞ for unbounded ones: their size is their distance), seen
    /// with pixels of `pixel` radians: the unit is the power of two nearest the median size
    /// `max(|point − origin|, extent)` of the objects whose extent covers at least half a
    /// pixel (of all, if none does; 1 without objects), moved as little as keeps every size
    /// within `2^±RANGE` of the unit. `Err` with the smallest and largest sizes when no unit
    /// can (they differ by more than `2^(2 RANGE)`, about 1e120).
    pub fn around(origin: E3, objects: impl IntoIterator<Item = (E3, f64)>, pixel: f64) -> Result<Self, Span> {
        let mut sizes: Vec<(f64, bool)> = Vec::new();
        for (x, extent) in objects {
            let d = norm(sub(x, origin));
            let size = if extent.is_infinite() { d } else { d.max(extent) };
            if size.is_finite() && size > 0.0 {
                sizes.push((size, extent >= 0.5 * pixel * d));
            }
        }
        let log = |x: f64| x.log2();
        let (lo, hi) = sizes.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &(s, _)| (a.min(s), b.max(s)));
        if sizes.is_empty() {
            return Ok(Frame { origin, scale: 1.0 });
        }
        if log(hi) - log(lo) > 2.0 * f64::from(RANGE) {
            return Err(Span { smallest: lo, largest: hi });
        }
        let mut shown: Vec<f64> = sizes.iter().filter(|s| s.1).map(|s| s.0).collect();
        if shown.is_empty() {
            shown = sizes.iter().map(|s| s.0).collect();
        }
        shown.sort_by(f64::total_cmp);
        let median = log(shown[shown.len() / 2]);
        // Rounded first, then kept within the range (rounding must not undo the clamp).
        let range = f64::from(RANGE);
        let unit = median.round().clamp((log(hi) - range).ceil(), (log(lo) + range).floor()).clamp(-1000.0, 1000.0);
        Ok(Frame { origin, scale: 2f64.powi(unit as i32) })
    }

    /// Whether a frame length (a size or a distance from the camera) lies within the range
    /// the frame holds, `2^RANGE` of its unit.
    pub fn holds(length: f64) -> bool {
        length.is_finite() && length <= 2f64.powi(RANGE)
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

    /// A length of the frame in world units (in any scalar: one ray's or a packet's lanes).
    #[inline]
    pub fn world_length<T: cga_core::Real>(&self, l: T) -> T {
        l * T::from_f64(self.scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_unit_is_a_power_of_two_near_the_median_size() {
        let object = |x: f64, r: f64| ([x, 0.0, 0.0], r);
        let f = Frame::around([1.0, 0.0, 0.0], [object(4.0, 1.0), ([1.0, 12.0, 0.0], 2.0), object(1e9, 1e8)], 1e-3)
            .unwrap();
        assert_eq!(f.scale, 16.0); // median size 12
        assert_eq!(f.point([9.0, 0.0, 0.0]), [0.5, 0.0, 0.0]);
        assert_eq!(f.world_point(f.point([5.0, -3.0, 2.0])), [5.0, -3.0, 2.0]);
        assert_eq!(Frame::around([0.0; 3], [], 1e-3).unwrap().scale, 1.0);
        // An object around the camera is as large as its extent.
        assert_eq!(Frame::around([0.0; 3], [object(0.0, 1e10)], 1e-3).unwrap().scale, 2f64.powi(33));
    }

    #[test]
    fn sub_pixel_objects_do_not_set_the_unit_unless_the_range_needs_them() {
        let near = ([10.0, 0.0, 0.0], 1.0);
        let far = |d: f64| ([d, 0.0, 0.0], 1.0);
        let f = Frame::around([0.0; 3], [near, far(1e50), far(1e50), far(1e50)], 1e-3).unwrap();
        assert_eq!(f.scale, 8.0);
        // At 1e90 the far ones would lie beyond 2^200 of a unit of 8: the unit moves up just
        // enough, and every size is held.
        let f = Frame::around([0.0; 3], [near, far(1e90), far(1e90)], 1e-3).unwrap();
        assert!(Frame::holds(1e90 / f.scale) && Frame::holds(f.scale / 10.0), "{:e}", f.scale);
        // Rounding never takes the unit past the range: an object at 2^200.3 beside unit ones.
        let f = Frame::around([0.0; 3], [near, ([2f64.powf(200.3), 0.0, 0.0], 1.0)], 1e-3).unwrap();
        assert!(Frame::holds(2f64.powf(200.3) / f.scale), "{:e}", f.scale);
        // Planes (unbounded) count by their distance; nothing spans more than f64 holds.
        let plane = ([0.0, 0.0, -1e-3], f64::INFINITY);
        assert_eq!(Frame::around([0.0; 3], [plane], 1e-3).unwrap().scale, 2f64.powi(-10));
        let e = Frame::around([0.0; 3], [([1e-300, 0.0, 0.0], 1e-300), far(1e100)], 1e-3).unwrap_err();
        assert_eq!((e.smallest, e.largest), (1e-300, 1e100));
    }
}
