//! Object transforms in scene files: a motor, or a list of rotations, translations and
//! motors composed in order, applied to an object's blade as the sandwich `X' = V X Ṽ`.
//!
//! Motors are given in world coordinates; the renderer's [`Frame`] is the world moved by
//! `−o` and scaled by `1/s`, so a world motor `T_t R` acts there as `T_t' R` with
//! `t' = (R o + t − o) / s` (the rotation is unchanged by a translation and a scaling of the
//! frame).

use super::numbers::{Num, Nums, V3};
use crate::frame::Frame;
use crate::invalid::Invalid;
use cga_core::euclid::{E3, norm};
use cga_core::{Motor, Rotor, Sandwich, Translator, Vector};
use serde::Deserialize;
use toml::Spanned;

/// One step of a `transform` list: exactly one of `rotate`, `translate`, `motor`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Step {
    rotate: Option<Rotation>,
    translate: Option<V3>,
    motor: Option<Nums<8>>,
}

/// `rotate = { axis = [x, y, z], degrees = θ }` (or `radians`), about the axis through the
/// origin or through `about`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Rotation {
    axis: V3,
    degrees: Option<Num>,
    radians: Option<Num>,
    about: Option<V3>,
}

/// How far a motor may be from rigid, relative to its translation: the `e123i` part of
/// `M R̃` (zero for `M = T R`) over `|t|/2`. Coefficients typed to six or more digits pass.
const RIGID_TOLERANCE: f64 = 1e-6;

/// The rigid motor of coefficients `s, e12, e13, e23, e1i, e2i, e3i, e123i`, normalised and
/// rebuilt as `T R` exactly. Refused if it has no rotation part or is not rigid: a motor
/// `M = T R` has `M R̃ = 1 − ½ t ei`, with no `e123i` part.
pub(crate) fn rigid(c: [f64; 8]) -> Result<Motor, Invalid> {
    let m = Motor::from_array(c);
    let rotor = Rotor { s: m.s, e12: m.e12, e13: m.e13, e23: m.e23 };
    let weight = norm([rotor.e12, rotor.e13, rotor.e23]).hypot(rotor.s);
    if weight == 0.0 || !weight.is_finite() {
        return Err(Invalid::Value("the motor has no rotation part (s, e12, e13, e23 are all zero)"));
    }
    let (m, rotor) = (m.scale(1.0 / weight), rotor.scale(1.0 / weight));
    let p = m * rotor.reverse();
    let t = [p.e1i, p.e2i, p.e3i].map(|x| -2.0 * x);
    if p.e123i.abs() > RIGID_TOLERANCE * norm(t) / 2.0 {
        return Err(Invalid::Value("the motor is not rigid: M R̃ has an e123i part (a motor is T R, T = 1 − ½ t ei)"));
    }
    Ok(Motor::from_rotor_translator(rotor, Translator::from_vector(t)))
}

impl Step {
    /// This step as a world motor.
    fn motor(&self) -> Result<Motor, Invalid> {
        match (&self.rotate, self.translate, self.motor) {
            (Some(r), None, None) => r.motor(),
            (None, Some(t), None) => Ok(Motor::from(Translator::from_vector(t.0))),
            (None, None, Some(m)) => rigid(m.0),
            _ => Err(Invalid::Value("a transform step takes exactly one of `rotate`, `translate`, `motor`")),
        }
    }
}

impl Rotation {
    fn motor(&self) -> Result<Motor, Invalid> {
        let angle = match (self.degrees, self.radians) {
            (Some(d), None) => d.0.to_radians(),
            (None, Some(r)) => r.0,
            _ => return Err(Invalid::Value("a rotation takes exactly one of `degrees`, `radians`")),
        };
        let r = Motor::from(Rotor::from_axis_angle(self.axis.0, angle)?);
        Ok(match self.about {
            // About an axis through p: shift p to the origin, turn, shift back.
            Some(p) => {
                Motor::from(Translator::from_vector(p.0)) * r * Motor::from(Translator::from_vector(p.0.map(|x| -x)))
            }
            None => r,
        })
    }
}

/// The world motor an object's `motor` or `transform` gives, if either: steps compose in the
/// order listed (the first acts first), `V = V_n ⋯ V_1`.
pub(crate) fn world_motor(
    motor: Option<&Spanned<Nums<8>>>,
    steps: Option<&Spanned<Vec<Spanned<Step>>>>,
) -> Result<Option<Motor>, Invalid> {
    let at = |span: std::ops::Range<usize>, field| move |reason| Invalid::at(field, span.clone(), reason);
    match (motor, steps) {
        (None, None) => Ok(None),
        (Some(m), None) => rigid(m.get_ref().0).map(Some).map_err(at(m.span(), "motor")),
        (None, Some(steps)) => {
            let mut v = Motor::from(Rotor { s: 1.0, ..Rotor::zero() });
            for step in steps.get_ref() {
                v = step.get_ref().motor().map_err(at(step.span(), "transform"))? * v;
            }
            Ok(Some(v))
        }
        (Some(m), Some(_)) => {
            Err(Invalid::at("motor", m.span(), Invalid::Value("give `motor` or `transform`, not both")))
        }
    }
}

