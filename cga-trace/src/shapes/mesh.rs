//! A triangle mesh as one shape: its own hierarchy over its triangles' boxes, their corners
//! kept together in the hierarchy's leaf order, and a crossing test that counts a line through
//! an edge or a corner shared by several triangles exactly once. So a ray meets a mesh at
//! the cost of its hierarchy, and a closed mesh bounds a solid (for CSG, capped clips and
//! glass): parity along a line says where it is inside.
//!
//! The test is the watertight one of Woop, Benthin and Wald (2013): the ray's direction is
//! sheared onto an axis, so each corner becomes a point `(x, y)` of a plane the line pierces
//! at the origin, computed once per corner (the same numbers for every triangle that shares
//! it). The line crosses a triangle where the origin is inside its three edges; an edge
//! `p → q` is the number `E(p, q) = p_x q_y − p_y q_x`, and `E(q, p)` is exactly `−E(p, q)` in
//! floating point, so of two triangles sharing an edge at most one has the origin inside.
//! Where `E = 0` the origin is moved by `(ε, ε²)` (a simulation of simplicity): an edge then
//! holds the origin iff `q_y < p_y`, or `q_y = p_y` and `q_x > p_x` — a rule that gives an
//! edge to exactly one of the two triangles sharing it, and a corner to exactly one of those
//! around it. The count along any line is then even for a closed mesh: a line that grazes
//! an edge or a corner is counted as the moved line is, twice or not at all. (`E(p, q)` is
//! the sheared form of the meet of the ray's line with the edge's line `p ∧ q ∧ n∞`, the
//! pseudoscalar of their outer product: its sign says on which side the one passes the other.)

use super::{Crossing, Shape, Spans, TriangleShape};
use crate::bvh::{Bvh, Wide};
use crate::ray::Ray;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use cga_core::simd::Lane;
use smallvec::SmallVec;
use std::ops::Range;

/// A triangle mesh: its triangles and their corners in its hierarchy's leaf order.
#[derive(Clone, Debug)]
pub struct MeshShape {
    triangles: Vec<TriangleShape>,
    corners: Vec<[E3; 3]>,
    /// The hierarchy: binary for rays four at a time, four-wide for one.
    bvh: Bvh,
    wide: Wide,
    bounds: (E3, f64),
    error: f64,
    closed: bool,
}

// A leaf's triangles fit [`Sheared::open`]'s four lanes.
const _: () = assert!(crate::bvh::LEAF <= 4);

/// The ray sheared onto its longest axis `z`: corners `(x, y, z)` relative to its origin.
struct Sheared {
    origin: E3,
    axes: [usize; 3],
    shear: [f64; 3],
}

impl Sheared {
    fn new(origin: E3, d: E3) -> Self {
        let z = (0..3).max_by(|&a, &b| d[a].abs().total_cmp(&d[b].abs())).unwrap_or(2);
        let (x, y) = ((z + 1) % 3, (z + 2) % 3);
        Sheared { origin, axes: [x, y, z], shear: [d[x] / d[z], d[y] / d[z], 1.0 / d[z]] }
    }

    /// Keeps triangle `k`'s crossing in `best` if it has one in `(t_min, t_max)` nearer than
    /// `best`'s, or as near and `k` is lower: the nearest crossing then does not depend on
    /// the order the triangles are tried in. Returns how far boxes are still worth entering
    /// ([`reach`]).
    #[inline(always)]
    fn keep(&self, corners: &[E3; 3], k: usize, t_min: f64, t_max: f64, best: &mut Option<(f64, u32)>) -> f64 {
        let k = k as u32;
        if let Some(t) = self.cross(corners).filter(|&t| t_min < t && t < t_max)
            && best.is_none_or(|(b, j)| t < b || (t == b && k < j))
        {
            *best = Some((t, k));
        }
        reach(*best, t_max)
    }

