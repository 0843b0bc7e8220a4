//! Seeing CGA objects: what each kind of blade is drawn as ([`Drawing`]), how large its marks
//! are in a scene ([`Marks`]), and labels written beside objects ([`Label`]).

mod builder;
pub mod cookbook;
mod drawing;
mod label;

pub use builder::{BladeError, Drawable, Figure, FigureError, MAX_FIGURE_OBJECTS, colour};
pub(crate) use drawing::Parts;
pub use drawing::{DrawError, Drawing, Sizes};
pub use label::{Label, MAX_LABEL_CHARS, draw_labels, project};

use cga_core::euclid::{E3, norm, sub};
use cga_core::{Bivector, Circle, Pseudoscalar, Sphere, Vector};

/// The names of the null-basis blades (`s`, `e1`, `eo`, `e1o`, `e12i`, …, `e123oi`), in the
/// order of the storage arrays (`to_storage`), from the generated types' own tables.
pub fn null_basis_names() -> [&'static str; 32] {
    let mut names = ["s"; 32];
    let mut put = |blades: &[&'static str], index: &[usize]| {
        for (name, &k) in blades.iter().zip(index) {
            names[k] = name;
        }
    };
    put(&Vector::<f64>::BLADES, &Vector::<f64>::STORAGE_INDEX);
    put(&Bivector::<f64>::BLADES, &Bivector::<f64>::STORAGE_INDEX);
    put(&Circle::<f64>::BLADES, &Circle::<f64>::STORAGE_INDEX);
    put(&Sphere::<f64>::BLADES, &Sphere::<f64>::STORAGE_INDEX);
    put(&Pseudoscalar::<f64>::BLADES, &Pseudoscalar::<f64>::STORAGE_INDEX);
    names
}

/// The marks of a scene's drawings, in world units: default sizes from the scene's extent,
/// and how far from the camera a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Marks {
    /// Default sizes ([`Sizes::for_extent`] of the scene's bounding sphere).
    pub sizes: Sizes,
    /// A pixel's angle (radians at the picture's centre).
    pub pixel: f64,
    /// The distance from the camera past the far side of the scene's bounding sphere
    /// (doubled): lines reach at least this far.
    pub reach: f64,
}

impl Marks {
    /// The marks for objects of the given `(point, extent)` (world units, an extent of ∞ for
    /// unbounded ones) seen from `camera` with pixels of `pixel` radians: sized by the sphere
    /// holding the bounded objects (about the unbounded ones' points when there are none;
    /// a tenth of its distance from the camera if it has no size, 1 if that is zero too).
    pub fn for_scene(objects: &[(E3, f64)], camera: E3, pixel: f64) -> Marks {
        let bounded: Vec<(E3, f64)> = objects.iter().copied().filter(|o| o.1.is_finite()).collect();
        let held: Vec<(E3, f64)> =
            if bounded.is_empty() { objects.iter().map(|o| (o.0, 0.0)).collect() } else { bounded };
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for (p, e) in &held {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k] - e);
                hi[k] = hi[k].max(p[k] + e);
            }
        }
        let centre = if held.is_empty() { camera } else { [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k])) };
        let mut radius = held.iter().map(|(p, e)| norm(sub(*p, centre)) + e).fold(0.0, f64::max);
        if !(radius > 0.0 && radius.is_finite()) {
            radius = 0.1 * norm(sub(centre, camera));
        }
        if !(radius > 0.0 && radius.is_finite()) {
            radius = 1.0;
        }
        let reach = 2.0 * (norm(sub(centre, camera)) + radius);
        Marks { sizes: Sizes::for_extent(centre, radius), pixel, reach }
    }

    /// How far from the camera (world units) a drawing is kept: a line to where its tube is a
    /// quarter of a pixel wide (`8 tube / pixel`: a tube under a pixel wide still covers the
    /// pixel centres it crosses), or past the scene if that is farther.
    pub fn view(&self, drawing: &Drawing) -> f64 {
        match drawing {
            Drawing::Line { tube, .. } => (8.0 * tube / self.pixel).max(self.reach),
            _ => self.reach,
        }
    }
}
