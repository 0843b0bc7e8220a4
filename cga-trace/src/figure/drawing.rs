//! What a blade is drawn as: the Euclidean reading of cga-core's [`Kind`] turned into the
//! renderer's shapes. A point is a ball, a point pair two balls (and optionally the segment
//! between), a line a thin cylinder clipped to the view, a circle a torus tube, a plane a
//! disk about its point nearest the origin, a sphere itself. Imaginary spheres and circles
//! (`r² < 0`) are dashed: rings of short rods at radius `√−r²` (a sphere's three great
//! circles); an imaginary point pair has nothing to draw and is refused. A tangent (a round
//! of zero radius with a direction) and a direction are arrows; a flat point, which has a
//! place but no direction, is a small cube.

use crate::format::Placement;
use crate::invalid::Invalid;
use crate::shapes::{BoxShape, ConeShape, DiskShape, Shape, SphereShape, TorusShape};
use cga_core::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub, unit};
use cga_core::{Kind, Reality};
use std::f64::consts::TAU;
use std::sync::Arc;

/// How large marks are drawn, in world units: defaults from the scene's extent
/// ([`Sizes::for_extent`]); `size` and `tube` overridable per object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sizes {
    /// A point's ball radius (a point pair's balls, a flat point's half edge).
    pub size: f64,
    /// The radius of tubes: a line's cylinder, a circle's torus, a segment, a dash, an arrow's
    /// shaft.
    pub tube: f64,
    /// A plane patch's radius.
    pub patch: f64,
    /// An arrow's length.
    pub arrow: f64,
    /// Where a direction (which has no place) is drawn: the scene's centre.
    pub centre: E3,
    /// The radius of the sphere about `centre` holding the scene's bounded objects.
    pub radius: f64,
}

impl Sizes {
    /// Nothing drawn: every mark of zero size, at the origin.
    pub const ZERO: Sizes = Sizes { size: 0.0, tube: 0.0, patch: 0.0, arrow: 0.0, centre: [0.0; 3], radius: 0.0 };

    /// Marks for a scene of bounding `radius` about `centre`: balls of `radius / 40`, tubes of
    /// `radius / 150`, patches of `radius / 2`, arrows of `radius / 4`.
    pub fn for_extent(centre: E3, radius: f64) -> Sizes {
        Sizes { size: radius / 40.0, tube: radius / 150.0, patch: radius / 2.0, arrow: radius / 4.0, centre, radius }
    }
}

/// A drawing's shapes, and where its label goes if not beside them all (centre and radius
/// in the frame).
pub(crate) type Parts = (Vec<Arc<dyn Shape>>, Option<(E3, f64)>);

/// Dashes a dashed ring is cut into, and the share of each dash's arc that is drawn.
const DASHES: usize = 24;
const DASH_FILL: f64 = 0.6;

/// A blade as it is drawn, in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Drawing {
    /// A ball of radius `size` at a point.
    Point {
        /// The point.
        at: E3,
        /// The ball's radius.
        size: f64,
    },
    /// Two balls, and the segment between them if `segment` gives its radius.
    PointPair {
        /// The points.
        points: [E3; 2],
        /// The balls' radius.
        size: f64,
        /// The segment's radius, if drawn.
        segment: Option<f64>,
    },
    /// A cylinder of radius `tube` along the line, clipped to the view.
    Line {
        /// A point of the line.
        point: E3,
        /// Its direction.
        direction: E3,
        /// The cylinder's radius.
        tube: f64,
    },
    /// A torus of tube radius `tube` about the circle; dashed for an imaginary circle.
    Circle {
        /// The centre.
        centre: E3,
        /// The unit normal.
        normal: E3,
        /// The radius (`√−r²` for an imaginary circle).
        radius: f64,
        /// The tube's radius.
        tube: f64,
        /// Whether imaginary (drawn dashed).
        dashed: bool,
    },
    /// A disk of radius `size` in the plane.
    PlanePatch {
        /// The patch's centre.
        centre: E3,
        /// The unit normal.
        normal: E3,
        /// Its radius.
        size: f64,
    },
    /// The sphere itself; an imaginary one as three dashed great circles.
    Sphere {
        /// The centre.
        centre: E3,
        /// The radius (`√−r²` for an imaginary sphere).
        radius: f64,
        /// The dashes' radius, for an imaginary sphere.
        tube: f64,
        /// Whether imaginary (drawn dashed).
        dashed: bool,
    },
    /// An arrow from `at` to `at + direction`.
    Arrow {
        /// Its foot.
        at: E3,
        /// Foot to tip.
        direction: E3,
        /// The shaft's radius.
        tube: f64,
    },
    /// A flat point `x ∧ ei`: a cube of half edge `size` at `x`.
    FlatPoint {
        /// The point.
        at: E3,
        /// Half the cube's edge.
        size: f64,
    },
}

