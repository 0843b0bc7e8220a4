//! Moving a million points by one motor, against glam on the same data in the same run.
//! `cargo bench --bench bulk`: criterion's medians per method, then an interleaved
//! comparison (`ROUNDS` alternating rounds of every method, medians and ratios to glam's
//! `DAffine3::transform_point3`), which is what the README's figure quotes: on a shared,
//! noisy machine only ratios measured side by side mean anything.

use cga_core::simd::{self, F64x4, F64x8, Kernel, Lane};
use cga_core::{Motor, Prepare, Rotor, Sandwich, Vector, down, up};
use criterion::{Criterion, Throughput};
use glam::{DAffine3, DQuat, DVec3};
use std::hint::black_box;
use std::time::{Duration, Instant};

const N: usize = 1_000_000;
const ROUNDS: usize = 15;

fn data() -> (Motor, Vec<[f64; 3]>) {
    let r = Rotor::from_axis_angle([0.3, -0.5, 0.8], 1.1).unwrap();
    let m = Motor::from_rotor_translation(r, [1.5, -2.0, 0.25]);
    let points =
        (0..N).map(|i| i as f64).map(|t| [(1.3 * t).sin() * 3.0, (0.7 * t).cos() * 2.0, (2.9 * t).sin()]).collect();
    (m, points)
}

