//! Error against run time of every evolved-surface method, on the rays the shipped scenes
//! cast and on adversarial rays over stiff surfaces:
//!
//! `cargo run --release -p cga-trace --example surface_report`
//!
//! writes `docs/surface-report.md` (tables) and `docs/images/surface_error_time.svg` (plot).
//! `--quick` runs a tenth of the rays (for a smoke test). The reference is f64 sampling of
//! `(f, f')` at 4096 points per ray with the close-pair search and Newton to rounding level.

use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{Circle, Interpolable, Line, Real};
use cga_trace::Renderer;
use cga_trace::ray::{Ray, offset};
use cga_trace::scene::Scene;
use cga_trace::shapes::{Crossing, Shape};
use cga_trace::surface::bernstein::Roots;
use cga_trace::surface::{EvolvedSurface, Family, Finder, Method};
use plotters::prelude::*;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::time::Instant;

/// A ray to test, with its `t_max` and what kind of ray it is.
#[derive(Clone, Copy)]
struct TestRay {
    ray: Ray,
    t_max: f64,
    kind: &'static str,
}

/// A surface and the rays tested on it.
struct Case {
    name: String,
    surface: EvolvedSurface,
    rays: Vec<TestRay>,
}

impl Case {
    /// The same surface with only the rays the scenes' renders cast.
    fn scene_rays(&self) -> Case {
        let rays = self.rays.iter().filter(|r| r.kind.starts_with("scene")).copied().collect();
        Case { name: self.name.clone(), surface: self.surface.clone(), rays }
    }
}

/// A method at one setting of its knobs, in one scalar type.
#[derive(Clone, Copy)]
enum Setting {
    F64(Method),
    F32(Finder),
}

impl Setting {
    fn label(&self) -> String {
        match *self {
            Setting::F64(Method::Sampling { samples }) => format!("sampling {samples}"),
            Setting::F64(Method::Polynomial { tolerance }) => format!("polynomial tol {tolerance:.0e}"),
            Setting::F64(Method::Hierarchy { leaves, per_leaf }) => format!("hierarchy {leaves}×{per_leaf}"),
            Setting::F64(Method::Hybrid { leaves, tolerance }) => format!("hybrid {leaves}, tol {tolerance:.0e}"),
            Setting::F32(Finder::Samples(n)) => format!("sampling {n} (f32)"),
            Setting::F32(Finder::Slope(n)) => format!("slope {n} (f32)"),
            Setting::F32(Finder::Polynomial(t)) => format!("polynomial tol {t:.0e} (f32)"),
        }
    }

    fn family(&self) -> &'static str {
        match self {
            Setting::F64(Method::Sampling { .. }) | Setting::F32(Finder::Samples(_)) => "sampling",
            Setting::F64(Method::Polynomial { .. }) | Setting::F32(Finder::Polynomial(_)) => "polynomial",
            Setting::F64(Method::Hierarchy { .. }) | Setting::F32(Finder::Slope(_)) => "hierarchy",
            Setting::F64(Method::Hybrid { .. }) => "hybrid",
        }
    }
}

/// One setting prepared for one surface.
enum Prepared {
    Surface(EvolvedSurface),
    Reference(Family<f64>, E3),
    F32(Family<f32>, E3, Finder),
}

impl Prepared {
    fn new(setting: Setting, surface: &EvolvedSurface) -> Self {
        let (family, origin) = surface.family();
        match setting {
            Setting::F64(m) => Prepared::Surface(surface.with_method(m).expect("the same surface")),
            Setting::F32(finder) => Prepared::F32(family.cast(), origin, finder),
        }
    }

    /// The reference: f64 `(f, f')` at 4096 samples over [0, 1], no culling.
    fn reference(surface: &EvolvedSurface) -> Self {
        let (family, origin) = surface.family();
        Prepared::Reference(family.clone(), origin)
    }

    /// The nearest crossing, in world coordinates (f32 results widened).
    fn intersect(&self, surface: &EvolvedSurface, r: &TestRay) -> Option<Crossing> {
        match self {
            Prepared::Surface(s) => s.intersect(&r.ray, 0.0, r.t_max),
            Prepared::Reference(family, origin) => plain_intersect(family, *origin, Finder::Slope(4096), surface, r),
            Prepared::F32(family, origin, finder) => plain_intersect(family, *origin, *finder, surface, r),
        }
    }
}

