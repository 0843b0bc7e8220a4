//! The scene file format (TOML, via serde): what each table and object may hold, and how a
//! parsed file becomes the camera, frame and shapes of a [`Scene`](crate::Scene).
//!
//! Unknown fields are errors; every number is checked where it is read (`numbers.rs`), so
//! that its error points at it. An object is one flat table (not a serde-tagged enum, which
//! would lose the position of every value inside it): its `type` decides which fields it
//! takes, and `build_object` builds it from them in the scene's [`Frame`], moved by its
//! `motor` or `transform` (`transform.rs`).

mod assets;
mod blade;
mod drawn;
mod error;
mod include;
mod instance;
mod load;
mod marks;
mod numbers;
mod sections;
mod specs;
mod transform;

pub(crate) use assets::Assets;
pub use error::SceneError;
pub use load::Source;
pub(crate) use specs::{MaterialRef, MaterialSpec, SettingsSpec};

use crate::camera::{Camera, CameraError, Lens};
use crate::drawing::Marks;
use crate::environment::Environment;
use crate::frame::Frame;
use crate::invalid::Invalid;
use crate::label::{Label, MAX_LABEL_CHARS};
use crate::light::{Light, Source as Emitter};
use crate::limits::{MAX_LIGHT_SAMPLES, MAX_OBJECTS, MAX_SIDE, MAX_TIME_SAMPLES};
use crate::object::Object;
use crate::shapes::{
    BoxShape, ConeShape, DiskShape, PlaneShape, Shading, Shape, SphereShape, TorusShape, TriangleShape,
};
use crate::shutter::Shutter;
use crate::surface::Method;
#[cfg(feature = "evolved")]
use crate::surface::{EvolvedSurface, RuledSurface, SplineSurface};
use blade::BladeSpec;
#[cfg(feature = "evolved")]
use cga_core::Circle;
#[cfg(feature = "evolved")]
use cga_core::Joining;
use cga_core::euclid::E3;
use cga_core::euclid::{norm, sub};
use cga_core::{GeometryError, Motor, Plane, circumcircle, circumsphere};
use marks::Parts;
use numbers::{Num, Nums, V3};
use serde::Deserialize;
use std::ops::Range;
use std::sync::Arc;
use toml::Spanned;
pub use transform::MAX_KEYS;
pub(crate) use transform::Placement;
use transform::{Step, motion_at, rigid, world_motor};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SceneFile {
    pub camera: Spanned<CameraSpec>,
    pub render: Option<Spanned<SettingsSpec>>,
    #[serde(default)]
    pub lights: Vec<Spanned<LightSpec>>,
    /// What rays leaving the scene see.
    pub environment: Option<Spanned<EnvironmentSpec>>,
    /// Named materials, `[materials.NAME]`, that objects give by name.
    #[serde(default)]
    pub materials: std::collections::BTreeMap<String, Spanned<MaterialSpec>>,
    /// Read one at a time by [`Scene::parse`](crate::Scene::parse), which takes the list out
    /// first; here only to report an `objects` that is not a list.
    #[serde(default, rename = "objects")]
    pub _objects: Vec<serde::de::IgnoredAny>,
}

/// A `[[lights]]` table: `position` (a point light), `direction` (a directional light: the
/// way its light travels), or both (a spot light shining along `direction`, full within
/// `radius` degrees of it and dark beyond `falloff`, as POV-Ray's `spotlight`), and a colour.
/// With `position`, `sphere = r` makes it a sphere of light of radius `r`, and `disk = r`
/// with `normal` a disk of light: area lights, `samples` of whose points light each hit.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LightSpec {
    position: Option<Spanned<V3>>,
    direction: Option<Spanned<V3>>,
    radius: Option<Spanned<Num>>,
    falloff: Option<Spanned<Num>>,
    colour: Option<Spanned<V3>>,
    sphere: Option<Spanned<Num>>,
    disk: Option<Spanned<Num>>,
    normal: Option<Spanned<V3>>,
    samples: Option<Spanned<u32>>,
}

/// `[environment]`: a gradient (`zenith`, `horizon`, `nadir`; the horizon's colour where
/// one is left out) or an equirectangular `image` turned by `rotate` degrees about `+z` and
/// scaled by `strength`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct EnvironmentSpec {
    zenith: Option<Spanned<V3>>,
    horizon: Option<Spanned<V3>>,
    nadir: Option<Spanned<V3>>,
    image: Option<Spanned<String>>,
    rotate: Option<Spanned<Num>>,
    strength: Option<Spanned<Num>>,
}

impl EnvironmentSpec {
    /// The environment, checked: colours and strength ≥ 0; a gradient or an image, not both.
    pub(crate) fn build(&self, assets: &Assets) -> Result<Environment, Invalid> {
        let why = |field, span: Range<usize>, reason| Invalid::at(field, span, Invalid::Value(reason));
        let gradient = first_given(&[("zenith", &self.zenith), ("horizon", &self.horizon), ("nadir", &self.nadir)]);
        for (field, colour) in [("zenith", &self.zenith), ("horizon", &self.horizon), ("nadir", &self.nadir)] {
            if let Some(c) = colour.as_ref().filter(|c| c.get_ref().0.iter().any(|&x| x < 0.0)) {
                return Err(why(field, c.span(), "an environment's colours must be ≥ 0"));
            }
        }
        match (&self.image, gradient) {
            (Some(file), None) => {
                let strength = self.strength.as_ref().map_or(1.0, |s| s.get_ref().0);
                if strength < 0.0 {
                    return Err(why("strength", self.strength.as_ref().expect("given").span(), "must be ≥ 0"));
                }
                let turn = self.rotate.as_ref().map_or(0.0, |r| r.get_ref().0).to_radians();
                Ok(Environment::Map { picture: assets.image(file, "environment image")?, turn, strength })
            }
            (None, Some(_)) => {
                if let Some((field, span)) = first_given(&[("rotate", &self.rotate), ("strength", &self.strength)]) {
                    return Err(why(field, span, "`rotate` and `strength` are an image's: give `image`"));
                }
                let colour = |c: &Option<Spanned<V3>>| c.as_ref().map(|c| c.get_ref().0);
                let horizon =
                    colour(&self.horizon).or(colour(&self.zenith)).or(colour(&self.nadir)).unwrap_or([0.0; 3]);
                let (zenith, nadir) = (colour(&self.zenith).unwrap_or(horizon), colour(&self.nadir).unwrap_or(horizon));
                Ok(Environment::Gradient { zenith, horizon, nadir })
            }
            (Some(file), Some((field, _))) => Err(why(field, file.span(), "give a gradient or an `image`, not both")),
            (None, None) => {
                Err(Invalid::Form("an [environment] takes `zenith`, `horizon`, `nadir` (a gradient) or an `image`"))
            }
        }
    }
}

/// Points of an area light that light each hit where a file gives no `samples`.
const AREA_SAMPLES: u32 = 16;

/// POV-Ray's spot light angles where a file gives none: full light within 30° of the axis,
/// none beyond 45°.
const SPOT_RADIUS: f64 = 30.0;
const SPOT_FALLOFF: f64 = 45.0;

