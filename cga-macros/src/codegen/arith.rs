//! Arithmetic that reads like the maths: scalars on either side (`x + s`, `s - x`, `s * x`),
//! inverses of the types whose `X X̃` is always a scalar, checked conversions between types
//! (`TryFrom`), and the error types they return.

use super::*;

impl Gen<'_> {
    /// `TruncationError` (a conversion that would drop nonzero blades) and `NormaliseError`
    /// (an element with no unit multiple), once per invocation.
    pub(super) fn error_types(&self) -> TokenStream {
        quote! {
            /// A conversion that would drop blades whose coefficients are not zero: returned by
            /// `TryFrom` between the generated types (where the target lacks some of the
            /// source's blades) and by `try_from_storage`. Displays as
            /// `converting Even to Motor would drop e1o = 0.5, e2o = -1.0`.
            #[derive(Clone, Debug, PartialEq)]
            pub struct TruncationError {
                /// The type converted from (`"storage array"` for `try_from_storage`).
                pub from: &'static str,
                /// The type converted to.
                pub to: &'static str,
                /// Every blade of the source that the target lacks and whose coefficient is not
                /// exactly zero, with that coefficient as `f64` (a dual number's value).
                pub dropped: ::std::vec::Vec<(&'static str, f64)>,
            }

            impl core::fmt::Display for TruncationError {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    write!(f, "converting {} to {} would drop ", self.from, self.to)?;
                    for (i, (blade, c)) in self.dropped.iter().enumerate() {
                        if i > 0 {
                            f.write_str(", ")?;
                        }
                        write!(f, "{blade} = {c:?}")?;
                    }
                    Ok(())
                }
            }

            impl ::std::error::Error for TruncationError {}

            /// Why `normalise` found no unit multiple `A / √|⟨A Ã⟩₀|` of an element.
            #[derive(Clone, Copy, Debug, PartialEq, Eq)]
            pub enum NormaliseError {
                /// Every coefficient is zero.
                Zero {
                    /// The type of the element.
                    type_name: &'static str,
                },
                /// `⟨A Ã⟩₀ = 0` with finite, nonzero coefficients: a null element (a conformal
                /// point, say), or one whose squared norm underflows.
                Null {
                    /// The type of the element.
                    type_name: &'static str,
                },
                /// A coefficient, the squared norm, its inverse square root or a coefficient of
                /// the result is not finite.
                NonFinite {
                    /// The type of the element.
                    type_name: &'static str,
                },
            }

            impl NormaliseError {
                /// The type of the element that could not be normalised.
                pub fn type_name(&self) -> &'static str {
                    match *self {
                        NormaliseError::Zero { type_name }
                        | NormaliseError::Null { type_name }
                        | NormaliseError::NonFinite { type_name } => type_name,
                    }
                }
            }

            impl core::fmt::Display for NormaliseError {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    match self {
                        NormaliseError::Zero { type_name } => {
                            write!(f, "cannot normalise {type_name}: every coefficient is zero")
                        }
                        NormaliseError::Null { type_name } => write!(
                            f,
                            "cannot normalise {type_name}: it is null (⟨A Ã⟩₀ = 0 with nonzero coefficients)"
                        ),
                        NormaliseError::NonFinite { type_name } => {
                            write!(f, "cannot normalise {type_name}: its norm or the result is not finite")
                        }
                    }
                }
            }

            impl ::std::error::Error for NormaliseError {}
        }
    }

    /// Scalars on either side. Generic: `X + s`, `X − s` (into `X` when it holds the scalar
    /// blade, else into the smallest declared type holding it and `X`'s blades, if any), and
    /// `X += s`, `X −= s` when `X` holds it. For every concrete scalar of the `scalars`
    /// option: `s * X`, `s + X`, `s − X` (the orphan rule forbids these generically).
    /// `A + B` and `A − B` of two different declared types, into the smallest declared type
    /// holding the blades of both (none where no type does). Hidden from the docs, as the
    /// products are.
    pub(super) fn mixed_sums(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for (l, lt) in self.spec.types.iter().enumerate() {
            for (r, rt) in self.spec.types.iter().enumerate() {
                let (a, b) = (&lt.model.blades, &rt.model.blades);
                let mut blades = a.clone();
                blades.extend(b.iter().filter(|x| !a.contains(x)));
                let Some(target) = self.declared_cover(&blades).filter(|_| l != r) else { continue };
                let exprs = |negate: bool| -> BTreeMap<usize, TokenStream> {
                    blades
                        .iter()
                        .map(|&x| {
                            let f = self.field(x);
                            let e = match (a.contains(&x), b.contains(&x), negate) {
                                (true, true, false) => quote!(a.#f + b.#f),
                                (true, true, true) => quote!(a.#f - b.#f),
                                (true, false, _) => quote!(a.#f),
                                (false, _, false) => quote!(b.#f),
                                (false, _, true) => quote!(-b.#f),
                            };
                            (x, e)
                        })
                        .collect()
                };
                let (add, sub) = (
                    self.construct(Target::Type(target), &exprs(false)),
                    self.construct(Target::Type(target), &exprs(true)),
                );
                let (li, ri, out_ty) = (&lt.ident, &rt.ident, self.target_ty(Target::Type(target)));
                out.extend(quote! {
                    #[doc(hidden)]
                    impl<T: #real> core::ops::Add<#ri<T>> for #li<T> {
                        type Output = #out_ty;
                        #[inline]
                        fn add(self, b: #ri<T>) -> #out_ty {
                            let a = self;
                            #add
                        }
                    }
                    #[doc(hidden)]
                    impl<T: #real> core::ops::Sub<#ri<T>> for #li<T> {
                        type Output = #out_ty;
                        #[inline]
                        fn sub(self, b: #ri<T>) -> #out_ty {
                            let a = self;
                            #sub
                        }
                    }
                });
            }
        }
        out
    }

    pub(super) fn scalar_ops(&self, t: &TypeSpec) -> TokenStream {
        let real = self.real;
        let ident = &t.ident;
        let mut out = TokenStream::new();
        let mut with_scalar = t.model.blades.clone();
        if !with_scalar.contains(&0) {
            with_scalar.push(0);
        }
        let sum = self.declared_cover(&with_scalar);
        if let Some(target) = sum {
            let s = self.field(0);
            let exprs = |negate: bool| -> BTreeMap<usize, TokenStream> {
                let mut exprs: BTreeMap<usize, TokenStream> = t
                    .model
                    .blades
                    .iter()
                    .map(|&b| {
                        let f = self.field(b);
                        (b, quote!(self.#f))
                    })
                    .collect();
                let add = match (exprs.contains_key(&0), negate) {
                    (true, false) => quote!(self.#s + s),
                    (true, true) => quote!(self.#s - s),
                    (false, false) => quote!(s),
                    (false, true) => quote!(-s),
                };
                exprs.insert(0, add);
                exprs
            };
            let (plus, minus) = (exprs(false), exprs(true));
            let (add_body, sub_body) =
                (self.construct(Target::Type(target), &plus), self.construct(Target::Type(target), &minus));
            let out_ty = self.target_ty(Target::Type(target));
            let out_name = self.target_name(Target::Type(target));
            let doc_add = format!(" `A + s`: the scalar coefficient `s` plus `s`, as a `{out_name}`.");
            let doc_sub = format!(" `A − s`: the scalar coefficient `s` minus `s`, as a `{out_name}`.");
            out.extend(quote! {
                #[doc = #doc_add]
                impl<T: #real> core::ops::Add<T> for #ident<T> {
                    type Output = #out_ty;
                    #[inline]
                    fn add(self, s: T) -> #out_ty {
                        #add_body
                    }
                }

                #[doc = #doc_sub]
                impl<T: #real> core::ops::Sub<T> for #ident<T> {
                    type Output = #out_ty;
                    #[inline]
                    fn sub(self, s: T) -> #out_ty {
                        #sub_body
                    }
                }
            });
            if t.model.blades.contains(&0) {
                out.extend(quote! {
                    /// `A += s`: the scalar coefficient plus `s`.
                    impl<T: #real> core::ops::AddAssign<T> for #ident<T> {
                        #[inline]
                        fn add_assign(&mut self, s: T) {
                            self.#s = self.#s + s;
                        }
                    }

                    /// `A −= s`: the scalar coefficient minus `s`.
                    impl<T: #real> core::ops::SubAssign<T> for #ident<T> {
                        #[inline]
                        fn sub_assign(&mut self, s: T) {
                            self.#s = self.#s - s;
                        }
                    }
                });
            }
        }
        for scalar in &self.spec.scalars {
            out.extend(quote! {
                /// `s A`: every coefficient times `s`, the same as `A * s` (scalars commute).
                impl core::ops::Mul<#ident<#scalar>> for #scalar {
                    type Output = #ident<#scalar>;
                    #[inline]
                    fn mul(self, x: #ident<#scalar>) -> #ident<#scalar> {
                        x.scale(self)
                    }
                }
            });
            let Some(target) = sum else { continue };
            let out_ident = &self.spec.types[target].ident;
            let out_name = out_ident.to_string();
            let doc_add = format!(" `s + A`, the same as `A + s`, as a `{out_name}`.");
            let doc_sub = format!(" `s − A`: `−A` with `s` added to its scalar coefficient, as a `{out_name}`.");
            out.extend(quote! {
                #[doc = #doc_add]
                impl core::ops::Add<#ident<#scalar>> for #scalar {
                    type Output = #out_ident<#scalar>;
                    #[inline]
                    fn add(self, x: #ident<#scalar>) -> #out_ident<#scalar> {
                        x + self
                    }
                }

                #[doc = #doc_sub]
                impl core::ops::Sub<#ident<#scalar>> for #scalar {
                    type Output = #out_ident<#scalar>;
                    #[inline]
                    fn sub(self, x: #ident<#scalar>) -> #out_ident<#scalar> {
                        -x + self
                    }
                }
            });
        }
        out
    }

    /// `try_inverse` and `inverse` for a type whose `X X̃` is a scalar for every value of its
    /// coefficients (decided here, from the Cayley table): `X⁻¹ = X̃ / ⟨X X̃⟩₀`.
    pub(super) fn inverse(&self, pos: usize, t: &TypeSpec) -> TokenStream {
        if !self.invertible[pos] {
            return TokenStream::new();
        }
        let real = self.real;
        let ident = &t.ident;
        let fields: Vec<_> = t.model.blades.iter().map(|&b| self.field(b)).collect();
        quote! {
            impl<T: #real> #ident<T> {
                /// The inverse `A⁻¹ = Ã / ⟨A Ã⟩₀` (for this type `A Ã` is a scalar whatever the
                /// coefficients, so `A A⁻¹ = A⁻¹ A = 1`), or `None` when `⟨A Ã⟩₀` is zero (a null
                /// or zero element) or not finite, or a coefficient of the result is not finite.
                #[inline]
                pub fn try_inverse(self) -> Option<Self> {
                    let n2 = self.norm_squared();
                    if n2 == <T as #real>::zero() || !n2.is_finite() {
                        return None;
                    }
                    let inv = self.reverse() / n2;
                    (true #( && inv.#fields.is_finite() )*).then_some(inv)
                }

                /// The inverse `A⁻¹ = Ã / ⟨A Ã⟩₀`, unchecked: its coefficients are not finite
                /// when `A` is not invertible (`⟨A Ã⟩₀ = 0`). Prefer `try_inverse`.
                #[inline]
                pub fn inverse(self) -> Self {
                    self.reverse() / self.norm_squared()
                }
            }
        }
    }

    /// `TryFrom<A> for B` for every ordered pair of distinct types where `A`'s blades are not
    /// all `B`'s but some are: `Ok` when every coefficient of `A` on a blade `B` lacks is
    /// exactly zero, else a `TruncationError` naming them. And from the dense type into every
    /// type.
    pub(super) fn truncations(&self) -> TokenStream {
        let real = self.real;
        let mut out = TokenStream::new();
        for a in &self.spec.types {
            for (pos, b) in self.spec.types.iter().enumerate() {
                let (ab, bb) = (&a.model.blades, &b.model.blades);
                let subset = ab.iter().all(|x| bb.contains(x));
                let shared = ab.iter().any(|x| bb.contains(x));
                if a.ident == b.ident || subset || !shared {
                    continue;
                }
                let lost: Vec<_> = ab.iter().filter(|x| !bb.contains(x)).map(|&x| self.field(x)).collect();
                let lost_names: Vec<String> = lost.iter().map(|f| f.to_string()).collect();
                let exprs = ab
                    .iter()
                    .filter(|x| bb.contains(x))
                    .map(|&x| {
                        let f = self.field(x);
                        (x, quote!(x.#f))
                    })
                    .collect();
                let body = self.construct(Target::Type(pos), &exprs);
                let (ai, bi) = (&a.ident, &b.ident);
                let (an, bn) = (ai.to_string(), bi.to_string());
                let doc = format!(
                    " A `{an}` as a `{bn}` when its coefficients on `{}` are exactly zero, else a `TruncationError` naming those that are not.",
                    lost_names.join("`, `")
                );
                out.extend(quote! {
                    #[doc = #doc]
                    impl<T: #real> TryFrom<#ai<T>> for #bi<T> {
                        type Error = TruncationError;
                        #[inline]
                        fn try_from(x: #ai<T>) -> Result<Self, TruncationError> {
                            let zero = <T as #real>::zero();
                            let mut dropped = ::std::vec::Vec::new();
                            #( if x.#lost != zero {
                                dropped.push((#lost_names, <T as #real>::to_f64(x.#lost)));
                            } )*
                            if dropped.is_empty() {
                                Ok(#body)
                            } else {
                                Err(TruncationError { from: #an, to: #bn, dropped })
                            }
                        }
                    }
                });
            }
        }
        if let Some(dense) = &self.spec.dense {
            let d = &dense.name;
            let dn = d.to_string();
            for t in &self.spec.types {
                let ti = &t.ident;
                let doc = format!(
                    " The `{ti}` blades of a dense multivector when its other storage-basis coefficients are exactly zero, else a `TruncationError` naming those that are not."
                );
                out.extend(quote! {
                    #[doc = #doc]
                    impl<T: #real> TryFrom<#d<T>> for #ti<T> {
                        type Error = TruncationError;
                        #[inline]
                        fn try_from(m: #d<T>) -> Result<Self, TruncationError> {
                            Self::try_from_storage(&m.to_storage()).map_err(|e| TruncationError { from: #dn, ..e })
                        }
                    }
                });
            }
        }
        out
    }
}
