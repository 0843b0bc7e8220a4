//! Moving a million points by one motor, against glam on the same data in the same run.
//! `cargo bench --bench bulk`: criterion's medians per method, then an interleaved
//! comparison (`ROUNDS` alternating rounds of every method, medians and ratios to glam's
//! `DAffine3::transform_point3`), which is what the README's figure quotes: on a shared,
//! noisy machine only ratios measured side by side mean anything.

use cga_core::simd::{self, F64x4, F64x8, Kernel, Lane, Lanes, Packed};
use cga_core::{Motor, Prepare, Rotor, RunInto, Sandwich, Vector, down, up};
use criterion::{Criterion, Throughput};
use glam::{DAffine3, DQuat, DVec3};
use std::cell::RefCell;
use std::hint::black_box;
use std::rc::Rc;
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

/// What a form's result must equal, bit for bit: the sandwich one at a time, the prepared
/// matrix one at a time, the points given (a copy), or nothing (glam's, and the copy of its
/// points: on other points).
#[derive(Clone, Copy, PartialEq)]
enum Same {
    Sandwich,
    Matrix,
    Input,
    Glam,
    Euclidean,
}

/// A form's timed call, on the arrays of conformal points in and out.
type Timed = Box<dyn Fn(&[Vector], &mut [Vector])>;
/// A form's last result, given the output array of its last call.
type Outcome = Box<dyn Fn(&[Vector]) -> Vec<Vector>>;

/// A form: its name, what it must equal, the timed call on the arrays of conformal points,
/// and its last result as such an array (unpacked after timing, for the forms that keep
/// their own).
struct Conformal {
    name: &'static str,
    same: Same,
    time: Timed,
    result: Outcome,
}

impl Conformal {
    /// A form on the arrays given, its result the output array.
    fn on_arrays(name: &'static str, same: Same, time: impl Fn(&[Vector], &mut [Vector]) + 'static) -> Conformal {
        Conformal { name, same, time: Box::new(time), result: Box::new(|out: &[Vector]| out.to_vec()) }
    }

    /// A form on the points stored packed (four to a packet, packed once, before timing),
    /// into packets of its own.
    fn packed(
        name: &'static str,
        same: Same,
        xs: &[Vector],
        f: impl Fn(&[Packed<Vector>], &mut [Packed<Vector>]) + 'static,
    ) -> Conformal {
        let input: Vec<Packed<Vector>> = xs.chunks(4).map(Lanes::pack_lanes::<F64x4>).collect();
        let out = Rc::new(RefCell::new(vec![Vector::<F64x4>::zero(); input.len()]));
        let (kept, n) = (out.clone(), xs.len());
        Conformal {
            name,
            same,
            time: Box::new(move |_: &[Vector], _: &mut [Vector]| f(&input, &mut out.borrow_mut())),
            result: Box::new(move |_: &[Vector]| {
                let mut back = vec![Vector::zero(); 4 * kept.borrow().len()];
                for (p, b) in kept.borrow().iter().zip(back.chunks_mut(4)) {
                    Vector::unpack_lanes(*p, b);
                }
                back.truncate(n);
                back
            }),
        }
    }
}

