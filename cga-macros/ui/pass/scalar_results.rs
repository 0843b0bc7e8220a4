// With no type holding the scalar blade alone, a product whose result is a scalar returns
// the scalar type itself: `v | v` is an `f64`.

mod vga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (3, 0);
        type Vector = [grade(1)];
        type Bivector = [grade(2)];
    }
}

use vga::{InnerProduct, LeftContraction};

fn main() {
    let v = vga::Vector { e1: 1.0, e2: 2.0, e3: 3.0 };
    let d: f64 = v | v;
    assert_eq!(d, 14.0);
    assert_eq!(v.inner(v), 14.0);
    assert_eq!(v.lc(v), 14.0);
    let b = v ^ vga::Vector { e1: 0.0, e2: 1.0, e3: 0.0 };
    let square: f64 = b | b;
    assert_eq!(square, -(b.e12 * b.e12 + b.e13 * b.e13 + b.e23 * b.e23));
    let entry = vga::product_table::<f64>()
        .into_iter()
        .find(|e| e.kind == vga::ProductKind::Inner && e.lhs == "Vector" && e.rhs == "Vector")
        .expect("Vector | Vector is generated");
    assert_eq!(entry.output, "T");
    let mut a = [0.0; 8];
    a[1..4].copy_from_slice(&[1.0, 2.0, 3.0]);
    assert_eq!((entry.eval)(&a, &a)[0], 14.0);
}
