//! Motors from Euclidean data: rotors about axes through the origin, translators, screws
//! about any line, and their composition. A motor `M` moves any object `X` by `M X M̃`
//! ([`Motor::apply`], the generated `sandwich`).
//!
//! With points `e123 + x e032 + y e013 + z e021`, the conventions are klein's:
//!
//! - rotor: `R = cos(θ/2) − sin(θ/2)(a₁ e23 + a₂ e31 + a₃ e12) = exp(−θ/2 L̂)`, `L̂` the unit
//!   line through the origin along `a`: a right-handed turn by `θ` about `a`;
//! - translator: `T = 1 − ½(t₁ e01 + t₂ e02 + t₃ e03)`: moves every point by `+t`;
//! - screw: `exp((−θ + δ I) L̂ / 2) = (1 + ½ δ I L̂)(cos(θ/2) − sin(θ/2) L̂)` turns by `θ` about
//!   the unit line `L̂` (right-handed about its direction) and slides by `δ` along it
//!   (`I = e0123`; `I L̂ = −d · (e01, e02, e03)` for direction `d`).

use super::error::{PgaError, finite};
use super::{Line, Motor, Pseudoscalar, Sandwich};
use crate::Real;
use cga_core::euclid::norm;

impl<T: Real> Motor<T> {
    /// The identity motor `1`.
    pub fn identity() -> Self {
        Motor::one()
    }

    /// The rotation by `angle` (radians, right-handed) about the axis through the origin
    /// along `axis` (normalised here): `cos(θ/2) − sin(θ/2)(a₁ e23 + a₂ e31 + a₃ e12)`, `a`
    /// the unit axis. klein: `kln::rotor(angle, x, y, z)`; kingdon: `(−θ/2 (a₁ e23 − a₂ e13 +
    /// a₃ e12)).exp()`. `ZeroVector` for a zero axis, `NonFinite` for a non-finite input.
    pub fn rotor(axis: [T; 3], angle: T) -> Result<Self, PgaError> {
        finite((), &[axis[0], axis[1], axis[2], angle])?;
        let len = norm(axis);
        if len == T::zero() {
            return Err(PgaError::ZeroVector);
        }
        let half = angle * T::from_f64(0.5);
        let k = -half.sin() / len;
        Ok(Motor { s: half.cos(), e23: k * axis[0], e31: k * axis[1], e12: k * axis[2], ..Motor::zero() })
    }

    /// The translation by `t`: `1 − ½(t₁ e01 + t₂ e02 + t₃ e03)`, which moves every point by
    /// `+t`. klein: `kln::translator(|t|, t₁, t₂, t₃)`; kingdon: `1 − ½ (t₁ e01 + t₂ e02 + t₃
    /// e03)` (`(−½ t · e0).exp()`). `NonFinite` for a non-finite input.
    pub fn translator(t: [T; 3]) -> Result<Self, PgaError> {
        finite((), &t)?;
        let h = -T::from_f64(0.5);
        Ok(Motor { s: T::one(), e01: h * t[0], e02: h * t[1], e03: h * t[2], ..Motor::zero() })
    }

    /// The motor that applies `rotor` first, then `translator`: the product `T R` (klein:
    /// `kln::motor` of `t * r`; kingdon: `T * R`). Any two motors compose so; see
    /// [`then`](Self::then).
    pub fn from_rotor_translator(rotor: Motor<T>, translator: Motor<T>) -> Self {
        translator * rotor
    }

    /// `self` first, then `next`: the product `next · self` (motors compose right to left,
    /// as `M₂ (M₁ X M̃₁) M̃₂ = (M₂ M₁) X (M₂ M₁)~`).
    pub fn then(self, next: Motor<T>) -> Self {
        next * self
    }

    /// The screw that turns by `angle` (right-handed about the line's direction) about `line`
    /// and slides by `distance` along its direction: `exp((−θ + δ I) L̂ / 2) = (1 + ½ δ I
    /// L̂)(cos(θ/2) − sin(θ/2) L̂)` with `L̂ = L / |d|`. klein: `kln::motor(angle, distance,
    /// line)`. `IdealLine` for a line at infinity (use [`translator`](Self::translator)),
    /// `NonFinite` for a non-finite input.
    pub fn screw(line: Line<T>, angle: T, distance: T) -> Result<Self, PgaError> {
        finite((), &[angle, distance])?;
        let unit = line.unit()?;
        let half = T::from_f64(0.5);
        let (c, s) = ((half * angle).cos(), (half * angle).sin());
        let turn = Motor { s: c, ..Motor::zero() } + Motor::from(unit.scale(-s));
        let i_line: Line<T> = Pseudoscalar { e0123: half * distance } * unit;
        let slide = Motor { s: T::one(), ..Motor::zero() } + Motor::from(i_line);
        let m = slide * turn;
        finite(m, &m.to_array())
    }

    /// The screw of `pitch` (distance slid per radian turned) turning by `angle` about
    /// `line`: [`screw`](Self::screw)`(line, angle, pitch · angle)`.
    pub fn from_line_pitch(line: Line<T>, angle: T, pitch: T) -> Result<Self, PgaError> {
        Self::screw(line, angle, pitch * angle)
    }

    /// `M X M̃`: the generated `sandwich` (klein: `m(x)`; kingdon: `M >> X`, `M.sw(X)`).
    pub fn apply<X>(self, x: X) -> <Self as Sandwich<X>>::Output
    where
        Self: Sandwich<X>,
    {
        self.sandwich(x)
    }

    /// The motor's rotation part `⟨M⟩₀ + ⟨M⟩₂`'s Euclidean terms `s + e12, e31, e23` and its
    /// translation: for a unit motor `M = T R` ([`renormalise`](Self::renormalise)
    /// first), `R = s + b` (the Euclidean part) and the translation `t = −2 ⟨M R̃⟩_{e0i}`,
    /// what [`from_rotor_translator`](Self::from_rotor_translator) would be given. `NotAMotor`
    /// where the rotation part is zero.
    pub fn rotor_translation(self) -> Result<(Motor<T>, [T; 3]), PgaError> {
        let m = self.renormalise()?;
        let r = Motor { s: m.s, e12: m.e12, e31: m.e31, e23: m.e23, ..Motor::zero() };
        let t = m * r.reverse();
        let k = -T::from_f64(2.0);
        let out = (r, [k * t.e01, k * t.e02, k * t.e03]);
        finite(out, &out.1)
    }
}
