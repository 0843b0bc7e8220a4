//! Circle interpolation (eq. 3–5) and the evolved-surface normal (eq. 6–11) against
//! clifford (`interpolation.json`, `evolved_normals.json`) and against an independent
//! finite-difference normal of the swept surface.

mod common;

use cga::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub, unit};
use cga::{Bivector, Circle, InterpolationError, Line, Pair, Plane, ScalarQuadvector, Sphere, interpolate};
use common::*;

fn e3(v: &serde_json::Value) -> E3 {
    floats(v).try_into().expect("three floats")
}

fn circle(v: &serde_json::Value) -> Circle {
    Circle::from_dense(&mv(v))
}

/// The angle between two lines' directions (sign ignored), well conditioned near zero.
fn angle(a: E3, b: E3) -> f64 {
    norm(cross(a, b)).atan2(dot(a, b).abs())
}

#[test]
fn interpolated_circles_match_clifford() {
    let file = golden("interpolation.json");
    for (n, case) in cases(&file).iter().enumerate() {
        let (c1, c2, alpha) = (circle(&case["c1"]), circle(&case["c2"]), case["alpha"].as_f64().unwrap());
        let x = c1 * (1.0 - alpha) + c2 * alpha;
        assert_mv_close(&x.into(), &mv(&case["x_alpha"]), 1e-12, &format!("case {n}: X"));
        let c = interpolate(c1, c2, alpha).unwrap();
        // clifford's result carries ~1e-16 grade-1 residue; ours is a pure trivector.
        assert_mv_close(&c.into(), &mv(&case["c_alpha"]).grade(3), 1e-10, &format!("case {n}: C_alpha"));
        let (centre, normal, radius) = c.centre_normal_radius().unwrap();
        let euc = &case["c_alpha_euc"];
        assert!(norm(sub(centre, e3(&euc["centre"]))) < 1e-9 * norm(centre).max(1.0), "case {n}: centre");
        assert!(
            angle(normal, e3(&euc["normal"])) < 1e-9,
            "case {n}: normal {normal:?} vs {:?}, centre {centre:?}, radius {radius}",
            e3(&euc["normal"])
        );
        assert!((radius - euc["radius"].as_f64().unwrap()).abs() < 1e-9 * radius.max(1.0), "case {n}: radius");
    }
}

#[test]
fn evolved_surface_normals_match_clifford() {
    let file = golden("evolved_normals.json");
    for (n, case) in cases(&file).iter().enumerate() {
        // The golden circles are oriented alike but not normalised: use them as they are.
        let pair = Pair { c1: circle(&case["c1"]), c2: circle(&case["c2"]) };
        let (alpha, x) = (case["alpha"].as_f64().unwrap(), e3(&case["x"]));
        let p = pair.normal_parts(alpha, x).unwrap();
        let at = |what: &str| format!("case {n}: {what}");
        assert_mv_close(&p.circle.into(), &mv(&case["c_alpha"]).grade(3), 1e-10, &at("C_alpha"));
        assert_mv_close(&p.point.into(), &mv(&case["X"]), 1e-12, &at("X"));
        assert_mv_close(&p.l_c.into(), &mv(&case["l_c"]).grade(3), 1e-10, &at("L_C"));
        // clifford's Ċ is a central difference (h = 1e-6) of `interp_objects_root`, whose
        // parameter runs the other way (α C1 + (1 − α) C2, the paper's): its Ċ, and with it
        // Ω, Ẋ, L_T and N, are the negatives of ours, to the difference's truncation error.
        let flipped = |key: &str, grade: usize| -mv(&case[key]).grade(grade);
        assert_mv_close(&p.circle_dot.into(), &flipped("c_dot", 3), 1e-6, &at("C_dot"));
        assert_mv_close(&p.omega.into(), &flipped("omega", 2), 1e-6, &at("Omega"));
        assert_mv_close(&p.x_dot.into(), &flipped("x_dot", 1), 1e-6, &at("X_dot"));
        assert_mv_close(&p.l_t.into(), &flipped("l_t", 3), 1e-6, &at("L_T"));
        assert_mv_close(&p.normal_line.into(), &flipped("normal_line", 3), 1e-6, &at("N"));
        let normal = pair.normal(alpha, x).unwrap();
        assert!(angle(normal, e3(&case["euclidean_normal"])) < 1e-6, "case {n}: Euclidean normal");
    }
}

