//! Scenes rendered to numpy arrays through cga-trace's pipeline: a scene file (or its text)
//! read once, rendered with any of the command line's options (the GIL released while it
//! renders), and its picture as linear values, as the 8-bit sRGB a PNG holds, in a notebook
//! (`_repr_png_`), or written atomically; over a transparent background as RGBA (linear
//! premultiplied, as EXR stores it; 8-bit straight, as PNG stores it).

use crate::errors::SceneError;
use cga_trace::film::Output;
use cga_trace::pipeline::{Options, Pipeline, RenderError, Rendered, View};
use cga_trace::settings::{AdaptiveMethod, Background, ToneMap};
use cga_trace::{Aov, BackendKind};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::IntoPyObjectExt;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::sync::Mutex;

/// A scene file and the files it reads, read once; `render` takes a picture of it.
#[pyclass(module = "cga")]
pub struct Scene {
    pipeline: Mutex<Pipeline>,
}

/// `e` in cga's `SceneError`.
fn scene_error(e: impl std::fmt::Display) -> PyErr {
    SceneError::new_err(e.to_string())
}

/// A scene of `pipeline`, checked by placing it once (every error of the file is found at
/// loading, not at the first picture).
fn checked(py: Python<'_>, pipeline: Result<Pipeline, RenderError>) -> PyResult<Scene> {
    let mut pipeline = pipeline.map_err(scene_error)?;
    py.detach(|| pipeline.scene(0.0).map(|_| ())).map_err(scene_error)?;
    Ok(Scene { pipeline: Mutex::new(pipeline) })
}

/// A `background` as Python gives it: `"transparent"`, a colour name or `"#rrggbb"` (sRGB, as
/// a figure's colours), or three linear values `[r, g, b]` (as a scene file's).
pub fn background_of(value: &Bound<'_, PyAny>) -> PyResult<Background> {
    let refused = || {
        SceneError::new_err(format!(
            "background = {value}: give \"transparent\", a colour name or \"#rrggbb\", or linear [r, g, b]"
        ))
    };
    if let Ok(name) = value.extract::<String>() {
        return match name.as_str() {
            "transparent" => Ok(Background::Transparent),
            _ => cga_trace::figure::colour(&name).map(Background::Colour).ok_or_else(refused),
        };
    }
    value.extract::<[f64; 3]>().map(Background::Colour).map_err(|_| refused())
}

/// An option's value among `choices`, refused by name otherwise.
fn choose<T: Copy>(option: &str, value: &str, choices: &[(&str, T)]) -> PyResult<T> {
    choices.iter().find(|(name, _)| *name == value).map(|(_, t)| *t).ok_or_else(|| {
        let names: Vec<&str> = choices.iter().map(|(n, _)| *n).collect();
        SceneError::new_err(format!("{option} = {value:?}: give one of {}", names.join(", ")))
    })
}

