//! The integrator: nearest hits, Blinn–Phong shading with shadows and attenuation, and
//! recursive mirror reflection (the paper's eq. 12), in linear RGB.
//!
//! `I = c k_a A + Σ_i S_i f_att,i (c k_d max(n·l_i, 0) + k_s max(n·h_i, 0)^q) L_i + k_r I_r`,
//! `A` the ambient intensity, `L_i` the light colours, `S_i` 1 or the scene's shadow
//! transmission when something lies between the point and light `i`, `h_i = unit(l_i + v)`.

use crate::backend::{Backend, Sparse};
use crate::bvh::Bvh;
use crate::film::Film;
use crate::ray::{Ray, crosses, leaving_origin};
use crate::scene::{Object, Scene};
use crate::shapes::{Crossing, Hit};
use cga_core::euclid::{E3, dot, norm, reflect, scale, sub, unit};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// What an image shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Aov {
    /// The shaded image.
    #[default]
    Shaded,
    /// False-colour normals of the first hit, `(n + 1) / 2`.
    Normal,
    /// The α of evolved-surface hits, blue (α = 0) to red (α = 1); black elsewhere.
    Alpha,
}

/// Crossings nearer than this (in the frame's units, about the scene's size) are the ray's
/// own origin: a camera standing on a plane or sphere, whose crossing at `t ≈ 0` rounds to
/// either side. Secondary rays start off their surface by more than this.
pub const T_MIN: f64 = 1e-9;

/// Scenes with at least this many bounded objects are traversed through a [`Bvh`]; fewer
/// are tested one by one (cheaper than any traversal).
const BVH_FROM: usize = 8;

/// Rays cast, by kind.
#[derive(Debug, Default)]
pub struct RayCounts {
    /// From the camera.
    pub primary: AtomicU64,
    /// Towards lights.
    pub shadow: AtomicU64,
    /// Mirror bounces.
    pub reflection: AtomicU64,
}

/// Rays cast by one thread, added to the shared [`RayCounts`] once per row.
#[derive(Clone, Copy, Debug, Default)]
struct Cast {
    primary: u64,
    shadow: u64,
    reflection: u64,
}

impl RayCounts {
    fn add(&self, cast: &Cast) {
        self.primary.fetch_add(cast.primary, Relaxed);
        self.shadow.fetch_add(cast.shadow, Relaxed);
        self.reflection.fetch_add(cast.reflection, Relaxed);
    }

    /// `(primary, shadow, reflection)`.
    pub fn get(&self) -> (u64, u64, u64) {
        (self.primary.load(Relaxed), self.shadow.load(Relaxed), self.reflection.load(Relaxed))
    }
}

/// Renders a scene with the geometry of back end `B` (by default the generated sparse types).
pub struct Renderer<'a, B: Backend = Sparse> {
    scene: &'a Scene,
    /// The objects in `B`'s form, in scene order.
    shapes: Vec<B::Shape>,
    /// Bounding spheres of the objects worth culling ([`Shape::cull`](crate::shapes::Shape::cull)).
    bounds: Vec<Option<(E3, f64)>>,
    /// For scenes of many objects, a hierarchy over all bounded ones.
    bvh: Option<Bvh>,
    /// Rays cast so far.
    pub counts: RayCounts,
}

impl<'a> Renderer<'a> {
    /// A renderer for `scene` on the sparse back end.
    pub fn new(scene: &'a Scene) -> Self {
        Renderer::with_backend(scene)
    }
}

impl<'a, B: Backend> Renderer<'a, B> {
    /// A renderer for `scene` on back end `B`: every object prepared once.
    pub fn with_backend(scene: &'a Scene) -> Self {
        let shapes = scene.objects.iter().map(|o| B::prepare(&o.shape)).collect();
        let all: Vec<_> = scene.objects.iter().map(|o| o.shape.bounds()).collect();
        let bvh = (all.iter().flatten().count() >= BVH_FROM).then(|| Bvh::new(&all));
        let cull = |(o, b): (&Object, &Option<(E3, f64)>)| b.filter(|_| o.shape.cull());
        let bounds = scene.objects.iter().zip(&all).map(cull).collect();
        Renderer { scene, shapes, bounds, bvh, counts: RayCounts::default() }
    }

    /// The same renderer testing every object for every ray, without the hierarchy (to
    /// measure what the hierarchy saves).
    pub fn without_bvh(mut self) -> Self {
        self.bvh = None;
        self
    }

    /// The nearest crossing with `t_min < t < t_max` over all objects, and the object's index.
    fn crossing(&self, ray: &Ray<B::Carrier>, t_min: f64, mut t_max: f64) -> Option<(Crossing, usize)> {
        let mut best = None;
        if let Some(bvh) = &self.bvh {
            bvh.traverse(ray.origin, ray.dir, t_min, t_max, |k, t_max| {
                let c = B::intersect(&self.shapes[k], ray, t_min, t_max);
                Some(c.map_or(t_max, |c| {
                    best = Some((c, k));
                    c.t
                }))
            });
            return best;
        }
        for (k, shape) in self.shapes.iter().enumerate() {
            if self.bounds[k].is_some_and(|(c, r)| !crosses(ray, c, r, t_min, t_max)) {
                continue;
            }
            if let Some(c) = B::intersect(shape, ray, t_min, t_max) {
                t_max = c.t;
                best = Some((c, k));
            }
        }
        best
    }

