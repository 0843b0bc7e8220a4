//! Constructive solid geometry and clipping, along the ray's line. A closed shape says where
//! the ray's whole line lies inside it ([`Shape::spans`]); a CSG tree ([`Csg`]) combines its
//! leaves' spans by the set operations, boundary by boundary in order along the line, so that
//! each crossing of the result is one leaf's own crossing, classified by the others' spans on
//! the same line: no point is tested for inside-ness, no ray is stepped past a surface, and a
//! face two leaves share (one leaving where the other enters, at the same parameter) is no
//! boundary at all. Each leaf is shown as its own scene object ([`CsgPart`]: the crossings of
//! the result that lie on it), so that it keeps its material; a glass body's parts share one
//! medium. A clip ([`Clipped`]) keeps the crossings of any shape, closed or not, that lie in a
//! region (the intersection of closed shapes: half-spaces, spheres, boxes), without caps; a
//! capped clip is the CSG intersection of a closed shape with the region.

use super::{Crossing, Shape};
use crate::ray::{Ray, in_range};
use cga_core::euclid::{E3, dot, norm, sub};
use smallvec::SmallVec;
use std::sync::Arc;

/// Where a ray's line lies inside a solid: sorted, disjoint `(enter, leave)` intervals of its
/// parameter; an end is infinite where the solid is (a half-space).
pub type Spans = SmallVec<[(f64, f64); 4]>;

/// The most crossings a closed shape's spans are read from, and the most a clipped shape's
/// crossings are tried: a torus has four; past this a line is taken to miss.
pub const MAX_CROSSINGS: usize = 64;

/// The spans of a closed shape read off its crossings along the whole line within its
/// bounds, in turn from outside (parity). A tangent ray touching the surface once leaves an
/// odd count: the crossing where the line runs most nearly along the surface is dropped. An
/// unbounded shape must give its spans itself.
pub fn spans_by_crossings<S: Shape + ?Sized>(shape: &S, ray: &Ray) -> Spans {
    let mut spans = Spans::new();
    let Some((centre, radius)) = shape.bounds() else { return spans };
    let along = dot(sub(centre, ray.origin), ray.dir);
    let reach = 1.01 * radius + shape.crossing_error();
    let (mut t, end) = (along - reach, along + reach);
    let step = shape.crossing_error().max(f64::MIN_POSITIVE);
    let mut crossings: SmallVec<[Crossing; 8]> = SmallVec::new();
    while crossings.len() < MAX_CROSSINGS {
        let Some(c) = shape.intersect(ray, t, end) else { break };
        crossings.push(c);
        t = c.t + step.max(4.0 * f64::EPSILON * c.t.abs());
    }
    if crossings.len() % 2 == 1 {
        let grazing = |c: &Crossing| dot(shape.normal(ray, c), ray.dir).abs();
        let touch = (0..crossings.len()).min_by(|&a, &b| grazing(&crossings[a]).total_cmp(&grazing(&crossings[b])));
        crossings.remove(touch.unwrap_or(0));
    }
    spans.extend(crossings.chunks_exact(2).map(|p| (p[0].t, p[1].t)));
    spans
}

/// The set operations of a CSG tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operation {
    /// In any child.
    Union,
    /// In every child.
    Intersection,
    /// In the first child and in none of the others.
    Difference,
}

impl Operation {
    /// Whether a point in `a` (or not) and in `b` (or not) is in the result of `a` and `b`
    /// (the first child so far and the next).
    fn keeps(self, a: bool, b: bool) -> bool {
        match self {
            Operation::Union => a || b,
            Operation::Intersection => a && b,
            Operation::Difference => a && !b,
        }
    }
}

/// A CSG tree: leaves are indices into [`Csg::leaves`].
#[derive(Clone, Debug)]
pub enum Node {
    /// A closed shape.
    Leaf(usize),
    /// An operation on two or more children.
    Op(Operation, Vec<Node>),
}

