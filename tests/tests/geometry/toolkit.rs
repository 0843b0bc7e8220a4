//! The everyday toolkit against Euclid and glam: rotors between directions, motors about
//! lines and as screws, log/exp, renormalisation, interpolation and splines of motors,
//! dilators and transversors, reflections and inversions of every object, projections,
//! distances, angles, Euclidean meets, bulk transforms and glam conversions.

use cga_tests::common;

use cga_core::euclid::E3;
use cga_core::reflect::{invert_point, reflect_point};
use cga_core::{
    Bivector, Circle, Dilator, Flat, Generator, Line, Meet, Motor, MotorSpline, Nearest, Plane, Reflect, Rotor,
    Sandwich, Sphere, Transversor, Vector, VersorError, distance, down, up,
};
use common::*;
use glam::{DAffine3, DQuat, DVec3};

fn v(x: E3) -> DVec3 {
    DVec3::from(x)
}

fn close(a: E3, b: E3, tol: f64, what: &str) {
    let scale = v(a).length().max(v(b).length()).max(1.0);
    assert!(v(a).distance(v(b)) <= tol * scale, "{what}: {a:?} vs {b:?}");
}

fn random_motor(rng: &mut Rng, t: f64) -> Motor {
    let r = Rotor::from_axis_angle(rng.direction(), rng.range(-3.0, 3.0)).unwrap();
    Motor::from_rotor_translation(r, rng.e3(-t, t))
}

#[test]
fn rotor_between_takes_one_direction_to_the_other() {
    let mut rng = Rng::new(1);
    for _ in 0..500 {
        let (a, b) = (rng.direction(), rng.e3(-5.0, 5.0));
        let r = Rotor::between(a, b).unwrap();
        close(r.rotate(a), v(b).normalize().to_array(), 1e-14, "R a R̃ = b̂");
        assert!(r.unit_defect() < 1e-15);
        // The shortest: the angle is the one between a and b.
        let (angle, _) = r.angle_axis().unwrap_or((0.0, [0.0; 3]));
        assert!((angle - v(a).angle_between(v(b))).abs() < 1e-12);
    }
    // Nearly opposite still works; exactly opposite is named.
    let r = Rotor::between([1.0, 0.0, 0.0], [-1.0, 1e-9, 0.0]).unwrap();
    close(r.rotate([1.0, 0.0, 0.0]), [-1.0, 1e-9, 0.0], 1e-12, "nearly antipodal");
    assert_eq!(Rotor::between([1.0, 2.0, 3.0], [-2.0, -4.0, -6.0]), Err(VersorError::Antipodal));
    assert_eq!(Rotor::between([0.0; 3], [1.0, 0.0, 0.0]), Err(VersorError::ZeroAxis));
    assert_eq!(Rotor::between([f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0]), Err(VersorError::ZeroAxis));
}

#[test]
fn motors_about_lines_and_screws_move_points_as_rodrigues_does() {
    let mut rng = Rng::new(2);
    for _ in 0..300 {
        let (p, d, angle, pitch) = (rng.e3(-50.0, 50.0), rng.direction(), rng.range(-6.0, 6.0), rng.range(-2.0, 2.0));
        let line = Line::new(p, d).unwrap();
        let m = Motor::screw(&line, angle, pitch).unwrap();
        let q = DQuat::from_axis_angle(v(d), angle);
        let x = rng.e3(-20.0, 20.0);
        let want = q * (v(x) - v(p)) + v(p) + v(d) * (pitch * angle);
        close(down(m.sandwich(up(x))).unwrap(), want.to_array(), 1e-12, "screw on a point");
        close(m.move_point(x), want.to_array(), 1e-13, "move_point");
        // The line itself is kept (an axis), and its generator reads back as the screw.
        let axis = m.sandwich(line);
        assert!(max_rel_diff(&axis.to_array(), &line.to_array()) < 1e-12, "the axis is fixed");
        if angle.abs() > 1e-3 && angle.abs() < 6.2 {
            let g = m.log().unwrap();
            let s = g.screw();
            // exp(log M) = M; the turn is |θ| (mod the log's principal range) about ±d.
            assert!(max_rel_diff(&Motor::exp(g).to_array(), &m.to_array()) < 1e-11);
            // log follows the motor's sign: the turn is |θ| (below 2π), not the shorter one.
            assert!((s.angle - angle.abs()).abs() < 1e-10, "angle {} vs {angle}", s.angle);
            assert!(v(s.axis).cross(v(d)).length() < 1e-10, "axis along d");
            assert!(line.distance_to(s.point).unwrap() < 1e-9 * (1.0 + v(p).length()), "axis point on the line");
        }
    }
    assert_eq!(Motor::about_line(&Line::zero(), 1.0), Err(VersorError::ZeroAxis));
}

#[test]
fn motor_parts_inverse_and_identity() {
    let mut rng = Rng::new(3);
    for _ in 0..200 {
        let m = random_motor(&mut rng, 100.0);
        let (r, t) = (m.rotor(), m.translation());
        assert!(max_rel_diff(&Motor::from_rotor_translation(r, t).to_array(), &m.to_array()) < 1e-14);
        let one = m * m.inverse();
        assert!(max_rel_diff(&one.to_array(), &Motor::identity().to_array()) < 1e-12, "M M⁻¹ = 1: {one:?}");
        let scaled = m.scale(3.0);
        let one = scaled * scaled.try_inverse().unwrap();
        assert!(max_rel_diff(&one.to_array(), &Motor::identity().to_array()) < 1e-12);
    }
    assert_eq!(Motor::<f64>::zero().try_inverse(), None);
    assert_eq!(Motor::<f64>::identity().sandwich(up([1.0, 2.0, 3.0])), up([1.0, 2.0, 3.0]));
}

#[test]
fn a_drifted_motor_is_refused_by_log_and_restored_by_renormalise() {
    let mut rng = Rng::new(4);
    let m = random_motor(&mut rng, 10.0);
    // A drift that a scale cannot undo: a small e123i part.
    let drifted = m + Motor { e123i: 1e-3, ..Motor::zero() };
    match drifted.log() {
        Err(VersorError::NotRigid { defect }) => assert!(defect > 1e-5, "defect {defect}"),
        other => panic!("log of a non-rigid motor: {other:?}"),
    }
    let fixed = drifted.scale(1.7).renormalise().unwrap();
    let (a, b) = fixed.study();
    assert!((a - 1.0).abs() < 1e-15 && b.abs() < 1e-15, "M M̃ = {a} + {b} e123i");
    assert!(fixed.log().is_ok());
    // A long chain of compositions drifts by rounding only and stays rigid.
    let step = random_motor(&mut rng, 0.1);
    let mut chain = Motor::identity();
    for _ in 0..1000 {
        chain = step * chain;
    }
    assert!(chain.rigid_defect() < 1e-12 && chain.log().is_ok());
}

