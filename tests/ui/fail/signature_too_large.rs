cga::algebra! {
    scalar = cga::Real;
    signature = (6, 3);
    type Scalar = [s];
}

fn main() {}
