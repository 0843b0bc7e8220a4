//! The algebra at expansion time: metric, blades, change of basis and product tables.
//!
//! Plain data in, plain data out; nothing here knows about `syn`. Every table is computed
//! in an orthonormal basis `e1..en` (diagonal metric, one blade per product of two blades)
//! and carried to the storage basis through the outermorphism of the basis change, so a
//! non-diagonal metric such as the null basis `eo, ei` of CGA costs nothing at run time.

use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};

/// Coefficients smaller than this are taken as exact zeros: every table entry is a small
/// dyadic rational (the change of basis only involves halves), so real entries are far
/// larger and rounding residues far smaller.
const ZERO: f64 = 1e-9;

/// A multivector during expansion: blade bitmask -> coefficient, zero entries removed.
pub type Mv = BTreeMap<usize, f64>;

/// The products the generator emits for every pair of types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Product {
    /// `A B`
    Geometric,
    /// `A ∧ B`: grade r + s of `A_r B_s`.
    Outer,
    /// Hestenes inner product `A · B`: grade |r − s| of `A_r B_s`, zero if r or s is 0.
    Inner,
    /// Left contraction `A ⌋ B`: grade s − r of `A_r B_s`, zero if r > s.
    LeftContraction,
    /// Right contraction `A ⌊ B`: grade r − s of `A_r B_s`, zero if s > r.
    RightContraction,
    /// Regressive product `A ∨ B = ∁⁻¹(∁A ∧ ∁B)`, `∁` the metric-free right complement
    /// (`e_S ∧ ∁e_S = I`): the meet of OPNS objects. It equals `undual(dual A ∧ dual B)`
    /// with `dual(X) = X I⁻¹` up to a sign that depends only on the grades.
    Regressive,
    /// Commutator product `A × B = ½(A B − B A)`. For orthonormal blades `e_a e_b = ±e_b e_a`,
    /// so each entry is the geometric product's where the blades anticommute, else zero.
    Commutator,
}

impl Product {
    pub const ALL: [Product; 7] = [
        Product::Geometric,
        Product::Outer,
        Product::Inner,
        Product::LeftContraction,
        Product::RightContraction,
        Product::Regressive,
        Product::Commutator,
    ];
}

/// Linear maps of one multivector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unary {
    /// `Ã`: grade k scaled by (−1)^(k(k−1)/2).
    Reverse,
    /// `Â`: grade k scaled by (−1)^k.
    Involute,
    /// `Ā = (Â)~`: grade k scaled by (−1)^(k(k+1)/2).
    Conjugate,
    /// `A I⁻¹`.
    Dual,
    /// `A I`, the inverse of [`Unary::Dual`].
    Undual,
}

/// A product table's key: the product and the blades of its two operands.
type TableKey = (Product, Vec<usize>, Vec<usize>);

/// The algebra: an orthonormal signature and a storage basis expressed in it.
#[derive(Clone, Debug)]
pub struct Algebra {
    /// Number of basis vectors.
    pub n: usize,
    /// Squares of the orthonormal vectors `e1..en`: +1 (the first p), −1 (the next q), 0
    /// (the last r, null).
    pub metric: Vec<f64>,
    /// The label of each storage vector, its name after `e` (`e1` → "1", `einf` → "inf").
    pub labels: Vec<String>,
    /// Storage blade (bitmask over storage vectors) → orthonormal multivector.
    to_ortho: Vec<Mv>,
    /// Orthonormal blade → storage multivector.
    from_ortho: Vec<Mv>,
    /// Every blade in canonical order, and each blade's position in it.
    order: Vec<usize>,
    rank: Vec<usize>,
    /// Blades declared with their labels out of basis order (`e31`): name and sign relative
    /// to the canonical blade (`e31 = −e13`). The sign is folded into `to_ortho` and
    /// `from_ortho`, so every table treats the declared blade as the storage blade.
    spelled: BTreeMap<usize, String>,
    /// Every table [`Algebra::bilinear`] has built, so that planning again with more types
    /// (the grade-mixed ones) rebuilds none; cloned with the algebra.
    tables: RefCell<HashMap<TableKey, Bilinear>>,
}

