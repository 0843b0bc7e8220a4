cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (4, 1, 2);
    type Scalar = [s];
}

fn main() {}
