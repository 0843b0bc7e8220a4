//! The generated `Exp`, `Log` and `Inverse`, in three metrics at once: G(2,1), whose
//! bivectors are rotations (`e12² = −1`), boosts (`e13² = e23² = +1`) and translations
//! (`(e12 + e13)² = 0`); STA and PGA from `cga-algebras`; cga-core's G(4,1). References:
//! kingdon 3.0.0's `exp` (`tools/kingdon_exp.py`), the exponential series summed on the dense
//! type, `exp(log R) = R`, Euclidean rotation and Minkowski boost formulas, and `X X⁻¹ = 1`.

use cga_tests::common;

use common::max_rel_diff;
use proptest::prelude::*;

mod g21 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (2, 1);
        /// All 8 coefficients.
        dense Multivector;
        /// A vector.
        versor Vector = [grade(1)];
        /// A bivector: every one is simple in three dimensions.
        type Bivector = [grade(2)];
        /// A rotor: rotation, boost or null rotation.
        versor Rotor = [s, grade(2)];
    }
}

use g21::{Exp, GeometricProduct, Log, LogError};

/// `Σ Bᵏ/k!` on the dense type, 60 terms (|B| ≤ 4: the last is below 1e-40 of the sum).
macro_rules! series {
    ($dense:ty, $b:expr, $n:expr) => {{
        let b = <$dense>::from_storage(&$b.to_storage());
        let mut one = [0.0; $n];
        one[0] = 1.0;
        let mut term = <$dense>::from_storage(&one);
        let mut sum = term;
        for k in 1..60 {
            term = term.gp(b).scale(1.0 / k as f64);
            sum = sum + term;
        }
        sum.to_storage()
    }};
}