impl LightSpec {
    /// The light in `frame`: colour non-negative; a point light's position one the frame
    /// holds; a directional light's direction not zero; a spot light's angles with
    /// `0 ≤ radius ≤ falloff ≤ 90` degrees.
    pub(crate) fn build(self, frame: &Frame) -> Result<Light, Invalid> {
        let colour = self.colour.as_ref().map_or([1.0; 3], |c| c.get_ref().0);
        if let Some(c) = self.colour.as_ref().filter(|_| colour.iter().any(|&c| c < 0.0)) {
            return Err(Invalid::at("colour", c.span(), Invalid::Value("a light's colour must be ≥ 0")));
        }
        if let Some(area) = self.area(frame)? {
            return Ok(Light { source: area, colour });
        }
        if (self.position.is_none() || self.direction.is_none())
            && let Some(a) = self.radius.as_ref().or(self.falloff.as_ref())
        {
            let why = Invalid::Value("`radius` and `falloff` are a spot light's: give it `position` and `direction`");
            return Err(Invalid::at(if self.radius.is_some() { "radius" } else { "falloff" }, a.span(), why));
        }
        let source = match (self.position, self.direction) {
            (Some(p), None) => Emitter::Point(light_position(&p, frame)?),
            (None, Some(d)) => {
                let unit = cga_core::euclid::unit(d.get_ref().0);
                Emitter::Directional(unit.ok_or(Invalid::at(
                    "direction",
                    d.span(),
                    GeometryError::ZeroVector.into(),
                ))?)
            }
            (Some(p), Some(d)) => {
                let position = light_position(&p, frame)?;
                let axis = cga_core::euclid::unit(d.get_ref().0);
                let axis = axis.ok_or(Invalid::at("direction", d.span(), GeometryError::ZeroVector.into()))?;
                let angle = |a: &Option<Spanned<Num>>, default| a.as_ref().map_or(default, |a| a.get_ref().0);
                let (radius, falloff) = (angle(&self.radius, SPOT_RADIUS), angle(&self.falloff, SPOT_FALLOFF));
                if !(0.0 < falloff && falloff <= 90.0 && 0.0 <= radius && radius <= falloff) {
                    // The radius when it is out of range or past the falloff, else the falloff.
                    let radius_wrong = self.radius.is_some() && !(0.0 <= radius && radius <= falloff && radius <= 90.0);
                    let (field, given) =
                        if radius_wrong { ("radius", &self.radius) } else { ("falloff", &self.falloff) };
                    let span = given.as_ref().or(self.radius.as_ref()).map_or(p.span(), |a| a.span());
                    let why = Invalid::Value("a spot light needs 0 ≤ radius ≤ falloff ≤ 90 degrees, falloff > 0");
                    return Err(Invalid::at(field, span, why));
                }
                let (cos_radius, cos_falloff) = (radius.to_radians().cos(), falloff.to_radians().cos());
                // A hard edge where the angles agree.
                let inverse_width = 1.0 / (cos_radius - cos_falloff).max(1e-12);
                Emitter::Spot { position, axis, cos_falloff, inverse_width }
            }
            (None, None) => {
                return Err(Invalid::Form(
                    "a light takes `position` (a point light), `direction` (a directional light), or both (a spot light)",
                ));
            }
        };
        Ok(Light { source, colour })
    }
}

impl LightSpec {
    /// The area light the table gives (`sphere` or `disk`), checked: a `position`, a radius
    /// `> 0` that the frame holds, a disk's non-zero `normal`, `1 ..= MAX_LIGHT_SAMPLES`
    /// samples; `None` for the other lights (which take none of these fields).
    fn area(&self, frame: &Frame) -> Result<Option<Emitter>, Invalid> {
        let at = |field, span: Range<usize>, why| Invalid::at(field, span, Invalid::Value(why));
        let radius = match (&self.sphere, &self.disk) {
            (Some(_), Some(d)) => return Err(at("disk", d.span(), "give `sphere` or `disk`, not both")),
            (Some(r), None) | (None, Some(r)) => r,
            (None, None) => {
                let stray = first_given(&[("normal", &self.normal), ("samples", &self.samples)]);
                return match stray {
                    Some((field, span)) => {
                        Err(at(field, span, "`normal` and `samples` are an area light's: give it `sphere` or `disk`"))
                    }
                    None => Ok(None),
                };
            }
        };
        let field = if self.sphere.is_some() { "sphere" } else { "disk" };
        let Some(p) = &self.position else {
            return Err(at(field, radius.span(), "an area light needs its centre as `position`"));
        };
        let spot = first_given(&[("direction", &self.direction), ("radius", &self.radius), ("falloff", &self.falloff)]);
        if let Some((field, span)) = spot {
            return Err(at(
                field,
                span,
                "an area light takes `position`, `sphere` or `disk` (its radius), `normal` (a disk's) and `samples`, not a spot light's `direction`, `radius` or `falloff`",
            ));
        }
        let r = frame.length(radius.get_ref().0);
        if !(r > 0.0 && Frame::holds(r)) {
            return Err(at(field, radius.span(), "an area light's radius must be > 0 and within the scene's range"));
        }
        let samples = self.samples.as_ref().map_or(AREA_SAMPLES, |n| *n.get_ref());
        if !(1..=MAX_LIGHT_SAMPLES).contains(&samples) {
            let span = self.samples.as_ref().expect("given").span();
            let why = Invalid::Limit {
                what: "samples of an area light",
                found: u64::from(samples),
                limit: u64::from(MAX_LIGHT_SAMPLES),
            };
            return Err(Invalid::at(
                "samples",
                span,
                if samples == 0 { Invalid::Value("an area light needs at least 1 sample") } else { why },
            ));
        }
        let centre = light_position(p, frame)?;
        Ok(Some(match (self.sphere.is_some(), &self.normal) {
            (true, None) => Emitter::Sphere { centre, radius: r, samples },
            (true, Some(n)) => return Err(at("normal", n.span(), "a sphere of light takes no `normal` (a disk does)")),
            (false, Some(n)) => {
                let normal = cga_core::euclid::unit(n.get_ref().0);
                let normal = normal.ok_or(Invalid::at("normal", n.span(), GeometryError::ZeroVector.into()))?;
                Emitter::Disk { centre, normal, radius: r, samples }
            }
            (false, None) => return Err(at("disk", radius.span(), "a disk of light needs its `normal`")),
        }))
    }
}

/// The first of the named fields that is given, and where.
fn first_given(fields: &[(&'static str, &dyn Given)]) -> Option<(&'static str, Range<usize>)> {
    fields.iter().find_map(|(name, f)| f.given().map(|span| (*name, span)))
}

/// An optional field's span where it is given.
trait Given {
    fn given(&self) -> Option<Range<usize>>;
}

impl<T> Given for Option<Spanned<T>> {
    fn given(&self) -> Option<Range<usize>> {
        self.as_ref().map(Spanned::span)
    }
}

impl Given for Option<Range<usize>> {
    fn given(&self) -> Option<Range<usize>> {
        self.clone()
    }
}

/// A point or spot light's position in `frame`. A light forms no conformal products: any
/// distance whose norm f64 holds (with room for the distances from points of the scene)
/// will do.
fn light_position(p: &Spanned<V3>, frame: &Frame) -> Result<E3, Invalid> {
    let x = frame.point(p.get_ref().0);
    let d = norm(x);
    if d.is_nan() || d > 1e300 {
        let why = format!(
            "the light is {:.1e} from the camera, more than f64 holds in units of the scene's size ({:.1e}): give it as `direction` (a light that far is a directional light)",
            norm(sub(p.get_ref().0, frame.origin)),
            frame.scale
        );
        return Err(Invalid::at("position", p.span(), Invalid::Range(why)));
    }
    Ok(x)
}

/// The camera: a pose (`position`, `look_at`, `up`, or a `motor`), focal length, image-plane
/// extents (or a horizontal field of view) and pixel size.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct CameraSpec {
    position: Option<V3>,
    look_at: Option<V3>,
    up: Option<V3>,
    /// Motor coefficients `s, e12, e13, e23, e1i, e2i, e3i, e123i` (instead of position/look_at).
    motor: Option<Spanned<Nums<8>>>,
    focal_length: Option<Spanned<Num>>,
    /// Image-plane width; default 2 (90° horizontal field of view with `f = 1`).
    x_max: Option<Spanned<Num>>,
    /// Image-plane height; default `x_max · height / width` (square pixels).
    y_max: Option<Spanned<Num>>,
    /// Horizontal field of view in degrees, instead of `x_max`: `x_max = 2 f tan(fov/2)`.
    fov: Option<Spanned<Num>>,
    /// Keyframe motors over the frame times 0 … 1, moving the pose (camera frame → world).
    motion: Option<Spanned<Vec<Spanned<Nums<8>>>>>,
    /// Pixels; may be left out when the caller gives the size (`--width` and `--height`).
    width: Option<Spanned<u32>>,
    height: Option<Spanned<u32>>,
    /// `"perspective"` (the default: eq. 2's pinhole, or a thin lens) or `"orthographic"`.
    projection: Option<Spanned<Projection>>,
    /// An orthographic view's width (world units); default what the perspective view shows at
    /// the `look_at` distance, `x_max d / f`.
    view_width: Option<Spanned<Num>>,
    /// A thin lens's radius (world units); 0 (the default) is the pinhole.
    aperture: Option<Spanned<Num>>,
    /// The distance of the plane of focus (world units); default the `look_at` distance.
    focus_distance: Option<Spanned<Num>>,
    /// The times, relative to the frame's, over which the shutter is open (motion blur).
    shutter: Option<Spanned<Nums<2>>>,
    /// The instants the shutter is sampled at; default the pixel samples (`spp`).
    time_samples: Option<Spanned<u32>>,
}

/// How the camera projects (`projection = "…"`).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum Projection {
    /// Rays through the camera's point (or its thin lens).
    #[default]
    Perspective,
    /// Parallel rays along the view axis.
    Orthographic,
}

