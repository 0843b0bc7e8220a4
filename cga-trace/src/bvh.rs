//! A bounding-volume hierarchy, built once at load: over a scene's bounded objects (axis-aligned
//! boxes around each one's bounding sphere) and over a mesh's triangles (each one's own box).
//! Each box is split along the axis its items' centres spread widest, where the surface area
//! heuristic puts the split (16 bins: the one of least `A_left n_left + A_right n_right`, each
//! side's count weighed by its area, the chance that a ray crossing the parent crosses it),
//! four items or fewer to a leaf. A ray visits only the boxes it crosses within
//! `(t_min, t_max)`, nearer child first, and `t_max` shrinks as hits are found.

use cga_core::euclid::E3;
use cga_core::simd::Lane;
use std::mem::MaybeUninit;
use std::ops::Range;
use std::sync::Arc;

/// A box and what it holds: `count > 0` for a leaf (`items[first .. first + count]`),
/// otherwise children at `index + 1` and `second`, split along `axis` (the first holds the
/// lower centres).
#[derive(Clone, Copy, Debug)]
struct Node {
    /// The box's lower and upper corners.
    corners: [E3; 2],
    first: u32,
    count: u32,
    second: u32,
    axis: u32,
}

/// The hierarchy: item indices in leaf order, and the objects without bounds (planes),
/// which every ray tests.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
    unbounded: Vec<u32>,
}

/// The most items a leaf holds (a mesh tests a leaf's triangles four at a time: `MeshShape`).
pub(crate) const LEAF: usize = 4;

/// Bins the surface area heuristic weighs splits at.
const BINS: usize = 16;

/// From this depth on, splits are at the median centre whatever the heuristic says, so that
/// the tree stays within the traversals' stacks (64 deep, [`WIDE_STACK`]) for any input: at most
/// `40 + log₂(2²⁰ / 4) = 58` levels for the most objects a scene may hold.
const SAH_DEPTH: usize = 40;

/// An item being placed: its index and box.
type Item = (u32, E3, E3);

/// The empty box.
const EMPTY: (E3, E3) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);

impl Bvh {
    /// The hierarchy over objects with these bounding spheres (`None`: unbounded).
    pub fn new(bounds: &[Option<(E3, f64)>]) -> Self {
        Bvh::over(bounds.iter().copied().enumerate())
    }

    /// The hierarchy over items with these boxes `(min, max)`.
    pub fn over_boxes(boxes: &[(E3, E3)]) -> Self {
        let items = boxes.iter().enumerate().map(|(k, &(lo, hi))| (k as u32, lo, hi)).collect();
        Bvh::build(items, Vec::new())
    }

    /// The hierarchy over the objects `(k, bounds)` given (a part of a scene's).
    fn over(bounds: impl Iterator<Item = (usize, Option<(E3, f64)>)>) -> Self {
        let mut items: Vec<Item> = Vec::new();
        let mut unbounded = Vec::new();
        for (k, b) in bounds {
            match b {
                Some((c, r)) => items.push((k as u32, c.map(|x| x - r), c.map(|x| x + r))),
                None => unbounded.push(k as u32),
            }
        }
        Bvh::build(items, unbounded)
    }

    fn build(mut items: Vec<Item>, unbounded: Vec<u32>) -> Self {
        let mut bvh = Bvh { nodes: Vec::with_capacity(2 * items.len() / LEAF + 1), items: Vec::new(), unbounded };
        if !items.is_empty() {
            bvh.build_at(&mut items, 0, 0);
        }
        bvh.items = items.iter().map(|i| i.0).collect();
        bvh
    }

    /// The items in leaf order: what the ranges [`Bvh::traverse_leaves`] gives index.
    pub fn order(&self) -> &[u32] {
        &self.items
    }

