//! The scene → picture pipeline, written once for the command line, [`Figure`](crate::Figure),
//! the tests and any program: a scene file read once ([`Source`]), placed at a time of its
//! motion with a [`View`]'s changes, rendered on a back end through its shutter (each instant
//! placed anew, never read again), false colour for a scalar AOV, and the picture developed
//! (exposure, tone map), labelled and written atomically; over a transparent background with
//! its coverage as alpha (PNG straight, EXR premultiplied; refused for HDR).
//!
//! ```no_run
//! use cga_trace::pipeline::{Options, Pipeline, View};
//! let mut pipeline = Pipeline::load("scene.toml".as_ref(), View { width: Some(640), ..View::default() })?;
//! let scene = pipeline.scene(0.0)?;
//! let rendered = pipeline.render(&scene, &Options::default(), &|| {})?;
//! rendered.save("out.png".as_ref(), None)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::backend::{Backend, BackendKind, Dense, Plain, Sparse};
use crate::camera::{Camera, CameraError};
use crate::colour::{Scale, false_colour};
use crate::film::{Encoding, Film, Output, OutputError, ToneMap};
use crate::format::{SceneError, Source};
use crate::input::Input;
use crate::integrator::{Aov, Kept, RayCounts, Renderer, Window};
use crate::invalid::Invalid;
use crate::label::{Label, draw_labels};
use crate::output::{OutputFile, OutputFileError};
use crate::scene::Scene;
use crate::settings::{Adaptive, AdaptiveMethod, Background};
use crate::shutter::Sample;
use std::borrow::Cow;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Changes to a scene's own camera and settings (the command line's `--width`, `--fov`, …);
/// `None` keeps the file's.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct View {
    /// Image width in pixels (the height follows at the image's aspect unless given; also
    /// the size of a camera that gives none).
    pub width: Option<u32>,
    /// Image height in pixels (the width follows unless given).
    pub height: Option<u32>,
    /// Horizontal field of view in degrees (`x_max = 2 f tan(fov/2)`; `y_max` follows).
    pub fov: Option<f64>,
    /// Samples per pixel (the most a pixel takes where sampling is adaptive).
    pub spp: Option<u32>,
    /// Adaptive sampling's contrast threshold ([`Adaptive`], with the scene's `min_spp`, or 4).
    pub adaptive: Option<f64>,
    /// Adaptive sampling's first samples a pixel (with the scene's threshold, or 0.3 where it
    /// gives none).
    pub adaptive_min: Option<u32>,
    /// Adaptive sampling's method (with the scene's threshold, or 0.3 where it gives none).
    pub adaptive_method: Option<AdaptiveMethod>,
    /// Camera rays a sample averages through a thin lens ([`crate::settings::Settings::blur_samples`]).
    pub blur_samples: Option<u32>,
    /// Reflection depth.
    pub max_depth: Option<u32>,
    /// Exposure of PNG output in stops.
    pub exposure: Option<f64>,
    /// Tone map of PNG output.
    pub tone_map: Option<ToneMap>,
    /// What camera rays that meet nothing show: a colour, or nothing (a transparent picture).
    pub background: Option<Background>,
}

impl View {
    /// `scene` with these changes, checked; a note where a resize leaves pixels that are not
    /// square (the file pins both extents).
    pub fn apply(&self, scene: &mut Scene) -> Result<Option<String>, ViewError> {
        if let Some(degrees) = self.fov {
            scene.set_fov(degrees).map_err(ViewError::Fov)?;
        }
        let note = scene.resize(self.width, self.height).map_err(ViewError::Size)?;
        let s = &mut scene.settings;
        s.max_depth = self.max_depth.unwrap_or(s.max_depth);
        s.spp = self.spp.unwrap_or(s.spp);
        s.blur_samples = self.blur_samples.unwrap_or(s.blur_samples);
        if self.adaptive.is_some() || self.adaptive_min.is_some() || self.adaptive_method.is_some() {
            let given = s.adaptive.unwrap_or(Adaptive::threshold(Adaptive::THRESHOLD));
            s.adaptive = Some(Adaptive {
                threshold: self.adaptive.unwrap_or(given.threshold),
                min_spp: self.adaptive_min.unwrap_or(given.min_spp),
                method: self.adaptive_method.unwrap_or(given.method),
            });
        }
        s.exposure = self.exposure.unwrap_or(s.exposure);
        s.tone_map = self.tone_map.unwrap_or(s.tone_map);
        if let Some(background) = self.background {
            s.set_background(background);
        }
        s.check().map_err(ViewError::Settings)?;
        Ok(note)
    }
}

