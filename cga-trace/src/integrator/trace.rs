//! Tracing rays in lanes: the nearest hit, its normal and shading, the mirror bounces, and
//! the sum of the layers from the deepest up; what each AOV shows along a ray.

use super::keep::{Keep, Taken};
use super::shade::lit;
use super::{Aov, RayCounts, Renderer, SampleKey, Window};
use crate::backend::{Backend, RayLanes, lanes3};
use crate::ray::{Ray, mirror, offset};
use crate::settings::Reflection;
use crate::shapes::ShadingPoint;
use cga_core::euclid::E3;
use cga_core::simd::Lane;
use rayon::prelude::*;
use smallvec::SmallVec;

impl<B: Backend> Renderer<'_, B> {
    /// The rays a one-sample render of `window` casts before any reflection: each pixel
    /// centre's primary ray, and from its nearest hit the shadow ray towards every light that
    /// lights it (as [`Renderer::trace`] casts them, shadows on or off), each with the end of
    /// its range (∞ for primary rays). For checking and timing shapes on a scene's own rays.
    pub fn first_rays(&self, window: &Window) -> Vec<(Ray<B::Carrier>, f64)>
    where
        B::Carrier: Send,
    {
        let rows: Vec<u32> = window.rows.clone().collect();
        rows.par_iter()
            .flat_map_iter(|&j| {
                let mut out = Vec::new();
                for i in window.columns.clone() {
                    let Some(ray) = B::camera_ray(&self.scene.camera, f64::from(i) + 0.5, f64::from(j) + 0.5) else {
                        continue;
                    };
                    out.push((ray, f64::INFINITY));
                    let Some((hit, k)) = self.hit(&ray, 0.0, f64::INFINITY) else { continue };
                    // The shadow rays `shade` casts.
                    let offset = offset(hit.point, ray.origin, self.errors[k]);
                    let at = (hit.point, hit.normal, ray.dir.map(|d| -d));
                    for light in &self.scene.lights {
                        let material = &self.scene.objects[k].material;
                        if let Some(term) = lit(light, light.toward(at.0), at, &[material], &[true], offset) {
                            out.push((B::ray(term.shadow_origin, term.l), term.distance));
                        }
                    }
                }
                out
            })
            .collect()
    }

    /// The colour seen along `ray`, `depth` bounces deep.
    pub fn trace(&self, ray: &Ray<B::Carrier>, depth: u32) -> [f64; 3] {
        let mut cast = RayCounts::default();
        let ([colour], _) = self.trace_met::<_, 1, Taken>(*ray, depth, &[SampleKey::default()], &mut cast);
        self.count(&cast);
        colour
    }

    /// What a ray leaving the scene along `dir` sees: the environment, or the background.
    #[inline(always)]
    pub(super) fn sky(&self, dir: E3) -> [f64; 3] {
        match &self.scene.environment {
            None => self.scene.settings.background,
            Some(e) => e.seen(dir),
        }
    }

    /// A hit's own colour `local` and the weight `k_r` of its mirror ray: eq. 12's `local` and
    /// `k_r`, or, where energy is conserved, `(1 − k_r) local` and `k_r` at most 1 (what a
    /// surface reflects it does not also shade).
    #[inline(always)]
    pub(super) fn reflected(&self, local: [f64; 3], kr: f64) -> ([f64; 3], f64) {
        if self.scene.settings.reflection == Reflection::Conserving && kr > 0.0 {
            let kr = kr.min(1.0);
            (local.map(|c| c * (1.0 - kr)), kr)
        } else {
            (local, kr)
        }
    }

    /// The colours seen along rays in lanes, `depth` bounces already made, for the pixel
    /// samples `keys` (which place points on area lights), counting the
    /// rays cast into `cast` (shared counters would be contended by every thread on every
    /// ray): nearest hit, normal, shading, and the mirror bounces of the lanes whose hit
    /// reflects (lanes whose ray has ended ride along with an empty range).
    ///
    /// Bounces are followed in a loop, not by recursion, so that no depth can overflow the
    /// stack: each hit's own colour and `k_r` are kept, and summed from the deepest up as
    /// recursion would, `I = I_local + k_r I_reflected` (the same operations in the same
    /// order, so the same bits).
    ///
    /// Beside the colours, whether each lane's ray met anything (its first crossing), where
    /// `K` keeps it (a transparent background's coverage; all `false` otherwise, and nothing
    /// done for it: an opaque picture's rays do what they did before).
    #[inline(always)]
    pub(crate) fn trace_met<R: RayLanes<B, W>, const W: usize, K: Keep>(
        &self,
        mut rays: R,
        mut depth: u32,
        keys: &[SampleKey; W],
        cast: &mut RayCounts,
    ) -> ([[f64; 3]; W], [bool; W]) {
        let settings = &self.scene.settings;
        let mut active = [true; W];
        let mut deepest = [settings.background; W];
        let mut layers: [Layers; W] = core::array::from_fn(|_| Layers::new());
        // Camera rays from inside a dielectric: what they see is absorbed on the way to it.
        let mut absorbed = [[1.0; 3]; W];
        let start: [Option<usize>; W] = match depth {
            0 if self.dielectrics => core::array::from_fn(|l| self.origin_medium(rays.ray(l).origin)),
            _ => [None; W],
        };
        let inside = start.iter().any(Option::is_some);
        let (mut met, mut first) = ([false; W], true);
        while active.iter().any(|&a| a) {
            // An inactive lane's range is empty: it finds nothing. (`map`, not `from_fn`,
            // here and for `errors`: LLVM leaves `from_fn` over them out of line, 7 % more
            // instructions on the anchor scene.)
            let t_max = active.map(|a| if a { f64::INFINITY } else { f64::NEG_INFINITY });
            let nearest = self.crossings(&rays, 0.0, t_max);
            let mut hits: [Option<(ShadingPoint, usize)>; W] = [None; W];
            for (l, hit) in hits.iter_mut().enumerate() {
                *hit = nearest[l].map(|(c, k)| {
                    let normal = B::normal(&self.shapes[k], rays.ray(l), &c);
                    (ShadingPoint::at(c, normal), k)
                });
            }
            if K::COVERS && first {
                (met, first) = (nearest.map(|n| n.is_some()), false);
            }
            let errors: [f64; W] = nearest.map(|n| n.map_or(0.0, |(_, k)| self.errors[k]));
            if inside && depth == 0 {
                for (l, hit) in hits.iter().enumerate() {
                    let Some(m) = start[l] else { continue };
                    let d = hit.map_or(0.0, |(h, _)| self.scene.frame.world_length(h.t));
                    absorbed[l] = self.scene.objects[m].material.absorption.map(|a| (-a * d).exp());
                }
            }
            let local = self.shade(&rays, &hits, keys, cast);
            let mut bounce = [false; W];
            for l in 0..W {
                if !active[l] {
                    continue;
                }
                let Some((hit, k)) = hits[l] else {
                    (deepest[l], active[l]) = (self.sky(rays.ray(l).dir), false);
                    continue;
                };
                let material = &self.scene.objects[k].material;
                if material.dielectric() && depth < settings.max_depth {
                    // Its rays branch: followed one at a time (glass.rs).
                    let medium = if depth == 0 { start[l] } else { None };
                    let rest = self.through_dielectric(rays.ray(l), &hit, k, (depth, medium), &keys[l], cast);
                    (deepest[l], active[l]) = ([0, 1, 2].map(|c| local[l][c] + rest[c]), false);
                    continue;
                }
                let (own, kr) = self.reflected(local[l], material.kr);
                if !(kr > 0.0 && depth < settings.max_depth) {
                    (deepest[l], active[l]) = (own, false);
                    continue;
                }
                cast.reflection += 1;
                layers[l].push((own, kr));
                bounce[l] = true;
            }
            if bounce.iter().any(|&b| b) {
                rays = mirrored(&rays, &hits, &errors, &bounce);
            }
            depth += 1;
        }
        let seen: [[f64; 3]; W] = core::array::from_fn(|l| sum_layers(&layers[l], deepest[l]));
        let seen = match inside {
            false => seen,
            true => core::array::from_fn(|l| [0, 1, 2].map(|c| seen[l][c] * absorbed[l][c])),
        };
        (seen, met)
    }
}

