//! Patches of a spline surface: a box around each piece of a segment's cell cut out by an
//! angle around its circles, all of them in one four-wide tree. A ray opens the nearer boxes
//! first and solves a cell when it first enters one of its patches; once a crossing is found,
//! the boxes beyond it are never opened. A cell's sphere holds its whole ring, so a ray that
//! crossed the front of the surface used to solve the cells behind it too; a patch's box holds
//! an eighth of it.
//!
//! A patch over `α ∈ [a₀, a₁]` and `θ ∈ [θ₀, θ₁]` is the points
//! `X(α, θ) = c(α) + r(α)(cos θ u(α) + sin θ v(α))`, where `(u, v)` is the middle circle's
//! in-plane frame projected onto each circle's plane (continuous over the cell; a cell whose
//! circles turn by more than [`TURN`] against the middle one is one patch all round). Its box
//! holds the points sampled on a grid, padded by what linear interpolation between grid points
//! can miss: `Δα²/8 max|X_αα| + Δθ²/8 max|X_θθ|` (`|X_θθ| = r`, `|X_αα|` from second differences
//! of the samples, doubled as the cells' bounds are), plus rounding.

use super::SurfaceError;
use crate::bvh::{Bvh, Wide};
use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use smallvec::SmallVec;

/// Patches around each cell's circles, and along α.
pub const SECTORS: usize = 16;
pub const PIECES: usize = 4;
/// Samples of α per piece, of the angle per sector (intervals).
const ALPHA_STEPS: usize = 8;
const ANGLE_STEPS: usize = 4;
/// The least `|n(α)·n_mid|` over a cell for the middle circle's frame to serve it (60°).
pub const TURN: f64 = 0.5;

/// A circle: centre, unit normal, radius.
type Circle3 = (E3, E3, f64);

/// The patches of a surface of `segments` segments, `cells` cells each, in one tree.
#[derive(Clone, Debug)]
pub struct Patches {
    wide: Wide,
    /// For each item in the tree's leaf order, its cell: `segment · cells + cell`.
    order: Vec<u32>,
    cells: usize,
    segments: usize,
}

impl Patches {
    /// The patches over `segments` segments of `cells` cells each, where `at(j, α)` is segment
    /// `j`'s circle at `α ∈ [0, 1]`.
    pub fn new(
        segments: usize,
        cells: usize,
        at: impl Fn(usize, f64) -> Result<Circle3, SurfaceError>,
    ) -> Result<Self, SurfaceError> {
        let mut boxes = Vec::with_capacity(segments * cells * SECTORS);
        let mut owner = Vec::with_capacity(boxes.capacity());
        for j in 0..segments {
            for i in 0..cells {
                let (lo, hi) = (i as f64 / cells as f64, (i + 1) as f64 / cells as f64);
                let steps = ALPHA_STEPS * PIECES;
                let circles = (0..=steps)
                    .map(|s| at(j, lo + (hi - lo) * s as f64 / steps as f64))
                    .collect::<Result<Vec<_>, _>>()?;
                for b in cell_boxes(&circles) {
                    boxes.push(b);
                    owner.push((j * cells + i) as u32);
                }
            }
        }
        let bvh = Bvh::over_boxes(&boxes);
        let order = bvh.order().iter().map(|&k| owner[k as usize]).collect();
        Ok(Patches { wide: Wide::new(&bvh), order, cells, segments })
    }

    /// Calls `solve(segment, cell, t_max)` once for every cell the ray can cross within
    /// `(t_min, t_max)`, nearer patches first: `solve` returns the new `t_max` (a crossing
    /// found) or `None` to stop at once. Returns the last `t_max`, or `None` if stopped.
    pub fn visit(
        &self,
        (origin, dir): (E3, E3),
        t_min: f64,
        t_max: f64,
        mut solve: impl FnMut(usize, usize, f64) -> Option<f64>,
    ) -> Option<f64> {
        let mut solved: SmallVec<[u64; 8]> = SmallVec::from_elem(0, (self.segments * self.cells).div_ceil(64));
        self.wide.traverse_leaves(origin, dir, t_min, t_max, |range, mut t_max| {
            for &key in &self.order[range] {
                let (word, bit) = (key as usize / 64, 1u64 << (key % 64));
                if solved[word] & bit == 0 {
                    solved[word] |= bit;
                    let key = key as usize;
                    t_max = solve(key / self.cells, key % self.cells, t_max)?;
                }
            }
            Some(t_max)
        })
    }
}