/// A boundary of a combined solid along the line: its parameter and the leaf it lies on.
#[derive(Clone, Copy, Debug)]
struct Boundary {
    t: f64,
    leaf: usize,
}

/// Sorted, disjoint runs inside a combined solid, their ends with their leaves.
type Runs = SmallVec<[(Boundary, Boundary); 4]>;

/// A CSG tree of closed shapes.
#[derive(Clone, Debug)]
pub struct Csg {
    leaves: Vec<Arc<dyn Shape>>,
    root: Node,
    bounds: Option<(E3, f64)>,
    error: f64,
}

/// Why a CSG tree cannot be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CsgError {
    /// A leaf that bounds no solid.
    #[error(
        "part {0} bounds no solid (CSG takes spheres, boxes, capped cylinders and cones, tori, planes as half-spaces, closed meshes, bodies and CSG trees)"
    )]
    Open(usize),
    /// An operation with fewer than two children, or a leaf index out of range.
    #[error("an operation takes two or more objects")]
    Children,
}

impl Csg {
    /// The tree `root` over `leaves`; every leaf must be [closed](Shape::closed).
    pub fn new(leaves: Vec<Arc<dyn Shape>>, root: Node) -> Result<Self, CsgError> {
        if let Some(open) = leaves.iter().position(|l| !l.closed()) {
            return Err(CsgError::Open(open + 1));
        }
        let bounds = Self::bounds_of(&leaves, &root)?;
        let error = leaves.iter().map(|l| l.crossing_error()).fold(0.0, f64::max);
        Ok(Csg { leaves, root, bounds, error })
    }

    /// The shapes of the leaves, in order.
    pub fn leaves(&self) -> &[Arc<dyn Shape>] {
        &self.leaves
    }

    /// A sphere holding `node`: a union's holds all its children's; an intersection's is its
    /// smallest bounded child's; a difference's is its first child's. `None` if unbounded.
    fn bounds_of(leaves: &[Arc<dyn Shape>], node: &Node) -> Result<Option<(E3, f64)>, CsgError> {
        let children = match node {
            Node::Leaf(i) => return leaves.get(*i).map(|l| l.bounds()).ok_or(CsgError::Children),
            Node::Op(_, children) if children.len() < 2 => return Err(CsgError::Children),
            Node::Op(_, children) => children,
        };
        let bounds: Vec<Option<(E3, f64)>> =
            children.iter().map(|c| Self::bounds_of(leaves, c)).collect::<Result<_, _>>()?;
        Ok(match node {
            Node::Op(Operation::Union, _) => enclosing(&bounds),
            Node::Op(Operation::Intersection, _) => bounds.into_iter().flatten().min_by(|a, b| a.1.total_cmp(&b.1)),
            _ => bounds[0],
        })
    }

    /// The runs of `node` along the ray's line.
    fn runs(&self, node: &Node, ray: &Ray) -> Runs {
        match node {
            Node::Leaf(i) => {
                let at = |t| Boundary { t, leaf: *i };
                self.leaves[*i].spans(ray).into_iter().map(|(a, b)| (at(a), at(b))).collect()
            }
            Node::Op(op, children) => {
                let mut runs = self.runs(&children[0], ray);
                for child in &children[1..] {
                    if runs.is_empty() && *op != Operation::Union {
                        break;
                    }
                    runs = combine(&runs, &self.runs(child, ray), *op);
                }
                runs
            }
        }
    }

    /// The nearest boundary of the whole solid with `t_min < t < t_max` lying on a leaf that
    /// `on` accepts.
    fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64, on: impl Fn(usize) -> bool) -> Option<Boundary> {
        let runs = self.runs(&self.root, ray);
        runs.iter().flat_map(|(a, b)| [*a, *b]).find(|b| on(b.leaf) && in_range(b.t, t_min, t_max))
    }
}

