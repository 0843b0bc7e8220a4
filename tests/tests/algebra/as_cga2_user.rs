//! A 2D conformal user's first program with `cga_algebras::cga2`, written from docs/PGA.md's
//! "2D CGA and STA" table and the `cga2` module's rustdoc alone. Expected values are plane
//! geometry worked out by hand here (circumcentres, rotations, chords), not the library's.

use cga_algebras::cga2::Cga2Error;
use cga_algebras::cga2::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

const EPS: f64 = 1e-12;

#[track_caller]
fn assert_near(got: [f64; 2], want: [f64; 2]) {
    assert!((got[0] - want[0]).abs() < EPS && (got[1] - want[1]).abs() < EPS, "got {got:?}, want {want:?}");
}

/// The two points, in either order, against the two expected.
#[track_caller]
fn assert_pair(got: [[f64; 2]; 2], want: [[f64; 2]; 2]) {
    let d = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs().max((a[1] - b[1]).abs());
    let straight = d(got[0], want[0]).max(d(got[1], want[1]));
    let crossed = d(got[0], want[1]).max(d(got[1], want[0]));
    assert!(straight.min(crossed) < EPS, "got {got:?}, want {want:?}");
}

#[test]
fn up_and_down() {
    let x = Vector::up([3.0, -4.0]);
    // x + ½x² ei + eo.
    assert_eq!((x.e1, x.e2, x.ei, x.eo), (3.0, -4.0, 12.5, 1.0));
    // A conformal point is null: X · X = 0.
    assert!((x | x).s.abs() < EPS);
    // −2 X · Y is the squared distance: (3, −4) to (0, 0) is 25.
    assert!((-2.0 * (x | Vector::up([0.0, 0.0])).s - 25.0).abs() < EPS);
    assert_near(x.down().unwrap(), [3.0, -4.0]);
    // Scaled points come down to the same place.
    assert_near((x * 2.5).down().unwrap(), [3.0, -4.0]);
}

#[test]
fn circle_through_three_points() {
    // The unit circle.
    let unit = Circle::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]).unwrap();
    let (c, r) = unit.centre_radius().unwrap();
    assert_near(c, [0.0, 0.0]);
    assert!((r - 1.0).abs() < EPS);
    assert!(!unit.is_line());
    // A right angle at the origin: the hypotenuse (4, 0)–(0, 2) is a diameter, so the
    // centre is its midpoint (2, 1) and the radius half its length, √5.
    let (c, r) = Circle::through([0.0, 0.0], [4.0, 0.0], [0.0, 2.0]).unwrap().centre_radius().unwrap();
    assert_near(c, [2.0, 1.0]);
    assert!((r - 5f64.sqrt()).abs() < EPS);
    // A point lies on the circle when X ∧ C = 0: (2 + √5, 1) does, (2, 1) does not.
    let on = Vector::up([2.0 + 5f64.sqrt(), 1.0]) ^ Circle::through([0.0, 0.0], [4.0, 0.0], [0.0, 2.0]).unwrap();
    assert!(on.to_array().iter().all(|c| c.abs() < 1e-11), "{on:?}");
    let off = Vector::up([2.0, 1.0]) ^ Circle::through([0.0, 0.0], [4.0, 0.0], [0.0, 2.0]).unwrap();
    assert!(off.to_array().iter().any(|c| c.abs() > 0.1));
    // The raw wedge is the same circle.
    let wedge = Vector::up([1.0, 0.0]) ^ Vector::up([0.0, 1.0]) ^ Vector::up([-1.0, 0.0]);
    let (c, r) = wedge.centre_radius().unwrap();
    assert_near(c, [0.0, 0.0]);
    assert!((r - 1.0).abs() < EPS);
    // Refusals, named.
    assert_eq!(Circle::through([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]), Err(Cga2Error::Collinear));
    assert_eq!(Circle::through([0.0, 0.0], [0.0, 0.0], [2.0, 2.0]), Err(Cga2Error::CoincidentPoints));
}

#[test]
fn line_through_two_points() {
    // The horizontal line y = 1, from (−3, 1) to (5, 1): nearest the origin at (0, 1), along +x.
    let line = Circle::line_through([-3.0, 1.0], [5.0, 1.0]).unwrap();
    assert!(line.is_line());
    let (p, d) = line.line_point_direction().unwrap();
    assert_near(p, [0.0, 1.0]);
    assert_near(d, [1.0, 0.0]);
    assert_eq!(line.centre_radius(), Err(Cga2Error::IsLine));
    // The line x + y = 2 from (2, 0) to (0, 2): foot (1, 1), direction (−1, 1)/√2.
    let (p, d) = Circle::line_through([2.0, 0.0], [0.0, 2.0]).unwrap().line_point_direction().unwrap();
    let k = 0.5f64.sqrt();
    assert_near(p, [1.0, 1.0]);
    assert_near(d, [-k, k]);
}