    /// Which of a leaf's triangles (at most four) the ray's line can cross: those whose
    /// three edge functions ([`Sheared::cross`]'s `u`, `v`, `w`) are not of both signs, the
    /// four computed side by side with `cross`'s own operations (so the same signs), for the
    /// leaf's triangles to be tried only where they may be crossed.
    #[inline(always)]
    fn open(&self, leaf: &[[E3; 3]]) -> [bool; 4] {
        let Some(last) = leaf.len().checked_sub(1) else { return [false; 4] };
        let [x, y, z] = self.axes;
        let [sx, sy, _] = self.shear;
        let at = |l: usize| &leaf[l.min(last)];
        // Corner j's sheared x and y, lane by lane.
        let corner = |j: usize| {
            let p = |k: usize| -> [f64; 4] { core::array::from_fn(|l| at(l)[j][k] - self.origin[k]) };
            let (px, py, pz) = (p(x), p(y), p(z));
            let sheared = |q: [f64; 4], s: f64| -> [f64; 4] { core::array::from_fn(|l| q[l] - s * pz[l]) };
            (sheared(px, sx), sheared(py, sy))
        };
        let (a, b, c) = (corner(0), corner(1), corner(2));
        let edge = |p: ([f64; 4], [f64; 4]), q: ([f64; 4], [f64; 4])| -> [f64; 4] {
            core::array::from_fn(|l| p.0[l] * q.1[l] - p.1[l] * q.0[l])
        };
        let (u, v, w) = (edge(b, c), edge(c, a), edge(a, b));
        core::array::from_fn(|l| {
            let negative = u[l] < 0.0 || v[l] < 0.0 || w[l] < 0.0;
            let positive = u[l] > 0.0 || v[l] > 0.0 || w[l] > 0.0;
            l < leaf.len() && !(negative && positive)
        })
    }

    /// A corner in the sheared frame: `(p_x − S_x p_z, p_y − S_y p_z, S_z p_z)` for
    /// `p = corner − origin`.
    #[inline(always)]
    fn corner(&self, c: &E3) -> [f64; 3] {
        let [x, y, z] = self.axes;
        let [sx, sy, sz] = self.shear;
        let (px, py, pz) = (c[x] - self.origin[x], c[y] - self.origin[y], c[z] - self.origin[z]);
        [px - sx * pz, py - sy * pz, sz * pz]
    }

    /// The parameter where the line crosses the triangle, if it does (the moved line's
    /// answer where it passes through an edge or a corner).
    #[inline(always)]
    fn cross(&self, corners: &[E3; 3]) -> Option<f64> {
        let (a, b, c) = (self.corner(&corners[0]), self.corner(&corners[1]), self.corner(&corners[2]));
        let edge = |p: [f64; 3], q: [f64; 3]| p[0] * q[1] - p[1] * q[0];
        let (u, v, w) = (edge(b, c), edge(c, a), edge(a, b));
        // Edges of both signs: the origin is outside, whichever way the triangle turns (most
        // triangles a leaf holds end here).
        if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
            return None;
        }
        let det = u + v + w;
        if det == 0.0 {
            return None;
        }
        let ccw = det > 0.0;
        let holds = |e: f64, p: [f64; 3], q: [f64; 3]| {
            let (e, p, q) = if ccw { (e, p, q) } else { (-e, q, p) };
            e > 0.0 || (e == 0.0 && (q[1] < p[1] || (q[1] == p[1] && q[0] > p[0])))
        };
        if !(holds(u, b, c) && holds(v, c, a) && holds(w, a, b)) {
            return None;
        }
        Some((u * a[2] + v * b[2] + w * c[2]) / det)
    }
}

