//! Whole pictures: the shipped scenes against their references and across back ends,
//! anti-aliasing, glass and the shutter, the same picture anywhere in space and at any scale,
//! figures of CGA objects, and transparent backgrounds. One module a subject; `cargo test -p
//! cga-trace --test pictures -- MODULE::` runs one.

mod antialiasing;
#[path = "../common/mod.rs"]
mod common;
mod figure;
mod invariance;
mod optics;
mod render;
mod transparent;
