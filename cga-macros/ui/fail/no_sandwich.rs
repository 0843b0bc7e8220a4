//! Only versors have sandwiches: the message says which types are versors. (A method call
//! `v.sandwich(x)` on a type with no sandwich at all stops earlier, at "no method named
//! `sandwich`"; the trait's message shows where the trait is asked for, as here.)

cga_macros::algebra! {
    scalar = cga_core::Real;
    signature = (3, 0);
    type Vector = [grade(1)];
    versor Rotor = [s, grade(2)];
}

fn main() {
    let v = Vector { e1: 1.0, e2: 0.0, e3: 0.0 };
    let _ = Sandwich::sandwich(v, v);
}
