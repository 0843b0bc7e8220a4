//! `algebra!`: declare a geometric algebra and get grade-sparse Rust types whose products
//! are computed at expansion time, term by term.
//!
//! The generator has three layers: `parse` reads the invocation (syntax only), `resolve`
//! (this file) checks it against the algebra and reports every mistake with the span of
//! the offending token, `model` computes metric, change of basis and Cayley tables with
//! no `syn` in sight, and `codegen` turns tables into code.
//!
//! # Input
//!
//! ```text
//! algebra! {
//!     scalar = crate::Real;                 // trait bound of the coefficient type T
//!     scalars = [f32, f64];                 // optional: concrete scalars for `2.0 * x`, `1.0 - r`
//!     lanes = cga_core::simd;               // optional: every type batches on SIMD lanes
//!     prelude = f64;                        // optional: `prelude::Circle` is `Circle<f64>`
//!     signature = (4, 1);                   // e1..e4 square to +1, e5 to −1
//!     basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), ei = e4 + e5];   // storage vectors
//!     /// docs…
//!     dense Multivector;                    // 2^n coefficients, orthonormal basis
//!     type Vector = [grade(1)];             // every blade of grade 1
//!     type Line = [e12i, e13i, e23i, e1oi, e2oi, e3oi];
//!     versor Motor = [s, e12, e13, e23, e1i, e2i, e3i, e123i];   // also gets sandwiches
//!     alias PointPair = Bivector;           // a type alias
//! }
//! ```
//!
//! `scalar` names the trait every coefficient type `T` implements. The generated code calls
//! its `zero()`, `one()`, `from_f64(f64)`, `to_f64(self) -> f64` (for `cast` and the values
//! in `TruncationError`), `sqrt`, `abs`, `is_finite` and `epsilon()` as associated
//! functions, and for `Exp` and `Log` also `max`, `binade` (a power of two near the value:
//! `|B|` of a tiny bivector without underflow), `sin`, `cos`, `atan2`, `sinh`, `cosh` and
//! `ln_1p` (`cga_core::Real` documents each); it needs `Copy + PartialEq + PartialOrd + Add +
//! Sub + Mul + Div + Neg` (all with `Output = Self`) and `Debug`: declare those in the trait
//! (`cga_core::Real` does). A trait that lacks one of those functions gets one error per
//! missing function spanned on the `scalar` item (“cannot find method … `to_f64` in trait
//! …”, `ui/fail/scalar_trait_lacks_a_method.rs`), besides the compiler's own errors at the
//! uses, which are spanned on the whole invocation.
//!
//! `scalars` (optional) lists concrete coefficient types (`f32`, `f64`, any type that
//! implements the `scalar` trait) that get the operators with the scalar on the left: the
//! orphan rule forbids `impl<T> Mul<X<T>> for T`, so for each listed `S` and type `X` the
//! macro emits `S * X<S>`, and where `X + s` exists (below) `S + X<S>` and `S − X<S>`.
//!
//! `lanes` (optional) names cga-core's `simd` module: every type, declared or generated,
//! then implements `cga_core::simd::Lanes` over `f64` and `f32` (packing, the AVX and AVX-512
//! transposes, `splat`), so `simd::run`, `run_packed`, `run_columns` and `map` batch the
//! algebra's products four or eight f64 values at a time, eight or sixteen f32 ones, with
//! the bits of one at a time, as they do cga-core's own types; and each prepared versor
//! (`v.prepare::<X>()`) on f64 or f32 values gets `run_into` (the generated trait `RunInto`,
//! also in the prelude): `apply_into`'s bits on lanes, `None` where the lengths differ. It
//! needs the `scalar` trait implemented by `f32` and by the lanes `F64x4`, `F64x8`, `F32x8`
//! and `F32x16` (`cga_core::Real` is).
//!
//! `prelude` (optional) names a scalar: a module `prelude` then holds every type at it
//! (`prelude::Circle` is `Circle<f64>`, aliases and the dense type included) and every
//! generated trait (imported as `_`: methods and operators, no names), so that after
//! `use …::prelude::*` a float literal needs no annotation (`Circle::through([1.3, …])`).
//!
//! `signature = (p, q, r)` declares a degenerate metric: after the p vectors that square to
//! +1 and the q to −1 come r null vectors (`e_i² = 0`), e.g. 3D PGA is `signature =
//! (3, 0, 1); basis = [e0 = e4, e1, e2, e3];` (the null vector renamed and listed first).
//! Products drop every term through a null square; the regressive product is metric-free
//! already; `dual` is then the right complement `∁A` (`e_S ∧ ∁e_S = I` blade by blade, `I`
//! the orthonormal `e1 ∧ … ∧ en`) and `undual` its inverse, since `I² = 0` has no `I⁻¹`.
//! `(p, q)` is `(p, q, 0)`.
//!
//! An algebra has 1 to 12 basis vectors. Products are tabulated pair by pair of declared
//! types (never the full 4ⁿ Cayley table, except for a `dense` type); what bounds n is that
//! every type converts to and from the 2ⁿ-coefficient storage array, which at n = 14 makes
//! even a few small types slow to compile. The default labels are `1`…`9`, then `a`, `b`, `c`
//! (the tenth vector is `ea`, as kingdon's `eA`). Expansion time per dimension:
//! `cargo test --release -p cga-macros -- --ignored --nocapture expansion_per_dimension`.
//!
//! `basis` is optional (default: the orthonormal `e1..en`); each storage vector is named
//! `e` plus a label of letters and digits (`eo`, `einf`, `e10`) and may be any linear
//! combination of `e1..en`, so a non-diagonal metric (the null vectors of CGA) is handled
//! here, not at run time. Blades are `s` (the scalar) or `e` followed by labels in basis order
//! (`e1oi`, `e1oinf`); labels that would make a blade's name read two ways (`1`, `2` and
//! `12`) are refused. A blade may also be written with its labels in any order, as PGA's
//! `e31`, `e021`, `e032`: the field is then the coefficient of that blade, `e31 = −e13` (the
//! sign of the permutation is folded into every table, so it costs nothing at run time), and
//! the storage array holds it in the canonical blade's slot. A blade is spelled one way in the
//! whole algebra (a `grade(k)` selector uses that spelling too); two spellings are refused.
//!
//! A type may not take the name of an item the macro generates in every algebra (the product
//! traits, `Sandwich`, `Prepare`, `Prepared`, `RunInto`, `ScalarProduct`, `Exp`, `Log`,
//! `Inverse`, `Blades`, the error and registry types, `prelude`): such a name is refused,
//! spanned on it (`ui/fail/generated_name.rs`).
//!
//! # Output
//!
//! For every type a `struct Name<T = f64>` with one named field per blade; for every
//! ordered pair of types the products whose Cayley table is not identically zero, as
//! traits (`GeometricProduct::gp`, `OuterProduct::wedge`, `InnerProduct::inner` (Hestenes),
//! `LeftContraction::lc` (`A ⌋ B`, grade s − r), `RightContraction::rc` (`A ⌊ B`, grade
//! r − s), `RegressiveProduct::vee`, the regressive product `∁⁻¹(∁A ∧ ∁B)` with the right
//! complement `e_S ∧ ∁e_S = I`, and
//! `CommutatorProduct::commutator`, `A × B = ½(A B − B A)`) and operators (`*`, `^`, `|`,
//! `&`); the result type is the smallest declared type holding every nonzero output blade
//! (ties: the first declared); else, for a result that is a scalar only, the scalar type `T`
//! itself; else the dense type. With no dense type, the macro declares a grade-mixed type of
//! its own for each set of grades that some product, sandwich, dual or grade part of the
//! declared types gives and no declared type holds: every blade of those grades, named after
//! them (`Grades1_3` for a vector times a rotor in G(3,0), `Grade9` for a vector's dual in
//! G(9,1)), documented with the maps that need it, and then a type like any other (its
//! products with every type, once: what they give that no type holds is not generated). It
//! is a result type only where no type the user declared holds the result. Beyond 32 blades
//! (G(4,1)'s whole algebra) none is declared: such a product is not generated, and the left
//! type's `# Products` table says `none` and names the grades a type must hold to get it.
//! `ScalarProduct::scalar_product` gives `⟨A B⟩₀` alone (one
//! multiplication per scalar term) for every pair whose geometric product has a scalar part.
//! The traits carry `#[diagnostic::on_unimplemented]` messages saying why a pair has none.
//! Their impls are hidden from rustdoc; each type's page has a `# Products` table of the
//! result types instead.
//!
//! Per type: reverse, involute, conjugate, dual, undual, grade projections, norm (`⟨A Ã⟩₀`,
//! and in a degenerate metric `bulk_norm` and `weight_norm`), `magnitude` (`√Σ c_I²` over the
//! orthonormal coefficients: positive definite in every signature),
//! `normalise` (`Result<Self, NormaliseError>`: zero, null or not finite) and
//! `try_normalise` (`Option`), scale, `cast::<U>()` (through `f64`: a dual number's derivative
//! is dropped), `from_storage` (drops other blades) and `try_from_storage` (refuses to), and
//! the arithmetic: `+`, `−`, unary `−`, `x * s`, `x / s` (each coefficient divided), `*=`,
//! `/=`; `A + B` and `A − B` of two different types into the smallest declared type holding
//! the blades of both (none if no type does; the impls are hidden from rustdoc). With the scalar on the right, generically: `x + s` and `x − s` into `X` when it holds
//! the scalar blade `s` (then also `+=`, `−=` and `X::one()`), else into the smallest declared
//! type holding `s` and `X`'s blades (none if no type does).
//!
//! Inverses: `try_inverse` (`Option`) and `inverse` (unchecked), `X⁻¹ = X̃ / ⟨X X̃⟩₀`, as
//! inherent methods of every type whose `X X̃` is a scalar for all values of its
//! coefficients, decided at expansion time from the Cayley table (every non-scalar blade's
//! polynomial in the coefficients cancels), and whose `⟨X X̃⟩₀` is not identically zero
//! (`inverse_table` lists them). The trait `Inverse` has the same two methods on every type
//! whose `⟨X X̃⟩₀` is not identically zero: those methods, or for the other types a run-time
//! check that `X X̃` is a scalar to rounding (`Σ |⟨X X̃⟩ₖ| ≤ 64 ε Σ c_I²` over k ≠ 0), which
//! holds for blades and versors: a 2-blade `a ∧ b` of CGA's `Bivector` inverts, `e12 + e3o`
//! does not. A CGA motor (`M M̃ = s + p e123i`) needs an inverse of its own, written by hand.
//!
//! Exponentials and logarithms, per metric: `Exp::exp` on every type of bivectors whose
//! `1 + B` a declared type holds (the smallest), with `B² = β`: `cos √−β + B sin √−β / √−β`
//! (β < 0, a rotation), `cosh √β + B sinh √β / √β` (β > 0, a boost), `1 + B` (β = 0, a
//! translation). Where every value of the type is simple (`B ∧ B` identically zero, as for
//! any bivector in three dimensions) it returns the rotor type, else a `Result` whose
//! `ExpError::NotSimple` gives `|⟨B²⟩₄|` relative to `Σ c_I²`. `Log::log` on every type of a
//! scalar and bivectors (a rotor, a translator) whose bivectors a declared type holds: the
//! principal logarithm `B θ/|B|` (θ = atan2(|B|, s)), `B asinh|B| / |B|` or `B / s`;
//! `LogError` names a non-simple `B`, a rotor more than `√ε` from unit (`NotUnit`, with
//! `R R̃ − 1`; closer ones are normalised first), `−1` and `−exp(B)` of a boost or
//! translation (`NoLogarithm`: no bivector gives them), and non-finite coefficients. Small
//! angles and rapidities keep full relative precision (`sin θ/θ`, `ln_1p`).
//!
//! Conversions: `From<A> for B` where `A`'s blades are all `B`'s; `TryFrom<A> for B` where
//! some but not all are, and from the dense type into every type, returning a
//! `TruncationError` (source and target names, and each dropped blade with its nonzero value)
//! unless every dropped coefficient is exactly zero.
//!
//! A scalar-valued result is the smallest declared type holding `s` (declare `type Scalar =
//! [s];` to get one: with a `Rotor = [s, …]` declared first, `a | b` would be a `Rotor`), `T`
//! only where no declared type holds `s`. A type of `s` alone is its number: `Deref` to `T`
//! (`*(a | b)`), `sqrt`, `abs`, and `From` into each of `scalars` (`f64::from(a | b)`).
//!
//! Versors get `Sandwich::sandwich` (`V X Ṽ`) on every type, and `Prepare` beside it: the
//! map `X ↦ V X Ṽ` is linear, so its matrix (each nonzero entry a quadratic form in `V`'s
//! coefficients) is computed once by `v.prepare()`, a `Prepared` whose `apply(x)`,
//! `apply_to(&xs)` and `apply_into(&xs, &mut out)` cost one multiplication per nonzero
//! entry (a 3D PGA motor on a point: 13, against the sandwich's 48); `v.apply_to(&xs)` is
//! the same in one call. The result is the sandwich's up to rounding (the terms are summed in
//! another order).
//!
//! With `lanes`, every type implements `cga_core::simd::Lanes`. With `prelude = f64;` the
//! module `prelude` holds each type as an alias at `f64` (`prelude::Point` is `Point<f64>`,
//! so it takes no parameter: code generic over lanes, `fn apply<L: Lane>(…, x: Point<L>)`,
//! names the algebra's own `Point`, not the prelude's) and every generated trait, imported as
//! `_`; what the crate adds by hand (its error types, say) is not in it.
//!
//! A registry (`product_table`,
//! `unary_table`, `inverse_table`) lists every generated map with its term count, for tests
//! that compare against the dense type. Besides the types, the invocation's module gets the
//! traits above, `TruncationError`, `NormaliseError`, the registry and, with `dense`, the
//! dense type's tables (hidden).
//!
//! # Seeing the generated code
//!
//! `cargo expand` (or, on nightly, `cargo rustc --profile=check -- -Zunpretty=expanded`) in the
//! crate that invokes the macro prints the expansion; `cargo test -p cga-macros
//! expand_cga_core` writes cga-core's, formatted, to `target/cga-core-expanded.rs`.
//! `docs/ALGEBRA_PEERS.md` compares the macro with GARAMON, ganja.js, kingdon and
//! Lichtso/geometric_algebra.

