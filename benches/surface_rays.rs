//! Primary visibility of one swept surface, for the comparison against Embree
//! (`benches/peers/embree.sh`): the camera ray through every pixel centre of a shipped scene,
//! met with that one surface alone as the renderer meets it (the sparse back end's prepared
//! shape, nearest crossing with `0 < t < ∞`), one thread. Prints the median over interleaved
//! rounds of the ns per ray of three batches through the same code: all rays in pixel order,
//! the rays that hit, and the rays that miss (timed as batches, since a timer per ray would
//! cost more than a miss does). Then the same through the renderer's own path for a pixel's
//! primary visibility, `Renderer::nearest` on the scene with that object alone (which adds
//! the normal of the hit and the object's crossing error as `t_min`).
//!
//! ```sh
//! cargo run --release -p cga-benches --example surface_rays -- SCENE.toml --object NAME \
//!     [--width 1280] [--height 960] [--rays OUT.bin] [--rounds 5] [--mesh MESH.ply]
//! ```
//!
//! The height follows the scene's aspect unless given; `--rounds 0` writes the rays without
//! timing. With `--mesh` (the surface's mesh as `cga-trace mesh` exports it) the same rays
//! are also timed against that mesh as the renderer meets a mesh object (its hierarchy and
//! watertight triangle test), in the same three batches, split by the exact surface's hits:
//! `ours-mesh`. `OUT.bin` holds, so that `benches/peers/embree.py` traces the very same rays,
//! one record a pixel — rows `j = 0 .. height` (the bottom row first), in each the columns
//! `i = 0 .. width` — of seven little-endian f64: the origin's x, y, z and the unit
//! direction's, in world coordinates (those of the mesh `cga-trace mesh` exports), and our
//! hit distance in world units, +∞ for a miss.

use cga_benches::medians_ns;
use cga_trace::backend::{Backend, Sparse, SparseShape};
use cga_trace::camera::Camera;
use cga_trace::ray::Ray;
use cga_trace::{Renderer, Scene};
use std::hint::black_box;
use std::io::Write;
use std::path::{Path, PathBuf};

/// What the command line asks for.
#[derive(clap::Parser)]
struct Args {
    /// The scene (a shipped one: fig3c, fig3b, catmull-rom, surface).
    scene: PathBuf,
    /// The swept surface's object name.
    #[arg(long)]
    object: String,
    /// Image width in pixels.
    #[arg(long, default_value_t = 1280)]
    width: u32,
    /// Image height (default: the scene's aspect).
    #[arg(long)]
    height: Option<u32>,
    /// Where to write the rays and our hit distances.
    #[arg(long)]
    rays: Option<PathBuf>,
    /// Interleaved rounds (0: only write the rays).
    #[arg(long, default_value_t = 5)]
    rounds: usize,
    /// A mesh of the surface to time on the same rays.
    #[arg(long)]
    mesh: Option<PathBuf>,
}

type Error = Box<dyn std::error::Error>;

/// The primary ray through every pixel centre, as the renderer forms it (the sparse back
/// end's camera ray), rows bottom first.
fn primary_rays(camera: &Camera) -> Result<Vec<Ray>, Error> {
    let pixels = (0..camera.height).flat_map(|j| (0..camera.width).map(move |i| (i, j)));
    let ray = |(i, j): (u32, u32)| Sparse::camera_ray(camera, f64::from(i) + 0.5, f64::from(j) + 0.5);
    pixels.map(|p| ray(p).ok_or_else(|| "the camera's pose forms no rays".into())).collect()
}

/// The nearest crossing of every ray with the surface: how many hit, and the sum of their
/// distances (so that no crossing can be optimised away).
fn cross_all(shape: &SparseShape, rays: &[Ray]) -> (usize, f64) {
    let (mut hits, mut sum) = (0, 0.0);
    for ray in black_box(rays) {
        if let Some(c) = Sparse::intersect(shape, black_box(ray), 0.0, f64::INFINITY) {
            hits += 1;
            sum += c.t;
        }
    }
    (hits, sum)
}

/// [`cross_all`] through the renderer's whole primary visibility of one ray.
fn nearest_all(renderer: &Renderer, rays: &[Ray]) -> (usize, f64) {
    let (mut hits, mut sum) = (0, 0.0);
    for ray in black_box(rays) {
        if let Some((hit, _)) = renderer.nearest(black_box(ray), 0.0, f64::INFINITY) {
            hits += 1;
            sum += hit.t;
        }
    }
    (hits, sum)
}

/// Writes the rays and our hit distances (`t`, frame units) in world coordinates.
fn write_rays(path: &Path, scene: &Scene, rays: &[Ray], t: &[Option<f64>]) -> Result<(), Error> {
    let mut out = std::io::BufWriter::new(std::fs::File::create(path)?);
    for (ray, t) in rays.iter().zip(t) {
        let t = t.map_or(f64::INFINITY, |t| scene.frame.world_length(t));
        for x in scene.frame.world_point(ray.origin).iter().chain(&ray.dir).chain([&t]) {
            out.write_all(&x.to_le_bytes())?;
        }
    }
    out.flush()?;
    Ok(())
}

