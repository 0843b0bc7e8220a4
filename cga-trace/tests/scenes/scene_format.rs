//! Scene files that speak CGA: an object moved by a motor or a list of transforms, or built
//! through points, renders as the same object given directly; and the image-size options keep
//! pixels square.

use cga_trace::{Aov, Renderer, Scene};

const CAMERA: &str = "[camera]\nposition = [2.0, -12.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 64\nheight = 48\n";
const LIGHT: &str = "[[lights]]\nposition = [-6.0, -10.0, 14.0]\n";
const MATERIAL: &str = "material = { colour = [0.8, 0.5, 0.2], kr = 0.3 }\n";

/// The 8-bit image of a scene holding a floor and `object` (TOML lines of one object).
fn image(object: &str) -> Vec<u8> {
    let text = format!(
        "{CAMERA}{LIGHT}[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, -3.0]\nnormal = [0.0, 0.0, 1.0]\n{MATERIAL}\
         [[objects]]\n{MATERIAL}{object}"
    );
    let scene = Scene::parse(&text, "test.toml").unwrap_or_else(|e| panic!("{e}\n{text}"));
    Renderer::new(&scene).render(Aov::Shaded, &|| {}).to_rgb8(scene.settings.encoding).into_raw()
}

/// Channels that differ by more than one level between two renders of one object. A moved
/// or point-built object is the same object to rounding, which can flip a pixel only where a
/// ray grazes it.
fn differing(a: &[u8], b: &[u8]) -> usize {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).filter(|(x, y)| x.abs_diff(**y) > 1).count()
}

/// Each pair: the object given directly, and given another way. Allowed: one channel in
/// a thousand (9 of 9,216) off by more than a level.
fn same(cases: &[(&str, &str, &str)]) {
    for (what, direct, other) in cases {
        let (a, b) = (image(direct), image(other));
        let n = differing(&a, &b);
        println!("{what}: {n} channels differ by more than a level");
        assert!(n <= a.len() / 1000, "{what}: {n} channels differ");
        // And the object is in the picture: it differs from the floor alone.
        assert!(differing(&a, &image("type = \"sphere\"\ncentre = [0.0, 0.0, 40.0]\nradius = 0.1\n")) > 100, "{what}");
    }
}

#[test]
fn moved_objects_render_as_the_object_given_there() {
    same(&[
        (
            "sphere, translated",
            "type = \"sphere\"\ncentre = [1.0, 2.0, 0.5]\nradius = 1.5\n",
            "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.5\ntransform = [{ translate = [1.0, 2.0, 0.5] }]\n",
        ),
        (
            "sphere, turned about a point then moved by a motor",
            "type = \"sphere\"\ncentre = [0.0, 1.0, 0.0]\nradius = 1.0\n",
            // About the axis z through (1, 0, 0), 180°: (2, 0, 0) goes to (0, 0, 0); then the
            // motor of a translation by (0, 1, 0): T = 1 − ½ e2i.
            "type = \"sphere\"\ncentre = [2.0, 0.0, 0.0]\nradius = 1.0\ntransform = [\
             { rotate = { axis = [0.0, 0.0, 1.0], degrees = 180.0, about = [1.0, 0.0, 0.0] } },\
             { motor = [1.0, 0.0, 0.0, 0.0, 0.0, -0.5, 0.0, 0.0] }]\n",
        ),
        (
            "disk, rotated 90° about x then translated, as one motor",
            "type = \"disk\"\ncentre = [0.0, 1.0, 1.0]\nnormal = [0.0, -1.0, 0.0]\nradius = 2.0\n",
            // R = cos 45° − sin 45° e23 turns e3 to −e2 about x; T R with t = (0, 1, 1).
            &format!(
                "type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 2.0\nmotor = {}\n",
                motor_toml(std::f64::consts::FRAC_PI_2, [1.0, 0.0, 0.0], [0.0, 1.0, 1.0])
            ),
        ),
        (
            "plane, tilted",
            // (0, 0, −4) turned by 45° about x is (0, 2√2, −2√2).
            "type = \"plane\"\npoint = [0.0, 2.8284271247461903, -2.8284271247461903]\nnormal = [0.0, -1.0, 1.0]\n",
            "type = \"plane\"\npoint = [0.0, 0.0, -4.0]\nnormal = [0.0, 0.0, 1.0]\ntransform = [{ rotate = { axis = [1.0, 0.0, 0.0], radians = 0.7853981633974483 } }]\n",
        ),
        (
            "triangle, rotated about z",
            "type = \"triangle\"\ncorners = [[0.0, 1.0, 0.0], [-4.0, 1.0, 0.0], [0.0, 1.0, 4.0]]\n",
            "type = \"triangle\"\ncorners = [[1.0, 0.0, 0.0], [1.0, 4.0, 0.0], [1.0, 0.0, 4.0]]\ntransform = [{ rotate = { axis = [0.0, 0.0, 1.0], degrees = 90.0 } }]\n",
        ),
        (
            "evolved surface, each circle and the whole moved",
            "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, -1.0], normal = [0.0, 0.0, 1.0], radius = 2.0 }\n\
             c2 = { centre = [1.0, 0.0, 2.0], normal = [1.0, 0.0, 1.0], radius = 1.0 }\n",
            "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 2.0, transform = [{ translate = [0.0, 0.0, -2.0] }] }\n\
             c2 = { centre = [1.0, 0.0, 1.0], normal = [1.0, 0.0, 1.0], radius = 1.0 }\n\
             transform = [{ translate = [0.0, 0.0, 1.0] }]\n",
        ),
    ]);
}

