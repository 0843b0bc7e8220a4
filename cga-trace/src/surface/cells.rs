//! Cells of an evolved surface: bounding spheres and tubes over equal α-intervals, built
//! once at scene load, that cull rays and isolate the intervals a ray can hit.

use super::SurfaceError;
use super::family::Circles;
use crate::ray::Ray;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use smallvec::SmallVec;

/// α-intervals a ray reaches, `(lo, hi, cells)`, touching ones merged.
pub type Intervals = SmallVec<[(f64, f64, usize); 8]>;

/// Cells as bits, 64 to a word (cell `i` is bit `i % 64` of word `i / 64`).
pub type CellBits = SmallVec<[u64; 4]>;

/// Whether bit `i` of `bits` is set.
pub fn has(bits: &[u64], i: usize) -> bool {
    bits.get(i / 64).is_some_and(|w| w >> (i % 64) & 1 == 1)
}

/// Samples per cell when bounding it.
const CELL_SAMPLES: usize = 32;
/// Relative padding of every bounding sphere.
pub const PAD: f64 = 1.02;

/// Points within `delta` of a circle: every circle of a cell lies inside. A ray can come
/// within `delta` of the circle only in the slab `|n·(x − c)| ≤ δ`, so within `δ/|d·n|` of the
/// plane crossing `p` along the ray, whose in-plane distance from `c` is then within δ of `r`:
/// `| |p − c| − r | ≤ δ + δ/|d·n|` ([`Four::reached`]). Conservative; rays nearly parallel to
/// the plane pass.
#[derive(Clone, Copy, Debug)]
struct Tube {
    centre: E3,
    normal: E3,
    radius: f64,
    delta: f64,
}

/// Four cells side by side (structure of arrays): a ray tests them in vector registers,
/// without a branch per cell.
#[derive(Clone, Copy, Debug, Default)]
struct Four {
    /// Bounding spheres: centres by axis, radii (negative for an unused lane).
    centre: [[f64; 4]; 3],
    radius: [f64; 4],
    /// Tubes: points within `delta` of the circle `(centre, normal, radius)`.
    tube_centre: [[f64; 4]; 3],
    tube_normal: [[f64; 4]; 3],
    tube_radius: [f64; 4],
    delta: [f64; 4],
}

impl Four {
    /// Puts cell `(sphere, tube)` in lane `l`.
    fn set(&mut self, l: usize, (centre, radius): (E3, f64), tube: &Tube) {
        for (k, axis) in centre.iter().enumerate() {
            self.centre[k][l] = *axis;
            self.tube_centre[k][l] = tube.centre[k];
            self.tube_normal[k][l] = tube.normal[k];
        }
        self.radius[l] = radius;
        self.tube_radius[l] = tube.radius;
        self.delta[l] = tube.delta;
    }