    /// Builds the subtree over `items` (a slice of the whole, at offset `first`, `depth`
    /// below the root), returning its node index.
    fn build_at(&mut self, items: &mut [Item], first: usize, depth: usize) -> usize {
        let (min, max) = enclosing(items.iter().map(|i| (i.1, i.2)));
        let index = self.nodes.len();
        self.nodes.push(Node {
            corners: [min, max],
            first: first as u32,
            count: items.len() as u32,
            second: 0,
            axis: 0,
        });
        if items.len() <= LEAF {
            return index;
        }
        let (mid, axis) = split(items, depth);
        let (left, right) = items.split_at_mut(mid);
        self.build_at(left, first, depth + 1);
        let second = self.build_at(right, first + mid, depth + 1);
        self.nodes[index] = Node { count: 0, second: second as u32, axis: axis as u32, ..self.nodes[index] };
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
        self.traverse_leaves(origin, dir, t_min, t_max, |leaf, mut t_max| {
            for &k in &self.items[leaf] {
                t_max = visit(k as usize, t_max)?;
            }
            Some(t_max)
        })
    }

    /// Calls `visit(leaf, t_max)` for every leaf whose box the ray crosses within
    /// `(t_min, t_max)`, `leaf` the range of its items in [leaf order](Bvh::order), nearer boxes
    /// first; `visit` returns the new `t_max` or `None` to stop at once. Unbounded objects are
    /// not visited.
    pub fn traverse_leaves(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        mut t_max: f64,
        mut visit: impl FnMut(Range<usize>, f64) -> Option<f64>,
    ) -> Option<f64> {
        if self.nodes.is_empty() {
            return Some(t_max);
        }
        let inv = Inverse::new(dir);
        if slab(&self.nodes[0], origin, &inv, t_min, t_max).is_none() {
            return Some(t_max);
        }
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            if node.count > 0 {
                t_max = visit(node.first as usize..(node.first + node.count) as usize, t_max)?;
                continue;
            }
            // Children the ray enters before t_max, the nearer on top. A child was entered
            // when its parent was pushed; t_max may have shrunk since, so test again.
            let (a, b) = (stack[top] + 1, node.second);
            let enter = |n: u32| slab(&self.nodes[n as usize], origin, &inv, t_min, t_max);
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

impl Bvh {
    /// [`Bvh::traverse_leaves`] for four rays at once, their origins and directions in lanes
    /// `L` (four of them): each box is tested against the four in lanes, and a leaf is visited
    /// with the lanes whose rays cross its box, `visit(leaf, lanes, t_max)` lowering their
    /// `t_max` (a lane with `t_max = −∞` is done) or returning `None` to stop. Nearer boxes
    /// first by the first ray's direction. A box is tested against a lane's present `t_max`
    /// with the numbers [`Bvh::traverse_leaves`] uses for that ray alone, but the order, and
    /// so which boxes a shrinking `t_max` cuts off, may differ: a `visit` that keeps the
    /// nearest crossing by a rule that does not depend on the order, and boxes a rounding
    /// past it (as a mesh's does), finds what each ray alone would.
    #[inline(always)]
    pub fn traverse_leaves4<L: Lane>(
        &self,
        origin: &E3<L>,
        dir: &E3<L>,
        t_min: [f64; 4],
        t_max: &mut [f64; 4],
        mut visit: impl FnMut(Range<usize>, [bool; 4], &mut [f64; 4]) -> Option<()>,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let inv: E3<L> = core::array::from_fn(|k| L::from_fn(|l| 1.0 / dir[k].lane(l)));
        let lower = core::array::from_fn::<bool, 3, _>(|k| dir[k].lane(0) < 0.0);
        let lo = L::from_fn(|l| t_min[l]);
        let mut hi = L::from_fn(|l| t_max[l]);
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let index = stack[top];
            let node = &self.nodes[index as usize];
            let enters = slab_lanes(node, origin, &inv, lo, hi);
            if !L::any(enters) {
                continue;
            }
            if node.count > 0 {
                let lanes = core::array::from_fn(|l| L::mask_lane(enters, l));
                if visit(node.first as usize..(node.first + node.count) as usize, lanes, t_max).is_none() {
                    return;
                }
                hi = L::from_fn(|l| t_max[l]);
                continue;
            }
            let (a, b) = (index + 1, node.second);
            for n in if lower[node.axis as usize] { [a, b] } else { [b, a] } {
                if top < stack.len() {
                    stack[top] = n;
                    top += 1;
                }
            }
        }
    }
}

/// Four boxes of a [`Bvh`] side by side (structure of arrays), tested against a ray at once:
/// the children, grandchildren or deeper descendants of one of its nodes, each a leaf (its
/// items' range) or another `Quad`.
#[derive(Clone, Copy, Debug)]
struct Quad {
    /// `[lower, upper][axis][lane]`; an unused lane holds the empty box (`+∞` below, `−∞`
    /// above).
    corners: [[[f64; 4]; 3]; 2],
    /// A leaf's first item, an inner lane's `Quad` index, or [`UNUSED`].
    first: [u32; 4],
    /// A leaf's item count; `0` for an inner lane.
    count: [u32; 4],
}

/// A [`Bvh`] with four children to a node (`Quad`), for one ray at a time: each of its
/// binary nodes is expanded into its two children, the larger of whose inner nodes (by
/// surface area) is expanded in turn until four boxes stand side by side. Every box of the
/// wide tree is a box of the binary one, and a ray that enters a box within `(t_min, t_max)`
/// enters every box holding it: with `t_max` fixed a ray visits the very leaves
/// [`Bvh::traverse_leaves`] does, opening about half as many nodes, four boxes at a time.
/// Where visits lower `t_max`, the order, and so which boxes that cuts off, may differ: a
/// visit that keeps the nearest crossing by a rule that does not depend on the order (a
/// mesh's) finds the same.
#[derive(Clone, Debug)]
pub struct Wide {
    quads: Vec<Quad>,
    /// The root's box: one test turns away most rays that miss.
    root: Node,
}

/// An unused lane's `first`: never opened, whatever its box's test says (a ray of NaNs passes
/// every slab test).
const UNUSED: u32 = u32::MAX;

/// The most [`Wide`] lanes a ray has pending: three a level, over at most 58 levels
/// ([`SAH_DEPTH`]).
const WIDE_STACK: usize = 192;

impl Wide {
    /// The wide tree of `bvh`'s nodes; its leaves index `bvh`'s [order](Bvh::order).
    pub fn new(bvh: &Bvh) -> Self {
        let empty = Node { corners: [EMPTY.0, EMPTY.1], first: 0, count: 0, second: 0, axis: 0 };
        let root = bvh.nodes.first().copied().unwrap_or(empty);
        let mut wide = Wide { quads: Vec::with_capacity(bvh.nodes.len() / 3 + 1), root };
        if !bvh.nodes.is_empty() {
            let lanes = if root.count > 0 { vec![0] } else { bvh.expanded(0) };
            wide.quad(bvh, &lanes);
        }
        wide
    }

