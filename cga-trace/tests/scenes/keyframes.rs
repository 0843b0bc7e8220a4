//! Keyframes written every way a `motion` takes them — motor coefficients, poses
//! `{ position, rotate }`, `{ transform = [...] }`, `{ motor = [...] }` and the camera's
//! poses `{ position, look_at, up }`, mixed in one list too — place an object, an instance
//! and the camera alike at every time; a key is where its pose says; a scene keyed by motors
//! draws the same bytes as before; the limit on keys.

use cga_core::euclid::{E3, dot, norm, sub, unit};
use cga_core::{Motor, Rotor};
use cga_trace::camera::Camera;
use cga_trace::shapes::TriangleShape;
use cga_trace::{Aov, Renderer, Scene, Source};

/// How far apart two placements that are the same motion written two ways may lie: one
/// written as motor coefficients is rounded to them (and rebuilt as `T R`), one written as a
/// pose is composed from its turn and move; both are a few units from the origin.
const TOLERANCE: f64 = 1e-12;

/// The frame times each placement is compared at: the keys and between them.
const TIMES: [f64; 6] = [0.0, 0.2, 0.5, 0.7, 0.9, 1.0];

/// A keyframe as a pose: a turn of `degrees` about `axis` (through `about`, if given), then a
/// move by `position`.
struct Pose {
    axis: E3,
    degrees: f64,
    about: Option<E3>,
    position: E3,
}

const POSES: [Pose; 3] = [
    Pose { axis: [0.0, 0.0, 1.0], degrees: 0.0, about: None, position: [0.0, 0.0, 0.0] },
    Pose { axis: [0.3, 0.2, 1.0], degrees: 70.0, about: None, position: [1.5, -0.5, 0.8] },
    Pose { axis: [1.0, 1.0, 0.0], degrees: 150.0, about: Some([0.5, 0.0, 1.0]), position: [-1.0, 2.0, 0.3] },
];

impl Pose {
    /// Its motor, from the conventions alone: `M = T(position) R`, `R` about `about`
    /// (`T(c) R T(−c)`).
    fn motor(&self) -> Motor {
        let r = Motor::from(Rotor::from_axis_angle(self.axis, self.degrees.to_radians()).unwrap());
        let r = match self.about {
            Some(c) => Motor::from_translation(c) * r * Motor::from_translation(c.map(|x| -x)),
            None => r,
        };
        Motor::from_translation(self.position) * r
    }

    /// Its `rotate` table.
    fn rotate(&self) -> String {
        let about = self.about.map_or(String::new(), |c| format!(", about = {c:?}"));
        format!("{{ axis = {:?}, degrees = {:?}{about} }}", self.axis, self.degrees)
    }

    /// The key written as a pose table.
    fn pose(&self) -> String {
        format!("{{ position = {:?}, rotate = {} }}", self.position, self.rotate())
    }

    /// The key written as transform steps: the turn, then the move.
    fn steps(&self) -> String {
        format!("{{ transform = [{{ rotate = {} }}, {{ translate = {:?} }}] }}", self.rotate(), self.position)
    }
}

/// A motor's eight coefficients as a scene file writes them (shortest round trip).
fn coefficients(m: &Motor) -> String {
    format!("[{}]", m.to_array().map(|x| format!("{x:?}")).join(", "))
}

/// Each way of writing the keys `POSES`, by name: `motion = [ … ]`'s inside.
fn spellings() -> Vec<(&'static str, String)> {
    let each = |f: &dyn Fn(&Pose) -> String| POSES.iter().map(f).collect::<Vec<_>>().join(", ");
    let mixed = [coefficients(&POSES[0].motor()), POSES[1].pose(), POSES[2].steps()].join(", ");
    vec![
        ("motors", each(&|p| coefficients(&p.motor()))),
        ("motor tables", each(&|p| format!("{{ motor = {} }}", coefficients(&p.motor())))),
        ("poses", each(&|p| p.pose())),
        ("transforms", each(&|p| p.steps())),
        ("mixed", mixed),
    ]
}

