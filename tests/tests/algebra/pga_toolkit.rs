//! The PGA toolkit of `cga_algebras::pga` (constructors, read-backs, `exp`/`log` of screws,
//! `sqrt`, interpolation, motor normalisation, distances, angles, projections, and the signs
//! `docs/PGA.md` tabulates) against kingdon 3.0.0's own results
//! (`tests/data/kingdon_pga_toolkit.json`, made by `tools/kingdon_pga_toolkit.py`) and against
//! Euclidean formulas, in f64 and f32, with tiny and near-π angles, far lines and pure
//! translations.

use cga_tests::common;

use common::PGA_STORAGE as STORAGE;
use proptest::prelude::*;

use cga_algebras::pga::{Line, Motor, PgaError, Plane, Point};

fn kingdon() -> serde_json::Value {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/kingdon_pga_toolkit.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let value: serde_json::Value = serde_json::from_str(&text).expect("kingdon_pga_toolkit.json parses");
    let blades: Vec<&str> = value["blades"].as_array().unwrap().iter().map(|b| b.as_str().unwrap()).collect();
    assert_eq!(blades[5..11], ["e01", "e02", "e03", "e12", "e13", "e23"], "canonical order");
    value
}

fn coeffs<const N: usize>(v: &serde_json::Value) -> [f64; N] {
    let list = v.as_array().expect("a list of numbers");
    assert_eq!(list.len(), N);
    core::array::from_fn(|k| list[k].as_f64().expect("a number"))
}

/// Kingdon's canonical coefficients in our storage basis: each times its spelling's sign.
fn ours(v: &serde_json::Value) -> [f64; 16] {
    let c: [f64; 16] = coeffs(v);
    core::array::from_fn(|k| c[k] * STORAGE[k].1)
}

fn motor(v: &serde_json::Value) -> Motor<f64> {
    Motor::from_storage(&ours(v))
}

fn line(v: &serde_json::Value) -> Line<f64> {
    Line::from_storage(&ours(v))
}

