//! Scenes: the renderer's [`Frame`] and what is in it — camera, objects, lights, settings,
//! labels, shutter and environment — with every file it was read from. Data only: the scene
//! format ([`crate::format`]) reads a file into one.

use crate::camera::{Camera, CameraError, Lens};
use crate::environment::Environment;
use crate::frame::Frame;
use crate::input::Input;
use crate::label::Label;
use crate::light::Light;
pub use crate::object::Object;
use crate::settings::{AdaptiveMethod, Settings};
use crate::shutter::Shutter;

/// A scene ready to render, in its [`Frame`]: camera, objects and lights are given
/// relative to the camera's position, in units of `frame.scale` (see [`crate::frame`]).
#[derive(Clone, Debug)]
pub struct Scene {
    /// World coordinates → the coordinates everything below is given in.
    pub frame: Frame,
    /// The camera, at the frame's origin.
    pub camera: Camera,
    /// Objects.
    pub objects: Vec<Object>,
    /// Point lights.
    pub lights: Vec<Light>,
    /// Settings.
    pub settings: Settings,
    /// Labels to write beside their objects in a colour picture ([`crate::label::draw_labels`]).
    pub labels: Vec<Label>,
    /// Whether the file gives both image-plane extents (`x_max` or `fov`, and `y_max`): then
    /// [`Scene::resize`] keeps them, and pixels need not be square.
    pub pinned: bool,
    /// The camera's shutter, where it blurs motion.
    pub shutter: Option<Shutter>,
    /// What rays leaving the scene see (the background colour where none).
    pub environment: Option<Environment>,
    /// Every file the scene was read from, with its role: the scene file, the files it
    /// includes, its images and meshes (an output must be none of them).
    pub inputs: Vec<Input>,
    /// The names of the file's templates (`template = true`), drawn only as their instances.
    pub templates: Vec<String>,
}

/// More objects than this sharing one bounding sphere get a note: the hierarchy (four to a
/// leaf) cannot separate them, so every ray that reaches them tests each.
const CROWD: usize = 64;

impl Scene {
    /// What a user should know about the scene that is not an error: objects that share one
    /// bounding sphere in crowds (the same object repeated), which no hierarchy can separate,
    /// so that rendering costs a test of each per ray there; a scene without lights.
    pub fn notes(&self) -> Vec<String> {
        let mut groups: std::collections::HashMap<[u64; 4], (usize, usize)> = std::collections::HashMap::new();
        for (k, object) in self.objects.iter().enumerate() {
            if let Some((c, r)) = object.shape.bounds() {
                groups.entry([c[0].to_bits(), c[1].to_bits(), c[2].to_bits(), r.to_bits()]).or_insert((k, 0)).1 += 1;
            }
        }
        let largest = groups.values().max_by_key(|(_, n)| *n);
        let dark = self.lights.is_empty().then(|| {
            format!(
                "the scene has no lights: objects show only their ambient colour (ambient = {}); add a [[lights]] table",
                self.settings.ambient
            )
        });
        largest
            .filter(|(_, n)| *n > CROWD)
            .map(|&(first, n)| {
                let (c, r) = self.objects[first].shape.bounds().expect("bounded");
                let (c, r) = (self.frame.world_point(c), self.frame.world_length(r));
                format!(
                    "{n} objects share one bounding sphere (centre [{:.6e}, {:.6e}, {:.6e}], radius {r:.6e}; the first is `{}`): no hierarchy separates them, so each ray that reaches them tests all {n}",
                    c[0],
                    c[1],
                    c[2],
                    self.objects[first].name.escape_debug()
                )
            })
            .into_iter()
            .chain(dark)
            .chain(self.adaptive_note())
            .chain(self.blur_note())
            .collect()
    }

    /// Why `blur_samples` above 1 changes nothing: the camera has no lens.
    fn blur_note(&self) -> Option<String> {
        let m = self.settings.blur_samples;
        (m > 1 && !matches!(self.camera.lens, Lens::Thin { .. })).then(|| {
            format!(
                "blur_samples ({m}) averages rays through a lens, and this camera has none: each sample takes one ray; give the camera an aperture"
            )
        })
    }

    /// Why adaptive sampling, where set, takes every sample: a shutter, or `spp` not above
    /// the first samples.
    fn adaptive_note(&self) -> Option<String> {
        let (a, spp) = (self.settings.adaptive?, self.settings.spp);
        if self.shutter.is_some() {
            Some("adaptive sampling does not apply under a shutter: every pixel takes all its samples".into())
        } else if a.adapts(spp) {
            None
        } else if a.method == AdaptiveMethod::Corners {
            Some(format!(
                "adaptive corners cut a pixel into at most spp squares: spp ({spp}) below 4 cuts none, so every pixel takes all its samples; raise spp (--spp)"
            ))
        } else {
            Some(format!(
                "adaptive sampling takes every sample: spp ({spp}) is not above the first samples each pixel takes (min_spp {}); raise spp (--spp)",
                a.min_spp
            ))
        }
    }

    /// The image resized to `width × height`; given one, the other follows at the image's
    /// present aspect (`h = round(w h₀ / w₀)`). Pixels stay square — `y_max = x_max h / w` —
    /// unless the file pins both extents ([`Scene::pinned`]): then both are kept, and the
    /// note returned says how far from square the pixels have become.
    pub fn resize(&mut self, width: Option<u32>, height: Option<u32>) -> Result<Option<String>, CameraError> {
        let c = self.camera;
        let follow = |a: u32, b0: u32, a0: u32| {
            let b = (f64::from(a) * f64::from(b0) / f64::from(a0)).round();
            b.clamp(1.0, f64::from(u32::MAX)) as u32
        };
        let (w, h) = match (width, height) {
            (None, None) => return Ok(None),
            (Some(w), None) => (w, follow(w, c.height, c.width)),
            (None, Some(h)) => (follow(h, c.width, c.height), h),
            (Some(w), Some(h)) => (w, h),
        };
        let y_max = if self.pinned { c.y_max } else { c.x_max * f64::from(h) / f64::from(w.max(1)) };
        self.camera = Camera::new(c.pose, c.focal, c.x_max, y_max, w, h)?.with_lens(c.lens)?;
        let aspect = (c.x_max / f64::from(w)) / (y_max / f64::from(h));
        Ok((self.pinned && (aspect - 1.0).abs() > 1e-3).then(|| {
            format!(
                "the scene gives both x_max and y_max, so they are kept: pixels are {aspect:.4} times as wide as tall"
            )
        }))
    }

    /// Set the horizontal field of view to `degrees` (strictly between 0 and 180):
    /// `x_max = 2 f tan(θ/2)`, and `y_max` follows for square pixels.
    pub fn set_fov(&mut self, degrees: f64) -> Result<(), CameraError> {
        let c = self.camera;
        if let Lens::Orthographic { .. } = c.lens {
            return Err(CameraError::OrthographicFov);
        }
        let x_max = Camera::x_max_for_fov(c.focal, degrees)?;
        let y_max = x_max * f64::from(c.height) / f64::from(c.width);
        self.camera = Camera::new(c.pose, c.focal, x_max, y_max, c.width, c.height)?.with_lens(c.lens)?;
        self.pinned = false;
        Ok(())
    }
}
