//! The tests' registry: every generated map with its operand blades, result, term count and
//! a function pointer (hidden from the docs).

use super::*;

impl Gen<'_> {
    /// `product_table` and `unary_table`: every generated map, with its cost and a function
    /// evaluating it on storage-basis arrays, so tests can check each against the dense type.
    pub(super) fn registry(&self) -> TokenStream {
        let real = self.real;
        let dim = self.dim;
        let mut products = Vec::new();
        for &Planned { kind, lhs: l, rhs: r, target, ref table } in &self.plans {
            let (li, ri) = (&self.spec.types[l].ident, &self.spec.types[r].ident);
            let n = names(kind);
            let (tr, m, variant) =
                (format_ident!("{}", n.trait_name), format_ident!("{}", n.method), format_ident!("{}", n.kind_variant));
            let terms: usize = table.iter().map(|(_, t)| t.len()).sum();
            let (ls, rs, os) = (li.to_string(), ri.to_string(), self.target_name(target));
            let (lb, rb, ob) =
                (self.target_index(Target::Type(l)), self.target_index(Target::Type(r)), self.target_index(target));
            let value = self.to_storage(target, quote!(#tr::#m(#li::<T>::from_storage(a), #ri::<T>::from_storage(b))));
            products.push(quote! {
                ProductEntry {
                    kind: ProductKind::#variant, lhs: #ls, rhs: #rs, output: #os, terms: #terms,
                    lhs_blades: #lb, rhs_blades: #rb, output_blades: #ob,
                    eval: |a, b| #value,
                }
            });
        }
        for plan in &self.scalar_plans {
            let (lt, rt) = (&self.spec.types[plan.lhs], &self.spec.types[plan.rhs]);
            let (li, ri) = (&lt.ident, &rt.ident);
            let (ls, rs, terms) = (li.to_string(), ri.to_string(), plan.terms.len());
            let (lb, rb) = (self.target_index(Target::Type(plan.lhs)), self.target_index(Target::Type(plan.rhs)));
            products.push(quote! {
                ProductEntry {
                    kind: ProductKind::ScalarProduct, lhs: #ls, rhs: #rs, output: "scalar", terms: #terms,
                    lhs_blades: #lb, rhs_blades: #rb, output_blades: &[0],
                    eval: |a, b| {
                        let mut out = [<T as #real>::zero(); #dim];
                        out[0] = ScalarProduct::scalar_product(#li::<T>::from_storage(a), #ri::<T>::from_storage(b));
                        out
                    },
                }
            });
        }
        for plan in &self.sandwich_plans {
            let (vpos, xpos, target) = (plan.versor, plan.object, plan.target);
            let (v, x) = (&self.spec.types[vpos], &self.spec.types[xpos]);
            let (s1, s2) = (&plan.stage1, &plan.stage2);
            let (vb, xb) = (self.target_index(Target::Type(vpos)), self.target_index(Target::Type(xpos)));
            let ob = self.target_index(target);
            let terms: usize = s1.iter().chain(s2).map(|(_, t)| t.len()).sum();
            let (vi, xi) = (&v.ident, &x.ident);
            let (vs, xs, os) = (vi.to_string(), xi.to_string(), self.target_name(target));
            let value = self
                .to_storage(target, quote!(Sandwich::sandwich(#vi::<T>::from_storage(a), #xi::<T>::from_storage(b))));
            products.push(quote! {
                ProductEntry {
                    kind: ProductKind::Sandwich, lhs: #vs, rhs: #xs, output: #os, terms: #terms,
                    lhs_blades: #vb, rhs_blades: #xb, output_blades: #ob,
                    eval: |a, b| #value,
                }
            });
        }

        let mut inverses = Vec::new();
        for (tpos, t) in self.spec.types.iter().enumerate().filter(|(pos, _)| self.invertible[*pos]) {
            let ty = &t.ident;
            let (ts, ib) = (ty.to_string(), self.target_index(Target::Type(tpos)));
            inverses.push(quote! {
                InverseEntry { input: #ts, input_blades: #ib,
                    eval: |a| #ty::<T>::from_storage(a).try_inverse().map(#ty::to_storage) }
            });
        }

        let mut unaries = Vec::new();
        for (tpos, t) in self.spec.types.iter().enumerate() {
            let ty = &t.ident;
            let ib = self.target_index(Target::Type(tpos));
            let ts = ty.to_string();
            let n = t.model.blades.len();
            for (variant, m) in [("Reverse", "reverse"), ("Involute", "involute"), ("Conjugate", "conjugate")] {
                let (v, m) = (format_ident!("{variant}"), format_ident!("{m}"));
                unaries.push(quote! {
                    UnaryEntry { kind: UnaryKind::#v, input: #ts, output: #ts, terms: #n,
                        input_blades: #ib, output_blades: #ib,
                        eval: |a| #ty::<T>::from_storage(a).#m().to_storage() }
                });
            }
            for (kind, variant, m) in [(Unary::Dual, "Dual", "dual"), (Unary::Undual, "Undual", "undual")] {
                if let Some((target, _, terms)) = self.unary_exprs(t, kind) {
                    let (v, m, os) = (format_ident!("{variant}"), format_ident!("{m}"), self.target_name(target));
                    let ob = self.target_index(target);
                    let value = self.to_storage(target, quote!(#ty::<T>::from_storage(a).#m()));
                    unaries.push(quote! {
                        UnaryEntry { kind: UnaryKind::#v, input: #ts, output: #os, terms: #terms,
                            input_blades: #ib, output_blades: #ob,
                            eval: |a| #value }
                    });
                }
            }
            for (k, blades) in self.grades_of(t) {
                if let Some(target) = self.target_for(&blades) {
                    let (m, os, terms) = (format_ident!("grade{k}"), self.target_name(target), blades.len());
                    let ob = self.target_index(target);
                    let value = self.to_storage(target, quote!(#ty::<T>::from_storage(a).#m()));
                    unaries.push(quote! {
                        UnaryEntry { kind: UnaryKind::Grade(#k), input: #ts, output: #os, terms: #terms,
                            input_blades: #ib, output_blades: #ob,
                            eval: |a| #value }
                    });
                }
            }
            let terms = self.norm_terms(t).len();
            unaries.push(quote! {
                UnaryEntry { kind: UnaryKind::NormSquared, input: #ts, output: "scalar", terms: #terms,
                    input_blades: #ib, output_blades: &[0],
                    eval: |a| {
                        let mut out = [<T as #real>::zero(); #dim];
                        out[0] = #ty::<T>::from_storage(a).norm_squared();
                        out
                    } }
            });
        }

        quote! {
            /// Which product a [`ProductEntry`] evaluates.
            #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
            #[doc(hidden)]
            pub enum ProductKind {
                /// `A B`
                Geometric,
                /// `A ∧ B`
                Outer,
                /// `A · B` (Hestenes)
                Inner,
                /// `A ⌋ B`
                LeftContraction,
                /// `A ⌊ B`
                RightContraction,
                /// `A ∨ B`
                Regressive,
                /// `A × B = ½(A B − B A)`
                Commutator,
                /// `⟨A B⟩₀`, returned in the scalar slot
                ScalarProduct,
                /// `V X Ṽ`, grades of `X` only
                Sandwich,
            }

            /// Which linear map a [`UnaryEntry`] evaluates.
            #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
            #[doc(hidden)]
            pub enum UnaryKind {
                /// `Ã`
                Reverse,
                /// `Â`
                Involute,
                /// `Ā`
                Conjugate,
                /// `A I⁻¹`
                Dual,
                /// `A I`
                Undual,
                /// `⟨A⟩ₖ`
                Grade(usize),
                /// `⟨A Ã⟩₀`, returned in the scalar slot
                NormSquared,
            }

            /// A generated product between two types, evaluated on storage-basis arrays.
            #[derive(Clone, Copy, Debug)]
            #[doc(hidden)]
            pub struct ProductEntry<T> {
                /// The product.
                pub kind: ProductKind,
                /// Left operand's type.
                pub lhs: &'static str,
                /// Right operand's type.
                pub rhs: &'static str,
                /// Result type.
                pub output: &'static str,
                /// Multiplications of operand coefficients the generated code performs.
                pub terms: usize,
                /// Storage indices of the left operand's blades.
                pub lhs_blades: &'static [usize],
                /// Storage indices of the right operand's blades.
                pub rhs_blades: &'static [usize],
                /// Storage indices of the result's blades.
                pub output_blades: &'static [usize],
                /// Runs the generated code: operands and result as storage-basis arrays.
                pub eval: fn(&[T; #dim], &[T; #dim]) -> [T; #dim],
            }

            /// A generated linear map (or the squared norm) of one type.
            #[derive(Clone, Copy, Debug)]
            #[doc(hidden)]
            pub struct UnaryEntry<T> {
                /// The map.
                pub kind: UnaryKind,
                /// Operand type.
                pub input: &'static str,
                /// Result type.
                pub output: &'static str,
                /// Terms (for the norm: multiplications) in the generated code.
                pub terms: usize,
                /// Storage indices of the operand's blades.
                pub input_blades: &'static [usize],
                /// Storage indices of the result's blades.
                pub output_blades: &'static [usize],
                /// Runs the generated code on a storage-basis array.
                pub eval: fn(&[T; #dim]) -> [T; #dim],
            }

            /// A type with a generated `try_inverse` (its `X X̃` is a scalar for every value).
            #[derive(Clone, Copy, Debug)]
            #[doc(hidden)]
            pub struct InverseEntry<T> {
                /// The type.
                pub input: &'static str,
                /// Storage indices of its blades.
                pub input_blades: &'static [usize],
                /// Runs `try_inverse` on a storage-basis array.
                pub eval: fn(&[T; #dim]) -> Option<[T; #dim]>,
            }

            /// Every type with a generated `try_inverse`, in declaration order.
            #[doc(hidden)]
            pub fn inverse_table<T: #real>() -> Vec<InverseEntry<T>> {
                vec![#(#inverses),*]
            }

            /// Every generated product (and sandwich), for checking them all against the dense type.
            #[doc(hidden)]
            pub fn product_table<T: #real>() -> Vec<ProductEntry<T>> {
                vec![#(#products),*]
            }

            /// Every generated unary map, for checking them all against the dense type.
            #[doc(hidden)]
            pub fn unary_table<T: #real>() -> Vec<UnaryEntry<T>> {
                vec![#(#unaries),*]
            }
        }
    }
}
