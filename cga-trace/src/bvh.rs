//! A bounding-volume hierarchy over a scene's bounded objects, built once at load:
//! axis-aligned boxes around each object's bounding sphere, split at the median centre along
//! the widest axis, four objects or fewer per leaf. A ray visits only the boxes it crosses
//! within `(t_min, t_max)`, nearer child first, and `t_max` shrinks as hits are found.

use cga_core::euclid::E3;
use std::sync::Arc;

/// A box and what it holds: `count > 0` for a leaf (`items[first .. first + count]`),
/// otherwise children at `index + 1` and `second`.
#[derive(Clone, Copy, Debug)]
struct Node {
    min: E3,
    max: E3,
    first: u32,
    count: u32,
    second: u32,
}

/// The hierarchy: object indices in leaf order, and the objects without bounds (planes),
/// which every ray tests.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
    unbounded: Vec<u32>,
}

const LEAF: usize = 4;

impl Bvh {
    /// The hierarchy over objects with these bounding spheres (`None`: unbounded).
    pub fn new(bounds: &[Option<(E3, f64)>]) -> Self {
        Bvh::over(bounds.iter().copied().enumerate())
    }

    /// The hierarchy over the objects `(k, bounds)` given (a part of a scene's).
    fn over(bounds: impl Iterator<Item = (usize, Option<(E3, f64)>)>) -> Self {
        let mut items: Vec<(u32, E3, E3)> = Vec::new();
        let mut unbounded = Vec::new();
        for (k, b) in bounds {
            match b {
                Some((c, r)) => items.push((k as u32, c.map(|x| x - r), c.map(|x| x + r))),
                None => unbounded.push(k as u32),
            }
        }
        let mut bvh = Bvh { nodes: Vec::with_capacity(2 * items.len() / LEAF + 1), items: Vec::new(), unbounded };
        if !items.is_empty() {
            bvh.build(&mut items);
        }
        bvh.items = items.iter().map(|i| i.0).collect();
        bvh
    }

    /// Builds the subtree over `items` (a slice of the whole, at offset `first`), returning its
    /// node index.
    fn build(&mut self, items: &mut [(u32, E3, E3)]) -> usize {
        self.build_at(items, 0)
    }

    fn build_at(&mut self, items: &mut [(u32, E3, E3)], first: usize) -> usize {
        let (mut min, mut max) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for (_, lo, hi) in items.iter() {
            for k in 0..3 {
                min[k] = min[k].min(lo[k]);
                max[k] = max[k].max(hi[k]);
            }
        }
        let index = self.nodes.len();
        self.nodes.push(Node { min, max, first: first as u32, count: items.len() as u32, second: 0 });
        if items.len() <= LEAF {
            return index;
        }
        let axis = (0..3).max_by(|&a, &b| (max[a] - min[a]).total_cmp(&(max[b] - min[b]))).unwrap_or(0);
        let centre = |i: &(u32, E3, E3)| i.1[axis] + i.2[axis];
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |a, b| centre(a).total_cmp(&centre(b)));
        let (left, right) = items.split_at_mut(mid);
        self.build_at(left, first);
        let second = self.build_at(right, first + mid);
        self.nodes[index].count = 0;
        self.nodes[index].second = second as u32;
        index
    }

    /// Calls `visit(k, t_max)` for every object `k` the ray may hit in `(t_min, t_max)`;
    /// `visit` returns the new `t_max` (a nearer hit) or `None` to stop at once (a blocker
    /// found). Unbounded objects come first. Returns the last `t_max`, or `None` if stopped.
    pub fn traverse(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        mut t_max: f64,
        mut visit: impl FnMut(usize, f64) -> Option<f64>,
    ) -> Option<f64> {
        for &k in &self.unbounded {
            t_max = visit(k as usize, t_max)?;
        }
        if self.nodes.is_empty() {
            return Some(t_max);
        }
        let inv = dir.map(|d| 1.0 / d);
        if slab(&self.nodes[0], origin, inv, t_min, t_max).is_none() {
            return Some(t_max);
        }
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if node.count > 0 {
                for &k in &self.items[node.first as usize..(node.first + node.count) as usize] {
                    t_max = visit(k as usize, t_max)?;
                }
                continue;
            }
            // Children the ray enters before t_max, the nearer on top. A child was entered
            // when its parent was pushed; t_max may have shrunk since, so test again.
            let (a, b) = (stack[top] + 1, node.second);
            let enter = |n: u32| slab(&self.nodes[n as usize], origin, inv, t_min, t_max);
            let (near, far) = match (enter(a), enter(b)) {
                (Some(ta), Some(tb)) if tb < ta => (Some(b), Some(a)),
                (Some(_), Some(_)) => (Some(a), Some(b)),
                (Some(_), None) => (Some(a), None),
                (None, Some(_)) => (Some(b), None),
                (None, None) => (None, None),
            };
            for n in [far, near].into_iter().flatten() {
                if top < stack.len() {
                    stack[top] = n;
                    top += 1;
                }
            }
        }
        Some(t_max)
    }
}

