cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Bivector = [e12, e13, e23];
    type Plane = [e12, e31, e23];
}

fn main() {}
