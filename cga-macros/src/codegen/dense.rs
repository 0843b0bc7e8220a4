//! The dense multivector: every coefficient, every product a loop over its Cayley table.

use super::*;

impl Gen<'_> {
    /// The dense multivector: 2^n coefficients in the orthonormal basis, every product a
    /// loop over a table of the nonzero entries computed here.
    pub(super) fn dense(&self) -> TokenStream {
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
        let dual_t = unary_table(&|m| self.a.ortho_dual(m));
        let (dual_doc, undual_doc) = self.dual_docs();
        let undual_t = unary_table(&|m| self.a.ortho_undual(m));
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
            convert(&|m| self.a.storage_to_ortho(m).iter().map(|(&k, &v)| (k, v)).collect(), self.a.rank(), &pos);
        let from_ortho =
            convert(&|m| self.a.ortho_blade_to_storage(m).iter().map(|(&k, &v)| (k, v)).collect(), &pos, self.a.rank());
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

                #[doc = #dual_doc]
                #[inline]
                pub fn dual(&self) -> Self {
                    self.permuted(&#tables.0)
                }

                #[doc = #undual_doc]
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

                /// The same coefficients in another scalar type, each through `f64`
                /// (`U::from_f64(c.to_f64())`); a dual number's derivative part is dropped.
                #[inline]
                pub fn cast<U: #real>(&self) -> #ident<U> {
                    #ident { coeffs: self.coeffs.map(|c| <U as #real>::from_f64(<T as #real>::to_f64(c))) }
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
}
