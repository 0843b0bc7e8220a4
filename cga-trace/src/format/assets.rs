//! The scene's shared assets: named materials and the files its objects read.

use super::MaterialRef;
use super::specs::{AxisSpec, FlipSpec, MaterialSpec, PatternSpec, TextureSpec};
use crate::import::TriangleMesh;
use crate::input::{Identity, Input, open_regular};
use crate::invalid::Invalid;
use crate::limits::{MAX_IMAGES, MAX_MESH_FILES, MAX_OCTAVES, MAX_SCENE_IMAGE_PIXELS};
use crate::material::Material;
use crate::picture::Picture;
use crate::texture::{Axis, Bump, Noise, Pattern, Placement, Texture};
use cga_core::euclid::E3;
use std::cell::{Cell, RefCell};
use std::collections::BTreeMap;
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

    /// A material table as a checked material and its texture: its `texture`, with its
    /// `bump` (a bump alone wears the material's own colour).
    pub(crate) fn build(&self, spec: &MaterialSpec) -> Result<(Material, Option<Arc<Texture>>), Invalid> {
        let material = Material::from(spec);
        material.check()?;
        let texture = spec.texture.as_ref().map(|t| self.texture(t, false)).transpose()?;
        let texture = match spec.bump.as_ref() {
            None => texture,
            Some(b) => {
                let strength = b.get_ref().strength.unwrap_or(1.0);
                let bump = Bump { heights: self.texture(b, true)?, strength };
                Some(texture.unwrap_or_else(|| Texture::new(Pattern::Plain)).bump(bump))
            }
        };
        Ok((material, texture.map(Arc::new)))
    }

    /// A texture table (a `bump`'s where `bump`), checked: a pattern and its colour (none in
    /// a bump), or an image; positive repeats and scales; each pattern's own fields only on
    /// it, in range; `strength` only in a bump.
    fn texture(&self, spec: &Spanned<TextureSpec>, bump: bool) -> Result<Texture, Invalid> {
        let t = spec.get_ref();
        let why = |field, reason: String| Invalid::at(field, spec.span(), Invalid::Range(reason));
        if !bump && t.strength.is_some() {
            return Err(why(
                "strength",
                "`strength` is a `bump`'s (a texture's colours do not tilt the normal)".into(),
            ));
        }
        let repeat = t.repeat.unwrap_or([1.0, 1.0]);
        if !repeat.iter().all(|&r| r > 0.0) {
            return Err(why("repeat", "a texture's repeats must be > 0".into()));
        }
        let scale = t.scale.unwrap_or([1.0, 1.0]);
        if !scale.iter().all(|&r| r > 0.0) {
            return Err(why("scale", "a texture's scale must be > 0 (`flip` mirrors it)".into()));
        }
        let flip = match t.flip {
            None => [false, false],
            Some(FlipSpec::U) => [true, false],
            Some(FlipSpec::V) => [false, true],
            Some(FlipSpec::Both) => [true, true],
        };
        let place = Placement { scale, rotate: t.rotate.unwrap_or(0.0), offset: t.offset.unwrap_or([0.0, 0.0]), flip };
        let pattern = match (&t.pattern, &t.image) {
            (Some(p), None) => procedural(t, *p.get_ref(), bump).map_err(|(field, reason)| match field {
                "pattern" => Invalid::at(field, p.span(), Invalid::Range(reason)),
                _ => why(field, reason),
            })?,
            (None, Some(file)) => {
                if t.colour.is_some() {
                    return Err(why("colour", "an image texture takes its colours from the image".into()));
                }
                only_for(t, None).map_err(|(field, reason)| why(field, reason))?;
                Pattern::Image(self.image(file, "texture")?)
            }
            (Some(p), Some(_)) => {
                return Err(Invalid::at(
                    "pattern",
                    p.span(),
                    Invalid::Value("give a `pattern` or an `image`, not both"),
                ));
            }
            (None, None) => return Err(why("texture", "a texture needs a `pattern` or an `image`".into())),
        };
        Ok(Texture { pattern, repeat, place, bump: None })
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

/// The procedural pattern `pattern` of texture table `t` (a bump's where `bump`: heights,
/// no colour), its fields checked; else the field at fault and why.
fn procedural(t: &TextureSpec, pattern: PatternSpec, bump: bool) -> Result<Pattern, (&'static str, String)> {
    let colour = match (t.colour, bump) {
        (Some(_), true) => {
            return Err(("colour", "a bump's heights are its pattern's own values: it takes no `colour`".into()));
        }
        (None, true) => [1.0; 3],
        (Some(c), false) => c,
        (None, false) => return Err(("pattern", "a pattern needs its second `colour`".into())),
    };
    if colour.iter().any(|&c| c < 0.0) {
        return Err(("colour", "a texture's colour must be ≥ 0".into()));
    }
    only_for(t, Some(pattern))?;
    let octaves = t.octaves.unwrap_or(Noise::default().octaves);
    if !(1..=MAX_OCTAVES).contains(&octaves) {
        return Err(("octaves", format!("a noise's octaves must be 1 to {MAX_OCTAVES}, not {octaves}")));
    }
    let noise = Noise { seed: t.seed.unwrap_or(0), octaves };
    Ok(match pattern {
        PatternSpec::Checker => Pattern::Checker(colour),
        PatternSpec::Stripes => Pattern::Stripes(colour),
        PatternSpec::Gradient => {
            Pattern::Gradient(colour, if t.along == Some(AxisSpec::V) { Axis::V } else { Axis::U })
        }
        PatternSpec::Noise => Pattern::Noise(colour, noise),
        PatternSpec::Marble => {
            let turbulence = t.turbulence.unwrap_or(1.0);
            if turbulence < 0.0 {
                return Err(("turbulence", "marble's turbulence must be ≥ 0".into()));
            }
            Pattern::Marble { colour, noise, turbulence }
        }
        PatternSpec::Bricks => {
            let (brick, mortar) = (t.brick.unwrap_or([1.0, 0.5]), t.mortar.unwrap_or(0.05));
            if !brick.iter().all(|&b| b > 0.0) {
                return Err(("brick", "a brick's length and height must be > 0".into()));
            }
            if !(mortar >= 0.0 && mortar < brick[0].min(brick[1])) {
                return Err(("mortar", "mortar must be ≥ 0 and narrower than a brick's length and height".into()));
            }
            Pattern::Bricks { colour, brick, mortar }
        }
    })
}

/// Refuses a pattern's own field given to another pattern (`None`: an image, which has none).
fn only_for(t: &TextureSpec, pattern: Option<PatternSpec>) -> Result<(), (&'static str, String)> {
    use PatternSpec::{Bricks, Gradient, Marble, Noise};
    let owners: [(&'static str, bool, &[PatternSpec], &str); 6] = [
        ("along", t.along.is_some(), &[Gradient], "a gradient's"),
        ("turbulence", t.turbulence.is_some(), &[Marble], "marble's"),
        ("octaves", t.octaves.is_some(), &[Noise, Marble], "noise's and marble's"),
        ("seed", t.seed.is_some(), &[Noise, Marble], "noise's and marble's"),
        ("brick", t.brick.is_some(), &[Bricks], "bricks'"),
        ("mortar", t.mortar.is_some(), &[Bricks], "bricks'"),
    ];
    for (field, given, patterns, whose) in owners {
        if given && !pattern.is_some_and(|p| patterns.contains(&p)) {
            return Err((field, format!("`{field}` is {whose} alone")));
        }
    }
    Ok(())
}
