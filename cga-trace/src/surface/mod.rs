//! Evolved circle surfaces: where a ray meets the family `C_α`, α ∈ [0, 1].
//!
//! A ray's line `L` touches `C_α` exactly when `f(α) = (C_α ∨ L)²` vanishes (the meet is
//! then the touching point). Every method:
//! 1. rejects rays that miss the surface's bounding sphere;
//! 2. finds candidate α in [0, 1] (the ends included, so hits at α = 0 and 1 count) — by
//!    sampling `f`, by the roots of a degree-8 polynomial, or through cells (bounding
//!    spheres and tubes over α-intervals) that pick the intervals a ray reaches ([`Method`]);
//! 3. verifies every candidate geometrically: the point must lie on the circle and on the
//!    line. Where the meet degenerates — the line lies in the circle's plane, so
//!    `C ∨ L = 0` for every point — the points come from the line–circle intersection
//!    in that plane instead of being missed. The nearest with `t_min < t < t_max` counts.
//!
//! Everything is computed in a frame centred between the two circles: conformal
//! coordinates carry `½x²`, and far from the origin precision falls as (|c|/r)³
//! (docs/STABILITY.md). Methods, errors and timings: docs/SURFACE.md.

#[cfg(feature = "evolved")]
pub mod bernstein;
#[cfg(feature = "evolved")]
mod cells;
#[cfg(feature = "evolved")]
mod evolved;
#[cfg(feature = "evolved")]
pub mod family;
#[cfg(feature = "evolved")]
mod newton;
#[cfg(feature = "evolved")]
mod patches;
#[cfg(feature = "evolved")]
mod ruled;
#[cfg(feature = "evolved")]
pub mod segment;
#[cfg(feature = "evolved")]
mod spline;
#[cfg(feature = "evolved")]
pub mod unsquared;

use cga_core::{GeometryError, InterpolationError};
#[cfg(feature = "evolved")]
pub use evolved::EvolvedSurface;
#[cfg(feature = "evolved")]
pub use family::{Circles, Family, Finder, TwoCircles};
#[cfg(feature = "evolved")]
pub use ruled::{RuledSurface, Rulings};
#[cfg(feature = "evolved")]
pub use segment::BezierSegment;
#[cfg(feature = "evolved")]
pub use spline::SplineSurface;

