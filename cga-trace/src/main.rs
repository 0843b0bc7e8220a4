//! `cga-trace render SCENE.toml -o out.png`: render a scene file to an image.

use anyhow::Context;
use cga_trace::film::Output;
use cga_trace::integrator::RayCounts;
use cga_trace::limits::{MAX_FRAMES, MAX_THREADS};
use cga_trace::output::OutputFile;
use cga_trace::pipeline::{Options, Pipeline, RenderError, View, ViewError, check_output, scale_path, window};
use cga_trace::settings::{AdaptiveMethod, Background, ToneMap};
use cga_trace::{Aov, BackendKind, Encoding, Scene};
use clap::{Parser, Subcommand};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "cga-trace",
    version,
    about = "Ray-trace spheres, planes, disks, triangles and evolved circle surfaces with conformal geometric algebra",
    after_help = "Scene files are TOML: every table and field, with examples, is in docs/SCENES.md#scene-files; \
                  cga-trace/scenes/ holds complete scenes."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene file to an image (PNG, OpenEXR or Radiance HDR, by extension).
    #[command(after_help = "The scene format: docs/SCENES.md#scene-files.")]
    Render(Render),
    /// Export an evolved, spline or ruled surface of a scene as a triangle mesh with analytic
    /// normals and (α, angle) texture coordinates: .obj, .ply or .glb, by extension.
    #[cfg(feature = "evolved")]
    Mesh(MeshArgs),
}

#[cfg(feature = "evolved")]
#[derive(clap::Args)]
struct MeshArgs {
    /// The scene (TOML; see docs/SCENES.md#scene-files).
    scene: PathBuf,
    /// The name of the surface's object in the scene.
    #[arg(long)]
    object: String,
    /// The mesh to write: .obj or .ply (f64 exact), .glb (f32).
    #[arg(short, long)]
    output: PathBuf,
    /// Circles along α (the mesh has one more ring of vertices).
    #[arg(long, default_value_t = 64)]
    rings: usize,
    /// Vertices around each circle.
    #[arg(long, default_value_t = 128)]
    segments: usize,
}

