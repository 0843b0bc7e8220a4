//! Shared helpers for the workspace tests: the golden vectors, tolerances, counting scalar.
#![allow(dead_code)]

pub mod dd;

use cga_core::{Multivector, Real};
use serde_json::Value;
use std::path::PathBuf;

/// `tests/golden`: clifford's vectors, carried by the repository (see PROVENANCE.md there).
pub fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("golden")
}

/// A golden file, parsed; its blade order is checked against [`Multivector::BLADES`].
pub fn golden(name: &str) -> Value {
    let path = golden_dir().join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let value: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("parsing {}: {e}", path.display()));
    let blades: Vec<&str> = value["blades"].as_array().expect("blades").iter().map(|b| b.as_str().unwrap()).collect();
    assert_eq!(blades, Multivector::<f64>::BLADES, "{name}: blade order differs from the dense type's");
    value
}

/// The cases of a golden file.
pub fn cases(file: &Value) -> &Vec<Value> {
    file["cases"].as_array().expect("cases")
}

/// A 32-float golden multivector as a dense one.
pub fn mv(v: &Value) -> Multivector {
    let c: Vec<f64> = v.as_array().expect("multivector").iter().map(|x| x.as_f64().unwrap()).collect();
    Multivector::new(c.try_into().expect("32 coefficients"))
}

/// A float list (a Euclidean vector) from a golden file.
pub fn floats(v: &Value) -> Vec<f64> {
    v.as_array().expect("list").iter().map(|x| x.as_f64().unwrap()).collect()
}

/// Grade of the blade at canonical index `i` of a 32-coefficient array (canonical order is
/// by grade, in either basis).
pub fn grade_at(i: usize) -> usize {
    [0, 1, 6, 16, 26, 31, 32].iter().position(|&start| start > i).expect("index < 32") - 1
}

/// Largest coefficient difference, relative to the larger magnitude when that exceeds 1.
pub fn max_rel_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs() / x.abs().max(y.abs()).max(1.0)).fold(0.0, f64::max)
}

/// Asserts two dense multivectors agree to `tol`: absolutely below magnitude 1, relatively
/// above (the generated `approx::RelativeEq`, coefficient by coefficient).
#[track_caller]
pub fn assert_mv_close(got: &Multivector, want: &Multivector, tol: f64, what: &str) {
    let d = max_rel_diff(&got.coeffs, &want.coeffs);
    assert!(
        approx::relative_eq!(*got, *want, epsilon = tol, max_relative = tol),
        "{what}: differs by {d:e} (> {tol:e})\n got  {:?}\n want {:?}",
        got.coeffs,
        want.coeffs
    );
}

/// A seeded stream (the `rand_xorshift` crate), so random tests are repeatable, with the
/// draws the tests use.
pub struct Rng(rand_xorshift::XorShiftRng);

impl Rng {
    /// The stream of `seed`.
    pub fn new(seed: u64) -> Self {
        Rng(rand::SeedableRng::seed_from_u64(seed))
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        rand::RngExt::random::<f64>(&mut self.0)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// A point with coordinates uniform in [lo, hi).
    pub fn e3(&mut self, lo: f64, hi: f64) -> [f64; 3] {
        [self.range(lo, hi), self.range(lo, hi), self.range(lo, hi)]
    }
    /// A unit vector, uniform over directions.
    pub fn direction(&mut self) -> [f64; 3] {
        loop {
            let v = self.e3(-1.0, 1.0);
            let n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if n2 > 1e-4 && n2 <= 1.0 {
                return v.map(|x| x / n2.sqrt());
            }
        }
    }
    /// `10^u`, `u` uniform in `[lo, hi)`: log-uniform between `10^lo` and `10^hi`.
    pub fn decades(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.range(lo, hi))
    }
}

/// Same as [`Real`] for `f64`, but counts multiplications: between two data values, and
/// by a constant (a value made by `from_f64`, `zero` or `one`).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Counted {
    pub x: f64,
    pub constant: bool,
}

thread_local! {
    static COUNTS: std::cell::Cell<(usize, usize)> = const { std::cell::Cell::new((0, 0)) };
}

impl Counted {
    pub fn data(x: f64) -> Self {
        Counted { x, constant: false }
    }
    /// Zeroes the counters.
    pub fn reset() {
        COUNTS.with(|c| c.set((0, 0)));
    }
    /// (data × data, by-constant) multiplications since the last reset.
    pub fn counts() -> (usize, usize) {
        COUNTS.with(|c| c.get())
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl std::ops::$tr for Counted {
            type Output = Counted;
            fn $m(self, o: Counted) -> Counted {
                Counted { x: self.x $op o.x, constant: self.constant && o.constant }
            }
        }
    };
}
binop!(Add, add, +);
binop!(Sub, sub, -);
binop!(Div, div, /);

impl std::ops::Mul for Counted {
    type Output = Counted;
    fn mul(self, o: Counted) -> Counted {
        COUNTS.with(|c| {
            let (data, constant) = c.get();
            c.set(if self.constant || o.constant { (data, constant + 1) } else { (data + 1, constant) });
        });
        Counted { x: self.x * o.x, constant: self.constant && o.constant }
    }
}

impl std::ops::Neg for Counted {
    type Output = Counted;
    fn neg(self) -> Counted {
        Counted { x: -self.x, ..self }
    }
}

