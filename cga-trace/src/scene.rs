//! Scenes as TOML: the file format, and its checked conversion into a [`Scene`].
//!
//! Unknown fields are errors; every error names the file, line and column, and for invalid
//! geometry the object's name (see the README for the format).

use crate::camera::{Camera, CameraError};
use crate::frame::Frame;
use crate::shapes::{DiskShape, PlaneShape, Shape, SphereShape, TriangleShape};
#[cfg(feature = "evolved")]
use crate::surface::EvolvedSurface;
use crate::surface::Method;
use cga_core::euclid::E3;
use cga_core::{GeometryError, Motor, Rotor};
use serde::Deserialize;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;
use toml::Spanned;

/// Surface colour and Blinn–Phong coefficients.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Linear RGB in [0, 1].
    pub colour: [f64; 3],
    /// Ambient coefficient `k_a`.
    #[serde(default = "half")]
    pub ka: f64,
    /// Diffuse coefficient `k_d`.
    #[serde(default = "one")]
    pub kd: f64,
    /// Specular coefficient `k_s`.
    #[serde(default = "one")]
    pub ks: f64,
    /// Specular exponent `q`.
    #[serde(default = "hundred")]
    pub q: f64,
    /// Mirror reflection `k_r`.
    #[serde(default)]
    pub kr: f64,
}

fn half() -> f64 {
    0.5
}
fn one() -> f64 {
    1.0
}
fn hundred() -> f64 {
    100.0
}

/// A point light.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Light {
    /// Where it is.
    pub position: E3,
    /// Linear RGB intensity.
    #[serde(default = "white")]
    pub colour: [f64; 3],
}

fn white() -> [f64; 3] {
    [1.0; 3]
}

/// How the output PNG encodes linear values.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, Default, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Encoding {
    /// The sRGB transfer curve (the default).
    #[default]
    Srgb,
    /// Clipped linear values, as the original renderer writes them.
    Linear,
}

/// Global render settings.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    /// Reflection recursion depth.
    #[serde(default = "five")]
    pub max_depth: u32,
    /// Colour of rays that hit nothing.
    #[serde(default)]
    pub background: [f64; 3],
    /// Ambient light intensity (times `k_a` and the colour).
    #[serde(default = "ambient")]
    pub ambient: f64,
    /// Fraction of a light's diffuse and specular that passes a blocker (0: hard shadows).
    #[serde(default)]
    pub shadow_transmission: f64,
    /// Whether shadow rays are cast at all (`false`: every light reaches every point).
    #[serde(default = "yes")]
    pub shadows: bool,
    /// `f_att = min(1, 1 / (c0 + c1 d + c2 d²))`, `d` the distance to the light.
    #[serde(default = "no_attenuation")]
    pub attenuation: [f64; 3],
    /// PNG encoding.
    #[serde(default)]
    pub encoding: Encoding,
    /// How rays meet evolved surfaces (default: hybrid — the α-tree culls, the degree-8
    /// polynomial finds the roots; docs/SURFACE.md).
    #[serde(default)]
    pub surface_method: Method,
}

fn yes() -> bool {
    true
}
fn five() -> u32 {
    5
}
fn ambient() -> f64 {
    0.3
}
fn no_attenuation() -> [f64; 3] {
    [1.0, 0.0, 0.0]
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_depth: five(),
            background: [0.0; 3],
            ambient: ambient(),
            shadow_transmission: 0.0,
            shadows: true,
            attenuation: no_attenuation(),
            encoding: Encoding::Srgb,
            surface_method: Method::default(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    camera: Spanned<CameraSpec>,
    render: Option<Spanned<Settings>>,
    #[serde(default)]
    lights: Vec<Spanned<Light>>,
    #[serde(default)]
    objects: Vec<Spanned<ObjectSpec>>,
}

/// The camera: a pose (`position`, `look_at`, `up`, or a `motor`), focal length, image-plane
/// extents and pixel size.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraSpec {
    position: Option<E3>,
    look_at: Option<E3>,
    #[serde(default = "z_up")]
    up: E3,
    /// Motor coefficients `s, e12, e13, e23, e1i, e2i, e3i, e123i` (instead of position/look_at).
    motor: Option<[f64; 8]>,
    #[serde(default = "one")]
    focal_length: f64,
    /// Image-plane width; default 2 (90° horizontal field of view with `f = 1`).
    x_max: Option<f64>,
    /// Image-plane height; default `x_max · height / width`.
    y_max: Option<f64>,
    width: u32,
    height: u32,
}

