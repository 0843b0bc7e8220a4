//! Parsing the `algebra!` input into plain declarations. Only syntax is checked here;
//! meaning (known blades, duplicates, a usable basis) is checked in `lib.rs` against the
//! model, with the span of the offending token.

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, LitInt, Path, Token, bracketed, parenthesized};

/// The whole invocation.
pub struct Input {
    pub scalar: Option<Path>,
    pub signature: Option<Signature>,
    pub basis: Option<Basis>,
    pub dense: Option<Named>,
    pub types: Vec<TypeDecl>,
    pub aliases: Vec<Alias>,
    pub approx: Option<PathItem>,
    pub lanes: Option<PathItem>,
    pub prelude: Option<PathItem>,
    pub scalars: Option<Scalars>,
}

/// `scalars = [f32, f64];`: concrete coefficient types that get the scalar-on-the-left
/// operators (`2.0 * x`, `1.0 - r`), which the orphan rule forbids generically.
pub struct Scalars {
    pub types: Vec<syn::Type>,
    pub span: Span,
}

/// An item naming a path, each generated impl carrying the item's attributes (so a crate can
/// gate them behind a feature):
/// - `#[cfg(…)] approx = path::to::approx;`: the `approx` crate's comparison traits for every
///   type;
/// - `lanes = cga_core::simd;`: `cga_core::simd::Lanes` for every type over `f64` and `f32`, so that
///   `simd::run`, `run_packed`, `run_columns` and `map` batch them (the path names
///   cga-core's `simd` module);
/// - `prelude = f64;`: a module `prelude` of every type at that scalar (`Circle` for
///   `Circle<f64>`) and every product trait, for `use …::prelude::*`.
#[derive(Clone)]
pub struct PathItem {
    pub attrs: Vec<Attribute>,
    pub path: Path,
}

/// `signature = (p, q);` or `signature = (p, q, r);`
pub struct Signature {
    pub p: LitInt,
    pub q: LitInt,
    /// Null vectors (a degenerate metric), when given.
    pub r: Option<LitInt>,
    pub span: Span,
}

/// `basis = [e1, e2, e3, eo = 0.5 * (e5 - e4), ei = e4 + e5];`
pub struct Basis {
    pub vectors: Vec<BasisVector>,
    pub span: Span,
}

/// One storage vector: a name, and its expression in the orthonormal vectors `e1..en`
/// (absent when the name is itself one of them).
pub struct BasisVector {
    pub name: Ident,
    pub expr: Option<Expr>,
}

/// `dense Multivector;`
#[derive(Clone)]
pub struct Named {
    pub attrs: Vec<Attribute>,
    pub name: Ident,
}

/// `type Name = [blade, grade(k), …];` or `versor Name = […];`
pub struct TypeDecl {
    pub attrs: Vec<Attribute>,
    pub name: Ident,
    pub elems: Vec<Elem>,
    pub versor: bool,
}

/// An entry of a type's blade list.
pub enum Elem {
    /// A blade by name: `s`, `e12`, `e1oi`.
    Blade(Ident),
    /// Every blade of a grade: `grade(2)`.
    Grade(LitInt),
}

