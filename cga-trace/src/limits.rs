//! The limits a scene file and the command line are held to. Each bounds what one number can
//! make the renderer do — memory, time per pixel, stack — so that no input aborts, hangs or
//! fills the machine; a value beyond one is an error that names the field and the limit.

/// The largest magnitude of any number in a scene file. Conformal coefficients are products
/// of up to three coordinates (`|x|² / r`), so values up to 1e100 keep every one finite in
/// f64 (whose range ends near 1.8e308); beyond it a message about overflow would be all the
/// user got.
pub const MAX_MAGNITUDE: f64 = 1e100;

/// Pixels per side of an image.
pub const MAX_SIDE: u32 = 1 << 16;

/// Pixels in an image: 2²⁵ (33.5 million, enough for 8K UHD, 7680 × 4320). The film holds
/// 24 bytes a pixel, so at most 805 MB.
pub const MAX_PIXELS: u64 = 1 << 25;

/// Reflection depth. Bounces are traced in a loop, not by recursion, so depth costs no
/// stack; the limit bounds the time a hall of mirrors can take per pixel.
pub const MAX_DEPTH: u32 = 1024;

/// Samples per pixel (`--spp`, `spp`).
pub const MAX_SPP: u32 = 4096;

/// Lens rays a sample takes (`--blur-samples`, `blur_samples`): with [`MAX_SPP`], at most
/// 2²⁰ camera rays a pixel.
pub const MAX_BLUR_SAMPLES: u32 = 256;

/// Objects in a scene.
pub const MAX_OBJECTS: usize = 1 << 20;

/// Named materials in a scene (`[materials.NAME]`).
pub const MAX_MATERIALS: usize = 1 << 16;

/// Lights in a scene (each costs a shadow ray at every hit).
pub const MAX_LIGHTS: usize = 1024;

/// Points of an area light that light each hit (`samples`): each is a shadow ray.
pub const MAX_LIGHT_SAMPLES: u32 = 4096;

/// Octaves of a noise or marble texture (`octaves`): each is a lookup of four hashed lattice
/// values at every textured hit, so the limit bounds the time a lookup takes (beyond 16 the
/// finest octave is 2¹⁵ times finer than the first, far below a pixel).
pub const MAX_OCTAVES: u32 = 16;

/// Shadow rays one hit may cast: a point, spot or directional light casts one, an area light
/// its `samples`, summed over the scene's lights. 2¹⁶ bounds the time one pixel can take
/// (1,024 lights of 4,096 samples each would be 4.2 million shadow rays at every hit).
pub const MAX_SHADOW_RAYS: u64 = 1 << 16;

/// Instants a shutter is sampled at (`time_samples`): each is the scene placed anew.
pub const MAX_TIME_SAMPLES: u32 = 4096;

/// Pixels of an image a scene reads (a texture or an environment): 2²⁶ (an 8K × 8K map).
/// Each is held as three f32, so at most 805 MB; checked from the file's header before
/// it is decoded.
pub const MAX_IMAGE_PIXELS: u64 = 1 << 26;

/// Pixels of all the images a scene reads together: 2²⁷ (two 8K × 8K maps), at most 1.6 GB
/// held. Each image is read once however many names it is given (by device and inode), and
/// its size is checked against what is left before it is decoded, so that many large images
/// are refused by name rather than by an allocation failing.
pub const MAX_SCENE_IMAGE_PIXELS: u64 = 1 << 27;

/// Images a scene reads (textures and its environment).
pub const MAX_IMAGES: usize = 64;

/// Bytes of a mesh file a scene reads (OBJ or PLY): 2²⁷ (128 MiB), checked before it is
/// read. Its triangles count against [`MAX_OBJECTS`] with the scene's other shapes.
pub const MAX_MESH_FILE_BYTES: u64 = 1 << 27;

/// Vertices of a mesh file a scene reads, checked against the file's header before any is
/// read: four for each shape a scene may hold ([`MAX_OBJECTS`]). Reading holds 64 bytes a
/// vertex (position, normal and texture coordinates as f64) and 12 a triangle; the file's
/// bytes are streamed, never held whole.
pub const MAX_MESH_VERTICES_READ: usize = 4 * MAX_OBJECTS;

/// Files a scene includes (`include = […]`, followed through the files it names); all of
/// them together hold at most [`MAX_FILE_BYTES`].
pub const MAX_INCLUDES: usize = 64;

/// Mesh files a scene reads (each read once, however many objects use it).
pub const MAX_MESH_FILES: usize = 64;

/// Tokens (values, keys, brackets, separators; not whitespace or comments) of a scene file
/// outside its `[[objects]]` tables (camera, settings, lights, and any objects written
/// inline as `objects = [ … ]`), which are parsed as one document: TOML's parser holds its
/// tokens, events and values at once, some 150 bytes a token, so this bounds that at about
/// 160 MB. `[[objects]]` tables are parsed one at a time and count only against
/// [`MAX_FILE_BYTES`].
pub const MAX_DOCUMENT_TOKENS: usize = 1 << 20;

/// Bytes of a scene file. Larger files (or endless ones such as `/dev/zero`) are refused
/// after reading this much.
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// Vertices of an exported mesh, `(rings + 1)(segments + 1)`: 2²² (4.2 million, a 2048 × 2048
/// grid). A vertex costs 88 bytes while the mesh is built (position, normal, texture
/// coordinates and its share of the triangles) and 56 more while a glb is encoded, so the
/// largest mesh needs about 0.6 GB; it is checked before anything is allocated.
pub const MAX_MESH_VERTICES: usize = 1 << 22;

/// Rings and segments of an exported mesh, each.
pub const MAX_MESH_SIDE: usize = 1 << 16;

/// Frames of an animation (`--frames`): each is a file, so this bounds what one command
/// writes (a million frames of the smallest PNG fill some 100 MB of names and headers).
pub const MAX_FRAMES: usize = 1_000_000;

/// Worker threads (`--threads`). Rendering gains nothing beyond the machine's cores; this
/// bounds what asking for more costs (1,024 threads start in about 1.4 s on two cores,
/// 4,096 in 10 s).
pub const MAX_THREADS: usize = 1024;

/// Root-finding samples per ray of an evolved surface (`samples`, `leaves × per_leaf`).
pub const MAX_SURFACE_SAMPLES: usize = 1 << 16;

/// The image-plane extents over the focal length, `x_max / f` and `y_max / f`: between a
/// field of view of about 1e-4 degrees and one of 180 degrees less 1e-4 degrees. Outside it
/// every ray of the image is the same ray in f64, or no ray at all.
pub const EXTENT_OVER_FOCAL: (f64, f64) = (1e-6, 1e6);

#[cfg(test)]
mod tests {
    /// Every limit here, and those kept beside their modules, is in the table of limits
    /// (`docs/LIMITS.md`), with its reason: a limit added without a row fails here.
    #[test]
    fn every_limit_has_a_row_in_the_table() {
        let table = include_str!("../../docs/LIMITS.md");
        let here = include_str!("limits.rs");
        let names =
            here.lines().filter_map(|l| l.strip_prefix("pub const ")).map(|l| l.split(':').next().unwrap_or(""));
        let beside = ["MAX_KEYS", "MAX_LABEL_CHARS", "MAX_FIGURE_OBJECTS", "MAX_EXPOSURE"];
        let missing: Vec<&str> = names.chain(beside).filter(|n| !table.contains(&format!("`{n}`"))).collect();
        assert!(missing.is_empty(), "limits without a row in docs/LIMITS.md: {missing:?}");
    }
}
