//! Conformal geometry on the generated types: constructors and read-backs, meets, versors,
//! the toolkit's operations, interpolation of circles, splines, curvature, and the stiff,
//! extreme and far-from-origin cases against Euclidean formulas and high precision. One
//! module a subject; `cargo test -p cga-tests --test geometry -- MODULE::` runs one.

mod clifford_tools;
mod conformal;
mod cookbook_clifford;
mod curvature;
mod far_reference;
mod fit;
mod interpolation;
mod meets;
mod operations;
mod precision;
mod spline;
mod stability;
mod toolkit;
mod versors;