/// A random circle: centre in [−5, 5]³, any normal, radius in [0.5, 3].
fn random_circle(rng: &mut Rng) -> Circle {
    Circle::from_centre_normal_radius(rng.e3(-5.0, 5.0), rng.e3(-1.0, 1.0), rng.range(0.5, 3.0)).unwrap()
}

/// The point at angle θ on a circle.
fn on_circle(c: &Circle, theta: f64) -> E3 {
    let (centre, normal, r) = c.centre_normal_radius().unwrap();
    let u = perpendicular(normal);
    let v = cross(normal, u);
    add(centre, add(scale(u, r * theta.cos()), scale(v, r * theta.sin())))
}

/// The point of circle `c` nearest to `x`.
fn nearest_on(c: &Circle, x: E3) -> E3 {
    let (centre, normal, r) = c.centre_normal_radius().unwrap();
    let d = sub(x, centre);
    let in_plane = sub(d, scale(normal, dot(d, normal)));
    add(centre, scale(unit(in_plane).unwrap(), r))
}

/// The surface normal by finite differences, with no CGA beyond reading circles back:
/// the circle's tangent at x crossed with the motion of the nearest point on the
/// neighbouring circles.
fn finite_difference_normal(pair: &Pair<Circle>, alpha: f64, x: E3) -> Option<E3> {
    let h = 1e-6;
    let (c, before, after) = (pair.at(alpha).ok()?, pair.at(alpha - h).ok()?, pair.at(alpha + h).ok()?);
    let (centre, normal, _) = c.centre_normal_radius().ok()?;
    let along_circle = cross(normal, sub(x, centre));
    let across = scale(sub(nearest_on(&after, x), nearest_on(&before, x)), 0.5 / h);
    unit(cross(along_circle, across))
}

#[test]
fn analytic_normal_agrees_with_finite_differences_on_random_pairs() {
    let mut rng = Rng::new(0x5eed);
    let (mut compared, mut worst, mut no_root, mut perpendicular_lines, mut cc_residue) = (0, 0.0f64, 0, 0, 0.0f64);
    while compared < 1000 {
        let pair = Pair::new(random_circle(&mut rng), random_circle(&mut rng)).unwrap();
        let alpha = rng.range(0.05, 0.95);
        let c = match pair.at(alpha) {
            Ok(c) => c,
            Err(InterpolationError::NoRealRoot { .. }) => {
                no_root += 1;
                continue;
            }
            Err(e) => panic!("{e}"),
        };
        let x = on_circle(&c, rng.range(0.0, std::f64::consts::TAU));
        let p = pair.normal_parts(alpha, x).unwrap();
        let Some(fd) = finite_difference_normal(&pair, alpha, x) else { continue };
        let analytic = p.normal_line.direction().unwrap();
        worst = worst.max(angle(analytic, fd));
        compared += 1;

        // The paper's claim: C Ċ is a pure bivector.
        let cc = p.circle * p.circle_dot;
        let omega = p.omega.norm_squared().abs().sqrt().max(1e-300);
        cc_residue =
            cc_residue.max(cc.s.abs().max(cc.grade4().to_array().iter().fold(0.0, |m, x| m.max(x.abs()))) / omega);
        // How often L_T ⟂ L_C: ⟨L_T L_C⟩₀ against the lines' sizes.
        let dotp = (p.l_t * p.l_c).s.abs();
        let sizes = (p.l_t.norm() * p.l_c.norm()).max(1e-300);
        if dotp <= 1e-9 * sizes {
            perpendicular_lines += 1;
        }
    }
    println!(
        "{compared} points: worst angle to the finite-difference normal {worst:.2e} rad; \
         {no_root} pairs skipped at an α with no real root; C Ċ non-bivector residue {cc_residue:.1e}; \
         L_T ⟂ L_C at {perpendicular_lines} of {compared} points"
    );
    assert!(worst < 1e-5, "worst angle {worst:e}");
    assert!(cc_residue < 1e-10, "C Ċ has a scalar or 4-vector part of {cc_residue:e}");
}

