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
    let v = vga::Vector { e1: 1.0, e2: 0.0, e3: 0.0 };
    let r = vga::Rotor { s: 1.0, e12: 0.0, e13: 0.0, e23: 0.0 };
    // Grades 1 and 3: no declared type holds them. (Written `v.gp(r)`, rustc infers the one
    // impl there is, `GeometricProduct<Vector>`, and reports a type mismatch instead.)
    let _ = <vga::Vector as GeometricProduct<vga::Rotor>>::gp(v, r);
}