/// A [`View`] a scene cannot take, by the change that fails.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    /// The field of view.
    #[error("fov: {0}")]
    Fov(#[source] CameraError),
    /// The width or height.
    #[error("width/height: {0}")]
    Size(#[source] CameraError),
    /// Depth, samples, adaptive threshold, exposure or background out of their range.
    #[error("max_depth/spp/adaptive/exposure/background: {0}")]
    Settings(#[source] Invalid),
}

/// How a picture is rendered; every choice has a default ([`Options::default`]: the shaded
/// picture of the whole image at time 0, on the sparse back end, in packets, labelled).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// The motion's time in [0, 1] the picture is taken at (an animation's frame).
    pub time: f64,
    /// What the picture shows.
    pub aov: Aov,
    /// The geometry code.
    pub backend: BackendKind,
    /// Only this window `[x0, x1, y0, y1]` (fractions of the image, y from the top).
    pub crop: Option<[f64; 4]>,
    /// Packets of four rays on SIMD lanes (the same picture; off to compare speed).
    pub packets: bool,
    /// Packets in AVX2 registers where the CPU has them.
    pub avx2: bool,
    /// The objects' labels, written into a shaded picture of the whole image.
    pub labels: bool,
    /// The PNG encoding, in place of the scene's.
    pub encoding: Option<Encoding>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            time: 0.0,
            aov: Aov::Shaded,
            backend: BackendKind::Sparse,
            crop: None,
            packets: true,
            avx2: true,
            labels: true,
            encoding: None,
        }
    }
}

