//! Shading written once for one ray and for a packet of four: the ambient term, and per
//! light the direction, Blinn–Phong terms, the shadow rays (cast together) and attenuation
//! (eq. 12 without the reflected term), over lanes ([`RayLanes`]). One ray and four take
//! the same steps, so `--no-packets` gives the same bits.

use super::{Dimension, Points, RayCounts, Renderer, SampleKey, disk};
use crate::backend::{Backend, RayLanes, lanes3};
use crate::light::{Light, Source, attenuation, blinn_phong, lights};
use crate::material::{Material, Reflectance, shine};
use crate::ray::{leaving_origin, offset};
use crate::shapes::ShadingPoint;
use crate::shapes::Unit;
use crate::texture::Pattern;
use cga_core::euclid::{E3, add, dot, norm, scale, sub};
use cga_core::simd::Lane;
use cga_core::{Real, Select};

/// `x` in the lanes where `keep`, `other` elsewhere.
#[inline(always)]
fn select3<T: Lane, const W: usize>(keep: &[bool; W], x: E3<T>, other: E3) -> E3<T> {
    let pick = |k: usize| T::from_fn(|l| if keep[l] { x[k].lane(l) } else { other[k] });
    [pick(0), pick(1), pick(2)]
}

/// `f` of each lane's hit and object, 0 where a lane has none.
#[inline(always)]
fn by_lane<T: Lane, const W: usize>(
    hits: &[Option<(ShadingPoint, usize)>; W],
    f: impl Fn(&ShadingPoint, usize) -> f64,
) -> T {
    T::from_fn(|l| hits[l].as_ref().map_or(0.0, |(h, k)| f(h, *k)))
}

/// A material for lanes without a hit (their terms are not used).
const NO_MATERIAL: Material = crate::material::NONE;

