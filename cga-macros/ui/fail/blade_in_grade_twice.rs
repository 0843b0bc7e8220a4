cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Even = [e12, grade(2)];
}

fn main() {}
