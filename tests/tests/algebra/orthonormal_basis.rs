//! The same generator with the orthonormal storage basis e1..e5: its sparse products are
//! compared directly with clifford's single-grade golden cases (no change of basis at all),
//! and its lines show why cga-core stores the null basis (9 coefficients instead of 6).

use cga_tests::common;

use common::*;

mod ortho {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (4, 1);
        dense Dense;
        type Scalar = [s];
        type Vector = [grade(1)];
        type Bivector = [grade(2)];
        type Trivector = [grade(3)];
        type Quadvector = [grade(4)];
        type Pseudoscalar = [grade(5)];
        /// A line `X1 ∧ X2 ∧ (e4 + e5)` in the orthonormal basis.
        type Line = [e124, e125, e134, e135, e145, e234, e235, e245, e345];
        type Even = [grade(0), grade(2), grade(4)];
        type Odd = [grade(1), grade(3), grade(5)];
    }
}

const GRADE_TYPES: [&str; 6] = ["Scalar", "Vector", "Bivector", "Trivector", "Quadvector", "Pseudoscalar"];

fn single_grade(c: &[f64]) -> Option<usize> {
    let mut grades: Vec<usize> = (0..32).filter(|&i| c[i] != 0.0).map(grade_at).collect();
    grades.dedup();
    (grades.len() == 1).then(|| grades[0])
}

#[test]
fn orthonormal_sparse_products_match_clifford_directly() {
    let file = golden("products.json");
    let table = ortho::product_table::<f64>();
    let mut checked = 0;
    for (n, case) in cases(&file).iter().enumerate() {
        let (a, b) = (mv(&case["a"]).coeffs, mv(&case["b"]).coeffs);
        let (Some(ga), Some(gb)) = (single_grade(&a), single_grade(&b)) else { continue };
        for (kind, key) in [
            (ortho::ProductKind::Geometric, "gp"),
            (ortho::ProductKind::Outer, "op"),
            (ortho::ProductKind::Inner, "hestenes_inner"),
            (ortho::ProductKind::LeftContraction, "left_contraction"),
            (ortho::ProductKind::Regressive, "vee"),
        ] {
            let want = mv(&case[key]).coeffs;
            let entry = table.iter().find(|e| e.kind == kind && e.lhs == GRADE_TYPES[ga] && e.rhs == GRADE_TYPES[gb]);
            match entry {
                Some(e) => {
                    let got = (e.eval)(&a, &b);
                    let d = max_rel_diff(&got, &want);
                    assert!(d <= 1e-12, "case {n}: {key} of grades {ga}, {gb} differs by {d:e}");
                }
                // Not generated: the table is identically zero, so must clifford's result be.
                None => approx::assert_abs_diff_eq!(want.as_slice(), [0.0; 32].as_slice(), epsilon = 1e-12),
            }
            checked += 1;
        }
    }
    assert!(checked >= 100, "only {checked} single-grade checks");
}

/// A golden line fits the 9-blade orthonormal `Line`; the null-basis one needs 6.
#[test]
fn lines_are_sparser_in_the_null_basis() {
    let file = golden("objects.json");
    for case in cases(&file) {
        let line = mv(&case["line"]);
        let o = ortho::Line::from_storage(&line.coeffs);
        let back = ortho::Dense::from_storage(&o.to_storage());
        assert!(max_rel_diff(&back.coeffs, &line.coeffs) <= 1e-15);
    }
    assert_eq!(ortho::Line::<f64>::BLADES.len(), 9);
    assert_eq!(cga_core::Line::<f64>::BLADES.len(), 6);
}