impl CameraSpec {
    /// The camera in its own frame (it only turns there), checked; where it is in the world;
    /// and whether the file gives both image-plane extents (pixels then need not be square).
    /// The position is read from the pose's coefficients, never through a conformal point,
    /// so it is exact wherever the camera is.
    /// `size` stands in for `width` and `height` where the file gives neither; `time` is the
    /// frame time its `motion` is read at.
    pub(crate) fn build(self, size: Option<(u32, u32)>, time: f64) -> Result<BuiltCamera, Invalid> {
        let look_distance = match (&self.position, &self.look_at) {
            (Some(p), Some(t)) => Some(norm(sub(t.0, p.0))),
            _ => None,
        };
        let pose = match (&self.motor, self.position, self.look_at) {
            (Some(m), None, None) => rigid(m.get_ref().0).map_err(|e| Invalid::at("motor", m.span(), e))?,
            (None, Some(p), Some(t)) => Camera::pose_look_at(p.0, t.0, self.up.map_or([0.0, 0.0, 1.0], |u| u.0))?,
            _ => return Err(Invalid::Value("give either `motor`, or `position` and `look_at`")),
        };
        let position = match self.position {
            Some(p) => p.0,
            None => pose.translation(),
        };
        let (pose, position) = match &self.motion {
            Some(keys) => {
                let m = motion_at(keys, time)?;
                (m * pose, m.move_point(position))
            }
            None => (pose, position),
        };
        let pose = Motor::from(pose.rotor());
        let (width, height) = match (&self.width, &self.height, size) {
            (Some(w), Some(h), _) => (*w.get_ref(), *h.get_ref()),
            (None, None, Some(size)) => size,
            _ => {
                return Err(Invalid::Form(
                    "give the picture's `width` and `height` (or leave both out and give --width and --height)",
                ));
            }
        };
        let value = |x: &Option<Spanned<Num>>| x.as_ref().map(|x| x.get_ref().0);
        let focal = value(&self.focal_length).unwrap_or(1.0);
        let x_max = match (&self.x_max, &self.fov) {
            (Some(_), Some(fov)) => {
                return Err(Invalid::at("fov", fov.span(), Invalid::Value("give `x_max` or `fov`, not both")));
            }
            (None, Some(fov)) => {
                Camera::x_max_for_fov(focal, fov.get_ref().0).map_err(|e| Invalid::at("fov", fov.span(), e.into()))?
            }
            (x_max, None) => value(x_max).unwrap_or(2.0),
        };
        let pinned = self.y_max.is_some() && (self.x_max.is_some() || self.fov.is_some());
        let y_max = value(&self.y_max).unwrap_or(x_max * f64::from(height) / f64::from(width.max(1)));
        let camera = Camera::new(pose, focal, x_max, y_max, width, height).map_err(|e| match e {
            // Camera::new holds the size limit; the error points at the side that breaks it.
            CameraError::TooLarge { .. } => match (height > MAX_SIDE && width <= MAX_SIDE, &self.width, &self.height) {
                (true, _, Some(h)) => Invalid::at("height", h.span(), e.into()),
                (false, Some(w), _) => Invalid::at("width", w.span(), e.into()),
                _ => e.into(),
            },
            e => e.into(),
        })?;
        let lens = self.lens(&camera, look_distance)?;
        let shutter = self.shutter()?;
        Ok(BuiltCamera { camera, position, pinned, lens, shutter })
    }

    /// The lens the file gives, in world units, checked: orthographic with a positive view
    /// width, or a thin lens with aperture ≥ 0 and a positive focus distance (either
    /// defaulting to the `look_at` distance, which a camera placed by `motor` has not).
    fn lens(&self, camera: &Camera, look_distance: Option<f64>) -> Result<Lens, Invalid> {
        let projection = self.projection.as_ref().map_or(Projection::Perspective, |p| *p.get_ref());
        let positive = |field: &'static str, x: &Spanned<Num>, why: &'static str| {
            let v = x.get_ref().0;
            if v > 0.0 { Ok(v) } else { Err(Invalid::at(field, x.span(), Invalid::Value(why))) }
        };
        // The `look_at` distance, where a length is not given.
        let looked = || {
            look_distance.ok_or(Invalid::Value(
                "a camera placed by `motor` has no `look_at` distance: give `view_width` (orthographic) or `focus_distance` (a lens)",
            ))
        };
        match projection {
            Projection::Orthographic => {
                if let Some((field, span)) =
                    first_given(&[("aperture", &self.aperture), ("focus_distance", &self.focus_distance)])
                {
                    return Err(Invalid::at(
                        field,
                        span,
                        Invalid::Value("an orthographic camera has no lens: leave out `aperture` and `focus_distance`"),
                    ));
                }
                let width = match &self.view_width {
                    Some(w) => positive("view_width", w, "an orthographic view's width must be > 0")?,
                    None => looked()? * camera.x_max / camera.focal,
                };
                Ok(Lens::Orthographic { k: width / camera.x_max })
            }
            Projection::Perspective => {
                if let Some(w) = &self.view_width {
                    return Err(Invalid::at(
                        "view_width",
                        w.span(),
                        Invalid::Value(
                            "`view_width` is an orthographic camera's: give `projection = \"orthographic\"`",
                        ),
                    ));
                }
                let aperture = self.aperture.as_ref().map_or(0.0, |a| a.get_ref().0);
                if aperture < 0.0 {
                    let span = self.aperture.as_ref().expect("given").span();
                    return Err(Invalid::at(
                        "aperture",
                        span,
                        Invalid::Value("a lens's aperture (its radius) must be ≥ 0"),
                    ));
                }
                if aperture == 0.0 {
                    return Ok(Lens::Pinhole);
                }
                let focus = match &self.focus_distance {
                    Some(d) => positive("focus_distance", d, "the focus distance must be > 0")?,
                    None => looked()?,
                };
                Ok(Lens::Thin { aperture, focus })
            }
        }
    }

    /// The shutter the file gives: open ≤ close, instants 1 ..= MAX_TIME_SAMPLES.
    fn shutter(&self) -> Result<Option<Shutter>, Invalid> {
        let Some(given) = &self.shutter else {
            if let Some(n) = &self.time_samples {
                return Err(Invalid::at(
                    "time_samples",
                    n.span(),
                    Invalid::Value("`time_samples` samples a shutter: give `shutter = [open, close]`"),
                ));
            }
            return Ok(None);
        };
        let [open, close] = given.get_ref().0;
        if open.partial_cmp(&close).is_none_or(|o| o == std::cmp::Ordering::Greater) {
            return Err(Invalid::at(
                "shutter",
                given.span(),
                Invalid::Value("the shutter is [open, close] with open ≤ close"),
            ));
        }
        let samples = self.time_samples.as_ref().map(|n| *n.get_ref());
        if let Some(n) = samples.filter(|n| !(1..=MAX_TIME_SAMPLES).contains(n)) {
            let span = self.time_samples.as_ref().expect("given").span();
            const _: () = assert!(MAX_TIME_SAMPLES == 4096, "the message below names the limit");
            let why = match n {
                0 => Invalid::Value("a shutter is sampled at 1 or more instants: give 1 to 4096"),
                _ => Invalid::Limit { what: "time samples", found: u64::from(n), limit: u64::from(MAX_TIME_SAMPLES) },
            };
            return Err(Invalid::at("time_samples", span, why));
        }
        Ok(Some(Shutter { open, close, samples }))
    }
}

/// A camera as its table gives it: the camera (a pinhole, in its own frame), where it is in
/// the world, whether both image-plane extents are given, its lens in world units and its
/// shutter.
pub(crate) struct BuiltCamera {
    pub camera: Camera,
    pub position: E3,
    pub pinned: bool,
    pub lens: Lens,
    pub shutter: Option<Shutter>,
}

