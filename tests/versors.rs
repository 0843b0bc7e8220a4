//! Rotors, translators, motors, exp/log and the rotor between lines, against clifford
//! (`rotors.json`), a dense Taylor series, and rigid transforms in glam.

mod common;

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

#[test]
fn rotors_translators_and_motors_match_clifford() {
    let file = golden("rotors.json");
    for (n, case) in cases(&file).iter().enumerate() {
        let rotor = Rotor::from_axis_angle(e3(&case["axis"]), case["angle"].as_f64().unwrap()).unwrap();
        assert_mv_close(&rotor.into(), &mv(&case["rotor"]), 1e-12, &format!("case {n}: rotor"));
        let translator = Translator::from_vector(e3(&case["translation"]));
        assert_mv_close(&translator.into(), &mv(&case["translator"]), 1e-12, &format!("case {n}: translator"));
        let motor = Motor::from_rotor_translator(rotor, translator);
        assert_mv_close(&motor.into(), &mv(&case["motor"]), 1e-12, &format!("case {n}: motor"));
        let moved = down(motor.sandwich(up(e3(&case["x"])))).unwrap();
        let want = DVec3::from(e3(&case["moved_euc"]));
        assert!(DVec3::from(moved).distance(want) < 1e-11 * want.length().max(1.0), "case {n}: moved point");
        // exp of the generators gives the same versors; log inverts exp.
        let half = -0.5 * case["angle"].as_f64().unwrap();
        let a = DVec3::from(e3(&case["axis"])).normalize();
        let gen_r = Bivector { e12: half * a.z, e13: -half * a.y, e23: half * a.x, ..Bivector::zero() };
        assert_mv_close(&exp(gen_r).unwrap().into(), &mv(&case["rotor"]), 1e-12, &format!("case {n}: exp rotor"));
        let t = e3(&case["translation"]);
        let gen_t = Bivector { e1i: -0.5 * t[0], e2i: -0.5 * t[1], e3i: -0.5 * t[2], ..Bivector::zero() };
        assert_mv_close(&exp(gen_t).unwrap().into(), &mv(&case["translator"]), 1e-12, &format!("case {n}: exp T"));
        let back = Motor::exp(motor.log().unwrap());
        assert_mv_close(&back.into(), &mv(&case["motor"]), 1e-11, &format!("case {n}: exp(log M)"));
    }
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
