//! The shipped algebras of `cga-algebras` besides PGA (tests/tests/algebra/pga.rs) and G(9,1)
//! (tests/tests/algebra/dimension.rs): 2D CGA G(3,1), the spacetime algebra G(1,3) and the
//! vector algebra G(3) (its products against kingdon in python/tests/test_vga.py). Each dense
//! type against kingdon 3.0.0 (`tools/kingdon_dense.py` → `tests/data/kingdon_dense.json`),
//! each generated map against the dense type, and the geometry against Euclidean and
//! Minkowski formulas.

use cga_tests::common;

use cga_algebras::{cga2, sta};
use common::max_rel_diff;
use proptest::prelude::*;

fn kingdon(name: &str) -> Vec<serde_json::Value> {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/kingdon_dense.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let data: serde_json::Value = serde_json::from_str(&text).expect("kingdon_dense.json parses");
    data[name]["cases"].as_array().expect("cases").clone()
}

fn list(v: &serde_json::Value) -> [f64; 16] {
    let list = v.as_array().expect("a list of numbers");
    core::array::from_fn(|k| list[k].as_f64().expect("a number"))
}

/// Both dense types against kingdon: every product, the dual `A I⁻¹` and the undual, in the
/// orthonormal basis. Coefficients ≤ 2, 16 terms at most per blade: 1e-12 relative.
macro_rules! dense_against_kingdon {
    ($test:ident, $alg:ident, $name:literal) => {
        #[test]
        fn $test() {
            use $alg::{
                GeometricProduct, LeftContraction, Multivector, OuterProduct, RegressiveProduct, RightContraction,
            };
            let cases = kingdon($name);
            assert_eq!(cases.len(), 30);
            for (n, case) in cases.iter().enumerate() {
                let (a, b) = (Multivector::new(list(&case["a"])), Multivector::new(list(&case["b"])));
                for (key, got) in [
                    ("gp", a.gp(b)),
                    ("op", a.wedge(b)),
                    ("lc", a.lc(b)),
                    ("rc", a.rc(b)),
                    ("rp", a.vee(b)),
                    ("dual", a.dual()),
                    ("undual", a.undual()),
                ] {
                    let d = max_rel_diff(&got.coeffs, &list(&case[key]));
                    assert!(d <= 1e-12, "{} case {n}: {key} differs from kingdon's by {d:e}", $name);
                }
            }
        }
    };
}

dense_against_kingdon!(cga2_dense_type_agrees_with_kingdon, cga2, "cga2");
dense_against_kingdon!(sta_dense_type_agrees_with_kingdon, sta, "sta");

/// Every generated product of both algebras equals its dense type's, on random operands.
macro_rules! sparse_against_dense {
    ($test:ident, $alg:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            #[test]
            fn $test(a in prop::array::uniform16(-2.0f64..2.0), b in prop::array::uniform16(-2.0f64..2.0)) {
                use $alg::{
                    CommutatorProduct, GeometricProduct, InnerProduct, LeftContraction, Multivector, OuterProduct,
                    ProductKind, RegressiveProduct, RightContraction,
                };
                let restrict = |c: &[f64; 16], blades: &[usize]| {
                    let mut out = [0.0; 16];
                    for &i in blades {
                        out[i] = c[i];
                    }
                    out
                };
                let mut checked = 0;
                for e in $alg::product_table::<f64>() {
                    if e.kind == ProductKind::Sandwich {
                        continue;
                    }
                    let (ra, rb) = (restrict(&a, e.lhs_blades), restrict(&b, e.rhs_blades));
                    let (x, y) = (Multivector::from_storage(&ra), Multivector::from_storage(&rb));
                    let want = match e.kind {
                        ProductKind::Geometric => x.gp(y),
                        ProductKind::Outer => x.wedge(y),
                        ProductKind::Inner => x.inner(y),
                        ProductKind::LeftContraction => x.lc(y),
                        ProductKind::RightContraction => x.rc(y),
                        ProductKind::Regressive => x.vee(y),
                        ProductKind::Commutator => x.commutator(y),
                        ProductKind::ScalarProduct => x.gp(y).grade(0),
                        ProductKind::Sandwich => unreachable!(),
                    };
                    let d = max_rel_diff(&(e.eval)(&a, &b), &want.to_storage());
                    prop_assert!(d <= 1e-12, "{:?} {} x {}: differs by {d:e}", e.kind, e.lhs, e.rhs);
                    checked += 1;
                }
                prop_assert!(checked > 50, "only {checked} products");
            }
        }
    };
}

