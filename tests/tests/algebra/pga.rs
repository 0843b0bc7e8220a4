//! A degenerate metric: 3D projective geometric algebra G(3,0,1) as `cga_algebras::pga`
//! declares it (`signature = (3, 0, 1)`, the null vector renamed `e0` and listed first). Its
//! generated maps are checked against its dense type and kingdon, and its geometry against
//! Euclidean formulas:
//! a plane `a e1 + b e2 + c e3 + d e0` is `a x + b y + c z + d = 0`, a point `(x, y, z)` is
//! `e123 + x e032 + y e013 + z e021`, the blades spelled as bivector.net spells them (`e031 =
//! −e013`…): kingdon's canonical coefficients are carried over with each blade's sign.

use cga_tests::common;

use common::{PGA_STORAGE as STORAGE, max_rel_diff};
use proptest::prelude::*;

use cga_algebras::pga;
use pga::{
    CommutatorProduct, GeometricProduct, InnerProduct, LeftContraction, Multivector, OuterProduct, Plane, Point,
    ProductKind, RegressiveProduct, RightContraction, UnaryKind,
};

/// The point `(x, y, z)`.
fn point(x: [f64; 3]) -> Point<f64> {
    Point::at(x)
}

/// The plane `a x + b y + c z + d = 0`.
fn plane([a, b, c, d]: [f64; 4]) -> Plane<f64> {
    Plane::new(a, b, c, d)
}

fn dense(c: &[f64; 16]) -> Multivector<f64> {
    Multivector::from_storage(c)
}

fn dense_product(kind: ProductKind, a: Multivector<f64>, b: Multivector<f64>) -> Multivector<f64> {
    match kind {
        ProductKind::Geometric => a.gp(b),
        ProductKind::Outer => a.wedge(b),
        ProductKind::Inner => a.inner(b),
        ProductKind::LeftContraction => a.lc(b),
        ProductKind::RightContraction => a.rc(b),
        ProductKind::Regressive => a.vee(b),
        ProductKind::Commutator => a.commutator(b),
        ProductKind::ScalarProduct => a.gp(b).grade(0),
        ProductKind::Sandwich => a.sandwich(&b),
    }
}

/// The grade of the blade at canonical position `i` (1, 4, 6, 4, 1 blades by grade).
fn grade_at(i: usize) -> usize {
    [0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 4][i]
}

fn restrict(c: &[f64; 16], blades: &[usize]) -> [f64; 16] {
    let mut out = [0.0; 16];
    for &i in blades {
        out[i] = c[i];
    }
    out
}

