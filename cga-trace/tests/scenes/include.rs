//! `include`: a scene split over files is the scene written as one, and every error names
//! the file it is in, with that file's own line and column.

use cga_trace::Scene;
use std::path::Path;

const CAMERA: &str = "[camera]\nposition = [0.0, -12.0, 4.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 64\nheight = 48\n";
const MATERIALS: &str = "[materials.gold]\ncolour = [0.9, 0.7, 0.2]\nks = 0.6\n";
const LIGHTS: &str = "[[lights]]\nposition = [-6.0, -8.0, 12.0]\n";
const BALL: &str =
    "[[objects]]\nname = \"ball\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = \"gold\"\n";
const FLOOR: &str = "[[objects]]\nname = \"floor\"\ntype = \"plane\"\npoint = [0.0, 0.0, -1.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = \"gold\"\n";

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

fn load(dir: &Path, name: &str) -> Result<Scene, String> {
    Scene::load(&dir.join(name)).map_err(|e| e.to_string())
}

#[test]
fn included_files_give_the_scene_written_as_one() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The materials in one file, which includes the floor's; the ball in the scene.
    write(d, "looks.toml", &format!("include = [\"floor.toml\"]\n{MATERIALS}{LIGHTS}"));
    write(d, "floor.toml", FLOOR);
    write(d, "split.toml", &format!("include = [\"looks.toml\"]\n{CAMERA}{BALL}"));
    let split = load(d, "split.toml").unwrap();
    // Objects in reading order: each included file's (in the order listed, their own
    // includes first), then the including file's own.
    let names = |s: &Scene| s.objects.iter().map(|o| o.name.to_string()).collect::<Vec<_>>();
    assert_eq!(names(&split), vec!["floor".to_string(), "ball".into()]);
    write(d, "one.toml", &format!("{CAMERA}{MATERIALS}{LIGHTS}{FLOOR}{BALL}"));
    let one = load(d, "one.toml").unwrap();
    assert_eq!(format!("{:?}", one.objects), format!("{:?}", split.objects));
    assert_eq!(format!("{:?}", one.lights), format!("{:?}", split.lights));
}

#[test]
fn a_scene_instances_the_templates_of_the_files_it_includes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The included file's template, read before the scene's own objects, is there to copy;
    // a byte-order mark at its start is no error.
    let template = BALL.replace("name = \"ball\"", "name = \"ball\"\ntemplate = true");
    write(d, "parts.toml", &format!("\u{feff}{MATERIALS}{template}"));
    let copy = "[[objects]]\ntype = \"instance\"\nof = \"ball\"\nname = \"copy\"\ntransform = [{ translate = [2.0, 0.0, 0.0] }]\n";
    write(d, "scene.toml", &format!("include = [\"parts.toml\"]\n{CAMERA}{LIGHTS}{copy}"));
    let scene = load(d, "scene.toml").unwrap();
    assert_eq!(scene.objects.iter().map(|o| &*o.name).collect::<Vec<_>>(), ["copy"]);
}

