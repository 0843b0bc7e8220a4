//! The products of every ordered pair of types (trait impls and operators) and the versor
//! sandwiches, from the plans computed once in [`super::Gen::new`].

use super::*;

impl Gen<'_> {
    /// One entry per nonzero product of an ordered pair of types, one per nonzero scalar
    /// part of their geometric product, and the nonzero products no type holds.
    pub(super) fn product_plan(&self) -> (Vec<Planned>, Vec<ScalarPlan>, Vec<Uncovered>) {
        let mut plan = Vec::new();
        let mut scalars = Vec::new();
        let mut uncovered = Vec::new();
        for (l, lt) in self.spec.types.iter().enumerate() {
            for (r, rt) in self.spec.types.iter().enumerate() {
                for kind in Product::ALL {
                    let table = self.a.bilinear(kind, &lt.model.blades, &rt.model.blades);
                    if kind == Product::Geometric
                        && let Some((_, terms)) = table.iter().find(|(b, _)| *b == 0)
                    {
                        scalars.push(ScalarPlan { lhs: l, rhs: r, terms: terms.clone() });
                    }
                    let outs: Vec<usize> = table.iter().map(|(b, _)| *b).collect();
                    if outs.is_empty() {
                        continue;
                    }
                    match self.target_for(&outs) {
                        Some(target) => plan.push(Planned { kind, lhs: l, rhs: r, target, table }),
                        None => {
                            let mut grades: Vec<u32> = outs.iter().map(|b| b.count_ones()).collect();
                            grades.sort_unstable();
                            grades.dedup();
                            uncovered.push(Uncovered { kind, lhs: l, rhs: r, grades });
                        }
                    }
                }
            }
        }
        (plan, scalars, uncovered)
    }

    /// `ScalarProduct` for every pair of types whose geometric product has a scalar part.
    pub(super) fn scalar_products(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for plan in &self.scalar_plans {
            let (lt, rt) = (&self.spec.types[plan.lhs], &self.spec.types[plan.rhs]);
            let body = self.sum(plan.terms.iter().map(|t| {
                let (l, r) = (self.field(lt.model.blades[t.lhs]), self.field(rt.model.blades[t.rhs]));
                (t.coeff, quote!(a.#l * b.#r))
            }));
            let (li, ri) = (&lt.ident, &rt.ident);
            let doc = format!(
                " `⟨A B⟩₀` with A: `{li}`, B: `{ri}`: {} multiplications, the scalar terms of the geometric product.",
                plan.terms.len()
            );
            out.extend(quote! {
                #[doc(hidden)]
                impl<T: #real> ScalarProduct<#ri<T>> for #li<T> {
                    type Output = T;
                    #[doc = #doc]
                    #[inline(always)]
                    fn scalar_product(self, rhs: #ri<T>) -> T {
                        let (a, b) = (self, rhs);
                        #body
                    }
                }
            });
        }
        out
    }

    pub(super) fn products(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for &Planned { kind, lhs: l, rhs: r, target, ref table } in &self.plans {
            let (lt, rt) = (&self.spec.types[l], &self.spec.types[r]);
            let n = names(kind);
            let (tr, m) = (format_ident!("{}", n.trait_name), format_ident!("{}", n.method));
            let exprs = self.bilinear_exprs(table, &lt.model.blades, &rt.model.blades);
            let body = self.construct(target, &exprs);
            let out_ty = self.target_ty(target);
            let (li, ri) = (&lt.ident, &rt.ident);
            let terms: usize = table.iter().map(|(_, t)| t.len()).sum();
            let doc = format!(
                " `{}` with A: `{li}`, B: `{ri}` → `{}`: {terms} multiplications, one per nonzero term of the Cayley table.",
                n.formula,
                self.target_name(target)
            );
            out.extend(quote! {
                #[doc(hidden)]
                impl<T: #real> #tr<#ri<T>> for #li<T> {
                    type Output = #out_ty;
                    #[doc = #doc]
                    #[inline(always)]
                    fn #m(self, rhs: #ri<T>) -> #out_ty {
                        let (a, b) = (self, rhs);
                        #body
                    }
                }
            });
            if let Some((op_trait, op_method)) = n.operator {
                let (ot, om) = (format_ident!("{op_trait}"), format_ident!("{op_method}"));
                out.extend(quote! {
                    #[doc(hidden)]
                    impl<T: #real> core::ops::#ot<#ri<T>> for #li<T> {
                        type Output = #out_ty;
                        #[doc = #doc]
                        #[inline(always)]
                        fn #om(self, rhs: #ri<T>) -> #out_ty {
                            #tr::#m(self, rhs)
                        }
                    }
                });
            }
        }
        out
    }

    /// For a versor type and an object type: the two stages of `V X Ṽ` and the result's
    /// target. Stage one is the full product `V X` (its nonzero blades become locals);
    /// stage two multiplies by `Ṽ` (reverse signs folded into the coefficients) and keeps
    /// only the grades of `X`, which a versor preserves.
    pub(super) fn sandwich_plan(&self, v: &TypeSpec, x: &TypeSpec) -> Option<(Bilinear, Bilinear, Target)> {
        let (stage1, stage2) = self.sandwich_stages(v, x);
        let outs: Vec<usize> = stage2.iter().map(|(b, _)| *b).collect();
        let target = self.target_for(&outs)?;
        Some((stage1, stage2, target))
    }

    /// The two stages of `V X Ṽ` (see [`Gen::sandwich_plan`]).
    pub(super) fn sandwich_stages(&self, v: &TypeSpec, x: &TypeSpec) -> (Bilinear, Bilinear) {
        let stage1 = self.a.bilinear(Product::Geometric, &v.model.blades, &x.model.blades);
        let mids: Vec<usize> = stage1.iter().map(|(b, _)| *b).collect();
        let rev: Vec<f64> =
            v.model.blades.iter().map(|&b| self.a.unary(Unary::Reverse, b).get(&b).copied().unwrap_or(1.0)).collect();
        let stage2 = self
            .a
            .bilinear(Product::Geometric, &mids, &v.model.blades)
            .into_iter()
            .filter(|(b, _)| x.model.blades.iter().any(|xb| xb.count_ones() == b.count_ones()))
            .map(|(b, terms)| {
                let terms = terms.into_iter().map(|t| Term { coeff: t.coeff * rev[t.rhs], ..t }).collect();
                (b, terms)
            })
            .collect::<Bilinear>();
        (stage1, stage2)
    }

    /// Every sandwich of a versor type on a type, in declaration order.
    pub(super) fn all_sandwich_plans(&self) -> Vec<SandwichPlan> {
        let types = &self.spec.types;
        let versors = types.iter().enumerate().filter(|(_, v)| v.model.versor);
        versors
            .flat_map(|(vi, v)| {
                types.iter().enumerate().filter_map(move |(xi, x)| {
                    let (stage1, stage2, target) = self.sandwich_plan(v, x)?;
                    Some(SandwichPlan { versor: vi, object: xi, stage1, stage2, target })
                })
            })
            .collect()
    }

    pub(super) fn sandwiches(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for plan in &self.sandwich_plans {
            let (v, x) = (&self.spec.types[plan.versor], &self.spec.types[plan.object]);
            let (stage1, stage2, target) = (&plan.stage1, &plan.stage2, plan.target);
            let mids: Vec<usize> = stage1.iter().map(|(b, _)| *b).collect();
            let locals = stage1.iter().map(|(b, terms)| {
                let name = format_ident!("p_{}", self.a.blade_name(*b));
                let e = self.sum(terms.iter().map(|t| {
                    let (vf, xf) = (self.field(v.model.blades[t.lhs]), self.field(x.model.blades[t.rhs]));
                    (t.coeff, quote!(v.#vf * x.#xf))
                }));
                quote!(let #name = #e;)
            });
            let exprs: BTreeMap<usize, TokenStream> = stage2
                .iter()
                .map(|(b, terms)| {
                    let e = self.sum(terms.iter().map(|t| {
                        let p = format_ident!("p_{}", self.a.blade_name(mids[t.lhs]));
                        let vf = self.field(v.model.blades[t.rhs]);
                        (t.coeff, quote!(#p * v.#vf))
                    }));
                    (*b, e)
                })
                .collect();
            let body = self.construct(target, &exprs);
            let terms: usize = stage1.iter().chain(stage2).map(|(_, t)| t.len()).sum();
            let (vi, xi, out_ty) = (&v.ident, &x.ident, self.target_ty(target));
            let doc = format!(
                " `V X Ṽ` with V: `{vi}`, X: `{xi}` → `{}`: {terms} multiplications in two stages.",
                self.target_name(target)
            );
            out.extend(quote! {
                #[doc(hidden)]
                impl<T: #real> Sandwich<#xi<T>> for #vi<T> {
                    type Output = #out_ty;
                    #[doc = #doc]
                    #[inline(always)]
                    #[allow(unused_variables)]
                    fn sandwich(self, x: #xi<T>) -> #out_ty {
                        let v = self;
                        #(#locals)*
                        #body
                    }
                }
            });
        }
        out
    }
}
