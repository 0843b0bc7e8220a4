//! The camera of the paper's eq. 2: a motor places it, and pixel `(i, j)` (`(0, 0)`
//! bottom-left) is the ray `L_ij = cam ∧ P_ij ∧ ei` with
//! `P_ij = M up(f e2 − x_max/2 (1 − 2u/w) e1 − y_max/2 (1 − 2v/h) e3) M̃`, `(u, v)` the
//! pixel centre `(i + ½, j + ½)`. In the camera's frame it looks along `e2` with `e3` up.
//!
//! That is the pinhole; a [`Lens`] may replace it: parallel rays (orthographic), or a thin
//! lens whose rays leave a point of the lens disk and pass through the pinhole ray's point on
//! the plane of focus (depth of field).

use crate::lanes::{lane, lanes3};
use crate::limits::{EXTENT_OVER_FOCAL, MAX_PIXELS, MAX_SIDE};
use crate::ray::Ray;
use cga_core::euclid::{E3, cross, scale, sub, unit};
use cga_core::simd::{Lane, Lanes};
use cga_core::{Line, Motor, Real, Rotor, Sandwich, Translator, Vector, down, ei, up};

/// Why a camera cannot be built.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum CameraError {
    /// The camera sits on the point it looks at.
    #[error("the camera position equals the look-at point")]
    NoDirection,
    /// The up vector is parallel to the viewing direction.
    #[error("the up vector is zero or parallel to the viewing direction")]
    UpParallel,
    /// A lens whose aperture is negative, or whose focus distance or view width is not
    /// positive (or any of them not finite).
    #[error("a lens needs aperture ≥ 0 and a focus distance (or orthographic view width) > 0, all finite")]
    Lens,
    /// A field of view asked of an orthographic camera, whose view has a width instead.
    #[error("an orthographic camera has no field of view: give its `view_width`")]
    OrthographicFov,
    /// A zero or negative size, focal length or image extent.
    #[error("focal length, image extents and size must be positive")]
    NotPositive,
    /// An image larger than [`MAX_SIDE`] per side or [`MAX_PIXELS`] in all.
    #[error("{width} × {height} pixels is larger than the limit ({MAX_SIDE} per side, {MAX_PIXELS} in all)")]
    TooLarge {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// The image-plane extents over the focal length outside [`EXTENT_OVER_FOCAL`]: every
    /// pixel would see the same direction in f64, or the field of view is all but 180°.
    #[error("the field of view is degenerate: x_max/f = {x:.3e} and y_max/f = {y:.3e} must lie in [1e-6, 1e6]")]
    FieldOfView {
        /// `x_max / f`.
        x: f64,
        /// `y_max / f`.
        y: f64,
    },
    /// A horizontal field of view outside (0°, 180°).
    #[error("the field of view must lie strictly between 0 and 180 degrees, not {0}")]
    FovDegrees(f64),
    /// The pose is not a rigid motion (its sandwich does not map points to points).
    #[error("the pose is not a rigid motion")]
    NotRigid,
}

/// How a camera turns image-plane points into rays (lengths in the scene's frame units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Lens {
    /// Every ray through the camera's point: `L = cam ∧ P ∧ ei` (eq. 2).
    #[default]
    Pinhole,
    /// Parallel rays along the view axis: the image-plane point `(x, f, z)` is the ray from
    /// `q = k (x e1 + z e3)` along `e2`, `L = up(q) ∧ e2 ∧ ei` moved by the pose; the view is
    /// `k x_max` wide.
    Orthographic {
        /// View width over `x_max`.
        k: f64,
    },
    /// A thin lens of radius `aperture` focused at distance `focus` along the view axis: the
    /// ray from the lens point `q = aperture (a e1 + b e3)` (`(a, b)` in the unit disk)
    /// through `F = (focus / f) P`, where the pinhole ray meets the plane of focus:
    /// `L = up(q) ∧ up(F) ∧ ei` moved by the pose. Points on that plane are sharp; a point at
    /// depth `D` blurs to a disk of diameter `2 aperture |D − focus| / D` on it.
    Thin {
        /// Lens radius.
        aperture: f64,
        /// Distance of the plane of focus.
        focus: f64,
    },
}

impl Lens {
    /// Lengths in world units moved to a frame whose unit is `scale` world units.
    pub fn in_frame(self, scale: f64) -> Lens {
        match self {
            Lens::Pinhole => Lens::Pinhole,
            Lens::Orthographic { k } => Lens::Orthographic { k: k / scale },
            Lens::Thin { aperture, focus } => Lens::Thin { aperture: aperture / scale, focus: focus / scale },
        }
    }

    /// Whether its numbers are usable.
    fn valid(self) -> bool {
        match self {
            Lens::Pinhole => true,
            Lens::Orthographic { k } => k > 0.0 && k.is_finite(),
            Lens::Thin { aperture, focus } => {
                aperture >= 0.0 && aperture.is_finite() && focus > 0.0 && focus.is_finite()
            }
        }
    }
}