#[test]
fn objects_through_points_render_as_the_object_given_directly() {
    same(&[
        (
            "sphere through four points",
            "type = \"sphere\"\ncentre = [1.0, 0.0, 0.5]\nradius = 2.0\n",
            "type = \"sphere\"\npoints = [[3.0, 0.0, 0.5], [1.0, 2.0, 0.5], [1.0, 0.0, 2.5], [-1.0, 0.0, 0.5]]\n",
        ),
        (
            "plane through three points",
            "type = \"plane\"\npoint = [0.0, 5.0, 0.0]\nnormal = [0.0, -1.0, 0.0]\n",
            "type = \"plane\"\npoints = [[0.0, 5.0, 0.0], [0.0, 5.0, 1.0], [1.0, 5.0, 0.0]]\n",
        ),
        (
            "disk through three points",
            "type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, -1.0, 1.0]\nradius = 2.0\n",
            // On the circle of centre 0, radius 2, in the plane y = z.
            &format!(
                "type = \"disk\"\npoints = [[2.0, 0.0, 0.0], [0.0, {s}, {s}], [-2.0, 0.0, 0.0]]\n",
                s = 2f64.sqrt()
            ),
        ),
        (
            "evolved surface through a circle of points",
            "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, -1.0], normal = [0.0, 0.0, 1.0], radius = 2.0 }\n\
             c2 = { centre = [1.0, 0.0, 2.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n",
            "type = \"evolved\"\nc1 = { points = [[2.0, 0.0, -1.0], [0.0, 2.0, -1.0], [-2.0, 0.0, -1.0]] }\n\
             c2 = { centre = [1.0, 0.0, 2.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n",
        ),
    ]);
}

/// The motor `T R` turning by `angle` about the unit `axis` through the origin and then
/// shifting by `t`, as a TOML array `[s, e12, e13, e23, e1i, e2i, e3i, e123i]`, written out
/// from the product here so that the scene's motor is checked against a hand computation.
fn motor_toml(angle: f64, axis: [f64; 3], t: [f64; 3]) -> String {
    let r = cga_trace::cga_core::Rotor::from_axis_angle(axis, angle).unwrap();
    let m = cga_trace::cga_core::Translator::from_vector(t) * r;
    format!("{:?}", m.to_array())
}

