//! Bad scene files give an error naming the file, line and column (and the field or
//! object), never a panic. `cargo test -p cga-trace --test bad_scenes -- --nocapture`
//! prints the table of inputs tried and the messages.

use cga_trace::Scene;

const CAMERA: &str = "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n";
const MATERIAL: &str = "material = { colour = [1.0, 0.0, 0.0] }\n";

fn with_object(body: &str) -> String {
    format!("{CAMERA}[[objects]]\nname = \"thing\"\n{MATERIAL}{body}")
}

/// (what is wrong, scene text, fragments the message must contain)
#[cfg(feature = "evolved")]
fn cases() -> Vec<(&'static str, String, Vec<&'static str>)> {
    vec![
        ("not TOML", "[camera\nwidth = 3".into(), vec!["bad.toml:1:"]),
        ("no camera", "[render]\nmax_depth = 1\n".into(), vec!["camera"]),
        ("unknown field", format!("{CAMERA}zoom = 2.0\n"), vec!["bad.toml:6:", "zoom"]),
        (
            "missing field",
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nwidth = 8\n".into(),
            vec!["height"],
        ),
        ("wrong type", format!("{CAMERA}[render]\nmax_depth = \"deep\"\n"), vec!["bad.toml:7:", "max_depth"]),
        ("unknown object type", with_object("type = \"torus\"\n"), vec!["torus"]),
        (
            "unknown object field",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmass = 3.0\n"),
            vec!["mass"],
        ),
        (
            "zero-radius sphere",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 0.0\n"),
            vec!["bad.toml:6:", "`thing`", "radius"],
        ),
        (
            "negative radius disk",
            with_object("type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = -1.0\n"),
            vec!["`thing`", "radius"],
        ),
        (
            "zero plane normal",
            with_object("type = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 0.0]\n"),
            vec!["`thing`", "zero"],
        ),
        (
            "collinear triangle",
            with_object("type = \"triangle\"\ncorners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]\n"),
            vec!["`thing`", "collinear"],
        ),
        (
            "circle pair through a line",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\nc2 = { centre = [3.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n",
            ),
            vec!["`thing`", "unbounded"],
        ),
        (
            "imaginary circle",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\nc2 = { blade = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0] }\n",
            ),
            vec!["`thing`", "c2"],
        ),
        (
            "circle both ways",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0, blade = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0] }\nc2 = { centre = [0.0, 0.0, 1.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n",
            ),
            vec!["`thing`", "either"],
        ),
        (
            "camera on its target",
            "[camera]\nposition = [1.0, 1.0, 1.0]\nlook_at = [1.0, 1.0, 1.0]\nwidth = 8\nheight = 8\n".into(),
            vec!["bad.toml:1:", "camera", "look-at"],
        ),
        (
            "up along the view",
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 0.0, 5.0]\nwidth = 8\nheight = 8\n".into(),
            vec!["camera", "parallel"],
        ),
        (
            "zero image size",
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nwidth = 0\nheight = 8\n".into(),
            vec!["camera", "positive"],
        ),
        (
            "NaN colour",
            format!(
                "{CAMERA}[[objects]]\nname = \"thing\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = {{ colour = [nan, 0.0, 0.0] }}\n"
            ),
            vec!["`thing`", "finite"],
        ),
        (
            "negative attenuation",
            format!("{CAMERA}[render]\nattenuation = [-1.0, 0.0, 0.0]\n"),
            vec!["bad.toml:6:", "render", "attenuation"],
        ),
        (
            "negative light",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 0.0]\ncolour = [-1.0, 1.0, 1.0]\n"),
            vec!["bad.toml:6:", "light 1"],
        ),
        ("bad encoding", format!("{CAMERA}[render]\nencoding = \"gamma\"\n"), vec!["bad.toml:7:", "gamma"]),
    ]
}

// Several cases are evolved surfaces; a build without them rejects those differently (below).
#[cfg(feature = "evolved")]
#[test]
fn bad_scene_files_give_located_errors() {
    println!("| input | error |\n|---|---|");
    for (what, text, fragments) in cases() {
        let err = match Scene::parse(&text, "bad.toml") {
            Ok(_) => panic!("{what}: accepted"),
            Err(e) => e.to_string(),
        };
        println!("| {what} | `{}` |", err.replace('\n', " ").replace('|', "\\|"));
        assert!(err.starts_with("bad.toml:"), "{what}: no location in `{err}`");
        for f in fragments {
            assert!(err.contains(f), "{what}: `{err}` lacks `{f}`");
        }
    }
}

#[test]
fn a_missing_file_is_an_error() {
    let err = Scene::load(std::path::Path::new("no/such/scene.toml")).unwrap_err().to_string();
    assert!(err.starts_with("no/such/scene.toml:"), "{err}");
}

/// A build without the `evolved` feature names what it left out.
#[cfg(not(feature = "evolved"))]
#[test]
fn evolved_objects_need_the_feature() {
    let body = "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n\
                c2 = { centre = [0.0, 0.0, 1.0], normal = [0.0, 0.0, 1.0], radius = 2.0 }\n";
    let err = Scene::parse(&with_object(body), "no-evolved.toml").unwrap_err().to_string();
    assert!(err.contains("no-evolved.toml") && err.contains("feature `evolved`"), "{err}");
}
