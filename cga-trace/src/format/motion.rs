//! Keyframes: `motion = [K0, K1, …]` on an object, an instance or the `[camera]`, at most
//! [`MAX_KEYS`], evenly spaced over the frame times 0 … 1 and interpolated by screw motion.
//!
//! Each key is a rigid motor `M = T R`, written as one of:
//! - its coefficients, `[s, e12, e13, e23, e1i, e2i, e3i, e123i]`;
//! - a pose, `{ position = [x, y, z], rotate = { axis, degrees } }` (either left out): turn,
//!   then move by `position`, `M = T(position) R`;
//! - an object's own placement fields, `{ transform = [steps] }` or `{ motor = [8 numbers] }`;
//! - on the camera, the camera's pose at that key, `{ position, look_at, up }`: the key is the
//!   motor `M = Q P̃` that takes the camera's own pose `P` to that pose `Q`, so that a key is
//!   applied after the camera's pose whichever way it is written.

use super::numbers::{Nums, V3, exactly};
use super::transform::{Rotation, Step, compose, rebuilt, rigid, shift, world_motor};
use crate::camera::Camera;
use crate::invalid::Invalid;
use cga_core::Motor;
use serde::de::{Error as _, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer};
use std::fmt;
use std::ops::Range;
use toml::Spanned;

/// Keyframes a `motion` list holds at most.
pub const MAX_KEYS: usize = 4096;

/// What a keyframe may be, as messages list it (the camera's may also be its pose).
const FORMS: &str = "a motor of 8 numbers `[s, e12, e13, e23, e1i, e2i, e3i, e123i]`, a pose `{ position = [x, y, z], rotate = { axis = [x, y, z], degrees = θ } }`, `{ transform = [steps] }` or `{ motor = [8 numbers] }`";

/// The keyframe forms an object's (`camera` false) or the camera's list takes.
struct Forms(bool);

impl fmt::Display for Forms {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(FORMS)?;
        if self.0 {
            f.write_str(", or the camera's pose `{ position = [x, y, z], look_at = [x, y, z], up = [x, y, z] }`")?;
        }
        Ok(())
    }
}

/// A `motion` list as read: its keys, each where it is written. `CAMERA` for the camera's,
/// whose keys may be camera poses.
pub(crate) struct Motion<const CAMERA: bool>(Vec<Spanned<Key<CAMERA>>>);

/// An object's or an instance's `motion`.
pub(crate) type ObjectMotion = Motion<false>;

/// The camera's `motion`.
pub(crate) type CameraMotion = Motion<true>;

/// One keyframe as written: coefficients, or a table (boxed: a list of motors stays small).
enum Key<const CAMERA: bool> {
    Motor(Nums<8>),
    Table(Box<KeyTable>),
}

/// A keyframe's table: a pose (`position`, `rotate`), the placement fields (`transform` or
/// `motor`), or the camera's pose (`position`, `look_at`, `up`).
#[derive(Default)]
struct KeyTable {
    position: Option<Spanned<V3>>,
    rotate: Option<Spanned<Rotation>>,
    transform: Option<Spanned<Vec<Spanned<Step>>>>,
    motor: Option<Spanned<Nums<8>>>,
    look_at: Option<Spanned<V3>>,
    up: Option<Spanned<V3>>,
}

impl<'de, const CAMERA: bool> Deserialize<'de> for Motion<CAMERA> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// The keys, refused past [`MAX_KEYS`] before the next is read.
        struct Keys<const CAMERA: bool>;
        impl<'de, const CAMERA: bool> Visitor<'de> for Keys<CAMERA> {
            type Value = Motion<CAMERA>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "a list of keyframes, each {}", Forms(CAMERA))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Motion<CAMERA>, A::Error> {
                let mut keys = Vec::with_capacity(seq.size_hint().unwrap_or(0).min(MAX_KEYS));
                while keys.len() < MAX_KEYS {
                    match seq.next_element()? {
                        Some(key) => keys.push(key),
                        None => return Ok(Motion(keys)),
                    }
                }
                let mut found = MAX_KEYS;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    found += 1;
                }
                if found > MAX_KEYS {
                    let why = Invalid::Limit { what: "keyframes", found: found as u64, limit: MAX_KEYS as u64 };
                    return Err(A::Error::custom(why));
                }
                Ok(Motion(keys))
            }
        }
        d.deserialize_seq(Keys::<CAMERA>)
    }
}

