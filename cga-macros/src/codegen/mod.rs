//! Tables → Rust. Every generated function is straight-line code over named fields: one
//! expression per nonzero output blade, one multiplication per nonzero table term.

use crate::model::{Algebra, Bilinear, Mv, Product, Term, Unary};
use crate::{Spec, TypeSpec};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeMap;

mod approx;
mod arith;
mod contract;
mod dense;
mod functions;
mod lanes;
mod mixed;
mod prelude;
mod prepared;
mod products;
mod registry;
mod types;

pub fn generate(spec: &Spec) -> TokenStream {
    let g = Gen::new(spec);
    let mixed = g.mixed_types();
    if mixed.is_empty() {
        return emit(&g);
    }
    let mut extended = spec.clone();
    extended.types.extend(mixed);
    emit(&Gen::new(&extended))
}

/// Every item of an algebra whose types are final.
fn emit(g: &Gen) -> TokenStream {
    let spec = g.spec;
    let mut out = g.traits();
    out.extend(g.error_types());
    out.extend(g.function_traits());
    let mut functions = TokenStream::new();
    for (pos, t) in spec.types.iter().enumerate() {
        out.extend(g.type_items(pos, t));
        out.extend(g.scalar_ops(t));
        out.extend(g.scalar_number(t));
        out.extend(g.inverse(pos, t));
        out.extend(g.inverse_trait(pos, t));
        functions.extend(g.exp(t));
        functions.extend(g.log(t));
    }
    out.extend(g.scalar_contract(!functions.is_empty()));
    out.extend(functions);
    out.extend(g.embeddings());
    out.extend(g.mixed_sums());
    out.extend(g.truncations());
    out.extend(g.products());
    out.extend(g.scalar_products());
    out.extend(g.sandwiches());
    out.extend(g.prepared());
    out.extend(g.run_into_trait());
    out.extend(g.dense());
    out.extend(g.registry());
    out.extend(g.aliases());
    out.extend(approx::approx(spec));
    out.extend(lanes::lanes(spec));
    out.extend(g.prelude());
    out
}

/// Where a map's result goes: a declared type; the scalar type `T` itself for a scalar no
/// declared type holds; or the dense type when none covers it.
#[derive(Clone, Copy)]
enum Target {
    Type(usize),
    Scalar,
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

/// The scalar part `⟨A B⟩₀` of the geometric product of two types: its terms.
struct ScalarPlan {
    lhs: usize,
    rhs: usize,
    terms: Vec<Term>,
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
        Product::RightContraction => ("RightContraction", "rc", None, "A ⌊ B", "RightContraction"),
        Product::Regressive => ("RegressiveProduct", "vee", Some(("BitAnd", "bitand")), "A ∨ B", "Regressive"),
        Product::Commutator => ("CommutatorProduct", "commutator", None, "A × B = ½(A B − B A)", "Commutator"),
    };
    ProductNames { trait_name, method, operator, formula, kind_variant }
}

/// A nonzero product of two types that no declared type holds: not generated; the docs name
/// the grades a type must hold to get it.
struct Uncovered {
    kind: Product,
    lhs: usize,
    rhs: usize,
    /// The grades of its nonzero blades, increasing.
    grades: Vec<u32>,
}

impl Uncovered {
    /// `[grade(1), grade(3)]`: the blades a type must hold for this product.
    fn declaration(&self) -> String {
        let grades: Vec<String> = self.grades.iter().map(|g| format!("grade({g})")).collect();
        format!("[{}]", grades.join(", "))
    }
}

/// The two stages of a versor's sandwich on a type (see `Gen::sandwich_plan`).
struct SandwichPlan {
    versor: usize,
    object: usize,
    stage1: Bilinear,
    stage2: Bilinear,
    target: Target,
}

struct Gen<'a> {
    spec: &'a Spec,
    a: &'a Algebra,
    real: &'a syn::Path,
    dim: usize,
    /// Every nonzero product of an ordered pair of types, planned once (the products and
    /// the registry both read it).
    plans: Vec<Planned>,
    /// Every sandwich of a versor on a type, planned once.
    sandwich_plans: Vec<SandwichPlan>,
    /// Every nonzero scalar part of a geometric product of two types.
    scalar_plans: Vec<ScalarPlan>,
    /// Every nonzero product whose result no declared type holds (with no dense type).
    uncovered: Vec<Uncovered>,
    /// Per type: whether `X X̃` is identically a (not identically zero) scalar.
    invertible: Vec<bool>,
}

impl<'a> Gen<'a> {
    fn new(spec: &'a Spec) -> Self {
        let a = &spec.algebra;
        let invertible = spec.types.iter().map(|t| a.has_reverse_inverse(&t.model.blades)).collect();
        let mut g = Gen {
            spec,
            a,
            real: &spec.scalar,
            dim: a.dim(),
            plans: vec![],
            sandwich_plans: vec![],
            scalar_plans: vec![],
            uncovered: vec![],
            invertible,
        };
        (g.plans, g.scalar_plans, g.uncovered) = g.product_plan();
        g.sandwich_plans = g.all_sandwich_plans();
        g
    }

    /// The docs of `dual` and `undual`: multiplication by `I⁻¹` and `I`, or in a degenerate
    /// metric (`I² = 0`) the right complement and its inverse.
    pub(super) fn dual_docs(&self) -> (String, String) {
        if self.a.degenerate() {
            (
                " The dual: the right complement `∁A`, `e_S ∧ ∁e_S = I` blade by blade (the metric is \
                 degenerate, `I² = 0`: no `I⁻¹`)."
                    .into(),
                " The undual: the left complement, inverse of `dual`.".into(),
            )
        } else {
            (" The dual `A I⁻¹` (I the unit pseudoscalar).".into(), " The undual `A I`, inverse of `dual`.".into())
        }
    }

