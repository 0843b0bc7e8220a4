//! An algebra author's first program: G(3,0) declared with `cga_macros::algebra!` from the
//! cga-macros crate documentation and docs/LIBRARY.md ("What `algebra!` generates") alone,
//! batched through `cga_core::simd` and prepared sandwiches. Expected values are worked out
//! by hand here (products of basis vectors, rotation matrices), and every batched result is
//! compared with the same call one value at a time.

mod g3 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        scalars = [f64];
        lanes = cga_core::simd;
        prelude = f64;
        signature = (3, 0);
        /// A vector x e1 + y e2 + z e3.
        type Vector = [grade(1)];
        /// A bivector: a plane of rotation.
        type Bivector = [e12, e13, e23];
        /// The pseudoscalar e123.
        type Trivector = [e123];
        /// A rotor: a scalar and a bivector.
        versor Rotor = [s, e12, e13, e23];
    }
}

use cga_core::simd::{F64x4, F64x8, Kernel, Lane, map, run, run_columns, splat};
use g3::prelude::*;
// The prelude's names are f64 aliases: a kernel generic over lanes names the generic structs.
use g3 as gx;
use std::f64::consts::{FRAC_PI_2, PI};

const EPS: f64 = 1e-12;

fn vector(x: f64, y: f64, z: f64) -> Vector {
    Vector { e1: x, e2: y, e3: z }
}

/// The rotor exp(−½θ e12) = cos θ/2 − sin θ/2 e12: a turn by θ from e1 towards e2.
fn turn_xy(theta: f64) -> Rotor {
    Rotor { s: (theta / 2.0).cos(), e12: -(theta / 2.0).sin(), e13: 0.0, e23: 0.0 }
}

#[track_caller]
fn assert_vec(got: Vector, want: [f64; 3]) {
    let g = [got.e1, got.e2, got.e3];
    assert!(g.iter().zip(want).all(|(a, b)| (a - b).abs() < EPS), "got {g:?}, want {want:?}");
}

#[test]
fn products_of_vectors_by_hand() {
    let (a, b) = (vector(1.0, 2.0, 0.0), vector(3.0, 4.0, 0.0));
    // (e1 + 2 e2)(3 e1 + 4 e2) = 3 + 4 e12 + 6 e21 + 8 = 11 − 2 e12.
    let ab: Rotor = a * b;
    assert_eq!((ab.s, ab.e12, ab.e13, ab.e23), (11.0, -2.0, 0.0, 0.0));
    // The outer product keeps the bivector, the inner the scalar.
    let wedge: Bivector = a ^ b;
    assert_eq!((wedge.e12, wedge.e13, wedge.e23), (-2.0, 0.0, 0.0));
    // Declared types come first: the scalar result is a Rotor (it holds `s`), not an f64.
    assert_eq!((a | b).s, 11.0);
    // e1 e2 e3 = e123, and e123² = −1.
    let (e1, e2, e3) = (vector(1.0, 0.0, 0.0), vector(0.0, 1.0, 0.0), vector(0.0, 0.0, 1.0));
    let i: Trivector = e1 ^ e2 ^ e3;
    assert_eq!(i.e123, 1.0);
    assert_eq!((i * i).s, -1.0);
    // e2 e1 = −e12; e1 e1 = 1.
    assert_eq!((e2 * e1).e12, -1.0);
    assert_eq!((e1 * e1).s, 1.0);
    // Scalars on either side.
    assert_eq!(2.0 * a, vector(2.0, 4.0, 0.0));
    assert_eq!(a / 2.0, vector(0.5, 1.0, 0.0));
}

#[test]
fn rotors_rotate_as_the_matrix_says() {
    let v = vector(2.0, -1.0, 5.0);
    for theta in [0.0, 0.4, FRAC_PI_2, 2.5, -1.3] {
        let (s, c) = theta.sin_cos();
        let got = turn_xy(theta).sandwich(v);
        assert_vec(got, [c * 2.0 + s * 1.0, s * 2.0 - c * 1.0, 5.0]);
    }
    // The rotor from exp of the bivector −½θ e12 is the same.
    let b = Bivector { e12: -0.35, e13: 0.0, e23: 0.0 };
    let r: Rotor = b.exp();
    assert!((r.s - 0.35f64.cos()).abs() < EPS && (r.e12 + 0.35f64.sin()).abs() < EPS);
    // Its log gives the bivector back.
    let l = r.log().unwrap();
    assert!((l.e12 + 0.35).abs() < EPS && l.e13.abs() < EPS && l.e23.abs() < EPS);
    // Two quarter turns are a half turn: e1 → −e1.
    let half = turn_xy(FRAC_PI_2) * turn_xy(FRAC_PI_2);
    assert_vec(half.sandwich(vector(1.0, 0.0, 0.0)), [-1.0, 0.0, 0.0]);
    // A rotor is invertible; its inverse turns back.
    let r = turn_xy(0.9);
    assert_vec(r.inverse().sandwich(r.sandwich(v)), [2.0, -1.0, 5.0]);
}

