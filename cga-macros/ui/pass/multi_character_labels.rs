// Labels of several characters: CGA's `eo` and `einf`, and blades such as `eoinf`, named as
// the labels run together (each name reads one way only).

mod cga {
    cga_macros::algebra! {
        scalar = cga_core::Real;
        signature = (4, 1);
        basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), einf = e4 + e5];
        type Vector = [grade(1)];
        type Bivector = [grade(2)];
        type FlatPoint = [e1inf, e2inf, e3inf, eoinf];
        type Scalar = [s];
    }
}

fn main() {
    let o = cga::Vector { eo: 1.0, ..Default::default() };
    let inf = cga::Vector { einf: 1.0, ..Default::default() };
    assert_eq!((o ^ inf).eoinf, 1.0);
    let flat: cga::FlatPoint = cga::FlatPoint::try_from(o ^ inf).unwrap();
    assert_eq!(flat.eoinf, 1.0);
    assert_eq!((o | inf).s, -1.0, "eo · einf = −1");
}
