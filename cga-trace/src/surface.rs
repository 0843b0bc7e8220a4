//! Evolved circle surfaces: where a ray meets the family `C_α`, α ∈ [0, 1].
//!
//! A ray's line `L` touches `C_α` exactly when `f(α) = (C_α ∨ L)²` vanishes (the meet is
//! then the touching point). This first, robust method:
//! 1. rejects rays that miss the surface's bounding sphere;
//! 2. samples `f` at `samples + 1` uniform α (the ends included, so hits at α = 0 and 1
//!    count);
//! 3. refines every sign change by bisection, and every local minimum of `|f|` without a
//!    sign change (a ray that only touches, or crosses twice within one step) by
//!    golden-section search;
//! 4. verifies every candidate geometrically: the point must lie on the circle and on the
//!    line. Where the meet degenerates — the line lies in the circle's plane, so
//!    `C ∨ L = 0` for every point — the points come from the line–circle intersection
//!    in that plane instead of being missed.
//!
//! Everything is computed in a frame centred between the two circles: conformal
//! coordinates carry `½x²`, and far from the origin precision falls as (|c|/r)³
//! (docs/STABILITY.md). The fast method is issue 5's.

use crate::ray::Ray;
use crate::shapes::Hit;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use cga_core::{Circle, GeometryError, InterpolationError, Line, Pair, Sandwich, Translator, down};

/// Why two circles make no surface this renderer can draw.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// An end circle is not a real circle (a line, imaginary, degenerate).
    #[error("circle {which} is not a real circle: {reason}")]
    NotACircle {
        /// 1 or 2.
        which: u8,
        /// What it is instead.
        reason: GeometryError,
    },
    /// The two circles cannot be normalised and aligned.
    #[error("the circles cannot be normalised")]
    Degenerate,
    /// Somewhere between them the interpolation has no circle.
    #[error("the circles do not interpolate: {0}")]
    NoInterpolation(#[from] InterpolationError),
    /// Somewhere between them the family passes through a line (infinite radius).
    #[error("the surface is unbounded: at α = {alpha} the interpolated circle is a line")]
    Unbounded {
        /// Where.
        alpha: f64,
    },
}

/// A surface swept by the circles interpolated between two circles.
#[derive(Clone, Debug)]
pub struct EvolvedSurface {
    /// The circles in the local frame.
    pair: Pair<Circle>,
    /// The local frame's origin, in world coordinates.
    origin: E3,
    /// Bounding-sphere radius about `origin`.
    radius: f64,
    /// Samples of `f(α)` per ray.
    samples: usize,
}

/// The bounding sphere is sampled this finely, then padded by `PAD`.
const BOUND_SAMPLES: usize = 512;
const PAD: f64 = 1.02;
/// `|f|` below this fraction of its sampled scale counts as zero: a tangential touch.
const TOUCH: f64 = 1e-12;

impl EvolvedSurface {
    /// The surface between `c1` (α = 0) and `c2` (α = 1), given in world coordinates and
    /// moved to a frame centred between them, sampled `samples` times per ray.
    pub fn new(c1: Circle, c2: Circle, samples: usize) -> Result<Self, SurfaceError> {
        let centre =
            |c: &Circle, which| c.centre_normal_radius().map_err(|reason| SurfaceError::NotACircle { which, reason });
        let ((p1, _, _), (p2, _, _)) = (centre(&c1, 1)?, centre(&c2, 2)?);
        let origin = scale(add(p1, p2), 0.5);
        let to_local = Translator::from_vector(origin.map(|x| -x));
        Self::in_frame(origin, to_local.sandwich(c1), to_local.sandwich(c2), samples)
    }