impl<B: Backend> Renderer<'_, B> {
    /// The ambient and direct light at the rays' hits (object index per lane), the shadow
    /// rays towards each light cast together (a flat object's own skipped, each starting off
    /// its hit by the object's crossing error); the background where a lane has no hit:
    /// `c k_a A + Σ_i S_i f_att,i (c k_d max(n·l_i, 0) + k_s max(n·h_i, 0)^q) L_i`.
    #[inline(always)]
    pub(crate) fn shade<R: RayLanes<B, W>, const W: usize>(
        &self,
        rays: &R,
        hits: &[Option<(ShadingPoint, usize)>; W],
        keys: &[SampleKey; W],
        cast: &mut RayCounts,
    ) -> [[f64; 3]; W] {
        let (settings, objects) = (&self.scene.settings, &self.scene.objects);
        // Textured objects' materials with the texture's colour at the hit.
        let mut tinted = [NO_MATERIAL; W];
        let mut textured = [false; W];
        if self.textured {
            for l in 0..W {
                if let Some((hit, k)) = &hits[l]
                    && let Some(colour) = self.textured_colour(hit, *k)
                {
                    (tinted[l], textured[l]) = (Material { colour, ..objects[*k].material }, true);
                }
            }
        }
        let m: [&Material; W] = core::array::from_fn(|l| match &hits[l] {
            _ if textured[l] => &tinted[l],
            Some((_, k)) => &objects[*k].material,
            None => &NO_MATERIAL,
        });
        // Arrays built by index, not by `map`: LLVM leaves `map` over these arrays out of
        // line, outside the AVX2 code.
        let mut colours: [[f64; 3]; W] =
            core::array::from_fn(|l| hits[l].as_ref().map_or(settings.background, |_| self.ambient(m[l])));
        if !hits.iter().any(Option::is_some) {
            return colours;
        }
        let x: E3<R::T> =
            [by_lane(hits, |h, _| h.point[0]), by_lane(hits, |h, _| h.point[1]), by_lane(hits, |h, _| h.point[2])];
        let n: E3<R::T> =
            [by_lane(hits, |h, _| h.normal[0]), by_lane(hits, |h, _| h.normal[1]), by_lane(hits, |h, _| h.normal[2])];
        let shading = if self.textured { self.bumped(hits) } else { None };
        let v = rays.dir().map(|d| -d);
        let own: [Option<usize>; W] = core::array::from_fn(|l| hits[l].as_ref().and_then(|(_, k)| self.skip_own(*k)));
        let offset = offset(x, rays.origin(), by_lane(hits, |_, k| self.errors[k]));
        let hit: [bool; W] = core::array::from_fn(|l| hits[l].is_some());
        let hits_at = Hits { x, n, shading, v, m: &m, hit: &hit, own: &own, offset };
        for light in &self.scene.lights {
            match light.samples() {
                None => self.add_light::<R, W>(&mut colours, light, light.toward(x), None, &hits_at, cast),
                Some(samples) => {
                    // Each lane's own points on the light, stratified over the pixel's samples.
                    let weight = Some(1.0 / f64::from(samples));
                    let points: [Points; W] = core::array::from_fn(|l| keys[l].points(Dimension::Light, samples));
                    for k in 0..samples {
                        let square: [(f64, f64); W] = core::array::from_fn(|l| points[l].at(k));
                        let on_disk = disk((R::T::from_fn(|l| square[l].0), R::T::from_fn(|l| square[l].1)));
                        let towards = toward(light.area_points::<R::T, W>(x, on_disk), x);
                        self.add_light::<R, W>(&mut colours, light, towards, weight, &hits_at, cast);
                    }
                }
            }
        }
        colours
    }

    /// One light's term at the hits, from the direction and distance `towards` it (a point of
    /// it, for an area light, whose points each add `weight` of its colour), shadowed.
    #[inline(always)]
    fn add_light<R: RayLanes<B, W>, const W: usize>(
        &self,
        colours: &mut [[f64; 3]; W],
        light: &Light,
        towards: (E3<R::T>, R::T),
        weight: Option<f64>,
        at: &Hits<'_, R::T, W>,
        cast: &mut RayCounts,
    ) {
        let settings = &self.scene.settings;
        let Some(Lit { lit, l, distance, diffuse, specular, cone, shadow_origin }) =
            lit(light, towards, (at.x, at.n, at.v), at.m, at.hit, at.offset)
        else {
            return;
        };
        // A bump tilts the normal the light's terms see; which lanes it lights and where
        // their shadow rays start stay the surface's own.
        let (diffuse, specular) = match at.shading {
            Some(n) => (dot(n, l), shine(at.m, n, add(l, at.v))),
            None => (diffuse, specular),
        };
        let mut s = R::T::one();
        if settings.shadows {
            cast.shadow += lit.iter().filter(|&&b| b).count() as u64;
            // Unlit lanes cast a harmless ray with an empty range.
            let shadow = R::cast(select3(&lit, shadow_origin, [0.0; 3]), select3(&lit, l, [0.0, 0.0, 1.0]));
            let t_max = core::array::from_fn(|k| if lit[k] { distance.lane(k) } else { 0.0 });
            let blocked = self.blocked(&shadow, &t_max, at.own);
            s = R::T::from_fn(|k| if blocked[k] { settings.shadow_transmission } else { 1.0 });
        }
        let mut s = s * cone;
        if let Some(w) = weight {
            s = s * R::T::from_f64(w);
        }
        let term = self.light(&Reflectance::lanes(at.m), light, distance, diffuse, specular, s);
        for (k, colour) in colours.iter_mut().enumerate().filter(|(k, _)| lit[*k]) {
            for (out, t) in colour.iter_mut().zip(&term) {
                *out += t.lane(k);
            }
        }
    }

    /// `c k_a A`: the ambient light on a material.
    pub(crate) fn ambient(&self, material: &Material) -> [f64; 3] {
        scale(material.colour, material.ka * self.scene.settings.ambient)
    }

    /// The colour object `k`'s texture gives it at `hit`, where it has one and the shape has
    /// parameters there (lengths in world units).
    fn textured_colour(&self, hit: &ShadingPoint, k: usize) -> Option<[f64; 3]> {
        let object = &self.scene.objects[k];
        let texture = object.texture.as_ref().filter(|t| !matches!(t.pattern, Pattern::Plain))?;
        let crossing = hit.crossing();
        let (uv, unit) = object.shape.uv(&crossing)?;
        let uv = match unit {
            Unit::Fraction => uv,
            Unit::Length => uv.map(|x| self.scene.frame.world_length(x)),
        };
        Some(texture.colour_on(object.material.colour, uv, object.shape.v_up()))
    }

    /// The shading normals of the hits where some lane's texture has a bump
    /// ([`crate::texture::Texture::shading_normal`]; the others' own normals); `None` where
    /// none has.
    fn bumped<T: Lane, const W: usize>(&self, hits: &[Option<(ShadingPoint, usize)>; W]) -> Option<E3<T>> {
        let bumps = |k: usize| self.scene.objects[k].texture.as_ref().filter(|t| t.bump.is_some());
        if !hits.iter().flatten().any(|(_, k)| bumps(*k).is_some()) {
            return None;
        }
        let normal = |l: usize| match &hits[l] {
            Some((hit, k)) => bumps(*k).map_or(hit.normal, |texture| {
                let object = &self.scene.objects[*k];
                let crossing = hit.crossing();
                texture.shading_normal(&*object.shape, &crossing, hit.normal, self.scene.frame.scale)
            }),
            None => [0.0; 3],
        };
        Some(lanes3::<T, W>(core::array::from_fn(normal)))
    }

    /// One light's term, `s f_att (c k_d max(n·l, 0) + k_s spec) L`, at `distance` (frame
    /// units) with `diffuse = n·l`, `specular = max(n·h, 0)^q` and shadow factor `s`: for one
    /// ray, or lane by lane for a packet (the same steps, so the same bits).
    #[inline(always)]
    pub(crate) fn light<T: Select>(
        &self,
        m: &Reflectance<T>,
        light: &Light,
        distance: T,
        diffuse: T,
        specular: T,
        s: T,
    ) -> [T; 3] {
        // Attenuation is in world units; the frame's are `frame.scale` of them.
        let f_att = attenuation(self.scene.settings.attenuation, self.scene.frame.world_length(distance));
        blinn_phong(m.colour, m.kd, m.ks, diffuse, specular, s * f_att, light.colour)
    }
}