#[test]
fn resizing_keeps_pixels_square_unless_both_extents_are_pinned() {
    let free = format!("{CAMERA}x_max = 1.6\n");
    let mut scene = Scene::parse(&free, "t.toml").unwrap();
    assert_eq!(scene.resize(Some(100), Some(30)).unwrap(), None);
    let c = scene.camera;
    assert!((c.x_max / 100.0 - c.y_max / 30.0).abs() < 1e-15, "square pixels");
    // Only a width: the height follows the image's aspect (64 × 48).
    let mut scene = Scene::parse(&free, "t.toml").unwrap();
    scene.resize(Some(1280), None).unwrap();
    assert_eq!((scene.camera.width, scene.camera.height), (1280, 960));
    // Both pinned: kept, and said.
    let pinned = format!("{CAMERA}x_max = 1.6\ny_max = 1.2\n");
    let mut scene = Scene::parse(&pinned, "t.toml").unwrap();
    let note = scene.resize(Some(100), Some(30)).unwrap().expect("a note");
    assert!(note.contains("x_max and y_max"), "{note}");
    assert_eq!((scene.camera.x_max, scene.camera.y_max), (1.6, 1.2));
    // The field of view instead of x_max.
    let fov = Scene::parse(&format!("{CAMERA}fov = 90.0\n"), "t.toml").unwrap();
    assert!((fov.camera.x_max - 2.0).abs() < 1e-15);
    // The shipped combined scene: --width 1280 gives 1280 × 960, not 961.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/combined.toml");
    let mut combined = Scene::load(&path).unwrap();
    combined.resize(Some(1280), None).unwrap();
    assert_eq!((combined.camera.width, combined.camera.height), (1280, 960));
    // Too large: refused before anything is allocated.
    assert!(combined.resize(Some(100_000), Some(100_000)).is_err());
}

/// Every TOML example in the README and the scene-format guide (`docs/SCENES.md`) parses
/// (those without a camera, with one after their top-level keys), the files they name read
/// beside the shipped scenes.
#[test]
fn the_documented_examples_are_valid_scenes() {
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let file = here.join("scenes/README.md");
    for doc in ["../README.md", "../docs/SCENES.md"] {
        let text = std::fs::read_to_string(here.join(doc)).unwrap();
        let blocks: Vec<&str> = text.split("```toml\n").skip(1).map(|b| b.split("```").next().unwrap()).collect();
        assert!(!blocks.is_empty(), "{doc} has scene examples");
        for block in blocks {
            let tables = block.find("\n[").map_or(block.len(), |k| k + 1);
            let (keys, rest) = block.split_at(if block.starts_with('[') { 0 } else { tables });
            let text = if block.contains("[camera]") { block.to_string() } else { format!("{keys}{CAMERA}{rest}") };
            if let Err(e) = Scene::parse(&text, file.to_str().unwrap()) {
                panic!("{doc}: {e}\n{text}");
            }
        }
    }
}

/// The first scene (the README's taste of a scene, and the guide's first scene: the same
/// block) renders as they say: the ball red at the image's centre, the floor grey (equal
/// channels) at the bottom, black sky at the top.
#[test]
fn the_first_scene_renders_a_red_ball_on_a_grey_floor() {
    let read = |doc: &str| std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(doc)).unwrap();
    let first = |text: &str, heading: &str| -> String {
        let section = text.split(heading).nth(1).unwrap_or_else(|| panic!("a section {heading}"));
        section.split("```toml\n").nth(1).and_then(|b| b.split("```").next()).unwrap().to_string()
    };
    let block = first(&read("../docs/SCENES.md"), "## Your first scene");
    assert_eq!(block, first(&read("../README.md"), "## A taste of a scene"), "the README's scene is the guide's");
    let mut scene = Scene::parse(&block, "first.toml").unwrap();
    scene.resize(Some(32), Some(24)).unwrap();
    let film = Renderer::new(&scene).render(Aov::Shaded, &|| {});
    // Rows from the bottom, as the film stores them.
    let at = |i: usize, j: usize| film.pixels[j * 32 + i];
    let ball = at(16, 12);
    assert!(ball[0] > 4.0 * ball[1].max(ball[2]) && ball[0] > 0.2, "the ball is red: {ball:?}");
    let floor = at(3, 1);
    assert!(floor[0] > 0.05 && (floor[0] - floor[1]).abs() < 1e-12 && (floor[1] - floor[2]).abs() < 1e-12, "{floor:?}");
    assert_eq!(at(3, 23), [0.0; 3], "the sky is the background");
}