/// What an object is.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum Kind {
    Sphere,
    Plane,
    Disk,
    Torus,
    Cylinder,
    Cone,
    Box,
    Triangle,
    Mesh,
    Instance,
    Evolved,
    Spline,
    Ruled,
    Point,
    PointPair,
    Line,
    Circle,
    PlanePatch,
    Blade,
}

/// `p1`, `p2`: one point (a cylinder's or cone's end) or two (a ruled surface's point pair).
#[derive(Deserialize)]
#[serde(untagged, expecting = "a point [x, y, z], or for a ruled surface two points [[x, y, z], [x, y, z]]")]
pub(crate) enum Ends {
    One(V3),
    Two(Vec<V3>),
}

impl Ends {
    /// The points given.
    fn points(&self) -> &[V3] {
        match self {
            Ends::One(p) => std::slice::from_ref(p),
            Ends::Two(p) => p,
        }
    }
}

/// `N` points from an `Ends` field, or a count error at it.
fn ends<const N: usize>(field: &'static str, p: &Spanned<Ends>) -> Result<[E3; N], Invalid> {
    let given = p.get_ref().points();
    if given.len() != N || matches!((N, p.get_ref()), (1, Ends::Two(_))) {
        let reason = Invalid::Count { what: "points", expected: N, found: given.len() };
        return Err(Invalid::at(field, p.span(), reason));
    }
    Ok(std::array::from_fn(|k| given[k].0))
}

/// A line of a ruled surface: a point on it and its direction.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct LineSpec {
    point: V3,
    direction: V3,
}

/// A sphere bounding the rulings of a ruled surface of lines.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct BoundSpec {
    centre: V3,
    radius: Num,
}

/// How a spline surface joins its circles (`joining = "…"`).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum JoiningSpec {
    /// Consecutive circles joined two by two.
    #[default]
    Linear,
    /// Quadratic Bézier segments (2m + 1 circles).
    Quadratic,
    /// Cubic Bézier segments (3m + 1 circles).
    Cubic,
    /// Through every circle, C¹.
    CatmullRom,
    /// Through every circle, with `tension`, `bias`, `continuity`.
    KochanekBartels,
}

impl Kind {
    /// The geometry fields this kind takes, and how to say so.
    fn takes(self) -> (&'static [&'static str], &'static str) {
        match self {
            Kind::Sphere => {
                (&["centre", "radius", "points"], "a sphere takes `centre` and `radius`, or `points` (four)")
            }
            Kind::Plane => (&["point", "normal", "points"], "a plane takes `point` and `normal`, or `points` (three)"),
            Kind::Disk => (
                &["centre", "normal", "radius", "points"],
                "a disk takes `centre`, `normal` and `radius`, or `points` (three)",
            ),
            Kind::Torus => (
                &["centre", "normal", "radius", "tube"],
                "a torus takes `centre`, `normal`, `radius` (of its core circle) and `tube` (the tube's radius)",
            ),
            Kind::Cylinder => (
                &["p1", "p2", "radius", "caps"],
                "a cylinder takes its axis's ends `p1` and `p2` (one point each), `radius`, and `caps` (default true)",
            ),
            Kind::Cone => (
                &["p1", "r1", "p2", "r2", "caps"],
                "a cone takes its axis's ends `p1` and `p2` (one point each), their radii `r1` and `r2`, and `caps` (default true)",
            ),
            Kind::Box => (
                &["min", "max"],
                "a box takes its opposite corners `min` and `max` (turn it with `motor` or `transform`)",
            ),
            Kind::Triangle => (&["corners"], "a triangle takes `corners` (three points)"),
            Kind::Instance => (
                &[],
                "an instance takes `of` (an earlier object's name) and its own `motor`, `transform`, `motion`, `name`, `label` and `material`",
            ),
            Kind::Mesh => (
                &["file", "scale", "smooth"],
                "a mesh takes `file` (an .obj or .ply), `scale` (default 1) and `smooth` (its vertex normals, default true)",
            ),
            Kind::Evolved => (
                &["c1", "c2", "caps"],
                "an evolved surface takes `c1` and `c2`, and `caps` (its end disks, default false)",
            ),
            Kind::Ruled => (
                &["p1", "p2", "l1", "l2", "bound"],
                "a ruled surface takes point pairs `p1` and `p2` (two points each), or lines `l1` and `l2` ({ point, direction }) and a `bound` ({ centre, radius })",
            ),
            Kind::Spline => (
                &["circles", "joining", "tension", "bias", "continuity", "caps"],
                "a spline surface takes `circles`, `joining`, for joining = \"kochanek-bartels\" `tension`, `bias`, `continuity`, and `caps` (the end circles' disks, default false)",
            ),
            Kind::Point => (&["point", "size"], "a point takes `point` and optionally `size` (its ball's radius)"),
            Kind::PointPair => (
                &["points", "size", "segment", "tube"],
                "a point pair takes `points` (two), optionally `size`, and `segment = true` (with its `tube`) to draw the segment",
            ),
            Kind::Line => (
                &["point", "direction", "tube"],
                "a line takes `point` and `direction`, and optionally `tube` (its cylinder's radius)",
            ),
            Kind::Circle => (
                &["centre", "normal", "radius", "points", "blade", "tube"],
                "a circle takes `centre`, `normal` and `radius`, or `points` (three), or `blade`; optionally `tube`",
            ),
            Kind::PlanePatch => (
                &["point", "normal", "points", "size"],
                "a plane patch takes `point` and `normal`, or `points` (three), and optionally `size` (its radius)",
            ),
            Kind::Blade => (
                &["blade", "size", "tube", "segment"],
                "a blade takes `blade`, its coefficients by blade name ({ e1 = 1.0, eo = 1.0, … }), and optionally `size`, `tube`, `segment`",
            ),
        }
    }
}

/// One `[[objects]]` table. Which geometry fields it needs depends on `type` ([`Kind::takes`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct ObjectSpec {
    #[serde(rename = "type")]
    kind: Kind,
    name: Option<String>,
    label: Option<Spanned<String>>,
    material: Spanned<MaterialRef>,
    centre: Option<Spanned<V3>>,
    radius: Option<Spanned<Num>>,
    tube: Option<Spanned<Num>>,
    size: Option<Spanned<Num>>,
    direction: Option<Spanned<V3>>,
    segment: Option<Spanned<bool>>,
    blade: Option<Spanned<BladeSpec>>,
    min: Option<Spanned<V3>>,
    max: Option<Spanned<V3>>,
    normal: Option<Spanned<V3>>,
    point: Option<Spanned<V3>>,
    corners: Option<Spanned<Vec<V3>>>,
    points: Option<Spanned<Vec<V3>>>,
    /// A mesh's file, relative to the scene's folder.
    file: Option<Spanned<String>>,
    /// A mesh's uniform scale about the file's origin, before its motor.
    scale: Option<Spanned<Num>>,
    /// Whether a mesh is shaded by its vertex normals (where the file gives them).
    smooth: Option<Spanned<bool>>,
    c1: Option<Spanned<CircleSpec>>,
    c2: Option<Spanned<CircleSpec>>,
    circles: Option<Spanned<Vec<Spanned<CircleSpec>>>>,
    p1: Option<Spanned<Ends>>,
    p2: Option<Spanned<Ends>>,
    r1: Option<Spanned<Num>>,
    r2: Option<Spanned<Num>>,
    caps: Option<Spanned<bool>>,
    l1: Option<Spanned<LineSpec>>,
    l2: Option<Spanned<LineSpec>>,
    bound: Option<Spanned<BoundSpec>>,
    joining: Option<Spanned<JoiningSpec>>,
    tension: Option<Spanned<Num>>,
    bias: Option<Spanned<Num>>,
    continuity: Option<Spanned<Num>>,
    motor: Option<Spanned<Nums<8>>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
    /// Keyframe motors over the frame times 0 … 1, applied after `motor`/`transform`.
    motion: Option<Spanned<Vec<Spanned<Nums<8>>>>>,
    /// Drawn only as instances ([`instance`]).
    template: Option<Spanned<bool>>,
    /// The frame time the object is built at (not in the file: the scene's).
    #[serde(skip)]
    pub(crate) time: f64,
    /// An instance's motor, applied after the object's own (not in the file).
    #[serde(skip)]
    pub(crate) outer: Option<Motor>,
}

