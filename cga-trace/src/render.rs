//! The integrator: nearest hits, Blinn–Phong shading with shadows and attenuation, and
//! recursive mirror reflection (the paper's eq. 12), in linear RGB.
//!
//! `I = c k_a A + Σ_i S_i f_att,i (c k_d max(n·l_i, 0) + k_s max(n·h_i, 0)^q) L_i + k_r I_r`,
//! `A` the ambient intensity, `L_i` the light colours, `S_i` 1 or the scene's shadow
//! transmission when something lies between the point and light `i`, `h_i = unit(l_i + v)`.

use crate::backend::{Backend, Sparse};
use crate::bvh::Bvh;
use crate::film::Film;
use crate::lanes::{RayLanes, lit, mirrored};
use crate::light::{Light, attenuation, blinn_phong};
use crate::material::Reflectance;
use crate::object::Object;
use crate::ray::{Ray, offset};
use crate::scene::Scene;
use crate::shapes::{Crossing, ShadingPoint};
use cga_core::Select;
use cga_core::euclid::{E3, dot, scale};
use rayon::prelude::*;
use smallvec::SmallVec;
use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// What an image shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum Aov {
    /// The shaded image.
    #[default]
    Shaded,
    /// False-colour normals of the first hit, `(n + 1) / 2`.
    Normal,
    /// The α of evolved-surface hits, blue (α = 0) to red (α = 1); black elsewhere.
    Alpha,
    /// Gaussian curvature `K` of swept surfaces (1/length², world units), false colour.
    Gaussian,
    /// Mean curvature `H`, positive where the surface bulges towards the viewer (1/length),
    /// false colour.
    Mean,
    /// The larger principal curvature `k₁` (normal towards the viewer), false colour.
    K1,
    /// The smaller principal curvature `k₂`, false colour.
    K2,
    /// The angle (degrees) between `L_C` and the nearest principal direction: the paper's
    /// postulate holds where it is 0.
    Postulate,
}

impl Aov {
    /// Whether the AOV is a scalar shown in false colour ([`crate::colour`]).
    pub fn is_scalar(self) -> bool {
        matches!(self, Aov::Gaussian | Aov::Mean | Aov::K1 | Aov::K2 | Aov::Postulate)
    }

    /// The scalar this AOV shows at a hit of curvature `k` seen along `dir`, in world units
    /// (`scale`: the frame's unit in world lengths).
    fn value(self, k: &cga_core::Curvature, dir: E3, scale: f64) -> f64 {
        // Curvatures positive where the surface bulges towards the viewer (a sphere seen from
        // outside), whichever way the surface's own normal `ν` points: with `ν` towards the
        // viewer a sphere has `H = −1/R` (`x_αα · ν < 0`), so the value is `−H` then.
        let sign = if dot(k.normal, dir) > 0.0 { 1.0 } else { -1.0 };
        let (a, b) = (sign * k.k[0] / scale, sign * k.k[1] / scale);
        match self {
            Aov::Gaussian => k.gaussian / (scale * scale),
            Aov::Mean => sign * k.mean / scale,
            Aov::K1 => a.max(b),
            Aov::K2 => a.min(b),
            _ => k.circle_angle().to_degrees(),
        }
    }
}

/// Scenes with at least this many bounded objects are traversed through a [`Bvh`]; fewer
/// are tested one by one (cheaper than any traversal).
const BVH_FROM: usize = 8;

/// Rays cast, by kind: one thread's tally of a row, or the renderer's total
/// ([`Renderer::counts`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// From the camera.
    pub primary: u64,
    /// Towards lights.
    pub shadow: u64,
    /// Mirror bounces.
    pub reflection: u64,
}

impl RayCounts {
    /// Adds `other`'s counts.
    pub(crate) fn add(&mut self, other: &RayCounts) {
        self.primary += other.primary;
        self.shadow += other.shadow;
        self.reflection += other.reflection;
    }

    /// `[primary, shadow, reflection]`.
    fn to_array(self) -> [u64; 3] {
        [self.primary, self.shadow, self.reflection]
    }
}

