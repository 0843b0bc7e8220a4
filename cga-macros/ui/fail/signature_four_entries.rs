cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0, 1, 1);
    type Scalar = [s];
}

fn main() {}