/// A circle for an evolved surface: Euclidean, through three points, or the original
/// renderer's grade-3 coefficients in the orthonormal basis (order e123, e124, e125, e134,
/// e135, e145, e234, e235, e245, e345); optionally moved.
// Still parsed without the `evolved` feature, so that such objects get a clear error.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[cfg_attr(not(feature = "evolved"), allow(dead_code))]
pub(crate) struct CircleSpec {
    centre: Option<V3>,
    normal: Option<V3>,
    radius: Option<Num>,
    points: Option<Spanned<Vec<V3>>>,
    blade: Option<Nums<10>>,
    motor: Option<Spanned<Nums<8>>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
}

/// The point of the plane through `p` of unit normal `n` nearest the origin, `n (n · p)`.
fn foot(p: E3, n: E3) -> E3 {
    let d = cga_core::euclid::dot(n, p);
    n.map(|x| x * d)
}

/// `N` points from a `points` or `corners` field, in world coordinates.
fn points<const N: usize>(field: &'static str, p: &Spanned<Vec<V3>>) -> Result<[E3; N], Invalid> {
    let given = p.get_ref();
    if given.len() != N {
        let reason = Invalid::Count { what: "points", expected: N, found: given.len() };
        return Err(Invalid::at(field, p.span(), reason));
    }
    Ok(std::array::from_fn(|k| given[k].0))
}

