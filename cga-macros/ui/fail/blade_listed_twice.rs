cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Rotor = [s, e12, e13, e23, e12];
}

fn main() {}