/// What can stop a picture.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The scene file, its includes or assets.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A change the scene cannot take.
    #[error(transparent)]
    View(#[from] ViewError),
    /// A crop window outside the image or empty.
    #[error("crop: {0}")]
    Crop(&'static str),
    /// The back end cannot hold the scene's range of sizes.
    #[error("backend: {0}")]
    Backend(String),
    /// A scene with a shutter given without its source: it must be placed at each instant.
    #[error("the scene has a shutter: render it through its Pipeline, which places it at each instant")]
    Shutter,
    /// The scene placed at one of its shutter's instants.
    #[error("the shutter's instant at time {time}: {source}")]
    Instant {
        /// The motion's time.
        time: f64,
        /// Why.
        source: Box<RenderError>,
    },
    /// The output's kind.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// Writing the output.
    #[error(transparent)]
    File(#[from] OutputFileError),
    /// Writing the output.
    #[error("writing {file}: {source}")]
    Write {
        /// The file.
        file: String,
        /// Why.
        source: std::io::Error,
    },
}

/// A scene file and every file it reads, read once, with the changes every picture of it
/// takes: the scene at any time of its motion, and its pictures.
pub struct Pipeline {
    source: Source,
    view: View,
    /// What renderers prepared of the objects, kept between instants and frames.
    kept: Kept,
    /// Pictures rendered so far (what is prepared is kept from the second on).
    pictures: usize,
}

impl Pipeline {
    /// The scene file `path` (and the files it reads).
    pub fn load(path: &Path, view: View) -> Result<Pipeline, RenderError> {
        Ok(Pipeline { source: Source::load(path)?, view, kept: Kept::default(), pictures: 0 })
    }

    /// A scene given as text; `file` names it in errors, and its folder is where the files
    /// it names are read from.
    pub fn parse(text: &str, file: &str, view: View) -> Result<Pipeline, RenderError> {
        Ok(Pipeline { source: Source::parse(text, file)?, view, kept: Kept::default(), pictures: 0 })
    }

    /// The changes every later scene and picture takes, in place of the present ones (the
    /// files stay read).
    pub fn set_view(&mut self, view: View) {
        self.view = view;
    }

    /// The scene at the motion's time `time` with the view's changes.
    pub fn scene(&mut self, time: f64) -> Result<Scene, RenderError> {
        Ok(self.scene_noted(time)?.0)
    }

    /// [`Pipeline::scene`], and a note where the view leaves pixels that are not square.
    pub fn scene_noted(&mut self, time: f64) -> Result<(Scene, Option<String>), RenderError> {
        let size = self.view.width.zip(self.view.height);
        let mut scene = self.source.scene(size, time)?;
        let note = self.view.apply(&mut scene)?;
        Ok((scene, note))
    }

    /// The picture of `scene` (this pipeline's, at `options.time`): through its shutter
    /// where it has one, each pixel sample at its own instant ([`crate::shutter`]), with the
    /// objects that move placed anew at each (those that stay, and their hierarchy, are kept
    /// from the instant before); `on_row` is called once a row, as the picture goes.
    pub fn render(
        &mut self,
        scene: &Scene,
        options: &Options,
        on_row: &(dyn Fn() + Sync),
    ) -> Result<Rendered, RenderError> {
        let window = window(scene, options)?;
        let start = std::time::Instant::now();
        let (film, counts) = match scene.shutter {
            None => {
                let kept = (self.pictures > 0).then_some(&mut self.kept);
                let (done, counts) = render_on(scene, options, Job::Window(window, on_row), kept)?;
                (done.film(), counts)
            }
            Some(shutter) => {
                let mut counts = RayCounts::default();
                let pixels = (window.columns.clone(), window.rows.clone());
                let (time, spp) = (options.time, scene.settings.spp);
                let mut instant = |t: f64, samples: &[Sample]| {
                    let at = self.scene(t).map_err(|e| RenderError::Instant { time: t, source: Box::new(e) })?;
                    let (done, cast) = render_on(&at, options, Job::Samples(samples), Some(&mut self.kept))?;
                    counts.add(&cast);
                    Ok::<_, RenderError>(done)
                };
                // The coverage too is averaged over the instants.
                let film = match options.aov.covered(&scene.settings) {
                    false => shutter.expose(time, spp, pixels, on_row, |t, s| instant(t, s).map(Done::colours))?,
                    true => shutter.expose(time, spp, pixels, on_row, |t, s| instant(t, s).map(Done::covered))?,
                };
                (film, counts)
            }
        };
        self.pictures += 1;
        Ok(Rendered::new(scene, options, film, counts, start.elapsed().as_secs_f64()))
    }
}

/// The picture of a scene that does not move (one built in code, or placed by its
/// [`Pipeline`] already); a scene with a shutter is refused ([`RenderError::Shutter`]).
pub fn render(scene: &Scene, options: &Options, on_row: &(dyn Fn() + Sync)) -> Result<Rendered, RenderError> {
    if scene.shutter.is_some() {
        return Err(RenderError::Shutter);
    }
    let window = window(scene, options)?;
    let start = std::time::Instant::now();
    let (done, counts) = render_on(scene, options, Job::Window(window, on_row), None)?;
    Ok(Rendered::new(scene, options, done.film(), counts, start.elapsed().as_secs_f64()))
}

/// Refuses `output` (at `path`) for the picture `options` take of `scene` where the picture
/// carries a coverage the format cannot store (a transparent background to HDR): found before
/// the render, not after it.
pub fn check_output(scene: &Scene, options: &Options, output: Output, path: &Path) -> Result<(), RenderError> {
    Ok(output.check_alpha(path, options.aov.covered(&scene.settings))?)
}

/// The window `options` crops the scene's image to, or the whole image.
pub fn window(scene: &Scene, options: &Options) -> Result<Window, RenderError> {
    let (w, h) = (scene.camera.width, scene.camera.height);
    match options.crop {
        Some(c) => Window::crop(w, h, c).map_err(RenderError::Crop),
        None => Ok(Window::full(w, h)),
    }
}

/// What a renderer is asked for: a window of the picture, or the colours of some samples.
enum Job<'a> {
    Window(Window, &'a (dyn Fn() + Sync)),
    Samples(&'a [Sample]),
}

/// What a [`Job`] gives: a film, or the samples' colours (with their coverage where the
/// picture carries it, [`Aov::covered`]).
enum Done {
    Film(Film),
    Colours(Vec<[f64; 3]>),
    Covered(Vec<[f64; 4]>),
}

impl Done {
    fn film(self) -> Film {
        match self {
            Done::Film(f) => f,
            _ => unreachable!("a window's job gives a film"),
        }
    }

    fn colours(self) -> Vec<[f64; 3]> {
        match self {
            Done::Colours(c) => c,
            _ => unreachable!("an opaque picture's samples give colours"),
        }
    }

    fn covered(self) -> Vec<[f64; 4]> {
        match self {
            Done::Covered(c) => c,
            _ => unreachable!("a transparent picture's samples give their coverage"),
        }
    }
}

/// `job` done on the options' back end, and the rays cast; what was prepared of the objects
/// for the last picture taken from `kept` (and left there) where given.
fn render_on(
    scene: &Scene,
    options: &Options,
    job: Job<'_>,
    kept: Option<&mut Kept>,
) -> Result<(Done, RayCounts), RenderError> {
    match options.backend {
        BackendKind::Sparse => render_with::<Sparse>(scene, options, job, kept),
        BackendKind::Dense => render_with::<Dense>(scene, options, job, kept),
        BackendKind::Plain => render_with::<Plain>(scene, options, job, kept),
    }
}

/// [`render_on`] on back end `B`.
fn render_with<B: Backend>(
    scene: &Scene,
    options: &Options,
    job: Job<'_>,
    kept: Option<&mut Kept>,
) -> Result<(Done, RayCounts), RenderError> {
    // What is prepared is kept for the next picture only where something moves.
    let mut renderer = match kept.filter(|_| scene.objects.iter().any(|o| o.moving)) {
        Some(kept) => Renderer::<B>::keeping(scene, kept),
        None => Renderer::<B>::with_backend(scene),
    };
    renderer.holds().map_err(RenderError::Backend)?;
    if !options.packets {
        renderer = renderer.without_packets();
    }
    if !options.avx2 {
        renderer = renderer.without_avx2();
    }
    let done = match job {
        Job::Window(window, on_row) => Done::Film(renderer.render_window(options.aov, window, on_row)),
        Job::Samples(samples) if options.aov.covered(&scene.settings) => {
            Done::Covered(renderer.render_covered_samples(options.aov, samples))
        }
        Job::Samples(samples) => Done::Colours(renderer.render_samples(options.aov, samples)),
    };
    Ok((done, renderer.counts()))
}

/// A rendered picture: the film as rendered (linear; in false colour for a scalar AOV, with
/// its scale) and what developing and writing it takes.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The film as rendered: linear values, or a scalar AOV in false colour with its bar.
    pub film: Film,
    /// What a false-colour picture's colours mean.
    pub scale: Option<Scale>,
    /// The rays cast.
    pub counts: RayCounts,
    /// Seconds spent rendering (wall time).
    pub seconds: f64,
    /// The PNG encoding.
    pub encoding: Encoding,
    /// Exposure and tone map, for a shaded picture (other AOVs are shown as rendered).
    develop: Option<(f64, ToneMap)>,
    /// Labels to write in, and the camera that places them; `None` where they are left out
    /// (another AOV, a crop, or asked so).
    labels: Option<(Vec<Label>, Camera)>,
    /// The files the scene was read from (no output may be one of them).
    inputs: Vec<Input>,
}

impl Rendered {
    fn new(scene: &Scene, options: &Options, film: Film, counts: RayCounts, seconds: f64) -> Rendered {
        let (film, scale) = match false_colour(&film, options.aov) {
            Some((coloured, scale)) => (coloured, Some(scale)),
            None => (film, None),
        };
        let labelled = options.aov == Aov::Shaded && options.crop.is_none() && options.labels;
        Rendered {
            film,
            scale,
            counts,
            seconds,
            encoding: options.encoding.unwrap_or(scene.settings.encoding),
            develop: (options.aov == Aov::Shaded).then_some((scene.settings.exposure, scene.settings.tone_map)),
            labels: labelled.then(|| (scene.labels.clone(), scene.camera)),
            inputs: scene.inputs.clone(),
        }
    }

    /// The picture as `output` stores it: a shaded PNG developed (`2^exposure`, then the tone
    /// map; EXR and HDR keep the linear values, other AOVs are as rendered), then the labels
    /// written in, in their own colours (opaque where drawn, over a transparent background).
    /// Borrowed as rendered where nothing changes it (no copy of the film).
    pub fn image(&self, output: Output) -> Cow<'_, Film> {
        let png = matches!(output, Output::Png8 | Output::Png16);
        let mut film = match self.develop {
            Some((exposure, tone_map)) if png && (exposure != 0.0 || tone_map != ToneMap::None) => {
                Cow::Owned(self.film.developed(exposure, tone_map))
            }
            _ => Cow::Borrowed(&self.film),
        };
        if let Some((labels, camera)) = self.labels.as_ref().filter(|(labels, _)| !labels.is_empty()) {
            draw_labels(film.to_mut(), camera, labels);
        }
        film
    }

    /// The image written to `image` as `output`, and a false-colour picture's scale (JSON) to
    /// `scale`; neither committed (their caller commits both once both are written).
    pub fn write(
        &self,
        image: &mut OutputFile,
        output: Output,
        scale: Option<&mut OutputFile>,
    ) -> Result<(), RenderError> {
        let io = |file: &OutputFile| {
            let file = file.path().display().to_string();
            move |source| RenderError::Write { file, source }
        };
        output.check_alpha(image.path(), self.film.coverage.is_some())?;
        self.image(output).write(image, output, self.encoding)?;
        if let (Some(file), Some(s)) = (scale, &self.scale) {
            let json = serde_json::to_string_pretty(s).expect("a scale serialises") + "\n";
            file.write_all(json.as_bytes()).map_err(io(file))?;
        }
        Ok(())
    }

    /// The picture written to `path` (PNG, EXR or HDR by its extension; `bits` 8 or 16 for a
    /// PNG), and a false-colour picture's scale beside it ([`scale_path`]), each to a
    /// temporary file renamed over the target once written; refused if either is one of the
    /// scene's files.
    pub fn save(&self, path: &Path, bits: Option<u8>) -> Result<(), RenderError> {
        let output = Output::for_path(path, bits)?;
        output.check_alpha(path, self.film.coverage.is_some())?;
        let mut image = OutputFile::create(path, &[])?;
        image.refuse(&self.inputs)?;
        let beside = scale_path(path);
        let mut scale = match &self.scale {
            Some(_) if !image.is_device() => {
                let file = OutputFile::create(&beside, &[("image", path)])?;
                file.refuse(&self.inputs)?;
                Some(file)
            }
            _ => None,
        };
        self.write(&mut image, output, scale.as_mut())?;
        image.commit()?;
        if let Some(file) = scale {
            file.commit()?;
        }
        Ok(())
    }
}

/// The file beside a false-colour image that holds its scale: `OUTPUT.scale.json`.
pub fn scale_path(output: &Path) -> PathBuf {
    let mut beside = output.as_os_str().to_owned();
    beside.push(".scale.json");
    beside.into()
}
