//! The prelude, on request (`prelude = f64;`): every type at one scalar, so that literals
//! need no annotation, and every generated trait.

use super::*;

/// The `prelude` module, on request: every type at the named scalar and every generated
/// trait, imported as `_` (their methods and operators, without their names).
impl Gen<'_> {
    pub(super) fn prelude(&self) -> TokenStream {
        let spec = self.spec;
        let Some(crate::parse::PathItem { attrs, path }) = &spec.prelude else { return TokenStream::new() };
        let types = spec.types.iter().map(|t| (&t.ident, &t.ident));
        let aliases = spec.aliases.iter().map(|a| (&a.name, &a.target));
        let dense = spec.dense.iter().map(|d| (&d.name, &d.name));
        let items = types.chain(aliases).chain(dense).map(|(name, target)| {
            let doc = format!(" `{target}<{}>`.", quote!(#path));
            quote! {
                #[doc = #doc]
                pub type #name = super::#target<#path>;
            }
        });
        let traits = Product::ALL.iter().map(|&k| format_ident!("{}", names(k).trait_name)).chain(
            ["Sandwich", "Prepare", "ScalarProduct", "Exp", "Log", "Inverse", "Blades"].map(|n| format_ident!("{n}")),
        );
        // With lanes, a prepared versor's `run_into` too, under the `lanes` item's attributes
        // (a crate may gate its lanes behind a feature).
        let run_into = spec.lanes.as_ref().map(|crate::parse::PathItem { attrs, .. }| {
            quote! {
                #(#attrs)*
                pub use super::RunInto as _;
            }
        });
        let doc = format!(
            " Every type of the algebra at `{}` and every generated trait: `use …::prelude::*`.",
            quote!(#path)
        );
        quote! {
            #(#attrs)*
            #[doc = #doc]
            pub mod prelude {
                #(pub use super::#traits as _;)*
                #run_into
                #(#items)*
            }
        }
    }
}
