cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Vector = [grade(1)];
    versor RunInto = [s, grade(2)];
}

fn main() {}