/// A finder over all of [0, 1] in `T`, after the same bounding-sphere test as every method.
fn plain_intersect<T: Real>(
    family: &Family<T>,
    origin: E3,
    finder: Finder,
    surface: &EvolvedSurface,
    r: &TestRay,
) -> Option<Crossing> {
    surface.local_ray(&r.ray, 0.0, r.t_max)?;
    let narrow = |x: E3| x.map(T::from_f64);
    let o = narrow(sub(r.ray.origin, origin));
    let d = narrow(r.ray.dir);
    let line = Line::<T>::from_point_direction(o, d).ok()?;
    let mut alphas = Roots::new();
    family.roots(&line, finder, 0.0, 1.0, &mut alphas);
    let t_max = if r.t_max.is_finite() { T::from_f64(r.t_max) } else { T::from_f64(f64::from(f32::MAX)) };
    let polish = finder.polishes();
    let (t, x, alpha) = family.nearest((o, d, &line), &alphas, T::zero(), t_max, polish)?;
    Some(Crossing { t: t.to_f64(), point: add(x.map(T::to_f64), origin), alpha: Some(alpha.to_f64()), part: 0 })
}

/// Errors of one setting against the reference.
#[derive(Clone, Copy, Default)]
struct Tally {
    rays: usize,
    hits: usize,
    missed: usize,
    false_hits: usize,
    /// Disagreements on rays tangent to the surface at the hit (`|d·n| < 1e-6`), where
    /// either answer is right.
    tangent: usize,
    /// The same point reached on another circle: a self-intersection of the surface.
    other_alpha: usize,
    /// Largest α error at simple roots (transversal crossings).
    alpha: f64,
    /// Largest α error at double roots (`|f'| < 1e-6` of `f`'s scale: tangent rays, rays in
    /// a circle's plane), where α is determined to √ε only.
    alpha_double: f64,
    point: f64,
    normal: f64,
}

impl Tally {
    fn add(&mut self, other: &Tally) {
        self.rays += other.rays;
        self.hits += other.hits;
        self.missed += other.missed;
        self.false_hits += other.false_hits;
        self.tangent += other.tangent;
        self.other_alpha += other.other_alpha;
        self.alpha = self.alpha.max(other.alpha);
        self.alpha_double = self.alpha_double.max(other.alpha_double);
        self.point = self.point.max(other.point);
        self.normal = self.normal.max(other.normal);
    }
}

/// Compares a result with the reference. Distances are relative to the surface's bounding
/// radius. A hit farther than the reference's counts as a miss (a nearer root was skipped),
/// one nearer as a false hit — unless the ray is tangent to the surface there.
fn compare(surface: &EvolvedSurface, ray: &Ray, want: Option<Crossing>, got: Option<Crossing>, tally: &mut Tally) {
    let size = surface.bounds().1;
    let tangent = |c: &Crossing| dot(surface.normal(c), ray.dir).abs() < 1e-6;
    tally.rays += 1;
    match (want, got) {
        (Some(w), Some(g)) => {
            let tol = 1e-6 * (size + w.t.abs());
            let nearer = if g.t < w.t { &g } else { &w };
            if (g.t - w.t).abs() > tol && tangent(nearer) {
                tally.tangent += 1;
            } else if g.t > w.t + tol {
                tally.missed += 1;
            } else if g.t < w.t - tol {
                tally.false_hits += 1;
            } else {
                tally.hits += 1;
                let point = norm(sub(w.point, g.point)) / size;
                let alpha = (w.alpha.unwrap_or(0.0) - g.alpha.unwrap_or(0.0)).abs();
                if alpha > 1e-6 {
                    tally.other_alpha += 1;
                } else {
                    if double_root(surface, ray, w.alpha.unwrap_or(0.0)) {
                        tally.alpha_double = tally.alpha_double.max(alpha);
                    } else {
                        tally.alpha = tally.alpha.max(alpha);
                    }
                    let (nw, ng) = (surface.normal(&w), surface.normal(&g));
                    tally.normal = tally.normal.max(norm(cross(nw, ng)).atan2(dot(nw, ng).abs()));
                }
                tally.point = tally.point.max(point);
            }
        }
        (Some(w), None) if tangent(&w) => tally.tangent += 1,
        (None, Some(g)) if tangent(&g) => tally.tangent += 1,
        (Some(_), None) => tally.missed += 1,
        (None, Some(_)) => tally.false_hits += 1,
        (None, None) => {}
    }
}

/// Whether `f` has a double root at α for this ray: `|f'(α)|` below 1e-6 of `f`'s scale.
fn double_root(surface: &EvolvedSurface, ray: &Ray, alpha: f64) -> bool {
    let (family, origin) = surface.family();
    let Ok(line) = Line::from_point_direction(sub(ray.origin, origin), ray.dir) else { return false };
    let scale =
        [0.0, 0.25, 0.5, 0.75, 1.0].iter().filter_map(|&a| family.f(&line, a)).fold(0.0f64, |m, f| m.max(f.abs()));
    family.f_and_slope(&line.lift(), alpha).is_some_and(|(_, d)| d.abs() < 1e-6 * scale)
}

/// A seeded stream (the `rand_xorshift` crate) with the draws the report uses.
struct Rng(rand_xorshift::XorShiftRng);

impl Rng {
    fn new(seed: u64) -> Self {
        Rng(rand::SeedableRng::seed_from_u64(seed))
    }
    fn next(&mut self) -> f64 {
        rand::RngExt::random::<f64>(&mut self.0)
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn unit(&mut self) -> E3 {
        loop {
            let v = [self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0)];
            if let Some(u) = unit(v).filter(|_| dot(v, v) <= 1.0) {
                return u;
            }
        }
    }
}

