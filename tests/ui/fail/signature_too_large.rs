cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (6, 3);
    type Scalar = [s];
}

fn main() {}