sparse_against_dense!(cga2_products_equal_the_dense_products, cga2);
sparse_against_dense!(sta_products_equal_the_dense_products, sta);

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// 2D CGA: points are null, `X · Y = −½|x − y|²`, the circle through three points holds
    /// a fourth on it (`X ∧ C = 0`) and not one off it, and a translator moves points.
    #[test]
    fn cga2_points_circles_and_translations_are_euclidean(
        c in prop::array::uniform2(-5.0f64..5.0),
        r in 0.5f64..4.0,
        angles in prop::array::uniform4(0.0f64..std::f64::consts::TAU),
        t in prop::array::uniform2(-3.0f64..3.0),
    ) {
        use cga2::{InnerProduct, Sandwich, Vector};
        let on = |a: f64| Vector::up([c[0] + r * a.cos(), c[1] + r * a.sin()]);
        let [p, q, s, u] = angles.map(on);
        prop_assert!(p.inner(p).s.abs() <= 1e-12 * (1.0 + 25.0), "a point is null");
        let (x, y) = (p.down().unwrap(), q.down().unwrap());
        let d2 = (x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2);
        prop_assert!((p.inner(q).s + 0.5 * d2).abs() <= 1e-12 * (1.0 + d2));
        let gaps = [(angles[0], angles[1]), (angles[0], angles[2]), (angles[1], angles[2])];
        prop_assume!(gaps.iter().all(|(a, b)| (a - b).abs() > 0.2 && (a - b).abs() < std::f64::consts::TAU - 0.2));
        let circle = p ^ q ^ s;
        let scale = circle.to_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
        let through = (u ^ circle).e12oi.abs() / scale;
        prop_assert!(through <= 1e-10, "{through:e}");
        let off = Vector::up([c[0] + 1.5 * r, c[1]]);
        prop_assert!((off ^ circle).e12oi.abs() / scale > 1e-3);
        // T = 1 − ½ t ei moves X by t.
        let translator = cga2::Motor { s: 1.0, e12: 0.0, e1i: -0.5 * t[0], e2i: -0.5 * t[1] };
        let moved = translator.sandwich(p).down().unwrap();
        prop_assert!((moved[0] - x[0] - t[0]).abs() <= 1e-10 && (moved[1] - x[1] - t[1]).abs() <= 1e-10);
    }

    /// STA: a boost `R = cosh(φ/2) + sinh(φ/2) e01` keeps the interval `v²` and takes the rest
    /// frame's `γ0` to `cosh φ γ0 + sinh φ γ1` (the four-velocity of rapidity φ along x).
    #[test]
    fn sta_boosts_keep_the_interval(v in prop::array::uniform4(-3.0f64..3.0), phi in -2.0f64..2.0) {
        use sta::{Rotor, Sandwich, Vector};
        let mut r = Rotor::<f64>::default();
        (r.s, r.e01) = ((phi / 2.0).cosh(), (phi / 2.0).sinh());
        let x = Vector { e0: v[0], e1: v[1], e2: v[2], e3: v[3] };
        let interval = (x * x).s;
        prop_assert!((interval - (v[0] * v[0] - v[1] * v[1] - v[2] * v[2] - v[3] * v[3])).abs() <= 1e-12 * 40.0);
        let y = r.sandwich(x);
        prop_assert!(((y * y).s - interval).abs() <= 1e-11 * (1.0 + 40.0 * phi.cosh().powi(2)));
        let g0 = r.sandwich(Vector { e0: 1.0, e1: 0.0, e2: 0.0, e3: 0.0 });
        let (ch, sh) = (phi.cosh(), phi.sinh());
        prop_assert!((g0.e0 - ch).abs() <= 1e-12 * ch && (g0.e1.abs() - sh.abs()).abs() <= 1e-12 * ch);
        prop_assert!(g0.e2 == 0.0 && g0.e3 == 0.0);
    }

    /// VGA: `Rotor::from_axis_angle` turns a vector as Rodrigues' formula does, and a vector
    /// squares to its length².
    #[test]
    fn vga_rotors_are_rodrigues(n in prop::array::uniform3(-2.0f64..2.0), x in prop::array::uniform3(-3.0f64..3.0), angle in -3.0f64..3.0) {
        use cga_algebras::vga::{GeometricProduct, Rotor, Sandwich, Vector};
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        prop_assume!(len > 1e-3);
        let u = n.map(|c| c / len);
        let r = Rotor::from_axis_angle(n, angle).unwrap();
        let y = r.sandwich(Vector { e1: x[0], e2: x[1], e3: x[2] });
        let (c, s) = (angle.cos(), angle.sin());
        let dot = u[0] * x[0] + u[1] * x[1] + u[2] * x[2];
        let cross = [u[1] * x[2] - u[2] * x[1], u[2] * x[0] - u[0] * x[2], u[0] * x[1] - u[1] * x[0]];
        let want: [f64; 3] = core::array::from_fn(|k| x[k] * c + cross[k] * s + u[k] * dot * (1.0 - c));
        for (got, want) in [y.e1, y.e2, y.e3].into_iter().zip(want) {
            prop_assert!((got - want).abs() <= 1e-13 * 6.0, "{got} against {want}");
        }
        let v = Vector { e1: x[0], e2: x[1], e3: x[2] };
        prop_assert!((v.gp(v).s - (x[0] * x[0] + x[1] * x[1] + x[2] * x[2])).abs() <= 1e-15 * 30.0);
    }
}

#[test]
fn vga_refuses_a_zero_or_unfinite_axis() {
    use cga_algebras::vga::Rotor;
    assert!(Rotor::from_axis_angle([0.0, 0.0, 0.0], 1.0).is_none());
    assert!(Rotor::<f64>::from_axis_angle([f64::NAN, 0.0, 1.0], 1.0).is_none());
    assert!(Rotor::<f64>::from_axis_angle([f64::INFINITY, 0.0, 1.0], 1.0).is_none());
}

mod quaternions {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (0, 2);
        /// `a + b e1 + c e2 + d e12`, every basis element squaring to −1: the quaternions.
        type Quaternion = [s, e1, e2, e12];
    }
}

/// The example: `⟨q q̃⟩₀` of `1 + 2 e1 + 3 e2 + 4 e12` in G(0,2) is 4, the magnitude
/// `Σ c²` is 30.
#[test]
fn magnitude_is_positive_definite_where_the_norm_is_not() {
    let q = quaternions::Quaternion { s: 1.0, e1: 2.0, e2: 3.0, e12: 4.0 };
    assert_eq!(q.norm_squared(), 4.0);
    assert_eq!(q.magnitude_squared(), 30.0);
    assert_eq!(q.magnitude(), 30f64.sqrt());
}
