//! The workspace's tests of cga-core and cga-macros: the helpers they share ([`common`]: the
//! golden vectors, tolerances, a counting scalar, double-double numbers, a seeded generator),
//! and the examples of the README and of the library guide as doctests. The tests themselves
//! are the targets in `tests/` (`algebra`, `geometry`, `ui`), one module a subject.
#![doc = include_str!("../README.md")]

pub mod common;

/// The library guide's examples, run as doctests.
#[doc = include_str!("../docs/LIBRARY.md")]
pub mod library_guide {}
