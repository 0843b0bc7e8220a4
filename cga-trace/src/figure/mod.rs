//! Figures: CGA objects given in code drawn into a picture ([`Figure`]), with what each kind
//! of blade is drawn as ([`Drawing`], [`Marks`]) and labels beside them ([`Label`]).

mod builder;
pub mod cookbook;

pub use crate::drawing::{DrawError, Drawing, Marks, Sizes, null_basis_names};
pub use crate::label::{Label, MAX_LABEL_CHARS, draw_labels, project};
pub use builder::{BladeError, Drawable, Figure, FigureError, MAX_FIGURE_OBJECTS, colour};
