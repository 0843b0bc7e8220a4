//! A product whose Cayley table is identically zero is not generated, and says so.

cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Vector = [grade(1)];
    type Bivector = [grade(2)];
    type Trivector = [grade(3)];
}

fn main() {
    let v = Vector { e1: 1.0, e2: 0.0, e3: 0.0 };
    let t = Trivector { e123: 1.0 };
    let _ = v.wedge(t);
}