/// A camera: a pose, an image plane and a [`Lens`].
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Camera frame → world.
    pub pose: Motor,
    /// Focal length `f`.
    pub focal: f64,
    /// Width of the image plane, `x_max`.
    pub x_max: f64,
    /// Height of the image plane, `y_max`.
    pub y_max: f64,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The lens (by default the pinhole of eq. 2).
    pub lens: Lens,
    position: E3,
    /// `cam = M up(0) M̃`.
    cam: Vector,
    /// The camera frame's axes in world coordinates (for the plain back end).
    axes: [E3; 3],
    /// `cam ∧ (M b M̃) ∧ ei` for the basis vectors `b = e1, e2, e3, eo, ei`: the ray of eq. 2
    /// is linear in `up(x)`, so it is these combined with `up(x)`'s coefficients.
    lines: [Line; 5],
}

impl Camera {
    /// A camera with pose `pose`.
    pub fn new(pose: Motor, focal: f64, x_max: f64, y_max: f64, width: u32, height: u32) -> Result<Self, CameraError> {
        if !(focal > 0.0 && x_max > 0.0 && y_max > 0.0 && width > 0 && height > 0) {
            return Err(CameraError::NotPositive);
        }
        if !(focal.is_finite() && x_max.is_finite() && y_max.is_finite()) {
            return Err(CameraError::NotPositive);
        }
        if width > MAX_SIDE || height > MAX_SIDE || u64::from(width) * u64::from(height) > MAX_PIXELS {
            return Err(CameraError::TooLarge { width, height });
        }
        let (x, y) = (x_max / focal, y_max / focal);
        let (lo, hi) = EXTENT_OVER_FOCAL;
        if !((lo..=hi).contains(&x) && (lo..=hi).contains(&y)) {
            return Err(CameraError::FieldOfView { x, y });
        }
        let cam = pose.sandwich(up([0.0; 3]));
        let position = down(cam).map_err(|_| CameraError::NotRigid)?;
        let axis = |k: usize| {
            let mut e = [0.0; 3];
            e[k] = 1.0;
            down(pose.sandwich(up(e))).map(|x| sub(x, position)).map_err(|_| CameraError::NotRigid)
        };
        let axes = [axis(0)?, axis(1)?, axis(2)?];
        let basis = |k: usize| {
            let mut c = [0.0; 5];
            c[k] = 1.0;
            (cam ^ pose.sandwich(Vector::from_array(c))) ^ ei()
        };
        let lines = [basis(0), basis(1), basis(2), basis(3), basis(4)];
        Ok(Camera { pose, focal, x_max, y_max, width, height, lens: Lens::Pinhole, position, cam, axes, lines })
    }

    /// The same camera with lens `lens` (lengths in frame units).
    pub fn with_lens(mut self, lens: Lens) -> Result<Self, CameraError> {
        if !lens.valid() {
            return Err(CameraError::Lens);
        }
        self.lens = lens;
        Ok(self)
    }

    /// The ray through the image-plane point at pixel coordinates `(u, v)` for the lens
    /// point `(a, b)` in the unit disk, as an origin and unit direction ([`Lens`]); the
    /// pinhole ignores `(a, b)`. `None` where no ray can be formed.
    pub fn lens_ray(&self, u: f64, v: f64, (a, b): (f64, f64)) -> Option<(E3, E3)> {
        let p = self.image_point(u, v);
        let (origin, through) = match self.lens {
            Lens::Pinhole => ([0.0; 3], p),
            Lens::Orthographic { k } => {
                let q = [k * p[0], 0.0, k * p[2]];
                (q, [q[0], 1.0, q[2]])
            }
            Lens::Thin { aperture, focus } => ([aperture * a, 0.0, aperture * b], scale(p, focus / self.focal)),
        };
        // The pose only turns the camera's frame (it sits at the frame's origin).
        let turn = |c: E3| [0, 1, 2].map(|k| c[0] * self.axes[0][k] + c[1] * self.axes[1][k] + c[2] * self.axes[2][k]);
        let dir = unit(turn(sub(through, origin)))?;
        let origin = turn(origin);
        Some(([0, 1, 2].map(|k| self.position[k] + origin[k]), dir))
    }

    /// The pose that puts the camera at `position`, looking at `target`, with `up` upwards:
    /// the rotor taking `(e1, e2, e3)` to `(right, forward, up')`, then the translator.
    pub fn pose_look_at(position: E3, target: E3, up_dir: E3) -> Result<Motor, CameraError> {
        let forward = unit(sub(target, position)).ok_or(CameraError::NoDirection)?;
        let right = unit(cross(forward, up_dir)).ok_or(CameraError::UpParallel)?;
        let true_up = cross(right, forward);
        let m = glam::DMat3::from_cols(right.into(), forward.into(), true_up.into());
        let q = glam::DQuat::from_mat3(&m).normalize();
        // A quaternion (w; x, y, z) turning about a by θ is cos θ/2 + sin θ/2 a; our rotor is
        // cos θ/2 − sin θ/2 a I3 = w − z e12 + y e13 − x e23.
        let rotor = Rotor { s: q.w, e12: -q.z, e13: q.y, e23: -q.x };
        Ok(Motor::from_rotor_translator(rotor, Translator::from_vector(position)))
    }