/// Renders a scene with the geometry of back end `B` (by default the generated sparse types).
pub struct Renderer<'a, B: Backend = Sparse> {
    pub(crate) scene: &'a Scene,
    /// The objects in `B`'s form, in scene order.
    pub(crate) shapes: Vec<B::Shape>,
    /// Whether rays go four at a time through packets: where `B` has them, unless switched
    /// off or the scene has a hierarchy.
    pub(crate) packets: bool,
    /// Bounding spheres of the objects worth culling ([`Shape::cull`](crate::shapes::Shape::cull)).
    pub(crate) bounds: Vec<Option<(E3, f64)>>,
    /// For scenes of many objects, a hierarchy over all bounded ones.
    pub(crate) bvh: Option<Bvh>,
    /// Which objects are [flat](crate::shapes::Shape::flat): their own shadow rays skip them.
    pub(crate) flat: Vec<bool>,
    /// Each object's [crossing error](crate::shapes::Shape::crossing_error): no ray counts a
    /// crossing nearer than it, and secondary rays start off the surface by a multiple of it.
    pub(crate) errors: Vec<f64>,
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
        let shapes: Vec<_> = scene.objects.iter().map(|o| B::prepare(&o.shape)).collect();
        let all: Vec<_> = scene.objects.iter().map(|o| o.shape.bounds()).collect();
        let bvh = (all.iter().flatten().count() >= BVH_FROM).then(|| Bvh::new(&all));
        let cull = |(o, b): (&Object, &Option<(E3, f64)>)| b.filter(|_| o.shape.cull());
        let bounds = scene.objects.iter().zip(&all).map(cull).collect();
        // Packets test every object: for scenes with a hierarchy, single rays through it.
        let packets = B::PACKETS && bvh.is_none();
        let flat = scene.objects.iter().map(|o| o.shape.flat()).collect();
        let errors = scene.objects.iter().map(|o| B::crossing_error(o.shape.as_ref())).collect();
        Renderer { scene, shapes, packets, bounds, bvh, flat, errors, counted: Default::default() }
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

    /// The nearest crossing with `t_min < t < t_max` over all objects (each beyond its own
    /// [crossing error](Renderer::t_min)), and the object's index.
    fn crossing(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(Crossing, usize)> {
        let [best] = self.crossings(ray, t_min, [t_max]);
        best
    }

    /// The nearest hit with `t_min < t < t_max`, and its object: the nearest crossing over
    /// all objects, then its normal, once.
    pub fn nearest(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(ShadingPoint, &'a Object)> {
        self.hit(ray, t_min, t_max).map(|(hit, k)| (hit, &self.scene.objects[k]))
    }

    /// [`Renderer::nearest`] with the object's index.
    fn hit(&self, ray: &Ray<B::Carrier>, t_min: f64, t_max: f64) -> Option<(ShadingPoint, usize)> {
        let (c, k) = self.crossing(ray, t_min, t_max)?;
        let hit = ShadingPoint { t: c.t, point: c.point, normal: B::normal(&self.shapes[k], ray, &c), alpha: c.alpha };
        Some((hit, k))
    }

    /// Object `k` if its shape is flat (its own shadow rays need not test it).
    pub(crate) fn skip_own(&self, k: usize) -> Option<usize> {
        self.flat[k].then_some(k)
    }

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
                        if let Some(term) = lit(light, at, &[material], &[true], offset) {
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
        let [colour] = self.trace_lanes(*ray, depth, &mut cast);
        self.count(&cast);
        colour
    }

    /// The colours seen along rays in lanes, `depth` bounces already made, counting the
    /// rays cast into `cast` (shared counters would be contended by every thread on every
    /// ray): nearest hit, normal, shading, and the mirror bounces of the lanes whose hit
    /// reflects (lanes whose ray has ended ride along with an empty range).
    ///
    /// Bounces are followed in a loop, not by recursion, so that no depth can overflow the
    /// stack: each hit's own colour and `k_r` are kept, and summed from the deepest up as
    /// recursion would, `I = I_local + k_r I_reflected` (the same operations in the same
    /// order, so the same bits).
    #[inline(always)]
    pub(crate) fn trace_lanes<R: RayLanes<B, W>, const W: usize>(
        &self,
        mut rays: R,
        mut depth: u32,
        cast: &mut RayCounts,
    ) -> [[f64; 3]; W] {
        let settings = &self.scene.settings;
        let mut active = [true; W];
        let mut deepest = [settings.background; W];
        let mut layers: [Layers; W] = core::array::from_fn(|_| Layers::new());
        while active.iter().any(|&a| a) {
            // An inactive lane's range is empty: it finds nothing. (`map`, not `from_fn`,
            // here and for `errors`: LLVM leaves `from_fn` over them out of line, 7 % more
            // instructions on the anchor scene.)
            let t_max = active.map(|a| if a { f64::INFINITY } else { f64::NEG_INFINITY });
            let nearest = self.crossings(&rays, 0.0, t_max);
            let hits: [Option<(ShadingPoint, usize)>; W] = core::array::from_fn(|l| {
                nearest[l].map(|(c, k)| {
                    let normal = B::normal(&self.shapes[k], rays.ray(l), &c);
                    (ShadingPoint { t: c.t, point: c.point, normal, alpha: c.alpha }, k)
                })
            });
            let errors: [f64; W] = nearest.map(|n| n.map_or(0.0, |(_, k)| self.errors[k]));
            let local = self.shade(&rays, &hits, cast);
            let mut bounce = [false; W];
            for l in 0..W {
                if !active[l] {
                    continue;
                }
                let Some((_, k)) = hits[l] else {
                    (deepest[l], active[l]) = (settings.background, false);
                    continue;
                };
                let kr = self.scene.objects[k].material.kr;
                if !(kr > 0.0 && depth < settings.max_depth) {
                    (deepest[l], active[l]) = (local[l], false);
                    continue;
                }
                cast.reflection += 1;
                layers[l].push((local[l], kr));
                bounce[l] = true;
            }
            if bounce.iter().any(|&b| b) {
                rays = mirrored(&rays, &hits, &errors, &bounce);
            }
            depth += 1;
        }
        core::array::from_fn(|l| sum_layers(&layers[l], deepest[l]))
    }

    /// `c k_a A`: the ambient light on an object.
    pub(crate) fn ambient(&self, object: &Object) -> [f64; 3] {
        scale(object.material.colour, object.material.ka * self.scene.settings.ambient)
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

    /// One pixel: the shaded colour or an AOV.
    pub fn pixel(&self, i: u32, j: u32, aov: Aov) -> [f64; 3] {
        let mut cast = RayCounts::default();
        let colour = self.pixel_counted(i, j, aov, &mut cast);
        self.count(&cast);
        colour
    }

    /// One pixel, averaged over the scene's `spp` samples ([`sample_offset`]; the centre
    /// alone for one sample); the background where the camera forms no ray.
    fn pixel_counted(&self, i: u32, j: u32, aov: Aov, cast: &mut RayCounts) -> [f64; 3] {
        self.pixels::<Ray<B::Carrier>, 1>(i, j, aov, cast).map_or(self.scene.settings.background, |[c]| c)
    }

    /// `W` neighbouring pixels of a row, `(i₀ + k, j)`, each averaged over the scene's
    /// `spp` samples, sample `s` of the `W` pixels cast as one set of rays in lanes; `None`
    /// where the camera forms no ray (nothing is counted then).
    #[inline(always)]
    pub(crate) fn pixels<R: RayLanes<B, W>, const W: usize>(
        &self,
        i0: u32,
        j: u32,
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[[f64; 3]; W]> {
        let spp = self.scene.settings.spp.max(1);
        let mut counted = RayCounts::default();
        let colours = if spp == 1 {
            let u = core::array::from_fn(|k| f64::from(i0 + k as u32) + 0.5);
            self.samples::<R, W>(u, [f64::from(j) + 0.5; W], aov, &mut counted)?
        } else {
            let mut sum = [[0.0; 3]; W];
            for s in 0..spp {
                let (mut u, mut v) = ([0.0; W], [0.0; W]);
                for k in 0..W {
                    let (du, dv) = sample_offset(i0 + k as u32, j, s);
                    (u[k], v[k]) = (f64::from(i0 + k as u32) + du, f64::from(j) + dv);
                }
                let colours = self.samples::<R, W>(u, v, aov, &mut counted)?;
                for (sum, c) in sum.iter_mut().zip(colours) {
                    *sum = [sum[0] + c[0], sum[1] + c[1], sum[2] + c[2]];
                }
            }
            let n = f64::from(spp);
            for c in &mut sum {
                *c = [c[0] / n, c[1] / n, c[2] / n];
            }
            sum
        };
        cast.add(&counted);
        Some(colours)
    }

    /// The colours (or AOVs, lane by lane) seen at continuous pixel coordinates
    /// `(u_k, v_k)`.
    #[inline(always)]
    fn samples<R: RayLanes<B, W>, const W: usize>(
        &self,
        u: [f64; W],
        v: [f64; W],
        aov: Aov,
        cast: &mut RayCounts,
    ) -> Option<[[f64; 3]; W]> {
        if aov != Aov::Shaded {
            let mut out = [[0.0; 3]; W];
            for l in 0..W {
                let ray = B::camera_ray(&self.scene.camera, u[l], v[l])?;
                cast.primary += 1;
                out[l] = self.aov(&ray, aov);
            }
            return Some(out);
        }
        let rays = R::camera(&self.scene.camera, u, v)?;
        cast.primary += W as u64;
        Some(self.trace_lanes(rays, 0, cast))
    }

    /// What AOV `aov` shows along `ray`.
    fn aov(&self, ray: &Ray<B::Carrier>, aov: Aov) -> [f64; 3] {
        match aov {
            Aov::Shaded => self.trace(ray, 0),
            Aov::Normal => {
                self.nearest(ray, 0.0, f64::INFINITY).map_or([0.0; 3], |(h, _)| h.normal.map(|x| 0.5 * (x + 1.0)))
            }
            Aov::Alpha => match self.nearest(ray, 0.0, f64::INFINITY) {
                Some((ShadingPoint { alpha: Some(a), .. }, _)) => [a, 0.2, 1.0 - a],
                _ => [0.0; 3],
            },
            // (value, 1) where the surface has a curvature, (0, 0) elsewhere: averaged over
            // samples, value / weight is the mean over the samples that had one.
            _ => match self.nearest(ray, 0.0, f64::INFINITY) {
                Some((hit, object)) => {
                    let crossing = Crossing { t: hit.t, point: hit.point, alpha: hit.alpha };
                    let scale = self.scene.frame.scale;
                    object.shape.curvature(&crossing).map_or([0.0; 3], |k| [aov.value(&k, ray.dir, scale), 1.0, 0.0])
                }
                None => [0.0; 3],
            },
        }
    }

    /// The whole image, rows in parallel on rayon's pool; `on_row` is called as each row
    /// finishes (for a progress bar).
    pub fn render(&self, aov: Aov, on_row: &(dyn Fn() + Sync)) -> Film {
        let camera = &self.scene.camera;
        self.render_window(aov, Window::full(camera.width, camera.height), on_row)
    }

    /// The pixels of `window` only, as an image of its size. Every pixel depends on its
    /// position alone, so windows of a frame rendered anywhere assemble into the frame,
    /// byte for byte, and any thread count gives the same bytes.
    pub fn render_window(&self, aov: Aov, window: Window, on_row: &(dyn Fn() + Sync)) -> Film {
        let (width, height) = (window.columns.len(), window.rows.len());
        // One allocation, each row written in place by whichever thread renders it.
        let mut pixels = vec![[0.0; 3]; width * height];
        // One row per task: rayon otherwise splits the image into few large pieces, and rows
        // differ in cost (mirrors, surfaces), so one thread idles at the end.
        pixels.par_chunks_mut(width).with_max_len(1).zip(window.rows.clone()).for_each(|(row, j)| {
            let mut cast = RayCounts::default();
            let mut done = 0;
            if aov == Aov::Shaded && self.packets {
                for (four, i0) in row.chunks_exact_mut(4).zip(window.columns.clone().step_by(4)) {
                    let Some(colours) = B::pixels4(self, i0, j, &mut cast) else { break };
                    four.copy_from_slice(&colours);
                    done += 4;
                }
            }
            for (pixel, i) in row.iter_mut().zip(window.columns.clone()).skip(done) {
                *pixel = self.pixel_counted(i, j, aov, &mut cast);
            }
            self.count(&cast);
            on_row();
        });
        Film { width: width as u32, height: height as u32, pixels }
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

/// Where sample `s` of pixel `(i, j)` falls, as an offset in `[0, 1)²` from the pixel's
/// corner: the first two dimensions of the Sobol' sequence (a (0, 2)-sequence: every prefix
/// of `2^k` samples has one in each of the `2^k` elementary boxes of every shape), with the
/// digits of each coordinate scrambled by a hash of the pixel (random digit scrambling keeps
/// that stratification and decorrelates neighbouring pixels). Deterministic: the same for
/// any thread count or crop.
pub fn sample_offset(i: u32, j: u32, s: u32) -> (f64, f64) {
    let pixel = hash(i ^ hash(j ^ 0x9e37_79b9));
    let x = s.reverse_bits() ^ hash(pixel ^ 0x68bc_21eb);
    let y = sobol_second(s) ^ hash(pixel ^ 0x02e5_be93);
    let unit = |bits: u32| f64::from(bits) / 4_294_967_296.0;
    (unit(x), unit(y))
}

/// The second dimension of the Sobol' sequence (primitive polynomial `x + 1`): direction
/// numbers `v₀ = 2³¹`, `v_k = v_{k−1} ⊕ (v_{k−1} >> 1)`, XORed over the bits of `s`.
fn sobol_second(mut s: u32) -> u32 {
    let (mut v, mut y) = (1u32 << 31, 0);
    while s != 0 {
        if s & 1 == 1 {
            y ^= v;
        }
        s >>= 1;
        v ^= v >> 1;
    }
    y
}

/// A 32-bit integer hash with good avalanche (two multiply–xorshift rounds).
fn hash(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^ (x >> 16)
}

/// The colours and `k_r` of the hits along a ray's mirror bounces, nearest first, summed
/// from the deepest up.
pub(crate) type Layers = SmallVec<[([f64; 3], f64); 8]>;

/// `I = I_local + k_r I_below` from the deepest bounce up, as recursion would sum it.
pub(crate) fn sum_layers(layers: &Layers, deepest: [f64; 3]) -> [f64; 3] {
    layers.iter().rev().fold(deepest, |below, (local, kr)| [0, 1, 2].map(|k| local[k] + kr * below[k]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_are_stratified_in_every_elementary_box() {
        // 16 samples: one in each of the 16 cells of the 16×1, 8×2, 4×4, 2×8, 1×16 grids.
        for (i, j) in [(0, 0), (7, 3), (1000, 20)] {
            let points: Vec<_> = (0..16).map(|s| sample_offset(i, j, s)).collect();
            for k in 0..=4 {
                let (nx, ny) = (1u32 << k, 1u32 << (4 - k));
                let mut seen = [false; 16];
                for &(x, y) in &points {
                    assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                    let cell = (x * f64::from(nx)) as u32 * ny + (y * f64::from(ny)) as u32;
                    assert!(!std::mem::replace(&mut seen[cell as usize], true), "pixel ({i}, {j}), {nx}×{ny}");
                }
            }
        }
        assert_ne!(sample_offset(0, 0, 0), sample_offset(1, 0, 0), "pixels are decorrelated");
    }

    #[test]
    fn curvatures_are_positive_where_the_surface_bulges_towards_the_viewer() {
        // A sphere of radius 2 seen from outside along −x at (2, 0, 0): the curvature module's
        // convention gives H = −1/R with the outward normal, +1/R with the inward one.
        for (normal, mean) in [([1.0, 0.0, 0.0], -0.5), ([-1.0, 0.0, 0.0], 0.5)] {
            let k = cga_core::Curvature {
                normal,
                k: [mean; 2],
                directions: [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                gaussian: 0.25,
                mean,
                circle_tangent: [0.0, 1.0, 0.0],
                condition: 0.0,
            };
            for aov in [Aov::Mean, Aov::K1, Aov::K2] {
                assert_eq!(aov.value(&k, [-1.0, 0.0, 0.0], 1.0), 0.5, "{aov:?}");
            }
            assert_eq!(Aov::Gaussian.value(&k, [-1.0, 0.0, 0.0], 2.0), 0.0625, "world units");
        }
    }

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
