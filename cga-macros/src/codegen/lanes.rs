//! Lanes for every type, on request: the types of an algebra whose invocation names
//! cga-core's `simd` module (`lanes = cga_core::simd;`) batch as cga-core's own do.

use crate::Spec;
use proc_macro2::TokenStream;
use quote::quote;

/// `cga_core::simd::Lanes` for every type, declared and generated (not the dense one: a
/// batch of dense values is the registry's, row by row), through that module's `lanes!`,
/// which holds the transposes; the invocation carries the item's attributes.
pub(super) fn lanes(spec: &Spec) -> TokenStream {
    let Some(crate::parse::PathItem { attrs, path }) = &spec.lanes else { return TokenStream::new() };
    let names = spec.types.iter().map(|t| &t.ident);
    quote! {
        #(#attrs)*
        #path::lanes! { #(#names),* }
    }
}
