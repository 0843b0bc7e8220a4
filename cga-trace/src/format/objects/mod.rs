//! An `[[objects]]` table: the fields every object takes ([`COMMON`]: `type`, `name`,
//! `label`, `material` and how it moves) and its kind's own, each kind in its own file
//! (`kind::Kind`, listed in `registry.rs`); read, placed by its motor and built.
//!
//! The table is one flat TOML table (not a serde-tagged enum, which would lose the position of
//! every value inside it): its `type` picks the kind, which reads the fields that are its
//! own. A field another kind takes is refused with what this kind takes; a field no kind
//! takes, as unknown.

mod blade;
mod circle;
mod circles;
mod clip;
mod cone;
mod csg;
mod cuboid;
mod cylinder;
mod disk;
pub(crate) mod drawn;
mod evolved;
pub(crate) mod kind;
mod line;
mod mesh;
mod plane;
mod plane_patch;
mod point;
mod point_pair;
pub(crate) mod registry;
mod ruled;
mod sphere;
mod spline;
mod torus;
mod triangle;

pub use kind::{Field, Role};

use super::motion::{ObjectMotion, motion_at};
use super::numbers::Nums;
use super::transform::{Placement, Step, world_motor};
use super::{Assets, MaterialRef};
use crate::drawing::Marks;
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::label::{Label, MAX_LABEL_CHARS};
use crate::material::Material;
use crate::object::Object;
use crate::shapes::{Clipped, Csg, CsgPart, Node, Operation, Shape};
use crate::surface::Method;
use crate::texture::Texture;
use cga_core::euclid::{E3, norm, sub};
use cga_core::{GeometryError, Motor};
use kind::{At, Geometry, Kind};
use serde::de::{Error as _, IgnoredAny, IntoDeserializer, MapAccess, Visitor};
use serde::{Deserialize, Deserializer};
use std::collections::HashMap;
use std::ops::Range;
use std::sync::{Arc, LazyLock};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// The fields every object takes, whatever its kind, with their roles.
pub const COMMON: &[Field] = &[
    Field { name: "type", role: Role::Other },
    Field { name: "name", role: Role::Other },
    Field { name: "label", role: Role::Other },
    Field { name: "material", role: Role::Other },
    Field { name: "motor", role: Role::Motor },
    Field { name: "transform", role: Role::Transform },
    Field { name: "motion", role: Role::Motion },
    Field { name: "template", role: Role::Other },
    Field { name: "clip", role: Role::Clip },
];

/// The fields an object of type `kind` takes ([`COMMON`] and its own), with their roles;
/// `None` for a type the format does not have. An `instance` takes `of`, the object it
/// copies, and the common fields.
pub fn fields(kind: &str) -> Option<Vec<Field>> {
    let own = match kind {
        registry::INSTANCE => &[Field { name: "of", role: Role::Other }][..],
        kind => registry::kind(kind)?.fields,
    };
    Some(COMMON.iter().chain(own).copied().collect())
}

/// The object kinds' `type` names, as files write them.
pub fn kinds() -> Vec<&'static str> {
    registry::NAMES.clone()
}

/// The fields of [`COMMON`], as read.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Common {
    #[serde(rename = "type")]
    kind: KindName,
    pub(crate) name: Option<String>,
    pub(crate) label: Option<Spanned<String>>,
    pub(crate) material: Spanned<MaterialRef>,
    motor: Option<Spanned<Nums<8>>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
    /// Keyframes over the frame times 0 … 1 (motors, poses or steps), applied after
    /// `motor`/`transform`.
    motion: Option<Spanned<ObjectMotion>>,
    /// Drawn only as instances (`instance.rs`).
    pub(crate) template: Option<Spanned<bool>>,
    /// The region it is cut to.
    clip: Option<Spanned<clip::ClipSpec>>,
}

/// An object's `type`, looked up in the registry.
struct KindName(&'static Kind);

impl<'de> Deserialize<'de> for KindName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// A kind's name, looked up.
        struct Name;
        impl Visitor<'_> for Name {
            type Value = KindName;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("the name of an object kind, such as \"sphere\"")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<KindName, E> {
                registry::kind(name).map(KindName).ok_or_else(|| E::unknown_variant(name, &registry::NAMES))
            }
        }
        d.deserialize_str(Name)
    }
}

