//! The integrator: nearest hits, Blinn–Phong shading with shadows and attenuation, and
//! recursive mirror reflection (the paper's eq. 12), in linear RGB, written once over rays in
//! lanes ([`RayLanes`](crate::backend::RayLanes)): one ray, or a packet of four.
//!
//! `I = c k_a A + Σ_i S_i f_att,i (c k_d max(n·l_i, 0) + k_s max(n·h_i, 0)^q) L_i + k_r I_r`,
//! `A` the ambient intensity, `L_i` the light colours, `S_i` 1 or the scene's shadow
//! transmission when something lies between the point and light `i`, `h_i = unit(l_i + v)`.
//!
//! - this file: the [`Renderer`], the image and its rows ([`Window`]);
//! - `sampler.rs`: pixels, their samples ([`sample_offset`]) and the camera rays;
//! - `keep.rs`: what a pixel keeps of its samples (colours, and coverage over a transparent
//!   background);
//! - `trace.rs`: the bounce loop, the sum of layers;
//! - `nearest.rs`: the nearest crossing and the shadow test;
//! - `shade.rs`: the ambient and each light's term;
//! - `aov.rs`: what an image shows ([`Aov`]);
//! - `counts.rs`: the rays cast ([`RayCounts`]).

mod adaptive;
mod aov;
#[cfg(target_arch = "x86_64")]
mod avx;
mod corners;
mod counts;
mod glass;
mod keep;
mod media;
mod nearest;
mod prepared;
mod sampler;
mod shade;
mod trace;

pub use aov::Aov;
pub use counts::RayCounts;
pub use glass::{CUTOFF, fresnel};
use keep::{Covered, Keep, Taken};
pub use prepared::Kept;
pub use sampler::sample_offset;
pub(crate) use sampler::{Dimension, Points, SampleKey, disk};

use crate::backend::{Backend, Sparse};
use crate::bvh::Layers;
use crate::film::{Channels, Film};
use crate::ray::Ray;
use crate::scene::Scene;
use crate::settings::AdaptiveMethod;
use cga_core::euclid::E3;
use rayon::prelude::*;
use std::borrow::Cow;
use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// Scenes with at least this many bounded objects are traversed through a [`Bvh`](crate::bvh::Bvh); fewer
/// are tested one by one (cheaper than any traversal).
const BVH_FROM: usize = 8;

