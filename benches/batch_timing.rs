//! Times the six operations of the Versor comparison (benches/peers/compare.sh) on our
//! generated types, one at a time (`scalar`) and four lanes at a time through
//! [`cga_core::simd`] (`simd`, packing and unpacking included), the same way
//! benches/peers/versor.cpp times Versor: batches of 256 operands, `REPS` passes per round,
//! the median over rounds, in ns per operation. Prints `operation form ns` lines.
//!
//! It also prints each operation's `floor`: its multiplications (the generated code does one
//! per nonzero term of the Cayley table, `cga_core::product_table`) at this core's peak rate
//! of f64 multiplications, measured here with the widest vectors the CPU has. No code doing
//! those multiplications, vectorised any way, is faster than its floor, so the floor bounds
//! what any ratio against a peer can be on this machine.
//!
//! `cargo run --release -p cga-benches --example batch_timing`

use cga_benches::kernels::{CircleCircle, MeetSphere, MotorMotor, MotorOnPoint, RotorRotor, ThreePoints};
use cga_benches::medians_ns;
use cga_core::simd::{F64x4, F64x8, Kernel, Lanes, map, run, run_packed};
use cga_core::{Circle, Line, Motor, ProductKind, Rotor, Sandwich, Sphere, Vector, product_table};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 256;
const REPS: usize = 4000;
const ROUNDS: usize = 15;

/// `up(x)` of the same deterministic spread of points as versor.cpp.
fn point(i: usize, seed: f64) -> Vector {
    let t = seed + i as f64;
    let x = [3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5];
    cga_core::up(x)
}

/// Times an operation over `input` one at a time (`scalar`), through
/// [`cga_core::simd::run`] (`batch`: packing, the lanes, unpacking, dispatched to the widest
/// lanes the CPU has), through [`cga_core::simd::map`] with the kernel's body as an
/// `#[inline(always)]` closure on four lanes (`map`) and on eight (`map8`), and over
/// packets already in lanes (`packets`),
/// printing each; every form gives the bits of one at a time.
fn both<K: Kernel + Default>(name: &str, input: &[K::Input], op: impl Fn(K::Input) -> K::Output)
where
    K::Input: Lanes<Element = f64>,
    K::Output: Lanes<Element = f64> + Default + PartialEq + std::fmt::Debug,
{
    let one_at_a_time: Vec<K::Output> = input.iter().map(|&x| op(x)).collect();
    let mut scalar_out = vec![K::Output::default(); input.len()];
    let (mut batch_out, mut map_out, mut map8_out) = (scalar_out.clone(), scalar_out.clone(), scalar_out.clone());
    let packed_in: Vec<_> = input.chunks_exact(4).map(|x| K::Input::pack([x[0], x[1], x[2], x[3]])).collect();
    let mut packed_out: Vec<_> = packed_in.iter().map(|&x| K::default().apply(x)).collect();
    let kernel = K::default();
    let medians = medians_ns(
        N,
        REPS,
        ROUNDS,
        &mut [
            &mut || {
                for (o, &x) in scalar_out.iter_mut().zip(black_box(input)) {
                    *o = op(x);
                }
                black_box(&scalar_out);
            },
            &mut || {
                run(&K::default(), black_box(input), &mut batch_out);
                black_box(&batch_out);
            },
            &mut || {
                map(
                    black_box(input),
                    &mut map_out,
                    #[inline(always)]
                    |x| kernel.apply::<F64x4>(x),
                );
                black_box(&map_out);
            },
            &mut || {
                map(
                    black_box(input),
                    &mut map8_out,
                    #[inline(always)]
                    |x| kernel.apply::<F64x8>(x),
                );
                black_box(&map8_out);
            },
            &mut || {
                run_packed(&K::default(), black_box(&packed_in), &mut packed_out);
                black_box(&packed_out);
            },
        ],
    );
    for (form, out) in [("scalar", &scalar_out), ("batch", &batch_out), ("map", &map_out), ("map8", &map8_out)] {
        assert_eq!(*out, one_at_a_time, "{name}: {form} differs from one at a time");
    }
    for (form, ns) in ["scalar", "batch", "map", "map8", "packets"].iter().zip(medians) {
        println!("{name} {form} {ns:.3}");
    }
}

/// The multiplications of the generated products `(kind, lhs, rhs)` the operation chains.
fn multiplications(products: &[(ProductKind, &str, &str)]) -> usize {
    let table = product_table::<f64>();
    let terms = |&(kind, lhs, rhs): &(ProductKind, &str, &str)| {
        let e = table.iter().find(|e| e.kind == kind && e.lhs == lhs && e.rhs == rhs);
        e.unwrap_or_else(|| panic!("no generated {kind:?} of {lhs} and {rhs}")).terms
    };
    products.iter().map(terms).sum()
}