/// Every field name the format knows for an object, as an unknown one's error lists them.
static ALL_FIELDS: LazyLock<Vec<&'static str>> = LazyLock::new(|| registry::all_fields(COMMON));

/// One `[[objects]]` table, read: the common fields, its kind and the kind's own fields.
pub(crate) struct ObjectSpec {
    pub(crate) common: Common,
    kind: &'static Kind,
    geometry: Box<dyn Geometry>,
    /// The first field given that another kind takes but this one does not.
    stray: Option<(&'static str, Range<usize>)>,
    /// The frame time the object is built at (not in the file: the scene's).
    pub(crate) time: f64,
    /// An instance's motor, applied after the object's own (not in the file).
    pub(crate) outer: Option<Motor>,
    /// A CSG tree's objects, read.
    parts: Vec<ObjectSpec>,
    /// A CSG part that gave no `material`: it takes the tree's.
    inherits: bool,
}

impl ObjectSpec {
    /// An object's table read whole: a field no kind takes is an error here, one another
    /// kind takes when it is built ([`build_object`]), after its material.
    pub(crate) fn read(value: Spanned<DeValue<'_>>) -> Result<ObjectSpec, toml::de::Error> {
        Self::split(value, true, None)
    }

    /// The table's common fields and its kind's own; with `whole`, the others checked. A CSG
    /// part (`part`: its depth and the parts counted so far in its tree) may leave out its
    /// `material`.
    fn split(
        value: Spanned<DeValue<'_>>,
        whole: bool,
        part: Option<(usize, &mut usize)>,
    ) -> Result<ObjectSpec, toml::de::Error> {
        let span = value.span();
        let inherits = part.is_some() && matches!(value.get_ref(), DeValue::Table(t) if !t.contains_key("material"));
        let value = if inherits { with_placeholder_material(value) } else { value };
        let DeValue::Table(table) = value.get_ref() else {
            // Not a table: serde says what it is instead, at it.
            let refused = HashMap::<String, IgnoredAny>::deserialize(value.into_deserializer()).err();
            return Err(refused.unwrap_or_else(|| toml::de::Error::custom("an object is a table")));
        };
        let (mut common, mut own, mut stray) = (DeTable::new(), DeTable::new(), None);
        let kind = match table.get("type").map(Spanned::get_ref) {
            Some(DeValue::String(name)) => registry::kind(name),
            _ => None,
        };
        for (key, v) in table.iter() {
            let name = key.get_ref().as_ref();
            if COMMON.iter().any(|f| f.name == name) {
                common.insert(key.clone(), v.clone());
            } else if kind.is_some_and(|k| k.fields.iter().any(|f| f.name == name)) {
                own.insert(key.clone(), v.clone());
            } else if !whole || kind.is_none() {
                // Checked once the object is read whole, and its `type` known.
            } else if let Some(&known) = ALL_FIELDS.iter().find(|f| **f == name) {
                stray = stray.or(Some((known, v.span())));
            } else {
                return Err(unknown_field(key));
            }
        }
        let common = Common::deserialize(Spanned::new(span.clone(), DeValue::Table(common)).into_deserializer())?;
        let kind = common.kind.0;
        let parts = match (kind.name, own.get("objects")) {
            ("csg", Some(objects)) => Self::parts(objects, whole, part)?,
            _ => Vec::new(),
        };
        let geometry = (kind.read)(Spanned::new(span, DeValue::Table(own)))?;
        Ok(ObjectSpec { common, kind, geometry, stray, time: 0.0, outer: None, parts, inherits })
    }

