//! The scene file format (TOML, via serde): what each table and object may hold, and how a
//! parsed file becomes the camera, frame and shapes of a [`Scene`](crate::Scene). Unknown
//! fields are errors. Each kind of object is one variant of `ObjectSpec` and one arm of
//! `build_object`, which calls the shape's own constructor.

use crate::camera::Camera;
use crate::frame::Frame;
use crate::light::Light;
use crate::material::{Material, one};
use crate::scene::{Invalid, Object};
use crate::settings::Settings;
use crate::shapes::{DiskShape, PlaneShape, Shape, SphereShape, TriangleShape};
#[cfg(feature = "evolved")]
use crate::surface::EvolvedSurface;
use crate::surface::Method;
use cga_core::euclid::E3;
use cga_core::{Motor, Rotor};
use serde::Deserialize;
use std::sync::Arc;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SceneFile {
    pub camera: Spanned<CameraSpec>,
    pub render: Option<Spanned<Settings>>,
    #[serde(default)]
    pub lights: Vec<Spanned<Light>>,
    #[serde(default)]
    pub objects: Vec<Spanned<ObjectSpec>>,
}

/// The camera: a pose (`position`, `look_at`, `up`, or a `motor`), focal length, image-plane
/// extents and pixel size.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct CameraSpec {
    position: Option<E3>,
    look_at: Option<E3>,
    #[serde(default = "z_up")]
    up: E3,
    /// Motor coefficients `s, e12, e13, e23, e1i, e2i, e3i, e123i` (instead of position/look_at).
    motor: Option<[f64; 8]>,
    #[serde(default = "one")]
    focal_length: f64,
    /// Image-plane width; default 2 (90° horizontal field of view with `f = 1`).
    x_max: Option<f64>,
    /// Image-plane height; default `x_max · height / width`.
    y_max: Option<f64>,
    width: u32,
    height: u32,
}

fn z_up() -> E3 {
    [0.0, 0.0, 1.0]
}

/// A circle for an evolved surface: Euclidean, or the original renderer's grade-3
/// coefficients in the orthonormal basis, order e123, e124, e125, e134, e135, e145, e234,
/// e235, e245, e345.
// Still parsed without the `evolved` feature, so that such objects get a clear error.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct CircleSpec {
    centre: Option<E3>,
    normal: Option<E3>,
    radius: Option<f64>,
    blade: Option<[f64; 10]>,
}

#[derive(Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) enum ObjectSpec {
    Sphere { name: Option<String>, material: Material, centre: E3, radius: f64 },
    Plane { name: Option<String>, material: Material, point: E3, normal: E3 },
    Disk { name: Option<String>, material: Material, centre: E3, normal: E3, radius: f64 },
    Triangle { name: Option<String>, material: Material, corners: [E3; 3] },
    Evolved { name: Option<String>, material: Material, c1: Box<CircleSpec>, c2: Box<CircleSpec> },
}

/// The camera in the frame centred on it (sized by `anchors`), and that frame.
pub(crate) fn build_camera(c: CameraSpec, anchors: Vec<E3>) -> Result<(Camera, Frame), Invalid> {
    let pose = match (c.motor, c.position, c.look_at) {
        (Some(m), None, None) => {
            let motor = Motor::from_array(m);
            motor.try_normalise().ok_or(Invalid::Value("the motor is zero"))?
        }
        (None, Some(p), Some(t)) => Camera::pose_look_at(p, t, c.up)?,
        _ => return Err(Invalid::Value("give either `motor`, or `position` and `look_at`")),
    };
    let x_max = c.x_max.unwrap_or(2.0);
    let y_max = c.y_max.unwrap_or(x_max * f64::from(c.height) / f64::from(c.width.max(1)));
    let world = Camera::new(pose, c.focal_length, x_max, y_max, c.width, c.height)?;
    let frame = Frame::around(world.position(), anchors);
    // In its own frame the camera only turns: M = T R, and R is M's scalar and e_jk parts.
    let turn = Rotor { s: pose.s, e12: pose.e12, e13: pose.e13, e23: pose.e23 };
    let turn = Motor::from(turn.try_normalise().ok_or(Invalid::Value("the motor has no rotation part"))?);
    let camera = Camera::new(turn, c.focal_length, x_max, y_max, c.width, c.height)?;
    Ok((camera, frame))
}

impl ObjectSpec {
    /// A point that places the object (for sizing the scene's frame), if it has one.
    pub(crate) fn anchor(&self) -> Option<E3> {
        match self {
            ObjectSpec::Sphere { centre, .. } | ObjectSpec::Disk { centre, .. } => Some(*centre),
            ObjectSpec::Plane { point, .. } => Some(*point),
            ObjectSpec::Triangle { corners, .. } => Some(corners[0]),
            ObjectSpec::Evolved { c1, .. } => c1.centre,
        }
    }
}