/// Renders a scene with the geometry of back end `B` (by default the generated sparse types).
pub struct Renderer<'a, B: Backend = Sparse> {
    pub(crate) scene: &'a Scene,
    /// The objects in `B`'s form, in scene order.
    pub(crate) shapes: Cow<'a, [B::Shape]>,
    /// Whether rays go four at a time through packets: where `B` has them, unless switched
    /// off or the scene has a hierarchy.
    pub(crate) packets: bool,
    /// Whether packets may run in AVX registers where the CPU has AVX2 ([`Renderer::pixels4`]).
    pub(crate) avx2: bool,
    /// Bounding spheres of the objects (`None`: unbounded).
    pub(crate) all: Cow<'a, [Option<(E3, f64)>]>,
    /// Bounding spheres of the objects worth culling ([`Shape::cull`](crate::shapes::Shape::cull)).
    pub(crate) bounds: Cow<'a, [Option<(E3, f64)>]>,
    /// For scenes of many objects, a hierarchy over all bounded ones.
    pub(crate) bvh: Option<Layers>,
    /// Which objects are [flat](crate::shapes::Shape::flat): their own shadow rays skip them.
    pub(crate) flat: Cow<'a, [bool]>,
    /// For each object, the solid it bounds as a dielectric, named by its first object (itself,
    /// or a closed mesh's first triangle); `None` for a thin sheet (flat, and no part of a
    /// closed solid), which light passes undeviated.
    pub(crate) medium: Cow<'a, [Option<usize>]>,
    /// The dielectric solid that holds the camera, if any ([`media::medium_at`]): a pinhole's
    /// rays start in it; a lens sample's or an orthographic view's, wherever the surfaces
    /// between the camera and their origin put them ([`Renderer::origin_medium`]).
    pub(crate) camera_medium: Option<usize>,
    /// Whether any object is a dielectric (only then can a camera ray start inside one).
    pub(crate) dielectrics: bool,
    /// Which objects are dielectrics: shadow rays pass them (as POV-Ray's through clear
    /// glass), caustics not being traced.
    pub(crate) clear: Cow<'a, [bool]>,
    /// Whether any object has a texture (shading then looks each hit's up).
    pub(crate) textured: bool,
    /// Each object's [crossing error](crate::shapes::Shape::crossing_error): no ray counts a
    /// crossing nearer than it, and secondary rays start off the surface by a multiple of it.
    pub(crate) errors: Cow<'a, [f64]>,
    /// The largest of `errors`.
    pub(crate) largest_error: f64,
    /// Which of two surfaces met in one place (within their crossing errors) shows: lower
    /// wins. An opaque surface before a dielectric (a ray inside a glass box resting on a
    /// floor meets the floor, not the box's face with nothing under it), then the smaller
    /// bounding sphere (a disk lying on a floor shows, as a decal does); last, the object
    /// declared first.
    pub(crate) tie: Cow<'a, [(bool, f64, usize)]>,
    /// Rays cast so far, `[primary, shadow, reflection]`: each thread adds its row's
    /// [`RayCounts`] once.
    counted: [AtomicU64; 3],
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
        let parts = prepared::Prepared::<B>::parts_of(&scene.objects);
        Renderer::from_parts(scene, parts, &mut crate::bvh::Kept::default())
    }

    /// [`Renderer::with_backend`], taking from `kept` what was prepared for the last picture
    /// of the scene (the same scene at another instant) for every object that is the same,
    /// and the hierarchy over the objects that do not move where they have not; left there
    /// for the next.
    pub fn keeping(scene: &'a Scene, kept: &'a mut Kept) -> Self {
        let (parts, hierarchy) = kept.prepared::<B>(&scene.objects);
        Renderer::from_parts(scene, parts, hierarchy)
    }

    /// A renderer of `scene` from its objects as prepared, its hierarchy from `hierarchy`.
    fn from_parts(scene: &'a Scene, p: prepared::Parts<'a, B>, hierarchy: &mut crate::bvh::Kept) -> Self {
        let bounded = p.all.iter().flatten().count();
        let bvh = (bounded >= BVH_FROM).then(|| hierarchy.layers(&p.all, &p.moving, !p.still_changed));
        // Packets test every object: for scenes with a hierarchy, single rays through it.
        let packets = B::PACKETS && bvh.is_none();
        let textured = scene.objects.iter().any(|o| o.texture.is_some());
        let largest_error = p.errors.iter().copied().fold(0.0, f64::max);
        let dielectrics = p.clear.iter().any(|&c| c);
        let camera_medium = if dielectrics {
            media::medium_at(&scene.objects, &p.medium, &p.errors, scene.camera.position())
        } else {
            None
        };
        let prepared::Parts { shapes, all, cull: bounds, flat, clear, errors, tie, medium, .. } = p;
        Renderer {
            scene,
            shapes,
            all,
            packets,
            avx2: true,
            bounds,
            bvh,
            flat,
            medium,
            camera_medium,
            dielectrics,
            clear,
            textured,
            errors,
            largest_error,
            tie,
            counted: Default::default(),
        }
    }

    /// Whether back end `B` renders every object as it is ([`crate::backend::holds`]).
    pub fn holds(&self) -> Result<(), String> {
        crate::backend::holds_bounds::<B>(self.all.iter().flatten().copied())
    }

    /// The rays cast so far, by kind.
    pub fn counts(&self) -> RayCounts {
        let [primary, shadow, reflection] = self.counted.each_ref().map(|c| c.load(Relaxed));
        RayCounts { primary, shadow, reflection }
    }

    /// Adds one thread's tally.
    fn count(&self, cast: &RayCounts) {
        for (total, n) in self.counted.iter().zip(cast.to_array()) {
            total.fetch_add(n, Relaxed);
        }
    }

    /// The same renderer tracing one ray at a time, without packets (to compare them).
    pub fn without_packets(mut self) -> Self {
        self.packets = false;
        self
    }

    /// The same renderer tracing its packets on four-lane arrays ([`F64x4`](cga_core::simd::F64x4))
    /// compiled for the baseline CPU, as on a CPU without AVX2, even where this one has it
    /// (to compare the two lane types).
    pub fn without_avx2(mut self) -> Self {
        self.avx2 = false;
        self
    }

    /// The same renderer testing every object for every ray, without the hierarchy (to
    /// measure what the hierarchy saves).
    pub fn without_bvh(mut self) -> Self {
        self.bvh = None;
        self
    }

    /// Where object `k`'s crossings start to count on a ray whose range starts at `t_min`:
    /// beyond the object's own crossing error (a ray leaving it, or a camera standing on it,
    /// meets it there only by rounding).
    #[inline(always)]
    pub(crate) fn t_min(&self, k: usize, t_min: f64) -> f64 {
        let e = self.errors[k];
        if e > t_min { e } else { t_min }
    }

    /// Object `k` if its shape is flat (its own shadow rays need not test it).
    pub(crate) fn skip_own(&self, k: usize) -> Option<usize> {
        self.flat[k].then_some(k)
    }

    /// The whole image, rows in parallel on rayon's pool; `on_row` is called as each row
    /// finishes (for a progress bar).
    pub fn render(&self, aov: Aov, on_row: &(dyn Fn() + Sync)) -> Film {
        let camera = &self.scene.camera;
        self.render_window(aov, Window::full(camera.width, camera.height), on_row)
    }

    /// The pixels of `window` only, as an image of its size. Every pixel depends on its
    /// position alone (and, under adaptive sampling, its neighbours' first samples, placed by
    /// theirs), so windows of a frame rendered anywhere assemble into the frame, byte for
    /// byte, and any thread count gives the same bytes. A shaded picture over a transparent
    /// background carries its coverage ([`Aov::covered`]).
    pub fn render_window(&self, aov: Aov, window: Window, on_row: &(dyn Fn() + Sync)) -> Film {
        // Chosen once: an opaque picture's samples keep only their colours.
        match aov.covered(&self.scene.settings) {
            false => self.render_kept::<Taken>(aov, window, on_row),
            true => self.render_kept::<Covered>(aov, window, on_row),
        }
    }

    /// [`Renderer::render_window`] with each pixel's samples kept by `K`.
    fn render_kept<K: Keep>(&self, aov: Aov, window: Window, on_row: &(dyn Fn() + Sync)) -> Film {
        let settings = &self.scene.settings;
        if let Some(a) = settings.adaptive.filter(|a| aov == Aov::Shaded && a.adapts(settings.spp)) {
            return match a.method {
                AdaptiveMethod::Samples => self.render_adaptive::<K>(a, window, on_row),
                AdaptiveMethod::Corners => self.render_corners::<K>(a, window, on_row),
            };
        }
        let (width, height) = (window.columns.len(), window.rows.len());
        // One allocation, each row written in place by whichever thread renders it.
        let mut pixels = vec![K::Pixel::default(); width * height];
        // One row per task: rayon otherwise splits the image into few large pieces, and rows
        // differ in cost (mirrors, surfaces), so one thread idles at the end.
        pixels.par_chunks_mut(width).with_max_len(1).zip(window.rows.clone()).for_each(|(row, j)| {
            let mut cast = RayCounts::default();
            let mut done = 0;
            if aov == Aov::Shaded && self.packets {
                for (four, i0) in row.chunks_exact_mut(4).zip(window.columns.clone().step_by(4)) {
                    let Some(colours) = self.pixels4::<K>(i0, j, &mut cast) else { break };
                    four.copy_from_slice(&colours);
                    done += 4;
                }
            }
            for (pixel, i) in row.iter_mut().zip(window.columns.clone()).skip(done) {
                *pixel = self.pixel_counted::<K>(i, j, aov, &mut cast);
            }
            self.count(&cast);
            on_row();
        });
        K::Pixel::film(width as u32, height as u32, pixels)
    }
}

