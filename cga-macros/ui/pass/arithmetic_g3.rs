// Arithmetic in a fresh crate's algebra (G(3,0), orthonormal): scalars on either side with
// `scalars = [f64]`, `one()`, inverses, checked conversions, `cast`, `normalise`'s errors,
// the scalar and commutator products.

cga_macros::algebra! {
    scalar = cga_core::Real;
    scalars = [f64];
    signature = (3, 0);
    dense Dense;
    type Scalar = [s];
    type Vector = [grade(1)];
    type Bivector = [grade(2)];
    type Trivector = [grade(3)];
    versor Rotor = [s, grade(2)];
    type Odd = [grade(1), grade(3)];
}

fn main() {
    let v = Vector { e1: 1.0, e2: 2.0, e3: 2.0 };
    let b = Bivector { e12: 1.0, e13: 0.0, e23: -1.0 };
    // Scalars on either side.
    assert_eq!(2.0 * v, v * 2.0);
    assert_eq!(v / 2.0, Vector { e1: 0.5, e2: 1.0, e3: 1.0 });
    let r: Rotor = 1.0 + b;
    assert_eq!(r, Rotor { s: 1.0, e12: 1.0, e13: 0.0, e23: -1.0 });
    assert_eq!(r - 1.0, Rotor::from(b));
    assert_eq!(3.0 - r, Rotor { s: 2.0, e12: -1.0, e13: 0.0, e23: 1.0 });
    assert_eq!(Rotor::<f64>::one() * r, r);
    // Inverses: v⁻¹ = v / v², and a rotor's.
    let inv = v.try_inverse().unwrap();
    assert_eq!(inv, v / 9.0);
    let unit: Rotor = v * inv;
    assert!((unit.s - 1.0).abs() < 1e-15 && unit.grade2() == Bivector::zero());
    assert_eq!(Vector::<f64>::zero().try_inverse(), None);
    let q: Rotor = r * r.try_inverse().unwrap();
    assert!((q.s - 1.0).abs() < 1e-15);
    // Checked conversions.
    let odd = Odd::from(v);
    assert_eq!(Vector::try_from(odd), Ok(v));
    let err = Vector::try_from(Odd { e123: 0.5, ..odd }).unwrap_err();
    assert_eq!(err.to_string(), "converting Odd to Vector would drop e123 = 0.5");
    assert_eq!(Bivector::try_from(r).unwrap_err().dropped, [("s", 1.0)]);
    assert_eq!(Vector::try_from(Dense::from(v)), Ok(v));
    // Casts, normalisation, the scalar and commutator products.
    assert_eq!(v.cast::<f32>(), Vector { e1: 1.0f32, e2: 2.0, e3: 2.0 });
    assert_eq!(v.normalise(), Ok(v / 3.0));
    assert_eq!(Vector::<f64>::zero().normalise(), Err(NormaliseError::Zero { type_name: "Vector" }));
    assert_eq!(v.scalar_product(v), 9.0);
    let e1 = Vector { e1: 1.0, e2: 0.0, e3: 0.0 };
    let e2 = Vector { e1: 0.0, e2: 1.0, e3: 0.0 };
    assert_eq!(e1.commutator(e2), Bivector { e12: 1.0, e13: 0.0, e23: 0.0 });
    assert_eq!(inverse_table::<f64>().len(), 6);
}