#[test]
fn prepared_sandwiches_match_one_at_a_time() {
    let r = (turn_xy(1.1) * Rotor { s: 0.6f64.cos(), e12: 0.0, e13: 0.0, e23: -0.6f64.sin() }).normalise().unwrap();
    let vs: Vec<Vector> = (0..21).map(|k| vector(k as f64, 1.0 - k as f64, 0.5 * k as f64)).collect();
    let prepared = r.prepare();
    let all = prepared.apply_to(&vs);
    let again = r.apply_to(&vs);
    for (k, v) in vs.iter().enumerate() {
        let one = r.sandwich(*v);
        // The same up to rounding (summed in another order).
        assert_vec(all[k], [one.e1, one.e2, one.e3]);
        assert_vec(again[k], [one.e1, one.e2, one.e3]);
        // A rotation keeps lengths.
        assert!(((all[k] | all[k]).s - (*v | *v).s).abs() < 1e-10);
    }
    // A quarter turn in the xy plane, prepared: (x, y, z) → (−y, x, z).
    let q = turn_xy(FRAC_PI_2).prepare();
    for v in &vs {
        assert_vec(q.apply(*v), [-v.e2, v.e1, v.e3]);
    }
    // Bivectors too: a quarter turn about z takes the plane e13 to e23.
    let b: Bivector = turn_xy(FRAC_PI_2).prepare().apply(Bivector { e12: 0.0, e13: 1.0, e23: 0.0 });
    assert!(b.e12.abs() < EPS && b.e13.abs() < EPS && (b.e23 - 1.0).abs() < EPS);
}

struct Rotate;
impl Kernel for Rotate {
    type Input = (Rotor, Vector);
    type Output = Vector;
    #[inline(always)]
    fn apply<L: Lane>(&self, (r, v): (gx::Rotor<L>, gx::Vector<L>)) -> gx::Vector<L> {
        r.sandwich(v)
    }
}

struct Wedge;
impl Kernel for Wedge {
    type Input = (Vector, Vector);
    type Output = Bivector;
    #[inline(always)]
    fn apply<L: Lane>(&self, (a, b): (gx::Vector<L>, gx::Vector<L>)) -> gx::Bivector<L> {
        a ^ b
    }
}

#[test]
fn batches_through_simd_equal_one_at_a_time() {
    let n = 29;
    let rotors: Vec<Rotor> = (0..n).map(|k| turn_xy(0.1 * k as f64)).collect();
    let vs: Vec<Vector> = (0..n).map(|k| vector(1.0, 0.0, k as f64)).collect();
    let input: Vec<(Rotor, Vector)> = rotors.iter().copied().zip(vs.iter().copied()).collect();

    // run: each e1 turned by 0.1 k: (cos, sin, z).
    let mut out = vec![Vector::zero(); n];
    run(&Rotate, &input, &mut out).unwrap();
    for k in 0..n {
        let t = 0.1 * k as f64;
        assert_vec(out[k], [t.cos(), t.sin(), k as f64]);
        assert_eq!(out[k], rotors[k].sandwich(vs[k])); // the bits of one at a time
    }
    // run_columns, the same operands in two arrays.
    let mut by_columns = vec![Vector::zero(); n];
    run_columns(&Rotate, (&rotors[..], &vs[..]), &mut by_columns).unwrap();
    assert_eq!(by_columns, out);
    // map with a closure on four lanes: geometric products.
    let pairs: Vec<(Vector, Vector)> = vs.iter().map(|v| (*v, vector(0.0, 1.0, 0.0))).collect();
    let mut products = vec![Rotor::zero(); n];
    map(
        &pairs,
        &mut products,
        #[inline(always)]
        |(a, b): (gx::Vector<F64x4>, gx::Vector<F64x4>)| a * b,
    )
    .unwrap();
    for k in 0..n {
        // (e1 + k e3) e2 = e12 + k e32 = e12 − k e23.
        assert_eq!(products[k], pairs[k].0 * pairs[k].1);
        assert_eq!((products[k].s, products[k].e12, products[k].e13, products[k].e23), (0.0, 1.0, 0.0, -(k as f64)));
    }
    // Wedges by run_columns.
    let ys = vec![vector(0.0, 1.0, 0.0); n];
    let mut wedges = vec![Bivector::zero(); n];
    run_columns(&Wedge, (&vs[..], &ys[..]), &mut wedges).unwrap();
    for k in 0..n {
        assert_eq!(wedges[k], vs[k] ^ ys[k]);
        assert_eq!((wedges[k].e12, wedges[k].e23), (1.0, -(k as f64)));
    }
    // map with one rotor splat into eight lanes: a half turn, (x, y, z) → (−x, −y, z).
    let half = turn_xy(PI);
    let lanes = splat::<Rotor, F64x8>(half);
    let mut turned = vec![Vector::zero(); n];
    map(
        &vs,
        &mut turned,
        #[inline(always)]
        |v: gx::Vector<F64x8>| lanes.sandwich(v),
    )
    .unwrap();
    for k in 0..n {
        assert_eq!(turned[k], half.sandwich(vs[k]));
        assert_vec(turned[k], [-1.0, 0.0, k as f64]);
    }
    // Lengths that differ: None.
    assert_eq!(run(&Rotate, &input[1..], &mut out), None);
}