impl<B: Backend> Renderer<'_, B> {
    /// The colour (or AOV) of each of `samples` (pixel `(i, j)`'s sample `s`, placed as in
    /// [`Renderer::render_window`]), in parallel on rayon's pool, neighbours of the list four
    /// at a time through packets: what one instant of a shutter takes ([`crate::shutter`]).
    /// Over a transparent background, the colours of samples that meet nothing are those
    /// they would see (the environment, or black): [`Renderer::render_covered_samples`] gives
    /// their coverage.
    pub fn render_samples(&self, aov: Aov, samples: &[[u32; 3]]) -> Vec<[f64; 3]> {
        self.render_kept_samples::<Taken>(aov, samples)
    }

    /// [`Renderer::render_samples`] over a transparent background: each sample's colour
    /// premultiplied by its coverage, and the coverage (1 where its camera ray met something,
    /// 0 where it did not: then no colour).
    pub fn render_covered_samples(&self, aov: Aov, samples: &[[u32; 3]]) -> Vec<[f64; 4]> {
        self.render_kept_samples::<Covered>(aov, samples)
    }

    /// The values of `samples`, each as `K` gives one sample's.
    fn render_kept_samples<K: Keep>(&self, aov: Aov, samples: &[[u32; 3]]) -> Vec<K::Pixel> {
        const CHUNK: usize = 256;
        let mut colours = vec![K::Pixel::default(); samples.len()];
        colours.par_chunks_mut(CHUNK).zip(samples.par_chunks(CHUNK)).for_each(|(out, samples)| {
            let mut cast = RayCounts::default();
            let mut done = 0;
            if aov == Aov::Shaded && self.packets {
                for (four, samples) in out.chunks_exact_mut(4).zip(samples.chunks_exact(4)) {
                    let Some(c) = self.listed4::<K>(samples.try_into().expect("four"), &mut cast) else { break };
                    four.copy_from_slice(&c);
                    done += 4;
                }
            }
            for (colour, &sample) in out.iter_mut().zip(samples).skip(done) {
                *colour = self
                    .listed::<Ray<B::Carrier>, 1, K>([sample], aov, &mut cast)
                    .map_or(K::empty(self.scene.settings.background), |[c]| c);
            }
            self.count(&cast);
        });
        colours
    }
}

