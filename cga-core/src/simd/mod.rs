//! Many lanes as a scalar: every generated type, product and sandwich runs on four or eight
//! independent f64 operands at once, or eight or sixteen f32 ones, `Line<F64x4>` being a
//! packet of four lines in structure-of-arrays form. [`run`] picks the lanes from the
//! values' scalar ([`Lanes::Element`]) and the CPU ([`Element::Avx512Lanes`]): f64 on
//! [`F64x4`], f32 on [`F32x16`] or [`F32x8`].
//!
//! Three ways to run an operation over many operands:
//!
//! - [`run_packed`]: over packets ([`Packed`]: `&[Line<F64x4>]`, `&[Line<F32x8>]`…), the
//!   form a ray tracer keeps its packets in, with no transpose;
//! - [`run`]: over slices of ordinary values, transposed into lanes and back in place:
//!   f64 values four at a time on [`F64x4`] (in a loop compiled for AVX-512 where the CPU
//!   has it, for AVX2 otherwise), f32 values sixteen at a time on [`F32x16`] with AVX-512,
//!   eight on [`F32x8`] with AVX2;
//! - [`run_columns`]: the same over operands kept in separate arrays (a tuple of slices),
//!   read in place;
//! - [`map`]: the same with an `#[inline(always)]` closure on lanes of the values' scalar.
//!
//! `run` and `run_packed` take the operation as a [`Kernel`] and compile it for each level
//! the CPU may have (AVX-512, AVX2 + FMA, the baseline SSE2), choosing at run time: no
//! `target-cpu` flag is needed and the binary runs on any x86-64. Every level gives the
//! bits of one at a time: no multiply–add is contracted.
//!
//! ```
//! use cga_core::simd::{F64x4, map};
//! use cga_core::{Line, PointPair, Sphere};
//! let sphere = Sphere::from_centre_radius([0.0, 0.0, 0.0], 1.0).unwrap();
//! let line = |k: usize| Line::through([k as f64 * 0.1, 0.0, -3.0], [0.0, 0.0, 3.0]).unwrap();
//! let input: Vec<(Line, Sphere)> = (0..10).map(|k| (line(k), sphere)).collect();
//! let mut pairs = vec![PointPair::zero(); 10];
//! map(&input, &mut pairs, #[inline(always)] |(l, s): (Line<F64x4>, Sphere<F64x4>)| l & s);
//! assert_eq!(pairs[7], line(7) & sphere); // the same bits as one at a time
//! ```

mod columns;
mod pack;
// Public for `lanes!`'s expansion in the crates whose `algebra!` asks for lanes.
#[cfg(target_arch = "x86_64")]
#[doc(hidden)]
pub mod transpose;
mod wide;

/// `Lanes` for the named generated types: what `algebra! { lanes = cga_core::simd; … }`
/// expands to (spelled through `$crate`, so it expands in any crate).
#[doc(hidden)]
pub use crate::__simd_lanes as lanes;
pub use columns::Columns;
pub use pack::{Lanes, splat};
pub use wide::{F32x8, F32x16, F64x4, F64x8, Lane, Mask4, Mask8, Mask32x8, Mask32x16};

/// The packed form of a [`Lanes`] type: one 256-bit packet per coefficient, four f64 lanes
/// ([`F64x4`]) or eight f32 ones ([`F32x8`]) — the lanes [`Element::Narrow`] of its scalar
/// (`Packed<Line>` is `Line<F64x4>`, `Packed<Line<f32>>` is `Line<F32x8>`). Values stored
/// this way (structure of arrays in blocks of a packet) run through [`run_packed`] with no
/// transpose.
pub type Packed<X> = <X as Lanes>::Over<<<X as Lanes>::Element as Element>::Narrow>;

/// `X` over the lanes `L` (`Over<Line, F64x8>` is `Line<F64x8>`).
pub type Over<X, L> = <X as Lanes>::Over<L>;

/// One operation on lanes, named so that [`run`] can compile it for the CPU it finds and
/// for the lanes it takes there: `apply` is generic over the lane type, and marked
/// `#[inline(always)]` it is inlined into each compiled loop (a closure handed to a function
/// compiled for AVX2 is a call LLVM may decline to inline, as it did for every product
/// bigger than a rotor's, and a call out of that function runs baseline code). A kernel
/// may carry state known only at run time (a motor, a sphere): `apply` takes `&self`, and
/// [`splat`] puts a value into every lane.
///
/// ```
/// use cga_core::simd::{Kernel, Lane, Over, run, splat};
/// use cga_core::{Line, PointPair, Sphere};
/// struct Meet;
/// impl Kernel for Meet {
///     type Input = (Line, Sphere);
///     type Output = PointPair;
///     #[inline(always)]
///     fn apply<L: Lane>(&self, (l, s): (Line<L>, Sphere<L>)) -> PointPair<L> {
///         l & s
///     }
/// }
/// let line = Line::through([0.5, 0.0, -3.0], [0.5, 0.0, 3.0]).unwrap();
/// let input = vec![(line, Sphere::from_centre_radius([0.0; 3], 1.0).unwrap()); 11];
/// let mut out = vec![PointPair::zero(); 11];
/// run(&Meet, &input, &mut out).unwrap();
/// assert_eq!(out[10], line & input[10].1);
///
/// // A kernel with state: one sphere, given at run time, met by many lines.
/// struct MeetSphere(Sphere);
/// impl Kernel for MeetSphere {
///     type Input = Line;
///     type Output = PointPair;
///     #[inline(always)]
///     fn apply<L: Lane>(&self, l: Line<L>) -> PointPair<L> {
///         l & splat::<Sphere, L>(self.0)
///     }
/// }
/// let sphere = Sphere::from_centre_radius([0.0; 3], 1.0).unwrap();
/// let lines = vec![line; 11];
/// run(&MeetSphere(sphere), &lines, &mut out).unwrap();
/// assert_eq!(out[3], line & sphere);
/// ```
pub trait Kernel {
    /// What one operation takes (a type, or a tuple of types).
    type Input: Lanes;
    /// What it gives.
    type Output: Lanes;
    /// The operation on `L::LANES` operands at once.
    fn apply<L: Lane>(&self, x: Over<Self::Input, L>) -> Over<Self::Output, L>;
}

#[cfg(target_arch = "x86_64")]
use rows::Transposed;
use rows::{Op, Rows as _};

/// A kernel at whichever lanes a loop takes.
struct AtLanes<'a, K>(&'a K);

impl<K: Kernel, L: Lane> Op<L> for AtLanes<'_, K> {
    type Input = K::Input;
    type Output = K::Output;
    #[inline(always)]
    fn op(&self, x: Over<K::Input, L>) -> Over<K::Output, L> {
        self.0.apply::<L>(x)
    }
}

