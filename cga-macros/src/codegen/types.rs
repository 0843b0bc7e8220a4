//! Per type: the struct, its constructors and conversions, reverse, involute, conjugate,
//! dual, grade projections, norms, arithmetic; embeddings between types; aliases; the
//! product traits.

use super::*;

impl Gen<'_> {
    pub(super) fn traits(&self) -> TokenStream {
        let mut out = TokenStream::new();
        let scalars = "to multiply by a scalar `s`, write `x * s` or `x.scale(s)`";
        for kind in Product::ALL {
            let n = names(kind);
            let (tr, m) = (format_ident!("{}", n.trait_name), format_ident!("{}", n.method));
            let doc = format!(
                " The product `{}`, generated for every pair of types whose Cayley table is not identically zero.",
                n.formula
            );
            let message = format!("`{{Self}}` has no product `{}` with `{{Rhs}}`", n.formula);
            let note = format!(
                "`{}` is generated for every ordered pair of declared types whose table for it is not identically \
                 zero: if both are declared types, the product of `{{Self}}` and `{{Rhs}}` is identically zero in \
                 this algebra, or (with no `dense` type declared) no declared type holds its result: the `# Products` \
                 table on `{{Self}}`'s page then names the grades a type must hold",
                n.trait_name
            );
            out.extend(quote! {
                #[doc = #doc]
                #[diagnostic::on_unimplemented(message = #message, note = #note, note = #scalars)]
                pub trait #tr<Rhs> {
                    /// The smallest declared type that holds every nonzero blade of the result.
                    type Output;
                    #[doc = #doc]
                    fn #m(self, rhs: Rhs) -> Self::Output;
                }
            });
        }
        out.extend(quote! {
            /// Every type's blades and coefficients through one trait, for code generic over
            /// the algebra's types (a display, a table of columns): `X::BLADES` and
            /// `X::to_array`. Generated for every type.
            pub trait Blades: Copy {
                /// The scalar of the coefficients.
                type Coefficient;
                /// Blade of every coefficient, in field order (`X::BLADES`).
                const NAMES: &'static [&'static str];
                /// The coefficients in field order (`X::to_array`).
                fn coefficients(self) -> impl Iterator<Item = Self::Coefficient>;
            }
        });
        let versors: Vec<String> =
            self.spec.types.iter().filter(|t| t.model.versor).map(|t| format!("`{}`", t.ident)).collect();
        let versors = match versors.len() {
            0 => "none are declared in this algebra".to_string(),
            _ => format!("here {}", versors.join(", ")),
        };
        let sandwich_note = format!(
            "sandwiches are generated for the types declared with `versor` ({versors}) acting on the declared types; \
             `{{Self}}` is not a versor, or `{{X}}` is not a declared type"
        );
        out.extend(quote! {
            /// The sandwich `V X Ṽ` of a versor `V` and any object `X`. A versor preserves
            /// grades, so only `X`'s grades are computed; the result type is the smallest
            /// declared type holding the nonzero blades of those grades (a translator turns
            /// a rotor into a motor, but keeps a line a line).
            #[diagnostic::on_unimplemented(
                message = "`{Self}` has no sandwich `V X Ṽ` with `{X}`",
                note = #sandwich_note,
                note = "for any other element `A`, write the products out (`A * x * A.reverse()`, say), or use the \
                        algebra's own methods for reflections and inversions"
            )]
            pub trait Sandwich<X> {
                /// The type of `V X Ṽ`.
                type Output;
                /// `V X Ṽ`.
                fn sandwich(self, x: X) -> Self::Output;
            }

            /// A versor's sandwich `V X Ṽ` as the linear map of `X` it is: its matrix (each
            /// nonzero entry a quadratic form in `V`'s coefficients) computed once by `matrix`,
            /// then applied to each operand by `apply_matrix` at one multiplication an entry.
            /// Generated wherever `Sandwich` is; used through `V::prepare` and `V::apply_to`.
            /// The same value as `sandwich` up to rounding (the terms are summed in another
            /// order).
            pub trait Prepare<X>: Sandwich<X> + Sized {
                /// The nonzero entries, row by row.
                type Matrix: Copy;
                /// The matrix of `X ↦ V X Ṽ`.
                fn matrix(self) -> Self::Matrix;
                /// `V X Ṽ` from `V`'s matrix.
                fn apply_matrix(m: &Self::Matrix, x: X) -> Self::Output;
            }

            /// A versor prepared to act on values of `X` (`V::prepare`): `apply` is
            /// `V X Ṽ` at one multiplication per nonzero entry of its matrix.
            pub struct Prepared<V: Prepare<X>, X> {
                matrix: V::Matrix,
                operand: core::marker::PhantomData<fn(X)>,
            }

            impl<V: Prepare<X>, X> Clone for Prepared<V, X> {
                fn clone(&self) -> Self {
                    *self
                }
            }

            impl<V: Prepare<X>, X> Copy for Prepared<V, X> {}

            impl<V: Prepare<X>, X: Copy> Prepared<V, X> {
                /// `V`'s matrix on `X`, computed once.
                pub fn new(v: V) -> Self {
                    Prepared { matrix: v.matrix(), operand: core::marker::PhantomData }
                }
                /// `V X Ṽ`.
                #[inline(always)]
                pub fn apply(&self, x: X) -> V::Output {
                    V::apply_matrix(&self.matrix, x)
                }
                /// `V X Ṽ` for each `X` of `xs`, in order.
                pub fn apply_to(&self, xs: &[X]) -> ::std::vec::Vec<V::Output> {
                    xs.iter().map(|&x| self.apply(x)).collect()
                }
                /// `V X Ṽ` for each `X` of `xs` into `out`, in order (as many as the shorter
                /// holds).
                pub fn apply_into(&self, xs: &[X], out: &mut [V::Output]) {
                    for (o, &x) in out.iter_mut().zip(xs) {
                        *o = self.apply(x);
                    }
                }
            }

            /// The scalar product `⟨A B⟩₀`: the scalar part of the geometric product, computed
            /// alone (one multiplication per scalar term of the Cayley table). Generated for every
            /// pair of types whose geometric product has a scalar part.
            #[diagnostic::on_unimplemented(
                message = "`{Self}` has no scalar product `⟨A B⟩₀` with `{Rhs}`",
                note = "`ScalarProduct` is generated for every ordered pair of declared types whose geometric product \
                        has a scalar part: if both are declared types, `⟨A B⟩₀` of `{Self}` and `{Rhs}` is identically \
                        zero in this algebra",
                note = #scalars
            )]
            pub trait ScalarProduct<Rhs> {
                /// The scalar type.
                type Output;
                /// `⟨A B⟩₀`.
                fn scalar_product(self, rhs: Rhs) -> Self::Output;
            }
        });
        out
    }

    /// The `# Products` section of a type's rustdoc: per right-hand type, the result type of
    /// each product (— where it is identically zero and not generated), and of the sandwich
    /// for a versor. The impls themselves are hidden from the docs.
    pub(super) fn products_doc(&self, pos: usize) -> Vec<String> {
        let kinds = [
            (Product::Geometric, "A * B"),
            (Product::Outer, "A ^ B"),
            (Product::Inner, "A \\| B"),
            (Product::Regressive, "A & B"),
            (Product::LeftContraction, "A.lc(B)"),
            (Product::RightContraction, "A.rc(B)"),
            (Product::Commutator, "A.commutator(B)"),
        ];
        let link = |target: Target| match target {
            Target::Scalar => "`T`".to_string(),
            _ => format!("[`{}`]", self.target_name(target)),
        };
        let versor = self.spec.types[pos].model.versor;
        let mut header = String::from("| B |");
        let mut rule = String::from("|---|");
        for (_, op) in kinds {
            header.push_str(&format!(" `{op}` |"));
            rule.push_str("---|");
        }
        header.push_str(" `A.scalar_product(B)` |");
        rule.push_str("---|");
        if versor {
            header.push_str(" `A.sandwich(B)` |");
            rule.push_str("---|");
        }
        let mut lines = vec![
            String::new(),
            "# Products".to_string(),
            String::new(),
            "The type of every product of this type `A` with a declared type `B` (`—`: identically zero in this \
             algebra, so not generated; `none`: no declared type holds the result, so not generated either, \
             the grades a type must hold follow the table); one multiplication per nonzero term of the Cayley \
             table. Their trait impls (`GeometricProduct`, `Mul`, `OuterProduct`, `BitXor`, … `Sandwich`) are \
             hidden from this page."
                .to_string(),
            String::new(),
            header,
            rule,
        ];
        for (r, rt) in self.spec.types.iter().enumerate() {
            let mut row = format!("| [`{}`] |", rt.ident);
            for (kind, _) in kinds {
                let plan = self.plans.iter().find(|p| p.kind == kind && p.lhs == pos && p.rhs == r);
                let none = self.uncovered.iter().any(|u| u.kind == kind && u.lhs == pos && u.rhs == r);
                let cell =
                    plan.map_or_else(|| if none { "none".to_string() } else { "—".to_string() }, |p| link(p.target));
                row.push_str(&format!(" {cell} |"));
            }
            let scalar = self.scalar_plans.iter().any(|p| p.lhs == pos && p.rhs == r);
            row.push_str(if scalar { " `T` |" } else { " — |" });
            if versor {
                let plan = self.sandwich_plans.iter().find(|p| p.versor == pos && p.object == r);
                row.push_str(&format!(" {} |", plan.map_or("—".to_string(), |p| link(p.target))));
            }
            lines.push(row);
        }
        let missing: Vec<&Uncovered> = self.uncovered.iter().filter(|u| u.lhs == pos).collect();
        if !missing.is_empty() {
            lines.push(String::new());
            lines.push("Not generated, for want of a type that holds the result (declare one to get it):".into());
            lines.push(String::new());
            for u in missing {
                lines.push(format!(
                    "- `{}` with [`{}`]: grades {:?}, e.g. `type … = {};`",
                    names(u.kind).formula,
                    self.spec.types[u.rhs].ident,
                    u.grades,
                    u.declaration()
                ));
            }
        }
        let mut with_scalar = self.spec.types[pos].model.blades.clone();
        with_scalar.push(0);
        let name = &self.spec.types[pos].ident;
        lines.push(String::new());
        lines.push(match self.declared_cover(&with_scalar) {
            Some(sum) => format!(
                "With a scalar `s`: `A * s`, `A / s` are [`{name}`]s, `A + s`, `A - s` are [`{}`]s.",
                self.spec.types[sum].ident
            ),
            None => format!(
                "With a scalar `s`: `A * s`, `A / s` are [`{name}`]s; no declared type holds `s` and this type's \
                 blades, so there is no `A + s`."
            ),
        });
        lines.into_iter().map(|l| if l.is_empty() { l } else { format!(" {l}") }).collect()
    }

    pub(super) fn type_items(&self, pos: usize, t: &TypeSpec) -> TokenStream {
        let real = self.real;
        let ident = &t.ident;
        let attrs = &t.attrs;
        let blades = &t.model.blades;
        let n = blades.len();
        let fields: Vec<_> = blades.iter().map(|&b| self.field(b)).collect();
        let blade_names: Vec<String> = blades.iter().map(|&b| self.a.blade_name(b)).collect();
        let field_docs = blades.iter().zip(&blade_names).map(|(&b, name)| {
            let canonical = self.a.canonical_name(b);
            match self.a.spelling_sign(b) {
                _ if b == 0 || *name == canonical => format!(" Coefficient of `{name}`."),
                s if s < 0.0 => format!(" Coefficient of `{name}` = −`{canonical}`."),
                _ => format!(" Coefficient of `{name}` = `{canonical}`."),
            }
        });
        let ranks = blades.iter().map(|&b| self.a.rank()[b]);
        let ranks2 = ranks.clone();
        let dim = self.dim;
        let summary = format!(" {n} coefficients: `{}`.", blade_names.join("`, `"));
        let products_doc = self.products_doc(pos);
        let name = ident.to_string();
        // Blades of a storage array this type lacks: what `try_from_storage` refuses to drop.
        let lacking: Vec<(usize, String)> =
            (0..dim).filter(|b| !blades.contains(b)).map(|b| (self.a.rank()[b], self.a.blade_name(b))).collect();
        let (lacking_index, lacking_name): (Vec<usize>, Vec<String>) = lacking.into_iter().unzip();
        let one = blades.contains(&0).then(|| {
            let fields = blades.iter().map(|&b| {
                let f = self.field(b);
                if b == 0 { quote!(#f: <T as #real>::one()) } else { quote!(#f: <T as #real>::zero()) }
            });
            quote! {
                /// The unit `1`: `s = 1`, every other coefficient zero.
                #[inline]
                pub fn one() -> Self {
                    Self { #(#fields),* }
                }
            }
        });

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
        let (dual_doc, undual_doc) = self.dual_docs();
        let dual = self.linear_map(t, Unary::Dual, "dual", &dual_doc);
        let undual = self.linear_map(t, Unary::Undual, "undual", &undual_doc);
        let grades = self.grade_projections(t);
        let norm = self.norm_squared(t);

        quote! {
            #(#attrs)*
            #[doc = ""]
            #[doc = #summary]
            #( #[doc = #products_doc] )*
            #[derive(Clone, Copy, PartialEq, Default)]
            // `repr(C)`: a value is its coefficients in field order (`[T; N]` in memory), which
            // `cga_core::simd` transposes in place into and out of lanes.
            #[repr(C)]
            pub struct #ident<T = f64> {
                #( #[doc = #field_docs] pub #fields: T, )*
            }

            /// The nonzero coefficients by blade (`Circle { e12o: 0.5, e3oi: -2.0 }`; all of
            /// them when every one is zero). `Display` gives the Euclidean reading.
            impl<T: #real> core::fmt::Debug for #ident<T> {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    let zero = <T as #real>::zero();
                    let all_zero = true #( && self.#fields == zero )*;
                    let mut out = f.debug_struct(stringify!(#ident));
                    #( if all_zero || self.#fields != zero { out.field(stringify!(#fields), &self.#fields); } )*
                    out.finish()
                }
            }

            impl<T: #real> Blades for #ident<T> {
                type Coefficient = T;
                const NAMES: &'static [&'static str] = &Self::BLADES;
                #[inline]
                fn coefficients(self) -> impl Iterator<Item = T> {
                    self.to_array().into_iter()
                }
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

                /// This type's blades taken from a storage-basis array; the other blades are
                /// dropped, whatever their values (`try_from_storage` refuses to drop nonzero ones).
                #[inline]
                pub fn from_storage(c: &[T; #dim]) -> Self {
                    Self { #(#fields: c[#ranks2]),* }
                }

                /// This type's blades taken from a storage-basis array, or a `TruncationError`
                /// naming every other blade whose coefficient is not exactly zero.
                #[inline]
                pub fn try_from_storage(c: &[T; #dim]) -> Result<Self, TruncationError> {
                    let zero = <T as #real>::zero();
                    let mut dropped = ::std::vec::Vec::new();
                    #( if c[#lacking_index] != zero {
                        dropped.push((#lacking_name, <T as #real>::to_f64(c[#lacking_index])));
                    } )*
                    if dropped.is_empty() {
                        Ok(Self::from_storage(c))
                    } else {
                        Err(TruncationError { from: "storage array", to: #name, dropped })
                    }
                }

                #one

                /// The same coefficients in another scalar type, each through `f64`
                /// (`U::from_f64(c.to_f64())`): exact from `f32` to `f64`, rounded the other way;
                /// a dual number's derivative part is dropped (only its value goes through).
                #[inline(always)]
                pub fn cast<U: #real>(self) -> #ident<U> {
                    #ident { #(#fields: <U as #real>::from_f64(<T as #real>::to_f64(self.#fields))),* }
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

                /// `A / √|⟨A Ã⟩₀|`, so that `A Ã = ±1` for blades and versors; a
                /// `NormaliseError` when every coefficient is zero (`Zero`), when a coefficient,
                /// the norm or a coefficient of the result is not finite (`NonFinite`), or when
                /// `⟨A Ã⟩₀ = 0` with finite nonzero coefficients (`Null`: a conformal point, or a
                /// squared norm that underflows). Never a non-finite `Ok`.
                #[inline]
                pub fn normalise(self) -> Result<Self, NormaliseError> {
                    let zero = <T as #real>::zero();
                    match self.try_normalise() {
                        Some(unit) => Ok(unit),
                        None if true #( && self.#fields == zero )* => Err(NormaliseError::Zero { type_name: #name }),
                        None if !(true #( && self.#fields.is_finite() )*) => {
                            Err(NormaliseError::NonFinite { type_name: #name })
                        }
                        None if self.norm_squared() == zero => Err(NormaliseError::Null { type_name: #name }),
                        None => Err(NormaliseError::NonFinite { type_name: #name }),
                    }
                }

                /// `A / √|⟨A Ã⟩₀|`, or `None` when `⟨A Ã⟩₀` is zero or not finite, or a
                /// coefficient of the result is not finite (`normalise` says which).
                #[inline]
                pub fn try_normalise(self) -> Option<Self> {
                    let n2 = self.norm_squared();
                    let inv = <T as #real>::one() / n2.abs().sqrt();
                    if n2 == <T as #real>::zero() || !n2.is_finite() || !inv.is_finite() {
                        return None;
                    }
                    let unit = self.scale(inv);
                    (true #( && unit.#fields.is_finite() )*).then_some(unit)
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

            /// `A s`: every coefficient times `s` (`scale`).
            impl<T: #real> core::ops::Mul<T> for #ident<T> {
                type Output = Self;
                /// Scale by a scalar.
                #[inline]
                fn mul(self, s: T) -> Self {
                    self.scale(s)
                }
            }

            /// `A *= s`: every coefficient times `s`.
            impl<T: #real> core::ops::MulAssign<T> for #ident<T> {
                #[inline]
                fn mul_assign(&mut self, s: T) {
                    *self = self.scale(s);
                }
            }

            /// `A / s`: every coefficient divided by `s` (one rounding each, not a
            /// multiplication by `1/s`); non-finite for `s = 0`.
            impl<T: #real> core::ops::Div<T> for #ident<T> {
                type Output = Self;
                /// Divide by a scalar.
                #[inline]
                fn div(self, s: T) -> Self {
                    Self { #(#fields: self.#fields / s),* }
                }
            }

            /// `A /= s`: every coefficient divided by `s`.
            impl<T: #real> core::ops::DivAssign<T> for #ident<T> {
                #[inline]
                fn div_assign(&mut self, s: T) {
                    *self = *self / s;
                }
            }
        }
    }

    /// A linear map (dual, undual) of one type into the type that covers its image.
    pub(super) fn linear_map(&self, t: &TypeSpec, kind: Unary, method: &str, doc: &str) -> TokenStream {
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
    pub(super) fn unary_exprs(
        &self,
        t: &TypeSpec,
        kind: Unary,
    ) -> Option<(Target, BTreeMap<usize, TokenStream>, usize)> {
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
    pub(super) fn grade_projections(&self, t: &TypeSpec) -> TokenStream {
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
    pub(super) fn grades_of(&self, t: &TypeSpec) -> Vec<(usize, Vec<usize>)> {
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
    pub(super) fn norm_terms(&self, t: &TypeSpec) -> Vec<(f64, usize, usize)> {
        self.quadratic_terms(t, &|b| Mv::from([(b, 1.0)]))
    }

    /// `⟨f(A) f(A)~⟩₀` for a linear map `f` given blade by blade, as terms `c · a_i a_j`
    /// over the type's coefficients (`i ≤ j`, symmetric terms merged, cancelled ones gone).
    fn quadratic_terms(&self, t: &TypeSpec, f: &dyn Fn(usize) -> Mv) -> Vec<(f64, usize, usize)> {
        let blades = &t.model.blades;
        let mut merged: BTreeMap<(usize, usize), f64> = BTreeMap::new();
        for (i, &x) in blades.iter().enumerate() {
            for (j, &y) in blades.iter().enumerate() {
                for (&fx, &cx) in &f(x) {
                    for (&fy, &cy) in &f(y) {
                        let rev = self.a.unary(Unary::Reverse, fy).get(&fy).copied().unwrap_or(1.0);
                        if let Some(c) = self.a.product(Product::Geometric, fx, fy).get(&0) {
                            *merged.entry((i.min(j), i.max(j))).or_insert(0.0) += cx * cy * c * rev;
                        }
                    }
                }
            }
        }
        merged.into_iter().filter(|(_, c)| c.abs() > 1e-9).map(|((i, j), c)| (c, i, j)).collect()
    }

    pub(super) fn norm_squared(&self, t: &TypeSpec) -> TokenStream {
        let terms = self.norm_terms(t);
        let body = self.quadratic(t, &terms);
        let doc = format!(
            " The squared norm `⟨A Ã⟩₀`: {} multiplications (symmetric terms merged). Zero for null elements such as points; its sign depends on the object.",
            terms.len()
        );
        let weight = if self.a.degenerate() { self.weight_norm(t) } else { TokenStream::new() };
        let magnitude = self.magnitude(t);
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn norm_squared(self) -> T {
                #body
            }

            #weight
            #magnitude
        }
    }

    /// `Σ c_I²` over the orthonormal-basis coefficients: positive definite in every signature,
    /// where `⟨A Ã⟩₀` is not (a quaternion of G(0,2) has `⟨q q̃⟩₀ = a² − b² − c² + d²`).
    fn magnitude(&self, t: &TypeSpec) -> TokenStream {
        let blades = &t.model.blades;
        let mut merged: BTreeMap<(usize, usize), f64> = BTreeMap::new();
        for (i, &x) in blades.iter().enumerate() {
            for (j, &y) in blades.iter().enumerate().skip(i) {
                let (ox, oy) = (self.a.storage_to_ortho(x), self.a.storage_to_ortho(y));
                let dot: f64 = ox.iter().filter_map(|(b, cx)| oy.get(b).map(|cy| cx * cy)).sum();
                if dot.abs() > 1e-9 {
                    merged.insert((i, j), if i == j { dot } else { 2.0 * dot });
                }
            }
        }
        let terms: Vec<(f64, usize, usize)> = merged.into_iter().map(|((i, j), c)| (c, i, j)).collect();
        let body = self.quadratic(t, &terms);
        let doc = format!(
            " `Σ c_I²` over the coefficients in the orthonormal basis `e1..en` (the storage basis carried there): \
             positive for every nonzero value in every signature, unlike `norm_squared` (for a quaternion \
             `a + b e1 + c e2 + d e12` of G(0,2), `a² + b² + c² + d²`); {} multiplications.",
            terms.len()
        );
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn magnitude_squared(self) -> T {
                #body
            }

            /// `√(Σ c_I²)`, the square root of [`magnitude_squared`](Self::magnitude_squared).
            #[inline]
            pub fn magnitude(self) -> T {
                self.magnitude_squared().sqrt()
            }
        }
    }

    /// In a degenerate metric: the bulk norm `‖A‖ = √|⟨A Ã⟩₀|` (the blades without a null
    /// vector) and the weight norm `‖∁A‖` (those with one), each squared too.
    fn weight_norm(&self, t: &TypeSpec) -> TokenStream {
        let terms = self.quadratic_terms(t, &|b| self.a.unary(Unary::Dual, b));
        let body = self.quadratic(t, &terms);
        let doc = format!(
            " The squared weight norm `⟨∁A (∁A)~⟩₀` (`∁` the dual, a complement): the part of `A` on blades that hold a null vector, which `norm_squared` (the bulk) does not see; {} multiplications.",
            terms.len()
        );
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn weight_norm_squared(self) -> T {
                #body
            }

            /// The weight norm `√|⟨∁A (∁A)~⟩₀|` (for a plane `a e1 + b e2 + c e3 + d e0` of
            /// 3D PGA, `|d|`).
            #[inline]
            pub fn weight_norm(self) -> T {
                self.weight_norm_squared().abs().sqrt()
            }

            /// The bulk norm `√|⟨A Ã⟩₀|`, `norm` by its degenerate-metric name (for a plane
            /// `a e1 + b e2 + c e3 + d e0` of 3D PGA, `√(a² + b² + c²)`).
            #[inline]
            pub fn bulk_norm(self) -> T {
                self.norm()
            }
        }
    }

    /// The sum `Σ c a_i a_j` of quadratic terms over the type's coefficients.
    fn quadratic(&self, t: &TypeSpec, terms: &[(f64, usize, usize)]) -> TokenStream {
        let real = self.real;
        let blades = &t.model.blades;
        if terms.is_empty() {
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
        }
    }

    /// `From<Sub> for Super` whenever one type's blades are a subset of another's.
    pub(super) fn embeddings(&self) -> TokenStream {
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

    /// A type of the scalar alone is its number: `Deref` to `T` (`*(a | b)`, and the number's
    /// methods reach through), `sqrt` and `abs`, and `From` into each of `scalars`.
    pub(super) fn scalar_number(&self, t: &TypeSpec) -> TokenStream {
        if t.model.blades != [0] {
            return TokenStream::new();
        }
        let (real, ident) = (self.real, &t.ident);
        let froms = self.spec.scalars.iter().map(|s| {
            quote! {
                impl From<#ident<#s>> for #s {
                    /// The scalar's number.
                    fn from(x: #ident<#s>) -> #s {
                        x.s
                    }
                }
            }
        });
        quote! {
            /// A scalar-valued product (`a | b`, `x * x`) is its number: `*(a | b)` is the
            /// `T`, and the number's own methods reach through.
            impl<T: #real> core::ops::Deref for #ident<T> {
                type Target = T;
                fn deref(&self) -> &T {
                    &self.s
                }
            }

            impl<T: #real> #ident<T> {
                /// `√s`, the square root of the scalar's number.
                pub fn sqrt(self) -> T {
                    <T as #real>::sqrt(self.s)
                }

                /// `|s|`.
                pub fn abs(self) -> T {
                    <T as #real>::abs(self.s)
                }
            }

            #(#froms)*
        }
    }

    pub(super) fn aliases(&self) -> TokenStream {
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
