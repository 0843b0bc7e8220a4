//! A ten-dimensional algebra, G(9,1), as `cga_algebras::g91` declares it (the default labels
//! go on past 9 with `a`: the tenth vector is `ea`), checked against kingdon 3.0.0 (`tools/kingdon_g91.py` →
//! `tests/data/kingdon_g91.json`): the geometric product of vectors, of a vector and a
//! bivector, an outer product, a left contraction and a rotor's sandwich.

use cga_tests::common;

use common::max_rel_diff;

use cga_algebras::g91;
use g91::{Bivector, LeftContraction, Rotor, Sandwich, Trivector, Vector};

fn list<const N: usize>(v: &serde_json::Value) -> [f64; N] {
    let list = v.as_array().expect("a list of numbers");
    assert_eq!(list.len(), N, "a value on the type's {N} blades");
    core::array::from_fn(|k| list[k].as_f64().expect("a number"))
}

#[test]
fn the_tenth_vector_is_ea_and_squares_to_minus_one() {
    let mut c = [0.0; 10];
    c[9] = 1.0;
    let ea = Vector::from_array(c);
    assert_eq!(ea.ea, 1.0);
    assert_eq!((ea * ea).s, -1.0);
}

/// Coefficients of magnitude ≤ 1, sums of at most 45 terms, both sides f64: 1e-12 relative.
#[test]
fn products_agree_with_kingdon() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/kingdon_g91.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let data: serde_json::Value = serde_json::from_str(&text).expect("kingdon_g91.json parses");
    let cases = data["cases"].as_array().expect("cases");
    assert_eq!(cases.len(), 12);
    for (n, case) in cases.iter().enumerate() {
        let (a, b) = (Vector::from_array(list(&case["a"])), Vector::from_array(list(&case["b"])));
        let (bv, t) = (Bivector::from_array(list(&case["B"])), Trivector::from_array(list(&case["T"])));
        let r = Rotor::from_array(list(&case["R"]));
        let check = |key: &str, got: &[f64], want: &[f64]| {
            let d = max_rel_diff(got, want);
            assert!(d <= 1e-12, "case {n}: {key} differs from kingdon's by {d:e}");
        };
        check("ab", &(a * b).to_array(), &list::<46>(&case["ab"]));
        check("aB", &(a * bv).to_array(), &list::<130>(&case["aB"]));
        check("B_wedge_a", &(bv ^ a).to_array(), &list::<120>(&case["B_wedge_a"]));
        check("a_lc_T", &a.lc(t).to_array(), &list::<45>(&case["a_lc_T"]));
        check("R_a_Rrev", &r.sandwich(a).to_array(), &list::<10>(&case["R_a_Rrev"]));
    }
}