#[pymethods]
impl Scene {
    /// The scene file `path` (TOML; the scene format of docs/SCENES.md).
    #[staticmethod]
    fn load(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Self> {
        checked(py, Pipeline::load(&path, View::default()))
    }

    /// A scene given as TOML text; `file` names it in errors, and its folder is where the
    /// files it names are read from.
    #[staticmethod]
    #[pyo3(signature = (text, file = "scene.toml"))]
    fn parse(py: Python<'_>, text: &str, file: &str) -> PyResult<Self> {
        checked(py, Pipeline::parse(text, file, View::default()))
    }

    /// The scene's picture: the scene's own size and settings unless given. `aov` is one of
    /// shaded, normal, alpha, gaussian, mean, k1, k2, postulate, coverage; `backend` sparse, dense or
    /// plain; `crop` four fractions `[x0, x1, y0, y1]` (y from the top); `time` the motion's
    /// time in [0, 1]; `blur_samples` the camera rays each sample averages through a thin lens
    /// (POV-Ray's `blur_samples`, 1 to 256); `adaptive` a contrast threshold (POV-Ray's `+A`, 0 to 3) that makes
    /// `spp` a maximum, taken only where a pixel's first samples (`adaptive_min`, default 4;
    /// given alone, it turns adaptive sampling on at the scene's threshold or 0.3) or its
    /// neighbours' differ by more; `adaptive_method` `"samples"` (that) or `"corners"`
    /// (POV-Ray's method 2: a ray at each pixel corner, shared by four pixels, and squares
    /// whose corners differ cut in four, down to log₄ `spp` levels); `background` `"transparent"` (the picture is RGBA, alpha
    /// each pixel's coverage), a colour name or `"#rrggbb"`, or linear `[r, g, b]`, in place of
    /// the scene's.
    #[pyo3(signature = (*, width = None, height = None, fov = None, spp = None, blur_samples = None, adaptive = None, adaptive_min = None, adaptive_method = None, max_depth = None,
        exposure = None, tone_map = None, time = 0.0, aov = "shaded", backend = "sparse", crop = None, labels = true, background = None))]
    #[allow(clippy::too_many_arguments)]
    fn render(
        &self,
        py: Python<'_>,
        width: Option<u32>,
        height: Option<u32>,
        fov: Option<f64>,
        spp: Option<u32>,
        blur_samples: Option<u32>,
        adaptive: Option<f64>,
        adaptive_min: Option<u32>,
        adaptive_method: Option<&str>,
        max_depth: Option<u32>,
        exposure: Option<f64>,
        tone_map: Option<&str>,
        time: f64,
        aov: &str,
        backend: &str,
        crop: Option<[f64; 4]>,
        labels: bool,
        background: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Picture> {
        let tone_map = tone_map
            .map(|t| choose("tone_map", t, &[("none", ToneMap::None), ("filmic", ToneMap::Filmic)]))
            .transpose()?;
        let background = background.as_ref().map(background_of).transpose()?;
        let adaptive_method = adaptive_method
            .map(|m| {
                let methods = [("samples", AdaptiveMethod::Samples), ("corners", AdaptiveMethod::Corners)];
                choose("adaptive_method", m, &methods)
            })
            .transpose()?;
        let view = View {
            width,
            height,
            fov,
            spp,
            blur_samples,
            adaptive,
            adaptive_min,
            adaptive_method,
            max_depth,
            exposure,
            tone_map,
            background,
        };
        let aov = choose(
            "aov",
            aov,
            &[
                ("shaded", Aov::Shaded),
                ("normal", Aov::Normal),
                ("alpha", Aov::Alpha),
                ("gaussian", Aov::Gaussian),
                ("mean", Aov::Mean),
                ("k1", Aov::K1),
                ("k2", Aov::K2),
                ("postulate", Aov::Postulate),
                ("coverage", Aov::Coverage),
            ],
        )?;
        let backend = choose(
            "backend",
            backend,
            &[("sparse", BackendKind::Sparse), ("dense", BackendKind::Dense), ("plain", BackendKind::Plain)],
        )?;
        let options = Options { time, aov, backend, crop, labels, ..Options::default() };
        let rendered = py.detach(|| {
            let mut pipeline =
                self.pipeline.lock().map_err(|_| "a render of this scene failed in another thread".to_string())?;
            pipeline.set_view(view);
            let scene = pipeline.scene(time).map_err(|e| e.to_string())?;
            pipeline.render(&scene, &options, &|| {}).map_err(|e| e.to_string())
        });
        Ok(Picture::new(rendered.map_err(scene_error)?))
    }
}

/// A rendered picture.
#[pyclass(module = "cga", frozen)]
pub struct Picture {
    rendered: Rendered,
}

impl Picture {
    /// A picture of a rendering.
    pub fn new(rendered: Rendered) -> Picture {
        Picture { rendered }
    }

    /// The picture as PNG bytes (8-bit, developed and labelled; RGBA over a transparent
    /// background).
    pub fn png(&self) -> Result<Vec<u8>, cga_trace::film::OutputError> {
        let mut bytes = std::io::Cursor::new(Vec::new());
        self.rendered.image(Output::Png8).write(&mut bytes, Output::Png8, self.rendered.encoding)?;
        Ok(bytes.into_inner())
    }

    /// The film's rows top to bottom as an (H, W, 3) array, or (H, W, 4) with its coverage
    /// (colours premultiplied, as rendered).
    fn rows<'py>(&self, py: Python<'py>, film: &cga_trace::Film) -> PyResult<Py<PyAny>> {
        let (w, h) = (film.width as usize, film.height as usize);
        let n = if film.coverage.is_some() { 4 } else { 3 };
        let mut flat = Vec::with_capacity(w * h * n);
        for j in (0..h).rev() {
            for i in j * w..(j + 1) * w {
                flat.extend_from_slice(&film.pixels[i]);
                if let Some(coverage) = &film.coverage {
                    flat.push(coverage[i]);
                }
            }
        }
        PyArray1::from_vec(py, flat).reshape([h, w, n])?.into_py_any(py)
    }
}

