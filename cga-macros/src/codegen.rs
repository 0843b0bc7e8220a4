//! Tables → Rust. Every generated function is straight-line code over named fields: one
//! expression per nonzero output blade, one multiplication per nonzero table term.

use crate::model::{Algebra, Bilinear, Product, Term, Unary, cover};
use crate::{Spec, TypeSpec};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeMap;

pub fn generate(spec: &Spec) -> TokenStream {
    let g = Gen::new(spec);
    let mut out = g.traits();
    for t in &spec.types {
        out.extend(g.type_items(t));
    }
    out.extend(g.embeddings());
    out.extend(g.products());
    out.extend(g.sandwiches());
    out.extend(g.dense());
    out.extend(g.registry());
    out.extend(g.aliases());
    out.extend(approx(spec));
    out
}

/// The `approx` crate's `AbsDiffEq`, `RelativeEq` and `UlpsEq` for every type and the dense
/// one, coefficient by coefficient (what `to_array` holds), when the invocation asks for
/// them; each impl carries the `approx` item's attributes.
fn approx(spec: &Spec) -> TokenStream {
    let Some(crate::parse::Approx { attrs, path }) = &spec.approx else { return TokenStream::new() };
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

/// Where a map's result goes: a declared type, or the dense type when none covers it.
#[derive(Clone, Copy)]
enum Target {
    Type(usize),
    Dense,
}

/// A product to generate: its kind, operand types (indices), result and table.
struct Planned {
    kind: Product,
    lhs: usize,
    rhs: usize,
    target: Target,
    table: Bilinear,
}

/// Names and symbols of a product kind.
struct ProductNames {
    trait_name: &'static str,
    method: &'static str,
    operator: Option<(&'static str, &'static str)>,
    formula: &'static str,
    kind_variant: &'static str,
}

fn names(kind: Product) -> ProductNames {
    let (trait_name, method, operator, formula, kind_variant) = match kind {
        Product::Geometric => ("GeometricProduct", "gp", Some(("Mul", "mul")), "A B", "Geometric"),
        Product::Outer => ("OuterProduct", "wedge", Some(("BitXor", "bitxor")), "A ∧ B", "Outer"),
        Product::Inner => ("InnerProduct", "inner", Some(("BitOr", "bitor")), "A · B (Hestenes)", "Inner"),
        Product::LeftContraction => ("LeftContraction", "lc", None, "A ⌋ B", "LeftContraction"),
        Product::Regressive => ("RegressiveProduct", "vee", Some(("BitAnd", "bitand")), "A ∨ B", "Regressive"),
    };
    ProductNames { trait_name, method, operator, formula, kind_variant }
}

struct Gen<'a> {
    spec: &'a Spec,
    a: &'a Algebra,
    real: &'a syn::Path,
    dim: usize,
    /// Canonical position of every storage blade: its index in storage arrays.
    rank: Vec<usize>,
}

impl<'a> Gen<'a> {
    fn new(spec: &'a Spec) -> Self {
        let a = &spec.algebra;
        Gen { spec, a, real: &spec.scalar, dim: a.dim(), rank: a.rank() }
    }

    fn field(&self, blade: usize) -> syn::Ident {
        format_ident!("{}", self.a.blade_name(blade))
    }

    fn target_for(&self, blades: &[usize]) -> Option<Target> {
        let models: Vec<_> = self.spec.types.iter().map(|t| t.model.clone()).collect();
        match cover(&models, blades) {
            Some(t) => Some(Target::Type(t)),
            None => self.spec.dense.as_ref().map(|_| Target::Dense),
        }
    }

