//! Geometric algebras other than cga-core's G(4,1), each declared once with
//! [`cga_macros::algebra!`] and ready to depend on, with the few constructors and read-backs
//! their users reach for first. Each module is its own algebra: its own types, product traits
//! (`GeometricProduct::gp`, `RightContraction::rc`, …), registry and dense type, generic over
//! the scalar (any [`cga_core::Real`]: `f32`, `f64`, dual numbers, SIMD lanes).
//!
//! - [`pga`]: 3D projective geometric algebra G(3,0,1) — planes, lines, points, motors; join
//!   `&`, meet `^`, projections, bulk and weight norms.
//! - [`cga2`]: 2D conformal geometric algebra G(3,1) — points, point pairs, circles and
//!   lines, rotors and motors.
//! - [`sta`]: the spacetime algebra G(1,3) — `γ0..γ3` as `e0..e3`, `γ0² = 1`.
//! - [`vga`]: the 3D vector algebra G(3) — vectors, bivectors, rotors.
//! - [`g91`]: G(9,1), the ten-dimensional algebra of the tests of dimension.
//!
//! Each is checked product by product against its dense type and against kingdon's golden
//! vectors (`tests/tests/algebra/pga.rs`, `tests/tests/algebra/algebras.rs`, `tests/tests/algebra/dimension.rs`).

pub mod cga2;
pub mod g91;
pub mod pga;
pub mod sta;
pub mod vga;

pub use cga_core::Real;
