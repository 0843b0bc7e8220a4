//! `type = "blade"`: a blade given by its coefficients under blade names, in the null basis
//! (`e1 … e3`, `eo`, `ei`: `e1o`, `e12i`, `e123oi`, …) or the orthonormal one (`e4`, `e5`:
//! `e14`, `e1235`, …), drawn as cga-core's classification says it is.

use super::drawn::{Draws, read, sized};
use super::kind::{Kind, flag, spec};
use crate::drawing::{Drawing, Sizes};
use crate::format::blade::BladeSpec;
use crate::format::numbers::Num;
use crate::invalid::Invalid;
use cga_core::euclid::E3;

const TAKES: &str = "a blade takes `blade`, its coefficients by blade name ({ e1 = 1.0, eo = 1.0, … }), and optionally `size`, `tube`, `segment`";

pub(crate) const KIND: Kind = Kind { name: "blade", fields: Blade::FIELDS, takes: TAKES, read: read::<Blade> };

spec!(Blade { blade: BladeSpec => Blade, size: Num => Length, tube: Num => Length, segment: bool => Other });

impl Draws for Blade {
    fn drawing(&self, defaults: &Sizes) -> Result<Drawing, Invalid> {
        let sizes = sized(&self.size, &self.tube, defaults)?;
        let b = self.blade.as_ref().ok_or(Invalid::Form(TAKES))?;
        if matches!(b.get_ref(), BladeSpec::Circle(_)) {
            return Err(Invalid::at("blade", b.span(), Invalid::Value("give a blade's coefficients by name")));
        }
        let on = |e| Invalid::at("blade", b.span(), e);
        let kind = b.get_ref().kind().map_err(on)?;
        Drawing::of(kind, &sizes, flag(&self.segment, false)).map_err(|e| on(e.into()))
    }

    fn place(&self, drawing: Drawing) -> Option<(E3, f64)> {
        let kind = self.blade.as_ref().and_then(|b| b.get_ref().kind().ok())?;
        drawing.place(&kind)
    }
}
