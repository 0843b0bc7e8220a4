cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (10, 2, 1);
    type Scalar = [s];
}

fn main() {}