/// Every ray a render of `scene` at its size casts (primary, shadow, reflection, to
/// `max_depth`) that reaches `surface`'s bounding sphere.
fn scene_rays(scene: &Scene, surface: &EvolvedSurface) -> Vec<TestRay> {
    let renderer = Renderer::new(scene);
    let camera = &scene.camera;
    let rows: Vec<Vec<TestRay>> = (0..camera.height)
        .into_par_iter()
        .map(|j| {
            let mut out = Vec::new();
            for i in 0..camera.width {
                let Some(primary) = camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5) else { continue };
                let mut todo = vec![(primary, f64::INFINITY, "scene: primary", 0)];
                while let Some((ray, t_max, kind, depth)) = todo.pop() {
                    if surface.local_ray(&ray, 0.0, t_max).is_some() {
                        out.push(TestRay { ray, t_max, kind });
                    }
                    if t_max.is_finite() {
                        continue;
                    }
                    let Some((hit, object)) = renderer.nearest(&ray, 0.0, f64::INFINITY) else { continue };
                    let off = offset(hit.point, ray.origin, object.shape.crossing_error());
                    for light in &scene.lights {
                        let (to, distance) = light.toward(hit.point);
                        if let Some(shadow) = Ray::leaving(hit.point, hit.normal, to, off) {
                            todo.push((shadow, distance, "scene: shadow", depth));
                        }
                    }
                    if object.material.kr > 0.0 && depth < scene.settings.max_depth {
                        let d = cga_core::euclid::reflect(ray.dir, hit.normal);
                        if let Some(r) = Ray::leaving(hit.point, hit.normal, d, off) {
                            todo.push((r, f64::INFINITY, "scene: reflection", depth + 1));
                        }
                    }
                }
            }
            out
        })
        .collect();
    rows.concat()
}

/// A point on `C_α`, in the local frame, with the circle's centre, normal and radius.
fn on_circle(family: &Family<f64>, alpha: f64, angle: f64) -> Option<(E3, E3, E3, f64)> {
    let (c, n, r) = family.at(alpha).ok()?.centre_normal_radius().ok()?;
    let u = cga_core::euclid::perpendicular(n);
    let v = cross(n, u);
    let x = add(c, add(scale(u, r * angle.cos()), scale(v, r * angle.sin())));
    Some((x, c, n, r))
}

/// Adversarial rays for a surface: aimed at random points, grazing, in a circle's plane,
/// near α = 0 and 1, through the narrowest part, and leaving the surface as shadow and
/// reflection rays do.
fn adversarial(surface: &EvolvedSurface, per_kind: usize, seed: u64) -> Vec<TestRay> {
    let (family, origin) = surface.family();
    let size = surface.bounds().1;
    let mut rng = Rng::new(seed);
    let mut out = Vec::new();
    let world = |x: E3| add(x, origin);
    let push = |out: &mut Vec<TestRay>, ray: Option<Ray>, t_max: f64, kind: &'static str| {
        if let Some(ray) = ray {
            out.push(TestRay { ray, t_max, kind });
        }
    };
    // The narrowest circle (by radius, over 1025 samples).
    let waist = (0..=1024)
        .map(|k| k as f64 / 1024.0)
        .filter_map(|a| Some((a, family.at(a).ok()?.centre_normal_radius().ok()?.2)))
        .fold((0.0, f64::INFINITY), |m, (a, r)| if r < m.1 { (a, r) } else { m })
        .0;
    for _ in 0..per_kind {
        let angle = rng.range(0.0, std::f64::consts::TAU);
        let alpha = rng.next();
        let Some((x, _, _, _)) = on_circle(family, alpha, angle) else { continue };
        let normal = surface.normal(&Crossing { t: 0.0, point: world(x), alpha: Some(alpha), part: 0 });
        // Aimed at a point of the surface from outside.
        let from = add(x, scale(rng.unit(), 3.0 * size));
        push(&mut out, Ray::new(world(from), sub(x, from)), f64::INFINITY, "aimed");
        // Grazing: along a tangent direction through the point.
        let tangent = unit(cross(normal, rng.unit())).unwrap_or([1.0, 0.0, 0.0]);
        push(&mut out, Ray::new(world(sub(x, scale(tangent, 2.0 * size))), tangent), f64::INFINITY, "grazing");
        // In the plane of C_α, through a random chord.
        if let Some((_, c, n, r)) = on_circle(family, alpha, 0.0) {
            let u = cga_core::euclid::perpendicular(n);
            let v = cross(n, u);
            let dir = add(scale(u, angle.cos()), scale(v, angle.sin()));
            let offset = scale(cross(n, dir), rng.range(-1.2, 1.2) * r);
            push(
                &mut out,
                Ray::new(world(sub(add(c, offset), scale(dir, 2.0 * size))), dir),
                f64::INFINITY,
                "in a circle's plane",
            );
        }
        // Near the ends: α within 1e-6 of 0 or 1, or exactly there.
        let end = match rng.next() {
            p if p < 0.25 => 0.0,
            p if p < 0.5 => 1.0,
            p if p < 0.75 => rng.range(0.0, 1e-6),
            _ => 1.0 - rng.range(0.0, 1e-6),
        };
        if let Some((y, _, _, _)) = on_circle(family, end, angle) {
            let from = add(y, scale(rng.unit(), 3.0 * size));
            push(&mut out, Ray::new(world(from), sub(y, from)), f64::INFINITY, "near α = 0 or 1");
        }
        // Through the narrowest part.
        let a = (waist + rng.range(-0.01, 0.01)).clamp(0.0, 1.0);
        if let Some((y, _, _, _)) = on_circle(family, a, angle) {
            let from = add(y, scale(rng.unit(), 3.0 * size));
            push(&mut out, Ray::new(world(from), sub(y, from)), f64::INFINITY, "narrowest part");
        }
        // Leaving the surface as a shadow ray (to a light) and a reflection ray.
        let light = scale(rng.unit(), 5.0 * size);
        let to = sub(light, x);
        let off = offset(world(x), world(x), surface.crossing_error());
        push(&mut out, Ray::leaving(world(x), normal, to, off), norm(to), "leaving: shadow");
        let side = if dot(normal, to) >= 0.0 { 1.0 } else { -1.0 };
        let bounce = cga_core::euclid::reflect(scale(rng.unit(), 1.0), normal);
        let bounce = if dot(bounce, normal) * side < 0.0 { bounce.map(|x| -x) } else { bounce };
        push(&mut out, Ray::leaving(world(x), scale(normal, side), bounce, off), f64::INFINITY, "leaving: reflection");
    }
    out
}