/// `max |a − b|` over the coefficients, relative to `1 + max |b|`.
fn close(a: &[f64], b: &[f64]) -> f64 {
    let scale = 1.0 + b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

/// `M` and `−M` are the same motion: the distance to the nearer.
fn close_motor(a: Motor<f64>, b: Motor<f64>) -> f64 {
    let (a, b) = (a.to_array(), b.to_array());
    close(&a, &b).min(close(&a.map(|x| -x), &b))
}

fn moved(m: Motor<f64>, x: [f64; 3]) -> [f64; 3] {
    m.apply(Point::at(x)).position().unwrap()
}

#[test]
fn rotors_and_translators_are_kingdons_and_move_as_named() {
    let data = kingdon();
    for case in data["rotors"].as_array().unwrap() {
        let (axis, angle, x): ([f64; 3], f64, [f64; 3]) =
            (coeffs(&case["axis"]), case["angle"].as_f64().unwrap(), coeffs(&case["x"]));
        let r = Motor::rotor(axis, angle).unwrap();
        assert!(close(&r.to_storage(), &ours(&case["motor"])) <= 1e-15, "rotor");
        let want = Point::from_storage(&ours(&case["moved"])).position().unwrap();
        assert!(close(&moved(r, x), &want) <= 1e-14);
    }
    for case in data["translators"].as_array().unwrap() {
        let (t, x): ([f64; 3], [f64; 3]) = (coeffs(&case["t"]), coeffs(&case["x"]));
        let m = Motor::translator(t).unwrap();
        assert!(close(&m.to_storage(), &ours(&case["motor"])) <= 1e-15, "translator");
        let want = Point::from_storage(&ours(&case["moved"])).position().unwrap();
        assert!(close(&moved(m, x), &want) <= 1e-14);
        // +t, as the name says.
        assert!(close(&moved(m, x), &[x[0] + t[0], x[1] + t[1], x[2] + t[2]]) <= 1e-14);
    }
}

/// A right-handed quarter turn about +z takes +x to +y; about +x, +y to +z.
#[test]
fn rotors_are_right_handed() {
    let q = std::f64::consts::FRAC_PI_2;
    let r = Motor::rotor([0.0, 0.0, 2.0], q).unwrap();
    assert!(close(&moved(r, [1.0, 0.0, 0.0]), &[0.0, 1.0, 0.0]) <= 1e-15);
    let r = Motor::rotor([1.0, 0.0, 0.0], q).unwrap();
    assert!(close(&moved(r, [0.0, 1.0, 0.0]), &[0.0, 0.0, 1.0]) <= 1e-15);
    assert_eq!(Motor::rotor([0.0; 3], 1.0), Err(PgaError::ZeroVector));
    assert_eq!(Motor::rotor([1.0, 0.0, 0.0], f64::NAN), Err(PgaError::NonFinite));
    assert_eq!(Motor::translator([f64::INFINITY, 0.0, 0.0]), Err(PgaError::NonFinite));
}

/// Screws (far lines, turns of 1e-9 and near ±π among them): `Motor::screw` is kingdon's
/// motor, `exp_motor` of the generator is too, `log` gives the generator back, and `sqrt`
/// is the half screw.
#[test]
fn screws_exp_log_and_sqrt_are_kingdons() {
    let data = kingdon();
    for (n, case) in data["screws"].as_array().unwrap().iter().enumerate() {
        let (p, d, x): ([f64; 3], [f64; 3], [f64; 3]) = (coeffs(&case["p"]), coeffs(&case["d"]), coeffs(&case["x"]));
        let (angle, distance) = (case["angle"].as_f64().unwrap(), case["distance"].as_f64().unwrap());
        let want = motor(&case["motor"]);
        let l = Line::from_point_direction(p, d).unwrap();
        // kingdon joins two points a thousand units out (case 12): its moment rounds at 1e-13.
        let dl = close(&l.unit().unwrap().to_storage(), &ours(&case["line"]));
        assert!(dl <= 1e-12, "case {n}: line differs by {dl:e}");
        let m = Motor::screw(l, angle, distance).unwrap();
        assert!(close_motor(m, want) <= 1e-13, "case {n}: screw {:e}", close_motor(m, want));
        let b = line(&case["generator"]);
        let e = b.exp_motor().unwrap();
        assert!(close_motor(e, want) <= 1e-13, "case {n}: exp {:e}", close_motor(e, want));
        let log = want.log().unwrap();
        let dl = close(&log.to_array(), &b.to_array());
        assert!(dl <= 1e-11, "case {n}: log differs by {dl:e}: {log:?} vs {b:?}");
        let moved_want = Point::from_storage(&ours(&case["moved"])).position().unwrap();
        assert!(close(&moved(m, x), &moved_want) <= 1e-12, "case {n}: moved");
        let half = want.sqrt().unwrap();
        assert!(close_motor(half, motor(&case["half"])) <= 1e-13, "case {n}: sqrt");
        // kingdon's own M.sqrt() divides `1 + M` by the real part of its norm only: it is
        // off by about `|θ δ| / 4` (the Study part), so agrees for rotations and slides.
        let ks = close_motor(half, motor(&case["kingdon_sqrt"]));
        assert!(ks <= 1e-12 + (angle * distance).abs() / 2.0, "case {n}: kingdon's sqrt off by {ks:e}");
    }
    for case in data["rotors"].as_array().unwrap() {
        let r = motor(&case["motor"]);
        let angle = case["angle"].as_f64().unwrap();
        let axis: [f64; 3] = coeffs(&case["axis"]);
        let half = Motor::rotor(axis, angle / 2.0).unwrap();
        assert!(close_motor(r.sqrt().unwrap(), half) <= 1e-14);
    }
}

#[test]
fn interpolation_and_normalisation_are_kingdons() {
    let data = kingdon();
    for (n, case) in data["interpolations"].as_array().unwrap().iter().enumerate() {
        let (a, b, t) = (motor(&case["a"]), motor(&case["b"]), case["t"].as_f64().unwrap());
        let got = Motor::interpolate(&a, &b, t).unwrap();
        let d = close_motor(got, motor(&case["want"]));
        assert!(d <= 1e-12, "case {n}: interpolation differs by {d:e}");
        assert!(close_motor(Motor::interpolate(&a, &b, 0.0).unwrap(), a) <= 1e-14);
        assert!(close_motor(Motor::interpolate(&a, &b, 1.0).unwrap(), b) <= 1e-12);
    }
    for case in data["normalised"].as_array().unwrap() {
        let got = motor(&case["motor"]).renormalise().unwrap();
        assert!(close(&got.to_storage(), &ours(&case["want"])) <= 1e-15);
        let n = got * got.reverse();
        assert!((n.s - 1.0).abs() <= 1e-15 && n.e0123.abs() <= 1e-15, "M M̃ = 1: {n:?}");
    }
}

/// The claims of `docs/PGA.md`'s table of signs, on kingdon's numbers and ours, and klein's
/// join `J(J(a) ∧ J(b))` with its relabelling dual `J` written out.
#[test]
fn the_sign_conventions_are_as_the_docs_say() {
    let data = kingdon();
    for case in data["signs"].as_array().unwrap() {
        let (x, c, y, c2): ([f64; 3], [f64; 4], [f64; 3], [f64; 4]) =
            (coeffs(&case["x"]), coeffs(&case["plane"]), coeffs(&case["y"]), coeffs(&case["plane2"]));
        let (p, plane, q, plane2) =
            (Point::at(x), Plane::new(c[0], c[1], c[2], c[3]), Point::at(y), Plane::new(c2[0], c2[1], c2[2], c2[3]));
        let distance = c[0] * x[0] + c[1] * x[1] + c[2] * x[2] + c[3];
        // kingdon: `p & P` = +distance, `P & p` = −distance; `p ^ P` = +distance I.
        let tol = 1e-12 * (1.0 + distance.abs());
        assert!((ours(&case["plane_vee_point"])[0] - distance).abs() <= tol);
        assert!((ours(&case["point_vee_plane"])[0] + distance).abs() <= tol);
        assert!((ours(&case["plane_wedge_point"])[15] - distance).abs() <= tol);
        assert!((ours(&case["point_wedge_plane"])[15] + distance).abs() <= tol);
        // Ours, spelled as kingdon spells it, the same numbers.
        assert!(((plane & p).s - distance).abs() <= tol);
        assert!(((p & plane).s + distance).abs() <= tol);
        assert!(((plane ^ p).e0123 - distance).abs() <= tol);
        assert!(((p ^ plane).e0123 + distance).abs() <= tol);
        // klein: `a & b = J(J(a) ∧ J(b))`, J relabelling e0 ↔ e123, e1 ↔ e032, e2 ↔ e013,
        // e3 ↔ e021 and the dual number's parts: `point & plane` = +distance, `plane & point`
        // = −distance.
        let j_plane = |pl: Plane<f64>| Point { e123: pl.e0, e032: pl.e1, e013: pl.e2, e021: pl.e3 };
        let j_point = |pt: Point<f64>| Plane { e0: pt.e123, e1: pt.e032, e2: pt.e013, e3: pt.e021 };
        let klein_point_vee_plane = (j_point(p) ^ j_plane(plane)).e0123;
        let klein_plane_vee_point = (j_plane(plane) ^ j_point(p)).e0123;
        assert!((klein_point_vee_plane - distance).abs() <= tol);
        assert!((klein_plane_vee_point + distance).abs() <= tol);
        // `P & Q` is kingdon's, directed from P to Q; `p ^ q` is kingdon's, along n_p × n_q.
        let join = p & q;
        assert!(close(&join.to_storage(), &ours(&case["points_join"])) <= 1e-13);
        assert!(close(&join.direction(), &[y[0] - x[0], y[1] - x[1], y[2] - x[2]]) <= 1e-14);
        let meet = plane ^ plane2;
        assert!(close(&meet.to_storage(), &ours(&case["planes_meet"])) <= 1e-14);
        let n = [c[1] * c2[2] - c[2] * c2[1], c[2] * c2[0] - c[0] * c2[2], c[0] * c2[1] - c[1] * c2[0]];
        assert!(close(&meet.direction(), &n) <= 1e-14);
        // klein's join of two points: J(J(P) ∧ J(Q)) with J relabelling e01 ↔ e23, e02 ↔ e31,
        // e03 ↔ e12 on the line: the same line as ours, the same direction.
        let kj = j_point(p) ^ j_point(q);
        let klein_join = Line { e01: kj.e23, e02: kj.e31, e03: kj.e12, e23: kj.e01, e31: kj.e02, e12: kj.e03 };
        assert!(close(&klein_join.to_storage(), &join.to_storage()) <= 1e-13, "{klein_join:?} vs {join:?}");
    }
}

/// Constructors and read-backs against Euclid, and the named errors.
#[test]
fn constructors_and_read_backs() {
    let plane = Plane::from_normal_distance([0.0, 0.0, 2.0], 3.0).unwrap();
    assert_eq!(plane, Plane::new(0.0, 0.0, 1.0, -3.0));
    assert_eq!(plane.normal_distance().unwrap(), ([0.0, 0.0, 1.0], 3.0));
    assert_eq!(Plane::<f64>::from_normal_distance([0.0; 3], 1.0), Err(PgaError::ZeroVector));
    assert_eq!(Plane::new(0.0, 0.0, 0.0, 1.0).normal_distance(), Err(PgaError::IdealPlane));
    let tri = Plane::through([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]).unwrap();
    let (n, d) = tri.normal_distance().unwrap();
    assert!(close(&n, &[0.0, 0.0, 1.0]) <= 1e-15 && (d - 1.0).abs() <= 1e-15, "{n:?} {d}");
    assert_eq!(Plane::through([0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]), Err(PgaError::CoincidentPoints));
    let l = Line::through([1.0, 2.0, 3.0], [1.0, 2.0, 5.0]).unwrap();
    assert_eq!(l.direction(), [0.0, 0.0, 2.0]);
    assert_eq!(l.moment(), [4.0, -2.0, 0.0]); // p × d
    let (p, u) = l.point_direction().unwrap();
    assert!(close(&p, &[1.0, 2.0, 0.0]) <= 1e-15 && u == [0.0, 0.0, 1.0]);
    assert_eq!(l, Line::from_point_direction([1.0, 2.0, 3.0], [0.0, 0.0, 2.0]).unwrap());
    assert_eq!(Line::through([1.0; 3], [1.0; 3]), Err(PgaError::CoincidentPoints));
    assert_eq!(Line::through([f64::NAN; 3], [1.0; 3]), Err(PgaError::NonFinite));
    assert_eq!(Line::from_plucker([0.0; 3], [1.0, 0.0, 0.0]).unit(), Err(PgaError::IdealLine));
    assert_eq!(Point::ideal([1.0, 0.0, 0.0]).try_position(), Err(PgaError::IdealPoint));
    assert_eq!(Point::at_weight([1.0, 2.0, 3.0], 2.0).position(), Some([1.0, 2.0, 3.0]));
    let (r, t) = Motor::from_rotor_translator(
        Motor::rotor([0.0, 0.0, 1.0], 0.5).unwrap(),
        Motor::translator([1.0, 2.0, 3.0]).unwrap(),
    )
    .rotor_translation()
    .unwrap();
    assert!(close(&t, &[1.0, 2.0, 3.0]) <= 1e-15);
    assert!(close_motor(r, Motor::rotor([0.0, 0.0, 1.0], 0.5).unwrap()) <= 1e-15);
    assert_eq!(Motor::<f64>::zero().log(), Err(PgaError::NotAMotor));
    assert_eq!(Motor { s: -1.0, e01: 0.3, ..Motor::zero() }.log(), Err(PgaError::FullTurn));
    assert_eq!(Motor { s: -1.0, ..Motor::<f64>::zero() }.sqrt(), Err(PgaError::FullTurn));
    assert_eq!(Motor { s: f64::NAN, ..Motor::<f64>::zero() }.sqrt(), Err(PgaError::NonFinite));
}

/// Stiff cases: a pure translation's log is its generator exactly; tiny turns and turns
/// near 2π round-trip; a screw a thousand units out.
#[test]
fn stiff_cases_round_trip() {
    let t = Motor::translator([3.0, -4.0, 1e-3]).unwrap();
    let log = t.log().unwrap();
    assert_eq!(log, Line { e01: -1.5, e02: 2.0, e03: -0.5e-3, e12: 0.0, e31: 0.0, e23: 0.0 });
    assert_eq!(log.exp_motor().unwrap(), t);
    use std::f64::consts::{PI, TAU};
    for angle in [1e-12, 1e-6, 0.05, 0.1, 1.0, 3.0, PI - 1e-5, PI, 6.0, TAU - 3e-3] {
        for far in [0.0, 1e3] {
            let l = Line::from_point_direction([far, -2.0, 0.5], [0.3, -0.4, 1.2]).unwrap();
            let m = Motor::screw(l, angle, 0.7).unwrap();
            let back = m.log().unwrap().exp_motor().unwrap();
            // Far lines carry moments of 1e3: relative to the motor's size.
            let d = close_motor(back, m);
            let tol = if angle > 6.0 { 1e-9 } else { 1e-13 } * (1.0 + far);
            assert!(d <= tol, "angle {angle}, far {far}: {d:e}");
            let x = [far + 1.0, 0.0, 2.0];
            let half = m.sqrt().unwrap();
            let twice = moved(half, moved(half, x));
            // Near a full turn `1 + M` is small: √M loses ε / (1 + s) (here 1e6 ε).
            let tol = if angle > 6.0 { 1e-9 } else { 1e-11 } * (1.0 + far);
            let d = close(&twice, &moved(m, x));
            assert!(d <= tol, "angle {angle}, far {far}: sqrt {d:e}");
        }
    }
}

/// f32 agrees with f64 to f32 rounding.
#[test]
fn f32_follows_f64() {
    let l64 = Line::from_point_direction([1.0, -2.0, 0.5], [0.3, -0.4, 1.2]).unwrap();
    let l32 = Line::<f32>::from_point_direction([1.0, -2.0, 0.5], [0.3, -0.4, 1.2]).unwrap();
    for angle in [1e-6f32, 0.3, 2.5] {
        let m32 = Motor::<f32>::screw(l32, angle, 0.7).unwrap();
        let m64 = Motor::<f64>::screw(l64, angle as f64, 0.7).unwrap();
        let diff = |a: Motor<f32>, b: Motor<f64>| close(&a.cast::<f64>().to_array(), &b.to_array());
        assert!(diff(m32, m64) <= 1e-6);
        assert!(diff(m32.log().unwrap().exp_motor().unwrap(), m64) <= 2e-6);
        assert!(diff(m32.sqrt().unwrap(), m64.sqrt().unwrap()) <= 1e-6);
        let a = Motor::<f32>::translator([1.0, 0.0, 0.0]).unwrap();
        let a64 = Motor::<f64>::translator([1.0, 0.0, 0.0]).unwrap();
        assert!(diff(Motor::interpolate(&a, &m32, 0.3).unwrap(), Motor::interpolate(&a64, &m64, 0.3).unwrap()) <= 2e-6);
    }
}

fn unit3(v: [f64; 3]) -> [f64; 3] {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / n)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn len(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A screw about the line through `p` along `u` moves `x` as Rodrigues' formula about
    /// that line, then along `u` by δ.
    #[test]
    fn screws_move_as_rodrigues_says(
        p in prop::array::uniform3(-5.0f64..5.0),
        d in prop::array::uniform3(-1.0f64..1.0),
        x in prop::array::uniform3(-5.0f64..5.0),
        angle in -6.0f64..6.0,
        delta in -3.0f64..3.0,
    ) {
        prop_assume!(len(d) > 0.1);
        let u = unit3(d);
        let r = sub(x, p);
        let (c, s) = (angle.cos(), angle.sin());
        let k = cross(u, r);
        let along = dot(u, r) * (1.0 - c);
        let want: [f64; 3] = core::array::from_fn(|i| p[i] + r[i] * c + k[i] * s + u[i] * along + u[i] * delta);
        let m = Motor::screw(Line::from_point_direction(p, d).unwrap(), angle, delta).unwrap();
        prop_assert!(close(&moved(m, x), &want) <= 1e-13);
        let pitch = Motor::from_line_pitch(Line::from_point_direction(p, d).unwrap(), angle, 0.5).unwrap();
        let slid = Motor::screw(Line::from_point_direction(p, d).unwrap(), angle, 0.5 * angle).unwrap();
        prop_assert_eq!(pitch, slid);
        // Any product of a rotor and translator has a log whose exp is itself, and a sqrt
        // whose square is itself.
        let q = Motor::from_rotor_translator(Motor::rotor(d, angle).unwrap(), Motor::translator(p).unwrap());
        prop_assert!(close_motor(q.log().unwrap().exp_motor().unwrap(), q) <= 1e-12);
        let h = q.sqrt().unwrap();
        prop_assert!(close_motor(h * h, q) <= 1e-13);
        prop_assert!(close_motor(q.pow(0.5).unwrap(), h) <= 1e-12 || angle.abs() > 2.0 * std::f64::consts::PI - 1e-3);
    }

    /// Distances and angles against Euclid.
    #[test]
    fn distances_and_angles_are_euclids(
        a in prop::array::uniform3(-5.0f64..5.0),
        b in prop::array::uniform3(-5.0f64..5.0),
        d1 in prop::array::uniform3(-1.0f64..1.0),
        d2 in prop::array::uniform3(-1.0f64..1.0),
        x in prop::array::uniform3(-5.0f64..5.0),
        w in 0.2f64..3.0,
        off in -4.0f64..4.0,
    ) {
        prop_assume!(len(d1) > 0.1 && len(d2) > 0.1 && len(cross(unit3(d1), unit3(d2))) > 0.05);
        let (pa, px) = (Point::at_weight(a, w), Point::at(x));
        prop_assert!((pa.distance_to_point(px).unwrap() - len(sub(a, x))).abs() <= 1e-13);
        // Point to plane: signed, positive on the normal's side.
        let plane = Plane::from_normal_distance(d1, off).unwrap();
        let want = dot(unit3(d1), x) - off;
        prop_assert!((px.distance_to_plane(plane.scale(2.0)).unwrap() - want).abs() <= 1e-13);
        // Point to line.
        let l1 = Line::from_point_direction(a, d1).unwrap();
        let want = len(cross(sub(x, a), unit3(d1)));
        prop_assert!((px.distance_to_line(l1.scale(0.5)).unwrap() - want).abs() <= 1e-13);
        // Line to line: skew, then parallel.
        let l2 = Line::from_point_direction(b, d2).unwrap();
        let n = cross(d1, d2);
        let want = dot(sub(b, a), n).abs() / len(n);
        prop_assert!((l1.distance_to_line(l2).unwrap() - want).abs() <= 1e-11 * (1.0 + want) / len(cross(unit3(d1), unit3(d2))));
        let vee = dot(l1.direction(), l2.moment()) + dot(l2.direction(), l1.moment());
        prop_assert!(((l1 & l2).s - vee).abs() <= 1e-12 * (1.0 + vee.abs()), "L₁ & L₂ = d₁ · m₂ + d₂ · m₁");
        let l3 = Line::from_point_direction(b, d1.map(|c| -3.0 * c)).unwrap();
        let want = len(cross(sub(b, a), unit3(d1)));
        prop_assert!((l1.distance_to_line(l3).unwrap() - want).abs() <= 1e-13);
        // Angles.
        let want = dot(unit3(d1), unit3(d2)).clamp(-1.0, 1.0).acos();
        prop_assert!((l1.angle_to_line(l2).unwrap() - want).abs() <= 1e-12);
        let p2 = Plane::from_normal_distance(d2, 0.0).unwrap();
        prop_assert!((plane.angle_to_plane(p2).unwrap() - want).abs() <= 1e-12);
        let want = dot(unit3(d1), unit3(d2)).abs().clamp(0.0, 1.0).asin();
        prop_assert!((l1.angle_to_plane(p2).unwrap() - want).abs() <= 1e-12);
        // Projections: the line onto the plane lies in it, keeps its orientation and is the
        // projection of two of its points; a plane and a line moved onto a point pass through
        // it, parallel and alike oriented.
        let proj = l1.project_onto_plane(p2);
        let (e, f) = (Point::at(a).project_onto_plane(p2), Point::at([a[0] + d1[0], a[1] + d1[1], a[2] + d1[2]]).project_onto_plane(p2));
        let want = e & f;
        let k = len(proj.direction()) / len(want.direction());
        prop_assert!(close(&proj.to_array(), &want.scale(k).to_array()) <= 1e-12, "{:?} vs {:?}", proj, want);
        let pp = plane.project_onto_point(px);
        prop_assert!(pp.distance_to_point_check(px));
        let (n1, _) = pp.normal_distance().unwrap();
        prop_assert!(close(&n1, &unit3(d1)) <= 1e-13);
        let lp = l1.project_onto_point(px);
        prop_assert!(px.distance_to_line(lp).unwrap() <= 1e-12);
        prop_assert!(close(&unit3(lp.direction()), &unit3(d1)) <= 1e-13);
        // Errors.
        prop_assert_eq!(Point::ideal(a).distance_to_point(px), Err(PgaError::IdealPoint));
        prop_assert_eq!(px.distance_to_line(Line::from_plucker([0.0; 3], a)), Err(PgaError::IdealLine));
    }
}

trait OnPlane {
    fn distance_to_point_check(self, p: Point<f64>) -> bool;
}

impl OnPlane for Plane<f64> {
    fn distance_to_point_check(self, p: Point<f64>) -> bool {
        p.distance_to_plane(self).unwrap().abs() <= 1e-12
    }
}

/// The Plücker defect `d · m` vanishes for a line joined from two points wherever they lie,
/// and is half the pseudoscalar of `B ∧ B` for a general bivector (a screw's generator, the
/// log of a screw), up to its sign convention.
#[test]
fn the_plucker_defect_is_zero_for_lines_and_half_b_wedge_b_otherwise() {
    for (p, q) in [([1.0, 2.0, 3.0], [-4.0, 0.5, 2.0]), ([1e6, -3e6, 2e6], [1e6 + 1.0, -3e6, 2e6 + 2.0])] {
        let l: Line<f64> = Line::through(p, q).unwrap();
        let scale = l.to_array().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!(l.plucker_defect().abs() <= 16.0 * f64::EPSILON * scale * scale, "{l:?}");
    }
    let axis: Line<f64> = Line::through([0.0, 1.0, 0.0], [1.0, 1.0, 1.0]).unwrap();
    let b = Motor::screw(axis, 0.8, 0.5).unwrap().log().unwrap();
    let defect = b.plucker_defect();
    let wedge = (b ^ b).e0123;
    assert!(defect.abs() > 1e-3, "a screw's generator is not a line: {defect}");
    assert!((wedge.abs() - 2.0 * defect.abs()).abs() < 1e-12, "{wedge} {defect}");
}
