//! The `approx` crate's comparison traits, on request.

use crate::Spec;
use proc_macro2::TokenStream;
use quote::quote;

/// The `approx` crate's `AbsDiffEq`, `RelativeEq` and `UlpsEq` for every type and the dense
/// one, coefficient by coefficient (what `to_array` holds), when the invocation asks for
/// them; each impl carries the `approx` item's attributes.
pub(super) fn approx(spec: &Spec) -> TokenStream {
    let Some(crate::parse::PathItem { attrs, path }) = &spec.approx else { return TokenStream::new() };
    let real = &spec.scalar;
    // Sparse types give their coefficients by `to_array`, the dense one holds `coeffs`.
    let sparse = spec.types.iter().map(|t| (&t.ident, quote!(to_array())));
    let names = sparse.chain(spec.dense.iter().map(|d| (&d.name, quote!(coeffs))));
    names
        .map(|(name, coefficients)| {
            quote! {
                #(#attrs)*
                impl<T: #real + #path::AbsDiffEq<Epsilon = T>> #path::AbsDiffEq for #name<T> {
                    type Epsilon = T;
                    fn default_epsilon() -> T {
                        T::default_epsilon()
                    }
                    fn abs_diff_eq(&self, other: &Self, epsilon: T) -> bool {
                        self.#coefficients.iter().zip(other.#coefficients.iter()).all(|(a, b)| a.abs_diff_eq(b, epsilon))
                    }
                }
                #(#attrs)*
                impl<T: #real + #path::RelativeEq<Epsilon = T>> #path::RelativeEq for #name<T> {
                    fn default_max_relative() -> T {
                        T::default_max_relative()
                    }
                    fn relative_eq(&self, other: &Self, epsilon: T, max_relative: T) -> bool {
                        self.#coefficients
                            .iter()
                            .zip(other.#coefficients.iter())
                            .all(|(a, b)| a.relative_eq(b, epsilon, max_relative))
                    }
                }
                #(#attrs)*
                impl<T: #real + #path::UlpsEq<Epsilon = T>> #path::UlpsEq for #name<T> {
                    fn default_max_ulps() -> u32 {
                        T::default_max_ulps()
                    }
                    fn ulps_eq(&self, other: &Self, epsilon: T, max_ulps: u32) -> bool {
                        self.#coefficients.iter().zip(other.#coefficients.iter()).all(|(a, b)| a.ulps_eq(b, epsilon, max_ulps))
                    }
                }
            }
        })
        .collect()
}