#[derive(clap::Args)]
struct Render {
    /// The scene (TOML; see docs/SCENES.md#scene-files).
    scene: PathBuf,
    /// The image to write: .png (8- or 16-bit, encoded), .exr or .hdr (linear floats).
    #[arg(short, long, default_value = "out.png")]
    output: PathBuf,
    /// Bits per channel of a PNG: 8 or 16.
    #[arg(long)]
    bit_depth: Option<u8>,
    /// Image width in pixels (the height follows at the same aspect unless given).
    #[arg(long)]
    width: Option<u32>,
    /// Image height in pixels (the width follows at the same aspect unless given).
    #[arg(long)]
    height: Option<u32>,
    /// Horizontal field of view in degrees (sets x_max = 2 f tan(fov/2); y_max follows).
    #[arg(long)]
    fov: Option<f64>,
    /// Samples per pixel, stratified (overrides the scene; 1 = the pixel centre).
    #[arg(long)]
    spp: Option<u32>,
    /// Camera rays each sample averages through a thin lens, POV-Ray's blur_samples, 1 to 256
    /// (overrides the scene; default 1): the lens is sampled that many times as finely, and
    /// adaptive sampling (--adaptive-method corners above all) compares the samples' means, so
    /// a blur's noise is not taken for an edge. A pinhole camera takes one ray.
    #[arg(long, value_name = "M")]
    blur_samples: Option<u32>,
    /// Adaptive anti-aliasing, POV-Ray's +A: --spp becomes a maximum, taken only by pixels
    /// whose first 4 samples (--adaptive-min), or whose mean against a neighbour's, differ by
    /// more than this contrast (Σ over R, G, B of the differences of what a PNG shows, 0 to 3;
    /// POV-Ray's default 0.3).
    #[arg(long, value_name = "THRESHOLD")]
    adaptive: Option<f64>,
    /// The samples every pixel takes first under adaptive sampling, 1 to 4096 (overrides the
    /// scene's min_spp; default 4; 1 is POV-Ray's method 1: the neighbours alone decide).
    /// Given alone, it turns adaptive sampling on at the scene's threshold or 0.3.
    #[arg(long, value_name = "N")]
    adaptive_min: Option<u32>,
    /// Where adaptive sampling puts the samples: `samples` (the default: each pixel's first
    /// --adaptive-min samples, the rest where they or the neighbours differ) or `corners`
    /// (POV-Ray's method 2, +AM2: a ray at each pixel corner, shared by four pixels, and squares
    /// whose corners differ cut in four, down to log4(--spp) levels). Given alone, it turns
    /// adaptive sampling on at the scene's threshold or 0.3.
    #[arg(long, value_name = "METHOD")]
    adaptive_method: Option<AdaptiveMethod>,
    /// Render only the window x0,x1,y0,y1 (fractions of the image, y from the top, as
    /// pbrt's --cropwindow); windows of one frame assemble into it byte for byte.
    #[arg(long, value_name = "X0,X1,Y0,Y1", value_parser = parse_crop, allow_hyphen_values = true)]
    crop: Option<[f64; 4]>,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Reflection depth (overrides the scene).
    #[arg(long)]
    max_depth: Option<u32>,
    /// PNG encoding (overrides the scene).
    #[arg(long, value_enum)]
    encoding: Option<Encoding>,
    /// Exposure of PNG output in stops, −64 to 64 (overrides the scene; EXR and HDR stay
    /// linear as rendered).
    #[arg(long, allow_hyphen_values = true)]
    exposure: Option<f64>,
    /// Tone map of PNG output (overrides the scene): none (clip) or filmic (ACES).
    #[arg(long, value_enum)]
    tone_map: Option<ToneMap>,
    /// What camera rays that meet nothing show (overrides the scene): `transparent` (an alpha
    /// channel of each pixel's coverage: PNG straight, EXR premultiplied; not HDR) or a linear
    /// colour R,G,B.
    #[arg(long, value_name = "transparent|R,G,B", value_parser = parse_background)]
    background: Option<Background>,
    /// Write a debug image instead of the shaded one: normals, α, or a curvature of swept
    /// surfaces in false colour (viridis; the scale is written to OUTPUT.scale.json).
    #[arg(long, value_enum, default_value_t = Aov::Shaded)]
    aov: Aov,
    /// Geometry code: generated sparse types, the dense multivector, or plain vectors.
    #[arg(long, value_enum, default_value_t = BackendKind::Sparse)]
    backend: BackendKind,
    /// Trace one ray at a time: no packets of four camera and shadow rays on SIMD lanes
    /// (the same image; for comparing their speed).
    #[arg(long)]
    no_packets: bool,
    /// Trace the packets on four-lane arrays compiled for the baseline CPU, as on a CPU
    /// without AVX2 (the same image; for comparing the two lane types' speed).
    #[arg(long)]
    no_avx2: bool,
    /// Leave out the objects' labels (a scene's `label` fields), which are written into
    /// shaded pictures of the whole image.
    #[arg(long)]
    no_labels: bool,
    /// Render an animation of N frames at the times 0, 1/(N−1), …, 1 (objects and the
    /// camera with a `motion` move by their keyframes), written as OUTPUT with the frame's
    /// number before the extension (out_0000.png, …).
    #[arg(long, value_name = "N")]
    frames: Option<usize>,
    /// Render only frames A to B − 1 of the animation (0-based), so that a range can be split
    /// across machines; each frame is independent.
    #[arg(long, value_name = "A..B", value_parser = parse_range, requires = "frames")]
    frame_range: Option<(usize, usize)>,
}

/// `a..b`: two frame numbers, `a < b`.
fn parse_range(s: &str) -> Result<(usize, usize), String> {
    let (a, b) = s.split_once("..").ok_or("give the range as A..B, e.g. 0..100")?;
    let (a, b) = (a.trim().parse::<usize>(), b.trim().parse::<usize>());
    match (a, b) {
        (Ok(a), Ok(b)) if a < b => Ok((a, b)),
        _ => Err("give the range as A..B with A < B, e.g. 0..100".into()),
    }
}

/// `path` with `_NNNN` (at least four digits, as many as `frames − 1` has) before its
/// extension.
fn numbered(path: &Path, frame: usize, frames: usize) -> PathBuf {
    let digits = (frames.saturating_sub(1)).to_string().len().max(4);
    let stem = path.file_stem().map_or_else(|| "out".into(), |s| s.to_string_lossy().into_owned());
    let name = match path.extension() {
        Some(e) => format!("{stem}_{frame:0digits$}.{}", e.to_string_lossy()),
        None => format!("{stem}_{frame:0digits$}"),
    };
    path.with_file_name(name)
}

/// `transparent`, or `r,g,b`: three numbers (checked with the scene's settings).
fn parse_background(s: &str) -> Result<Background, String> {
    if s.trim() == "transparent" {
        return Ok(Background::Transparent);
    }
    let numbers: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("`{s}`: give `transparent` or a linear colour R,G,B (three numbers)"))?;
    let colour: [f64; 3] =
        numbers.try_into().map_err(|v: Vec<f64>| format!("`transparent` or three numbers R,G,B, not {}", v.len()))?;
    Ok(Background::Colour(colour))
}

/// `x0,x1,y0,y1`: four numbers.
fn parse_crop(s: &str) -> Result<[f64; 4], String> {
    let numbers: Vec<f64> =
        s.split(',').map(|x| x.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|e| e.to_string())?;
    numbers.try_into().map_err(|v: Vec<f64>| format!("four numbers x0,x1,y0,y1, not {}", v.len()))
}