/// The smallest sphere about the centres' mean holding every sphere; `None` if any is
/// unbounded.
pub(super) fn enclosing(bounds: &[Option<(E3, f64)>]) -> Option<(E3, f64)> {
    let spheres: Vec<(E3, f64)> = bounds.iter().copied().collect::<Option<_>>()?;
    let n = spheres.len() as f64;
    let centre = [0, 1, 2].map(|k| spheres.iter().map(|s| s.0[k]).sum::<f64>() / n);
    let radius = spheres.iter().map(|(c, r)| norm(sub(*c, centre)) + r).fold(0.0, f64::max);
    Some((centre, radius))
}

/// The runs of `op` applied to `a` and `b`: their ends merged in order along the line, those
/// at one parameter taken together (a face `a` leaves where `b` enters is no boundary of a
/// union), a boundary where the result's inside changes, on the leaf whose change decided it.
fn combine(a: &Runs, b: &Runs, op: Operation) -> Runs {
    let mut ends: SmallVec<[(Boundary, bool); 16]> = SmallVec::new();
    for (runs, first) in [(a, true), (b, false)] {
        ends.extend(runs.iter().flat_map(|(s, e)| [(*s, first), (*e, first)]));
    }
    ends.sort_by(|x, y| x.0.t.total_cmp(&y.0.t));
    let (mut in_a, mut in_b) = (false, false);
    let (mut out, mut open) = (Runs::new(), None);
    let mut i = 0;
    while i < ends.len() {
        let (before, was) = (op.keeps(in_a, in_b), (in_a, in_b));
        let group = ends[i..].iter().take_while(|e| e.0.t == ends[i].0.t).count();
        for &(_, first) in &ends[i..i + group] {
            if first {
                in_a = !in_a;
            } else {
                in_b = !in_b;
            }
        }
        let after = op.keeps(in_a, in_b);
        if before != after {
            // The leaf whose change alone changes the result, else the group's first.
            let decides = |&&(_, first): &&(Boundary, bool)| {
                let (x, y) = if first { (!was.0, was.1) } else { (was.0, !was.1) };
                op.keeps(x, y) != before
            };
            let here = &ends[i..i + group];
            let boundary = here.iter().find(decides).unwrap_or(&here[0]).0;
            match open.take() {
                Some(start) if !after => out.push((start, boundary)),
                _ => open = Some(boundary),
            }
        }
        i += group;
    }
    out
}

/// One leaf of a CSG tree shown as a scene object: the crossings of the whole solid that lie
/// on it. The scene's nearest over every part is the solid's nearest crossing.
#[derive(Clone, Debug)]
pub struct CsgPart {
    csg: Arc<Csg>,
    leaf: usize,
}

impl CsgPart {
    /// Every leaf of `csg` as a part, in order.
    pub fn parts(csg: Csg) -> Vec<CsgPart> {
        let csg = Arc::new(csg);
        (0..csg.leaves.len()).map(|leaf| CsgPart { csg: csg.clone(), leaf }).collect()
    }

    fn shape(&self) -> &dyn Shape {
        &*self.csg.leaves[self.leaf]
    }
}

impl Shape for CsgPart {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let b = self.csg.nearest(ray, t_min, t_max, |leaf| leaf == self.leaf)?;
        // The boundary's own parameter (in range); the leaf says which piece it lies on.
        let on = self.shape().crossing_on(ray, b.t);
        Some(Crossing { t: b.t, point: ray.at(b.t), ..on })
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        self.shape().normal(ray, crossing)
    }

    fn facet(&self, crossing: &Crossing) -> Option<E3> {
        self.shape().facet(crossing)
    }

    /// The smaller of its leaf's and the whole tree's: its crossings lie on its leaf's
    /// surface and on the tree's, so a ray that misses either meets no part of the tree here.
    fn bounds(&self) -> Option<(E3, f64)> {
        match (self.shape().bounds(), self.csg.bounds) {
            (Some(leaf), Some(tree)) => Some(if leaf.1 < tree.1 { leaf } else { tree }),
            (leaf, tree) => leaf.or(tree),
        }
    }

    /// The largest of its leaves': a crossing is one leaf's own.
    fn crossing_error(&self) -> f64 {
        self.csg.error
    }

    fn cull(&self) -> bool {
        true
    }

    fn closed(&self) -> bool {
        false
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], super::Unit)> {
        self.shape().uv(crossing)
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        self.shape().curvature(crossing)
    }

    fn v_up(&self) -> bool {
        self.shape().v_up()
    }
}

