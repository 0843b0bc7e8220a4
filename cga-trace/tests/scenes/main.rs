//! Scene files and the command: the format's fields and messages (every bad scene named by
//! file, line and field), includes, instances, keyframes, imported meshes, textures, outputs
//! that are never inputs, the CLI, and the hostile-input fuzz. One module a subject; `cargo test -p
//! cga-trace --test scenes -- MODULE::` runs one.

mod bad_scenes;
mod cli;
#[path = "../common/mod.rs"]
mod common;
mod fuzz;
mod import;
mod include;
mod instances;
mod keyframes;
mod outputs;
mod scene_format;
mod textures;
mod texturing;