/// `alias PointPair = Bivector;`
#[derive(Clone)]
pub struct Alias {
    pub attrs: Vec<Attribute>,
    pub name: Ident,
    pub target: Ident,
}

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut out = Input {
            scalar: None,
            signature: None,
            basis: None,
            dense: None,
            types: vec![],
            aliases: vec![],
            approx: None,
            lanes: None,
            prelude: None,
            scalars: None,
        };
        while !input.is_empty() {
            let attrs = input.call(Attribute::parse_outer)?;
            if input.peek(Token![type]) {
                input.parse::<Token![type]>()?;
                out.types.push(parse_type(input, attrs, false)?);
                input.parse::<Token![;]>()?;
                continue;
            }
            let key: Ident = input.parse()?;
            match key.to_string().as_str() {
                "scalar" => {
                    input.parse::<Token![=]>()?;
                    set_once(&mut out.scalar, input.parse()?, &key)?;
                }
                "signature" => {
                    input.parse::<Token![=]>()?;
                    let content;
                    let parens = parenthesized!(content in input);
                    let p = content.parse()?;
                    content.parse::<Token![,]>()?;
                    let q = content.parse()?;
                    let r = if content.is_empty() {
                        None
                    } else {
                        content.parse::<Token![,]>()?;
                        Some(content.parse()?)
                    };
                    if !content.is_empty() {
                        return Err(content
                            .error("a signature is `(p, q)` or `(p, q, r)`: p vectors square to +1, q to −1, r to 0"));
                    }
                    set_once(&mut out.signature, Signature { p, q, r, span: parens.span.join() }, &key)?;
                }
                "basis" => {
                    input.parse::<Token![=]>()?;
                    let content;
                    let brackets = bracketed!(content in input);
                    let list = Punctuated::<BasisVector, Token![,]>::parse_terminated(&content)?;
                    let basis = Basis { vectors: list.into_iter().collect(), span: brackets.span.join() };
                    set_once(&mut out.basis, basis, &key)?;
                }
                "dense" => {
                    let named = Named { attrs, name: input.parse()? };
                    set_once(&mut out.dense, named, &key)?;
                }
                "versor" => out.types.push(parse_type(input, attrs, true)?),
                "approx" => {
                    input.parse::<Token![=]>()?;
                    set_once(&mut out.approx, PathItem { attrs, path: input.parse()? }, &key)?;
                }
                "lanes" => {
                    input.parse::<Token![=]>()?;
                    set_once(&mut out.lanes, PathItem { attrs, path: input.parse()? }, &key)?;
                }
                "prelude" => {
                    input.parse::<Token![=]>()?;
                    set_once(&mut out.prelude, PathItem { attrs, path: input.parse()? }, &key)?;
                }
                "scalars" => {
                    input.parse::<Token![=]>()?;
                    let content;
                    let brackets = bracketed!(content in input);
                    let list = Punctuated::<syn::Type, Token![,]>::parse_terminated(&content)?;
                    let scalars = Scalars { types: list.into_iter().collect(), span: brackets.span.join() };
                    set_once(&mut out.scalars, scalars, &key)?;
                }
                "alias" => {
                    let name = input.parse()?;
                    input.parse::<Token![=]>()?;
                    out.aliases.push(Alias { attrs, name, target: input.parse()? });
                }
                other => {
                    return Err(syn::Error::new(
                        key.span(),
                        format!(
                            "unknown item `{other}`: expected `scalar`, `signature`, `basis`, `dense`, `type`, `versor`, `alias`, `approx`, `lanes`, `prelude` or `scalars`"
                        ),
                    ));
                }
            }
            input.parse::<Token![;]>()?;
        }
        Ok(out)
    }
}

fn set_once<T>(slot: &mut Option<T>, value: T, key: &Ident) -> syn::Result<()> {
    if slot.is_some() {
        return Err(syn::Error::new(key.span(), format!("`{key}` is given twice")));
    }
    *slot = Some(value);
    Ok(())
}

fn parse_type(input: ParseStream, attrs: Vec<Attribute>, versor: bool) -> syn::Result<TypeDecl> {
    let name = input.parse()?;
    input.parse::<Token![=]>()?;
    let content;
    bracketed!(content in input);
    let elems = Punctuated::<Elem, Token![,]>::parse_terminated(&content)?;
    Ok(TypeDecl { attrs, name, elems: elems.into_iter().collect(), versor })
}

impl Parse for BasisVector {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name = input.parse()?;
        let expr = if input.peek(Token![=]) {
            input.parse::<Token![=]>()?;
            Some(input.parse()?)
        } else {
            None
        };
        Ok(BasisVector { name, expr })
    }
}

impl Parse for Elem {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let ident: Ident = input.parse()?;
        if ident == "grade" && input.peek(syn::token::Paren) {
            let content;
            parenthesized!(content in input);
            return Ok(Elem::Grade(content.parse()?));
        }
        Ok(Elem::Blade(ident))
    }
}