    /// The image-plane width `x_max = 2 f tan(θ/2)` for a horizontal field of view of
    /// `degrees` (strictly between 0 and 180) at focal length `focal`.
    pub fn x_max_for_fov(focal: f64, degrees: f64) -> Result<f64, CameraError> {
        if !(degrees > 0.0 && degrees < 180.0) {
            return Err(CameraError::FovDegrees(degrees));
        }
        Ok(2.0 * focal * (degrees.to_radians() / 2.0).tan())
    }

    /// Where the camera is.
    pub fn position(&self) -> E3 {
        self.position
    }

    /// The ray `cam ∧ P ∧ ei` through the image-plane point at continuous pixel coordinates
    /// `(u, v)` (pixel `(i, j)`'s centre is `(i + ½, j + ½)`). `None` only for a pose that
    /// is not a rigid motion.
    pub fn ray(&self, u: f64, v: f64) -> Option<Ray> {
        let x = up(self.image_point(u, v)).to_array();
        let (line, dir) = unit_line(&self.lines, x)?;
        Some(Ray { origin: self.position, dir, carrier: line })
    }

    /// [`Camera::ray`] for four points `(u_k, v_k)` at once, on four lanes: the rays, and
    /// their lines and unit directions in lanes (for a [`Packet`](crate::backend::Packet));
    /// the same operations lane by lane, so the same bits. `None` where a ray cannot be
    /// formed.
    #[inline(always)]
    pub fn rays4<L: Lane>(&self, u: [f64; 4], v: [f64; 4]) -> Option<([Ray; 4], Line<L>, E3<L>)> {
        let points: [E3; 4] = core::array::from_fn(|k| self.image_point(u[k], v[k]));
        let x = up(lanes3::<L, 4>(points)).to_array();
        let basis = |k: usize| self.lines[k].cast::<L>();
        let (line, dir) = unit_line(&[basis(0), basis(1), basis(2), basis(3), basis(4)], x)?;
        let mut lines = [Line::zero(); 4];
        Line::unpack_lanes(line, &mut lines);
        let rays = core::array::from_fn(|l| Ray { origin: self.position, dir: lane(&dir, l), carrier: lines[l] });
        Some((rays, line, dir))
    }

    /// The same ray computed term by term as eq. 2 writes it (`cam ∧ M up(x) M̃ ∧ ei`), to
    /// check [`Camera::ray`] against.
    pub fn ray_by_sandwich(&self, u: f64, v: f64) -> Option<Ray> {
        let p = self.pose.sandwich(up(self.image_point(u, v)));
        let line = ((self.cam ^ p) ^ ei()).try_normalise()?;
        Ray::from_line(self.position, line)
    }

    /// The image-plane point at pixel coordinates `(u, v)` in the camera's frame:
    /// `f e2 − x_max/2 (1 − 2u/w) e1 − y_max/2 (1 − 2v/h) e3`.
    pub fn image_point(&self, u: f64, v: f64) -> E3 {
        [
            -self.x_max / 2.0 * (1.0 - 2.0 * u / f64::from(self.width)),
            self.focal,
            -self.y_max / 2.0 * (1.0 - 2.0 * v / f64::from(self.height)),
        ]
    }

    /// `cam = M up(0) M̃`, the camera's conformal point.
    pub fn cam(&self) -> Vector {
        self.cam
    }

    /// The camera frame's axes `M e_k M̃` as world directions.
    pub fn axes(&self) -> [E3; 3] {
        self.axes
    }
}

/// `cam ∧ M up(x) M̃ ∧ ei` for `up(x)`'s coefficients `x` and the lines `lines[k]` it takes
/// for each basis vector (the sandwich and both wedges are linear), normalised, and its unit
/// direction; `None` where it has none. A Euclidean line's norm is that of its direction
/// part: one division normalises both. Generic, so one ray and four lanes share it.
#[inline(always)]
fn unit_line<T: Real>(lines: &[Line<T>; 5], x: [T; 5]) -> Option<(Line<T>, E3<T>)> {
    let mut line = Line::zero();
    for k in 0..5 {
        line += lines[k].scale(x[k]);
    }
    let d = [-line.e1oi, -line.e2oi, -line.e3oi];
    let inv = T::one() / cga_core::euclid::norm(d);
    if inv.is_finite() { Some((line.scale(inv), scale(d, inv))) } else { None }
}
