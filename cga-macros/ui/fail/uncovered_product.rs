mod g7 {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (7, 0);
        type Vector = [grade(1)];
        versor Rotor = [s, grade(2)];
    }
}

use g7::GeometricProduct;

fn main() {
    let v = g7::Vector::<f64>::default();
    let r = g7::Rotor::<f64>::default();
    // Grades 1 and 3 are 42 blades, more than `algebra!` declares by itself: no type holds
    // them. (Written `v.gp(r)`, rustc infers the one impl there is, `GeometricProduct<Vector>`,
    // and reports a type mismatch instead.)
    let _ = <g7::Vector as GeometricProduct<g7::Rotor>>::gp(v, r);
}
