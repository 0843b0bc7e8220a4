//! Time per ray of every swept surface of the shipped scenes on the scene's own primary and
//! shadow rays (those reaching the surface's bounds), one thread, median of interleaved
//! passes:
//!
//! `cargo run --release -p cga-trace --example swept_time -- [WIDTH] [SCENE ...]`
//!
//! (default 640 wide, every scene with a swept surface). `SWEPT_LEAVES=n` sets the default
//! method's cells; `SWEPT_SPLIT=1` also times the rays that hit the surface apart from those
//! that miss it (one pass each). For profiling one scene's surface
//! work: `perf record` on the same command; for instruction counts, which a shared machine's
//! load does not change, `SWEPT_PASSES=1 valgrind --tool=callgrind` on it.

use cga_trace::Renderer;
use cga_trace::integrator::Window;
use cga_trace::ray::{Ray, crosses};
use cga_trace::scene::Scene;
use cga_trace::shapes::Shape;
use cga_trace::surface::{EvolvedSurface, Method, RuledSurface, SplineSurface};
use std::time::Instant;

const SCENES: [&str; 8] = ["combined", "surface", "transforms", "fig3a", "fig3b", "fig3c", "catmull-rom", "ruled"];
/// Timed passes (the median is reported); `SWEPT_PASSES` sets it (1 under callgrind, whose
/// instruction counts do not depend on a shared machine's load).
fn passes() -> usize {
    std::env::var("SWEPT_PASSES").ok().and_then(|p| p.parse().ok()).unwrap_or(7)
}

/// The swept surfaces of a scene, each with its exact methods: `(label, shape)`.
fn swept(scene: &Scene) -> Vec<(String, Box<dyn Shape>)> {
    let mut out: Vec<(String, Box<dyn Shape>)> = Vec::new();
    let default = match std::env::var("SWEPT_LEAVES").ok().and_then(|l| l.parse().ok()) {
        Some(leaves) => Method::Hybrid { leaves, tolerance: 0.0 },
        None => Method::default(),
    };
    let methods = [("default", default), ("polynomial", Method::Polynomial { tolerance: 0.0 })];
    // `SWEPT_METHOD=default` times that one alone.
    let only = std::env::var("SWEPT_METHOD").ok();
    let methods: Vec<_> = methods.into_iter().filter(|(n, _)| only.as_deref().is_none_or(|o| o == *n)).collect();
    for object in &scene.objects {
        let any: &dyn Shape = &*object.shape;
        for &(name, method) in &methods {
            let label = format!("{} ({name})", object.name);
            if let Some(s) = any.downcast_ref::<EvolvedSurface>() {
                out.push((label, Box::new(s.with_method(method).unwrap())));
            } else if let Some(s) = any.downcast_ref::<SplineSurface>() {
                out.push((label, Box::new(s.with_method(method).unwrap())));
            } else if let Some(s) = any.downcast_ref::<RuledSurface>()
                && name == "default"
            {
                out.push((label, Box::new(s.clone())));
            }
        }
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let width: u32 = args.first().and_then(|a| a.parse().ok()).unwrap_or(640);
    let chosen: Vec<&str> = args.iter().filter(|a| a.parse::<u32>().is_err()).map(String::as_str).collect();
    let scenes: Vec<&str> = if chosen.is_empty() { SCENES.to_vec() } else { chosen };
    println!("| scene | surface (method) | rays | hits | ns per ray |\n|---|---|---:|---:|---:|");
    for name in scenes {
        let path = format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let mut scene = Scene::load(std::path::Path::new(&path)).unwrap();
        scene.resize(Some(width), None).unwrap();
        let (w, h) = (scene.camera.width, scene.camera.height);
        let rays = Renderer::new(&scene).first_rays(&Window::full(w, h));
        for (label, shape) in swept(&scene) {
            let (c, r) = shape.bounds().unwrap();
            let mine: Vec<(Ray, f64)> = rays.iter().filter(|(ray, t)| crosses(ray, c, r, 0.0, *t)).copied().collect();
            let mut times = Vec::new();
            let mut hits = 0;
            for _ in 0..passes() {
                let start = Instant::now();
                hits = mine.iter().filter(|(ray, t)| shape.intersect(ray, 0.0, *t).is_some()).count();
                times.push(start.elapsed().as_secs_f64());
            }
            times.sort_by(f64::total_cmp);
            let ns = times[times.len() / 2] * 1e9 / mine.len().max(1) as f64;
            if std::env::var("SWEPT_SPLIT").is_ok() {
                let (hit, miss): (Vec<_>, Vec<_>) =
                    mine.iter().partition(|(ray, t)| shape.intersect(ray, 0.0, *t).is_some());
                for (what, set) in [("hit", &hit), ("miss", &miss)] {
                    let start = Instant::now();
                    let found = set.iter().filter(|(ray, t)| shape.intersect(ray, 0.0, *t).is_some()).count();
                    let seconds = start.elapsed().as_secs_f64();
                    let per_ray = seconds * 1e9 / set.len().max(1) as f64;
                    println!("  {what}: {} rays ({found} hit), {per_ray:.0} ns per ray, {seconds:.3} s", set.len());
                }
            }
            println!("| {name} | {label} | {} | {hits} | {ns:.0} |", mine.len());
        }
    }
}