    /// Appends the `Quad` over the binary nodes `lanes` (and those below), returning its index.
    fn quad(&mut self, bvh: &Bvh, lanes: &[u32]) -> u32 {
        let index = self.quads.len();
        let empty = [[f64::INFINITY; 4], [f64::NEG_INFINITY; 4]];
        self.quads.push(Quad { corners: [[empty[0]; 3], [empty[1]; 3]], first: [UNUSED; 4], count: [0; 4] });
        for (l, &n) in lanes.iter().enumerate() {
            let node = &bvh.nodes[n as usize];
            let first = if node.count > 0 { node.first } else { self.quad(bvh, &bvh.expanded(n)) };
            let quad = &mut self.quads[index];
            for (side, corner) in node.corners.iter().enumerate() {
                for (k, &x) in corner.iter().enumerate() {
                    quad.corners[side][k][l] = x;
                }
            }
            (quad.first[l], quad.count[l]) = (first, node.count);
        }
        index as u32
    }

    /// [`Bvh::traverse_leaves`] through the wide tree: the same leaves visited, nearer
    /// boxes first. Compiled for AVX2 where the CPU has it (chosen at run time; the same
    /// operations, so the same leaves).
    pub fn traverse_leaves(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        t_max: f64,
        visit: impl FnMut(Range<usize>, f64) -> Option<f64>,
    ) -> Option<f64> {
        #[cfg(target_arch = "x86_64")]
        if cga_core::simd::avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.traverse_avx2(origin, dir, t_min, t_max, visit) };
        }
        self.traverse_here(origin, dir, t_min, t_max, visit)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn traverse_avx2(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        t_max: f64,
        visit: impl FnMut(Range<usize>, f64) -> Option<f64>,
    ) -> Option<f64> {
        self.traverse_here(origin, dir, t_min, t_max, visit)
    }

