//! Conformal embedding and objects against clifford (`conformal.json`, `objects.json`,
//! `line_sphere.json`, 1e-10) and against plain Euclidean formulas computed with glam.

mod common;

use cga_core::euclid::E3;
use cga_core::{Bivector, Circle, GeometryError, Line, Multivector, Plane, Sphere, down, up};
use common::*;
use glam::DVec3;

const TOL: f64 = 1e-10;

fn e3(v: &serde_json::Value) -> E3 {
    floats(v).try_into().expect("three floats")
}

fn close3(a: E3, b: E3, tol: f64) -> bool {
    (DVec3::from(a) - DVec3::from(b)).length() <= tol * DVec3::from(b).length().max(1.0)
}

#[test]
fn up_and_down_match_clifford() {
    let file = golden("conformal.json");
    for (n, case) in cases(&file).iter().enumerate() {
        let x = e3(&case["x"]);
        assert_mv_close(&up(x).into(), &mv(&case["up"]), TOL, &format!("case {n}: up"));
        assert!(close3(down(up(x)).unwrap(), e3(&case["down"]), 1e-14), "case {n}: down");
    }
}

#[test]
fn objects_through_points_match_clifford() {
    let file = golden("objects.json");
    for (n, case) in cases(&file).iter().enumerate() {
        let p: Vec<E3> = case["points"].as_array().unwrap().iter().map(e3).collect();
        let line = Line::through(p[0], p[1]).unwrap();
        assert_mv_close(&line.into(), &mv(&case["line"]), TOL, &format!("case {n}: line"));
        let circle = Circle::through(p[0], p[1], p[2]).unwrap();
        assert_mv_close(&circle.into(), &mv(&case["circle"]), TOL, &format!("case {n}: circle"));
        let sphere = Sphere::through(p[0], p[1], p[2], p[3]).unwrap();
        assert_mv_close(&sphere.into(), &mv(&case["sphere"]), TOL, &format!("case {n}: sphere"));
        assert_mv_close(&sphere.dual().into(), &mv(&case["sphere_dual"]), TOL, &format!("case {n}: sphere dual"));
        let plane = Plane::through(p[0], p[1], p[2]).unwrap();
        assert_mv_close(&plane.into(), &mv(&case["plane"]), TOL, &format!("case {n}: plane"));

        let (centre, normal, radius) = circle.centre_normal_radius().unwrap();
        let euc = &case["circle_euc"];
        assert!(close3(centre, e3(&euc["centre"]), TOL), "case {n}: circle centre");
        let want_normal = DVec3::from(e3(&euc["normal"]));
        assert!(DVec3::from(normal).cross(want_normal).length() < TOL, "case {n}: circle normal");
        assert!((radius - euc["radius"].as_f64().unwrap()).abs() < TOL, "case {n}: circle radius");
        let (c, r) = sphere.centre_radius().unwrap();
        assert!((r - case["sphere_radius"].as_f64().unwrap()).abs() < TOL * r, "case {n}: sphere radius");
        // The golden `sphere_centre` is the e1..e3 part of an unnormalised centre point (not
        // divided by its eo weight): it is parallel to the centre, which lies at the golden
        // radius from all four points.
        let golden_centre = DVec3::from(e3(&case["sphere_centre"]));
        assert!(DVec3::from(c).normalize().cross(golden_centre.normalize()).length() < TOL, "case {n}: sphere centre");
        for q in &p {
            assert!((DVec3::from(*q).distance(DVec3::from(c)) - r).abs() < TOL * r, "case {n}: point off sphere");
        }
    }
}

#[test]
fn line_sphere_meets_match_clifford() {
    let file = golden("line_sphere.json");
    let mut hits = 0;
    for (n, case) in cases(&file).iter().enumerate() {
        let ends: Vec<E3> = case["line_points"].as_array().unwrap().iter().map(e3).collect();
        let line = Line::through(ends[0], ends[1]).unwrap();
        assert_mv_close(&line.into(), &mv(&case["line"]), TOL, &format!("case {n}: line"));
        let sphere = Sphere::from_centre_radius(e3(&case["centre"]), case["radius"].as_f64().unwrap()).unwrap();
        // clifford's sphere here may differ in scale and sign: compare the meets' geometry.
        let golden_sphere = Sphere::from_dense(&mv(&case["sphere"]));
        let (c, r) = golden_sphere.centre_radius().unwrap();
        assert!(close3(c, e3(&case["centre"]), TOL) && (r - case["radius"].as_f64().unwrap()).abs() < TOL);
        let pair: Bivector = line & golden_sphere;
        assert_mv_close(&pair.into(), &mv(&case["meet"]), TOL, &format!("case {n}: meet"));
        let hit = case["hits"].as_bool().unwrap();
        assert_eq!((pair * pair).s > 0.0, hit, "case {n}: hit classification");
        let ours = line & sphere;
        assert_eq!((ours * ours).s > 0.0, hit, "case {n}: hit classification, our sphere");
        if hit {
            hits += 1;
            for x in pair.end_points().unwrap() {
                let d = DVec3::from(x) - DVec3::from(e3(&case["centre"]));
                approx::assert_relative_eq!(d.length(), r, epsilon = 1e-9, max_relative = 1e-9); // on the sphere
            }
        }
    }
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
