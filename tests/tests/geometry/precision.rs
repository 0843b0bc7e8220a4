//! Precision anywhere: classification that no translation or scaling changes, constructors
//! at the accuracy the null basis allows, and named refusals where f64 cannot deliver.
//!
//! References we did not write: exact Euclidean formulas (glam-style, on the inputs), and
//! for interpolation and normals the same generic code run in double-double arithmetic
//! (`twofloat`, about 32 digits), which measures f64's rounding.
//!
//! `cargo test --test geometry precision:: -- --ignored --nocapture` prints the tables of
//! docs/STABILITY.md.

use cga_tests::common;

use cga_core::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub, unit};
use cga_core::{
    Circle, Disk, GeometryError, Hit, InterpolationError, Line, NormalError, Pair, Plane, Real, Sphere, up,
};
use common::Rng;
use common::dd::{Dd, dd3, f3};

const EPS: f64 = f64::EPSILON;

/// A line at distance `h` from `c`, along a random direction, through a random point of it.
fn line_at(rng: &mut Rng, c: E3, h: f64, r: f64) -> (Line, E3) {
    let d = rng.direction();
    let off = unit(cross(d, rng.direction())).unwrap();
    let p = add(add(c, scale(off, h)), scale(d, r * rng.range(-5.0, 5.0)));
    (Line::from_point_direction(p, d).unwrap(), d)
}

/// The documented band of `RoundMeet::new`: `(32 + 4 (1 + ρ)²) ε r`.
fn band(rho: f64) -> f64 {
    (32.0 + 4.0 * (1.0 + rho).powi(2)) * EPS
}

#[test]
fn sphere_meets_are_classified_alike_anywhere_and_at_any_scale() {
    let mut rng = Rng::new(11);
    let (mut checked, mut sharp, mut outside_band_wrong) = (0, 0, Vec::new());
    for _ in 0..20_000 {
        let (distance, r) = (rng.decades(0.0, 6.0), rng.decades(-4.0, 4.0));
        let c = scale(rng.direction(), distance);
        // Half the lines near tangency (within 1e-3 r), half anywhere within 2 r.
        let h = if rng.unit() < 0.5 { r * (1.0 + rng.range(-1e-3, 1e-3)) } else { r * rng.range(0.0, 2.0) };
        let (line, _) = line_at(&mut rng, c, h, r);
        let sphere = Sphere::from_centre_radius(c, r).unwrap();
        let hit = line.meet_sphere(&sphere).hit;
        let euclid = if h < r { Hit::Two } else { Hit::Miss };
        let rho = distance / r;
        let w = band(rho);
        checked += 1;
        sharp += usize::from(w < 1e-3);
        if hit != euclid && (h - r).abs() > w * r {
            outside_band_wrong.push(format!("|c| {distance:e}, r {r:e}, h/r − 1 = {:e}: {hit:?}", h / r - 1.0));
        }
    }
    assert!(
        outside_band_wrong.is_empty(),
        "{} misclassified outside the band: {:#?}",
        outside_band_wrong.len(),
        &outside_band_wrong[..outside_band_wrong.len().min(10)]
    );
    assert!(sharp > checked / 2, "the band was narrow (< 1e-3 r) in only {sharp} of {checked} cases");
}

#[test]
fn the_same_configuration_moved_and_scaled_is_classified_the_same() {
    // Lines 1e-9 r off tangency, inside and out: beyond the band near the origin, so the
    // classification must be the Euclidean one there and wherever the band stays narrower.
    let mut rng = Rng::new(12);
    for _ in 0..2000 {
        let inside = rng.unit() < 0.5;
        let h = if inside { 1.0 - 1e-9 } else { 1.0 + 1e-9 };
        let want = if inside { Hit::Two } else { Hit::Miss };
        let (d, off) = (rng.direction(), rng.direction());
        let off = unit(cross(d, off)).unwrap();
        for (shift, size) in [(0.0, 1.0), (1e-4, 1e-4), (1.0, 1e4), (10.0, 1.0), (100.0, 1e2), (3e3, 1e4), (1e6, 1e5)] {
            let c = scale([1.0, 1.0, 1.0], shift);
            let p = add(c, scale(off, h * size));
            let line = Line::from_point_direction(p, d).unwrap();
            let meet = line.meet_sphere(&Sphere::from_centre_radius(c, size).unwrap());
            assert!(band(norm(c) / size) < 1e-9);
            assert_eq!(meet.hit, want, "shift {shift}, size {size}, inside {inside}");
        }
    }
}

