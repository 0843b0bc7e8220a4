//! Rotors, translators, motors, exp/log and the rotor between lines, against clifford
//! (`rotors.json`) and the exact far set (`../data/far_objects.json`, translations and points
//! up to 1e3, by the same comparison), a dense Taylor series, and rigid transforms in glam.

use cga_tests::common;

use cga_core::euclid::E3;
use cga_core::{
    Bivector, Circle, GeometricProduct, Line, Motor, Multivector, Plane, Rotor, Sandwich, Sphere, Translator, down,
    exp, rotor_between_lines, up,
};
use common::*;
use glam::{DQuat, DVec3};

fn e3(v: &serde_json::Value) -> E3 {
    floats(v).try_into().expect("three floats")
}

/// Tolerances `k ε M` (see `Model`; no size scale, so `ρ = 0`), `M` a multivector's largest
/// coefficient or, for the moved point, `|x| + |t|`: ours (measured on the far set, ×10), and
/// clifford's float64 error on the near file (measured against the 50-digit reference of
/// `tools/far_objects.py --check`, ×10).
mod models {
    use super::Model;
    pub const ROTOR: Model = Model { ours: (24.0, 0), clifford: (4.0, 0) };
    pub const TRANSLATOR: Model = Model { ours: (12.0, 0), clifford: (4.0, 0) };
    pub const MOTOR: Model = Model { ours: (16.0, 0), clifford: (4.0, 0) };
    pub const MOVED: Model = Model { ours: (16.0, 0), clifford: (480.0, 0) };
    pub const EXP_LOG: Model = Model { ours: (16.0, 0), clifford: (4.0, 0) };
}
use models::*;

/// A rotors.json case: rotor, translator, motor, the moved point, and exp/log of them.
fn check_rotors(case: &serde_json::Value, label: &str, r: &mut Ratios) {
    let rotor = Rotor::from_axis_angle(e3(&case["axis"]), case["angle"].as_f64().unwrap()).unwrap();
    r.check("rotor", ROTOR, 0.0, mv_ulps(&rotor.into(), &mv(&case["rotor"])), label);
    let translator = Translator::from_vector(e3(&case["translation"]));
    r.check("translator", TRANSLATOR, 0.0, mv_ulps(&translator.into(), &mv(&case["translator"])), label);
    let motor = Motor::from_rotor_translator(rotor, translator);
    r.check("motor", MOTOR, 0.0, mv_ulps(&motor.into(), &mv(&case["motor"])), label);
    let x = e3(&case["x"]);
    let moved = DVec3::from(down(motor.sandwich(up(x))).unwrap());
    let size = DVec3::from(x).length() + DVec3::from(e3(&case["translation"])).length();
    let err = moved.distance(DVec3::from(e3(&case["moved_euc"]))) / (f64::EPSILON * size);
    r.check("moved point: M = |x| + |t|", MOVED, 0.0, err, label);
    // exp of the generators gives the same versors; log inverts exp.
    let half = -0.5 * case["angle"].as_f64().unwrap();
    let a = DVec3::from(e3(&case["axis"])).normalize();
    let gen_r = Bivector { e12: half * a.z, e13: -half * a.y, e23: half * a.x, ..Bivector::zero() };
    r.check("exp rotor", ROTOR, 0.0, mv_ulps(&exp(gen_r).unwrap().into(), &mv(&case["rotor"])), label);
    let t = e3(&case["translation"]);
    let gen_t = Bivector { e1i: -0.5 * t[0], e2i: -0.5 * t[1], e3i: -0.5 * t[2], ..Bivector::zero() };
    r.check("exp translator", TRANSLATOR, 0.0, mv_ulps(&exp(gen_t).unwrap().into(), &mv(&case["translator"])), label);
    let back = Motor::exp(motor.log().unwrap());
    r.check("exp(log M)", EXP_LOG, 0.0, mv_ulps(&back.into(), &mv(&case["motor"])), label);
}