mod codegen;
mod model;
mod parse;

use model::{Algebra, ModelError, TypeModel};
use proc_macro::TokenStream;
use std::collections::BTreeMap;
use syn::spanned::Spanned;
use syn::{Error, Expr, Ident};

/// Declare an algebra and generate its types. See the crate documentation for the input.
#[proc_macro]
pub fn algebra(input: TokenStream) -> TokenStream {
    let input = syn::parse_macro_input!(input as parse::Input);
    match resolve(input) {
        Ok(spec) => codegen::generate(&spec).into(),
        Err(e) => e.to_compile_error().into(),
    }
}

/// The checked declaration: a model plus what codegen needs to name things.
#[derive(Clone)]
pub(crate) struct Spec {
    pub algebra: Algebra,
    pub scalar: syn::Path,
    pub dense: Option<parse::Named>,
    pub types: Vec<TypeSpec>,
    pub aliases: Vec<parse::Alias>,
    pub approx: Option<parse::PathItem>,
    /// `lanes = cga_core::simd;`: where `Lanes` is, when the types are to batch.
    pub lanes: Option<parse::PathItem>,
    /// `prelude = f64;`: the scalar of the prelude's types, when one is asked for.
    pub prelude: Option<parse::PathItem>,
    /// Concrete scalars that get the scalar-on-the-left operators (`scalars = [f32, f64];`).
    pub scalars: Vec<syn::Type>,
}

