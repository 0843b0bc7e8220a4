//! Lights: points, spot lights (points lighting a cone), directional lights at infinity
//! (a sun), which light every point from one direction and cast shadows without end, and
//! area lights — disks and spheres, whose points each light as a point light would, so that
//! shadows have penumbras.

use crate::lanes::lanes3;
use cga_core::euclid::{E3, norm, scale, sub};
use cga_core::simd::Lane;
use cga_core::{Real, Select};

/// A light in a scene's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Where its light comes from.
    pub source: Source,
    /// Linear RGB intensity.
    pub colour: [f64; 3],
}

/// Where a light's light comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    /// A point light at this position.
    Point(E3),
    /// A directional light: its light travels along this unit direction.
    Directional(E3),
    /// A spot light at `position` shining along the unit `axis`: full within `radius` of the
    /// axis, nothing beyond `falloff`, a smooth step between (POV-Ray's `spotlight`, with
    /// the angles given by their cosines).
    Spot {
        /// Where it is.
        position: E3,
        /// The unit direction it shines along.
        axis: E3,
        /// `cos falloff`: no light beyond this cone.
        cos_falloff: f64,
        /// `1 / (cos radius − cos falloff)`: full light within `radius` (a hard edge where the
        /// two agree).
        inverse_width: f64,
    },
    /// A disk of light (POV-Ray's circular `area_light`): `samples` of its points light each
    /// hit, each with `1/samples` of the colour, stratified over the pixel's samples.
    Disk {
        /// Its centre.
        centre: E3,
        /// Its unit normal.
        normal: E3,
        /// Its radius.
        radius: f64,
        /// Points of it that light each hit.
        samples: u32,
    },
    /// A sphere of light, seen from each hit as its disk through the centre facing the hit
    /// (POV-Ray's circular `area_light` with `orient`): as [`Source::Disk`] otherwise.
    Sphere {
        /// Its centre.
        centre: E3,
        /// Its radius.
        radius: f64,
        /// Points of it that light each hit.
        samples: u32,
    },
}

impl Light {
    /// The unit direction `l` from `x` towards the light and the distance to it (∞ for a
    /// directional light): `(p − x)/|p − x|` and `|p − x|`, or `−d` and ∞. Generic, so that a
    /// point and a packet's four points (lanes) take the same operations.
    #[inline(always)]
    pub fn toward<T: Real>(&self, x: E3<T>) -> (E3<T>, T) {
        match self.source {
            Source::Point(p)
            | Source::Spot { position: p, .. }
            | Source::Disk { centre: p, .. }
            | Source::Sphere { centre: p, .. } => {
                let to_light = sub(p.map(T::from_f64), x);
                let distance = norm(to_light);
                (scale(to_light, T::one() / distance), distance)
            }
            Source::Directional(d) => (d.map(|c| T::from_f64(-c)), T::from_f64(f64::INFINITY)),
        }
    }
}

impl Light {
    /// How many of its points light each hit: `None` for a point, spot or directional light.
    #[inline(always)]
    pub fn samples(&self) -> Option<u32> {
        match self.source {
            Source::Disk { samples, .. } | Source::Sphere { samples, .. } => Some(samples),
            _ => None,
        }
    }

    /// The point of an area light at `(a, b)` of the unit disk, seen from `x`: `c + r (a u +
    /// b w)` for the light's centre `c`, radius `r`, and `u`, `w` a right-handed pair
    /// orthogonal to its normal (a sphere's: towards `x`). Other lights' own position.
    pub fn area_point(&self, x: E3, (a, b): (f64, f64)) -> E3 {
        let (centre, normal, radius) = match self.source {
            Source::Disk { centre, normal, radius, .. } => (centre, normal, radius),
            Source::Sphere { centre, radius, .. } => {
                (centre, cga_core::euclid::unit(sub(x, centre)).unwrap_or([0.0, 0.0, 1.0]), radius)
            }
            _ => return self.position().unwrap_or(x),
        };
        on_disk(centre, normal, radius, (a, b))
    }

    /// [`Light::area_point`] in `W` lanes (`W` of the lane type `T`'s): a disk's frame found
    /// once for all of them, the same steps as one at a time.
    #[inline(always)]
    pub fn area_points<T: Select + Lane, const W: usize>(&self, x: E3<T>, (a, b): (T, T)) -> E3<T> {
        if let Source::Disk { centre, normal, radius, .. } = self.source {
            return on_disk(centre, normal, radius, (a, b));
        }
        let p: [E3; W] = core::array::from_fn(|l| self.area_point(x.map(|c| c.lane(l)), (a.lane(l), b.lane(l))));
        lanes3(p)
    }

