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
    write(d, "one.toml", &format!("{CAMERA}{MATERIALS}{LIGHTS}{BALL}{FLOOR}"));
    // The materials in one file, which includes the floor's; the ball in the scene.
    write(d, "looks.toml", &format!("include = [\"floor.toml\"]\n{MATERIALS}{LIGHTS}"));
    write(d, "floor.toml", FLOOR);
    write(d, "split.toml", &format!("include = [\"looks.toml\"]\n{CAMERA}{BALL}"));
    let (one, split) = (load(d, "one.toml").unwrap(), load(d, "split.toml").unwrap());
    // Objects in reading order: the scene's own, then each included file's.
    let names = |s: &Scene| s.objects.iter().map(|o| o.name.clone()).collect::<Vec<_>>();
    assert_eq!(
        (names(&one), names(&split)),
        (vec!["ball".to_string(), "floor".into()], vec!["ball".into(), "floor".into()])
    );
    assert_eq!(format!("{:?}", one.objects), format!("{:?}", split.objects));
    assert_eq!(format!("{:?}", one.lights), format!("{:?}", split.lights));
}

#[test]
fn errors_name_the_included_file_and_its_own_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scene = |parts: &str| format!("include = [\"{parts}\"]\n{CAMERA}{MATERIALS}");
    let cases: [(&str, String, String); 6] = [
        // A bad radius on the fifth line of the included file.
        ("bad.toml", BALL.replace("radius = 1.0", "radius = -1.0"), "bad.toml:5:".into()),
        ("typo.toml", BALL.replace("centre", "center"), "typo.toml:4:".into()),
        ("camera.toml", format!("{LIGHTS}{CAMERA}"), "camera.toml:3:2: `camera` belongs in the scene file".into()),
        ("cycle.toml", "include = [\"cycle.toml\"]\n".into(), "cycle.toml:1:12: `cycle.toml` is read already".into()),
        ("missing.toml", "include = [\"nowhere.toml\"]\n".into(), "missing.toml:1:12: include `nowhere.toml`".into()),
        ("list.toml", "include = \"x.toml\"\n".into(), "list.toml:1:1: `include`: give a list of file names".into()),
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
