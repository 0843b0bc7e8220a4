//! Dual numbers `a + b ε` with `ε² = 0`: running generic code on them yields exact first
//! derivatives (forward-mode differentiation), with no step size to tune.

use crate::Real;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// `re + du ε`, `ε² = 0`. For `f(x + ε) = f(x) + f'(x) ε`, seed `du = 1` on the variable.
#[derive(Clone, Copy, Debug, Default, PartialEq, PartialOrd)]
pub struct Dual<T = f64> {
    /// The value.
    pub re: T,
    /// The derivative.
    pub du: T,
}

impl<T: Real> Dual<T> {
    /// `re + du ε`.
    pub fn new(re: T, du: T) -> Self {
        Dual { re, du }
    }

    /// A constant: derivative zero.
    pub fn constant(re: T) -> Self {
        Dual { re, du: T::zero() }
    }

    /// The differentiation variable at `re`: derivative one.
    pub fn variable(re: T) -> Self {
        Dual { re, du: T::one() }
    }
}

impl<T: Real> Add for Dual<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Dual { re: self.re + o.re, du: self.du + o.du }
    }
}

impl<T: Real> Sub for Dual<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Dual { re: self.re - o.re, du: self.du - o.du }
    }
}

/// `(a + a'ε)(b + b'ε) = ab + (a'b + ab')ε`.
impl<T: Real> Mul for Dual<T> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Dual { re: self.re * o.re, du: self.du * o.re + self.re * o.du }
    }
}

/// `(a + a'ε)/(b + b'ε) = a/b + (a'b − ab')/b² ε`.
impl<T: Real> Div for Dual<T> {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        let q = self.re / o.re;
        Dual { re: q, du: (self.du - q * o.du) / o.re }
    }
}

impl<T: Real> Neg for Dual<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Dual { re: -self.re, du: -self.du }
    }
}

impl<T: Real> Real for Dual<T> {
    fn zero() -> Self {
        Self::constant(T::zero())
    }
    fn one() -> Self {
        Self::constant(T::one())
    }
    fn from_f64(x: f64) -> Self {
        Self::constant(T::from_f64(x))
    }
    fn to_f64(self) -> f64 {
        self.re.to_f64()
    }
    /// `√(a + a'ε) = √a + a'/(2√a) ε`.
    fn sqrt(self) -> Self {
        let r = self.re.sqrt();
        Dual { re: r, du: self.du / (r + r) }
    }
    /// `|a + a'ε| = |a| + sign(a) a' ε`.
    fn abs(self) -> Self {
        if self.re < T::zero() { -self } else { self }
    }
    fn is_finite(self) -> bool {
        self.re.is_finite() && self.du.is_finite()
    }
    fn epsilon() -> Self {
        Self::constant(T::epsilon())
    }
    /// `sin(a + a'ε) = sin a + a' cos a ε`.
    fn sin(self) -> Self {
        Dual { re: self.re.sin(), du: self.du * self.re.cos() }
    }
    /// `cos(a + a'ε) = cos a − a' sin a ε`.
    fn cos(self) -> Self {
        Dual { re: self.re.cos(), du: -(self.du * self.re.sin()) }
    }
    /// `exp(a + a'ε) = eᵃ + a' eᵃ ε`.
    fn exp(self) -> Self {
        let e = self.re.exp();
        Dual { re: e, du: self.du * e }
    }
    /// `ln(a + a'ε) = ln a + (a'/a) ε`.
    fn ln(self) -> Self {
        Dual { re: self.re.ln(), du: self.du / self.re }
    }
    /// `sinh(a + a'ε) = sinh a + a' cosh a ε`.
    fn sinh(self) -> Self {
        Dual { re: self.re.sinh(), du: self.du * self.re.cosh() }
    }
    /// `cosh(a + a'ε) = cosh a + a' sinh a ε`.
    fn cosh(self) -> Self {
        Dual { re: self.re.cosh(), du: self.du * self.re.sinh() }
    }
    /// `ln(1 + a + a'ε) = ln(1 + a) + a'/(1 + a) ε`.
    fn ln_1p(self) -> Self {
        Dual { re: self.re.ln_1p(), du: self.du / (T::one() + self.re) }
    }
    fn min_positive() -> Self {
        Self::constant(T::min_positive())
    }
    /// The value's binade, as a constant: scaling by it scales both parts exactly.
    fn binade(self) -> Self {
        Self::constant(self.re.binade())
    }
    /// `d atan2(y, x) = (x dy − y dx) / (x² + y²)`.
    fn atan2(self, x: Self) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        Dual { re: self.re.atan2(x.re), du: (x.re * self.du - self.re * x.du) / r2 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivative_of_a_quotient_and_root() {
        // f(x) = √x / (x + 1) at x = 4: f' = (1/(2√x)(x+1) − √x) / (x+1)² = (1.25 − 2)/25.
        let x = Dual::variable(4.0);
        let f = x.sqrt() / (x + Dual::one());
        assert!((f.re - 0.4).abs() < 1e-15);
        assert!((f.du - (-0.75 / 25.0)).abs() < 1e-15);
    }
}
