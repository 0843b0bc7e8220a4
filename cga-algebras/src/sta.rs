//! The spacetime algebra G(1,3): `γ0..γ3` are `e0..e3`, with `γ0² = 1` and `γk² = −1` (the
//! signature (+, −, −, −)); the pseudoscalar `I = e0123`, `I² = −1`.
//!
//! - An event or four-velocity is a [`Vector`]; `v * v` is its squared interval.
//! - Lorentz transformations are even [`Rotor`]s moving by `R v R̃`: the boost that takes `γ0`
//!   to velocity `tanh φ` along `+γk` is `cosh(φ/2) − sinh(φ/2) e0k` ([`Rotor::boost`]; `+`
//!   boosts along `−γk`, as `e0k γ0 = −γk`), the right-handed rotation about `γk` is
//!   `cos(θ/2) + sin(θ/2) e_ij` ([`Rotor::rotation`]; `γk² = −1` flips G(3)'s sign).
//! - The electromagnetic field is a [`Bivector`].
//!
//! Constructors and read-backs (`sta/construct.rs`): [`Vector::new`], [`Vector::from_velocity`],
//! [`Rotor::boost`], [`Rotor::rotation`], [`Bivector::from_fields`], [`Bivector::fields`].

mod construct;

pub use construct::StaError;

cga_macros::algebra! {
    scalar = crate::Real;
    scalars = [f32, f64];
    lanes = cga_core::simd;
    prelude = f64;
    signature = (1, 3);
    basis = [e0 = e1, e1 = e2, e2 = e3, e3 = e4];

    /// All 16 coefficients in the orthonormal basis `e1..e4` (`e1 = γ0`).
    dense Multivector;

    /// A scalar.
    type Scalar = [s];
    /// A spacetime vector.
    versor Vector = [grade(1)];
    /// A bivector: a field, or a boost or rotation generator.
    type Bivector = [grade(2)];
    /// A trivector.
    type Trivector = [grade(3)];
    /// The pseudoscalar `e0123`.
    type Pseudoscalar = [grade(4)];
    /// A rotor: the even subalgebra.
    versor Rotor = [s, grade(2), grade(4)];
}
