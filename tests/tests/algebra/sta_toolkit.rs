//! The spacetime algebra's constructors and read-backs (`cga_algebras::sta`'s
//! `sta/construct.rs`) against special relativity: boosts take the observer `γ0` to velocity
//! `tanh φ` along the direction, rotations are right-handed, four-velocities have `u² = 1`,
//! the field `F = E + I B` reads back and its invariants `E² − B²`, `E · B` survive a boost.

use cga_algebras::sta::{Bivector, Rotor, Sandwich, StaError, Vector};
use proptest::prelude::*;

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol * (1.0 + y.abs()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn boosts_rotations_and_fields_are_relativitys(
        n in prop::array::uniform3(-1.0f64..1.0),
        phi in -3.0f64..3.0,
        angle in -6.0f64..6.0,
        e in prop::array::uniform3(-2.0f64..2.0),
        b in prop::array::uniform3(-2.0f64..2.0),
        v in prop::array::uniform3(-0.5f64..0.5),
    ) {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        prop_assume!(len > 0.1);
        let u = n.map(|c| c / len);
        let boost = Rotor::boost(n, phi).unwrap();
        let moved: Vector<f64> = boost.sandwich(Vector::new([1.0, 0.0, 0.0, 0.0]));
        let want = [phi.cosh(), phi.sinh() * u[0], phi.sinh() * u[1], phi.sinh() * u[2]];
        prop_assert!(close(&moved.components(), &want, 1e-13), "{:?} vs {want:?}", moved.components());
        let vel = moved.velocity().unwrap();
        prop_assert!(close(&vel, &u.map(|c| c * phi.tanh()), 1e-13));
        // Right-handed rotation: Rodrigues' formula on a spatial vector.
        let r = Rotor::rotation(n, angle).unwrap();
        let x = [v[0], v[1], v[2]];
        let k = [u[1] * x[2] - u[2] * x[1], u[2] * x[0] - u[0] * x[2], u[0] * x[1] - u[1] * x[0]];
        let along = (u[0] * x[0] + u[1] * x[1] + u[2] * x[2]) * (1.0 - angle.cos());
        let want: [f64; 3] = core::array::from_fn(|i| x[i] * angle.cos() + k[i] * angle.sin() + u[i] * along);
        let turned: Vector<f64> = r.sandwich(Vector::new([0.0, x[0], x[1], x[2]]));
        let c = turned.components();
        prop_assert!(close(&c[1..], &want, 1e-13) && c[0].abs() <= 1e-15, "{c:?} vs {want:?}");
        // Four-velocity.
        let w = Vector::from_velocity(v).unwrap();
        prop_assert!((w.interval() - 1.0).abs() <= 1e-14);
        prop_assert!(close(&w.velocity().unwrap(), &v, 1e-14));
        // The field: back, and its invariants F² = (E² − B²) + 2 E · B I under a boost.
        let f = Bivector::from_fields(e, b);
        let (e2, b2) = f.fields();
        prop_assert!(close(&e2, &e, 1e-15) && close(&b2, &b, 1e-15));
        let dot = |a: [f64; 3], c: [f64; 3]| a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
        let square = f * f;
        prop_assert!((square.s - (dot(e, e) - dot(b, b))).abs() <= 1e-13);
        prop_assert!((square.e0123 - 2.0 * dot(e, b)).abs() <= 1e-13);
        let (e3, b3) = boost.sandwich(f).fields();
        let scale = (phi.abs().cosh()).powi(2);
        prop_assert!(((dot(e3, e3) - dot(b3, b3)) - (dot(e, e) - dot(b, b))).abs() <= 1e-12 * scale);
        prop_assert!((dot(e3, b3) - dot(e, b)).abs() <= 1e-12 * scale);
    }
}

#[test]
fn the_named_errors_and_f32() {
    assert_eq!(Rotor::<f64>::boost([0.0; 3], 1.0), Err(StaError::ZeroVector));
    assert_eq!(Rotor::<f64>::rotation([1.0, 0.0, 0.0], f64::NAN), Err(StaError::NonFinite));
    assert_eq!(Vector::<f64>::from_velocity([1.0, 0.0, 0.0]), Err(StaError::NotTimelike));
    assert_eq!(Vector::<f64>::new([0.0, 1.0, 0.0, 0.0]).velocity(), Err(StaError::NotTimelike));
    let moved: Vector<f32> =
        Rotor::<f32>::boost([0.0, 0.0, 2.0], 0.5).unwrap().sandwich(Vector::new([1.0, 0.0, 0.0, 0.0]));
    assert!((moved.components()[3] - 0.5f32.sinh()).abs() <= 1e-6);
}
