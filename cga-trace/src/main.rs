//! `cga-trace render SCENE.toml -o out.png`: render a scene file to a PNG.

use anyhow::Context;
use cga_trace::backend::{Backend, Dense, Plain, Sparse};
use cga_trace::{Aov, BackendKind, Encoding, Film, Renderer, Scene};
use clap::{Parser, Subcommand};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "cga-trace",
    version,
    about = "Ray-trace spheres, planes, disks, triangles and evolved circle surfaces with conformal geometric algebra"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file to a PNG.
    Render {
        /// The scene (TOML).
        scene: PathBuf,
        /// The PNG to write.
        #[arg(short, long, default_value = "out.png")]
        output: PathBuf,
        /// Image width in pixels (overrides the scene; the height follows the aspect unless given).
        #[arg(long)]
        width: Option<u32>,
        /// Image height in pixels (overrides the scene).
        #[arg(long)]
        height: Option<u32>,
        /// Worker threads (default: all cores).
        #[arg(long)]
        threads: Option<usize>,
        /// Reflection depth (overrides the scene).
        #[arg(long)]
        max_depth: Option<u32>,
        /// PNG encoding (overrides the scene).
        #[arg(long, value_enum)]
        encoding: Option<Encoding>,
        /// Write a debug image instead of the shaded one.
        #[arg(long, value_enum, default_value_t = Aov::Shaded)]
        aov: Aov,
        /// Geometry code: generated sparse types, the dense multivector, or plain vectors.
        #[arg(long, value_enum, default_value_t = BackendKind::Sparse)]
        backend: BackendKind,
    },
}

fn main() -> anyhow::Result<()> {
    let Command::Render { scene, output, width, height, threads, max_depth, encoding, aov, backend } =
        Cli::parse().command;
    let mut scene = Scene::load(&scene)?;
    resize(&mut scene, width, height)?;
    if let Some(d) = max_depth {
        scene.settings.max_depth = d;
    }
    let encoding = encoding.unwrap_or(scene.settings.encoding);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads.unwrap_or(0)).build()?;

    let bar = indicatif::ProgressBar::new(u64::from(scene.camera.height));
    if !std::io::stderr().is_terminal() {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let render = match backend {
        BackendKind::Sparse => render::<Sparse>,
        BackendKind::Dense => render::<Dense>,
        BackendKind::Plain => render::<Plain>,
    };
    let start = Instant::now();
    let (film, (primary, shadow, reflection)) = pool.install(|| render(&scene, aov, &|| bar.inc(1)));
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    film.save_png(&output, encoding).with_context(|| format!("writing {}", output.display()))?;

    let total = primary + shadow + reflection;
    eprintln!(
        "{} pixels, {total} rays ({primary} primary, {shadow} shadow, {reflection} reflection), {seconds:.3} s, {:.0} rays/s -> {}",
        u64::from(film.width) * u64::from(film.height),
        total as f64 / seconds.max(1e-9),
        output.display()
    );
    Ok(())
}

/// The image and the rays cast `(primary, shadow, reflection)`, on back end `B`.
fn render<B: Backend>(scene: &Scene, aov: Aov, on_row: &(dyn Fn() + Sync)) -> (Film, (u64, u64, u64)) {
    let renderer = Renderer::<B>::with_backend(scene);
    let film = renderer.render(aov, on_row);
    (film, renderer.counts.get())
}

/// Apply `--width`/`--height`, keeping the image plane's aspect when only one is given.
fn resize(scene: &mut Scene, width: Option<u32>, height: Option<u32>) -> anyhow::Result<()> {
    let c = scene.camera;
    let (w, h) = match (width, height) {
        (None, None) => return Ok(()),
        (Some(w), None) => (w, ((f64::from(w) * c.y_max / c.x_max).round() as u32).max(1)),
        (None, Some(h)) => (((f64::from(h) * c.x_max / c.y_max).round() as u32).max(1), h),
        (Some(w), Some(h)) => (w, h),
    };
    scene.camera = cga_trace::camera::Camera::new(c.pose, c.focal, c.x_max, c.y_max, w, h)?;
    Ok(())
}
