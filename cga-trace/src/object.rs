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
    pub name: std::sync::Arc<str>,
    /// Geometry.
    pub shape: Arc<dyn Shape>,
    /// Material.
    pub material: Material,
    /// A texture in place of the material's colour.
    pub texture: Option<Arc<Texture>>,
    /// The closed solid this shape bounds together with others of the same id (a closed
    /// glass mesh's triangles): a ray that crosses any of them enters or leaves the whole.
    /// `None`: the shape is a solid of its own, or, if flat, a thin sheet.
    pub solid: Option<usize>,
    /// Whether it moves over the frame times (a `motion`): only objects that move are placed
    /// anew at each of a shutter's instants; the rest, and their hierarchy, are kept.
    pub moving: bool,
}
