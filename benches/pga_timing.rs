//! Times 3D PGA (cga-algebras' `pga`) on the operations of the klein comparison
//! (benches/peers/klein.sh), the same way benches/peers/klein.cpp times klein: a motor moving
//! 1e6 points (`motor_points`, by the prepared matrix `motor.prepare()`), and over batches
//! of 256 operands the motor product (`motor_motor`), the join of two points (`join`), the
//! meet of two planes (`meet`) and of three (`meet3`), each in f32 and f64, the median over
//! rounds in ns per operation (interleaved rounds for the batches; for the points, each form's
//! rounds in turn, as klein.cpp times them). Prints `operation form ns` lines (`form` is `f32`
//! or `f64` one at a time, `f32-lanes` or `f64-lanes` on SIMD lanes by `simd::run`: sixteen
//! f32 to an AVX-512 register (eight with AVX2) or four f64 to an AVX one, transposed from and
//! to the arrays of values (for the points the prepared motor's generated `run_into`, the same
//! transposes through `simd::map`); `f32-packed` or `f64-packed` by `simd::run_packed` on the
//! same values stored packed, eight f32 or four f64 to a 256-bit packet, packed once before
//! timing); and
//! for the points `f32-copy` and `f64-copy`, a plain copy of the same points, the floor of the
//! memory path that moving them takes.
//!
//! `cargo run --release -p cga-benches --example pga_timing`

use cga_algebras::pga::{Line, Motor, Plane, Point, Prepare, RunInto, Sandwich};
use cga_benches::medians_ns;
use cga_core::Real;
use cga_core::simd::{Element, Kernel, Lane, Lanes, Packed, run, run_packed};
use std::hint::black_box;

const BATCH: usize = 256;
const POINTS: usize = 1_000_000;
const ROUNDS: usize = 15;

/// The same deterministic spread as klein.cpp: coordinate `k` of operand `i`.
fn coord(i: usize, k: usize, seed: f64) -> f64 {
    let t = seed + i as f64;
    [3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5][k]
}

fn point<T: Real>(i: usize, seed: f64) -> Point<T> {
    Point::at([0, 1, 2].map(|k| T::from_f64(coord(i, k, seed))))
}

fn plane<T: Real>(i: usize, seed: f64) -> Plane<T> {
    let [a, b, c] = [0, 1, 2].map(|k| coord(i, k, seed));
    let n = (a * a + b * b + c * c).sqrt();
    Plane::new(T::from_f64(a / n), T::from_f64(b / n), T::from_f64(c / n), T::from_f64(coord(i, 0, seed + 7.0)))
}

/// A unit motor: a rotation about an axis by an angle, then a translation (klein.cpp's
/// `motor(i)`, the same numbers).
fn motor<T: Real>(i: usize) -> Motor<T> {
    let (s, c) = ((0.01 * i as f64 + 0.3).sin(), (0.01 * i as f64 + 0.3).cos());
    // r = c + s (0.6 e23 − 0.48 e31 + 0.64 e12): the axis (0.6, −0.48, 0.64) is a unit vector.
    let r = [c, 0.0, 0.0, 0.0, 0.64 * s, -0.48 * s, 0.6 * s, 0.0];
    // t = 1 + ½ (0.3 e01 − 0.2 e02 + 0.1 e03) moves by (−0.6, 0.4, −0.2) in this basis.
    let t = [1.0, 0.15, -0.1, 0.05, 0.0, 0.0, 0.0, 0.0];
    let m = Motor::from_array(t) * Motor::from_array(r);
    Motor::from_array(m.to_array().map(T::from_f64))
}

/// An operation over a batch of 256 operands in f32 and in f64, one at a time and on SIMD
/// lanes (`simd::run` of the same operation as a kernel), timed interleaved.
fn batch<K32: Kernel, K64: Kernel>(
    name: &str,
    input: (&[K32::Input], &[K64::Input]),
    (k32, k64): (K32, K64),
    (op32, op64): (impl Fn(K32::Input) -> K32::Output, impl Fn(K64::Input) -> K64::Output),
) where
    K32::Output: Default + core::fmt::Debug + PartialEq + Lanes<Element = <K32::Input as Lanes>::Element>,
    K64::Output: Default + core::fmt::Debug + PartialEq + Lanes<Element = <K64::Input as Lanes>::Element>,
{
    let (mut out32, mut out64) = (vec![K32::Output::default(); BATCH], vec![K64::Output::default(); BATCH]);
    let (mut lanes32, mut lanes64) = (out32.clone(), out64.clone());
    let (packed32, packed64) = (packed(input.0), packed(input.1));
    let (mut packed_out32, mut packed_out64) = (packets(&out32), packets(&out64));
    let medians = medians_ns(
        BATCH,
        4000,
        ROUNDS,
        &mut [
            &mut || {
                for (o, &x) in out32.iter_mut().zip(black_box(input.0)) {
                    *o = op32(x);
                }
                black_box(&out32);
            },
            &mut || {
                for (o, &x) in out64.iter_mut().zip(black_box(input.1)) {
                    *o = op64(x);
                }
                black_box(&out64);
            },
            &mut || {
                run(&k32, black_box(input.0), &mut lanes32).unwrap();
                black_box(&lanes32);
            },
            &mut || {
                run(&k64, black_box(input.1), &mut lanes64).unwrap();
                black_box(&lanes64);
            },
            &mut || {
                run_packed(&k32, black_box(&packed32), &mut packed_out32).unwrap();
                black_box(&packed_out32);
            },
            &mut || {
                run_packed(&k64, black_box(&packed64), &mut packed_out64).unwrap();
                black_box(&packed_out64);
            },
        ],
    );
    // Lanes, and packets, give the bits of one at a time.
    assert_eq!(lanes32, out32, "{name} f32");
    assert_eq!(lanes64, out64, "{name} f64");
    assert_eq!(unpacked::<K32::Output>(&packed_out32, BATCH), out32, "{name} f32 packed");
    assert_eq!(unpacked::<K64::Output>(&packed_out64, BATCH), out64, "{name} f64 packed");
    for (form, ns) in ["f32", "f64", "f32-lanes", "f64-lanes", "f32-packed", "f64-packed"].iter().zip(medians) {
        println!("{name} {form} {ns:.3}");
    }
}

