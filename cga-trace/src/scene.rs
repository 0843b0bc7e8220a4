//! Scenes: a checked scene file ([`crate::format`]) read into the renderer's
//! [`Frame`] — camera, objects, lights and settings — and the errors a
//! file can have, each naming the file, line and column and, for invalid values or
//! geometry, the table or object and a typed reason.

use crate::camera::{Camera, CameraError};
use crate::format::{SceneFile, build_camera, build_object};
use crate::frame::Frame;
use crate::light::Light;
use crate::material::Material;
use crate::settings::Settings;
use crate::shapes::Shape;
#[cfg(feature = "evolved")]
use crate::surface::SurfaceError;
use cga_core::GeometryError;
use cga_core::euclid::E3;
use std::ops::Range;
use std::path::Path;
use std::sync::Arc;
use toml::Spanned;

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
        reason: Invalid,
    },
}

/// Why a well-formed table or object is invalid: the core's named errors, wrapped, or a
/// value out of range.
#[derive(Debug, thiserror::Error)]
pub enum Invalid {
    /// A value out of range or missing (the message names it).
    #[error("{0}")]
    Value(&'static str),
    /// The surface method's settings.
    #[error("surface_method: {0}")]
    SurfaceMethod(&'static str),
    /// Geometry that cannot be built (cga-core's reason).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// A camera that cannot be built.
    #[error(transparent)]
    Camera(#[from] CameraError),
    /// Two circles that make no surface.
    #[cfg(feature = "evolved")]
    #[error(transparent)]
    Surface(#[from] SurfaceError),
    /// One circle of an evolved surface.
    #[error("{which}: {reason}")]
    Circle {
        /// `c1` or `c2`.
        which: &'static str,
        /// Why.
        reason: Box<Invalid>,
    },
    /// An evolved surface in a build without them.
    #[error("this build leaves out evolved surfaces (cargo feature `evolved`)")]
    NoEvolved,
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
        let invalid = |span: Range<usize>, what: String, reason: Invalid| {
            let (line, column) = at(Some(span));
            SceneError::Invalid { file: file.into(), line, column, what, reason }
        };
        let (settings, render_span) = spec.render.map_or((Settings::default(), 0..0), |r| (*r.get_ref(), r.span()));
        settings.check().map_err(|reason| invalid(render_span, "render".into(), reason))?;
        let camera_span = spec.camera.span();
        let anchors: Vec<E3> = (spec.objects.iter().filter_map(|o| o.get_ref().anchor()))
            .chain(spec.lights.iter().map(|l| l.get_ref().position))
            .collect();
        let (camera, frame) = build_camera(spec.camera.into_inner(), anchors)
            .map_err(|reason| invalid(camera_span, "camera".into(), reason))?;
        for (k, light) in spec.lights.iter().enumerate() {
            light.get_ref().check().map_err(|reason| invalid(light.span(), format!("light {}", k + 1), reason))?;
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