/// Why an algebra cannot be built.
#[derive(Debug, PartialEq)]
pub enum ModelError {
    /// The storage vectors are linearly dependent.
    DegenerateBasis,
    /// A coefficient of the basis or of its inverse is not finite or too large to tabulate.
    NonFinite,
}

impl Algebra {
    /// An algebra of signature (p, q, r) whose storage vectors are `basis[a] = Σ_i B[a][i] e_i`.
    pub fn new([p, q, r]: [usize; 3], labels: Vec<String>, basis: Vec<Vec<f64>>) -> Result<Self, ModelError> {
        let n = p + q + r;
        let metric: Vec<f64> = (0..n)
            .map(|i| {
                if i < p {
                    1.0
                } else if i < p + q {
                    -1.0
                } else {
                    0.0
                }
            })
            .collect();
        let finite = |m: &[Vec<f64>]| m.iter().flatten().all(|x| x.is_finite() && x.abs() <= 1e100);
        if !finite(&basis) {
            return Err(ModelError::NonFinite);
        }
        let inverse = invert(&basis).ok_or(ModelError::DegenerateBasis)?;
        if !finite(&inverse) {
            return Err(ModelError::NonFinite);
        }
        let to_ortho = (0..1 << n).map(|m| outermorphism(m, &basis)).collect();
        let from_ortho = (0..1 << n).map(|m| outermorphism(m, &inverse)).collect();
        let mut order: Vec<usize> = (0..1 << n).collect();
        order.sort_by_cached_key(|&m| (m.count_ones(), index_tuple(m)));
        let mut rank = vec![0; order.len()];
        for (pos, &m) in order.iter().enumerate() {
            rank[m] = pos;
        }
        Ok(Algebra {
            n,
            metric,
            labels,
            to_ortho,
            from_ortho,
            order,
            rank,
            spelled: BTreeMap::new(),
            tables: RefCell::default(),
        })
    }

    /// Number of blades, 2^n.
    pub fn dim(&self) -> usize {
        1 << self.n
    }

    /// All blades in canonical order: by grade, then lexicographically by vector index
    /// (`1, e1, …, en, e12, e13, …`), the order of the golden files.
    pub fn canonical_order(&self) -> Vec<usize> {
        self.order.clone()
    }

    /// Name of a storage blade: `s` for the scalar, its declared spelling, else `e` and the
    /// vector labels in basis order.
    pub fn blade_name(&self, mask: usize) -> String {
        if mask == 0 {
            return "s".into();
        }
        if let Some(name) = self.spelled.get(&mask) {
            return name.clone();
        }
        self.canonical_name(mask)
    }

    /// `e` and the vector labels in basis order, whatever the declared spelling.
    pub fn canonical_name(&self, mask: usize) -> String {
        let labels: String = (0..self.n).filter(|i| mask >> i & 1 == 1).map(|i| self.labels[i].as_str()).collect();
        format!("e{labels}")
    }

    /// Name of an orthonormal blade (`1`, `e1`, `e12`, …) as the golden files write it.
    pub fn ortho_name(&self, mask: usize) -> String {
        if mask == 0 {
            return "1".into();
        }
        let digits: String = (0..self.n).filter(|i| mask >> i & 1 == 1).map(|i| (i + 1).to_string()).collect();
        format!("e{digits}")
    }

    /// The storage blade named `name`: its declared spelling, or the canonical name (labels
    /// in basis order, read one way only) of a blade not spelled otherwise.
    pub fn parse_blade(&self, name: &str) -> Option<usize> {
        if name == "s" {
            return Some(0);
        }
        if let Some((&mask, _)) = self.spelled.iter().find(|(_, n)| *n == name) {
            return Some(mask);
        }
        let rest = name.strip_prefix('e')?;
        match self.label_parses(rest, true).as_slice() {
            [one] => Some(one.iter().fold(0, |m, &i| m | 1 << i)).filter(|m| !self.spelled.contains_key(m)),
            _ => None,
        }
    }

