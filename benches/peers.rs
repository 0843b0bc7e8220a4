//! Ours against the Rust crates that implement 3D CGA, on the operations of the Versor
//! comparison: `clifford` 0.3.0 (typed, generated per type; its Motor is the whole even
//! subalgebra, 16 coefficients, and Circle × Circle returns one) and `hisab` 1.4 (a dense
//! 32-coefficient multivector). Batches of 256 as in `products.rs`; criterion's median per
//! operation. Only timing: the operands are generic (points on a spread, generic versors),
//! not checked to be the same objects across libraries' conventions — `clifford`
//! documents e4² = +1, e5² = −1 while its products use the opposite metric, so its
//! coefficients are not comparable one to one.
//!
//! `cargo bench --bench peers --features peers`, then `python3 benches/report.py`.

use cga_benches::kernels::{CircleCircle, MeetSphere, MotorMotor, MotorOnPoint, RotorRotor, ThreePoints};
use cga_core::simd::{Kernel, Lanes, run_packed};
use clifford::ops::{Antiwedge, Sandwich as _, Wedge};
use clifford::specialized::conformal::dim3 as cl;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main, measurement::WallTime};
use std::hint::black_box;
use std::time::Duration;

const BATCH: usize = 256;

fn coords(i: usize, seed: f64) -> [f64; 3] {
    let t = seed + i as f64;
    [3.0 * (1.3 * t).sin(), 2.0 * (0.7 * t).cos(), (2.9 * t).sin() - 0.5]
}

/// Time `op` over the batch of operands; criterion divides by the batch size.
fn run<A: Copy, R>(g: &mut BenchmarkGroup<WallTime>, name: &str, a: &[A], op: impl Fn(A) -> R) {
    let mut out: Vec<R> = Vec::with_capacity(BATCH);
    g.bench_function(name, |bench| {
        bench.iter(|| {
            out.clear();
            out.extend(black_box(a).iter().map(|&x| op(x)));
            black_box(&out);
        })
    });
}

/// Runs on references for the crate whose types are not `Copy`.
fn run_ref<A, R>(g: &mut BenchmarkGroup<WallTime>, name: &str, a: &[A], op: impl Fn(&A) -> R) {
    let mut out: Vec<R> = Vec::with_capacity(BATCH);
    g.bench_function(name, |bench| {
        bench.iter(|| {
            out.clear();
            out.extend(black_box(a).iter().map(&op));
            black_box(&out);
        })
    });
}

/// Ours on packets of four ([`cga_core::simd::run_packed`]): the same 256 operations as 64
/// packets, packed beforehand (the form a packet tracer keeps its data in).
fn run_packets<K: Kernel + Default>(g: &mut BenchmarkGroup<WallTime>, input: &[K::Input]) {
    let packed: Vec<_> = input.chunks_exact(4).map(|x| K::Input::pack([x[0], x[1], x[2], x[3]])).collect();
    let mut out: Vec<_> = packed.iter().map(|&x| K::default().apply(x)).collect();
    g.bench_function("cga-packets", |bench| {
        bench.iter(|| {
            run_packed(&K::default(), black_box(&packed), &mut out);
            black_box(&out);
        })
    });
}

fn group<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, WallTime> {
    let mut g = c.benchmark_group(format!("peers/{name}"));
    g.throughput(Throughput::Elements(BATCH as u64));
    g
}

