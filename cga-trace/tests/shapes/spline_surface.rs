//! Spline surfaces (the paper's Fig. 3) hit exactly: the degree-(12d − 4) polynomial of each
//! segment against a dense reference (samples of `f` over the whole surface, sign changes
//! bisected and minima of `|f|` searched) on the rays of renders and on adversarial rays — in a knot
//! circle's plane, grazing the surface, through a knot — with no missed and no false hits and
//! α to 1e-9; and the segments meet without a crack.

use crate::common;

use cga_core::Joining;
use cga_core::euclid::{E3, add, circle_distance, cross, dot, perpendicular, scale, sub, unit};
use cga_trace::camera::Camera;
use cga_trace::ray::Ray;
use cga_trace::shapes::{Crossing, Shape};
use cga_trace::surface::{EvolvedSurface, Method, SplineSurface};
use common::swept::Whole;
use rand::{RngExt, SeedableRng};
use rand_xorshift::XorShiftRng;
use std::time::Instant;

/// A circle as `(centre, normal, radius)`.
type Round = (E3, E3, f64);

/// The control circles of the Fig. 3 scenes: `(centre, normal, radius)`.
const FIG3: [Round; 4] = [
    ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0),
    ([1.2, 0.0, 1.8], [0.4, 0.0, 1.0], 0.9),
    ([-0.3, 0.3, 3.6], [-0.4, 0.2, 1.0], 1.7),
    ([0.4, 0.0, 5.6], [0.0, 0.3, 1.0], 0.8),
];

fn surfaces() -> Vec<(String, SplineSurface)> {
    let mut rng = XorShiftRng::seed_from_u64(31);
    let mut random = |n: usize| -> Vec<Round> {
        (0..n)
            .map(|k| {
                let c = [
                    rng.random_range(-1.5..1.5),
                    rng.random_range(-1.5..1.5),
                    2.0 * k as f64 + rng.random_range(0.0..1.0),
                ];
                let n = [rng.random_range(-0.6..0.6), rng.random_range(-0.6..0.6), 1.0];
                (c, n, rng.random_range(0.7..2.0))
            })
            .collect()
    };
    let quadratic = [FIG3[0], FIG3[1], FIG3[3]];
    let kb = Joining::KochanekBartels { tension: 0.3, bias: -0.4, continuity: 0.5 };
    let cases: Vec<(&str, Vec<Round>, Joining)> = vec![
        ("linear", FIG3.to_vec(), Joining::Linear),
        ("quadratic", quadratic.to_vec(), Joining::Quadratic),
        ("cubic", FIG3.to_vec(), Joining::Cubic),
        ("catmull-rom", FIG3.to_vec(), Joining::CATMULL_ROM),
        ("kochanek-bartels", FIG3.to_vec(), kb),
        ("random quadratic", random(5), Joining::Quadratic),
        ("random cubic", random(4), Joining::Cubic),
        ("random catmull-rom", random(5), Joining::CATMULL_ROM),
    ];
    cases
        .into_iter()
        .filter_map(|(name, circles, joining)| {
            // A random set may pass through an imaginary circle: such a set is refused, by name.
            SplineSurface::new(&circles, joining, Method::default()).ok().map(|s| (name.to_string(), s))
        })
        .collect()
}

/// Rays of a 64×48 render from the Fig. 3 camera, and the shadow rays of their hits.
fn render_rays(surface: &SplineSurface) -> Vec<Ray> {
    let pose = Camera::pose_look_at([0.0, -14.0, 5.0], [0.0, 0.0, 2.6], [0.0, 0.0, 1.0]).unwrap();
    let camera = Camera::new(pose, 1.0, 0.93, 0.7, 64, 48).unwrap();
    let mut rays = Vec::new();
    for j in 0..48 {
        for i in 0..64 {
            let ray = camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5).unwrap();
            if let Some(hit) = surface.hit(&ray, 0.0, f64::INFINITY) {
                let off = cga_trace::ray::offset(hit.point, ray.origin, surface.crossing_error());
                rays.extend(Ray::leaving(hit.point, hit.normal, sub([-8.0, -10.0, 14.0], hit.point), off));
            }
            rays.push(ray);
        }
    }
    rays
}

/// A point of circle `(c, n, r)` at angle θ.
fn on_circle((c, n, r): (E3, E3, f64), theta: f64) -> E3 {
    let u = perpendicular(n);
    let v = cross(n, u);
    add(c, add(scale(u, r * theta.cos()), scale(v, r * theta.sin())))
}

