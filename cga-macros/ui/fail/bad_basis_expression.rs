cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (4, 1);
    basis = [e1, e2, e3, eo = 0.5 * (e5 - e6), ei = e4 + e5];
    type Vector = [grade(1)];
}

fn main() {}
