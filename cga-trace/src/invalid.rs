//! Why a well-formed table or object of a scene is invalid: a value out of range, a form
//! that makes no object, or the named error of the geometry that could not be built. The
//! domain types' checks ([`crate::material::Material::check`],
//! [`crate::settings::Settings::check`]) and the scene format share it; the format adds the
//! field and its place in the file.

use crate::camera::CameraError;
#[cfg(feature = "evolved")]
use crate::surface::SurfaceError;
use cga_core::GeometryError;
use std::ops::Range;

/// Why a well-formed table or object is invalid: the core's named errors, wrapped, or a
/// value out of range.
#[derive(Debug, thiserror::Error)]
pub enum Invalid {
    /// A value out of range or missing (the message names it).
    #[error("{0}")]
    Value(&'static str),
    /// The fields given do not make the object (the message says which it takes).
    #[error("{0}")]
    Form(&'static str),
    /// A list of the wrong length.
    #[error("expected {expected} {what}, found {found}")]
    Count {
        /// What is counted.
        what: &'static str,
        /// How many it takes.
        expected: usize,
        /// How many were given.
        found: usize,
    },
    /// More of something than its limit allows ([`crate::limits`], or the module's own).
    #[error("{found} {what} exceed the limit of {limit}")]
    Limit {
        /// What is counted.
        what: &'static str,
        /// How many were given.
        found: u64,
        /// The limit.
        limit: u64,
    },
    /// One element of a list (`circle 3`).
    #[error("{what} {index}: {reason}")]
    Indexed {
        /// What the list holds.
        what: &'static str,
        /// 1-based position.
        index: usize,
        /// Why.
        reason: Box<Invalid>,
    },
    /// The problem is with one field, at `span` in the file.
    #[error("`{field}`: {reason}")]
    Field {
        /// The field's name.
        field: &'static str,
        /// Its bytes in the file.
        span: Range<usize>,
        /// Why.
        reason: Box<Invalid>,
    },
    /// The problem is with one field of a table whose fields carry no place of their own
    /// (a material's): named, at the table's place.
    #[error("`{field}`: {reason}")]
    Of {
        /// The field's name.
        field: &'static str,
        /// Why.
        reason: Box<Invalid>,
    },
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
    /// Numbers the frame cannot hold beside the rest of the scene (the message says which
    /// and how far).
    #[error("{0}")]
    Range(String),
    /// A blade name the algebra does not have.
    #[error(
        "`{0}` is not a blade of the algebra: name blades in the null basis (e1, e2, e3, eo, ei: e12, e1o, e23i, eoi, e123oi, …) or the orthonormal one (e1 … e5: e14, e1235, …)"
    )]
    Name(String),
    /// Blade names from both bases in one blade.
    #[error(
        "`{0}` is in the null basis (eo, ei) and `{1}` in the orthonormal one (e4, e5): name every blade in one of them"
    )]
    Mixed(String, String),
    /// A blade of another kind than the object's.
    #[error("the blade is {1}, not a {0}: give it as `type = \"blade\"` to draw it as what it is")]
    NotA(&'static str, &'static str),
    /// A blade that has no picture.
    #[error(transparent)]
    Draw(crate::drawing::DrawError),
    /// An image (a texture or an environment) that cannot be read.
    #[error("{0}")]
    Image(String),
    /// A mesh file that cannot be read.
    #[error("{0}")]
    Mesh(String),
    /// An evolved surface in a build without them.
    #[error("this build leaves out evolved surfaces (cargo feature `evolved`)")]
    NoEvolved,
}

impl Invalid {
    /// `reason`, about the field `field` at `span`.
    pub fn at(field: &'static str, span: Range<usize>, reason: Invalid) -> Invalid {
        Invalid::Field { field, span, reason: Box::new(reason) }
    }

    /// `reason`, about the field `field` of a table whose fields have no span.
    pub fn of(field: &'static str, reason: Invalid) -> Invalid {
        Invalid::Of { field, reason: Box::new(reason) }
    }

    /// The field this is about, if it is about one.
    pub(crate) fn field(&self) -> Option<&'static str> {
        match self {
            Invalid::Field { field, .. } => Some(field),
            _ => None,
        }
    }

    /// The span of the innermost field this is about, if any.
    pub(crate) fn span(&self) -> Option<Range<usize>> {
        match self {
            Invalid::Field { span, reason, .. } => reason.span().or_else(|| Some(span.clone())),
            Invalid::Indexed { reason, .. } => reason.span(),
            _ => None,
        }
    }
}