/// Rays in each knot circle's plane (through it, at several offsets, and just outside it),
/// grazing the surface (along a tangent at a point of it), and through knot circles.
fn adversarial_rays(surface: &SplineSurface, rng: &mut XorShiftRng) -> Vec<Ray> {
    let spline = surface.spline();
    let o = surface.origin();
    let m = surface.segments();
    let mut rays = Vec::new();
    for j in 0..=m {
        let alpha = j as f64 / m as f64;
        let Some((c, n, r)) = spline.at(alpha).ok().and_then(|c| c.centre_normal_radius().ok()) else { continue };
        let c = add(c, o);
        let n = unit(n).unwrap();
        for k in 0..8 {
            let theta = k as f64 * std::f64::consts::TAU / 8.0 + 0.1;
            let along = on_circle(([0.0; 3], n, 1.0), theta);
            let across = cross(n, along);
            for offset in [0.0, 0.3, 0.9, 0.999, 1.001, 1.2] {
                let start = add(add(c, scale(across, offset * r)), scale(along, -20.0));
                rays.extend(Ray::new(start, along));
            }
            // Through a point of the knot circle, in a random direction.
            let x = on_circle((c, n, r), theta);
            let d =
                unit([rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)]).unwrap();
            rays.extend(Ray::new(sub(x, scale(d, 15.0)), d));
        }
    }
    // Grazing: along the tangent plane at random points of the surface.
    for _ in 0..200 {
        let alpha = rng.random_range(0.0..1.0);
        let Ok(circle) = spline.at(alpha) else { continue };
        let Ok((c, n, r)) = circle.centre_normal_radius() else { continue };
        let x = on_circle((c, n, r), rng.random_range(0.0..std::f64::consts::TAU));
        let Ok(normal) = spline.normal(alpha, x) else { continue };
        let random = [rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)];
        let Some(d) = unit(cross(normal, random)) else { continue };
        rays.extend(Ray::new(add(sub(x, scale(d, 15.0)), o), d));
    }
    rays
}

/// Rays per surface in `cargo test` (a debug build); the ignored test runs them all.
const QUICK: usize = 150;

#[test]
fn every_root_against_a_dense_reference() {
    let tally = against_the_reference(Some(QUICK), 512, &[Method::default()]);
    tally[0].check();
}

/// All rays of every surface against 16,384 samples of `f` over the whole surface, for every
/// method, with its time per ray — the error-against-run-time table of docs/SURFACE.md:
/// `cargo test --release -p cga-trace --test shapes spline_surface:: -- --ignored --nocapture`.
#[test]
#[ignore]
fn every_root_against_a_dense_reference_all_rays() {
    let methods = [
        Method::Sampling { samples: 64 },
        Method::Sampling { samples: 256 },
        Method::Sampling { samples: 1024 },
        Method::Hierarchy { leaves: 64, per_leaf: 4 },
        Method::Polynomial { tolerance: 0.0 },
        Method::default(),
    ];
    let tallies = against_the_reference(None, 16_384, &methods);
    println!(
        "| method | rays | hits | missed | false | worst α error (crossing) | ns per ray |\n|---|---|---|---|---|---|---|"
    );
    for (method, t) in methods.iter().zip(&tallies) {
        println!(
            "| `{method:?}` | {} | {} | {} | {} | {:.1e} | {:.0} |",
            t.rays,
            t.hits,
            t.missed.len(),
            t.false_hits.len(),
            t.worst_alpha,
            t.seconds * 1e9 / t.rays as f64
        );
    }
    println!(
        "(default: {} nearer roots and {} touches found that the reference stepped over, {} touches \
         placed more precisely; {} grazing hits, cos < 1e-3, not compared in α)",
        tallies[5].nearer, tallies[5].touches, tallies[5].refined, tallies[5].grazing
    );
    tallies[4].check();
    tallies[5].check();
}

/// One method's agreement with the reference.
#[derive(Default)]
struct Tally {
    rays: usize,
    hits: usize,
    missed: Vec<(E3, E3, f64, f64)>,
    false_hits: Vec<(E3, E3, f64, f64)>,
    nearer: usize,
    touches: usize,
    refined: usize,
    grazing: usize,
    worst_alpha: f64,
    seconds: f64,
}

