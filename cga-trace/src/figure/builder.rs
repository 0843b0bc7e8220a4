//! [`Figure`]: CGA objects handed over from Rust, each with a colour and an optional label,
//! drawn as what they are, e.g.
//! `Figure::new().add(&circle, "red").add(&line, "blue").render("fig.png")`.
//!
//! [`Figure::build`] makes the scene from the objects directly; [`Figure::scene`] writes it as
//! a scene file (each object a `type = "blade"` table of its coefficients, printed so that
//! they read back to the bit) that renders the same picture from the command line. The
//! camera frames every bounded object unless given.

use super::{DrawError, Drawing, Marks, Sizes};
use crate::Film;
use crate::film::{Output, OutputError};
use crate::format::{CameraSpec, Placement, draw, label};
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::light::{Light, Source as Emitter};
use crate::limits::MAX_OBJECTS;
use crate::material::Material;
use crate::output::{OutputFile, OutputFileError};
use crate::pipeline::{self, Options, RenderError, Rendered};
use crate::scene::{Object, Scene};
use crate::settings::{Background, Settings};
use cga_core::euclid::{E3, add, cross, norm, scale, sub, unit};
use cga_core::{GeometryError, Kind, classify_storage};
use std::fmt::Write as _;
use std::path::Path;
use std::sync::Arc;

/// Objects in a figure.
pub const MAX_FIGURE_OBJECTS: usize = 4096;

