//! The dense multivector against clifford's products (`tests/golden/products.json`), and
//! the basis change and the sparse types against the other golden files' raw multivectors.

use cga_tests::common;

use cga_core::{GeometricProduct, InnerProduct, LeftContraction, Multivector, OuterProduct, RegressiveProduct};
use common::*;

const TOL: f64 = 1e-12;

#[test]
fn dense_products_match_clifford() {
    let file = golden("products.json");
    let cases = cases(&file);
    assert!(cases.len() >= 50);
    for (n, case) in cases.iter().enumerate() {
        let (a, b) = (mv(&case["a"]), mv(&case["b"]));
        let checks: [(&str, Multivector); 8] = [
            ("gp", a.gp(b)),
            ("op", a.wedge(b)),
            ("hestenes_inner", a.inner(b)),
            ("left_contraction", a.lc(b)),
            ("vee", a.vee(b)),
            ("reverse_a", a.reverse()),
            ("dual_a", a.dual()),
            ("grade_involution_a", a.involute()),
        ];
        for (key, got) in checks {
            assert_mv_close(&got, &mv(&case[key]), TOL, &format!("case {n}: {key}"));
        }
    }
}

#[test]
fn operators_are_the_documented_products() {
    let file = golden("products.json");
    let case = &cases(&file)[0];
    let (a, b) = (mv(&case["a"]), mv(&case["b"]));
    assert_eq!(a * b, a.gp(b));
    assert_eq!(a ^ b, a.wedge(b));
    assert_eq!(a | b, a.inner(b));
    assert_eq!(a & b, a.vee(b));
}

#[test]
fn undual_inverts_dual_and_pseudoscalar_squares_to_minus_one() {
    let file = golden("products.json");
    let case = &cases(&file)[3];
    let a = mv(&case["a"]);
    assert_mv_close(&a.dual().undual(), &a, TOL, "undual(dual(a))");
    let mut i5 = Multivector::zero();
    i5.coeffs[31] = 1.0;
    let mut minus_one = Multivector::zero();
    minus_one.coeffs[0] = -1.0;
    assert_mv_close(&(i5 * i5), &minus_one, 0.0, "I5²");
}

/// The sparse types store the null basis; the golden files hold orthonormal coefficients.
/// Every golden object, carried into its sparse type and back, must be unchanged — this
/// checks the change of basis and that each type holds the blades its objects need.
#[test]
fn golden_objects_fit_their_sparse_types_exactly() {
    let objects = golden("objects.json");
    for (n, case) in cases(&objects).iter().enumerate() {
        let line = mv(&case["line"]);
        let back: Multivector = cga_core::Line::from_dense(&line).into();
        assert_mv_close(&back, &line, TOL, &format!("objects {n}: line"));
        let circle = mv(&case["circle"]);
        assert_mv_close(&cga_core::Circle::from_dense(&circle).into(), &circle, TOL, &format!("objects {n}: circle"));
        let sphere = mv(&case["sphere"]);
        assert_mv_close(&cga_core::Sphere::from_dense(&sphere).into(), &sphere, TOL, &format!("objects {n}: sphere"));
        let plane = mv(&case["plane"]);
        assert_mv_close(&cga_core::Plane::from_dense(&plane).into(), &plane, TOL, &format!("objects {n}: plane"));
    }
    let rotors = golden("rotors.json");
    for (n, case) in cases(&rotors).iter().enumerate() {
        for (key, check) in [
            ("rotor", (|m: &Multivector| cga_core::Rotor::from_dense(m).into()) as fn(&Multivector) -> Multivector),
            ("translator", |m| cga_core::Translator::from_dense(m).into()),
            ("motor", |m| cga_core::Motor::from_dense(m).into()),
        ] {
            let m = mv(&case[key]);
            assert_mv_close(&check(&m), &m, TOL, &format!("rotors {n}: {key}"));
        }
    }
}

/// The generated sparse products reproduce clifford's results on clifford's own objects:
/// the line–sphere meet, the circle and sphere through points, and the motor on a point.
#[test]
fn sparse_products_reproduce_golden_meets_and_sandwiches() {
    use cga_core::Sandwich;
    for (n, case) in cases(&golden("line_sphere.json")).iter().enumerate() {
        let line = cga_core::Line::from_dense(&mv(&case["line"]));
        let sphere = cga_core::Sphere::from_dense(&mv(&case["sphere"]));
        let meet: Multivector = (line & sphere).into();
        assert_mv_close(&meet, &mv(&case["meet"]), TOL, &format!("line_sphere {n}: meet"));
        let square = (line & sphere) * (line & sphere);
        let want = case["meet_squared"].as_f64().unwrap();
        assert!((square.s - want).abs() <= TOL * want.abs().max(1.0), "line_sphere {n}: square {} vs {want}", square.s);
    }
    for (n, case) in cases(&golden("rotors.json")).iter().enumerate() {
        let motor = cga_core::Motor::from_dense(&mv(&case["motor"]));
        let x = floats(&case["x"]);
        let x2 = x.iter().map(|v| v * v).sum::<f64>();
        let point = cga_core::Vector { e1: x[0], e2: x[1], e3: x[2], eo: 1.0, ei: 0.5 * x2 };
        let moved: Multivector = motor.sandwich(point).into();
        // clifford's result carries rounding-level grade-3 residue; compare the vector part.
        assert_mv_close(&moved, &mv(&case["moved"]).grade(1), 1e-11, &format!("rotors {n}: moved point"));
    }
}
