//! A binary tree of bounding spheres over α-intervals of an evolved surface, built once at
//! scene load: a ray visits only the intervals whose spheres (and, at the leaves, whose
//! tubes around the middle circle) it passes through.

use super::SurfaceError;
use super::family::Circles;
use crate::ray::{Ray, crosses};
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use smallvec::SmallVec;

/// α-intervals a ray reaches, `(lo, hi, leaves)`, touching ones merged.
pub type Intervals = SmallVec<[(f64, f64, usize); 8]>;

/// Samples per leaf interval when bounding it.
const LEAF_SAMPLES: usize = 8;
/// Relative padding of every bounding sphere.
pub const PAD: f64 = 1.02;

/// A bounding sphere of the circles `C_α`, `α ∈ [lo, hi]`; for a leaf also a tube.
#[derive(Clone, Copy, Debug)]
struct Node {
    centre: E3,
    radius: f64,
    lo: f64,
    hi: f64,
    tube: Option<Tube>,
}

/// Points within `delta` of a circle: every circle of a leaf lies inside.
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

/// An implicit complete binary tree: root at 0, children of `k` at `2k + 1`, `2k + 2`,
/// leaves last, in increasing α.
#[derive(Clone, Debug)]
pub struct Tree {
    nodes: Vec<Node>,
}

impl Tree {
    /// The tree over `leaves` (a power of two) equal α-intervals: each leaf bounds the
    /// circles sampled over its interval, padded by the largest motion between samples
    /// (centre, radius and tilt) twice over; each inner node bounds its children.
    pub fn new(circles: &impl Circles<f64>, leaves: usize) -> Result<Self, SurfaceError> {
        let empty = Node { centre: [0.0; 3], radius: 0.0, lo: 0.0, hi: 0.0, tube: None };
        let mut nodes = vec![empty; 2 * leaves - 1];
        for leaf in 0..leaves {
            nodes[leaves - 1 + leaf] =
                leaf_node(circles, leaf as f64 / leaves as f64, (leaf + 1) as f64 / leaves as f64)?;
        }
        for k in (0..leaves - 1).rev() {
            let (a, b) = (nodes[2 * k + 1], nodes[2 * k + 2]);
            let (centre, radius) = enclose((a.centre, a.radius), (b.centre, b.radius));
            nodes[k] = Node { centre, radius, lo: a.lo, hi: b.hi, tube: None };
        }
        Ok(Tree { nodes })
    }

    /// The α-intervals whose leaves the ray reaches within `(t_min, t_max)`, in increasing α.
    pub fn intervals(&self, ray: &Ray, t_min: f64, t_max: f64) -> Intervals {
        let mut out = Intervals::new();
        let mut stack: SmallVec<[usize; 32]> = SmallVec::new();
        stack.push(0);
        let first_leaf = self.nodes.len() / 2;
        while let Some(k) = stack.pop() {
            let node = &self.nodes[k];
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
}

/// The leaf over `[lo, hi]`: a sphere around the sampled circles and a tube around the middle
/// one, each padded by the largest step between samples.
fn leaf_node(family: &impl Circles<f64>, lo: f64, hi: f64) -> Result<Node, SurfaceError> {
    let mut circles = [([0.0; 3], [0.0; 3], 0.0); LEAF_SAMPLES + 1];
    for (s, slot) in circles.iter_mut().enumerate() {
        let alpha = lo + (hi - lo) * s as f64 / LEAF_SAMPLES as f64;
        *slot = family.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?;
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
    Ok(Node { centre, radius: radius * PAD, lo, hi, tube: Some(tube) })
}

/// The smallest sphere holding two spheres.
fn enclose(a: (E3, f64), b: (E3, f64)) -> (E3, f64) {
    let d = norm(sub(b.0, a.0));
    if d + b.1 <= a.1 {
        a
    } else if d + a.1 <= b.1 {
        b
    } else {
        let radius = 0.5 * (d + a.1 + b.1);
        (add(a.0, scale(sub(b.0, a.0), (radius - a.1) / d)), radius)
    }
}