/// The hits in lanes that shading lights: points, unit normals (and bumped ones), directions to the eye,
/// materials, which lanes hit, the objects their shadow rays skip, and how far off the
/// surfaces those start.
pub(crate) struct Hits<'a, T, const W: usize> {
    x: E3<T>,
    n: E3<T>,
    /// The normals lights see where a bump tilts them ([`Renderer::bumped`]).
    shading: Option<E3<T>>,
    v: E3<T>,
    m: &'a [&'a Material; W],
    hit: &'a [bool; W],
    own: &'a [Option<usize>; W],
    offset: T,
}

/// The unit directions from points `x` towards points `p` and the distances (one square
/// root for both).
#[inline(always)]
fn toward<T: Real>(p: E3<T>, x: E3<T>) -> (E3<T>, T) {
    let to_light = sub(p, x);
    let distance = norm(to_light);
    (scale(to_light, T::one() / distance), distance)
}

/// What one light gives hits in lanes before shadowing.
pub(crate) struct Lit<T, const W: usize> {
    /// Which lanes it lights: a hit, the light ahead of it and in front of the surface for
    /// the diffuse or the specular term.
    pub lit: [bool; W],
    /// Unit direction to the light.
    pub l: E3<T>,
    /// Distance to it (frame units; ∞ for a directional light).
    pub distance: T,
    /// `n · l`.
    pub diffuse: T,
    /// `max(n · h, 0)^q`.
    pub specular: T,
    /// How much of it reaches the hits ([`Light::cone`]: 1 but for a spot light).
    pub cone: T,
    /// Where the shadow rays towards it start ([`leaving_origin`]).
    pub shadow_origin: E3<T>,
}

/// The unshadowed terms of `light` at hits `x` (unit normals `n`, materials `m`, `hit` where
/// a lane has one) seen from `v`, the light (or its point) lying along the unit `l` at
/// `distance` ([`Light::toward`]), shadow rays starting `offset` off the surfaces; `None`
/// where it lights no lane.
#[inline(always)]
pub(crate) fn lit<T: Lane, const W: usize>(
    light: &Light,
    (l, distance): (E3<T>, T),
    (x, n, v): (E3<T>, E3<T>, E3<T>),
    m: &[&Material; W],
    hit: &[bool; W],
    offset: T,
) -> Option<Lit<T, W>> {
    let diffuse = dot(n, l);
    let specular = shine(m, n, add(l, v));
    let lighting = lights(distance, diffuse, specular);
    // Only a spot light's cone darkens anything (kept off the other lights' path).
    let (cone, lighting) = match light.source {
        Source::Spot { .. } => {
            let cone = light.cone(l);
            (cone, lighting & T::zero().lt(cone))
        }
        _ => (T::one(), lighting),
    };
    let lit: [bool; W] = core::array::from_fn(|k| hit[k] && T::mask_lane(lighting, k));
    let shadow_origin = leaving_origin(x, n, diffuse, offset);
    lit.iter().any(|&b| b).then_some(Lit { lit, l, distance, diffuse, specular, cone, shadow_origin })
}