impl MeshShape {
    /// The mesh of these triangles; `closed` where the caller knows that they close a solid
    /// (every edge shared by two, [`crate::import::TriangleMesh::is_closed`]). `None` if there
    /// are none, or more than a `u32` counts.
    pub fn new(triangles: Vec<TriangleShape>, closed: bool) -> Option<Self> {
        if triangles.is_empty() || triangles.len() > u32::MAX as usize {
            return None;
        }
        let boxes: Vec<(E3, E3)> = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.corners;
                ([0, 1, 2].map(|k| a[k].min(b[k]).min(c[k])), [0, 1, 2].map(|k| a[k].max(b[k]).max(c[k])))
            })
            .collect();
        let bvh = Bvh::over_boxes(&boxes);
        let mut slots: Vec<Option<TriangleShape>> = triangles.into_iter().map(Some).collect();
        let triangles: Vec<TriangleShape> =
            bvh.order().iter().map(|&k| slots[k as usize].take().expect("each triangle once")).collect();
        let (lo, hi) = boxes.iter().fold(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]), |(lo, hi), (a, b)| {
            ([0, 1, 2].map(|k| lo[k].min(a[k])), [0, 1, 2].map(|k| hi[k].max(b[k])))
        });
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let radius = triangles.iter().flat_map(|t| t.corners).map(|c| norm(sub(c, centre))).fold(0.0, f64::max);
        let error = triangles.iter().map(|t| t.crossing_error()).fold(0.0, f64::max);
        let corners = triangles.iter().map(|t| t.corners).collect();
        let wide = Wide::new(&bvh);
        Some(MeshShape { bvh, wide, corners, triangles, bounds: (centre, radius), error, closed })
    }

    /// The triangles of `leaf` that the sheared ray's line may cross ([`Sheared::open`]).
    #[inline(always)]
    fn open(&self, sheared: &Sheared, leaf: Range<usize>) -> impl Iterator<Item = usize> {
        let open = sheared.open(&self.corners[leaf.clone()]);
        leaf.zip(open).filter_map(|(k, open)| open.then_some(k))
    }

    /// Its triangles.
    pub fn triangles(&self) -> &[TriangleShape] {
        &self.triangles
    }

    /// Every crossing of the ray's line with `t_min < t < t_max`: `(t, triangle)`, in order.
    fn crossings(&self, ray: &Ray, t_min: f64, t_max: f64) -> SmallVec<[(f64, u32); 8]> {
        let sheared = Sheared::new(ray.origin, ray.dir);
        let mut found: SmallVec<[(f64, u32); 8]> = SmallVec::new();
        self.wide.traverse_leaves(ray.origin, ray.dir, t_min, t_max, |leaf, t_max| {
            for k in self.open(&sheared, leaf) {
                if let Some(t) = sheared.cross(&self.corners[k]).filter(|&t| t_min < t && t < t_max) {
                    found.push((t, k as u32));
                }
            }
            Some(t_max)
        });
        found.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        found
    }

    /// The nearest crossing with `t_min < t < t_max` of the ray from `origin` along unit
    /// `dir` ([`Shape::intersect`], without the ray's line): leaves in the order the ray
    /// enters their boxes, each triangle's crossing kept where it is nearer than the nearest
    /// yet.
    pub fn nearest(&self, origin: E3, dir: E3, t_min: f64, t_max: f64) -> Option<Crossing> {
        let sheared = Sheared::new(origin, dir);
        let mut best = None;
        self.wide.traverse_leaves(origin, dir, t_min, t_max, |leaf, mut limit| {
            for k in self.open(&sheared, leaf) {
                limit = sheared.keep(&self.corners[k], k, t_min, t_max, &mut best);
            }
            Some(limit)
        });
        best.map(|c| crossing_at(origin, dir, c))
    }

    /// Whether the ray from `origin` along unit `dir` crosses the mesh with
    /// `t_min < t < t_max` ([`Shape::occludes`]): stops at the first crossing found.
    pub fn blocks(&self, origin: E3, dir: E3, t_min: f64, t_max: f64) -> bool {
        let sheared = Sheared::new(origin, dir);
        let crossed = |k: usize| sheared.cross(&self.corners[k]).is_some_and(|t| t_min < t && t < t_max);
        self.wide
            .traverse_leaves(origin, dir, t_min, t_max, |leaf, limit| {
                (!self.open(&sheared, leaf).any(crossed)).then_some(limit)
            })
            .is_none()
    }

    /// Each of four rays' nearest crossing with `t_min < t < t_max` (a lane with
    /// `t_max = −∞` finds none), the four through the hierarchy together in lanes `L`: the
    /// crossings [`Shape::intersect`] finds for each.
    #[inline(always)]
    pub fn intersect4<L: Lane>(
        &self,
        rays: [(E3, E3); 4],
        t_min: &[f64; 4],
        t_max: &[f64; 4],
    ) -> [Option<Crossing>; 4] {
        let sheared = rays.map(|(o, d)| Sheared::new(o, d));
        let mut best = [None; 4];
        let mut limit = *t_max;
        let (origin, dir) = lanes::<L>(&rays);
        self.bvh.traverse_leaves4(&origin, &dir, *t_min, &mut limit, |leaf, lanes, limit| {
            for l in (0..4).filter(|&l| lanes[l]) {
                for k in leaf.clone() {
                    limit[l] = sheared[l].keep(&self.corners[k], k, t_min[l], t_max[l], &mut best[l]);
                }
            }
            Some(())
        });
        core::array::from_fn(|l| best[l].map(|c| crossing_at(rays[l].0, rays[l].1, c)))
    }

    /// Whether each of four rays crosses the mesh with `t_min < t < t_max` (a lane with
    /// `t_max = −∞` is never blocked), the four through the hierarchy together in lanes `L`:
    /// what [`Shape::occludes`] answers for each.
    #[inline(always)]
    pub fn occludes4<L: Lane>(&self, rays: [(E3, E3); 4], t_min: &[f64; 4], t_max: &[f64; 4]) -> [bool; 4] {
        let sheared = rays.map(|(o, d)| Sheared::new(o, d));
        let mut blocked = [false; 4];
        let mut limit = *t_max;
        let (origin, dir) = lanes::<L>(&rays);
        self.bvh.traverse_leaves4(&origin, &dir, *t_min, &mut limit, |leaf, lanes, limit| {
            for l in (0..4).filter(|&l| lanes[l]) {
                let crossed =
                    |k: usize| sheared[l].cross(&self.corners[k]).is_some_and(|t| t_min[l] < t && t < t_max[l]);
                if leaf.clone().any(crossed) {
                    (blocked[l], limit[l]) = (true, f64::NEG_INFINITY);
                }
            }
            limit.iter().any(|&t| t > f64::NEG_INFINITY).then_some(())
        });
        blocked
    }

    /// The triangle a crossing lies on.
    fn triangle(&self, c: &Crossing) -> &TriangleShape {
        &self.triangles[(c.part as usize).min(self.triangles.len() - 1)]
    }
}