#[test]
fn interpolation_reaches_both_ends_at_constant_velocity_along_the_shorter_path() {
    let mut rng = Rng::new(5);
    let same_motion = |a: &Motor, b: &Motor| {
        max_rel_diff(&a.to_array(), &b.to_array()).min(max_rel_diff(&a.to_array(), &(-*b).to_array())) < 1e-10
    };
    for _ in 0..200 {
        let (m0, m1) = (random_motor(&mut rng, 10.0), random_motor(&mut rng, 10.0));
        assert!(same_motion(&Motor::interpolate(&m0, &m1, 0.0).unwrap(), &m0));
        assert!(same_motion(&Motor::interpolate(&m0, &m1, 1.0).unwrap(), &m1));
        // Constant velocity: equal steps have equal relative motors.
        let at = |t: f64| Motor::interpolate(&m0, &m1, t).unwrap();
        let (a, b) =
            (Motor::relative_log(&at(0.1), &at(0.3)).unwrap(), Motor::relative_log(&at(0.6), &at(0.8)).unwrap());
        assert!(max_rel_diff(&a.to_array(), &b.to_array()) < 1e-9, "{a:?} vs {b:?}");
        // The shorter path: the relative turn is at most π.
        assert!(Motor::relative_log(&m0, &m1).unwrap().screw().angle <= std::f64::consts::PI + 1e-12);
        // pow: M^½ M^½ = M.
        let half = m1.pow(0.5).unwrap();
        assert!(max_rel_diff(&(half * half).to_array(), &m1.to_array()) < 1e-10);
    }
    // A relative half turn has two shortest paths.
    let turn = Motor::about_line(&Line::new([0.0; 3], [0.0, 0.0, 1.0]).unwrap(), std::f64::consts::PI).unwrap();
    let exact = Motor { s: 0.0, ..turn };
    assert_eq!(Motor::interpolate(&Motor::identity(), &exact, 0.5), Err(VersorError::Antipodal));
    let bad = Motor { e123i: 0.5, ..Motor::identity() };
    assert!(matches!(Motor::interpolate(&Motor::identity(), &bad, 0.5), Err(VersorError::NotRigid { .. })));
}

#[test]
fn a_spline_of_motors_passes_through_its_poses_with_continuous_velocity() {
    let mut rng = Rng::new(6);
    let poses: Vec<Motor> = (0..6).map(|_| random_motor(&mut rng, 3.0)).collect();
    let spline = MotorSpline::new(&poses).unwrap();
    for (k, m) in poses.iter().enumerate() {
        let got = spline.at(k as f64).unwrap();
        let same = max_rel_diff(&got.to_array(), &m.to_array()).min(max_rel_diff(&got.to_array(), &(-*m).to_array()));
        assert!(same < 1e-10, "pose {k}");
    }
    for k in 0..=50 {
        let m = spline.at(k as f64 * 0.1).unwrap();
        assert!(m.rigid_defect() < 1e-14, "at {}: defect {:e} {m:?}", k as f64 * 0.1, m.rigid_defect());
    }
    // Velocity on either side of each interior knot, by central differences of the log.
    let h = 1e-5;
    for k in 1..5 {
        let u = k as f64;
        let vel = |a: f64, b: f64| {
            let g = Motor::relative_log(&spline.at(a).unwrap(), &spline.at(b).unwrap()).unwrap();
            g.to_array().map(|x| x / (b - a))
        };
        let (left, right) = (vel(u - 2.0 * h, u - h), vel(u + h, u + 2.0 * h));
        assert!(max_rel_diff(&left, &right) < 1e-3, "C¹ at knot {k}: {left:?} vs {right:?}");
    }
    assert_eq!(MotorSpline::<f64>::new(&poses[..1]).err(), Some(VersorError::TooFewPoses));
}

#[test]
fn dilators_scale_about_their_centre_and_transversors_are_inverted_translations() {
    let mut rng = Rng::new(7);
    for _ in 0..200 {
        let (c, s, x) = (rng.e3(-10.0, 10.0), rng.decades(-3.0, 3.0), rng.e3(-10.0, 10.0));
        let d = Dilator::new(c, s).unwrap();
        let want = v(c) + s * (v(x) - v(c));
        close(down(d.sandwich(up(x))).unwrap(), want.to_array(), 1e-12, "dilated point");
        assert!((d.factor() - s).abs() < 1e-12 * s);
        let sphere = Sphere::new(x, 0.5).unwrap();
        let (centre, r) = d.sandwich(sphere).centre_radius().unwrap();
        close(centre, want.to_array(), 1e-11, "dilated sphere centre");
        // Read back at ρ = |c|/r: the sphere's own ε ρ² (docs/STABILITY.md).
        let rho = v(want.to_array()).length() / (0.5 * s);
        // and the dilator's own coefficients, which span a factor s (or 1/s).
        let tol = 1e-14 * (1.0 + rho).powi(2) * s.max(1.0 / s);
        assert!((r - 0.5 * s).abs() < tol * 0.5 * s, "radius {r} vs {}", 0.5 * s);
    }
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(Dilator::new([0.0; 3], bad), Err(VersorError::Factor));
    }
    for _ in 0..200 {
        let (t, x) = (rng.e3(-1.0, 1.0), rng.e3(-2.0, 2.0));
        let k = Transversor::from_vector(t);
        let (t, x) = (v(t), v(x));
        let want = (x + x.length_squared() * t) / (1.0 + 2.0 * t.dot(x) + t.length_squared() * x.length_squared());
        close(down(k.sandwich(up(x.to_array()))).unwrap(), want.to_array(), 1e-11, "transversion");
    }
}

#[test]
fn reflections_mirror_every_object_and_twice_are_the_identity() {
    let mut rng = Rng::new(8);
    for _ in 0..200 {
        let plane = Plane::new(rng.e3(-5.0, 5.0), rng.direction()).unwrap();
        let (a, b, c, d) = (rng.e3(-5.0, 5.0), rng.e3(-5.0, 5.0), rng.e3(-5.0, 5.0), rng.e3(-5.0, 5.0));
        let m = |x: E3| reflect_point(x, &plane).unwrap();
        close(down(up(a).reflect_in(&plane).unwrap()).unwrap(), m(a), 1e-12, "point");
        // Every object is the object through the mirrored points, in the same order.
        let pair = Bivector::from_points(a, b).unwrap();
        let want = Bivector::from_points(m(a), m(b)).unwrap();
        assert!(max_rel_diff(&pair.reflect_in(&plane).unwrap().to_array(), &want.to_array()) < 1e-10, "pair");
        let line = Line::through(a, b).unwrap();
        let want = Line::through(m(a), m(b)).unwrap();
        assert!(max_rel_diff(&line.reflect_in(&plane).unwrap().to_array(), &want.to_array()) < 1e-10, "line");
        let circle = Circle::through(a, b, c).unwrap();
        let want = Circle::through(m(a), m(b), m(c)).unwrap();
        assert!(max_rel_diff(&circle.reflect_in(&plane).unwrap().to_array(), &want.to_array()) < 1e-8, "circle");
        let p = Plane::through(a, b, c).unwrap();
        let want = Plane::through(m(a), m(b), m(c)).unwrap();
        assert!(max_rel_diff(&p.reflect_in(&plane).unwrap().to_array(), &want.to_array()) < 1e-10, "plane");
        let sphere = Sphere::through(a, b, c, d).unwrap();
        let want = Sphere::through(m(a), m(b), m(c), m(d)).unwrap();
        assert!(max_rel_diff(&sphere.reflect_in(&plane).unwrap().to_array(), &want.to_array()) < 1e-7, "sphere");
        // Twice: the identity.
        let twice = circle.reflect_in(&plane).unwrap().reflect_in(&plane).unwrap();
        assert!(max_rel_diff(&twice.to_array(), &circle.to_array()) < 1e-10);
        // In a point and a line.
        close(down(up(a).reflect_in_point(c)).unwrap(), (2.0 * v(c) - v(a)).to_array(), 1e-12, "point in a point");
        let foot = line.nearest_point(c).unwrap();
        let got = down(up(c).reflect_in_line(&line).unwrap()).unwrap();
        close(got, (2.0 * v(foot) - v(c)).to_array(), 1e-12, "point in a line");
        let twice = sphere.reflect_in_point(d).reflect_in_point(d);
        assert!(max_rel_diff(&twice.to_array(), &sphere.to_array()) < 1e-10);
    }
}