/// ns per f64 multiplication at this core's peak: twelve independent chains of vector
/// multiplications (more than latency × ports on current x86-64 cores), 4 lanes with AVX
/// and 8 with AVX-512 where the CPU has them; the faster, median over rounds.
#[cfg(target_arch = "x86_64")]
fn peak_multiplication_ns() -> f64 {
    use std::arch::x86_64::*;
    const STEPS: usize = 1 << 20;
    const CHAINS: usize = 12;
    /// The chains: `STEPS` multiplications by `c` of each of `CHAINS` vectors of ones.
    #[inline(always)]
    fn chains<V: Copy>(one: V, c: V, mul: impl Fn(V, V) -> V) -> [V; CHAINS] {
        let mut acc = [one; CHAINS];
        for _ in 0..STEPS {
            for a in &mut acc {
                *a = mul(*a, c);
            }
        }
        acc
    }
    #[target_feature(enable = "avx")]
    fn avx(c: f64) -> f64 {
        let acc = chains(_mm256_set1_pd(1.0), _mm256_set1_pd(c), |a, c| _mm256_mul_pd(a, c));
        let mut lanes = [0.0; 4];
        // SAFETY: `lanes` holds four f64.
        unsafe {
            _mm256_storeu_pd(lanes.as_mut_ptr(), acc.into_iter().fold(_mm256_setzero_pd(), |s, a| _mm256_add_pd(s, a)))
        };
        lanes.iter().sum()
    }
    #[target_feature(enable = "avx512f")]
    fn avx512(c: f64) -> f64 {
        let acc = chains(_mm512_set1_pd(1.0), _mm512_set1_pd(c), |a, c| _mm512_mul_pd(a, c));
        _mm512_reduce_add_pd(acc.into_iter().fold(_mm512_setzero_pd(), |s, a| _mm512_add_pd(s, a)))
    }
    let time = |lanes: usize, f: &dyn Fn(f64) -> f64| {
        let mut r: Vec<f64> = (0..ROUNDS)
            .map(|_| {
                let t = Instant::now();
                black_box(f(black_box(1.0)));
                t.elapsed().as_nanos() as f64 / (STEPS * CHAINS * lanes) as f64
            })
            .collect();
        r.sort_by(f64::total_cmp);
        r[ROUNDS / 2]
    };
    let mut best = f64::INFINITY;
    if std::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU has AVX.
        let ns = time(4, &|c| unsafe { avx(c) });
        println!("multiply avx {ns:.4}");
        best = best.min(ns);
    }
    if std::is_x86_feature_detected!("avx512f") {
        // SAFETY: the CPU has AVX-512F.
        let ns = time(8, &|c| unsafe { avx512(c) });
        println!("multiply avx512 {ns:.4}");
        best = best.min(ns);
    }
    best
}

fn main() {
    let (a, b, c): (Vec<_>, Vec<_>, Vec<_>) =
        (0..N).map(|i| (point(i, 0.0), point(i, 100.0), point(i, 200.0))).collect();
    let ei = Vector::from_array([0.0, 0.0, 0.0, 0.0, 1.0]);
    let lines: Vec<Line> = (0..N).map(|i| (a[i] ^ b[i]) ^ cga_core::ei()).collect();
    let spheres: Vec<Sphere> = (0..N).map(|i| (c[i] - ei.scale(0.5 * (1.0 + 0.1 * (i % 7) as f64))).dual()).collect();
    let circles: Vec<(Circle, Circle)> =
        (0..N).map(|i| ((a[i] ^ b[i]) ^ c[i], (b[i] ^ c[i]) ^ point(i, 300.0))).collect();
    let rotor = |s: f64, k: f64, v: [f64; 3]| Rotor { s, e12: v[0] * k, e13: v[1] * k, e23: v[2] * k };
    let motor = |r: Rotor, t: [f64; 4]| Motor {
        s: r.s,
        e12: r.e12,
        e13: r.e13,
        e23: r.e23,
        e1i: t[0],
        e2i: t[1],
        e3i: t[2],
        e123i: t[3],
    };
    let (mut rotors, mut motors) = (Vec::new(), Vec::new());
    for i in 0..N {
        let (s, k) = ((0.01 * i as f64).sin(), (0.01 * i as f64).cos());
        let (r1, r2) = (rotor(k, s, [0.6, -0.48, 0.64]), rotor(s, k, [0.36, 0.8, -0.48]));
        rotors.push((r1, r2));
        let m1 = motor(r1, [0.3 * i as f64, -0.2, 0.1 * s, 0.05 * k]);
        let m2 = motor(r2, [0.1, 0.7 * s, -0.2 * i as f64, 0.02 * s]);
        motors.push((m1, m2));
    }
    let meets: Vec<(Line, Sphere)> = lines.iter().copied().zip(spheres).collect();
    let triples: Vec<(Vector, Vector, Vector)> = (0..N).map(|i| (a[i], b[i], c[i])).collect();
    let moved: Vec<(Motor, Vector)> = (0..N).map(|i| (motors[i].0, a[i])).collect();

    both::<MeetSphere>("line_meet_sphere", &meets, |(l, s)| l & s);
    both::<ThreePoints>("circle_from_3_points", &triples, |(x, y, z)| (x ^ y) ^ z);
    both::<MotorOnPoint>("motor_on_point", &moved, |(m, x)| m.sandwich(x));
    both::<CircleCircle>("circle_times_circle", &circles, |(x, y)| x * y);
    both::<MotorMotor>("motor_times_motor", &motors, |(x, y)| x * y);
    both::<RotorRotor>("rotor_times_rotor", &rotors, |(x, y)| x * y);

    #[cfg(target_arch = "x86_64")]
    {
        use ProductKind::{Geometric, Outer, Regressive, Sandwich};
        let peak = peak_multiplication_ns();
        println!("multiply peak {peak:.4}");
        for (name, products) in [
            ("line_meet_sphere", &[(Regressive, "Line", "Sphere")][..]),
            ("circle_from_3_points", &[(Outer, "Vector", "Vector"), (Outer, "Bivector", "Vector")]),
            ("motor_on_point", &[(Sandwich, "Motor", "Vector")]),
            ("circle_times_circle", &[(Geometric, "Circle", "Circle")]),
            ("motor_times_motor", &[(Geometric, "Motor", "Motor")]),
            ("rotor_times_rotor", &[(Geometric, "Rotor", "Rotor")]),
        ] {
            let n = multiplications(products);
            println!("{name} multiplications {n}");
            println!("{name} floor {:.3}", n as f64 * peak);
        }
    }
}