/// The median ns per ray of `trace` over all rays, the hit rays and the missed rays, in
/// interleaved rounds after an untimed pass over all; prints them as
/// `label hits=… all=… hit=… miss=…` (`hits`: of all rays, as `trace` found them).
fn time(label: &str, rounds: usize, batches: [&[Ray]; 3], trace: impl Fn(&[Ray]) -> (usize, f64)) {
    let [all, hit, miss] = batches;
    let hits = trace(all).0;
    let trace = &trace;
    let mut forms = batches.map(|rays| {
        move || {
            black_box(trace(rays));
        }
    });
    let [a, b, c] = &mut forms;
    let ns = medians_ns(1, 1, rounds, &mut [a, b, c]);
    let per = |k: usize, n: usize| if n == 0 { f64::NAN } else { ns[k] / n as f64 };
    let (all, hit, miss) = (per(0, all.len()), per(1, hit.len()), per(2, miss.len()));
    println!("{label} hits={hits} all={all:.1} hit={hit:.1} miss={miss:.1}");
}

fn main() -> Result<(), Error> {
    let args = <Args as clap::Parser>::parse();
    let mut scene = Scene::load(&args.scene)?;
    scene.resize(Some(args.width), args.height)?;
    let object = scene.objects.iter().find(|o| *o.name == *args.object).ok_or_else(|| {
        let names: Vec<&str> = scene.objects.iter().map(|o| &*o.name).collect();
        format!("no object `{}` in {} (it has {names:?})", args.object, args.scene.display())
    })?;
    let shape = Sparse::prepare(&object.shape);
    let rays = primary_rays(&scene.camera)?;
    // Read before any timing, so that a bad mesh fails at once.
    let mesh = args.mesh.as_deref().map(|mesh| mesh_of(&args, mesh)).transpose()?;
    // Also the untimed first pass of every ray.
    let t: Vec<Option<f64>> =
        rays.iter().map(|r| Sparse::intersect(&shape, r, 0.0, f64::INFINITY).map(|c| c.t)).collect();
    let split = |hits: bool| -> Vec<Ray> {
        rays.iter().zip(&t).filter(|(_, t)| t.is_some() == hits).map(|(r, _)| *r).collect()
    };
    let (hit, miss) = (split(true), split(false));
    let (w, h) = (scene.camera.width, scene.camera.height);
    println!(
        "ours rays={} hits={} misses={} width={w} height={h} rounds={}",
        rays.len(),
        hit.len(),
        miss.len(),
        args.rounds
    );
    if let Some(path) = &args.rays {
        write_rays(path, &scene, &rays, &t)?;
    }
    if args.rounds == 0 {
        return Ok(());
    }
    let batches = [&rays[..], &hit[..], &miss[..]];
    time("ours-surface", args.rounds, batches, |rays| cross_all(&shape, rays));
    let mut alone = scene.clone();
    alone.objects.retain(|o| *o.name == *args.object);
    let renderer = Renderer::new(&alone);
    time("ours-renderer", args.rounds, batches, |rays| nearest_all(&renderer, rays));
    if let Some((shape, rays)) = &mesh {
        let split = |hits: bool| -> Vec<Ray> {
            rays.iter().zip(&t).filter(|(_, t)| t.is_some() == hits).map(|(r, _)| *r).collect()
        };
        let (hit, miss) = (split(true), split(false));
        time("ours-mesh", args.rounds, [&rays[..], &hit[..], &miss[..]], |rays| cross_all(shape, rays));
    }
    Ok(())
}

/// The scene with the mesh file added as an object, `mesh of surface`: that object prepared
/// as the renderer prepares it, and the scene's camera rays (in its own frame, which the
/// added object may move; the same pixels in the same order).
fn mesh_of(args: &Args, mesh: &Path) -> Result<(SparseShape, Vec<Ray>), Error> {
    const NAME: &str = "mesh of surface";
    let file = std::path::absolute(mesh)?;
    let file = file.to_str().ok_or_else(|| format!("{} is not UTF-8", file.display()))?;
    // A TOML basic string: `\` and `"` escaped, and control characters as `\uXXXX`.
    let quoted: String = file
        .chars()
        .map(|c| match c {
            '\\' | '"' => format!("\\{c}"),
            c if c.is_control() => format!("\\u{:04X}", c as u32),
            c => c.to_string(),
        })
        .collect();
    let text = std::fs::read_to_string(&args.scene)?
        + &format!(
            "\n[[objects]]\nname = \"{NAME}\"\ntype = \"mesh\"\nfile = \"{quoted}\"\nmaterial = {{ colour = [0.5, 0.5, 0.5] }}\n"
        );
    let mut scene = Scene::parse(&text, &args.scene.display().to_string())?;
    scene.resize(Some(args.width), args.height)?;
    // The last object of that name: the one added.
    let object = scene.objects.iter().rfind(|o| *o.name == *NAME).ok_or("the mesh object was not built")?;
    Ok((Sparse::prepare(&object.shape), primary_rays(&scene.camera)?))
}