#[test]
fn plane_meets_are_classified_by_angle_alone() {
    let mut rng = Rng::new(13);
    for _ in 0..5000 {
        let (distance, size) = (rng.decades(0.0, 6.0), rng.decades(-4.0, 4.0));
        let c = scale(rng.direction(), distance);
        let n = rng.direction();
        let plane = Plane::from_point_normal(c, n).unwrap();
        // Exactly parallel (in the plane's own axes): no crossing, at any place and scale.
        let u = perpendicular(n);
        let p = add(c, scale(n, size));
        assert_eq!(Line::from_point_direction(p, u).unwrap().meet_plane(&plane), None);
        // At an angle well above the band (|d·n| ≥ 1e-10): a crossing, where Euclid puts it.
        let sine = rng.decades(-10.0, 0.0);
        let d = add(scale(u, (1.0 - sine * sine).sqrt()), scale(n, -sine));
        let x = Line::from_point_direction(p, d).unwrap().meet_plane(&plane).expect("crosses");
        let want = add(p, scale(d, size / sine));
        let err = norm(sub(x, want)) / (norm(want) + size / sine);
        assert!(err < 1e-6, "crossing off by {err:e} (sine {sine:e})");
    }
}

#[test]
fn disks_keep_their_rim_anywhere() {
    let mut rng = Rng::new(14);
    for _ in 0..5000 {
        let (distance, r) = (rng.decades(0.0, 6.0), rng.decades(-4.0, 4.0));
        let (c, n) = (scale(rng.direction(), distance), rng.direction());
        let disk = Disk::from_centre_normal_radius(c, n, r).unwrap();
        assert_eq!((disk.centre, disk.radius), (c, r), "kept exactly");
        // A line through the plane at 1 ± 1e-6 radii from the centre: the rim test may err
        // only within the crossing's own rounding, ε (|x| + r).
        let u = perpendicular(n);
        for (k, want) in [(1.0 - 1e-6, true), (1.0 + 1e-6, false)] {
            let x = add(c, scale(u, k * r));
            let line = Line::from_point_direction(add(x, scale(n, r)), scale(n, -1.0)).unwrap();
            let got = line.meet_disk(&disk).is_some();
            if (distance + r) * 64.0 * EPS < 1e-6 * r {
                assert_eq!(got, want, "|c| {distance:e}, r {r:e}, at {k} radii");
            }
        }
    }
}

/// Relative error of a circle's read-back centre, radius and normal against its parameters.
fn circle_error(c: &Circle, (centre, n, r): (E3, E3, f64)) -> f64 {
    match c.centre_normal_radius() {
        Ok((c2, n2, r2)) => {
            let angle = norm(cross(n, n2)).atan2(dot(n, n2).abs());
            (norm(sub(c2, centre)) / r).max((r2 - r).abs() / r).max(angle)
        }
        Err(_) => f64::INFINITY,
    }
}

/// Three points of the circle `(c, n, r)`, counter-clockwise about `n`.
fn three_points((c, n, r): (E3, E3, f64)) -> [E3; 3] {
    let u = scale(perpendicular(unit(n).unwrap()), r);
    let v = cross(unit(n).unwrap(), u);
    [add(c, u), add(c, v), sub(c, u)]
}

/// The circle of `(c, n, r)` as the wedge of three of its conformal points, as
/// constructors built it before.
fn circle_through_points(p: (E3, E3, f64)) -> Circle {
    let [a, b, c] = three_points(p);
    ((up(a) ^ up(b)) ^ up(c)).try_normalise().unwrap()
}

/// Worst read-back error of circles at `ρ = |c|/r` over random placements and sizes:
/// `(from_centre_normal_radius, Circle::through, the wedge of three points)`.
fn circle_errors(rng: &mut Rng, rho: f64, samples: usize) -> (f64, f64, f64) {
    let (mut closed, mut through, mut wedge) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..samples {
        let r = rng.decades(-3.0, 3.0);
        let p = (scale(rng.direction(), rho * r), rng.direction(), r);
        closed = closed.max(circle_error(&Circle::from_centre_normal_radius(p.0, p.1, p.2).unwrap(), p));
        let [a, b, c] = three_points(p);
        through = through.max(Circle::through(a, b, c).map_or(f64::INFINITY, |k| circle_error(&k, p)));
        wedge = wedge.max(circle_error(&circle_through_points(p), p));
    }
    (closed, through, wedge)
}

