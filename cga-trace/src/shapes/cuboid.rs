//! A box: three slabs about its centre along orthonormal axes (the scene's `min`/`max`
//! corners turned by the object's motor). A ray is inside a slab between two parameters; it
//! meets the box where it has entered all three and left none (the slab test).

use super::{Crossing, Shape, Unit, crossing_at, facing, largest, rounding};
use crate::ray::{Ray, in_range};
use cga_core::GeometryError;
use cga_core::euclid::{E3, dot, sub, unit};

/// A box of `centre`, orthonormal `axes` and half extents `half` along them.
#[derive(Clone, Debug)]
pub struct BoxShape {
    /// The centre.
    pub centre: E3,
    /// The unit edge directions, orthonormal.
    pub axes: [E3; 3],
    /// Half the edge lengths along `axes`.
    pub half: [f64; 3],
}

impl BoxShape {
    /// The box with opposite corners `min` and `max` along the coordinate axes, then with its
    /// axes turned to `axes` about its centre moved to `centre` (the axes must be
    /// orthonormal: the images of e1, e2, e3 under a rotation). `ZeroRadius` for an edge that
    /// is not positive (`max ≤ min` on some axis).
    pub fn new(half: [f64; 3], centre: E3, axes: [E3; 3]) -> Result<Self, GeometryError> {
        if !half.iter().chain(&centre).all(|x| x.is_finite()) {
            return Err(GeometryError::NonFinite);
        }
        if half.iter().any(|&h| h <= 0.0) {
            return Err(GeometryError::ZeroRadius);
        }
        let axes = [0, 1, 2].map(|k| unit(axes[k]));
        let [Some(a), Some(b), Some(c)] = axes else { return Err(GeometryError::ZeroVector) };
        Ok(BoxShape { centre, axes: [a, b, c], half })
    }

    /// The box between the corners `min` and `max`, along the coordinate axes.
    pub fn between(min: E3, max: E3) -> Result<Self, GeometryError> {
        let half = [0, 1, 2].map(|k| 0.5 * (max[k] - min[k]));
        let centre = [0, 1, 2].map(|k| 0.5 * (max[k] + min[k]));
        BoxShape::new(half, centre, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    }

    /// Where the ray's line enters and leaves the box, and the axis of each: `None` where
    /// it misses (or runs along a face outside it).
    fn span(&self, ray: &Ray) -> Option<((f64, usize), (f64, usize))> {
        let rel = sub(self.centre, ray.origin);
        let (mut enter, mut leave) = ((f64::NEG_INFINITY, 0), (f64::INFINITY, 0));
        for k in 0..3 {
            let (along, speed) = (dot(rel, self.axes[k]), dot(ray.dir, self.axes[k]));
            if speed == 0.0 {
                if along.abs() > self.half[k] {
                    return None;
                }
                continue;
            }
            let (a, b) = ((along - self.half[k]) / speed, (along + self.half[k]) / speed);
            let (near, far) = if a < b { (a, b) } else { (b, a) };
            if near > enter.0 {
                enter = (near, k);
            }
            if far < leave.0 {
                leave = (far, k);
            }
        }
        (enter.0 <= leave.0).then_some((enter, leave))
    }

    /// The axis of the face a point `rel` (from the centre) lies on: the one along which it
    /// is farthest out, relative to the half extent.
    fn face(&self, rel: E3) -> usize {
        let out = |k: usize| dot(rel, self.axes[k]).abs() / self.half[k];
        (0..3).max_by(|&a, &b| out(a).total_cmp(&out(b))).unwrap_or(0)
    }
}

impl Shape for BoxShape {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let ((t_in, _), (t_out, _)) = self.span(ray)?;
        let t = [t_in, t_out].into_iter().find(|&t| in_range(t, t_min, t_max))?;
        Some(crossing_at(ray, ray.at(t)))
    }

    /// The axis of the face the crossing lies on: the one along which the point is farthest
    /// out, relative to the half extent.
    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let k = self.face(sub(crossing.point, self.centre));
        facing(self.axes[k], ray.dir)
    }

    /// Each face's own fractions, reading as drawn seen from outside with `v` down a page:
    /// up is the box's own `+z` on its four sides, `+y` on its top (`+z`) and `−y` on its
    /// bottom (as the top shows when the box is turned over about `x`); right is `up × n`.
    /// `u = ½ + (x·right)/(2 h_right)`, `v = ½ − (x·up)/(2 h_up)`, `x` from the centre and
    /// `h` the half extents: each in `[0, 1]` across the face.
    fn uv(&self, c: &Crossing) -> Option<([f64; 2], Unit)> {
        let rel = sub(c.point, self.centre);
        let k = self.face(rel);
        let out = dot(rel, self.axes[k]) > 0.0;
        let sign = |positive: bool| if positive { 1.0 } else { -1.0 };
        // (axis, sign) of up and of right = up × n, in the box's own right-handed axes.
        let ((up, su), (right, sr)) = match k {
            0 => ((2, 1.0), (1, sign(out))),
            1 => ((2, 1.0), (0, -sign(out))),
            _ => ((1, sign(out)), (0, 1.0)),
        };
        let along = |axis: usize, s: f64| s * dot(rel, self.axes[axis]) / (2.0 * self.half[axis]);
        Some(([0.5 + along(right, sr), 0.5 - along(up, su)], Unit::Fraction))
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some((self.centre, dot(self.half, self.half).sqrt()))
    }

    fn closed(&self) -> bool {
        true
    }

    /// Between the slabs' last entry and first exit.
    fn spans(&self, ray: &Ray) -> super::Spans {
        self.span(ray).filter(|(a, b)| a.0 < b.0).map(|((a, _), (b, _))| (a, b)).into_iter().collect()
    }

    /// The rounding of its faces' offsets from the camera: `64 ε (|c| + |h|)`.
    fn crossing_error(&self) -> f64 {
        rounding(largest(self.centre) + largest(self.half))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_core::euclid::{add, scale};

    /// The corner `c − Σ h_k a_k`.
    fn corner(b: &BoxShape) -> E3 {
        (0..3).fold(b.centre, |x, k| add(x, scale(b.axes[k], -b.half[k])))
    }

    #[test]
    fn a_ray_along_x_enters_and_leaves_at_the_faces() {
        let b = BoxShape::between([1.0, -1.0, -2.0], [3.0, 1.0, 2.0]).unwrap();
        assert_eq!(corner(&b), [1.0, -1.0, -2.0]);
        let ray = Ray::new([-5.0, 0.25, 0.5], [1.0, 0.0, 0.0]).unwrap();
        let hit = b.hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!((hit.t, hit.normal), (6.0, [-1.0, 0.0, 0.0]));
        let out = b.hit(&ray, 6.5, f64::INFINITY).unwrap();
        assert_eq!((out.t, out.normal), (8.0, [-1.0, 0.0, 0.0]));
        assert!(b.intersect(&Ray::new([-5.0, 1.5, 0.0], [1.0, 0.0, 0.0]).unwrap(), 0.0, f64::INFINITY).is_none());
        assert_eq!(BoxShape::between([0.0; 3], [1.0, 0.0, 1.0]).unwrap_err(), GeometryError::ZeroRadius);
    }
}
