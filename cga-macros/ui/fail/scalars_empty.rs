cga_macros::algebra! {
    scalar = cga_core::Real;
    scalars = [];
    signature = (3, 0);
    type Vector = [grade(1)];
}

fn main() {}
