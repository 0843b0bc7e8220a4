cga::algebra! {
    scalar = cga::Real;
    signature = (3, 0);
    kind Vector = [grade(1)];
}

fn main() {}
