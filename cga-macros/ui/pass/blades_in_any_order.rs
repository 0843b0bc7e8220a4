// Blades declared with their labels in any order, each field the coefficient of the blade
// as spelled: `eio = −eoi` (one swap), `e312 = e123` (two), `e31 = −e13`.

mod cga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (4, 1);
        basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), ei = e4 + e5];
        type Vector = [grade(1)];
        type Bivector = [grade(2)];
        type FlatPoint = [e1i, e2i, e3i, eio];
        type Scalar = [s];
    }
}

mod vga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (3, 0);
        type Vector = [grade(1)];
        type Bivector = [e12, e31, e23];
        type Trivector = [e312];
        type Even = [s, e12, e31, e23];
    }
}

fn main() {
    let o = cga::Vector { eo: 1.0, ..Default::default() };
    let i = cga::Vector { ei: 1.0, ..Default::default() };
    let flat = cga::FlatPoint::try_from(i ^ o).unwrap();
    assert_eq!(flat.eio, 1.0, "ei ∧ eo = eio");
    assert_eq!((o ^ i).eio, -1.0, "eo ∧ ei = −eio");
    assert_eq!(cga::FlatPoint::<f64>::BLADES, ["e1i", "e2i", "e3i", "eio"]);
    assert!(cga::Bivector::<f64>::BLADES.contains(&"eio"), "grade(2) spells the blade as declared");
    assert_eq!((o | i).s, -1.0, "eo · ei = −1");

    let e = |k: usize| {
        let mut c = [0.0; 3];
        c[k] = 1.0;
        vga::Vector { e1: c[0], e2: c[1], e3: c[2] }
    };
    assert_eq!((e(2) ^ e(0)).e31, 1.0, "e3 ∧ e1 = e31");
    assert_eq!((e(0) ^ e(2)).e31, -1.0, "e1 ∧ e3 = −e31");
    assert_eq!((e(0) ^ e(1) ^ e(2)).e312, 1.0, "e123 = e312");
    // e31 e12 = e3 e2 = −e23.
    let b31 = vga::Bivector { e12: 0.0, e31: 1.0, e23: 0.0 };
    let b12 = vga::Bivector { e12: 1.0, e31: 0.0, e23: 0.0 };
    let p = b31 * b12;
    assert_eq!((p.e23, p.e12, p.e31, p.s), (-1.0, 0.0, 0.0, 0.0));
}