/// Keyframes a `motion` list holds at most.
pub const MAX_KEYS: usize = 4096;

/// The motor of a `motion` list at `time` in [0, 1]: rigid keyframe motors evenly spaced over
/// the frame times, `M(t)` the screw motion between the two keys about `t`
/// (`Motor::interpolate`: constant screw velocity, through each key).
pub(crate) fn motion_at(keys: &Spanned<Vec<Spanned<Nums<8>>>>, time: f64) -> Result<Motor, Invalid> {
    let at = |reason| Invalid::at("motion", keys.span(), reason);
    let list = keys.get_ref();
    if list.is_empty() {
        return Err(at(Invalid::Value("a motion needs at least one keyframe motor")));
    }
    if list.len() > MAX_KEYS {
        return Err(at(Invalid::Limit { what: "keyframes", found: list.len() as u64, limit: MAX_KEYS as u64 }));
    }
    let motors: Vec<Motor> = list
        .iter()
        .map(|k| rigid(k.get_ref().0).map_err(|e| Invalid::at("motion", k.span(), e)))
        .collect::<Result<_, _>>()?;
    if motors.len() == 1 {
        return Ok(motors[0]);
    }
    let x = time.clamp(0.0, 1.0) * (motors.len() - 1) as f64;
    let k = (x.floor() as usize).min(motors.len() - 2);
    Motor::interpolate(&motors[k], &motors[k + 1], x - k as f64)
        .map_err(|e| at(Invalid::Range(format!("keyframes {} and {} cannot be interpolated: {e}", k + 1, k + 2))))
}

/// Where an object's world coordinates go: its rigid world motor (if any) `x ↦ R x + t`,
/// then the frame's `x ↦ (x − o) / s`, in one step `x ↦ (R x + (t − o)) / s`. The translation
/// is taken relative to the camera first, so a motor that carries an object next to a
/// distant camera loses nothing to the distance, and no conformal point `up(x)` (whose `½|x|²`
/// costs `ε |x|²`) is formed: Euclidean data moves with `ε |x|` of rounding, as given.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Placement {
    rotor: Option<Rotor>,
    shift: E3,
    scale: f64,
}

impl Placement {
    /// The world motor `m` (if any) followed by the change to `frame`.
    pub(crate) fn new(m: Option<Motor>, frame: &Frame) -> Self {
        let (rotor, t) = match m {
            Some(m) => (Some(m.rotor()), m.translation()),
            None => (None, [0.0; 3]),
        };
        let o = frame.origin;
        Placement { rotor, shift: [0, 1, 2].map(|k| t[k] - o[k]), scale: frame.scale }
    }

    /// A world point in the frame, moved; refused where the frame cannot hold it beside the
    /// rest of the scene ([`Frame::holds`]: a motor that carries the object too far, or an
    /// object too far from the others).
    pub(crate) fn point(&self, x: E3) -> Result<E3, Invalid> {
        let r = self.direction(x);
        let moved: E3 = [0, 1, 2].map(|k| (r[k] + self.shift[k]) / self.scale);
        let distance = moved.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if Frame::holds(distance) {
            return Ok(moved);
        }
        let moves = if self.rotor.is_some() { "its motor carries it to" } else { "it lies" };
        Err(Invalid::Range(format!(
            "{moves} {:.1e} from the camera, {distance:.1e} times the scene's size ({:.1e}): ill-conditioned, beyond the 2^200 that f64 renders beside the rest of the scene",
            distance * self.scale,
            self.scale
        )))
    }

    /// A plane through the world point `p` with normal `n`, in the frame: the point of it
    /// nearest the camera (so that a point given far along the plane neither leaves the frame
    /// nor costs its offset digits, and a plane through the camera keeps offset 0 exactly)
    /// and its normal, turned.
    pub(crate) fn plane(&self, p: E3, n: E3) -> Result<(E3, E3), Invalid> {
        let n = self.direction(n);
        let r = self.direction(p);
        let moved: E3 = [0, 1, 2].map(|k| r[k] + self.shift[k]);
        let unit = cga_core::euclid::unit(n).ok_or(Invalid::Geometry(cga_core::GeometryError::ZeroVector))?;
        let d = cga_core::euclid::dot(unit, moved);
        let foot = unit.map(|x| x * d / self.scale);
        let distance = foot.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if Frame::holds(distance) {
            return Ok((foot, n));
        }
        Err(Invalid::Range(format!(
            "the plane passes {:.1e} from the camera, {distance:.1e} times the scene's size ({:.1e}): ill-conditioned, beyond the 2^200 that f64 renders beside the rest of the scene",
            distance * self.scale,
            self.scale
        )))
    }

    /// A world direction, turned.
    pub(crate) fn direction(&self, d: E3) -> E3 {
        match self.rotor {
            Some(r) => {
                let v = r.sandwich(Vector::from_array([d[0], d[1], d[2], 0.0, 0.0])).to_array();
                [v[0], v[1], v[2]]
            }
            None => d,
        }
    }

    /// A world length in the frame.
    pub(crate) fn length(&self, l: f64) -> f64 {
        l / self.scale
    }
}