/// Writes one line to stderr, ignoring failure: a closed or full stderr must not turn a
/// finished render (or its error) into a panic.
macro_rules! say {
    ($($arg:tt)*) => {{
        let _ = writeln!(std::io::stderr().lock(), $($arg)*);
    }};
}

/// User errors print one line (every cause once, no backtrace, whatever `RUST_BACKTRACE`
/// says) and exit with status 1; a command line clap cannot read, its first line (status 2).
/// Nothing here panics when stderr cannot be written: the status still says what happened.
fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            say!("{} (see --help)", clap_line(&e.render().to_string()));
            return ExitCode::from(2);
        }
        Err(e) => {
            // --help and --version: print them, whether or not stdout can take them.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    let result = match cli.command {
        Command::Render(args) => render_command(args),
        #[cfg(feature = "evolved")]
        Command::Mesh(args) => mesh_command(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            say!("error: {}", one_line(&e));
            ExitCode::FAILURE
        }
    }
}

/// clap's message on one line: its first line with the lines that name what is missing or
/// wrong (`the following required arguments were not provided:` is followed by them), up
/// to the usage and tips.
fn clap_line(text: &str) -> String {
    let mut line = String::new();
    for part in text.lines().map(str::trim).take_while(|l| !l.starts_with("Usage:") && !l.starts_with("tip:")) {
        if !part.is_empty() {
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(part);
        }
    }
    if line.is_empty() { "error: bad arguments".into() } else { line }
}

/// The error and its causes on one line, each cause left out when an earlier message
/// already says it.
fn one_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if !line.contains(&text) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&text);
        }
    }
    line.replace(['\n', '\r'], " ")
}

#[cfg(feature = "evolved")]
fn mesh_command(args: MeshArgs) -> anyhow::Result<()> {
    let format = cga_trace::mesh::MeshFormat::of(&args.output)?;
    let mut file = OutputFile::create(&args.output, &[("scene", &args.scene)])?;
    let scene = Scene::load(&args.scene)?;
    file.refuse(&scene.inputs)?;
    let mesh = scene.mesh(&args.object, args.rings, args.segments)?;
    mesh.save(&mut file, format).with_context(|| format!("writing {}", args.output.display()))?;
    file.commit()?;
    say!("{} triangles -> {}", mesh.triangles.len(), args.output.display());
    Ok(())
}

/// The worker pool `--threads` asks for (all cores when not given), refused outside
/// `1 ..= MAX_THREADS`; a note when it asks for more threads than there are cores.
fn thread_pool(threads: Option<usize>) -> anyhow::Result<rayon::ThreadPool> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if let Some(n) = threads {
        if !(1..=MAX_THREADS).contains(&n) {
            anyhow::bail!(
                "--threads {n}: give 1 to {MAX_THREADS} (or leave it out for one per core; this machine has {cores})"
            );
        }
        if n > cores {
            say!("note: {n} threads on {cores} cores: threads beyond the cores only add overhead");
        }
    }
    // 0: rayon's own choice, one per core unless RAYON_NUM_THREADS says otherwise.
    Ok(rayon::ThreadPoolBuilder::new().num_threads(threads.unwrap_or(0)).build()?)
}

fn render_command(args: Render) -> anyhow::Result<()> {
    let pool = thread_pool(args.threads)?;
    let Some(frames) = args.frames else { return render_frame(&args, &pool, &args.output, 0.0, true, &mut None) };
    if !(1..=MAX_FRAMES).contains(&frames) {
        anyhow::bail!("--frames {frames}: give 1 to {MAX_FRAMES}");
    }
    let (first, end) = args.frame_range.unwrap_or((0, frames));
    if end > frames {
        anyhow::bail!("--frame-range {first}..{end}: the animation has frames 0 to {}", frames - 1);
    }
    if !args.output.is_file() && args.output.exists() {
        anyhow::bail!(
            "--frames: {} is not a file; numbered frames are written beside a file name",
            args.output.display()
        );
    }
    // No frame may be written over another through a link, this command's or another's.
    let outputs: Vec<PathBuf> = (0..frames).map(|frame| numbered(&args.output, frame, frames)).collect();
    cga_trace::output::distinct(&outputs).context("--frames")?;
    // The scene's files are read once, for every frame.
    let mut pipeline = None;
    for frame in first..end {
        let time = if frames > 1 { frame as f64 / (frames - 1) as f64 } else { 0.0 };
        let output = numbered(&args.output, frame, frames);
        render_frame(&args, &pool, &output, time, frame == first, &mut pipeline)
            .with_context(|| format!("frame {frame}"))?;
    }
    Ok(())
}

