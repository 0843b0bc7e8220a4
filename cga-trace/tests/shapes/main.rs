//! Each shape and swept surface against its own reference: boxes, cones, tori, ruled and
//! spline surfaces (every crossing at full resolution), meshes exported from them, capped
//! swept surfaces as solids, curvature pictures, and silhouettes against POV-Ray (ignored:
//! they need `povray`). One module a subject; `cargo test -p cga-trace --test shapes --
//! MODULE::` runs one.

mod boxes;
#[path = "../common/mod.rs"]
mod common;
mod cone;
mod curvature_aov;
mod full_resolution;
mod mesh;
mod ruled_surface;
mod silhouettes;
mod solids;
mod spline_surface;
mod torus;