/// Packets per value: eight f32 or four f64 values to a packet.
fn per_packet<X: Lanes>() -> usize {
    <<X::Element as Element>::Narrow as Lane>::LANES
}

/// `xs` stored packed ([`Packed`]: structure of arrays in blocks of a packet, a last packet
/// padded with zeros), as a user who keeps them so holds them: done once, outside the timing.
fn packed<X: Lanes>(xs: &[X]) -> Vec<Packed<X>> {
    xs.chunks(per_packet::<X>()).map(X::pack_lanes).collect()
}

/// Room for as many packets as `xs` takes.
fn packets<X: Lanes>(xs: &[X]) -> Vec<Packed<X>> {
    vec![X::pack_lanes(&[X::pack_filler()]); xs.len().div_ceil(per_packet::<X>())]
}

/// The first `n` values of `packets`, one at a time (to check them).
fn unpacked<X: Lanes>(packets: &[Packed<X>], n: usize) -> Vec<X> {
    let mut out = vec![X::pack_filler(); packets.len() * per_packet::<X>()];
    for (p, o) in packets.iter().zip(out.chunks_mut(per_packet::<X>())) {
        X::unpack_lanes(*p, o);
    }
    out.truncate(n);
    out
}

/// The motor product, the join of two points, and the meets of two and of three planes, as
/// kernels on lanes of either precision.
macro_rules! kernel {
    ($name:ident, ($($input:ident),*) -> $output:ident, |$pat:pat_param| $body:expr) => {
        struct $name<T>(core::marker::PhantomData<T>);
        kernel!(@impl $name f32, ($($input),*) -> $output, |$pat| $body);
        kernel!(@impl $name f64, ($($input),*) -> $output, |$pat| $body);
        impl<T> $name<T> {
            const NEW: Self = $name(core::marker::PhantomData);
        }
    };
    (@impl $name:ident $t:ident, ($($input:ident),*) -> $output:ident, |$pat:pat_param| $body:expr) => {
        impl Kernel for $name<$t> {
            type Input = ($($input<$t>,)*);
            type Output = $output<$t>;
            #[inline(always)]
            fn apply<L: Lane>(&self, $pat: ($($input<L>,)*)) -> $output<L> {
                $body
            }
        }
    };
}

kernel!(MotorProduct, (Motor, Motor) -> Motor, |(a, b)| a * b);
kernel!(Join, (Point, Point) -> Line, |(p, q)| p & q);
kernel!(Meet, (Plane, Plane) -> Line, |(p, q)| p ^ q);
kernel!(Meet3, (Plane, Plane, Plane) -> Point, |(p, q, r)| p ^ q ^ r);

/// The prepared matrix of a motor on points, in every lane: `run_packed`'s kernel.
struct MovePoints<T>([T; 13]);

macro_rules! move_points {
    ($($t:ident),*) => {$(
        impl Kernel for MovePoints<$t> {
            type Input = Point<$t>;
            type Output = Point<$t>;
            #[inline(always)]
            fn apply<L: Lane>(&self, x: Point<L>) -> Point<L> {
                let m = self.0.map(|c| L::from_fn(|_| c.to_f64()));
                <Motor<L> as Prepare<Point<L>>>::apply_matrix(&m, x)
            }
        }
    )*};
}
move_points!(f32, f64);