#[derive(Clone)]
pub(crate) struct TypeSpec {
    pub model: TypeModel,
    /// Declared by the generator, not the user (a grade-mixed result type): a result type
    /// only where no type the user declared holds the result.
    pub generated: bool,
    pub ident: Ident,
    pub attrs: Vec<syn::Attribute>,
}

/// Largest supported dimension. The products are built pair by pair of declared types, but
/// every type converts to and from the 2ⁿ-coefficient storage array: at n = 14 an algebra of
/// four small types takes 37 s and 2.5 GB to compile, at n = 12 1.5 s (and a dense type's
/// tables are 4ⁿ entries).
const MAX_DIM: usize = 12;

fn resolve(input: parse::Input) -> syn::Result<Spec> {
    let call_site = proc_macro2::Span::call_site();
    let scalar = input.scalar.ok_or_else(|| {
        Error::new(call_site, "missing `scalar = path::to::Trait;` (the bound of the coefficient type)")
    })?;
    let sig = input.signature.ok_or_else(|| Error::new(call_site, "missing `signature = (p, q);`"))?;
    let (p, q): (usize, usize) = (sig.p.base10_parse()?, sig.q.base10_parse()?);
    let r: usize = sig.r.as_ref().map_or(Ok(0), syn::LitInt::base10_parse)?;
    let n = p.saturating_add(q).saturating_add(r);
    if n == 0 || n > MAX_DIM {
        let r = sig.r.as_ref().map_or(String::new(), |_| format!(", {r}"));
        return Err(Error::new(
            sig.span,
            format!("bad signature ({p}, {q}{r}): the algebra needs 1 to {MAX_DIM} basis vectors, this has {n}"),
        ));
    }
    let (labels, rows, basis_span) = match input.basis {
        Some(basis) => {
            let (labels, rows) = resolve_basis(&basis, n)?;
            (labels, rows, basis.span)
        }
        None => (
            (1..=n).map(|i| char::from_digit(i as u32, 36).unwrap_or('?').to_string()).collect(),
            identity(n),
            sig.span,
        ),
    };
    let mut algebra = Algebra::new([p, q, r], labels, rows).map_err(|e| match e {
        ModelError::DegenerateBasis => {
            Error::new(basis_span, "the basis vectors are linearly dependent: they do not span the algebra")
        }
        ModelError::NonFinite => Error::new(basis_span, "the basis coefficients overflow: keep them within ±1e100"),
    })?;
    if let Some(name) = algebra.ambiguous_blade() {
        return Err(Error::new(
            basis_span,
            format!(
                "the basis labels make blade `{name}` read two ways: rename a basis vector so that no label is a run of others"
            ),
        ));
    }

    resolve_spellings(&mut algebra, &input.types)?;
    let mut names: Vec<Ident> = input.dense.iter().map(|d| d.name.clone()).collect();
    let mut types = Vec::new();
    for decl in input.types {
        check_new_name(&names, &decl.name)?;
        names.push(decl.name.clone());
        let blades = resolve_blades(&algebra, &decl)?;
        let model = TypeModel { blades, versor: decl.versor };
        types.push(TypeSpec { model, generated: false, ident: decl.name, attrs: decl.attrs });
    }
    for alias in &input.aliases {
        check_new_name(&names, &alias.name)?;
        if !types.iter().any(|t| t.ident == alias.target) {
            return Err(Error::new(alias.target.span(), format!("unknown type `{}`", alias.target)));
        }
        names.push(alias.name.clone());
    }
    let scalars = resolve_scalars(input.scalars)?;
    Ok(Spec {
        algebra,
        scalar,
        dense: input.dense,
        types,
        aliases: input.aliases,
        approx: input.approx,
        lanes: input.lanes,
        prelude: input.prelude,
        scalars,
    })
}