/// A closure on the lanes `L` ([`map`]).
struct Closure<I, R, F>(F, core::marker::PhantomData<fn(I) -> R>);

impl<L: Lane, I: Lanes, R: Lanes, F: Fn(Over<I, L>) -> Over<R, L>> Op<L> for Closure<I, R, F> {
    type Input = I;
    type Output = R;
    #[inline(always)]
    fn op(&self, x: Over<I, L>) -> Over<R, L> {
        (self.0)(x)
    }
}

/// The lanes [`map`] runs a closure on: [`F64x4`] or [`F64x8`] for f64 values, [`F32x8`]
/// or [`F32x16`] for f32 ones (sealed: no others), each moved into and out of lanes by the
/// transposes its CPU level has.
pub trait Width: Lane + rows::Rows {
    /// The scalar of the values these lanes take: a closure on f32 lanes cannot be handed
    /// f64 values (it would round them).
    ///
    /// ```compile_fail,E0271
    /// use cga_core::simd::{F32x8, map};
    /// use cga_core::Vector;
    /// let points = vec![Vector::<f64>::zero(); 9];
    /// let mut out = points.clone();
    /// map(&points, &mut out, |x: Vector<F32x8>| x);
    /// ```
    type Element: Element;
}

impl Width for F64x4 {
    type Element = f64;
}
impl Width for F64x8 {
    type Element = f64;
}
impl Width for F32x8 {
    type Element = f32;
}
impl Width for F32x16 {
    type Element = f32;
}

/// The scalar of the values [`run`] takes, and the lanes it runs them on: f64 on [`F64x4`]
/// (one AVX2 register) at every level, f32 on [`F32x8`] or, with AVX-512, [`F32x16`].
/// Sealed: f64 and f32.
pub trait Element: crate::Real + rows::Sealed {
    /// The lanes of one AVX2 register, and of the baseline loop.
    type Narrow: Width;
    /// The lanes of one AVX-512 register.
    type Broad: Width;
    /// The lanes [`run`] takes where the CPU has AVX-512 (its loop compiled for AVX-512
    /// either way, with 32 registers): [`F64x4`] for f64, whose 4 × 4 AVX transposes
    /// (128-bit loads, in-lane shuffles, 256-bit stores) cost less than the 8-row AVX-512
    /// ones, where AMD's Zen 4 takes twice a 256-bit shuffle's time for a 512-bit one and
    /// more for a masked store (benches/README.md: every row of the klein table, the join
    /// of two points 1.26 ns against 1.72 on eight lanes); [`F32x16`] for f32, whose
    /// sixteen lanes there stay ahead of eight on the same join (1.11 ns against 1.23).
    type Avx512Lanes: Width;
}

impl Element for f64 {
    type Narrow = F64x4;
    type Broad = F64x8;
    type Avx512Lanes = F64x4;
}

impl Element for f32 {
    type Narrow = F32x8;
    type Broad = F32x16;
    type Avx512Lanes = F32x16;
}

mod rows {
    use super::{Columns, F32x8, F32x16, F64x4, F64x8, Lane, Lanes, Over};

    /// What only f64 and f32 are ([`Element`](super::Element)).
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}

    /// An operation on the lanes `L`: a [`Kernel`](super::Kernel) at `L`, or
    /// [`map`](super::map)'s closure.
    pub trait Op<L: Lane> {
        type Input: Lanes;
        type Output: Lanes;
        fn op(&self, x: Over<Self::Input, L>) -> Over<Self::Output, L>;
    }

    /// The loops over rows of one lane width, at the two x86-64 levels above baseline.
    pub trait Rows: Lane + Sized {
        /// The loop compiled with AVX2 and FMA enabled.
        ///
        /// # Safety
        /// The CPU must have AVX2 and FMA.
        #[cfg(target_arch = "x86_64")]
        unsafe fn rows_avx2<F: Op<Self>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]);
        /// The loop compiled with AVX-512 enabled.
        ///
        /// # Safety
        /// The CPU must have AVX-512 F, DQ and VL, AVX2 and FMA.
        #[cfg(target_arch = "x86_64")]
        unsafe fn rows_avx512<F: Op<Self>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]);
    }

    /// Each width's loops: by in-place transposes where a level has them for its rows (four
    /// f64 or eight f32 with AVX, eight f64 or sixteen f32 with AVX-512), by value where it
    /// has not (eight f64 or sixteen f32 lanes are two AVX2 registers).
    macro_rules! rows {
        ($($t:ident: $avx2:ident;)*) => {$(
            impl Rows for $t {
                #[cfg(target_arch = "x86_64")]
                unsafe fn rows_avx2<F: Op<Self>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]) {
                    // SAFETY: the caller's CPU has AVX2, which the transposes on these lanes need.
                    unsafe { super::$avx2(f, input, out) }
                }
                #[cfg(target_arch = "x86_64")]
                unsafe fn rows_avx512<F: Op<Self>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]) {
                    // SAFETY: the caller's CPU has AVX-512.
                    unsafe { super::transposed_avx512(f, input, out) }
                }
            }
        )*};
    }
    rows! {
        F64x4: transposed_avx2;
        F64x8: by_value_avx2;
        F32x8: transposed_avx2;
        F32x16: by_value_avx2;
    }

    /// Lanes that values move into and out of by transposes in place (`Lanes`' row moves
    /// of their width).
    #[cfg(target_arch = "x86_64")]
    pub trait Transposed: Lane {
        /// Rows `first .. first + LANES` of `input`, in lanes.
        ///
        /// # Safety
        /// The CPU must have the transposes' level (AVX for four f64 or eight f32 lanes,
        /// AVX-512 F and DQ for eight f64 or sixteen f32), and the rows must exist.
        unsafe fn pack<S: Columns>(input: &S, first: usize) -> Over<S::Item, Self>;
        /// The lanes of `p` to the `LANES` values from `rows`.
        ///
        /// # Safety
        /// As for [`Transposed::pack`], the values writable.
        unsafe fn unpack<X: Lanes>(p: Over<X, Self>, rows: *mut X);
    }

    macro_rules! transposed {
        ($($t:ident: $pack:ident, $unpack:ident;)*) => {$(
            #[cfg(target_arch = "x86_64")]
            impl Transposed for $t {
                #[inline(always)]
                unsafe fn pack<S: Columns>(input: &S, first: usize) -> Over<S::Item, Self> {
                    // SAFETY: the caller's.
                    unsafe { input.$pack(first) }
                }
                #[inline(always)]
                unsafe fn unpack<X: Lanes>(p: Over<X, Self>, rows: *mut X) {
                    // SAFETY: the caller's.
                    unsafe { X::$unpack(p, core::array::from_fn(|i| rows.add(i))) }
                }
            }
        )*};
    }
    transposed! {
        F64x4: pack_rows, unpack_rows;
        F64x8: pack_rows8, unpack_rows8;
        F32x8: pack_rows_f32x8, unpack_rows_f32x8;
        F32x16: pack_rows16, unpack_rows16;
    }
}

