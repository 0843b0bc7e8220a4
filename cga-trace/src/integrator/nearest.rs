//! The nearest crossing along rays, and whether anything blocks them, written once for one
//! ray and for a packet ([`RayLanes`]): one ray through the BVH where the scene has one;
//! otherwise every object in turn, in lanes (packets run only in scenes without a BVH, and
//! would meet every object in one).

use super::Renderer;
use crate::backend::{Backend, RayLanes};
use crate::object::Object;
use crate::ray::{Ray, crosses};
use crate::shapes::{Crossing, ShadingPoint};

impl<'a, B: Backend> Renderer<'a, B> {
    /// The nearest crossing with `t_min < t < t_max` over all objects (each beyond its own
    /// [crossing error](Renderer::t_min)), and the object's index.
    pub(super) fn crossing(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(Crossing, usize)> {
        let [best] = self.crossings(ray, t_min, [t_max]);
        best
    }

    /// The nearest hit with `t_min < t < t_max`, and its object: the nearest crossing over
    /// all objects, then its normal, once.
    pub fn nearest(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(ShadingPoint, &'a Object)> {
        self.hit(ray, t_min, t_max).map(|(hit, k)| (hit, &self.scene.objects[k]))
    }

    /// [`Renderer::nearest`] with the object's index.
    pub(super) fn hit(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(ShadingPoint, usize)> {
        let (c, k) = self.crossing(ray, t_min, t_max)?;
        let hit = ShadingPoint::at(c, B::normal(&self.shapes[k], ray, &c));
        Some((hit, k))
    }

    /// The nearest crossing per lane with `t_min < t < t_max[l]` over all objects (each
    /// beyond its own [crossing error](Renderer::t_min)), and its object; a lane with
    /// `t_max = −∞` finds nothing.
    #[inline(always)]
    pub(crate) fn crossings<R: RayLanes<B, W>, const W: usize>(
        &self,
        rays: &R,
        t_min: f64,
        mut t_max: [f64; W],
    ) -> [Option<(Crossing, usize)>; W] {
        let mut best = [None; W];
        if let Some(bvh) = self.bvh.as_ref().filter(|_| W == 1) {
            for (l, best) in best.iter_mut().enumerate() {
                let ray = rays.ray(l);
                bvh.traverse(ray.origin, ray.dir, t_min, t_max[l], |k, t_max| {
                    let c = B::intersect(&self.shapes[k], ray, self.t_min(k, t_min), t_max);
                    Some(match c {
                        Some(c) if self.wins(c.t, k, best) => {
                            *best = Some((c, k));
                            self.reach(c.t, k)
                        }
                        _ => t_max,
                    })
                });
            }
            return best;
        }
        for k in 0..self.shapes.len() {
            if self.culled(rays, k, t_min, &t_max) {
                continue;
            }
            for (l, c) in rays.cross(&self.shapes[k], &[self.t_min(k, t_min); W], &t_max).into_iter().enumerate() {
                if let Some(c) = c.filter(|c| self.wins(c.t, k, &best[l])) {
                    t_max[l] = self.reach(c.t, k);
                    best[l] = Some((c, k));
                }
            }
        }
        best
    }

    /// Whether a crossing of object `k` at `t` takes the place of `best`: it is nearer by
    /// more than the two crossings' errors, or within them (two surfaces in one place, such
    /// as a disk on a floor or a glass box resting on one) and [`Renderer::tie`] prefers it.
    /// So which surface shows at a contact is decided by the surfaces, never by the order
    /// they are declared in.
    #[inline(always)]
    fn wins(&self, t: f64, k: usize, best: &Option<(Crossing, usize)>) -> bool {
        match best {
            None => true,
            Some((b, j)) => {
                let tolerance = self.errors[k] + self.errors[*j];
                t < b.t - tolerance || (t <= b.t + tolerance && self.tie[k] < self.tie[*j])
            }
        }
    }

    /// How far past the best crossing `t` (of object `k`) other objects are still met: far
    /// enough for any crossing within both errors of it to be weighed by [`Renderer::wins`].
    #[inline(always)]
    fn reach(&self, t: f64, k: usize) -> f64 {
        t + self.errors[k] + self.largest_error
    }

    /// Which rays are blocked before their `t_max`, less the blocker's own crossing error (a
    /// light standing on a surface is lit, not decided by rounding), by an object other than the lane's
    /// `skip` and the dielectrics, which are not tested (a lane with `t_max ≤ 0` or NaN is inactive and never
    /// blocked): stops at the first blocker (once every active lane is blocked), and computes no normals.
    #[inline(always)]
    pub(crate) fn blocked<R: RayLanes<B, W>, const W: usize>(
        &self,
        rays: &R,
        t_max: &[f64; W],
        skip: &[Option<usize>; W],
    ) -> [bool; W] {
        // Inactive lanes count as blocked while the objects are met, and are not at the end.
        let active = t_max.map(|t| t > 0.0);
        let mut blocked = active.map(|a| !a);
        if let Some(bvh) = self.bvh.as_ref().filter(|_| W == 1) {
            for l in (0..W).filter(|&l| active[l]) {
                let ray = rays.ray(l);
                bvh.traverse(ray.origin, ray.dir, 0.0, t_max[l], |k, t| {
                    blocked[l] = Some(k) != skip[l]
                        && !self.clear[k]
                        && B::occludes(&self.shapes[k], ray, self.t_min(k, 0.0), t - self.errors[k]);
                    (!blocked[l]).then_some(t)
                });
            }
            return core::array::from_fn(|l| active[l] && blocked[l]);
        }
        for k in 0..self.shapes.len() {
            if blocked.iter().all(|&b| b) {
                break;
            }
            // Dielectrics are never asked: they block nothing.
            if self.clear[k] {
                continue;
            }
            let tests: [bool; W] = core::array::from_fn(|l| !blocked[l] && skip[l] != Some(k));
            if !tests.iter().any(|&b| b) {
                continue;
            }
            // A light on a surface (within its crossing error) is not blocked by it: the ray
            // stops short of the light by the surface's own error.
            let range = core::array::from_fn(|l| if tests[l] { t_max[l] - self.errors[k] } else { f64::NEG_INFINITY });
            if self.culled(rays, k, 0.0, &range) {
                continue;
            }
            for (l, hit) in rays.occluded_by(&self.shapes[k], &[self.t_min(k, 0.0); W], &range).into_iter().enumerate()
            {
                blocked[l] |= hit;
            }
        }
        core::array::from_fn(|l| active[l] && blocked[l])
    }

    /// Whether one ray cannot cross object `k`'s bounding sphere within `(t_min, t_max)`.
    /// A packet meets every object (its meets in lanes cost less than four such tests).
    #[inline(always)]
    fn culled<R: RayLanes<B, W>, const W: usize>(&self, rays: &R, k: usize, t_min: f64, t_max: &[f64; W]) -> bool {
        W == 1 && self.bounds[k].is_some_and(|(c, r)| !crosses(rays.ray(0), c, r, t_min, t_max[0]))
    }
}