/// 2D projective geometric algebra G(2,0,1), declared as the crate docs show for 3D PGA: the
/// null vector renamed e0 and listed first, blades spelled as bivector.net does (e20).
mod pga2 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        scalars = [f64];
        lanes = cga_core::simd;
        prelude = f64;
        signature = (2, 0, 1);
        basis = [e0 = e3, e1, e2];
        /// A line a x + b y + c = 0: a e1 + b e2 + c e0.
        versor Line = [e0, e1, e2];
        /// A point (x, y): e12 + x e20 + y e01.
        type Point = [e20, e01, e12];
        /// A motor: reflections in two lines.
        versor Motor = [s, e20, e01, e12];
    }
}

mod plane_pga {
    use super::pga2 as gx;
    use super::pga2::prelude::*;
    use cga_core::simd::{F64x4, Kernel, Lane, map, run, run_columns, splat};

    const EPS: f64 = 1e-12;

    fn point(x: f64, y: f64) -> Point {
        Point { e12: 1.0, e20: x, e01: y }
    }

    #[track_caller]
    fn assert_at(p: Point, want: [f64; 2]) {
        let got = [p.e20 / p.e12, p.e01 / p.e12];
        assert!((got[0] - want[0]).abs() < EPS && (got[1] - want[1]).abs() < EPS, "got {got:?}, want {want:?}");
    }

    /// The line a x + b y + c = 0, its normal (a, b) of unit length.
    fn line(a: f64, b: f64, c: f64) -> Line {
        let n = (a * a + b * b).sqrt();
        Line { e1: a / n, e2: b / n, e0: c / n }
    }

    #[test]
    fn two_lines_meet_in_a_point_and_two_points_join_in_a_line() {
        // x = 1 and y = 2 meet at (1, 2): (e1 − e0) ∧ (e2 − 2 e0) = e12 + 2 e01 + e20.
        let p = line(1.0, 0.0, -1.0) ^ line(0.0, 1.0, -2.0);
        assert_eq!((p.e12, p.e20, p.e01), (1.0, 1.0, 2.0));
        // x + y = 3 and x − y = 1 meet at (2, 1).
        assert_at(line(1.0, 1.0, -3.0) ^ line(1.0, -1.0, -1.0), [2.0, 1.0]);
        // The join of (0, 1) and (1, 2) is y = x + 1: −x + y − 1 = 0, up to a factor.
        let l: Line = point(0.0, 1.0) & point(1.0, 2.0);
        assert!(l.e2.abs() > 0.5);
        assert!((l.e1 / l.e2 + 1.0).abs() < EPS && (l.e0 / l.e2 + 1.0).abs() < EPS);
        // A point on a line: P & L = 0 (a scalar, in the Motor: the smallest type holding s).
        assert!((point(4.0, 5.0) & l).s.abs() < EPS);
        assert!((point(4.0, 4.0) & l).s.abs() > 0.5);
    }

    #[test]
    fn two_reflections_translate_and_rotate() {
        // Reflections in x = 0, then x = 1: a translation by 2 along x.
        let shift: Motor = line(1.0, 0.0, -1.0) * line(1.0, 0.0, 0.0);
        assert_at(shift.sandwich(point(0.3, 0.5)), [2.3, 0.5]);
        // In x = 0 (normal (1, 0)), then the line through the origin of normal (1, 1)/√2:
        // twice 45°, a quarter turn counter-clockwise: (1, 0) → (0, 1), (2, 3) → (−3, 2).
        let turn: Motor = line(1.0, 1.0, 0.0) * line(1.0, 0.0, 0.0);
        assert_at(turn.sandwich(point(1.0, 0.0)), [0.0, 1.0]);
        assert_at(turn.sandwich(point(2.0, 3.0)), [-3.0, 2.0]);
        // Composed right to left: turn, then shift: (1, 0) → (0, 1) → (2, 1).
        assert_at((shift * turn).sandwich(point(1.0, 0.0)), [2.0, 1.0]);
        // A single line reflects: x = 1 takes (3, 7) to (−1, 7).
        assert_at(line(1.0, 0.0, -1.0).sandwich(point(3.0, 7.0)), [-1.0, 7.0]);
        // exp of b e12: cos b + sin b e12 (e12² = −1); exp of t e01: 1 + t e01 (e01² = 0).
        let r: Motor = Point { e12: 0.3, e20: 0.0, e01: 0.0 }.exp();
        assert!((r.s - 0.3f64.cos()).abs() < EPS && (r.e12 - 0.3f64.sin()).abs() < EPS);
        let t: Motor = Point { e12: 0.0, e20: 0.0, e01: 0.7 }.exp();
        assert_eq!((t.s, t.e01, t.e20, t.e12), (1.0, 0.7, 0.0, 0.0));
    }

