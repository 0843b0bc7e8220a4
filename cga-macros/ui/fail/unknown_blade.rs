cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (4, 1);
    basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), ei = e4 + e5];
    type Rotor = [s, e12, e4];
}

fn main() {}