/// `caps = true` closes a swept surface with its end circles' disks: the same picture as the
/// surface and two `disk` objects, and different from the open surface (whose inside shows).
#[cfg(feature = "evolved")]
#[test]
fn caps_close_swept_surfaces_with_their_end_disks() {
    let (c1, c2) = (
        "{ centre = [0.0, 0.0, -1.0], normal = [0.0, 0.3, 1.0], radius = 1.5 }",
        "{ centre = [0.5, 0.0, 1.5], normal = [0.2, 0.0, 1.0], radius = 1.0 }",
    );
    let disks = format!(
        "[[objects]]\n{MATERIAL}type = \"disk\"\ncentre = [0.0, 0.0, -1.0]\nnormal = [0.0, 0.3, 1.0]\nradius = 1.5\n\
         [[objects]]\n{MATERIAL}type = \"disk\"\ncentre = [0.5, 0.0, 1.5]\nnormal = [0.2, 0.0, 1.0]\nradius = 1.0\n"
    );
    for surface in [
        format!("type = \"evolved\"\nc1 = {c1}\nc2 = {c2}\n"),
        format!(
            "type = \"spline\"\ncircles = [{c1}, {{ centre = [0.3, 0.2, 0.3], normal = [0.0, 0.0, 1.0], radius = 1.2 }}, {c2}]\n"
        ),
    ] {
        let capped = image(&format!("{surface}caps = true\n"));
        let open = image(&surface);
        let with_disks = image(&format!("{surface}{disks}"));
        assert!(differing(&capped, &with_disks) <= 9, "{surface}");
        let shown = differing(&capped, &open);
        println!("{shown} channels differ from the open surface");
        assert!(shown > 20, "{surface}: the caps are in view");
    }
}

#[test]
fn a_scene_without_lights_gets_a_note() {
    let dark = Scene::parse(
        &format!("{CAMERA}[[objects]]\n{MATERIAL}type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n"),
        "dark.toml",
    )
    .unwrap();
    assert!(dark.notes().iter().any(|n| n.starts_with("the scene has no lights")), "{:?}", dark.notes());
    let lit = Scene::parse(&format!("{CAMERA}{LIGHT}"), "lit.toml").unwrap();
    assert!(lit.notes().is_empty());
}

/// `[materials.NAME]` tables, given by name, render as the same material written inline.
#[test]
fn named_materials_render_as_written_inline() {
    let sphere = "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 2.0\n";
    let named = format!(
        "{CAMERA}{LIGHT}[materials.copper]\ncolour = [0.8, 0.5, 0.2]\nkr = 0.3\n\n[[objects]]\nmaterial = \"copper\"\n{sphere}"
    );
    let scene = Scene::parse(&named, "named.toml").unwrap_or_else(|e| panic!("{e}"));
    let film = Renderer::new(&scene).render(Aov::Shaded, &|| {}).to_rgb8(scene.settings.encoding).into_raw();
    let inline = format!("{CAMERA}{LIGHT}[[objects]]\n{MATERIAL}{sphere}");
    let scene = Scene::parse(&inline, "inline.toml").unwrap();
    assert_eq!(film, Renderer::new(&scene).render(Aov::Shaded, &|| {}).to_rgb8(scene.settings.encoding).into_raw());
}

fn motor_of(m: cga_core::Motor) -> String {
    let c = [m.s, m.e12, m.e13, m.e23, m.e1i, m.e2i, m.e3i, m.e123i];
    format!("[{}]", c.map(|x| format!("{x:?}")).join(", "))
}

/// Keyframed motion: at each key's time an object (and the camera) stands where that key's
/// motor puts it, and between keys where the screw motion between them does.
#[test]
fn keyframed_motors_pass_through_their_keys() {
    use cga_core::{Line, Motor};
    let axis = Line::new([0.5, 0.0, 0.0], [0.2, 0.3, 1.0]).unwrap();
    let keys = [0.0, 1.2, 2.0].map(|a| Motor::screw(&axis, a, 0.4).unwrap());
    let list = keys.map(motor_of).join(", ");
    let cam = Motor::from_translation([0.3, -0.5, 0.2]);
    let box_ = "type = \"box\"\nmin = [-3.0, -1.5, -1.0]\nmax = [3.0, 1.5, 1.0]\n";
    let file = |object: &str, camera: &str| {
        format!(
            "[camera]\nposition = [2.0, -12.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 64\nheight = 48\n{camera}{LIGHT}[[objects]]\n{MATERIAL}{object}"
        )
    };
    let picture = |text: &str, time: f64| {
        let scene = cga_trace::Source::parse(text, "motion.toml")
            .and_then(|mut s| s.scene(None, time))
            .unwrap_or_else(|e| panic!("{e}"));
        Renderer::new(&scene).render(Aov::Shaded, &|| {}).to_rgb8(scene.settings.encoding).into_raw()
    };
    let moving = file(
        &format!("{box_}motion = [{list}]\n"),
        &format!("motion = [{}, {}]\n", motor_of(Motor::identity()), motor_of(cam)),
    );
    for (k, time) in [0.0, 0.5, 1.0].into_iter().enumerate() {
        let camera_at = Motor::interpolate(&Motor::identity(), &cam, time).unwrap();
        let fixed =
            file(&format!("{box_}motor = {}\n", motor_of(keys[k])), &format!("motion = [{}]\n", motor_of(camera_at)));
        assert!(differing(&picture(&moving, time), &picture(&fixed, 0.0)) <= 9, "key {k}");
    }
    // A quarter of the way: the screw motion between the first two keys.
    let between = Motor::interpolate(&keys[0], &keys[1], 0.5).unwrap();
    let camera_at = Motor::interpolate(&Motor::identity(), &cam, 0.25).unwrap();
    let fixed =
        file(&format!("{box_}motor = {}\n", motor_of(between)), &format!("motion = [{}]\n", motor_of(camera_at)));
    assert!(differing(&picture(&moving, 0.25), &picture(&fixed, 0.0)) <= 9);
    let moved = differing(&picture(&moving, 0.0), &picture(&moving, 0.25));
    assert!(moved > 100, "it moves: {moved} channels");
}

