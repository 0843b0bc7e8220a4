//! 2D CGA's constructors and read-backs (`cga_algebras::cga2`'s `cga2/construct.rs`): the
//! circle through three points and its centre and radius, lines, point pairs and their ends,
//! rotors and translators, against Euclid (the circumcentre formula, distances, turns), in
//! f64 and f32, with the named errors.

use cga_algebras::cga2::{Cga2Error, Circle, Motor, PointPair, Rotor, Sandwich, Vector};
use proptest::prelude::*;

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// The circumcentre of a triangle, by the perpendicular bisectors.
fn circumcentre(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    let (a2, b2, c2) = (a[0] * a[0] + a[1] * a[1], b[0] * b[0] + b[1] * b[1], c[0] * c[0] + c[1] * c[1]);
    [
        (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
        (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn circles_lines_and_pairs_read_back_as_euclid_says(
        a in prop::array::uniform2(-5.0f64..5.0),
        b in prop::array::uniform2(-5.0f64..5.0),
        c in prop::array::uniform2(-5.0f64..5.0),
        angle in -6.0f64..6.0,
        t in prop::array::uniform2(-5.0f64..5.0),
    ) {
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
        prop_assume!((u[0] * v[1] - u[1] * v[0]).abs() > 0.5);
        let (centre, r) = Circle::through(a, b, c).unwrap().centre_radius().unwrap();
        let want = circumcentre(a, b, c);
        let scale = 1.0 + dist(want, [0.0, 0.0]);
        prop_assert!(dist(centre, want) <= 1e-10 * scale, "{centre:?} vs {want:?}");
        prop_assert!((r - dist(want, a)).abs() <= 1e-10 * scale);
        // The line through a and b: a line, through both, directed from a to b.
        let line = Circle::line_through(a, b).unwrap();
        prop_assert!(line.is_line() && !Circle::through(a, b, c).unwrap().is_line());
        prop_assert_eq!(line.centre_radius(), Err(Cga2Error::IsLine));
        let (p, d) = line.line_point_direction().unwrap();
        let ab = dist(a, b);
        let want_d = [(b[0] - a[0]) / ab, (b[1] - a[1]) / ab];
        prop_assert!(dist(d, want_d) <= 1e-12, "{d:?} vs {want_d:?}");
        let off = (a[0] - p[0]) * d[1] - (a[1] - p[1]) * d[0];
        prop_assert!(off.abs() <= 1e-12 * (1.0 + dist(a, [0.0, 0.0])), "a on the line");
        prop_assert!((p[0] * d[0] + p[1] * d[1]).abs() <= 1e-12 * (1.0 + dist(p, [0.0, 0.0])), "p nearest the origin");
        // The pair's ends, in order.
        let [e, f] = PointPair::through(a, b).unwrap().ends().unwrap();
        prop_assert!(dist(e, a) <= 1e-11 * scale && dist(f, b) <= 1e-11 * scale, "{e:?} {f:?} vs {a:?} {b:?}");
        // Rotors turn counter-clockwise, translators move by +t, rotation_about keeps the centre.
        let moved = |m: Motor<f64>, x: [f64; 2]| m.sandwich(Vector::up(x)).down().unwrap();
        let turned = moved(Motor::from(Rotor::from_angle(angle)), a);
        let (cs, sn) = (angle.cos(), angle.sin());
        prop_assert!(dist(turned, [cs * a[0] - sn * a[1], sn * a[0] + cs * a[1]]) <= 1e-12 * scale);
        prop_assert!((Rotor::from_angle(angle).angle() - angle).abs() <= 1e-12);
        prop_assert!(dist(moved(Motor::translator(t), a), [a[0] + t[0], a[1] + t[1]]) <= 1e-12 * scale);
        let about = Motor::rotation_about(c, angle);
        prop_assert!(dist(moved(about, c), c) <= 1e-11 * scale);
        prop_assert!((dist(moved(about, a), c) - dist(a, c)).abs() <= 1e-11 * scale);
    }
}

#[test]
fn the_named_errors() {
    assert_eq!(Circle::<f64>::through([0.0, 0.0], [0.0, 0.0], [1.0, 0.0]), Err(Cga2Error::CoincidentPoints));
    assert_eq!(Circle::<f64>::through([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]), Err(Cga2Error::Collinear));
    assert_eq!(Circle::<f64>::through([f64::NAN, 0.0], [1.0, 1.0], [2.0, 0.0]), Err(Cga2Error::NonFinite));
    assert_eq!(Circle::<f64>::line_through([1.0, 1.0], [1.0, 1.0]), Err(Cga2Error::CoincidentPoints));
    assert_eq!(Circle::<f64>::zero().centre_radius(), Err(Cga2Error::Degenerate));
    let circle = Circle::through([0.0, 0.0], [2.0, 0.0], [0.0, 2.0]).unwrap();
    assert_eq!(circle.line_point_direction(), Err(Cga2Error::Degenerate));
    // An imaginary circle: its dual `σ = eo + ei` has `σ² = 2 eo · ei = −2`, radius² −2.
    let imaginary = (Vector::up([0.0, 0.0]) + Vector { e1: 0.0, e2: 0.0, eo: 0.0, ei: 1.0 }).undual();
    assert_eq!(imaginary.centre_radius(), Err(Cga2Error::Imaginary));
}

#[test]
fn f32_reads_back_the_unit_circle() {
    let (centre, r) = Circle::<f32>::through([1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]).unwrap().centre_radius().unwrap();
    assert!(centre[0].abs() <= 1e-6 && centre[1].abs() <= 1e-6 && (r - 1.0).abs() <= 1e-6);
    // Far from the origin: a circle of radius 1 a thousand units out, to f64's 1e-9 of it.
    let (centre, r) =
        Circle::<f64>::through([1001.0, 1000.0], [1000.0, 1001.0], [999.0, 1000.0]).unwrap().centre_radius().unwrap();
    assert!((centre[0] - 1000.0).abs() <= 1e-9 * 1e3 && (r - 1.0).abs() <= 1e-6, "{centre:?} {r}");
}