#[test]
fn the_null_vector_squares_to_zero_and_the_others_to_one() {
    let e = |k: usize| {
        let mut c = [0.0; 16];
        c[1 + k] = 1.0;
        dense(&c)
    };
    assert_eq!(e(0).gp(e(0)).to_storage(), [0.0; 16], "e0² = 0");
    for k in 1..4 {
        let mut one = [0.0; 16];
        one[0] = 1.0;
        assert_eq!(e(k).gp(e(k)).to_storage(), one, "e{k}² = 1");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn every_product_equals_the_dense_product(
        a in prop::array::uniform16(-2.0f64..2.0),
        b in prop::array::uniform16(-2.0f64..2.0),
    ) {
        let mut checked = 0;
        for e in pga::product_table::<f64>() {
            let (ra, rb) = (restrict(&a, e.lhs_blades), restrict(&b, e.rhs_blades));
            let mut want = dense_product(e.kind, dense(&ra), dense(&rb)).to_storage();
            if e.kind == ProductKind::Sandwich {
                let grades: Vec<usize> = e.rhs_blades.iter().map(|&i| grade_at(i)).collect();
                let keep: Vec<usize> = (0..16).filter(|&i| grades.contains(&grade_at(i))).collect();
                want = restrict(&want, &keep);
            }
            let got = (e.eval)(&a, &b);
            let d = max_rel_diff(&got, &want);
            prop_assert!(d <= 1e-12, "{:?} {} x {} -> {}: differs by {d:e}", e.kind, e.lhs, e.rhs, e.output);
            checked += 1;
        }
        prop_assert!(checked > 100, "only {checked} products generated");
    }

    #[test]
    fn every_unary_map_equals_the_dense_map(a in prop::array::uniform16(-2.0f64..2.0)) {
        for e in pga::unary_table::<f64>() {
            let eval = e.eval;
            let x = dense(&restrict(&a, e.input_blades));
            let want = match e.kind {
                UnaryKind::Dual => x.dual(),
                UnaryKind::Undual => x.undual(),
                UnaryKind::Reverse => x.reverse(),
                _ => continue,
            };
            let got = eval(&restrict(&a, e.input_blades));
            let d = max_rel_diff(&got, &want.to_storage());
            prop_assert!(d <= 1e-12, "{:?} of {}: differs by {d:e}", e.kind, e.input);
        }
    }

    /// The dual is the right complement: `e_S ∧ ∁e_S` is the same pseudoscalar for every
    /// blade, the undual inverts it, and the regressive product is `∁⁻¹(∁A ∧ ∁B)`.
    #[test]
    fn the_dual_is_a_complement_and_the_regressive_product_its_dual(
        a in prop::array::uniform16(-2.0f64..2.0),
        b in prop::array::uniform16(-2.0f64..2.0),
    ) {
        let mut pseudoscalar = None;
        for k in 0..16 {
            let mut c = [0.0; 16];
            c[k] = 1.0;
            let blade = dense(&c);
            let i = blade.wedge(blade.dual()).to_storage();
            prop_assert_eq!(i[..15].iter().map(|x| x.abs()).sum::<f64>(), 0.0, "blade {}", k);
            prop_assert_eq!(i[15].abs(), 1.0);
            prop_assert_eq!(*pseudoscalar.get_or_insert(i[15]), i[15], "blade {}", k);
        }
        let (a, b) = (dense(&a), dense(&b));
        prop_assert!(max_rel_diff(&a.dual().undual().to_storage(), &a.to_storage()) <= 1e-15);
        let vee = a.dual().wedge(b.dual()).undual();
        prop_assert!(max_rel_diff(&a.vee(b).to_storage(), &vee.to_storage()) <= 1e-12);
    }

    /// `Π ∧ P` is the signed distance `a x + b y + c z + d` of the point from the plane (unit
    /// normal) times the pseudoscalar; zero exactly when the point lies on the plane.
    #[test]
    fn a_plane_wedge_a_point_is_the_signed_distance(
        x in prop::array::uniform3(-10.0f64..10.0),
        n in prop::array::uniform3(-1.0f64..1.0),
        d in -5.0f64..5.0,
    ) {
        let norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        prop_assume!(norm > 0.1);
        let [a, b, c] = n.map(|v| v / norm);
        let distance = a * x[0] + b * x[1] + c * x[2] + d;
        let got = plane([a, b, c, d]).wedge(point(x)).e0123;
        prop_assert!((got.abs() - distance.abs()).abs() <= 1e-12 * (1.0 + distance.abs()), "{got} vs {distance}");
        prop_assert!(got * distance >= 0.0 || distance.abs() < 1e-12, "one sign for one side");
    }

    /// The join `P ∨ Q` of two points holds every point of the segment between them and
    /// no point off the line; the meet `Π₁ ∧ Π₂` of two planes holds the points on both.
    #[test]
    fn joins_and_meets_hold_the_right_points(
        p in prop::array::uniform3(-5.0f64..5.0),
        q in prop::array::uniform3(-5.0f64..5.0),
        t in 0.0f64..1.0,
    ) {
        let gap = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
        prop_assume!(gap > 0.5);
        let line = point(p).vee(point(q));
        let on = point([0, 1, 2].map(|k| p[k] + t * (q[k] - p[k])));
        let off = point([p[0] + 1.0, p[1] - 2.0 * (q[2] - p[2]), p[2] + 2.0 * (q[1] - p[1])]);
        let (on, off) = (line.vee(on).e0, line.vee(off).to_array().map(f64::abs).into_iter().sum::<f64>());
        prop_assert!(on.abs() <= 1e-10 && off > 1e-6, "on {on:e}, off {off:e}");
        // Two planes through p, x = p.x and y = p.y: their line holds p and p + z e3 (its
        // join with them vanishes) and not p + e1.
        let meet = plane([1.0, 0.0, 0.0, -p[0]]).wedge(plane([0.0, 1.0, 0.0, -p[1]]));
        let size = |x: Plane<f64>| x.to_array().map(f64::abs).into_iter().sum::<f64>();
        for z in [0.0, 3.0, -7.5] {
            let w = size(meet.vee(point([p[0], p[1], p[2] + z])));
            prop_assert!(w <= 1e-12, "{w:e}");
        }
        prop_assert!(size(meet.vee(point([p[0] + 1.0, p[1], p[2]]))) > 0.5);
    }

    /// Bulk and weight norms, by their Euclidean meaning: a plane `a x + b y + c z + d = 0`
    /// has bulk `√(a² + b² + c²)` and weight `|d|`; a point `w (x, y, z)` (homogeneous) has
    /// bulk `|w|` and weight `|w| √(x² + y² + z²)`, its distance from the origin times `|w|`.
    #[test]
    fn bulk_and_weight_norms_are_the_euclidean_ones(
        c in prop::array::uniform4(-3.0f64..3.0),
        x in prop::array::uniform3(-10.0f64..10.0),
        w in 0.1f64..4.0,
    ) {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + b.abs());
        let pi = plane(c);
        let normal = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
        prop_assert!(close(pi.bulk_norm(), normal) && close(pi.norm(), normal));
        prop_assert!(close(pi.weight_norm(), c[3].abs()), "{} vs {}", pi.weight_norm(), c[3]);
        let p = point(x).scale(w);
        let distance = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        prop_assert!(close(p.bulk_norm(), w));
        prop_assert!(close(p.weight_norm(), w * distance), "{} vs {}", p.weight_norm(), w * distance);
    }
}

