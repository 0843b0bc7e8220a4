//! What an object kind is: its fields (each declared once, with its role when the scene is
//! moved), how it is read, the point and extent that size the scene's frame, and how it
//! builds its shapes. Each kind's file fills this in; the registry (`registry.rs`) lists
//! them.

use crate::drawing::Marks;
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::V3;
use crate::format::transform::Placement;
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::surface::Method;
use cga_core::euclid::{E3, norm, sub};
use serde::Deserialize;
use serde::de::{DeserializeOwned, IntoDeserializer};
use std::ops::Range;
use toml::Spanned;
use toml::de::DeValue;

/// How a field's value moves when the whole scene is moved by a similarity `x ↦ s x + t`
/// (the role a test that moves scenes reads; the renderer reads each field by its type).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A point `[x, y, z]`: `s x + t`.
    Point,
    /// A list of points, each moved.
    Points,
    /// A length: scaled by `s`.
    Length,
    /// A direction: unchanged.
    Direction,
    /// A circle table (`centre`, `normal`, `radius`, or `points`, or ten orthonormal
    /// coefficients as `blade`).
    Circle,
    /// A list of circle tables.
    Circles,
    /// A line table `{ point, direction }`.
    Line,
    /// A sphere table `{ centre, radius }`.
    Bound,
    /// A blade's coefficients by name: moved as its points are, `V X Ṽ`.
    Blade,
    /// A mesh's scale about its file's origin: scaled by `s`, the shift added to its steps.
    Scale,
    /// A motor (eight coefficients): conjugated, `S M S⁻¹`.
    Motor,
    /// Keyframes (motors as coefficients here; poses and steps are the scene format's too),
    /// each conjugated.
    Motion,
    /// Object tables (a CSG tree's), each moved as an object.
    Objects,
    /// A clip's region (`plane`, `sphere`, `box` tables): its points and lengths moved.
    Clip,
    /// A list of transform steps (rotations about points, translations, motors).
    Transform,
    /// Unchanged by moving the scene: a flag, a count, a name, a file, a material.
    Other,
}

/// A field of an object's table: its name as files write it and its [`Role`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Field {
    pub name: &'static str,
    pub role: Role,
}

/// Where an object is built: its placement (its motor, then the scene's frame), the surface
/// method, the frame, the drawings' marks, and the scene's images and meshes.
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct At<'a> {
    pub place: Placement,
    pub method: Method,
    pub frame: &'a Frame,
    pub marks: &'a Marks,
    pub assets: &'a Assets,
}

impl<'a> At<'a> {
    /// Where objects are built in `frame`, placed by no motor.
    pub fn new(method: Method, frame: &'a Frame, marks: &'a Marks, assets: &'a Assets) -> Self {
        At { place: Placement::new(None, frame), method, frame, marks, assets }
    }
}

/// The fields an object kind's table gave, with their spans (written by [`spec!`]).
pub(crate) trait Fields {
    /// Where `field` is written, if given.
    fn span(&self, field: &str) -> Option<Range<usize>>;
}

/// An object kind's fields as read: where it is, what it builds.
pub(crate) trait Geometry: Fields + Send + Sync {
    /// A point of it and its extent (a radius; infinite for a plane), in world coordinates
    /// before its motor, for sizing the scene's frame; `None` where the fields do not say
    /// (building the object then says what is wrong).
    fn extent(&self, assets: &Assets) -> Option<(E3, f64)>;

    /// Its shapes in the frame (one but for drawings, meshes and capped surfaces) and where a
    /// drawing's label goes.
    fn build(&self, at: &At) -> Result<Parts, Invalid>;

    /// The field that coinciding points are about: a triangle's `corners`, a cylinder's `p2`.
    fn coincident(&self) -> &'static str {
        "corners"
    }

    /// The triangles a mesh adds, known from its file before anything is placed.
    fn triangles(&self, _assets: &Assets) -> Option<usize> {
        None
    }

    /// Whether its shapes close a solid (a closed mesh).
    fn closed(&self, _assets: &Assets) -> Result<bool, Invalid> {
        Ok(false)
    }

    /// Whether it draws a CGA object (its marks are sized by the scene).
    fn draws(&self) -> bool {
        false
    }

    /// A CSG tree's operation (or why it has none), where it is one.
    fn operation(&self) -> Option<Result<crate::shapes::Operation, Invalid>> {
        None
    }
}

