//! `type = "evolved"`: the surface swept between circles `c1` and `c2` (the paper's
//! `X_α = α C1 + (1 − α) C2`, each made a circle again), with `caps`, its end disks.

use super::circles::{self, CircleSpec};
use super::kind::{At, Geometry, Kind, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::invalid::Invalid;
use cga_core::euclid::E3;

const TAKES: &str = "an evolved surface takes `c1` and `c2`, and `caps` (its end disks, default false)";

pub(crate) const KIND: Kind = Kind { name: "evolved", fields: Evolved::FIELDS, takes: TAKES, read: read::<Evolved> };

spec!(Evolved { c1: CircleSpec => Circle, c2: CircleSpec => Circle, caps: bool => Other });

impl Geometry for Evolved {
    fn extent(&self, _: &Assets) -> Option<(E3, f64)> {
        let c2 = self.c2.as_ref().map(|c| c.get_ref());
        circles::extent(std::iter::once(self.c1.as_ref()?.get_ref()).chain(c2))
    }

    #[cfg(feature = "evolved")]
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        use super::circles::capped;
        use super::kind::flag;
        let (Some(c1), Some(c2)) = (&self.c1, &self.c2) else { return Err(Invalid::Form(TAKES)) };
        let surface = std::sync::Arc::new(surface(c1, c2, at)?);
        Ok((capped(surface, [c1, c2], flag(&self.caps, false), at)?, None))
    }

    #[cfg(not(feature = "evolved"))]
    fn build(&self, _: &At) -> Result<Parts, Invalid> {
        Err(Invalid::NoEvolved)
    }

    /// With `caps`, its surface and end disks close a solid.
    fn closed(&self, _: &Assets) -> Result<bool, Invalid> {
        Ok(super::kind::flag(&self.caps, false))
    }
}

/// The surface, its circles built in the frame of [`EvolvedSurface::frame_origin`] (inside
/// the scene's frame), each moved by its own transform and then by the object's.
#[cfg(feature = "evolved")]
fn surface(
    c1: &toml::Spanned<CircleSpec>,
    c2: &toml::Spanned<CircleSpec>,
    at: &At,
) -> Result<crate::surface::EvolvedSurface, Invalid> {
    use super::circles::circle;
    use crate::surface::EvolvedSurface;
    use cga_core::Circle;
    use cga_core::euclid::sub;
    let on = |which, span: std::ops::Range<usize>| move |e| Invalid::at(which, span.clone(), e);
    let (s1, s2) = (c1.span(), c2.span());
    let (c1, n1, r1) = circle(c1.get_ref(), &at.place).map_err(on("c1", s1.clone()))?;
    let (c2, n2, r2) = circle(c2.get_ref(), &at.place).map_err(on("c2", s2.clone()))?;
    let origin = EvolvedSurface::frame_origin((c1, r1), (c2, r2));
    let local = |c: E3, n, r| Circle::from_centre_normal_radius(sub(c, origin), n, r);
    let c1 = local(c1, n1, r1).map_err(|e| on("c1", s1)(e.into()))?;
    let c2 = local(c2, n2, r2).map_err(|e| on("c2", s2)(e.into()))?;
    Ok(EvolvedSurface::in_frame(origin, c1, c2, at.method)?)
}