/// `out[k] = f(input[k])` for every `k`, `L::LANES` at a time on the lanes the closure
/// takes ([`F64x4`] or [`F64x8`] for f64 values, [`F32x8`] or [`F32x16`] for f32 ones: the
/// lanes' scalar is the values'; a tail is padded with copies of the last input),
/// dispatched at run time to a loop compiled for AVX-512 or AVX2 and FMA as [`run`] is,
/// with the same bits. `None`, and nothing written, where the lengths differ.
///
/// Mark the closure `#[inline(always)]`: the body is then compiled inside the dispatched
/// loop, with its instruction set. Without the mark LLVM declines to inline a body of
/// several hundred instructions (a motor's sandwich), and the call runs baseline SSE2 code
/// (2.4–2.7× `run`'s time moving a million points; `cargo bench --bench bulk` times both). [`run`] picks the lane width
/// for the CPU; a closure has one: on f64 values four lanes match `run` on every CPU, on f32
/// values eight match it on AVX2 CPUs and sixteen on AVX-512 ones (benches/README.md gives
/// four and eight f64 lanes against `run`).
///
/// ```
/// use cga_core::simd::{F64x4, F64x8, map, splat};
/// use cga_core::{Motor, Rotor, Sandwich, Vector, up};
/// let m = Motor::from_rotor_translation(Rotor::from_axis_angle([0.0, 0.0, 1.0], 0.5).unwrap(), [1.0, 0.0, 0.0]);
/// let points: Vec<Vector> = (0..9).map(|k| up([k as f64, 1.0, 2.0])).collect();
/// let mut moved = vec![Vector::zero(); points.len()];
/// let four = splat::<Motor, F64x4>(m);
/// map(&points, &mut moved, #[inline(always)] |x: Vector<F64x4>| four.sandwich(x)).unwrap();
/// assert_eq!(moved[8], m.sandwich(points[8]));
/// let eight = splat::<Motor, F64x8>(m);
/// map(&points, &mut moved, #[inline(always)] |x: Vector<F64x8>| eight.sandwich(x)).unwrap();
/// assert_eq!(moved[8], m.sandwich(points[8]));
/// ```
#[inline]
pub fn map<L: Width, I: Lanes<Element = L::Element>, R: Lanes<Element = L::Element>>(
    input: &[I],
    out: &mut [R],
    f: impl Fn(Over<I, L>) -> Over<R, L>,
) -> Option<()> {
    map_at(Level::detect(), input, out, f)
}

/// [`map`] at a given level (the tests run each one the CPU has).
#[inline(always)]
fn map_at<L: Width, I: Lanes<Element = L::Element>, R: Lanes<Element = L::Element>>(
    level: Level,
    input: &[I],
    out: &mut [R],
    f: impl Fn(Over<I, L>) -> Over<R, L>,
) -> Option<()> {
    if input.len() != out.len() {
        return None;
    }
    let f = Closure(f, core::marker::PhantomData);
    match level {
        // SAFETY: `detect` found the features each loop is compiled for.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { L::rows_avx512(&f, input, out) },
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { L::rows_avx2(&f, input, out) },
        Level::Baseline => by_value(&f, input, out),
    }
    Some(())
}

/// The baseline loop: `L::LANES` values packed by value, a tail padded with copies of the
/// last input.
#[inline(always)]
fn by_value<L: Lane, F: Op<L>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]) {
    let (n, len) = (L::LANES, out.len());
    let whole = len / n * n;
    for (c, out) in out[..whole].chunks_exact_mut(n).enumerate() {
        F::Output::unpack_lanes(f.op(input.pack_lanes::<L>(c * n)), out);
        not_across_iterations();
    }
    if whole < len {
        // Room for the widest lanes, sixteen (`Width` is sealed to four, eight and sixteen).
        let last = len - 1;
        let padded: [F::Input; 16] = core::array::from_fn(|k| input.row((whole + k).min(last)));
        let mut lanes = [F::Output::pack_filler(); 16];
        F::Output::unpack_lanes(f.op(F::Input::pack_lanes(&padded[..n])), &mut lanes[..n]);
        out[whole..].copy_from_slice(&lanes[..len - whole]);
    }
}

/// `out[k] = K(input[k])` for every `k`: f64 values four at a time on [`F64x4`], in a loop
/// compiled for AVX-512 (F, DQ and VL) where the CPU has it, for AVX2 and FMA otherwise, in
/// baseline code without them (detected once, at run time: the build stays baseline
/// x86-64); f32 values sixteen at a time on [`F32x16`] with AVX-512, eight on [`F32x8`]
/// otherwise ([`Element::Avx512Lanes`] says why). The values go into and out of lanes by
/// transposes in place. The results are
/// the same bits at every level (no multiply–add is contracted). `None`, and nothing
/// written, where the lengths differ.
pub fn run<K: Kernel>(kernel: &K, input: &[K::Input], out: &mut [K::Output]) -> Option<()> {
    run_at(Level::detect(), kernel, input, out)
}

/// [`run`] on operands kept in separate arrays of one length (a tuple of slices, each an
/// element of the kernel's tuple input: [`Columns`]), read in place: no array of tuples is
/// built. The same loops, levels and bits as `run`; `None`, and nothing written, where a
/// length differs.
///
/// ```
/// use cga_core::simd::{Kernel, Lane, run_columns};
/// use cga_core::{Bivector, Vector, up};
/// struct Wedge;
/// impl Kernel for Wedge {
///     type Input = (Vector, Vector);
///     type Output = Bivector;
///     #[inline(always)]
///     fn apply<L: Lane>(&self, (a, b): (Vector<L>, Vector<L>)) -> Bivector<L> {
///         a ^ b
///     }
/// }
/// let a: Vec<Vector> = (0..9).map(|k| up([k as f64, 0.0, 1.0])).collect();
/// let b: Vec<Vector> = (0..9).map(|k| up([0.0, k as f64, 2.0])).collect();
/// let mut pairs = vec![Bivector::zero(); 9];
/// run_columns(&Wedge, (&a[..], &b[..]), &mut pairs).unwrap();
/// assert_eq!(pairs[5], a[5] ^ b[5]);
/// assert_eq!(run_columns(&Wedge, (&a[..], &b[1..]), &mut pairs), None);
/// ```
pub fn run_columns<K: Kernel, S: Columns<Item = K::Input>>(kernel: &K, input: S, out: &mut [K::Output]) -> Option<()> {
    run_at(Level::detect(), kernel, input, out)
}

