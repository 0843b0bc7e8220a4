//! Conformal embedding and objects against clifford (`conformal.json`, `objects.json`,
//! `line_sphere.json`) and against the exact far set (`../data/far_objects.json`, made by
//! `tools/far_objects.py` in 50-digit mpmath: coordinates up to 1e3, sizes 1e-2 … 1e2), by the
//! same comparison functions; and against plain Euclidean formulas computed with glam.
//!
//! Every golden tolerance is `ε M (k (1 + ρ)^p)` with `M` the quantity's own magnitude (a
//! multivector's largest coefficient, a point's `|c| + r`, a radius) and `ρ` the case's
//! `|position| / size` (the largest point's distance from the origin over the smallest point
//! separation, or the sphere's radius): ours always, plus clifford's own error at that scale for
//! the near (clifford) files — the reference's error plus ours. The constants are in [`MODELS`]
//! (ours measured on the far set, clifford's on the near files against the same 50-digit
//! reference, `python3 tools/far_objects.py --check`), each about 10× the worst measured ratio.

use cga_tests::common;

use cga_core::euclid::E3;
use cga_core::{Bivector, Circle, GeometryError, Line, Multivector, Plane, Sphere, down, up};
use common::*;
use glam::DVec3;

fn e3(v: &serde_json::Value) -> E3 {
    floats(v).try_into().expect("three floats")
}

fn close3(a: E3, b: E3, tol: f64) -> bool {
    (DVec3::from(a) - DVec3::from(b)).length() <= tol * DVec3::from(b).length().max(1.0)
}

/// `|a − b|`.
fn dist(a: E3, b: E3) -> f64 {
    DVec3::from(a).distance(DVec3::from(b))
}

/// `|a|`.
fn len(a: E3) -> f64 {
    DVec3::from(a).length()
}

/// A tolerance: ours `k ε M (1 + ρ)^p`, clifford's likewise.
const fn model(k: f64, p: i32, k_clifford: f64, p_clifford: i32) -> Model {
    Model { ours: (k, p), clifford: (k_clifford, p_clifford) }
}

/// The tolerance of each quantity (see the module's doc): `model(k, p, k_clifford, p_clifford)` is
/// `ε M (k (1 + ρ)^p)` for us plus `ε M (k_clifford (1 + ρ)^p_clifford)` against clifford. Lines and
/// planes lose `ε ρ` (the direction from two nearby far points); rounds `ε ρ²` (their `ei`
/// coefficient, docs/STABILITY.md); the read-backs of a file's sphere and the end points of a
/// meet carry their own condition `κ` in `M` instead.
mod models {
    use super::{Model, model};
    pub const UP: Model = model(12.0, 0, 4.0, 0);
    pub const DOWN: Model = model(2.0, 0, 2.0, 0);
    pub const LINE: Model = model(16.0, 1, 8.0, 2);
    pub const PLANE: Model = model(32.0, 1, 16.0, 2);
    pub const CIRCLE: Model = model(4.0, 2, 16.0, 2);
    pub const SPHERE: Model = model(4.0, 2, 48.0, 2);
    pub const CIRCLE_CENTRE: Model = model(2.0, 2, 12.0, 2);
    pub const CIRCLE_NORMAL: Model = model(6.0, 1, 24.0, 2);
    pub const CIRCLE_RADIUS: Model = model(16.0, 2, 16.0, 2);
    pub const SPHERE_RADIUS: Model = model(8.0, 2, 32.0, 2);
    pub const SPHERE_CENTRE: Model = model(4.0, 2, 64.0, 2);
    pub const ON_SPHERE: Model = model(8.0, 2, 8.0, 2);
    pub const MEET: Model = model(4.0, 2, 16.0, 2);
    pub const MEET_SQUARED: Model = model(1.0, 2, 8.0, 2);
    pub const READ_CENTRE: Model = model(10.0, 0, 90.0, 0);
    pub const READ_RADIUS: Model = model(8.0, 2, 8.0, 2);
    pub const END_POINTS: Model = model(16.0, 0, 360.0, 0);
}
use models::*;

