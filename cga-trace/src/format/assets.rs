//! The scene's shared assets: named materials and the files its objects read.

use super::MaterialRef;
use super::specs::{MaterialSpec, PatternSpec, TextureSpec};
use crate::import::TriangleMesh;
use crate::input::{Identity, Input, open_regular};
use crate::invalid::Invalid;
use crate::limits::{MAX_IMAGES, MAX_MESH_FILES, MAX_SCENE_IMAGE_PIXELS};
use crate::material::Material;
use crate::picture::Picture;
use crate::texture::{Pattern, Texture};
use cga_core::euclid::E3;
use std::cell::{Cell, RefCell};
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use toml::Spanned;

/// What a scene shares among its objects: its named materials, checked, and the files it
/// reads — images for textures and the environment, meshes — each read once (by device and
/// inode, whatever names it is given), relative to the scene file's folder, and recorded
/// with its role.
pub(crate) struct Assets {
    named: BTreeMap<String, (Material, Option<Arc<Texture>>)>,
    folder: PathBuf,
    images: Cache<Picture>,
    meshes: Cache<TriangleMesh>,
    /// Whether each mesh read closes a solid, and the sphere about its vertices, worked out
    /// once per file (not per instance).
    shape: RefCell<BTreeMap<Identity, MeshShape>>,
    /// Pixels the images read so far hold, against [`MAX_SCENE_IMAGE_PIXELS`].
    pixels: Cell<u64>,
    /// Every file read, with its role, in the order read.
    inputs: RefCell<Vec<Input>>,
    /// The roles each file has been read in.
    roles: RefCell<std::collections::BTreeSet<(Identity, &'static str)>>,
}

/// Files read so far: each file's identity by the name the scene gives it, and the file read.
struct Cache<T> {
    names: RefCell<BTreeMap<String, Identity>>,
    read: RefCell<BTreeMap<Identity, Arc<T>>>,
}

impl<T> Default for Cache<T> {
    fn default() -> Self {
        Cache { names: Default::default(), read: Default::default() }
    }
}

/// What instances of a mesh need of it, worked out once per file.
#[derive(Clone, Copy)]
struct MeshShape {
    closed: bool,
    bounds: Option<(E3, f64)>,
}

impl Assets {
    /// No named materials yet, files read relative to `folder`.
    pub(crate) fn new(folder: &Path) -> Self {
        Assets {
            named: Default::default(),
            folder: folder.to_path_buf(),
            images: Default::default(),
            meshes: Default::default(),
            shape: Default::default(),
            pixels: Cell::new(0),
            inputs: Default::default(),
            roles: Default::default(),
        }
    }

    /// The files read so far, with their roles.
    pub(crate) fn inputs(&self) -> Vec<Input> {
        self.inputs.borrow().clone()
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
                Pattern::Image(self.image(file, "texture")?)
            }
            (Some(p), Some(_)) => return Err(why("pattern", p.span(), "give a `pattern` or an `image`, not both")),
            (None, None) => return Err(why("texture", spec.span(), "a texture needs a `pattern` or an `image`")),
        };
        Ok(Arc::new(Texture { pattern, repeat }))
    }

    /// The image `file` names (relative to the scene's folder), read once; `role` says what
    /// it is to the scene (`texture`, `environment image`). Images count against
    /// [`MAX_IMAGES`] and, by their pixels, [`MAX_SCENE_IMAGE_PIXELS`], checked from each
    /// file's header before it is decoded.
    pub(crate) fn image(&self, file: &Spanned<String>, role: &'static str) -> Result<Arc<Picture>, Invalid> {
        let read = self.read(&self.images, ("image", "images", MAX_IMAGES, role), file, |f, _, path| {
            let picture = Picture::read(f, path, MAX_SCENE_IMAGE_PIXELS - self.pixels.get())?;
            self.pixels.set(self.pixels.get() + u64::from(picture.width) * u64::from(picture.height));
            Ok(picture)
        })?;
        Ok(read)
    }

    /// The mesh `file` names (relative to the scene's folder), read once.
    pub(crate) fn mesh(&self, file: &Spanned<String>) -> Result<Arc<TriangleMesh>, Invalid> {
        self.read(&self.meshes, ("file", "mesh files", MAX_MESH_FILES, "mesh"), file, TriangleMesh::read)
    }

    /// Whether the mesh in `file` closes a solid ([`TriangleMesh::is_closed`]).
    pub(crate) fn mesh_is_closed(&self, file: &Spanned<String>) -> Result<bool, Invalid> {
        Ok(self.mesh_shape(file)?.closed)
    }

    /// The sphere about the vertices of the mesh in `file` ([`TriangleMesh::bounds`]).
    pub(crate) fn mesh_bounds(&self, file: &Spanned<String>) -> Result<Option<(E3, f64)>, Invalid> {
        Ok(self.mesh_shape(file)?.bounds)
    }

    fn mesh_shape(&self, file: &Spanned<String>) -> Result<MeshShape, Invalid> {
        let mesh = self.mesh(file)?;
        let identity = self.meshes.names.borrow()[file.get_ref()].clone();
        if let Some(&shape) = self.shape.borrow().get(&identity) {
            return Ok(shape);
        }
        let shape = MeshShape { closed: mesh.is_closed(), bounds: mesh.bounds() };
        self.shape.borrow_mut().insert(identity, shape);
        Ok(shape)
    }

    /// `file` from `cache` (by the name given, or by the file it names), or read by `load`
    /// (errors at `field`) unless `limit` files of its kind are read already; recorded as an
    /// input with `role`. Only regular files are opened ([`open_regular`]).
    fn read<T>(
        &self,
        cache: &Cache<T>,
        (field, what, limit, role): (&'static str, &'static str, usize, &'static str),
        file: &Spanned<String>,
        load: impl FnOnce(std::fs::File, u64, &Path) -> Result<T, Invalid>,
    ) -> Result<Arc<T>, Invalid> {
        if let Some(identity) = cache.names.borrow().get(file.get_ref()) {
            return Ok(cache.read.borrow()[identity].clone());
        }
        let at = |reason| Invalid::at(field, file.span(), reason);
        let path = self.folder.join(file.get_ref());
        let unreadable = |e: std::io::Error| {
            let text = format!("{}: {e}", path.display());
            at(if role == "mesh" { Invalid::Mesh(text) } else { Invalid::Image(text) })
        };
        let (opened, identity, size) = open_regular(&path).map_err(unreadable)?;
        let known = cache.read.borrow().get(&identity).cloned();
        let read = match known {
            Some(read) => read,
            None => {
                if cache.read.borrow().len() >= limit {
                    return Err(at(Invalid::Limit { what, found: limit as u64 + 1, limit: limit as u64 }));
                }
                let read = Arc::new(load(opened, size, &path).map_err(at)?);
                cache.read.borrow_mut().insert(identity.clone(), read.clone());
                read
            }
        };
        // One file in two roles (a texture and the environment) is both.
        if self.roles.borrow_mut().insert((identity.clone(), role)) {
            self.inputs.borrow_mut().push(Input { role, path });
        }
        cache.names.borrow_mut().insert(file.get_ref().clone(), identity);
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
