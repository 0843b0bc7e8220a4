//! The workspace's tests of cga-core and cga-macros live beside this file, one integration
//! test each; this library only runs the README's examples as doctests.
#![doc = include_str!("../README.md")]
