//! `cga.draw([sphere, circle, line], …)`: CGA objects drawn as what they are, as pyganja
//! draws them, into a picture.

use crate::classes::values_of;
use crate::errors::SceneError;
use crate::figure::{PALETTE, add};
use crate::render::{Picture, background_of};
use cga_trace::figure::Figure;
use cga_trace::pipeline::Options;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

/// The picture of `objects` (values or arrays of them), each in its colour (a name such as
/// "red" or "#rrggbb"; the palette in turn where none is given) and with its label, framed by
/// the figure's camera unless `camera` gives `(position, look_at)`, over `background`
/// (`"transparent"`: an RGBA picture, alpha each pixel's coverage; a colour name or
/// `"#rrggbb"`; linear `[r, g, b]`; the figure's dark blue-grey where not given).
#[pyfunction]
#[pyo3(signature = (objects, colours = None, labels = None, width = 640, height = 480, camera = None, background = None))]
#[allow(clippy::too_many_arguments)]
pub fn draw(
    py: Python<'_>,
    objects: Vec<Bound<'_, PyAny>>,
    colours: Option<Vec<String>>,
    labels: Option<Vec<Option<String>>>,
    width: u32,
    height: u32,
    camera: Option<([f64; 3], [f64; 3])>,
    background: Option<Bound<'_, PyAny>>,
) -> PyResult<Picture> {
    let mut figure = Figure::new().resolution(width, height);
    if let Some(background) = &background {
        figure = figure.background(background_of(background)?);
    }
    if let Some((position, look_at)) = camera {
        figure = figure.camera(position, look_at);
    }
    for (k, object) in objects.iter().enumerate() {
        let values = values_of(object).ok_or_else(|| {
            PyTypeError::new_err(format!(
                "object {}: expected a cga value, got {}",
                k + 1,
                object.get_type().name().map(|n| n.to_string()).unwrap_or_default()
            ))
        })?;
        let colour =
            colours.as_ref().and_then(|c| c.get(k).cloned()).unwrap_or_else(|| PALETTE[k % PALETTE.len()].into());
        let label = labels.as_ref().and_then(|l| l.get(k).cloned().flatten());
        figure = add(figure, values, &colour, label.as_deref());
    }
    let rendered =
        py.detach(|| figure.rendered(&Options::default())).map_err(|e| SceneError::new_err(e.to_string()))?;
    Ok(Picture::new(rendered))
}
