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
use serde::de::value::MapAccessDeserializer;
use serde::de::{Error as _, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer};
use std::fmt;
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
struct Turn {
    axis: V3,
    degrees: Option<Num>,
    radians: Option<Num>,
    about: Option<V3>,
}

/// A `rotate` as read: a [`Turn`]'s table. An array, as POV-Ray writes Euler angles, is
/// refused with the steps that say it here.
pub(crate) struct Rotation(Turn);

impl<'de> Deserialize<'de> for Rotation {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// A turn's table, or the angles of an array, read to quote them back.
        struct Table;
        impl<'de> Visitor<'de> for Table {
            type Value = Rotation;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a turn, `{ axis = [x, y, z], degrees = θ }`")
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Rotation, A::Error> {
                Turn::deserialize(MapAccessDeserializer::new(map)).map(Rotation)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Rotation, A::Error> {
                let mut angles = Vec::new();
                while let Ok(Some(x)) = seq.next_element::<f64>() {
                    angles.push(x);
                    if angles.len() > 3 {
                        break;
                    }
                }
                Err(A::Error::custom(euler_angles(&angles)))
            }
        }
        d.deserialize_any(Table)
    }
}

/// What to write for POV-Ray's `rotate <x, y, z>` (`angles`, if three numbers): a turn
/// about x, then about y, then about z, as steps; the turns of 0 left out.
fn euler_angles(angles: &[f64]) -> String {
    let three = angles.len() == 3;
    let still = three && angles.iter().all(|a| *a == 0.0);
    let turns: Vec<String> = (0..3)
        .filter(|&k| !three || still || angles[k] != 0.0)
        .map(|k| {
            let degrees = if three { angles[k].to_string() } else { ["x", "y", "z"][k].to_string() };
            let mut axis = ["0"; 3];
            axis[k] = "1";
            format!("{{ rotate = {{ axis = [{}], degrees = {degrees} }} }}", axis.join(", "))
        })
        .collect();
    format!(
        "`rotate` takes one turn, `{{ axis = [x, y, z], degrees = θ }}` (or `radians`, and `about = [x, y, z]`); POV-Ray's `rotate <x, y, z>` is three turns, about x, then y, then z: write the steps `transform = [{}]`",
        turns.join(", ")
    )
}

/// How far a motor may be from rigid, relative to its translation: the `e123i` part of
/// `M R̃` (zero for `M = T R`) over `|t|/2`. Coefficients typed to six or more digits pass.
const RIGID_TOLERANCE: f64 = 1e-6;

/// The rigid motor of coefficients `s, e12, e13, e23, e1i, e2i, e3i, e123i`, normalised and
/// rebuilt as `T R` exactly. Refused if it has no rotation part or is not rigid: a motor
/// `M = T R` has `M R̃ = 1 − ½ t ei`, with no `e123i` part.
pub(crate) fn rigid(c: [f64; 8]) -> Result<Motor, Invalid> {
    rebuild(c, RIGID_TOLERANCE)
}

/// A motor composed of rigid ones (a pose's turn and move, steps, one pose relative to
/// another), rebuilt as `T R` as [`rigid`] rebuilds one read from a file. It is rigid to
/// its rounding, which for a motion near the identity is not small beside its translation
/// (itself of the size of the rounding), so it is not checked.
pub(crate) fn rebuilt(m: Motor) -> Result<Motor, Invalid> {
    rebuild(m.to_array(), f64::INFINITY)
}

/// [`rigid`] with `M R̃`'s `e123i` part allowed up to `tolerance` times `|t|/2`.
fn rebuild(c: [f64; 8], tolerance: f64) -> Result<Motor, Invalid> {
    let m = Motor::from_array(c);
    let rotor = Rotor { s: m.s, e12: m.e12, e13: m.e13, e23: m.e23 };
    let weight = norm([rotor.e12, rotor.e13, rotor.e23]).hypot(rotor.s);
    if weight == 0.0 || !weight.is_finite() {
        return Err(Invalid::Value("the motor has no rotation part (s, e12, e13, e23 are all zero)"));
    }
    let (m, rotor) = (m.scale(1.0 / weight), rotor.scale(1.0 / weight));
    let p = m * rotor.reverse();
    let t = [p.e1i, p.e2i, p.e3i].map(|x| -2.0 * x);
    // (∞ · 0 is NaN, which passes: no tolerance, nothing refused.)
    if p.e123i.abs() > tolerance * norm(t) / 2.0 {
        return Err(Invalid::Value("the motor is not rigid: M R̃ has an e123i part (a motor is T R, T = 1 − ½ t ei)"));
    }
    Ok(Motor::from_rotor_translator(rotor, Translator::from_vector(t)))
}

impl Step {
    /// This step as a world motor.
    fn motor(&self) -> Result<Motor, Invalid> {
        match (&self.rotate, self.translate, self.motor) {
            (Some(r), None, None) => r.motor(),
            (None, Some(t), None) => Ok(shift(t.0)),
            (None, None, Some(m)) => rigid(m.0),
            _ => Err(Invalid::Value("a transform step takes exactly one of `rotate`, `translate`, `motor`")),
        }
    }
}

impl Rotation {
    /// This turn as a world motor.
    pub(crate) fn motor(&self) -> Result<Motor, Invalid> {
        let Rotation(turn) = self;
        let angle = match (turn.degrees, turn.radians) {
            (Some(d), None) => d.0.to_radians(),
            (None, Some(r)) => r.0,
            _ => return Err(Invalid::Value("a rotation takes exactly one of `degrees`, `radians`")),
        };
        let r = Motor::from(Rotor::from_axis_angle(turn.axis.0, angle)?);
        Ok(match turn.about {
            // About an axis through p: shift p to the origin, turn, shift back.
            Some(p) => shift(p.0) * r * shift(p.0.map(|x| -x)),
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
            compose(steps.get_ref().iter().map(|step| step.get_ref().motor().map_err(at(step.span(), "transform"))))
                .map(Some)
        }
        (Some(m), Some(_)) => {
            Err(Invalid::at("motor", m.span(), Invalid::Value("give `motor` or `transform`, not both")))
        }
    }
}

/// Motors composed in the order given (the first acts first), `V = V_n ⋯ V_1`: a
/// `transform`'s steps, and a pose's turn, then its move.
pub(crate) fn compose(steps: impl IntoIterator<Item = Result<Motor, Invalid>>) -> Result<Motor, Invalid> {
    let mut v = Motor::from(Rotor { s: 1.0, ..Rotor::zero() });
    for step in steps {
        v = step? * v;
    }
    Ok(v)
}

/// The translation by `t`, as a motor: `T = 1 − ½ t ei`.
pub(crate) fn shift(t: E3) -> Motor {
    Motor::from(Translator::from_vector(t))
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