    /// A name whose labels are distinct basis labels in some order (`e31`), read one way
    /// only: its blade and the sign relative to the canonical blade (`e31 = −e13`: −1, one
    /// swap of anticommuting vectors per pair out of order).
    pub fn permuted_blade(&self, name: &str) -> Option<(usize, f64)> {
        let rest = name.strip_prefix('e')?;
        let [positions] = self.label_parses(rest, false).try_into().ok()?;
        let swaps: usize =
            (0..positions.len()).map(|i| positions[i + 1..].iter().filter(|&&j| j < positions[i]).count()).sum();
        let mask = positions.iter().fold(0, |m, &i| m | 1 << i);
        Some((mask, if swaps.is_multiple_of(2) { 1.0 } else { -1.0 }))
    }

    /// Declare blade `mask` as `name = sign · (canonical blade)`: its coefficient is then the
    /// one of `name`, and every table carries the sign (a diagonal change of storage basis).
    pub fn respell(&mut self, mask: usize, name: String, sign: f64) {
        if sign < 0.0 {
            self.to_ortho[mask].values_mut().for_each(|c| *c = -*c);
            for image in &mut self.from_ortho {
                if let Some(c) = image.get_mut(&mask) {
                    *c = -*c;
                }
            }
        }
        self.spelled.insert(mask, name);
    }

    /// The sign of a declared spelling relative to the canonical blade (+1 if none).
    pub fn spelling_sign(&self, mask: usize) -> f64 {
        self.spelled.get(&mask).and_then(|n| self.permuted_blade(n)).map_or(1.0, |(_, s)| s)
    }

    /// The ways `rest` reads as distinct labels (vector indices, in the order written), at
    /// most two; with `increasing`, only those in basis order.
    pub fn label_parses(&self, rest: &str, increasing: bool) -> Vec<Vec<usize>> {
        fn walk(a: &Algebra, rest: &str, increasing: bool, path: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
            if out.len() >= 2 {
                return;
            }
            if rest.is_empty() {
                if !path.is_empty() {
                    out.push(path.clone());
                }
                return;
            }
            for (i, label) in a.labels.iter().enumerate() {
                let fresh = !path.contains(&i) && (!increasing || path.last().is_none_or(|&l| i > l));
                if let Some(tail) = rest.strip_prefix(label.as_str()).filter(|_| fresh) {
                    path.push(i);
                    walk(a, tail, increasing, path, out);
                    path.pop();
                }
            }
        }
        let mut out = Vec::new();
        walk(self, rest, increasing, &mut Vec::new(), &mut out);
        out
    }

    /// A blade whose canonical name also reads as another blade's, if the labels allow one
    /// (`1`, `2` and `12` make `e12` two blades).
    pub fn ambiguous_blade(&self) -> Option<String> {
        (1..self.dim()).map(|m| self.canonical_name(m)).find(|name| self.label_parses(&name[1..], true).len() != 1)
    }

    /// Blades of grade `k` in canonical order.
    pub fn grade_blades(&self, k: usize) -> Vec<usize> {
        self.order.iter().copied().filter(|m| m.count_ones() as usize == k).collect()
    }