impl Tally {
    /// 0 missed, 0 false, α to 1e-9 where the ray crosses the surface.
    fn check(&self) {
        println!(
            "{} rays, {} hits: {} missed, {} false; {} nearer roots and {} touches found that sampling \
             stepped over, {} touches placed more precisely; worst α difference {:.1e} where the ray \
             crosses the surface ({} grazing hits, cos < 1e-3, not compared)",
            self.rays,
            self.hits,
            self.missed.len(),
            self.false_hits.len(),
            self.nearer,
            self.touches,
            self.refined,
            self.worst_alpha,
            self.grazing
        );
        assert!(self.missed.is_empty(), "missed {:?}", &self.missed[..self.missed.len().min(5)]);
        assert!(self.false_hits.is_empty(), "false {:?}", &self.false_hits[..self.false_hits.len().min(5)]);
        assert!(self.worst_alpha <= 1e-9, "{:e}", self.worst_alpha);
        assert!(self.hits > self.rays / 10, "{} of {}", self.hits, self.rays);
    }

    /// Where the method's crossing `got` stands against the reference's `want`.
    fn add(&mut self, surface: &SplineSurface, ray: &Ray, want: Option<Crossing>, got: Option<Crossing>) {
        self.rays += 1;
        match (want, got) {
            (Some(want), Some(got)) => {
                self.hits += 1;
                let scale = want.t.max(1.0);
                let on = on_its_circle(surface, got.alpha.unwrap(), got.point);
                if (want.t - got.t).abs() <= 1e-9 * scale {
                    // α is defined to rounding where the ray crosses the surface; where it
                    // grazes (cos < 1e-3), ray and surface stay within ε of each other over ~√ε
                    // of the ray, and any method's α is that uncertain.
                    let cos = dot(surface.normal(ray, &got), ray.dir).abs();
                    if cos >= 1e-3 {
                        self.worst_alpha = self.worst_alpha.max((want.alpha.unwrap() - got.alpha.unwrap()).abs());
                    } else {
                        self.grazing += 1;
                    }
                } else if got.t < want.t && on < 1e-9 {
                    // A nearer root that sampling stepped over (a close pair or a touch).
                    self.nearer += 1;
                } else if (got.t - want.t).abs() <= 1e-6 * scale && on < 1e-9 {
                    // The same point: a touch that sampling placed by minimising |f| (to about
                    // √ε), this method to rounding.
                    self.refined += 1;
                } else {
                    self.missed.push((ray.origin, ray.dir, want.t, got.t));
                }
            }
            (Some(want), None) => self.missed.push((ray.origin, ray.dir, want.t, f64::NAN)),
            (None, Some(got)) => {
                // Sampling can step over a touch; the method's hit must lie on C_α.
                let on = on_its_circle(surface, got.alpha.unwrap(), got.point);
                if on < 1e-9 {
                    self.touches += 1;
                } else {
                    self.false_hits.push((ray.origin, ray.dir, got.t, on));
                }
            }
            (None, None) => {}
        }
    }
}

/// Every method against the reference on the rays of every surface (all, or `rays_per_surface`
/// evenly thinned), and the time each method takes over them.
fn against_the_reference(rays_per_surface: Option<usize>, samples: usize, methods: &[Method]) -> Vec<Tally> {
    let mut rng = XorShiftRng::seed_from_u64(8);
    let mut tallies: Vec<Tally> = methods.iter().map(|_| Tally::default()).collect();
    let surfaces = surfaces();
    assert!(surfaces.len() >= 7, "{} surfaces", surfaces.len());
    for (name, surface) in &surfaces {
        let whole = Whole(surface.spline().clone());
        let reference = EvolvedSurface::of(surface.origin(), whole, Method::Sampling { samples }).unwrap();
        let mut rays = render_rays(surface);
        rays.extend(adversarial_rays(surface, &mut rng));
        if let Some(n) = rays_per_surface {
            // Every kind of ray, evenly thinned.
            let step = rays.len().div_ceil(n);
            rays = rays.into_iter().step_by(step).collect();
        }
        let wants: Vec<Option<Crossing>> = rays.iter().map(|r| reference.intersect(r, 0.0, f64::INFINITY)).collect();
        for (method, tally) in methods.iter().zip(&mut tallies) {
            let surface = surface.with_method(*method).unwrap();
            let start = Instant::now();
            let gots: Vec<Option<Crossing>> = rays.iter().map(|r| surface.intersect(r, 0.0, f64::INFINITY)).collect();
            tally.seconds += start.elapsed().as_secs_f64();
            let before = (tally.missed.len(), tally.false_hits.len());
            for ((ray, want), got) in rays.iter().zip(&wants).zip(gots) {
                tally.add(&surface, ray, *want, got);
            }
            let (missed, false_hits) = (tally.missed.len() - before.0, tally.false_hits.len() - before.1);
            println!("{name}, {method:?}: {} rays, {missed} missed, {false_hits} false", rays.len());
        }
    }
    tallies
}

