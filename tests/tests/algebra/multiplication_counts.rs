//! Each generated map does exactly one multiplication per nonzero term of its Cayley table
//! and none by constants. The expected counts are derived here, independently of the
//! generator, from dense products of single basis blades; the generated code runs on a
//! scalar that counts its multiplications.
//!
//! `cargo test --test algebra multiplication_counts:: -- --nocapture` prints the table.

use cga_tests::common;

use cga_core::{Multivector, ProductKind, UnaryKind, product_table, unary_table};
use common::{Counted, grade_at};

const EPS: f64 = 1e-12;

/// The storage-basis blade at canonical index `i`, as a dense multivector.
fn blade(i: usize) -> Multivector {
    let mut c = [0.0; 32];
    c[i] = 1.0;
    Multivector::from_storage(&c)
}

/// Nonzero storage-basis coefficients of a dense multivector, by canonical index.
fn support(m: &Multivector) -> Vec<usize> {
    m.to_storage().iter().enumerate().filter(|(_, c)| c.abs() > EPS).map(|(i, _)| i).collect()
}

fn dense(kind: ProductKind, a: Multivector, b: Multivector) -> Multivector {
    use cga_core::{
        CommutatorProduct, GeometricProduct, InnerProduct, LeftContraction, OuterProduct, RegressiveProduct,
        RightContraction,
    };
    match kind {
        ProductKind::Geometric | ProductKind::Sandwich => a.gp(b),
        ProductKind::ScalarProduct => a.gp(b).grade(0),
        ProductKind::Commutator => a.commutator(b),
        ProductKind::Outer => a.wedge(b),
        ProductKind::Inner => a.inner(b),
        ProductKind::LeftContraction => a.lc(b),
        ProductKind::RightContraction => a.rc(b),
        ProductKind::Regressive => a.vee(b),
    }
}

/// Nonzero (lhs blade, rhs blade, output blade) triples of a product, outputs limited to `keep`.
fn table_terms(kind: ProductKind, lhs: &[usize], rhs: &[usize], keep: impl Fn(usize) -> bool) -> (usize, Vec<usize>) {
    let mut terms = 0;
    let mut outputs = Vec::new();
    for &i in lhs {
        for &j in rhs {
            for k in support(&dense(kind, blade(i), blade(j))).into_iter().filter(|&k| keep(k)) {
                terms += 1;
                if !outputs.contains(&k) {
                    outputs.push(k);
                }
            }
        }
    }
    (terms, outputs)
}

/// Expected multiplications: table terms; for a sandwich, `V X` in full, then `(V X) Ṽ` on
/// the grades of X.
fn expected_product_terms(kind: ProductKind, lhs: &[usize], rhs: &[usize]) -> usize {
    if kind != ProductKind::Sandwich {
        return table_terms(kind, lhs, rhs, |_| true).0;
    }
    let (stage1, mids) = table_terms(ProductKind::Geometric, lhs, rhs, |_| true);
    let grades: Vec<usize> = rhs.iter().map(|&i| grade_at(i)).collect();
    let (stage2, _) = table_terms(ProductKind::Geometric, &mids, lhs, |k| grades.contains(&grade_at(k)));
    stage1 + stage2
}

fn counted_input(seed: usize) -> [Counted; 32] {
    std::array::from_fn(|i| Counted::data(1.0 + ((i + seed) % 7) as f64 / 8.0))
}

#[test]
fn products_do_one_multiplication_per_table_term() {
    let (a, b) = (counted_input(0), counted_input(3));
    let mut rows = Vec::new();
    for e in product_table::<Counted>() {
        Counted::reset();
        let _ = (e.eval)(&a, &b);
        let (data, constant) = Counted::counts();
        let expected = expected_product_terms(e.kind, e.lhs_blades, e.rhs_blades);
        assert_eq!(constant, 0, "{:?} {} x {}: multiplications by constants", e.kind, e.lhs, e.rhs);
        assert_eq!(
            data, expected,
            "{:?} {} x {}: {data} multiplications, table has {expected} terms",
            e.kind, e.lhs, e.rhs
        );
        assert_eq!(e.terms, expected, "{:?} {} x {}: registry says {}", e.kind, e.lhs, e.rhs, e.terms);
        let dense_terms = e.lhs_blades.len() * e.rhs_blades.len();
        rows.push(format!("| {:?} | {} | {} | {} | {data} | {dense_terms} |", e.kind, e.lhs, e.rhs, e.output));
    }
    println!("| product | lhs | rhs | output | multiplications | operand pairs |");
    println!("|---|---|---|---|---|---|");
    for row in &rows {
        println!("{row}");
    }
    println!("{} generated products", rows.len());
    assert!(rows.len() > 500);
}

#[test]
fn unary_maps_multiply_only_for_the_norm() {
    let a = counted_input(1);
    for e in unary_table::<Counted>() {
        Counted::reset();
        let _ = (e.eval)(&a);
        let (data, constant) = Counted::counts();
        assert_eq!(constant, 0, "{:?} of {}: multiplications by constants", e.kind, e.input);
        let expected = match e.kind {
            UnaryKind::NormSquared => norm_terms(e.input_blades),
            _ => 0,
        };
        assert_eq!(data, expected, "{:?} of {}: {data} multiplications, expected {expected}", e.kind, e.input);
        println!("| {:?} | {} | {} | {data} |", e.kind, e.input, e.output);
    }
}

/// Unordered blade pairs {i, j} with a nonzero merged coefficient in `⟨A Ã⟩₀`.
fn norm_terms(blades: &[usize]) -> usize {
    use cga_core::GeometricProduct;
    let scalar = |i: usize, j: usize| blade(i).gp(blade(j).reverse()).coeffs[0];
    let mut n = 0;
    for (x, &i) in blades.iter().enumerate() {
        for &j in &blades[x..] {
            let c = if i == j { scalar(i, i) } else { scalar(i, j) + scalar(j, i) };
            if c.abs() > EPS {
                n += 1;
            }
        }
    }
    n
}
