// Products no declared type holds get a type named after their grades: in G(3,0) with
// vectors and rotors, `v r` has grades 1 and 3, so `algebra!` declares `Grades1_3`, and its
// products with the declared types follow (`v r r̃` is a vector again, held by `Grades1_3`).

mod vga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (3, 0);
        type Vector = [grade(1)];
        versor Rotor = [s, grade(2)];
    }
}

use vga::GeometricProduct;

fn main() {
    let v = vga::Vector { e1: 1.0, e2: 2.0, e3: 3.0 };
    let r = vga::Rotor { s: 0.5, e12: 0.5, e13: -0.5, e23: 0.5 };
    let vr: vga::Grades1_3 = v * r;
    // e1 e13 = e3, e2 e23 = e3, e3 e12 = e123, …: written out by hand.
    assert_eq!(vr.e123, 1.0 * 0.5 - 2.0 * -0.5 + 3.0 * 0.5);
    let back: vga::Grades1_3 = vr.gp(r.reverse());
    assert_eq!(back.e123, 0.0);
    assert_eq!([back.e1, back.e2, back.e3], [1.0, 2.0, 3.0].map(|x| x * r.norm_squared()));
    assert_eq!(vga::Grades1_3::<f64>::BLADES, ["e1", "e2", "e3", "e123"]);
}
