// Two invocations in one crate, each in its own module: their traits, registries and types
// do not clash, and both are usable side by side.

mod vga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (3, 0);
        type Vector = [grade(1)];
        versor Rotor = [s, grade(2)];
    }
}

mod pga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (3, 0, 1);
        basis = [e0 = e4, e1, e2, e3];
        type Plane = [grade(1)];
        type Line = [grade(2)];
    }
}

fn main() {
    let v = vga::Vector { e1: 1.0, e2: 2.0, e3: 3.0 };
    let r = v * v;
    assert_eq!(r.s, 14.0);
    let x = pga::Plane { e0: 0.0, e1: 1.0, e2: 0.0, e3: 0.0 };
    let y = pga::Plane { e0: 1.0, e1: 0.0, e2: 1.0, e3: 0.0 };
    let line = x ^ y;
    assert_eq!(line.e12, 1.0);
    assert!(!vga::product_table::<f64>().is_empty() && !pga::product_table::<f64>().is_empty());
}
