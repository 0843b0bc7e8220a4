//! Every generated sparse map equals the same map through the dense multivector, on
//! random operands: each product of each ordered pair of types, each sandwich, each
//! unary map. The dense type is itself checked against clifford (golden_products.rs).

use cga_tests::common;

use cga_core::{
    CommutatorProduct, GeometricProduct, InnerProduct, LeftContraction, Multivector, OuterProduct, ProductKind,
    RegressiveProduct, RightContraction, UnaryKind, product_table, unary_table,
};
use common::{grade_at, max_rel_diff};
use proptest::prelude::*;

/// Keep only `blades` of a storage array.
fn restrict(c: &[f64; 32], blades: &[usize]) -> [f64; 32] {
    let mut out = [0.0; 32];
    for &i in blades {
        out[i] = c[i];
    }
    out
}

fn dense_product(kind: ProductKind, a: Multivector, b: Multivector) -> Multivector {
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

fn dense_unary(kind: UnaryKind, a: Multivector) -> Multivector {
    match kind {
        UnaryKind::Reverse => a.reverse(),
        UnaryKind::Involute => a.involute(),
        UnaryKind::Conjugate => a.conjugate(),
        UnaryKind::Dual => a.dual(),
        UnaryKind::Undual => a.undual(),
        UnaryKind::Grade(k) => a.grade(k),
        UnaryKind::NormSquared => {
            let mut s = Multivector::zero();
            s.coeffs[0] = a.norm_squared();
            s
        }
    }
}

const TOL: f64 = 1e-12;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn every_product_equals_the_dense_product(
        a in prop::array::uniform32(-2.0f64..2.0),
        b in prop::array::uniform32(-2.0f64..2.0),
    ) {
        for e in product_table::<f64>() {
            let (ra, rb) = (restrict(&a, e.lhs_blades), restrict(&b, e.rhs_blades));
            let want = dense_product(e.kind, Multivector::from_storage(&ra), Multivector::from_storage(&rb));
            let mut want = want.to_storage();
            if e.kind == ProductKind::Sandwich {
                // A sandwich computes X's grades only (all a versor can produce): compare
                // with the dense result's parts of those grades.
                let grades: Vec<usize> = e.rhs_blades.iter().map(|&i| grade_at(i)).collect();
                let keep: Vec<usize> = (0..32).filter(|&i| grades.contains(&grade_at(i))).collect();
                want = restrict(&want, &keep);
            }
            let got = (e.eval)(&a, &b);
            let d = max_rel_diff(&got, &want);
            prop_assert!(d <= TOL, "{:?} {} x {} -> {}: differs by {d:e}", e.kind, e.lhs, e.rhs, e.output);
            // Nothing of the result may fall outside the output type.
            let outside = restrict(&want, e.output_blades);
            prop_assert!(max_rel_diff(&outside, &want) <= TOL, "{:?} {} x {}: result leaves {}", e.kind, e.lhs, e.rhs, e.output);
        }
    }

    #[test]
    fn every_unary_map_equals_the_dense_map(a in prop::array::uniform32(-2.0f64..2.0)) {
        for e in unary_table::<f64>() {
            let ra = restrict(&a, e.input_blades);
            let want = dense_unary(e.kind, Multivector::from_storage(&ra)).to_storage();
            let got = (e.eval)(&a);
            let d = max_rel_diff(&got, &want);
            prop_assert!(d <= TOL, "{:?} of {} -> {}: differs by {d:e}", e.kind, e.input, e.output);
        }
    }

    /// The change of basis is exact both ways on any multivector.
    #[test]
    fn storage_and_orthonormal_round_trip(a in prop::array::uniform32(-1e3f64..1e3)) {
        let back = Multivector::from_storage(&a).to_storage();
        let scale = a.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        let worst = back.iter().zip(&a).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
        prop_assert!(worst <= 4.0 * f64::EPSILON * scale, "round trip off by {worst:e}");
    }
}

/// For true versors (a rotor, a translator, their product) the typed sandwich loses
/// nothing: the dense `V X Ṽ` has no blade outside the sandwich's output type.
#[test]
fn versor_sandwiches_stay_in_type() {
    use cga_core::{Dilator, Motor, Rotor, Translator, Transversor, Vector};
    let rotor = Rotor { s: 0.3, e12: -0.5, e13: 0.7, e23: 0.2 }.normalise().unwrap();
    let translator = Translator { s: 1.0, e1i: -0.6, e2i: 1.5, e3i: 0.25 };
    let motor: Motor = rotor * translator;
    let dilator = Dilator::new([0.4, -1.2, 2.0], 1.7).unwrap();
    let transversor = Transversor::from_vector([0.3, -0.2, 0.5]);
    // A vector versor: the dual sphere of centre (1, 2, −1) and radius 1.5.
    let sphere = Vector { e1: 1.0, e2: 2.0, e3: -1.0, eo: 1.0, ei: 0.5 * (6.0 - 2.25) };
    let versors: [(&str, Multivector); 6] = [
        ("Rotor", rotor.into()),
        ("Translator", translator.into()),
        ("Motor", motor.into()),
        ("Dilator", dilator.into()),
        ("Transversor", transversor.into()),
        ("Vector", sphere.into()),
    ];
    let a: [f64; 32] = std::array::from_fn(|i| ((i * 37 % 11) as f64 - 5.0) / 3.0);
    let mut checked = 0;
    for e in product_table::<f64>().into_iter().filter(|e| e.kind == ProductKind::Sandwich) {
        let (_, v) = versors.iter().find(|(name, _)| *name == e.lhs).expect("a declared versor");
        let x = Multivector::from_storage(&restrict(&a, e.rhs_blades));
        let full = v.sandwich(&x).to_storage();
        let d = max_rel_diff(&restrict(&full, e.output_blades), &full);
        assert!(d <= 1e-12, "{} X Ṽ with X a {} leaves {} by {d:e}", e.lhs, e.rhs, e.output);
        let typed = (e.eval)(&v.to_storage(), &a);
        assert!(max_rel_diff(&typed, &full) <= 1e-12, "{} X Ṽ with X a {}: typed differs", e.lhs, e.rhs);
        checked += 1;
    }
    assert!(checked >= 6 * 10, "only {checked} sandwiches");
}
