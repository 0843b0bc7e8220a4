cga::algebra! {
    scalar = cga::Real;
    signature = (3, 0);
    type Even = [e12, grade(2)];
}

fn main() {}