/// One picture of the scene at the frame time `time`, written to `output`; the scene's files
/// are read into `pipeline` the first time (after the outputs are checked) and kept.
fn render_frame(
    args: &Render,
    pool: &rayon::ThreadPool,
    output_path: &Path,
    time: f64,
    notes: bool,
    pipeline: &mut Option<Pipeline>,
) -> anyhow::Result<()> {
    // Everything that can be wrong with the command line and the outputs is found before the
    // scene is read; nothing is written over until the render has succeeded.
    let output = Output::for_path(output_path, args.bit_depth)?;
    let mut image = OutputFile::create(output_path, &[("scene", &args.scene)])?;
    // A false-colour image's scale goes beside it (not beside a device: on stderr alone).
    let beside = scale_path(output_path);
    let mut scale_file = if args.aov.is_scalar() && !image.is_device() {
        Some(OutputFile::create(&beside, &[("scene", &args.scene), ("image", output_path)])?)
    } else {
        None
    };

    let pipeline = match pipeline {
        Some(pipeline) => pipeline,
        None => pipeline.insert(Pipeline::load(&args.scene, view(args)).map_err(flagged)?),
    };
    let (scene, resized) = pipeline.scene_noted(time).map_err(flagged)?;
    // Only the scene knows the files it reads: none may be an output.
    image.refuse(&scene.inputs)?;
    if let Some(file) = &scale_file {
        file.refuse(&scene.inputs)?;
    }
    // An animation's notes are the same for every frame: said once.
    if notes {
        for note in scene.notes().into_iter().chain(resized) {
            say!("note: {note}");
        }
    }
    let options = Options {
        time,
        aov: args.aov,
        backend: args.backend,
        crop: args.crop,
        packets: !args.no_packets,
        avx2: !args.no_avx2,
        labels: !args.no_labels,
        encoding: args.encoding,
    };
    // A transparent picture where the format has no alpha: refused before the render.
    check_output(&scene, &options, output, output_path)?;
    let rows = window(&scene, &options).map_err(flagged)?.rows.len();
    let bar = indicatif::ProgressBar::new(rows as u64).with_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} rows, {per_sec}, {elapsed} gone, {eta} left")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    if !std::io::stderr().is_terminal() {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let rendered = pool.install(|| pipeline.render(&scene, &options, &|| bar.inc(1))).map_err(flagged)?;
    bar.finish_and_clear();
    if let Some(scale) = &rendered.scale {
        say!(
            "{}: {} ({}) from {:.4e} (left of the bar) to {:.4e} (right), {} pixels -> {}",
            scale.map,
            scale.quantity,
            scale.unit,
            scale.low,
            scale.high,
            scale.pixels,
            if scale_file.is_some() { beside.display().to_string() } else { "stderr".into() }
        );
    }
    let writing = Instant::now();
    pool.install(|| rendered.write(&mut image, output, scale_file.as_mut()))?;
    // The image first, then its scale: each is the old file or the new, whatever fails.
    image.commit()?;
    if let Some(file) = scale_file {
        file.commit()?;
    }
    let written = writing.elapsed().as_secs_f64();

    let RayCounts { primary, shadow, reflection } = rendered.counts;
    let total = primary + shadow + reflection;
    let seconds = rendered.seconds;
    say!(
        "{} pixels, {total} rays ({primary} primary, {shadow} shadow, {reflection} reflection), {seconds:.3} s, {:.0} rays/s, written in {written:.3} s -> {}",
        u64::from(rendered.film.width) * u64::from(rendered.film.height),
        total as f64 / seconds.max(1e-9),
        output_path.display()
    );
    Ok(())
}

/// The command line's changes to the scene.
fn view(args: &Render) -> View {
    View {
        width: args.width,
        height: args.height,
        fov: args.fov,
        spp: args.spp,
        blur_samples: args.blur_samples,
        adaptive: args.adaptive,
        adaptive_min: args.adaptive_min,
        adaptive_method: args.adaptive_method,
        max_depth: args.max_depth,
        exposure: args.exposure,
        tone_map: args.tone_map,
        background: args.background,
    }
}

/// A pipeline's error, naming the flag that caused it where one did.
fn flagged(e: RenderError) -> anyhow::Error {
    let (flag, inner): (&str, anyhow::Error) = match e {
        RenderError::View(ViewError::Fov(e)) => ("--fov", e.into()),
        RenderError::View(ViewError::Size(e)) => ("--width/--height", e.into()),
        RenderError::View(ViewError::Settings(e)) => (
            "--max-depth/--spp/--blur-samples/--adaptive/--adaptive-min/--adaptive-method/--exposure/--background",
            e.into(),
        ),
        RenderError::Crop(e) => ("--crop", anyhow::Error::msg(e)),
        RenderError::Backend(e) => ("--backend", anyhow::Error::msg(e)),
        e => return e.into(),
    };
    inner.context(flag)
}