/// A spot light lights its cone as a point light there does (full within `radius` of its
/// axis) and nothing beyond `falloff`, with a smooth step between.
#[test]
fn a_spot_light_lights_its_cone_and_nothing_beyond() {
    let camera = "[camera]\nposition = [0.0, -0.001, 20.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 64\nheight = 64\n[render]\nambient = 0.0\n";
    let floor = "[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = { colour = [1.0, 1.0, 1.0], ks = 0.0 }\n";
    let film = |light: &str| {
        let scene = Scene::parse(&format!("{camera}{light}{floor}"), "spot.toml").unwrap_or_else(|e| panic!("{e}"));
        Renderer::new(&scene).render(Aov::Shaded, &|| {})
    };
    // Above the origin at height 10: radius 20° reaches 3.64 from the axis, falloff 30° 5.77.
    let spot =
        film("[[lights]]\nposition = [0.0, 0.0, 10.0]\ndirection = [0.0, 0.0, -1.0]\nradius = 20.0\nfalloff = 30.0\n");
    let point = film("[[lights]]\nposition = [0.0, 0.0, 10.0]\n");
    let camera_scene = Scene::parse(&format!("{camera}{floor}"), "c.toml").unwrap();
    let (mut inside, mut outside, mut between) = (0, 0, 0);
    for j in 0..64 {
        for i in 0..64 {
            let ray = camera_scene.camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5).unwrap();
            // Where the pixel's ray meets the floor, in world coordinates.
            let floor_z = camera_scene.frame.point([0.0; 3])[2];
            let x = camera_scene.frame.world_point(ray.at((floor_z - ray.origin[2]) / ray.dir[2]));
            let r = x[0].hypot(x[1]);
            let (s, p) = (spot.get(i, j)[0], point.get(i, j)[0]);
            if r < 3.6 {
                assert_eq!(s, p, "inside the hot spot at r = {r}");
                inside += 1;
            } else if r > 5.8 {
                assert_eq!(s, 0.0, "beyond the falloff at r = {r}");
                outside += 1;
            } else if r > 3.7 && r < 5.7 {
                assert!(s > 0.0 && s < p, "the penumbra at r = {r}: {s} of {p}");
                between += 1;
            }
        }
    }
    assert!(inside > 100 && outside > 100 && between > 100, "{inside} {outside} {between}");
}

/// Between two facing mirrors that also shade themselves (colour 1 under ambient 1), the
/// paper's additive reflection sums `1 + k_r + k_r² + …` (about 1/(1 − k_r)); the conserving
/// one weights each surface's own colour by `1 − k_r`, so no pixel exceeds the light a
/// surface gets (a furnace test: 1).
#[test]
fn conserving_reflection_never_makes_more_light_than_it_receives() {
    let scene = |reflection: &str| {
        let text = format!(
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [1.0, 0.0, 0.2]\nwidth = 32\nheight = 24\n\
             [render]\nambient = 1.0\nmax_depth = 200\nreflection = \"{reflection}\"\n\
             [[objects]]\ntype = \"plane\"\npoint = [3.0, 0.0, 0.0]\nnormal = [-1.0, 0.0, 0.0]\nmaterial = {{ colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0, kr = 0.9 }}\n\
             [[objects]]\ntype = \"plane\"\npoint = [-3.0, 0.0, 0.0]\nnormal = [1.0, 0.0, 0.0]\nmaterial = {{ colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0, kr = 0.9 }}\n"
        );
        let scene = Scene::parse(&text, "mirrors.toml").unwrap();
        let film = Renderer::new(&scene).render(Aov::Shaded, &|| {});
        film.pixels.iter().flatten().fold(0.0f64, |m, &v| m.max(v))
    };
    let (additive, conserving) = (scene("additive"), scene("conserving"));
    assert!(additive > 5.0, "{additive}");
    assert!(conserving <= 1.0 + 1e-12 && conserving > 0.99, "{conserving}");
}