/// The commutator, inner product and left contraction of the degenerate algebra also drop
/// every term through `e0²`: `e0 · e0 = 0` and `e01 × e0 = 0`.
#[test]
fn products_through_the_null_vector_vanish() {
    let e0 = Plane { e0: 1.0, e1: 0.0, e2: 0.0, e3: 0.0 };
    assert_eq!(e0.inner(e0).s, 0.0);
    assert_eq!(e0.lc(e0).s, 0.0);
    let mut c = [0.0; 16];
    c[5] = 1.0; // e01
    let e01 = dense(&c);
    let mut v = [0.0; 16];
    v[1] = 1.0;
    assert_eq!(e01.commutator(dense(&v)).to_storage(), [0.0; 16]);
}

/// `tests/data/kingdon_pga.json` (made by `tools/kingdon_pga.py`, kingdon 3.0.0), in
/// canonical blade order.
fn kingdon() -> serde_json::Value {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/kingdon_pga.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let value: serde_json::Value = serde_json::from_str(&text).expect("kingdon_pga.json parses");
    let blades: Vec<&str> = value["blades"].as_array().expect("blades").iter().map(|b| b.as_str().unwrap()).collect();
    assert_eq!(blades, CANONICAL, "kingdon_pga.json: blade order differs from ours");
    value
}