#[test]
fn errors_name_the_included_file_and_its_own_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scene = |parts: &str| format!("include = [\"{parts}\"]\n{CAMERA}{MATERIALS}");
    let cases: [(&str, String, String); 10] = [
        // A bad radius on the fifth line of the included file.
        ("bad.toml", BALL.replace("radius = 1.0", "radius = -1.0"), "bad.toml:5:".into()),
        ("typo.toml", BALL.replace("centre", "center"), "typo.toml:4:".into()),
        ("camera.toml", format!("{LIGHTS}{CAMERA}"), "camera.toml:3:2: `camera` belongs in the scene file".into()),
        ("cycle.toml", "include = [\"cycle.toml\"]\n".into(), "cycle.toml:1:12: `cycle.toml` is being read".into()),
        ("missing.toml", "include = [\"nowhere.toml\"]\n".into(), "missing.toml:1:12: include `nowhere.toml`".into()),
        ("list.toml", "include = \"x.toml\"\n".into(), "list.toml:1:1: `include`: give a list of file names".into()),
        // A key-value before the file's first table would join the including file's last table.
        (
            "keys.toml",
            format!("lights = []\n{BALL}"),
            "keys.toml:1:1: `lights` is given as a key outside a table".into(),
        ),
        // A table that would add to the including file's last object.
        (
            "adds.toml",
            "[objects.material]\ncolour = [1.0, 0.0, 0.0]\n".into(),
            "adds.toml:1:1: a table under `objects` away from its object".into(),
        ),
        ("dotted.toml", "materials.red = { colour = [1.0, 0.0, 0.0] }\n".into(), "dotted.toml:1:1: `materials`".into()),
        // An include after a table would be a field of that table.
        (
            "late.toml",
            format!("{MATERIALS}include = [\"fine.toml\"]\n"),
            "late.toml:4:1: `include` comes before the first table".into(),
        ),
    ];
    for (name, text, says) in cases {
        write(d, name, &text);
        write(d, "scene.toml", &scene(name));
        let e = load(d, "scene.toml").unwrap_err();
        assert!(e.contains(&says), "{name}: {e}");
    }
    // The scene's own lines keep their numbers after an include line.
    write(d, "fine.toml", BALL);
    write(d, "scene.toml", &format!("{}[render]\nspp = 0\n", scene("fine.toml")));
    let e = load(d, "scene.toml").unwrap_err();
    let line = 1 + CAMERA.lines().count() + MATERIALS.lines().count() + 1;
    assert!(e.contains(&format!("scene.toml:{line}:")), "{e}");
}

#[test]
fn a_file_included_twice_is_named_and_the_count_is_limited() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A diamond: two parts both include the same file, which is read once.
    write(d, "shared.toml", MATERIALS);
    write(d, "a.toml", "include = [\"shared.toml\"]\n");
    write(d, "b.toml", "include = [\"shared.toml\"]\n");
    write(d, "scene.toml", &format!("include = [\"a.toml\", \"b.toml\"]\n{CAMERA}{LIGHTS}{BALL}"));
    let e = load(d, "scene.toml").unwrap_err();
    assert!(e.contains("b.toml:1:12: `shared.toml` is included already"), "{e}");
    // At most 64 included files, the scene not counted, read from disk or given as text.
    let names: Vec<String> = (0..65).map(|k| format!("p{k}.toml")).collect();
    for name in &names {
        write(d, name, "");
    }
    let list = |n: usize| names[..n].iter().map(|s| format!("\"{s}\"")).collect::<Vec<_>>().join(", ");
    for (n, fine) in [(64, true), (65, false)] {
        let text = format!("include = [{}]\n{CAMERA}{MATERIALS}{LIGHTS}{BALL}", list(n));
        write(d, "many.toml", &text);
        let in_memory = Scene::parse(&text, d.join("nowhere.toml").to_str().unwrap()).map_err(|e| e.to_string());
        for result in [load(d, "many.toml"), in_memory] {
            match result {
                Ok(_) => assert!(fine, "{n} files read"),
                Err(e) => assert!(!fine && e.contains("more than 64 included files"), "{n}: {e}"),
            }
        }
    }
}

#[test]
fn an_included_file_that_does_not_parse_is_reported_in_it() {
    // The bracket left open would swallow the next file once joined: the error is the
    // broken file's own, at its own line, not one found in the file after it.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(d, "broken.toml", "[materials.red]\ncolour = [1.0, 0.0,\n");
    write(d, "after.toml", LIGHTS);
    write(d, "scene.toml", &format!("include = [\"broken.toml\", \"after.toml\"]\n{CAMERA}{MATERIALS}{BALL}"));
    let e = load(d, "scene.toml").unwrap_err();
    assert!(e.contains("broken.toml:") && !e.contains("after.toml"), "{e}");
}
