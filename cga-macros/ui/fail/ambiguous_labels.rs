cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    basis = [e1, e2, e12 = e3];
    type Vector = [grade(1)];
}

fn main() {}
