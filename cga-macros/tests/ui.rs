//! The macro's error messages for bad input (spanned, never a panic), and an algebra in
//! the orthonormal basis that compiles and runs from a fresh crate.
//!
//! Regenerate the expected messages with `TRYBUILD=overwrite cargo test -p cga-macros --test ui`.

#[test]
fn macro_input_errors_and_a_plain_algebra() {
    let t = trybuild::TestCases::new();
    t.compile_fail("ui/fail/*.rs");
    t.pass("ui/pass/*.rs");
}