    /// A CSG tree's `objects`, each read as an object table, within [`csg::MAX_PARTS`] and
    /// [`csg::MAX_DEPTH`].
    fn parts(
        objects: &Spanned<DeValue<'_>>,
        whole: bool,
        part: Option<(usize, &mut usize)>,
    ) -> Result<Vec<ObjectSpec>, toml::de::Error> {
        let limit = |what: &str, found: usize, limit: usize| {
            refused(objects.span(), format!("{found} {what} exceed the limit of {limit}"))
        };
        let mut own_count = 0;
        let (depth, count) = match part {
            Some((depth, count)) => (depth + 1, count),
            None => (1, &mut own_count),
        };
        if depth > csg::MAX_DEPTH {
            return Err(limit("levels of CSG", depth, csg::MAX_DEPTH));
        }
        let DeValue::Array(items) = objects.get_ref() else {
            return Err(refused(objects.span(), "`objects` is a list of object tables".into()));
        };
        *count += items.len();
        if *count > csg::MAX_PARTS {
            return Err(limit("objects in one CSG tree", *count, csg::MAX_PARTS));
        }
        items.iter().map(|item| Self::split(item.clone(), whole, Some((depth, &mut *count)))).collect()
    }

    /// Where the object is and how large, in world coordinates, for sizing the scene's frame,
    /// read from the fields that place it alone (the others are checked when it is built),
    /// and the triangles its mesh file adds.
    pub(crate) fn extent_of(
        value: &Spanned<DeValue<'_>>,
        time: f64,
        outer: Option<Motor>,
        assets: &Assets,
    ) -> Result<(Option<(E3, f64)>, usize), toml::de::Error> {
        if !matches!(value.get_ref(), DeValue::Table(_)) {
            return Ok((None, 0));
        }
        let mut spec = Self::split(value.clone(), false, None)?;
        (spec.time, spec.outer) = (time, outer);
        Ok((spec.extent(assets), spec.geometry.triangles(assets).unwrap_or(0)))
    }

    /// A point of the object (moved by its motor) and its extent, if the file says.
    fn extent(&self, assets: &Assets) -> Option<(E3, f64)> {
        self.extent_at(assets, self.time, self.outer)
    }

    /// [`ObjectSpec::extent`] at frame time `time` after the motor `outer`; a CSG tree's
    /// holds its parts'.
    fn extent_at(&self, assets: &Assets, time: f64, outer: Option<Motor>) -> Option<(E3, f64)> {
        let motor = self.placed_motor(time, outer).ok().flatten();
        if self.geometry.operation().is_some() {
            let extents: Vec<(E3, f64)> = self.parts.iter().filter_map(|p| p.extent_at(assets, time, motor)).collect();
            let (first, _) = *extents.first()?;
            return Some((first, extents.iter().map(|(p, r)| norm(sub(*p, first)) + r).fold(0.0, f64::max)));
        }
        let (point, extent) = self.geometry.extent(assets)?;
        Some((motor.map_or(point, |m| m.move_point(point)), extent))
    }

    /// The object's world motor at its frame time: its `motor` or `transform`, then its
    /// `motion` at that time, then an instance's motor.
    fn world_motor(&self) -> Result<Option<Motor>, Invalid> {
        self.placed_motor(self.time, self.outer)
    }

    /// [`ObjectSpec::world_motor`] at frame time `time`, after the motor `outer` (an
    /// instance's, or the CSG tree's a part is in).
    fn placed_motor(&self, time: f64, outer: Option<Motor>) -> Result<Option<Motor>, Invalid> {
        let c = &self.common;
        let own = world_motor(c.motor.as_ref(), c.transform.as_ref())?;
        let moved = match &c.motion {
            Some(keys) => Some(motion_at(keys, time, None)? * own.unwrap_or(Motor::identity())),
            None => own,
        };
        Ok(match (outer, moved) {
            (Some(outer), Some(m)) => Some(outer * m),
            (outer, m) => outer.or(m),
        })
    }

    /// Whether it draws a CGA object (its marks are sized by the scene).
    pub(crate) fn draws(&self) -> bool {
        self.geometry.draws()
    }

    /// The object's name, or `object N` (1-based `index`) where it has none.
    pub(crate) fn name_or(&self, index: usize) -> String {
        self.common.name.clone().unwrap_or_else(|| format!("object {}", index + 1))
    }