    struct Apply;
    impl Kernel for Apply {
        type Input = (Motor, Point);
        type Output = Point;
        #[inline(always)]
        fn apply<L: Lane>(&self, (m, p): (gx::Motor<L>, gx::Point<L>)) -> gx::Point<L> {
            m.sandwich(p)
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

    #[test]
    fn batches_and_prepared_sandwiches() {
        let n = 19;
        let turn: Motor = line(1.0, 1.0, 0.0) * line(1.0, 0.0, 0.0); // a quarter turn
        let points: Vec<Point> = (0..n).map(|k| point(k as f64, 1.0 - 0.5 * k as f64)).collect();
        let want = |p: &Point| [-p.e01, p.e20]; // (x, y) → (−y, x)
        // Prepared, one motor on many points.
        let prepared = turn.prepare().apply_to(&points);
        // run over (motor, point) pairs; run_columns over the same in two arrays.
        let motors = vec![turn; n];
        let input: Vec<(Motor, Point)> = motors.iter().copied().zip(points.iter().copied()).collect();
        let mut by_run = vec![Point::zero(); n];
        run(&Apply, &input, &mut by_run).unwrap();
        let mut by_columns = vec![Point::zero(); n];
        run_columns(&Apply, (&motors[..], &points[..]), &mut by_columns).unwrap();
        // map with the motor splat into four lanes.
        let lanes = splat::<Motor, F64x4>(turn);
        let mut by_map = vec![Point::zero(); n];
        map(
            &points,
            &mut by_map,
            #[inline(always)]
            |p: gx::Point<F64x4>| lanes.sandwich(p),
        )
        .unwrap();
        for k in 0..n {
            let one = turn.sandwich(points[k]);
            assert_eq!(by_run[k], one);
            assert_eq!(by_columns[k], one);
            assert_eq!(by_map[k], one);
            assert_at(one, want(&points[k]));
            assert_at(prepared[k], want(&points[k]));
        }
        // Joins in a batch: each line through (k, ·) and the origin-shifted copy.
        let others: Vec<Point> = points.iter().map(|p| point(p.e20 + 1.0, p.e01 + 1.0)).collect();
        let mut joins = vec![Line::zero(); n];
        run_columns(&Join, (&points[..], &others[..]), &mut joins).unwrap();
        for k in 0..n {
            assert_eq!(joins[k], points[k] & others[k]);
            // Direction (1, 1): the line's normal (e1, e2) is ±(1, −1)/√2 times its weight.
            assert!((joins[k].e1 + joins[k].e2).abs() < EPS && joins[k].e1.abs() > 0.5);
        }
    }
}

/// Generic code over an algebra's types through the generated `Blades` trait: each type's
/// blades and coefficients, as its own `BLADES` and `to_array` give them.
fn named<X: g3::Blades<Coefficient = f64>>(x: X) -> Vec<(&'static str, f64)> {
    X::NAMES.iter().copied().zip(x.coefficients()).collect()
}

#[test]
fn every_type_names_its_blades_through_one_trait() {
    let r = turn_xy(0.5);
    assert_eq!(named(r), Rotor::BLADES.iter().copied().zip(r.to_array()).collect::<Vec<_>>());
    assert_eq!(named(vector(1.0, 2.0, 3.0)), [("e1", 1.0), ("e2", 2.0), ("e3", 3.0)]);
    assert_eq!(named(Trivector::from_array([4.0])), [("e123", 4.0)]);
    // The CGA types too: `Display` of any type falls back on them.
    let c = cga_core::Circle::<f64>::zero();
    assert_eq!(<cga_core::Circle as cga_core::Blades>::NAMES, &cga_core::Circle::<f64>::BLADES[..]);
    assert_eq!(cga_core::Blades::coefficients(c).count(), cga_core::Circle::<f64>::BLADES.len());
}