    /// The surface between circles given in a frame whose origin is `origin` (world
    /// coordinates). Building them there, rather than far out in world coordinates, keeps
    /// their precision.
    pub fn in_frame(origin: E3, c1: Circle, c2: Circle, samples: usize) -> Result<Self, SurfaceError> {
        let pair = Pair::new(c1, c2).ok_or(SurfaceError::Degenerate)?;
        let mut radius = 0.0f64;
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            let (c, _, r) = pair.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?;
            radius = radius.max(norm(c) + r);
        }
        Ok(EvolvedSurface { pair, origin, radius: radius * PAD, samples: samples.max(2) })
    }

    /// The bounding sphere `(centre, radius)` in world coordinates.
    pub fn bounds(&self) -> (E3, f64) {
        (self.origin, self.radius)
    }

    /// The two end circles in the local frame, and the frame's origin.
    pub fn pair(&self) -> (&Pair<Circle>, E3) {
        (&self.pair, self.origin)
    }

    /// `f(α) = (C_α ∨ L)²` for a line in the local frame.
    pub fn f(&self, line: &Line, alpha: f64) -> Option<f64> {
        let c = self.pair.at(alpha).ok()?;
        Some(line.meet_circle(&c).norm_squared())
    }

    /// The nearest hit with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let o = sub(ray.origin, self.origin);
        // 1. Bounding sphere.
        let tc = -dot(o, ray.dir);
        let miss2 = dot(add(o, scale(ray.dir, tc)), add(o, scale(ray.dir, tc)));
        if miss2 > self.radius * self.radius || tc + self.radius < t_min || tc - self.radius > t_max {
            return None;
        }
        let line = Line::from_point_direction(o, ray.dir).ok()?;
        let local = Ray { origin: o, dir: ray.dir, line };
        // 2.–3. Candidate α.
        let mut best: Option<Hit> = None;
        for alpha in self.candidates(&line) {
            // 4. Verified points on C_α and the line, nearest first.
            let Ok(circle) = self.pair.at(alpha) else { continue };
            for x in hit_points(&circle, &local) {
                let t = local.t_of(x);
                if t <= t_min || t >= t_max || best.is_some_and(|b| b.t <= t) {
                    continue;
                }
                let Ok(n) = self.pair.normal(alpha, x) else { continue };
                let normal = if dot(n, ray.dir) > 0.0 { n.map(|v| -v) } else { n };
                best = Some(Hit { t, point: add(x, self.origin), normal, alpha: Some(alpha) });
            }
        }
        best
    }

    /// Every α where `f` changes sign or `|f|` has a local minimum, refined.
    fn candidates(&self, line: &Line) -> Vec<f64> {
        let n = self.samples;
        let alphas: Vec<f64> = (0..=n).map(|k| k as f64 / n as f64).collect();
        let values: Vec<Option<f64>> = alphas.iter().map(|&a| self.f(line, a)).collect();
        let scale = values.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut out = Vec::new();
        for k in 0..=n {
            let Some(fk) = values[k] else { continue };
            if fk == 0.0 {
                out.push(alphas[k]);
                continue;
            }
            if k < n
                && let Some(fn_) = values[k + 1]
                && fk.signum() != fn_.signum()
                && fn_ != 0.0
            {
                out.push(self.bisect(line, alphas[k], alphas[k + 1], fk));
            }
            // A local minimum of |f| (the ends included) that did not change sign.
            let left = if k > 0 { values[k - 1] } else { None };
            let right = if k < n { values[k + 1] } else { None };
            let no_lower = |v: Option<f64>| v.is_none_or(|v| v.abs() >= fk.abs() && v.signum() == fk.signum());
            if no_lower(left) && no_lower(right) {
                let lo = alphas[k.saturating_sub(1)];
                let hi = alphas[(k + 1).min(n)];
                let alpha = self.minimise_abs(line, lo, hi);
                // A touch is real only where |f| reaches rounding level: a near miss has a
                // small but clearly nonzero minimum.
                if self.f(line, alpha).is_some_and(|f| f.abs() <= TOUCH * scale) {
                    out.push(alpha);
                }
            }
        }
        out
    }

    /// The root of `f` in `[lo, hi]`, where `f(lo) = f_lo` and `f(hi)` differ in sign.
    fn bisect(&self, line: &Line, mut lo: f64, mut hi: f64, mut f_lo: f64) -> f64 {
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            match self.f(line, mid) {
                Some(0.0) => return mid,
                Some(fm) if fm.signum() == f_lo.signum() => {
                    lo = mid;
                    f_lo = fm;
                }
                _ => hi = mid,
            }
        }
        0.5 * (lo + hi)
    }

    /// The α minimising `|f|` on `[lo, hi]` (golden-section search).
    fn minimise_abs(&self, line: &Line, mut lo: f64, mut hi: f64) -> f64 {
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let h = |a: f64| self.f(line, a).map_or(f64::INFINITY, f64::abs);
        let (mut a, mut b) = (hi - g * (hi - lo), lo + g * (hi - lo));
        let (mut ha, mut hb) = (h(a), h(b));
        for _ in 0..80 {
            if ha < hb {
                hi = b;
                (b, hb) = (a, ha);
                a = hi - g * (hi - lo);
                ha = h(a);
            } else {
                lo = a;
                (a, ha) = (b, hb);
                b = lo + g * (hi - lo);
                hb = h(b);
            }
        }
        let ends = [(lo, h(lo)), (hi, h(hi)), (0.5 * (lo + hi), h(0.5 * (lo + hi)))];
        ends.into_iter().min_by(|x, y| x.1.total_cmp(&y.1)).map_or(lo, |e| e.0)
    }
}

/// Points where the ray's line meets `circle`, each checked to lie on both. The meet
/// `C ∨ L` is the touching point; when it vanishes (the line in the circle's plane), the
/// in-plane intersection is solved instead.
fn hit_points(circle: &Circle, ray: &Ray) -> Vec<E3> {
    let Ok((c, n, r)) = circle.centre_normal_radius() else { return Vec::new() };
    let scale_ = r + norm(sub(ray.origin, c));
    let tol = 1e-6 * scale_;
    let on_both = |x: &E3| {
        let d = sub(*x, c);
        let along = dot(sub(*x, ray.origin), ray.dir);
        let to_line = norm(sub(sub(*x, ray.origin), scale(ray.dir, along)));
        (norm(d) - r).abs() < tol && dot(d, n).abs() < tol && to_line < tol
    };
    let mut points: Vec<E3> = down(ray.line.meet_circle(circle)).into_iter().filter(on_both).collect();
    if points.is_empty() {
        // The line in the circle's plane: |o + t d − c|² = r².
        let oc = sub(ray.origin, c);
        if dot(ray.dir, n).abs() < 1e-9 && dot(oc, n).abs() < tol {
            let (b, cc) = (dot(oc, ray.dir), dot(oc, oc) - r * r);
            let disc = b * b - cc;
            if disc >= 0.0 {
                let s = disc.sqrt();
                points.extend([-b - s, -b + s].map(|t| ray.at(t)));
            }
        }
    }
    points
}