/// A shape cut to a region: its crossings that lie in every one of `region`'s closed shapes
/// (on their surfaces included), the cut left open.
#[derive(Clone, Debug)]
pub struct Clipped {
    shape: Arc<dyn Shape>,
    region: Vec<Arc<dyn Shape>>,
}

impl Clipped {
    /// `shape` cut to the intersection of `region` (closed shapes).
    pub fn new(shape: Arc<dyn Shape>, region: Vec<Arc<dyn Shape>>) -> Result<Self, CsgError> {
        if let Some(open) = region.iter().position(|r| !r.closed()) {
            return Err(CsgError::Open(open + 1));
        }
        Ok(Clipped { shape, region })
    }

    /// The region's spans along the ray's line: the intersection of its shapes'.
    fn region_spans(&self, ray: &Ray) -> Runs {
        let leaf = |t| Boundary { t, leaf: 0 };
        let mut runs: Runs = [(leaf(f64::NEG_INFINITY), leaf(f64::INFINITY))].into_iter().collect();
        for r in &self.region {
            let spans: Runs = r.spans(ray).into_iter().map(|(a, b)| (leaf(a), leaf(b))).collect();
            runs = combine(&runs, &spans, Operation::Intersection);
        }
        runs
    }
}

impl Shape for Clipped {
    /// The shape's crossings in turn from `t_min`, the first inside the region; between
    /// the region's spans the search moves on to the next span.
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let spans = self.region_spans(ray);
        let step = self.shape.crossing_error().max(f64::MIN_POSITIVE);
        let mut t = t_min;
        for _ in 0..MAX_CROSSINGS {
            let (start, end) = spans.iter().find(|(_, e)| e.t > t).map(|(s, e)| (s.t, e.t))?;
            let (from, to) = (t.max(start - step), t_max.min(end + step));
            if from >= to {
                return None;
            }
            t = match self.shape.intersect(ray, from, to) {
                Some(c) if start <= c.t && c.t <= end => return Some(c),
                // Just outside the span: on to the next crossing.
                Some(c) => c.t + step.max(4.0 * f64::EPSILON * c.t.abs()),
                None => end,
            };
        }
        None
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        self.shape.normal(ray, crossing)
    }

    fn facet(&self, crossing: &Crossing) -> Option<E3> {
        self.shape.facet(crossing)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        self.shape.bounds()
    }

    fn crossing_error(&self) -> f64 {
        self.shape.crossing_error()
    }

    fn cull(&self) -> bool {
        true
    }

    fn flat(&self) -> bool {
        self.shape.flat()
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        self.shape.curvature(crossing)
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], super::Unit)> {
        self.shape.uv(crossing)
    }

    fn v_up(&self) -> bool {
        self.shape.v_up()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::testing::{ray, stream};
    use crate::shapes::{BoxShape, PlaneShape, SphereShape};

    /// The nearest crossing of the whole tree: the nearest over its parts, with the part.
    fn nearest(parts: &[CsgPart], r: &Ray, t_min: f64) -> Option<(f64, usize)> {
        let hits = parts.iter().enumerate().filter_map(|(k, p)| p.intersect(r, t_min, f64::INFINITY).map(|c| (c.t, k)));
        hits.min_by(|a, b| a.0.total_cmp(&b.0))
    }

    #[test]
    fn a_face_shared_by_a_union_is_no_boundary() {
        let a: Arc<dyn Shape> = Arc::new(BoxShape::between([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]).unwrap());
        let b: Arc<dyn Shape> = Arc::new(BoxShape::between([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]).unwrap());
        let tree = Node::Op(Operation::Union, vec![Node::Leaf(0), Node::Leaf(1)]);
        let parts = CsgPart::parts(Csg::new(vec![a, b], tree).unwrap());
        let r = ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]);
        assert_eq!(nearest(&parts, &r, 0.0), Some((1.0, 0)));
        // From inside the first box: out through the far face of the second, not at x = 1.
        assert_eq!(nearest(&parts, &r, 1.5), Some((3.0, 1)));
    }

    #[test]
    fn a_difference_shows_the_cutter_s_face_inside() {
        let a: Arc<dyn Shape> = Arc::new(SphereShape::new([0.0; 3], 1.0).unwrap());
        let b: Arc<dyn Shape> = Arc::new(BoxShape::between([-2.0, -2.0, 0.0], [2.0, 0.0, 2.0]).unwrap());
        let tree = Node::Op(Operation::Difference, vec![Node::Leaf(0), Node::Leaf(1)]);
        let parts = CsgPart::parts(Csg::new(vec![a, b], tree).unwrap());
        // Down through the cut quarter: the box's face z = 0 is the surface, on part 1.
        let r = ray([0.0, -0.5, 3.0], [0.0, 0.0, -1.0]);
        let (t, part) = nearest(&parts, &r, 0.0).unwrap();
        assert_eq!(part, 1);
        assert!((t - 3.0).abs() < 1e-12, "{t}");
        // Through the part kept: the sphere.
        let r = ray([0.0, 0.5, 3.0], [0.0, 0.0, -1.0]);
        let (t, part) = nearest(&parts, &r, 0.0).unwrap();
        assert_eq!(part, 0);
        assert!((t - (3.0 - 0.75f64.sqrt())).abs() < 1e-12, "{t}");
    }

    #[test]
    fn open_parts_are_refused() {
        let disk: Arc<dyn Shape> = Arc::new(crate::shapes::DiskShape::new([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap());
        let ball: Arc<dyn Shape> = Arc::new(SphereShape::new([0.0; 3], 1.0).unwrap());
        let tree = Node::Op(Operation::Union, vec![Node::Leaf(0), Node::Leaf(1)]);
        assert_eq!(Csg::new(vec![ball.clone(), disk.clone()], tree).err(), Some(CsgError::Open(2)));
        assert!(Csg::new(vec![ball], Node::Op(Operation::Union, vec![Node::Leaf(0)])).is_err());
        assert!(Clipped::new(disk.clone(), vec![disk]).is_err());
    }

    /// The inside of a tree by point tests, the reference the spans are checked against.
    enum Solid {
        Ball(E3, f64),
        Cube(E3, E3),
        Half(E3, E3),
        Op(Operation, Vec<Solid>),
    }

    impl Solid {
        fn inside(&self, x: E3) -> bool {
            match self {
                Solid::Ball(c, r) => norm(sub(x, *c)) < *r,
                Solid::Cube(lo, hi) => (0..3).all(|k| lo[k] < x[k] && x[k] < hi[k]),
                Solid::Half(p, n) => dot(sub(x, *p), *n) < 0.0,
                Solid::Op(op, children) => {
                    let mut inside = children[0].inside(x);
                    for c in &children[1..] {
                        inside = op.keeps(inside, c.inside(x));
                    }
                    inside
                }
            }
        }

        fn build(&self, leaves: &mut Vec<Arc<dyn Shape>>) -> Node {
            let leaf = |leaves: &mut Vec<Arc<dyn Shape>>, s: Arc<dyn Shape>| {
                leaves.push(s);
                Node::Leaf(leaves.len() - 1)
            };
            match self {
                Solid::Ball(c, r) => leaf(leaves, Arc::new(SphereShape::new(*c, *r).unwrap())),
                Solid::Cube(lo, hi) => leaf(leaves, Arc::new(BoxShape::between(*lo, *hi).unwrap())),
                Solid::Half(p, n) => leaf(leaves, Arc::new(PlaneShape::new(*p, *n).unwrap())),
                Solid::Op(op, children) => Node::Op(*op, children.iter().map(|c| c.build(leaves)).collect()),
            }
        }
    }

    /// Random trees of balls, boxes and half-spaces, two levels deep: the nearest crossing
    /// of the parts is where marching along the ray first finds the inside test change
    /// (bisected to 1e-12), on 2,000 rays aimed near the origin.
    #[test]
    fn crossings_are_where_marching_finds_the_inside_change() {
        let mut random = stream(0x05ee_dc56);
        let mut point = |s: f64| [0, 1, 2].map(|_| s * random());
        let mut checked = 0;
        for tree in 0..40 {
            let mut leaf = |k: usize| match k % 3 {
                0 => Solid::Ball(point(0.8), 0.6 + 0.4 * (point(1.0)[0] + 1.0)),
                1 => {
                    let (c, h) = (point(0.8), point(1.0).map(|x| 0.4 + 0.3 * (x + 1.0)));
                    Solid::Cube([0, 1, 2].map(|i| c[i] - h[i]), [0, 1, 2].map(|i| c[i] + h[i]))
                }
                _ => Solid::Half(point(0.5), point(1.0)),
            };
            let ops = [Operation::Union, Operation::Intersection, Operation::Difference];
            let inner = Solid::Op(ops[(tree / 3) % 3], vec![leaf(tree), leaf(tree + 1)]);
            let solid = Solid::Op(ops[tree % 3], vec![inner, leaf(tree + 2), leaf(tree + 4)]);
            let mut leaves = Vec::new();
            let root = solid.build(&mut leaves);
            let parts = CsgPart::parts(Csg::new(leaves, root).unwrap());
            for _ in 0..50 {
                let o = point(6.0);
                let d = sub(point(0.5), o);
                let r = ray(o, d);
                let got = nearest(&parts, &r, 0.0).map(|h| h.0);
                // March in steps of 1e-3 from the origin to 20 units.
                let inside_at = |t: f64| solid.inside(r.at(t));
                let start = inside_at(0.0);
                let change = (1..20_000).map(|k| k as f64 * 1e-3).find(|&t| inside_at(t) != start);
                let want = change.map(|t| {
                    let (mut lo, mut hi) = (t - 1e-3, t);
                    while hi - lo > 1e-12 {
                        let mid = 0.5 * (lo + hi);
                        if inside_at(mid) == start { lo = mid } else { hi = mid }
                    }
                    hi
                });
                match (got, want) {
                    (Some(g), Some(w)) => assert!((g - w).abs() < 1e-9, "tree {tree}: {g} against {w}"),
                    // A boundary thinner than the march's step may fall between its points.
                    (Some(g), None) => assert!((0..4).any(|k| inside_at(g + k as f64 * 1e-4) != start) || g > 19.9),
                    (None, Some(w)) => panic!("tree {tree}: missed the change at {w}"),
                    (None, None) => {}
                }
                checked += 1;
            }
        }
        assert_eq!(checked, 2000);
    }

    #[test]
    fn a_clip_keeps_the_crossings_in_its_region() {
        let ball: Arc<dyn Shape> = Arc::new(SphereShape::new([0.0; 3], 1.0).unwrap());
        let half: Arc<dyn Shape> = Arc::new(PlaneShape::new([0.0; 3], [0.0, -1.0, 0.0]).unwrap());
        let clipped = Clipped::new(ball, vec![half]).unwrap();
        // Along +y: the front half (y < 0) is cut away, the inside of the back half is seen.
        let c = clipped.intersect(&ray([0.0, -5.0, 0.0], [0.0, 1.0, 0.0]), 0.0, f64::INFINITY).unwrap();
        assert!((c.t - 6.0).abs() < 1e-12, "{}", c.t);
        // A ray through the cut's plane only: nothing.
        assert!(clipped.intersect(&ray([0.0, -5.0, 0.5], [0.0, 1.0, -0.1]), 0.0, 4.0).is_none());
        // Shadow rays read the same crossings.
        assert!(clipped.occludes(&ray([0.0, -5.0, 0.0], [0.0, 1.0, 0.0]), 0.0, f64::INFINITY));
    }
}