fn bivector([a, b, c]: [f64; 3]) -> g21::Bivector {
    g21::Bivector { e12: a, e13: b, e23: c }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// `exp B` in closed form is the series, whatever the sign of `B²`.
    #[test]
    fn exp_is_the_series_in_every_metric(c in prop::array::uniform3(-2.0f64..2.0)) {
        let b = bivector(c);
        let got = b.exp().to_storage();
        let want = series!(g21::Multivector, b, 8);
        prop_assert!(max_rel_diff(&got, &want) <= 1e-13, "{got:?} vs {want:?}");
    }

    /// `log(exp B) = B` where `B` is the principal logarithm: boosts and translations always,
    /// rotations by less than π (`|e12|` part of a rotation-type `B` below π).
    #[test]
    fn log_inverts_exp(c in prop::array::uniform3(-2.0f64..2.0)) {
        let b = bivector(c);
        let beta = b.gp(b);
        prop_assume!(beta.s > -9.0);
        let back = b.exp().log().unwrap();
        prop_assert!(max_rel_diff(&back.to_storage(), &b.to_storage()) <= 1e-12, "{back:?} vs {b:?}");
        let again = back.exp().to_storage();
        prop_assert!(max_rel_diff(&again, &b.exp().to_storage()) <= 1e-13);
    }

    /// `log` is the inverse of `exp` on every rotor of the form `±exp B` it accepts, and
    /// refuses the rest by name.
    #[test]
    fn log_of_a_rotor_exponentiates_back(c in prop::array::uniform3(-3.0f64..3.0), flip in any::<bool>()) {
        let r = bivector(c).exp() * if flip { -1.0 } else { 1.0 };
        match r.log() {
            Ok(b) => {
                let d = max_rel_diff(&b.exp().to_storage(), &r.to_storage());
                prop_assert!(d <= 1e-12, "exp(log R) off by {d:e}");
            }
            Err(LogError::NoLogarithm { type_name }) => {
                prop_assert_eq!(type_name, "Rotor");
                prop_assert!(flip && r.s <= 0.0 && bivector(c).gp(bivector(c)).s >= 0.0, "{r:?}");
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
    }
}

/// A rotation by θ in the e1e2 plane, `exp(−θ/2 e12)`, turns e1 by θ towards e2: the
/// Euclidean formula. A boost of rapidity φ along e1, `exp(φ/2 e13)`... keeps the interval
/// `x² + y² − t²` and sends the rest frame's `e3` to `cosh φ e3 + sinh φ e1` (up to the sign
/// convention of the sandwich).
#[test]
fn rotations_and_boosts_are_the_textbook_ones() {
    use g21::Sandwich;
    let theta = 0.7;
    let r = bivector([-theta / 2.0, 0.0, 0.0]).exp();
    let v = r.sandwich(g21::Vector { e1: 1.0, e2: 0.0, e3: 0.0 });
    assert!(max_rel_diff(&[v.e1, v.e2, v.e3], &[theta.cos(), theta.sin(), 0.0]) <= 1e-15, "{v:?}");
    let phi = 1.3;
    let boost = bivector([0.0, phi / 2.0, 0.0]).exp();
    let t = boost.sandwich(g21::Vector { e1: 0.0, e2: 0.0, e3: 1.0 });
    assert!(max_rel_diff(&[t.e1.abs(), t.e2, t.e3], &[phi.sinh(), 0.0, phi.cosh()]) <= 1e-15, "{t:?}");
    assert!((t.e1 * t.e1 + t.e2 * t.e2 - t.e3 * t.e3 + 1.0).abs() <= 1e-14, "interval kept");
}

/// Tiny angles and rapidities keep full relative precision: no `1 − cos`, `e^φ − e^−φ` or
/// `ln(1 + b)` cancellation (the log of a boost takes `ln_1p`).
#[test]
fn tiny_generators_round_trip_to_the_last_bits() {
    for size in [1e-3, 1e-8, 1e-15, 1e-300] {
        for c in [[size, 0.0, 0.0], [0.0, size, 0.0], [0.0, 0.3 * size, 0.8 * size], [size, size, 0.0]] {
            let b = bivector(c);
            let back = b.exp().log().unwrap();
            let d = back.to_storage().iter().zip(b.to_storage()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
            assert!(d <= 4.0 * f64::EPSILON * size, "{c:?}: {back:?} ({d:e})");
        }
    }
}

#[test]
fn log_refuses_by_name() {
    let rotor = |s: f64, c: [f64; 3]| g21::Rotor { s, e12: c[0], e13: c[1], e23: c[2] };
    let e = rotor(2.0, [0.0; 3]).log().unwrap_err();
    assert_eq!(e, LogError::NotUnit { type_name: "Rotor", defect: 3.0 });
    assert_eq!(e.to_string(), "log of Rotor: not a unit rotor (R R̃ − 1 = 3e0)");
    assert_eq!(rotor(-1.0, [0.0; 3]).log().unwrap_err(), LogError::NoLogarithm { type_name: "Rotor" });
    assert_eq!(rotor(f64::NAN, [0.0; 3]).log().unwrap_err(), LogError::NonFinite { type_name: "Rotor" });
    // A near-unit rotor is normalised first: its log is the unit rotor's.
    let unit = bivector([0.4, 0.1, 0.2]).exp();
    let near = unit * (1.0 + 1e-10);
    let d = max_rel_diff(&near.log().unwrap().to_storage(), &unit.log().unwrap().to_storage());
    assert!(d <= 1e-15, "{d:e}");
    // A rotation by exactly π has a logarithm (the plane is known), −1 alone has none.
    let half_turn = rotor(-1.0, [1e-300, 0.0, 0.0]).log().unwrap();
    assert!((half_turn.e12 - std::f64::consts::PI).abs() <= 1e-15, "{half_turn:?}");
}

/// STA: a plane of two vectors exponentiates as the series, space-like (a rotation),
/// time-like (a boost) or null; a bivector in two planes is refused by name.
#[test]
fn sta_simple_bivectors_and_a_refusal() {
    use cga_algebras::sta::{self, Exp, ExpError, GeometricProduct, OuterProduct};
    let v = |c: [f64; 4]| sta::Vector { e0: c[0], e1: c[1], e2: c[2], e3: c[3] };
    for (a, b) in [
        (v([0.0, 1.0, 0.5, 0.0]), v([0.0, 0.2, -1.0, 0.7])),
        (v([1.5, 0.3, 0.0, 0.0]), v([0.1, 0.0, 0.9, 0.4])),
        (v([1.0, 1.0, 0.0, 0.0]), v([0.0, 0.0, 0.8, 0.0])),
    ] {
        let plane = a.wedge(b);
        let got = plane.exp().unwrap().to_storage();
        let want = series!(sta::Multivector, plane, 16);
        assert!(max_rel_diff(&got, &want) <= 1e-13, "{plane:?}: {got:?} vs {want:?}");
        let _ = plane.gp(plane);
    }
    let two_planes = sta::Bivector { e01: 1.0, e23: 1.0, ..Default::default() };
    let e = two_planes.exp().unwrap_err();
    assert_eq!(e, ExpError::NotSimple { type_name: "Bivector", wedge: 2.0 / 2.0 });
}

/// PGA: the exponential of a line through two points is the series (a rotation about it),
/// of an ideal line a translation `1 + B`; a screw is refused.
#[test]
fn pga_lines_exponentiate() {
    use cga_algebras::pga::{self, Exp, ExpError, GeometricProduct, Point, RegressiveProduct, Sandwich};
    let line = Point::at([1.0, 2.0, -1.0]).vee(Point::at([0.5, -1.0, 3.0])).scale(0.3);
    let m = line.exp().unwrap();
    let want = series!(pga::Multivector, line, 16);
    assert!(max_rel_diff(&m.to_storage(), &want) <= 1e-13);
    // The points of the line stay put.
    let on = m.sandwich(Point::at([1.0, 2.0, -1.0])).position().unwrap();
    assert!(max_rel_diff(&on, &[1.0, 2.0, -1.0]) <= 1e-14, "{on:?}");
    let ideal = pga::Line { e01: 0.5, e02: -1.0, e03: 0.25, ..Default::default() };
    let t = ideal.exp().unwrap();
    assert_eq!((t.s, t.e01, t.e02, t.e03, t.e12), (1.0, 0.5, -1.0, 0.25, 0.0));
    let screw = pga::Line { e12: 1.0, e03: 1.0, ..Default::default() };
    assert!(matches!(screw.exp(), Err(ExpError::NotSimple { type_name: "Line", .. })));
}

/// Blades of a type that also holds non-blades invert at run time; non-blades do not.
#[test]
fn blades_invert_where_their_type_does_not_always() {
    use cga_core::{Bivector, GeometricProduct as _, Inverse, Vector};
    let a = Vector { e1: 0.3, e2: -1.0, e3: 2.0, eo: 0.5, ei: 1.5 };
    let b = Vector { e1: 1.0, e2: 0.4, e3: -0.2, eo: -1.0, ei: 0.7 };
    let blade: Bivector = a ^ b;
    let inv = Inverse::try_inverse(blade).unwrap();
    let one = blade.gp(inv).to_storage();
    let mut want = [0.0; 32];
    want[0] = 1.0;
    assert!(max_rel_diff(&one, &want) <= 1e-14, "{one:?}");
    let two_planes = Bivector { e12: 1.0, ..Default::default() } + Bivector { e3o: 1.0, ..Default::default() };
    assert_eq!(Inverse::try_inverse(two_planes), None, "e12 + e3o squares to a grade-4 part");
    let g = g21::Vector { e1: 1.0, e2: 2.0, e3: 0.5 };
    assert!(max_rel_diff(&(g * g21::Inverse::try_inverse(g).unwrap()).to_storage(), &[1.0, 0.0, 0.0, 0.0]) <= 1e-15);
}

/// `tests/data/kingdon_exp.json` (made by `tools/kingdon_exp.py`, kingdon 3.0.0): per
/// algebra, bivectors and kingdon's `exp`, canonical blades.
fn kingdon(name: &str) -> Vec<(Vec<f64>, Vec<f64>)> {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/kingdon_exp.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let data: serde_json::Value = serde_json::from_str(&text).expect("kingdon_exp.json parses");
    let list = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array().expect("a list").iter().map(|x| x.as_f64().expect("a number")).collect()
    };
    let cases = data[name].as_array().expect("cases");
    assert_eq!(cases.len(), 20);
    cases.iter().map(|c| (list(&c["b"]), list(&c["exp"]))).collect()
}

/// Our `exp` against kingdon's in three metrics: coefficients of size ≤ 4, both f64: 1e-13
/// relative (kingdon's rounding and ours).
#[test]
fn exp_agrees_with_kingdon() {
    for (b, want) in kingdon("g21") {
        let got = g21::Bivector::from_storage(&b.clone().try_into().unwrap()).exp().to_storage();
        assert!(max_rel_diff(&got, &want) <= 1e-13, "g21 {b:?}: {got:?} vs {want:?}");
    }
    {
        use cga_algebras::sta::{Bivector, Exp};
        for (b, want) in kingdon("sta") {
            let got = Bivector::from_storage(&b.clone().try_into().unwrap()).exp().unwrap().to_storage();
            assert!(max_rel_diff(&got, &want) <= 1e-13, "sta {b:?}: {got:?} vs {want:?}");
        }
    }
    use cga_algebras::pga::{Exp, Line};
    let ours = |c: &[f64]| -> [f64; 16] { core::array::from_fn(|k| c[k] * common::PGA_STORAGE[k].1) };
    for (b, want) in kingdon("pga") {
        let got = Line::from_storage(&ours(&b)).exp().unwrap().to_storage();
        assert!(max_rel_diff(&got, &ours(&want)) <= 1e-13, "pga {b:?}: {got:?} vs {want:?}");
    }
}
