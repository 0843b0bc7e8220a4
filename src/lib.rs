//! `cga`: conformal geometric algebra as generated, grade-sparse Rust types.
//!
//! Re-exports the workspace crates: [`cga_core`] (types and geometry), [`cga_macros`]
//! (the `algebra!` generator) and [`cga_trace`] (the renderer).

pub use cga_core;
pub use cga_core::*;
pub use cga_macros::algebra;
pub use cga_trace;