/// Why a figure cannot be drawn or written.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// A colour that is neither a name this module knows nor `#rrggbb`.
    #[error("object {index}: unknown colour `{colour}` (a name such as \"red\", or \"#rrggbb\")")]
    Colour {
        /// 1-based position of the object.
        index: usize,
        /// As given.
        colour: String,
    },
    /// An object that is not a blade, or one with no picture.
    #[error("object {index}: {reason}")]
    Blade {
        /// 1-based position of the object.
        index: usize,
        /// Why.
        reason: BladeError,
    },
    /// A mark's size or tube that is not a positive finite number.
    #[error("object {index}: a size or tube must be positive and finite, not {value}")]
    Size {
        /// 1-based position of the object.
        index: usize,
        /// As given.
        value: f64,
    },
    /// More objects than [`MAX_FIGURE_OBJECTS`].
    #[error("{0} objects exceed the figure's limit of {MAX_FIGURE_OBJECTS}")]
    TooMany(usize),
    /// The camera, given or framing the objects, that the figure cannot have (a position
    /// not finite, objects too far apart for one frame).
    #[error("camera: {0}")]
    Camera(#[source] Invalid),
    /// An object whose shapes or label cannot be built.
    #[error("object {index}: {reason}")]
    Object {
        /// 1-based position of the object.
        index: usize,
        /// Why.
        reason: Invalid,
    },
    /// Rendering or writing the picture.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// The output file.
    #[error(transparent)]
    File(#[from] OutputFileError),
    /// Encoding the picture.
    #[error(transparent)]
    Image(#[from] OutputError),
    /// Writing.
    #[error("writing {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// Why.
        source: std::io::Error,
    },
}

/// Why one object has no picture.
#[derive(Debug, thiserror::Error)]
pub enum BladeError {
    /// Not a blade (mixed grades, or not factorable).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// A blade with nothing to draw.
    #[error(transparent)]
    Draw(#[from] DrawError),
}

/// A cga-core object a figure draws: its coefficients in the null basis (`to_storage`
/// order), as the typed objects hold them (through the dense type's orthonormal basis an
/// object far from the origin would lose its small `eo` coefficients).
pub trait Drawable {
    /// The null-basis coefficients.
    fn coefficients(&self) -> [f64; 32];
}

macro_rules! drawable {
    ($($ty:ident),*) => {$(
        impl Drawable for cga_core::$ty<f64> {
            fn coefficients(&self) -> [f64; 32] {
                self.to_storage()
            }
        }
    )*};
}

drawable!(Vector, Bivector, Circle, Sphere, Line, Plane, FlatPoint, Multivector);

/// One object of a figure.
#[derive(Clone, Debug)]
struct Item {
    blade: [f64; 32],
    colour: String,
    label: Option<String>,
    segment: bool,
    size: Option<f64>,
    tube: Option<f64>,
}

impl Item {
    /// Its colour (checked known by [`Figure::drawings`]) with a softer highlight than the
    /// default's: `k_s = 0.4`, `q = 40`.
    fn material(&self) -> Material {
        let rgb = colour(&self.colour).unwrap_or([1.0; 3]);
        Material { ks: 0.4, q: 40.0, ..Material::new(rgb) }
    }
}

/// The field of view of a figure's camera, degrees.
const FOV: f64 = 40.0;

/// A figure's ambient light.
const AMBIENT: f64 = 0.3;

/// A figure's lights: directional, a key light from above and a dim fill.
const LIGHTS: [(E3, [f64; 3]); 2] = [([-0.3, 0.5, -1.0], [0.85, 0.85, 0.85]), ([0.6, 0.2, 0.3], [0.25, 0.25, 0.3])];

/// A picture of CGA objects, built by chaining [`Figure::add`] and friends.
#[derive(Clone, Debug)]
pub struct Figure {
    items: Vec<Item>,
    camera: Option<(E3, E3)>,
    width: u32,
    height: u32,
    background: Background,
}

impl Default for Figure {
    fn default() -> Self {
        Figure::new()
    }
}

impl Figure {
    /// An empty figure: 800 × 600 pixels, a dark background, the camera framing the objects.
    pub fn new() -> Figure {
        let background = Background::Colour([0.02, 0.025, 0.035]);
        Figure { items: Vec::new(), camera: None, width: 800, height: 600, background }
    }

    /// Add any cga-core object (a point, point pair, line, circle, plane, sphere, flat point,
    /// tangent or direction, or a dense blade) in `colour`: a name (`"red"`, `"sky"`, …, see
    /// [`colour`]) or `"#rrggbb"` (sRGB).
    pub fn add(mut self, object: &impl Drawable, colour: &str) -> Figure {
        let blade = object.coefficients();
        self.items.push(Item {
            blade,
            colour: colour.to_string(),
            label: None,
            segment: false,
            size: None,
            tube: None,
        });
        self
    }

    /// The figure with `change` made to the object added last (none: unchanged).
    fn last(mut self, change: impl FnOnce(&mut Item)) -> Figure {
        if let Some(item) = self.items.last_mut() {
            change(item);
        }
        self
    }

    /// Label the object added last (written beside it in the picture).
    pub fn label(self, text: &str) -> Figure {
        self.last(|item| item.label = Some(text.to_string()))
    }

    /// Draw the segment between the points of the point pair added last.
    pub fn segment(self) -> Figure {
        self.last(|item| item.segment = true)
    }

    /// The size of the last object's marks (world units): a point's ball radius, a plane
    /// patch's radius; by default a small fraction of the figure's extent (the patch, half).
    pub fn size(self, size: f64) -> Figure {
        self.last(|item| item.size = Some(size))
    }

    /// The radius of the last object's tube (a line's, a circle's, a segment's).
    pub fn tube(self, tube: f64) -> Figure {
        self.last(|item| item.tube = Some(tube))
    }

    /// Look from `position` at `look_at` (z up) instead of framing the objects.
    pub fn camera(mut self, position: E3, look_at: E3) -> Figure {
        self.camera = Some((position, look_at));
        self
    }

    /// What the picture shows where there are no objects: a linear colour (by default a dark
    /// blue-grey), or [`Background::Transparent`] (for a paper or a slide: PNG with alpha, or
    /// EXR with premultiplied alpha; labels opaque).
    pub fn background(mut self, background: Background) -> Figure {
        self.background = background;
        self
    }

    /// The picture's size in pixels.
    pub fn resolution(mut self, width: u32, height: u32) -> Figure {
        (self.width, self.height) = (width, height);
        self
    }

    /// Each object's classification and what it is drawn as with marks of no size (where it
    /// is, for framing and sizing the scene): checked, located errors.
    fn drawings(&self) -> Result<Vec<(Kind<f64>, Drawing)>, FigureError> {
        if self.items.len() > MAX_FIGURE_OBJECTS {
            return Err(FigureError::TooMany(self.items.len()));
        }
        let mut drawings = Vec::with_capacity(self.items.len());
        for (k, item) in self.items.iter().enumerate() {
            let blade = |reason: BladeError| FigureError::Blade { index: k + 1, reason };
            colour(&item.colour).ok_or_else(|| FigureError::Colour { index: k + 1, colour: item.colour.clone() })?;
            if let Some(value) = [item.size, item.tube].into_iter().flatten().find(|v| !(v.is_finite() && *v > 0.0)) {
                return Err(FigureError::Size { index: k + 1, value });
            }
            let kind = classify_storage(&item.blade).map_err(|e| blade(e.into()))?;
            let drawing = Drawing::of(kind, &Sizes::ZERO, item.segment).map_err(|e| blade(e.into()))?;
            drawings.push((kind, drawing));
        }
        Ok(drawings)
    }

    /// Where the camera is, what it looks at and which way is up: as given, or framing the
    /// objects' `places` (the bounded ones) from above and in front at [`FOV`].
    fn view(&self, places: &[(E3, f64)]) -> (E3, E3, E3) {
        let (position, look_at) = self.camera.unwrap_or_else(|| {
            let marks = Marks::for_scene(places, [0.0; 3], 1.0);
            let (centre, radius) = (marks.sizes.centre, marks.sizes.radius);
            // Far enough that the bounding sphere fits the narrower side's field of view.
            let aspect = f64::from(self.height.min(self.width)) / f64::from(self.width.max(1));
            let half = (FOV.to_radians() / 2.0).tan() * aspect;
            let distance = 1.15 * radius * (1.0 + half * half).sqrt() / half;
            let from = unit([0.45, -1.0, 0.6]).unwrap_or([0.0, -1.0, 0.0]);
            (add(centre, scale(from, distance)), centre)
        });
        let view = unit(sub(look_at, position)).unwrap_or([0.0, 1.0, 0.0]);
        let up = if norm(cross(view, [0.0, 0.0, 1.0])) < 1e-6 { [0.0, 1.0, 0.0] } else { [0.0, 0.0, 1.0] };
        (position, look_at, up)
    }

    /// Where each object is: a direction has no place. With `own`, each drawn with its own
    /// `size` and `tube` (the extent that sizes the frame and the marks; the camera frames
    /// the objects drawn with none).
    fn places(&self, drawings: &[(Kind<f64>, Drawing)], own: bool) -> Vec<(E3, f64)> {
        let sized = |item: &Item, kind: &Kind<f64>| {
            Drawing::of(*kind, &Sizes::ZERO.with(item.size, item.tube), item.segment).ok()
        };
        drawings
            .iter()
            .zip(&self.items)
            .filter_map(|((kind, drawing), item)| match own {
                true => sized(item, kind)?.place(kind),
                false => drawing.place(kind),
            })
            .collect()
    }

    /// The figure as a scene, built directly from its objects: the camera (given, or framing
    /// the objects), two lights, no shadows, and each object drawn as what it is with marks
    /// sized by the scene (its own `size` and `tube` where given). [`Figure::scene`] writes
    /// the same scene as a file.
    pub fn build(&self) -> Result<Scene, FigureError> {
        let drawings = self.drawings()?;
        let (position, look_at, up) = self.view(&self.places(&drawings, false));
        let places = self.places(&drawings, true);
        if !position.iter().chain(&look_at).all(|x| x.is_finite()) {
            return Err(FigureError::Camera(Invalid::Value("the camera's position and look_at must be finite")));
        }
        let built = CameraSpec::looking(position, look_at, up, FOV, (self.width, self.height))
            .build(None, 0.0)
            .map_err(FigureError::Camera)?;
        let camera = built.camera;
        let pixel = camera.x_max / camera.focal / f64::from(camera.width);
        let marks = Marks::for_scene(&places, built.position, pixel);
        let frame = Frame::around(built.position, places, pixel)
            .map_err(|span| FigureError::Camera(Invalid::Range(span.to_string())))?;
        let camera = camera.with_lens(built.lens.in_frame(frame.scale)).map_err(|e| FigureError::Camera(e.into()))?;
        let lights = LIGHTS
            .iter()
            .map(|&(direction, colour)| Light {
                source: Emitter::Directional(unit(direction).expect("not zero")),
                colour,
            })
            .collect();
        let place = Placement::new(None, &frame);
        let (mut objects, mut labels) = (Vec::with_capacity(self.items.len()), Vec::new());
        for (k, (item, (kind, _))) in self.items.iter().zip(&drawings).enumerate() {
            let index = k + 1;
            let drawing = Drawing::of(*kind, &marks.sizes.with(item.size, item.tube), item.segment)
                .map_err(|e| FigureError::Blade { index, reason: e.into() })?;
            let object = |reason| FigureError::Object { index, reason };
            let (shapes, anchor) = draw(&drawing, &place, &frame, &marks).map_err(object)?;
            let material = item.material();
            if let Some(text) = &item.label {
                labels.push(label(text, &shapes, anchor, material.colour).map_err(object)?);
            }
            let name: Arc<str> = format!("object {index}").into();
            objects.extend(shapes.into_iter().map(|shape| Object {
                name: name.clone(),
                shape,
                material,
                texture: None,
                solid: None,
                moving: false,
            }));
        }
        if objects.len() > MAX_OBJECTS {
            let found = objects.len() as u64;
            return Err(FigureError::Object {
                index: self.items.len(),
                reason: Invalid::Limit { what: "shapes", found, limit: MAX_OBJECTS as u64 },
            });
        }
        let mut settings = Settings { ambient: AMBIENT, shadows: false, ..Settings::default() };
        settings.set_background(self.background);
        Ok(Scene {
            frame,
            camera,
            objects,
            lights,
            settings,
            labels,
            pinned: false,
            shutter: None,
            environment: None,
            inputs: Vec::new(),
            templates: Vec::new(),
        })
    }

    /// The figure as a scene file (TOML) that reads back to the scene [`Figure::build`] gives:
    /// the camera, the lights and each object as a `type = "blade"` table of its
    /// coefficients, printed so that they read back to the bit.
    pub fn scene(&self) -> Result<String, FigureError> {
        let drawings = self.drawings()?;
        let (position, look_at, up) = self.view(&self.places(&drawings, false));
        let v = |x: E3| format!("[{:?}, {:?}, {:?}]", x[0], x[1], x[2]);
        let mut out = String::from("# A figure of CGA objects (cga_trace::figure::Figure).\n\n");
        let _ = write!(
            out,
            "[camera]\nposition = {}\nlook_at = {}\nup = {}\nfov = {FOV:?}\nwidth = {}\nheight = {}\n\n\
             [render]\nbackground = {}\nambient = {AMBIENT:?}\nshadows = false\n",
            v(position),
            v(look_at),
            v(up),
            self.width,
            self.height,
            match self.background {
                Background::Colour(c) => v(c),
                Background::Transparent => "\"transparent\"".into(),
            },
        );
        for (direction, colour) in LIGHTS {
            let _ = write!(out, "\n[[lights]]\ndirection = {}\ncolour = {}\n", v(direction), v(colour));
        }
        let names = super::null_basis_names();
        for item in &self.items {
            let _ = write!(out, "\n[[objects]]\ntype = \"blade\"\n");
            if let Some(label) = &item.label {
                let _ = writeln!(out, "label = {}", toml_string(label));
            }
            if item.segment {
                out += "segment = true\n";
            }
            if let Some(size) = item.size {
                let _ = writeln!(out, "size = {size:?}");
            }
            if let Some(tube) = item.tube {
                let _ = writeln!(out, "tube = {tube:?}");
            }
            let terms: Vec<String> = item
                .blade
                .iter()
                .zip(names)
                .filter(|(c, _)| **c != 0.0)
                .map(|(c, name)| format!("{name} = {c:?}"))
                .collect();
            let _ = writeln!(out, "blade = {{ {} }}", terms.join(", "));
            let m = item.material();
            let _ = writeln!(out, "material = {{ colour = {}, ks = {:?}, q = {:?} }}", v(m.colour), m.ks, m.q);
        }
        Ok(out)
    }

    /// The picture rendered with `options` (any AOV, back end, crop; through the pipeline
    /// every scene takes, [`crate::pipeline`]).
    pub fn rendered(&self, options: &Options) -> Result<Rendered, FigureError> {
        Ok(pipeline::render(&self.build()?, options, &|| {})?)
    }

    /// The picture, labels written in.
    pub fn film(&self) -> Result<Film, FigureError> {
        Ok(self.rendered(&Options::default())?.image(Output::Png8).into_owned())
    }

    /// Render to `path`: PNG, EXR or HDR by its extension, written to a temporary file and
    /// renamed on success.
    pub fn render(&self, path: impl AsRef<Path>) -> Result<(), FigureError> {
        let path = path.as_ref();
        Output::for_path(path, None)?.check_alpha(path, self.background == Background::Transparent)?;
        Ok(self.rendered(&Options::default())?.save(path, None)?)
    }

    /// Write the figure as a scene file to `path` (temporary file, renamed on success).
    pub fn write_scene(&self, path: impl AsRef<Path>) -> Result<(), FigureError> {
        use std::io::Write;
        let path = path.as_ref();
        let mut file = OutputFile::create(path, &[])?;
        let text = self.scene()?;
        file.write_all(text.as_bytes())
            .map_err(|source| FigureError::Io { path: path.display().to_string(), source })?;
        Ok(file.commit()?)
    }
}

/// A TOML basic string.
fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out += "\\\"",
            '\\' => out += "\\\\",
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out + "\""
}

/// The linear RGB of a colour: a name (`red`, `green`, `blue`, `yellow`, `orange`,
/// `purple`, `pink`, `cyan`, `magenta`, `sky`, `brown`, `white`, `grey`/`gray`, `black`) or
/// `#rrggbb`, both sRGB as written.
pub fn colour(name: &str) -> Option<[f64; 3]> {
    let srgb: [u8; 3] = match name.to_ascii_lowercase().as_str() {
        "red" => [230, 60, 50],
        "green" => [70, 190, 80],
        "blue" => [60, 110, 235],
        "yellow" => [245, 210, 60],
        "orange" => [245, 140, 40],
        "purple" => [150, 90, 210],
        "pink" => [245, 130, 190],
        "cyan" => [60, 210, 220],
        "magenta" => [220, 60, 200],
        "sky" => [120, 180, 245],
        "brown" => [150, 100, 60],
        "white" => [240, 240, 240],
        "grey" | "gray" => [150, 150, 150],
        "black" => [20, 20, 20],
        hex => {
            let hex = hex.strip_prefix('#').filter(|h| h.len() == 6 && h.is_ascii())?;
            let byte = |k: usize| u8::from_str_radix(&hex[2 * k..2 * k + 2], 16).ok();
            [byte(0)?, byte(1)?, byte(2)?]
        }
    };
    Some(srgb.map(crate::film::srgb_to_linear))
}
