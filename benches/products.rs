//! Sparse generated types against the dense multivector, in f32 and f64, for the operations
//! the renderer leans on. `cargo bench --bench products`, then `python3 benches/report.py`
//! prints the table of medians and dense/sparse ratios (see benches/README.md).

use cga::{Circle, Line, Motor, Multivector, Real, Rotor, Sandwich, Sphere, Translator, Vector};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// `up(x) = x + ½x² ei + eo`.
fn point<T: Real>(x: &[f64; 3]) -> Vector<T> {
    let x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    Vector::from_array([x[0], x[1], x[2], 1.0, 0.5 * x2].map(T::from_f64))
}

fn convert<T: Real>(c: [f64; 32]) -> [T; 32] {
    c.map(T::from_f64)
}

struct Inputs<T: Real> {
    points: [Vector<T>; 3],
    line: Line<T>,
    sphere: Sphere<T>,
    motor: Motor<T>,
    circles: [Circle<T>; 2],
    dense: [Multivector<T>; 2],
}

impl<T: Real> Inputs<T> {
    fn new() -> Self {
        let points = [point(&[1.0, 2.0, -0.5]), point(&[-1.5, 0.3, 2.0]), point(&[0.2, -2.2, 1.1])];
        // X1 ∧ X2 ∧ ei: a grade-3 result whose non-line blades are zero.
        let ei = Vector::from_array([0.0, 0.0, 0.0, 0.0, 1.0].map(T::from_f64));
        let line = Line::from_storage(&((points[0] ^ points[1]) ^ ei).to_storage());
        let sphere = (points[0] ^ points[1]) ^ points[2] ^ point(&[2.0, 1.0, 1.0]);
        let rotor: Rotor<f64> = Rotor { s: 0.8, e12: 0.36, e13: 0.0, e23: -0.48 };
        let motor: Motor<f64> = rotor * Translator { s: 1.0, e1i: 1.5, e2i: -0.5, e3i: 2.0 };
        let circles = [points[0] ^ points[1] ^ points[2], (points[2] ^ points[0]) ^ point(&[0.0, 3.0, 0.0])];
        let full = |s: f64| Multivector::new(convert(std::array::from_fn(|i| (s * (i as f64 + 1.0)).sin())));
        Inputs {
            points,
            line,
            sphere,
            motor: Motor::from_array(motor.to_array().map(T::from_f64)),
            circles,
            dense: [full(0.37), full(1.13)],
        }
    }
}

fn dense<T: Real, X: Into<Multivector<T>>>(x: X) -> Multivector<T> {
    x.into()
}

macro_rules! bench_scalar {
    ($c:expr, $t:ty, $name:literal) => {{
        let i = Inputs::<$t>::new();
        let [p1, p2, p3] = i.points;
        let [d1, d2, d3] = i.points.map(dense);
        let mut g = $c.benchmark_group(concat!("circle_from_3_points/", $name));
        g.bench_function("sparse", |b| b.iter(|| black_box(p1) ^ black_box(p2) ^ black_box(p3)));
        g.bench_function("dense", |b| b.iter(|| black_box(d1) ^ black_box(d2) ^ black_box(d3)));
        g.finish();

        let (dl, ds) = (dense(i.line), dense(i.sphere));
        let mut g = $c.benchmark_group(concat!("line_meet_sphere/", $name));
        g.bench_function("sparse", |b| b.iter(|| black_box(i.line) & black_box(i.sphere)));
        g.bench_function("dense", |b| b.iter(|| black_box(dl) & black_box(ds)));
        g.finish();

        let (dm, dx) = (dense(i.motor), dense(p1));
        let mut g = $c.benchmark_group(concat!("motor_on_point/", $name));
        g.bench_function("sparse", |b| b.iter(|| black_box(i.motor).sandwich(black_box(p1))));
        g.bench_function("dense", |b| b.iter(|| black_box(dm).sandwich(&black_box(dx))));
        g.finish();

        let [c1, c2] = i.circles;
        let (dc1, dc2) = (dense(c1), dense(c2));
        let mut g = $c.benchmark_group(concat!("circle_times_circle/", $name));
        g.bench_function("sparse", |b| b.iter(|| black_box(c1) * black_box(c2)));
        g.bench_function("dense", |b| b.iter(|| black_box(dc1) * black_box(dc2)));
        g.finish();

        let [m1, m2] = i.dense;
        let mut g = $c.benchmark_group(concat!("dense_gp_32x32/", $name));
        g.bench_function("dense", |b| b.iter(|| black_box(m1) * black_box(m2)));
        g.finish();
    }};
}

fn products(c: &mut Criterion) {
    bench_scalar!(c, f64, "f64");
    bench_scalar!(c, f32, "f32");
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2)).sample_size(60);
    targets = products
}
criterion_main!(benches);