/// Why a blade has no drawing.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum DrawError {
    /// Every coefficient zero.
    #[error("the blade is zero: it has no picture")]
    Zero,
    /// An imaginary point pair.
    #[error("an imaginary point pair (r² = {radius_squared:.3e}) has no real points to draw")]
    ImaginaryPair {
        /// Its squared radius.
        radius_squared: f64,
    },
    /// `ei` or `e123 ∧ ei`: a direction with nothing to point along.
    #[error("a grade-{grade} blade at infinity with no Euclidean direction (ei, or e123 ∧ ei) has no picture")]
    AtInfinity {
        /// Its grade.
        grade: usize,
    },
}

impl Drawing {
    /// What `kind` is drawn as, its marks sized by `sizes`; a point pair's segment drawn if
    /// `segment`.
    pub fn of(kind: Kind<f64>, sizes: &Sizes, segment: bool) -> Result<Drawing, DrawError> {
        let tube = sizes.tube;
        Ok(match kind {
            Kind::Zero => return Err(DrawError::Zero),
            Kind::Round { grade, reality, centre, radius_squared, direction } => {
                let radius = radius_squared.abs().sqrt();
                let dashed = reality == Reality::Imaginary;
                match (grade, reality) {
                    (1 | 4, Reality::Tangent) => Drawing::Point { at: centre, size: sizes.size },
                    (1 | 4, _) => Drawing::Sphere { centre, radius, tube, dashed },
                    (2, Reality::Imaginary) => return Err(DrawError::ImaginaryPair { radius_squared }),
                    (2, Reality::Real) => Drawing::PointPair {
                        points: [-radius, radius].map(|s| add(centre, direction.map(|d| s * d))),
                        size: sizes.size,
                        segment: segment.then_some(tube),
                    },
                    (_, Reality::Tangent) => {
                        Drawing::Arrow { at: centre, direction: scale(direction, sizes.arrow), tube }
                    }
                    _ => Drawing::Circle { centre, normal: direction, radius, tube, dashed },
                }
            }
            Kind::FlatPoint(at) => Drawing::FlatPoint { at, size: sizes.size },
            Kind::Line { point, direction } => Drawing::Line { point, direction, tube },
            Kind::Plane { normal, offset, .. } => {
                Drawing::PlanePatch { centre: scale(normal, offset), normal, size: sizes.patch }
            }
            Kind::Direction { grade, direction } => {
                if norm(direction) == 0.0 {
                    return Err(DrawError::AtInfinity { grade });
                }
                Drawing::Arrow { at: sizes.centre, direction: scale(direction, sizes.arrow), tube }
            }
        })
    }

    /// A point of the drawing and how far it reaches from it (world units; a line or plane
    /// reaches everywhere), to size the scene's frame by.
    pub fn extent(&self) -> (E3, f64) {
        match *self {
            Drawing::Point { at, size } | Drawing::FlatPoint { at, size } => (at, size),
            Drawing::PointPair { points: [a, b], size, .. } => (a, norm(sub(b, a)) + size),
            Drawing::Line { point, .. } => (point, f64::INFINITY),
            Drawing::Circle { centre, radius, tube, .. } => (centre, radius + tube),
            Drawing::PlanePatch { centre, size, .. } => (centre, size),
            Drawing::Sphere { centre, radius, tube, .. } => (centre, radius + tube),
            Drawing::Arrow { at, direction, tube } => (at, norm(direction) + 3.0 * tube),
        }
    }

