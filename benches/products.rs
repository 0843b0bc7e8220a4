//! Sparse generated types against the dense multivector, in f32 and f64, for the operations
//! the renderer leans on. `cargo bench --bench products`, then `python3 benches/report.py`
//! prints the table of medians and dense/sparse ratios (see benches/README.md).
//!
//! Each measurement runs one operation over a batch of `BATCH` independent inputs (as a
//! renderer does over rays) and criterion reports time per operation. Timing a single call
//! with its operands behind `black_box` would mostly time their trip through memory.

use cga_core::{Circle, Line, Motor, Multivector, Real, Rotor, Sandwich, Sphere, Translator, Vector};
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main, measurement::WallTime};
use std::hint::black_box;
use std::time::Duration;

const BATCH: usize = 256;

/// `up(x) = x + ½x² ei + eo`.
fn point<T: Real>(x: [f64; 3]) -> Vector<T> {
    let x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    Vector::from_array([x[0], x[1], x[2], 1.0, 0.5 * x2].map(T::from_f64))
}

/// A deterministic spread of points, one per batch slot and argument.
fn points<T: Real>(seed: f64) -> Vec<Vector<T>> {
    (0..BATCH)
        .map(|i| {
            let t = seed + i as f64;
            point([3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5])
        })
        .collect()
}

fn dense<T: Real, X: Into<Multivector<T>> + Copy>(xs: &[X]) -> Vec<Multivector<T>> {
    xs.iter().map(|&x| x.into()).collect()
}

/// Time `op` over the whole batch; criterion divides by the batch size.
fn run<A: Copy, B: Copy, R>(g: &mut BenchmarkGroup<WallTime>, name: &str, a: &[A], b: &[B], op: impl Fn(A, B) -> R) {
    let mut out: Vec<R> = Vec::with_capacity(BATCH);
    g.bench_function(name, |bench| {
        bench.iter(|| {
            out.clear();
            out.extend(black_box(a).iter().zip(black_box(b)).map(|(&x, &y)| op(x, y)));
            black_box(&out);
        })
    });
}

fn group<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, WallTime> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(BATCH as u64));
    g
}

fn bench_scalar<T: Real>(c: &mut Criterion, scalar: &str) {
    let (p1, p2, p3) = (points::<T>(0.0), points::<T>(100.0), points::<T>(200.0));
    let ei = Vector::from_array([0.0, 0.0, 0.0, 0.0, 1.0].map(T::from_f64));

    let pairs: Vec<(Vector<T>, Vector<T>)> = p1.iter().copied().zip(p2.iter().copied()).collect();
    let dense_pairs: Vec<(Multivector<T>, Multivector<T>)> = pairs.iter().map(|&(x, y)| (x.into(), y.into())).collect();
    let mut g = group(c, &format!("circle_from_3_points/{scalar}"));
    run(&mut g, "sparse", &pairs, &p3, |(x, y), z| x ^ y ^ z);
    run(&mut g, "dense", &dense_pairs, &dense(&p3), |(x, y), z| x ^ y ^ z);
    g.finish();

    // Lines X1 ∧ X2 ∧ ei (grade 3, non-line blades zero) against spheres through 4 points.
    let lines: Vec<Line<T>> = pairs.iter().map(|&(x, y)| Line::from_storage(&(x ^ y ^ ei).to_storage())).collect();
    let p4 = points::<T>(300.0);
    let spheres: Vec<Sphere<T>> = (0..BATCH).map(|i| p1[i] ^ p2[i] ^ p3[i] ^ p4[i]).collect();
    let mut g = group(c, &format!("line_meet_sphere/{scalar}"));
    run(&mut g, "sparse", &lines, &spheres, |l, s| l & s);
    run(&mut g, "dense", &dense(&lines), &dense(&spheres), |l, s| l & s);
    g.finish();

    let motors: Vec<Motor<T>> = (0..BATCH)
        .map(|i| {
            let t = i as f64;
            let r: Rotor =
                Rotor { s: (0.3 * t).cos(), e12: (0.3 * t).sin() * 0.6, e13: 0.0, e23: (0.3 * t).sin() * -0.8 };
            let m: Motor = r * Translator { s: 1.0, e1i: (0.5 * t).sin(), e2i: -0.5, e3i: (0.2 * t).cos() };
            Motor::from_array(m.to_array().map(T::from_f64))
        })
        .collect();
    let mut g = group(c, &format!("motor_on_point/{scalar}"));
    run(&mut g, "sparse", &motors, &p1, |m, x| m.sandwich(x));
    run(&mut g, "dense", &dense(&motors), &dense(&p1), |m, x| m.sandwich(&x));
    g.finish();

    let circles: Vec<Circle<T>> = pairs.iter().zip(&p3).map(|(&(x, y), &z)| x ^ y ^ z).collect();
    let others: Vec<Circle<T>> = (0..BATCH).map(|i| p4[i] ^ p2[i] ^ p1[i]).collect();
    let mut g = group(c, &format!("circle_times_circle/{scalar}"));
    run(&mut g, "sparse", &circles, &others, |a, b| a * b);
    run(&mut g, "dense", &dense(&circles), &dense(&others), |a, b| a * b);
    g.finish();

    let full = |s: f64| -> Vec<Multivector<T>> {
        (0..BATCH)
            .map(|i| Multivector::new(std::array::from_fn(|k| T::from_f64((s * (k + i) as f64 + 0.1).sin()))))
            .collect()
    };
    let mut g = group(c, &format!("dense_gp_32x32/{scalar}"));
    run(&mut g, "dense", &full(0.37), &full(1.13), |a, b| a * b);
    g.finish();
}

fn products(c: &mut Criterion) {
    bench_scalar::<f64>(c, "f64");
    bench_scalar::<f32>(c, "f32");
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(40);
    targets = products
}
criterion_main!(benches);
