//! A klein user's first program with `cga_algebras::pga`, written from docs/PGA.md, the
//! `pga` module's rustdoc and docs/LIBRARY.md alone. Every expected value is Euclidean
//! geometry worked out by hand here (rotations by their matrices, distances by Pythagoras),
//! never the library's own output. Each test names the klein call it stands for.

use cga_algebras::pga::PgaError;
use cga_algebras::pga::prelude::*;
// The prelude's names are f64 aliases: code generic over lanes names the generic structs.
use cga_algebras::pga as gx;
use cga_core::simd::{F64x4, F64x8, Kernel, Lane, map, run, run_columns, splat};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, FRAC_PI_4, PI};

const EPS: f64 = 1e-12;

fn close3(got: [f64; 3], want: [f64; 3]) -> bool {
    got.iter().zip(want).all(|(g, w)| (g - w).abs() < EPS)
}

#[track_caller]
fn assert_at(p: Point, want: [f64; 3]) {
    let got = p.position().expect("a finite point");
    assert!(close3(got, want), "got {got:?}, want {want:?}");
}

/// A rotation about the unit axis `a` by `θ`, by Rodrigues' formula: what the motor must do.
fn rodrigues(a: [f64; 3], theta: f64, v: [f64; 3]) -> [f64; 3] {
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let a = a.map(|c| c / n);
    let (s, c) = theta.sin_cos();
    let dot = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    let cross = [a[1] * v[2] - a[2] * v[1], a[2] * v[0] - a[0] * v[2], a[0] * v[1] - a[1] * v[0]];
    std::array::from_fn(|i| v[i] * c + cross[i] * s + a[i] * dot * (1.0 - c))
}

// kln::point(x, y, z), kln::plane(a, b, c, d), kln::direction.
#[test]
fn points_and_planes_read_back() {
    let p = Point::at([1.0, -2.0, 3.5]);
    assert_at(p, [1.0, -2.0, 3.5]);
    // klein's layout: e123 the weight, e032, e013, e021 the position.
    assert_eq!((p.e123, p.e032, p.e013, p.e021), (1.0, 1.0, -2.0, 3.5));
    // A point of weight 2 is the same point.
    assert_at(Point::at_weight([1.0, -2.0, 3.5], 2.0), [1.0, -2.0, 3.5]);
    // A direction (kln::direction) has no position.
    assert_eq!(Point::ideal([0.0, 0.0, 1.0]).position(), None);
    assert_eq!(Point::ideal([0.0, 0.0, 1.0]).try_position(), Err(PgaError::IdealPoint));

    // The plane 3x + 4z = 10: unit normal (0.6, 0, 0.8), distance 2 from the origin.
    let plane = Plane::from_normal_distance([3.0, 0.0, 4.0], 2.0).unwrap();
    let (n, d) = plane.normal_distance().unwrap();
    assert!(close3(n, [0.6, 0.0, 0.8]) && (d - 2.0).abs() < EPS);
    // Plane::new(a, b, c, d) is a x + b y + c z + d = 0, klein's kln::plane(a, b, c, d).
    let same = Plane::new(0.6, 0.0, 0.8, -2.0);
    assert!((plane - same).to_array().iter().all(|c| c.abs() < EPS));
    assert_eq!(Plane::from_normal_distance([0.0; 3], 1.0), Err(PgaError::ZeroVector));
}

// kln::rotor(angle, x, y, z), m(p).
#[test]
fn rotors_turn_points_as_rodrigues_says() {
    // A quarter turn about +z takes x to y (right-handed).
    let quarter = Motor::rotor([0.0, 0.0, 1.0], FRAC_PI_2).unwrap();
    assert_at(quarter.apply(Point::at([1.0, 0.0, 0.0])), [0.0, 1.0, 0.0]);
    // A third of a turn about (1, 1, 1) cycles the axes: x → y → z → x.
    let third = Motor::rotor([1.0, 1.0, 1.0], 2.0 * FRAC_PI_3).unwrap();
    assert_at(third.apply(Point::at([1.0, 0.0, 0.0])), [0.0, 1.0, 0.0]);
    assert_at(third.apply(Point::at([0.0, 0.0, 2.0])), [2.0, 0.0, 0.0]);
    // Any axis and point, against Rodrigues' formula.
    for (axis, theta, v) in [
        ([0.3, -1.2, 0.5], 0.7, [1.0, 2.0, 3.0]),
        ([-2.0, 0.1, 0.4], -2.9, [-0.5, 4.0, 1.5]),
        ([0.0, 1.0, 0.0], PI, [1.0, 7.0, 0.0]),
    ] {
        let m = Motor::rotor(axis, theta).unwrap();
        assert_at(m.apply(Point::at(v)), rodrigues(axis, theta, v));
        // m(p) and the sandwich M P M̃ are one call.
        assert_eq!(m.apply(Point::at(v)), m.sandwich(Point::at(v)));
    }
    assert_eq!(Motor::rotor([0.0; 3], 1.0), Err(PgaError::ZeroVector));
}