    #[inline(always)]
    fn traverse_here(
        &self,
        origin: E3,
        dir: E3,
        t_min: f64,
        mut t_max: f64,
        mut visit: impl FnMut(Range<usize>, f64) -> Option<f64>,
    ) -> Option<f64> {
        let inv = Inverse::new(dir);
        if self.quads.is_empty() || slab(&self.root, origin, &inv, t_min, t_max).is_none() {
            return Some(t_max);
        }
        // (entry distance, first, count): a leaf for `count > 0`, else a `Quad`. Left
        // uninitialised: zeroing it cost a missed ray more than its whole traversal.
        let mut stack = [const { MaybeUninit::<(f64, u32, u32)>::uninit() }; WIDE_STACK];
        stack[0].write((t_min, 0, 0));
        let mut top = 1;
        while top > 0 {
            top -= 1;
            // SAFETY: every slot below `top` was written before `top` passed it.
            let (enter, first, count) = unsafe { stack[top].assume_init() };
            // Entered when its parent was opened; `t_max` may have shrunk since.
            if enter > t_max {
                continue;
            }
            if count > 0 {
                t_max = visit(first as usize..(first + count) as usize, t_max)?;
                continue;
            }
            let quad = &self.quads[first as usize];
            let enters = slab4(quad, origin, &inv, t_min, t_max);
            // The lanes entered, farthest pushed first so that the nearest is opened next.
            let mut order: [(f64, usize); 4] = [(0.0, 0); 4];
            let mut n = 0;
            for (l, t) in enters.iter().enumerate() {
                if let (Some(t), true) = (*t, quad.first[l] != UNUSED) {
                    let mut at = n;
                    while at > 0 && order[at - 1].0 < t {
                        order[at] = order[at - 1];
                        at -= 1;
                    }
                    order[at] = (t, l);
                    n += 1;
                }
            }
            for &(t, l) in &order[..n] {
                if top < stack.len() {
                    stack[top].write((t, quad.first[l], quad.count[l]));
                    top += 1;
                }
            }
        }
        Some(t_max)
    }
}

impl Bvh {
    /// Binary node `n`'s descendants that stand side by side in its [`Quad`]: its two children,
    /// then the inner one of largest surface area replaced by its two, while there are fewer
    /// than four.
    fn expanded(&self, n: u32) -> Vec<u32> {
        let node = &self.nodes[n as usize];
        let mut lanes = vec![n + 1, node.second];
        while lanes.len() < 4 {
            let inner = (0..lanes.len())
                .filter(|&i| self.nodes[lanes[i] as usize].count == 0)
                .max_by(|&a, &b| self.area_of(lanes[a]).total_cmp(&self.area_of(lanes[b])));
            let Some(i) = inner else { break };
            let m = lanes[i];
            lanes[i] = m + 1;
            lanes.push(self.nodes[m as usize].second);
        }
        lanes
    }

    fn area_of(&self, n: u32) -> f64 {
        let [lo, hi] = self.nodes[n as usize].corners;
        area((lo, hi))
    }
}

