//! What a blade is drawn as: the Euclidean reading of cga-core's [`Kind`] turned into the
//! renderer's shapes (`format/marks.rs` builds them), how large its marks are in a scene
//! ([`Marks`]) and the names of the blades. A point is a ball, a point pair two balls (and
//! optionally the segment between), a line a thin cylinder clipped to the view, a circle a
//! torus tube, a plane a disk about its point nearest the origin, a sphere itself. Imaginary
//! spheres and circles (`r² < 0`) are dashed: rings of short rods at radius `√−r²` (a
//! sphere's three great circles); an imaginary point pair has nothing to draw and is refused.
//! A tangent (a round of zero radius with a direction) and a direction are arrows; a flat
//! point, which has a place but no direction, is a small cube.

use cga_core::euclid::{E3, add, norm, scale, sub};
use cga_core::{Bivector, Circle, Pseudoscalar, Sphere, Vector};
use cga_core::{Kind, Reality};

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

    /// These sizes with an object's own `size` (a ball's radius and a patch's) and `tube`
    /// where it gives them.
    pub fn with(self, size: Option<f64>, tube: Option<f64>) -> Sizes {
        Sizes {
            size: size.unwrap_or(self.size),
            tube: tube.unwrap_or(self.tube),
            patch: size.unwrap_or(self.patch),
            ..self
        }
    }
}

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

    /// Where the drawing of a blade of `kind` is, for sizing the scene: [`Drawing::extent`],
    /// but an arrow has a place only as a tangent (a round of zero radius at its point), not
    /// as a direction (drawn wherever the scene's centre is).
    pub fn place(&self, kind: &Kind<f64>) -> Option<(E3, f64)> {
        match *self {
            Drawing::Arrow { at, .. } => matches!(kind, Kind::Round { .. }).then_some((at, 0.0)),
            _ => Some(self.extent()),
        }
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
}