    /// The nearest hit with `t_min < t < t_max`, and its object: the nearest crossing over
    /// all objects, then its normal, once.
    pub fn nearest(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(Hit, &'a Object)> {
        let (c, k) = self.crossing(ray, t_min, t_max)?;
        let hit = Hit { t: c.t, point: c.point, normal: B::normal(&self.shapes[k], ray, &c), alpha: c.alpha };
        Some((hit, &self.scene.objects[k]))
    }

    /// Whether anything lies on the ray before `t_max`: stops at the first blocker, and
    /// computes no normals.
    fn blocked(&self, ray: &Ray<B::Carrier>, t_max: f64) -> bool {
        if let Some(bvh) = &self.bvh {
            let mut blocked = false;
            bvh.traverse(ray.origin, ray.dir, 0.0, t_max, |k, t| {
                blocked = B::intersect(&self.shapes[k], ray, 0.0, t).is_some();
                (!blocked).then_some(t)
            });
            return blocked;
        }
        self.shapes.iter().zip(&self.bounds).any(|(shape, bound)| {
            bound.is_none_or(|(c, r)| crosses(ray, c, r, 0.0, t_max)) && B::intersect(shape, ray, 0.0, t_max).is_some()
        })
    }

    /// The colour seen along `ray`, `depth` bounces deep.
    pub fn trace(&self, ray: &Ray<B::Carrier>, depth: u32) -> [f64; 3] {
        let mut cast = Cast::default();
        let colour = self.trace_counted(ray, depth, &mut cast);
        self.counts.add(&cast);
        colour
    }

    /// [`Renderer::trace`], counting the rays cast into `cast` (shared counters would be
    /// contended by every thread on every ray).
    fn trace_counted(&self, ray: &Ray<B::Carrier>, depth: u32, cast: &mut Cast) -> [f64; 3] {
        let settings = &self.scene.settings;
        let Some((hit, object)) = self.nearest(ray, T_MIN, f64::INFINITY) else {
            return settings.background;
        };
        let m = &object.material;
        let (n, v) = (hit.normal, ray.dir.map(|x| -x));
        let mut colour = scale(m.colour, m.ka * settings.ambient);
        for light in &self.scene.lights {
            let to_light = sub(light.position, hit.point);
            let distance = norm(to_light);
            let Some(l) = unit(to_light) else { continue };
            let (diffuse, h) = (dot(n, l), unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]));
            let specular = h.map_or(0.0, |h| dot(n, h).max(0.0).powf(m.q));
            if diffuse <= 0.0 && specular <= 0.0 {
                continue;
            }
            let mut s = 1.0;
            if settings.shadows
                && let Some(shadow) = B::ray(leaving_origin(hit.point, n, l), l)
            {
                cast.shadow += 1;
                if self.blocked(&shadow, distance) {
                    s = settings.shadow_transmission;
                }
            }
            // Attenuation is in world units; the frame's are `frame.scale` of them.
            let distance = self.scene.frame.world_length(distance);
            let [c0, c1, c2] = settings.attenuation;
            let f_att = (1.0 / (c0 + c1 * distance + c2 * distance * distance)).min(1.0);
            for ((out, c), l) in colour.iter_mut().zip(m.colour).zip(light.colour) {
                *out += s * f_att * (c * m.kd * diffuse.max(0.0) + m.ks * specular) * l;
            }
        }
        if m.kr > 0.0 && depth < settings.max_depth {
            let r = reflect(ray.dir, n);
            if let Some(reflected) = B::ray(leaving_origin(hit.point, n, r), r) {
                cast.reflection += 1;
                let bounced = self.trace_counted(&reflected, depth + 1, cast);
                for (out, b) in colour.iter_mut().zip(bounced) {
                    *out += m.kr * b;
                }
            }
        }
        colour
    }

    /// One pixel: the shaded colour or an AOV.
    pub fn pixel(&self, i: u32, j: u32, aov: Aov) -> [f64; 3] {
        let mut cast = Cast::default();
        let colour = self.pixel_counted(i, j, aov, &mut cast);
        self.counts.add(&cast);
        colour
    }

    fn pixel_counted(&self, i: u32, j: u32, aov: Aov, cast: &mut Cast) -> [f64; 3] {
        let camera = &self.scene.camera;
        let Some(ray) = B::camera_ray(camera, f64::from(i) + 0.5, f64::from(j) + 0.5) else {
            return self.scene.settings.background;
        };
        cast.primary += 1;
        match aov {
            Aov::Shaded => self.trace_counted(&ray, 0, cast),
            Aov::Normal => {
                self.nearest(&ray, T_MIN, f64::INFINITY).map_or([0.0; 3], |(h, _)| h.normal.map(|x| 0.5 * (x + 1.0)))
            }
            Aov::Alpha => match self.nearest(&ray, T_MIN, f64::INFINITY) {
                Some((Hit { alpha: Some(a), .. }, _)) => [a, 0.2, 1.0 - a],
                _ => [0.0; 3],
            },
        }
    }

    /// The whole image, rows in parallel on rayon's pool; `on_row` is called as each row
    /// finishes (for a progress bar).
    pub fn render(&self, aov: Aov, on_row: &(dyn Fn() + Sync)) -> Film {
        let (w, h) = (self.scene.camera.width, self.scene.camera.height);
        let rows: Vec<Vec<[f64; 3]>> = (0..h)
            .into_par_iter()
            .map(|j| {
                let mut cast = Cast::default();
                let row = (0..w).map(|i| self.pixel_counted(i, j, aov, &mut cast)).collect();
                self.counts.add(&cast);
                on_row();
                row
            })
            .collect();
        Film::from_rows(w, h, rows)
    }
}
