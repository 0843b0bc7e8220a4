//! The scene file format (TOML, via serde): what each table and object may hold, and how a
//! parsed file becomes the camera, frame and shapes of a [`Scene`](crate::Scene).
//!
//! Unknown fields are errors; every number is checked where it is read (`numbers.rs`), so
//! that its error points at it. Each table has its file: `camera.rs`, `light.rs`,
//! `environment.rs`, `specs.rs` (`[render]`, materials) and `objects/`, one file per object
//! kind; `transform.rs` reads motors and steps, `motion.rs` keyframes. `load.rs` reads a file
//! with its includes, images and meshes and places it at any time of its motion.

mod assets;
mod blade;
mod camera;
mod environment;
mod error;
mod given;
mod include;
mod instance;
mod light;
mod load;
mod marks;
mod motion;
mod numbers;
pub mod objects;
mod sections;
mod specs;
mod transform;

pub(crate) use assets::Assets;
pub use error::SceneError;
pub use load::Source;
pub use motion::MAX_KEYS;
pub use objects::{COMMON, Field, Role, fields, kinds};
pub(crate) use specs::{MaterialRef, MaterialSpec, SettingsSpec};

// What a scene built in code (`Figure`) shares with a file's: the camera, a drawing's
// shapes and label, placed in the frame.
pub(crate) use camera::CameraSpec;
pub(crate) use objects::{drawn::draw, label};
pub(crate) use transform::Placement;

use environment::EnvironmentSpec;
use light::LightSpec;
use serde::Deserialize;
use toml::Spanned;

/// A scene file's tables but its objects.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SceneFile {
    pub camera: Spanned<CameraSpec>,
    pub render: Option<Spanned<SettingsSpec>>,
    #[serde(default)]
    pub lights: Vec<Spanned<LightSpec>>,
    /// What rays leaving the scene see.
    pub environment: Option<Spanned<EnvironmentSpec>>,
    /// Named materials, `[materials.NAME]`, that objects give by name.
    #[serde(default)]
    pub materials: std::collections::BTreeMap<String, Spanned<MaterialSpec>>,
    /// Read one at a time by [`Scene::parse`](crate::Scene::parse), which takes the list out
    /// first; here only to report an `objects` that is not a list.
    #[serde(default, rename = "objects")]
    pub _objects: Vec<serde::de::IgnoredAny>,
}