/// Distance of `x` from `C_α`, in radii.
fn on_its_circle(surface: &SplineSurface, alpha: f64, x: E3) -> f64 {
    let circle = surface.spline().at(alpha).ok().and_then(|c| c.centre_normal_radius().ok());
    circle.map_or(f64::INFINITY, |c| circle_distance(sub(x, surface.origin()), c))
}

/// Neighbouring segments meet on the same knot circle: rays aimed at points of every knot
/// circle hit the surface there, and the α they report is the knot's.
#[test]
fn segments_meet_without_a_crack() {
    for (name, surface) in surfaces() {
        let m = surface.segments();
        let o = surface.origin();
        for j in 1..m {
            let alpha = j as f64 / m as f64;
            let (c, n, r) = surface.spline().at(alpha).unwrap().centre_normal_radius().unwrap();
            for k in 0..64 {
                let x = add(on_circle((c, n, r), k as f64 * std::f64::consts::TAU / 64.0), o);
                // From outside, straight at the knot point, along the outward radial direction
                // tilted off the knot's plane.
                let outward = unit(add(sub(sub(x, o), c), scale(n, 0.3))).unwrap();
                let ray = Ray::new(add(x, scale(outward, 30.0)), scale(outward, -1.0)).unwrap();
                let hit = surface.intersect(&ray, 0.0, f64::INFINITY);
                let hit = hit.unwrap_or_else(|| panic!("{name}: a crack at knot {j}, point {k}"));
                // The first hit is at the knot point or nearer (the surface may bulge out).
                assert!(hit.t <= 30.0 + 1e-9, "{name}: knot {j}, point {k}: t = {}", hit.t);
            }
        }
    }
}

/// Rays aimed at points of a segment's circles near its ends (α within 1e-7 to 3e-2 of
/// either end, where the polynomial's coefficients are many decades below its largest): each
/// hits where it is aimed, to 1e-9 in α, for linear, quadratic and cubic segments, at two
/// scales, from every side and slanted towards grazing. (The root finder's own test of that
/// cause is `a_root_among_tiny_coefficients_is_placed_to_its_own_rounding`.)
#[test]
fn roots_near_a_segment_end_for_every_degree() {
    let sets: [(&str, Vec<Round>, Joining); 3] = [
        ("linear", FIG3[..2].to_vec(), Joining::Linear),
        ("quadratic", vec![FIG3[0], FIG3[1], FIG3[3]], Joining::Quadratic),
        ("cubic", FIG3.to_vec(), Joining::Cubic),
    ];
    for ((name, circles, joining), size) in sets.into_iter().flat_map(|s| [1.0, 1.0 / 16.0].map(|k| (s.clone(), k))) {
        let circles: Vec<Round> = circles.iter().map(|&(c, n, r)| (scale(c, size), n, r * size)).collect();
        let spline = SplineSurface::new(&circles, joining, Method::default()).unwrap();
        assert_eq!(spline.segments(), 1, "{name}");
        let controls = spline.spline().segment(0);
        let o = spline.origin();
        let surfaces: Vec<(String, Box<dyn Shape>)> = vec![
            ("spline".into(), Box::new(spline.clone())),
            ("polynomial".into(), Box::new(spline.with_method(Method::Polynomial { tolerance: 0.0 }).unwrap())),
        ];
        let (mut aimed, mut total) = (0, 0);
        for &near in &[1e-7, 1e-5, 1e-3, 3e-3, 1e-2, 3e-2] {
            for alpha in [near, 1.0 - near] {
                let circle = cga_core::bezier(controls, alpha);
                let circle = cga_core::project_at(circle, alpha).unwrap();
                let (c, n, r) = circle.centre_normal_radius().unwrap();
                for k in 0..16 {
                    let x = on_circle((c, n, r), k as f64 * std::f64::consts::TAU / 16.0 + 0.05);
                    // From outside, at the point: radial, tilted off the circle's plane both
                    // ways, and slanted along the circle (towards grazing, as a camera looking
                    // down on a rim sees it).
                    let radial = unit(sub(x, c)).unwrap();
                    let along = cross(unit(n).unwrap(), radial);
                    for (tilt, slant) in [(-0.4, 0.0), (0.4, 0.0), (0.4, 1.5), (-0.4, -1.5), (1.2, 3.0), (-1.2, 3.0)] {
                        let outward = unit(add(add(radial, scale(n, tilt)), scale(along, slant))).unwrap();
                        let ray = Ray::new(add(add(x, o), scale(outward, 30.0 * size)), scale(outward, -1.0)).unwrap();
                        for (method, surface) in &surfaces {
                            total += 1;
                            let hit = surface.intersect(&ray, 0.0, f64::INFINITY);
                            let hit = hit.unwrap_or_else(|| panic!("{name}, {method}: missed α = {alpha}, point {k}"));
                            assert!(hit.t <= (30.0 + 1e-9) * size, "{name}, {method}: α = {alpha}: t = {}", hit.t);
                            if (hit.t - 30.0 * size).abs() <= 1e-9 * 30.0 * size {
                                aimed += 1;
                                let got = hit.alpha.unwrap();
                                assert!((got - alpha).abs() <= 1e-9, "{name}, {method}: α {got} for {alpha}");
                            }
                        }
                    }
                }
            }
        }
        // Most rays meet the surface first where they are aimed.
        assert!(aimed * 10 >= total * 8, "{name}: {aimed} of {total} at the aimed point");
    }
}

