//! Versors: rotors, translators, motors, dilators and transversors; the exponential and
//! logarithm of rigid motions, their interpolation and splines; reflections and inversions
//! by vectors. Objects move by the sandwich `X' = V X Ṽ` ([`crate::Sandwich`], generated for
//! every versor type and every object).
//!
//! Conventions (checked against `tests/golden/rotors.json` and `operations.json`):
//! - `R = cos(θ/2) − sin(θ/2) a I3` (`I3 = e123`, so the axis `e3` gives the plane `e12`)
//!   turns by `θ` right-handedly about the unit axis `a`; `T = 1 − ½ t ei` shifts by `t`;
//!   `M = T R` turns, then shifts (clifford's order).
//! - A motor is rigid when `M M̃ = 1` (the Study condition: its scalar part 1 and its
//!   `e123i` part 0); [`Motor::renormalise`] restores it, [`Motor::log`] refuses a motor that
//!   is not.
//! - The generator `B` of `M = exp(B)` is a [`Generator`](crate::Generator):
//!   `B = −½(θ a I3 + t ∧ ei)` for a turn `θ a` and a velocity `t`, which moves a point
//!   with velocity `θ a × x + t` (a screw, [`Screw`]).
//! - `M` and `−M` are the same motion; [`Motor::interpolate`] picks the shorter path between
//!   them, [`Motor::pow`] follows the sign it is given.

mod between;
mod bulk;
mod dilator;
mod generator;
mod motor;
mod rotor;
mod spline;

pub use between::{Frame, VersorBetween};
pub use generator::Screw;
pub use spline::MotorSpline;

use crate::conformal::GeometryError;
use crate::{Line, Motor, Real, ScalarQuadvector};

/// Why a versor cannot be built, or a logarithm or an interpolation taken.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum VersorError {
    /// The bivector has `e1o, e2o, e3o` or `eoi` parts: it generates more than a rigid motion.
    #[error("the bivector is not the generator of a rigid motion (it has eo parts)")]
    NotAGenerator,
    /// `M M̃ ≠ 1`: the motor has drifted from a rigid motion (`defect` is the larger of
    /// `|⟨M M̃⟩₀ − 1|` and `⟨M M̃⟩_{e123i}` relative to the translation); renormalise first.
    #[error("the motor is not rigid: M M̃ differs from 1 by {defect:e} (renormalise it first)")]
    NotRigid {
        /// The Study defect.
        defect: f64,
    },
    /// `R R̃ ≠ 1`: the rotor is not of unit norm.
    #[error("the rotor is not of unit norm: R R̃ differs from 1 by {defect:e} (normalise it first)")]
    NotUnit {
        /// `|R R̃ − 1|`.
        defect: f64,
    },
    /// The generator has translation parts, so its exponential is not a rotor.
    #[error("the generator has translation parts: its exponential is a motor, not a rotor")]
    NotARotation,
    /// `1 + L2 L1` has no normalising square root (the lines are anti-parallel).
    #[error("no rotor takes the first line to the second this way (anti-parallel lines)")]
    NoRotor,
    /// Opposite directions, or a relative half turn: every axis perpendicular gives a
    /// shortest path, so none is unique.
    #[error("the two are antipodal: opposite directions or a half turn apart, with no unique shortest path")]
    Antipodal,
    /// An axis, direction or line of zero length (or not finite).
    #[error("the axis or direction is zero or not finite")]
    ZeroAxis,
    /// A dilation factor that is not positive and finite.
    #[error("the dilation factor is not positive and finite")]
    Factor,
    /// Input and output slices of different lengths.
    #[error("{input} inputs but room for {output} outputs")]
    Lengths {
        /// The inputs' count.
        input: usize,
        /// The outputs' room.
        output: usize,
    },
    /// A spline needs at least two poses.
    #[error("a spline of motors needs at least two poses")]
    TooFewPoses,
    /// Three axes that are not orthonormal (to `√ε`): `defect` is the largest
    /// `|aᵢ·aⱼ − δᵢⱼ|`.
    #[error("the axes are not an orthonormal frame: aᵢ·aⱼ differs from δᵢⱼ by {defect:e}")]
    NotAFrame {
        /// The largest `|aᵢ·aⱼ − δᵢⱼ|`.
        defect: f64,
    },
    /// Two frames of opposite handedness: a reflection, not a rotation, takes one to the other.
    #[error("the frames have opposite handedness: no rotation takes one to the other")]
    Handedness,
    /// `Y = 1 + γ X₂ X₁` has no normalising square root: the objects are opposite
    /// (`X₂ ≈ −X₁`, where no versor of this form is unique) or `Y Ỹ` has no real root.
    #[error(
        "no versor of the form 1 + γ X2 X1 takes the first object to the second (opposite objects, or Y Ỹ has no real root)"
    )]
    NoVersor,
    /// A versor whose `V Ṽ` is zero or not finite: it has no inverse.
    #[error("the versor has no inverse (V Ṽ is zero or not finite)")]
    NotInvertible,
}