/// What the CPU offers the loops here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Level {
    Baseline,
    #[cfg(target_arch = "x86_64")]
    Avx2,
    #[cfg(target_arch = "x86_64")]
    Avx512,
}

impl Level {
    /// The widest level this CPU has (`std` caches the detection).
    #[inline]
    fn detect() -> Level {
        #[cfg(target_arch = "x86_64")]
        if avx512() {
            return Level::Avx512;
        } else if avx2() {
            return Level::Avx2;
        }
        Level::Baseline
    }
}

/// [`run`] at a given level (the tests run each one the CPU has).
fn run_at<K: Kernel, S: Columns<Item = K::Input>>(
    level: Level,
    kernel: &K,
    input: S,
    out: &mut [K::Output],
) -> Option<()> {
    if input.rows() != Some(out.len()) {
        return None;
    }
    type Narrow<K> = <<<K as Kernel>::Input as Lanes>::Element as Element>::Narrow;
    type Avx512Lanes<K> = <<<K as Kernel>::Input as Lanes>::Element as Element>::Avx512Lanes;
    let kernel = AtLanes(kernel);
    match level {
        // SAFETY: `detect` found the features each loop is compiled for.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { Avx512Lanes::<K>::rows_avx512(&kernel, input, out) },
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { Narrow::<K>::rows_avx2(&kernel, input, out) },
        Level::Baseline => by_value::<Narrow<K>, _, _>(&kernel, input, out),
    }
    Some(())
}

/// The by-value loop compiled with AVX2 and FMA enabled (eight lanes as two registers).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn by_value_avx2<L: Lane, F: Op<L>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]) {
    by_value(f, input, out)
}

/// The transposing loop compiled with AVX2 and FMA enabled (four f64 or eight f32 lanes).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn transposed_avx2<L: Transposed, F: Op<L>, S: Columns<Item = F::Input>>(
    f: &F,
    input: S,
    out: &mut [F::Output],
) {
    // SAFETY: the caller's lanes have AVX transposes, and the CPU has AVX.
    unsafe { transposed(f, input, out) }
}

/// The transposing loop compiled with AVX-512 enabled: [`run`]'s lanes there
/// ([`Element::Avx512Lanes`]) or a closure's, with the 32 vector registers AVX-512 gives
/// (fewer spills than AVX2's 16).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
unsafe fn transposed_avx512<L: Transposed, F: Op<L>, S: Columns<Item = F::Input>>(
    f: &F,
    input: S,
    out: &mut [F::Output],
) {
    // SAFETY: the CPU has AVX-512, which every lanes' transposes need at most.
    unsafe { transposed(f, input, out) }
}

/// `L::LANES` rows at a time by transposes in place, a tail of fewer padded by value.
///
/// # Safety
/// The CPU must have the level `L`'s transposes need.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn transposed<L: Transposed, F: Op<L>, S: Columns<Item = F::Input>>(f: &F, input: S, out: &mut [F::Output]) {
    let n = L::LANES;
    let whole = out.len() / n * n;
    for (c, y) in out[..whole].chunks_exact_mut(n).enumerate() {
        // SAFETY: the caller's CPU level; the input has as many rows as `out` (checked by
        // the caller), so rows `nc .. nc + n` exist, and the output's are the chunk's.
        unsafe {
            let lanes = L::pack(&input, n * c);
            L::unpack::<F::Output>(f.op(lanes), y.as_mut_ptr());
        }
        not_across_iterations();
    }
    by_value::<L, _, _>(f, input.part(whole..out.len()), &mut out[whole..])
}

/// [`run`] on operands already in lanes, `out[k] = K(input[k])` for each packet: f64
/// values four to a packet ([`F64x4`]), f32 values eight ([`F32x8`]) — [`Packed`], the form
/// a ray tracer keeps its packets in, or any data stored as structure of arrays in blocks
/// of a packet. Nothing is packed or unpacked: each packet's coefficients are loaded, the
/// kernel applied, and the result's stored. Dispatched at run time to a loop compiled for
/// AVX-512 (the same lanes, with 32 registers instead of 16: fewer spills in the larger
/// products) or AVX2 and FMA, baseline code otherwise; every level gives the bits of one at
/// a time (no multiply–add is contracted). An output of 8 MiB or more is written by
/// non-temporal stores, past the caches (it would not stay in them, and the input would be
/// evicted for it). `None`, and nothing written, where the lengths differ.
///
/// ```
/// use cga_core::simd::{F32x8, Kernel, Lane, Lanes, Packed, run_packed};
/// use cga_core::{Bivector, Vector, up};
/// struct Wedge;
/// impl Kernel for Wedge {
///     type Input = (Vector<f32>, Vector<f32>);
///     type Output = Bivector<f32>;
///     #[inline(always)]
///     fn apply<L: Lane>(&self, (a, b): (Vector<L>, Vector<L>)) -> Bivector<L> {
///         a ^ b
///     }
/// }
/// let point = |k: usize| Vector::<f32>::from_array(up([k as f64, 1.0, 2.0]).to_array().map(|c| c as f32));
/// let pairs: Vec<(Vector<f32>, Vector<f32>)> = (0..16).map(|k| (point(k), point(k + 1))).collect();
/// // Stored packed: eight pairs a packet.
/// let packets: Vec<Packed<(Vector<f32>, Vector<f32>)>> = pairs.chunks(8).map(Lanes::pack_lanes::<F32x8>).collect();
/// let mut out = vec![Bivector::<F32x8>::zero(); 2];
/// run_packed(&Wedge, &packets, &mut out).unwrap();
/// let mut back = [Bivector::<f32>::zero(); 8];
/// Bivector::unpack_lanes(out[1], &mut back);
/// assert_eq!(back[3], pairs[11].0 ^ pairs[11].1); // the same bits as one at a time
/// ```
pub fn run_packed<K: Kernel>(kernel: &K, input: &[Packed<K::Input>], out: &mut [Packed<K::Output>]) -> Option<()>
where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    run_packed_at(Level::detect(), STREAM_BYTES, kernel, input, out)
}

/// [`run_packed`] at a given level, streaming outputs of `stream_bytes` or more (the tests
/// run each level the CPU has, with stores of either kind).
fn run_packed_at<K: Kernel>(
    level: Level,
    stream_bytes: usize,
    kernel: &K,
    input: &[Packed<K::Input>],
    out: &mut [Packed<K::Output>],
) -> Option<()>
where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    if input.len() != out.len() {
        return None;
    }
    match level {
        // SAFETY: `detect` found the features each loop is compiled for.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => unsafe { run_packed_avx512(kernel, input, out, stream_bytes) },
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => unsafe { run_packed_avx2(kernel, input, out, stream_bytes) },
        Level::Baseline => packed_loop(kernel, input, out),
    }
    Some(())
}

