//! Patches of a spline surface: each segment's cells cut along α and around the circles into
//! pieces, each with a box and a slab across it, all the boxes in one four-wide tree. A ray opens
//! the nearer boxes first and solves a cell when it first passes through the box and the slab
//! of one of its patches together; once a crossing is found, the boxes beyond it are never
//! opened. A cell's bounding sphere holds its whole ring, so a ray that crossed the front of
//! the surface used to solve the cells behind it too, and the rays passing by the surface
//! reached cells through the spheres' empty parts.
//!
//! A patch over `α ∈ [a₀, a₁]` and `θ ∈ [θ₀, θ₁]` is the points
//! `X(α, θ) = c(α) + r(α)(cos θ u(α) + sin θ v(α))`, where `(u, v)` is the middle circle's
//! in-plane frame projected onto each circle's plane (continuous over the cell; a cell whose
//! circles turn by more than [`TURN`] against the middle one is cut along α only). Its box and
//! slab (`near ≤ n·x ≤ far`, `n` the normal at its middle) hold the points sampled on a grid,
//! padded by what linear interpolation between grid points can miss:
//! `Δα²/8 max|X_αα| + Δθ²/8 max|X_θθ|` (`|X_θθ| = r`, `|X_αα|` from the samples' second
//! differences, doubled: measured, not proven, as the cells' bounds are), plus rounding. The interpolant lies in the
//! convex hull of the grid points, so in the box and the slab.

use super::{Method, SurfaceError};
use crate::bvh::{Bvh, Wide};
use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};

/// Patches around each cell's circles.
const SECTORS: usize = 16;
/// Patches along each cell (2 and 8 were no faster on fig3c and catmull-rom).
const PIECES: usize = 4;
/// Samples of α per piece, of the angle per sector (intervals).
const ALPHA_STEPS: usize = 8;
const ANGLE_STEPS: usize = 4;
/// The least `|n(α)·n_mid|` over a cell for the middle circle's frame to serve it (60°).
const TURN: f64 = 0.5;

/// The most cells (over all segments) a surface builds patches over (64 patches a cell, 88
/// bytes each, about 6 MB at the most): beyond it, rays reach cells through their spheres.
pub const PATCH_CELLS: usize = 1024;

/// A circle: centre, unit normal, radius.
type Circle3 = (E3, E3, f64);

/// The patches of a surface of `segments` segments, `cells` cells each, in one tree.
#[derive(Clone, Debug)]
pub struct Patches {
    wide: Wide,
    /// For each item in the tree's leaf order, its cell: `segment · cells + cell`.
    order: Vec<u32>,
    /// The patches in the tree's leaf order.
    patches: Vec<Patch>,
    /// Cells per segment.
    cells: usize,
}

impl Patches {
    /// The patches over `segments` segments of `cells` cells each, where `at(j, α)` is segment
    /// `j`'s circle at `α ∈ [0, 1]`.
    pub fn new(
        segments: usize,
        cells: usize,
        at: impl Fn(usize, f64) -> Result<Circle3, SurfaceError>,
    ) -> Result<Self, SurfaceError> {
        let mut patches = Vec::with_capacity(segments * cells * SECTORS * PIECES);
        let mut owner = Vec::with_capacity(patches.capacity());
        for j in 0..segments {
            for i in 0..cells {
                let (lo, hi) = (i as f64 / cells as f64, (i + 1) as f64 / cells as f64);
                let steps = ALPHA_STEPS * PIECES;
                let circles = (0..=steps)
                    .map(|s| at(j, lo + (hi - lo) * s as f64 / steps as f64))
                    .collect::<Result<Vec<_>, _>>()?;
                for patch in cell_patches(&circles) {
                    patches.push(patch);
                    owner.push((j * cells + i) as u32);
                }
            }
        }
        let bvh = Bvh::over_boxes(&patches.iter().map(|p| (p.lo, p.hi)).collect::<Vec<_>>());
        let order = bvh.order().iter().map(|&k| owner[k as usize]).collect();
        let patches = bvh.order().iter().map(|&k| patches[k as usize]).collect();
        Ok(Patches { wide: Wide::new(&bvh), order, patches, cells })
    }

    /// The cells per segment a spline of `segments` Bézier segments builds patches over with
    /// `method`: the hybrid method's, where there are at most [`PATCH_CELLS`] in all.
    pub fn cells_for(method: Method, segments: usize) -> Option<usize> {
        match (method, method.cells()) {
            (Method::Hybrid { .. }, Some(cells)) if cells.saturating_mul(segments) <= PATCH_CELLS => Some(cells),
            _ => None,
        }
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
        // A ray of NaNs would pass every box (the walk needs finite numbers to turn it away).
        if !origin.iter().chain(&dir).all(|x| x.is_finite()) {
            return Some(t_max);
        }
        let inv = dir.map(|d| 1.0 / d);
        // One bit a cell, on the stack, for the `PATCH_CELLS` a surface builds patches over
        // (`cells_for`): no allocation a ray. A cell beyond them (a caller that built more)
        // is solved each time a patch of it is crossed: more work, the same answer.
        let mut solved = [0u64; PATCH_CELLS / 64];
        self.wide.traverse_leaves(origin, dir, t_min, t_max, |range, mut t_max| {
            for (&key, patch) in self.order[range.clone()].iter().zip(&self.patches[range]) {
                let (word, bit) = (key as usize / 64, 1u64 << (key % 64));
                let seen = solved.get(word).is_some_and(|w| w & bit != 0);
                if !seen && patch.crossed(origin, (dir, inv), t_min, t_max) {
                    if let Some(w) = solved.get_mut(word) {
                        *w |= bit;
                    }
                    let key = key as usize;
                    t_max = solve(key / self.cells, key % self.cells, t_max)?;
                }
            }
            Some(t_max)
        })
    }
}

