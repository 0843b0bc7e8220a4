//! `type = "csg"`: `operation` (`"union"`, `"intersection"` or `"difference"`) of the closed
//! objects in `objects` (each an object table, itself perhaps a `csg`; its `material`
//! defaults to the tree's, its `motor`/`transform` act before the tree's). The children are
//! read and built by [`super::ObjectSpec`], which holds them; this kind reads the operation.

use super::kind::{At, Geometry, Kind, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::invalid::Invalid;
use crate::shapes::Operation;
use cga_core::euclid::E3;
use serde::Deserialize;
use serde::de::IgnoredAny;

pub(crate) const TAKES: &str =
    "a csg takes `operation` (\"union\", \"intersection\" or \"difference\") and `objects`, two or more closed objects";

/// Said of a part that bounds no solid.
pub(crate) const OPEN: &str = "a CSG part bounds a solid: a sphere, box, capped cylinder or cone, torus, plane (the half-space behind its normal), closed mesh, evolved or spline surface with `caps = true`, or csg";

pub(crate) const KIND: Kind = Kind { name: "csg", fields: Csg::FIELDS, takes: TAKES, read: super::kind::read::<Csg> };

/// The most objects one CSG tree holds, nested ones counted.
pub const MAX_PARTS: usize = 64;

/// The most levels CSG trees nest.
pub const MAX_DEPTH: usize = 16;

spec!(Csg { operation: OperationName => Other, objects: IgnoredAny => Objects });

/// An `operation`'s name.
#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "lowercase", expecting = "\"union\", \"intersection\" or \"difference\"")]
pub(crate) enum OperationName {
    Union,
    Intersection,
    Difference,
}

impl Geometry for Csg {
    /// Its children size the frame (read by [`super::ObjectSpec`]).
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        None
    }

    /// Built by [`super::ObjectSpec`], which holds the children.
    fn build(&self, _: &At) -> Result<Parts, Invalid> {
        Err(Invalid::Form(TAKES))
    }

    /// The operation, or what the kind takes.
    fn operation(&self) -> Option<Result<Operation, Invalid>> {
        let name = self.operation.as_ref().map(|n| *n.get_ref());
        Some(name.ok_or(Invalid::Form(TAKES)).map(|name| match name {
            OperationName::Union => Operation::Union,
            OperationName::Intersection => Operation::Intersection,
            OperationName::Difference => Operation::Difference,
        }))
    }
}
