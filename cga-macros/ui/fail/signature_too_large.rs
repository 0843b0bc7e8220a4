cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (9, 6);
    type Scalar = [s];
}

fn main() {}