impl ObjectSpec {
    /// Where the object is and how large, in world coordinates, for sizing the scene's frame:
    /// a point of it (moved by its motor) and its extent (a radius, or the spread of its
    /// points; 0 for a plane), if the file says; `None` for what only a blade gives.
    pub(crate) fn extent(&self, assets: &Assets) -> Option<(E3, f64)> {
        let spread = |p: &[V3]| p.iter().map(|x| norm(sub(x.0, p[0].0))).fold(0.0, f64::max);
        // A torus reaches its tube's radius beyond its core circle's.
        let tube = self.tube.as_ref().map_or(0.0, |r| r.get_ref().0);
        let radius = self.radius.as_ref().map_or(0.0, |r| r.get_ref().0) + tube;
        let circle = |c: &CircleSpec| c.centre.map(|x| (x.0, c.radius.map_or(0.0, |r| r.0)));
        let size = self.size.as_ref().map_or(0.0, |s| s.get_ref().0);
        let (point, extent) = if let Some(drawn) = self.drawn_extent() {
            drawn?
        } else if let (Kind::Mesh, Some(file)) = (self.kind, &self.file) {
            let (c, r) = assets.mesh_bounds(file).ok()??;
            let s = self.mesh_scale().ok()?;
            (c.map(|x| x * s), r * s)
        } else if self.kind == Kind::Plane {
            let p =
                self.point.as_ref().map(|p| p.get_ref().0).or_else(|| Some(self.points.as_ref()?.get_ref().first()?.0));
            let (p, n) = (p?, self.normal.as_ref().and_then(|n| cga_core::euclid::unit(n.get_ref().0)));
            (n.map_or(p, |n| foot(p, n)), f64::INFINITY)
        } else if let Some(c) = self.centre.as_ref().or(self.point.as_ref()) {
            (c.get_ref().0, radius + size)
        } else if let (Some(lo), Some(hi)) = (&self.min, &self.max) {
            let (lo, hi) = (lo.get_ref().0, hi.get_ref().0);
            ([0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k])), 0.5 * norm(sub(hi, lo)))
        } else if let (Kind::Cylinder | Kind::Cone, Some(p1), Some(p2)) = (self.kind, &self.p1, &self.p2) {
            let (a, b) = (p1.get_ref().points().first()?.0, p2.get_ref().points().first()?.0);
            let r = |x: &Option<Spanned<Num>>| x.as_ref().map_or(0.0, |r| r.get_ref().0);
            (a, norm(sub(b, a)) + radius.max(r(&self.r1)).max(r(&self.r2)))
        } else if let Some(p) = self.points.as_ref().or(self.corners.as_ref()) {
            (p.get_ref().first()?.0, spread(p.get_ref()))
        } else if let Some(p) = &self.p1 {
            (p.get_ref().points().first()?.0, spread(p.get_ref().points()))
        } else if let Some(b) = &self.bound {
            (b.get_ref().centre.0, b.get_ref().radius.0)
        } else if let Some(c) = &self.c1 {
            let (x, r) = circle(c.get_ref())?;
            let r2 = self.c2.as_ref().and_then(|c| circle(c.get_ref())).map_or(0.0, |(y, r2)| r2 + norm(sub(x, y)));
            (x, r.max(r2))
        } else {
            let circles = self.circles.as_ref()?.get_ref();
            let (x, r) = circle(circles.first()?.get_ref())?;
            let far = circles.iter().filter_map(|c| circle(c.get_ref())).map(|(y, r)| r + norm(sub(x, y)));
            (x, far.fold(r, f64::max))
        };
        let motor = self.world_motor().ok().flatten();
        Some((motor.map_or(point, |m| m.move_point(point)), extent))
    }

    /// The object's world motor at its frame time: its `motor` or `transform`, then its
    /// `motion` at that time, then an instance's motor.
    fn world_motor(&self) -> Result<Option<Motor>, Invalid> {
        let own = world_motor(self.motor.as_ref(), self.transform.as_ref())?;
        let moved = match &self.motion {
            Some(keys) => Some(motion_at(keys, self.time)? * own.unwrap_or(Motor::identity())),
            None => own,
        };
        Ok(match (self.outer, moved) {
            (Some(outer), Some(m)) => Some(outer * m),
            (outer, m) => outer.or(m),
        })
    }

    /// [`ObjectSpec::extent`] of an object as parsed, read from its placement fields alone
    /// (what else it holds is checked when it is built), and the triangles its mesh file adds
    /// (what else it holds is checked when it is built).
    pub(crate) fn extent_of(
        value: &Spanned<toml::de::DeValue<'_>>,
        time: f64,
        outer: Option<Motor>,
        assets: &Assets,
    ) -> Result<(Option<(E3, f64)>, usize), toml::de::Error> {
        use serde::de::IntoDeserializer;
        const READ: [&str; 28] = [
            "type",
            "file",
            "scale",
            "motion",
            "normal",
            "direction",
            "segment",
            "size",
            "blade",
            "material",
            "centre",
            "point",
            "radius",
            "tube",
            "min",
            "max",
            "p2",
            "r1",
            "r2",
            "points",
            "corners",
            "p1",
            "bound",
            "c1",
            "c2",
            "circles",
            "motor",
            "transform",
        ];
        let toml::de::DeValue::Table(table) = value.get_ref() else { return Ok((None, 0)) };
        let mut placement = toml::de::DeTable::new();
        for (key, v) in table.iter().filter(|(k, _)| READ.contains(&k.get_ref().as_ref())) {
            placement.insert(key.clone(), v.clone());
        }
        let table = Spanned::new(value.span(), toml::de::DeValue::Table(placement));
        let mut spec = ObjectSpec::deserialize(table.into_deserializer())?;
        (spec.time, spec.outer) = (time, outer);
        Ok((spec.extent(assets), spec.mesh_triangles(assets).unwrap_or(0)))
    }

    /// The geometry fields given, with their spans.
    fn given(&self) -> Vec<(&'static str, Range<usize>)> {
        let span = |name, s: Option<Range<usize>>| s.map(|s| (name, s));
        [
            span("centre", self.centre.as_ref().map(Spanned::span)),
            span("radius", self.radius.as_ref().map(Spanned::span)),
            span("tube", self.tube.as_ref().map(Spanned::span)),
            span("size", self.size.as_ref().map(Spanned::span)),
            span("direction", self.direction.as_ref().map(Spanned::span)),
            span("segment", self.segment.as_ref().map(Spanned::span)),
            span("blade", self.blade.as_ref().map(Spanned::span)),
            span("min", self.min.as_ref().map(Spanned::span)),
            span("max", self.max.as_ref().map(Spanned::span)),
            span("r1", self.r1.as_ref().map(Spanned::span)),
            span("r2", self.r2.as_ref().map(Spanned::span)),
            span("caps", self.caps.as_ref().map(Spanned::span)),
            span("normal", self.normal.as_ref().map(Spanned::span)),
            span("point", self.point.as_ref().map(Spanned::span)),
            span("corners", self.corners.as_ref().map(Spanned::span)),
            span("points", self.points.as_ref().map(Spanned::span)),
            span("file", self.file.as_ref().map(Spanned::span)),
            span("scale", self.scale.as_ref().map(Spanned::span)),
            span("smooth", self.smooth.as_ref().map(Spanned::span)),
            span("c1", self.c1.as_ref().map(Spanned::span)),
            span("c2", self.c2.as_ref().map(Spanned::span)),
            span("circles", self.circles.as_ref().map(Spanned::span)),
            span("p1", self.p1.as_ref().map(Spanned::span)),
            span("p2", self.p2.as_ref().map(Spanned::span)),
            span("l1", self.l1.as_ref().map(Spanned::span)),
            span("l2", self.l2.as_ref().map(Spanned::span)),
            span("bound", self.bound.as_ref().map(Spanned::span)),
            span("joining", self.joining.as_ref().map(Spanned::span)),
            span("tension", self.tension.as_ref().map(Spanned::span)),
            span("bias", self.bias.as_ref().map(Spanned::span)),
            span("continuity", self.continuity.as_ref().map(Spanned::span)),
        ]
        .into_iter()
        .flatten()
        .collect()
    }

    /// A geometry error about one field, placed at that field when the object gives it.
    fn locate(&self, e: Invalid) -> Invalid {
        use cga_core::GeometryError as G;
        let field = match &e {
            Invalid::Geometry(G::ZeroRadius) => "radius",
            Invalid::Geometry(G::ZeroVector) => "normal",
            Invalid::Geometry(G::CoincidentPoints | G::CollinearPoints | G::CoplanarPoints)
                if self.points.is_some() =>
            {
                "points"
            }
            Invalid::Geometry(G::CoincidentPoints) if matches!(self.kind, Kind::Cylinder | Kind::Cone) => "p2",
            Invalid::Geometry(G::CoincidentPoints | G::CollinearPoints) => "corners",
            _ => return e,
        };
        match self.given().into_iter().find(|(f, _)| *f == field) {
            Some((field, span)) => Invalid::at(field, span, e),
            None => e,
        }
    }

    /// The shapes, in `frame` (one but for drawings), with errors placed at their field
    /// ([`ObjectSpec::locate`]).
    fn shapes(&self, method: Method, frame: &Frame, marks: &Marks, assets: &Assets) -> Result<Parts, Invalid> {
        self.build(method, frame, marks, assets).map_err(|e| self.locate(e))
    }

    /// The shape, in `frame`: fields checked against the kind, its Euclidean data (made from
    /// points, if given so, in world coordinates) moved by its motor into the frame, built.
    fn build(&self, method: Method, frame: &Frame, marks: &Marks, assets: &Assets) -> Result<Parts, Invalid> {
        let (takes, says) = self.kind.takes();
        if let Some((field, span)) = self.given().into_iter().find(|(f, _)| !takes.contains(f)) {
            return Err(Invalid::at(field, span, Invalid::Form(says)));
        }
        let place = Placement::new(self.world_motor()?, frame);
        let v = |x: &Option<Spanned<V3>>| x.as_ref().map(|x| x.get_ref().0);
        let (centre, normal, point) = (v(&self.centre), v(&self.normal), v(&self.point));
        let radius = self.radius.as_ref().map(|r| r.get_ref().0);
        let form = || Invalid::Form(says);
        let shape: Arc<dyn Shape> = match self.kind {
            Kind::Sphere => {
                let (c, r) = match (centre, radius, &self.points) {
                    (Some(c), Some(r), None) => (c, r),
                    (None, None, Some(p)) => {
                        let [a, b, c, d] = points("points", p)?;
                        let (c, r, _) = circumsphere(a, b, c, d)?;
                        (c, r)
                    }
                    _ => return Err(form()),
                };
                let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|a| place.direction(a));
                Arc::new(SphereShape::new(place.point(c)?, place.length(r))?.with_axes(axes))
            }
            Kind::Plane => {
                let (p, n) = match (point, normal, &self.points) {
                    (Some(p), Some(n), None) => (p, n),
                    (None, None, Some(p)) => {
                        let [a, b, c] = points("points", p)?;
                        let (n, _) = Plane::through(a, b, c)?.normal_offset()?;
                        (a, n)
                    }
                    _ => return Err(form()),
                };
                let (foot, n) = place.plane(p, n)?;
                // The texture's origin is the point given, where the frame holds it.
                let anchor = place.point(p).unwrap_or(foot);
                Arc::new(PlaneShape { anchor, ..PlaneShape::new(foot, n)? })
            }
            Kind::Disk => {
                let (c, n, r) = match (centre, normal, radius, &self.points) {
                    (Some(c), Some(n), Some(r), None) => (c, n, r),
                    (None, None, None, Some(p)) => {
                        let [a, b, c] = points("points", p)?;
                        circumcircle(a, b, c)?
                    }
                    _ => return Err(form()),
                };
                Arc::new(DiskShape::new(place.point(c)?, place.direction(n), place.length(r))?)
            }
            Kind::Torus => {
                let (Some(c), Some(n), Some(r), Some(tube)) = (centre, normal, radius, self.tube.as_ref()) else {
                    return Err(form());
                };
                if !(tube.get_ref().0 > 0.0 && tube.get_ref().0.is_finite()) {
                    return Err(Invalid::at("tube", tube.span(), Invalid::Value("the tube's radius must be positive")));
                }
                TorusShape::new(c, n, r, tube.get_ref().0)?;
                let (c, n, r, tube) =
                    (place.point(c)?, place.direction(n), place.length(r), place.length(tube.get_ref().0));
                Arc::new(TorusShape::new(c, n, r, tube)?)
            }
            Kind::Cylinder | Kind::Cone => {
                let (Some(a), Some(b)) = (&self.p1, &self.p2) else { return Err(form()) };
                let num = |x: &Option<Spanned<Num>>| x.as_ref().map(|r| r.get_ref().0);
                let (r1, r2) = match self.kind {
                    Kind::Cylinder => (radius.ok_or_else(form)?, radius.ok_or_else(form)?),
                    _ => (num(&self.r1).ok_or_else(form)?, num(&self.r2).ok_or_else(form)?),
                };
                let ([a], [b]) = (ends("p1", a)?, ends("p2", b)?);
                let caps = self.caps.as_ref().is_none_or(|c| *c.get_ref());
                ConeShape::new(a, r1, b, r2, caps)?;
                let (a, b) = (place.point(a)?, place.point(b)?);
                Arc::new(ConeShape::new(a, place.length(r1), b, place.length(r2), caps)?)
            }
            Kind::Box => {
                let (Some(lo), Some(hi)) = (v(&self.min), self.max.as_ref()) else { return Err(form()) };
                let box_ = BoxShape::between(lo, hi.get_ref().0).map_err(|e| match e {
                    GeometryError::ZeroRadius => {
                        Invalid::at("max", hi.span(), Invalid::Value("`max` must exceed `min` on every axis"))
                    }
                    e => e.into(),
                })?;
                let axes = box_.axes.map(|a| place.direction(a));
                let half = box_.half.map(|h| place.length(h));
                Arc::new(BoxShape::new(half, place.point(box_.centre)?, axes)?)
            }
            Kind::Triangle => {
                let corners = self.corners.as_ref().ok_or_else(form)?;
                let corners: [E3; 3] = points("corners", corners)?;
                // Checked as given: corners that coincide only after the move are a scale
                // problem (`Range`), not the user's.
                TriangleShape::new(corners)?;
                let [a, b, c] = corners;
                Arc::new(TriangleShape::new([place.point(a)?, place.point(b)?, place.point(c)?])?)
            }
            Kind::Mesh => return Ok((self.mesh(&place, assets)?, None)),
            Kind::Instance => return Err(form()),
            #[cfg(feature = "evolved")]
            Kind::Evolved => match (&self.c1, &self.c2) {
                (Some(c1), Some(c2)) => {
                    let surface: Arc<dyn Shape> = Arc::new(evolved(c1, c2, &place, method)?);
                    return Ok((self.capped(surface, [c1, c2], &place)?, None));
                }
                _ => return Err(form()),
            },
            #[cfg(feature = "evolved")]
            Kind::Spline => {
                let surface: Arc<dyn Shape> = Arc::new(self.spline(&place, method)?);
                let ends = self.circles.as_ref().and_then(|c| Some([c.get_ref().first()?, c.get_ref().last()?]));
                return Ok((self.capped(surface, ends.ok_or_else(form)?, &place)?, None));
            }
            #[cfg(feature = "evolved")]
            Kind::Ruled => Arc::new(self.ruled(&place)?),
            #[cfg(not(feature = "evolved"))]
            Kind::Evolved | Kind::Spline | Kind::Ruled => {
                let _ = method;
                return Err(Invalid::NoEvolved);
            }
            Kind::Point | Kind::PointPair | Kind::Line | Kind::Circle | Kind::PlanePatch | Kind::Blade => {
                let drawing = self.drawing(&marks.sizes)?;
                return marks::parts(
                    &drawing,
                    &place,
                    frame.point(marks.sizes.centre),
                    place.length(marks.view(&drawing)),
                );
            }
        };
        Ok((vec![shape], None))
    }
}