fn peers(c: &mut Criterion) {
    use cga_core::{Circle, Line, Motor, Rotor, Sandwich, Sphere, Vector, up};
    let ours = |s: f64| -> Vec<Vector> { (0..BATCH).map(|i| up(coords(i, s))).collect() };
    let (a, b, p, q) = (ours(0.0), ours(100.0), ours(200.0), ours(300.0));
    let theirs = |s: f64| -> Vec<cl::RoundPoint<f64>> {
        (0..BATCH)
            .map(|i| {
                let [x, y, z] = coords(i, s);
                cl::RoundPoint::from_euclidean(x, y, z)
            })
            .collect()
    };
    let (ca, cb, cp, cq) = (theirs(0.0), theirs(100.0), theirs(200.0), theirs(300.0));
    let dense = |s: f64| -> Vec<hisab::geo::cga::Multivector> {
        (0..BATCH)
            .map(|i| {
                let [x, y, z] = coords(i, s);
                hisab::geo::cga::point(x, y, z)
            })
            .collect()
    };
    let (ha, hb, hp, hq) = (dense(0.0), dense(100.0), dense(200.0), dense(300.0));
    let angle = |i: usize| 0.01 * i as f64;

    // Line ∨ sphere (hisab has no regressive product).
    let mut g = group(c, "line_meet_sphere");
    let meets: Vec<(Line, Sphere)> = (0..BATCH)
        .map(|i| {
            let line = (a[i] ^ b[i]) ^ cga_core::ei();
            (line, Sphere::from_centre_radius(coords(i, 200.0), 1.0 + 0.1 * (i % 7) as f64).expect("radius > 0"))
        })
        .collect();
    run(&mut g, "cga", &meets, |(l, s)| l & s);
    run_packets::<MeetSphere>(&mut g, &meets);
    let cl_meets: Vec<(cl::Line<f64>, cl::Sphere<f64>)> = (0..BATCH)
        .map(|i| {
            let ([x, y, z], [u, v, w]) = (coords(i, 0.0), coords(i, 100.0));
            let [cx, cy, cz] = coords(i, 200.0);
            let line = cl::Line::new_unchecked(u - x, v - y, w - z, y * w - z * v, z * u - x * w, x * v - y * u);
            (line, cl::Sphere::from_center_radius(cx, cy, cz, 1.0 + 0.1 * (i % 7) as f64))
        })
        .collect();
    run(&mut g, "clifford", &cl_meets, |(l, s)| l.antiwedge(&s));
    g.finish();

    // Circle through three points.
    let mut g = group(c, "circle_from_3_points");
    let triples: Vec<_> = (0..BATCH).map(|i| (a[i], b[i], p[i])).collect();
    run(&mut g, "cga", &triples, |(x, y, z)| (x ^ y) ^ z);
    run_packets::<ThreePoints>(&mut g, &triples);
    let cl_triples: Vec<_> = (0..BATCH).map(|i| (ca[i], cb[i], cp[i])).collect();
    run(&mut g, "clifford", &cl_triples, |(x, y, z)| x.wedge(&y).wedge(&z));
    let h_triples: Vec<_> = (0..BATCH).map(|i| (ha[i].clone(), hb[i].clone(), hp[i].clone())).collect();
    run_ref(&mut g, "hisab", &h_triples, |(x, y, z)| x.outer(y).outer(z));
    g.finish();

    // Motor on a point, M X M̃.
    let mut g = group(c, "motor_on_point");
    let motor = |i: usize| {
        let r = Rotor::from_axis_angle([0.6, -0.48, 0.64], angle(i)).expect("unit axis");
        Motor::from_rotor_translator(r, cga_core::Translator::from_vector(coords(i, 400.0)))
    };
    let moved: Vec<(Motor, Vector)> = (0..BATCH).map(|i| (motor(i), a[i])).collect();
    run(&mut g, "cga", &moved, |(m, x)| m.sandwich(x));
    run_packets::<MotorOnPoint>(&mut g, &moved);
    let cl_motor = |i: usize| {
        let m = motor(i);
        let z = 0.0;
        cl::Motor::new_unchecked(m.s, m.e12, m.e13, m.e23, m.e1i, m.e2i, m.e3i, m.e123i, z, z, z, z, z, z, z, z)
    };
    let cl_moved: Vec<_> = (0..BATCH).map(|i| (cl_motor(i), ca[i])).collect();
    run(&mut g, "clifford", &cl_moved, |(m, x)| m.sandwich(&x));
    let h_motor = |i: usize| {
        let [tx, ty, tz] = coords(i, 400.0);
        hisab::geo::cga::translator(tx, ty, tz).geo(&hisab::geo::cga::rotor(0.6, -0.48, 0.64, angle(i)))
    };
    let h_moved: Vec<_> = (0..BATCH).map(|i| (h_motor(i), ha[i].clone())).collect();
    run_ref(&mut g, "hisab", &h_moved, |(m, x)| x.sandwich(m));
    g.finish();

    // Circle · circle, the whole geometric product.
    let mut g = group(c, "circle_times_circle");
    let circles: Vec<(Circle, Circle)> = (0..BATCH).map(|i| ((a[i] ^ b[i]) ^ p[i], (b[i] ^ p[i]) ^ q[i])).collect();
    run(&mut g, "cga", &circles, |(x, y)| x * y);
    run_packets::<CircleCircle>(&mut g, &circles);
    let cl_circles: Vec<_> =
        (0..BATCH).map(|i| (ca[i].wedge(&cb[i]).wedge(&cp[i]), cb[i].wedge(&cp[i]).wedge(&cq[i]))).collect();
    run(&mut g, "clifford", &cl_circles, |(x, y)| x * y);
    let h_circles: Vec<_> =
        (0..BATCH).map(|i| (ha[i].outer(&hb[i]).outer(&hp[i]), hb[i].outer(&hp[i]).outer(&hq[i]))).collect();
    run_ref(&mut g, "hisab", &h_circles, |(x, y)| x.geo(y));
    g.finish();

    // Motor ∘ motor.
    let mut g = group(c, "motor_times_motor");
    let motors: Vec<_> = (0..BATCH).map(|i| (motor(i), motor(BATCH - i))).collect();
    run(&mut g, "cga", &motors, |(x, y)| x * y);
    run_packets::<MotorMotor>(&mut g, &motors);
    let cl_motors: Vec<_> = (0..BATCH).map(|i| (cl_motor(i), cl_motor(BATCH - i))).collect();
    run(&mut g, "clifford", &cl_motors, |(x, y)| x * y);
    let h_motors: Vec<_> = (0..BATCH).map(|i| (h_motor(i), h_motor(BATCH - i))).collect();
    run_ref(&mut g, "hisab", &h_motors, |(x, y)| x.geo(y));
    g.finish();

    // Rotor ∘ rotor (clifford's CGA has no rotor type: its motor stands in).
    let mut g = group(c, "rotor_times_rotor");
    let rotor = |i: usize| Rotor::from_axis_angle([0.6, -0.48, 0.64], angle(i)).expect("unit axis");
    let rotors: Vec<_> = (0..BATCH).map(|i| (rotor(i), rotor(BATCH - i))).collect();
    run(&mut g, "cga", &rotors, |(x, y)| x * y);
    run_packets::<RotorRotor>(&mut g, &rotors);
    let h_rotor = |i: usize| hisab::geo::cga::rotor(0.6, -0.48, 0.64, angle(i));
    let h_rotors: Vec<_> = (0..BATCH).map(|i| (h_rotor(i), h_rotor(BATCH - i))).collect();
    run_ref(&mut g, "hisab", &h_rotors, |(x, y)| x.geo(y));
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(30)
}

criterion_group! { name = benches; config = config(); targets = peers }
criterion_main!(benches);