    pub(super) fn field(&self, blade: usize) -> syn::Ident {
        format_ident!("{}", self.a.blade_name(blade))
    }

    /// Where a result holding `blades` goes: the smallest type the user declared; else `T`
    /// for a scalar; else the smallest generated grade-mixed type; else the dense type.
    pub(super) fn target_for(&self, blades: &[usize]) -> Option<Target> {
        match self.cover_among(blades, false) {
            Some(t) => Some(Target::Type(t)),
            None if blades == [0] => Some(Target::Scalar),
            None => match self.cover_among(blades, true) {
                Some(t) => Some(Target::Type(t)),
                None => self.spec.dense.as_ref().map(|_| Target::Dense),
            },
        }
    }

    /// A value of `target` as a storage array, for the registry's function pointers.
    pub(super) fn to_storage(&self, target: Target, value: TokenStream) -> TokenStream {
        let (real, dim) = (self.real, self.dim);
        match target {
            Target::Scalar => quote!({
                let mut out = [<T as #real>::zero(); #dim];
                out[0] = #value;
                out
            }),
            _ => quote!((#value).to_storage()),
        }
    }

    /// The smallest declared type holding `blades` (never the dense type): among the user's
    /// types first, then among the generated ones.
    pub(super) fn declared_cover(&self, blades: &[usize]) -> Option<usize> {
        self.cover_among(blades, false).or_else(|| self.cover_among(blades, true))
    }

    /// The smallest user-declared (or generated) type holding `blades`; ties: the first.
    fn cover_among(&self, blades: &[usize], generated: bool) -> Option<usize> {
        let types = self.spec.types.iter().enumerate().filter(|(_, t)| t.generated == generated);
        types
            .filter(|(_, t)| blades.iter().all(|b| t.model.blades.contains(b)))
            .min_by_key(|(pos, t)| (t.model.blades.len(), *pos))
            .map(|(pos, _)| pos)
    }

    pub(super) fn target_ty(&self, target: Target) -> TokenStream {
        let ident = match target {
            Target::Type(t) => &self.spec.types[t].ident,
            Target::Scalar => return quote!(T),
            Target::Dense => &self.dense_ident(),
        };
        quote!(#ident<T>)
    }

    pub(super) fn target_name(&self, target: Target) -> String {
        match target {
            Target::Type(t) => self.spec.types[t].ident.to_string(),
            Target::Scalar => "T".to_string(),
            Target::Dense => self.dense_ident().to_string(),
        }
    }

    /// Storage indices of a target's blades, as a `&'static [usize]` expression.
    pub(super) fn target_index(&self, target: Target) -> TokenStream {
        match target {
            Target::Type(t) => {
                let ranks = self.spec.types[t].model.blades.iter().map(|&b| self.a.rank()[b]);
                quote!(&[#(#ranks),*])
            }
            Target::Scalar => quote!(&[0]),
            Target::Dense => {
                let all = 0..self.dim;
                quote!(&[#(#all),*])
            }
        }
    }

    pub(super) fn dense_ident(&self) -> syn::Ident {
        self.spec.dense.as_ref().map_or_else(|| format_ident!("Multivector"), |d| d.name.clone())
    }

    /// A value of `target` whose blades are given by `exprs` (the rest zero).
    pub(super) fn construct(&self, target: Target, exprs: &BTreeMap<usize, TokenStream>) -> TokenStream {
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
            Target::Scalar => exprs.get(&0).cloned().unwrap_or_else(|| quote!(<T as #real>::zero())),
            Target::Dense => {
                let dense = self.dense_ident();
                let dim = self.dim;
                let sets = exprs.iter().map(|(b, e)| {
                    let i = self.a.rank()[*b];
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
    /// one multiplication by a constant. The sum starts with a positive term where there is
    /// one (a leading `−` is a sign flip of its own: an extra instruction on the critical
    /// path), and a sum of negative terms only is written `−(p₁ + p₂ + …)`, one flip.
    pub(super) fn sum(&self, terms: impl IntoIterator<Item = (f64, TokenStream)>) -> TokenStream {
        let real = self.real;
        let mut terms: Vec<_> = terms.into_iter().collect();
        let all_negative = terms.iter().all(|(c, _)| *c < 0.0);
        if let Some(first) = terms.iter().position(|(c, _)| *c > 0.0) {
            let positive = terms.remove(first);
            terms.insert(0, positive);
        }
        let mut out = TokenStream::new();
        for (i, (c, p)) in terms.into_iter().enumerate() {
            let magnitude = c.abs();
            let p = if (magnitude - 1.0).abs() < 1e-12 {
                p
            } else {
                let m = Literal::f64_suffixed(magnitude);
                quote!(<T as #real>::from_f64(#m) * (#p))
            };
            out.extend(match (i, c < 0.0 && !all_negative) {
                (0, _) => p,
                (_, false) => quote!(+ #p),
                (_, true) => quote!(- #p),
            });
        }
        if all_negative && !out.is_empty() { quote!(-(#out)) } else { out }
    }

    pub(super) fn bilinear_exprs(
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
}

fn subscript(k: usize) -> char {
    char::from_u32(0x2080 + k as u32).unwrap_or('?')
}