#[pymethods]
impl Picture {
    /// The linear values as rendered, an (H, W, 3) float array, the top row first (a scalar
    /// AOV in false colour); over a transparent background (H, W, 4), RGB premultiplied by
    /// the alpha, each pixel's coverage (as an EXR stores them).
    #[getter]
    fn linear(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.rows(py, &self.rendered.film)
    }

    /// The picture as an 8-bit PNG holds it (developed, labelled, encoded): an (H, W, 3)
    /// uint8 array, the top row first; over a transparent background (H, W, 4), straight
    /// (unassociated) colours and the coverage as alpha, labels opaque.
    #[getter]
    fn srgb(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let image = self.rendered.image(Output::Png8);
        let (w, h) = (image.width as usize, image.height as usize);
        let (flat, n) = match image.coverage {
            Some(_) => (image.to_rgba8(self.rendered.encoding).into_raw(), 4),
            None => (image.to_rgb8(self.rendered.encoding).into_raw(), 3),
        };
        PyArray1::from_vec(py, flat).reshape([h, w, n])?.into_py_any(py)
    }

    /// Each pixel's coverage over a transparent background, the fraction of its samples whose
    /// camera ray met something: an (H, W) float array, the top row first (labels not
    /// written in); `None` for an opaque picture.
    #[getter]
    fn coverage(&self, py: Python<'_>) -> PyResult<Option<Py<PyAny>>> {
        let film = &self.rendered.film;
        let Some(coverage) = &film.coverage else { return Ok(None) };
        let (w, h) = (film.width as usize, film.height as usize);
        let rows: Vec<f64> = (0..h).rev().flat_map(|j| coverage[j * w..(j + 1) * w].iter().copied()).collect();
        Ok(Some(PyArray1::from_vec(py, rows).reshape([h, w])?.into_py_any(py)?))
    }

    /// `(width, height)`.
    #[getter]
    fn size(&self) -> (u32, u32) {
        (self.rendered.film.width, self.rendered.film.height)
    }

    /// Rays cast: `(primary, shadow, reflection)`.
    #[getter]
    fn rays(&self) -> (u64, u64, u64) {
        let c = self.rendered.counts;
        (c.primary, c.shadow, c.reflection)
    }

    /// Writes the picture to `path` (PNG, EXR or HDR by its extension; `bit_depth` 8 or 16
    /// for a PNG), to a temporary file renamed over the target once written; refused if it is
    /// one of the scene's files, or HDR for a transparent picture (HDR has no alpha).
    #[pyo3(signature = (path, bit_depth = None))]
    fn save(&self, py: Python<'_>, path: std::path::PathBuf, bit_depth: Option<u8>) -> PyResult<()> {
        py.detach(|| self.rendered.save(&path, bit_depth)).map_err(scene_error)
    }

    /// The picture as PNG bytes, for Jupyter.
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let mut bytes = std::io::Cursor::new(Vec::new());
        self.rendered
            .image(Output::Png8)
            .write(&mut bytes, Output::Png8, self.rendered.encoding)
            .map_err(scene_error)?;
        Ok(PyBytes::new(py, bytes.get_ref()))
    }

    fn __repr__(&self) -> String {
        let (w, h) = self.size();
        format!("Picture {w}×{h} ({:.3} s)", self.rendered.seconds)
    }
}

/// The scene format's object kinds as files write them, each with the fields it takes beyond
/// those every object takes (`type`, `name`, `label`, `material`, `motor`, `transform`,
/// `motion`, `template`): the registry the loader reads them by.
#[pyfunction]
pub(crate) fn _object_kinds() -> Vec<(&'static str, Vec<&'static str>)> {
    let common = cga_trace::format::COMMON.len();
    let fields =
        |kind| cga_trace::format::fields(kind).unwrap_or_default().iter().skip(common).map(|f| f.name).collect();
    cga_trace::format::kinds().into_iter().map(|kind| (kind, fields(kind))).collect()
}