/// The colours and `k_r` of the hits along a ray's mirror bounces, nearest first, summed
/// from the deepest up.
pub(crate) type Layers = SmallVec<[([f64; 3], f64); 8]>;

/// `I = I_local + k_r I_below` from the deepest bounce up, as recursion would sum it.
pub(crate) fn sum_layers(layers: &Layers, deepest: [f64; 3]) -> [f64; 3] {
    layers.iter().rev().fold(deepest, |below, (local, kr)| [0, 1, 2].map(|k| local[k] + kr * below[k]))
}

/// The mirror bounces of the lanes that `bounce` at their hits (object index per lane), each
/// off its object's crossing error `errors` ([`mirror`] in lanes: the reflected direction,
/// starting off the surface); the other lanes keep their ray (a zero normal reflects nothing).
#[inline(always)]
pub(crate) fn mirrored<B: Backend, R: RayLanes<B, W>, const W: usize>(
    rays: &R,
    hits: &[Option<(ShadingPoint, usize)>; W],
    errors: &[f64; W],
    bounce: &[bool; W],
) -> R {
    let at = |l: usize| match hits[l] {
        Some((hit, _)) if bounce[l] => (hit.point, hit.normal),
        _ => (rays.ray(l).origin, [0.0; 3]),
    };
    let x: E3<R::T> = lanes3::<R::T, W>(core::array::from_fn(|l| at(l).0));
    let n: E3<R::T> = lanes3::<R::T, W>(core::array::from_fn(|l| at(l).1));
    let (origin, r) = mirror(rays.dir(), rays.origin(), x, n, R::T::from_fn(|l| errors[l]));
    R::cast(origin, r)
}

impl<B: Backend> Renderer<'_, B> {
    /// What AOV `aov` shows along `ray`.
    pub(super) fn aov(&self, ray: &Ray<B::Carrier>, aov: Aov) -> [f64; 3] {
        match aov {
            Aov::Shaded => self.trace(ray, 0),
            Aov::Normal => {
                self.nearest(ray, 0.0, f64::INFINITY).map_or([0.0; 3], |(h, _)| h.normal.map(|x| 0.5 * (x + 1.0)))
            }
            Aov::Coverage => match self.nearest(ray, 0.0, f64::INFINITY) {
                Some(_) => [1.0; 3],
                None => [0.0; 3],
            },
            Aov::Alpha => match self.nearest(ray, 0.0, f64::INFINITY) {
                Some((ShadingPoint { alpha: Some(a), .. }, _)) => [a, 0.2, 1.0 - a],
                _ => [0.0; 3],
            },
            // (value, 1) where the surface has a curvature, (0, 0) elsewhere: averaged over
            // samples, value / weight is the mean over the samples that had one.
            _ => match self.nearest(ray, 0.0, f64::INFINITY) {
                Some((hit, object)) => {
                    let crossing = hit.crossing();
                    let scale = self.scene.frame.scale;
                    object.shape.curvature(&crossing).map_or([0.0; 3], |k| [aov.value(&k, ray.dir, scale), 1.0, 0.0])
                }
                None => [0.0; 3],
            },
        }
    }
}