    /// Orthonormal-basis product of two orthonormal blades, `None` when it vanishes.
    pub fn ortho_product(&self, kind: Product, a: usize, b: usize) -> Option<(usize, f64)> {
        let (ga, gb) = (a.count_ones() as i64, b.count_ones() as i64);
        let out = a ^ b;
        let go = out.count_ones() as i64;
        let keep = match kind {
            Product::Geometric => true,
            Product::Outer => a & b == 0,
            Product::Inner => ga > 0 && gb > 0 && go == (ga - gb).abs(),
            Product::LeftContraction => ga <= gb && go == gb - ga,
            Product::RightContraction => gb <= ga && go == ga - gb,
            Product::Regressive => {
                // ∁⁻¹(∁a ∧ ∁b) with the right complement e_S ∧ ∁e_S = I (metric-free).
                let full = self.full_mask();
                let (ca, cb) = (a ^ full, b ^ full);
                let (w, sw) = wedge_blades(ca, cb)?;
                let r = w ^ full;
                let sign = complement_sign(a, full) * complement_sign(b, full) * sw * complement_sign(r, full);
                return Some((r, sign * self.orientation()));
            }
            Product::Commutator => {
                // ½(s − s') with s' = ±s: s where the blades anticommute, nothing where they commute.
                let ((r, s), (_, s_swapped)) = (self.ortho_gp(a, b), self.ortho_gp(b, a));
                return (s != s_swapped && s != 0.0).then_some((r, s));
            }
        };
        // A shared null vector makes the product zero.
        keep.then(|| self.ortho_gp(a, b)).filter(|&(_, s)| s != 0.0)
    }

    /// Whether some basis vector is null: `I² = 0`, so no dual is a product with `I⁻¹`.
    pub fn degenerate(&self) -> bool {
        self.metric.contains(&0.0)
    }

    /// The sign of the unit pseudoscalar `I` the complements are taken against, relative to
    /// the orthonormal `e1 ∧ … ∧ en`: +1, except in a degenerate metric, where `I` has the
    /// orientation of the declared basis (3D PGA's `e0123` with `e0` listed first, as kingdon
    /// and bivector.net take it).
    fn orientation(&self) -> f64 {
        let full = self.full_mask();
        match self.to_ortho[full].get(&full) {
            Some(c) if self.degenerate() && *c < 0.0 => -1.0,
            _ => 1.0,
        }
    }

    /// The dual of an orthonormal blade: `e_S I⁻¹`, or in a degenerate metric the right
    /// complement `∁e_S = σ e_(S^c)` with `e_S ∧ ∁e_S = I` (metric-free: Poincaré duality).
    pub fn ortho_dual(&self, a: usize) -> (usize, f64) {
        let full = self.full_mask();
        if self.degenerate() {
            return (a ^ full, complement_sign(a, full) * self.orientation());
        }
        let (r, s) = self.ortho_gp(a, full);
        (r, s * self.pseudo_inverse_sign())
    }

    /// The inverse of [`Algebra::ortho_dual`]: `e_S I`, or the left complement
    /// `∁⁻¹e_T = σ(T^c) e_(T^c)`.
    pub fn ortho_undual(&self, a: usize) -> (usize, f64) {
        let full = self.full_mask();
        if self.degenerate() {
            return (a ^ full, complement_sign(a ^ full, full) * self.orientation());
        }
        self.ortho_gp(a, full)
    }

    /// `e_a e_b = sign e_(a xor b)` for orthonormal blades: reordering sign times the
    /// squares of the shared vectors.
    pub fn ortho_gp(&self, a: usize, b: usize) -> (usize, f64) {
        let mut sign = reorder_sign(a, b);
        for i in 0..self.n {
            if (a & b) >> i & 1 == 1 {
                sign *= self.metric[i];
            }
        }
        (a ^ b, sign)
    }

    fn full_mask(&self) -> usize {
        self.dim() - 1
    }

    /// I⁻¹ = I / (I I), and I I = ±1: the sign of I⁻¹ relative to I.
    fn pseudo_inverse_sign(&self) -> f64 {
        self.ortho_gp(self.full_mask(), self.full_mask()).1
    }

    /// Storage-basis product of two storage blades.
    pub fn product(&self, kind: Product, a: usize, b: usize) -> Mv {
        let mut ortho = Mv::new();
        for (&i, &ci) in &self.to_ortho[a] {
            for (&j, &cj) in &self.to_ortho[b] {
                if let Some((r, c)) = self.ortho_product(kind, i, j) {
                    *ortho.entry(r).or_insert(0.0) += ci * cj * c;
                }
            }
        }
        self.ortho_to_storage(&ortho)
    }