/// An object kind: its `type` name, its fields, what it takes (said when a field is missing
/// or not its own), and how its fields are read.
pub(crate) struct Kind {
    pub name: &'static str,
    pub fields: &'static [Field],
    pub takes: &'static str,
    pub read: Read,
}

/// How a kind's fields are read from the part of an object's table that is its own.
pub(crate) type Read = fn(Spanned<DeValue<'_>>) -> Result<Box<dyn Geometry>, toml::de::Error>;

/// [`Kind::read`] for a kind whose spec is `T`.
pub(crate) fn read<T: Geometry + DeserializeOwned + 'static>(
    table: Spanned<DeValue<'_>>,
) -> Result<Box<dyn Geometry>, toml::de::Error> {
    Ok(Box::new(T::deserialize(table.into_deserializer())?))
}

/// Declares a kind's spec: a struct of optional, spanned fields (unknown ones refused), its
/// [`Field`] list with each field's [`Role`], and [`Fields`] for it.
macro_rules! spec {
    ($(#[$meta:meta])* $name:ident { $($(#[$fmeta:meta])* $field:ident: $ty:ty => $role:ident),* $(,)? }) => {
        $(#[$meta])*
        #[derive(serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        pub(crate) struct $name {
            $($(#[$fmeta])* $field: Option<toml::Spanned<$ty>>,)*
        }

        impl $name {
            /// Its fields, each with its role.
            pub(crate) const FIELDS: &'static [$crate::format::objects::kind::Field] = &[$(
                $crate::format::objects::kind::Field {
                    name: stringify!($field),
                    role: $crate::format::objects::kind::Role::$role,
                }
            ),*];
        }

        impl $crate::format::objects::kind::Fields for $name {
            fn span(&self, field: &str) -> Option<std::ops::Range<usize>> {
                match field {
                    $(stringify!($field) => self.$field.as_ref().map(toml::Spanned::span),)*
                    _ => None,
                }
            }
        }
    };
}
pub(crate) use spec;

/// A point field's coordinates, where given.
pub(crate) fn point(x: &Option<Spanned<V3>>) -> Option<E3> {
    x.as_ref().map(|x| x.get_ref().0)
}

/// A number field's value, where given.
pub(crate) fn number(x: &Option<Spanned<crate::format::numbers::Num>>) -> Option<f64> {
    x.as_ref().map(|x| x.get_ref().0)
}

/// A flag's value, `default` where not given.
pub(crate) fn flag(x: &Option<Spanned<bool>>, default: bool) -> bool {
    x.as_ref().map_or(default, |x| *x.get_ref())
}

/// `N` points from a `points` or `corners` field, or a count error at it.
pub(crate) fn points<const N: usize>(field: &'static str, p: &Spanned<Vec<V3>>) -> Result<[E3; N], Invalid> {
    let given = p.get_ref();
    if given.len() != N {
        let reason = Invalid::Count { what: "points", expected: N, found: given.len() };
        return Err(Invalid::at(field, p.span(), reason));
    }
    Ok(std::array::from_fn(|k| given[k].0))
}

/// How far the points reach from the first: the extent of what they define.
pub(crate) fn spread(p: &[V3]) -> f64 {
    p.iter().map(|x| norm(sub(x.0, p[0].0))).fold(0.0, f64::max)
}

/// `p1`, `p2`: one point (a cylinder's or cone's end) or two (a ruled surface's point pair).
#[derive(Deserialize)]
#[serde(untagged, expecting = "a point [x, y, z], or for a ruled surface two points [[x, y, z], [x, y, z]]")]
pub(crate) enum Ends {
    One(V3),
    Two(Vec<V3>),
}

impl Ends {
    /// The points given.
    pub(crate) fn points(&self) -> &[V3] {
        match self {
            Ends::One(p) => std::slice::from_ref(p),
            Ends::Two(p) => p,
        }
    }
}

/// `N` points from an `Ends` field, or a count error at it.
pub(crate) fn ends<const N: usize>(field: &'static str, p: &Spanned<Ends>) -> Result<[E3; N], Invalid> {
    let given = p.get_ref().points();
    if given.len() != N || matches!((N, p.get_ref()), (1, Ends::Two(_))) {
        let reason = Invalid::Count { what: "points", expected: N, found: given.len() };
        return Err(Invalid::at(field, p.span(), reason));
    }
    Ok(std::array::from_fn(|k| given[k].0))
}

/// One shape, labelled beside the sphere holding it.
pub(crate) fn one(shape: impl crate::shapes::Shape + 'static) -> Parts {
    (vec![std::sync::Arc::new(shape)], None)
}
