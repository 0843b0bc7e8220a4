//! Lights: points, spot lights (points lighting a cone), and directional lights at infinity
//! (a sun), which light every point from one direction and cast shadows without end.

use cga_core::euclid::{E3, norm, scale, sub};
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
}

impl Light {
    /// The unit direction `l` from `x` towards the light and the distance to it (∞ for a
    /// directional light): `(p − x)/|p − x|` and `|p − x|`, or `−d` and ∞. Generic, so that a
    /// point and a packet's four points (lanes) take the same operations.
    #[inline(always)]
    pub fn toward<T: Real>(&self, x: E3<T>) -> (E3<T>, T) {
        match self.source {
            Source::Point(p) | Source::Spot { position: p, .. } => {
                let to_light = sub(p.map(T::from_f64), x);
                let distance = norm(to_light);
                (scale(to_light, T::one() / distance), distance)
            }
            Source::Directional(d) => (d.map(|c| T::from_f64(-c)), T::from_f64(f64::INFINITY)),
        }
    }
}

impl Light {
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
    core::array::from_fn(|k| sf * (colour[k] * kd * facing + shine) * T::from_f64(light[k]))
}

/// Whether a light adds anything at a hit: it lies ahead (`distance > 0`; not at the hit point,
/// not NaN) and in front of the surface for the diffuse or the specular term. Lane by lane for
/// a packet ([`Select`]): one ray and four decide the same way.
#[inline(always)]
pub(crate) fn lights<T: Select>(distance: T, diffuse: T, specular: T) -> T::Mask {
    T::zero().lt(distance) & !(diffuse.le(T::zero()) & specular.le(T::zero()))
}
