cga_macros::algebra! {
    scalar = cga_core::Real;
    scalars = [f32, f64, f32];
    signature = (3, 0);
    type Vector = [grade(1)];
}

fn main() {}
