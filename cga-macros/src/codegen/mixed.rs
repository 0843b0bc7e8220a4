//! Grade-mixed types the generator declares by itself: where no declared type (and no dense
//! type) holds the result of a product, sandwich, dual or grade part, a type holding every
//! blade of the result's grades, named after them (`Grades1_3`, `Grade2`), so that the
//! result type of every map follows from the grades alone.

use super::*;
use crate::model::TypeModel;
use std::collections::BTreeSet;

/// The largest grade-mixed type declared automatically, in blades: G(4,1)'s whole algebra.
/// Beyond it every product with the type is a large table (G(9,1)'s grades 0, 2, 4 and 6
/// hold 466 blades); such results stay ungenerated, named in the `# Products` tables.
pub(super) const MAX_MIXED: usize = 32;

impl Gen<'_> {
    /// The grade sets of the results no declared type holds, with the maps that need each.
    fn missing_grades(&self) -> BTreeMap<Vec<u32>, Vec<String>> {
        let mut missing: BTreeMap<Vec<u32>, Vec<String>> = BTreeMap::new();
        let types = &self.spec.types;
        let mut need = |outs: &[usize], what: String| {
            if self.target_for(outs).is_none() {
                let grades: BTreeSet<u32> = outs.iter().map(|b| b.count_ones()).collect();
                missing.entry(grades.into_iter().collect()).or_default().push(what);
            }
        };
        for u in &self.uncovered {
            let outs: Vec<usize> = (0..self.dim).filter(|b| u.grades.contains(&b.count_ones())).collect();
            let what = format!("`{}` of `{}` and `{}`", names(u.kind).formula, types[u.lhs].ident, types[u.rhs].ident);
            need(&outs, what);
        }
        for v in types.iter().filter(|t| t.model.versor) {
            for x in types {
                let (_, stage2) = self.sandwich_stages(v, x);
                let outs: Vec<usize> = stage2.iter().map(|(b, _)| *b).collect();
                if !outs.is_empty() {
                    need(&outs, format!("the sandwich of `{}` by `{}`", x.ident, v.ident));
                }
            }
        }
        for t in types {
            for (kind, name) in [(Unary::Dual, "dual"), (Unary::Undual, "undual")] {
                let outs: BTreeSet<usize> =
                    t.model.blades.iter().flat_map(|&b| self.a.unary(kind, b).into_keys()).collect();
                let outs: Vec<usize> = outs.into_iter().collect();
                need(&outs, format!("the {name} of `{}`", t.ident));
            }
            for (k, blades) in self.grades_of(t) {
                need(&blades, format!("the grade-{k} part of `{}`", t.ident));
            }
        }
        missing
    }

    /// The types to add: one per grade set of [`Gen::missing_grades`] with at most
    /// [`MAX_MIXED`] blades and a name no declared item has.
    pub(super) fn mixed_types(&self) -> Vec<TypeSpec> {
        if self.spec.dense.is_some() {
            // Every result has a type: the dense one.
            return Vec::new();
        }
        let taken: Vec<String> = (self.spec.types.iter().map(|t| t.ident.to_string()))
            .chain(self.spec.aliases.iter().map(|a| a.name.to_string()))
            .chain(self.spec.dense.iter().map(|d| d.name.to_string()))
            .collect();
        let mut out = Vec::new();
        for (grades, uses) in self.missing_grades() {
            let blades: Vec<usize> =
                self.a.canonical_order().into_iter().filter(|b| grades.contains(&b.count_ones())).collect();
            let list: Vec<String> = grades.iter().map(u32::to_string).collect();
            let name = match grades.as_slice() {
                [k] => format!("Grade{k}"),
                _ => format!("Grades{}", list.join("_")),
            };
            if blades.len() > MAX_MIXED || taken.contains(&name) {
                continue;
            }
            let doc = format!(
                " Declared by `algebra!` itself: every blade of grade {}, the result of {} (no declared type \
                 holds it).",
                list.join(" and "),
                uses.join(", ")
            );
            out.push(TypeSpec {
                model: TypeModel { blades, versor: false },
                generated: true,
                ident: format_ident!("{name}"),
                attrs: vec![syn::parse_quote!(#[doc = #doc])],
            });
        }
        out
    }
}