/// The `scalars` list: at least one type, none twice.
fn resolve_scalars(scalars: Option<parse::Scalars>) -> syn::Result<Vec<syn::Type>> {
    let Some(scalars) = scalars else { return Ok(Vec::new()) };
    if scalars.types.is_empty() {
        return Err(Error::new(
            scalars.span,
            "`scalars` lists no type: name the concrete scalars (`scalars = [f32, f64];`) or leave the option out",
        ));
    }
    let mut seen: Vec<String> = Vec::new();
    for ty in &scalars.types {
        let name = quote::ToTokens::to_token_stream(ty).to_string();
        if seen.contains(&name) {
            return Err(Error::new(ty.span(), format!("scalar `{name}` is listed twice in `scalars`")));
        }
        seen.push(name);
    }
    Ok(scalars.types)
}

/// The items every invocation generates beside the declared types (traits, the prepared
/// sandwich, the registry's and the errors' types), whose names a declared type cannot take.
const GENERATED: [&str; 26] = [
    "GeometricProduct",
    "OuterProduct",
    "InnerProduct",
    "RegressiveProduct",
    "LeftContraction",
    "RightContraction",
    "CommutatorProduct",
    "Sandwich",
    "Prepare",
    "Prepared",
    "RunInto",
    "ScalarProduct",
    "Exp",
    "Log",
    "Inverse",
    "Blades",
    "TruncationError",
    "NormaliseError",
    "ExpError",
    "LogError",
    "ProductKind",
    "UnaryKind",
    "ProductEntry",
    "UnaryEntry",
    "InverseEntry",
    "prelude",
];