/// Whether this CPU has AVX2 and FMA, which the dispatched loops here (and callers' own,
/// such as a ray tracer's packet loops) are compiled for; detected once (`std` caches it).
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn avx2() -> bool {
    std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")
}

/// Whether this CPU has AVX-512 F, DQ and VL (and AVX2 and FMA), which [`run`]'s loop and
/// [`map`]'s are compiled for where it has.
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn avx512() -> bool {
    avx2()
        && std::is_x86_feature_detected!("avx512f")
        && std::is_x86_feature_detected!("avx512dq")
        && std::is_x86_feature_detected!("avx512vl")
}

/// [`run_packed`]'s loop compiled with AVX2 and FMA enabled.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn run_packed_avx2<K: Kernel>(
    kernel: &K,
    input: &[Packed<K::Input>],
    out: &mut [Packed<K::Output>],
    stream_bytes: usize,
) where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    // SAFETY: the CPU has AVX.
    unsafe { packed_loop_avx(kernel, input, out, stream_bytes) }
}

/// [`run_packed`]'s loop compiled with AVX-512 enabled: the same lanes, 32 registers.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
unsafe fn run_packed_avx512<K: Kernel>(
    kernel: &K,
    input: &[Packed<K::Input>],
    out: &mut [Packed<K::Output>],
    stream_bytes: usize,
) where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    // SAFETY: the CPU has AVX.
    unsafe { packed_loop_avx(kernel, input, out, stream_bytes) }
}

/// Outputs of this many bytes or more are written by non-temporal stores in [`run_packed`]:
/// past the L2 of any x86-64 core and a quarter or more of most L3s, where a store that
/// first reads its line into the cache (and evicts the input to make room) costs more than
/// the cache gives back; below it the result stays in cache for whatever reads it next.
const STREAM_BYTES: usize = 8 << 20;

/// [`packed_loop`] with each result written as 32-byte AVX stores, one a packet: with
/// AVX-512 enabled LLVM otherwise merges pairs of 256-bit packets into 512-bit registers
/// by shuffles (2–3× the time of the join of two points); non-temporal stores for an
/// output of `stream_bytes` or more ([`STREAM_BYTES`]).
///
/// # Safety
/// The CPU must have AVX.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn packed_loop_avx<K: Kernel>(
    kernel: &K,
    input: &[Packed<K::Input>],
    out: &mut [Packed<K::Output>],
    stream_bytes: usize,
) where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    use core::arch::x86_64::{__m256i, _mm_sfence, _mm256_load_si256, _mm256_store_si256, _mm256_stream_si256};
    type Narrow<K> = <<<K as Kernel>::Input as Lanes>::Element as Element>::Narrow;
    let (size, align) = (size_of::<Packed<K::Output>>(), align_of::<Packed<K::Output>>());
    // Every packet is 32 bytes, aligned to 32, and a generated type (or a tuple of them) is
    // nothing else: checked all the same, with the plain loop for anything that is not.
    if size % 32 != 0 || align < 32 {
        return packed_loop(kernel, input, out);
    }
    let stream = size_of_val(out) >= stream_bytes;
    for (o, &x) in out.iter_mut().zip(input) {
        let y = kernel.apply::<Narrow<K>>(x);
        let (from, to) = ((&raw const y).cast::<__m256i>(), (o as *mut Packed<K::Output>).cast::<__m256i>());
        for k in 0..size / 32 {
            // SAFETY: `y` and `*o` are `size` bytes each, aligned to 32 (checked above):
            // every packet of 32 bytes is in both and aligned; the caller's CPU has AVX.
            unsafe {
                let v = _mm256_load_si256(from.add(k));
                if stream { _mm256_stream_si256(to.add(k), v) } else { _mm256_store_si256(to.add(k), v) }
            }
        }
        not_across_iterations();
    }
    if stream {
        // Non-temporal stores are weakly ordered: fenced before anything reads `out`.
        // SAFETY: SSE, which every x86-64 has.
        unsafe { _mm_sfence() };
    }
}

/// [`run_packed`]'s baseline loop.
#[inline(always)]
fn packed_loop<K: Kernel>(kernel: &K, input: &[Packed<K::Input>], out: &mut [Packed<K::Output>])
where
    K::Output: Lanes<Element = <K::Input as Lanes>::Element>,
{
    type Narrow<K> = <<<K as Kernel>::Input as Lanes>::Element as Element>::Narrow;
    for (o, &x) in out.iter_mut().zip(input) {
        *o = kernel.apply::<Narrow<K>>(x);
        not_across_iterations();
    }
}

