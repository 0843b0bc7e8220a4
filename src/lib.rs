#![doc = include_str!("../README.md")]
//!
//! The crate re-exports the workspace: [`cga_core`] (types and geometry, also glob-imported
//! here), [`cga_macros`]'s `algebra!` generator, and [`cga_trace`] (the renderer).

pub use cga_core;
pub use cga_core::*;
pub use cga_macros::algebra;
pub use cga_trace;