    /// Storage-basis image of one storage blade under a unary map.
    pub fn unary(&self, kind: Unary, a: usize) -> Mv {
        let k = a.count_ones() as i64;
        let grade_sign = |e: i64| if e % 2 == 0 { 1.0 } else { -1.0 };
        let sign = match kind {
            Unary::Reverse => grade_sign(k * (k - 1) / 2),
            Unary::Involute => grade_sign(k),
            Unary::Conjugate => grade_sign(k * (k + 1) / 2),
            Unary::Dual | Unary::Undual => {
                let mut ortho = Mv::new();
                for (&i, &ci) in &self.to_ortho[a] {
                    let (r, s) = if kind == Unary::Dual { self.ortho_dual(i) } else { self.ortho_undual(i) };
                    *ortho.entry(r).or_insert(0.0) += ci * s;
                }
                return self.ortho_to_storage(&ortho);
            }
        };
        Mv::from([(a, sign)])
    }

    /// Storage blade → coefficients in the orthonormal basis.
    pub fn storage_to_ortho(&self, a: usize) -> &Mv {
        &self.to_ortho[a]
    }

    /// Orthonormal blade → coefficients in the storage basis.
    pub fn ortho_blade_to_storage(&self, i: usize) -> &Mv {
        &self.from_ortho[i]
    }

    fn ortho_to_storage(&self, ortho: &Mv) -> Mv {
        let mut out = Mv::new();
        for (&r, &c) in ortho {
            for (&s, &cs) in &self.from_ortho[r] {
                *out.entry(s).or_insert(0.0) += c * cs;
            }
        }
        clean(out)
    }
}

/// One term `coeff · lhs[i] · rhs[j]` of a bilinear map between two sparse types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Term {
    /// Index into the left operand's blades.
    pub lhs: usize,
    /// Index into the right operand's blades.
    pub rhs: usize,
    pub coeff: f64,
}

/// A bilinear map between sparse operands: each nonzero output blade with its terms, in
/// canonical blade order. Blades whose terms all cancel are absent.
pub type Bilinear = Vec<(usize, Vec<Term>)>;

/// A quadratic form per output blade: blade → monomial `(i, j)` (i ≤ j, indices into the
/// operand's blades) → coefficient.
pub type Quadratic = BTreeMap<usize, BTreeMap<(usize, usize), f64>>;

/// A declared type: a name and the storage blades it holds, in field order.
#[derive(Clone, Debug)]
pub struct TypeModel {
    pub blades: Vec<usize>,
    /// Declared with `versor`: gets a sandwich `V X Ṽ` on every type.
    pub versor: bool,
}

impl Algebra {
    /// The product `kind` of operands holding blades `lhs` and `rhs`, term by term.
    pub fn bilinear(&self, kind: Product, lhs: &[usize], rhs: &[usize]) -> Bilinear {
        let key = (kind, lhs.to_vec(), rhs.to_vec());
        if let Some(table) = self.tables.borrow().get(&key) {
            return table.clone();
        }
        let table = self.tabulate(kind, lhs, rhs);
        self.tables.borrow_mut().insert(key, table.clone());
        table
    }

    fn tabulate(&self, kind: Product, lhs: &[usize], rhs: &[usize]) -> Bilinear {
        let mut outputs: BTreeMap<usize, Vec<Term>> = BTreeMap::new();
        for (i, &a) in lhs.iter().enumerate() {
            for (j, &b) in rhs.iter().enumerate() {
                for (r, coeff) in self.product(kind, a, b) {
                    outputs.entry(r).or_default().push(Term { lhs: i, rhs: j, coeff });
                }
            }
        }
        let rank = self.rank();
        let mut out: Bilinear = outputs.into_iter().collect();
        out.sort_by_key(|(blade, _)| rank[*blade]);
        out
    }

    /// `X X̃` for a type holding `blades`, as polynomials in its coefficients: per output
    /// blade, the coefficient of every monomial `c_i c_j` (i ≤ j, the `(i, j)` and `(j, i)`
    /// terms combined), monomials and blades that cancel removed.
    pub fn reverse_square(&self, blades: &[usize]) -> Quadratic {
        self.square(blades, true)
    }