/// [`slab`] for a [`Quad`]'s four boxes: where the ray enters each within `(t_min, t_max)`,
/// with the same numbers as `slab` on each box alone (so the same answer).
#[inline(always)]
fn slab4(quad: &Quad, origin: E3, ray: &Inverse, t_min: f64, t_max: f64) -> [Option<f64>; 4] {
    let (mut lo, mut hi) = ([t_min; 4], [t_max; 4]);
    for (k, (o, (i, n))) in origin.into_iter().zip(ray.inv.into_iter().zip(ray.near)).enumerate() {
        let (near, far) = (&quad.corners[n][k], &quad.corners[1 - n][k]);
        for l in 0..4 {
            let (a, b) = ((near[l] - o) * i, (far[l] - o) * i);
            // NaN (0 · ∞: a ray in a face's plane, parallel to it) leaves the bound as it was.
            lo[l] = if a > lo[l] { a } else { lo[l] };
            hi[l] = if b < hi[l] { b } else { hi[l] };
        }
    }
    core::array::from_fn(|l| (lo[l] <= hi[l]).then_some(lo[l]))
}

/// The box holding these boxes.
fn enclosing(boxes: impl Iterator<Item = (E3, E3)>) -> (E3, E3) {
    let (mut min, mut max) = EMPTY;
    for (lo, hi) in boxes {
        for k in 0..3 {
            min[k] = min[k].min(lo[k]);
            max[k] = max[k].max(hi[k]);
        }
    }
    (min, max)
}

/// Half a box's surface area (`0` for the empty box).
fn area((lo, hi): (E3, E3)) -> f64 {
    let [x, y, z] = [0, 1, 2].map(|k| (hi[k] - lo[k]).max(0.0));
    x * y + y * z + z * x
}

/// Reorders `items` into two sides and returns where the second starts, and the axis: the one
/// their centres spread widest along, at the bin boundary of least `A_left n_left + A_right n_right`
/// while `depth` is below [`SAH_DEPTH`]; deeper, or where every centre falls in one bin, at
/// the median centre.
fn split(items: &mut [Item], depth: usize) -> (usize, usize) {
    let centre = |i: &Item, k: usize| 0.5 * (i.1[k] + i.2[k]);
    let (lo, hi) = enclosing(items.iter().map(|i| {
        let c = [0, 1, 2].map(|k| centre(i, k));
        (c, c)
    }));
    let axis = (0..3).max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b]))).unwrap_or(0);
    let (base, width) = (lo[axis], hi[axis] - lo[axis]);
    let bin = |i: &Item| (((centre(i, axis) - base) / width * BINS as f64) as usize).min(BINS - 1);
    let best = if depth < SAH_DEPTH && width > 0.0 { cheapest(items, bin) } else { None };
    let Some(first_right) = best else {
        let mid = items.len() / 2;
        items.select_nth_unstable_by(mid, |a, b| centre(a, axis).total_cmp(&centre(b, axis)));
        return (mid, axis);
    };
    let mut mid = 0;
    for k in 0..items.len() {
        if bin(&items[k]) < first_right {
            items.swap(k, mid);
            mid += 1;
        }
    }
    (mid, axis)
}

/// The first bin of the right side of the cheapest split between bins (`None` where all
/// items fall in one).
fn cheapest(items: &[Item], bin: impl Fn(&Item) -> usize) -> Option<usize> {
    let mut bins = [(0usize, EMPTY); BINS];
    for i in items {
        let b = &mut bins[bin(i)];
        b.0 += 1;
        b.1 = enclosing([b.1, (i.1, i.2)].into_iter());
    }
    // Swept from the right: the count and area of bins b.. for every b.
    let mut right = [(0usize, 0.0f64); BINS];
    let mut acc = (0, EMPTY);
    for b in (1..BINS).rev() {
        acc = (acc.0 + bins[b].0, enclosing([acc.1, bins[b].1].into_iter()));
        right[b] = (acc.0, area(acc.1));
    }
    let mut left = (0, EMPTY);
    let mut best: Option<(f64, usize)> = None;
    for b in 1..BINS {
        left = (left.0 + bins[b - 1].0, enclosing([left.1, bins[b - 1].1].into_iter()));
        let (n_right, a_right) = right[b];
        let cost = area(left.1) * left.0 as f64 + a_right * n_right as f64;
        if left.0 > 0 && n_right > 0 && best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, b));
        }
    }
    best.map(|(_, b)| b)
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

