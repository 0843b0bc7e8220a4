//! Conformal geometric algebra G(4,1) as grade-sparse, compile-time generated types, and the
//! conformal geometry of points, lines, circles, spheres and planes built on them.
//!
//! [`algebra`] holds the one `algebra!` invocation that generates every type and product;
//! [`Real`] is the scalar they are generic over (`f32`, `f64`, [`Dual`]). Depend on this crate
//! alone for geometry: it pulls in nothing of the renderer.
//!
//! # A guide
//!
//! **Objects from Euclidean data, and back.** Every constructor returns `Result` with a
//! named [`GeometryError`]; read-backs return the Euclidean parameters. The convention
//! throughout: `Result` with a named error wherever something is wrong ([`GeometryError`],
//! [`InterpolationError`], [`NormalError`], [`VersorError`]: `down` of a point at infinity,
//! the points of a missed sphere, …); `Option` only where "nothing" is an ordinary answer
//! with no more to say (a line parallel to a plane, or crossing it outside a disk).
//!
//! ```
//! use cga_core::{Circle, Line, Sphere};
//! let sphere: Sphere = Sphere::from_centre_radius([1.0, 2.0, 3.0], 0.5)?;
//! let (centre, radius) = sphere.centre_radius()?;
//! assert!((radius - 0.5).abs() < 1e-15 && (centre[2] - 3.0).abs() < 1e-15);
//! let circle: Circle = Circle::through([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0])?;
//! let (_, normal, r) = circle.centre_normal_radius()?;
//! assert!((r - 1.0).abs() < 1e-15 && (normal[2] - 1.0).abs() < 1e-15);
//! assert!(Line::<f64>::through([0.0; 3], [0.0; 3]).is_err()); // CoincidentPoints
//! # Ok::<(), cga_core::GeometryError>(())
//! ```
//!
//! **Products.** `*` geometric, `^` outer, `|` inner, `&` regressive (the meet); each
//! result has the smallest type that holds it, and only nonzero terms are computed.
//!
//! ```
//! use cga_core::{Circle, up};
//! let (a, b, c) = (up([1.0, 0.0, 0.0]), up([0.0, 1.0, 0.0]), up([-1.0, 0.0, 0.0]));
//! let circle: Circle = a ^ b ^ c; // the circle through three conformal points
//! let (_, _, radius) = circle.centre_normal_radius().unwrap();
//! assert!((radius - 1.0).abs() < 1e-12);
//! ```
//!
//! **Meets, classified** by tolerances that no translation or scaling changes
//! ([`RoundMeet::new`] states the band where rounding can still misclassify).
//!
//! ```
//! use cga_core::{Hit, Line, Sphere};
//! let sphere: Sphere = Sphere::from_centre_radius([0.0, 0.0, 0.0], 1.0)?;
//! let axis: Line = Line::through([0.0, 0.0, -3.0], [0.0, 0.0, 3.0])?;
//! let meet = axis.meet_sphere(&sphere);
//! assert_eq!(meet.hit, Hit::Two);
//! let [enter, exit] = meet.points(&axis).unwrap(); // ordered along the line
//! assert!((enter[2] + 1.0).abs() < 1e-12 && (exit[2] - 1.0).abs() < 1e-12);
//! // A thousand units away, lines a millionth of the radius outside and inside the sphere:
//! // classified as Euclid would (the band of doubt there is 1e-9 of the radius).
//! let far: Sphere = Sphere::from_centre_radius([1e3, 0.0, 0.0], 1.0)?;
//! let at = |x: f64| Line::<f64>::through([1e3 + x, 0.0, -1.0], [1e3 + x, 0.0, 1.0]);
//! assert_eq!(at(1.0 + 1e-6)?.meet_sphere(&far).hit, Hit::Miss);
//! assert_eq!(at(1.0 - 1e-6)?.meet_sphere(&far).hit, Hit::Two);
//! # Ok::<(), cga_core::GeometryError>(())
//! ```
//!
//! **Versors**: rotors, translators and motors move any object by `V X Ṽ`.
//!
//! ```
//! use cga_core::{Motor, Rotor, Sandwich, Translator, down, up};
//! let turn = Rotor::from_axis_angle([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2)?;
//! let motor = Motor::from_rotor_translator(turn, Translator::from_vector([2.0, 0.0, 0.0]));
//! let moved = down(motor.sandwich(up([1.0, 0.0, 0.0]))).unwrap();
//! assert!((moved[0] - 2.0).abs() < 1e-12 && (moved[1] - 1.0).abs() < 1e-12);
//! # Ok::<(), cga_core::GeometryError>(())
//! ```
//!
//! **Interpolation and the evolved surface's normal.** [`Pair::new`] checks that f64 can
//! deliver the interpolation (else `IllConditioned`, with an estimate); the normal is
//! analytic (`Ω = C Ċ`, `Ċ` exact on dual numbers).
//!
//! ```
//! use cga_core::{Circle, InterpolationError, Pair};
//! let c1: Circle = Circle::from_centre_normal_radius([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1.0).unwrap();
//! let c2 = Circle::from_centre_normal_radius([0.0, 0.0, 2.0], [0.0, 0.0, 1.0], 2.0).unwrap();
//! let surface = Pair::new(c1, c2)?;
//! let (centre, _, r) = surface.at(0.5)?.centre_normal_radius().unwrap();
//! let normal = surface.normal(0.5, [centre[0] + r, centre[1], centre[2]]).unwrap();
//! assert!(normal[1].abs() < 1e-12); // in the plane of the axis and the point
//! // Unit circles 1e5 from the origin: f64 cannot deliver, and says so.
//! let far = |z| Circle::<f64>::from_centre_normal_radius([1e5, 0.0, z], [0.0, 0.0, 1.0], 1.0).unwrap();
//! assert!(matches!(Pair::new(far(0.0), far(2.0)), Err(InterpolationError::IllConditioned { .. })));
//! # Ok::<(), InterpolationError>(())
//! ```
//!
//! **Exact derivatives**: run any generic code on [`Dual`] numbers.
//!
//! ```
//! use cga_core::{Dual, up};
//! let t = Dual::variable(2.0); // d/dt at t = 2
//! let p = up([t, Dual::constant(0.0), Dual::constant(0.0)]);
//! assert_eq!((p.ei.re, p.ei.du), (2.0, 2.0)); // ½t² and its derivative t
//! ```
//!
//! **clifford.tools' helpers**: seeded random objects ([`random`], feature `random`, on by
//! default), fits with a stated error ([`Fit`]), [`average_objects`], the closest points of
//! a circle and a line or two circles ([`closest`]), and versors between frames, objects and
//! rounds ([`Rotor::between_frames`], [`VersorBetween`], [`Motor::between_circles`]).
//!
//! Conventions (basis, signs, dual, meet) are in the repository's ARCHITECTURE.md and on
//! [`algebra`]; error bounds against `ρ = |c|/r` in docs/STABILITY.md.