/// The blades in canonical order (`e` the scalar, as kingdon names them).
const CANONICAL: [&str; 16] =
    ["e", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e13", "e23", "e012", "e013", "e023", "e123", "e0123"];

#[test]
fn the_storage_order_is_the_canonical_one_with_the_declared_spellings() {
    let at = |c: [f64; 16]| c.iter().position(|&x| x != 0.0).map(|k| (STORAGE[k].0, c[k]));
    assert_eq!(at(Plane { e0: 1.0, e1: 0.0, e2: 0.0, e3: 0.0 }.to_storage()), Some(("e0", 1.0)));
    assert_eq!(at(Point { e021: 0.0, e013: 1.0, e032: 0.0, e123: 0.0 }.to_storage()), Some(("e013", 1.0)));
    assert_eq!(at(Point { e021: 0.0, e013: 0.0, e032: 2.0, e123: 0.0 }.to_storage()), Some(("e032", 2.0)));
    assert_eq!(at(pga::Pseudoscalar { e0123: 1.0 }.to_storage()), Some(("e0123", 1.0)));
    assert_eq!(pga::Line::<f64>::BLADES, ["e01", "e02", "e03", "e12", "e31", "e23"]);
    assert_eq!(Point::<f64>::BLADES, ["e021", "e013", "e032", "e123"]);
}

/// `e3 ∧ e1 = e31` and `e1 ∧ e3 = −e31`; `e0 ∧ e2 ∧ e1 = e021`, `e0 ∧ e3 ∧ e2 = e032`: each
/// field holds the blade as spelled.
#[test]
fn spelled_blades_carry_their_sign() {
    let e = |k: usize| {
        let mut c = [0.0; 4];
        c[k] = 1.0;
        Plane { e0: c[0], e1: c[1], e2: c[2], e3: c[3] }
    };
    assert_eq!((e(3) ^ e(1)).e31, 1.0);
    assert_eq!((e(1) ^ e(3)).e31, -1.0);
    assert_eq!((e(0) ^ e(2) ^ e(1)).e021, 1.0);
    assert_eq!((e(0) ^ e(3) ^ e(2)).e032, 1.0);
    assert_eq!((e(0) ^ e(1) ^ e(3)).e013, 1.0);
    // The dense type is orthonormal (e4 = e0): e31 = −e13 there, in its e13 slot.
    let line = pga::Line { e01: 0.0, e02: 0.0, e03: 0.0, e12: 0.0, e31: 1.0, e23: 0.0 };
    let d = dense(&line.to_storage());
    let e13 = Multivector::<f64>::BLADES.iter().position(|&b| b == "e13").unwrap();
    assert_eq!(d.coeffs[e13], -1.0);
}

/// A list of numbers from the golden file.
fn coeffs<const N: usize>(v: &serde_json::Value) -> [f64; N] {
    let list = v.as_array().expect("a list of numbers");
    core::array::from_fn(|k| list[k].as_f64().expect("a number"))
}

/// Kingdon's canonical coefficients in our storage basis: each times its spelling's sign.
fn ours(v: &serde_json::Value) -> [f64; 16] {
    let c: [f64; 16] = coeffs(v);
    core::array::from_fn(|k| c[k] * STORAGE[k].1)
}

/// Every product, the dual (right complement against `e0123`) and the undual agree with
/// kingdon to rounding (both f64, coefficients of magnitude ≤ 2: 1e-12 relative).
#[test]
fn the_dense_type_agrees_with_kingdon() {
    let data = kingdon();
    let cases = data["cases"].as_array().expect("cases");
    for (n, case) in cases.iter().enumerate() {
        let (a, b) = (dense(&ours(&case["a"])), dense(&ours(&case["b"])));
        for (key, got) in [
            ("gp", a.gp(b)),
            ("op", a.wedge(b)),
            ("lc", a.lc(b)),
            ("rc", a.rc(b)),
            ("rp", a.vee(b)),
            ("dual", a.dual()),
            ("undual", a.undual()),
        ] {
            let want = ours(&case[key]);
            let d = max_rel_diff(&got.to_storage(), &want);
            assert!(d <= 1e-12, "case {n}: {key} differs from kingdon's by {d:e}");
        }
    }
    assert_eq!(cases.len(), 40);
}

/// The join of two points and the meet of two planes, on the sparse types, as kingdon
/// gives them.
#[test]
fn joins_and_meets_agree_with_kingdon() {
    let data = kingdon();
    for case in data["joins"].as_array().expect("joins") {
        let line = point(coeffs(&case["p"])).vee(point(coeffs(&case["q"])));
        let want = ours(&case["join"]);
        let d = max_rel_diff(&line.to_storage(), &want);
        assert!(d <= 1e-12, "join differs by {d:e}");
    }
    for case in data["meets"].as_array().expect("meets") {
        let line = plane(coeffs(&case["m"])).wedge(plane(coeffs(&case["n"])));
        let want = ours(&case["meet"]);
        let d = max_rel_diff(&line.to_storage(), &want);
        assert!(d <= 1e-12, "meet differs by {d:e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// The shipped projections against Euclid: onto the plane `n·x + d = 0` (unit n) the
    /// point goes to `x − (n·x + d) n`; onto the line through `p` along unit `u`, to
    /// `p + ((x − p)·u) u`.
    #[test]
    fn projections_are_the_euclidean_ones(
        x in prop::array::uniform3(-10.0f64..10.0),
        p in prop::array::uniform3(-5.0f64..5.0),
        n in prop::array::uniform3(-1.0f64..1.0),
        d in -5.0f64..5.0,
    ) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        prop_assume!(len > 0.2);
        let u = n.map(|c| c / len);
        let dist = u[0] * x[0] + u[1] * x[1] + u[2] * x[2] + d;
        let want: [f64; 3] = core::array::from_fn(|k| x[k] - dist * u[k]);
        let got = point(x).project_onto_plane(plane([u[0], u[1], u[2], d])).position().unwrap();
        prop_assert!(max_rel_diff(&got, &want) <= 1e-12, "{got:?} vs {want:?}");
        let q: [f64; 3] = core::array::from_fn(|k| p[k] + 2.0 * u[k]);
        let line = point(p).vee(point(q));
        let along = (0..3).map(|k| (x[k] - p[k]) * u[k]).sum::<f64>();
        let want: [f64; 3] = core::array::from_fn(|k| p[k] + along * u[k]);
        let got = point(x).project_onto_line(line).position().unwrap();
        prop_assert!(max_rel_diff(&got, &want) <= 1e-11, "{got:?} vs {want:?}");
    }

    /// The product `q p` of two parallel planes `x = 0` and `x = h` is a translation by `2h`
    /// along x, applied by the motor's sandwich.
    #[test]
    fn two_parallel_planes_make_a_translation(x in prop::array::uniform3(-10.0f64..10.0), h in -3.0f64..3.0) {
        use pga::Sandwich;
        let m: pga::Motor<f64> = plane([1.0, 0.0, 0.0, -h]) * plane([1.0, 0.0, 0.0, 0.0]);
        let got = m.sandwich(point(x)).position().unwrap();
        let want = [x[0] + 2.0 * h, x[1], x[2]];
        prop_assert!(max_rel_diff(&got, &want) <= 1e-12, "{got:?} vs {want:?}");
    }
}
