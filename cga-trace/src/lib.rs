//! cga-trace: a ray tracer whose geometry is conformal geometric algebra (cga-core).
//!
//! Kept apart as pbrt keeps them: [`camera`] makes rays (eq. 2), [`shapes`] and [`surface`]
//! meet them with objects (CGA meets; evolved surfaces by robust root isolation), the
//! [`integrator`] traces and shades (eq. 12), [`film`] stores and encodes, [`scene`] reads
//! TOML. [`backend`] runs the same integrator on the sparse types, a dense multivector or
//! plain vectors, to compare them, one ray at a time or four in SIMD lanes (a packet).

pub mod backend;
pub mod bvh;
pub mod camera;
pub mod colour;
pub mod drawing;
pub mod environment;
pub mod figure;
pub mod film;
pub mod format;
pub mod frame;
mod hash;
pub mod import;
pub mod input;
pub mod integrator;
pub mod invalid;
pub mod label;
mod lanes;
pub mod light;
pub mod limits;
pub mod material;
#[cfg(feature = "evolved")]
pub mod mesh;
pub mod object;
pub mod output;
pub mod picture;
pub mod pipeline;
pub mod ray;
pub mod scene;
pub mod settings;
pub mod shapes;
pub mod shutter;
pub mod surface;
pub mod texture;

pub use backend::{Backend, BackendKind};
pub use cga_core;
pub use figure::Figure;
pub use film::Film;
pub use format::{SceneError, Source};
pub use frame::Frame;
pub use integrator::{Aov, RayCounts, Renderer, Window};
pub use invalid::Invalid;
pub use pipeline::{Options, Pipeline, Rendered, View};
pub use scene::Scene;
pub use settings::{Encoding, Settings};