/// A rectangle of pixels: `columns` from the left, `rows` from the bottom (the film's
/// `(0, 0)` is bottom-left).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Window {
    /// Pixel columns `i`.
    pub columns: Range<u32>,
    /// Pixel rows `j`, counted from the bottom.
    pub rows: Range<u32>,
}

impl Window {
    /// The whole `width × height` image.
    pub fn full(width: u32, height: u32) -> Self {
        Window { columns: 0..width, rows: 0..height }
    }

    /// pbrt's crop window: the fractions `[x0, x1] × [y0, y1]` of a `width × height` image,
    /// `x` from the left and `y` from the top, as pixels `⌈x0 w⌉ .. ⌈x1 w⌉` and
    /// `⌈y0 h⌉ .. ⌈y1 h⌉` (so windows that share an edge share no pixel and miss none).
    pub fn crop(width: u32, height: u32, [x0, x1, y0, y1]: [f64; 4]) -> Result<Self, &'static str> {
        let ok = |a: f64, b: f64| (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) && a < b;
        if !(ok(x0, x1) && ok(y0, y1)) {
            return Err("a crop window is x0,x1,y0,y1 with 0 ≤ x0 < x1 ≤ 1 and 0 ≤ y0 < y1 ≤ 1");
        }
        let at = |f: f64, n: u32| (f * f64::from(n)).ceil() as u32;
        let (columns, top) = (at(x0, width)..at(x1, width), at(y0, height)..at(y1, height));
        if columns.is_empty() || top.is_empty() {
            return Err("the crop window holds no pixel centre at this image size");
        }
        // Rows from the top to rows from the bottom.
        Ok(Window { columns, rows: height - top.end..height - top.start })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crop_windows_tile_the_image() {
        let w = Window::crop(10, 7, [0.0, 0.5, 0.0, 1.0 / 3.0]).unwrap();
        assert_eq!(w, Window { columns: 0..5, rows: 4..7 });
        let rest = Window::crop(10, 7, [0.5, 1.0, 1.0 / 3.0, 1.0]).unwrap();
        assert_eq!(rest, Window { columns: 5..10, rows: 0..4 });
        assert!(Window::crop(10, 7, [0.5, 0.5, 0.0, 1.0]).is_err());
        assert!(Window::crop(10, 7, [0.0, 1.0, 0.0, 1.1]).is_err());
        assert!(Window::crop(10, 7, [0.0, 1.0, f64::NAN, 1.0]).is_err());
    }
}
