//! cga-trace: the ray tracer built on cga-core (camera, shapes, lights, integrator, film).
//!
//! Not yet built: this crate holds the workspace's place for the renderer of issue 4.
//! Its one dependency, cga-core, already provides the types the renderer will use.

pub use cga_core;