impl ObjectSpec {
    /// A mesh's scale, checked: finite and > 0.
    fn mesh_scale(&self) -> Result<f64, Invalid> {
        match &self.scale {
            Some(s) if !(s.get_ref().0 > 0.0 && s.get_ref().0.is_finite()) => {
                Err(Invalid::at("scale", s.span(), Invalid::Value("a mesh's scale must be finite and > 0")))
            }
            s => Ok(s.as_ref().map_or(1.0, |s| s.get_ref().0)),
        }
    }

    /// Whether the object is a mesh whose triangles close a solid.
    /// The object's name, or `object N` (1-based `index`) where it has none.
    pub(crate) fn name_or(&self, index: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("object {}", index + 1))
    }

    /// The triangles a mesh object will add to the scene, known from its file before any is
    /// placed (so that instances past the limit of shapes are refused before they are built).
    pub(crate) fn mesh_triangles(&self, assets: &Assets) -> Option<usize> {
        match (self.kind, &self.file) {
            (Kind::Mesh, Some(file)) => assets.mesh(file).ok().map(|m| m.triangles.len()),
            _ => None,
        }
    }

    fn is_closed_mesh(&self, assets: &Assets) -> Result<bool, Invalid> {
        match (self.kind, &self.file) {
            (Kind::Mesh, Some(file)) => assets.mesh_is_closed(file),
            _ => Ok(false),
        }
    }

    /// A mesh's triangles, scaled, moved by `place`, with the file's normals (turned) and
    /// texture coordinates. Triangles without area (in the file, or once placed) are left
    /// out: no ray sees them; a mesh left with none (or with no triangles) is refused.
    fn mesh(&self, place: &Placement, assets: &Assets) -> Result<Vec<Arc<dyn Shape>>, Invalid> {
        let file = self.file.as_ref().ok_or(Invalid::Form(Kind::Mesh.takes().1))?;
        let mesh = assets.mesh(file)?;
        let s = self.mesh_scale()?;
        if mesh.triangles.len() > MAX_OBJECTS {
            let many =
                Invalid::Limit { what: "triangles", found: mesh.triangles.len() as u64, limit: MAX_OBJECTS as u64 };
            return Err(Invalid::at("file", file.span(), many));
        }
        let smooth = self.smooth.as_ref().is_none_or(|s| *s.get_ref());
        let mut shapes: Vec<Arc<dyn Shape>> = Vec::with_capacity(mesh.triangles.len());
        let mut flat_in_file = 0;
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize].map(|x| x * s));
            if TriangleShape::new([a, b, c]).is_err() {
                flat_in_file += 1;
                continue;
            }
            let corner = |i: u32| i as usize;
            let shading = Shading {
                normals: mesh.normals.as_ref().filter(|_| smooth).map(|n| t.map(|i| place.direction(n[corner(i)]))),
                uvs: mesh.uvs.as_ref().map(|uv| t.map(|i| uv[corner(i)])),
            };
            // A sliver that placing far out makes flat is lost to rounding: no ray sees it.
            let Ok(triangle) = TriangleShape::new([place.point(a)?, place.point(b)?, place.point(c)?]) else {
                continue;
            };
            shapes.push(Arc::new(
                triangle.with_shading(shading).map_err(|e| Invalid::at("file", file.span(), e.into()))?,
            ));
        }
        if shapes.is_empty() {
            let why = if flat_in_file == mesh.triangles.len() {
                "no triangle of the mesh has an area: nothing to see"
            } else {
                "no triangle of the mesh has an area f64 can hold at this scale and place"
            };
            return Err(Invalid::at("file", file.span(), Invalid::Value(why)));
        }
        Ok(shapes)
    }
}

#[cfg(feature = "evolved")]
impl ObjectSpec {
    /// A swept surface and, with `caps = true`, the disks of its end circles.
    fn capped(
        &self,
        surface: Arc<dyn Shape>,
        ends: [&Spanned<CircleSpec>; 2],
        place: &Placement,
    ) -> Result<Vec<Arc<dyn Shape>>, Invalid> {
        let mut shapes = vec![surface];
        if self.caps.as_ref().is_some_and(|c| *c.get_ref()) {
            for end in ends {
                let (c, n, r) = circle(end.get_ref(), place).map_err(|e| Invalid::at("caps", end.span(), e))?;
                shapes.push(Arc::new(DiskShape::new(c, n, r)?));
            }
        }
        Ok(shapes)
    }

    /// A spline surface through `circles`, each moved by its own transform and then by the
    /// object's (`place`).
    fn spline(&self, place: &Placement, method: Method) -> Result<SplineSurface, Invalid> {
        let form = || Invalid::Form(Kind::Spline.takes().1);
        let circles = self.circles.as_ref().ok_or_else(form)?;
        let joining = self.joining.as_ref().map_or(JoiningSpec::Linear, |j| *j.get_ref());
        let parameter = |p: &Option<Spanned<Num>>| p.as_ref().map(|p| p.get_ref().0);
        let (tension, bias, continuity) =
            (parameter(&self.tension), parameter(&self.bias), parameter(&self.continuity));
        if joining != JoiningSpec::KochanekBartels
            && let Some((field, span)) =
                self.given().into_iter().find(|(f, _)| ["tension", "bias", "continuity"].contains(f))
        {
            return Err(Invalid::at(
                field,
                span,
                Invalid::Value("tension, bias and continuity need joining = \"kochanek-bartels\""),
            ));
        }
        let joining = match joining {
            JoiningSpec::Linear => Joining::Linear,
            JoiningSpec::Quadratic => Joining::Quadratic,
            JoiningSpec::Cubic => Joining::Cubic,
            JoiningSpec::CatmullRom => Joining::CATMULL_ROM,
            JoiningSpec::KochanekBartels => Joining::KochanekBartels {
                tension: tension.unwrap_or(0.0),
                bias: bias.unwrap_or(0.0),
                continuity: continuity.unwrap_or(0.0),
            },
        };
        let mut built = Vec::with_capacity(circles.get_ref().len());
        for (k, c) in circles.get_ref().iter().enumerate() {
            let reason = |e| {
                Invalid::at("circles", c.span(), Invalid::Indexed { what: "circle", index: k + 1, reason: Box::new(e) })
            };
            built.push(circle(c.get_ref(), place).map_err(reason)?);
        }
        Ok(SplineSurface::new(&built, joining, method)?)
    }
}

#[cfg(feature = "evolved")]
impl ObjectSpec {
    /// A ruled surface of point pairs or of lines, moved into the frame by `place`, in a local
    /// frame at the mean of its defining points.
    fn ruled(&self, place: &Placement) -> Result<RuledSurface, Invalid> {
        let form = || Invalid::Form(Kind::Ruled.takes().1);
        let surface = match (&self.p1, &self.p2, &self.l1, &self.l2, &self.bound) {
            (Some(p1), Some(p2), None, None, None) => {
                let (p1, p2): ([E3; 2], [E3; 2]) = (ends("p1", p1)?, ends("p2", p2)?);
                let (p1, p2) = ([place.point(p1[0])?, place.point(p1[1])?], [place.point(p2[0])?, place.point(p2[1])?]);
                let origin = [0, 1, 2].map(|k| (p1[0][k] + p1[1][k] + p2[0][k] + p2[1][k]) / 4.0);
                let local = |x: E3| sub(x, origin);
                RuledSurface::point_pairs(origin, p1.map(local), p2.map(local))?
            }
            (None, None, Some(l1), Some(l2), Some(bound)) => {
                let (l1, l2, b) = (l1.get_ref(), l2.get_ref(), bound.get_ref());
                let origin = place.point(b.centre.0)?;
                let line = |l: &LineSpec| -> Result<(E3, E3), Invalid> {
                    Ok((sub(place.point(l.point.0)?, origin), place.direction(l.direction.0)))
                };
                let radius = place.length(b.radius.0);
                if radius <= 0.0 {
                    return Err(Invalid::at(
                        "bound",
                        bound.span(),
                        Invalid::Value("the bound's radius must be positive"),
                    ));
                }
                RuledSurface::lines(origin, line(l1)?, line(l2)?, ([0.0; 3], radius))?
            }
            _ => return Err(form()),
        };
        Ok(surface)
    }
}