impl Real for Counted {
    fn zero() -> Self {
        Counted { x: 0.0, constant: true }
    }
    fn one() -> Self {
        Counted { x: 1.0, constant: true }
    }
    fn from_f64(x: f64) -> Self {
        Counted { x, constant: true }
    }
    fn to_f64(self) -> f64 {
        self.x
    }
    fn sqrt(self) -> Self {
        Counted { x: self.x.sqrt(), ..self }
    }
    fn abs(self) -> Self {
        Counted { x: self.x.abs(), ..self }
    }
    fn is_finite(self) -> bool {
        self.x.is_finite()
    }
    fn epsilon() -> Self {
        Counted { x: f64::EPSILON, constant: true }
    }
    fn sin(self) -> Self {
        Counted { x: self.x.sin(), ..self }
    }
    fn cos(self) -> Self {
        Counted { x: self.x.cos(), ..self }
    }
    fn atan2(self, x: Self) -> Self {
        Counted { x: self.x.atan2(x.x), constant: self.constant && x.constant }
    }
    fn exp(self) -> Self {
        Counted { x: self.x.exp(), ..self }
    }
    fn ln(self) -> Self {
        Counted { x: self.x.ln(), ..self }
    }
}

/// The point at angle θ on a circle (from the perpendicular of its normal).
#[allow(dead_code)]
pub fn on_circle(c: &cga_core::Circle, theta: f64) -> cga_core::euclid::E3 {
    use cga_core::euclid::{add, cross, perpendicular, scale};
    let (centre, normal, r) = c.centre_normal_radius().unwrap();
    let u = perpendicular(normal);
    let v = cross(normal, u);
    add(centre, add(scale(u, r * theta.cos()), scale(v, r * theta.sin())))
}

/// `tests/data/far_objects.json` (made by `tools/far_objects.py`, mpmath 50 digits): the
/// golden files' families (`objects`, `line_sphere`, `conformal`, `rotors`) with the same keys,
/// far from the origin and exact for their f64 inputs.
pub fn far_objects() -> Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/far_objects.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let value: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("parsing {}: {e}", path.display()));
    let blades: Vec<&str> = value["blades"].as_array().expect("blades").iter().map(|b| b.as_str().unwrap()).collect();
    assert_eq!(blades, Multivector::<f64>::BLADES, "far_objects.json: blade order differs from the dense type's");
    value
}

/// What a golden comparison is against, and so whose error its tolerance holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// clifford 1.5.1 (float64): its own error at the case's scale plus ours.
    Clifford,
    /// The 50-digit mpmath reference: ours only.
    Exact,
}

/// A tolerance `ε (k (1 + ρ)^p)` in units of a quantity's own magnitude, for us and for
/// clifford; `ρ` is the case's |position| / size.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    pub ours: (f64, i32),
    pub clifford: (f64, i32),
}

impl Model {
    /// The bound in units of `ε` times the quantity's magnitude.
    pub fn bound(&self, reference: Reference, rho: f64) -> f64 {
        let term = |(k, p): (f64, i32)| k * (1.0 + rho).powi(p);
        term(self.ours) + if reference == Reference::Clifford { term(self.clifford) } else { 0.0 }
    }
}

/// `max |a − b| / (ε max |b|)`: a multivector's error in units of rounding its largest
/// coefficient.
pub fn mv_ulps(got: &Multivector, want: &Multivector) -> f64 {
    let size = want.coeffs.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    got.coeffs.iter().zip(&want.coeffs).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / (f64::EPSILON * size)
}

/// `a ≤ b`, false when either is NaN.
pub fn at_most(a: f64, b: f64) -> bool {
    a <= b
}

/// Worst error / tolerance per quantity over a file, and every case over its tolerance.
pub struct Ratios {
    title: String,
    reference: Reference,
    worst: std::collections::BTreeMap<&'static str, (f64, String)>,
    failures: Vec<String>,
}

impl Ratios {
    pub fn new(title: &str, reference: Reference) -> Self {
        Ratios { title: title.into(), reference, worst: Default::default(), failures: vec![] }
    }
    /// Records `err` (in units of `ε` times the quantity's magnitude) against `model` at `rho`.
    pub fn check(&mut self, what: &'static str, model: Model, rho: f64, err: f64, case: &str) {
        let bound = model.bound(self.reference, rho);
        let ratio = err / bound;
        let entry = self.worst.entry(what).or_insert((0.0, String::new()));
        if !at_most(ratio, entry.0) {
            *entry = (ratio, case.to_string());
        }
        if !at_most(err, bound) {
            self.failures.push(format!("{case}: {what} off by {err:.3e} ε > {bound:.3e} ε (ρ = {rho:.3e})"));
        }
    }
    /// Records a failure outright.
    pub fn fail(&mut self, case: &str, msg: impl std::fmt::Display) {
        self.failures.push(format!("{case}: {msg}"));
    }
    /// Prints the worst ratios (see them with `--nocapture`) and fails on any case over.
    pub fn finish(self) {
        println!("{} ({:?}): worst error / tolerance", self.title, self.reference);
        for (what, (ratio, case)) in &self.worst {
            println!("  {what:<40} {ratio:9.3e}  ({case})");
        }
        assert!(
            self.failures.is_empty(),
            "{}: {} failures:\n{}",
            self.title,
            self.failures.len(),
            self.failures.join("\n")
        );
    }
}

/// `cga_algebras::pga`'s storage blades, position by position: the canonical ones spelled as
/// it declares them, and the sign of each spelling (`e31 = −e13`).
#[allow(dead_code)]
pub const PGA_STORAGE: [(&str, f64); 16] = [
    ("s", 1.0),
    ("e0", 1.0),
    ("e1", 1.0),
    ("e2", 1.0),
    ("e3", 1.0),
    ("e01", 1.0),
    ("e02", 1.0),
    ("e03", 1.0),
    ("e12", 1.0),
    ("e31", -1.0),
    ("e23", 1.0),
    ("e021", -1.0),
    ("e013", 1.0),
    ("e032", -1.0),
    ("e123", 1.0),
    ("e0123", 1.0),
];