    fn target_ty(&self, target: Target) -> TokenStream {
        let ident = match target {
            Target::Type(t) => &self.spec.types[t].ident,
            Target::Dense => &self.dense_ident(),
        };
        quote!(#ident<T>)
    }

    fn target_name(&self, target: Target) -> String {
        match target {
            Target::Type(t) => self.spec.types[t].ident.to_string(),
            Target::Dense => self.dense_ident().to_string(),
        }
    }

    /// Storage indices of a target's blades, as a `&'static [usize]` expression.
    fn target_index(&self, target: Target) -> TokenStream {
        match target {
            Target::Type(t) => {
                let ranks = self.spec.types[t].model.blades.iter().map(|&b| self.rank[b]);
                quote!(&[#(#ranks),*])
            }
            Target::Dense => {
                let all = 0..self.dim;
                quote!(&[#(#all),*])
            }
        }
    }

    fn dense_ident(&self) -> syn::Ident {
        self.spec.dense.as_ref().map_or_else(|| format_ident!("Multivector"), |d| d.name.clone())
    }

    /// A value of `target` whose blades are given by `exprs` (the rest zero).
    fn construct(&self, target: Target, exprs: &BTreeMap<usize, TokenStream>) -> TokenStream {
        let real = self.real;
        match target {
            Target::Type(t) => {
                let ty = &self.spec.types[t];
                let ident = &ty.ident;
                let fields = ty.model.blades.iter().map(|&b| {
                    let f = self.field(b);
                    match exprs.get(&b) {
                        Some(e) => quote!(#f: #e),
                        None => quote!(#f: <T as #real>::zero()),
                    }
                });
                quote!(#ident { #(#fields),* })
            }
            Target::Dense => {
                let dense = self.dense_ident();
                let dim = self.dim;
                let sets = exprs.iter().map(|(b, e)| {
                    let i = self.rank[*b];
                    quote!(c[#i] = #e;)
                });
                quote!({
                    let mut c = [<T as #real>::zero(); #dim];
                    #(#sets)*
                    #dense::from_storage(&c)
                })
            }
        }
    }

    /// `Σ coeff · product`, signs folded into `+`/`−`; a coefficient other than ±1 costs
    /// one multiplication by a constant.
    fn sum(&self, terms: impl IntoIterator<Item = (f64, TokenStream)>) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for (i, (c, p)) in terms.into_iter().enumerate() {
            let magnitude = c.abs();
            let p = if (magnitude - 1.0).abs() < 1e-12 {
                p
            } else {
                let m = Literal::f64_suffixed(magnitude);
                quote!(<T as #real>::from_f64(#m) * (#p))
            };
            out.extend(match (i, c < 0.0) {
                (0, false) => p,
                (0, true) => quote!(-#p),
                (_, false) => quote!(+ #p),
                (_, true) => quote!(- #p),
            });
        }
        out
    }

    fn bilinear_exprs(
        &self,
        terms: &[(usize, Vec<Term>)],
        lhs: &[usize],
        rhs: &[usize],
    ) -> BTreeMap<usize, TokenStream> {
        terms
            .iter()
            .map(|(blade, terms)| {
                let e = self.sum(terms.iter().map(|t| {
                    let (l, r) = (self.field(lhs[t.lhs]), self.field(rhs[t.rhs]));
                    (t.coeff, quote!(a.#l * b.#r))
                }));
                (*blade, e)
            })
            .collect()
    }

    fn traits(&self) -> TokenStream {
        let mut out = TokenStream::new();
        for kind in Product::ALL {
            let n = names(kind);
            let (tr, m) = (format_ident!("{}", n.trait_name), format_ident!("{}", n.method));
            let doc = format!(
                " The product `{}`, generated for every pair of types whose Cayley table is not identically zero.",
                n.formula
            );
            out.extend(quote! {
                #[doc = #doc]
                pub trait #tr<Rhs> {
                    /// The smallest declared type that holds every nonzero blade of the result.
                    type Output;
                    #[doc = #doc]
                    fn #m(self, rhs: Rhs) -> Self::Output;
                }
            });
        }
        out.extend(quote! {
            /// The sandwich `V X Ṽ` of a versor `V` and any object `X`. A versor preserves
            /// grades, so only `X`'s grades are computed; the result type is the smallest
            /// declared type holding the nonzero blades of those grades (a translator turns
            /// a rotor into a motor, but keeps a line a line).
            pub trait Sandwich<X> {
                /// The type of `V X Ṽ`.
                type Output;
                /// `V X Ṽ`.
                fn sandwich(self, x: X) -> Self::Output;
            }
        });
        out
    }

    fn type_items(&self, t: &TypeSpec) -> TokenStream {
        let real = self.real;
        let ident = &t.ident;
        let attrs = &t.attrs;
        let blades = &t.model.blades;
        let n = blades.len();
        let fields: Vec<_> = blades.iter().map(|&b| self.field(b)).collect();
        let blade_names: Vec<String> = blades.iter().map(|&b| self.a.blade_name(b)).collect();
        let field_docs = blade_names.iter().map(|b| format!(" Coefficient of `{b}`."));
        let ranks = blades.iter().map(|&b| self.rank[b]);
        let ranks2 = ranks.clone();
        let dim = self.dim;
        let summary = format!(" {n} coefficients: `{}`.", blade_names.join("`, `"));

        let signs = |kind: Unary| -> Vec<TokenStream> {
            blades
                .iter()
                .map(|&b| {
                    let f = self.field(b);
                    let sign = self.a.unary(kind, b).get(&b).copied().unwrap_or(1.0);
                    if sign < 0.0 { quote!(#f: -self.#f) } else { quote!(#f: self.#f) }
                })
                .collect()
        };
        let (rev, inv, conj) = (signs(Unary::Reverse), signs(Unary::Involute), signs(Unary::Conjugate));
        let dual = self.linear_map(t, Unary::Dual, "dual", "The dual `A I⁻¹` (I the unit pseudoscalar).");
        let undual = self.linear_map(t, Unary::Undual, "undual", "The undual `A I`, inverse of `dual`.");
        let grades = self.grade_projections(t);
        let norm = self.norm_squared(t);

        quote! {
            #(#attrs)*
            #[doc = ""]
            #[doc = #summary]
            #[derive(Clone, Copy, Debug, PartialEq, Default)]
            pub struct #ident<T = f64> {
                #( #[doc = #field_docs] pub #fields: T, )*
            }

            impl<T: #real> #ident<T> {
                /// Blade of every field, in field order.
                pub const BLADES: [&'static str; #n] = [#(#blade_names),*];
                /// Index of every field in a storage-basis array (canonical blade order).
                pub const STORAGE_INDEX: [usize; #n] = [#(#ranks),*];

                /// All coefficients zero.
                #[inline]
                pub fn zero() -> Self {
                    Self { #(#fields: <T as #real>::zero()),* }
                }

                /// From coefficients in field order.
                #[inline]
                pub fn from_array(c: [T; #n]) -> Self {
                    let [#(#fields),*] = c;
                    Self { #(#fields),* }
                }

                /// Coefficients in field order.
                #[inline]
                pub fn to_array(self) -> [T; #n] {
                    [#(self.#fields),*]
                }

                /// This type's blades taken from a storage-basis array; other blades are dropped.
                #[inline]
                pub fn from_storage(c: &[T; #dim]) -> Self {
                    Self { #(#fields: c[#ranks2]),* }
                }

                /// As a storage-basis array (canonical blade order), other blades zero.
                #[inline]
                pub fn to_storage(self) -> [T; #dim] {
                    let mut c = [<T as #real>::zero(); #dim];
                    for (i, x) in Self::STORAGE_INDEX.iter().zip(self.to_array()) {
                        c[*i] = x;
                    }
                    c
                }

                /// Reverse `Ã`: grade k times (−1)^(k(k−1)/2).
                #[inline]
                pub fn reverse(self) -> Self {
                    Self { #(#rev),* }
                }

                /// Grade involution `Â`: grade k times (−1)^k.
                #[inline]
                pub fn involute(self) -> Self {
                    Self { #(#inv),* }
                }

                /// Clifford conjugate `Ā`: grade k times (−1)^(k(k+1)/2).
                #[inline]
                pub fn conjugate(self) -> Self {
                    Self { #(#conj),* }
                }

                /// Every coefficient times `s`.
                #[inline]
                pub fn scale(self, s: T) -> Self {
                    Self { #(#fields: self.#fields * s),* }
                }

                #dual
                #undual
                #grades
                #norm

                /// `√|⟨A Ã⟩₀|`.
                #[inline]
                pub fn norm(self) -> T {
                    self.norm_squared().abs().sqrt()
                }

                /// `A / √|⟨A Ã⟩₀|`, so that `A Ã = ±1` for blades and versors. A null `A`
                /// (a point, `⟨A Ã⟩₀ = 0`) gives non-finite coefficients: see `try_normalise`.
                #[inline]
                pub fn normalise(self) -> Self {
                    self.scale(<T as #real>::one() / self.norm())
                }

                /// `A / √|⟨A Ã⟩₀|`, or `None` when `⟨A Ã⟩₀` is zero or not finite.
                #[inline]
                pub fn try_normalise(self) -> Option<Self> {
                    let inv = <T as #real>::one() / self.norm();
                    (self.norm_squared() != <T as #real>::zero() && inv.is_finite()).then(|| self.scale(inv))
                }
            }

            impl<T: #real> core::ops::Add for #ident<T> {
                type Output = Self;
                #[inline]
                fn add(self, rhs: Self) -> Self {
                    Self { #(#fields: self.#fields + rhs.#fields),* }
                }
            }

            impl<T: #real> core::ops::Sub for #ident<T> {
                type Output = Self;
                #[inline]
                fn sub(self, rhs: Self) -> Self {
                    Self { #(#fields: self.#fields - rhs.#fields),* }
                }
            }

            impl<T: #real> core::ops::Neg for #ident<T> {
                type Output = Self;
                #[inline]
                fn neg(self) -> Self {
                    Self { #(#fields: -self.#fields),* }
                }
            }

            impl<T: #real> core::ops::AddAssign for #ident<T> {
                #[inline]
                fn add_assign(&mut self, rhs: Self) {
                    *self = *self + rhs;
                }
            }

            impl<T: #real> core::ops::SubAssign for #ident<T> {
                #[inline]
                fn sub_assign(&mut self, rhs: Self) {
                    *self = *self - rhs;
                }
            }

            impl<T: #real> core::ops::Mul<T> for #ident<T> {
                type Output = Self;
                /// Scale by a scalar.
                #[inline]
                fn mul(self, s: T) -> Self {
                    self.scale(s)
                }
            }
        }
    }

    /// A linear map (dual, undual) of one type into the type that covers its image.
    fn linear_map(&self, t: &TypeSpec, kind: Unary, method: &str, doc: &str) -> TokenStream {
        let Some((target, exprs, _)) = self.unary_exprs(t, kind) else {
            return TokenStream::new();
        };
        let (m, out_ty, body) = (format_ident!("{method}"), self.target_ty(target), self.construct(target, &exprs));
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn #m(self) -> #out_ty {
                let a = self;
                #body
            }
        }
    }

    /// The image of every blade of `t` under `kind`, grouped by output blade, and its target.
    fn unary_exprs(&self, t: &TypeSpec, kind: Unary) -> Option<(Target, BTreeMap<usize, TokenStream>, usize)> {
        let mut by_out: BTreeMap<usize, Vec<(f64, TokenStream)>> = BTreeMap::new();
        for &b in &t.model.blades {
            let f = self.field(b);
            for (r, c) in self.a.unary(kind, b) {
                by_out.entry(r).or_default().push((c, quote!(a.#f)));
            }
        }
        let outs: Vec<usize> = by_out.keys().copied().collect();
        let target = self.target_for(&outs)?;
        let terms = by_out.values().map(Vec::len).sum();
        let exprs = by_out.into_iter().map(|(r, ts)| (r, self.sum(ts))).collect();
        Some((target, exprs, terms))
    }

    /// `gradeK()` for every grade of a type that holds more than one grade.
    fn grade_projections(&self, t: &TypeSpec) -> TokenStream {
        let mut out = TokenStream::new();
        for (k, blades) in self.grades_of(t) {
            let Some(target) = self.target_for(&blades) else { continue };
            let exprs = blades
                .iter()
                .map(|&b| {
                    let f = self.field(b);
                    (b, quote!(self.#f))
                })
                .collect();
            let (m, ty, body) = (format_ident!("grade{k}"), self.target_ty(target), self.construct(target, &exprs));
            let doc = format!(" The grade-{k} part `⟨A⟩{}`.", subscript(k));
            out.extend(quote! {
                #[doc = #doc]
                #[inline]
                pub fn #m(self) -> #ty {
                    #body
                }
            });
        }
        out
    }

    /// Grades present in a type with their blades, when it holds more than one grade.
    fn grades_of(&self, t: &TypeSpec) -> Vec<(usize, Vec<usize>)> {
        let mut by_grade: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for &b in &t.model.blades {
            by_grade.entry(b.count_ones() as usize).or_default().push(b);
        }
        if by_grade.len() < 2 {
            return Vec::new();
        }
        by_grade.into_iter().collect()
    }

    /// Terms of `⟨A Ã⟩₀` with `a_i a_j` and `a_j a_i` merged: `(coeff, i, j)`, i ≤ j.
    fn norm_terms(&self, t: &TypeSpec) -> Vec<(f64, usize, usize)> {
        let blades = &t.model.blades;
        let mut merged: BTreeMap<(usize, usize), f64> = BTreeMap::new();
        for (i, &x) in blades.iter().enumerate() {
            for (j, &y) in blades.iter().enumerate() {
                let rev = self.a.unary(Unary::Reverse, y).get(&y).copied().unwrap_or(1.0);
                if let Some(c) = self.a.product(Product::Geometric, x, y).get(&0) {
                    *merged.entry((i.min(j), i.max(j))).or_insert(0.0) += c * rev;
                }
            }
        }
        merged.into_iter().filter(|(_, c)| c.abs() > 1e-9).map(|((i, j), c)| (c, i, j)).collect()
    }

    fn norm_squared(&self, t: &TypeSpec) -> TokenStream {
        let real = self.real;
        let terms = self.norm_terms(t);
        let blades = &t.model.blades;
        let body = if terms.is_empty() {
            quote!(<T as #real>::zero())
        } else {
            self.sum(terms.iter().map(|&(c, i, j)| {
                let (x, y) = (self.field(blades[i]), self.field(blades[j]));
                // Merged cross terms carry ±2: `x (y + y)` doubles without a constant.
                if (c.abs() - 2.0).abs() < 1e-12 {
                    (c.signum(), quote!(self.#x * (self.#y + self.#y)))
                } else {
                    (c, quote!(self.#x * self.#y))
                }
            }))
        };
        let doc = format!(
            " The squared norm `⟨A Ã⟩₀`: {} multiplications (symmetric terms merged). Zero for null elements such as points; its sign depends on the object.",
            terms.len()
        );
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn norm_squared(self) -> T {
                #body
            }
        }
    }

    /// `From<Sub> for Super` whenever one type's blades are a subset of another's.
    fn embeddings(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for sub in &self.spec.types {
            for (pos, sup) in self.spec.types.iter().enumerate() {
                let fits = sub.model.blades.iter().all(|b| sup.model.blades.contains(b));
                if sub.ident == sup.ident || !fits {
                    continue;
                }
                let exprs = sub
                    .model
                    .blades
                    .iter()
                    .map(|&b| {
                        let f = self.field(b);
                        (b, quote!(x.#f))
                    })
                    .collect();
                let body = self.construct(Target::Type(pos), &exprs);
                let (s, p) = (&sub.ident, &sup.ident);
                let doc = format!(" Every `{s}` is a `{p}` whose other blades are zero.");
                out.extend(quote! {
                    #[doc = #doc]
                    impl<T: #real> From<#s<T>> for #p<T> {
                        #[inline]
                        fn from(x: #s<T>) -> Self {
                            #body
                        }
                    }
                });
            }
        }
        out
    }

    /// One entry per nonzero product of an ordered pair of types.
    fn product_plan(&self) -> Vec<Planned> {
        let mut plan = Vec::new();
        for (l, lt) in self.spec.types.iter().enumerate() {
            for (r, rt) in self.spec.types.iter().enumerate() {
                for kind in Product::ALL {
                    let table = self.a.bilinear(kind, &lt.model.blades, &rt.model.blades);
                    let outs: Vec<usize> = table.iter().map(|(b, _)| *b).collect();
                    if outs.is_empty() {
                        continue;
                    }
                    if let Some(target) = self.target_for(&outs) {
                        plan.push(Planned { kind, lhs: l, rhs: r, target, table });
                    }
                }
            }
        }
        plan
    }

    fn products(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for Planned { kind, lhs: l, rhs: r, target, table } in self.product_plan() {
            let (lt, rt) = (&self.spec.types[l], &self.spec.types[r]);
            let n = names(kind);
            let (tr, m) = (format_ident!("{}", n.trait_name), format_ident!("{}", n.method));
            let exprs = self.bilinear_exprs(&table, &lt.model.blades, &rt.model.blades);
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
                impl<T: #real> #tr<#ri<T>> for #li<T> {
                    type Output = #out_ty;
                    #[doc = #doc]
                    #[inline]
                    fn #m(self, rhs: #ri<T>) -> #out_ty {
                        let (a, b) = (self, rhs);
                        #body
                    }
                }
            });
            if let Some((op_trait, op_method)) = n.operator {
                let (ot, om) = (format_ident!("{op_trait}"), format_ident!("{op_method}"));
                out.extend(quote! {
                    impl<T: #real> core::ops::#ot<#ri<T>> for #li<T> {
                        type Output = #out_ty;
                        #[doc = #doc]
                        #[inline]
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
    fn sandwich_plan(&self, v: &TypeSpec, x: &TypeSpec) -> Option<(Bilinear, Bilinear, Target)> {
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
        let outs: Vec<usize> = stage2.iter().map(|(b, _)| *b).collect();
        let target = self.target_for(&outs)?;
        Some((stage1, stage2, target))
    }

    fn sandwiches(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for v in &self.spec.types {
            if !v.model.versor {
                continue;
            }
            for x in &self.spec.types {
                let Some((stage1, stage2, target)) = self.sandwich_plan(v, x) else { continue };
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
                let terms: usize = stage1.iter().chain(&stage2).map(|(_, t)| t.len()).sum();
                let (vi, xi, out_ty) = (&v.ident, &x.ident, self.target_ty(target));
                let doc = format!(
                    " `V X Ṽ` with V: `{vi}`, X: `{xi}` → `{}`: {terms} multiplications in two stages.",
                    self.target_name(target)
                );
                out.extend(quote! {
                    impl<T: #real> Sandwich<#xi<T>> for #vi<T> {
                        type Output = #out_ty;
                        #[doc = #doc]
                        #[inline]
                        #[allow(unused_variables)]
                        fn sandwich(self, x: #xi<T>) -> #out_ty {
                            let v = self;
                            #(#locals)*
                            #body
                        }
                    }
                });
            }
        }
        out
    }

    /// The dense multivector: 2^n coefficients in the orthonormal basis, every product a
    /// loop over a table of the nonzero entries computed here.
    fn dense(&self) -> TokenStream {
        let Some(dense) = &self.spec.dense else {
            return TokenStream::new();
        };
        let real = self.real;
        let (ident, attrs, dim) = (&dense.name, &dense.attrs, self.dim);
        let order = self.a.canonical_order();
        let ortho_names: Vec<String> = order.iter().map(|&m| self.a.ortho_name(m)).collect();
        let mut pos = vec![0usize; dim];
        for (p, &m) in order.iter().enumerate() {
            pos[m] = p;
        }
        let upper = ident.to_string().to_uppercase();

        let mut out = TokenStream::new();
        let mut product_impls = TokenStream::new();
        for kind in Product::ALL {
            // Entries split by sign, so that the loops carry no branch.
            let (mut plus, mut minus) = (Vec::new(), Vec::new());
            for &i in &order {
                for &j in &order {
                    if let Some((r, s)) = self.a.ortho_product(kind, i, j) {
                        let (pi, pj, pr) = (pos[i] as u8, pos[j] as u8, pos[r] as u8);
                        let side = if s < 0.0 { &mut minus } else { &mut plus };
                        side.push(quote!((#pi, #pj, #pr)));
                    }
                }
            }
            let table = format_ident!("__{}_{}", upper, names(kind).trait_name.to_uppercase());
            let (np, nm) = (plus.len(), minus.len());
            let len = np + nm;
            out.extend(quote! {
                #[doc(hidden)]
                const #table: ([(u8, u8, u8); #np], [(u8, u8, u8); #nm]) = ([#(#plus),*], [#(#minus),*]);
            });
            let n = names(kind);
            let (tr, m) = (format_ident!("{}", n.trait_name), format_ident!("{}", n.method));
            let doc = format!(" `{}`, a loop over the {len} nonzero entries of its table.", n.formula);
            product_impls.extend(quote! {
                impl<T: #real> #tr<#ident<T>> for #ident<T> {
                    type Output = #ident<T>;
                    #[doc = #doc]
                    #[inline]
                    fn #m(self, rhs: #ident<T>) -> #ident<T> {
                        self.apply_table(&rhs, &#table.0, &#table.1)
                    }
                }
            });
            if let Some((op_trait, op_method)) = n.operator {
                let (ot, om) = (format_ident!("{op_trait}"), format_ident!("{op_method}"));
                product_impls.extend(quote! {
                    impl<T: #real> core::ops::#ot<#ident<T>> for #ident<T> {
                        type Output = #ident<T>;
                        #[doc = #doc]
                        #[inline]
                        fn #om(self, rhs: #ident<T>) -> #ident<T> {
                            #tr::#m(self, rhs)
                        }
                    }
                });
            }
        }

        // Orthonormal → orthonormal unary tables: one (target, negate) per blade.
        let unary_table = |f: &dyn Fn(usize) -> (usize, f64)| -> Vec<TokenStream> {
            order
                .iter()
                .map(|&m| {
                    let (r, s) = f(m);
                    let (pr, neg) = (pos[r] as u8, s < 0.0);
                    quote!((#pr, #neg))
                })
                .collect()
        };
        let full = dim - 1;
        let inv_sign = self.a.ortho_gp(full, full).1;
        let dual_t = unary_table(&|m| {
            let (r, s) = self.a.ortho_gp(m, full);
            (r, s * inv_sign)
        });
        let undual_t = unary_table(&|m| self.a.ortho_gp(m, full));
        let grade_sign = |e: i64| if e % 2 == 0 { 1.0 } else { -1.0 };
        let sign_t = |f: &dyn Fn(i64) -> f64| -> Vec<TokenStream> {
            order
                .iter()
                .map(|&m| {
                    let neg = f(m.count_ones() as i64) < 0.0;
                    quote!(#neg)
                })
                .collect()
        };
        let rev_t = sign_t(&|k| grade_sign(k * (k - 1) / 2));
        let inv_t = sign_t(&|k| grade_sign(k));
        let conj_t = sign_t(&|k| grade_sign(k * (k + 1) / 2));
        let grades: Vec<u8> = order.iter().map(|m| m.count_ones() as u8).collect();

        // Storage ↔ orthonormal conversions, unrolled.
        let convert = |src: &dyn Fn(usize) -> Vec<(usize, f64)>, src_pos: &[usize], dst_pos: &[usize]| {
            let mut by_dst: BTreeMap<usize, Vec<(f64, TokenStream)>> = BTreeMap::new();
            for (m, &s) in src_pos.iter().enumerate() {
                for (r, c) in src(m) {
                    by_dst.entry(dst_pos[r]).or_default().push((c, quote!(c[#s])));
                }
            }
            let sets: Vec<TokenStream> = by_dst
                .into_iter()
                .map(|(d, terms)| {
                    let e = self.sum(terms);
                    quote!(out[#d] = #e;)
                })
                .collect();
            sets
        };
        let to_ortho =
            convert(&|m| self.a.storage_to_ortho(m).iter().map(|(&k, &v)| (k, v)).collect(), &self.rank, &pos);
        let from_ortho =
            convert(&|m| self.a.ortho_blade_to_storage(m).iter().map(|(&k, &v)| (k, v)).collect(), &pos, &self.rank);
        let tables = format_ident!("__{}_UNARY", upper);
        let summary = format!(
            " {dim} coefficients in the orthonormal basis, in canonical order: `{}`.",
            ortho_names.join("`, `")
        );
        out.extend(quote! {
            #[doc(hidden)]
            #[allow(clippy::type_complexity)]
            const #tables: ([(u8, bool); #dim], [(u8, bool); #dim], [bool; #dim], [bool; #dim], [bool; #dim], [u8; #dim]) = (
                [#(#dual_t),*], [#(#undual_t),*], [#(#rev_t),*], [#(#inv_t),*], [#(#conj_t),*], [#(#grades),*]
            );

            #(#attrs)*
            #[doc = ""]
            #[doc = #summary]
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub struct #ident<T = f64> {
                /// Coefficients, indexed as `BLADES`.
                pub coeffs: [T; #dim],
            }

            impl<T: #real> Default for #ident<T> {
                fn default() -> Self {
                    Self::zero()
                }
            }

            impl<T: #real> #ident<T> {
                /// Orthonormal blade of every coefficient.
                pub const BLADES: [&'static str; #dim] = [#(#ortho_names),*];

                /// All coefficients zero.
                #[inline]
                pub fn zero() -> Self {
                    Self { coeffs: [<T as #real>::zero(); #dim] }
                }

                /// From orthonormal-basis coefficients in `BLADES` order.
                #[inline]
                pub fn new(coeffs: [T; #dim]) -> Self {
                    Self { coeffs }
                }

                /// From storage-basis coefficients (canonical order of the storage blades).
                #[inline]
                pub fn from_storage(c: &[T; #dim]) -> Self {
                    let mut out = [<T as #real>::zero(); #dim];
                    #(#to_ortho)*
                    Self { coeffs: out }
                }

                /// To storage-basis coefficients (canonical order of the storage blades).
                #[inline]
                pub fn to_storage(&self) -> [T; #dim] {
                    let c = &self.coeffs;
                    let mut out = [<T as #real>::zero(); #dim];
                    #(#from_ortho)*
                    out
                }

                /// `out[k] += a[i] b[j]` over the positive entries of a product table, then
                /// `out[k] −= a[i] b[j]` over the negative ones. Indices are masked to the
                /// array size, which lets the compiler drop the bounds checks.
                #[inline]
                fn apply_table(&self, rhs: &Self, plus: &[(u8, u8, u8)], minus: &[(u8, u8, u8)]) -> Self {
                    const MASK: usize = #dim - 1;
                    let (a, b) = (&self.coeffs, &rhs.coeffs);
                    let mut out = [<T as #real>::zero(); #dim];
                    for &(i, j, k) in plus {
                        let k = k as usize & MASK;
                        out[k] = out[k] + a[i as usize & MASK] * b[j as usize & MASK];
                    }
                    for &(i, j, k) in minus {
                        let k = k as usize & MASK;
                        out[k] = out[k] - a[i as usize & MASK] * b[j as usize & MASK];
                    }
                    Self { coeffs: out }
                }

                fn signed(&self, negate: &[bool; #dim]) -> Self {
                    let mut out = self.coeffs;
                    for (x, &n) in out.iter_mut().zip(negate) {
                        if n {
                            *x = -*x;
                        }
                    }
                    Self { coeffs: out }
                }

                fn permuted(&self, table: &[(u8, bool); #dim]) -> Self {
                    let mut out = [<T as #real>::zero(); #dim];
                    for (&x, &(k, n)) in self.coeffs.iter().zip(table) {
                        out[k as usize] = if n { -x } else { x };
                    }
                    Self { coeffs: out }
                }

                /// Reverse `Ã`.
                #[inline]
                pub fn reverse(&self) -> Self {
                    self.signed(&#tables.2)
                }

                /// Grade involution `Â`.
                #[inline]
                pub fn involute(&self) -> Self {
                    self.signed(&#tables.3)
                }

                /// Clifford conjugate `Ā`.
                #[inline]
                pub fn conjugate(&self) -> Self {
                    self.signed(&#tables.4)
                }

                /// Dual `A I⁻¹`.
                #[inline]
                pub fn dual(&self) -> Self {
                    self.permuted(&#tables.0)
                }

                /// Undual `A I`.
                #[inline]
                pub fn undual(&self) -> Self {
                    self.permuted(&#tables.1)
                }

                /// The grade-k part `⟨A⟩ₖ`.
                #[inline]
                pub fn grade(&self, k: usize) -> Self {
                    let mut out = self.coeffs;
                    for (x, &g) in out.iter_mut().zip(&#tables.5) {
                        if g as usize != k {
                            *x = <T as #real>::zero();
                        }
                    }
                    Self { coeffs: out }
                }

                /// Squared norm `⟨A Ã⟩₀`.
                #[inline]
                pub fn norm_squared(&self) -> T {
                    GeometricProduct::gp(*self, self.reverse()).coeffs[0]
                }

                /// Every coefficient times `s`.
                #[inline]
                pub fn scale(&self, s: T) -> Self {
                    Self { coeffs: self.coeffs.map(|x| x * s) }
                }

                /// `V X Ṽ`, in full.
                #[inline]
                pub fn sandwich(&self, x: &Self) -> Self {
                    GeometricProduct::gp(GeometricProduct::gp(*self, *x), self.reverse())
                }
            }

            impl<T: #real> core::ops::Add for #ident<T> {
                type Output = Self;
                #[inline]
                fn add(self, rhs: Self) -> Self {
                    let mut out = self.coeffs;
                    for (x, y) in out.iter_mut().zip(rhs.coeffs) {
                        *x = *x + y;
                    }
                    Self { coeffs: out }
                }
            }

            impl<T: #real> core::ops::Sub for #ident<T> {
                type Output = Self;
                #[inline]
                fn sub(self, rhs: Self) -> Self {
                    self + (-rhs)
                }
            }

            impl<T: #real> core::ops::Neg for #ident<T> {
                type Output = Self;
                #[inline]
                fn neg(self) -> Self {
                    Self { coeffs: self.coeffs.map(|x| -x) }
                }
            }

            #product_impls
        });

        // Every sparse type converts to and from the dense one.
        for t in &self.spec.types {
            let ty = &t.ident;
            let doc_in = format!(" The dense form of a `{ty}` (orthonormal basis).");
            let doc_out = format!(" The `{ty}` blades of a dense multivector (the rest is dropped).");
            out.extend(quote! {
                #[doc = #doc_in]
                impl<T: #real> From<#ty<T>> for #ident<T> {
                    #[inline]
                    fn from(x: #ty<T>) -> Self {
                        #ident::from_storage(&x.to_storage())
                    }
                }
                impl<T: #real> #ty<T> {
                    #[doc = #doc_out]
                    #[inline]
                    pub fn from_dense(m: &#ident<T>) -> Self {
                        Self::from_storage(&m.to_storage())
                    }
                }
            });
        }
        out
    }

    /// `product_table` and `unary_table`: every generated map, with its cost and a function
    /// evaluating it on storage-basis arrays, so tests can check each against the dense type.
    fn registry(&self) -> TokenStream {
        let real = self.real;
        let dim = self.dim;
        let mut products = Vec::new();
        for Planned { kind, lhs: l, rhs: r, target, table } in self.product_plan() {
            let (li, ri) = (&self.spec.types[l].ident, &self.spec.types[r].ident);
            let n = names(kind);
            let (tr, m, variant) =
                (format_ident!("{}", n.trait_name), format_ident!("{}", n.method), format_ident!("{}", n.kind_variant));
            let terms: usize = table.iter().map(|(_, t)| t.len()).sum();
            let (ls, rs, os) = (li.to_string(), ri.to_string(), self.target_name(target));
            let (lb, rb, ob) =
                (self.target_index(Target::Type(l)), self.target_index(Target::Type(r)), self.target_index(target));
            products.push(quote! {
                ProductEntry {
                    kind: ProductKind::#variant, lhs: #ls, rhs: #rs, output: #os, terms: #terms,
                    lhs_blades: #lb, rhs_blades: #rb, output_blades: #ob,
                    eval: |a, b| #tr::#m(#li::<T>::from_storage(a), #ri::<T>::from_storage(b)).to_storage(),
                }
            });
        }
        for (vpos, v) in self.spec.types.iter().enumerate().filter(|(_, v)| v.model.versor) {
            for (xpos, x) in self.spec.types.iter().enumerate() {
                let Some((s1, s2, target)) = self.sandwich_plan(v, x) else { continue };
                let (vb, xb) = (self.target_index(Target::Type(vpos)), self.target_index(Target::Type(xpos)));
                let ob = self.target_index(target);
                let terms: usize = s1.iter().chain(&s2).map(|(_, t)| t.len()).sum();
                let (vi, xi) = (&v.ident, &x.ident);
                let (vs, xs, os) = (vi.to_string(), xi.to_string(), self.target_name(target));
                products.push(quote! {
                    ProductEntry {
                        kind: ProductKind::Sandwich, lhs: #vs, rhs: #xs, output: #os, terms: #terms,
                        lhs_blades: #vb, rhs_blades: #xb, output_blades: #ob,
                        eval: |a, b| Sandwich::sandwich(#vi::<T>::from_storage(a), #xi::<T>::from_storage(b)).to_storage(),
                    }
                });
            }
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
                    unaries.push(quote! {
                        UnaryEntry { kind: UnaryKind::#v, input: #ts, output: #os, terms: #terms,
                            input_blades: #ib, output_blades: #ob,
                            eval: |a| #ty::<T>::from_storage(a).#m().to_storage() }
                    });
                }
            }
            for (k, blades) in self.grades_of(t) {
                if let Some(target) = self.target_for(&blades) {
                    let (m, os, terms) = (format_ident!("grade{k}"), self.target_name(target), blades.len());
                    let ob = self.target_index(target);
                    unaries.push(quote! {
                        UnaryEntry { kind: UnaryKind::Grade(#k), input: #ts, output: #os, terms: #terms,
                            input_blades: #ib, output_blades: #ob,
                            eval: |a| #ty::<T>::from_storage(a).#m().to_storage() }
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
            #[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
                /// `A ∨ B`
                Regressive,
                /// `V X Ṽ`, grades of `X` only
                Sandwich,
            }

            /// Which linear map a [`UnaryEntry`] evaluates.
            #[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

    fn aliases(&self) -> TokenStream {
        let mut out = TokenStream::new();
        for alias in &self.spec.aliases {
            let (attrs, name, target) = (&alias.attrs, &alias.name, &alias.target);
            out.extend(quote! {
                #(#attrs)*
                pub type #name<T = f64> = #target<T>;
            });
        }
        out
    }
}

fn subscript(k: usize) -> char {
    char::from_u32(0x2080 + k as u32).unwrap_or('?')
}