fn check_new_name(names: &[Ident], name: &Ident) -> syn::Result<()> {
    if names.contains(name) {
        return Err(Error::new(name.span(), format!("duplicate type `{name}`: it is declared twice")));
    }
    if GENERATED.iter().any(|g| name == g) {
        return Err(Error::new(
            name.span(),
            format!("`{name}` is the name of an item the macro generates in every algebra: name the type otherwise"),
        ));
    }
    Ok(())
}

fn identity(n: usize) -> Vec<Vec<f64>> {
    (0..n).map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect()).collect()
}

/// Storage vectors: labels from the names, rows from the expressions.
fn resolve_basis(basis: &parse::Basis, n: usize) -> syn::Result<(Vec<String>, Vec<Vec<f64>>)> {
    if basis.vectors.len() != n {
        return Err(Error::new(
            basis.span,
            format!("the signature has {n} basis vectors but `basis` lists {}", basis.vectors.len()),
        ));
    }
    let mut labels = Vec::new();
    let mut rows = Vec::new();
    for v in &basis.vectors {
        let name = v.name.to_string();
        let label = match name.strip_prefix('e') {
            Some(l) if !l.is_empty() && l.chars().all(|c| c.is_ascii_alphanumeric()) => l.to_string(),
            _ => {
                return Err(Error::new(
                    v.name.span(),
                    format!("basis vector `{name}` must be named `e` plus letters or digits, e.g. `eo` or `einf`"),
                ));
            }
        };
        if labels.contains(&label) {
            return Err(Error::new(v.name.span(), format!("basis vector `{name}` is listed twice")));
        }
        labels.push(label);
        let row = match &v.expr {
            Some(expr) => match eval(expr, n)? {
                Value::Vector(row) => row,
                Value::Number(_) => {
                    return Err(Error::new(expr.span(), "a basis vector must be a combination of e1..en"));
                }
            },
            None => ortho_vector(&v.name, n)?,
        };
        rows.push(row);
    }
    Ok((labels, rows))
}

/// A basis expression's value: a number or a vector in the orthonormal basis.
enum Value {
    Number(f64),
    Vector(Vec<f64>),
}

fn ortho_vector(ident: &Ident, n: usize) -> syn::Result<Vec<f64>> {
    let name = ident.to_string();
    let index = name.strip_prefix('e').and_then(|d| d.parse::<usize>().ok()).filter(|&i| (1..=n).contains(&i));
    match index {
        Some(i) => Ok((1..=n).map(|j| f64::from(u8::from(i == j))).collect()),
        None => Err(Error::new(ident.span(), format!("unknown vector `{name}`: the orthonormal vectors are e1..e{n}"))),
    }
}

/// Evaluate `0.5 * (e5 - e4)`-style expressions: numbers, e1..en, + − * / and parentheses.
fn eval(expr: &Expr, n: usize) -> syn::Result<Value> {
    use syn::{BinOp, Lit, UnOp};
    let unsupported = || Error::new(expr.span(), "expected a linear combination such as `0.5 * (e5 - e4)`");
    match expr {
        Expr::Paren(e) => eval(&e.expr, n),
        Expr::Group(e) => eval(&e.expr, n),
        Expr::Lit(lit) => match &lit.lit {
            Lit::Int(i) => Ok(Value::Number(i.base10_parse::<f64>()?)),
            Lit::Float(f) => Ok(Value::Number(f.base10_parse::<f64>()?)),
            _ => Err(unsupported()),
        },
        Expr::Path(path) => match path.path.get_ident() {
            Some(ident) => ortho_vector(ident, n).map(Value::Vector),
            None => Err(unsupported()),
        },
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Ok(match eval(&u.expr, n)? {
            Value::Number(x) => Value::Number(-x),
            Value::Vector(v) => Value::Vector(v.iter().map(|x| -x).collect()),
        }),
        Expr::Binary(b) => {
            let (l, r) = (eval(&b.left, n)?, eval(&b.right, n)?);
            let add = |sign: f64, l: Value, r: Value| match (l, r) {
                (Value::Number(x), Value::Number(y)) => Ok(Value::Number(x + sign * y)),
                (Value::Vector(x), Value::Vector(y)) => {
                    Ok(Value::Vector(x.iter().zip(&y).map(|(a, b)| a + sign * b).collect()))
                }
                _ => Err(Error::new(expr.span(), "cannot add a number to a vector")),
            };
            let scale = |v: Vec<f64>, s: f64| Value::Vector(v.iter().map(|x| x * s).collect());
            match (&b.op, l, r) {
                (BinOp::Add(_), l, r) => add(1.0, l, r),
                (BinOp::Sub(_), l, r) => add(-1.0, l, r),
                (BinOp::Mul(_), Value::Number(x), Value::Number(y)) => Ok(Value::Number(x * y)),
                (BinOp::Mul(_), Value::Number(s), Value::Vector(v))
                | (BinOp::Mul(_), Value::Vector(v), Value::Number(s)) => Ok(scale(v, s)),
                (BinOp::Div(_), Value::Number(x), Value::Number(y)) if y != 0.0 => Ok(Value::Number(x / y)),
                (BinOp::Div(_), Value::Vector(v), Value::Number(s)) if s != 0.0 => Ok(scale(v, 1.0 / s)),
                _ => Err(Error::new(expr.span(), "not a linear combination of basis vectors")),
            }
        }
        _ => Err(unsupported()),
    }
}