    /// The shapes under the world motor `motor` (`at`'s placement unused): a field its kind
    /// does not take refused with what it takes, then built, a geometry error placed at the
    /// field it is about ([`ObjectSpec::locate`]).
    fn shapes_at(&self, motor: Option<Motor>, at: &At) -> Result<Parts, Invalid> {
        if let Some((field, span)) = &self.stray {
            return Err(Invalid::at(field, span.clone(), Invalid::Form(self.kind.takes)));
        }
        let at = At { place: Placement::new(motor, at.frame), ..*at };
        self.geometry.build(&at).map_err(|e| self.locate(e))
    }

    /// A CSG tree's leaves (shape and look, appended to `leaves` in order) and its nodes,
    /// built under the world motor `motor` at frame time `time`; a part's error placed at its
    /// tree's `objects` as `object N`.
    fn tree(
        &self,
        (motor, time): (Option<Motor>, f64),
        look: &Look,
        at: &At,
        leaves: &mut Looked,
    ) -> Result<Node, Invalid> {
        let operation = self.geometry.operation().ok_or(Invalid::Form(self.kind.takes))??;
        let at_objects = |e: Invalid| match self.geometry.span("objects") {
            Some(span) => Invalid::at("objects", span, e),
            None => e,
        };
        if self.parts.len() < 2 {
            return Err(at_objects(Invalid::Form(csg::TAKES)));
        }
        let mut children = Vec::with_capacity(self.parts.len());
        for (k, part) in self.parts.iter().enumerate() {
            let indexed = |e| at_objects(Invalid::Indexed { what: "object", index: k + 1, reason: Box::new(e) });
            let child = (|| {
                if part.common.label.is_some() || part.common.clip.is_some() {
                    return Err(Invalid::Form("a CSG part takes no `label` or `clip`: give them to the whole tree"));
                }
                let own = if part.inherits { look.clone() } else { at.assets.resolve(&part.common.material)? };
                let placed = part.placed_motor(time, motor)?;
                if part.geometry.operation().is_some() {
                    return part.tree((placed, time), &own, at, leaves);
                }
                let (shapes, _) = part.shapes_at(placed, at)?;
                let shape = one_solid(shapes, part.geometry.closed(at.assets)?).ok_or(Invalid::Form(csg::OPEN))?;
                leaves.push((shape, own));
                Ok(Node::Leaf(leaves.len() - 1))
            })();
            children.push(child.map_err(indexed)?);
        }
        Ok(Node::Op(operation, children))
    }

    /// The object's parts, each with its look (`look`, but for a CSG part's own), cut by its
    /// `clip`, and where a drawing's label goes.
    fn looks(&self, look: &Look, at: &At) -> Result<Looks, Invalid> {
        let motor = self.world_motor()?;
        let (parts, anchor, tree) = if self.geometry.operation().is_some() {
            let mut leaves = Vec::new();
            let root = self.tree((motor, self.time), look, at, &mut leaves)?;
            (leaves, None, Some(root))
        } else {
            let (shapes, anchor) = self.shapes_at(motor, at)?;
            (shapes.into_iter().map(|s| (s, look.clone())).collect(), anchor, None)
        };
        let objects = self.geometry.span("objects");
        let Some(clip) = &self.common.clip else {
            let parts = match tree {
                Some(root) => solid(parts, root, (objects, "objects"))?,
                None => parts,
            };
            return Ok((parts, anchor));
        };
        let region =
            clip.get_ref().region(&Placement::new(motor, at.frame)).map_err(|e| Invalid::at("clip", clip.span(), e))?;
        let at_clip = (Some(clip.span()), "clip");
        if !clip.get_ref().capped() {
            // Open: the tree (if any) first, then each part cut.
            let parts = match tree {
                Some(root) => solid(parts, root, (objects, "objects"))?,
                None => parts,
            };
            let cut = |(shape, look): (Arc<dyn Shape>, Look)| {
                Clipped::new(shape, region.clone()).map(|c| (Arc::new(c) as Arc<dyn Shape>, look))
            };
            return Ok((parts.into_iter().map(cut).collect::<Result<_, _>>().map_err(csg_error(at_clip))?, anchor));
        }
        // Capped: the solid intersected with the region, whose surface takes the object's look.
        let (root, mut parts) = match tree {
            Some(root) => (root, parts),
            None => {
                let shapes = parts.into_iter().map(|(s, _)| s).collect();
                let closed = self.geometry.closed(at.assets)?;
                let Some(solid) = one_solid(shapes, closed) else {
                    return Err(Invalid::at("clip", clip.span(), Invalid::Form(clip::CAPPED_OPEN)));
                };
                (Node::Leaf(0), vec![(solid, look.clone())])
            }
        };
        let first = parts.len();
        parts.extend(region.into_iter().map(|r| (r, look.clone())));
        let root = Node::Op(
            Operation::Intersection,
            std::iter::once(root).chain((first..parts.len()).map(Node::Leaf)).collect(),
        );
        Ok((solid(parts, root, at_clip)?, anchor))
    }

