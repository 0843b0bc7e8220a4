//! Conformal geometric algebra G(4,1) as grade-sparse, compile-time generated types.
//!
//! [`algebra`] holds the one `algebra!` invocation that generates every type and product;
//! [`Real`] is the scalar they are generic over (`f32`, `f64`, [`Dual`]).

pub mod algebra;
pub mod conformal;
mod dual;
pub mod euclid;
pub mod evolved;
pub mod interpolate;
pub mod meet;
mod real;
pub mod versor;

pub use algebra::*;
pub use conformal::{Disk, GeometryError, down, ei, up};
pub use dual::Dual;
pub use evolved::{NormalError, NormalParts};
pub use interpolate::{Interpolable, InterpolationError, Pair, align, interpolate};
pub use meet::{Hit, RoundMeet};
pub use real::Real;
pub use versor::{VersorError, exp, rotor_between_lines};
