//! Prepared sandwiches: `V X Ṽ` is linear in `X`, so for a versor used on many operands its
//! matrix (each entry a quadratic form in `V`'s coefficients) is computed once and each
//! operand then costs one multiplication per nonzero entry — klein's precomputed motor,
//! generated for every versor and every type it acts on.

use super::*;

/// One nonzero entry of a sandwich's matrix: output blade, operand field index, and the
/// quadratic form in the versor's coefficients (`(i, j)` with `i ≤ j` → coefficient).
struct Entry {
    out: usize,
    x: usize,
    form: BTreeMap<(usize, usize), f64>,
}

impl Gen<'_> {
    /// The nonzero entries of a sandwich's matrix, by output blade then operand field: the
    /// two stages multiplied out, `Σ c₁ c₂ v_a v_b` for `p_m = Σ c₁ v_a x_i`, `out = Σ c₂ p_m v_b`.
    fn matrix(plan: &SandwichPlan) -> Vec<Entry> {
        let mut forms: BTreeMap<(usize, usize), BTreeMap<(usize, usize), f64>> = BTreeMap::new();
        for (out, terms2) in &plan.stage2 {
            for t2 in terms2 {
                for t1 in &plan.stage1[t2.lhs].1 {
                    let monomial = (t1.lhs.min(t2.rhs), t1.lhs.max(t2.rhs));
                    *forms.entry((*out, t1.rhs)).or_default().entry(monomial).or_default() += t1.coeff * t2.coeff;
                }
            }
        }
        forms
            .into_iter()
            .filter_map(|((out, x), mut form)| {
                // The coefficients are sums of products of small dyadic numbers: exact, so a
                // term that cancels is exactly zero.
                form.retain(|_, c| *c != 0.0);
                (!form.is_empty()).then_some(Entry { out, x, form })
            })
            .collect()
    }

    /// `Prepare<X>` for every versor `V` and type `X` with a sandwich.
    pub(super) fn prepared(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for plan in &self.sandwich_plans {
            let (v, x) = (&self.spec.types[plan.versor], &self.spec.types[plan.object]);
            let entries = Self::matrix(plan);
            let n = entries.len();
            // One binding per entry: an array literal of sums reads to clippy as a missing comma.
            let forms = entries.iter().enumerate().map(|(k, e)| {
                let sum = self.sum(e.form.iter().map(|(&(i, j), &c)| {
                    let (fi, fj) = (self.field(v.model.blades[i]), self.field(v.model.blades[j]));
                    (c, quote!(v.#fi * v.#fj))
                }));
                let name = format_ident!("m{k}");
                quote!(let #name = #sum;)
            });
            let names = (0..n).map(|k| format_ident!("m{k}"));
            let mut rows: BTreeMap<usize, Vec<(f64, TokenStream)>> = BTreeMap::new();
            for (k, e) in entries.iter().enumerate() {
                let xf = self.field(x.model.blades[e.x]);
                rows.entry(e.out).or_default().push((1.0, quote!(m[#k] * x.#xf)));
            }
            let exprs: BTreeMap<usize, TokenStream> = rows.into_iter().map(|(b, t)| (b, self.sum(t))).collect();
            let body = self.construct(plan.target, &exprs);
            let (vi, xi) = (&v.ident, &x.ident);
            let doc = format!(
                " The matrix of `V X Ṽ` with V: `{vi}`, X: `{xi}`: its {n} nonzero entries, each a quadratic form \
                 in V's coefficients; applying it costs {n} multiplications an operand."
            );
            out.extend(quote! {
                #[doc(hidden)]
                impl<T: #real> Prepare<#xi<T>> for #vi<T> {
                    type Matrix = [T; #n];
                    #[doc = #doc]
                    #[inline]
                    fn matrix(self) -> [T; #n] {
                        let v = self;
                        #(#forms)*
                        [#(#names),*]
                    }
                    #[inline(always)]
                    fn apply_matrix(m: &[T; #n], x: #xi<T>) -> Self::Output {
                        #body
                    }
                }
            });
            out.extend(self.prepared_lanes(vi, xi));
        }
        for v in self.spec.types.iter().filter(|t| t.model.versor) {
            let vi = &v.ident;
            out.extend(quote! {
                impl<T: #real> #vi<T> {
                    /// The versor prepared to act on values of `X`: its sandwich's matrix, computed
                    /// once, then `V X Ṽ` at one multiplication per nonzero entry
                    /// (`prepared.apply(x)`, `prepared.apply_to(&xs)`); `X` is inferred from the
                    /// first use.
                    pub fn prepare<X: Copy>(self) -> Prepared<Self, X>
                    where
                        Self: Prepare<X>,
                    {
                        Prepared::new(self)
                    }
                    /// `V X Ṽ` for every `X` of `xs`, by the matrix computed once.
                    pub fn apply_to<X: Copy>(self, xs: &[X]) -> ::std::vec::Vec<<Self as Sandwich<X>>::Output>
                    where
                        Self: Prepare<X>,
                    {
                        Prepared::new(self).apply_to(xs)
                    }
                }
            });
        }
        out
    }

    /// With lanes, `RunInto` for `V`'s matrix on `X` in f64 and f32: `apply_into` through
    /// `simd::map`, its matrix in every lane, at the width `simd::run` takes on the CPU (four
    /// f64; eight f32, sixteen with AVX-512). The lane types are concrete (the `lanes`
    /// contract has the scalar trait implemented by each), and `#[inline]` leaves a pair
    /// no crate calls uncompiled.
    fn prepared_lanes(&self, vi: &syn::Ident, xi: &syn::Ident) -> TokenStream {
        let Some(crate::parse::PathItem { attrs, path }) = &self.spec.lanes else { return TokenStream::new() };
        let map = |lane: TokenStream| {
            quote! {{
                let m = self.matrix.map(|c| <#path::#lane as #path::Lane>::from_fn(|_| f64::from(c)));
                #path::map(
                    xs,
                    out,
                    #[inline(always)]
                    |x: #xi<#path::#lane>| <#vi<#path::#lane> as Prepare<#xi<#path::#lane>>>::apply_matrix(&m, x),
                )
            }}
        };
        let (f64x4, f32x8, f32x16) = (map(quote!(F64x4)), map(quote!(F32x8)), map(quote!(F32x16)));
        let run_into = |scalar: TokenStream, body: TokenStream| {
            quote! {
                #(#attrs)*
                #[doc(hidden)]
                impl RunInto<#xi<#scalar>> for Prepared<#vi<#scalar>, #xi<#scalar>> {
                    type Output = <#vi<#scalar> as Sandwich<#xi<#scalar>>>::Output;
                    #[inline]
                    fn run_into(&self, xs: &[#xi<#scalar>], out: &mut [Self::Output]) -> Option<()> {
                        #body
                    }
                }
            }
        };
        let f32_body = quote! {
            #[cfg(target_arch = "x86_64")]
            let wide = #path::avx512();
            #[cfg(not(target_arch = "x86_64"))]
            let wide = false;
            if wide { #f32x16 } else { #f32x8 }
        };
        let mut out = run_into(quote!(f64), f64x4);
        out.extend(run_into(quote!(f32), f32_body));
        out
    }

    /// With lanes, the trait of `run_into` (one per algebra; [`Gen::prepared_lanes`] gives
    /// its impls).
    pub(super) fn run_into_trait(&self) -> TokenStream {
        let Some(crate::parse::PathItem { attrs, .. }) = &self.spec.lanes else { return TokenStream::new() };
        quote! {
            #(#attrs)*
            /// A prepared versor's `V X Ṽ` on SIMD lanes (generated for every versor and each
            /// type it acts on, in f64 and f32, where the algebra has lanes): `run_into` gives
            /// the bits of [`Prepared::apply_into`], faster — the matrix in every lane through
            /// `simd::map`, four f64 values at a time, eight f32 ones (sixteen with AVX-512).
            pub trait RunInto<X> {
                /// The type of `V X Ṽ`.
                type Output;
                /// `V X Ṽ` for each `X` of `xs` into `out`, in order. `None`, and nothing
                /// written, where the lengths differ.
                fn run_into(&self, xs: &[X], out: &mut [Self::Output]) -> Option<()>;
            }
        }
    }
}
