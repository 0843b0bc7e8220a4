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
use crate::shapes::Crossing;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use cga_core::{Circle, Dual, GeometryError, Interpolable, InterpolationError, Line, Pair, Sandwich, Translator, down};

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

/// How rays are intersected with the surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "lowercase", tag = "method", deny_unknown_fields)]
pub enum Method {
    /// Baseline (the paper's): `samples` uniform samples of `f` over [0, 1] per ray, sign
    /// changes bisected, local minima of `|f|` searched.
    Sampling {
        /// Samples per ray.
        samples: usize,
    },
    /// Bounding spheres over `leaves` α-intervals (a binary tree, built once per surface)
    /// reject rays and isolate the intervals a ray can hit; each is sampled `per_leaf`
    /// times and roots are refined by safeguarded Newton with the exact `f'`.
    Hierarchy {
        /// α-intervals at the bottom of the tree (a power of two).
        leaves: usize,
        /// Samples per interval a ray reaches.
        per_leaf: usize,
    },
}

impl Default for Method {
    fn default() -> Self {
        Method::Hierarchy { leaves: 64, per_leaf: 4 }
    }
}

/// A bounding sphere of the circles `C_α`, `α ∈ [lo, hi]`; for a leaf also a tube: every
/// such circle lies within `delta` of the middle circle `(mid_centre, mid_normal, mid_radius)`.
#[derive(Clone, Copy, Debug)]
struct Node {
    centre: E3,
    radius: f64,
    lo: f64,
    hi: f64,
    tube: Option<Tube>,
}

/// Points within `delta` of a circle.
#[derive(Clone, Copy, Debug)]
struct Tube {
    centre: E3,
    normal: E3,
    radius: f64,
    delta: f64,
}

impl Tube {
    /// Whether the ray can come within `delta` of the circle for `t` in `(t_min, t_max)`.
    /// Such a point lies in the slab `|n·(x − c)| ≤ δ`, so within `δ/|d·n|` of the plane
    /// crossing `p` along the ray, and its in-plane distance from `c` is within δ of `r`:
    /// `| |p − c| − r | ≤ δ + δ/|d·n|`. Conservative; rays nearly parallel to the plane pass.
    fn may_meet(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let dn = dot(ray.dir, self.normal);
        if dn.abs() < 1e-3 {
            return true;
        }
        let t0 = -dot(sub(ray.origin, self.centre), self.normal) / dn;
        let half = self.delta / dn.abs();
        let p = ray.at(t0);
        (norm(sub(p, self.centre)) - self.radius).abs() <= self.delta + half && t0 + half > t_min && t0 - half < t_max
    }
}

/// A surface swept by the circles interpolated between two circles.
#[derive(Clone, Debug)]
pub struct EvolvedSurface {
    /// The circles in the local frame.
    pair: Pair<Circle>,
    /// The same over dual numbers, for exact `f'`.
    lifted: Pair<Circle<Dual>>,
    /// The local frame's origin, in world coordinates.
    origin: E3,
    /// Bounding-sphere radius about `origin`.
    radius: f64,
    /// How rays are intersected.
    method: Method,
    /// For [`Method::Hierarchy`]: an implicit complete binary tree, root at 0, children of
    /// `k` at `2k + 1`, `2k + 2`, leaves last.
    tree: Vec<Node>,
}

/// The bounding sphere is sampled this finely, then padded by `PAD`.
const BOUND_SAMPLES: usize = 512;
const PAD: f64 = 1.02;
/// `|f|` below this fraction of its sampled scale counts as zero: a tangential touch.
const TOUCH: f64 = 1e-12;

impl EvolvedSurface {
    /// The surface between `c1` (α = 0) and `c2` (α = 1), given in world coordinates and
    /// moved to a frame centred between them.
    pub fn new(c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let centre =
            |c: &Circle, which| c.centre_normal_radius().map_err(|reason| SurfaceError::NotACircle { which, reason });
        let ((p1, _, _), (p2, _, _)) = (centre(&c1, 1)?, centre(&c2, 2)?);
        let origin = scale(add(p1, p2), 0.5);
        let to_local = Translator::from_vector(origin.map(|x| -x));
        Self::in_frame(origin, to_local.sandwich(c1), to_local.sandwich(c2), method)
    }

