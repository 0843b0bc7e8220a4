// A scalar trait written to the earlier contract (no `to_f64`, `epsilon`, `binade`, …): one
// error per missing method, at the `scalar` item.
pub trait MyReal:
    Copy
    + PartialEq
    + PartialOrd
    + core::fmt::Debug
    + core::ops::Add<Output = Self>
    + core::ops::Sub<Output = Self>
    + core::ops::Mul<Output = Self>
    + core::ops::Div<Output = Self>
    + core::ops::Neg<Output = Self>
{
    fn zero() -> Self;
    fn one() -> Self;
    fn from_f64(x: f64) -> Self;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    fn is_finite(self) -> bool;
}

cga_macros::algebra! {
    scalar = crate::MyReal;
    signature = (3, 0);
    type Vector = [grade(1)];
    type Bivector = [grade(2)];
}

fn main() {}