/// A scene's hierarchy in two layers visited as one: over the objects that stay in place
/// (shared, built once for all of a shutter's instants: [`Kept`]) and over those that move
/// (built for each instant).
#[derive(Clone, Debug)]
pub struct Layers {
    still: Arc<Bvh>,
    moving: Option<Bvh>,
}

impl Layers {
    /// [`Bvh::traverse`] through the objects that stay, then, with the `t_max` they leave,
    /// those that move.
    pub fn traverse(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        t_max: f64,
        mut visit: impl FnMut(usize, f64) -> Option<f64>,
    ) -> Option<f64> {
        let t_max = self.still.traverse(origin, dir, t_min, t_max, &mut visit)?;
        match &self.moving {
            Some(moving) => moving.traverse(origin, dir, t_min, t_max, visit),
            None => Some(t_max),
        }
    }
}

/// The hierarchy over a scene's objects that stay in place, kept from one picture of it to
/// the next (a shutter's instants, an animation's frames): built again only where their
/// bounds differ from the last picture's.
#[derive(Debug, Default)]
pub struct Kept {
    bounds: Vec<(usize, Option<(E3, f64)>)>,
    still: Option<Arc<Bvh>>,
}

impl Kept {
    /// The two layers over objects with these `bounds`, `moving[k]` saying which move;
    /// `same` where the caller knows the objects that do not move are as at the last call
    /// (their bounds are then not compared).
    pub fn layers(&mut self, bounds: &[Option<(E3, f64)>], moving: &[bool], same: bool) -> Layers {
        let still = match &self.still {
            Some(still) if same => still.clone(),
            _ => self.still_layer(bounds, moving),
        };
        let moved = moving.iter().any(|&m| m);
        let moving = moved.then(|| Bvh::over(bounds.iter().copied().enumerate().filter(|&(k, _)| moving[k])));
        Layers { still, moving }
    }

    /// The layer over the objects that do not move: the last one where their bounds are as
    /// then, else built anew.
    fn still_layer(&mut self, bounds: &[Option<(E3, f64)>], moving: &[bool]) -> Arc<Bvh> {
        let still_bounds: Vec<_> = bounds.iter().copied().enumerate().filter(|&(k, _)| !moving[k]).collect();
        match &self.still {
            Some(still) if self.bounds == still_bounds => still.clone(),
            _ => {
                let still = Arc::new(Bvh::over(still_bounds.iter().copied()));
                (self.bounds, self.still) = (still_bounds, Some(still.clone()));
                still
            }
        }
    }
}

