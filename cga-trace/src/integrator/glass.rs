//! Dielectrics (glass, water): at each hit Fresnel's reflectance `F` of unpolarised light
//! splits the ray into a mirror ray of weight `F` and a ray refracted by Snell's law of
//! weight `1 − F` (all of it reflected past the critical angle); inside, light is absorbed
//! by Beer–Lambert's `exp(−a d)`. A flat dielectric (disk, plane, triangle) is a thin sheet:
//! the transmitted ray goes on undeviated; but the triangles of a closed mesh bound one
//! solid, which a ray enters at one and leaves at another.
//!
//! Rays that meet a dielectric branch, so they are followed one at a time on a stack of
//! weighted rays — `I = Σ w_i I_local,i` over the hits of the tree, each ray's weight the
//! product of the `F`, `1 − F`, `k_r` and absorption along its path — in a loop, not by
//! recursion, so that no depth can overflow the stack. A ray whose weight falls below
//! [`CUTOFF`] in every channel is dropped (POV-Ray's `adc_bailout`). Dielectrics may not
//! overlap: a ray inside one that meets another enters the second.

use super::{RayCounts, Renderer, SampleKey};
use crate::backend::Backend;
use crate::ray::{Ray, leaving_origin, mirror, offset};
use crate::shapes::ShadingPoint;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use smallvec::SmallVec;

/// The weight below which a branch of a dielectric's tree of rays is dropped: 1/256, under
/// half a level of an 8-bit picture.
pub const CUTOFF: f64 = 1.0 / 256.0;

/// A ray still to follow: its weight per channel, its bounces so far, and the medium it
/// travels inside (`None`: outside every one).
struct Pending<C> {
    ray: Ray<C>,
    weight: [f64; 3],
    depth: u32,
    inside: Option<usize>,
}

/// Fresnel's reflectance of unpolarised light meeting an interface at `cos_i = −d·n > 0`
/// from index `n1` into `n2`, and the refracted direction by Snell's law
/// (`n1 sin θ_i = n2 sin θ_t`): `t = η d + (η cos_i − cos_t) n`, `η = n1/n2`; `None` past the
/// critical angle (total internal reflection). `d` and `n` unit, `n` facing the ray.
pub fn fresnel(d: E3, n: E3, n1: f64, n2: f64) -> (f64, Option<E3>) {
    let eta = n1 / n2;
    let cos_i = (-dot(d, n)).clamp(0.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return (1.0, None);
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let t = add(scale(d, eta), scale(n, eta * cos_i - cos_t));
    (0.5 * (r_s * r_s + r_p * r_p), Some(t))
}

impl<B: Backend> Renderer<'_, B> {
    /// The medium a camera ray starting at `origin` starts in: the camera's, changed at every
    /// dielectric surface between the camera and `origin` (a point of
    /// a thin lens, or of an orthographic view's plane); a pinhole's rays start at the camera.
    pub(super) fn origin_medium(&self, origin: E3) -> Option<usize> {
        let camera = self.scene.camera.position();
        let d = norm(sub(origin, camera));
        if !self.dielectrics || d == 0.0 {
            return self.camera_medium;
        }
        let ray = B::ray(camera, scale(sub(origin, camera), 1.0 / d));
        let mut inside = self.camera_medium;
        let mut t = 0.0;
        // Crossings counted at most (dielectrics do not overlap: one toggles in or out).
        for _ in 0..64 {
            let Some((c, k)) = self.crossing(&ray, t, d) else { break };
            if let Some(m) = self.medium[k].filter(|_| self.clear[k]) {
                inside = if inside == Some(m) { None } else { Some(m) };
            }
            t = c.t + self.errors[k].max(c.t.abs() * 1e-12).max(f64::MIN_POSITIVE);
        }
        inside
    }

    /// The light a ray brings from its hit `hit` on dielectric `k`, `depth` bounces made,
    /// inside the medium `inside` (`None`: outside every one), beyond the hit's own shading:
    /// the reflected and refracted rays' colours, weighted.
    pub(super) fn through_dielectric(
        &self,
        ray: &Ray<B::Carrier>,
        hit: &ShadingPoint,
        k: usize,
        (depth, inside): (u32, Option<usize>),
        key: &SampleKey,
        cast: &mut RayCounts,
    ) -> [f64; 3] {
        let settings = &self.scene.settings;
        let mut total = [0.0; 3];
        let mut stack: SmallVec<[Pending<B::Carrier>; 16]> = SmallVec::new();
        let first = Pending { ray: *ray, weight: [1.0; 3], depth, inside };
        self.split(&first, hit, k, &mut stack, cast);
        while let Some(p) = stack.pop() {
            let Some((hit, j)) = self.hit(&p.ray, 0.0, f64::INFINITY) else {
                add_to(&mut total, p.weight, self.sky(p.ray.dir));
                continue;
            };
            let mut p = p;
            if let Some(m) = p.inside {
                // Absorbed on the way through the medium (world units).
                let d = self.scene.frame.world_length(hit.t);
                let a = self.scene.objects[m].material.absorption;
                p.weight = [0, 1, 2].map(|c| p.weight[c] * (-a[c] * d).exp());
            }
            let [local] = self.shade(&p.ray, &[Some((hit, j))], &[*key], cast);
            let material = &self.scene.objects[j].material;
            if p.depth >= settings.max_depth {
                add_to(&mut total, p.weight, local);
            } else if material.dielectric() {
                add_to(&mut total, p.weight, local);
                self.split(&p, &hit, j, &mut stack, cast);
            } else {
                let (own, kr) = self.reflected(local, material.kr);
                add_to(&mut total, p.weight, own);
                if kr > 0.0 {
                    let error = self.errors[j];
                    let (origin, r) = mirror(p.ray.dir, p.ray.origin, hit.point, hit.normal, error);
                    let weight = p.weight.map(|w| w * kr);
                    let next = Pending { ray: B::ray(origin, r), weight, depth: p.depth + 1, inside: p.inside };
                    cast.reflection += u64::from(push(&mut stack, next));
                }
            }
        }
        total
    }

    /// The rays a ray `p` splits into at its hit on dielectric `k`: reflected with weight
    /// `F`, refracted (or, through a flat one, transmitted undeviated) with `1 − F`.
    fn split(
        &self,
        p: &Pending<B::Carrier>,
        hit: &ShadingPoint,
        k: usize,
        stack: &mut SmallVec<[Pending<B::Carrier>; 16]>,
        cast: &mut RayCounts,
    ) {
        let objects = &self.scene.objects;
        let ior = objects[k].material.ior;
        let here = self.medium[k];
        let leaving = here.is_some() && p.inside == here;
        let outside = p.inside.filter(|&m| Some(m) != here).map_or(1.0, |m| objects[m].material.ior);
        let (n1, n2) = if leaving { (ior, 1.0) } else { (outside, ior) };
        // Light bends at the surface itself: a mesh's blended normal only shades.
        let normal = match objects[k].shape.facet(&hit.crossing()) {
            Some(f) if dot(f, p.ray.dir) > 0.0 => scale(f, -1.0),
            Some(f) => f,
            None => hit.normal,
        };
        let (f, refracted) = fresnel(p.ray.dir, normal, n1, n2);
        let error = self.errors[k];
        let (origin, r) = mirror(p.ray.dir, p.ray.origin, hit.point, normal, error);
        let depth = p.depth + 1;
        let reflected = Pending { ray: B::ray(origin, r), weight: p.weight.map(|w| w * f), depth, inside: p.inside };
        cast.reflection += u64::from(push(stack, reflected));
        let Some(t) = refracted else { return };
        let (t, inside) = match (here, leaving) {
            (None, _) => (p.ray.dir, p.inside),
            (Some(_), true) => (t, None),
            (Some(m), false) => (t, Some(m)),
        };
        let start = leaving_origin(hit.point, normal, dot(normal, t), offset(hit.point, p.ray.origin, error));
        let refracted = Pending { ray: B::ray(start, t), weight: p.weight.map(|w| w * (1.0 - f)), depth, inside };
        cast.reflection += u64::from(push(stack, refracted));
    }
}