#[test]
fn the_dual_derivative_is_exact() {
    // Against a Richardson-extrapolated central difference (h = 1e-4), accurate to ~1e-11.
    let mut rng = Rng::new(42);
    for _ in 0..200 {
        let pair = Pair::new(random_circle(&mut rng), random_circle(&mut rng)).unwrap();
        let alpha = rng.range(0.1, 0.9);
        let Ok((_, dc)) = pair.with_derivative(alpha) else { continue };
        let d = |h: f64| (pair.at(alpha + h).unwrap() - pair.at(alpha - h).unwrap()).scale(0.5 / h);
        let richardson = d(1e-4).scale(-1.0 / 3.0) + d(5e-5).scale(4.0 / 3.0);
        let (a, b) = (dc.to_array(), richardson.to_array());
        assert!(max_rel_diff(&a, &b) < 1e-9, "exact {a:?} vs extrapolated {b:?}");
    }
}

#[test]
fn opposite_orientations_are_aligned_not_failed() {
    let c1 = Circle::from_centre_normal_radius([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 2.0).unwrap();
    let pair = Pair::new(c1, -c1).unwrap();
    for alpha in [0.0, 0.25, 0.5, 1.0] {
        let c = pair.at(alpha).unwrap();
        assert!(max_rel_diff(&c.to_array(), &c1.to_array()) < 1e-12);
    }
    // Without alignment the sum passes through zero at α = ½: a named error, not NaN.
    assert_eq!(interpolate(c1, -c1, 0.5), Err(InterpolationError::Singular { alpha: 0.5 }));
}

#[test]
fn endpoints_are_reproduced_for_every_kind() {
    let mut rng = Rng::new(7);
    let (a, b) = (rng.e3(-3.0, 3.0), rng.e3(-3.0, 3.0));
    let (c, d) = (rng.e3(-3.0, 3.0), rng.e3(-3.0, 3.0));
    fn check<X: cga::Interpolable<f64> + Copy>(x1: X, x2: X, arr: fn(X) -> Vec<f64>) {
        let pair = Pair::new(x1, x2).unwrap();
        let close = |p: X, q: X| max_rel_diff(&arr(p), &arr(q)) < 1e-10;
        assert!(close(pair.at(0.0).unwrap(), pair.c1) && close(pair.at(1.0).unwrap(), pair.c2));
        let mid = pair.at(0.5).unwrap();
        assert!(arr(mid).iter().all(|v| v.is_finite()));
    }
    check(Bivector::from_points(a, b).unwrap(), Bivector::from_points(c, d).unwrap(), |x| x.to_array().to_vec());
    check(Line::through(a, b).unwrap(), Line::through(c, d).unwrap(), |x| x.to_array().to_vec());
    check(Plane::through(a, b, c).unwrap(), Plane::through(b, c, d).unwrap(), |x| x.to_array().to_vec());
    check(Sphere::from_centre_radius(a, 1.0).unwrap(), Sphere::from_centre_radius(b, 2.0).unwrap(), |x| {
        x.to_array().to_vec()
    });
    // Concentric spheres interpolate to concentric spheres.
    let pair =
        Pair::new(Sphere::from_centre_radius(a, 1.0).unwrap(), Sphere::from_centre_radius(a, 3.0).unwrap()).unwrap();
    let (centre, r) = pair.at(0.5).unwrap().centre_radius().unwrap();
    assert!(norm(sub(centre, a)) < 1e-12 && r > 1.0 && r < 3.0);
}

#[test]
fn square_roots_square_back() {
    let mut rng = Rng::new(99);
    let mut real = 0;
    for _ in 0..500 {
        let s: ScalarQuadvector = ScalarQuadvector::from_array(std::array::from_fn(|_| rng.range(-2.0, 2.0)));
        for k in s.sqrt_roots().into_iter().flatten() {
            let back = ScalarQuadvector::from_storage(&(k * k).to_storage());
            assert!(max_rel_diff(&back.to_array(), &s.to_array()) < 1e-12, "{k:?}² ≠ {s:?}");
            real += 1;
        }
        if s.sqrt_roots()[0].is_none() {
            let q = s.grade4();
            assert!(s.s * s.s - (q * q).s < 0.0 || s.s <= 0.0, "a real root was missed for {s:?}");
        }
    }
    assert!(real > 100);
}