impl From<GeometryError> for VersorError {
    fn from(_: GeometryError) -> Self {
        VersorError::ZeroAxis
    }
}

/// How far from rigid a motor may be and still be taken as one: `M M̃` within this of 1
/// (relative). Rounding of a product of motors adds about 4ε; a thousand compositions stay
/// well inside.
pub fn rigid_tolerance<T: Real>() -> T {
    T::from_f64(4096.0) * T::epsilon()
}

/// `x ≤ bound`, false for a NaN (so `!within(…)` refuses NaN too).
pub(crate) fn within<T: PartialOrd>(x: T, bound: T) -> bool {
    x <= bound
}

/// `e123i`, which squares to zero and commutes with every motor.
fn pseudo_infinity<T: Real>() -> Motor<T> {
    Motor { e123i: T::one(), ..Motor::zero() }
}

/// `(sin φ / φ, (sin φ − φ cos φ) / (2φ³))`. Below `φ = 1` the second is summed as its
/// series `Σ_{k≥1} (−1)^{k+1} k φ^{2k−2} / (2k+1)!` (ten terms: the closed form cancels to a
/// relative `ε/φ²` there, which left drifted motors at `φ ≈ 1e-4`), the first as
/// `Σ (−1)^k φ^{2k} / (2k+1)!` (exact at `φ = 0`). The exponentials of screws use it, in
/// this algebra and in cga-algebras' PGA.
pub fn sinc_terms<T: Real>(phi: T) -> (T, T) {
    let p2 = phi * phi;
    if phi.abs() < T::one() {
        let (mut c1, mut dc) = (T::zero(), T::zero());
        let (mut power, mut fact) = (T::one(), 1.0f64); // φ^{2k−2}, (2k−1)!
        for k in 1..=10 {
            let odd = (2 * k) as f64 * (2 * k + 1) as f64;
            let sign = if k % 2 == 1 { T::one() } else { -T::one() };
            // c1's term k−1: (−1)^{k−1} φ^{2k−2}/(2k−1)!; dc's term k: (−1)^{k+1} k φ^{2k−2}/(2k+1)!.
            c1 = c1 + sign * power / T::from_f64(fact);
            fact *= odd;
            dc = dc + sign * T::from_f64(k as f64) * power / T::from_f64(fact);
            power = power * p2;
        }
        return (c1, dc);
    }
    let (s, c) = (phi.sin(), phi.cos());
    (s / phi, (s - phi * c) / (T::from_f64(2.0) * p2 * phi))
}

/// `exp(B)` for a bivector `B` with rotation and translation parts only (see
/// [`Motor::exp`]); `NotAGenerator` when it has `eo` parts.
pub fn exp<T: Real>(b: crate::Bivector<T>) -> core::result::Result<Motor<T>, VersorError> {
    let scale_ = b.to_array().iter().fold(T::one(), |m, x| if x.abs() > m { x.abs() } else { m });
    let tol = T::from_f64(64.0) * T::epsilon() * scale_;
    if [b.e1o, b.e2o, b.e3o, b.eoi].iter().any(|x| x.abs() > tol) {
        return Err(VersorError::NotAGenerator);
    }
    Ok(Motor::exp(crate::Generator { e12: b.e12, e13: b.e13, e23: b.e23, e1i: b.e1i, e2i: b.e2i, e3i: b.e3i }))
}

/// The rotor taking `l1` to `l2` (`R l1 R̃ = l2`) by the shortest motion:
/// `R = (1 + L2 L1) K^(−½)`, `K = (1 + L2 L1)(1 + L2 L1)~ = 2 + L2 L1 + L1 L2`, a scalar plus
/// `e123i`, inverted through its square root as in interpolation. Both lines normalised.
pub fn rotor_between_lines<T: Real>(l1: Line<T>, l2: Line<T>) -> core::result::Result<Motor<T>, VersorError> {
    let (l1, l2) = (l1.try_normalise().ok_or(VersorError::NoRotor)?, l2.try_normalise().ok_or(VersorError::NoRotor)?);
    let y = Motor { s: T::one(), ..Motor::zero() } + l2 * l1;
    let k = ScalarQuadvector::from_storage(&(y * y.reverse()).to_storage());
    let root = k.try_sqrt().ok_or(VersorError::NoRotor)?;
    let star = root.star();
    let inv = T::one() / (star * root).s;
    if !inv.is_finite() {
        return Err(VersorError::NoRotor);
    }
    Ok(Motor::from_storage(&(y * star).to_storage()).scale(inv))
}

/// `Result` of this module.
pub type VersorResult<T> = core::result::Result<T, VersorError>;
