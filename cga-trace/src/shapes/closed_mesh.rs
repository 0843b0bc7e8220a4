//! A closed triangle mesh as one solid, for CSG and capped clips: its own hierarchy over its
//! triangles, and a crossing test that counts a line through an edge or a corner shared by
//! several triangles exactly once, so that parity along the line says where it is inside.
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
//! an edge or a corner is counted as the moved line is, twice or not at all.

use super::{Crossing, Shape, Spans, TriangleShape};
use crate::bvh::Bvh;
use crate::ray::Ray;
use cga_core::euclid::{E3, dot, norm, sub};
use smallvec::SmallVec;

/// A closed mesh: triangles whose every edge two of them share.
#[derive(Clone, Debug)]
pub struct ClosedMesh {
    triangles: Vec<TriangleShape>,
    bvh: Bvh,
    bounds: (E3, f64),
    error: f64,
}

/// The ray sheared onto its longest axis `z`: corners `(x, y, z)` relative to its origin.
struct Sheared {
    origin: E3,
    axes: [usize; 3],
    shear: [f64; 3],
}

impl Sheared {
    fn new(ray: &Ray) -> Self {
        let d = ray.dir;
        let z = (0..3).max_by(|&a, &b| d[a].abs().total_cmp(&d[b].abs())).unwrap_or(2);
        let (x, y) = ((z + 1) % 3, (z + 2) % 3);
        Sheared { origin: ray.origin, axes: [x, y, z], shear: [d[x] / d[z], d[y] / d[z], 1.0 / d[z]] }
    }

    /// A corner in the sheared frame: `(p_x − S_x p_z, p_y − S_y p_z, S_z p_z)` for
    /// `p = corner − origin`.
    fn corner(&self, c: E3) -> [f64; 3] {
        let p = sub(c, self.origin);
        let [x, y, z] = self.axes;
        let [sx, sy, sz] = self.shear;
        [p[x] - sx * p[z], p[y] - sy * p[z], sz * p[z]]
    }

    /// The parameter where the line crosses the triangle, if it does (the moved line's
    /// answer where it passes through an edge or a corner).
    fn cross(&self, corners: &[E3; 3]) -> Option<f64> {
        let [a, b, c] = corners.map(|k| self.corner(k));
        let edge = |p: [f64; 3], q: [f64; 3]| p[0] * q[1] - p[1] * q[0];
        let (u, v, w) = (edge(b, c), edge(c, a), edge(a, b));
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

impl ClosedMesh {
    /// The solid the triangles bound; the caller knows that they close one (every edge
    /// shared by two, [`crate::import::TriangleMesh::is_closed`]). `None` if there are none.
    pub fn new(triangles: Vec<TriangleShape>) -> Option<Self> {
        if triangles.is_empty() || triangles.len() > u32::MAX as usize {
            return None;
        }
        let spheres: Vec<Option<(E3, f64)>> = triangles.iter().map(|t| t.bounds()).collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for c in triangles.iter().flat_map(|t| t.corners) {
            for k in 0..3 {
                lo[k] = lo[k].min(c[k]);
                hi[k] = hi[k].max(c[k]);
            }
        }
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let radius = triangles.iter().flat_map(|t| t.corners).map(|c| norm(sub(c, centre))).fold(0.0, f64::max);
        let error = triangles.iter().map(|t| t.crossing_error()).fold(0.0, f64::max);
        Some(ClosedMesh { bvh: Bvh::new(&spheres), triangles, bounds: (centre, radius), error })
    }

    /// Its triangles.
    pub fn triangles(&self) -> &[TriangleShape] {
        &self.triangles
    }

    /// Every crossing of the ray's line with `t_min < t < t_max`: `(t, triangle)`, in order.
    fn crossings(&self, ray: &Ray, t_min: f64, t_max: f64) -> SmallVec<[(f64, u32); 8]> {
        let sheared = Sheared::new(ray);
        let mut found: SmallVec<[(f64, u32); 8]> = SmallVec::new();
        self.bvh.traverse(ray.origin, ray.dir, t_min, t_max, |k, t_max| {
            if let Some(t) = sheared.cross(&self.triangles[k].corners).filter(|&t| t_min < t && t < t_max) {
                found.push((t, k as u32));
            }
            Some(t_max)
        });
        found.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        found
    }

    /// The triangle's crossing at `t`.
    fn crossing(&self, ray: &Ray, (t, k): (f64, u32)) -> Crossing {
        Crossing { t, point: ray.at(t), alpha: None, part: k }
    }

    /// The triangle a crossing lies on.
    fn triangle(&self, c: &Crossing) -> &TriangleShape {
        &self.triangles[(c.part as usize).min(self.triangles.len() - 1)]
    }
}

impl Shape for ClosedMesh {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let sheared = Sheared::new(ray);
        let mut best = None;
        self.bvh.traverse(ray.origin, ray.dir, t_min, t_max, |k, limit| {
            match sheared.cross(&self.triangles[k].corners).filter(|&t| t_min < t && t < limit) {
                Some(t) => {
                    best = Some((t, k as u32));
                    Some(t)
                }
                None => Some(limit),
            }
        });
        best.map(|b| self.crossing(ray, b))
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
        true
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
        nearest.map_or(Crossing { t, point: ray.at(t), alpha: None, part: 0 }, |&c| self.crossing(ray, c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::testing::{ray, stream};

    /// Triangles over `corners`, every `flip`-th one wound the other way (CSG does not need
    /// the mesh oriented).
    fn mesh(corners: &[E3], faces: &[[usize; 3]], flip: usize) -> ClosedMesh {
        let triangle = |(k, f): (usize, &[usize; 3])| {
            let [a, b, c] = f.map(|i| corners[i]);
            TriangleShape::new(if flip > 0 && k % flip == 0 { [a, c, b] } else { [a, b, c] }).unwrap()
        };
        ClosedMesh::new(faces.iter().enumerate().map(triangle).collect()).unwrap()
    }

    /// The cube [−1, 1]³, each face cut into `n × n` squares of two triangles, its corners
    /// on a grid of exact binary fractions.
    fn cube(n: usize, flip: usize) -> ClosedMesh {
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
    fn torus(m: usize, n: usize, flip: usize) -> ClosedMesh {
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