/// Worst read-back error of spheres through four of their points at `ρ = |c|/r`:
/// `(Sphere::through, the wedge of four points)`.
fn sphere_errors(rng: &mut Rng, rho: f64, samples: usize) -> (f64, f64) {
    let (mut through, mut wedge) = (0.0f64, 0.0f64);
    for _ in 0..samples {
        let r = rng.decades(-3.0, 3.0);
        let c = scale(rng.direction(), rho * r);
        let p: Vec<E3> = (0..4).map(|_| add(c, scale(rng.direction(), r))).collect();
        let err = |s: Option<Sphere>| match s.map(|s| s.centre_radius()) {
            Some(Ok((c2, r2))) => (norm(sub(c2, c)) / r).max((r2 - r).abs() / r),
            _ => f64::INFINITY,
        };
        through = through.max(err(Sphere::through(p[0], p[1], p[2], p[3]).ok()));
        wedge = wedge.max(err((((up(p[0]) ^ up(p[1])) ^ up(p[2])) ^ up(p[3])).try_normalise()));
    }
    (through, wedge)
}

#[test]
fn circles_from_parameters_lose_only_eps_rho_squared() {
    let mut rng = Rng::new(15);
    for rho in [1.0, 1e2, 1e4, 1e6] {
        let (closed, through, _) = circle_errors(&mut rng, rho, 300);
        assert!(closed <= 16.0 * EPS * (1.0 + rho).powi(2), "ρ = {rho:e}: {closed:e}");
        assert!(through <= 16.0 * EPS * (1.0 + rho).powi(2), "through points, ρ = {rho:e}: {through:e}");
        // Random points on a sphere are not well spread: allow for their conditioning.
        let (sphere, _) = sphere_errors(&mut rng, rho, 100);
        assert!(sphere <= 1e3 * EPS * (1.0 + rho).powi(2), "sphere through points, ρ = {rho:e}: {sphere:e}");
    }
    // Spheres and their read-back likewise.
    for rho in [1.0, 1e2, 1e4, 1e6] {
        let (c, r) = (scale(rng.direction(), rho * 3.0), 3.0);
        let (c2, r2) = Sphere::from_centre_radius(c, r).unwrap().centre_radius().unwrap();
        let err = (norm(sub(c2, c)) / r).max((r2 - r).abs() / r);
        assert!(err <= 16.0 * EPS * (1.0 + rho).powi(2), "sphere ρ = {rho:e}: {err:e}");
    }
}

/// Worst end-point read-back error (relative to the half-distance `h`) of point pairs at
/// `ρ = |midpoint|/h`: `(closed form, the wedge up(a) ∧ up(b))`.
fn pair_errors(rng: &mut Rng, rho: f64, samples: usize) -> (f64, f64) {
    let (mut closed, mut wedge) = (0.0f64, 0.0f64);
    for _ in 0..samples {
        let h = rng.decades(-3.0, 3.0);
        let (m, d) = (scale(rng.direction(), rho * h), rng.direction());
        let (a, b) = (add(m, scale(d, -h)), add(m, scale(d, h)));
        let err = |p: cga_core::Bivector| match p.end_points() {
            Ok([x, y]) => norm(sub(x, a)).max(norm(sub(y, b))) / h,
            Err(_) => f64::INFINITY,
        };
        closed = closed.max(err(cga_core::Bivector::from_points(a, b).unwrap()));
        wedge = wedge.max(err(up(a) ^ up(b)));
    }
    (closed, wedge)
}

#[test]
fn point_pairs_from_points_lose_only_eps_rho_squared() {
    let mut rng = Rng::new(18);
    for rho in [1.0, 1e2, 1e4, 1e6] {
        let (closed, _) = pair_errors(&mut rng, rho, 300);
        assert!(closed <= 16.0 * EPS * (1.0 + rho).powi(2), "ρ = {rho:e}: {closed:e}");
    }
}

/// Unit-ish circles at distance `d` from the origin, as a pair.
fn far_pair(d: f64) -> ((E3, E3, f64), (E3, E3, f64)) {
    let c1 = [d, 0.3 * d, -0.2 * d];
    ((c1, [0.0, 0.2, 1.0], 1.0), (add(c1, [0.5, 0.2, 2.0]), [0.3, -0.1, 1.0], 1.5))
}

fn pair_f64(a: (E3, E3, f64), b: (E3, E3, f64)) -> Result<Pair<Circle>, InterpolationError> {
    Pair::new(
        Circle::from_centre_normal_radius(a.0, a.1, a.2).unwrap(),
        Circle::from_centre_normal_radius(b.0, b.1, b.2).unwrap(),
    )
}

