//! What the kinds that draw a CGA object share (`point`, `point-pair`, `line`, `circle`,
//! `plane-patch`, `blade`): each reads its fields into a [`Drawing`], in world coordinates
//! before its motor, which [`marks`](crate::format::marks) turns into shapes sized for the
//! scene.

use super::kind::{At, Fields, Geometry};
use crate::drawing::{Drawing, Marks, Sizes};
use crate::format::Assets;
use crate::format::marks::{self, Parts};
use crate::format::numbers::Num;
use crate::format::transform::Placement;
use crate::frame::Frame;
use crate::invalid::Invalid;
use cga_core::euclid::E3;
use serde::de::{DeserializeOwned, IntoDeserializer};
use std::ops::Range;
use toml::Spanned;
use toml::de::DeValue;

/// A kind that draws a CGA object.
pub(crate) trait Draws: Fields + Send + Sync {
    /// What it draws, its marks sized by its own `size` and `tube` where given, else by
    /// `defaults` ([`sized`]).
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid>;

    /// Where a drawing is, for sizing the scene: a point of it and its extent (`None` for a
    /// direction, which has no place).
    fn place(&self, drawing: Drawing) -> Option<(E3, f64)> {
        Some(drawing.extent())
    }
}

/// A drawing kind as an object kind.
pub(crate) struct Drawn<T>(T);

/// [`Kind::read`](super::kind::Kind::read) for a drawing kind whose spec is `T`.
pub(crate) fn read<T: Draws + DeserializeOwned + 'static>(
    table: Spanned<DeValue<'_>>,
) -> Result<Box<dyn Geometry>, toml::de::Error> {
    Ok(Box::new(Drawn(T::deserialize(table.into_deserializer())?)))
}

impl<T: Draws> Fields for Drawn<T> {
    fn span(&self, field: &str) -> Option<Range<usize>> {
        self.0.span(field)
    }
}

impl<T: Draws> Geometry for Drawn<T> {
    /// Where it is drawn with marks of no size (`None` for fields that make no object:
    /// building it says why).
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        self.0.place(self.0.drawing(&Sizes::ZERO).ok()?)
    }

    /// Its marks, sized for the scene; a line kept within [`Marks::view`](crate::drawing::Marks::view).
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        draw(&self.0.drawing(&at.marks.sizes)?, &at.place, at.frame, at.marks)
    }

    fn draws(&self) -> bool {
        true
    }
}

/// A drawing's shapes placed in `frame` by `place`, a line kept within
/// [`Marks::view`](crate::drawing::Marks::view) of the camera about its point nearest the
/// scene's centre.
pub(crate) fn draw(drawing: &Drawing, place: &Placement, frame: &Frame, marks: &Marks) -> Result<Parts, Invalid> {
    let centre = frame.point(marks.sizes.centre);
    marks::parts(drawing, place, centre, place.length(marks.view(drawing)))
}

/// `defaults` with a drawing's own `size` (a ball's radius, a patch's) and `tube` where it
/// gives them, each checked positive.
pub(crate) fn sized(
    size: &Option<Spanned<Num>>,
    tube: &Option<Spanned<Num>>,
    defaults: &Sizes,
) -> Result<Sizes, Invalid> {
    let length = |field: &'static str, x: &Option<Spanned<Num>>| match x {
        // Numbers are finite where they are read.
        Some(l) if l.get_ref().0 <= 0.0 => Err(Invalid::at(field, l.span(), Invalid::Value("a size must be positive"))),
        Some(l) => Ok(Some(l.get_ref().0)),
        None => Ok(None),
    };
    Ok(defaults.with(length("size", size)?, length("tube", tube)?))
}

/// A unit direction, or the zero-vector error.
pub(crate) fn nonzero(d: E3) -> Result<E3, Invalid> {
    cga_core::euclid::unit(d).ok_or(Invalid::Geometry(cga_core::GeometryError::ZeroVector))
}