/// Why two circles make no surface this renderer can draw.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// An end circle is not a real circle (a line, imaginary, degenerate).
    #[error("circle {which} is not a real circle: {reason}")]
    NotACircle {
        /// 1-based: 1 or 2, or the control circle's place in a spline.
        which: usize,
        /// What it is instead.
        reason: GeometryError,
    },
    /// The two circles are one circle (to 1e-12 of its radius), the same way round or
    /// reversed: the family is that circle alone, which bounds nothing.
    #[error(
        "{} are the same circle{}: they sweep no surface",
        between.map_or("c1 and c2".into(), |(a, b)| format!("circles {a} and {b}")),
        if *reversed { " with opposite orientations" } else { "" }
    )]
    SameCircle {
        /// Which two control circles of a spline (1-based); `None` for `c1` and `c2`.
        between: Option<(usize, usize)>,
        /// Whether the normals are opposite.
        reversed: bool,
    },
    /// The two circles cannot be normalised and aligned.
    #[error("the circles cannot be normalised")]
    Degenerate,
    /// Somewhere between them the interpolation has no circle.
    #[error("the circles do not interpolate: {0}")]
    NoInterpolation(#[from] InterpolationError),
    /// The control circles make no spline (their count, or its parameters).
    #[error(transparent)]
    Spline(#[from] cga_core::SplineError),
    /// Somewhere between them the family passes through a line (infinite radius).
    #[error("the surface is unbounded: at α = {alpha} the interpolated circle is a line")]
    Unbounded {
        /// Where.
        alpha: f64,
    },
}

/// `(α, angle)` of a crossing on a swept surface whose circle `C_α` has centre `c` and unit
/// normal `n`: the angle about `n` as a fraction of a turn, from the first axis
/// [`orthonormal`](crate::light::orthonormal) to `n`.
#[cfg(feature = "evolved")]
pub(crate) fn swept_uv(
    crossing: &crate::shapes::Crossing,
    (c, n): (cga_core::euclid::E3, cga_core::euclid::E3),
) -> Option<([f64; 2], crate::shapes::Unit)> {
    use cga_core::euclid::{dot, sub};
    let (a, b) = crate::light::orthonormal(n);
    let d = sub(crossing.point, c);
    let angle = 0.5 + dot(d, b).atan2(dot(d, a)) / std::f64::consts::TAU;
    Some(([crossing.alpha?, angle], crate::shapes::Unit::Fraction))
}

/// The crossing error of a swept surface of bounding radius `radius` centred at `origin`
/// (frame units): its crossings are verified on their circle `C_α` to `1e-6` of its radius
/// (`family.rs`, `hit_points`), and its local frame's origin carries its own rounding.
#[cfg(feature = "evolved")]
pub(crate) fn swept_error(origin: cga_core::euclid::E3, radius: f64) -> f64 {
    1e-6 * radius + crate::shapes::rounding(crate::shapes::largest(origin))
}

/// How rays are intersected with the surface.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize)]
#[serde(rename_all = "lowercase", tag = "method", deny_unknown_fields)]
pub enum Method {
    /// Baseline (the paper's): `samples` uniform samples of `f` over [0, 1] per ray, sign
    /// changes bisected, local minima of `|f|` searched.
    Sampling {
        /// Samples per ray.
        samples: usize,
    },
    /// The degree-8 polynomial in α ([`Family::polynomial`]) per ray, its roots in [0, 1]
    /// isolated by Bernstein subdivision and refined to `tolerance` in α.
    Polynomial {
        /// Refinement tolerance in α (0: to rounding level).
        tolerance: f64,
    },
    /// Bounding spheres and tubes over `leaves` equal α-intervals (cells, built once per
    /// surface, tested four at a time) reject rays and isolate the intervals a ray can hit;
    /// each is sampled `per_leaf` times and roots are refined by safeguarded Newton with the
    /// exact `f'`.
    Hierarchy {
        /// α-cells (a power of two).
        leaves: usize,
        /// Samples per interval a ray reaches.
        per_leaf: usize,
    },
    /// The cells of [`Method::Hierarchy`] to cull, and the polynomial of
    /// [`Method::Polynomial`], built on each interval reached, to find the roots.
    Hybrid {
        /// α-cells (a power of two).
        leaves: usize,
        /// Refinement tolerance in α.
        tolerance: f64,
    },
}

impl Default for Method {
    fn default() -> Self {
        Method::Hybrid { leaves: 16, tolerance: 0.0 }
    }
}

/// The one place where a [`Method`] becomes the two things it decides: how rays are culled
/// (α-cells of bounding spheres and tubes, or none) and how roots are found over each α-interval a
/// ray reaches ([`Finder`]).
#[cfg(feature = "evolved")]
impl Method {
    /// The α-cells the method culls with (a power of two), `None` for none.
    pub fn cells(&self) -> Option<usize> {
        match *self {
            Method::Hierarchy { leaves, .. } | Method::Hybrid { leaves, .. } => Some(leaves.next_power_of_two().max(1)),
            Method::Sampling { .. } | Method::Polynomial { .. } => None,
        }
    }

    /// The root finder over an interval spanning `leaves` cells (the whole of `[0, 1]` for
    /// methods without cells).
    pub fn finder(&self, leaves: usize) -> Finder {
        match *self {
            Method::Sampling { samples } => Finder::Samples(samples),
            Method::Polynomial { tolerance } | Method::Hybrid { tolerance, .. } => Finder::Polynomial(tolerance),
            Method::Hierarchy { per_leaf, .. } => Finder::Slope(per_leaf.max(2) * leaves),
        }
    }
}

impl Method {
    /// Why these settings cannot work, if they cannot: too few samples to find a root, more
    /// than [`MAX_SURFACE_SAMPLES`](crate::limits::MAX_SURFACE_SAMPLES) per ray, more than
    /// 65536 leaves, or a tolerance outside `[0, 0.1]`.
    pub fn check(&self) -> Result<(), &'static str> {
        use crate::limits::MAX_SURFACE_SAMPLES as MAX;
        let leaves_ok = |leaves: usize| (1..=1 << 16).contains(&leaves);
        let tolerance_ok = |t: f64| (0.0..=0.1).contains(&t);
        match *self {
            Method::Sampling { samples } if !(2..=MAX).contains(&samples) => Err("samples must be 2 to 65536"),
            Method::Hierarchy { leaves, per_leaf }
                if !leaves_ok(leaves) || per_leaf < 2 || leaves.next_power_of_two().saturating_mul(per_leaf) > MAX =>
            {
                Err("leaves must be 1 to 65536, per_leaf at least 2, and leaves × per_leaf at most 65536")
            }
            Method::Polynomial { tolerance } if !tolerance_ok(tolerance) => Err("tolerance must be 0 to 0.1"),
            Method::Hybrid { leaves, tolerance } if !leaves_ok(leaves) || !tolerance_ok(tolerance) => {
                Err("leaves must be 1 to 65536 and tolerance 0 to 0.1")
            }
            _ => Ok(()),
        }
    }
}