impl<'de, const CAMERA: bool> Deserialize<'de> for Key<CAMERA> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// An array of coefficients or a table, by what the file gives.
        struct Either<const CAMERA: bool>;
        impl<'de, const CAMERA: bool> Visitor<'de> for Either<CAMERA> {
            type Value = Key<CAMERA>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "a keyframe: {}", Forms(CAMERA))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Key<CAMERA>, A::Error> {
                exactly::<A, Coefficient, 8>(seq).map(|c| Key::Motor(Nums(c)))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Key<CAMERA>, A::Error> {
                let mut t = KeyTable::default();
                while let Some(FieldName::<CAMERA>(field)) = map.next_key()? {
                    match field {
                        Field::Position => t.position = Some(map.next_value()?),
                        Field::Rotate => t.rotate = Some(map.next_value()?),
                        Field::Transform => t.transform = Some(map.next_value()?),
                        Field::Motor => t.motor = Some(map.next_value()?),
                        Field::LookAt => t.look_at = Some(map.next_value()?),
                        Field::Up => t.up = Some(map.next_value()?),
                    }
                }
                Ok(Key::Table(Box::new(t)))
            }
        }
        d.deserialize_any(Either::<CAMERA>)
    }
}

/// A field of a keyframe's table.
#[derive(Clone, Copy)]
enum Field {
    Position,
    Rotate,
    Transform,
    Motor,
    LookAt,
    Up,
}

/// A keyframe table's key, looked up: `look_at` and `up` only in the camera's.
struct FieldName<const CAMERA: bool>(Field);

impl<'de, const CAMERA: bool> Deserialize<'de> for FieldName<CAMERA> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// The name, or what a keyframe takes instead.
        struct Name<const CAMERA: bool>;
        impl<const CAMERA: bool> Visitor<'_> for Name<CAMERA> {
            type Value = FieldName<CAMERA>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a keyframe's field")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<FieldName<CAMERA>, E> {
                let field = match name {
                    "position" => Field::Position,
                    "rotate" => Field::Rotate,
                    "transform" => Field::Transform,
                    "motor" => Field::Motor,
                    "look_at" if CAMERA => Field::LookAt,
                    "up" if CAMERA => Field::Up,
                    "look_at" | "up" => {
                        return Err(E::custom(format!(
                            "`{name}` is the camera's: a camera's keyframe may be its pose `{{ position, look_at, up }}`, an object's is {FORMS}"
                        )));
                    }
                    _ => {
                        let name = name.escape_debug();
                        return Err(E::custom(format!(
                            "unknown field `{name}` in a keyframe: a keyframe is {}",
                            Forms(CAMERA)
                        )));
                    }
                };
                Ok(FieldName(field))
            }
        }
        d.deserialize_identifier(Name::<CAMERA>)
    }
}

/// One of a motor key's coefficients: a number, or an error that says what a key is.
struct Coefficient(f64);

impl From<Coefficient> for f64 {
    fn from(c: Coefficient) -> f64 {
        c.0
    }
}

impl<'de> Deserialize<'de> for Coefficient {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        /// A number, integer or float.
        struct Number;
        impl Visitor<'_> for Number {
            type Value = Coefficient;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(
                    "a number: a keyframe written as an array is a motor of 8 numbers `[s, e12, e13, e23, e1i, e2i, e3i, e123i]` (a pose or steps are tables: `{ position, rotate }`, `{ transform = [steps] }`)",
                )
            }
            fn visit_f64<E>(self, x: f64) -> Result<Coefficient, E> {
                Ok(Coefficient(x))
            }
            fn visit_i64<E>(self, x: i64) -> Result<Coefficient, E> {
                Ok(Coefficient(x as f64))
            }
            fn visit_u64<E>(self, x: u64) -> Result<Coefficient, E> {
                Ok(Coefficient(x as f64))
            }
        }
        d.deserialize_f64(Number)
    }
}

impl<const CAMERA: bool> Key<CAMERA> {
    /// The key's rigid motor; `pose` is the camera's own, which a camera pose key is taken
    /// from.
    fn motor(&self, pose: Option<&Motor>) -> Result<Motor, Invalid> {
        match self {
            Key::Motor(c) => rigid(c.0),
            Key::Table(t) => t.motor(pose),
        }
    }
}

