//! The integrator: nearest hits, Blinn–Phong shading with shadows and attenuation, and
//! recursive mirror reflection (the paper's eq. 12), in linear RGB.
//!
//! `I = c k_a A + Σ_i S_i f_att,i (c k_d max(n·l_i, 0) + k_s max(n·h_i, 0)^q) L_i + k_r I_r`,
//! `A` the ambient intensity, `L_i` the light colours, `S_i` 1 or the scene's shadow
//! transmission when something lies between the point and light `i`, `h_i = unit(l_i + v)`.

use crate::film::Film;
use crate::ray::Ray;
use crate::scene::{Object, Scene};
use crate::shapes::Hit;
use cga_core::euclid::{dot, norm, reflect, scale, sub, unit};
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

impl RayCounts {
    /// `(primary, shadow, reflection)`.
    pub fn get(&self) -> (u64, u64, u64) {
        (self.primary.load(Relaxed), self.shadow.load(Relaxed), self.reflection.load(Relaxed))
    }
}

/// Renders a scene.
pub struct Renderer<'a> {
    scene: &'a Scene,
    /// Rays cast so far.
    pub counts: RayCounts,
}

impl<'a> Renderer<'a> {
    /// A renderer for `scene`.
    pub fn new(scene: &'a Scene) -> Self {
        Renderer { scene, counts: RayCounts::default() }
    }

    /// The nearest hit with `t_min < t < t_max`, and its object: the nearest crossing over
    /// all objects, then its normal, once.
    pub fn nearest(&self, ray: &Ray, t_min: f64, mut t_max: f64) -> Option<(Hit, &'a Object)> {
        let mut best = None;
        for object in &self.scene.objects {
            if let Some(c) = object.shape.intersect(ray, t_min, t_max) {
                t_max = c.t;
                best = Some((c, object));
            }
        }
        let (c, object) = best?;
        let hit = Hit { t: c.t, point: c.point, normal: object.shape.normal(ray, &c), alpha: c.alpha };
        Some((hit, object))
    }

    /// Whether anything lies on the ray before `t_max`: stops at the first blocker, and
    /// computes no normals.
    fn blocked(&self, ray: &Ray, t_max: f64) -> bool {
        self.scene.objects.iter().any(|o| o.shape.intersect(ray, 0.0, t_max).is_some())
    }

    /// The colour seen along `ray`, `depth` bounces deep.
    pub fn trace(&self, ray: &Ray, depth: u32) -> [f64; 3] {
        let settings = &self.scene.settings;
        let Some((hit, object)) = self.nearest(ray, 0.0, f64::INFINITY) else {
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
            if let Some(shadow) = Ray::leaving(hit.point, n, l) {
                self.counts.shadow.fetch_add(1, Relaxed);
                if self.blocked(&shadow, distance) {
                    s = settings.shadow_transmission;
                }
            }
            let [c0, c1, c2] = settings.attenuation;
            let f_att = (1.0 / (c0 + c1 * distance + c2 * distance * distance)).min(1.0);
            for ((out, c), l) in colour.iter_mut().zip(m.colour).zip(light.colour) {
                *out += s * f_att * (c * m.kd * diffuse.max(0.0) + m.ks * specular) * l;
            }
        }
        if m.kr > 0.0 && depth < settings.max_depth {
            if let Some(reflected) = Ray::leaving(hit.point, n, reflect(ray.dir, n)) {
                self.counts.reflection.fetch_add(1, Relaxed);
                let bounced = self.trace(&reflected, depth + 1);
                for (out, b) in colour.iter_mut().zip(bounced) {
                    *out += m.kr * b;
                }
            }
        }
        colour
    }

    /// One pixel: the shaded colour or an AOV.
    pub fn pixel(&self, i: u32, j: u32, aov: Aov) -> [f64; 3] {
        let camera = &self.scene.camera;
        let Some(ray) = camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5) else {
            return self.scene.settings.background;
        };
        self.counts.primary.fetch_add(1, Relaxed);
        match aov {
            Aov::Shaded => self.trace(&ray, 0),
            Aov::Normal => {
                self.nearest(&ray, 0.0, f64::INFINITY).map_or([0.0; 3], |(h, _)| h.normal.map(|x| 0.5 * (x + 1.0)))
            }
            Aov::Alpha => match self.nearest(&ray, 0.0, f64::INFINITY) {
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
                let row = (0..w).map(|i| self.pixel(i, j, aov)).collect();
                on_row();
                row
            })
            .collect();
        Film::from_rows(w, h, rows)
    }
}
