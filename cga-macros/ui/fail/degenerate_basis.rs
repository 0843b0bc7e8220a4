cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (2, 0);
    basis = [ea = e1 + e2, eb = 2 * (e1 + e2)];
    type Vector = [grade(1)];
}

fn main() {}