fn pair_dd(a: (E3, E3, f64), b: (E3, E3, f64)) -> Pair<Circle<Dd>> {
    let c = |p: (E3, E3, f64)| Circle::<Dd>::from_centre_normal_radius(dd3(p.0), dd3(p.1), Dd::from_f64(p.2)).unwrap();
    Pair::new_unchecked(c(a), c(b)).unwrap()
}

/// `(centre/radius error of C_½, normal angle error)` of an f64 pair against double-double.
fn interpolation_errors(p: &Pair<Circle>, q: &Pair<Circle<Dd>>) -> (f64, f64) {
    let (bc, bn, br) = q.at(Dd::from_f64(0.5)).unwrap().centre_normal_radius().unwrap();
    let (bc, bn, br) = (f3(bc), f3(bn), br.hi());
    let Ok(Ok((ac, _, ar))) = p.at(0.5).map(|c| c.centre_normal_radius()) else {
        return (f64::INFINITY, f64::INFINITY);
    };
    let x = add(bc, scale(perpendicular(bn), br));
    let normal = match (p.normal_parts(0.5, x), q.normal(Dd::from_f64(0.5), dd3(x))) {
        (Ok(parts), Ok(want)) => parts.normal_line.direction().map_or(f64::INFINITY, |n| norm(cross(n, f3(want)))),
        _ => f64::INFINITY,
    };
    ((norm(sub(ac, bc)) / br).max((ar - br).abs() / br), normal)
}

#[test]
fn interpolation_far_away_is_refused_by_name_and_the_estimate_bounds_the_error() {
    // The case: unit circles at |c| = 1.5e5 came back Ok with a radius 10× off.
    let (a, b) = far_pair(1.5e5);
    assert!(matches!(pair_f64(a, b), Err(InterpolationError::IllConditioned { .. })));
    // A circle of radius 1e-6 six units from the origin (ρ = 6e6) paired with a unit one:
    // f64 loses 1.2e-6 there, beyond the promised accuracy, and says so.
    let tiny = pair_f64(([5.0, -3.0, 2.0], [0.0, 0.0, 1.0], 1e-6), ([5.3, -2.9, 3.0], [0.2, 0.0, 1.0], 1.0));
    assert!(matches!(tiny, Err(InterpolationError::IllConditioned { .. })), "{tiny:?}");
    // At the origin the same pair is well conditioned (sizes alone do not matter) and exact.
    let (a, b) = (([0.0; 3], [0.0, 0.0, 1.0], 1e-6), ([0.3, 0.1, 1.0], [0.2, 0.0, 1.0], 1.0));
    let p = pair_f64(a, b).expect("accepted");
    let (circle, _) = interpolation_errors(&p, &pair_dd(a, b));
    assert!(circle <= p.condition() && circle < 1e-14, "{circle:e}");
    // Wherever the pair is accepted, the estimate bounds the error of C_½ and of the normal.
    for d in [1.0, 10.0, 100.0, 300.0, 1e3, 3e3, 6e3] {
        let (a, b) = far_pair(d);
        let Ok(p) = pair_f64(a, b) else { continue };
        let (circle, normal) = interpolation_errors(&p, &pair_dd(a, b));
        let estimate = p.condition() + 4.0 * EPS;
        assert!(circle <= estimate && normal <= estimate, "d {d:e}: errors {circle:e}, {normal:e} > {estimate:e}");
    }
}

#[test]
fn normals_say_when_they_cannot_be_trusted() {
    let a = ([1.0, 2.0, 3.0], [0.2, 0.3, 1.0], 1.5);
    // Nearly identical circles: Ċ is rounding noise.
    let b = ([1.0 + 1e-15, 2.0, 3.0], [0.2, 0.3, 1.0], 1.5 + 1e-15);
    let p = pair_f64(a, b).unwrap();
    let (c, n, r) = p.at(0.5).unwrap().centre_normal_radius().unwrap();
    let x = add(c, scale(perpendicular(n), r));
    assert!(matches!(p.normal(0.5, x), Err(NormalError::IllConditioned { .. })));
    // 1e-3 apart: fine, and a point off the circle is refused.
    let b = ([1.0 + 1e-3, 2.0, 3.0], [0.2, 0.3, 1.0], 1.5 + 1e-3);
    let p = pair_f64(a, b).unwrap();
    let (c, n, r) = p.at(0.5).unwrap().centre_normal_radius().unwrap();
    let x = add(c, scale(perpendicular(n), r));
    assert!(p.normal(0.5, x).is_ok());
    let off = add(x, scale(n, 1e-3 * r));
    assert!(matches!(p.normal(0.5, off), Err(NormalError::OffCircle { distance }) if (distance - 1e-3).abs() < 1e-6));
}

