//! Double-double numbers (the `twofloat` crate, about 106 bits) as a [`Real`]: the same
//! generic code run with 32 digits, a reference for the rounding error of the f64 run.

use cga_core::Real;
use core::ops::{Add, Div, Mul, Neg, Sub};
use twofloat::TwoFloat;

/// A double-double number.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Dd(pub TwoFloat);

impl Dd {
    /// The nearest f64.
    pub fn hi(self) -> f64 {
        self.0.hi() + self.0.lo()
    }
}

macro_rules! op {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for Dd {
            type Output = Dd;
            #[inline]
            fn $f(self, o: Dd) -> Dd {
                Dd(self.0.$f(o.0))
            }
        }
    )*};
}
op!(Add add, Sub sub, Mul mul, Div div);

impl Neg for Dd {
    type Output = Dd;
    fn neg(self) -> Dd {
        Dd(-self.0)
    }
}

impl Real for Dd {
    fn zero() -> Self {
        Dd(TwoFloat::from(0.0))
    }
    fn one() -> Self {
        Dd(TwoFloat::from(1.0))
    }
    fn from_f64(x: f64) -> Self {
        Dd(TwoFloat::from(x))
    }
    fn to_f64(self) -> f64 {
        self.hi()
    }
    fn sqrt(self) -> Self {
        if self.0 == TwoFloat::from(0.0) { self } else { Dd(self.0.sqrt()) }
    }
    fn abs(self) -> Self {
        Dd(self.0.abs())
    }
    fn is_finite(self) -> bool {
        self.0.hi().is_finite() && self.0.lo().is_finite()
    }
    fn epsilon() -> Self {
        Dd(TwoFloat::from(f64::EPSILON * f64::EPSILON))
    }
    fn sin(self) -> Self {
        Dd(self.0.sin())
    }
    fn cos(self) -> Self {
        Dd(self.0.cos())
    }
    fn atan2(self, x: Self) -> Self {
        Dd(self.0.atan2(x.0))
    }
    fn exp(self) -> Self {
        Dd(self.0.exp())
    }
    fn ln(self) -> Self {
        Dd(self.0.ln())
    }
}

/// An f64 vector as double-double.
pub fn dd3(x: [f64; 3]) -> [Dd; 3] {
    x.map(Dd::from_f64)
}

/// A double-double vector rounded to f64.
pub fn f3(x: [Dd; 3]) -> [f64; 3] {
    x.map(Dd::hi)
}