pub mod algebra;
pub mod classify;
pub mod closest;
pub mod conformal;
mod convert;
#[cfg(feature = "glam")]
pub mod cookbook;
pub mod curvature;
mod display;
mod dual;
pub mod euclid;
pub mod evolved;
pub mod fit;
pub mod flat;
pub mod interpolate;
pub mod intersect;
pub mod measure;
pub mod meet;
#[cfg(feature = "random")]
pub mod random;
mod real;
pub mod reflect;
pub mod simd;
pub mod spline;
pub mod versor;

pub use algebra::*;

/// Everything at `f64`, for `use cga_core::prelude::*;`: every type as an alias
/// (`prelude::Circle` is `Circle<f64>`, so float literals need no annotation), the generated
/// products and the toolkit's traits (methods and operators), and the free functions.
///
/// ```
/// use cga_core::prelude::*;
/// let c = Circle::through([1.3, 0.0, 0.0], [0.0, 1.3, 0.0], [-1.3, 0.0, 0.0]).unwrap();
/// let (centre, _, radius) = c.centre_normal_radius().unwrap();
/// assert!((radius - 1.3).abs() < 1e-12 && centre.iter().all(|x| x.abs() < 1e-12));
/// let moved: Vector = Motor::from_translation([0.0, 0.0, 2.0]).sandwich(up([1.0, 2.0, 3.0]));
/// assert!((down(moved).unwrap()[2] - 5.0).abs() < 1e-12);
/// ```
pub mod prelude {
    pub use crate::algebra::prelude::*;
    pub use crate::{
        AsFlat as _, Interpolable as _, Meet, Nearest as _, Real, Reflect as _, RoundMeet, distance, down, ei, eo,
        fit_circle, fit_line, fit_plane, fit_sphere, interpolate, up,
    };
}
pub use classify::{Kind, Reality, classify_storage};
pub use conformal::{Disk, GeometryError, circumcircle, circumsphere, down, down_lanes, down_unit, ei, eo, up};
pub use curvature::{Curvature, CurvatureError, curvature, from_fundamental_forms};
pub use dual::Dual;
pub use evolved::{NormalError, NormalParts};
pub use fit::{
    Fit, fit_circle, fit_circle_with_error, fit_line, fit_line_with_error, fit_plane, fit_plane_with_error, fit_sphere,
    fit_sphere_with_error,
};
pub use flat::{AsFlat, Flat};
pub use interpolate::{
    Interpolable, InterpolationError, Pair, align, average_objects, average_objects_weighted, interpolate, project_at,
};
pub use intersect::Meet;
pub use measure::{Closest, Nearest, distance};
pub use meet::{Hit, RoundMeet};
pub use real::{Real, Select};
pub use reflect::Reflect;
pub use spline::{Joining, Spline, SplineError, bezier};
pub use versor::{Frame, MotorSpline, Screw, VersorBetween, VersorError, exp, rotor_between_lines};