/// Where the ray enters the node's box within `(t_min, t_max)`, if it does (the slab test).
fn slab(node: &Node, origin: E3, inv: E3, t_min: f64, t_max: f64) -> Option<f64> {
    let (mut lo, mut hi) = (t_min, t_max);
    for k in 0..3 {
        let (a, b) = ((node.min[k] - origin[k]) * inv[k], (node.max[k] - origin[k]) * inv[k]);
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        // NaN (0 · ∞ on a face) leaves the bound as it was.
        lo = if a > lo { a } else { lo };
        hi = if b < hi { b } else { hi };
    }
    (lo <= hi).then_some(lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visits_every_object_the_ray_can_hit() {
        // A 10×10×10 grid of unit spheres and two unbounded objects.
        let mut bounds: Vec<Option<(E3, f64)>> = (0..1000)
            .map(|k| Some(([(k % 10) as f64 * 3.0, ((k / 10) % 10) as f64 * 3.0, (k / 100) as f64 * 3.0], 1.0)))
            .collect();
        bounds.extend([None, None]);
        let bvh = Bvh::new(&bounds);
        for (o, d) in [([-5.0, 0.1, 0.2], [1.0, 0.0, 0.0]), ([-5.0, -5.0, -5.0], [0.577, 0.577, 0.577])] {
            let mut seen = Vec::new();
            bvh.traverse(o, d, 0.0, f64::INFINITY, |k, t| {
                seen.push(k);
                Some(t)
            });
            for (k, b) in bounds.iter().enumerate() {
                // Every sphere the line passes within its radius of is visited.
                let must = b.is_none_or(|(c, r)| {
                    let oc = [c[0] - o[0], c[1] - o[1], c[2] - o[2]];
                    let t = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
                    let n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    let miss2 = oc.iter().map(|x| x * x).sum::<f64>() - t * t / n2;
                    miss2 <= r * r
                });
                assert!(!must || seen.contains(&k), "object {k} not visited");
            }
            assert!(seen.len() < 200, "{} visited: the hierarchy culls nothing", seen.len());
        }
    }

    #[test]
    fn two_layers_visit_every_object_the_ray_can_hit_and_the_still_one_is_kept() {
        let grid = |shift: f64| -> Vec<Option<(E3, f64)>> {
            (0..200)
                .map(|k| Some(([(k % 10) as f64 * 3.0 + shift * (k % 2) as f64, (k / 10) as f64 * 3.0, 0.0], 1.0)))
                .collect()
        };
        // The odd objects move.
        let moving: Vec<bool> = (0..200).map(|k| k % 2 == 1).collect();
        let mut kept = Kept::default();
        let first = kept.layers(&grid(0.0), &moving, false);
        let later = kept.layers(&grid(0.5), &moving, false);
        assert!(Arc::ptr_eq(&first.still, &later.still), "the still layer is built again");
        let bounds = grid(0.5);
        for (o, d) in [([-5.0, 0.1, 0.0], [1.0, 0.0, 0.0]), ([-5.0, -5.0, 0.0], [0.7, 0.7, 0.0])] {
            let mut seen = Vec::new();
            later.traverse(o, d, 0.0, f64::INFINITY, |k, t| {
                seen.push(k);
                Some(t)
            });
            // Every sphere the line passes within its radius of is visited, whichever layer.
            for (k, (c, r)) in bounds.iter().flatten().enumerate() {
                let oc = [c[0] - o[0], c[1] - o[1], c[2] - o[2]];
                let t = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
                let miss2 = oc.iter().map(|x| x * x).sum::<f64>() - t * t / (d[0] * d[0] + d[1] * d[1]);
                assert!(miss2 > r * r || seen.contains(&k), "object {k} not visited");
            }
            assert!(seen.len() < 100, "{} visited: the layers cull nothing", seen.len());
        }
        // A still object that is elsewhere: the still layer is built again.
        let mut moved = grid(0.5);
        moved[0] = Some(([100.0, 0.0, 0.0], 1.0));
        assert!(!Arc::ptr_eq(&later.still, &kept.layers(&moved, &moving, false).still));
    }
}
