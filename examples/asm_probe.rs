use cga::{Circle, Vector};
#[inline(never)]
pub fn circle3(a: Vector, b: Vector, c: Vector) -> Circle {
    a ^ b ^ c
}
fn main() {
    let v = Vector { e1: 1.0, e2: 2.0, e3: 3.0, eo: 1.0, ei: 7.0 };
    println!("{:?}", std::hint::black_box(circle3(std::hint::black_box(v), v, v)));
}