/// `total += w c`.
fn add_to(total: &mut [f64; 3], w: [f64; 3], c: [f64; 3]) {
    for k in 0..3 {
        total[k] += w[k] * c[k];
    }
}

/// `p` onto the stack unless its weight is below [`CUTOFF`] in every channel; whether it
/// went (a ray dropped is not cast, nor counted).
fn push<C>(stack: &mut SmallVec<[Pending<C>; 16]>, p: Pending<C>) -> bool {
    let kept = p.weight.iter().any(|&w| w >= CUTOFF);
    if kept {
        stack.push(p);
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_at_normal_incidence_and_snell() {
        // ((n1 − n2)/(n1 + n2))² at normal incidence: 0.04 for glass.
        let (f, t) = fresnel([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], 1.0, 1.5);
        assert!((f - 0.04).abs() < 1e-15 && t == Some([0.0, 0.0, -1.0]));
        // Snell: sin θ_t = sin θ_i / 1.5, the ray bent towards the normal.
        let theta = 0.7f64;
        let d = [theta.sin(), 0.0, -theta.cos()];
        let (f, t) = fresnel(d, [0.0, 0.0, 1.0], 1.0, 1.5);
        let t = t.unwrap();
        assert!((t[0] - theta.sin() / 1.5).abs() < 1e-15 && (dot(t, t) - 1.0).abs() < 1e-15);
        assert!(f > 0.04 && f < 0.1, "{f}");
        // Past the critical angle asin(1/1.5) from inside: all reflected.
        let inside = [0.8f64.sin(), 0.0, -0.8f64.cos()];
        assert_eq!(fresnel(inside, [0.0, 0.0, 1.0], 1.5, 1.0), (1.0, None));
        // Grazing: all reflected.
        assert!((fresnel([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0, 1.5).0 - 1.0).abs() < 1e-12);
    }
}
