//! The benchmarks live beside this file (`products.rs`, `render.rs`); this library only holds
//! what they share.

/// A shipped scene file of cga-trace, by name (`primitives`, `surface`, `combined`).
pub fn scene_path(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cga-trace/scenes").join(format!("{name}.toml"))
}