/// A circle by centre, normal and radius (panics on bad input: these are fixed cases).
fn circle(c: E3, n: E3, r: f64) -> Circle {
    Circle::from_centre_normal_radius(c, n, r).expect("a real circle")
}

/// The stiff and extreme surfaces, each with a one-line description.
fn stiff_surfaces() -> Vec<(String, EvolvedSurface)> {
    let m = Method::default();
    let z = [0.0, 0.0, 1.0];
    let tilted = unit([0.3, 0.2, 1.0]).unwrap();
    let far = [1.0e4, -2.0e3, 5.0e3];
    let local = |origin: E3, c1: Circle, c2: Circle| EvolvedSurface::in_frame(origin, c1, c2, m);
    let cases: Vec<(&str, Result<EvolvedSurface, _>)> = vec![
        (
            "far from the origin (‖c‖ ≈ 1.1e4), built in a local frame",
            local(far, circle([0.0; 3], z, 1.0), circle([0.5, 0.0, 1.0], tilted, 1.5)),
        ),
        (
            "far from the origin (‖c‖ ≈ 1.1e4), built in world coordinates",
            EvolvedSurface::new(circle(far, z, 1.0), circle(add(far, [0.5, 0.0, 1.0]), tilted, 1.5), m),
        ),
        (
            "tiny radii (1e-4 and 1.5e-4)",
            EvolvedSurface::new(circle([0.0; 3], z, 1e-4), circle([0.5e-4, 0.0, 1e-4], tilted, 1.5e-4), m),
        ),
        (
            "huge radii (1e4 and 1.5e4)",
            EvolvedSurface::new(circle([0.0; 3], z, 1e4), circle([0.5e4, 0.0, 1e4], tilted, 1.5e4), m),
        ),
        (
            "radii eight decades apart (1e-4 and 1e4)",
            EvolvedSurface::new(circle([0.0; 3], z, 1e-4), circle([0.0, 0.0, 1.0], z, 1e4), m),
        ),
        (
            "nearly identical (moved 1e-7, tilted 1e-7)",
            EvolvedSurface::new(
                circle([0.0; 3], z, 1.0),
                circle([1e-7, 0.0, 0.0], unit([1e-7, 0.0, 1.0]).unwrap(), 1.0),
                m,
            ),
        ),
        (
            "anti-aligned (opposite normals, one above the other)",
            EvolvedSurface::new(circle([0.0; 3], z, 1.0), circle([0.0, 0.0, 1.0], [0.0, 0.0, -1.0], 1.2), m),
        ),
        (
            "twisted a quarter turn (normals z and x)",
            EvolvedSurface::new(circle([0.0; 3], z, 1.0), circle([0.0, 0.0, 1.5], [1.0, 0.0, 0.0], 1.0), m),
        ),
        (
            "twisted, passing near a point-like circle",
            EvolvedSurface::new(
                circle([0.0; 3], z, 1.0),
                circle([0.0, 0.0, 0.3], unit([1.0, 0.0, 0.05]).unwrap(), 0.05),
                m,
            ),
        ),
        (
            "co-spherical (both on the sphere ‖x‖ = 2: W = 0)",
            EvolvedSurface::new(
                circle([0.0, 0.0, 1.0], z, 3f64.sqrt()),
                circle(scale(unit([1.0, 0.0, 1.0]).unwrap(), -1.5), unit([1.0, 0.0, 1.0]).unwrap(), 1.75f64.sqrt()),
                m,
            ),
        ),
    ];
    cases
        .into_iter()
        .filter_map(|(name, s)| match s {
            Ok(s) => Some((name.to_string(), s)),
            Err(e) => {
                eprintln!("skipping {name}: {e}");
                None
            }
        })
        .collect()
}