    /// A geometry error about one field, placed at that field when the object gives it: a
    /// zero radius at `radius`, a zero vector at `normal`, points that coincide or line up at
    /// `points` or the kind's own field ([`Geometry::coincident`]).
    fn locate(&self, e: Invalid) -> Invalid {
        use GeometryError as G;
        let given = |field| self.geometry.span(field);
        let field = match &e {
            Invalid::Geometry(G::ZeroRadius) => "radius",
            Invalid::Geometry(G::ZeroVector) => "normal",
            Invalid::Geometry(G::CoincidentPoints | G::CollinearPoints | G::CoplanarPoints)
                if given("points").is_some() =>
            {
                "points"
            }
            Invalid::Geometry(G::CoincidentPoints) => self.geometry.coincident(),
            Invalid::Geometry(G::CollinearPoints) => "corners",
            _ => return e,
        };
        match given(field) {
            Some(span) => Invalid::at(field, span, e),
            None => e,
        }
    }

    /// The object's label ([`label`]), its errors at its `label` field.
    fn label(
        &self,
        shapes: &[Arc<dyn Shape>],
        anchor: Option<(E3, f64)>,
        colour: [f64; 3],
    ) -> Result<Option<Label>, Invalid> {
        let Some(text) = &self.common.label else { return Ok(None) };
        label(text.get_ref(), shapes, anchor, colour).map(Some).map_err(|e| Invalid::at("label", text.span(), e))
    }
}

/// An object's label `text`, beside `anchor` if given, else the sphere holding its `shapes`;
/// refused for an unbounded object (a plane: label a `plane-patch`) or past
/// [`MAX_LABEL_CHARS`].
pub(crate) fn label(
    text: &str,
    shapes: &[Arc<dyn Shape>],
    anchor: Option<(E3, f64)>,
    colour: [f64; 3],
) -> Result<Label, Invalid> {
    let chars = text.chars().count();
    if chars > MAX_LABEL_CHARS {
        return Err(Invalid::Limit { what: "characters", found: chars as u64, limit: MAX_LABEL_CHARS as u64 });
    }
    let text = text.to_string();
    if let Some((at, reach)) = anchor {
        return Ok(Label { text, at, reach, colour });
    }
    let bounds: Option<Vec<(E3, f64)>> = shapes.iter().map(|s| s.bounds()).collect();
    let Some(bounds) = bounds else {
        return Err(Invalid::Value("an unbounded object has nowhere to put a label: label a `plane-patch`"));
    };
    let n = bounds.len() as f64;
    let centre = [0, 1, 2].map(|k| bounds.iter().map(|b| b.0[k]).sum::<f64>() / n);
    let reach = bounds.iter().map(|(c, r)| norm(sub(*c, centre)) + r).fold(0.0, f64::max);
    Ok(Label { text, at: centre, reach, colour })
}

use super::marks::Parts;

/// An object's parts and its label.
pub(crate) type Built = (Vec<Object>, Option<Label>);

/// A part's material and texture.
type Look = (Material, Option<Arc<Texture>>);

/// Shapes, each with its look.
type Looked = Vec<(Arc<dyn Shape>, Look)>;

/// An object's parts with their looks, and where a drawing's label goes.
type Looks = (Looked, Option<(E3, f64)>);

/// The CSG tree `root` over `leaves` as parts, each in its leaf's look; an error placed at
/// `field` (its span where given).
fn solid(
    leaves: Vec<(Arc<dyn Shape>, Look)>,
    root: Node,
    field: (Option<Range<usize>>, &'static str),
) -> Result<Looked, Invalid> {
    let (shapes, looks): (Vec<_>, Vec<_>) = leaves.into_iter().unzip();
    let csg = Csg::new(shapes, root).map_err(csg_error(field))?;
    Ok(CsgPart::parts(csg).into_iter().map(|p| Arc::new(p) as Arc<dyn Shape>).zip(looks).collect())
}

/// One closed shape from an object's shapes: its one shape if that bounds a solid (a sphere,
/// a closed mesh, …); if the object says its shapes close one (`closed`), a capped swept
/// surface's surface and disks as one [`Body`](crate::shapes::Body). `None` if they bound none.
fn one_solid(shapes: Vec<Arc<dyn Shape>>, closed: bool) -> Option<Arc<dyn Shape>> {
    if let [shape] = &shapes[..] {
        return shape.closed().then(|| shape.clone());
    }
    if !closed {
        return None;
    }
    Some(Arc::new(crate::shapes::Body::new(shapes)?))
}

/// A CSG error as a value error at `field` (its span where given).
fn csg_error((span, field): (Option<Range<usize>>, &'static str)) -> impl Fn(crate::shapes::CsgError) -> Invalid {
    move |e| {
        let e = Invalid::Range(e.to_string());
        match span.clone() {
            Some(span) => Invalid::at(field, span, e),
            None => e,
        }
    }
}

/// A placeholder `material` for a CSG part that gives none (it takes its tree's, and the
/// placeholder is never resolved).
fn with_placeholder_material(value: Spanned<DeValue<'_>>) -> Spanned<DeValue<'_>> {
    let span = value.span();
    let DeValue::Table(mut table) = value.into_inner() else { unreachable!("checked to be a table") };
    let key = Spanned::new(span.clone(), std::borrow::Cow::Borrowed("material"));
    table.insert(key, Spanned::new(span.clone(), DeValue::String(std::borrow::Cow::Borrowed(""))));
    Spanned::new(span, DeValue::Table(table))
}

/// The object, built in `frame` (a drawing's parts as objects of one name), its label if it
/// has one, and its name (for errors, control characters escaped).
pub(crate) fn build_object(
    spec: ObjectSpec,
    index: usize,
    method: Method,
    frame: &Frame,
    marks: &Marks,
    assets: &Assets,
) -> (Result<Built, Invalid>, String) {
    let name = spec.name_or(index);
    let shown = name.escape_debug().to_string();
    let built = assets.resolve(&spec.common.material).and_then(|look| {
        let at = At::new(method, frame, marks, assets);
        let (parts, anchor) = spec.looks(&look, &at)?;
        let shapes: Vec<Arc<dyn Shape>> = parts.iter().map(|(s, _)| s.clone()).collect();
        let label = spec.label(&shapes, anchor, look.0.colour)?;
        // A closed glass mesh, or a CSG body, is one solid: light enters at one part and
        // leaves at another.
        let closed = spec.geometry.operation().is_some() || spec.geometry.closed(assets)?;
        let name: Arc<str> = name.as_str().into();
        let object = |(shape, (material, texture)): (Arc<dyn Shape>, Look)| {
            let solid = (material.dielectric() && closed).then_some(index);
            Object { name: name.clone(), shape, material, texture, solid, moving: false }
        };
        Ok((parts.into_iter().map(object).collect(), label))
    });
    (built, shown)
}

/// An error saying `why`, at `span`.
fn refused(span: Range<usize>, why: String) -> toml::de::Error {
    /// Refuses whatever it reads, saying why: the error then carries the value's span.
    struct Refuse(String);
    impl<'de> serde::de::DeserializeSeed<'de> for Refuse {
        type Value = ();
        fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            /// The visitor that refuses.
            struct Never(String);
            impl Visitor<'_> for Never {
                type Value = ();
                fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                    f.write_str(&self.0)
                }
                fn visit_bool<E: serde::de::Error>(self, _: bool) -> Result<(), E> {
                    Err(E::custom(self.0))
                }
            }
            d.deserialize_bool(Never(self.0))
        }
    }
    let value = Spanned::new(span, DeValue::Boolean(true));
    let seed = serde::de::DeserializeSeed::deserialize(Refuse(why.clone()), value.into_deserializer());
    seed.err().unwrap_or_else(|| toml::de::Error::custom(why))
}

/// The error for a field no object kind takes, at its key, listing those the format knows.
fn unknown_field(key: &Spanned<std::borrow::Cow<'_, str>>) -> toml::de::Error {
    /// Reads a one-field table only to refuse its field: the error then carries the table's
    /// span, the key's.
    struct Unknown;
    impl<'de> Deserialize<'de> for Unknown {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            d.deserialize_map(Unknown)
        }
    }
    impl<'de> Visitor<'de> for Unknown {
        type Value = Unknown;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an object's table")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unknown, A::Error> {
            let key: String = map.next_key()?.unwrap_or_default();
            Err(A::Error::unknown_field(&key, &ALL_FIELDS))
        }
    }
    let mut table = DeTable::new();
    table.insert(key.clone(), Spanned::new(key.span(), DeValue::Boolean(true)));
    let refused = Unknown::deserialize(Spanned::new(key.span(), DeValue::Table(table)).into_deserializer());
    refused.err().unwrap_or_else(|| toml::de::Error::unknown_field(key.get_ref(), &ALL_FIELDS))
}

