//! Instances: `type = "instance"` and `of = "NAME"` place a copy of an earlier named object
//! under a further motor (`motor`, `transform` and `motion`, as any object's), applied after
//! the object's own; `name` and `material` replace the object's where given (an instance of
//! an instance wears the nearest material given along the chain); a copy carries a label
//! only where the instance gives its own, as a label names one thing. An object with
//! `template = true` is only instanced, never drawn itself.

use super::MaterialRef;
use super::motion::{ObjectMotion, motion_at};
use super::numbers::Nums;
use super::objects::ObjectSpec;
use super::transform::{Step, world_motor};
use crate::invalid::Invalid;
use cga_core::Motor;
use serde::Deserialize;
use toml::Spanned;
use toml::de::DeValue;

/// An `[[objects]]` table of `type = "instance"`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct InstanceSpec {
    #[serde(rename = "type")]
    _kind: String,
    /// The name of the object copied.
    pub(crate) of: Spanned<String>,
    name: Option<String>,
    label: Option<Spanned<String>>,
    pub(crate) material: Option<Spanned<MaterialRef>>,
    motor: Option<Spanned<Nums<8>>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
    motion: Option<Spanned<ObjectMotion>>,
}

impl InstanceSpec {
    /// Its own motor at frame time `time`: `motor` or `transform`, then `motion`.
    pub(crate) fn motor(&self, time: f64) -> Result<Option<Motor>, Invalid> {
        let own = world_motor(self.motor.as_ref(), self.transform.as_ref())?;
        Ok(match &self.motion {
            Some(keys) => Some(motion_at(keys, time, None)? * own.unwrap_or(Motor::identity())),
            None => own,
        })
    }

    /// `original` placed as this instance: moved by `outer` after its own motor, named by
    /// the instance (or `NAME (instance)`), labelled only by its own `label`, in `material`
    /// where the chain of instances gives one; never a template.
    pub(crate) fn dress(
        self,
        mut original: ObjectSpec,
        outer: Option<Motor>,
        material: Option<Spanned<MaterialRef>>,
    ) -> ObjectSpec {
        original.outer = outer;
        let common = &mut original.common;
        common.template = None;
        common.name = Some(self.name.unwrap_or_else(|| format!("{} (instance)", self.of.get_ref())));
        common.label = self.label;
        if let Some(m) = material {
            common.material = m;
        }
        original
    }
}

/// A field of an object's table, if the table has it.
fn field<'a>(value: &'a Spanned<DeValue<'_>>, key: &str) -> Option<&'a DeValue<'a>> {
    match value.get_ref() {
        DeValue::Table(t) => t.get(key).map(Spanned::get_ref),
        _ => None,
    }
}

/// Whether an object's table is an instance (`type = "instance"`).
pub(crate) fn is_instance(value: &Spanned<DeValue<'_>>) -> bool {
    matches!(field(value, "type"), Some(DeValue::String(s)) if s == "instance")
}

/// Whether an object's table is a template (`template = true`), drawn only as instances.
pub(crate) fn is_template(value: &Spanned<DeValue<'_>>) -> bool {
    matches!(field(value, "template"), Some(DeValue::Boolean(true)))
}

/// Whether an object's table moves over the frame times (`motion`): only then does it
/// differ between a shutter's instants.
pub(crate) fn moves(value: &Spanned<DeValue<'_>>) -> bool {
    field(value, "motion").is_some()
}

/// An object's `name`, if it gives one.
pub(crate) fn name_of(value: &Spanned<DeValue<'_>>) -> Option<String> {
    match field(value, "name") {
        Some(DeValue::String(s)) => Some(s.to_string()),
        _ => None,
    }
}