/// An empty instruction sequence LLVM cannot see through: it keeps the loop vectoriser from
/// vectorising a loop of packet operations a second time, across iterations, which it
/// otherwise does with per-lane loads and shuffles (2–3× slower than the packets alone).
#[inline(always)]
fn not_across_iterations() {
    #[cfg(any(target_arch = "x86_64", target_arch = "x86", target_arch = "aarch64"))]
    // SAFETY: an empty sequence: it reads, writes and clobbers nothing.
    unsafe {
        core::arch::asm!("", options(nomem, nostack, preserves_flags))
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Real;

    #[test]
    fn lanes_select_each_as_one_value_does() {
        use crate::Select;
        let (a, b) = ([1.0, f64::NAN, 3.0, -0.5], [2.0, 0.0, 3.0, f64::INFINITY]);
        let (x, y) = (F64x4(a), F64x4(b));
        for l in 0..4 {
            assert_eq!(x.lt(y).lane(l), a[l].lt(b[l]));
            assert_eq!(x.le(y).lane(l), a[l].le(b[l]));
            assert_eq!(y.finite().lane(l), Select::finite(b[l]));
            assert_eq!(F64x4::select(x.lt(y), x, y).0[l].to_bits(), f64::select(a[l] < b[l], a[l], b[l]).to_bits());
            assert_eq!(x.min_lanes(y).0[l].to_bits(), a[l].min(b[l]).to_bits());
            assert_eq!(x.max_lanes(y).0[l].to_bits(), a[l].max(b[l]).to_bits());
        }
        assert!(F64x4::any(x.lt(y)) && !F64x4::all(x.lt(y)) && F64x4::all(!Mask4::default()));
        // A mask from truth values, and its logic lane by lane.
        let (m, n) = (Mask4::new([true, false, true, false]), Mask4::new([true, true, false, false]));
        assert_eq!(m.to_array(), [true, false, true, false]);
        assert_eq!((m & n).to_array(), [true, false, false, false]);
        assert_eq!((m | n).to_array(), [true, true, true, false]);
        assert_eq!((!m).to_array(), [false, true, false, true]);
        assert_eq!(F64x4::select(m, x, y).to_array().map(f64::to_bits), [a[0], b[1], a[2], b[3]].map(f64::to_bits));
        assert!(!F64x4::any(Mask4::default()) && F64x4::all(Mask4::new([true; 4])));
        assert_eq!(format!("{m:?}"), "Mask4([true, false, true, false])");
    }

    #[test]
    fn down_in_lanes_is_down_in_each_lane() {
        use crate::{Select, Vector, down, down_lanes};
        // Ordinary weights, zero, a weight whose inverse overflows, a NaN, a quotient that
        // overflows, and a negative weight.
        let cases = [
            Vector { e1: 1.0, e2: -2.0, e3: 3.0, eo: 2.0, ei: 0.0 },
            Vector { e1: 1.0, e2: 0.0, e3: 0.0, eo: 0.0, ei: 1.0 },
            Vector { e1: 1e-310, e2: 2e-310, e3: 0.0, eo: 1e-310, ei: 0.0 },
            Vector { e1: 1.0, e2: 0.0, e3: 0.0, eo: f64::NAN, ei: 0.0 },
            Vector { e1: 1e300, e2: 0.0, e3: 0.0, eo: 1e-300, ei: 0.0 },
            Vector { e1: 4.0, e2: 6.0, e3: 8.0, eo: -2.0, ei: 0.0 },
            Vector { e1: 3.0, e2: 1.0, e3: 2.0, eo: 0.5, ei: 0.0 },
            Vector { e1: 3.0, e2: 1.0, e3: 2.0, eo: 1.0, ei: 0.0 },
        ];
        for four in cases.chunks(4) {
            let (points, ok) = down_lanes(Vector::pack([four[0], four[1], four[2], four[3]]));
            for (l, v) in four.iter().enumerate() {
                let (point, valid) = down_lanes(*v);
                assert_eq!(valid, down(*v).is_ok(), "{v:?}");
                assert_eq!(ok.lane(l), valid, "lane {l}: {v:?}");
                if let Ok(want) = down(*v) {
                    assert_eq!(point.map(f64::to_bits), want.map(f64::to_bits));
                    assert_eq!(points.map(|c| c.0[l].to_bits()), want.map(f64::to_bits), "lane {l}");
                }
            }
            assert_eq!(F64x4::any(ok), ok.to_array().iter().any(|&b| b));
        }
    }
    use crate::{Circle, Even, Line, Motor, Rotor, Sandwich, Sphere, Translator, Vector, up};

    struct Sandwiched;
    impl Kernel for Sandwiched {
        type Input = (Motor, Vector);
        type Output = Vector;
        #[inline(always)]
        fn apply<L: Lane>(&self, (m, x): (Motor<L>, Vector<L>)) -> Vector<L> {
            m.sandwich(x)
        }
    }

    /// Three operands: `(M x M̃ ∧ x) ∧ y`.
    struct Wedged;
    impl Kernel for Wedged {
        type Input = (Motor, Vector, Vector);
        type Output = Circle;
        #[inline(always)]
        fn apply<L: Lane>(&self, (m, x, y): (Motor<L>, Vector<L>, Vector<L>)) -> Circle<L> {
            (m.sandwich(x) ^ x) ^ y
        }
    }

    /// A motor given at run time, in every lane.
    struct MoveBy(Motor);
    impl Kernel for MoveBy {
        type Input = Vector;
        type Output = Vector;
        #[inline(always)]
        fn apply<L: Lane>(&self, x: Vector<L>) -> Vector<L> {
            splat::<Motor, L>(self.0).sandwich(x)
        }
    }

    #[test]
    fn kernels_carry_run_time_state_and_give_the_bits_of_one_at_a_time() {
        let m: Motor =
            Motor::from_rotor_translation(Rotor::from_axis_angle([1.0, 2.0, 3.0], 0.7).unwrap(), [1.0, -2.0, 0.5]);
        let points: Vec<Vector> = (0..11).map(|k| up([k as f64, 0.5 * k as f64, -1.0])).collect();
        let mut out = vec![Vector::zero(); points.len()];
        run(&MoveBy(m), &points, &mut out).unwrap();
        for (x, y) in points.iter().zip(&out) {
            assert_eq!(*y, m.sandwich(*x));
        }
    }

    struct Product;
    impl Kernel for Product {
        type Input = (Circle, Circle);
        type Output = Even;
        #[inline(always)]
        fn apply<L: Lane>(&self, (a, b): (Circle<L>, Circle<L>)) -> Even<L> {
            a * b
        }
    }

    fn point(k: usize, seed: f64) -> Vector {
        let t = seed + k as f64;
        up([3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5])
    }

    fn motor(k: usize) -> Motor {
        let r = Rotor::from_axis_angle([0.6, -0.48, 0.64], 0.1 * k as f64).unwrap();
        Motor::from_rotor_translator(r, Translator::from_vector([k as f64, -2.0, 0.5]))
    }

    /// `pack_rows`/`unpack_rows` (AVX transposes in place) and `pack_rows8`/`unpack_rows8`
    /// (AVX-512) against packing by value, for types of every size of block and remainder
    /// (1, 4, 5, 6, 8, 10 and 16 coefficients) and a tuple.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn transposes_in_place_agree_with_packing() {
        fn check<X: Lanes + PartialEq + core::fmt::Debug>(values: [X; 8], blank: X)
        where
            Over<X, F64x4>: PartialEq + core::fmt::Debug,
            Over<X, F64x8>: PartialEq + core::fmt::Debug,
        {
            // SAFETY: run only where the CPU has AVX (AVX-512 for the second part); the
            // pointers are to `values` and `back`.
            unsafe {
                let four = [0, 1, 2, 3].map(|l| values[l]);
                let packed = X::pack_rows(four.each_ref().map(|v| v as *const X));
                assert_eq!(packed, X::pack(four));
                let mut back = [blank; 4];
                X::unpack_rows(packed, back.each_mut().map(|v| v as *mut X));
                assert_eq!(back, four);
                if avx512() {
                    let packed = X::pack_rows8(values.each_ref().map(|v| v as *const X));
                    assert_eq!(packed, X::pack_lanes::<F64x8>(&values));
                    let mut back = [blank; 8];
                    X::unpack_rows8(packed, back.each_mut().map(|v| v as *mut X));
                    assert_eq!(back, values);
                }
            }
        }
        if !std::is_x86_feature_detected!("avx") {
            return;
        }
        // Distinct values in every coefficient of every lane.
        macro_rules! values {
            ($t:ident, $seed:expr) => {
                core::array::from_fn::<crate::$t, 8, _>(|l| {
                    crate::$t::from_array(core::array::from_fn(|k| (100 * l + k) as f64 + $seed))
                })
            };
        }
        macro_rules! each {
            ($($t:ident),*) => {$(
                check(values!($t, 0.5), crate::$t::zero());
            )*};
        }
        each!(Scalar, Plane, Vector, Line, Motor, Circle, Even);
        let (rotors, points) = (values!(Rotor, 0.25), values!(Vector, 0.75));
        check(core::array::from_fn(|l| (rotors[l], points[l])), (crate::Rotor::zero(), Vector::zero()));
    }

    /// The f32 transposes, AVX on eight rows (`pack_rows_f32x8`) and AVX-512 on sixteen
    /// (`pack_rows16`), against packing by value, for every size of block and remainder
    /// (1, 4, 5, 6, 8, 10 and 16 coefficients) and a tuple.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn f32_transposes_in_place_agree_with_packing() {
        fn check<X: Lanes + PartialEq + core::fmt::Debug>(values: [X; 16], blank: X)
        where
            Over<X, F32x8>: PartialEq + core::fmt::Debug,
            Over<X, F32x16>: PartialEq + core::fmt::Debug,
        {
            // SAFETY: run only where the CPU has AVX (AVX-512 for the second part); the
            // pointers are to `values` and `back`.
            unsafe {
                let eight: [X; 8] = core::array::from_fn(|l| values[l]);
                let packed = X::pack_rows_f32x8(eight.each_ref().map(|v| v as *const X));
                assert_eq!(packed, X::pack_lanes::<F32x8>(&eight));
                let mut back = [blank; 8];
                X::unpack_rows_f32x8(packed, back.each_mut().map(|v| v as *mut X));
                assert_eq!(back, eight);
                if avx512() {
                    let packed = X::pack_rows16(values.each_ref().map(|v| v as *const X));
                    assert_eq!(packed, X::pack_lanes::<F32x16>(&values));
                    let mut back = [blank; 16];
                    X::unpack_rows16(packed, back.each_mut().map(|v| v as *mut X));
                    assert_eq!(back, values);
                }
            }
        }
        if !std::is_x86_feature_detected!("avx") {
            return;
        }
        // Distinct values in every coefficient of every lane, exact in f32.
        macro_rules! values {
            ($t:ident, $seed:expr) => {
                core::array::from_fn::<crate::$t<f32>, 16, _>(|l| {
                    crate::$t::from_array(core::array::from_fn(|k| (100 * l + k) as f32 + $seed))
                })
            };
        }
        macro_rules! each {
            ($($t:ident),*) => {$(
                check(values!($t, 0.5), crate::$t::zero());
            )*};
        }
        each!(Scalar, Plane, Vector, Line, Motor, Circle, Even);
        let (rotors, points) = (values!(Rotor, 0.25), values!(Vector, 0.75));
        check(core::array::from_fn(|l| (rotors[l], points[l])), (crate::Rotor::zero(), Vector::zero()));
    }

    /// Every level this CPU has.
    fn levels() -> Vec<Level> {
        let mut levels = vec![Level::Baseline];
        #[cfg(target_arch = "x86_64")]
        {
            if avx2() {
                levels.push(Level::Avx2);
            }
            if avx512() {
                levels.push(Level::Avx512);
            }
        }
        levels
    }

    #[test]
    fn every_path_gives_the_bits_of_one_at_a_time() {
        for n in [0, 1, 3, 4, 5, 7, 8, 11, 12, 16, 21] {
            let moved: Vec<_> = (0..n).map(|k| (motor(k), point(k, 0.0))).collect();
            let want: Vec<Vector> = moved.iter().map(|&(m, x)| m.sandwich(x)).collect();
            let mut got = vec![Vector::zero(); n];
            for level in levels() {
                got.fill(Vector::zero());
                run_at(level, &Sandwiched, &moved[..], &mut got).unwrap();
                assert_eq!(got, want, "run at {level:?}, n = {n}");
            }
            // The same operands as two arrays read in place.
            let (motors, points): (Vec<Motor>, Vec<Vector>) = moved.iter().copied().unzip();
            for level in levels() {
                got.fill(Vector::zero());
                run_at(level, &Sandwiched, (&motors[..], &points[..]), &mut got).unwrap();
                assert_eq!(got, want, "columns at {level:?}, n = {n}");
            }
            let thirds: Vec<Vector> = (0..n).map(|k| point(k, 7.0)).collect();
            let wedged: Vec<Circle> = (0..n).map(|k| (motors[k].sandwich(points[k]) ^ points[k]) ^ thirds[k]).collect();
            let mut circles = vec![Circle::zero(); n];
            for level in levels() {
                circles.fill(Circle::zero());
                run_at(level, &Wedged, (&motors[..], &points[..], &thirds[..]), &mut circles).unwrap();
                assert_eq!(circles, wedged, "three columns at {level:?}, n = {n}");
            }
            for level in levels() {
                got.fill(Vector::zero());
                let f = |(m, x): (Motor<F64x4>, Vector<F64x4>)| m.sandwich(x);
                map_at(level, &moved, &mut got, f).unwrap();
                assert_eq!(got, want, "map on four lanes at {level:?}, n = {n}");
                got.fill(Vector::zero());
                let f = |(m, x): (Motor<F64x8>, Vector<F64x8>)| m.sandwich(x);
                map_at(level, &moved, &mut got, f).unwrap();
                assert_eq!(got, want, "map on eight lanes at {level:?}, n = {n}");
            }

            let circles: Vec<(Circle, Circle)> = (0..n)
                .map(|k| {
                    ((point(k, 0.0) ^ point(k, 1.0)) ^ point(k, 2.0), (point(k, 3.0) ^ point(k, 4.0)) ^ point(k, 5.0))
                })
                .collect();
            let packets: Vec<_> =
                circles.chunks_exact(4).map(|c| <(Circle, Circle)>::pack([c[0], c[1], c[2], c[3]])).collect();
            for level in levels() {
                for stream_bytes in [STREAM_BYTES, 0] {
                    let mut out = vec![Even::<F64x4>::zero(); packets.len()];
                    run_packed_at(level, stream_bytes, &Product, &packets, &mut out).unwrap();
                    for (k, &(a, b)) in circles.iter().enumerate().take(packets.len() * 4) {
                        let got = Even::unpack(out[k / 4])[k % 4];
                        assert_eq!(got, a * b, "packets at {level:?} streaming from {stream_bytes} B, n = {n}");
                    }
                }
            }
        }
    }

    /// f32 values on [`F32x8`] and [`F32x16`] lanes: `run`, `run_columns` and `map` at
    /// every level give the bits of one at a time, for lengths about each lane count.
    #[test]
    fn f32_paths_give_the_bits_of_one_at_a_time() {
        let to32 = |m: Motor| Motor::<f32>::from_array(m.to_array().map(|c| c as f32));
        let p32 = |v: Vector| Vector::<f32>::from_array(v.to_array().map(|c| c as f32));
        struct Sandwiched32;
        impl Kernel for Sandwiched32 {
            type Input = (Motor<f32>, Vector<f32>);
            type Output = Vector<f32>;
            #[inline(always)]
            fn apply<L: Lane>(&self, (m, x): (Motor<L>, Vector<L>)) -> Vector<L> {
                m.sandwich(x)
            }
        }
        for n in [0, 1, 7, 8, 9, 15, 16, 17, 31, 32, 33, 45] {
            let moved: Vec<_> = (0..n).map(|k| (to32(motor(k)), p32(point(k, 0.0)))).collect();
            let want: Vec<Vector<f32>> = moved.iter().map(|&(m, x)| m.sandwich(x)).collect();
            let (motors, points): (Vec<Motor<f32>>, Vec<Vector<f32>>) = moved.iter().copied().unzip();
            let mut got = vec![Vector::<f32>::zero(); n];
            for level in levels() {
                got.fill(Vector::zero());
                run_at(level, &Sandwiched32, &moved[..], &mut got).unwrap();
                assert_eq!(got, want, "run at {level:?}, n = {n}");
                got.fill(Vector::zero());
                run_at(level, &Sandwiched32, (&motors[..], &points[..]), &mut got).unwrap();
                assert_eq!(got, want, "columns at {level:?}, n = {n}");
                got.fill(Vector::zero());
                map_at(level, &moved, &mut got, |(m, x): (Motor<F32x8>, Vector<F32x8>)| m.sandwich(x)).unwrap();
                assert_eq!(got, want, "map on eight lanes at {level:?}, n = {n}");
                got.fill(Vector::zero());
                map_at(level, &moved, &mut got, |(m, x): (Motor<F32x16>, Vector<F32x16>)| m.sandwich(x)).unwrap();
                assert_eq!(got, want, "map on sixteen lanes at {level:?}, n = {n}");
            }
            // Stored packed, eight to a packet (a last one part zeros): no transposes.
            let packets: Vec<Packed<(Motor<f32>, Vector<f32>)>> =
                moved.chunks(8).map(Lanes::pack_lanes::<F32x8>).collect();
            for level in levels() {
                let mut out = vec![Vector::<F32x8>::zero(); packets.len()];
                for stream_bytes in [STREAM_BYTES, 0] {
                    out.fill(Vector::zero());
                    run_packed_at(level, stream_bytes, &Sandwiched32, &packets, &mut out).unwrap();
                    let mut back = vec![Vector::<f32>::zero(); 8 * packets.len()];
                    for (p, b) in out.iter().zip(back.chunks_mut(8)) {
                        Vector::unpack_lanes(*p, b);
                    }
                    assert_eq!(back[..n], want[..], "packed at {level:?} streaming from {stream_bytes} B, n = {n}");
                }
            }
        }
    }

    /// A value in every lane is the packing of that many copies, for every lane width, for a
    /// value of f64 and of f32 and for a tuple.
    #[test]
    fn splat_is_copies_packed() {
        use crate::{Motor, Vector};
        let m = Motor::<f64>::from_array([0.5, -0.25, 1.5, 2.0, -3.0, 0.125, 7.0, -0.75]);
        let v = Vector::<f32>::from_array([1.5, -2.0, 0.25, 3.0, -0.5]);
        fn same<X: Lanes, L: Lane>(x: X) -> bool
        where
            X::Over<L>: PartialEq,
        {
            splat::<X, L>(x) == X::pack_lanes::<L>(&[x; 16][..L::LANES])
        }
        assert!(same::<_, F64x4>(m) && same::<_, F64x8>(m) && same::<_, f64>(m));
        assert!(same::<_, F32x8>(v) && same::<_, F32x16>(v) && same::<_, f32>(v));
        assert!(same::<_, F64x8>((m, Vector::<f64>::from_array([1.0, 2.0, 3.0, 4.0, 5.0]))));
    }

    #[test]
    fn lengths_must_agree() {
        let input = vec![(motor(1), point(1, 0.0)); 3];
        let mut out = vec![Vector::zero(); 2];
        assert_eq!(run(&Sandwiched, &input, &mut out), None);
        let (motors, points): (Vec<Motor>, Vec<Vector>) = input.iter().copied().unzip();
        assert_eq!(run_columns(&Sandwiched, (&motors[..2], &points[..]), &mut out), None);
        assert_eq!(run_columns(&Sandwiched, (&motors[..], &points[..]), &mut out), None);
        assert_eq!(map(&input, &mut out, |(m, x): (Motor<F64x4>, Vector<F64x4>)| m.sandwich(x)), None);
        assert_eq!(out, vec![Vector::zero(); 2], "nothing written");
        let mut packed = vec![Vector::<F64x4>::zero(); 1];
        assert_eq!(run_packed(&Sandwiched, &[], &mut packed), None);
    }

    #[test]
    fn lanes_are_ordered_only_when_all_agree() {
        let (a, b) = (F64x4::new([1.0, 2.0, 3.0, 4.0]), F64x4::new([2.0, 3.0, 4.0, 5.0]));
        assert!(a < b);
        assert!(b > a);
        assert_ne!(a, b);
        let mixed = F64x4::new([0.0, 5.0, 3.0, 4.0]);
        assert_eq!(a.partial_cmp(&mixed), None);
        assert_eq!(Real::max(a, mixed).to_array(), [1.0, 5.0, 3.0, 4.0]);
        assert!(F64x4::splat(1.0).is_finite() && !F64x4::new([1.0, f64::NAN, 1.0, 1.0]).is_finite());
        assert_eq!((-a).to_array(), [-1.0, -2.0, -3.0, -4.0]);
        assert_eq!(Real::sqrt(F64x4::new([4.0, 9.0, 16.0, 0.25])).to_array(), [2.0, 3.0, 4.0, 0.5]);
        let (l, s) =
            (Line::through([0.0; 3], [1.0, 0.0, 0.0]).unwrap(), Sphere::from_centre_radius([0.0; 3], 1.0).unwrap());
        assert_eq!(crate::PointPair::unpack(Line::pack([l; 4]) & Sphere::pack([s; 4]))[2], l & s);
    }
}
