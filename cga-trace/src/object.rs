//! One object of a scene: its name, its geometry and its material, as the scene format
//! builds it and the renderer reads it.

use crate::material::Material;
use crate::shapes::Shape;
use crate::texture::Texture;
use std::sync::Arc;

/// One object of a scene.
#[derive(Clone, Debug)]
pub struct Object {
    /// Its name in the scene file (or `object N`).
    pub name: String,
    /// Geometry.
    pub shape: Arc<dyn Shape>,
    /// Material.
    pub material: Material,
    /// A texture in place of the material's colour.
    pub texture: Option<Arc<Texture>>,
}
