cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (0, 0);
    type Scalar = [s];
}

fn main() {}
