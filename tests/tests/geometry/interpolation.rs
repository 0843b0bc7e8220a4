//! Circle interpolation (eq. 3–5) and the evolved-surface normal (eq. 6–11) against
//! clifford (`interpolation.json`, `evolved_normals.json`) and against an independent
//! finite-difference normal of the swept surface.

use cga_tests::common;

use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{Bivector, Circle, InterpolationError, Line, Pair, Plane, ScalarQuadvector, Sphere, interpolate};
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

/// `max |a − b| / max |b|`: an error relative to the blade's size, which is what rounding of
/// its largest coefficients leaves (coefficients of a round grow like `|c|²/r`).
fn relative(a: &cga_core::Multivector, b: &cga_core::Multivector) -> f64 {
    let size = b.coeffs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.coeffs.iter().zip(&b.coeffs).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / size
}

/// How much of an input's blade residue η reaches C_α's centre, radius and normal (measured
/// at most 1.35 on the far set; near the origin η is below rounding anyway).
const ETA_GAIN: f64 = 4.0;

/// `max |⟨C C̃⟩₄| / |⟨C C̃⟩₀|`: how far a circle typed from coefficients is from a blade.
fn residue(c: &Circle) -> f64 {
    let square = *c * c.reverse();
    let quad = square.grade4().to_array().iter().fold(0.0f64, |m, x| m.max(x.abs()));
    quad / square.s.abs()
}

/// One check for every file of interpolated circle pairs, whatever its scale: the tolerance is
/// what f64 allows for the case's own `ρ` ([`Pair::condition`] of its circles, `ε (1 + ρ)³`),
/// ours plus the reference's (clifford computes in float64 too; the far set is 50-digit
/// mpmath) for the geometry of C_α (centre, radius, normal).
fn check_interpolation_file(file: &serde_json::Value, name: &str) -> (usize, f64) {
    let reference_in_f64 = file["reference_digits"].as_u64().is_none_or(|d| d <= 17);
    let mut worst = 0.0f64;
    for (n, case) in cases(file).iter().enumerate() {
        let (c1, c2, alpha) = (circle(&case["c1"]), circle(&case["c2"]), case["alpha"].as_f64().unwrap());
        let kappa = Pair::new_unchecked(c1, c2).unwrap().condition() + 64.0 * f64::EPSILON;
        // Typed from rounded coefficients, c1 and c2 are blades only to η, the 4-vector part
        // of C C̃ (a blade has none): no computation can place C_α better than that.
        let eta = [c1, c2].iter().map(residue).fold(0.0, f64::max);
        let tol = if reference_in_f64 { 2.0 * kappa } else { kappa } + ETA_GAIN * eta;
        let at = |what: &str| format!("{name} case {n}: {what}");
        let x = c1 * (1.0 - alpha) + c2 * alpha;
        let e = relative(&x.into(), &mv(&case["x_alpha"]));
        assert!(e <= 8.0 * f64::EPSILON, "{}: {e:e}", at("X"));
        let c = interpolate(c1, c2, alpha).unwrap();
        // clifford's result carries ~1e-16 grade-1 residue; ours is a pure trivector. A blade
        // typed from rounded coefficients is not exactly a blade (`C C̃` has a 4-vector part
        // of order ε ρ⁴ against 1), and the projector carries that residue into C_α's
        // coefficients in directions that move no centre or radius: ε (1 + ρ)⁴ for them.
        let rho = (kappa / f64::EPSILON).cbrt();
        let e = relative(&c.into(), &mv(&case["c_alpha"]).grade(3));
        let blade_tol = tol.max(2.0 * f64::EPSILON * rho.powi(4));
        assert!(e <= blade_tol, "{}: {e:e} > {blade_tol:e}", at("C_alpha"));
        let (centre, normal, radius) = c.centre_normal_radius().unwrap();
        let euc = &case["c_alpha_euc"];
        let want_radius = euc["radius"].as_f64().unwrap();
        let errors = [
            norm(sub(centre, e3(&euc["centre"]))) / want_radius,
            (radius - want_radius).abs() / want_radius,
            angle(normal, e3(&euc["normal"])),
        ];
        for (what, e) in ["centre", "radius", "normal"].iter().zip(errors) {
            assert!(e <= tol, "{}: {e:e} > {tol:e}", at(what));
            worst = worst.max(e / tol);
        }
    }
    (cases(file).len(), worst)
}

#[test]
fn interpolated_circles_match_clifford() {
    let (n, worst) = check_interpolation_file(&golden("interpolation.json"), "interpolation.json");
    println!("interpolation.json: {n} cases, worst error {worst:.2} of the tolerance");
}

/// The same test on circles with centres up to 1e3 and radii 1e-2 … 1e2 (50-digit mpmath,
/// `tools/far_reference.py`): tolerances that mean something pass at any scale.
#[test]
fn interpolated_circles_far_from_the_origin_match_high_precision() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/far_interpolation.json")).unwrap();
    let file: serde_json::Value = serde_json::from_str(&text).unwrap();
    let (n, worst) = check_interpolation_file(&file, "far_interpolation.json");
    println!("far_interpolation.json: {n} cases, worst error {worst:.2} of the tolerance");
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
    // Against a Richardson-extrapolated central difference (h = 1e-4), accurate to ~1e-10 of
    // the blade's size.
    let mut rng = Rng::new(42);
    for _ in 0..200 {
        let pair = Pair::new(random_circle(&mut rng), random_circle(&mut rng)).unwrap();
        let alpha = rng.range(0.1, 0.9);
        let Ok((_, dc)) = pair.with_derivative(alpha) else { continue };
        let d = |h: f64| (pair.at(alpha + h).unwrap() - pair.at(alpha - h).unwrap()).scale(0.5 / h);
        let richardson = d(1e-4).scale(-1.0 / 3.0) + d(5e-5).scale(4.0 / 3.0);
        // Relative to the blade's size: the difference's rounding is ε|C|/h on every coefficient.
        let e = relative(&dc.into(), &richardson.into());
        assert!(e < 1e-9, "exact {:?} vs extrapolated {:?}: {e:e}", dc.to_array(), richardson.to_array());
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
    fn check<X: cga_core::Interpolable<f64> + Copy>(x1: X, x2: X, arr: fn(X) -> Vec<f64>) {
        let pair = Pair::new(x1, x2).unwrap();
        let close = |p: X, q: X| max_rel_diff(&arr(p), &arr(q)) < 1e-10;
        assert!(close(pair.at(0.0).unwrap(), pair.c1) && close(pair.at(1.0).unwrap(), pair.c2));
        let mid = pair.at(0.5).unwrap();
        assert!(arr(mid).iter().all(|v| v.is_finite()));
    }
    check(Bivector::from_points(a, b).unwrap(), Bivector::from_points(c, d).unwrap(), |x| x.to_array().to_vec());
    check(Line::through(a, b).unwrap(), Line::through(c, d).unwrap(), |x| x.to_array().to_vec());
    check(Plane::through(a, b, c).unwrap(), Plane::through(b, c, d).unwrap(), |x| x.to_array().to_vec());
    // Spheres that overlap enough to interpolate (disjoint ones pass through a plane: refused).
    let reach = 2.0 + glam::DVec3::from(a).distance(glam::DVec3::from(b));
    check(Sphere::from_centre_radius(a, 1.0).unwrap(), Sphere::from_centre_radius(b, reach).unwrap(), |x| {
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