    /// `X X` (or with `reverse`, `X X̃`) for a type holding `blades`, as polynomials in its
    /// coefficients, as [`Algebra::reverse_square`] gives them.
    pub fn square(&self, blades: &[usize], reverse: bool) -> Quadratic {
        let mut out: Quadratic = BTreeMap::new();
        for (i, &x) in blades.iter().enumerate() {
            for (j, &y) in blades.iter().enumerate() {
                let rev = if reverse { self.unary(Unary::Reverse, y).get(&y).copied().unwrap_or(1.0) } else { 1.0 };
                for (r, c) in self.product(Product::Geometric, x, y) {
                    *out.entry(r).or_default().entry((i.min(j), i.max(j))).or_insert(0.0) += c * rev;
                }
            }
        }
        out.into_iter()
            .map(|(r, poly)| (r, poly.into_iter().filter(|(_, c)| c.abs() > ZERO).collect::<BTreeMap<_, _>>()))
            .filter(|(_, poly)| !poly.is_empty())
            .collect()
    }

    /// Whether every value of a type holding `blades` has `X X̃` a scalar (every other blade's
    /// polynomial identically zero) that is not identically zero itself: then `X⁻¹ = X̃ / ⟨X X̃⟩₀`
    /// wherever `⟨X X̃⟩₀ ≠ 0`.
    pub fn has_reverse_inverse(&self, blades: &[usize]) -> bool {
        let square = self.reverse_square(blades);
        square.contains_key(&0) && square.keys().all(|&r| r == 0)
    }

    /// Position of every blade in canonical order.
    pub fn rank(&self) -> &[usize] {
        &self.rank
    }
}

/// The sign in `∁e_S = sign · e_(S^c)`: `e_S ∧ e_(S^c) = sign · I` read backwards (±1).
fn complement_sign(s: usize, full: usize) -> f64 {
    wedge_blades(s, s ^ full).map_or(1.0, |(_, sign)| sign)
}

/// Drop the zeros left by cancellation.
fn clean(mv: Mv) -> Mv {
    mv.into_iter().filter(|(_, c)| c.abs() > ZERO).collect()
}

/// Vector indices of a blade, for lexicographic ordering.
fn index_tuple(mask: usize) -> Vec<usize> {
    (0..usize::BITS as usize).filter(|i| mask >> i & 1 == 1).collect()
}

/// The metric-free outer product of basis blades given as bitmasks: sign of reordering.
fn wedge_blades(a: usize, b: usize) -> Option<(usize, f64)> {
    (a & b == 0).then(|| (a | b, reorder_sign(a, b)))
}

/// The sign of reordering the vectors of `e_a e_b` into increasing order: (−1)^swaps, a
/// swap for every pair of a vector of `a` above a vector of `b`.
fn reorder_sign(a: usize, b: usize) -> f64 {
    let mut swaps = 0;
    let mut rest = a >> 1;
    while rest != 0 {
        swaps += (rest & b).count_ones();
        rest >>= 1;
    }
    if swaps % 2 == 0 { 1.0 } else { -1.0 }
}

/// Image of a blade under the linear map sending vector `a` to `Σ_i m[a][i] e_i`: the wedge
/// of the images of its vectors (outer products are metric-free).
fn outermorphism(mask: usize, m: &[Vec<f64>]) -> Mv {
    let mut acc = Mv::from([(0usize, 1.0)]);
    for (a, row) in m.iter().enumerate() {
        if mask >> a & 1 == 0 {
            continue;
        }
        let mut next = Mv::new();
        for (&blade, &c) in &acc {
            for (i, &ci) in row.iter().enumerate() {
                if ci == 0.0 {
                    continue;
                }
                if let Some((r, s)) = wedge_blades(blade, 1 << i) {
                    *next.entry(r).or_insert(0.0) += c * ci * s;
                }
            }
        }
        acc = clean(next);
    }
    acc
}