/// The object, built in `frame`, and its name (for errors).
pub(crate) fn build_object(
    spec: ObjectSpec,
    index: usize,
    method: Method,
    frame: &Frame,
) -> (Result<Object, Invalid>, String) {
    let name_of = |n: &Option<String>| n.clone().unwrap_or_else(|| format!("object {}", index + 1));
    let (name, material) = match &spec {
        ObjectSpec::Sphere { name, material, .. }
        | ObjectSpec::Plane { name, material, .. }
        | ObjectSpec::Disk { name, material, .. }
        | ObjectSpec::Triangle { name, material, .. }
        | ObjectSpec::Evolved { name, material, .. } => (name_of(name), *material),
    };
    let shape = || -> Result<Arc<dyn Shape>, Invalid> {
        material.check()?;
        let (at, length) = (|x| frame.point(x), |l| frame.length(l));
        Ok(match spec {
            ObjectSpec::Sphere { centre, radius, .. } => Arc::new(SphereShape::new(at(centre), length(radius))?),
            ObjectSpec::Plane { point, normal, .. } => Arc::new(PlaneShape::new(at(point), normal)?),
            ObjectSpec::Disk { centre, normal, radius, .. } => {
                Arc::new(DiskShape::new(at(centre), normal, length(radius))?)
            }
            ObjectSpec::Triangle { corners, .. } => Arc::new(TriangleShape::new(corners.map(at))?),
            #[cfg(feature = "evolved")]
            ObjectSpec::Evolved { c1, c2, .. } => Arc::new(evolved(*c1, *c2, method, frame)?),
            #[cfg(not(feature = "evolved"))]
            ObjectSpec::Evolved { .. } => {
                let _ = method;
                return Err(Invalid::NoEvolved);
            }
        })
    };
    (shape().map(|shape| Object { name: name.clone(), shape, material }), name)
}

/// An evolved surface, its circles built in the frame of [`EvolvedSurface::frame_origin`]
/// (inside `frame`).
#[cfg(feature = "evolved")]
fn evolved(c1: CircleSpec, c2: CircleSpec, method: Method, frame: &Frame) -> Result<EvolvedSurface, Invalid> {
    let on = |which| move |e| Invalid::Circle { which, reason: Box::new(e) };
    let (c1, n1, r1) = circle(c1, frame).map_err(on("c1"))?;
    let (c2, n2, r2) = circle(c2, frame).map_err(on("c2"))?;
    let origin = EvolvedSurface::frame_origin((c1, r1), (c2, r2));
    let local = |c: E3, n, r| cga_core::Circle::from_centre_normal_radius(cga_core::euclid::sub(c, origin), n, r);
    let c1 = local(c1, n1, r1).map_err(|e| on("c1")(e.into()))?;
    let c2 = local(c2, n2, r2).map_err(|e| on("c2")(e.into()))?;
    Ok(EvolvedSurface::in_frame(origin, c1, c2, method)?)
}

/// The orthonormal grade-3 blades, in the order scene files give them.
#[cfg(feature = "evolved")]
const BLADE_ORDER: [&str; 10] = ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"];

/// The centre, normal and radius of a circle spec, the centre and radius in `frame`. A blade
/// is read in world coordinates (where the file gives it) and then moved: its coefficients
/// carry the circle no better than `ε (|c|/r)²` there, which is what the file holds.
#[cfg(feature = "evolved")]
fn circle(spec: CircleSpec, frame: &Frame) -> Result<(E3, E3, f64), Invalid> {
    let (centre, normal, radius) = match spec {
        CircleSpec { blade: Some(b), centre: None, normal: None, radius: None } => {
            let mut dense = cga_core::Multivector::zero();
            for (name, value) in BLADE_ORDER.iter().zip(b) {
                let k = cga_core::Multivector::<f64>::BLADES
                    .iter()
                    .position(|x| x == name)
                    .ok_or(Invalid::Value("blade order"))?;
                dense.coeffs[k] = value;
            }
            let c = cga_core::Circle::from_dense(&dense)
                .try_normalise()
                .ok_or(Invalid::Value("the blade is zero or null"))?;
            c.centre_normal_radius()?
        }
        CircleSpec { blade: None, centre: Some(c), normal: Some(n), radius: Some(r) } => (c, n, r),
        _ => return Err(Invalid::Value("give either `blade`, or `centre`, `normal` and `radius`")),
    };
    Ok((frame.point(centre), normal, frame.length(radius)))
}