#[test]
fn point_pair_ends() {
    let pair = PointPair::through([1.0, 2.0], [-3.0, 0.5]).unwrap();
    let [a, b] = pair.ends().unwrap();
    assert_near(a, [1.0, 2.0]);
    assert_near(b, [-3.0, 0.5]);
    // The wedge of the two points is the same pair.
    let [a, b] = (Vector::up([1.0, 2.0]) ^ Vector::up([-3.0, 0.5])).ends().unwrap();
    assert_near(a, [1.0, 2.0]);
    assert_near(b, [-3.0, 0.5]);
    assert_eq!(PointPair::through([1.0, 2.0], [1.0, 2.0]), Err(Cga2Error::CoincidentPoints));
}

#[test]
fn rotate_and_translate_points() {
    // A quarter turn counter-clockwise: (1, 0) → (0, 1), (0, 2) → (−2, 0).
    let quarter = Rotor::from_angle(FRAC_PI_2);
    assert_near(quarter.sandwich(Vector::up([1.0, 0.0])).down().unwrap(), [0.0, 1.0]);
    assert_near(quarter.sandwich(Vector::up([0.0, 2.0])).down().unwrap(), [-2.0, 0.0]);
    assert!((quarter.angle() - FRAC_PI_2).abs() < EPS);
    // Any angle, against the rotation matrix.
    for theta in [0.3, -1.1, 2.9] {
        let (s, c) = f64::sin_cos(theta);
        let (x, y) = (1.5, -0.5);
        let got = Rotor::from_angle(theta).sandwich(Vector::up([x, y])).down().unwrap();
        assert_near(got, [c * x - s * y, s * x + c * y]);
    }
    // A translation by (1, 2).
    let t = Motor::translator([1.0, 2.0]);
    assert_near(t.sandwich(Vector::up([0.0, 0.0])).down().unwrap(), [1.0, 2.0]);
    assert_near(t.sandwich(Vector::up([-4.0, 0.5])).down().unwrap(), [-3.0, 2.5]);
    // A half turn about (1, 1): (3, 1) → (−1, 1); a quarter turn: (2, 1) → (1, 2).
    assert_near(Motor::rotation_about([1.0, 1.0], PI).sandwich(Vector::up([3.0, 1.0])).down().unwrap(), [-1.0, 1.0]);
    assert_near(
        Motor::rotation_about([1.0, 1.0], FRAC_PI_2).sandwich(Vector::up([2.0, 1.0])).down().unwrap(),
        [1.0, 2.0],
    );
    // Composed: turn a quarter about the origin, then shift by (1, 2): (1, 0) → (0, 1) → (1, 3).
    let m = t * quarter;
    assert_near(m.sandwich(Vector::up([1.0, 0.0])).down().unwrap(), [1.0, 3.0]);
    // A circle moves as a whole: the unit circle shifted by (1, 2) has centre (1, 2), radius 1.
    let unit = Circle::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]).unwrap();
    let (c, r) = t.sandwich(unit).centre_radius().unwrap();
    assert_near(c, [1.0, 2.0]);
    assert!((r - 1.0).abs() < EPS);
}

#[test]
fn many_points_through_a_prepared_motor() {
    let m = Motor::rotation_about([1.0, 1.0], FRAC_PI_2);
    let points: Vec<Vector> = (0..17).map(|k| Vector::up([k as f64, 2.0 - k as f64 * 0.5])).collect();
    let moved = m.prepare().apply_to(&points);
    for (k, x) in points.iter().enumerate() {
        // About (1, 1) by a quarter turn: (x, y) → (1 − (y − 1), 1 + (x − 1)).
        let [a, b] = x.down().unwrap();
        assert_near(moved[k].down().unwrap(), [2.0 - b, a]);
    }
}

#[test]
fn a_line_meets_a_circle() {
    let unit = Circle::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]).unwrap();
    // y = 0.6 cuts the unit circle at x = ±0.8.
    let chord = Circle::line_through([-2.0, 0.6], [2.0, 0.6]).unwrap();
    assert_pair((chord & unit).ends().unwrap(), [[-0.8, 0.6], [0.8, 0.6]]);
    // The line y = x through the circle of centre (1, 0) and radius 1, through (0, 0), (2, 0),
    // (1, 1): (x − 1)² + x² = 1 gives x = 0 and x = 1.
    let circle = Circle::through([0.0, 0.0], [2.0, 0.0], [1.0, 1.0]).unwrap();
    let diagonal = Circle::line_through([-1.0, -1.0], [3.0, 3.0]).unwrap();
    assert_pair((diagonal & circle).ends().unwrap(), [[0.0, 0.0], [1.0, 1.0]]);
    // A line that misses: y = 2 and the unit circle meet in an imaginary pair.
    let miss = Circle::line_through([0.0, 2.0], [1.0, 2.0]).unwrap();
    assert_eq!((miss & unit).ends(), Err(Cga2Error::Imaginary));
    // Two unit circles centred 1 apart meet at (½, ±√3/2).
    let other = Circle::through([2.0, 0.0], [1.0, 1.0], [0.0, 0.0]).unwrap();
    let h = 0.75f64.sqrt();
    assert_pair((unit & other).ends().unwrap(), [[0.5, h], [0.5, -h]]);
}
