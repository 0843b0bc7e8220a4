cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    kind Vector = [grade(1)];
}

fn main() {}
