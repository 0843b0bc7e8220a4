//! Facts the READMEs state that a test can check: how many products and sandwiches the
//! generator emits, and how many pairs × products it leaves out as identically zero.

use cga_core::{ProductKind, product_table};

fn read(path: &str) -> String {
    std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path)).unwrap()
}

#[test]
fn the_readmes_state_the_generated_counts() {
    // The READMEs count the five products of the operators and `lc` (not `rc`, the commutator
    // or the scalar product, which the registry lists too).
    use ProductKind::{Commutator, RightContraction, Sandwich, ScalarProduct};
    let table = product_table::<f64>();
    let sandwiches = table.iter().filter(|e| e.kind == Sandwich).count();
    let products =
        table.iter().filter(|e| !matches!(e.kind, Sandwich | Commutator | ScalarProduct | RightContraction)).count();
    let types: std::collections::BTreeSet<&str> = table.iter().flat_map(|e| [e.lhs, e.rhs]).collect();
    let zero = types.len() * types.len() * 5 - products;
    let with_commas = |n: usize| {
        let s = n.to_string();
        if s.len() > 3 { format!("{},{}", &s[..s.len() - 3], &s[s.len() - 3..]) } else { s }
    };
    let readme = read("README.md").replace('\n', " ");
    let want = format!("every generated product ({} of them, plus {sandwiches} sandwiches)", with_commas(products));
    assert!(readme.contains(&want), "README.md should say: {want}");
    let benches = read("benches/README.md").replace('\n', " ");
    for want in [
        format!("{} products ({zero} pairs × products are identically zero", with_commas(products)),
        format!("{sandwiches} sandwiches"),
    ] {
        assert!(benches.contains(&want), "benches/README.md should say: {want}");
    }
}