/// `x`, `up(x)`, `down(up(x))`: our embedding against the case's.
fn check_up_down(case: &serde_json::Value, label: &str, r: &mut Ratios) {
    let x = e3(&case["x"]);
    r.check("up(x)", UP, 0.0, mv_ulps(&up(x).into(), &mv(&case["up"])), label);
    let back = down(up(x)).unwrap();
    r.check(
        "down(up(x))",
        DOWN,
        0.0,
        dist(back, e3(&case["down"])) / (f64::EPSILON * len(x).max(f64::MIN_POSITIVE)),
        label,
    );
}

/// `max |coefficient|`.
fn max_abs(m: &Multivector) -> f64 {
    m.coeffs.iter().fold(0.0f64, |a, x| a.max(x.abs()))
}

/// The case's |position| / size: its farthest point over its closest pair.
fn rho_of(points: &[E3]) -> f64 {
    let far = points.iter().map(|p| len(*p)).fold(0.0, f64::max);
    let mut near = f64::INFINITY;
    for (i, a) in points.iter().enumerate() {
        for b in &points[..i] {
            near = near.min(dist(*a, *b));
        }
    }
    far / near
}

/// Line, circle, sphere, plane through the case's four points, and their read-backs.
fn check_objects(case: &serde_json::Value, label: &str, r: &mut Ratios) {
    let eps = f64::EPSILON;
    let p: Vec<E3> = case["points"].as_array().unwrap().iter().map(e3).collect();
    let rho = rho_of(&p);
    let line = Line::through(p[0], p[1]).unwrap();
    r.check("line", LINE, rho, mv_ulps(&line.into(), &mv(&case["line"])), label);
    let circle = Circle::through(p[0], p[1], p[2]).unwrap();
    r.check("circle", CIRCLE, rho, mv_ulps(&circle.into(), &mv(&case["circle"])), label);
    let sphere = Sphere::through(p[0], p[1], p[2], p[3]).unwrap();
    r.check("sphere", SPHERE, rho, mv_ulps(&sphere.into(), &mv(&case["sphere"])), label);
    r.check("sphere dual", SPHERE, rho, mv_ulps(&sphere.dual().into(), &mv(&case["sphere_dual"])), label);
    let plane = Plane::through(p[0], p[1], p[2]).unwrap();
    r.check("plane", PLANE, rho, mv_ulps(&plane.into(), &mv(&case["plane"])), label);

    let (centre, normal, radius) = circle.centre_normal_radius().unwrap();
    let euc = &case["circle_euc"];
    let (want_c, want_r) = (e3(&euc["centre"]), euc["radius"].as_f64().unwrap());
    r.check(
        "circle centre: M = |c| + r",
        CIRCLE_CENTRE,
        rho,
        dist(centre, want_c) / (eps * (len(want_c) + want_r)),
        label,
    );
    let want_normal = DVec3::from(e3(&euc["normal"])).normalize();
    let sine = DVec3::from(normal).cross(want_normal).length();
    r.check("circle normal (up to sign): M = 1", CIRCLE_NORMAL, rho, sine / eps, label);
    r.check("circle radius: M = r", CIRCLE_RADIUS, rho, (radius - want_r).abs() / (eps * want_r), label);
    let (c, s_r) = sphere.centre_radius().unwrap();
    let want_r = case["sphere_radius"].as_f64().unwrap();
    r.check("sphere radius: M = r", SPHERE_RADIUS, rho, (s_r - want_r).abs() / (eps * want_r), label);
    // The golden `sphere_centre` is the e1..e3 part of an unnormalised centre point (not
    // divided by its eo weight): it is parallel to the centre, which lies at the golden
    // radius from all four points. The angle between them is the centre's error over |c|.
    let golden_centre = DVec3::from(e3(&case["sphere_centre"]));
    let sine = DVec3::from(c).normalize().cross(golden_centre.normalize()).length();
    r.check(
        "sphere centre direction: M = (|c| + r)/|c|",
        SPHERE_CENTRE,
        rho,
        sine * len(c) / (eps * (len(c) + want_r)),
        label,
    );
    for q in &p {
        r.check("points on the sphere: M = r", ON_SPHERE, rho, (dist(*q, c) - s_r).abs() / (eps * s_r), label);
    }
}