/// A ray's direction inverted, `1/d_k` (`±∞` for `d_k = ±0`), and which corner of a box it
/// enters by along each axis (the upper where `1/d_k < 0`).
struct Inverse {
    inv: E3,
    near: [usize; 3],
}

impl Inverse {
    fn new(dir: E3) -> Self {
        let inv = dir.map(|d| 1.0 / d);
        Inverse { inv, near: inv.map(|i| usize::from(i < 0.0)) }
    }
}

/// Where the ray enters the node's box within `(t_min, t_max)`, if it does (the slab test):
/// along each axis it enters at the nearer of the box's two faces and leaves at the other.
#[inline(always)]
fn slab(node: &Node, origin: E3, ray: &Inverse, t_min: f64, t_max: f64) -> Option<f64> {
    let (mut lo, mut hi) = (t_min, t_max);
    for (k, (o, (i, n))) in origin.into_iter().zip(ray.inv.into_iter().zip(ray.near)).enumerate() {
        let near = (node.corners[n][k] - o) * i;
        let far = (node.corners[1 - n][k] - o) * i;
        // NaN (0 · ∞: a ray in a face's plane, parallel to it) leaves the bound as it was.
        lo = if near > lo { near } else { lo };
        hi = if far < hi { far } else { hi };
    }
    (lo <= hi).then_some(lo)
}