/// Inverse of a square matrix by Gauss–Jordan elimination with partial pivoting; `None`
/// when it is singular. Rows are vectors: `inv[i]` expresses `e_i` in the storage basis.
fn invert(m: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = m.len();
    // Solve X M = I: work on the transpose so that rows stay rows.
    let mut a: Vec<Vec<f64>> = (0..n).map(|i| (0..n).map(|j| m[j][i]).collect()).collect();
    let mut inv: Vec<Vec<f64>> = (0..n).map(|i| (0..n).map(|j| f64::from(u8::from(i == j))).collect()).collect();
    for col in 0..n {
        let pivot = (col..n).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        if a[pivot][col].abs() < ZERO {
            return None;
        }
        a.swap(col, pivot);
        inv.swap(col, pivot);
        let p = a[col][col];
        for j in 0..n {
            a[col][j] /= p;
            inv[col][j] /= p;
        }
        for row in 0..n {
            if row != col {
                let f = a[row][col];
                for j in 0..n {
                    a[row][j] -= f * a[col][j];
                    inv[row][j] -= f * inv[col][j];
                }
            }
        }
    }
    // inv solves Mᵀ X = I, so X = (Mᵀ)⁻¹ = (M⁻¹)ᵀ: transpose back.
    Some((0..n).map(|i| (0..n).map(|j| inv[j][i]).collect()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cga_null() -> Algebra {
        let basis = vec![
            vec![1.0, 0.0, 0.0, 0.0, 0.0],
            vec![0.0, 1.0, 0.0, 0.0, 0.0],
            vec![0.0, 0.0, 1.0, 0.0, 0.0],
            vec![0.0, 0.0, 0.0, -0.5, 0.5],
            vec![0.0, 0.0, 0.0, 1.0, 1.0],
        ];
        Algebra::new([4, 1, 0], ['1', '2', '3', 'o', 'i'].map(String::from).to_vec(), basis).unwrap()
    }

    #[test]
    fn null_vectors_have_the_cga_metric() {
        let a = cga_null();
        let (o, i) = (1 << 3, 1 << 4);
        assert!(a.product(Product::Geometric, o, o).is_empty(), "eo² = 0");
        assert!(a.product(Product::Geometric, i, i).is_empty(), "e∞² = 0");
        let oi = a.product(Product::Geometric, o, i);
        assert_eq!(oi, Mv::from([(0, -1.0), (o | i, 1.0)]), "eo e∞ = −1 + eo∧e∞");
    }

    #[test]
    fn change_of_basis_round_trips() {
        let a = cga_null();
        for m in 0..a.dim() {
            let mut back = Mv::new();
            for (&i, &c) in a.storage_to_ortho(m) {
                for (&s, &cs) in a.ortho_blade_to_storage(i) {
                    *back.entry(s).or_insert(0.0) += c * cs;
                }
            }
            assert_eq!(clean(back), Mv::from([(m, 1.0)]));
        }
    }

    #[test]
    fn singular_basis_is_rejected() {
        let basis = vec![vec![1.0, 1.0], vec![2.0, 2.0]];
        assert_eq!(
            Algebra::new([2, 0, 0], ['a', 'b'].map(String::from).to_vec(), basis).unwrap_err(),
            ModelError::DegenerateBasis
        );
    }

    #[test]
    fn commutator_is_half_the_difference() {
        let a = cga_null();
        for x in 0..a.dim() {
            for y in 0..a.dim() {
                let (xy, yx) = (a.product(Product::Geometric, x, y), a.product(Product::Geometric, y, x));
                let mut want = Mv::new();
                for (&r, &c) in &xy {
                    *want.entry(r).or_insert(0.0) += 0.5 * c;
                }
                for (&r, &c) in &yx {
                    *want.entry(r).or_insert(0.0) -= 0.5 * c;
                }
                assert_eq!(a.product(Product::Commutator, x, y), clean(want), "{x} x {y}");
            }
        }
    }

    #[test]
    fn inverses_by_the_reverse() {
        let a = cga_null();
        let grade = |k| a.grade_blades(k);
        let named = |names: &[&str]| names.iter().map(|n| a.parse_blade(n).unwrap()).collect::<Vec<_>>();
        // Vectors, 4-vectors (every one a blade in 5 dimensions), rotors and translators.
        for blades in [grade(0), grade(1), grade(4), grade(5), named(&["s", "e12", "e13", "e23"])] {
            assert!(a.has_reverse_inverse(&blades), "{blades:?}");
        }
        assert!(a.has_reverse_inverse(&named(&["s", "e1i", "e2i", "e3i"])));
        // Motors (M M̃ = s + p e123i), bivectors, trivectors; ei alone squares to zero.
        let motor = named(&["s", "e12", "e13", "e23", "e1i", "e2i", "e3i", "e123i"]);
        for blades in [motor, grade(2), grade(3), named(&["ei"])] {
            assert!(!a.has_reverse_inverse(&blades), "{blades:?}");
        }
    }

    #[test]
    fn blade_names_parse_back() {
        let a = cga_null();
        for m in 0..a.dim() {
            assert_eq!(a.parse_blade(&a.blade_name(m)), Some(m));
        }
        assert_eq!(a.parse_blade("eo1"), None, "labels out of order");
        let labels = ["1", "2", "3", "o", "inf"].map(String::from).to_vec();
        let cga = Algebra::new(
            [4, 1, 0],
            labels,
            (0..5).map(|i| (0..5).map(|j| f64::from(u8::from(i == j))).collect()).collect(),
        )
        .unwrap();
        assert_eq!(cga.parse_blade("e1oinf"), Some(0b11001));
        assert_eq!(cga.blade_name(0b11001), "e1oinf");
        assert_eq!(cga.ambiguous_blade(), None);
        let clash = Algebra::new(
            [3, 0, 0],
            ["1", "2", "12"].map(String::from).to_vec(),
            vec![vec![1.0, 0.0, 0.0], vec![0.0, 1.0, 0.0], vec![0.0, 0.0, 1.0]],
        );
        assert_eq!(clash.unwrap().ambiguous_blade().as_deref(), Some("e12"), "e1 ∧ e2 or e12");
        assert_eq!(a.parse_blade("e4"), None, "unknown label");
    }

    /// A blade declared out of basis order is a diagonal change of storage basis: every
    /// product and unary map is the canonical one with the spellings' signs applied.
    #[test]
    fn respelled_blades_conjugate_every_table() {
        let canonical = cga_null();
        let mut a = cga_null();
        let mut sign = vec![1.0; a.dim()];
        for name in ["eio", "e31", "e2o1", "e321i"] {
            let (mask, s) = a.permuted_blade(name).unwrap();
            a.respell(mask, name.into(), s);
            sign[mask] = s;
        }
        assert_eq!((sign[0b11000], sign[0b101], sign[0b1011], sign[0b10111]), (-1.0, -1.0, 1.0, -1.0));
        assert_eq!(a.parse_blade("e31"), Some(0b101));
        assert_eq!(a.parse_blade("e13"), None, "one spelling per blade");
        assert_eq!(a.blade_name(0b11000), "eio");
        let signed = |mv: Mv| -> Mv { mv.into_iter().map(|(r, c)| (r, c * sign[r])).collect() };
        for x in 0..a.dim() {
            for y in 0..a.dim() {
                for kind in Product::ALL {
                    let want =
                        signed(canonical.product(kind, x, y)).into_iter().map(|(r, c)| (r, c * sign[x] * sign[y]));
                    assert_eq!(a.product(kind, x, y), want.collect::<Mv>(), "{kind:?} {x} {y}");
                }
            }
            for kind in [Unary::Reverse, Unary::Dual, Unary::Undual] {
                let want = signed(canonical.unary(kind, x)).into_iter().map(|(r, c)| (r, c * sign[x]));
                assert_eq!(a.unary(kind, x), want.collect::<Mv>(), "{kind:?} {x}");
            }
        }
    }
}
