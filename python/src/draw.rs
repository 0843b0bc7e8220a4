//! Pictures of CGA objects, as pyganja draws them: `cga.draw([sphere, circle, line], …)` and
//! every object's `_repr_png_` in a notebook, through cga-trace's `Figure` (each blade drawn
//! as what it is: a point as a ball, a circle as a torus tube, an imaginary round dashed).

use crate::classes::values_of;
use crate::errors::SceneError;
use crate::render::Picture;
use crate::values::Values;
use cga_trace::figure::{Drawable, Figure};
use cga_trace::pipeline::Options;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

/// Colours given to objects in turn when none is named.
const PALETTE: [&str; 8] = ["red", "blue", "green", "orange", "purple", "cyan", "magenta", "yellow"];

/// One value's null-basis coefficients, as a figure draws them.
struct Stored([f64; 32]);

impl Drawable for Stored {
    fn coefficients(&self) -> [f64; 32] {
        self.0
    }
}

/// `figure` with every row of `values` added in `colour`, the first labelled `label`.
fn add(mut figure: Figure, values: &Values, colour: &str, label: Option<&str>) -> Figure {
    for i in 0..values.n {
        figure = figure.add(&Stored(values.storage(i)), colour);
        if let (0, Some(text)) = (i, label) {
            figure = figure.label(text);
        }
    }
    figure
}

/// The picture of `objects` (values or arrays of them), each in its colour (a name such as
/// "red" or "#rrggbb"; the palette in turn where none is given) and with its label, framed by
/// the figure's camera unless `camera` gives `(position, look_at)`.
#[pyfunction]
#[pyo3(signature = (objects, colours = None, labels = None, width = 640, height = 480, camera = None))]
pub fn draw(
    py: Python<'_>,
    objects: Vec<Bound<'_, PyAny>>,
    colours: Option<Vec<String>>,
    labels: Option<Vec<Option<String>>>,
    width: u32,
    height: u32,
    camera: Option<([f64; 3], [f64; 3])>,
) -> PyResult<Picture> {
    let mut figure = Figure::new().resolution(width, height);
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
        figure = add(figure, &values, &colour, label.as_deref());
    }
    let rendered =
        py.detach(|| figure.rendered(&Options::default())).map_err(|e| SceneError::new_err(e.to_string()))?;
    Ok(Picture::new(rendered))
}

/// One value (or array) drawn alone at 320 × 240 as PNG bytes; `None` where it has no picture
/// (a versor, a zero blade), so that a notebook shows its text instead.
pub fn png(py: Python<'_>, values: &Values) -> Option<Vec<u8>> {
    let figure = add(Figure::new().resolution(320, 240), values, PALETTE[0], None);
    let rendered = py.detach(|| figure.rendered(&Options::default())).ok()?;
    Picture::new(rendered).png().ok()
}
