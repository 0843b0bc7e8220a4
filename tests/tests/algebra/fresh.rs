//! Algebras declared outside cga-core, used as a user's crate uses them: the macro's
//! `ui/pass` programs (an orthonormal G(3,0), blades in any order, labels of several
//! characters, results of mixed grades and scalar results, two algebras in one crate,
//! arithmetic), each in a module of its own, its `main` run as a test. `cargo test -p
//! cga-macros --test ui -- --ignored` builds each as a crate of its own as well.

/// Each program, as its file writes it, in a module named after it.
macro_rules! programs {
    ($($name:ident),* $(,)?) => {$(
        // As a user writes it: the lints of this workspace are not theirs.
        #[allow(clippy::all, dead_code, unused_imports)]
        mod $name {
            include!(concat!(env!("CARGO_MANIFEST_DIR"), "/../cga-macros/ui/pass/", stringify!($name), ".rs"));

            #[test]
            fn runs() {
                main();
            }
        }
    )*};
}

programs!(
    arithmetic_g3,
    blades_in_any_order,
    grade_mixed_results,
    multi_character_labels,
    orthonormal_g3,
    scalar_results,
    two_algebras_one_crate,
);