fn z_up() -> E3 {
    [0.0, 0.0, 1.0]
}

/// A circle for an evolved surface: Euclidean, or the original renderer's grade-3
/// coefficients in the orthonormal basis, order e123, e124, e125, e134, e135, e145, e234,
/// e235, e245, e345.
// Still parsed without the `evolved` feature, so that such objects get a clear error.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
struct CircleSpec {
    centre: Option<E3>,
    normal: Option<E3>,
    radius: Option<f64>,
    blade: Option<[f64; 10]>,
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
enum ObjectSpec {
    Sphere { name: Option<String>, material: Material, centre: E3, radius: f64 },
    Plane { name: Option<String>, material: Material, point: E3, normal: E3 },
    Disk { name: Option<String>, material: Material, centre: E3, normal: E3, radius: f64 },
    Triangle { name: Option<String>, material: Material, corners: [E3; 3] },
    Evolved { name: Option<String>, material: Material, c1: Box<CircleSpec>, c2: Box<CircleSpec> },
}

/// One object of a scene.
#[derive(Clone, Debug)]
pub struct Object {
    /// Its name in the scene file (or `object N`).
    pub name: String,
    /// Geometry.
    pub shape: Arc<dyn Shape>,
    /// Material.
    pub material: Material,
}

/// A scene ready to render, in its [`Frame`]: camera, objects and lights are given
/// relative to the camera's position, in units of `frame.scale` (see [`crate::frame`]).
#[derive(Clone, Debug)]
pub struct Scene {
    /// World coordinates → the coordinates everything below is given in.
    pub frame: Frame,
    /// The camera, at the frame's origin.
    pub camera: Camera,
    /// Objects.
    pub objects: Vec<Object>,
    /// Point lights.
    pub lights: Vec<Light>,
    /// Settings.
    pub settings: Settings,
}

/// What is wrong with a scene file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file cannot be read.
    #[error("{file}: {source}")]
    Io {
        /// The file.
        file: String,
        /// Why.
        source: std::io::Error,
    },
    /// The TOML is malformed, or a field is unknown, missing or of the wrong type.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What and which field.
        message: String,
    },
    /// Well-formed, but the geometry or values are invalid.
    #[error("{file}:{line}:{column}: {what}: {reason}")]
    Invalid {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The object (`object `disk`) or table (`camera`).
        what: String,
        /// Why.
        reason: String,
    },
}

impl Scene {
    /// Read and check a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io { file: file.clone(), source })?;
        Scene::parse(&text, &file)
    }

    /// Check a scene given as text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
        let at = |span: Option<Range<usize>>| line_column(text, span.map_or(0, |s| s.start));
        let spec: SceneFile = toml::from_str(text).map_err(|e| {
            let (line, column) = at(e.span());
            let mut message = e.message().trim().to_string();
            if let Some(key) = key_at(text, e.span().map_or(0, |s| s.start)).filter(|k| !message.contains(k.as_str())) {
                message = format!("field `{key}`: {message}");
            }
            SceneError::Syntax { file: file.into(), line, column, message }
        })?;
        let invalid = |span: Range<usize>, what: String, reason: String| {
            let (line, column) = at(Some(span));
            SceneError::Invalid { file: file.into(), line, column, what, reason }
        };
        let (settings, render_span) = spec.render.map_or((Settings::default(), 0..0), |r| (*r.get_ref(), r.span()));
        check_settings(&settings).map_err(|reason| invalid(render_span, "render".into(), reason))?;
        let camera_span = spec.camera.span();
        let anchors: Vec<E3> = (spec.objects.iter().filter_map(|o| o.get_ref().anchor()))
            .chain(spec.lights.iter().map(|l| l.get_ref().position))
            .collect();
        let (camera, frame) = build_camera(spec.camera.into_inner(), anchors)
            .map_err(|reason| invalid(camera_span, "camera".into(), reason))?;
        for (k, light) in spec.lights.iter().enumerate() {
            let l = light.get_ref();
            if !l.position.iter().chain(&l.colour).all(|x| x.is_finite()) || l.colour.iter().any(|&c| c < 0.0) {
                let reason = "position and colour must be finite, colour ≥ 0".into();
                return Err(invalid(light.span(), format!("light {}", k + 1), reason));
            }
        }
        let lights = (spec.lights.into_iter().map(Spanned::into_inner))
            .map(|l| Light { position: frame.point(l.position), ..l })
            .collect();
        let mut objects = Vec::new();
        for (k, spanned) in spec.objects.into_iter().enumerate() {
            let span = spanned.span();
            let (object, name) = build_object(spanned.into_inner(), k, settings.surface_method, &frame);
            let what = format!("object `{name}`");
            objects.push(object.map_err(|reason| invalid(span, what, reason))?);
        }
        Ok(Scene { frame, camera, objects, lights, settings })
    }
}

/// The key assigned at or just before `offset` (`max_depth` in `max_depth = "deep"`),
/// for errors whose message does not name the field.
fn key_at(text: &str, offset: usize) -> Option<String> {
    let before = &text[..offset.min(text.len())];
    let segment = before.rsplit(['\n', '{', ',']).next()?;
    let key = segment.split('=').next()?.trim();
    (!key.is_empty() && segment.contains('=') && key.chars().all(|c| c.is_alphanumeric() || c == '_' || c == '.'))
        .then(|| key.to_string())
}

/// 1-based line and column of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

fn check_settings(s: &Settings) -> Result<(), String> {
    let finite =
        s.background.iter().chain(&s.attenuation).chain([&s.ambient, &s.shadow_transmission]).all(|x| x.is_finite());
    if !finite {
        return Err("values must be finite".into());
    }
    if !(0.0..=1.0).contains(&s.shadow_transmission) {
        return Err("shadow_transmission must lie in [0, 1]".into());
    }
    if s.attenuation.iter().any(|&c| c < 0.0) || s.attenuation.iter().all(|&c| c == 0.0) {
        return Err("attenuation coefficients must be ≥ 0 and not all zero".into());
    }
    s.surface_method.check().map_err(|e| format!("surface_method: {e}"))?;
    Ok(())
}

/// The camera in the frame centred on it (sized by `anchors`), and that frame.
fn build_camera(c: CameraSpec, anchors: Vec<E3>) -> Result<(Camera, Frame), String> {
    let pose = match (c.motor, c.position, c.look_at) {
        (Some(m), None, None) => {
            let motor = Motor::from_array(m);
            motor.try_normalise().ok_or("the motor is zero")?
        }
        (None, Some(p), Some(t)) => Camera::pose_look_at(p, t, c.up).map_err(|e| e.to_string())?,
        _ => return Err("give either `motor`, or `position` and `look_at`".into()),
    };
    let x_max = c.x_max.unwrap_or(2.0);
    let y_max = c.y_max.unwrap_or(x_max * f64::from(c.height) / f64::from(c.width.max(1)));
    let world = Camera::new(pose, c.focal_length, x_max, y_max, c.width, c.height).map_err(|e| e.to_string())?;
    let frame = Frame::around(world.position(), anchors);
    // In its own frame the camera only turns: M = T R, and R is M's scalar and e_jk parts.
    let turn = Rotor { s: pose.s, e12: pose.e12, e13: pose.e13, e23: pose.e23 };
    let turn = Motor::from(turn.try_normalise().ok_or("the motor has no rotation part")?);
    let camera =
        Camera::new(turn, c.focal_length, x_max, y_max, c.width, c.height).map_err(|e: CameraError| e.to_string())?;
    Ok((camera, frame))
}

fn check_material(m: &Material) -> Result<(), String> {
    let all = m.colour.iter().chain([&m.ka, &m.kd, &m.ks, &m.q, &m.kr]);
    if all.clone().any(|x| !x.is_finite() || *x < 0.0) {
        return Err("material values must be finite and ≥ 0".into());
    }
    Ok(())
}

fn geometry(e: GeometryError) -> String {
    e.to_string()
}

impl ObjectSpec {
    /// A point that places the object (for sizing the scene's frame), if it has one.
    fn anchor(&self) -> Option<E3> {
        match self {
            ObjectSpec::Sphere { centre, .. } | ObjectSpec::Disk { centre, .. } => Some(*centre),
            ObjectSpec::Plane { point, .. } => Some(*point),
            ObjectSpec::Triangle { corners, .. } => Some(corners[0]),
            ObjectSpec::Evolved { c1, .. } => c1.centre,
        }
    }
}

/// The object, built in `frame`, and its name (for errors).
fn build_object(spec: ObjectSpec, index: usize, method: Method, frame: &Frame) -> (Result<Object, String>, String) {
    let name_of = |n: &Option<String>| n.clone().unwrap_or_else(|| format!("object {}", index + 1));
    let (name, material) = match &spec {
        ObjectSpec::Sphere { name, material, .. }
        | ObjectSpec::Plane { name, material, .. }
        | ObjectSpec::Disk { name, material, .. }
        | ObjectSpec::Triangle { name, material, .. }
        | ObjectSpec::Evolved { name, material, .. } => (name_of(name), *material),
    };
    let shape = || -> Result<Arc<dyn Shape>, String> {
        check_material(&material)?;
        let (at, length) = (|x| frame.point(x), |l| frame.length(l));
        Ok(match spec {
            ObjectSpec::Sphere { centre, radius, .. } => {
                Arc::new(SphereShape::new(at(centre), length(radius)).map_err(geometry)?)
            }
            ObjectSpec::Plane { point, normal, .. } => Arc::new(PlaneShape::new(at(point), normal).map_err(geometry)?),
            ObjectSpec::Disk { centre, normal, radius, .. } => {
                Arc::new(DiskShape::new(at(centre), normal, length(radius)).map_err(geometry)?)
            }
            ObjectSpec::Triangle { corners, .. } => Arc::new(TriangleShape::new(corners.map(at)).map_err(geometry)?),
            #[cfg(feature = "evolved")]
            ObjectSpec::Evolved { c1, c2, .. } => Arc::new(evolved(*c1, *c2, method, frame)?),
            #[cfg(not(feature = "evolved"))]
            ObjectSpec::Evolved { .. } => {
                let _ = method;
                return Err("this build leaves out evolved surfaces (cargo feature `evolved`)".into());
            }
        })
    };
    (shape().map(|shape| Object { name: name.clone(), shape, material }), name)
}

/// An evolved surface, its circles built in a frame centred between them (inside `frame`).
#[cfg(feature = "evolved")]
fn evolved(c1: CircleSpec, c2: CircleSpec, method: Method, frame: &Frame) -> Result<EvolvedSurface, String> {
    let (c1, n1, r1) = circle(c1, frame).map_err(|e| format!("c1: {e}"))?;
    let (c2, n2, r2) = circle(c2, frame).map_err(|e| format!("c2: {e}"))?;
    let origin = [0, 1, 2].map(|k| 0.5 * (c1[k] + c2[k]));
    let local = |c: E3, n, r| {
        cga_core::Circle::from_centre_normal_radius(cga_core::euclid::sub(c, origin), n, r).map_err(geometry)
    };
    let (c1, c2) =
        (local(c1, n1, r1).map_err(|e| format!("c1: {e}"))?, local(c2, n2, r2).map_err(|e| format!("c2: {e}"))?);
    EvolvedSurface::in_frame(origin, c1, c2, method).map_err(|e| e.to_string())
}

/// The orthonormal grade-3 blades, in the order scene files give them.
#[cfg(feature = "evolved")]
const BLADE_ORDER: [&str; 10] = ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"];

/// The centre, normal and radius of a circle spec, the centre and radius in `frame`. A blade
/// is read in world coordinates (where the file gives it) and then moved: its coefficients
/// carry the circle no better than `ε (|c|/r)²` there, which is what the file holds.
#[cfg(feature = "evolved")]
fn circle(spec: CircleSpec, frame: &Frame) -> Result<(E3, E3, f64), String> {
    let (centre, normal, radius) = match spec {
        CircleSpec { blade: Some(b), centre: None, normal: None, radius: None } => {
            let mut dense = cga_core::Multivector::zero();
            for (name, value) in BLADE_ORDER.iter().zip(b) {
                let k = cga_core::Multivector::<f64>::BLADES.iter().position(|x| x == name).ok_or("blade order")?;
                dense.coeffs[k] = value;
            }
            let c = cga_core::Circle::from_dense(&dense).try_normalise().ok_or("the blade is zero or null")?;
            c.centre_normal_radius().map_err(geometry)?
        }
        CircleSpec { blade: None, centre: Some(c), normal: Some(n), radius: Some(r) } => (c, n, r),
        _ => return Err("give either `blade`, or `centre`, `normal` and `radius`".into()),
    };
    Ok((frame.point(centre), normal, frame.length(radius)))
}
