//! The products users batch most, in every algebra of the package (CGA, PGA, 2D CGA, VGA,
//! STA: each asks `algebra!` for lanes), on SIMD lanes: each is compiled as a cga-core
//! [`Kernel`] (four or eight rows at once, the CPU's widest level chosen at run time, the
//! same bits as one row at a time) in three forms — both operands arrays, or one of them a
//! single value put in every lane — and run in blocks shared between the caller and rayon's
//! threads for large arrays ([`crate::threads`]). The arrays' rows are read in place as the
//! typed values they are (a generated type is `repr(C)`, its coefficients in field order),
//! and each kernel notes in its lanes whether a result coefficient is not finite. Every other product goes through the
//! registry's storage-basis path ([`crate::classes`]). A chain of two outer products over
//! arrays (the circle through three points) runs as one kernel, its intermediate never
//! leaving the lanes.

use crate::threads::share;
use crate::values::{Algebra, Type, Values};
use cga_core::ProductKind;
use cga_core::simd::{Columns, Kernel, Lane, Lanes, Over, run_columns, splat};
use std::cell::Cell;
use std::marker::PhantomData;
use std::sync::atomic::{AtomicBool, Ordering};

/// A product of an `A` and a `B` giving an `O`, on any lanes.
trait Product {
    /// Its kind, and the names of its operands' and result's classes.
    const KIND: ProductKind;
    const NAMES: [&'static str; 3];
    type A: Lanes<Element = f64> + Send + Sync;
    type B: Lanes<Element = f64> + Send + Sync;
    type O: Lanes<Element = f64> + Send + Sync;
    fn op<L: Lane>(a: Over<Self::A, L>, b: Over<Self::B, L>) -> Over<Self::O, L>;
    /// Lanes whose result has every coefficient finite.
    fn finite<L: Lane>(o: &Over<Self::O, L>) -> L::Mask;
}

/// A kernel that notes, as it runs, whether any result had a coefficient that is not finite
/// (checked in the lanes, so it costs no pass over the results).
trait Noting: Kernel {
    /// Whether every result so far was finite.
    fn finite(&self) -> bool;
}

/// `o`, noted in `finite` (false from the first result with a coefficient that is not).
#[inline(always)]
fn noted<P: Product, L: Lane>(finite: &Cell<bool>, o: Over<P::O, L>) -> Over<P::O, L> {
    finite.set(finite.get() & L::all(P::finite::<L>(&o)));
    o
}

/// Both operands vary.
struct Rows<P>(Cell<bool>, PhantomData<fn() -> P>);

impl<P: Product> Kernel for Rows<P> {
    type Input = (P::A, P::B);
    type Output = P::O;
    #[inline(always)]
    fn apply<L: Lane>(&self, (a, b): Over<(P::A, P::B), L>) -> Over<P::O, L> {
        noted::<P, L>(&self.0, P::op::<L>(a, b))
    }
}

/// One left operand for every row.
struct FixedLeft<P: Product>(P::A, Cell<bool>);

impl<P: Product> Kernel for FixedLeft<P> {
    type Input = P::B;
    type Output = P::O;
    #[inline(always)]
    fn apply<L: Lane>(&self, b: Over<P::B, L>) -> Over<P::O, L> {
        noted::<P, L>(&self.1, P::op::<L>(splat::<P::A, L>(self.0), b))
    }
}

/// One right operand for every row.
struct FixedRight<P: Product>(P::B, Cell<bool>);

impl<P: Product> Kernel for FixedRight<P> {
    type Input = P::A;
    type Output = P::O;
    #[inline(always)]
    fn apply<L: Lane>(&self, a: Over<P::A, L>) -> Over<P::O, L> {
        noted::<P, L>(&self.1, P::op::<L>(a, splat::<P::B, L>(self.0)))
    }
}

/// Two products in a row, `(a ∘ b) ∘ c`, without leaving the lanes between them: the same
/// operations in the same order as the steps one by one (so the same bits), with one
/// transpose in and one out instead of one each per step. Only the result is checked: no
/// product makes an infinity or a NaN finite again.
struct Fused<P, Q>(Cell<bool>, PhantomData<fn() -> (P, Q)>);

impl<P: Product, Q: Product<A = P::O>> Kernel for Fused<P, Q> {
    type Input = (P::A, P::B, Q::B);
    type Output = Q::O;
    #[inline(always)]
    fn apply<L: Lane>(&self, (a, b, c): Over<(P::A, P::B, Q::B), L>) -> Over<Q::O, L> {
        noted::<Q, L>(&self.0, Q::op::<L>(P::op::<L>(a, b), c))
    }
}

macro_rules! noting {
    ($($kernel:ident<$($p:ident),*> . $field:tt),*) => {$(
        impl<$($p: Product),*> Noting for $kernel<$($p),*> where Self: Kernel {
            fn finite(&self) -> bool {
                self.$field.get()
            }
        }
    )*};
}
noting!(Rows<P> . 0, FixedLeft<P> . 1, FixedRight<P> . 1, Fused<P, Q> . 0);

/// Rows of `k` coefficients read as values of `X`.
fn typed<X>(data: &[f64], k: usize) -> &[X] {
    assert!(size_of::<X>() == k * size_of::<f64>() && align_of::<X>() == align_of::<f64>() && k > 0);
    // SAFETY: a generated type is `repr(C)` with `k` coefficients of f64 (size and alignment
    // checked above), so `k` consecutive f64 are one value of it.
    unsafe { std::slice::from_raw_parts(data.as_ptr().cast::<X>(), data.len() / k) }
}

/// [`typed`], writable.
fn typed_mut<X>(data: &mut [f64], k: usize) -> &mut [X] {
    assert!(size_of::<X>() == k * size_of::<f64>() && align_of::<X>() == align_of::<f64>() && k > 0);
    // SAFETY: as in `typed`; the borrow is exclusive.
    unsafe { std::slice::from_raw_parts_mut(data.as_mut_ptr().cast::<X>(), data.len() / k) }
}

/// Rows a thread takes at a time, and the array length from which threads are used.
const BLOCK: usize = 8192;
const THREADED: usize = 1 << 15;

/// A kernel from `make` over `input` (an array, or arrays of one length read in place) into
/// `out`, in blocks on threads for large arrays (a kernel each); whether every result
/// coefficient is finite.
fn run_blocks<K: Noting, S: Columns<Item = K::Input> + Send + Sync>(
    make: impl Fn() -> K + Sync,
    input: S,
    out: &mut [K::Output],
) -> bool
where
    K::Output: Send + Sync,
{
    if out.len() < THREADED {
        let kernel = make();
        run_columns(&kernel, input, out).expect("equal lengths");
        return kernel.finite();
    }
    let finite = AtomicBool::new(true);
    share(
        out,
        BLOCK,
        || (),
        |(), c, o| {
            let (first, kernel) = (c * BLOCK, make());
            run_columns(&kernel, input.part(first..first + o.len()), o).expect("equal lengths");
            if !kernel.finite() {
                finite.store(false, Ordering::Relaxed);
            }
        },
    );
    finite.into_inner()
}

/// `P` on rows `a` and `b`, each as (data, coefficients a row), one of them broadcast where a
/// single row, `n` rows of `k` coefficients into `out`; whether every coefficient is finite.
fn product_of<P: Product>(a: (&[f64], usize), b: (&[f64], usize), n: usize, k: usize, out: &mut [f64]) -> bool {
    let (xs, ys) = (typed::<P::A>(a.0, a.1), typed::<P::B>(b.0, b.1));
    let out = typed_mut::<P::O>(out, k);
    match (xs.len(), ys.len()) {
        (1, m) if m == n && n > 1 => run_blocks(|| FixedLeft::<P>(xs[0], Cell::new(true)), ys, out),
        (m, 1) if m == n => run_blocks(|| FixedRight::<P>(ys[0], Cell::new(true)), xs, out),
        _ => run_blocks(|| Rows::<P>(Cell::new(true), PhantomData), (xs, ys), out),
    }
}

/// The kernels: `Name: "algebra" module::Kind(A, B) -> O, |a, b| op` for each, `module` the
/// Rust module of the algebra's types and `"algebra"` its Python module.
macro_rules! kernels {
    ($($name:ident: $alg:literal $m:ident::$kind:ident($a:ident, $b:ident) -> $o:ident, |$x:ident, $y:ident| $op:expr;)*) => {
        $(
            struct $name;
            impl Product for $name {
                const KIND: ProductKind = ProductKind::$kind;
                const NAMES: [&'static str; 3] = [stringify!($a), stringify!($b), stringify!($o)];
                type A = $m::$a<f64>;
                type B = $m::$b<f64>;
                type O = $m::$o<f64>;
                #[inline(always)]
                fn op<L: Lane>($x: $m::$a<L>, $y: $m::$b<L>) -> $m::$o<L> {
                    $op
                }
                #[inline(always)]
                fn finite<L: Lane>(o: &$m::$o<L>) -> L::Mask {
                    // x − x is 0 for a finite x and NaN otherwise: one test of their sum.
                    let c = o.to_array();
                    c[1..].iter().fold(c[0] - c[0], |s, &x| s + (x - x)).finite()
                }
            }
        )*

        /// The products with a kernel: algebra, kind, left and right operand types.
        pub const KERNELS: &[(Algebra, ProductKind, &str, &str)] =
            &[$((Algebra($alg), ProductKind::$kind, stringify!($a), stringify!($b))),*];

        /// The product `kind` of rows `a` (of type `ta`) and `b` (of `tb`), one of them
        /// broadcast where a single row, into `out` (`n` rows of `to`'s coefficients): whether
        /// every coefficient is finite, or `None` where it is not one of the kernels.
        pub fn lanes_into(
            kind: ProductKind,
            (ta, a): (&Type, &[f64]),
            (tb, b): (&Type, &[f64]),
            (to, out): (&Type, &mut [f64]),
        ) -> Option<bool> {
            let (k, n) = (to.blades.len(), out.len() / to.blades.len().max(1));
            if ta.algebra != tb.algebra || ta.algebra != to.algebra {
                return None;
            }
            match (ta.algebra.0, kind, ta.name, tb.name) {
                $(($alg, ProductKind::$kind, stringify!($a), stringify!($b)) if to.name == stringify!($o) => {
                    Some(product_of::<$name>((a, ta.blades.len()), (b, tb.blades.len()), n, k, out))
                })*
                _ => None,
            }
        }

        /// The product `kind` of `a` and `b` on lanes (`n` rows of `out`'s coefficients), and
        /// whether every coefficient is finite, where it is one of the kernels.
        pub fn lanes(kind: ProductKind, a: &Values, b: &Values, n: usize, out: &Type) -> Option<(Vec<f64>, bool)> {
            if !KERNELS.contains(&(a.ty.algebra, kind, a.ty.name, b.ty.name)) {
                return None;
            }
            let mut data = crate::values::scratch(n * out.blades.len());
            let finite = lanes_into(kind, (a.ty, &a.data), (b.ty, &b.data), (out, &mut data))?;
            Some((data, finite))
        }
    };
}

use cga_algebras::{cga2, pga, sta, vga};
use cga_algebras::{cga2::Sandwich as _, pga::Sandwich as _, sta::Sandwich as _, vga::Sandwich as _};
use cga_core as cga;
use cga_core::Sandwich as _;

kernels! {
    MotorVector: "cga" cga::Sandwich(Motor, Vector) -> Vector, |m, x| m.sandwich(x);
    MotorBivector: "cga" cga::Sandwich(Motor, Bivector) -> Bivector, |m, x| m.sandwich(x);
    MotorLine: "cga" cga::Sandwich(Motor, Line) -> Line, |m, x| m.sandwich(x);
    MotorCircle: "cga" cga::Sandwich(Motor, Circle) -> Circle, |m, x| m.sandwich(x);
    MotorSphere: "cga" cga::Sandwich(Motor, Sphere) -> Sphere, |m, x| m.sandwich(x);
    MotorPlane: "cga" cga::Sandwich(Motor, Plane) -> Plane, |m, x| m.sandwich(x);
    RotorVector: "cga" cga::Sandwich(Rotor, Vector) -> Vector, |m, x| m.sandwich(x);
    RotorLine: "cga" cga::Sandwich(Rotor, Line) -> Line, |m, x| m.sandwich(x);
    RotorCircle: "cga" cga::Sandwich(Rotor, Circle) -> Circle, |m, x| m.sandwich(x);
    TranslatorVector: "cga" cga::Sandwich(Translator, Vector) -> Vector, |m, x| m.sandwich(x);
    TranslatorLine: "cga" cga::Sandwich(Translator, Line) -> Line, |m, x| m.sandwich(x);
    TranslatorCircle: "cga" cga::Sandwich(Translator, Circle) -> Circle, |m, x| m.sandwich(x);
    MotorMotor: "cga" cga::Geometric(Motor, Motor) -> Motor, |a, b| a * b;
    VectorVector: "cga" cga::Outer(Vector, Vector) -> Bivector, |a, b| a ^ b;
    BivectorVector: "cga" cga::Outer(Bivector, Vector) -> Circle, |a, b| a ^ b;
    CircleVector: "cga" cga::Outer(Circle, Vector) -> Sphere, |a, b| a ^ b;
    LineSphere: "cga" cga::Regressive(Line, Sphere) -> Bivector, |a, b| a & b;
    LinePlane: "cga" cga::Regressive(Line, Plane) -> FlatPoint, |a, b| a & b;
    CircleSphere: "cga" cga::Regressive(Circle, Sphere) -> Bivector, |a, b| a & b;
    CirclePlane: "cga" cga::Regressive(Circle, Plane) -> Bivector, |a, b| a & b;
    SphereSphere: "cga" cga::Regressive(Sphere, Sphere) -> Circle, |a, b| a & b;
    PlanePlane: "cga" cga::Regressive(Plane, Plane) -> Line, |a, b| a & b;
    PgaMotorPoint: "cga.pga" pga::Sandwich(Motor, Point) -> Point, |m, x| m.sandwich(x);
    PgaMotorLine: "cga.pga" pga::Sandwich(Motor, Line) -> Line, |m, x| m.sandwich(x);
    PgaMotorPlane: "cga.pga" pga::Sandwich(Motor, Plane) -> Plane, |m, x| m.sandwich(x);
    PgaMotorMotor: "cga.pga" pga::Geometric(Motor, Motor) -> Motor, |a, b| a * b;
    PgaJoin: "cga.pga" pga::Regressive(Point, Point) -> Line, |a, b| a & b;
    PgaPointLine: "cga.pga" pga::Regressive(Point, Line) -> Plane, |a, b| a & b;
    PgaMeet: "cga.pga" pga::Outer(Plane, Plane) -> Line, |a, b| a ^ b;
    PgaLinePlane: "cga.pga" pga::Outer(Line, Plane) -> Point, |a, b| a ^ b;
    Cga2MotorVector: "cga.cga2" cga2::Sandwich(Motor, Vector) -> Vector, |m, x| m.sandwich(x);
    Cga2MotorCircle: "cga.cga2" cga2::Sandwich(Motor, Circle) -> Circle, |m, x| m.sandwich(x);
    Cga2VectorVector: "cga.cga2" cga2::Outer(Vector, Vector) -> PointPair, |a, b| a ^ b;
    Cga2PointPairVector: "cga.cga2" cga2::Outer(PointPair, Vector) -> Circle, |a, b| a ^ b;
    Cga2CircleCircle: "cga.cga2" cga2::Regressive(Circle, Circle) -> PointPair, |a, b| a & b;
    VgaRotorVector: "cga.vga" vga::Sandwich(Rotor, Vector) -> Vector, |m, x| m.sandwich(x);
    VgaRotorRotor: "cga.vga" vga::Geometric(Rotor, Rotor) -> Rotor, |a, b| a * b;
    StaRotorVector: "cga.sta" sta::Sandwich(Rotor, Vector) -> Vector, |m, x| m.sandwich(x);
}

/// `(a ∘ b) ∘ c` for arrays of one length as `P` then `Q` fused, where the operands and the
/// result `out` are their classes; `None` otherwise.
fn fused_as<P: Product, Q: Product<A = P::O>>(
    kind: ProductKind,
    [a, b, c]: [&Values; 3],
    out: &Type,
    n: usize,
) -> Option<(Vec<f64>, bool)> {
    let names = [a.ty.name, b.ty.name, c.ty.name, out.name];
    if kind != P::KIND || kind != Q::KIND || names != [P::NAMES[0], P::NAMES[1], Q::NAMES[1], Q::NAMES[2]] {
        return None;
    }
    let (xs, ys, zs) = (typed::<P::A>(&a.data, a.k()), typed::<P::B>(&b.data, b.k()), typed::<Q::B>(&c.data, c.k()));
    let k = out.blades.len();
    let mut data = crate::values::scratch(n * k);
    let finite =
        run_blocks(|| Fused::<P, Q>(Cell::new(true), PhantomData), (xs, ys, zs), typed_mut::<Q::O>(&mut data, k));
    Some((data, finite))
}

/// A chain of two steps of cga-core's classes over arrays of one length, fused where its
/// kernels are (the circle through three points, the sphere through a pair and two points).
fn fused(kind: ProductKind, values: &[&Values], out: &Type, n: usize) -> Option<(Vec<f64>, bool)> {
    let &[a, b, c] = values else { return None };
    if n < 2 || [a, b, c].iter().any(|v| v.n != n || v.ty.algebra != crate::values::Algebra::CGA) {
        return None;
    }
    fused_as::<VectorVector, BivectorVector>(kind, [a, b, c], out, n)
        .or_else(|| fused_as::<BivectorVector, CircleVector>(kind, [a, b, c], out, n))
}

/// Rows a block of a chain takes: its intermediates (at most 32 coefficients a row) stay
/// within a core's cache.
const CHAIN_BLOCK: usize = 1024;

/// The rows of `v` in the block `first .. first + len` (a single value's one row for any).
fn block_rows(v: &Values, first: usize, len: usize) -> &[f64] {
    if v.n == 1 { &v.data } else { &v.data[first * v.k()..(first + len) * v.k()] }
}

/// A chain of products `((v₀ ∘ v₁) ∘ v₂) ∘ …` of one kind on lanes, every step a kernel
/// (`types[i]` the type of step i's result, `types[0]` the first operand's), `n` rows into a
/// new array, a block of rows at a time: each block's intermediates stay in buffers in the
/// core's cache, so the operands are read and the result written once, and every row gets
/// the numbers of the chain taken step by step. `None` where a step has no kernel.
pub fn chain(kind: ProductKind, values: &[&Values], types: &[&'static Type], n: usize) -> Option<(Vec<f64>, bool)> {
    let steps = values.len().checked_sub(1).filter(|&s| s > 0)?;
    let known =
        (1..=steps).all(|i| KERNELS.contains(&(values[i].ty.algebra, kind, types[i - 1].name, values[i].ty.name)));
    if !known || values.iter().any(|v| v.n != 1 && v.n != n) {
        return None;
    }
    if let Some(data) = fused(kind, values, types[steps], n) {
        return Some(data);
    }
    let k = types[steps].blades.len();
    let mut out = crate::values::scratch(n * k);
    // A step whose result type is not its kernel's: no answer here (the operators give it).
    let (refused, unfinite) = (AtomicBool::new(false), AtomicBool::new(false));
    let block = |bufs: &mut [Vec<f64>; 2], (c, o): (usize, &mut [f64])| {
        let (first, len) = (c * CHAIN_BLOCK, o.len() / k);
        // Rows of step i's result: one while every operand so far is a single value.
        let width = |i: usize| if values[..=i].iter().all(|v| v.n == 1) { 1 } else { len };
        for i in 1..=steps {
            let b = (values[i].ty, block_rows(values[i], first, len));
            let (done, previous) = bufs.split_at_mut(1);
            let (into, from) = if i % 2 == 1 { (&mut done[0], &previous[0]) } else { (&mut previous[0], &done[0]) };
            let a = (types[i - 1], if i == 1 { block_rows(values[0], first, len) } else { &from[..] });
            let known = if i == steps {
                lanes_into(kind, a, b, (types[i], &mut *o))
            } else {
                into.clear();
                into.resize(width(i) * types[i].blades.len(), 0.0);
                lanes_into(kind, a, b, (types[i], into))
            };
            match known {
                None => refused.store(true, Ordering::Relaxed),
                // A step's non-finite coefficient reaches the result (no product makes an
                // infinity or a NaN finite again): the last step's tell.
                Some(false) if i == steps => unfinite.store(true, Ordering::Relaxed),
                Some(_) => {}
            }
        }
    };
    if n < THREADED {
        let mut bufs = [Vec::new(), Vec::new()];
        out.chunks_mut(CHAIN_BLOCK * k).enumerate().for_each(|c| block(&mut bufs, c));
    } else {
        share(&mut out, CHAIN_BLOCK * k, || [Vec::new(), Vec::new()], |bufs, c, o| block(bufs, (c, o)));
    }
    (!refused.into_inner()).then_some((out, !unfinite.into_inner()))
}
