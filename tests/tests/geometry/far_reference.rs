//! The golden-style checks on a set far from the origin: centres up to 1e3, radii 1e-2 …
//! 1e2 (`tests/data/far_interpolation.json`, made by `tools/far_reference.py` in 50-digit
//! mpmath with an independent implementation of the algebra, which agrees with clifford's
//! `interpolation.json` to 3e-13). Tolerances are the ones f64 allows at each case's scale,
//! `ρ = |c|/r`, as documented on the functions: constructors `16 ε (1 + ρ)²`, interpolation
//! [`Pair::condition`] — the same formulas under which the near-origin golden files pass.

use cga_core::euclid::{E3, norm, sub};
use cga_core::{Circle, InterpolationError, Multivector, Pair, interpolate::accuracy};
use serde_json::Value;

fn e3(v: &Value) -> E3 {
    let a: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    [a[0], a[1], a[2]]
}

fn dense(v: &Value) -> Multivector {
    let c: Vec<f64> = v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    Multivector::new(c.try_into().unwrap())
}

/// `max |a − b| / max |b|`: the error relative to the blade's size, which is what rounding
/// of its largest coefficients leaves.
fn relative(a: &Multivector, b: &Multivector) -> f64 {
    let size = b.coeffs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.coeffs.iter().zip(&b.coeffs).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / size
}

fn circle(v: &Value) -> (Circle, f64) {
    let (c, n, r) = (e3(&v["centre"]), e3(&v["normal"]), v["radius"].as_f64().unwrap());
    (Circle::from_centre_normal_radius(c, n, r).unwrap(), norm(c) / r)
}

#[test]
fn far_circles_and_their_interpolation_agree_with_high_precision() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/data/far_interpolation.json")).unwrap();
    let file: Value = serde_json::from_str(&text).unwrap();
    let blades: Vec<&str> = file["blades"].as_array().unwrap().iter().map(|b| b.as_str().unwrap()).collect();
    assert_eq!(blades, Multivector::<f64>::BLADES);
    let eps = f64::EPSILON;
    let (mut accepted, mut refused, mut worst_constructor, mut worst_interpolation) = (0, 0, 0.0f64, 0.0f64);
    for (k, case) in file["cases"].as_array().unwrap().iter().enumerate() {
        let params = &case["params"];
        let ((c1, rho1), (c2, rho2)) = (circle(&params["c1"]), circle(&params["c2"]));
        for (c, rho, want) in [(c1, rho1, &case["c1"]), (c2, rho2, &case["c2"])] {
            // C2 is compared up to the alignment sign, which Pair::new decides.
            let (got, want) = (Multivector::from(c), dense(want));
            let err = relative(&got, &want).min(relative(&(-got), &want));
            let bound = 16.0 * eps * (1.0 + rho).powi(2);
            assert!(err <= bound, "case {k}: circle off by {err:e} > {bound:e} (ρ = {rho:e})");
            worst_constructor = worst_constructor.max(err / bound);
        }
        let pair = match Pair::new(c1, c2) {
            Ok(p) => p,
            Err(InterpolationError::IllConditioned { estimate }) => {
                assert!(estimate > accuracy::<f64>());
                refused += 1;
                continue;
            }
            Err(e) => panic!("case {k}: {e}"),
        };
        accepted += 1;
        let got = pair.at(case["alpha"].as_f64().unwrap()).unwrap();
        let (centre, _, radius) = got.centre_normal_radius().unwrap();
        // Against C_α of the exact parameters (the blades in the file are rounded, and a
        // rounded blade is not exactly a blade: tests/tests/geometry/interpolation.rs checks those as given).
        let exact = &params["c_alpha"];
        let (want_centre, want_radius) = (e3(&exact["centre"]), exact["radius"].as_f64().unwrap());
        let err = (norm(sub(centre, want_centre)) / want_radius).max((radius - want_radius).abs() / want_radius);
        let bound = pair.condition() + 64.0 * eps;
        assert!(err <= bound, "case {k}: C_α off by {err:e} > {bound:e}");
        worst_interpolation = worst_interpolation.max(err / bound);
    }
    println!(
        "{accepted} pairs interpolated, {refused} refused as ill-conditioned; worst error / bound: constructors {worst_constructor:.2}, interpolation {worst_interpolation:.2}"
    );
    assert!(accepted >= 25, "only {accepted} of the cases were accepted");
}
