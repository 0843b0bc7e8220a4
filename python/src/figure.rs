//! Values in a figure: each row of an array added to cga-trace's `Figure` (which draws each
//! blade as what it is: a point as a ball, a circle as a torus tube, an imaginary round
//! dashed), and one value's picture as PNG bytes for a notebook.

use crate::render::Picture;
use crate::values::Values;
use cga_trace::figure::{Drawable, Figure};
use cga_trace::pipeline::Options;
use pyo3::prelude::*;

/// Colours given to objects in turn when none is named.
pub const PALETTE: [&str; 8] = ["red", "blue", "green", "orange", "purple", "cyan", "magenta", "yellow"];

/// One value's null-basis coefficients, as a figure draws them.
struct Stored([f64; 32]);

impl Drawable for Stored {
    fn coefficients(&self) -> [f64; 32] {
        self.0
    }
}

/// `figure` with every row of `values` added in `colour`, the first labelled `label`.
pub fn add(mut figure: Figure, values: &Values, colour: &str, label: Option<&str>) -> Figure {
    for i in 0..values.n {
        figure = figure.add(&Stored(values.storage(i)), colour);
        if let (0, Some(text)) = (i, label) {
            figure = figure.label(text);
        }
    }
    figure
}

/// One value (or array) drawn alone at 320 × 240 as PNG bytes; `None` where it has no picture
/// (a versor, a zero blade), so that a notebook shows its text instead.
pub fn png(py: Python<'_>, values: &Values) -> Option<Vec<u8>> {
    if values.ty.algebra != crate::values::Algebra::CGA {
        return None;
    }
    let figure = add(Figure::new().resolution(320, 240), values, PALETTE[0], None);
    let rendered = py.detach(|| figure.rendered(&Options::default())).ok()?;
    Picture::new(rendered).png().ok()
}