    /// Where a light is: its position or centre; `None` for a directional light.
    pub fn position(&self) -> Option<E3> {
        match self.source {
            Source::Point(p) | Source::Spot { position: p, .. } => Some(p),
            Source::Disk { centre, .. } | Source::Sphere { centre, .. } => Some(centre),
            Source::Directional(_) => None,
        }
    }

    /// How much of the light reaches along the unit direction `l` towards it: 1 but for a
    /// spot light, whose `c = −l · axis` gives `smoothstep(cos falloff, cos radius, c)`,
    /// `u² (3 − 2u)` for `u = (c − cos falloff)/(cos radius − cos falloff)` clamped to
    /// [0, 1]. Lane by lane for a packet.
    #[inline(always)]
    pub fn cone<T: Select>(&self, l: E3<T>) -> T {
        match self.source {
            Source::Spot { axis, cos_falloff, inverse_width, .. } => {
                let c = T::zero() - cga_core::euclid::dot(l, axis.map(T::from_f64));
                let u = ((c - T::from_f64(cos_falloff)) * T::from_f64(inverse_width))
                    .max_lanes(T::zero())
                    .min_lanes(T::one());
                u * u * (T::from_f64(3.0) - T::from_f64(2.0) * u)
            }
            _ => T::one(),
        }
    }
}

/// Two unit vectors that make a right-handed orthonormal frame with the unit `n`, continuous
/// but at `n_z = −1` (Duff et al., "Building an orthonormal basis, revisited", 2017).
pub fn orthonormal(n: E3) -> (E3, E3) {
    let sign = 1f64.copysign(n[2]);
    let a = -1.0 / (sign + n[2]);
    let b = n[0] * n[1] * a;
    ([1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]], [b, sign + n[1] * n[1] * a, -n[1]])
}

/// `c + r (a u + b w)`: the point `(a, b)` of the unit disk on the disk of centre `c`, radius
/// `r` and unit normal `n`, `u` and `w` a right-handed pair orthogonal to `n`; lane by lane.
#[inline(always)]
fn on_disk<T: Real>(centre: E3, normal: E3, radius: f64, (a, b): (T, T)) -> E3<T> {
    let (u, w) = orthonormal(normal);
    let r = T::from_f64(radius);
    core::array::from_fn(|k| T::from_f64(centre[k]) + r * (a * T::from_f64(u[k]) + b * T::from_f64(w[k])))
}

/// `min(1, 1/(c₀ + c₁ d + c₂ d²))` for the attenuation coefficients `c` at distance `d` (world
/// units); `min(1, 1/c₀)` at infinity, where a directional light's light comes from. Lane by
/// lane for a packet ([`Select`]): one ray and four take the same steps.
#[inline(always)]
pub fn attenuation<T: Select>(c: [f64; 3], d: T) -> T {
    let [c0, c1, c2] = c.map(T::from_f64);
    let f = T::select(d.finite(), T::one() / (c0 + c1 * d + c2 * d * d), T::one() / c0);
    f.min_lanes(T::one())
}

/// One light's Blinn–Phong term (eq. 12 without the ambient and reflected parts), per colour
/// channel: `s f_att (c k_d max(n·l, 0) + k_s spec) L`, with `sf = s f_att` the shadow and
/// attenuation factors, `n_l = n·l` and `spec = max(n·h, 0)^q`. Lane by lane for a packet
/// ([`Select`]): one ray and four take the same steps.
#[inline(always)]
pub fn blinn_phong<T: Select>(colour: [T; 3], kd: T, ks: T, n_l: T, spec: T, sf: T, light: [f64; 3]) -> [T; 3] {
    let (facing, shine) = (n_l.max_lanes(T::zero()), ks * spec);
    let channel = |k: usize| sf * (colour[k] * kd * facing + shine) * T::from_f64(light[k]);
    [channel(0), channel(1), channel(2)]
}

/// Whether a light adds anything at a hit: it lies ahead (`distance > 0`; not at the hit point,
/// not NaN) and in front of the surface for the diffuse or the specular term. Lane by lane for
/// a packet ([`Select`]): one ray and four decide the same way.
#[inline(always)]
pub(crate) fn lights<T: Select>(distance: T, diffuse: T, specular: T) -> T::Mask {
    T::zero().lt(distance) & !(diffuse.le(T::zero()) & specular.le(T::zero()))
}