/// Blades written with their labels out of basis order (`e31`, `e021`): each becomes its
/// type's field, with the sign carried into every table (`e31 = −e13`). A blade has one
/// spelling in the whole algebra, so that every type names a coefficient the same way.
fn resolve_spellings(algebra: &mut Algebra, decls: &[parse::TypeDecl]) -> syn::Result<()> {
    let mut seen: BTreeMap<usize, (String, String)> = BTreeMap::new();
    for decl in decls {
        for elem in &decl.elems {
            let parse::Elem::Blade(ident) = elem else { continue };
            let name = ident.to_string();
            // Names that are no blade are reported with their type (`resolve_blades`).
            let Some(mask) = algebra.parse_blade(&name).or_else(|| algebra.permuted_blade(&name).map(|(m, _)| m))
            else {
                continue;
            };
            match seen.get(&mask) {
                Some((other, ty)) if *other != name => {
                    let relation = relation(algebra, &name, other);
                    return Err(Error::new(
                        ident.span(),
                        format!(
                            "blade `{name}` is written `{other}` in `{ty}` ({relation}): spell each blade one way in the whole algebra"
                        ),
                    ));
                }
                _ => {
                    seen.insert(mask, (name, decl.name.to_string()));
                }
            }
        }
    }
    for (mask, (name, _)) in seen {
        if let Some((_, sign)) = algebra.permuted_blade(&name).filter(|_| name != algebra.canonical_name(mask)) {
            algebra.respell(mask, name, sign);
        }
    }
    Ok(())
}

/// `a = −b` or `a = b` for two spellings of one blade.
fn relation(algebra: &Algebra, a: &str, b: &str) -> String {
    let sign = |n: &str| algebra.permuted_blade(n).map_or(1.0, |(_, s)| s);
    if sign(a) * sign(b) < 0.0 { format!("`{a}` = −`{b}`") } else { format!("`{a}` = `{b}`") }
}

/// Why a blade name is not one: labels that read two ways, or unknown.
fn unknown_blade(algebra: &Algebra, ident: &Ident) -> Error {
    let name = ident.to_string();
    let labels = &algebra.labels;
    if name.strip_prefix('e').is_some_and(|rest| algebra.label_parses(rest, false).len() > 1) {
        return Error::new(
            ident.span(),
            format!(
                "blade `{name}` reads as more than one run of the basis labels ({}): write the labels in basis order",
                labels.join(", ")
            ),
        );
    }
    Error::new(
        ident.span(),
        format!(
            "unknown blade `{name}`: a blade is `s` (the scalar) or `e` followed by distinct basis labels ({}), e.g. `{}`",
            labels.join(", "),
            algebra.blade_name(0b11)
        ),
    )
}

/// The storage blades of a type declaration, in field order.
fn resolve_blades(algebra: &Algebra, decl: &parse::TypeDecl) -> syn::Result<Vec<usize>> {
    let mut blades: Vec<usize> = Vec::new();
    let push = |mask: usize, span: proc_macro2::Span, blades: &mut Vec<usize>| {
        if blades.contains(&mask) {
            let blade = algebra.blade_name(mask);
            return Err(Error::new(span, format!("blade `{blade}` is listed twice in `{}`", decl.name)));
        }
        blades.push(mask);
        Ok(())
    };
    for elem in &decl.elems {
        match elem {
            parse::Elem::Blade(ident) => {
                let name = ident.to_string();
                let mask = algebra.parse_blade(&name).ok_or_else(|| unknown_blade(algebra, ident))?;
                push(mask, ident.span(), &mut blades)?;
            }
            parse::Elem::Grade(lit) => {
                let k: usize = lit.base10_parse()?;
                if k > algebra.n {
                    return Err(Error::new(
                        lit.span(),
                        format!("grade {k} does not exist: grades run from 0 to {}", algebra.n),
                    ));
                }
                for mask in algebra.grade_blades(k) {
                    push(mask, lit.span(), &mut blades)?;
                }
            }
        }
    }
    if blades.is_empty() {
        return Err(Error::new(decl.name.span(), format!("type `{}` has no blades", decl.name)));
    }
    Ok(blades)
}

#[cfg(test)]
mod tests {
    use std::alloc::{GlobalAlloc, Layout, System};
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

    /// The test binary's allocator, counting the bytes it hands out (for the expansion's
    /// memory per dimension).
    struct Counting;
    static ALLOCATED: AtomicUsize = AtomicUsize::new(0);

