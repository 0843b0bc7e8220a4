//! Drawing each kind of CGA object, from Rust and from a scene file. The text is
//! docs/FIGURES.md; its Rust blocks run as doctests.
#![doc = include_str!("../../../docs/FIGURES.md")]
