//! Which of a table's optional fields are given, and where: errors point at the first one
//! given that should not be.

use std::ops::Range;
use toml::Spanned;

/// The first of the named fields that is given, and where.
pub(crate) fn first_given(fields: &[(&'static str, &dyn Given)]) -> Option<(&'static str, Range<usize>)> {
    fields.iter().find_map(|(name, f)| f.given().map(|span| (*name, span)))
}

/// An optional field's span where it is given.
pub(crate) trait Given {
    fn given(&self) -> Option<Range<usize>>;
}

impl<T> Given for Option<Spanned<T>> {
    fn given(&self) -> Option<Range<usize>> {
        self.as_ref().map(Spanned::span)
    }
}

impl Given for Option<Range<usize>> {
    fn given(&self) -> Option<Range<usize>> {
        self.clone()
    }
}