/// The smallest and largest radius along the family (1025 samples).
fn radius_range(surface: &EvolvedSurface) -> (f64, f64) {
    let (family, _) = surface.family();
    (0..=1024)
        .filter_map(|k| family.at(k as f64 / 1024.0).ok()?.centre_normal_radius().ok())
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), (_, _, r)| (lo.min(r), hi.max(r)))
}

/// Median over `repeats` runs of the time per ray (ns) of one setting on one case.
fn time_per_ray(prepared: &Prepared, case: &Case, repeats: usize) -> f64 {
    let mut runs: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let mut hits = 0usize;
            for r in &case.rays {
                hits += usize::from(prepared.intersect(&case.surface, r).is_some());
            }
            std::hint::black_box(hits);
            start.elapsed().as_secs_f64() * 1e9 / case.rays.len().max(1) as f64
        })
        .collect();
    runs.sort_by(f64::total_cmp);
    runs[runs.len() / 2]
}

fn settings() -> Vec<Setting> {
    let mut s = Vec::new();
    for samples in [16, 32, 64, 128, 256, 1024] {
        s.push(Setting::F64(Method::Sampling { samples }));
    }
    for tolerance in [1e-3, 1e-6, 1e-9, 0.0] {
        s.push(Setting::F64(Method::Polynomial { tolerance }));
    }
    for (leaves, per_leaf) in [(16, 2), (16, 4), (64, 2), (64, 4), (256, 4)] {
        s.push(Setting::F64(Method::Hierarchy { leaves, per_leaf }));
    }
    for (leaves, tolerance) in [(4, 0.0), (16, 1e-6), (16, 0.0), (64, 0.0)] {
        s.push(Setting::F64(Method::Hybrid { leaves, tolerance }));
    }
    s.extend([
        Setting::F32(Finder::Samples(64)),
        Setting::F32(Finder::Polynomial(1e-6)),
        Setting::F32(Finder::Polynomial(0.0)),
    ]);
    s
}