impl KeyTable {
    /// The key's rigid motor: its `motor` or `transform`, or its pose.
    fn motor(&self, pose: Option<&Motor>) -> Result<Motor, Invalid> {
        let given = world_motor(self.motor.as_ref(), self.transform.as_ref())?;
        let posed = [("position", &self.position), ("look_at", &self.look_at), ("up", &self.up)]
            .into_iter()
            .find_map(|(field, v)| v.as_ref().map(|v| (field, v.span())))
            .or(self.rotate.as_ref().map(|r| ("rotate", r.span())));
        match (given, posed) {
            (Some(_), Some((field, span))) => Err(Invalid::at(
                field,
                span,
                Invalid::Form("a keyframe is a pose (`position`, `rotate`) or `transform` or `motor`, not two of them"),
            )),
            // A `motor` is rigid already; steps are rebuilt as `T R`, as a motor key is.
            (Some(m), None) if self.motor.is_some() => Ok(m),
            (Some(m), None) => rebuilt(m),
            (None, _) => match (&self.look_at, pose) {
                (Some(target), Some(own)) => self.camera_pose(target, own),
                (Some(target), None) => Err(Invalid::at(
                    "look_at",
                    target.span(),
                    Invalid::Form("`look_at` is the camera's: an object's keyframe is a pose `{ position, rotate }`"),
                )),
                (None, _) => self.pose(),
            },
        }
    }

    /// `{ position, rotate }`: the turn, then the move, `M = T(position) R`, composed as the
    /// steps `[{ rotate }, { translate = position }]` are.
    fn pose(&self) -> Result<Motor, Invalid> {
        if let Some(up) = &self.up {
            return Err(Invalid::at(
                "up",
                up.span(),
                Invalid::Form("`up` goes with `look_at`: the camera's pose `{ position, look_at, up }`"),
            ));
        }
        let turn = self.rotate.as_ref().map(|r| r.get_ref().motor().map_err(|e| Invalid::at("rotate", r.span(), e)));
        let moved = self.position.as_ref().map(|p| Ok(shift(p.get_ref().0)));
        rebuilt(compose(turn.into_iter().chain(moved))?)
    }

    /// `{ position, look_at, up }` on the camera: the motor `Q P̃` that takes its own pose
    /// `P` to this one, `Q`.
    fn camera_pose(&self, target: &Spanned<V3>, own: &Motor) -> Result<Motor, Invalid> {
        let field = |field, span: Range<usize>, why: &'static str| Err(Invalid::at(field, span, Invalid::Form(why)));
        if let Some(r) = &self.rotate {
            return field(
                "rotate",
                r.span(),
                "a camera pose turns the camera to look at `look_at`: leave out `rotate`",
            );
        }
        let Some(position) = &self.position else {
            return field("look_at", target.span(), "a camera pose needs `position` as well as `look_at`");
        };
        let up = self.up.as_ref().map_or([0.0, 0.0, 1.0], |u| u.get_ref().0);
        let q = Camera::pose_look_at(position.get_ref().0, target.get_ref().0, up)
            .map_err(|e| Invalid::at("look_at", target.span(), e.into()))?;
        rebuilt(q * own.reverse())
    }
}

/// The motor of a `motion` list at `time` in [0, 1]: its keys evenly spaced over the frame
/// times, `M(t)` the screw motion between the two keys about `t` (`Motor::interpolate`:
/// constant screw velocity, through each key). `pose` is the camera's own (its keys may be
/// camera poses); `None` for an object's.
pub(crate) fn motion_at<const CAMERA: bool>(
    keys: &Spanned<Motion<CAMERA>>,
    time: f64,
    pose: Option<&Motor>,
) -> Result<Motor, Invalid> {
    let at = |reason| Invalid::at("motion", keys.span(), reason);
    let list = &keys.get_ref().0;
    if list.is_empty() {
        return Err(at(Invalid::Value("a motion needs at least one keyframe")));
    }
    let motors: Vec<Motor> = list
        .iter()
        .enumerate()
        .map(|(k, key)| {
            let keyframe = |e| Invalid::Indexed { what: "keyframe", index: k + 1, reason: Box::new(e) };
            key.get_ref().motor(pose).map_err(|e| Invalid::at("motion", key.span(), keyframe(e)))
        })
        .collect::<Result<_, _>>()?;
    if motors.len() == 1 {
        return Ok(motors[0]);
    }
    let x = time.clamp(0.0, 1.0) * (motors.len() - 1) as f64;
    let k = (x.floor() as usize).min(motors.len() - 2);
    Motor::interpolate(&motors[k], &motors[k + 1], x - k as f64)
        .map_err(|e| at(Invalid::Range(format!("keyframes {} and {} cannot be interpolated: {e}", k + 1, k + 2))))
}
