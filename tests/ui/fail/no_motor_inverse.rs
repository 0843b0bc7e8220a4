//! A motor's `M M̃` is a scalar plus an `e123i` part: no inverse is generated for it.

fn main() {
    let _ = cga_core::Motor::<f64>::one().try_inverse();
}