fn main() {
    let (m32, m64) = (motor::<f32>(1), motor::<f64>(1));
    let (p32, p64): (Vec<Point<f32>>, Vec<Point<f64>>) =
        ((0..POINTS).map(|i| point(i, 0.0)).collect(), (0..POINTS).map(|i| point(i, 0.0)).collect());
    let (mut o32, mut o64, mut lanes, mut lanes32) = (
        vec![Point::zero(); POINTS],
        vec![Point::zero(); POINTS],
        vec![Point::zero(); POINTS],
        vec![Point::zero(); POINTS],
    );
    let (mut copied32, mut copied64) = (o32.clone(), o64.clone());
    let (packed32, packed64) = (packed(&p32), packed(&p64));
    let (mut packed_out32, mut packed_out64) = (packets(&p32), packets(&p64));
    // Each form timed in rounds of its own, one after another (as klein.cpp times klein's):
    // 16 or 32 MB of points in and as many out fill the L3, and a form timed between the
    // others would find its data evicted by theirs, where klein's finds its own.
    let forms: &mut [&mut dyn FnMut()] = &mut [
        &mut || {
            m32.prepare().apply_into(black_box(&p32), &mut o32);
            black_box(&o32);
        },
        &mut || {
            m64.prepare().apply_into(black_box(&p64), &mut o64);
            black_box(&o64);
        },
        &mut || {
            m64.prepare().run_into(black_box(&p64), &mut lanes).unwrap();
            black_box(&lanes);
        },
        &mut || {
            m32.prepare().run_into(black_box(&p32), &mut lanes32).unwrap();
            black_box(&lanes32);
        },
        &mut || {
            run_packed(&MovePoints(Prepare::<Point<f32>>::matrix(m32)), black_box(&packed32), &mut packed_out32)
                .unwrap();
            black_box(&packed_out32);
        },
        &mut || {
            run_packed(&MovePoints(Prepare::<Point>::matrix(m64)), black_box(&packed64), &mut packed_out64).unwrap();
            black_box(&packed_out64);
        },
        // The floor of the memory path: the same bytes read and written with no arithmetic.
        &mut || {
            copied32.copy_from_slice(black_box(&p32));
            black_box(&copied32);
        },
        &mut || {
            copied64.copy_from_slice(black_box(&p64));
            black_box(&copied64);
        },
    ];
    let medians: Vec<f64> = forms.iter_mut().map(|f| medians_ns(POINTS, 3, ROUNDS, &mut [&mut **f])[0]).collect();
    // Each form moves the points as the sandwich does.
    for k in [0, POINTS / 2, POINTS - 1] {
        let want = m64.sandwich(p64[k]).to_array();
        for got in [o64[k].to_array(), lanes[k].to_array(), o32[k].to_array().map(f64::from)] {
            assert!(want.iter().zip(got).all(|(a, b)| (a - b).abs() < 1e-5 * (1.0 + a.abs())), "{want:?} {got:?}");
        }
    }
    assert_eq!(lanes32, o32, "f32 lanes give the bits of one at a time");
    assert_eq!(unpacked::<Point<f32>>(&packed_out32, POINTS), o32, "f32 packets give the bits of one at a time");
    assert_eq!(unpacked::<Point<f64>>(&packed_out64, POINTS), lanes, "f64 packets give the bits of lanes");
    assert!(copied32 == p32 && copied64 == p64);
    let forms = ["f32", "f64", "f64-lanes", "f32-lanes", "f32-packed", "f64-packed", "f32-copy", "f64-copy"];
    for (form, ns) in forms.iter().zip(medians) {
        println!("motor_points {form} {ns:.3}");
    }

    let motors32: Vec<(Motor<f32>, Motor<f32>)> = (0..BATCH).map(|i| (motor(i), motor(i + 300))).collect();
    let motors64: Vec<(Motor<f64>, Motor<f64>)> = (0..BATCH).map(|i| (motor(i), motor(i + 300))).collect();
    batch(
        "motor_motor",
        (&motors32, &motors64),
        (MotorProduct::<f32>::NEW, MotorProduct::<f64>::NEW),
        (|(a, b)| a * b, |(a, b)| a * b),
    );

    let points32: Vec<(Point<f32>, Point<f32>)> = (0..BATCH).map(|i| (point(i, 0.0), point(i, 100.0))).collect();
    let points64: Vec<(Point<f64>, Point<f64>)> = (0..BATCH).map(|i| (point(i, 0.0), point(i, 100.0))).collect();
    batch("join", (&points32, &points64), (Join::<f32>::NEW, Join::<f64>::NEW), (|(p, q)| p & q, |(p, q)| p & q));

    let planes32: Vec<(Plane<f32>, Plane<f32>, Plane<f32>)> =
        (0..BATCH).map(|i| (plane(i, 0.0), plane(i, 100.0), plane(i, 200.0))).collect();
    let planes64: Vec<(Plane<f64>, Plane<f64>, Plane<f64>)> =
        (0..BATCH).map(|i| (plane(i, 0.0), plane(i, 100.0), plane(i, 200.0))).collect();
    let pairs32: Vec<(Plane<f32>, Plane<f32>)> = planes32.iter().map(|&(p, q, _)| (p, q)).collect();
    let pairs64: Vec<(Plane<f64>, Plane<f64>)> = planes64.iter().map(|&(p, q, _)| (p, q)).collect();
    batch("meet", (&pairs32, &pairs64), (Meet::<f32>::NEW, Meet::<f64>::NEW), (|(p, q)| p ^ q, |(p, q)| p ^ q));
    batch(
        "meet3",
        (&planes32, &planes64),
        (Meet3::<f32>::NEW, Meet3::<f64>::NEW),
        (|(p, q, r)| p ^ q ^ r, |(p, q, r)| p ^ q ^ r),
    );
}
