//! The generator's counts, owned here: how many products and sandwiches it emits for
//! cga-core, and how many pairs × products it leaves out as identically zero. The docs that
//! state them (`docs/TESTS.md`, `benches/README.md`) are checked to hold each number, not
//! their wording.

use cga_core::{ProductKind, product_table};

/// Products of the operators and `lc` (not `rc`, the commutator or the scalar product,
/// which the registry lists too).
const PRODUCTS: usize = 1447;
/// Sandwiches of every versor with every type.
const SANDWICHES: usize = 114;
/// Pairs of types × those five products whose table is identically zero (not emitted).
const ZERO: usize = 358;

/// `n` as the docs write it, with a comma between thousands.
fn with_commas(n: usize) -> String {
    let s = n.to_string();
    if s.len() > 3 { format!("{},{}", &s[..s.len() - 3], &s[s.len() - 3..]) } else { s }
}

#[test]
fn the_generated_counts_are_the_stated_ones() {
    use ProductKind::{Commutator, RightContraction, Sandwich, ScalarProduct};
    let table = product_table::<f64>();
    let sandwiches = table.iter().filter(|e| e.kind == Sandwich).count();
    let products =
        table.iter().filter(|e| !matches!(e.kind, Sandwich | Commutator | ScalarProduct | RightContraction)).count();
    let types: std::collections::BTreeSet<&str> = table.iter().flat_map(|e| [e.lhs, e.rhs]).collect();
    let zero = types.len() * types.len() * 5 - products;
    assert_eq!((products, sandwiches, zero), (PRODUCTS, SANDWICHES, ZERO));
    for (doc, numbers) in
        [("docs/TESTS.md", vec![PRODUCTS, SANDWICHES]), ("benches/README.md", vec![PRODUCTS, ZERO, SANDWICHES])]
    {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(doc);
        let text = std::fs::read_to_string(&path).unwrap().replace('\n', " ");
        for n in numbers {
            assert!(text.contains(&with_commas(n)), "{doc} should state {}", with_commas(n));
        }
    }
}