    // SAFETY: every call is passed on to the system allocator unchanged.
    unsafe impl GlobalAlloc for Counting {
        unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
            ALLOCATED.fetch_add(layout.size(), Relaxed);
            // SAFETY: the caller's layout, as `GlobalAlloc::alloc` requires.
            unsafe { System.alloc(layout) }
        }
        unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
            // SAFETY: `ptr` came from `alloc` with this layout.
            unsafe { System.dealloc(ptr, layout) }
        }
    }

    #[global_allocator]
    static ALLOCATOR: Counting = Counting;

    /// A product no declared type holds gets a grade-mixed type of its own (`Grades1_3`), up
    /// to `MAX_MIXED` blades; beyond, it is not generated, and the type's docs say which
    /// grades a type must hold to get it.
    #[test]
    fn uncovered_products_get_a_type_or_are_named_with_their_grades() {
        let expand = |input: &str| {
            let input: super::parse::Input = syn::parse_str(input).expect("parses");
            super::codegen::generate(&super::resolve(input).expect("resolves")).to_string()
        };
        let vga = expand(
            "scalar = cga_core::Real; signature = (3, 0); type Vector = [grade(1)]; versor Rotor = [s, grade(2)];",
        );
        assert!(
            vga.contains("pub struct Grades1_3 < T = f64 > { # [doc = \" Coefficient of `e1`.\"] pub e1 : T"),
            "{vga}"
        );
        assert!(vga.contains("GeometricProduct < Rotor < T >> for Vector < T > { type Output = Grades1_3 < T >"));
        // G(7,0): grades 1 and 3 are 7 + 35 = 42 blades, more than MAX_MIXED.
        let g7 = expand(
            "scalar = cga_core::Real; signature = (7, 0); type Vector = [grade(1)]; versor Rotor = [s, grade(2)];",
        );
        assert!(g7.contains("`A B` with [`Rotor`]: grades [1, 3], e.g. `type … = [grade(1), grade(3)];`"));
        assert!(!g7.contains("GeometricProduct < Rotor < T >> for Vector"), "not generated");
        assert!(!g7.contains("Grades1_3"));
    }

    /// Expansion time, bytes allocated and output size per dimension, for an algebra of
    /// vectors, bivectors, rotors and the pseudoscalar (no dense type: its tables are 4ⁿ).
    /// `cargo test --release -p cga-macros -- --ignored --nocapture expansion_per_dimension`
    #[test]
    #[ignore = "a measurement: run it by name"]
    fn expansion_per_dimension() {
        println!("| n | blades | expansion ms | allocated MiB | output KiB |\n|---:|---:|---:|---:|---:|");
        for n in [4, 6, 8, 10, 12] {
            let input = format!(
                "scalar = cga_core::Real; signature = ({}, 1); type Scalar = [s]; type Vector = [grade(1)]; \
                 type Bivector = [grade(2)]; versor Rotor = [s, grade(2)]; type Pseudoscalar = [grade({n})];",
                n - 1
            );
            let before = ALLOCATED.load(Relaxed);
            let start = std::time::Instant::now();
            let input: super::parse::Input = syn::parse_str(&input).expect("parses");
            let spec = super::resolve(input).expect("resolves");
            let out = super::codegen::generate(&spec).to_string();
            let ms = start.elapsed().as_secs_f64() * 1e3;
            let allocated = (ALLOCATED.load(Relaxed) - before) as f64 / (1 << 20) as f64;
            println!("| {n} | {} | {ms:.0} | {allocated:.0} | {} |", 1 << n, out.len() / 1024);
        }
    }

    /// Random, mostly malformed invocations: each must expand or give an error, never panic.
    #[test]
    fn random_input_never_panics() {
        let pieces = [
            "scalar = crate::Real;",
            "scalar = ;",
            "signature = (3, 0);",
            "signature = (4, 1);",
            "signature = (0, 0);",
            "signature = (2, 1, 0);",
            "signature = (3, 0, 1);",
            "signature = (0, 0, 2);",
            "signature = (1, 1, 1, 1);",
            "signature = (99999999999999999999, 1);",
            "basis = [e1, e2, e3];",
            "basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), ei = e4 + e5];",
            "basis = [ea = e1 / 0, eb = e2];",
            "basis = [ea = 1e300 * e1, eb = 1e300 * e2, ec = e3];",
            "basis = [e1, e1, e3];",
            "basis = [ex = e1 * e2];",
            "dense M;",
            "dense;",
            "type V = [grade(1)];",
            "type V = [grade(9)];",
            "type R = [s, e12];",
            "type R = [s, e12, e12];",
            "type Q = [];",
            "type E = [grade(0), grade(2)];",
            "versor R2 = [s, e12, e13, e23];",
            "versor X = [s, eo1];",
            "alias P = V;",
            "alias P = Nope;",
            "scalars = [f64];",
            "scalars = [f32, f64];",
            "scalars = [];",
            "scalars = [f64, f64];",
            "scalars = [f64",
            "type V = [e1];",
            "type W = [e1oi, e2i];",
            "type",
            "= [",
            "]",
            ";",
            "grade(1)",
            "type Z = [grade(-1)];",
            "type Y = [s e1];",
        ];
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_xorshift::XorShiftRng::seed_from_u64(0x9e37_79b9_7f4a_7c15);
        let mut next = move || rng.random::<u64>();
        let (mut expanded, mut rejected) = (0, 0);
        for _ in 0..400 {
            // Mostly well-formed headers, so that the checks past the parser are reached.
            let mut text = String::new();
            if next() % 5 != 0 {
                text.push_str("scalar = crate::Real; ");
            }
            if next() % 5 != 0 {
                text.push_str(
                    ["signature = (3, 0); ", "signature = (2, 1); ", "signature = (1, 0); "][(next() % 3) as usize],
                );
            }
            for _ in 0..next() % 6 {
                text.push_str(pieces[(next() % pieces.len() as u64) as usize]);
                text.push(' ');
            }
            let Ok(tokens) = text.parse::<proc_macro2::TokenStream>() else { continue };
            match syn::parse2::<super::parse::Input>(tokens).and_then(super::resolve) {
                Ok(spec) => {
                    let _ = super::codegen::generate(&spec);
                    expanded += 1;
                }
                Err(_) => rejected += 1,
            }
        }
        assert!(expanded > 40 && rejected > 100, "expanded {expanded}, rejected {rejected}");
    }

    /// The macro's errors for the `ui/fail` inputs, checked in process (no compiler run): each
    /// input the macro itself refuses gives the message and the line and column its
    /// `.stderr` file holds (the file rustc's output is checked against by `cargo test -p
    /// cga-macros --test ui -- --ignored`, which also runs the inputs whose errors come from
    /// the compiler: a product or sandwich the algebra does not have).
    #[test]
    fn ui_inputs_give_their_messages_where_their_stderr_files_say() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("ui/fail");
        let mut checked = 0;
        let mut names: Vec<_> = std::fs::read_dir(&dir).expect("ui/fail").flatten().map(|e| e.path()).collect();
        names.sort();
        for path in names.iter().filter(|p| p.extension().is_some_and(|e| e == "rs")) {
            let expected = std::fs::read_to_string(path.with_extension("stderr")).expect("a .stderr file");
            // Only the macro's own errors: the compiler's (`error[E…]`) need a compiler.
            let Some(message) = expected.lines().next().and_then(|l| l.strip_prefix("error: ")) else { continue };
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            let at = expected.lines().nth(1).and_then(|l| l.split(&format!("{name}:")).nth(1)).expect("a location");
            let (line, column) = at.split_once(':').expect("line:column");
            let source = std::fs::read_to_string(path).expect("input");
            let file = syn::parse_file(&source).expect("the input parses as Rust");
            let tokens = file
                .items
                .iter()
                .find_map(|item| match item {
                    syn::Item::Macro(m) => Some(m.mac.tokens.clone()),
                    _ => None,
                })
                .expect("an algebra! invocation");
            let error = match syn::parse2::<super::parse::Input>(tokens).and_then(super::resolve) {
                Ok(_) => panic!("{name}: the macro accepts it"),
                Err(e) => e,
            };
            assert_eq!(error.to_string(), message, "{name}");
            let start = error.span().start();
            // A span of the whole invocation (a field that is missing) is where the macro is
            // called: line 1 of the input, which has no place in process.
            if (line, column) != ("1", "1") {
                assert_eq!(
                    (start.line.to_string(), (start.column + 1).to_string()),
                    (line.into(), column.into()),
                    "{name}"
                );
            }
            checked += 1;
        }
        assert_eq!(checked, 17, "the ui/fail inputs the macro refuses itself");
    }

    /// Expands cga-core's own invocation and writes it, formatted, to
    /// `cga-core-expanded.rs` in the target directory (`$CARGO_TARGET_DIR` or `target/`): the
    /// generated code as a user would read it. Its size is the one benches/README.md states.
    #[test]
    fn expand_cga_core() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let source = std::fs::read_to_string(root.join("cga-core/src/algebra.rs")).expect("cga-core/src/algebra.rs");
        let file = syn::parse_file(&source).expect("parses");
        let mac = file
            .items
            .iter()
            .find_map(|item| match item {
                syn::Item::Macro(m)
                    if m.mac.path.is_ident("algebra")
                        || m.mac.path.segments.last().is_some_and(|s| s.ident == "algebra") =>
                {
                    Some(m.mac.tokens.clone())
                }
                _ => None,
            })
            .expect("an algebra! invocation");
        let input: super::parse::Input = syn::parse2(mac).expect("input parses");
        let spec = super::resolve(input).expect("input resolves");
        let tokens = super::codegen::generate(&spec);
        let pretty = prettyplease::unparse(&syn::parse2(tokens).expect("output parses"));
        let target = std::env::var_os("CARGO_TARGET_DIR").map_or(root.join("target"), std::path::PathBuf::from);
        std::fs::create_dir_all(&target).expect("target dir");
        let out = target.join("cga-core-expanded.rs");
        std::fs::write(&out, &pretty).expect("write expansion");
        // Every sum of several terms starts with a positive one where it has one, and is
        // `−(…)` where it has none: a leading `−` on one term is a sign flip of its own.
        let leading_minus = pretty
            .lines()
            .map(str::trim)
            .filter(|l| {
                let rhs = l.split_once(": ").or_else(|| l.split_once(" = ")).map_or("", |(_, r)| r);
                rhs.starts_with('-') && !rhs.starts_with("-(") && (rhs.contains(" + ") || rhs.contains(" - "))
            })
            .count();
        assert_eq!(leading_minus, 0, "sums that start with a negative term");
        let lines = pretty.lines().count();
        println!("generated: {lines} lines, {} bytes -> {}", pretty.len(), out.display());
        // The figure published in benches/README.md ("The expansion is N lines"), within 1 %.
        let readme = std::fs::read_to_string(root.join("benches/README.md")).expect("benches/README.md");
        let stated: usize = (readme.split("The expansion is ").nth(1))
            .and_then(|rest| rest.split(' ').next())
            .map(|n| n.replace(',', ""))
            .and_then(|n| n.parse().ok())
            .expect("benches/README.md states the expansion's size");
        let off = stated.abs_diff(lines) as f64 / lines as f64;
        assert!(off < 0.01, "benches/README.md says {stated} lines, the expansion has {lines}");
    }
}
