//! The functions of one element: `exp` of a simple bivector, `log` of a unit rotor (each
//! per metric: Euclidean, hyperbolic, null) and the inverse `X̃ / ⟨X X̃⟩₀` of any element
//! whose `X X̃` is a scalar. The conditions that decide them (`B²` a scalar, `X X̃` a scalar)
//! are polynomials in the coefficients, computed here at expansion time: a type where they
//! hold for every value skips the run-time check.

use super::*;
use crate::model::Quadratic;

/// The relative size, in units of the scalar's epsilon, under which a polynomial that
/// vanishes in exact arithmetic (the grade-4 part of `B²` for a simple `B`, the non-scalar
/// part of `X X̃` for a blade) is taken as rounding: a few roundings per monomial.
const ROUNDING: f64 = 64.0;

impl Gen<'_> {
    /// The traits `Exp`, `Log`, `Inverse` and their errors.
    pub(super) fn function_traits(&self) -> TokenStream {
        quote! {
            /// `exp(B)` of a bivector, by the metric of `B² = β` (a scalar for a simple
            /// bivector): `cos √−β + B sin √−β / √−β` for β < 0 (a rotation), `cosh √β + B
            /// sinh √β / √β` for β > 0 (a boost), `1 + B` for β = 0 (a translation). Generated
            /// for every type of bivectors whose `1 + B` a declared type holds. `Output` is that
            /// type where every value of the bivector type is simple (decided from the Cayley
            /// table), else `Result` with an [`ExpError`].
            pub trait Exp {
                /// The rotor type, or a `Result` of it.
                type Output;
                /// `exp(self)`.
                fn exp(self) -> Self::Output;
            }

            /// The principal logarithm of a unit rotor `R = s + B` (`B` a simple bivector):
            /// `B θ/|B|` with `θ = atan2(|B|, s)` when `B² < 0`, `B φ/|B|` with `φ = asinh |B|`
            /// when `B² > 0`, `B / s` when `B² = 0`; `exp(log R) = R`. A rotor within `√ε` of
            /// unit (`R R̃ = 1`) is normalised first. Generated for every type of a scalar and
            /// bivectors whose bivector part a declared type holds.
            pub trait Log {
                /// The bivector type.
                type Output;
                /// `log(self)`, or why there is none.
                fn log(self) -> Result<Self::Output, LogError>;
            }

            /// The inverse `X⁻¹ = X̃ / ⟨X X̃⟩₀` where `X X̃` is a scalar: for every value of the
            /// types that have inherent `try_inverse`, and checked at run time for the others
            /// (blades and versors in a type that also holds other elements).
            pub trait Inverse: Sized {
                /// `X⁻¹`, or `None` when `X X̃` is not a nonzero scalar (to rounding) or the
                /// result is not finite.
                fn try_inverse(self) -> Option<Self>;
                /// `X̃ / ⟨X X̃⟩₀` unchecked: not the inverse unless `X X̃` is a nonzero scalar.
                fn inverse(self) -> Self;
            }

            /// Why `exp` has no value.
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub enum ExpError {
                /// `B²` is not a scalar: `B ∧ B ≠ 0`, a sum of bivectors in two planes.
                NotSimple {
                    /// The bivector's type.
                    type_name: &'static str,
                    /// `Σ |⟨B²⟩ₖ|` over grades k ≠ 0, relative to `Σ c_I²`.
                    wedge: f64,
                },
                /// A coefficient is not finite.
                NonFinite {
                    /// The bivector's type.
                    type_name: &'static str,
                },
            }

            impl core::fmt::Display for ExpError {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    match self {
                        ExpError::NotSimple { type_name, wedge } => write!(
                            f,
                            "exp of {type_name}: not a simple bivector (B ∧ B is {wedge:e} of |B|²); split it into commuting planes"
                        ),
                        ExpError::NonFinite { type_name } => write!(f, "exp of {type_name}: a coefficient is not finite"),
                    }
                }
            }

            impl ::std::error::Error for ExpError {}

            /// Why `log` has no value.
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub enum LogError {
                /// The bivector part `B` has `B² ` not a scalar.
                NotSimple {
                    /// The rotor's type.
                    type_name: &'static str,
                    /// `Σ |⟨B²⟩ₖ|` over grades k ≠ 0, relative to `Σ c_I²`.
                    wedge: f64,
                },
                /// `R R̃ − 1` is larger than `√ε`: not a unit rotor.
                NotUnit {
                    /// The rotor's type.
                    type_name: &'static str,
                    /// `R R̃ − 1`.
                    defect: f64,
                },
                /// No bivector's exponential is `R`: `R = −1` (a full turn about no one plane),
                /// or `s ≤ 0` with `B² ≥ 0` (`−exp(B)` of a boost or translation).
                NoLogarithm {
                    /// The rotor's type.
                    type_name: &'static str,
                },
                /// A coefficient is not finite.
                NonFinite {
                    /// The rotor's type.
                    type_name: &'static str,
                },
            }

            impl core::fmt::Display for LogError {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    match self {
                        LogError::NotSimple { type_name, wedge } => write!(
                            f,
                            "log of {type_name}: its bivector part is not simple (B ∧ B is {wedge:e} of |R|²)"
                        ),
                        LogError::NotUnit { type_name, defect } => {
                            write!(f, "log of {type_name}: not a unit rotor (R R̃ − 1 = {defect:e})")
                        }
                        LogError::NoLogarithm { type_name } => write!(
                            f,
                            "log of {type_name}: no bivector has this exponential (−1, or −exp(B) of a boost or translation)"
                        ),
                        LogError::NonFinite { type_name } => write!(f, "log of {type_name}: a coefficient is not finite"),
                    }
                }
            }

            impl ::std::error::Error for LogError {}
        }
    }

    /// `Σ c · x.f_i x.f_j` of one polynomial of a quadratic form over `fields`.
    fn polynomial(&self, fields: &[syn::Ident], poly: Option<&BTreeMap<(usize, usize), f64>>) -> TokenStream {
        let values: Vec<TokenStream> = fields.iter().map(|f| quote!(x.#f)).collect();
        self.polynomial_of(&values, poly)
    }

    /// `Σ c · v_i v_j` of one polynomial of a quadratic form over the expressions `values`.
    fn polynomial_of(&self, values: &[TokenStream], poly: Option<&BTreeMap<(usize, usize), f64>>) -> TokenStream {
        let real = self.real;
        match poly {
            Some(poly) if !poly.is_empty() => self.sum(poly.iter().map(|(&(i, j), &c)| {
                let (a, b) = (&values[i], &values[j]);
                (c, quote!(#a * #b))
            })),
            _ => quote!(<T as #real>::zero()),
        }
    }

    /// `Σ |p|` over the non-scalar polynomials of a quadratic form: zero in exact arithmetic
    /// exactly when the form is a scalar.
    fn off_scalar(&self, fields: &[syn::Ident], square: &Quadratic) -> TokenStream {
        let real = self.real;
        let parts = square.iter().filter(|(b, _)| **b != 0).map(|(_, poly)| {
            let p = self.polynomial(fields, Some(poly));
            quote!(<T as #real>::abs(#p))
        });
        quote!(<T as #real>::zero() #(+ #parts)*)
    }

    /// The run-time test that the off-scalar part is rounding: `Σ |p| ≤ 64 ε Σ c_I²`, binding
    /// `wedge` (relative, as `f64`) and returning `#fail` otherwise.
    fn rounding_check(&self, fields: &[syn::Ident], square: &Quadratic, fail: TokenStream) -> TokenStream {
        let real = self.real;
        let off = self.off_scalar(fields, square);
        quote! {
            let size = x.magnitude_squared();
            let off = #off;
            let bound = <T as #real>::from_f64(#ROUNDING) * <T as #real>::epsilon() * size;
            if !(off <= bound) {
                let wedge = <T as #real>::to_f64(off) / <T as #real>::to_f64(size);
                return #fail;
            }
        }
    }

    /// `Exp` for a type of bivectors, into the smallest declared type holding `1 + B`.
    pub(super) fn exp(&self, t: &TypeSpec) -> TokenStream {
        let blades = &t.model.blades;
        let mut with_one = vec![0];
        with_one.extend(blades);
        let Some(target) = self.declared_cover(&with_one).filter(|_| blades.iter().all(|b| b.count_ones() == 2)) else {
            return TokenStream::new();
        };
        let real = self.real;
        let fields: Vec<_> = blades.iter().map(|&b| self.field(b)).collect();
        let square = self.a.square(blades, false);
        let beta = self.polynomial(&fields, square.get(&0));
        let simple = square.keys().all(|&b| b == 0);
        let (ident, name) = (&t.ident, t.ident.to_string());
        let mut exprs: BTreeMap<usize, TokenStream> =
            blades.iter().zip(&fields).map(|(&b, f)| (b, quote!(k * x.#f))).collect();
        exprs.insert(0, quote!(c));
        let value = self.construct(Target::Type(target), &exprs);
        let out_ty = self.target_ty(Target::Type(target));
        let (ty, check, ret) = if simple {
            (out_ty.clone(), TokenStream::new(), value)
        } else {
            let check =
                self.rounding_check(&fields, &square, quote!(Err(ExpError::NotSimple { type_name: #name, wedge })));
            let finite = quote! {
                if !(true #(&& <T as #real>::is_finite(x.#fields))*) {
                    return Err(ExpError::NonFinite { type_name: #name });
                }
            };
            (quote!(Result<#out_ty, ExpError>), quote!(#finite #check), quote!(Ok(#value)))
        };
        let doc = format!(
            " `exp(B)` into `{}`: `B² = β` decides the metric (see [`Exp`]).{}",
            self.target_name(Target::Type(target)),
            if simple {
                " Every value of this type is simple."
            } else {
                " `B` must be simple: `ExpError::NotSimple` otherwise."
            }
        );
        quote! {
            impl<T: #real> Exp for #ident<T> {
                type Output = #ty;
                #[doc = #doc]
                #[inline]
                fn exp(self) -> #ty {
                    let x = self;
                    let (zero, one) = (<T as #real>::zero(), <T as #real>::one());
                    #check
                    let beta: T = #beta;
                    let (c, k) = if beta < zero {
                        let angle = <T as #real>::sqrt(-beta);
                        (<T as #real>::cos(angle), <T as #real>::sin(angle) / angle)
                    } else if beta > zero {
                        let rapidity = <T as #real>::sqrt(beta);
                        (<T as #real>::cosh(rapidity), <T as #real>::sinh(rapidity) / rapidity)
                    } else {
                        (one, one)
                    };
                    #ret
                }
            }
        }
    }

    /// `Log` for a type of a scalar and bivectors, into the smallest declared type holding
    /// its bivectors.
    pub(super) fn log(&self, t: &TypeSpec) -> TokenStream {
        let blades = &t.model.blades;
        let bivectors: Vec<usize> = blades.iter().copied().filter(|&b| b != 0).collect();
        let shape = blades.contains(&0) && !bivectors.is_empty() && bivectors.iter().all(|b| b.count_ones() == 2);
        let Some(target) = self.declared_cover(&bivectors).filter(|_| shape) else {
            return TokenStream::new();
        };
        let real = self.real;
        let fields: Vec<_> = bivectors.iter().map(|&b| self.field(b)).collect();
        let all_fields: Vec<_> = blades.iter().map(|&b| self.field(b)).collect();
        let square = self.a.square(&bivectors, false);
        // `B²` of `B / m`, `m` the binade of B's largest coefficient: `|B|` neither underflows
        // nor overflows where its coefficients do not (a half turn `−1 + 1e-300 e12` has one).
        let scaled: Vec<TokenStream> = fields.iter().map(|f| quote!((x.#f * inv_m))).collect();
        let beta_scaled = self.polynomial_of(&scaled, square.get(&0));
        let (ident, name) = (&t.ident, t.ident.to_string());
        let s = self.field(0);
        let check = if square.keys().all(|&b| b == 0) {
            TokenStream::new()
        } else {
            self.rounding_check(&fields, &square, quote!(Err(LogError::NotSimple { type_name: #name, wedge })))
        };
        let exprs: BTreeMap<usize, TokenStream> =
            bivectors.iter().zip(&fields).map(|(&b, f)| (b, quote!(k * x.#f))).collect();
        let value = self.construct(Target::Type(target), &exprs);
        let out_ty = self.target_ty(Target::Type(target));
        let doc = format!(" The logarithm into `{}` (see [`Log`]).", self.target_name(Target::Type(target)));
        quote! {
            impl<T: #real> Log for #ident<T> {
                type Output = #out_ty;
                #[doc = #doc]
                #[inline]
                fn log(self) -> Result<#out_ty, LogError> {
                    let x = self;
                    let (zero, one) = (<T as #real>::zero(), <T as #real>::one());
                    if !(true #(&& <T as #real>::is_finite(x.#all_fields))*) {
                        return Err(LogError::NonFinite { type_name: #name });
                    }
                    #check
                    let m = <T as #real>::binade(zero #(.max(<T as #real>::abs(x.#fields)))*);
                    let inv_m = one / m;
                    let beta_scaled: T = #beta_scaled;
                    // R R̃ = s² − B² for a simple B.
                    let unit = x.#s * x.#s - beta_scaled * m * m;
                    let defect = unit - one;
                    if !(<T as #real>::abs(defect) <= <T as #real>::sqrt(<T as #real>::epsilon())) {
                        return Err(LogError::NotUnit { type_name: #name, defect: <T as #real>::to_f64(defect) });
                    }
                    // The unit rotor R / r: its scalar s and |B| = b.
                    let r = <T as #real>::sqrt(unit);
                    let s = x.#s / r;
                    let b = <T as #real>::sqrt(<T as #real>::abs(beta_scaled)) * m / r;
                    let k = if beta_scaled < zero {
                        <T as #real>::atan2(b, s) / b
                    } else if s <= zero {
                        return Err(LogError::NoLogarithm { type_name: #name });
                    } else if beta_scaled > zero {
                        // asinh b = ln(1 + b + b²/(1 + √(1 + b²))), and √(1 + b²) = s.
                        <T as #real>::ln_1p(b + b * b / (one + s)) / b
                    } else {
                        one / s
                    } / r;
                    Ok(#value)
                }
            }
        }
    }

    /// `Inverse` for every type whose `⟨X X̃⟩₀` is not identically zero: the inherent methods
    /// where `X X̃` is always a scalar, a run-time check of its other blades otherwise.
    pub(super) fn inverse_trait(&self, pos: usize, t: &TypeSpec) -> TokenStream {
        let real = self.real;
        let ident = &t.ident;
        if self.invertible[pos] {
            return quote! {
                impl<T: #real> Inverse for #ident<T> {
                    #[inline]
                    fn try_inverse(self) -> Option<Self> {
                        #ident::<T>::try_inverse(self)
                    }
                    #[inline]
                    fn inverse(self) -> Self {
                        #ident::<T>::inverse(self)
                    }
                }
            };
        }
        let square = self.a.reverse_square(&t.model.blades);
        if !square.contains_key(&0) {
            return TokenStream::new();
        }
        let fields: Vec<_> = t.model.blades.iter().map(|&b| self.field(b)).collect();
        let check = self.rounding_check(
            &fields,
            &square,
            quote!({
                let _ = wedge;
                None
            }),
        );
        quote! {
            impl<T: #real> Inverse for #ident<T> {
                /// `X̃ / ⟨X X̃⟩₀` when `X X̃` is a scalar to rounding (`Σ |⟨X X̃⟩ₖ| ≤ 64 ε Σ c_I²`
                /// over k ≠ 0: a blade or a versor), nonzero and finite.
                #[inline]
                fn try_inverse(self) -> Option<Self> {
                    let x = self;
                    #check
                    let n2 = x.norm_squared();
                    if n2 == <T as #real>::zero() || !<T as #real>::is_finite(n2) {
                        return None;
                    }
                    let inv = x.reverse() / n2;
                    (true #( && <T as #real>::is_finite(inv.#fields) )*).then_some(inv)
                }
                #[inline]
                fn inverse(self) -> Self {
                    self.reverse() / self.norm_squared()
                }
            }
        }
    }
}