    /// Which of the four cells the ray can reach within `(t_min, t_max)`: through the
    /// sphere (as [`crosses`](crate::ray::crosses) tests) and within the tube ([`Tube`]),
    /// lane by lane; and of those, which have part of their sphere at `t ≤ t_min` or
    /// `t ≥ t_max` (where a crossing can lie outside the window).
    #[inline(always)]
    fn reached(&self, ray: &Ray, t_min: f64, t_max: f64) -> ([bool; 4], [bool; 4]) {
        let (o, d) = (ray.origin, ray.dir);
        let mut out = [false; 4];
        let mut ends = [false; 4];
        for (l, (slot, end)) in out.iter_mut().zip(&mut ends).enumerate() {
            // `&` rather than `&&`: every lane computes everything, with no branch to mispredict.
            let oc = [0, 1, 2].map(|k| o[k] - self.centre[k][l]);
            let tc = -dot(oc, d);
            let miss = [0, 1, 2].map(|k| oc[k] + d[k] * tc);
            let r = self.radius[l];
            let sphere = (dot(miss, miss) <= r * r) & (tc + r > t_min) & (tc - r < t_max) & (r >= 0.0);
            // The tube's test times |d·n| > 0, free of divisions and square roots: with
            // `on = n·(o − c)`, `|d·n| (p − c) = q = (o − c)|d·n| − d on sign(d·n)`, and
            // `| |q| − r|d·n| | ≤ δ|d·n| + δ` holds iff `(a − b)₊² ≤ |q|² ≤ (a + b)²`.
            let n = [0, 1, 2].map(|k| self.tube_normal[k][l]);
            let oc = [0, 1, 2].map(|k| o[k] - self.tube_centre[k][l]);
            let dn = dot(d, n);
            let (adn, on) = (dn.abs(), dot(oc, n) * dn.signum());
            let q = [0, 1, 2].map(|k| oc[k] * adn - d[k] * on);
            let q2 = dot(q, q);
            let delta = self.delta[l];
            let (a, b) = (self.tube_radius[l] * adn, delta * adn + delta);
            let ring = (q2 <= (a + b) * (a + b)) & ((a <= b) | (q2 >= (a - b) * (a - b)));
            // `t₀ = −on / |d·n|` within `δ / |d·n|` of (t_min, t_max), times |d·n|.
            let near = ring & (delta - on > t_min * adn) & (-on - delta < t_max * adn);
            *slot = sphere & ((adn < PARALLEL) | near);
            *end = *slot & ((tc - r <= t_min) | (tc + r >= t_max));
        }
        (out, ends)
    }
}

/// Rays closer than this (`|d·n|`) to a tube's plane pass its test: the slab is too thick
/// to bound anything.
const PARALLEL: f64 = 1e-3;

/// Bounding spheres and tubes over `cells` equal α-intervals of a surface, built once at
/// scene load: a ray visits only the intervals whose sphere and tube it passes through. Every
/// cell is tested, four at a time: a binary tree over 16 cells visited 13–20 of its 31 nodes
/// per ray, with a branch each, and cost more than a flat pass.
#[derive(Clone, Debug)]
pub struct Cells {
    fours: Vec<Four>,
    cells: usize,
}

impl Cells {
    /// The cells over `cells` (a power of two) equal α-intervals: each bounds the circles
    /// sampled over its interval (32 samples), the sphere padded by the largest motion between
    /// samples (centre, radius and tilt) and the tube by twice it (a circle between samples is
    /// within one step of both neighbours).
    pub fn new(circles: &impl Circles<f64>, cells: usize) -> Result<Self, SurfaceError> {
        let mut fours = vec![Four { radius: [-1.0; 4], ..Four::default() }; cells.div_ceil(4)];
        for cell in 0..cells {
            let (sphere, tube) = cell_bounds(circles, cell as f64 / cells as f64, (cell + 1) as f64 / cells as f64)?;
            fours[cell / 4].set(cell % 4, sphere, &tube);
        }
        Ok(Cells { fours, cells })
    }