fn evolved(scene: &Scene) -> &EvolvedSurface {
    scene
        .objects
        .iter()
        .find_map(|o| o.shape.downcast_ref::<EvolvedSurface>())
        .expect("the scene has an evolved surface")
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let per_kind = if quick { 300 } else { 3000 };
    let mut cases = Vec::new();
    for name in ["combined", "surface"] {
        let path = format!("cga-trace/scenes/{name}.toml");
        let scene = Scene::load(std::path::Path::new(&path)).expect("a shipped scene");
        let surface = evolved(&scene).clone();
        let mut rays = scene_rays(&scene, &surface);
        if quick {
            rays = rays.into_iter().step_by(10).collect();
        }
        rays.extend(adversarial(&surface, per_kind, 7));
        cases.push(Case { name: format!("{name}.toml"), surface, rays });
    }
    let scene_cases = cases.len();
    for (k, (name, surface)) in stiff_surfaces().into_iter().enumerate() {
        let rays = adversarial(&surface, per_kind / 3, 100 + k as u64);
        cases.push(Case { name, surface, rays });
    }
    let total: usize = cases.iter().map(|c| c.rays.len()).sum();
    let only = std::env::var("SURFACE_REPORT_ONLY").ok();
    if std::env::args().any(|a| a == "--time") {
        time_only(&cases[..scene_cases], only.as_deref());
        return;
    }
    eprintln!("{} cases, {total} rays; computing the reference", cases.len());

    let references: Vec<Vec<Option<Crossing>>> = cases
        .iter()
        .map(|case| {
            let reference = Prepared::reference(&case.surface);
            case.rays.par_iter().map(|r| reference.intersect(&case.surface, r)).collect()
        })
        .collect();

    let settings: Vec<Setting> =
        settings().into_iter().filter(|s| only.as_ref().is_none_or(|o| s.label().contains(o.as_str()))).collect();
    // tallies[setting][case], times[setting][case] (ns per ray)
    let mut tallies = vec![vec![Tally::default(); cases.len()]; settings.len()];
    let mut times = vec![vec![0.0; cases.len()]; settings.len()];
    let mut kinds: Vec<(&'static str, usize)> = Vec::new();
    for case in &cases {
        for r in &case.rays {
            match kinds.iter_mut().find(|k| k.0 == r.kind) {
                Some(k) => k.1 += 1,
                None => kinds.push((r.kind, 1)),
            }
        }
    }
    // by_kind[setting][kind]
    let mut by_kind = vec![vec![Tally::default(); kinds.len()]; settings.len()];
    // scene_rays[setting]: (total ns, rays) over the scene cases' own rays.
    let mut scene_rays = vec![(0.0, 0usize); settings.len()];
    for (s, setting) in settings.iter().enumerate() {
        eprintln!("{}", setting.label());
        for (c, case) in cases.iter().enumerate() {
            let prepared = Prepared::new(*setting, &case.surface);
            let results: Vec<Option<Crossing>> =
                case.rays.par_iter().map(|r| prepared.intersect(&case.surface, r)).collect();
            for ((r, want), got) in case.rays.iter().zip(&references[c]).zip(results) {
                let mut one = Tally::default();
                compare(&case.surface, &r.ray, *want, got, &mut one);
                let odd = one.missed + one.false_hits > 0 || one.alpha > 1e-9;
                if odd && std::env::var("SURFACE_REPORT_DUMP").is_ok_and(|v| setting.label().contains(&v)) {
                    let inc = |c: &Option<Crossing>| c.map(|c| dot(case.surface.normal(&c), r.ray.dir).abs());
                    eprintln!(
                        "  {} / {}: {} incidence want {:?} got {:?} | {:?} t_max {}: want {:?} got {:?}",
                        case.name,
                        r.kind,
                        if one.missed > 0 {
                            "MISSED"
                        } else if one.false_hits > 0 {
                            "FALSE"
                        } else if one.other_alpha > 0 {
                            "OTHER"
                        } else {
                            "ALPHA"
                        },
                        inc(want),
                        inc(&got),
                        r.ray,
                        r.t_max,
                        want,
                        got
                    );
                }
                tallies[s][c].add(&one);
                let k = kinds.iter().position(|k| k.0 == r.kind).expect("a known kind");
                by_kind[s][k].add(&one);
            }
            times[s][c] = time_per_ray(&prepared, case, 3);
            if c < scene_cases {
                let own = case.scene_rays();
                scene_rays[s].0 += time_per_ray(&prepared, &own, 3) * own.rays.len() as f64;
                scene_rays[s].1 += own.rays.len();
            }
        }
    }
    let scene_ray_times: Vec<f64> = scene_rays.iter().map(|&(ns, n)| ns / n.max(1) as f64).collect();

    let report =
        write_report(&cases, scene_cases, &settings, &tallies, (&times, &scene_ray_times), &kinds, &by_kind, total);
    std::fs::write("docs/surface-report.md", report).expect("docs/ is writable");
    let scene_alpha: Vec<f64> = by_kind
        .iter()
        .map(|row| {
            row.iter().zip(&kinds).filter(|(_, k)| k.0.starts_with("scene")).fold(0.0f64, |m, (t, _)| m.max(t.alpha))
        })
        .collect();
    plot(&settings, &tallies, &times, scene_cases, &scene_alpha).expect("the plot is written");
    eprintln!("wrote docs/surface-report.md and docs/images/surface_error_time.svg");
}

/// `--time`: time per ray on the scene cases, all rays and the scenes' own, median of 7 runs,
/// no reference (for profiling: `SURFACE_REPORT_REPEAT` runs more). The default method, or
/// the settings `SURFACE_REPORT_ONLY` picks.
fn time_only(cases: &[Case], only: Option<&str>) {
    let repeats = std::env::var("SURFACE_REPORT_REPEAT").ok().and_then(|v| v.parse().ok()).unwrap_or(7);
    let settings: Vec<Setting> = match only {
        Some(o) => settings().into_iter().filter(|s| s.label().contains(o)).collect(),
        None => vec![Setting::F64(Method::default())],
    };
    for setting in settings {
        for case in cases {
            let prepared = Prepared::new(setting, &case.surface);
            let scene = case.scene_rays();
            println!(
                "{} on {}: {:.0} ns/ray over its {} scene rays, {:.0} over all {}",
                setting.label(),
                case.name,
                time_per_ray(&prepared, &scene, repeats),
                scene.rays.len(),
                time_per_ray(&prepared, case, repeats),
                case.rays.len()
            );
        }
    }
}

/// Sum of the tallies over the given cases, and the ray-weighted mean time per ray.
fn summary(tallies: &[Tally], times: &[f64], cases: std::ops::Range<usize>) -> (Tally, f64) {
    let mut sum = Tally::default();
    let mut time = 0.0;
    for c in cases {
        sum.add(&tallies[c]);
        time += times[c] * tallies[c].rays as f64;
    }
    (sum, time / sum.rays.max(1) as f64)
}

fn fmt_err(x: f64) -> String {
    if x == 0.0 { "0".into() } else { format!("{x:.1e}") }
}

#[allow(clippy::too_many_arguments)]
fn write_report(
    cases: &[Case],
    scene_cases: usize,
    settings: &[Setting],
    tallies: &[Vec<Tally>],
    (times, scene_ray_times): (&[Vec<f64>], &[f64]),
    kinds: &[(&str, usize)],
    by_kind: &[Vec<Tally>],
    total: usize,
) -> String {
    let mut md = String::new();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let _ = writeln!(md, "# Evolved-surface intersection: error against run time\n");
    let _ = writeln!(
        md,
        "Generated by `cargo run --release -p cga-trace --example surface_report` ({total} rays, {} surfaces; \
         {cores} cores, times single-threaded, median of 3 runs). Reference: f64 `(f, f')` sampling at 4096 \
         points per ray over [0, 1] (no culling) with the close-pair search and Newton to rounding level. α and hit-point errors are maxima over rays where both hit the same root; hit-point \
         distance is relative to the surface's bounding radius; normal error is the angle between the normals at \
         the two hits. *Missed*: the reference hits and the method does not, or hits farther on (it skipped the \
         nearest root); *false*: the method hits where the reference does not, or nearer. *Tangent*: the two \
         disagree on a ray tangent to the surface there (`|d·n| < 1e-6`), where hit and miss are both right to \
         rounding. *Other α*: the same point found on another circle of the family (the surface crosses itself \
         there). Every candidate is verified on the circle and the line (to 1e-6 r + 1e-9 |o − c| in f64), so \
         a loose tolerance shows as misses, never as a wrong point. *Scene rays*: the rays renders of the two \
         shipped scenes cast (primary, shadow, reflection) that reach the surface's bounding sphere; *scene \
         surfaces*: those and the adversarial rays on the same two surfaces. `--time` prints the default \
         method's times alone.\n",
        cases.len()
    );
    let _ = writeln!(md, "## Rays\n");
    let _ = writeln!(md, "| kind | rays |\n|---|---:|");
    for (k, n) in kinds {
        let _ = writeln!(md, "| {k} | {n} |");
    }
    let _ = writeln!(md, "\n## All rays, every setting\n");
    let _ = writeln!(
        md,
        "| setting | ns/ray (scene rays) | missed / false (scene rays) | ns/ray (scene surfaces) | ns/ray (all) | missed | false | tangent | other α | max α err, scene rays | max α err, simple roots | max α err, double roots | max point err | max normal err (rad) |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for (s, setting) in settings.iter().enumerate() {
        let (_, scene_time) = summary(&tallies[s], &times[s], 0..scene_cases);
        let (all, all_time) = summary(&tallies[s], &times[s], 0..cases.len());
        let scene = by_kind[s].iter().zip(kinds).filter(|(_, k)| k.0.starts_with("scene")).fold(
            Tally::default(),
            |mut sum, (t, _)| {
                sum.add(t);
                sum
            },
        );
        let _ = writeln!(
            md,
            "| {} | {:.0} | {} / {} | {scene_time:.0} | {all_time:.0} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            setting.label(),
            scene_ray_times[s],
            scene.missed,
            scene.false_hits,
            all.missed,
            all.false_hits,
            all.tangent,
            all.other_alpha,
            fmt_err(
                by_kind[s]
                    .iter()
                    .zip(kinds)
                    .filter(|(_, k)| k.0.starts_with("scene"))
                    .fold(0.0f64, |m, (t, _)| m.max(t.alpha))
            ),
            fmt_err(all.alpha),
            fmt_err(all.alpha_double),
            fmt_err(all.point),
            fmt_err(all.normal)
        );
    }
    let _ = writeln!(md, "\n## By kind of ray: missed / false (max α error)\n");
    let mut header = String::from("| setting |");
    let mut rule = String::from("|---|");
    for (k, _) in kinds {
        let _ = write!(header, " {k} |");
        rule.push_str("---:|");
    }
    let _ = writeln!(md, "{header}\n{rule}");
    for (s, setting) in settings.iter().enumerate() {
        let mut row = format!("| {} |", setting.label());
        for t in &by_kind[s] {
            let _ = write!(row, " {} / {} ({}) |", t.missed, t.false_hits, fmt_err(t.alpha));
        }
        let _ = writeln!(md, "{row}");
    }
    let _ = writeln!(md, "\n## By surface: missed / false (max α error), ns/ray\n");
    let _ = writeln!(md, "| surface | radii along the family | rays | reference hits |\n|---|---|---:|---:|");
    for (c, case) in cases.iter().enumerate() {
        let (lo, hi) = radius_range(&case.surface);
        let hits = tallies[0][c].hits + tallies[0][c].missed;
        let _ = writeln!(md, "| {} | {lo:.3e} … {hi:.3e} | {} | {hits} |", case.name, case.rays.len());
    }
    let _ = writeln!(md);
    let mut header = String::from("| setting |");
    let mut rule = String::from("|---|");
    for (c, _) in cases.iter().enumerate() {
        let _ = write!(header, " {} |", c + 1);
        rule.push_str("---:|");
    }
    let _ = writeln!(md, "Columns follow the rows of the table above.\n\n{header}\n{rule}");
    for (s, setting) in settings.iter().enumerate() {
        let mut row = format!("| {} |", setting.label());
        for (c, t) in tallies[s].iter().enumerate() {
            let _ = write!(row, " {} / {} ({}), {:.0} |", t.missed, t.false_hits, fmt_err(t.alpha), times[s][c]);
        }
        let _ = writeln!(md, "{row}");
    }
    md
}

/// Two panels against time per scene ray: the largest α error over the scene rays (simple
/// roots), and the missed plus false hits over all rays. One colour per method, one point per
/// setting (hollow: f32), labelled by its knobs.
fn plot(
    settings: &[Setting],
    tallies: &[Vec<Tally>],
    times: &[Vec<f64>],
    scene_cases: usize,
    scene_alpha: &[f64],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new("docs/images/surface_error_time.svg", (1100, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(550);
    // (setting, ns per scene ray, α error on scene rays, missed + false over all rays)
    let points: Vec<(Setting, f64, f64, f64)> = settings
        .iter()
        .enumerate()
        .map(|(s, setting)| {
            let (all, _) = summary(&tallies[s], &times[s], 0..tallies[s].len());
            let (_, time) = summary(&tallies[s], &times[s], 0..scene_cases);
            (*setting, time, scene_alpha[s].max(1e-16), (all.missed + all.false_hits) as f64 + 1.0)
        })
        .collect();
    let (t_lo, t_hi) = points.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let wrong_hi = points.iter().fold(1.0f64, |m, p| m.max(p.3)) * 3.0;
    // (area, title, y range, which value: 2 the α error, 3 the wrong-hit count)
    type Panel<'a, 'b> = (&'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>, &'static str, f64, f64, usize);
    let panels: [Panel; 2] = [
        (&left, "max α error, scene rays (simple roots)", 1e-16, 1.0, 2),
        (&right, "missed + false hits + 1, all rays", 0.7, wrong_hi, 3),
    ];
    let families = [("sampling", RED), ("polynomial", BLUE), ("hierarchy", GREEN), ("hybrid", MAGENTA)];
    for (area, y_desc, y_lo, y_hi, field) in panels {
        let mut chart = ChartBuilder::on(area)
            .caption(y_desc, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d((t_lo * 0.7..t_hi * 1.6).log_scale(), (y_lo..y_hi).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("ns per scene ray (one core)")
            .y_label_formatter(&|y| if field == 2 { format!("{y:.0e}") } else { format!("{y:.0}") })
            .x_label_formatter(&|x| format!("{x:.0}"))
            .draw()?;
        let y = |p: &(Setting, f64, f64, f64)| if field == 2 { p.2 } else { p.3 };
        for (family, colour) in families {
            let mine: Vec<_> = points.iter().filter(|p| p.0.family() == family).collect();
            chart
                .draw_series(mine.iter().map(|p| {
                    let style = if matches!(p.0, Setting::F32(_)) { colour.stroke_width(2) } else { colour.filled() };
                    EmptyElement::at((p.1, y(p))) + plotters::element::Circle::new((0, 0), 5, style)
                }))?
                .label(family)
                .legend(move |(x, y)| plotters::element::Circle::new((x, y), 5, colour.filled()));
            chart.draw_series(mine.iter().map(|p| {
                let text = knobs(&p.0);
                EmptyElement::at((p.1, y(p)))
                    + Text::new(text, (7, -4), ("sans-serif", 10).into_font().color(&colour.mix(0.9)))
            }))?;
        }
        // Where each panel has no points: top right of the error panel, bottom right of the
        // count panel.
        let corner = if field == 2 { SeriesLabelPosition::UpperRight } else { SeriesLabelPosition::LowerRight };
        chart.configure_series_labels().position(corner).border_style(BLACK).background_style(WHITE.mix(0.9)).draw()?;
    }
    root.present()?;
    Ok(())
}

/// A setting's knobs, short, for plot labels.
fn knobs(setting: &Setting) -> String {
    let tol = |t: f64| if t == 0.0 { "0".to_string() } else { format!("{t:.0e}") };
    let core = match *setting {
        Setting::F64(Method::Sampling { samples }) | Setting::F32(Finder::Samples(samples)) => samples.to_string(),
        Setting::F64(Method::Polynomial { tolerance }) | Setting::F32(Finder::Polynomial(tolerance)) => tol(tolerance),
        Setting::F64(Method::Hierarchy { leaves, per_leaf }) => format!("{leaves}×{per_leaf}"),
        Setting::F32(Finder::Slope(n)) => n.to_string(),
        Setting::F64(Method::Hybrid { leaves, tolerance }) => format!("{leaves}, {}", tol(tolerance)),
    };
    if matches!(setting, Setting::F32(_)) { format!("{core} f32") } else { core }
}