#[test]
fn inversions_follow_the_euclidean_map_and_send_spheres_through_the_centre_to_planes() {
    let mut rng = Rng::new(9);
    for _ in 0..200 {
        let (c, r) = (rng.e3(-3.0, 3.0), rng.range(0.5, 3.0));
        let sphere = Sphere::new(c, r).unwrap();
        let x = rng.e3(-5.0, 5.0);
        let want = invert_point(x, &sphere).unwrap();
        close(down(up(x).invert_in(&sphere).unwrap()).unwrap(), want, 1e-11, "inverted point");
        let back = up(x).invert_in(&sphere).unwrap().invert_in(&sphere).unwrap();
        close(down(back).unwrap(), x, 1e-11, "inversion twice");
        // A sphere through the centre becomes a plane; a line not through it a circle.
        let through = Sphere::new(add(c, x), v(x).length()).unwrap();
        let image = through.invert_in(&sphere).unwrap();
        let dual = image.dual();
        let largest = dual.to_array().iter().fold(0.0f64, |m, k| m.max(k.abs()));
        assert!(dual.eo.abs() < 1e-12 * largest, "a plane: its dual has no eo part ({dual:?})");
        let (a, b) = (rng.e3(-5.0, 5.0), rng.e3(-5.0, 5.0));
        let circle = Line::through(a, b).unwrap().invert_in(&sphere).unwrap();
        let (cc, _, rr) = circle.centre_normal_radius().unwrap();
        assert!((distance(cc, c) - rr).abs() < 1e-8 * rr, "the image circle passes through the centre");
        let mid = invert_point(v(a).lerp(v(b), 0.3).to_array(), &sphere).unwrap();
        assert!((distance(cc, mid) - rr).abs() < 1e-8 * rr, "and through the image of the line's points");
    }
    let sphere = Sphere::new([1.0, 2.0, 3.0], 2.0).unwrap();
    assert_eq!(up([1.0, 2.0, 3.0]).invert_in(&sphere), Err(cga_core::GeometryError::AtInfinity));
    assert!(invert_point([1.0, 2.0, 3.0], &sphere).is_err());
}

fn add(a: E3, b: E3) -> E3 {
    (v(a) + v(b)).to_array()
}

#[test]
fn projections_distances_and_angles_are_euclids() {
    let mut rng = Rng::new(10);
    for _ in 0..300 {
        let (p, d, x) = (rng.e3(-10.0, 10.0), rng.direction(), rng.e3(-10.0, 10.0));
        let line = Line::new(p, d).unwrap();
        let foot = v(p) + v(d) * (v(x) - v(p)).dot(v(d));
        close(up(x).project_onto(&line).unwrap(), foot.to_array(), 1e-13, "onto a line");
        assert!((line.distance_to(x).unwrap() - v(x).distance(foot)).abs() < 1e-12);
        let plane = Plane::new(p, d).unwrap();
        let h = (v(x) - v(p)).dot(v(d));
        close(up(x).project_onto(&plane).unwrap(), (v(x) - h * v(d)).to_array(), 1e-13, "onto a plane");
        assert!((plane.signed_distance(x).unwrap() - h).abs() < 1e-12);
        let r = rng.range(0.5, 4.0);
        let sphere = Sphere::new(p, r).unwrap();
        let on = v(p) + r * (v(x) - v(p)).normalize();
        close(up(x).project_onto(&sphere).unwrap(), on.to_array(), 1e-12, "onto a sphere");
        assert!((sphere.signed_distance(x).unwrap() - (v(x).distance(v(p)) - r)).abs() < 1e-12);
        let circle = Circle::new(p, d, r).unwrap();
        let inplane = (v(x) - v(p)) - v(d) * (v(x) - v(p)).dot(v(d));
        close(
            up(x).project_onto(&circle).unwrap(),
            (v(p) + r * inplane.normalize()).to_array(),
            1e-11,
            "onto a circle",
        );
        let (a, b) = (rng.e3(-5.0, 5.0), rng.e3(-5.0, 5.0));
        let pair = Bivector::from_points(a, b).unwrap();
        let nearer = if v(x).distance(v(a)) <= v(x).distance(v(b)) { a } else { b };
        close(up(x).project_onto(&pair).unwrap(), nearer, 1e-10, "onto a point pair");
        assert!((distance(a, b) - v(a).distance(v(b))).abs() < 1e-14);
        // Two lines: closest points against the perpendicular's Euclidean conditions.
        let other = Line::new(rng.e3(-10.0, 10.0), rng.direction()).unwrap();
        let k = line.closest_points(&other).unwrap();
        let gap = v(k.on_other) - v(k.on_self);
        assert!(gap.dot(v(d)).abs() < 1e-10 && gap.dot(v(other.direction().unwrap())).abs() < 1e-10);
        assert!(line.distance_to(k.on_self).unwrap() < 1e-10 && other.distance_to(k.on_other).unwrap() < 1e-10);
        assert!((line.angle_to(&other).unwrap() - v(d).angle_between(v(other.direction().unwrap()))).abs() < 1e-12);
        let plane2 = Plane::new(x, other.direction().unwrap()).unwrap();
        let want = std::f64::consts::FRAC_PI_2
            - v(d)
                .angle_between(v(other.direction().unwrap()))
                .min(std::f64::consts::PI - v(d).angle_between(v(other.direction().unwrap())));
        assert!((line.angle_to_plane(&plane2).unwrap() - want).abs() < 1e-12);
    }
    let parallel: cga_core::Closest<f64> = Line::new([0.0, 1.0, 0.0], [1.0, 0.0, 0.0])
        .unwrap()
        .closest_points(&Line::new([0.0; 3], [2.0, 0.0, 0.0]).unwrap())
        .unwrap();
    assert!(parallel.parallel && (parallel.distance - 1.0).abs() < 1e-15);
    assert!(Sphere::new([0.0; 3], 1.0).unwrap().nearest_point([0.0; 3]).is_err(), "at the centre");
}