/// [`slab`] for rays in lanes: which of them enter the node's box within their ranges (the
/// same numbers, so the same answer, as each ray's own test).
#[inline(always)]
fn slab_lanes<L: Lane>(node: &Node, origin: &E3<L>, inv: &E3<L>, mut lo: L, mut hi: L) -> L::Mask {
    for k in 0..3 {
        let a = (L::from_f64(node.corners[0][k]) - origin[k]) * inv[k];
        let b = (L::from_f64(node.corners[1][k]) - origin[k]) * inv[k];
        // The faces by the sign of `1/d`, as `slab` picks them (a NaN bound is then ignored
        // in both).
        let upper = inv[k].lt(L::zero());
        let (near, far) = (L::select(upper, b, a), L::select(upper, a, b));
        lo = L::select(lo.lt(near), near, lo);
        hi = L::select(far.lt(hi), far, hi);
    }
    lo.le(hi)
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

    /// Boxes whose centres crowd towards one end (`2⁻ᵏ`), where the surface area heuristic
    /// would peel one off at a time: the depth guard keeps the tree within the stack, so a ray
    /// through each box visits it, one ray at a time and four together in lanes (each lane
    /// visiting at least what its ray alone visits).
    #[test]
    fn crowded_boxes_are_all_reached_alone_and_in_lanes() {
        use cga_core::simd::F64x4;
        let boxes: Vec<(E3, E3)> =
            (0..600).map(|k| 0.5f64.powi(k)).map(|x| ([x, -0.1, -0.1], [x + x * 1e-3, 0.1, 0.1])).collect();
        let bvh = Bvh::over_boxes(&boxes);
        let leaves = |o: E3, d: E3| {
            let mut seen = Vec::new();
            bvh.traverse_leaves(o, d, 0.0, f64::INFINITY, |leaf, t| {
                seen.extend(leaf.map(|i| bvh.order()[i]));
                Some(t)
            });
            seen
        };
        for (k, (lo, hi)) in boxes.iter().enumerate().step_by(5) {
            let rays: [(E3, E3); 4] = core::array::from_fn(|l| {
                let x = 0.5 * (lo[0] + hi[0]);
                ([x, -1.0, 0.01 * l as f64], [0.0, 1.0, 0.0])
            });
            let origin: E3<F64x4> = core::array::from_fn(|c| F64x4(rays.map(|r| r.0[c])));
            let dir: E3<F64x4> = core::array::from_fn(|c| F64x4(rays.map(|r| r.1[c])));
            let mut four: [Vec<u32>; 4] = Default::default();
            bvh.traverse_leaves4(&origin, &dir, [0.0; 4], &mut [f64::INFINITY; 4], |leaf, lanes, _| {
                for l in (0..4).filter(|&l| lanes[l]) {
                    four[l].extend(leaf.clone().map(|i| bvh.order()[i]));
                }
                Some(())
            });
            for (l, (o, d)) in rays.iter().enumerate() {
                let alone = leaves(*o, *d);
                assert!(alone.contains(&(k as u32)), "box {k} not reached");
                assert!(alone.iter().all(|i| four[l].contains(i)), "lane {l} misses what its ray alone visits");
            }
        }
    }

    /// The wide tree visits the very leaves the binary one does, for any `(t_min, t_max)`
    /// (kept fixed): over scattered boxes, crowded ones (a deep tree), one leaf and none; rays
    /// from inside and outside, along an axis (zero components, ±0) and in a face's plane.
    #[test]
    fn the_wide_tree_visits_the_leaves_the_binary_one_does() {
        let mut next = crate::hash::stream(0x9e37_79b9_7f4a_7c15);
        let scattered: Vec<(E3, E3)> = (0..500)
            .map(|_| {
                let c = [next() * 10.0, next() * 10.0, next() * 10.0];
                let h = [next() * 0.5, next() * 0.5, next() * 0.5];
                ([0, 1, 2].map(|k| c[k] - h[k]), [0, 1, 2].map(|k| c[k] + h[k]))
            })
            .collect();
        let crowded: Vec<(E3, E3)> =
            (0..600).map(|k| 0.5f64.powi(k)).map(|x| ([x, -0.1, -0.1], [x + x * 1e-3, 0.1, 0.1])).collect();
        let one = vec![([0.0; 3], [1.0; 3]); 3];
        for boxes in [scattered, crowded, one, Vec::new()] {
            let bvh = Bvh::over_boxes(&boxes);
            let wide = Wide::new(&bvh);
            // Every other ray aimed at a box's centre.
            let mut rays: Vec<(E3, E3)> = (0..400)
                .map(|k| {
                    let o = [next() * 14.0 - 2.0, next() * 14.0 - 2.0, next() * 14.0 - 2.0];
                    let d = match boxes.get((next() * boxes.len() as f64) as usize) {
                        Some((lo, hi)) if k % 2 == 0 => [0, 1, 2].map(|c| 0.5 * (lo[c] + hi[c]) - o[c]),
                        _ => [next() - 0.5, next() - 0.5, next() - 0.5],
                    };
                    (o, d)
                })
                .collect();
            // Rays of NaNs and infinities pass every slab test: every leaf, and no more.
            let nan = f64::NAN;
            rays.extend([
                ([0.5; 3], [nan; 3]),
                ([nan; 3], [1.0, 0.0, 0.0]),
                ([0.5; 3], [f64::INFINITY; 3]),
                ([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]),
                ([-1.0, 0.5, 0.5], [1.0, -0.0, 0.0]),
                ([0.5, 0.0, -1.0], [0.0, 0.0, 1.0]),
                ([1.0, 0.5, -1.0], [0.0, 0.0, 1.0]),
                ([0.5, 0.5, 0.5], [0.3, -0.2, 0.9]),
            ]);
            let mut visited = 0;
            for (k, &(o, d)) in rays.iter().enumerate() {
                let (t_min, t_max) = if k % 3 == 0 { (0.0, f64::INFINITY) } else { (next() * 4.0, 4.0 + next() * 8.0) };
                let (mut binary, mut four) = (Vec::new(), Vec::new());
                bvh.traverse_leaves(o, d, t_min, t_max, |leaf, t| {
                    binary.push((leaf.start, leaf.end));
                    Some(t)
                });
                wide.traverse_leaves(o, d, t_min, t_max, |leaf, t| {
                    four.push((leaf.start, leaf.end));
                    Some(t)
                });
                binary.sort();
                four.sort();
                assert_eq!(binary, four, "ray {k} from {o:?} along {d:?} in ({t_min}, {t_max})");
                visited += four.len();
            }
            assert!(boxes.is_empty() || visited > rays.len() / 8, "{visited} leaves visited in all");
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
