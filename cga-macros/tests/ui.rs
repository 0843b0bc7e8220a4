//! The macro's error messages for bad input as the compiler prints them (spanned, never a
//! panic), the compiler's own for a product or sandwich an algebra does not have, and
//! algebras that compile and run from a fresh crate: each input built by the compiler as a
//! crate of its own, which builds cga-core anew (minutes). Run with `cargo test -p
//! cga-macros --test ui -- --ignored`; regenerate the expected messages with
//! `TRYBUILD=overwrite cargo test -p cga-macros --test ui -- --ignored`. The test run checks
//! the same messages and places in process (`ui_inputs_give_their_messages_where_their_stderr_files_say`)
//! and runs the `ui/pass` programs as tests (`tests/tests/algebra/fresh.rs`).

#[test]
#[ignore = "builds every input as a crate of its own, cga-core with it: minutes"]
fn macro_input_errors_and_a_plain_algebra() {
    let t = trybuild::TestCases::new();
    t.compile_fail("ui/fail/*.rs");
    t.pass("ui/pass/*.rs");
}