/// A line and a sphere: the line, the sphere read back, their meet, its square and
/// classification, and the end points. Returns whether the line hits.
fn check_line_sphere(case: &serde_json::Value, label: &str, r: &mut Ratios) -> bool {
    let eps = f64::EPSILON;
    let ends: Vec<E3> = case["line_points"].as_array().unwrap().iter().map(e3).collect();
    let (want_c, want_r) = (e3(&case["centre"]), case["radius"].as_f64().unwrap());
    let rho = ends.iter().map(|p| len(*p)).fold(len(want_c), f64::max) / want_r.min(dist(ends[0], ends[1]));
    let line = Line::through(ends[0], ends[1]).unwrap();
    r.check("line", LINE, rho, mv_ulps(&line.into(), &mv(&case["line"])), label);
    let sphere = Sphere::from_centre_radius(want_c, want_r).unwrap();
    // clifford's sphere here may differ in scale and sign: compare the meets' geometry.
    let golden_sphere = Sphere::from_dense(&mv(&case["sphere"]));
    let (c, s_r) = golden_sphere.centre_radius().unwrap();
    // The file's sphere is rounded in the e4, e5 layout, whose coefficients (~|c|²/2r) dwarf
    // the eo weight w (1/r) far out: reading it back loses ε κ, κ = max|coefficient| / w, of
    // the weight, so the centre moves by ε κ (1 + |c|) and r² by ε κ |c|² (the layout's own
    // limit, not the meet's; exactly what clifford's file pays at |c| ≈ 5 too).
    let kappa = max_abs(&mv(&case["sphere"])) / golden_sphere.dual().eo.abs();
    let err = dist(c, want_c) / (eps * kappa * (1.0 + len(want_c)));
    r.check("sphere read back: centre, M = κ (1 + |c|)", READ_CENTRE, rho, err, label);
    r.check(
        "sphere read back: radius, M = κ r",
        READ_RADIUS,
        rho,
        (s_r - want_r).abs() / (eps * kappa * want_r),
        label,
    );
    let pair: Bivector = line & golden_sphere;
    let want = mv(&case["meet"]);
    r.check("meet", MEET, rho, mv_ulps(&pair.into(), &want), label);
    let m = max_abs(&want);
    let square = (pair * pair).s;
    let want_square = case["meet_squared"].as_f64().unwrap();
    r.check("meet squared: M = max|meet|²", MEET_SQUARED, rho, (square - want_square).abs() / (eps * m * m), label);
    let hit = case["hits"].as_bool().unwrap();
    if (square > 0.0) != hit {
        r.fail(label, format!("hit classification: P² = {square:e}, reference {want_square:e}"));
    }
    let ours = line & sphere;
    if ((ours * ours).s > 0.0) != hit {
        r.fail(label, format!("hit classification, our sphere: P² = {:e}", (ours * ours).s));
    }
    if hit {
        let [x, y] = pair.end_points().unwrap();
        if let Some(want) = case.get("end_points") {
            let w: Vec<E3> = want.as_array().unwrap().iter().map(e3).collect();
            // In either order (ours are the pair's orientation, clifford's its own).
            let err = (dist(x, w[0]).max(dist(y, w[1]))).min(dist(x, w[1]).max(dist(y, w[0])));
            // √P² carries the rounding of terms of size max|P|² (κ = max|P|²/P²), and moves
            // the points along the chord by ε κ of its half-length (~ r).
            let kappa = m * m / square.abs();
            r.check("end points: M = κ r, κ = max|P|²/P²", END_POINTS, rho, err / (eps * kappa * want_r), label);
        }
    }
    hit
}