    /// The α-intervals whose cells the ray reaches within `(t_min, t_max)`, in increasing α,
    /// neighbours merged; and the cells reached whose bounding sphere reaches to `t ≤ t_min`
    /// or `t ≥ t_max` (the others hold only crossings within the window). Four lanes at once
    /// in AVX2 where the CPU has it (chosen at run time).
    pub fn reach(&self, ray: &Ray, t_min: f64, t_max: f64) -> (Intervals, CellBits) {
        #[cfg(target_arch = "x86_64")]
        if cga_core::simd::avx2() {
            // SAFETY: the CPU has the features the function is compiled for.
            return unsafe { self.reach_avx2(ray, t_min, t_max) };
        }
        self.reach_lanes(ray, t_min, t_max)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn reach_avx2(&self, ray: &Ray, t_min: f64, t_max: f64) -> (Intervals, CellBits) {
        self.reach_lanes(ray, t_min, t_max)
    }

    /// The number of cells.
    pub fn count(&self) -> usize {
        self.cells
    }

    /// Whether cell `i`'s bounding sphere reaches to `t ≤ t_min` or `t ≥ t_max` along the ray
    /// (where a crossing of the cell can lie outside the window; [`Cells::reach`]'s marks).
    pub fn beyond(&self, ray: &Ray, i: usize, t_min: f64, t_max: f64) -> bool {
        let (four, l) = (&self.fours[i / 4], i % 4);
        let oc = [0, 1, 2].map(|k| ray.origin[k] - four.centre[k][l]);
        let (tc, r) = (-dot(oc, ray.dir), four.radius[l]);
        tc - r <= t_min || tc + r >= t_max
    }

    /// The cells reached as bits, 64 cells to a word, then read off run by run (a branch
    /// per interval, not per cell).
    #[inline(always)]
    fn reach_lanes(&self, ray: &Ray, t_min: f64, t_max: f64) -> (Intervals, CellBits) {
        let mut out = Intervals::new();
        let mut ends = CellBits::new();
        let width = 1.0 / self.cells as f64;
        let bits = |lanes: [bool; 4]| lanes.iter().rev().fold(0u64, |m, &r| (m << 1) | u64::from(r));
        for (b, block) in self.fours.chunks(16).enumerate() {
            let (mut mask, mut end) = (0u64, 0u64);
            for (g, four) in block.iter().enumerate() {
                let (reached, beyond) = four.reached(ray, t_min, t_max);
                mask |= bits(reached) << (4 * g);
                end |= bits(beyond) << (4 * g);
            }
            ends.push(end);
            while mask != 0 {
                let start = mask.trailing_zeros() as usize;
                let run = (!(mask >> start)).trailing_zeros() as usize;
                mask = if start + run >= 64 { 0 } else { mask & (!0u64 << (start + run)) };
                let first = 64 * b + start;
                let (lo, hi) = (first as f64 * width, (first + run) as f64 * width);
                match out.last_mut() {
                    Some(last) if last.1 == lo => {
                        last.1 = hi;
                        last.2 += run;
                    }
                    _ => out.push((lo, hi, run)),
                }
            }
        }
        (out, ends)
    }
}

/// The cell over `[lo, hi]`: a sphere around the sampled circles and a tube around the middle
/// one, each padded by the largest step between samples.
fn cell_bounds(family: &impl Circles<f64>, lo: f64, hi: f64) -> Result<((E3, f64), Tube), SurfaceError> {
    let mut circles = [([0.0; 3], [0.0; 3], 0.0); CELL_SAMPLES + 1];
    for (s, slot) in circles.iter_mut().enumerate() {
        let alpha = lo + (hi - lo) * s as f64 / CELL_SAMPLES as f64;
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
    let mid = circles[CELL_SAMPLES / 2];
    let delta = circles.iter().map(|c| apart(c, &mid)).fold(0.0, f64::max) + 2.0 * step;
    let tube = Tube { centre: mid.0, normal: mid.1, radius: mid.2, delta };
    Ok(((centre, radius * PAD), tube))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hash::stream;
    use crate::surface::TwoCircles;
    use cga_core::euclid::{cross, perpendicular, unit};
    use cga_core::{Circle, Pair};

    /// A twisted family: circles of radius 1 and 0.6, normals z and nearly x.
    fn twisted() -> TwoCircles<f64> {
        let c1 = Circle::from_centre_normal_radius([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
        let c2 = Circle::from_centre_normal_radius([0.3, 0.0, 1.5], unit([1.0, 0.2, 0.3]).unwrap(), 0.6).unwrap();
        TwoCircles::new(Pair::new(c1, c2).unwrap())
    }

    /// The point of `C_α` at `angle`, and the circle's normal.
    fn on_circle(circles: &TwoCircles<f64>, alpha: f64, angle: f64) -> (E3, E3) {
        let (c, n, r) = circles.at(alpha).unwrap().centre_normal_radius().unwrap();
        let (u, v) = (perpendicular(n), cross(n, perpendicular(n)));
        (add(c, add(scale(u, r * angle.cos()), scale(v, r * angle.sin()))), n)
    }

    /// Culling never loses a hit: every ray through a point of `C_α` — from any direction,
    /// grazing and in the circle's plane included — reaches an interval holding α, and where
    /// a window leaves the point out, its cell is marked as one whose crossings can lie
    /// outside; and it culls: rays that pass the surface by reach nothing, and a hitting ray
    /// few cells.
    #[test]
    fn every_ray_through_a_circle_reaches_its_cell() {
        let circles = twisted();
        // Fewer cells than lanes, and more than one 64-cell word.
        for count in [2, 256] {
            let cells = Cells::new(&circles, count).unwrap();
            let mut next = stream(7);
            for _ in 0..2000 {
                let (alpha, angle) = (next(), next() * std::f64::consts::TAU);
                let (x, _) = on_circle(&circles, alpha, angle);
                let dir = unit([next() - 0.5, next() - 0.5, next() - 0.5]).unwrap();
                let ray = Ray::new(sub(x, scale(dir, 3.0)), dir).unwrap();
                let found = cells.reach(&ray, 0.0, f64::INFINITY).0;
                assert!(found.iter().any(|&(lo, hi, _)| lo <= alpha && alpha <= hi), "{count} cells, α = {alpha}");
                // Intervals are disjoint, increasing, and count their cells.
                for w in found.windows(2) {
                    assert!(w[0].1 < w[1].0, "{found:?}");
                }
                assert!(found.iter().all(|&(lo, hi, k)| ((hi - lo) * count as f64 - k as f64).abs() < 1e-9));
            }
        }
        let cells = Cells::new(&circles, 16).unwrap();
        let mut next = stream(0x2545_f491_4f6c_dd1d);
        let mut reached = 0;
        for k in 0..20_000 {
            let (alpha, angle) = (next(), next() * std::f64::consts::TAU);
            let (x, n) = on_circle(&circles, alpha, angle);
            let random = unit([next() - 0.5, next() - 0.5, next() - 0.5]).unwrap();
            // Every fourth ray lies in the circle's plane.
            let dir = if k % 4 == 0 { unit(sub(random, scale(n, dot(random, n)))).unwrap() } else { random };
            let ray = Ray::new(sub(x, scale(dir, 3.0)), dir).unwrap();
            let found = cells.reach(&ray, 0.0, f64::INFINITY).0;
            assert!(found.iter().any(|&(lo, hi, _)| lo <= alpha && alpha <= hi), "α = {alpha}, {ray:?}: {found:?}");
            // The point lies at t = 3: a shorter ray does not get there.
            let short = cells.reach(&ray, 0.0, 3.0 + 1e-9).0;
            assert!(short.iter().any(|&(lo, hi, _)| lo <= alpha && alpha <= hi), "α = {alpha}, t_max 3");
            // A window that leaves the point out marks its cell, where it reaches it, as one
            // whose crossings can lie outside.
            let cell = ((alpha * 16.0) as usize).min(15);
            for (t_min, t_max) in [(0.0, 3.0 - 1e-9), (3.0 + 1e-9, f64::INFINITY)] {
                let (found, ends) = cells.reach(&ray, t_min, t_max);
                let reached = found.iter().any(|&(lo, hi, _)| lo * 16.0 <= cell as f64 && (cell as f64) < hi * 16.0);
                assert!(!reached || has(&ends, cell), "α = {alpha} in ({t_min}, {t_max}): cell {cell} not marked");
            }
            reached += found.iter().map(|i| i.2).sum::<usize>();
        }
        assert!(reached < 20_000 * 12, "{} cells per ray on average", reached as f64 / 20_000.0);
        let passing_by = Ray::new([5.0, 5.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
        assert!(cells.reach(&passing_by, 0.0, f64::INFINITY).0.is_empty());
        let behind = Ray::new([0.0, 0.0, 10.0], [0.0, 0.0, 1.0]).unwrap();
        assert!(cells.reach(&behind, 0.0, f64::INFINITY).0.is_empty());
    }
}