#[test]
fn huge_coordinates_give_named_errors_never_nan() {
    let big = 1e154;
    let line = Line::through([big, 0.0, 0.0], [big, big, 0.0]).unwrap();
    assert!(line.to_array().iter().all(|x| x.is_finite()), "{line:?}");
    assert_eq!(line.direction().unwrap(), [0.0, 1.0, 0.0]);
    assert_eq!(Line::through([1e308, 0.0, 0.0], [-1e308, 0.0, 0.0]), Err(GeometryError::Overflow));
    let plane = Plane::through([big, 0.0, 0.0], [big, big, 0.0], [big, 0.0, big]).unwrap();
    assert!(plane.to_array().iter().all(|x| x.is_finite()));
    let sphere = Sphere::from_centre_radius([big, 0.0, 0.0], 1.0).unwrap();
    assert!(sphere.to_array().iter().all(|x| x.is_finite()));
    assert_eq!(Sphere::from_centre_radius([2.0 * big, 0.0, 0.0], 1.0), Err(GeometryError::Overflow));
    let huge = 2.0 * big;
    // Built from scaled differences, the circle through three far points exists; reading its
    // centre back squares coordinates of 1e154 and is refused by name, never NaN.
    match Circle::through([huge, 0.0, 0.0], [0.0, huge, 0.0], [0.0, 0.0, huge]) {
        Ok(c) => assert!(c.to_array().iter().all(|x| x.is_finite()) && c.centre_normal_radius().is_err()),
        Err(e) => assert_eq!(e, GeometryError::Overflow),
    }
    assert_eq!(Circle::from_centre_normal_radius([huge, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0), Err(GeometryError::Overflow));
    assert!(up::<f64>([huge, 0.0, 0.0]).ei.is_infinite(), "up itself overflows: constructors must catch it");
}

/// The tables of docs/STABILITY.md.
#[test]
#[ignore = "prints the tables of docs/STABILITY.md"]
fn stability_tables() {
    let mut rng = Rng::new(16);
    println!("### Circles from centre, normal, radius: read-back error against ρ = |c|/r\n");
    println!(
        "| ρ | before: wedge of three points | after: S ∨ Π (from centre) | after: `Circle::through` | ε ρ² | f32, after (from centre) |"
    );
    println!("|---|---|---|---|---|---|");
    for rho in [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6] {
        let (closed, through, points) = circle_errors(&mut rng, rho, 200);
        let f32_err = {
            let (c, n, r) = (scale(rng.direction(), rho), rng.direction(), 1.0);
            let t = |v: E3| v.map(|x| x as f32);
            match Circle::<f32>::from_centre_normal_radius(t(c), t(n), r as f32).and_then(|k| k.centre_normal_radius())
            {
                Ok((c2, n2, r2)) => {
                    let f = |v: [f32; 3]| v.map(f64::from);
                    (norm(sub(f(c2), c)) / r).max((f64::from(r2) - r).abs() / r).max(norm(cross(f(n2), n)))
                }
                Err(_) => f64::INFINITY,
            }
        };
        println!(
            "| {rho:.0e} | {points:.1e} | {closed:.1e} | {through:.1e} | {:.1e} | {f32_err:.1e} |",
            EPS * rho * rho
        );
    }
    println!("\n### Spheres through four points: centre and radius read-back error against ρ = |c|/r\n");
    println!("| ρ | before: wedge of four points | after: `Sphere::through` (circumsphere) | ε ρ² |");
    println!("|---|---|---|---|");
    for rho in [1.0, 1e2, 1e4, 1e6] {
        let (through, wedge) = sphere_errors(&mut rng, rho, 200);
        println!("| {rho:.0e} | {wedge:.1e} | {through:.1e} | {:.1e} |", EPS * rho * rho);
    }
    println!("\n### Point pairs from two points: end-point read-back error against ρ = |midpoint|/half-distance\n");
    println!("| ρ | before: up(a) ∧ up(b) | after: L ∨ S (closed form) | ε ρ² |");
    println!("|---|---|---|---|");
    for rho in [1.0, 1e2, 1e4, 1e6] {
        let (closed, wedge) = pair_errors(&mut rng, rho, 200);
        println!("| {rho:.0e} | {wedge:.1e} | {closed:.1e} | {:.1e} |", EPS * rho * rho);
    }
    println!("\n### Line ∨ sphere: error of P² = (r² − d²)/r² against ρ (distances 1…1e6, radii 1e-4…1e4)\n");
    println!(
        "| ρ | max \\|P² − (r² − d²)/r²\\| | / ε(1 + ρ)² | band \\|d − r\\|/r | misclassified, before (64 ε Σ P_k²) | misclassified, after | f32: max \\|P² − …\\| | f32: misclassified |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for rho in [1.0, 1e2, 1e4, 1e6, 1e8] {
        let (mut worst, mut before, mut after) = (0.0f64, 0, 0);
        let (mut worst32, mut after32) = (0.0f64, 0);
        for _ in 0..1000 {
            let r = rng.decades(-4.0, 4.0);
            let c = scale(rng.direction(), rho * r);
            let h = r * rng.range(0.5, 1.5);
            let (line, _) = line_at(&mut rng, c, h, r);
            let m = line.meet_sphere(&Sphere::from_centre_radius(c, r).unwrap());
            worst = worst.max((m.square - (r * r - h * h) / (r * r)).abs());
            let euclid = if h < r { Hit::Two } else { Hit::Miss };
            // The rule before: tangent when |P²| ≤ 64 ε Σ (coefficients of P)².
            let size: f64 = m.pair.to_array().iter().map(|x| x * x).sum();
            let old = if m.square.abs() <= 64.0 * EPS * size {
                Hit::Tangent
            } else if m.square > 0.0 {
                Hit::Two
            } else {
                Hit::Miss
            };
            before += usize::from(old != euclid);
            after += usize::from(m.hit != euclid);
            // The same configuration in f32.
            let t = |x: E3| x.map(|v| v as f32);
            let (p, d) = (line.point().unwrap(), line.direction().unwrap());
            let line32 = Line::<f32>::from_point_direction(t(p), t(d)).unwrap();
            match Sphere::<f32>::from_centre_radius(t(c), r as f32) {
                Ok(s32) => {
                    let m32 = line32.meet_sphere(&s32);
                    worst32 = worst32.max((f64::from(m32.square) - (r * r - h * h) / (r * r)).abs());
                    after32 += usize::from(m32.hit != euclid);
                }
                Err(_) => {
                    worst32 = f64::INFINITY;
                    after32 += 1;
                }
            }
        }
        let w = worst / (EPS * (1.0 + rho).powi(2));
        println!(
            "| {rho:.0e} | {worst:.1e} | {w:.2} | {:.1e} | {before} / 1000 | {after} / 1000 | {worst32:.1e} | {after32} / 1000 |",
            band(rho)
        );
    }
    println!("\n### Interpolation C_½ and its normal against ρ (unit circles at distance d), f64 vs double-double\n");
    println!(
        "| d | before: three-point circles | C_½ centre/radius | normal (rad) | f32 C_½ | `Pair::condition` | `Pair::new` |"
    );
    println!("|---|---|---|---|---|---|---|");
    for d in [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1.5e5] {
        let (a, b) = far_pair(d);
        let unchecked = Pair::new_unchecked(
            Circle::from_centre_normal_radius(a.0, a.1, a.2).unwrap(),
            Circle::from_centre_normal_radius(b.0, b.1, b.2).unwrap(),
        )
        .unwrap();
        let reference = pair_dd(a, b);
        let (circle, normal) = interpolation_errors(&unchecked, &reference);
        let old = Pair::new_unchecked(circle_through_points(a), circle_through_points(b)).unwrap();
        let (before, _) = interpolation_errors(&old, &reference);
        let f32_err = {
            let t = |p: (E3, E3, f64)| {
                Circle::<f32>::from_centre_normal_radius(p.0.map(|x| x as f32), p.1.map(|x| x as f32), p.2 as f32)
            };
            let (bc, _, br) = reference.at(Dd::from_f64(0.5)).unwrap().centre_normal_radius().unwrap();
            let got = t(a).and_then(|x| Ok((x, t(b)?))).ok().and_then(|(x, y)| Pair::new_unchecked(x, y).ok());
            match got.map(|p| p.at(0.5f32).map(|c| c.centre_normal_radius())) {
                Some(Ok(Ok((c, _, r)))) => {
                    let c = c.map(f64::from);
                    (norm(sub(c, f3(bc))) / br.hi()).max((f64::from(r) - br.hi()).abs() / br.hi())
                }
                _ => f64::INFINITY,
            }
        };
        let checked = match pair_f64(a, b) {
            Ok(_) => "Ok".to_string(),
            Err(e) => format!("{e:?}").split(' ').next().unwrap_or("").to_string(),
        };
        println!(
            "| {d:.1e} | {before:.1e} | {circle:.1e} | {normal:.1e} | {f32_err:.1e} | {:.1e} | {checked} |",
            unchecked.condition()
        );
    }
    println!("\n### Normal of nearly identical circles against their difference Δ\n");
    println!(
        "| Δ | normal error (rad), unchecked | `normal_condition` | `Pair::normal` | f32: normal error (rad), unchecked |"
    );
    println!("|---|---|---|---|---|");
    for delta in [1e-3, 1e-6, 1e-8, 1e-10, 1e-12, 1e-15] {
        let a = ([1.0, 2.0, 3.0], [0.2, 0.3, 1.0], 1.5);
        let b = ([1.0 + delta, 2.0, 3.0 - delta], [0.2, 0.3 + delta, 1.0], 1.5 + delta);
        let p = pair_f64(a, b).unwrap();
        let (_, normal) = interpolation_errors(&p, &pair_dd(a, b));
        let (c, n, r) = p.at(0.5).unwrap().centre_normal_radius().unwrap();
        let checked = match p.normal(0.5, add(c, scale(perpendicular(n), r))) {
            Ok(_) => "Ok".to_string(),
            Err(e) => format!("{e:?}").split(' ').next().unwrap_or("").to_string(),
        };
        // f32: the same circles, the normal at the same point, against double-double.
        let reference = pair_dd(a, b);
        let (dc, dn, dr) = reference.at(Dd::from_f64(0.5)).unwrap().centre_normal_radius().unwrap();
        let x = add(f3(dc), scale(perpendicular(f3(dn)), dr.hi()));
        let want = f3(reference.normal(Dd::from_f64(0.5), dd3(x)).unwrap());
        let t = |v: E3| v.map(|y| y as f32);
        let c32 = |q: (E3, E3, f64)| Circle::<f32>::from_centre_normal_radius(t(q.0), t(q.1), q.2 as f32).ok();
        let normal32 = (c32(a).zip(c32(b)))
            .and_then(|(x1, x2)| Pair::new_unchecked(x1, x2).ok())
            .and_then(|p32| p32.normal_parts(0.5f32, t(x)).ok())
            .and_then(|parts| parts.normal_line.direction().ok())
            .map_or(f64::INFINITY, |n| norm(cross(n.map(f64::from), want)));
        println!("| {delta:.0e} | {normal:.1e} | {:.1e} | {checked} | {normal32:.1e} |", p.normal_condition());
    }
}

#[test]
fn circle_meets_are_classified_alike_anywhere_and_at_any_scale() {
    let mut rng = Rng::new(17);
    let (mut wrong, mut sharp, mut total) = (Vec::new(), 0, 0);
    for k in 0..10_000 {
        let (distance, r) = (rng.decades(0.0, 6.0), rng.decades(-4.0, 4.0));
        let (c, n) = (scale(rng.direction(), distance), rng.direction());
        let circle = Circle::from_centre_normal_radius(c, n, r).unwrap();
        let u = perpendicular(n);
        let rho = distance / r;
        if k % 10 == 0 {
            // In the circle's plane, at distance h from the centre: two points, or none.
            let h = r * rng.range(0.0, 2.0);
            let p = add(c, scale(u, h));
            let line = Line::from_point_direction(p, cross(n, u)).unwrap();
            let want = if h < r { Hit::Two } else { Hit::Miss };
            let got = line.meet_circle_classified(&circle).hit;
            if got != want && (h - r).abs() > band(rho) * r {
                wrong.push(format!("in plane: |c| {distance:e} r {r:e} h/r {}: {got:?}", h / r));
            }
            // Parallel to the plane, 0.1 r off it: no meet (where that is beyond rounding).
            let above = Line::from_point_direction(add(p, scale(n, 0.1 * r)), cross(n, u)).unwrap();
            if 64.0 * EPS * (1.0 + rho).powi(2) < 0.1 {
                assert_eq!(above.meet_circle_classified(&circle).hit, Hit::Miss, "|c| {distance:e}, r {r:e}");
            }
            continue;
        }
        // Crossing the plane at distance x from the centre, at angle θ to it.
        let x = if rng.unit() < 0.5 { r * (1.0 + rng.range(-1e-3, 1e-3)) } else { r * rng.range(0.0, 2.0) };
        let sine = rng.range(0.1, 1.0);
        let d = add(scale(n, sine), scale(cross(n, u), (1.0 - sine * sine).sqrt()));
        let at = add(c, scale(u, x));
        let line = Line::from_point_direction(add(at, scale(d, r * rng.range(-3.0, 3.0))), d).unwrap();
        let want = if x < r { Hit::Two } else { Hit::Miss };
        let got = line.meet_circle_classified(&circle).hit;
        let w = band(rho) / (sine * sine);
        total += 1;
        sharp += usize::from(w < 1e-3);
        if got != want && (x - r).abs() > w * r {
            wrong.push(format!("|c| {distance:e} r {r:e} x/r − 1 = {:e}, sin θ {sine}: {got:?}", x / r - 1.0));
        }
    }
    assert!(wrong.is_empty(), "{} misclassified outside the band: {:#?}", wrong.len(), &wrong[..wrong.len().min(10)]);
    assert!(sharp > total / 2, "the band was narrow in only {sharp} of {total} cases");
}

/// Norms, points, distinctness and the constructions through points hold at every scale f64
/// has, down to its smallest normal numbers and up to its largest: each rescales (by exact
/// powers of two) before it squares.
#[test]
fn norms_points_and_constructions_hold_at_every_scale() {
    use cga_core::euclid::norm;
    use cga_core::{Vector, down};
    let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    for s in [1e-307, 1e-300, 1e-200, 1e-154, 1.0, 1e154, 1e200, 1e300] {
        assert!(close(norm([3.0 * s, 4.0 * s, 0.0]), 5.0 * s), "norm at {s:e}");
        assert!(close(norm([s, -s, s]), 3f64.sqrt() * s), "norm at {s:e}");
    }
    assert_eq!(norm([5e-324, 0.0, 0.0]), 5e-324, "a subnormal");
    assert_eq!(norm([0.0; 3]), 0.0);
    // A point of any weight, at any distance f64 holds.
    for w in [1e-300, 1e-22, 1.0, 1e22, 1e300] {
        for x in [1e-300, 1e-12, 1.0, 1e22, 1e100] {
            let p = Vector { e1: w * x, e2: -w * x, e3: 0.0, eo: w, ei: 0.0 };
            if p.e1.is_finite() && p.e1.abs() >= f64::MIN_POSITIVE {
                let back = down(p).unwrap();
                assert!(close(back[0], x) && close(back[1], -x), "weight {w:e}, point {x:e}: {back:?}");
            }
        }
    }
    assert_eq!(down(Vector { e1: 1.0, e2: 0.0, e3: 0.0, eo: 0.0, ei: 0.0 }), Err(GeometryError::AtInfinity));
    // Points 1e-300 apart are distinct, and what passes through them has their size.
    for s in [1e-300, 1e-150, 1.0, 1e100] {
        let (o, x, y, z) = ([0.0; 3], [s, 0.0, 0.0], [0.0, s, 0.0], [0.0, 0.0, s]);
        assert!(Line::through(o, x).is_ok(), "{s:e}");
        let (c, n, r) = cga_core::circumcircle(x, y, o).unwrap();
        assert!(
            close(r, s / 2f64.sqrt()) && close(c[0], s / 2.0) && close(n[2], 1.0),
            "circle at {s:e}: {c:?} {n:?} {r:e}"
        );
        let (c, r, _) = cga_core::circumsphere(x, y, z, [-s, 0.0, 0.0]).unwrap();
        assert!(close(r, s) && c.iter().all(|v| v.abs() <= 4.0 * f64::EPSILON * s), "sphere at {s:e}: {c:?} {r:e}");
        assert!(Plane::through(o, x, y).is_ok(), "{s:e}");
        assert_eq!(Plane::through(o, x, x), Err(GeometryError::CoincidentPoints), "{s:e}");
        assert_eq!(Plane::through(o, x, [2.0 * s, 0.0, 0.0]), Err(GeometryError::CollinearPoints), "{s:e}");
        // A sphere of that size, read back.
        let (c, r) = Sphere::from_centre_radius(x, s).unwrap().centre_radius().unwrap();
        assert!(close(r, s) && close(c[0], s), "sphere read back at {s:e}: {c:?} {r:e}");
    }
}