#[test]
fn up_and_down_match_clifford() {
    let mut r = Ratios::new("conformal.json", Reference::Clifford);
    for (n, case) in cases(&golden("conformal.json")).iter().enumerate() {
        check_up_down(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

#[test]
fn far_up_and_down_match_the_exact_reference() {
    let mut r = Ratios::new("far_objects.json conformal", Reference::Exact);
    for (n, case) in far_objects()["conformal"].as_array().unwrap().iter().enumerate() {
        check_up_down(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

#[test]
fn objects_match_clifford() {
    let mut r = Ratios::new("objects.json", Reference::Clifford);
    for (n, case) in cases(&golden("objects.json")).iter().enumerate() {
        check_objects(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

#[test]
fn far_objects_match_the_exact_reference() {
    let mut r = Ratios::new("far_objects.json objects", Reference::Exact);
    for (n, case) in far_objects()["objects"].as_array().unwrap().iter().enumerate() {
        check_objects(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

#[test]
fn line_sphere_meets_match_clifford() {
    let mut r = Ratios::new("line_sphere.json", Reference::Clifford);
    let mut hits = 0;
    for (n, case) in cases(&golden("line_sphere.json")).iter().enumerate() {
        hits += check_line_sphere(case, &format!("case {n}"), &mut r) as usize;
    }
    r.finish();
    assert!(hits > 5, "only {hits} hitting cases");
}

#[test]
fn far_line_sphere_meets_match_the_exact_reference() {
    let mut r = Ratios::new("far_objects.json line_sphere", Reference::Exact);
    let mut hits = 0;
    for (n, case) in far_objects()["line_sphere"].as_array().unwrap().iter().enumerate() {
        hits += check_line_sphere(case, &format!("case {n}"), &mut r) as usize;
    }
    r.finish();
    assert!(hits > 5, "only {hits} hitting cases");
}

/// A deterministic spread of test points in [−10, 10]³.
fn random_points(seed: u64, n: usize) -> Vec<E3> {
    let mut rng = Rng::new(seed.wrapping_mul(0x9e3779b97f4a7c15) | 1);
    (0..n).map(|_| rng.e3(-10.0, 10.0)).collect()
}

#[test]
fn objects_agree_with_euclidean_formulas() {
    for seed in 0..300 {
        let p: Vec<DVec3> = random_points(seed, 4).into_iter().map(DVec3::from).collect();
        let (a, b, c, d) = (p[0], p[1], p[2], p[3]);

        // Circumcircle of a, b, c.
        let (u, v) = (b - a, c - a);
        let w = u.cross(v);
        let centre =
            a + (v.length_squared() * w.cross(u) + u.length_squared() * v.cross(w)) / (2.0 * w.length_squared());
        let circle = Circle::through(a.into(), b.into(), c.into()).unwrap();
        let (cc, cn, cr) = circle.centre_normal_radius().unwrap();
        assert!(close3(cc, centre.into(), 1e-9), "seed {seed}: circle centre {cc:?} vs {centre}");
        assert!((DVec3::from(cn) - w.normalize()).length() < 1e-9, "seed {seed}: circle normal");
        approx::assert_relative_eq!(cr, (a - centre).length(), epsilon = 1e-9, max_relative = 1e-9);

        // Circumsphere of a, b, c, d: solve 2 (x_i − a) · c = |x_i|² − |a|².
        let m = glam::DMat3::from_cols(b - a, c - a, d - a).transpose();
        let rhs = DVec3::new(
            b.length_squared() - a.length_squared(),
            c.length_squared() - a.length_squared(),
            d.length_squared() - a.length_squared(),
        ) / 2.0;
        let sc = m.inverse() * rhs;
        let (s_c, s_r) = Sphere::through(a.into(), b.into(), c.into(), d.into()).unwrap().centre_radius().unwrap();
        assert!(close3(s_c, sc.into(), 1e-7), "seed {seed}: sphere centre {s_c:?} vs {sc}");
        approx::assert_relative_eq!(s_r, (a - sc).length(), epsilon = 1e-7, max_relative = 1e-7);

        // Line through a, b: direction and nearest point to the origin.
        let line = Line::through(a.into(), b.into()).unwrap();
        let dir = (b - a).normalize();
        assert!((DVec3::from(line.direction().unwrap()) - dir).length() < 1e-12);
        let nearest = a - dir * a.dot(dir);
        assert!(close3(line.point().unwrap(), nearest.into(), 1e-12), "seed {seed}: line point");

        // Plane through a, b, c: normal and offset.
        let (n, off) = Plane::through(a.into(), b.into(), c.into()).unwrap().normal_offset().unwrap();
        assert!((DVec3::from(n) - w.normalize()).length() < 1e-9, "seed {seed}: plane normal");
        approx::assert_relative_eq!(off, w.normalize().dot(a), epsilon = 1e-9, max_relative = 1e-9);

        // Point pair a ∧ b: its end points, in order.
        let [x, y] = Bivector::from_points(a.into(), b.into()).unwrap().end_points().unwrap();
        assert!(close3(x, a.into(), 1e-9) && close3(y, b.into(), 1e-9), "seed {seed}: end points");

        // Constructions from parameters give back their parameters.
        let (cc2, cn2, cr2) =
            Circle::from_centre_normal_radius(centre.into(), w.into(), 2.5).unwrap().centre_normal_radius().unwrap();
        assert!(close3(cc2, centre.into(), 1e-9) && (DVec3::from(cn2) - w.normalize()).length() < 1e-9);
        approx::assert_abs_diff_eq!(cr2, 2.5, epsilon = 1e-9);
        let (c3, r3) = Sphere::from_centre_radius(a.into(), 0.75).unwrap().centre_radius().unwrap();
        assert!(close3(c3, a.into(), 1e-12));
        approx::assert_abs_diff_eq!(r3, 0.75, epsilon = 1e-12);
        let (n4, off4) = Plane::from_point_normal(a.into(), w.into()).unwrap().normal_offset().unwrap();
        approx::assert_abs_diff_eq!(n4.as_slice(), w.normalize().to_array().as_slice(), epsilon = 1e-9);
        approx::assert_abs_diff_eq!(off4, w.normalize().dot(a), epsilon = 1e-9);
        let l5 = Line::from_point_direction(a.into(), (b - a).into()).unwrap();
        assert!((DVec3::from(l5.direction().unwrap()) - dir).length() < 1e-12);
    }
}

#[test]
fn degenerate_input_is_rejected_with_a_reason() {
    let (o, x, y) = ([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let two_x = [2.0, 0.0, 0.0];
    let z = [0.0, 0.0, 1.0];
    assert_eq!(Line::through(x, x), Err(GeometryError::CoincidentPoints));
    assert_eq!(Line::from_point_direction(x, o), Err(GeometryError::ZeroVector));
    assert_eq!(Plane::through(o, x, two_x), Err(GeometryError::CollinearPoints));
    assert_eq!(Plane::through(o, x, x), Err(GeometryError::CoincidentPoints));
    assert_eq!(Circle::through(o, x, two_x), Err(GeometryError::CollinearPoints));
    assert_eq!(Sphere::through(o, x, y, [1.0, 1.0, 0.0]), Err(GeometryError::CoplanarPoints));
    assert_eq!(Sphere::through(o, x, y, y), Err(GeometryError::CoincidentPoints));
    assert_eq!(Sphere::from_centre_radius(o, 0.0), Err(GeometryError::ZeroRadius));
    assert_eq!(Sphere::from_centre_radius(o, -1.0), Err(GeometryError::ZeroRadius));
    assert_eq!(Circle::from_centre_normal_radius(o, z, 0.0), Err(GeometryError::ZeroRadius));
    assert_eq!(Circle::from_centre_normal_radius(o, o, 1.0), Err(GeometryError::ZeroVector));
    assert_eq!(Line::through([f64::NAN, 0.0, 0.0], x), Err(GeometryError::NonFinite));
    assert_eq!(Sphere::from_centre_radius(o, f64::INFINITY), Err(GeometryError::NonFinite));
    // A line read as a circle has no centre; a point pair of a missed meet is imaginary.
    let line_as_circle: Circle = Line::through(o, x).unwrap().into();
    assert_eq!(line_as_circle.centre_normal_radius(), Err(GeometryError::AtInfinity));
    let far_line = Line::through([0.0, 5.0, 0.0], [1.0, 5.0, 0.0]).unwrap();
    let unit_sphere = Sphere::from_centre_radius(o, 1.0).unwrap();
    assert_eq!((far_line & unit_sphere).end_points(), Err(GeometryError::Imaginary));
    let _: Multivector = unit_sphere.into();
}

/// `Line::from_point_direction` writes the normalised line down directly; it is the same
/// blade as the wedge `up(p) ∧ up(p + d) ∧ ei`, normalised.
#[test]
fn line_from_point_direction_is_the_normalised_wedge() {
    let points = random_points(11, 400);
    for pair in points.chunks(2) {
        let (p, d) = (pair[0], pair[1]);
        let direct = Line::from_point_direction(p, d).unwrap();
        let q = [p[0] + d[0], p[1] + d[1], p[2] + d[2]];
        let wedge = ((up(p) ^ up(q)) ^ cga_core::ei()).try_normalise().unwrap();
        let scale = 1.0 + p.iter().map(|x| x.abs()).fold(0.0, f64::max);
        approx::assert_abs_diff_eq!(direct, wedge, epsilon = 1e-12 * scale);
    }
}

/// `Plane::from_point_normal` writes the plane down from its dual; it is the blade
/// `Plane::through` gives for three points spanning it counter-clockwise about the normal.
#[test]
fn plane_from_point_normal_is_the_plane_through_three_points() {
    let points = random_points(12, 400);
    for pair in points.chunks(2) {
        let (p, n) = (pair[0], pair[1]);
        let direct = Plane::from_point_normal(p, n).unwrap();
        let u = cga_core::euclid::perpendicular(cga_core::euclid::unit(n).unwrap());
        let v = cga_core::euclid::cross(cga_core::euclid::unit(n).unwrap(), u);
        let add = |a: E3, b: E3| [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
        let through = Plane::through(p, add(p, u), add(p, v)).unwrap();
        let scale = 1.0 + p.iter().map(|x| x.abs()).fold(0.0, f64::max);
        approx::assert_abs_diff_eq!(direct, through, epsilon = 1e-12 * scale);
    }
}

/// Points convert from and to `[f64; 3]` and glam vectors (feature `glam`), through `up` and
/// `down`; a point at infinity is a named error.
#[test]
fn points_convert_to_and_from_euclidean_vectors() {
    let x = [1.5, -2.0, 0.25];
    let p: cga_core::Vector = x.into();
    assert_eq!(p, up(x));
    assert_eq!(p.to_point(), Ok(x));
    let g: cga_core::Vector = DVec3::from(x).into();
    assert_eq!(DVec3::try_from(g), Ok(DVec3::from(x)));
    let single: cga_core::Vector<f32> = glam::Vec3::new(1.0, 2.0, 3.0).into();
    assert_eq!(glam::Vec3::try_from(single), Ok(glam::Vec3::new(1.0, 2.0, 3.0)));
    let infinity = cga_core::Vector::<f64> { ei: 1.0, ..cga_core::Vector::zero() };
    assert_eq!(DVec3::try_from(infinity), Err(GeometryError::AtInfinity));
}

/// The constructors a user guesses first (`new`) are the documented ones.
#[test]
fn new_is_the_constructor_from_euclidean_data() {
    let (c, n) = ([1.0, -2.0, 0.5], [0.3, 0.1, 1.0]);
    assert_eq!(Sphere::new(c, 2.0), Sphere::from_centre_radius(c, 2.0));
    assert_eq!(Circle::new(c, n, 2.0), Circle::from_centre_normal_radius(c, n, 2.0));
    assert_eq!(Plane::new(c, n), Plane::from_point_normal(c, n));
    assert_eq!(Line::new(c, n), Line::from_point_direction(c, n));
}