#[test]
fn joins_of_lines_and_points_are_the_planes_that_hold_them() {
    let x_axis: Line = Line::new([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let (n, d) = x_axis.join_point([0.0, 2.0, 5.0]).unwrap().normal_offset().unwrap();
    close(n, [0.0, -5.0 / 29f64.sqrt(), 2.0 / 29f64.sqrt()], 1e-15, "normal d × (x − p)");
    assert!(d.abs() < 1e-15);
    assert_eq!(x_axis.join_point([3.0, 0.0, 0.0]), Err(cga_core::GeometryError::CollinearPoints));
    let crossing = Line::new([2.0, -1.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
    let (n, d) = x_axis.join_line(&crossing).unwrap().normal_offset().unwrap();
    close(n, [0.0, 0.0, 1.0], 1e-15, "crossing lines' plane");
    assert!(d.abs() < 1e-15);
    let parallel = Line::new([0.0, 0.0, 3.0], [2.0, 0.0, 0.0]).unwrap();
    let (n, _) = x_axis.join_line(&parallel).unwrap().normal_offset().unwrap();
    close(n, [0.0, -1.0, 0.0], 1e-15, "parallel lines' plane");
    let skew = Line::new([0.0, 0.0, 1.0], [0.0, 1.0, 0.0]).unwrap();
    assert_eq!(x_axis.join_line(&skew), Err(cga_core::GeometryError::Skew));
    // Far from the origin, a crossing is still a crossing.
    let far: Line = Line::new([1e6, 1e6, 1e6], [1.0, 0.0, 0.0]).unwrap();
    let other = Line::new([1e6, 1e6, 1e6], [0.0, 1.0, 1.0]).unwrap();
    assert!(far.join_line(&other).is_ok());
}

#[test]
fn meets_hand_back_euclidean_points_lines_and_circles() {
    let unit = Sphere::new([0.0; 3], 1.0).unwrap();
    let z = |x: f64, y: f64| Line::new([x, y, 0.0], [0.0, 0.0, 1.0]).unwrap();
    assert_eq!(z(0.0, 0.0).intersect_sphere(&unit).unwrap(), Meet::Points([[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]]));
    assert_eq!(z(1.0, 0.0).intersect_sphere(&unit).unwrap(), Meet::Point([1.0, 0.0, 0.0]));
    assert_eq!(z(1.5, 0.0).intersect_sphere(&unit).unwrap(), Meet::Miss);
    let other = Sphere::new([1.0, 0.0, 0.0], 1.0).unwrap();
    match unit.intersect_sphere(&other).unwrap() {
        Meet::Circle { centre, normal, radius } => {
            close(centre, [0.5, 0.0, 0.0], 1e-15, "circle centre");
            close(normal, [1.0, 0.0, 0.0], 1e-15, "normal");
            assert!((radius - 0.75f64.sqrt()).abs() < 1e-15);
        }
        m => panic!("{m:?}"),
    }
    assert_eq!(
        unit.intersect_sphere(&Sphere::new([2.0, 0.0, 0.0], 1.0).unwrap()).unwrap(),
        Meet::Point([1.0, 0.0, 0.0])
    );
    assert_eq!(unit.intersect_sphere(&Sphere::new([3.0, 0.0, 0.0], 1.0).unwrap()).unwrap(), Meet::Miss);
    assert_eq!(unit.intersect_sphere(&unit).unwrap(), Meet::Contained);
    let floor = Plane::new([0.0, 0.0, 0.5], [0.0, 0.0, 1.0]).unwrap();
    match floor.intersect_sphere(&unit).unwrap() {
        Meet::Circle { centre, radius, .. } => {
            close(centre, [0.0, 0.0, 0.5], 1e-15, "cut centre");
            assert!((radius - 0.75f64.sqrt()).abs() < 1e-15);
        }
        m => panic!("{m:?}"),
    }
    let wall = Plane::new([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let side = Plane::new([0.0; 3], [0.0, 1.0, 0.0]).unwrap();
    assert_eq!(Plane::intersect_planes(&floor, &wall, &side).unwrap(), Meet::Point([0.0, 0.0, 0.5]));
    match wall.intersect_plane(&side).unwrap() {
        Meet::Line(l) => assert!(l.distance_to([0.0, 0.0, 7.0]).unwrap() < 1e-15),
        m => panic!("{m:?}"),
    }
    let ring = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
    let across = Line::new([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    assert_eq!(across.intersect_circle(&ring).unwrap(), Meet::Points([[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]));
    assert_eq!(wall.intersect_circle(&ring).unwrap(), Meet::Points([[0.0, -1.0, 0.0], [0.0, 1.0, 0.0]]));
    // Circles in one plane, in two planes, and a circle on a sphere.
    let beside = Circle::new([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
    let h = 0.75f64.sqrt();
    assert_eq!(ring.intersect_circle(&beside).unwrap(), Meet::Points([[0.5, -h, 0.0], [0.5, h, 0.0]]));
    let far = Circle::new([2.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
    assert_eq!(ring.intersect_circle(&far).unwrap(), Meet::Point([1.0, 0.0, 0.0]));
    assert_eq!(ring.intersect_circle(&ring).unwrap(), Meet::Contained);
    let upright = Circle::new([2.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0).unwrap(); // in y = 0, through (1, 0, 0) and (3, 0, 0)
    match ring.intersect_circle(&upright).unwrap() {
        Meet::Point(x) => close(x, [1.0, 0.0, 0.0], 1e-15, "crossing planes: the one common point"),
        m => panic!("{m:?}"),
    }
    let crossing = Circle::new([0.0; 3], [0.0, 1.0, 0.0], 1.0).unwrap(); // the unit circle in y = 0
    // Ordered along n1 × n2 = e3 × e2 = −e1.
    assert_eq!(ring.intersect_circle(&crossing).unwrap(), Meet::Points([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]));
    assert_eq!(ring.intersect_sphere(&unit).unwrap(), Meet::Contained);
    match ring.intersect_sphere(&Sphere::new([1.0, 0.0, 0.0], 1.0).unwrap()).unwrap() {
        Meet::Points([a, b]) => {
            close(a, [0.5, -h, 0.0], 1e-15, "circle ∩ sphere");
            close(b, [0.5, h, 0.0], 1e-15, "circle ∩ sphere");
        }
        m => panic!("{m:?}"),
    }
    assert_eq!(ring.intersect_sphere(&Sphere::new([0.0, 0.0, 5.0], 1.0).unwrap()).unwrap(), Meet::Miss);
}

#[test]
fn meets_give_one_answer_whichever_object_is_asked() {
    let unit = Sphere::new([0.0; 3], 1.0).unwrap();
    let floor = Plane::new([0.0, 0.0, 0.5], [0.0, 0.0, 1.0]).unwrap();
    let ring = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
    let tilted = Circle::new([0.2, 0.1, 0.3], [0.3, -0.2, 1.0], 0.9).unwrap();
    let wall = Plane::new([0.3, 0.0, 0.0], [1.0, 0.2, 0.1]).unwrap();
    for line in [
        Line::new([-3.0, 0.1, 0.2], [1.0, 0.05, 0.0]).unwrap(),
        Line::new([0.3, -0.4, -2.0], [0.1, 0.2, 1.0]).unwrap(),
        Line::new([5.0, 5.0, 5.0], [0.0, 0.0, 1.0]).unwrap(),
    ] {
        assert_eq!(unit.intersect_line(&line).unwrap(), line.intersect_sphere(&unit).unwrap());
        assert_eq!(floor.intersect_line(&line).unwrap(), line.intersect_plane(&floor).unwrap());
        assert_eq!(ring.intersect_line(&line).unwrap(), line.intersect_circle(&ring).unwrap());
    }
    // The circle of a sphere and a plane is normal to the plane, from either side.
    let cut = unit.intersect_plane(&floor).unwrap();
    assert_eq!(cut, floor.intersect_sphere(&unit).unwrap());
    match cut {
        Meet::Circle { normal, .. } => close(normal, [0.0, 0.0, 1.0], 1e-15, "the plane's normal"),
        m => panic!("{m:?}"),
    }
    assert_eq!(unit.intersect_circle(&tilted).unwrap(), tilted.intersect_sphere(&unit).unwrap());
    assert_eq!(tilted.intersect_plane(&wall).unwrap(), wall.intersect_circle(&tilted).unwrap());
    assert!(matches!(tilted.intersect_plane(&wall).unwrap(), Meet::Points(_)));
}

#[test]
fn every_blade_type_classifies_as_its_grade_does() {
    use cga_core::{FlatPoint, Kind};
    let line = Line::new([1.0, 2.0, 3.0], [0.0, 0.6, 0.8]).unwrap();
    match line.classify().unwrap() {
        Kind::Line { point, direction } => {
            close(direction, [0.0, 0.6, 0.8], 1e-15, "line direction");
            assert!(line.distance_to(point).unwrap() < 1e-14);
        }
        k => panic!("{k:?}"),
    }
    let plane = Plane::new([0.0, 0.0, 2.0], [0.0, 0.0, 1.0]).unwrap();
    match plane.classify().unwrap() {
        Kind::Plane { grade: 4, normal, offset } => {
            close(normal, [0.0, 0.0, 1.0], 1e-15, "plane normal");
            assert!((offset - 2.0).abs() < 1e-15);
        }
        k => panic!("{k:?}"),
    }
    let flat_point = FlatPoint { e1i: 2.0, e2i: -4.0, e3i: 6.0, eoi: 2.0 };
    assert_eq!(flat_point.classify().unwrap(), Bivector::from_storage(&flat_point.to_storage()).classify().unwrap());
    assert!(matches!(flat_point.classify().unwrap(), Kind::FlatPoint(_)));
    assert_eq!(Line::<f64>::zero().classify().unwrap(), Kind::Zero);
}

#[test]
fn the_origin_and_scalar_results_are_numbers_as_written() {
    let o = cga_core::eo::<f64>();
    assert_eq!(o, up([0.0; 3]));
    assert_eq!(*(o | cga_core::ei::<f64>()), -1.0);
    // A scalar-valued product is its number: deref, the number's methods, and `f64::from`.
    let (a, b) = (up([1.0, 2.0, 3.0]), up([4.0, 6.0, 3.0]));
    let half_squared = -*(a | b);
    assert_eq!(half_squared, 12.5);
    assert_eq!((a | b).abs(), 12.5);
    let x = Vector { e1: 3.0, e2: 4.0, e3: 0.0, eo: 0.0, ei: 0.0 };
    assert_eq!((x | x).sqrt(), 5.0);
    assert_eq!(f64::from(x | x), 25.0);
    let (y, e1) = (
        Vector::<f32> { e1: 3.0, e2: 4.0, e3: 0.0, eo: 0.0, ei: 0.0 },
        Vector::<f32> { e1: 1.0, e2: 0.0, e3: 0.0, eo: 0.0, ei: 0.0 },
    );
    assert_eq!(f32::from(y | e1), 3.0);
}

#[test]
fn bulk_transforms_are_the_single_ones_to_the_bit_and_glam_round_trips() {
    let mut rng = Rng::new(11);
    let m = random_motor(&mut rng, 100.0);
    let points: Vec<E3> = (0..1000).map(|_| rng.e3(-1e3, 1e3)).collect();
    let mut out = vec![[0.0; 3]; points.len()];
    m.transform_points(&points, &mut out).unwrap();
    let affine = DAffine3::from(m);
    for (x, y) in points.iter().zip(&out) {
        assert_eq!(*y, m.transform_point(*x), "bit for bit");
        close(*y, m.move_point(*x), 1e-14, "as the sandwich");
        close(*y, affine.transform_point3(v(*x)).to_array(), 1e-14, "as glam");
    }
    assert_eq!(m.transform_points(&points, &mut out[..3]), Err(VersorError::Lengths { input: 1000, output: 3 }));
    let lines: Vec<Line> = (0..50).map(|_| Line::new(rng.e3(-5.0, 5.0), rng.direction()).unwrap()).collect();
    let mut moved = vec![Line::zero(); 50];
    m.transform_objects(&lines, &mut moved).unwrap();
    assert_eq!(moved[7], m.sandwich(lines[7]));
    // glam: rotors and quaternions, motors and affine maps, both ways.
    let r = m.rotor();
    let q = DQuat::from(r);
    let x = rng.e3(-3.0, 3.0);
    close((q * v(x)).to_array(), r.rotate(x), 1e-14, "DQuat from a rotor");
    assert_eq!(Rotor::from(q), r);
    let back = Motor::try_from(affine).unwrap();
    let same = max_rel_diff(&back.to_array(), &m.to_array()).min(max_rel_diff(&back.to_array(), &(-m).to_array()));
    assert!(same < 1e-12);
    let (q, t): (DQuat, DVec3) = m.into();
    assert!(max_rel_diff(&Motor::from((q, t)).to_array(), &m.to_array()) < 1e-14);
    assert!(matches!(Motor::try_from(DAffine3::from_scale(DVec3::splat(2.0))), Err(VersorError::NotRigid { .. })));
    assert_eq!(up(DVec3::new(1.0, 2.0, 3.0)), up([1.0, 2.0, 3.0])); // up(impl Into<[f64; 3]>)
    let p: Vector = DVec3::new(1.0, 2.0, 3.0).into();
    assert_eq!(DVec3::try_from(p).unwrap(), DVec3::new(1.0, 2.0, 3.0));
}

#[test]
fn generators_print_as_screws() {
    let line = Line::new([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
    let m = Motor::screw(&line, std::f64::consts::FRAC_PI_2, 0.5).unwrap();
    let g = m.log().unwrap();
    assert_eq!(
        format!("{g:.2}"),
        "generator of rotation 90.00° about the line through (0.00, 1.00, 0.00) along (0.00, 0.00, 1.00), pitch 0.50"
    );
    assert_eq!(format!("{:.1}", Generator::translation([1.0, 0.0, 0.0])), "generator of translation (1.0, 0.0, 0.0)");
    assert_eq!(format!("{:.1}", Dilator::new([1.0, 0.0, 0.0], 2.0).unwrap()), "dilation by 2.0 about (1.0, 0.0, 0.0)");
    assert_eq!(Rotor::exp(Generator::translation([1.0, 0.0, 0.0])), Err(VersorError::NotARotation));
}

#[test]
fn blades_are_classified_as_they_were_built() {
    use cga_core::{Kind, Multivector, Reality};
    let file = golden("operations.json");
    let e3 = |v: &serde_json::Value| -> E3 { floats(v).try_into().unwrap() };
    let mut checked = 0;
    for case in file["classify"].as_array().unwrap() {
        let (label, form, p) = (case["kind"].as_str().unwrap(), case["form"].as_str().unwrap(), &case["params"]);
        // Grade 1 reads as a dual sphere or plane; higher dual forms read as the direct
        // object of their grade (a dual circle is a point pair), which is what they are too.
        if form == "dual" && case["grade"] != 1 {
            continue;
        }
        let kind = Multivector::new(floats(&case["mv"]).try_into().unwrap()).classify().unwrap();
        let round = |reality: Reality| match kind {
            Kind::Round { reality: r, centre, radius_squared, .. } => {
                assert_eq!(r, reality, "{label}: {kind:?}");
                let want = if p["centre"].is_null() { &p["point"] } else { &p["centre"] };
                let want = if want.is_null() { &p["x"] } else { want };
                close(centre, e3(want), 1e-12, label);
                let r2 = p["radius_squared"].as_f64().unwrap_or(0.0);
                assert!(
                    (radius_squared - r2).abs() < 1e-12 * r2.abs().max(1.0),
                    "{label}: r² {radius_squared} vs {r2}"
                );
            }
            _ => panic!("{label}: {kind:?}"),
        };
        match label {
            "conformal point" | "origin (eo)" | "tangent vector" | "tangent bivector" => round(Reality::Tangent),
            l if l.starts_with("tangent trivector") => round(Reality::Tangent),
            "real sphere" | "dual real sphere" | "real circle" | "point pair real" => round(Reality::Real),
            "imaginary sphere" | "dual imaginary sphere" | "imaginary circle" | "point pair imaginary" => {
                round(Reality::Imaginary)
            }
            "infinity (einf)" | "free trivector" => {
                assert!(matches!(kind, Kind::Direction { .. }), "{label}: {kind:?}")
            }
            "direction (free vector)" | "free bivector" => match kind {
                Kind::Direction { direction, .. } => {
                    let want = v(e3(if p["normal"].is_null() { &p["direction"] } else { &p["normal"] })).normalize();
                    assert!(v(direction).cross(want).length() < 1e-12, "{label}: {kind:?}");
                }
                _ => panic!("{label}: {kind:?}"),
            },
            "flat point" => {
                assert!(matches!(kind, Kind::FlatPoint(x) if v(x).distance(v(e3(&p["x"]))) < 1e-12), "{kind:?}")
            }
            "line" => match kind {
                Kind::Line { point, direction } => {
                    assert!(v(direction).cross(v(e3(&p["direction"]))).length() < 1e-12);
                    assert!(
                        Line::new(e3(&p["point"]), e3(&p["direction"])).unwrap().distance_to(point).unwrap() < 1e-12
                    );
                }
                _ => panic!("{label}: {kind:?}"),
            },
            "plane" | "dual plane" => match kind {
                Kind::Plane { normal, offset, .. } => {
                    let n = v(e3(&p["normal"]));
                    let s = n.dot(v(normal)).signum(); // an orientation the label does not fix
                    assert!((v(normal) - s * n).length() < 1e-12);
                    assert!((offset - s * n.dot(v(e3(&p["point"])))).abs() < 1e-12, "{label}: {kind:?}");
                }
                _ => panic!("{label}: {kind:?}"),
            },
            other => panic!("unlisted label {other}"),
        }
        checked += 1;
    }
    assert!(checked >= 24, "{checked} classified");
    let mixed =
        Multivector::from(up([1.0, 0.0, 0.0])) + Multivector::from(Line::new([0.0; 3], [1.0, 0.0, 0.0]).unwrap());
    assert_eq!(mixed.classify(), Err(cga_core::GeometryError::NotABlade));
}

#[test]
fn rounds_carry_their_pair_axis_and_circle_normal_anywhere_in_space() {
    use cga_core::{Kind, Reality};
    let mut rng = Rng::new(28);
    for _ in 0..300 {
        // Objects of size s at up to 100 s from the origin: coefficients grow like (|c|/s)²,
        // and so does the rounding of the direction read from them.
        let s = rng.decades(-3.0, 3.0);
        let a = rng.e3(-100.0 * s, 100.0 * s);
        let (u, w) = (rng.direction(), rng.direction());
        if v(u).cross(v(w)).length() < 0.1 {
            continue;
        }
        let (b, c) = (add(a, u.map(|x| s * x)), add(a, w.map(|x| s * x)));
        let tol = 1e-10;
        let pair = up(a) ^ up(b);
        match pair.classify().unwrap() {
            Kind::Round { grade: 2, reality: Reality::Real, direction, .. } => {
                close(direction, (v(b) - v(a)).normalize().into(), tol, "pair axis")
            }
            k => panic!("{k:?}"),
        }
        let circle = up(a) ^ up(b) ^ up(c);
        let normal = (v(b) - v(a)).cross(v(c) - v(a)).normalize();
        match circle.classify().unwrap() {
            Kind::Round { grade: 3, reality: Reality::Real, direction, .. } => {
                close(direction, normal.into(), tol, "circle normal")
            }
            k => panic!("{k:?}"),
        }
        match (-circle).classify().unwrap() {
            Kind::Round { direction, .. } => close(direction, (-normal).into(), tol, "the opposite orientation"),
            k => panic!("{k:?}"),
        }
    }
}

#[test]
fn disjoint_spheres_are_refused_by_name_not_interpolated_through_a_plane() {
    use cga_core::{InterpolationError, Pair};
    let (a, b): (Sphere, Sphere) = (Sphere::new([0.0; 3], 1.0).unwrap(), Sphere::new([10.0, 0.0, 0.0], 2.0).unwrap());
    // Aligned, the duals' weights are 1/r1 and −1/r2: their blend vanishes at
    // α = λ1/(λ1 − λ2) = 1/(1 + 1/2) = 2/3.
    match Pair::new(a, b) {
        Err(InterpolationError::ThroughInfinity { alpha }) => assert!((alpha - 2.0 / 3.0).abs() < 1e-15, "{alpha}"),
        other => panic!("{other:?}"),
    }
    // What it refuses: unchecked, the centre leaves the segment between the two (at α = 0.3 it
    // is at x ≈ −12, radius ≈ 15, as the issue found) and runs off to infinity near 2/3.
    let unchecked = Pair::new_unchecked(a, b).unwrap();
    let (c, _) = unchecked.at(0.3).unwrap().centre_radius().unwrap();
    assert!(c[0] < 0.0, "centre {c:?}");
    let (c, _) = unchecked.at(0.66).unwrap().centre_radius().unwrap();
    assert!(c[0].abs() > 100.0, "centre {c:?}");
    // Overlapping spheres interpolate as before, centres between, radii between.
    let pair = Pair::new(a, Sphere::new([1.5, 0.0, 0.0], 2.0).unwrap()).unwrap();
    for k in 0..=10 {
        let (c, r) = pair.at(k as f64 / 10.0).unwrap().centre_radius().unwrap();
        assert!((0.0..=1.5).contains(&c[0]) && (0.99..=2.01).contains(&r), "centre {c:?}, radius {r}");
    }
}

/// The same meet, points to 1e-15.
fn same_meet(got: Meet, want: Meet) {
    match (got, want) {
        (Meet::Point(x), Meet::Point(y)) => close(x, y, 1e-15, "meet point"),
        (Meet::Points([a, b]), Meet::Points([c, d])) => {
            close(a, c, 1e-15, "first meet point");
            close(b, d, 1e-15, "second meet point");
        }
        (got, want) => assert_eq!(got, want),
    }
}

/// A flat moved by `x ↦ s (M x)` (a motor, then a scaling about the origin).
fn moved_flat(f: &Flat, m: &Motor, s: f64) -> Flat {
    let at = |x: E3| m.move_point(x).map(|c| c * s);
    match f {
        Flat::Point(x) => Flat::Point(at(*x)),
        Flat::Line(l) => {
            Flat::Line(Line::new(at(l.point().unwrap()), m.move_direction(l.direction().unwrap())).unwrap())
        }
        Flat::Plane(p) => {
            let (n, d) = p.normal_offset().unwrap();
            Flat::Plane(Plane::new(at(n.map(|c| c * d)), m.move_direction(n)).unwrap())
        }
    }
}

/// The same flat (and orientation) to `tol` of the positions' scale `size`.
fn same_flat(a: &Flat, b: &Flat, size: f64, tol: f64, what: &str) {
    let dir_close = |x: E3, y: E3| v(x).distance(v(y)) <= tol;
    let ok = match (a, b) {
        (Flat::Point(x), Flat::Point(y)) => distance(*x, *y) <= tol * size,
        (Flat::Line(k), Flat::Line(l)) => {
            dir_close(k.direction().unwrap(), l.direction().unwrap())
                && l.distance_to(k.point().unwrap()).unwrap() <= tol * size
        }
        (Flat::Plane(p), Flat::Plane(q)) => {
            let ((n, d), (m, e)) = (p.normal_offset().unwrap(), q.normal_offset().unwrap());
            dir_close(n, m) && (d - e).abs() <= tol * size
        }
        _ => false,
    };
    assert!(ok, "{what}: {a:?} vs {b:?}");
}

#[test]
fn flats_project_onto_flats_the_same_way_anywhere_and_the_image_lies_in_the_target() {
    let mut rng = Rng::new(24);
    let mut dimensions = [[0usize; 3]; 3];
    for case in 0..600 {
        let p = rng.e3(-3.0, 3.0);
        let d = rng.direction();
        // Targets: a line or a plane; sources: a point, a line or a plane, a third of them
        // exactly perpendicular or parallel to the target's direction.
        let t_dir = rng.direction();
        let pick = |rng: &mut Rng, n: f64| (rng.unit() * n) as usize;
        let target = if pick(&mut rng, 2.0) == 0 {
            Flat::Line(Line::new(rng.e3(-2.0, 2.0), t_dir).unwrap())
        } else {
            Flat::Plane(Plane::new(rng.e3(-2.0, 2.0), t_dir).unwrap())
        };
        let d = match pick(&mut rng, 3.0) {
            0 => d,
            1 => t_dir,
            _ => v(t_dir).cross(v(d)).normalize().to_array(),
        };
        let source = match pick(&mut rng, 3.0) {
            0 => Flat::Point(p),
            1 => Flat::Line(Line::new(p, d).unwrap()),
            _ => Flat::Plane(Plane::new(p, d).unwrap()),
        };
        let image = source.project_onto(&target).unwrap();
        dimensions[source.dimension()][image.dimension()] += 1;
        assert!(image.dimension() <= source.dimension().min(target.dimension()), "case {case}: {image:?}");
        // In the target, and a projection: projecting the image again changes nothing.
        same_flat(&image.project_onto(&target).unwrap(), &image, 10.0, 1e-13, "idempotent");
        let inside = match image {
            Flat::Point(x) => x,
            Flat::Line(l) => l.point().unwrap(),
            Flat::Plane(q) => q.normal_offset().map(|(n, d)| n.map(|c| c * d)).unwrap(),
        };
        let on_target = match target {
            Flat::Line(l) => l.distance_to(inside).unwrap(),
            Flat::Plane(q) => q.signed_distance(inside).unwrap().abs(),
            Flat::Point(_) => unreachable!(),
        };
        assert!(on_target < 1e-14 * 10.0, "case {case}: the image is off the target by {on_target:e}");
        // Moved up to 1e3 away and scaled by 1e-3 … 1e3: the image moved the same way.
        let (m, s) = (random_motor(&mut rng, 1e3), rng.decades(-3.0, 3.0));
        let far = moved_flat(&source, &m, s).project_onto(&moved_flat(&target, &m, s)).unwrap();
        same_flat(&far, &moved_flat(&image, &m, s), s * (1e3 + 10.0), 1e-13, "moved and scaled");
    }
    // Every relation was reached: point → point; line → point, line; plane → point, line, plane.
    assert!(
        dimensions[1][0] > 0 && dimensions[2][0] > 0 && dimensions[2][1] > 0 && dimensions[2][2] > 0,
        "{dimensions:?}"
    );
}

/// A random point of the flat, within about `r` of its own point.
fn point_on(f: &Flat, rng: &mut Rng, r: f64) -> E3 {
    match f {
        Flat::Point(x) => *x,
        Flat::Line(l) => {
            let t = rng.range(-r, r);
            add(l.point().unwrap(), l.direction().unwrap().map(|c| c * t))
        }
        Flat::Plane(p) => {
            let ((n, d), t) = (p.normal_offset().unwrap(), rng.range(-r, r));
            let along = v(rng.direction()).reject_from(v(n)).to_array();
            add(n.map(|c| c * d), along.map(|c| c * t))
        }
    }
}

#[test]
fn flats_split_into_projection_and_rejection_the_same_way_anywhere() {
    let mut rng = Rng::new(25);
    let mut dimensions = [[0usize; 3]; 3];
    for case in 0..600 {
        let (p, t_dir) = (rng.e3(-3.0, 3.0), rng.direction());
        let pick = |rng: &mut Rng, n: f64| (rng.unit() * n) as usize;
        let target = match pick(&mut rng, 3.0) {
            0 => Flat::Point(rng.e3(-2.0, 2.0)),
            1 => Flat::Line(Line::new(rng.e3(-2.0, 2.0), t_dir).unwrap()),
            _ => Flat::Plane(Plane::new(rng.e3(-2.0, 2.0), t_dir).unwrap()),
        };
        // A third of the sources exactly along or across the target's direction.
        let d = match pick(&mut rng, 3.0) {
            0 => rng.direction(),
            1 => t_dir,
            _ => v(t_dir).cross(v(rng.direction())).normalize().to_array(),
        };
        let source = match pick(&mut rng, 3.0) {
            0 => Flat::Point(p),
            1 => Flat::Line(Line::new(p, d).unwrap()),
            _ => Flat::Plane(Plane::new(p, d).unwrap()),
        };
        let rejection = source.reject_from(&target).unwrap();
        dimensions[source.dimension()][rejection.dimension()] += 1;
        // Every point x of the source is P(x) + R(x): x − P(x) lies on the rejection, and
        // the rejection is perpendicular to the target's directions.
        for _ in 0..4 {
            let x = point_on(&source, &mut rng, 5.0);
            let Flat::Point(foot) = Flat::Point(x).project_onto(&target).unwrap() else { panic!("a point's image") };
            let offset = (v(x) - v(foot)).to_array();
            let Flat::Point(on) = Flat::Point(offset).project_onto(&rejection).unwrap() else { panic!("a point") };
            assert!(distance(on, offset) <= 1e-14 * 20.0, "case {case}: x − P(x) is {:e} off", distance(on, offset));
            let r = point_on(&rejection, &mut rng, 5.0);
            let across = match target {
                Flat::Point(_) => 0.0,
                Flat::Line(_) => v(r).dot(v(t_dir)).abs(),
                Flat::Plane(_) => v(r).cross(v(t_dir)).length(),
            };
            assert!(
                across <= 1e-14 * 20.0,
                "case {case}: the rejection reaches along the target by {across:e}: {rejection:?}"
            );
        }
        // Moved up to 1e3 away and scaled by 1e-3 … 1e3: the rejection, a set of offsets, is
        // rotated and scaled, not moved.
        let (m, s) = (random_motor(&mut rng, 1e3), rng.decades(-3.0, 3.0));
        let far = moved_flat(&source, &m, s).reject_from(&moved_flat(&target, &m, s)).unwrap();
        let turned = Motor::from_rotor_translation(m.rotor(), [0.0; 3]);
        same_flat(&far, &moved_flat(&rejection, &turned, s), s * (1e3 + 10.0), 1e-13, "moved and scaled");
    }
    // Point → point; line → point, line; plane → point, line, plane.
    assert!(
        [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2)].iter().all(|&(a, b)| dimensions[a][b] > 0),
        "{dimensions:?}"
    );
}

#[test]
fn point_pairs_meet_objects_in_their_points_on_them_the_same_way_anywhere() {
    let mut rng = Rng::new(2024);
    for case in 0..400 {
        let (m, s) = (random_motor(&mut rng, 1e3), rng.decades(-3.0, 3.0));
        let at = |x: E3| m.move_point(x).map(|c| c * s);
        let (c, r) = (rng.e3(-2.0, 2.0), rng.range(0.5, 2.0));
        let on = add(c, rng.direction().map(|x| x * r));
        let off = add(c, rng.direction().map(|x| x * r * rng.range(1.1, 2.0)));
        let (sphere, far_sphere) = (Sphere::new(c, r).unwrap(), Sphere::new(at(c), s * r).unwrap());
        let (pair, far_pair) = match case % 3 {
            0 => ([on, off], Meet::Point(on)),
            1 => ([off, on], Meet::Point(on)),
            _ => ([off, add(off, [0.0, 0.0, 3.0 * r])], Meet::Miss),
        };
        let got = Bivector::from_points(pair[0], pair[1]).unwrap().intersect(&sphere).unwrap();
        let far = Bivector::from_points(at(pair[0]), at(pair[1])).unwrap().intersect(&far_sphere).unwrap();
        match (got, far, far_pair) {
            (Meet::Point(x), Meet::Point(y), Meet::Point(w)) => {
                close(x, w, 1e-14, "near");
                // The pair's ends 1e3 away are good to ε ρ² r (ρ up to 1e3/r).
                assert!(distance(y, at(w)) <= 1e-9 * s, "case {case}: {y:?} vs {:?}", at(w));
            }
            (Meet::Miss, Meet::Miss, Meet::Miss) => {}
            other => panic!("case {case}: near, far and wanted meets differ: {other:?}"),
        }
    }
    // An imaginary pair (a line missing a sphere) has no points; a pair meets a plane, a
    // line, a circle, another pair and a point in the points it shares with them.
    let unit = Sphere::new([0.0; 3], 1.0).unwrap();
    let missing = Line::new([0.0, 2.0, 0.0], [1.0, 0.0, 0.0]).unwrap() & unit;
    assert_eq!(missing.intersect(&unit).unwrap(), Meet::Miss);
    let pair = Bivector::from_points([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
    let floor = Plane::new([0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    same_meet(pair.intersect(&floor).unwrap(), Meet::Point([1.0, 0.0, 0.0]));
    same_meet(pair.intersect(&unit).unwrap(), Meet::Points([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]));
    let ring = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0).unwrap();
    same_meet(pair.intersect(&ring).unwrap(), Meet::Point([1.0, 0.0, 0.0]));
    let z = Line::new([0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    same_meet(pair.intersect(&z).unwrap(), Meet::Point([0.0, 0.0, 1.0]));
    let other = Bivector::from_points([0.0, 0.0, 1.0], [5.0, 5.0, 5.0]).unwrap();
    same_meet(pair.intersect(&other).unwrap(), Meet::Point([0.0, 0.0, 1.0]));
    same_meet(pair.intersect(&up([0.0, 0.0, 1.0])).unwrap(), Meet::Point([0.0, 0.0, 1.0]));
    // Two lines: crossing, parallel, skew, the same.
    let x = Line::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
    assert_eq!(x.intersect_line(&z).unwrap(), Meet::Point([0.0, 0.0, 1.0]));
    assert_eq!(x.intersect_line(&Line::new([0.0, 1.0, 1.0], [-1.0, 0.0, 0.0]).unwrap()).unwrap(), Meet::Miss);
    assert_eq!(x.intersect_line(&Line::new([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap()).unwrap(), Meet::Miss);
    assert_eq!(x.intersect_line(&Line::new([7.0, 0.0, 1.0], [-1.0, 0.0, 0.0]).unwrap()).unwrap(), Meet::Contained);
}