/// The boxes `(min, max)` of one cell's patches, from its circles sampled at equal steps of α.
fn cell_boxes(circles: &[Circle3]) -> Vec<(E3, E3)> {
    let mid = circles[circles.len() / 2];
    let turned = circles.iter().any(|c| dot(c.1, mid.1).abs() < TURN);
    let sectors = if turned { 1 } else { SECTORS };
    // Each circle's in-plane frame: the middle one's `u` projected onto its plane.
    let u_mid = cga_core::euclid::perpendicular(mid.1);
    let frames: Vec<(E3, E3)> = circles
        .iter()
        .map(|&(_, n, _)| {
            let u = unit(sub(u_mid, scale(n, dot(u_mid, n)))).unwrap_or(u_mid);
            (u, cross(n, u))
        })
        .collect();
    let point = |a: usize, theta: f64| {
        let ((c, _, r), (u, v)) = (circles[a], frames[a]);
        add(c, scale(add(scale(u, theta.cos()), scale(v, theta.sin())), r))
    };
    let r_max = circles.iter().fold(0.0f64, |m, c| m.max(c.2));
    let size = circles.iter().fold(0.0f64, |m, c| m.max(norm(c.0) + c.2));
    (0..sectors * PIECES)
        .map(|patch| {
            let (s, piece) = (patch % sectors, patch / sectors);
            let rows = piece * ALPHA_STEPS..=(piece + 1) * ALPHA_STEPS;
            let width = std::f64::consts::TAU / sectors as f64;
            let steps = ANGLE_STEPS * if turned { SECTORS } else { 1 };
            let angle = |k: usize| width * (s as f64 + k as f64 / steps as f64);
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            let mut bend = 0.0f64;
            for k in 0..=steps {
                let theta = angle(k);
                let column: Vec<E3> = rows.clone().map(|a| point(a, theta)).collect();
                for x in &column {
                    for axis in 0..3 {
                        lo[axis] = lo[axis].min(x[axis]);
                        hi[axis] = hi[axis].max(x[axis]);
                    }
                }
                for w in column.windows(3) {
                    bend = bend.max(norm(add(sub(w[0], scale(w[1], 2.0)), w[2])));
                }
            }
            // Δα²/8 · 2 max|X_αα| with |X_αα| ≈ |second difference| / Δα²; Δθ²/8 · r.
            let step = width / steps as f64;
            let pad = bend / 4.0 + step * step / 8.0 * r_max + 1e-12 * size;
            (lo.map(|x| x - pad), hi.map(|x| x + pad))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hash::stream;
    use crate::ray::Ray;
    use crate::surface::family::Circles;
    use crate::surface::{BezierSegment, TwoCircles};
    use cga_core::{Circle, Pair};

    /// A twisted cubic segment and a two-circle family: every ray through a point of `C_α`, at
    /// any angle and from any direction (the circle's plane included), has that point's cell
    /// solved, and no cell is solved twice.
    #[test]
    fn every_ray_through_a_circle_solves_its_cell() {
        let circle = |c: E3, n: E3, r: f64| Circle::from_centre_normal_radius(c, unit(n).unwrap(), r).unwrap();
        let cubic = BezierSegment::new(&[
            circle([0.0; 3], [0.0, 0.0, 1.0], 1.0),
            circle([0.5, 0.2, 1.0], [0.3, 0.1, 1.0], 0.7),
            circle([0.2, 0.9, 1.8], [1.0, 0.4, 0.3], 0.9),
            circle([-0.4, 1.2, 2.5], [0.2, 1.0, 0.1], 0.5),
        ]);
        let pair = TwoCircles::new(
            Pair::new(circle([3.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0), circle([3.3, 0.0, 1.5], [1.0, 0.2, 0.3], 0.6))
                .unwrap(),
        );
        let at = |j: usize, alpha: f64| -> Result<Circle3, SurfaceError> {
            let c = if j == 0 { cubic.at(alpha) } else { pair.at(alpha) }.unwrap();
            Ok(c.centre_normal_radius().unwrap())
        };
        let cells = 16;
        let patches = Patches::new(2, cells, at).unwrap();
        let mut next = stream(11);
        let mut solved_total = 0;
        for k in 0..20_000 {
            let (j, alpha, angle) = (k % 2, next(), next() * std::f64::consts::TAU);
            let (c, n, r) = at(j, alpha).unwrap();
            let u = cga_core::euclid::perpendicular(n);
            let x = add(c, scale(add(scale(u, angle.cos()), scale(cross(n, u), angle.sin())), r));
            let random = unit([next() - 0.5, next() - 0.5, next() - 0.5]).unwrap();
            let dir = if k % 4 == 1 { unit(sub(random, scale(n, dot(random, n)))).unwrap() } else { random };
            // From 3 units away, and from 0.1 (with few cells on the way).
            let back = if k % 3 == 0 { 0.1 } else { 3.0 };
            let ray = Ray::new(sub(x, scale(dir, back)), dir).unwrap();
            let cell = ((alpha * cells as f64) as usize).min(cells - 1);
            let mut seen = Vec::new();
            patches.visit((ray.origin, ray.dir), 0.0, back + 1e-9, |s, i, t_max| {
                seen.push((s, i));
                Some(t_max)
            });
            assert!(seen.contains(&(j, cell)), "segment {j}, α = {alpha}, angle {angle}: {seen:?}");
            let mut unique = seen.clone();
            unique.sort();
            unique.dedup();
            assert_eq!(unique.len(), seen.len(), "{seen:?}");
            if back < 1.0 {
                solved_total += seen.len();
            }
        }
        // A ray that stops just past its point solves few cells.
        let per_ray = solved_total as f64 / (20_000 / 3) as f64;
        assert!(per_ray < 2.5, "{per_ray} cells per ray");
        // Rays that pass by solve none; a stop ends the walk.
        let by = Ray::new([10.0, 10.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
        assert!(patches.visit((by.origin, by.dir), 0.0, f64::INFINITY, |_, _, _| panic!("reached")).is_some());
        let through = Ray::new([0.0, 1.0, 0.2], [0.0, -1.0, 0.0]).unwrap();
        assert!(patches.visit((through.origin, through.dir), 0.0, f64::INFINITY, |_, _, _| None).is_none());
    }
}