/// A blade named in either basis is the object it spells: the point (1, 0, 0) as
/// `e1 + eo + ½ ei` and as `e1 + e5` (`eo = ½(e5 − e4)`, `ei = e4 + e5`), names shared by both
/// bases (`e1`) kept in either.
#[test]
fn blades_named_in_either_basis_draw_the_object_they_spell() {
    let point = image("type = \"point\"\npoint = [1.0, 0.0, 0.0]\nsize = 0.5\n");
    let null = image("type = \"blade\"\nblade = { e1 = 1.0, eo = 1.0, ei = 0.5 }\nsize = 0.5\n");
    let ortho = image("type = \"blade\"\nblade = { e1 = 1.0, e5 = 1.0 }\nsize = 0.5\n");
    assert!(differing(&point, &null) <= 9 && differing(&point, &ortho) <= 9);
    // A circle given by centre, normal and radius counts in the scene's extent (its default
    // tube is a fraction of it): the same picture with and without an explicit tube of that.
    let circle = "type = \"circle\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.3, 1.0]\nradius = 3.0\n";
    assert!(differing(&image(circle), &image(&format!("{circle}tube = {:?}\n", 3.0 / 150.0))) <= 9);
}

/// A `csg` object is one scene object per part, each in its own material (a part without one
/// takes the tree's), its parts moved by their own motors before the tree's; a glass tree is
/// one solid (its parts share the medium light enters and leaves).
#[test]
fn csg_parts_keep_their_materials_and_glass_is_one_body() {
    let text = format!(
        "{CAMERA}[[objects]]\nname = \"cut\"\ntype = \"csg\"\noperation = \"difference\"\nmaterial = {{ colour = [1.0, 0.0, 0.0] }}\n\
         objects = [{{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }}, \
         {{ type = \"box\", min = [0.0, -2.0, 0.0], max = [2.0, 2.0, 2.0], material = {{ colour = [0.0, 0.0, 1.0] }} }}]\n\
         [[objects]]\nname = \"lens\"\ntype = \"csg\"\noperation = \"intersection\"\nmaterial = {{ colour = [1.0, 1.0, 1.0], ior = 1.5 }}\n\
         objects = [{{ type = \"sphere\", centre = [3.0, 0.0, 0.0], radius = 1.0 }}, {{ type = \"sphere\", centre = [3.5, 0.0, 0.0], radius = 1.0 }}]\n"
    );
    let scene = Scene::parse(&text, "csg.toml").unwrap();
    let colours: Vec<[f64; 3]> =
        scene.objects.iter().filter(|o| &*o.name == "cut").map(|o| o.material.colour).collect();
    assert_eq!(colours, [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    let lens: Vec<_> = scene.objects.iter().filter(|o| &*o.name == "lens").collect();
    assert_eq!(lens.len(), 2);
    assert!(
        lens[0].solid.is_some() && lens[0].solid == lens[1].solid,
        "{:?}",
        lens.iter().map(|o| o.solid).collect::<Vec<_>>()
    );
}

/// The nearest crossing of a ray from `o` along `d` (in the world) with the objects named
/// `name`: its `t` (world lengths), its normal and the colour of the part it lies on.
fn nearest_on(scene: &Scene, name: &str, o: [f64; 3], d: [f64; 3]) -> Option<(f64, [f64; 3], [f64; 3])> {
    // Shapes lie in the scene's frame: lengths there are the world's over its scale.
    let r = cga_trace::ray::Ray::new(scene.frame.point(o), d).unwrap();
    let hits = scene.objects.iter().filter(|o| &*o.name == name).filter_map(|o| {
        let hit = o.shape.hit(&r, 0.0, f64::INFINITY)?;
        Some((scene.frame.world_length(hit.t), hit.normal, o.material.colour))
    });
    hits.min_by(|a, b| a.0.total_cmp(&b.0))
}

/// A closed mesh (a box in an .obj file, one face of it wound the other way) and an
/// evolved surface with `caps = true` are CSG parts: the crossings are the solids', on the
/// part whose material they show; a mesh that does not close (a face left out) and a
/// surface without caps are refused.
#[test]
fn closed_meshes_and_capped_swept_surfaces_are_csg_parts() {
    let dir = tempfile::tempdir().unwrap();
    // The box [0, 2] × [−2, 2] × [0, 2].
    let corners = "v 0 -2 0\nv 2 -2 0\nv 2 2 0\nv 0 2 0\nv 0 -2 2\nv 2 -2 2\nv 2 2 2\nv 0 2 2\n";
    let faces = [
        "f 1 3 2\nf 1 4 3\n",
        "f 5 6 7\nf 5 7 8\n",
        "f 1 2 6\nf 1 6 5\n",
        "f 2 3 7\nf 2 7 6\n",
        "f 3 4 8\nf 3 8 7\n",
        "f 4 1 5\nf 4 8 5\n",
    ];
    std::fs::write(dir.path().join("box.obj"), format!("{corners}{}", faces.concat())).unwrap();
    std::fs::write(dir.path().join("open.obj"), format!("{corners}{}", faces[1..].concat())).unwrap();
    let scene = |objects: &str| {
        let path = dir.path().join("s.toml");
        std::fs::write(&path, format!("{CAMERA}{objects}")).unwrap();
        Scene::load(&path)
    };
    let mesh_cut = "[[objects]]\nname = \"cut\"\ntype = \"csg\"\noperation = \"difference\"\nmaterial = { colour = [1.0, 0.0, 0.0] }\n\
         objects = [{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }, \
         { type = \"mesh\", file = \"box.obj\", material = { colour = [0.0, 0.0, 1.0] } }]\n";
    let swept = "[[objects]]\nname = \"tube\"\ntype = \"csg\"\noperation = \"difference\"\nmaterial = { colour = [0.0, 1.0, 0.0] }\n\
         objects = [{ type = \"evolved\", c1 = { centre = [5.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }, \
         c2 = { centre = [5.0, 0.0, 2.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }, caps = true }, \
         { type = \"sphere\", centre = [5.0, 0.0, 2.0], radius = 0.5, material = { colour = [1.0, 1.0, 0.0] } }]\n";
    let s = scene(&format!("{mesh_cut}{swept}")).unwrap();
    let near = |a: f64, b: f64| (a - b).abs() < 1e-9;
    // Down onto the cut quarter: the box's floor z = 0, on the mesh's part.
    let (t, n, colour) = nearest_on(&s, "cut", [0.5, -0.3, 5.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(near(t, 5.0) && colour == [0.0, 0.0, 1.0] && near(n[2], 1.0), "{t} {n:?} {colour:?}");
    // Down beside it: the sphere's own top.
    let (t, _, colour) = nearest_on(&s, "cut", [-0.5, -0.3, 5.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(near(t, 5.0 - (1.0f64 - 0.34).sqrt()) && colour == [1.0, 0.0, 0.0], "{t}");
    // Along the box's face x = 0 and through its edge (0, ·, 0): the sphere's rim.
    let (t, _, _) = nearest_on(&s, "cut", [-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]).unwrap();
    assert!(near(t, 4.0), "{t}");
    // Down the tube's axis: the cap's middle is cut away, the ball's floor inside shows.
    let (t, _, colour) = nearest_on(&s, "tube", [5.0, 0.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(near(t, 3.5) && colour == [1.0, 1.0, 0.0], "{t} {colour:?}");
    // Down beside the ball: the cap, on the tube's part, facing up.
    let (t, n, colour) = nearest_on(&s, "tube", [5.8, 0.0, 5.0], [0.0, 0.0, -1.0]).unwrap();
    assert!(near(t, 3.0) && colour == [0.0, 1.0, 0.0] && near(n[2], 1.0), "{t} {n:?} {colour:?}");
    // A mesh that does not close, a surface without caps.
    let open = scene(&mesh_cut.replace("box.obj", "open.obj")).unwrap_err().to_string();
    assert!(open.contains("bounds a solid") && open.contains("s.toml:"), "{open}");
    let uncapped = scene(&swept.replace("caps = true", "caps = false")).unwrap_err().to_string();
    assert!(uncapped.contains("bounds a solid"), "{uncapped}");
}