/// How far past the nearest crossing yet, `b`, boxes are still entered (within `t_max`):
/// `b (1 + 64 ε)`, since a box's entry computed by the slab test may round a few ulps past a
/// crossing inside it that the triangle test puts at `b`, and a tie there (coincident faces)
/// goes to the lower index, whichever box is reached first.
#[inline(always)]
fn reach(best: Option<(f64, u32)>, t_max: f64) -> f64 {
    best.map_or(t_max, |(b, _)| (b + 64.0 * f64::EPSILON * b.abs()).min(t_max))
}

/// The rays' origins and directions in lanes.
#[inline(always)]
fn lanes<L: Lane>(rays: &[(E3, E3); 4]) -> (E3<L>, E3<L>) {
    let origin = core::array::from_fn(|k| L::from_fn(|l| rays[l].0[k]));
    (origin, core::array::from_fn(|k| L::from_fn(|l| rays[l].1[k])))
}

/// Triangle `k`'s crossing at `t` of the ray from `origin` along `dir` (its point as
/// [`Ray::at`] computes it).
fn crossing_at(origin: E3, dir: E3, (t, k): (f64, u32)) -> Crossing {
    Crossing { t, point: add(origin, scale(dir, t)), alpha: None, part: k }
}

impl Shape for MeshShape {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        self.nearest(ray.origin, ray.dir, t_min, t_max)
    }

    fn occludes(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.blocks(ray.origin, ray.dir, t_min, t_max)
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        self.triangle(crossing).normal(ray, crossing)
    }

    fn facet(&self, crossing: &Crossing) -> Option<E3> {
        self.triangle(crossing).facet(crossing)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some(self.bounds)
    }

    /// The largest of its triangles'.
    fn crossing_error(&self) -> f64 {
        self.error
    }

    fn cull(&self) -> bool {
        true
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], super::Unit)> {
        self.triangle(crossing).uv(crossing)
    }

    fn closed(&self) -> bool {
        self.closed
    }

    /// Its crossings along the whole line, paired in turn from outside. An odd count (only
    /// where rounding breaks the edge rule's premise, a corner's sheared place) drops the
    /// crossing whose triangle the line runs most nearly along.
    fn spans(&self, ray: &Ray) -> Spans {
        let mut found = self.crossings(ray, f64::NEG_INFINITY, f64::INFINITY);
        if found.len() % 2 == 1 {
            let grazing = |c: &(f64, u32)| dot(self.triangles[c.1 as usize].normal, ray.dir).abs();
            let touch = (0..found.len()).min_by(|&a, &b| grazing(&found[a]).total_cmp(&grazing(&found[b])));
            found.remove(touch.unwrap_or(0));
        }
        found.chunks_exact(2).map(|p| (p[0].0, p[1].0)).collect()
    }

    /// The crossing at exactly `t` (spans' ends are crossings' own parameters), else the
    /// nearest.
    fn crossing_on(&self, ray: &Ray, t: f64) -> Crossing {
        let reach = 4.0 * self.error + 4.0 * f64::EPSILON * t.abs();
        let found = self.crossings(ray, t - reach, t + reach);
        let nearest = found.iter().min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs()));
        nearest.map_or(Crossing { t, point: ray.at(t), alpha: None, part: 0 }, |&c| crossing_at(ray.origin, ray.dir, c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::testing::{ray, stream};
    use cga_core::simd::F64x4;

    /// Triangles over `corners`, every `flip`-th one wound the other way (CSG does not need
    /// the mesh oriented).
    fn mesh(corners: &[E3], faces: &[[usize; 3]], flip: usize) -> MeshShape {
        let triangle = |(k, f): (usize, &[usize; 3])| {
            let [a, b, c] = f.map(|i| corners[i]);
            TriangleShape::new(if flip > 0 && k % flip == 0 { [a, c, b] } else { [a, b, c] }).unwrap()
        };
        MeshShape::new(faces.iter().enumerate().map(triangle).collect(), true).unwrap()
    }

    /// The cube [−1, 1]³, each face cut into `n × n` squares of two triangles, its corners
    /// on a grid of exact binary fractions.
    fn cube(n: usize, flip: usize) -> MeshShape {
        let mut corners = Vec::new();
        let mut index = std::collections::HashMap::new();
        let mut at = |p: [i64; 3]| {
            *index.entry(p).or_insert_with(|| {
                corners.push(p.map(|x| -1.0 + 2.0 * x as f64 / n as f64));
                corners.len() - 1
            })
        };
        let mut faces = Vec::new();
        let n = n as i64;
        for axis in 0..3 {
            for side in [0, n] {
                for i in 0..n {
                    for j in 0..n {
                        let p = |a: i64, b: i64| {
                            let mut p = [0; 3];
                            p[axis] = side;
                            p[(axis + 1) % 3] = a;
                            p[(axis + 2) % 3] = b;
                            p
                        };
                        let q = [p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)].map(&mut at);
                        faces.push([q[0], q[1], q[2]]);
                        faces.push([q[0], q[2], q[3]]);
                    }
                }
            }
        }
        mesh(&corners, &faces, flip)
    }

    /// A torus about z (radii 2 and 0.7) as an `m × n` grid of quads, closed around both ways.
    fn torus(m: usize, n: usize, flip: usize) -> MeshShape {
        let corner = |i: usize, j: usize| {
            let (u, v) = (std::f64::consts::TAU * i as f64 / m as f64, std::f64::consts::TAU * j as f64 / n as f64);
            let r = 2.0 + 0.7 * v.cos();
            [r * u.cos(), r * u.sin(), 0.7 * v.sin()]
        };
        let corners: Vec<E3> = (0..m).flat_map(|i| (0..n).map(move |j| corner(i, j))).collect();
        let at = |i: usize, j: usize| (i % m) * n + j % n;
        let faces: Vec<[usize; 3]> = (0..m)
            .flat_map(|i| {
                (0..n).flat_map(move |j| {
                    [[at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]]
                })
            })
            .collect();
        mesh(&corners, &faces, flip)
    }

    /// Lines along the grid's lines and through its corners, where two, four or six
    /// triangles meet: each crossing counted once, the spans the cube's, orientation or not.
    #[test]
    fn lines_through_edges_and_corners_cross_once() {
        for flip in [0, 3] {
            let cube = cube(4, flip);
            for i in 0..=4 {
                for j in 0..=4 {
                    let (x, y) = (-1.0 + 0.5 * i as f64, -1.0 + 0.5 * j as f64);
                    let spans = cube.spans(&ray([x, y, -3.0], [0.0, 0.0, 1.0]));
                    if i == 0 || i == 4 || j == 0 || j == 4 {
                        // Along a face: the line moved off it is in or out, a span or none.
                        assert!(spans.len() <= 1 && spans.iter().all(|s| *s == (2.0, 4.0)), "{x} {y}: {spans:?}");
                    } else {
                        assert_eq!(&spans[..], &[(2.0, 4.0)], "{x} {y}");
                    }
                    // Tilted through the same grid corner on the bottom face.
                    let spans = cube.spans(&ray([x - 1.0, y - 0.5, -2.0], [1.0, 0.5, 1.0]));
                    assert!(spans.len() <= 1, "{spans:?}");
                }
            }
            // The long diagonal, through two of the cube's corners.
            let spans = cube.spans(&ray([-2.0; 3], [1.0; 3]));
            assert_eq!(spans.len(), 1);
            let s3 = 3f64.sqrt();
            assert!((spans[0].0 - s3).abs() < 1e-15 && (spans[0].1 - 3.0 * s3).abs() < 1e-14, "{spans:?}");
        }
    }

    /// On 2,000 random lines through a torus mesh (a third of its triangles wound the
    /// other way): an even count of crossings, and the middle of every span inside and of
    /// every gap between spans outside by an independent test, the parity of the plain
    /// triangle test's crossings along another direction; `intersect` is the first span end
    /// past its `t_min`.
    #[test]
    fn spans_hold_the_inside_of_a_torus_mesh() {
        let torus = torus(24, 12, 3);
        let mut random = stream(0x7025_1a3b);
        let mut point = |s: f64| [0, 1, 2].map(|_| s * random());
        let inside = |x: E3, d: E3| {
            let r = ray(x, d);
            torus.triangles.iter().filter(|t| t.intersect(&r, 0.0, f64::INFINITY).is_some()).count() % 2 == 1
        };
        let mut spans_seen = 0;
        for _ in 0..2_000 {
            let o = point(6.0);
            let r = ray(o, sub(point(2.5), o));
            let spans = torus.spans(&r);
            let ends: Vec<f64> = spans.iter().flat_map(|s| [s.0, s.1]).collect();
            assert!(ends.windows(2).all(|w| w[0] <= w[1]), "{spans:?}");
            let probe = point(1.0);
            for (k, w) in ends.windows(2).enumerate() {
                if w[1] - w[0] > 1e-6 {
                    assert_eq!(inside(r.at(0.5 * (w[0] + w[1])), probe), k % 2 == 0, "{spans:?}");
                }
            }
            if let Some(&first) = ends.iter().find(|&&t| t > 0.5) {
                let got = torus.intersect(&r, 0.5, f64::INFINITY).map(|c| c.t);
                assert_eq!(got, Some(first));
            }
            spans_seen += spans.len();
        }
        assert!(spans_seen > 1_000, "{spans_seen}");
    }

    /// On 3,000 random rays at an open mesh (a torus's outer half), from outside and from
    /// inside its hull: the nearest crossing is the least `t` over all triangles (ties to the
    /// lower index), found through the hierarchy; four rays at a time give the same bits in
    /// every lane, with lanes left out (`t_max = −∞`) finding nothing; and shadow tests agree.
    #[test]
    fn the_nearest_crossing_is_every_triangles_least_one_at_a_time_or_four() {
        let closed = torus(32, 16, 0);
        let open: Vec<TriangleShape> =
            closed.triangles.iter().filter(|t| t.corners.iter().all(|c| c[0] > -0.5)).cloned().collect();
        let n = open.len();
        let mesh = MeshShape::new(open, false).unwrap();
        assert!(!mesh.closed() && mesh.triangles().len() == n);
        let mut random = stream(0x51ab_77c3);
        let mut point = |s: f64| [0, 1, 2].map(|_| s * random());
        let mut hits = 0;
        for round in 0..750 {
            let rays: [Ray; 4] = core::array::from_fn(|_| {
                let o = point(if round % 2 == 0 { 6.0 } else { 1.5 });
                ray(o, sub(point(2.5), o))
            });
            let t_min = [1e-9, 0.5, 1e-9, 1.0];
            let t_max = [f64::INFINITY, 8.0, f64::NEG_INFINITY, f64::INFINITY];
            let one: [Option<Crossing>; 4] = core::array::from_fn(|l| mesh.intersect(&rays[l], t_min[l], t_max[l]));
            for l in 0..4 {
                // Every triangle tried in turn.
                let sheared = Sheared::new(rays[l].origin, rays[l].dir);
                let all = (0..n).filter_map(|k| sheared.cross(&mesh.corners[k]).map(|t| (t, k as u32)));
                let least = all
                    .filter(|&(t, _)| t_min[l] < t && t < t_max[l])
                    .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
                assert_eq!(one[l].map(|c| (c.t, c.part)), least, "round {round} lane {l}");
                hits += usize::from(least.is_some());
            }
            let rays4 = rays.each_ref().map(|r| (r.origin, r.dir));
            assert_eq!(mesh.intersect4::<F64x4>(rays4, &t_min, &t_max), one, "round {round}");
            let blocked: [bool; 4] = core::array::from_fn(|l| mesh.occludes(&rays[l], t_min[l], t_max[l]));
            assert_eq!(blocked, one.map(|c| c.is_some()));
            assert_eq!(mesh.occludes4::<F64x4>(rays4, &t_min, &t_max), blocked, "round {round}");
        }
        assert!(hits > 600, "{hits} hits");
    }

    /// A ray along an axis, through the edges of a grid-cut cube, with the other components
    /// `+0` or `−0` (`1/d = ±∞`; its origin in the plane of a box's faces, `0 · ∞`): the
    /// same crossing either way, one ray or four, and the spans of a line from inside.
    #[test]
    fn signed_zero_directions_meet_what_positive_zeros_do() {
        let cube = cube(4, 0);
        for x in [-0.5, 0.0, 0.5] {
            for y in [0.3, -0.3] {
                let o = [x, y, -3.0];
                let want = cube.nearest(o, [0.0, 0.0, 1.0], 1e-9, f64::INFINITY).map(|c| (c.t, c.part));
                assert_eq!(want.map(|c| c.0), Some(2.0), "{o:?}");
                for d in [[-0.0, 0.0, 1.0], [0.0, -0.0, 1.0], [-0.0, -0.0, 1.0]] {
                    let one = cube.nearest(o, d, 1e-9, f64::INFINITY).map(|c| (c.t, c.part));
                    assert_eq!(one, want, "{o:?} {d:?}");
                    assert!(cube.blocks(o, d, 1e-9, f64::INFINITY), "{o:?} {d:?}");
                    let four = cube.intersect4::<F64x4>([(o, d); 4], &[1e-9; 4], &[f64::INFINITY; 4]);
                    assert_eq!(four[3].map(|c| (c.t, c.part)), want, "{o:?} {d:?}");
                }
                // From inside, through the grid's lines.
                let spans = cube.spans(&ray([x, y, 0.0], [0.0, 0.0, 1.0]));
                assert_eq!(&spans[..], &[(-1.0, 1.0)], "{x} {y}");
            }
        }
    }

    /// Eight copies of one triangle (coincident faces, two leaves): of 20,000 rays, those that
    /// cross all eight at one `t` keep the same one alone and four together.
    #[test]
    fn coincident_faces_go_to_the_same_triangle_one_ray_or_four() {
        let copies = (0..8).map(|_| TriangleShape::new([[-1.0, -1.0, 0.3], [1.1, -0.9, 0.3], [0.1, 1.3, 0.3]]));
        let mesh = MeshShape::new(copies.collect::<Result<_, _>>().unwrap(), false).unwrap();
        let mut random = stream(0x1234_5678);
        let mut hits = 0;
        for _ in 0..5_000 {
            let rays: [(E3, E3); 4] = core::array::from_fn(|_| {
                let o = [0.2 * random(), 0.2 * random(), 2.0 + random()];
                (o, cga_core::euclid::unit([0.3 * random(), 0.3 * random(), -1.0]).unwrap())
            });
            let four = mesh.intersect4::<F64x4>(rays, &[1e-9; 4], &[f64::INFINITY; 4]);
            for (l, (o, d)) in rays.into_iter().enumerate() {
                let one = mesh.nearest(o, d, 1e-9, f64::INFINITY);
                assert_eq!(four[l], one, "{o:?} {d:?}");
                hits += usize::from(one.is_some());
            }
        }
        assert!(hits > 15_000, "{hits} hits");
    }

    /// The crossing at a span's end names the triangle it lies on, whose normal it takes.
    #[test]
    fn a_crossing_names_its_triangle() {
        let cube = cube(2, 0);
        let r = ray([0.3, -0.2, -3.0], [0.0, 0.0, 1.0]);
        let c = cube.crossing_on(&r, 2.0);
        assert_eq!(c.t, 2.0);
        let t = &cube.triangles()[c.part as usize];
        assert!(t.corners.iter().all(|p| p[2] == -1.0), "{t:?}");
        assert_eq!(cube.normal(&r, &c), [0.0, 0.0, -1.0]);
    }
}
