//! The scene's shared assets: named materials and the files its objects read.

use super::MaterialRef;
use super::specs::{MaterialSpec, PatternSpec, TextureSpec};
use crate::import::TriangleMesh;
use crate::invalid::Invalid;
use crate::limits::{MAX_IMAGES, MAX_MESH_FILES};
use crate::material::Material;
use crate::picture::Picture;
use crate::texture::{Pattern, Texture};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use toml::Spanned;

/// What a scene shares among its objects: its named materials, checked, and the files it
/// reads — images for textures and the environment, meshes — each read once, relative to
/// the scene file's folder.
pub(crate) struct Assets {
    named: BTreeMap<String, (Material, Option<Arc<Texture>>)>,
    folder: PathBuf,
    images: Cache<Picture>,
    meshes: Cache<TriangleMesh>,
    /// Whether each mesh read closes a solid, worked out once per file (not per instance).
    closed: RefCell<BTreeMap<String, bool>>,
}

/// Files read so far, by the name the scene gives them.
type Cache<T> = RefCell<BTreeMap<String, Arc<T>>>;

impl Assets {
    /// No named materials yet, files read relative to `folder`.
    pub(crate) fn new(folder: &Path) -> Self {
        Assets {
            named: Default::default(),
            folder: folder.to_path_buf(),
            images: Default::default(),
            meshes: Default::default(),
            closed: Default::default(),
        }
    }

    /// `[materials.NAME]`, checked.
    pub(crate) fn insert(&mut self, name: String, spec: &MaterialSpec) -> Result<(), Invalid> {
        let built = self.build(spec)?;
        self.named.insert(name, built);
        Ok(())
    }

    /// A material table as a checked material and its texture.
    pub(crate) fn build(&self, spec: &MaterialSpec) -> Result<(Material, Option<Arc<Texture>>), Invalid> {
        let material = Material::from(spec);
        material.check()?;
        let texture = spec.texture.as_ref().map(|t| self.texture(t)).transpose()?;
        Ok((material, texture))
    }

    /// A texture table, checked: a pattern and its colour, or an image; positive repeats.
    pub(crate) fn texture(&self, spec: &Spanned<TextureSpec>) -> Result<Arc<Texture>, Invalid> {
        let t = spec.get_ref();
        let why = |field, span: Range<usize>, reason| Invalid::at(field, span, Invalid::Value(reason));
        let repeat = t.repeat.unwrap_or([1.0, 1.0]);
        if !repeat.iter().all(|&r| r > 0.0) {
            return Err(why("repeat", spec.span(), "a texture's repeats must be > 0"));
        }
        let pattern = match (&t.pattern, &t.image) {
            (Some(p), None) => {
                let colour = t.colour.ok_or(why("pattern", p.span(), "a pattern needs its second `colour`"))?;
                if colour.iter().any(|&c| c < 0.0) {
                    return Err(why("colour", spec.span(), "a texture's colour must be ≥ 0"));
                }
                match p.get_ref() {
                    PatternSpec::Checker => Pattern::Checker(colour),
                    PatternSpec::Stripes => Pattern::Stripes(colour),
                }
            }
            (None, Some(file)) => {
                if t.colour.is_some() {
                    return Err(why("colour", spec.span(), "an image texture takes its colours from the image"));
                }
                Pattern::Image(self.image(file)?)
            }
            (Some(p), Some(_)) => return Err(why("pattern", p.span(), "give a `pattern` or an `image`, not both")),
            (None, None) => return Err(why("texture", spec.span(), "a texture needs a `pattern` or an `image`")),
        };
        Ok(Arc::new(Texture { pattern, repeat }))
    }

    /// The image `file` names (relative to the scene's folder), read once.
    pub(crate) fn image(&self, file: &Spanned<String>) -> Result<Arc<Picture>, Invalid> {
        self.read(&self.images, ("image", "images", MAX_IMAGES), file, Picture::load)
    }

    /// The mesh `file` names (relative to the scene's folder), read once.
    pub(crate) fn mesh(&self, file: &Spanned<String>) -> Result<Arc<TriangleMesh>, Invalid> {
        self.read(&self.meshes, ("file", "mesh files", MAX_MESH_FILES), file, TriangleMesh::load)
    }

    /// Whether the mesh in `file` closes a solid ([`TriangleMesh::is_closed`]).
    pub(crate) fn mesh_is_closed(&self, file: &Spanned<String>) -> Result<bool, Invalid> {
        if let Some(&closed) = self.closed.borrow().get(file.get_ref()) {
            return Ok(closed);
        }
        let closed = self.mesh(file)?.is_closed();
        self.closed.borrow_mut().insert(file.get_ref().clone(), closed);
        Ok(closed)
    }

    /// `file` from `cache`, or read by `load` (errors at `field`) unless `limit` files of
    /// its kind are read already.
    fn read<T>(
        &self,
        cache: &Cache<T>,
        (field, what, limit): (&'static str, &'static str, usize),
        file: &Spanned<String>,
        load: impl FnOnce(&Path) -> Result<T, Invalid>,
    ) -> Result<Arc<T>, Invalid> {
        if let Some(p) = cache.borrow().get(file.get_ref()) {
            return Ok(p.clone());
        }
        let at = |reason| Invalid::at(field, file.span(), reason);
        if cache.borrow().len() >= limit {
            return Err(at(Invalid::Limit { what, found: limit as u64 + 1, limit: limit as u64 }));
        }
        let read = Arc::new(load(&self.folder.join(file.get_ref())).map_err(at)?);
        cache.borrow_mut().insert(file.get_ref().clone(), read.clone());
        Ok(read)
    }

    /// The material an object gives, by table or by name.
    pub(crate) fn resolve(&self, given: &Spanned<MaterialRef>) -> Result<(Material, Option<Arc<Texture>>), Invalid> {
        match given.get_ref() {
            MaterialRef::Given(m) => self.build(m),
            MaterialRef::Named(n) => self.named.get(n).cloned().ok_or_else(|| {
                let known: Vec<&str> = self.named.keys().map(String::as_str).collect();
                let why = format!(
                    "no material `{}` in the file's [materials] (it has {})",
                    n.escape_debug(),
                    if known.is_empty() { "none".into() } else { format!("`{}`", known.join("`, `")) }
                );
                Invalid::at("material", given.span(), Invalid::Range(why))
            }),
        }
    }
}
