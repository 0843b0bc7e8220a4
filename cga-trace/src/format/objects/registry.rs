//! Every object kind, in the order the format's errors list them: a new kind is its shape,
//! its spec file and one line here.

use super::kind::{Field, Kind};
use std::sync::LazyLock;

/// The object kinds.
pub(crate) const KINDS: &[&Kind] = &[
    &super::sphere::KIND,
    &super::plane::KIND,
    &super::disk::KIND,
    &super::torus::KIND,
    &super::cylinder::KIND,
    &super::cone::KIND,
    &super::cuboid::KIND,
    &super::triangle::KIND,
    &super::mesh::KIND,
    &super::evolved::KIND,
    &super::spline::KIND,
    &super::ruled::KIND,
    &super::point::KIND,
    &super::point_pair::KIND,
    &super::line::KIND,
    &super::circle::KIND,
    &super::plane_patch::KIND,
    &super::blade::KIND,
    &super::csg::KIND,
];

/// An instance's `type`: it copies an earlier object (`format/instance.rs`), so it has no
/// kind of its own.
pub(crate) const INSTANCE: &str = "instance";

/// The kind named `name`.
pub(crate) fn kind(name: &str) -> Option<&'static Kind> {
    KINDS.iter().copied().find(|k| k.name == name)
}

/// Every `type` a file may give, as an unknown one's error lists them.
pub(crate) static NAMES: LazyLock<Vec<&'static str>> =
    LazyLock::new(|| KINDS.iter().map(|k| k.name).chain([INSTANCE]).collect());

/// Every field any kind takes, after the fields every object takes (`common`), once each,
/// as an unknown field's error lists them.
pub(crate) fn all_fields(common: &[Field]) -> Vec<&'static str> {
    let mut all: Vec<&'static str> = common.iter().map(|f| f.name).collect();
    for field in KINDS.iter().flat_map(|k| k.fields) {
        if !all.contains(&field.name) {
            all.push(field.name);
        }
    }
    all
}