type Method = (&'static str, Box<dyn Fn(&[[f64; 3]], &mut [[f64; 3]])>);

fn methods(m: Motor) -> Vec<Method> {
    let affine = DAffine3::from(m);
    let (q, t): (DQuat, DVec3) = m.into();
    vec![
        (
            "glam DAffine3::transform_point3",
            Box::new(move |x: &[[f64; 3]], out: &mut [[f64; 3]]| {
                for (o, p) in out.iter_mut().zip(x) {
                    *o = affine.transform_point3(DVec3::from(*p)).to_array();
                }
            }),
        ),
        (
            "glam DQuat * v + t",
            Box::new(move |x: &[[f64; 3]], out: &mut [[f64; 3]]| {
                for (o, p) in out.iter_mut().zip(x) {
                    *o = (q * DVec3::from(*p) + t).to_array();
                }
            }),
        ),
        (
            "Motor::transform_points",
            Box::new(move |x: &[[f64; 3]], out: &mut [[f64; 3]]| {
                m.transform_points(x, out).unwrap();
            }),
        ),
        (
            "Motor::move_point",
            Box::new(move |x: &[[f64; 3]], out: &mut [[f64; 3]]| {
                for (o, p) in out.iter_mut().zip(x) {
                    *o = m.move_point(*p);
                }
            }),
        ),
        (
            "down(M up(x) M̃)",
            Box::new(move |x: &[[f64; 3]], out: &mut [[f64; 3]]| {
                for (o, p) in out.iter_mut().zip(x) {
                    *o = down(m.sandwich(up(*p))).unwrap();
                }
            }),
        ),
    ]
}

fn criterion_runs(c: &mut Criterion, m: Motor, points: &[[f64; 3]]) {
    let mut g = c.benchmark_group("move_1e6_points");
    g.throughput(Throughput::Elements(N as u64)).sample_size(20).measurement_time(Duration::from_secs(4));
    let mut out = vec![[0.0; 3]; N];
    for (name, f) in methods(m) {
        g.bench_function(name, |b| b.iter(|| f(black_box(points), black_box(&mut out))));
    }
    g.finish();
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Every method once per round, in turn, `ROUNDS` times; medians in ms and ratios to glam's
/// affine map.
fn interleaved(m: Motor, points: &[[f64; 3]]) {
    let methods = methods(m);
    let mut out = vec![[0.0; 3]; N];
    let mut times = vec![Vec::new(); methods.len()];
    for _ in 0..ROUNDS {
        for (k, (_, f)) in methods.iter().enumerate() {
            let start = Instant::now();
            f(black_box(points), black_box(&mut out));
            times[k].push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    let medians: Vec<f64> = times.into_iter().map(median).collect();
    println!("\nmoving {N} points, {ROUNDS} interleaved rounds, median ms and ratio to glam's affine map:");
    for ((name, _), t) in methods.iter().zip(&medians) {
        println!("  {name:34} {t:7.3} ms  {:5.2}×", t / medians[0]);
    }
}

/// `M X M̃` on many conformal points at once, the motor given at run time.
struct MoveBy(Motor);

impl Kernel for MoveBy {
    type Input = Vector;
    type Output = Vector;
    #[inline(always)]
    fn apply<L: Lane>(&self, x: Vector<L>) -> Vector<L> {
        simd::splat::<Motor, L>(self.0).sandwich(x)
    }
}

/// The same by the motor's prepared matrix (`Prepare`: 21 multiplications a point against
/// the sandwich's two stages), in every lane.
struct MoveByMatrix(<Motor as Prepare<Vector>>::Matrix);

impl Kernel for MoveByMatrix {
    type Input = Vector;
    type Output = Vector;
    #[inline(always)]
    fn apply<L: Lane>(&self, x: Vector<L>) -> Vector<L> {
        let m = self.0.map(|c| L::from_fn(|_| c));
        <Motor<L> as Prepare<Vector<L>>>::apply_matrix(&m, x)
    }
}

type Conformal = (&'static str, Box<dyn Fn(&[Vector], &mut [Vector])>);

/// Moving conformal points (`M X M̃`, all five coefficients) one at a time, through
/// `simd::run` with a kernel and through `simd::map` with a closure on eight lanes and on
/// four, marked `#[inline(always)]` and not: the marked closure is meant to cost nothing
/// over the kernel at the lane width `run` takes on this CPU.
fn conformal_methods(m: Motor, points: &[[f64; 3]]) -> Vec<Conformal> {
    let (lanes, eight) = (simd::splat::<Motor, F64x4>(m), simd::splat::<Motor, F64x8>(m));
    let (affine, euclidean) = (DAffine3::from(m), points.to_vec());
    let moved = std::cell::RefCell::new(vec![[0.0; 3]; points.len()]);
    let prepared = m.prepare::<Vector>();
    vec![
        (
            "sandwich, one at a time",
            Box::new(move |x: &[Vector], out: &mut [Vector]| {
                for (o, p) in out.iter_mut().zip(x) {
                    *o = m.sandwich(*p);
                }
            }),
        ),
        ("simd::run(MoveBy)", Box::new(move |x: &[Vector], out: &mut [Vector]| simd::run(&MoveBy(m), x, out).unwrap())),
        (
            "simd::run(MoveByMatrix)",
            Box::new(move |x: &[Vector], out: &mut [Vector]| {
                simd::run(&MoveByMatrix(Prepare::<Vector>::matrix(m)), x, out).unwrap()
            }),
        ),
        ("m.prepare().apply_into", Box::new(move |x: &[Vector], out: &mut [Vector]| prepared.apply_into(x, out))),
        (
            "glam DAffine3 (Euclidean points)",
            Box::new(move |_: &[Vector], _: &mut [Vector]| {
                for (o, p) in moved.borrow_mut().iter_mut().zip(&euclidean) {
                    *o = affine.transform_point3(DVec3::from(*p)).to_array();
                }
            }),
        ),
        (
            "simd::map(#[inline(always)] |x| …) ×8",
            Box::new(move |x: &[Vector], out: &mut [Vector]| {
                simd::map(
                    x,
                    out,
                    #[inline(always)]
                    |p: Vector<F64x8>| eight.sandwich(p),
                )
                .unwrap()
            }),
        ),
        (
            "simd::map(#[inline(always)] |x| …)",
            Box::new(move |x: &[Vector], out: &mut [Vector]| {
                simd::map(
                    x,
                    out,
                    #[inline(always)]
                    |p: Vector<F64x4>| lanes.sandwich(p),
                )
                .unwrap()
            }),
        ),
        (
            "simd::map(|x| m.sandwich(x))",
            Box::new(move |x: &[Vector], out: &mut [Vector]| {
                simd::map(x, out, |p: Vector<F64x4>| lanes.sandwich(p)).unwrap()
            }),
        ),
    ]
}

/// [`interleaved`] for conformal points; ratios to one at a time.
fn interleaved_conformal(m: Motor, points: &[[f64; 3]]) {
    let methods = conformal_methods(m, points);
    let xs: Vec<Vector> = points.iter().map(|&p| up(p)).collect();
    let mut out = vec![Vector::zero(); N];
    let mut times = vec![Vec::new(); methods.len()];
    for _ in 0..ROUNDS {
        for (k, (_, f)) in methods.iter().enumerate() {
            let start = Instant::now();
            f(black_box(&xs), black_box(&mut out));
            times[k].push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    let medians: Vec<f64> = times.into_iter().map(median).collect();
    println!(
        "\nmoving {N} conformal points, {ROUNDS} interleaved rounds, median ms, ratio to one at a time and to run:"
    );
    for ((name, _), t) in methods.iter().zip(&medians) {
        println!("  {name:34} {t:7.3} ms  {:5.2}×  {:5.2}× run", t / medians[0], t / medians[1]);
    }
}

fn main() {
    let (m, points) = data();
    interleaved(m, &points);
    interleaved_conformal(m, &points);
    let mut c = Criterion::default().configure_from_args();
    criterion_runs(&mut c, m, &points);
    c.final_summary();
}
