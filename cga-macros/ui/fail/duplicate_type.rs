cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (4, 1);
    type Vector = [grade(1)];
    type Circle = [grade(3)];
    type Vector = [e1, e2];
}

fn main() {}