const CAMERA: &str = "[camera]\nposition = [2.0, -12.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 32\nheight = 24\n";
const MATERIAL: &str = "material = { colour = [0.8, 0.5, 0.2] }\n";
const CORNERS: [E3; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.2], [0.3, 1.2, -0.4]];
/// The triangle's own transform, which its keys act after.
const OWN: &str = "transform = [{ rotate = { axis = [1.0, 0.0, 0.0], degrees = 20.0 } }]\n";

fn triangle() -> String {
    format!("type = \"triangle\"\ncorners = {CORNERS:?}\n{MATERIAL}{OWN}")
}

/// The scene `text` at frame time `time`.
fn at(text: &str, time: f64) -> Scene {
    Source::parse(text, "keys.toml").and_then(|mut s| s.scene(None, time)).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// The world corners of the scene's one triangle.
fn corners(scene: &Scene) -> [E3; 3] {
    let [object] = &scene.objects[..] else { panic!("one object, not {}", scene.objects.len()) };
    let triangle = object.shape.downcast_ref::<TriangleShape>().expect("a triangle");
    triangle.corners.map(|c| scene.frame.world_point(c))
}

/// The largest difference between two lists of points.
fn apart(a: &[E3], b: &[E3]) -> f64 {
    a.iter().zip(b).map(|(x, y)| norm(sub(*x, *y))).fold(0.0, f64::max)
}

/// The corners of the scene `scene(motion)` at each of [`TIMES`], for each spelling of the
/// keys: the same to the bit where the keys are the same motor (motors and motor tables;
/// poses and transforms, composed alike), within [`TOLERANCE`] across them; at the last
/// key, the corners moved by the object's own transform and then the key's motor.
fn placed_alike(scene: &dyn Fn(&str) -> String) {
    let placements: Vec<(&str, Vec<[E3; 3]>)> = spellings()
        .into_iter()
        .map(|(name, keys)| {
            let text = scene(&format!("motion = [{keys}]\n"));
            (name, TIMES.iter().map(|&t| corners(&at(&text, t))).collect())
        })
        .collect();
    let of = |name: &str| &placements.iter().find(|p| p.0 == name).expect("a spelling").1;
    assert_eq!(of("motors"), of("motor tables"), "a motor key as an array and as `{{ motor = … }}`");
    assert_eq!(of("poses"), of("transforms"), "a pose and its steps");
    for (name, placed) in &placements {
        for (k, (a, b)) in placed.iter().zip(of("motors")).enumerate() {
            let d = apart(a, b);
            assert!(d <= TOLERANCE, "{name} at t = {}: {d:e} from the motor keys", TIMES[k]);
        }
    }
    let own = Motor::from(Rotor::from_axis_angle([1.0, 0.0, 0.0], 20f64.to_radians()).unwrap());
    let last = CORNERS.map(|c| POSES[2].motor().move_point(own.move_point(c)));
    let d = apart(&of("poses")[TIMES.len() - 1], &last);
    assert!(d <= TOLERANCE, "the last key: {d:e} from T R applied after the object's own transform");
    let moved = apart(&of("poses")[0], &of("poses")[2]);
    assert!(moved > 0.5, "it moves: {moved}");
}

#[test]
fn an_objects_keys_place_it_alike_however_they_are_written() {
    placed_alike(&|motion| format!("{CAMERA}[[objects]]\n{}{motion}", triangle()));
}

#[test]
fn an_instances_keys_place_it_alike_however_they_are_written() {
    placed_alike(&|motion| {
        format!(
            "{CAMERA}[[objects]]\nname = \"part\"\ntemplate = true\ntype = \"triangle\"\ncorners = {CORNERS:?}\n{MATERIAL}\
             [[objects]]\ntype = \"instance\"\nof = \"part\"\n{OWN}{motion}"
        )
    });
}

/// A camera pose `(position, look_at, up)`.
type Sight = (E3, E3, E3);

/// The camera's poses at its keys (its own pose first, so that its first key stands still).
const SIGHTS: [Sight; 3] = [
    ([2.0, -12.0, 5.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
    ([4.0, -10.0, 6.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
    ([-3.0, -11.0, 2.0], [1.0, 0.0, 1.0], [0.1, 0.0, 1.0]),
];

/// Where the camera stands and which way it looks, in world coordinates.
fn camera_at(scene: &Scene) -> (E3, E3) {
    (scene.frame.origin, scene.camera.pose.move_direction([0.0, 1.0, 0.0]))
}

/// The camera's placements at [`TIMES`] under `motion`.
fn camera_path(motion: &str) -> Vec<(E3, E3)> {
    let text = format!("{CAMERA}{motion}[[objects]]\n{}", triangle());
    TIMES.iter().map(|&t| camera_at(&at(&text, t))).collect()
}

/// Camera poses as keys place the camera as the motors `Q P̃` that take its own pose `P` to
/// each do, and at each key it stands at that key's `position` looking at its `look_at`;
/// the poses and steps an object takes move the camera as their motors do.
#[test]
fn the_cameras_keys_place_it_alike_however_they_are_written() {
    let own = Camera::pose_look_at(SIGHTS[0].0, SIGHTS[0].1, SIGHTS[0].2).unwrap();
    // Written as `T R` (its rotor, its translation), as a file would give a rigid motor.
    let relative = |(p, t, u): &Sight| {
        let m = Camera::pose_look_at(*p, *t, *u).unwrap() * own.reverse();
        Motor::from_rotor_translation(m.rotor(), m.translation())
    };
    let sight = |(p, t, u): &Sight| format!("{{ position = {p:?}, look_at = {t:?}, up = {u:?} }}");
    let list = |f: &dyn Fn(&Sight) -> String| SIGHTS.iter().map(f).collect::<Vec<_>>().join(", ");
    let motors = camera_path(&format!("motion = [{}]\n", list(&|s| coefficients(&relative(s)))));
    let sights = camera_path(&format!("motion = [{}]\n", list(&sight)));
    let close = |a: &[(E3, E3)], b: &[(E3, E3)], what: &str| {
        for (k, ((p, d), (q, e))) in a.iter().zip(b).enumerate() {
            let off = norm(sub(*p, *q)).max(norm(sub(*d, *e)));
            assert!(off <= TOLERANCE, "{what} at t = {}: {off:e}", TIMES[k]);
        }
    };
    close(&sights, &motors, "camera poses against their motors");
    // At the keys (t = 0, 0.5, 1): where each pose says, looking where it says.
    for (k, time) in [0, 2, 5].into_iter().enumerate() {
        let (p, t, _) = SIGHTS[k];
        let (stands, looks) = sights[time];
        assert!(norm(sub(stands, p)) <= TOLERANCE * norm(p), "key {k} stands at {stands:?}, not {p:?}");
        let towards = unit(sub(t, p)).unwrap();
        assert!(dot(looks, towards) >= 1.0 - TOLERANCE, "key {k} looks along {looks:?}, not {towards:?}");
    }
    assert!(norm(sub(sights[0].0, sights[2].0)) > 1.0, "it moves");
    // An object's forms on the camera: a pose and its steps to the bit, their motors close.
    let poses = camera_path(&format!("motion = [{}]\n", POSES.map(|p| p.pose()).join(", ")));
    let steps = camera_path(&format!("motion = [{}]\n", POSES.map(|p| p.steps()).join(", ")));
    let motors = camera_path(&format!("motion = [{}]\n", POSES.map(|p| coefficients(&p.motor())).join(", ")));
    assert_eq!(poses, steps);
    close(&poses, &motors, "poses on the camera against their motors");
    // Mixed in one list.
    let mixed =
        format!("motion = [{}, {}, {}]\n", coefficients(&relative(&SIGHTS[0])), sight(&SIGHTS[1]), sight(&SIGHTS[2]));
    close(&camera_path(&mixed), &sights, "a mixed list");
}

/// `motion.toml` (a ring and a ball keyed by motors, and the camera still) with every key
/// written `{ motor = [...] }` draws the same bytes as written as arrays, at the keys and
/// between them: the table is the same motor, not one rounded again.
#[test]
fn motor_keys_as_tables_draw_the_same_bytes_as_arrays() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join("motion.toml");
    let text = std::fs::read_to_string(path).unwrap().replace("shutter = [0.0, 1.0]\n", "");
    let small = text.replace("width = 320\nheight = 240", "width = 48\nheight = 36").replace("spp = 32", "spp = 1");
    assert_ne!(small, text, "motion.toml's size and samples are as this test writes them");
    let tables = small
        .lines()
        .map(|line| match line.strip_prefix("motion = [").and_then(|l| l.strip_suffix(']')) {
            Some(keys) => format!("motion = [{}]", keys.replace("[", "{ motor = [").replace("]", "] }")),
            None => line.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    assert_eq!(tables.matches("{ motor = [").count(), 4, "{tables}");
    let bytes = |text: &str, time: f64| {
        let scene = at(text, time);
        Renderer::new(&scene).render(Aov::Shaded, &|| {}).to_rgb8(scene.settings.encoding).into_raw()
    };
    for time in [0.0, 0.35, 1.0] {
        assert!(bytes(&small, time) == bytes(&tables, time), "t = {time}");
    }
    assert!(bytes(&small, 0.0) != bytes(&small, 1.0), "it moves");
}

/// At most `MAX_KEYS` keys, of any form: one more is refused by count, at the list, before
/// the rest are kept.
#[test]
fn a_motion_holds_at_most_the_limit_of_keys() {
    use cga_trace::format::MAX_KEYS;
    let forms = ["[1, 0, 0, 0, 0, 0, 0, 0]", "{ position = [0.0, 0.0, 1.0] }", "{ transform = [] }", "{}"];
    let list = |n: usize| (0..n).map(|k| forms[k % forms.len()]).collect::<Vec<_>>().join(", ");
    let scene = |n: usize| format!("{CAMERA}[[objects]]\n{}motion = [{}]\n", triangle(), list(n));
    assert!(Scene::parse(&scene(MAX_KEYS), "keys.toml").is_ok());
    for n in [MAX_KEYS + 1, 100_000] {
        let err = Scene::parse(&scene(n), "keys.toml").err().map(|e| e.to_string()).unwrap_or_default();
        let says = format!("{n} keyframes exceed the limit of {MAX_KEYS}");
        assert!(err.starts_with("keys.toml:11:10:") && err.contains("`motion`") && err.contains(&says), "{err}");
    }
    let camera = |n: usize| format!("{CAMERA}motion = [{}]\n", list(n));
    let err = Scene::parse(&camera(MAX_KEYS + 1), "keys.toml").err().map(|e| e.to_string()).unwrap_or_default();
    assert!(err.starts_with("keys.toml:6:10:") && err.contains("4097 keyframes exceed the limit of 4096"), "{err}");
}

/// The guide's table of keyframes (`docs/SCENES.md`): each example loads, an object's on an
/// object and the camera's on the camera; the motor written out moves by (2, 0, 0), as it
/// says; and the pose example is the motor `[c, 0, 0, −c, −c, 0, 0, c]` (`c = cos 45°`)
/// that the guide gives for a quarter turn about x, then a move by 2 along x.
#[test]
fn the_guides_keyframe_examples_mean_what_it_says() {
    let guide = include_str!("../../../docs/SCENES.md");
    let table = guide.split("| key | means | example |").nth(1).expect("the table of keyframes");
    let examples: Vec<(bool, String)> = table
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|row| {
            let example = row.trim_end_matches('|').rsplit(" | ").next().unwrap().trim();
            let key = example.split('`').nth(1).expect("an example in backticks");
            (row.contains("the camera only"), key.to_string())
        })
        .collect();
    assert_eq!(examples.len(), 5, "{examples:?}");
    let placed = |key: &str| corners(&at(&format!("{CAMERA}[[objects]]\n{}motion = [{key}]\n", triangle()), 0.0));
    let still = placed("{}");
    for (camera, key) in &examples {
        if *camera {
            camera_path(&format!("motion = [{key}]\n"));
        } else {
            placed(key);
        }
    }
    let moved = placed(&examples[0].1);
    let by = (0..3).map(|k| sub(moved[k], still[k])).collect::<Vec<_>>();
    assert!(by.iter().all(|d| norm(sub(*d, [2.0, 0.0, 0.0])) <= TOLERANCE), "{by:?}");
    let c = 45f64.to_radians().cos();
    let motor = coefficients(&Motor::from_array([c, 0.0, 0.0, -c, -c, 0.0, 0.0, c]));
    let d = apart(&placed(&examples[1].1), &placed(&motor));
    assert!(d <= TOLERANCE, "the pose example is {d:e} from its motor");
}