/// A shadow ray's test stops at the first crossing it verifies, or at one proved to lie within
/// its range: it answers as the nearest crossing does, on the rays of renders, their shadow
/// rays and adversarial rays, with ranges that end before, between and after the crossings (`t_max`
/// at a crossing's `t` and either side of it) and that start at, before and just after one
/// (a shadow ray leaving the surface).
#[test]
fn occlusion_is_whether_a_crossing_is_in_range() {
    let mut rng = XorShiftRng::seed_from_u64(5);
    for (name, surface) in surfaces() {
        let mut rays = render_rays(&surface);
        rays.extend(adversarial_rays(&surface, &mut rng));
        let (mut blocked, mut tested) = (0, 0);
        for ray in rays.iter().step_by(3) {
            let nearest = surface.intersect(ray, 0.0, f64::INFINITY);
            let inf = f64::INFINITY;
            let ranges = match nearest {
                Some(c) => vec![
                    (0.0, inf),
                    (0.0, c.t * (1.0 + 1e-9)),
                    (0.0, c.t * (1.0 - 1e-9)),
                    (0.0, 0.5 * c.t),
                    (0.0, 2.0 * c.t),
                    (c.t * (1.0 - 1e-9), inf),
                    (c.t * (1.0 + 1e-9), inf),
                    (c.t + 1e-5, inf),
                    (c.t - 1e-5, c.t + 1e-5),
                ],
                None => vec![(0.0, inf), (0.0, 30.0)],
            };
            for (t_min, t_max) in ranges {
                let want = surface.intersect(ray, t_min, t_max).is_some();
                assert_eq!(surface.occludes(ray, t_min, t_max), want, "{name}: {ray:?} in ({t_min}, {t_max})");
                blocked += usize::from(want);
                tested += 1;
            }
        }
        assert!(blocked > 0 && blocked < tested, "{name}: {blocked} of {tested} blocked");
    }
}

/// A ray that touches the Catmull–Rom surface of Fig. 3 (`f` has a double root at α ≈ 0.3895,
/// t = 15, inside one cell), found by every method; the hybrid method's cells reach it alone
/// (the nearest cell first, before any crossing narrows the window): the squared
/// polynomial's touch level is its whole polynomial's, whatever the interval it is restricted
/// to. Relative to the restriction's own coefficients, a cell's touch was lost where a wider
/// interval found it.
#[test]
fn a_touch_inside_one_cell_is_found() {
    let (origin, dir) = (
        [7.009789413861853, 5.918700683199715, 14.712621495435679],
        [-0.32607567175461344, -0.40811200482895205, -0.8527128753597376],
    );
    let ray = Ray { origin, dir, carrier: cga_core::Line::from_point_unit_direction(origin, dir) };
    let surface = SplineSurface::new(&FIG3, Joining::CATMULL_ROM, Method::default()).unwrap();
    let polynomial = surface.with_method(Method::Polynomial { tolerance: 0.0 }).unwrap();
    for (t_max, s) in [(f64::INFINITY, &surface), (15.5, &surface), (f64::INFINITY, &polynomial)] {
        let hit = s.intersect(&ray, 0.0, t_max).expect("the touch");
        assert!((hit.t - 15.0).abs() < 1e-9, "t = {}", hit.t);
        assert!((hit.alpha.unwrap() - 0.3894660300495663).abs() < 1e-6, "α = {:?}", hit.alpha);
    }
}
