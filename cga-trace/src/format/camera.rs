//! The `[camera]` table read and checked: pose, focal length, image plane, size, lens and
//! shutter.

use super::given::first_given;
use super::motion::{CameraMotion, motion_at};
use super::numbers::{Num, Nums, V3};
use super::transform::rigid;
use crate::camera::{Camera, CameraError, Lens};
use crate::invalid::Invalid;
use crate::limits::{MAX_SIDE, MAX_TIME_SAMPLES};
use crate::shutter::Shutter;
use cga_core::Motor;
use cga_core::euclid::{E3, norm, sub};
use serde::Deserialize;
use toml::Spanned;

/// The camera: a pose (`position`, `look_at`, `up`, or a `motor`), focal length, image-plane
/// extents (or a horizontal field of view) and pixel size.
#[derive(Default, Deserialize)]
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
    /// Keyframes over the frame times 0 … 1, moving the pose (camera frame → world): motors,
    /// or the camera's poses at those times.
    motion: Option<Spanned<CameraMotion>>,
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
    /// The instants the shutter is cut into, at least (default 256; each pixel sample at its own).
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
    /// A pinhole camera at `position` looking at `look_at`, `up` upward, with a horizontal
    /// field of view of `fov` degrees and `width × height` pixels (as a scene built in code
    /// gives it, with no file to point into).
    pub(crate) fn looking(position: E3, look_at: E3, up: E3, fov: f64, (width, height): (u32, u32)) -> CameraSpec {
        CameraSpec {
            position: Some(Nums(position)),
            look_at: Some(Nums(look_at)),
            up: Some(Nums(up)),
            fov: Some(Spanned::new(0..0, Num(fov))),
            width: Some(Spanned::new(0..0, width)),
            height: Some(Spanned::new(0..0, height)),
            ..CameraSpec::default()
        }
    }

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
                let m = motion_at(keys, time, Some(&pose))?;
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