/// Moving conformal points (`M X M̃`, all five coefficients) one at a time, through
/// `simd::run` with a kernel, through `simd::run_packed` on points stored packed, and
/// through `simd::map` with a closure on eight lanes and on four, marked `#[inline(always)]`
/// and not: the marked closure is meant to cost nothing over the kernel at the lane width
/// `run` takes on this CPU. Last, a plain copy of the conformal points and of glam's
/// Euclidean ones: the floors of the memory path, which say what the bytes alone allow.
fn conformal_methods(m: Motor, points: &[[f64; 3]], xs: &[Vector]) -> Vec<Conformal> {
    let (lanes, eight) = (simd::splat::<Motor, F64x4>(m), simd::splat::<Motor, F64x8>(m));
    let (affine, euclidean, euclidean_copy) = (DAffine3::from(m), points.to_vec(), points.to_vec());
    let (moved, copied) = (RefCell::new(vec![[0.0; 3]; points.len()]), RefCell::new(vec![[0.0; 3]; points.len()]));
    let prepared = m.prepare::<Vector>();
    let matrix = Prepare::<Vector>::matrix(m);
    vec![
        Conformal::on_arrays("sandwich, one at a time", Same::Sandwich, move |x, out| {
            for (o, p) in out.iter_mut().zip(x) {
                *o = m.sandwich(*p);
            }
        }),
        Conformal::on_arrays("simd::run(MoveBy)", Same::Sandwich, move |x, out| simd::run(&MoveBy(m), x, out).unwrap()),
        Conformal::on_arrays("simd::run(MoveByMatrix)", Same::Matrix, move |x, out| {
            simd::run(&MoveByMatrix(matrix), x, out).unwrap()
        }),
        Conformal::on_arrays("m.prepare().apply_into", Same::Matrix, move |x, out| prepared.apply_into(x, out)),
        Conformal::on_arrays("m.prepare().run_into", Same::Matrix, move |x, out| prepared.run_into(x, out).unwrap()),
        Conformal::packed("stored packed: run_packed(MoveBy)", Same::Sandwich, xs, move |x, out| {
            simd::run_packed(&MoveBy(m), x, out).unwrap()
        }),
        Conformal::packed("stored packed: run_packed(Matrix)", Same::Matrix, xs, move |x, out| {
            simd::run_packed(&MoveByMatrix(matrix), x, out).unwrap()
        }),
        Conformal {
            name: "glam DAffine3 (Euclidean points)",
            same: Same::Glam,
            time: Box::new(move |_: &[Vector], _: &mut [Vector]| {
                for (o, p) in moved.borrow_mut().iter_mut().zip(&euclidean) {
                    *o = affine.transform_point3(DVec3::from(*p)).to_array();
                }
            }),
            result: Box::new(|out: &[Vector]| out.to_vec()),
        },
        Conformal::on_arrays("simd::map(#[inline(always)] |x| …) ×8", Same::Sandwich, move |x, out| {
            simd::map(
                x,
                out,
                #[inline(always)]
                |p: Vector<F64x8>| eight.sandwich(p),
            )
            .unwrap()
        }),
        Conformal::on_arrays("simd::map(#[inline(always)] |x| …)", Same::Sandwich, move |x, out| {
            simd::map(
                x,
                out,
                #[inline(always)]
                |p: Vector<F64x4>| lanes.sandwich(p),
            )
            .unwrap()
        }),
        Conformal::on_arrays("simd::map(|x| m.sandwich(x))", Same::Sandwich, move |x, out| {
            simd::map(x, out, |p: Vector<F64x4>| lanes.sandwich(p)).unwrap()
        }),
        // The floors of the memory path: the same bytes read and written with no arithmetic.
        Conformal::on_arrays("copy of the conformal points", Same::Input, |x, out| out.copy_from_slice(x)),
        Conformal {
            name: "copy of glam's Euclidean points",
            same: Same::Euclidean,
            time: Box::new(move |_: &[Vector], _: &mut [Vector]| copied.borrow_mut().copy_from_slice(&euclidean_copy)),
            result: Box::new(|out: &[Vector]| out.to_vec()),
        },
    ]
}

/// [`interleaved`] for conformal points, timed two ways: every form once per round in turn
/// (`ROUNDS` rounds), and each form for `ROUNDS` rounds of its own, one form after another.
/// Interleaved, a form finds its arrays (80 MB a pass for the conformal forms, 48 for glam's)
/// evicted from the L3 by the forms before it; in its own block, it finds what its last
/// round left there. Glam's form is timed both ways as ours are. Ratios to glam's affine map
/// and to `run`. Every result is then checked against one at a time, bit for bit.
fn interleaved_conformal(m: Motor, points: &[[f64; 3]]) {
    let xs: Vec<Vector> = points.iter().map(|&p| up(p)).collect();
    let methods = conformal_methods(m, points, &xs);
    let glam = methods.iter().position(|f| f.same == Same::Glam).unwrap();
    let mut out = vec![Vector::zero(); N];
    let mut times = vec![Vec::new(); methods.len()];
    for _ in 0..ROUNDS {
        for (k, f) in methods.iter().enumerate() {
            let start = Instant::now();
            (f.time)(black_box(&xs), black_box(&mut out));
            times[k].push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    let mixed: Vec<f64> = times.into_iter().map(median).collect();
    let alone: Vec<f64> = methods
        .iter()
        .map(|f| {
            median(
                (0..ROUNDS)
                    .map(|_| {
                        let start = Instant::now();
                        (f.time)(black_box(&xs), black_box(&mut out));
                        start.elapsed().as_secs_f64() * 1e3
                    })
                    .collect(),
            )
        })
        .collect();
    println!(
        "\nmoving {N} conformal points, median ms and ratio to glam's affine map and to run: {ROUNDS} interleaved rounds | {ROUNDS} rounds of each form alone:"
    );
    for (k, f) in methods.iter().enumerate() {
        let (t, u) = (mixed[k], alone[k]);
        println!(
            "  {:34} {t:7.3} ms  {:5.2}× glam  {:5.2}× run | {u:7.3} ms  {:5.2}× glam  {:5.2}× run",
            f.name,
            t / mixed[glam],
            t / mixed[1],
            u / alone[glam],
            u / alone[1]
        );
    }
    let sandwich: Vec<Vector> = xs.iter().map(|&x| m.sandwich(x)).collect();
    let mut matrix = vec![Vector::zero(); N];
    m.prepare::<Vector>().apply_into(&xs, &mut matrix);
    for f in &methods {
        let want = match f.same {
            Same::Sandwich => &sandwich,
            Same::Matrix => &matrix,
            Same::Input => &xs,
            Same::Glam | Same::Euclidean => continue,
        };
        (f.time)(&xs, &mut out);
        assert!((f.result)(&out) == *want, "{} differs from one at a time", f.name);
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
