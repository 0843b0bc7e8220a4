//! cga-trace: a ray tracer whose geometry is conformal geometric algebra (cga-core).
//!
//! Kept apart as pbrt keeps them: [`camera`] makes rays (eq. 2), [`shapes`] and [`surface`]
//! meet them with objects (CGA meets; evolved surfaces by robust root isolation), [`render`]
//! shades (eq. 12), [`film`] stores and encodes, [`scene`] reads TOML. [`backend`] runs the
//! same renderer on the sparse types, a dense multivector or plain vectors, to compare them;
//! [`packet`] traces camera and shadow rays four at a time on the sparse types' SIMD lanes.

pub mod backend;
pub mod bvh;
pub mod camera;
pub mod colour;
pub mod film;
pub mod format;
pub mod frame;
pub mod invalid;
pub mod lanes;
pub mod light;
pub mod limits;
pub mod material;
#[cfg(feature = "evolved")]
pub mod mesh;
mod nearest;
pub mod object;
pub mod output;
pub mod packet;
pub mod ray;
pub mod render;
pub mod scene;
pub mod settings;
pub mod shade;
pub mod shapes;
pub mod surface;

pub use backend::{Backend, BackendKind};
pub use cga_core;
pub use film::Film;
pub use frame::Frame;
pub use invalid::Invalid;
pub use render::{Aov, Renderer};
pub use scene::{Scene, SceneError};
pub use settings::{Encoding, Settings};
