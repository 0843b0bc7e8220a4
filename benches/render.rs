//! The whole tracer on three back ends — generated sparse types, the dense multivector and
//! plain vectors (glam) — rendering the same scenes: `cargo bench --bench render`, then
//! `python3 benches/report.py` prints time per frame, rays/s and the ratios
//! (benches/README.md, docs/PERFORMANCE.md).
//!
//! Frames are rendered on one thread so that the figures compare code, not scheduling; the
//! scaling over cores is measured by `cargo run --release -p cga-trace --example perf_report`.
//! `cargo bench --bench render --no-default-features` runs the primitives scene in a build
//! without evolved surfaces (reported as `sparse-no-evolved`, …), to show that supporting
//! them costs a primitives-only scene nothing.

use cga_trace::backend::{Backend, Dense, Plain, Sparse};
use cga_trace::camera::Camera;
use cga_trace::{Aov, Renderer, Scene};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// A shipped scene at `w × h`.
fn scene(name: &str, w: u32, h: u32) -> Scene {
    let mut scene = Scene::load(&cga_benches::scene_path(name)).expect("a shipped scene");
    let c = scene.camera;
    scene.camera = Camera::new(c.pose, c.focal, c.x_max, c.y_max, w, h).expect("a camera");
    scene
}

/// Rays one frame casts (the same on every back end: they render the same image).
fn rays(scene: &Scene) -> u64 {
    let renderer = Renderer::new(scene);
    renderer.render(Aov::Shaded, &|| {});
    let cga_trace::integrator::RayCounts { primary: p, shadow: s, reflection: r } = renderer.counts();
    p + s + r
}

fn frame<B: Backend>(c: &mut Criterion, name: &str, scene: &Scene, rays: u64) {
    let mut g = c.benchmark_group(format!("render/{name}"));
    // A build without evolved surfaces (`--no-default-features`) reports under its own name,
    // to compare with the full build on the same scene.
    let id = if cfg!(feature = "evolved") { B::NAME.to_string() } else { format!("{}-no-evolved", B::NAME) };
    g.throughput(Throughput::Elements(rays));
    if B::NAME == "dense" {
        g.sample_size(10).measurement_time(Duration::from_secs(20));
    } else {
        g.sample_size(20).measurement_time(Duration::from_secs(5));
    }
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
    g.bench_function(id, |b| {
        b.iter(|| pool.install(|| black_box(Renderer::<B>::with_backend(scene).render(Aov::Shaded, &|| {}))))
    });
    g.finish();
}

fn back_ends(c: &mut Criterion) {
    let scenes: &[&str] = if cfg!(feature = "evolved") { &["primitives", "combined"] } else { &["primitives"] };
    for &name in scenes {
        let scene = scene(name, 160, 120);
        let rays = rays(&scene);
        frame::<Sparse>(c, name, &scene, rays);
        frame::<Plain>(c, name, &scene, rays);
        frame::<Dense>(c, name, &scene, rays);
    }
}

criterion_group!(benches, back_ends);
criterion_main!(benches);