/// An object's parts and its label.
pub(crate) type Built = (Vec<Object>, Option<Label>);

/// The object, built in `frame` (a drawing's parts as objects of one name), its label if it
/// has one, and its name (for errors, control characters escaped).
pub(crate) fn build_object(
    spec: ObjectSpec,
    index: usize,
    method: Method,
    frame: &Frame,
    marks: &Marks,
    assets: &Assets,
) -> (Result<Built, Invalid>, String) {
    let name = spec.name_or(index);
    let shown = name.escape_debug().to_string();
    let built = assets.resolve(&spec.material).and_then(|(material, texture)| {
        let (shapes, anchor) = spec.shapes(method, frame, marks, assets)?;
        let label = spec.label(&shapes, anchor, material.colour)?;
        // A closed glass mesh is one solid: light enters at one triangle and leaves at another.
        let solid = (material.dielectric() && spec.is_closed_mesh(assets)?).then_some(index);
        let name: std::sync::Arc<str> = name.as_str().into();
        let object =
            |shape| Object { name: name.clone(), shape, material, texture: texture.clone(), solid, moving: false };
        let objects = shapes.into_iter().map(object).collect();
        Ok((objects, label))
    });
    (built, shown)
}

impl ObjectSpec {
    /// The object's label, beside `anchor` if given, else the sphere holding its `shapes`;
    /// refused for an unbounded object (a plane: label a `plane-patch`) or past
    /// [`MAX_LABEL_CHARS`].
    fn label(
        &self,
        shapes: &[Arc<dyn Shape>],
        anchor: Option<(E3, f64)>,
        colour: [f64; 3],
    ) -> Result<Option<Label>, Invalid> {
        let Some(text) = &self.label else { return Ok(None) };
        let at = |reason| Invalid::at("label", text.span(), reason);
        let chars = text.get_ref().chars().count();
        if chars > MAX_LABEL_CHARS {
            return Err(at(Invalid::Limit { what: "characters", found: chars as u64, limit: MAX_LABEL_CHARS as u64 }));
        }
        if let Some((at, reach)) = anchor {
            return Ok(Some(Label { text: text.get_ref().clone(), at, reach, colour }));
        }
        let bounds: Option<Vec<(E3, f64)>> = shapes.iter().map(|s| s.bounds()).collect();
        let Some(bounds) = bounds else {
            return Err(at(Invalid::Value("an unbounded object has nowhere to put a label: label a `plane-patch`")));
        };
        let n = bounds.len() as f64;
        let centre = [0, 1, 2].map(|k| bounds.iter().map(|b| b.0[k]).sum::<f64>() / n);
        let reach = bounds.iter().map(|(c, r)| norm(sub(*c, centre)) + r).fold(0.0, f64::max);
        Ok(Some(Label { text: text.get_ref().clone(), at: centre, reach, colour }))
    }
}

/// An evolved surface, its circles built in the frame of [`EvolvedSurface::frame_origin`]
/// (inside the scene's frame), each moved by its own transform and then by the object's.
#[cfg(feature = "evolved")]
fn evolved(
    c1: &Spanned<CircleSpec>,
    c2: &Spanned<CircleSpec>,
    place: &Placement,
    method: Method,
) -> Result<EvolvedSurface, Invalid> {
    let on = |which, span: Range<usize>| move |e| Invalid::at(which, span.clone(), e);
    let (s1, s2) = (c1.span(), c2.span());
    let (c1, n1, r1) = circle(c1.get_ref(), place).map_err(on("c1", s1.clone()))?;
    let (c2, n2, r2) = circle(c2.get_ref(), place).map_err(on("c2", s2.clone()))?;
    let origin = EvolvedSurface::frame_origin((c1, r1), (c2, r2));
    let local = |c: E3, n, r| Circle::from_centre_normal_radius(sub(c, origin), n, r);
    let c1 = local(c1, n1, r1).map_err(|e| on("c1", s1)(e.into()))?;
    let c2 = local(c2, n2, r2).map_err(|e| on("c2", s2)(e.into()))?;
    Ok(EvolvedSurface::in_frame(origin, c1, c2, method)?)
}

/// The centre, normal and radius of a circle spec, moved by its own transform and then by
/// the object's `place` (its motor and the frame). A blade is read in world coordinates
/// (where the file gives it): its coefficients carry the circle no better than
/// `ε (|c|/r)²` there, which is what the file holds.
#[cfg(feature = "evolved")]
fn circle(spec: &CircleSpec, place: &Placement) -> Result<(E3, E3, f64), Invalid> {
    let (c, n, r) = match (spec.blade, spec.centre, spec.normal, spec.radius, &spec.points) {
        (Some(b), None, None, None, None) => {
            let c = Circle::from_dense(&blade::circle_blade(b.0))
                .try_normalise()
                .ok_or(Invalid::Value("the blade is zero or null"))?;
            c.centre_normal_radius()?
        }
        (None, Some(c), Some(n), Some(r), None) => {
            // A zero radius or normal (numbers are finite) is named here, before the frame or a
            // motor acts on it.
            if r.0 <= 0.0 {
                return Err(GeometryError::ZeroRadius.into());
            }
            cga_core::euclid::unit(n.0).ok_or(GeometryError::ZeroVector)?;
            (c.0, n.0, r.0)
        }
        (None, None, None, None, Some(p)) => {
            let [a, b, c] = points("points", p)?;
            circumcircle(a, b, c)?
        }
        _ => return Err(Invalid::Form("give `blade`, or `centre`, `normal` and `radius`, or `points` (three)")),
    };
    // Its own transform, then the object's placement.
    let own = world_motor(spec.motor.as_ref(), spec.transform.as_ref())?;
    let (c, n) = match own {
        Some(m) => (m.move_point(c), m.move_direction(n)),
        None => (c, n),
    };
    Ok((place.point(c)?, place.direction(n), place.length(r)))
}

#[cfg(test)]
mod tests {
    use super::Kind;

    /// The scene-format guide (`docs/SCENES.md`) names every object kind and every field each
    /// kind takes: a kind or field added without its documentation fails here.
    #[test]
    fn the_guide_documents_every_kind_and_its_fields() {
        let guide = include_str!("../../../docs/SCENES.md");
        let kinds = [
            Kind::Sphere,
            Kind::Plane,
            Kind::Disk,
            Kind::Torus,
            Kind::Cylinder,
            Kind::Cone,
            Kind::Box,
            Kind::Triangle,
            Kind::Mesh,
            Kind::Instance,
            Kind::Evolved,
            Kind::Spline,
            Kind::Ruled,
            Kind::Point,
            Kind::PointPair,
            Kind::Line,
            Kind::Circle,
            Kind::PlanePatch,
            Kind::Blade,
        ];
        let mut missing = Vec::new();
        for kind in kinds {
            // The name as files write it: kebab-case, as serde reads it.
            let name = format!("{kind:?}").chars().fold(String::new(), |mut s, c| {
                if c.is_uppercase() && !s.is_empty() {
                    s.push('-');
                }
                s.push(c.to_ascii_lowercase());
                s
            });
            if !guide.contains(&format!("\"{name}\"")) && !guide.contains(&format!("`{name}`")) {
                missing.push(name.clone());
            }
            for field in kind.takes().0 {
                if !guide.contains(&format!("{field} =")) && !guide.contains(&format!("`{field}`")) {
                    missing.push(format!("{name}.{field}"));
                }
            }
        }
        assert!(missing.is_empty(), "kinds and fields docs/SCENES.md does not name: {missing:?}");
    }
}
