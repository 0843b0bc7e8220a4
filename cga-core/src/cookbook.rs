//! Everyday tasks, one doctest each, beside clifford's, kingdon's and Versor's spellings,
//! and the conventions that differ. The text is docs/COOKBOOK.md.
#![doc = include_str!("../../docs/COOKBOOK.md")]
