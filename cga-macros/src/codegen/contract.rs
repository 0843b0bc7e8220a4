//! The scalar trait's contract, checked once where `scalar = …` names it: a trait written
//! to an earlier contract, lacking a method the generated code calls, gets one error per
//! missing method spanned on that item (`cannot find method … in trait`), which names every
//! missing method; the compiler's own errors at the uses, spanned on the whole invocation,
//! still come beside them.

use super::*;
use quote::quote_spanned;
use syn::spanned::Spanned;

/// The associated functions every algebra's code calls on the scalar.
const ALWAYS: [&str; 8] = ["zero", "one", "from_f64", "to_f64", "sqrt", "abs", "is_finite", "epsilon"];

/// Those `exp` and `log` call, where either is generated.
const FUNCTIONS: [&str; 8] = ["max", "binade", "sin", "cos", "atan2", "sinh", "cosh", "ln_1p"];

impl Gen<'_> {
    /// A function naming `<T as Scalar>::method` for each method the code needs, spanned on
    /// the `scalar` item's path (never called: it only has to resolve).
    pub(super) fn scalar_contract(&self, functions: bool) -> TokenStream {
        let real = self.real;
        let span = real.span();
        let needed = ALWAYS.iter().chain(if functions { &FUNCTIONS[..] } else { &[] });
        let probes = needed.map(|m| {
            let m = format_ident!("{m}", span = span);
            quote_spanned!(span=> let _ = <T as #real>::#m;)
        });
        quote! {
            // Never called: each line only has to resolve (see `cga_macros`' docs on `scalar`).
            const _: () = {
                #[allow(dead_code)]
                fn scalar_contract<T: #real>() {
                    #(#probes)*
                }
            };
        }
    }
}