#[cfg(test)]
mod tests {
    use super::registry::{INSTANCE, KINDS};

    /// The scene-format guide (`docs/SCENES.md`) names every object kind and every field each
    /// kind takes: a kind or field added without its documentation fails here.
    #[test]
    fn the_guide_documents_every_kind_and_its_fields() {
        let guide = include_str!("../../../../docs/SCENES.md");
        let mut missing = Vec::new();
        for name in KINDS.iter().map(|k| k.name).chain([INSTANCE]) {
            if !guide.contains(&format!("\"{name}\"")) && !guide.contains(&format!("`{name}`")) {
                missing.push(name.to_string());
            }
            for field in super::fields(name).expect("a kind").iter().skip(super::COMMON.len()) {
                let field = field.name;
                if !guide.contains(&format!("{field} =")) && !guide.contains(&format!("`{field}`")) {
                    missing.push(format!("{name}.{field}"));
                }
            }
        }
        assert!(missing.is_empty(), "kinds and fields docs/SCENES.md does not name: {missing:?}");
    }

    /// Every common field is one [`super::Common`] reads, and no kind declares one again.
    #[test]
    fn the_common_fields_are_read_and_no_kind_repeats_them() {
        let text = "type = \"sphere\"\nname = \"n\"\nlabel = \"l\"\nmaterial = \"m\"\nmotor = [1, 0, 0, 0, 0, 0, 0, 0]\ntransform = []\nmotion = []\ntemplate = false\nclip = { sphere = { centre = [0, 0, 0], radius = 1 } }\n";
        let table: toml::de::DeTable = toml::de::DeTable::parse(text).expect("TOML").into_inner();
        assert_eq!(table.len(), super::COMMON.len());
        for field in super::COMMON {
            assert!(table.keys().any(|k| k.get_ref() == field.name), "{}", field.name);
        }
        let value = toml::Spanned::new(0..text.len(), toml::de::DeValue::Table(table));
        let common =
            <super::Common as serde::Deserialize>::deserialize(serde::de::IntoDeserializer::into_deserializer(value));
        assert!(common.is_ok(), "{:?}", common.err());
        for kind in KINDS {
            for field in kind.fields {
                assert!(super::COMMON.iter().all(|c| c.name != field.name), "{}.{}", kind.name, field.name);
            }
        }
    }
}
