cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Trivector = [e312];
}

fn main() {}