    /// The shapes, placed in the frame by `place`; a line kept over the ball of radius `view`
    /// (frame units) about the camera ([`super::Marks::view`]: where its tube is a quarter
    /// of a pixel wide), as a
    /// segment about its point nearest `centre` (the scene's, in the frame: where its label
    /// goes), and where a label goes when not beside the sphere holding the shapes (a line's
    /// beside that point, its tube's radius away).
    pub(crate) fn shapes(&self, place: &Placement, centre: E3, view: f64) -> Result<Parts, Invalid> {
        let len = |l: f64| place.length(l);
        let mut out: Vec<Arc<dyn Shape>> = Vec::new();
        let mut anchor = None;
        match *self {
            Drawing::Point { at, size } => out.push(Arc::new(SphereShape::new(place.point(at)?, len(size))?)),
            Drawing::PointPair { points, size, segment } => {
                let [a, b] = [place.point(points[0])?, place.point(points[1])?];
                for p in [a, b] {
                    out.push(Arc::new(SphereShape::new(p, len(size))?));
                }
                if let Some(tube) = segment {
                    out.push(Arc::new(ConeShape::cylinder(a, b, len(tube), true)?));
                }
            }
            Drawing::Line { point, direction, tube } => {
                let (p, d) =
                    (place.point(point)?, unit(place.direction(direction)).ok_or(cga_core::GeometryError::ZeroVector)?);
                // The camera is the frame's origin: every point of the line within `view` of
                // it lies within `view + |foot|` of the foot.
                let foot = add(p, scale(d, dot(sub(centre, p), d)));
                let half = view + norm(foot);
                let (a, b) = (sub(foot, scale(d, half)), add(foot, scale(d, half)));
                out.push(Arc::new(ConeShape::cylinder(a, b, len(tube), true)?));
                anchor = Some((foot, len(tube)));
            }
            Drawing::Circle { centre, normal, radius, tube, dashed } => {
                let (c, n, r, t) = (place.point(centre)?, place.direction(normal), len(radius), len(tube));
                if dashed {
                    dashes(&mut out, c, n, r, t)?;
                } else {
                    out.push(Arc::new(TorusShape::new(c, n, r, t)?));
                }
            }
            Drawing::PlanePatch { centre, normal, size } => {
                out.push(Arc::new(DiskShape::new(place.point(centre)?, place.direction(normal), len(size))?));
            }
            Drawing::Sphere { centre, radius, tube, dashed } => {
                let (c, r) = (place.point(centre)?, len(radius));
                if dashed {
                    for n in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
                        dashes(&mut out, c, place.direction(n), r, len(tube))?;
                    }
                } else {
                    out.push(Arc::new(SphereShape::new(c, r)?));
                }
            }
            Drawing::Arrow { at, direction, tube } => {
                let (a, d, t) = (place.point(at)?, place.direction(direction).map(len), len(tube));
                // A shaft three quarters of the length, a head of three tubes' radius.
                let (neck, tip) = (add(a, scale(d, 0.75)), add(a, d));
                out.push(Arc::new(ConeShape::cylinder(a, neck, t, true)?));
                out.push(Arc::new(ConeShape::new(neck, 3.0 * t, tip, 0.0, true)?));
            }
            Drawing::FlatPoint { at, size } => {
                let (c, axes) = (place.point(at)?, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
                out.push(Arc::new(BoxShape::new([len(size); 3], c, axes.map(|a| place.direction(a)))?));
            }
        }
        Ok((out, anchor))
    }
}

/// A dashed ring: [`DASHES`] straight rods of radius `tube` on the circle of `centre`,
/// `normal` and `radius`, each over [`DASH_FILL`] of its arc.
fn dashes(out: &mut Vec<Arc<dyn Shape>>, centre: E3, normal: E3, radius: f64, tube: f64) -> Result<(), Invalid> {
    let n = unit(normal).ok_or(cga_core::GeometryError::ZeroVector)?;
    let u = unit(perpendicular(n)).ok_or(cga_core::GeometryError::ZeroVector)?;
    let v = cross(n, u);
    let on = |theta: f64| add(centre, add(scale(u, radius * theta.cos()), scale(v, radius * theta.sin())));
    for k in 0..DASHES {
        let start = TAU * k as f64 / DASHES as f64;
        let end = start + DASH_FILL * TAU / DASHES as f64;
        out.push(Arc::new(ConeShape::cylinder(on(start), on(end), tube, true)?));
    }
    Ok(())
}