    /// The surface between circles given in a frame whose origin is `origin` (world
    /// coordinates). Building them there, rather than far out in world coordinates, keeps
    /// their precision.
    pub fn in_frame(origin: E3, c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let pair = Pair::new(c1, c2).ok_or(SurfaceError::Degenerate)?;
        let lifted = Pair { c1: pair.c1.lift(), c2: pair.c2.lift() };
        let mut radius = 0.0f64;
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            let (c, _, r) = pair.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?;
            radius = radius.max(norm(c) + r);
        }
        let tree = match method {
            Method::Hierarchy { leaves, .. } => build_tree(&pair, leaves.next_power_of_two().max(1))?,
            Method::Sampling { .. } => Vec::new(),
        };
        Ok(EvolvedSurface { pair, lifted, origin, radius: radius * PAD, method, tree })
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

    /// The nearest crossing with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        // 1. Bounding sphere.
        if !crosses(ray, self.origin, self.radius, t_min, t_max) {
            return None;
        }
        let o = sub(ray.origin, self.origin);
        let line = Line::from_point_direction(o, ray.dir).ok()?;
        let local = Ray { origin: o, dir: ray.dir, line };
        // 2.–3. Candidate α.
        let candidates = match self.method {
            Method::Sampling { samples } => self.candidates(&line, 0.0, 1.0, samples.max(2)),
            Method::Hierarchy { per_leaf, .. } => self
                .intervals(&local, t_min, t_max)
                .into_iter()
                .flat_map(|(lo, hi, leaves)| self.candidates_with_slope(&line, lo, hi, per_leaf.max(2) * leaves))
                .collect(),
        };
        // 4. Verified points on C_α and the line; the nearest.
        let mut best: Option<Crossing> = None;
        for alpha in candidates {
            let Ok(circle) = self.pair.at(alpha) else { continue };
            for x in hit_points(&circle, &local) {
                let t = local.t_of(x);
                if t > t_min && t < t_max && best.is_none_or(|b| t < b.t) {
                    best = Some(Crossing { t, point: add(x, self.origin), alpha: Some(alpha) });
                }
            }
        }
        best
    }

    /// The unit normal at a crossing (eq. 6–11, sign not yet turned to the ray). Where the
    /// circles do not move (`Ẋ = 0`, so `N = 0`) the surface has no normal of its own; the
    /// circle's outward radial direction is used there.
    pub fn normal(&self, crossing: &Crossing) -> E3 {
        let x = sub(crossing.point, self.origin);
        let alpha = crossing.alpha.unwrap_or(0.0);
        self.pair
            .normal(alpha, x)
            .ok()
            .or_else(|| {
                let (c, _, _) = self.pair.at(alpha).ok()?.centre_normal_radius().ok()?;
                cga_core::euclid::unit(sub(x, c))
            })
            .unwrap_or([0.0, 0.0, 1.0])
    }

    /// Every α in `[lo, hi]` where `f` changes sign or `|f|` has a local minimum, refined,
    /// from `n + 1` samples.
    fn candidates(&self, line: &Line, lo: f64, hi: f64, n: usize) -> Vec<f64> {
        let alphas: Vec<f64> = (0..=n).map(|k| lo + (hi - lo) * k as f64 / n as f64).collect();
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

    /// Every root of `f` in `[lo, hi]` from `n + 1` samples of `(f, f')`: sign changes of `f`
    /// are refined by Newton; where `f` keeps its sign but `f'` turns towards zero between
    /// two samples, the extremum is found by bisection on `f'`, and if `f` crosses zero
    /// there both roots are bracketed (a pair of roots closer than the sample spacing), or
    /// if it only reaches zero, the touch is kept.
    fn candidates_with_slope(&self, line: &Line, lo: f64, hi: f64, n: usize) -> Vec<f64> {
        let lifted: Line<Dual> = line.lift();
        let alphas: Vec<f64> = (0..=n).map(|k| lo + (hi - lo) * k as f64 / n as f64).collect();
        let values: Vec<Option<(f64, f64)>> = alphas.iter().map(|&a| self.f_and_slope(&lifted, a)).collect();
        let scale = values.iter().flatten().fold(0.0f64, |m, v| m.max(v.0.abs()));
        let mut out = Vec::new();
        for k in 0..=n {
            let Some((fk, dk)) = values[k] else { continue };
            if fk == 0.0 {
                out.push(alphas[k]);
                continue;
            }
            let Some((fn_, dn)) = values.get(k + 1).copied().flatten() else { continue };
            if fn_ != 0.0 && fk.signum() != fn_.signum() {
                out.push(self.newton(&lifted, alphas[k], alphas[k + 1], fk));
                continue;
            }
            // f keeps its sign; does it turn back towards zero in between?
            let towards_zero = (fk > 0.0 && dk < 0.0 && dn > 0.0) || (fk < 0.0 && dk > 0.0 && dn < 0.0);
            if !towards_zero {
                continue;
            }
            let (a, b) = (alphas[k], alphas[k + 1]);
            let e = self.extremum(&lifted, a, b, dk);
            let Some((fe, _)) = self.f_and_slope(&lifted, e) else { continue };
            if fe != 0.0 && fe.signum() != fk.signum() {
                out.push(self.newton(&lifted, a, e, fk));
                out.push(self.newton(&lifted, e, b, fe));
            } else if fe.abs() <= TOUCH * scale {
                out.push(e);
            }
        }
        out
    }

    /// Where `f'` changes sign in `[lo, hi]` (`f'(lo) = d_lo`), by bisection.
    fn extremum(&self, line: &Line<Dual>, mut lo: f64, mut hi: f64, d_lo: f64) -> f64 {
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            match self.f_and_slope(line, mid) {
                Some((_, d)) if d.signum() == d_lo.signum() => lo = mid,
                _ => hi = mid,
            }
        }
        0.5 * (lo + hi)
    }

    /// `(f, f')` at α, exact: the interpolation and meet run on dual numbers.
    fn f_and_slope(&self, line: &Line<Dual>, alpha: f64) -> Option<(f64, f64)> {
        let c = self.lifted.at(Dual::variable(alpha)).ok()?;
        let f = line.meet_circle(&c).norm_squared();
        Some((f.re, f.du))
    }

    /// The root of `f` in `[lo, hi]` (`f(lo) = f_lo`, `f(hi)` of the other sign): Newton
    /// steps with the exact slope, replaced by bisection whenever one would leave the bracket
    /// or shrink it too little.
    fn newton(&self, lifted: &Line<Dual>, mut lo: f64, mut hi: f64, f_lo: f64) -> f64 {
        let sign_lo = f_lo.signum();
        let mut x = 0.5 * (lo + hi);
        for _ in 0..64 {
            let Some((f, slope)) = self.f_and_slope(lifted, x) else { return x };
            if f == 0.0 {
                return x;
            }
            if f.signum() == sign_lo {
                lo = x
            } else {
                hi = x
            }
            let step = x - f / slope;
            let next = if step > lo && step < hi { step } else { 0.5 * (lo + hi) };
            if (next - x).abs() <= 4.0 * f64::EPSILON * next.abs().max(1e-300) || hi - lo <= 2.0 * f64::EPSILON {
                return next;
            }
            x = next;
        }
        x
    }

    /// The α-intervals, from the leaves of the tree, whose bounding spheres the ray crosses
    /// within `[t_min, t_max]`; touching intervals merged, each with its number of leaves.
    fn intervals(&self, ray: &Ray, t_min: f64, t_max: f64) -> Vec<(f64, f64, usize)> {
        let mut out: Vec<(f64, f64, usize)> = Vec::new();
        let mut stack = vec![0usize];
        let first_leaf = self.tree.len() / 2;
        while let Some(k) = stack.pop() {
            let node = &self.tree[k];
            if !crosses(ray, node.centre, node.radius, t_min, t_max)
                || node.tube.is_some_and(|tube| !tube.may_meet(ray, t_min, t_max))
            {
                continue;
            }
            if k >= first_leaf {
                match out.last_mut() {
                    Some(last) if last.1 == node.lo => {
                        last.1 = node.hi;
                        last.2 += 1;
                    }
                    _ => out.push((node.lo, node.hi, 1)),
                }
            } else {
                // Right child first, so leaves pop in increasing α.
                stack.push(2 * k + 2);
                stack.push(2 * k + 1);
            }
        }
        out
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

/// Whether the ray passes through the sphere within `(t_min, t_max)`.
fn crosses(ray: &Ray, centre: E3, radius: f64, t_min: f64, t_max: f64) -> bool {
    let oc = sub(ray.origin, centre);
    let tc = -dot(oc, ray.dir);
    let miss = add(oc, scale(ray.dir, tc));
    dot(miss, miss) <= radius * radius && tc + radius > t_min && tc - radius < t_max
}

/// Leaf samples per α-interval when bounding it.
const LEAF_SAMPLES: usize = 8;

/// The tree of bounding spheres: each leaf bounds the circles sampled over its interval,
/// padded by half the largest motion between samples (centre and radius) twice over; each
/// inner node bounds its children.
fn build_tree(pair: &Pair<Circle>, leaves: usize) -> Result<Vec<Node>, SurfaceError> {
    let mut tree = vec![Node { centre: [0.0; 3], radius: 0.0, lo: 0.0, hi: 0.0, tube: None }; 2 * leaves - 1];
    for leaf in 0..leaves {
        let (lo, hi) = (leaf as f64 / leaves as f64, (leaf + 1) as f64 / leaves as f64);
        let mut circles = Vec::with_capacity(LEAF_SAMPLES + 1);
        for s in 0..=LEAF_SAMPLES {
            let alpha = lo + (hi - lo) * s as f64 / LEAF_SAMPLES as f64;
            circles.push(pair.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?);
        }
        let n = circles.len() as f64;
        let centre = circles.iter().fold([0.0; 3], |m, (c, _, _)| add(m, scale(*c, 1.0 / n)));
        // How far a circle can move between two samples, and from the middle circle.
        let apart = |a: &(E3, E3, f64), b: &(E3, E3, f64)| {
            let tilt = norm(sub(a.1, b.1)).min(norm(add(a.1, b.1)));
            norm(sub(a.0, b.0)) + (a.2 - b.2).abs() + a.2.max(b.2) * tilt
        };
        let step = circles.windows(2).map(|w| apart(&w[0], &w[1])).fold(0.0, f64::max);
        let radius = circles.iter().map(|(c, _, r)| norm(sub(*c, centre)) + r).fold(0.0, f64::max) + step;
        let mid = circles[LEAF_SAMPLES / 2];
        let delta = circles.iter().map(|c| apart(c, &mid)).fold(0.0, f64::max) + step;
        let tube = Tube { centre: mid.0, normal: mid.1, radius: mid.2, delta: 2.0 * delta };
        tree[leaves - 1 + leaf] = Node { centre, radius: radius * PAD, lo, hi, tube: Some(tube) };
    }
    for k in (0..leaves - 1).rev() {
        let (a, b) = (tree[2 * k + 1], tree[2 * k + 2]);
        let d = norm(sub(b.centre, a.centre));
        let (centre, radius) = if d + b.radius <= a.radius {
            (a.centre, a.radius)
        } else if d + a.radius <= b.radius {
            (b.centre, b.radius)
        } else {
            let radius = 0.5 * (d + a.radius + b.radius);
            (add(a.centre, scale(sub(b.centre, a.centre), (radius - a.radius) / d)), radius)
        };
        tree[k] = Node { centre, radius, lo: a.lo, hi: b.hi, tube: None };
    }
    Ok(tree)
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