// kln::translator(dist, x, y, z), and a translation of planes and lines too.
#[test]
fn translators_move_points_planes_and_lines() {
    let t = Motor::translator([1.0, -2.0, 0.5]).unwrap();
    assert_at(t.apply(Point::at([0.0, 0.0, 0.0])), [1.0, -2.0, 0.5]);
    assert_at(t.apply(Point::at([3.0, 3.0, 3.0])), [4.0, 1.0, 3.5]);
    // The floor z = 0 shifted up by 0.5 is z = 0.5, its normal kept.
    let floor = Plane::from_normal_distance([0.0, 0.0, 1.0], 0.0).unwrap();
    let (n, d) = t.apply(floor).normal_distance().unwrap();
    assert!(close3(n, [0.0, 0.0, 1.0]) && (d - 0.5).abs() < EPS);
    // The z axis shifted by (1, −2, ·) is the vertical line through (1, −2, 0).
    let z_axis = Line::through([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
    let (p, dir) = t.apply(z_axis).point_direction().unwrap();
    assert!(close3(p, [1.0, -2.0, 0.0]) && close3(dir, [0.0, 0.0, 1.0]));
}

// t * r (kln::motor), and composition in both orders.
#[test]
fn composed_motors_apply_right_to_left() {
    let r = Motor::rotor([0.0, 0.0, 1.0], FRAC_PI_2).unwrap();
    let t = Motor::translator([2.0, 0.0, 0.0]).unwrap();
    let x = Point::at([1.0, 0.0, 0.0]);
    // Turn first ((1,0,0) → (0,1,0)), then shift: (2, 1, 0).
    let turn_then_shift = Motor::from_rotor_translator(r, t);
    assert_at(turn_then_shift.apply(x), [2.0, 1.0, 0.0]);
    assert_at(r.then(t).apply(x), [2.0, 1.0, 0.0]);
    assert_at((t * r).apply(x), [2.0, 1.0, 0.0]); // klein's t * r
    // Shift first ((1,0,0) → (3,0,0)), then turn: (0, 3, 0).
    assert_at(t.then(r).apply(x), [0.0, 3.0, 0.0]);
    assert_at((r * t).apply(x), [0.0, 3.0, 0.0]);
    // The motor's parts come back: the turn and the shift it was given.
    let (rot, shift) = turn_then_shift.rotor_translation().unwrap();
    assert!(close3(shift, [2.0, 0.0, 0.0]));
    assert_at(rot.apply(x), [0.0, 1.0, 0.0]);
    // The reverse undoes it (a unit motor's inverse).
    assert_at(turn_then_shift.reverse().apply(Point::at([2.0, 1.0, 0.0])), [1.0, 0.0, 0.0]);
}

// kln::log, kln::exp, kln::sqrt, and powers.
#[test]
fn log_exp_sqrt_and_pow_of_a_screw() {
    // Half a turn about the vertical line through (1, 0, 0), sliding 2 along +z.
    let axis = Line::through([1.0, 0.0, 0.0], [1.0, 0.0, 1.0]).unwrap();
    let screw = Motor::screw(axis, PI, 2.0).unwrap();
    // The origin: half a turn about (1, 0) in the xy plane is (2, 0), then up 2.
    assert_at(screw.apply(Point::at([0.0; 3])), [2.0, 0.0, 2.0]);
    // log then exp is the same motion.
    let generator = screw.log().unwrap();
    let back = generator.exp_motor().unwrap();
    for v in [[0.0; 3], [1.0, 2.0, 3.0], [-4.0, 0.5, 1.0]] {
        let want = screw.apply(Point::at(v)).position().unwrap();
        assert_at(back.apply(Point::at(v)), want);
    }
    // The square root is the quarter turn, 1 up: the origin goes to (1, −1, 1).
    let half = screw.sqrt().unwrap();
    assert_at(half.apply(Point::at([0.0; 3])), [1.0, -1.0, 1.0]);
    // A third of it: a sixth of a turn (60°) and 2/3 up. Relative to the axis the origin
    // is (−1, 0), turned by 60° to (−cos 60°, −sin 60°).
    let third = screw.pow(1.0 / 3.0).unwrap();
    let (s, c) = FRAC_PI_3.sin_cos();
    assert_at(third.apply(Point::at([0.0; 3])), [1.0 - c, -s, 2.0 / 3.0]);
    // The square root of a translation is half the translation.
    let t = Motor::translator([4.0, -2.0, 6.0]).unwrap();
    assert_at(t.sqrt().unwrap().apply(Point::at([0.0; 3])), [2.0, -1.0, 3.0]);
    // −1 (a full turn) has no principal log or square root.
    let minus_one = Motor::identity() * -1.0;
    assert_eq!(minus_one.log(), Err(PgaError::FullTurn));
    assert_eq!(minus_one.sqrt(), Err(PgaError::FullTurn));
}

// kln::exp(t * kln::log(b * ~a)) * a.
#[test]
fn interpolating_two_motors_lands_halfway() {
    // Two turns about z: 30° and 90°; halfway is 60°.
    let a = Motor::rotor([0.0, 0.0, 1.0], PI / 6.0).unwrap();
    let b = Motor::rotor([0.0, 0.0, 1.0], FRAC_PI_2).unwrap();
    let mid = Motor::interpolate(&a, &b, 0.5).unwrap();
    let (s, c) = FRAC_PI_3.sin_cos();
    assert_at(mid.apply(Point::at([1.0, 0.0, 0.0])), [c, s, 0.0]);
    // The ends are the motors themselves.
    assert_at(Motor::interpolate(&a, &b, 0.0).unwrap().apply(Point::at([1.0, 0.0, 0.0])), [(PI / 6.0).cos(), 0.5, 0.0]);
    assert_at(Motor::interpolate(&a, &b, 1.0).unwrap().apply(Point::at([1.0, 0.0, 0.0])), [0.0, 1.0, 0.0]);
    // Two translations: halfway between (2, 0, 0) and (4, 2, 0) is (3, 1, 0).
    let ta = Motor::translator([2.0, 0.0, 0.0]).unwrap();
    let tb = Motor::translator([4.0, 2.0, 0.0]).unwrap();
    assert_at(Motor::interpolate(&ta, &tb, 0.5).unwrap().apply(Point::at([0.0; 3])), [3.0, 1.0, 0.0]);
    // From the identity to a quarter turn about the vertical line through (1, 1, 0): the
    // origin is at (−1, −1) from the axis; an eighth of a turn takes it to (0, −√2).
    let axis = Line::from_point_direction([1.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap();
    let quarter = Motor::screw(axis, FRAC_PI_2, 0.0).unwrap();
    let mid = Motor::interpolate(&Motor::identity(), &quarter, 0.5).unwrap();
    assert_at(mid.apply(Point::at([0.0; 3])), [1.0, 1.0 - 2f64.sqrt(), 0.0]);
    // And a quarter turn's quarter: 22.5°, about (1, 1).
    let q = Motor::interpolate(&Motor::identity(), &quarter, 0.25).unwrap();
    // (−1, −1) from the axis is at 225°; turned by 22.5° it is at 247.5°, √2 away.
    let (s2, c2) = (5.0 * FRAC_PI_4 + FRAC_PI_4 / 2.0).sin_cos();
    let want = [1.0 + 2f64.sqrt() * c2, 1.0 + 2f64.sqrt() * s2, 0.0];
    assert_at(q.apply(Point::at([0.0; 3])), want);
}

// m.normalize().
#[test]
fn renormalise_repairs_a_scaled_and_drifted_motor() {
    let m = Motor::from_rotor_translator(
        Motor::rotor([1.0, 0.0, 0.0], 0.8).unwrap(),
        Motor::translator([0.0, 1.0, 2.0]).unwrap(),
    );
    let (a, b) = (Point::at([1.0, 2.0, 3.0]), Point::at([-2.0, 0.5, 4.0]));
    let d = a.distance_to_point(b).unwrap();
    // Scaled by 3: the same motion once renormalised, M M̃ = 1.
    let fixed = (m * 3.0).renormalise().unwrap();
    assert_at(fixed.apply(a), m.apply(a).position().unwrap());
    let mm = fixed * fixed.reverse();
    assert!((mm.s - 1.0).abs() < EPS && mm.e0123.abs() < EPS);
    // Pushed off the Study condition by a grade-4 part: renormalised, M M̃ = 1 again and
    // the motion rigid (distances kept), close to the motion it drifted from.
    let mut bad = m * 3.0;
    bad.e0123 += 0.05;
    let dist =
        |p: [f64; 3], q: [f64; 3]| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
    let fixed = bad.renormalise().unwrap();
    let mm = fixed * fixed.reverse();
    assert!((mm.s - 1.0).abs() < EPS && mm.e0123.abs() < EPS);
    let (fa, fb) = (fixed.apply(a).position().unwrap(), fixed.apply(b).position().unwrap());
    assert!((dist(fa, fb) - d).abs() < EPS);
    // It stays close to the motion it drifted from.
    assert!(dist(fa, m.apply(a).position().unwrap()) < 0.1);
}

// p1 & p2 (join), pl1 ^ pl2 (meet).
#[test]
fn joins_and_meets() {
    let (p, q) = (Point::at([1.0, 2.0, 3.0]), Point::at([4.0, 6.0, 3.0]));
    let line = p & q;
    // Direction q − p, moment p × q (Plücker).
    assert!(close3(line.direction(), [3.0, 4.0, 0.0]));
    assert!(close3(line.moment(), [2.0 * 3.0 - 3.0 * 6.0, 3.0 * 4.0 - 1.0 * 3.0, 1.0 * 6.0 - 2.0 * 4.0]));
    assert_eq!(Line::through([1.0, 2.0, 3.0], [4.0, 6.0, 3.0]).unwrap(), line);
    assert_eq!(Line::through([1.0; 3], [1.0; 3]), Err(PgaError::CoincidentPoints));
    // The plane through (1,0,0), (0,1,0), (0,0,1): x + y + z = 1, normal (b−a)×(c−a) = (1,1,1).
    let plane = (Point::at([1.0, 0.0, 0.0]) & Point::at([0.0, 1.0, 0.0])) & Point::at([0.0, 0.0, 1.0]);
    let (n, d) = plane.normal_distance().unwrap();
    let k = 1.0 / 3f64.sqrt();
    assert!(close3(n, [k, k, k]) && (d - k).abs() < EPS);
    let (n2, _) = Plane::through([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).unwrap().normal_distance().unwrap();
    assert!(close3(n2, [k, k, k]));
    // The planes x = 1 and y = 2 meet in the vertical line through (1, 2, 0), along n₁ × n₂ = +z.
    let x1 = Plane::from_normal_distance([1.0, 0.0, 0.0], 1.0).unwrap();
    let y2 = Plane::from_normal_distance([0.0, 1.0, 0.0], 2.0).unwrap();
    let z3 = Plane::from_normal_distance([0.0, 0.0, 1.0], 3.0).unwrap();
    let (on, dir) = (x1 ^ y2).point_direction().unwrap();
    assert!(close3(on, [1.0, 2.0, 0.0]) && close3(dir, [0.0, 0.0, 1.0]));
    // Three planes meet in a point; a line meets a plane in a point.
    assert_at(x1 ^ y2 ^ z3, [1.0, 2.0, 3.0]);
    let vertical = Point::at([1.0, 2.0, 0.0]) & Point::at([1.0, 2.0, 5.0]);
    assert_at(vertical ^ z3, [1.0, 2.0, 3.0]);
    // The slanted line from (0, 0, 0) to (2, 4, 6) crosses z = 3 halfway, at (1, 2, 3).
    assert_at(Line::through([0.0; 3], [2.0, 4.0, 6.0]).unwrap() ^ z3, [1.0, 2.0, 3.0]);
}

// (a & b).norm(), plane & point, and the distances klein leaves to the user.
#[test]
fn distances() {
    let o = Point::at([1.0, 1.0, 1.0]);
    assert!((o.distance_to_point(Point::at([4.0, 5.0, 1.0])).unwrap() - 5.0).abs() < EPS);
    // The plane z = 2, normal +z: (1, 1, 5) is 3 above it, (1, 1, −1) 3 below.
    let z2 = Plane::from_normal_distance([0.0, 0.0, 1.0], 2.0).unwrap();
    assert!((Point::at([1.0, 1.0, 5.0]).distance_to_plane(z2).unwrap() - 3.0).abs() < EPS);
    assert!((Point::at([1.0, 1.0, -1.0]).distance_to_plane(z2).unwrap() + 3.0).abs() < EPS);
    // The regressive product gives it as a Scalar: p & P = +dist, P & p = −dist (klein's
    // plane & point is −dist, docs/PGA.md).
    let above = Point::at([1.0, 1.0, 5.0]);
    assert!(((z2 & above).s - 3.0).abs() < EPS);
    assert!(((above & z2).s + 3.0).abs() < EPS);
    // (3, 4, 7) is 5 from the z axis; the x axis and the y-parallel line at height 2 are 2 apart.
    let z_axis = Line::through([0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    assert!((Point::at([3.0, 4.0, 7.0]).distance_to_line(z_axis).unwrap() - 5.0).abs() < EPS);
    let x_axis = Line::from_point_direction([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    let high = Line::from_point_direction([0.0, 0.0, 2.0], [0.0, 1.0, 0.0]).unwrap();
    assert!((x_axis.distance_to_line(high).unwrap() - 2.0).abs() < EPS);
    // Parallel lines 3 apart.
    let parallel = Line::from_point_direction([0.0, 3.0, 0.0], [2.0, 0.0, 0.0]).unwrap();
    assert!((x_axis.distance_to_line(parallel).unwrap() - 3.0).abs() < EPS);
    // Angles: the x axis and the line along (1, 1, 0) are 45° apart.
    let diagonal = Line::from_point_direction([0.0; 3], [1.0, 1.0, 0.0]).unwrap();
    assert!((x_axis.angle_to_line(diagonal).unwrap() - FRAC_PI_4).abs() < EPS);
}

// kln::project(a, p), kln::project(l, p), kln::project(l, a), kln::project(p, a).
#[test]
fn projections() {
    let x = Point::at([1.0, 2.0, 3.0]);
    let floor = Plane::from_normal_distance([0.0, 0.0, 1.0], 0.0).unwrap();
    assert_at(x.project_onto_plane(floor), [1.0, 2.0, 0.0]);
    // Onto the slanted plane x + y = 0 (normal (1,1,0)/√2): x − ((x·n)) n = (−0.5, 0.5, 3).
    let slant = Plane::from_normal_distance([1.0, 1.0, 0.0], 0.0).unwrap();
    assert_at(x.project_onto_plane(slant), [-0.5, 0.5, 3.0]);
    let x_axis = Line::from_point_direction([0.0; 3], [1.0, 0.0, 0.0]).unwrap();
    assert_at(x.project_onto_line(x_axis), [1.0, 0.0, 0.0]);
    // A slope projected onto the floor: its shadow runs along x through the origin.
    let slope = Line::from_point_direction([0.0, 0.0, 2.0], [1.0, 0.0, 1.0]).unwrap();
    let (p, d) = slope.project_onto_plane(floor).point_direction().unwrap();
    assert!(close3(p, [0.0, 0.0, 0.0]) && close3(d, [1.0, 0.0, 0.0]));
    // The x axis moved parallel through (1, 2, 3).
    let (p, d) = x_axis.project_onto_point(x).point_direction().unwrap();
    assert!(close3(p, [0.0, 2.0, 3.0]) && close3(d, [1.0, 0.0, 0.0]));
    // The floor moved parallel through (1, 2, 3): z = 3.
    let (n, dist) = floor.project_onto_point(x).normal_distance().unwrap();
    assert!(close3(n, [0.0, 0.0, 1.0]) && (dist - 3.0).abs() < EPS);
}

fn cloud(n: usize) -> Vec<Point> {
    (0..n).map(|k| Point::at([k as f64 * 0.5, 1.0 - k as f64, (k % 3) as f64])).collect()
}

// Moving many points: klein's `m(points, out, count)`.
#[test]
fn batch_move_with_a_prepared_motor() {
    let m = Motor::from_rotor_translator(
        Motor::rotor([0.0, 0.0, 1.0], FRAC_PI_2).unwrap(),
        Motor::translator([10.0, 0.0, -1.0]).unwrap(),
    );
    let points = cloud(37);
    let prepared = m.prepare();
    let moved = prepared.apply_to(&points);
    let again = m.apply_to(&points);
    assert_eq!(moved.len(), points.len());
    let mut into = vec![Point::zero(); points.len()];
    prepared.apply_into(&points, &mut into);
    for (k, x) in points.iter().enumerate() {
        // A quarter turn about z: (x, y, z) → (−y, x, z), then (+10, 0, −1).
        let [a, b, c] = x.position().unwrap();
        let want = [10.0 - b, a, c - 1.0];
        assert_at(moved[k], want);
        assert_at(again[k], want);
        assert_at(into[k], want);
        assert_at(prepared.apply(*x), want);
    }
}

struct Join;
impl Kernel for Join {
    type Input = (Point, Point);
    type Output = Line;
    #[inline(always)]
    fn apply<L: Lane>(&self, (p, q): (gx::Point<L>, gx::Point<L>)) -> gx::Line<L> {
        p & q
    }
}

struct MoveBy(Motor);
impl Kernel for MoveBy {
    type Input = Point;
    type Output = Point;
    #[inline(always)]
    fn apply<L: Lane>(&self, p: gx::Point<L>) -> gx::Point<L> {
        splat::<Motor, L>(self.0).apply(p)
    }
}

// Batches through cga_core::simd with PGA types.
#[test]
fn batch_through_simd() {
    let points = cloud(23);
    let others: Vec<Point> = points.iter().map(|p| Point::at(p.position().unwrap().map(|c| c + 1.0))).collect();
    // Joins: each line's direction is q − p = (1, 1, 1).
    let pairs: Vec<(Point, Point)> = points.iter().copied().zip(others.iter().copied()).collect();
    let mut lines = vec![Line::zero(); pairs.len()];
    run(&Join, &pairs, &mut lines).unwrap();
    for (k, l) in lines.iter().enumerate() {
        assert!(close3(l.direction(), [1.0; 3]));
        assert_eq!(*l, points[k] & others[k]);
    }
    let mut by_columns = vec![Line::zero(); pairs.len()];
    run_columns(&Join, (&points[..], &others[..]), &mut by_columns).unwrap();
    assert_eq!(by_columns, lines);
    let mut mapped = vec![Line::zero(); pairs.len()];
    map(
        &pairs,
        &mut mapped,
        #[inline(always)]
        |(p, q): (gx::Point<F64x4>, gx::Point<F64x4>)| p & q,
    )
    .unwrap();
    assert_eq!(mapped, lines);
    // Mismatched lengths: None, nothing written.
    assert_eq!(run(&Join, &pairs[1..], &mut lines), None);

    // Moving: a half turn about x, (x, y, z) → (x, −y, −z).
    let m = Motor::rotor([1.0, 0.0, 0.0], PI).unwrap();
    let mut moved = vec![Point::zero(); points.len()];
    run(&MoveBy(m), &points, &mut moved).unwrap();
    let lanes = splat::<Motor, F64x8>(m);
    let mut mapped = vec![Point::zero(); points.len()];
    map(
        &points,
        &mut mapped,
        #[inline(always)]
        |p: gx::Point<F64x8>| lanes.sandwich(p),
    )
    .unwrap();
    for (k, x) in points.iter().enumerate() {
        let [a, b, c] = x.position().unwrap();
        assert_at(moved[k], [a, -b, -c]);
        assert_eq!(moved[k], m.apply(*x)); // the bits of one at a time
        assert_eq!(mapped[k], m.sandwich(*x));
    }
}
