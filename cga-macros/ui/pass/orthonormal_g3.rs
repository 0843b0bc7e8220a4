// An algebra with no `basis`: the orthonormal e1..e3 of G(3,0), used from a fresh crate,
// with the `approx` comparisons.

cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    dense Dense;
    type Scalar = [s];
    type Vector = [grade(1)];
    type Bivector = [grade(2)];
    versor Rotor = [s, grade(2)];
    approx = ::approx;
}

fn main() {
    let x = Vector { e1: 1.0, e2: 2.0, e3: 0.5 };
    let y = Vector { e1: -1.0, e2: 0.0, e3: 3.0 };
    // x y = x · y + x ∧ y.
    let r: Rotor = x * y;
    assert_eq!(r.s, 0.5);
    assert_eq!(r.grade2(), x ^ y);
    // A quarter turn in the e12 plane: R = cos(π/4) − sin(π/4) e12, R e1 R̃ = e2.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let quarter = Rotor { s: h, e12: -h, e13: 0.0, e23: 0.0 };
    let turned = quarter.sandwich(Vector { e1: 1.0, e2: 0.0, e3: 0.0 });
    approx::assert_abs_diff_eq!(turned, Vector { e1: 0.0, e2: 1.0, e3: 0.0 }, epsilon = 1e-15);
    let dense: Dense = x.into();
    assert_eq!(Vector::from_dense(&(dense * dense)), Vector::zero());
    assert_eq!((x * x).s, x.norm_squared());
    assert_eq!(product_table::<f32>().len(), unary_table::<f32>().len() * 0 + product_table::<f64>().len());
}