#[test]
fn rotors_translators_and_motors_match_clifford() {
    let mut r = Ratios::new("rotors.json", Reference::Clifford);
    for (n, case) in cases(&golden("rotors.json")).iter().enumerate() {
        check_rotors(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

#[test]
fn far_rotors_translators_and_motors_match_the_exact_reference() {
    let mut r = Ratios::new("far_objects.json rotors", Reference::Exact);
    for (n, case) in far_objects()["rotors"].as_array().unwrap().iter().enumerate() {
        check_rotors(case, &format!("case {n}"), &mut r);
    }
    r.finish();
}

/// A point in [−s, s]³.
fn vec(rng: &mut Rng, s: f64) -> DVec3 {
    DVec3::from(rng.e3(-s, s))
}

/// A rigid-motion generator: rotation parts in [−rot, rot], translation in [−trans, trans].
fn generator(rng: &mut Rng, rot: f64, trans: f64) -> Bivector {
    let (r, t) = (vec(rng, rot), vec(rng, trans));
    Bivector { e12: r.x, e13: r.y, e23: r.z, e1i: t.x, e2i: t.y, e3i: t.z, ..Bivector::zero() }
}

/// `Σ Bⁿ/n!` with the dense multivector.
fn dense_exp(b: Bivector) -> Multivector {
    let b: Multivector = b.into();
    let (mut term, mut sum) = (Multivector::zero(), Multivector::zero());
    term.coeffs[0] = 1.0;
    for n in 1..60 {
        sum = sum + term;
        term = term.gp(b).scale(1.0 / n as f64);
    }
    sum
}

#[test]
fn exp_matches_the_series_and_log_inverts_it() {
    let mut rng = Rng::new(3);
    for i in 0..300 {
        // Include tiny rotations, where the closed form switches to its series.
        let rot = if i % 5 == 0 { 1e-7 } else { 1.5 };
        let b = generator(&mut rng, rot, 4.0);
        let m = exp(b).unwrap();
        assert_mv_close(&m.into(), &dense_exp(b), 1e-12, "exp against the series");
        assert!((m * m.reverse()).s - 1.0 < 1e-12, "exp(B) is normalised");
        let back = Bivector::from(m.log().unwrap());
        assert!(max_rel_diff(&back.to_array(), &b.to_array()) < 1e-10, "log(exp B) = B: {back:?} vs {b:?}");
    }
    assert_eq!(exp(Bivector { eoi: 1.0, ..Bivector::zero() }), Err(cga_core::VersorError::NotAGenerator));
}

#[test]
fn motors_move_every_object_rigidly() {
    let mut rng = Rng::new(8);
    for _ in 0..200 {
        let (axis, angle, t) = (vec(&mut rng, 1.0).normalize(), 3.0 * rng.range(-0.5, 0.5), vec(&mut rng, 5.0));
        let motor = Motor::from_rotor_translator(
            Rotor::from_axis_angle(axis.into(), angle).unwrap(),
            Translator::from_vector(t.into()),
        );
        let q = DQuat::from_axis_angle(axis, angle);
        let apply = |x: DVec3| q * x + t;
        let (a, b, c, d) = (vec(&mut rng, 3.0), vec(&mut rng, 3.0), vec(&mut rng, 3.0), vec(&mut rng, 3.0));

        let line = motor.sandwich(Line::through(a.into(), b.into()).unwrap());
        let want = Line::through(apply(a).into(), apply(b).into()).unwrap();
        assert!(max_rel_diff(&line.to_array(), &want.to_array()) < 1e-10, "line");

        let plane = motor.sandwich(Plane::through(a.into(), b.into(), c.into()).unwrap());
        let want = Plane::through(apply(a).into(), apply(b).into(), apply(c).into()).unwrap();
        assert!(max_rel_diff(&plane.to_array(), &want.to_array()) < 1e-10, "plane");

        let circle = motor.sandwich(Circle::through(a.into(), b.into(), c.into()).unwrap());
        let want = Circle::through(apply(a).into(), apply(b).into(), apply(c).into()).unwrap();
        assert!(max_rel_diff(&circle.to_array(), &want.to_array()) < 1e-9, "circle");

        let sphere = motor.sandwich(Sphere::through(a.into(), b.into(), c.into(), d.into()).unwrap());
        let want = Sphere::through(apply(a).into(), apply(b).into(), apply(c).into(), apply(d).into()).unwrap();
        assert!(max_rel_diff(&sphere.to_array(), &want.to_array()) < 1e-8, "sphere");
    }
}

#[test]
fn the_rotor_between_two_lines_takes_one_to_the_other() {
    let mut rng = Rng::new(21);
    for _ in 0..300 {
        let l1 = Line::through(vec(&mut rng, 4.0).into(), vec(&mut rng, 4.0).into()).unwrap();
        let l2 = Line::through(vec(&mut rng, 4.0).into(), vec(&mut rng, 4.0).into()).unwrap();
        let r = rotor_between_lines(l1, l2).unwrap();
        approx::assert_abs_diff_eq!((r * r.reverse()).s, 1.0, epsilon = 1e-10); // R R̃ = 1
        let moved = r.sandwich(l1);
        assert!(max_rel_diff(&moved.to_array(), &l2.to_array()) < 1e-9, "R L1 R̃ = L2: {moved:?} vs {l2:?}");
    }
}
