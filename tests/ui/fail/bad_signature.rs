cga::algebra! {
    scalar = cga::Real;
    signature = (0, 0);
    type Scalar = [s];
}

fn main() {}