/// One patch: its box, and the slab `near ≤ n·x ≤ far` across it (`n` the surface's normal at
/// its middle), which a ray passing by a curved patch's box often misses.
#[derive(Clone, Copy, Debug)]
struct Patch {
    lo: E3,
    hi: E3,
    normal: E3,
    near: f64,
    far: f64,
}

impl Patch {
    /// Whether the ray `origin + t dir` (`inv` the reciprocals of `dir`'s components) passes
    /// through the box and the slab together within `(t_min, t_max)`. Each axis's faces are
    /// taken in the order the sign of `1/d` gives, as [`Bvh`]'s slab test does: a NaN bound
    /// (`0 · ∞`, the ray in a face's plane and parallel to it) then leaves the interval as it
    /// was.
    #[inline(always)]
    fn crossed(&self, origin: E3, (dir, inv): (E3, E3), t_min: f64, t_max: f64) -> bool {
        let (mut enter, mut leave) = (t_min, t_max);
        for k in 0..3 {
            let (a, b) = ((self.lo[k] - origin[k]) * inv[k], (self.hi[k] - origin[k]) * inv[k]);
            let (near, far) = if inv[k] < 0.0 { (b, a) } else { (a, b) };
            enter = if near > enter { near } else { enter };
            leave = if far < leave { far } else { leave };
        }
        let (on, dn) = (dot(self.normal, origin), dot(self.normal, dir));
        if dn == 0.0 {
            return enter <= leave && self.near <= on && on <= self.far;
        }
        let (a, b) = ((self.near - on) / dn, (self.far - on) / dn);
        let (near, far) = if dn < 0.0 { (b, a) } else { (a, b) };
        enter = if near > enter { near } else { enter };
        leave = if far < leave { far } else { leave };
        enter <= leave
    }
}

/// The patches of one cell, from its circles sampled at equal steps of α.
fn cell_patches(circles: &[Circle3]) -> Vec<Patch> {
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
            let rows: Vec<usize> = (piece * ALPHA_STEPS..=(piece + 1) * ALPHA_STEPS).collect();
            let width = std::f64::consts::TAU / sectors as f64;
            let steps = ANGLE_STEPS * if turned { SECTORS } else { 1 };
            let angle = |k: usize| width * (s as f64 + k as f64 / steps as f64);
            let grid: Vec<Vec<E3>> = (0..=steps).map(|k| rows.iter().map(|&a| point(a, angle(k))).collect()).collect();
            let mut bend = 0.0f64;
            for column in &grid {
                for w in column.windows(3) {
                    bend = bend.max(norm(add(sub(w[0], scale(w[1], 2.0)), w[2])));
                }
            }
            // Δα²/8 · 2 max|X_αα| with |X_αα| ≈ |second difference| / Δα²; Δθ²/8 · r.
            let step = width / steps as f64;
            let pad = bend / 4.0 + step * step / 8.0 * r_max + 1e-12 * size;
            // The normal at the middle, across the middle row and column (a patch all round,
            // turned, has none that serves: its slab is everything).
            let (a_mid, k_mid) = (rows.len() / 2, steps / 2);
            let along = sub(grid[k_mid][rows.len() - 1], grid[k_mid][0]);
            let around = sub(grid[steps][a_mid], grid[0][a_mid]);
            let normal = if turned { None } else { unit(cross(along, around)) }.unwrap_or([0.0; 3]);
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            let (mut near, mut far) = (f64::INFINITY, f64::NEG_INFINITY);
            for x in grid.iter().flatten() {
                for axis in 0..3 {
                    lo[axis] = lo[axis].min(x[axis]);
                    hi[axis] = hi[axis].max(x[axis]);
                }
                near = near.min(dot(normal, *x));
                far = far.max(dot(normal, *x));
            }
            if normal == [0.0; 3] {
                (near, far) = (f64::NEG_INFINITY, f64::INFINITY);
            }
            Patch { lo: lo.map(|x| x - pad), hi: hi.map(|x| x + pad), normal, near: near - pad, far: far + pad }
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
        assert!(per_ray < 1.8, "{per_ray} cells per ray");
        // Every point of a circle lies in the box and the slab of a patch of its cell.
        for k in 0..20_000 {
            let (j, alpha, angle) = (k % 2, next(), next() * std::f64::consts::TAU);
            let (c, n, r) = at(j, alpha).unwrap();
            let u = cga_core::euclid::perpendicular(n);
            let x = add(c, scale(add(scale(u, angle.cos()), scale(cross(n, u), angle.sin())), r));
            let key = (j * cells + ((alpha * cells as f64) as usize).min(cells - 1)) as u32;
            let inside = |p: &Patch| {
                (0..3).all(|a| p.lo[a] <= x[a] && x[a] <= p.hi[a]) && (p.near..=p.far).contains(&dot(p.normal, x))
            };
            let held = patches.order.iter().zip(&patches.patches).any(|(&owner, p)| owner == key && inside(p));
            assert!(held, "segment {j}, α = {alpha}, angle {angle}");
        }
        // Rays that pass by solve none; a stop ends the walk.
        let by = Ray::new([10.0, 10.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
        assert!(patches.visit((by.origin, by.dir), 0.0, f64::INFINITY, |_, _, _| panic!("reached")).is_some());
        let through = Ray::new([0.0, 1.0, 0.2], [0.0, -1.0, 0.0]).unwrap();
        assert!(patches.visit((through.origin, through.dir), 0.0, f64::INFINITY, |_, _, _| None).is_none());
    }
}
