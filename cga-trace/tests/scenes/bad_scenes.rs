//! Bad scene files give an error naming the file, line and column (and the field or
//! object), never a panic. `cargo test -p cga-trace --test scenes bad_scenes:: -- --nocapture`
//! prints the table of inputs tried and the messages.

use cga_trace::Scene;

const CAMERA: &str = "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n";
const MATERIAL: &str = "material = { colour = [1.0, 0.0, 0.0] }\n";
/// A camera 1e-299 from the origin, looking at it.
#[cfg(feature = "evolved")]
const TINY_CAMERA: &str =
    "[camera]\nposition = [0.0, -1e-299, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n";

fn with_object(body: &str) -> String {
    format!("{CAMERA}[[objects]]\nname = \"thing\"\n{MATERIAL}{body}")
}

/// A sphere whose material (line 11) holds `fields` after its colour.
fn textured(fields: &str) -> String {
    format!(
        "{CAMERA}[[objects]]\nname = \"thing\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n\
         material = {{ colour = [1.0, 0.0, 0.0], {fields} }}\n"
    )
}

/// A circle of radius `r` about the z axis at height `z`, as scene files write it.
#[cfg(feature = "evolved")]
fn circle_at(z: f64, r: f64) -> String {
    format!("{{ centre = [0.0, 0.0, {z:?}], normal = [0.0, 0.0, 1.0], radius = {r:?} }}")
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
        ("unknown object type", with_object("type = \"teapot\"\n"), vec!["teapot"]),
        (
            "torus without a tube",
            with_object("type = \"torus\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1.0\n"),
            vec!["`thing`", "a torus takes `centre`, `normal`, `radius`", "`tube`"],
        ),
        (
            "torus with a zero tube",
            with_object(
                "type = \"torus\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1.0\ntube = 0.0\n",
            ),
            vec!["bad.toml:13:", "`thing`", "tube", "positive"],
        ),
        (
            "cylinder end given as two points",
            with_object(
                "type = \"cylinder\"\np1 = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\np2 = [0.0, 0.0, 1.0]\nradius = 1.0\n",
            ),
            vec!["bad.toml:10:", "`thing`", "`p1`: expected 1 points, found 2"],
        ),
        (
            "cone without r2",
            with_object("type = \"cone\"\np1 = [0.0, 0.0, 0.0]\nr1 = 1.0\np2 = [0.0, 0.0, 1.0]\n"),
            vec!["`thing`", "a cone takes", "`r2`"],
        ),
        (
            "cylinder of coincident ends",
            with_object("type = \"cylinder\"\np1 = [0.0, 0.0, 0.0]\np2 = [0.0, 0.0, 0.0]\nradius = 1.0\n"),
            vec!["bad.toml:11:", "`thing`", "`p2`", "coincide"],
        ),
        (
            "box with max below min",
            with_object("type = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, -1.0, 1.0]\n"),
            vec!["bad.toml:11:", "`thing`", "max", "exceed"],
        ),
        (
            "torus with a zero normal",
            with_object(
                "type = \"torus\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 0.0]\nradius = 1.0\ntube = 0.2\n",
            ),
            vec!["bad.toml:11:", "normal"],
        ),
        (
            "unknown object field",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmass = 3.0\n"),
            vec!["mass"],
        ),
        (
            "zero-radius sphere",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 0.0\n"),
            vec!["bad.toml:11:", "`thing`", "radius"],
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
            vec!["bad.toml:10:", "`thing`", "c1", "give `blade`"],
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
            vec!["bad.toml:11:", "colour", "NaN"],
        ),
        (
            "negative attenuation",
            format!("{CAMERA}[render]\nattenuation = [-1.0, 0.0, 0.0]\n"),
            vec!["bad.toml:6:", "render", "attenuation"],
        ),
        (
            "negative light",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 0.0]\ncolour = [-1.0, 1.0, 1.0]\n"),
            vec!["bad.toml:8:", "light 1", "`colour`", "≥ 0"],
        ),
        ("bad encoding", format!("{CAMERA}[render]\nencoding = \"gamma\"\n"), vec!["bad.toml:7:", "gamma"]),
        (
            "adaptive threshold out of range",
            format!("{CAMERA}[render]\nspp = 16\nadaptive = 4.0\n"),
            vec!["bad.toml:8:", "adaptive", "[0, 3]", "0.3"],
        ),
        (
            "adaptive as a word",
            format!("{CAMERA}[render]\nadaptive = \"on\"\n"),
            vec!["bad.toml:7:", "adaptive", "a contrast threshold", "min_spp"],
        ),
        (
            "adaptive min_spp of none",
            format!("{CAMERA}[render]\nadaptive = {{ threshold = 0.3, min_spp = 0 }}\n"),
            vec!["bad.toml:7:", "adaptive", "min_spp must be 1 to 4096"],
        ),
        (
            "adaptive by an unknown method",
            format!("{CAMERA}[render]\nadaptive = {{ threshold = 0.3, method = \"edges\" }}\n"),
            vec!["bad.toml:7:", "adaptive method `edges`", "corners"],
        ),
        (
            "no lens rays a sample",
            format!("{CAMERA}[render]\nblur_samples = 0\n"),
            vec!["bad.toml:7:", "blur_samples", "must be 1 to 256"],
        ),
        (
            "more lens rays a sample than the limit",
            format!("{CAMERA}[render]\nblur_samples = 257\n"),
            vec!["bad.toml:7:", "blur_samples", "must be 1 to 256"],
        ),
        (
            "adaptive with an unknown field",
            format!("{CAMERA}[render]\nadaptive = {{ threshold = 0.3, first = 4 }}\n"),
            vec!["bad.toml:7:", "adaptive", "`first`", "min_spp"],
        ),
        // Counts and sizes beyond crate::limits.
        ("deep mirrors", format!("{CAMERA}[render]\nmax_depth = 5000\n"), vec!["render", "5000 bounces", "1024"]),
        (
            "huge image",
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nwidth = 4294967295\nheight = 1\n".into(),
            vec!["bad.toml:4:", "`width`", "larger than the limit"],
        ),
        (
            "100000 × 100000",
            "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nwidth = 100000\nheight = 100000\n".into(),
            vec!["camera", "larger than the limit"],
        ),
        (
            "many samples",
            format!("{CAMERA}[render]\nsurface_method = {{ method = \"sampling\", samples = 100000000000 }}\n"),
            vec!["render", "samples must be 2 to 65536"],
        ),
        (
            "many per_leaf",
            format!(
                "{CAMERA}[render]\nsurface_method = {{ method = \"hierarchy\", leaves = 64, per_leaf = 100000000000 }}\n"
            ),
            vec!["render", "per_leaf"],
        ),
        ("spp zero", format!("{CAMERA}[render]\nspp = 0\n"), vec!["render", "spp"]),
        ("spp huge", format!("{CAMERA}[render]\nspp = 100000\n"), vec!["render", "4096"]),
        (
            "too many lights",
            format!("{CAMERA}{}", "[[lights]]\nposition = [0.0, 0.0, 9.0]\n".repeat(1025)),
            vec!["1025 lights", "1024"],
        ),
        // Extra or missing numbers, wherever they are.
        (
            "camera position of 4",
            CAMERA.replace("0.0, -10.0, 0.0]", "0.0, -10.0, 0.0, 7.0]"),
            vec!["bad.toml:2:", "position", "expected 3 numbers, found 4"],
        ),
        (
            "look_at of 4",
            CAMERA.replace("look_at = [0.0, 0.0, 0.0]", "look_at = [0.0, 0.0, 0.0, 1.0]"),
            vec!["bad.toml:3:", "look_at", "found 4"],
        ),
        ("up of 2", format!("{CAMERA}up = [0.0, 1.0]\n"), vec!["bad.toml:6:", "up", "found 2"]),
        (
            "camera motor of 9",
            "[camera]\nmotor = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n".into(),
            vec!["bad.toml:2:", "motor", "expected 8 numbers, found 9"],
        ),
        (
            "light position of 4",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 0.0, 1.0]\n"),
            vec!["bad.toml:7:", "found 4"],
        ),
        (
            "light colour of 4",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 0.0]\ncolour = [1.0, 1.0, 1.0, 1.0]\n"),
            vec!["bad.toml:8:", "colour", "found 4"],
        ),
        (
            "background of 4",
            format!("{CAMERA}[render]\nbackground = [0.0, 0.0, 0.0, 0.0]\n"),
            vec!["bad.toml:7:", "background", "found 4"],
        ),
        (
            "attenuation of 2",
            format!("{CAMERA}[render]\nattenuation = [1.0, 0.0]\n"),
            vec!["bad.toml:7:", "attenuation", "found 2"],
        ),
        (
            "object centre of 4",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0, 0.0]\nradius = 1.0\n"),
            vec!["bad.toml:10:", "centre", "found 4"],
        ),
        (
            "material colour of 2",
            format!(
                "{CAMERA}[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = {{ colour = [1.0, 0.0] }}\n"
            ),
            vec!["bad.toml:10:", "colour", "found 2"],
        ),
        (
            "corners of 4",
            with_object(
                "type = \"triangle\"\ncorners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]\n",
            ),
            vec!["bad.toml:10:", "corners", "expected 3 points, found 4"],
        ),
        (
            "sphere through 3 points",
            with_object("type = \"sphere\"\npoints = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]\n"),
            vec!["bad.toml:10:", "points", "expected 4 points, found 3"],
        ),
        // Numbers that are not finite or are out of range, named as such.
        ("NaN camera", CAMERA.replace("-10.0", "nan"), vec!["bad.toml:2:", "position", "NaN"]),
        (
            "infinite camera",
            CAMERA.replace("look_at = [0.0, 0.0, 0.0]", "look_at = [inf, 0.0, 0.0]"),
            vec!["bad.toml:3:", "inf is not finite"],
        ),
        (
            "disk of radius 1e200",
            with_object("type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1e200\n"),
            vec!["bad.toml:12:", "radius", "out of range"],
        ),
        (
            "sphere at 1e308",
            with_object("type = \"sphere\"\ncentre = [1e308, 0.0, 0.0]\nradius = 1.0\n"),
            vec!["bad.toml:10:", "centre", "out of range"],
        ),
        (
            "focal length 1e300",
            format!("{CAMERA}focal_length = 1e300\n"),
            vec!["bad.toml:6:", "focal_length", "out of range"],
        ),
        ("focal length 1e50", format!("{CAMERA}focal_length = 1e50\n"), vec!["camera", "field of view is degenerate"]),
        ("fov of 180", format!("{CAMERA}fov = 180.0\n"), vec!["bad.toml:6:", "fov", "between 0 and 180"]),
        ("fov and x_max", format!("{CAMERA}fov = 60.0\nx_max = 1.0\n"), vec!["bad.toml:6:", "not both"]),
        // Duplicates, forms, degenerate values.
        ("duplicate key", format!("{CAMERA}width = 9\n"), vec!["bad.toml:6:", "duplicate key `width`"]),
        ("negative ambient", format!("{CAMERA}[render]\nambient = -0.5\n"), vec!["render", "ambient"]),
        (
            "non-rigid camera motor",
            "[camera]\nmotor = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0]\nwidth = 8\nheight = 8\n".into(),
            vec!["bad.toml:2:", "motor", "not rigid"],
        ),
        (
            "non-rigid object motor",
            with_object(
                "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmotor = [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0, 5.0]\n",
            ),
            vec!["bad.toml:12:", "motor", "not rigid"],
        ),
        (
            "zero motor",
            with_object(
                "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmotor = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]\n",
            ),
            vec!["motor", "no rotation part"],
        ),
        (
            "motor and transform",
            with_object(
                "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmotor = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\ntransform = [{ translate = [1.0, 0.0, 0.0] }]\n",
            ),
            vec!["bad.toml:12:", "not both"],
        ),
        (
            "a step of two kinds",
            with_object(
                "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\ntransform = [{ translate = [1.0, 0.0, 0.0], rotate = { axis = [0.0, 0.0, 1.0], degrees = 9.0 } }]\n",
            ),
            vec!["bad.toml:12:", "exactly one"],
        ),
        (
            "a rotation about nothing",
            with_object(
                "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\ntransform = [{ rotate = { axis = [0.0, 0.0, 0.0], degrees = 9.0 } }]\n",
            ),
            vec!["bad.toml:12:", "zero"],
        ),
        (
            "sphere with a normal",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nnormal = [0.0, 0.0, 1.0]\n"),
            vec!["bad.toml:12:", "`normal`", "a sphere takes"],
        ),
        (
            "disk without radius",
            with_object("type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n"),
            vec!["`thing`", "a disk takes"],
        ),
        (
            "coincident points",
            with_object("type = \"disk\"\npoints = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]]\n"),
            vec!["bad.toml:10:", "points", "coincide"],
        ),
        (
            "identical circles",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\nc2 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n",
            ),
            vec!["`thing`", "same circle", "no surface"],
        ),
        (
            "reversed circles",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\nc2 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, -1.0], radius = 1.0 }\n",
            ),
            vec!["`thing`", "opposite orientations"],
        ),
        // Tables written as lists and lists as tables: the mistake, not serde's field types.
        ("[[render]]", format!("{CAMERA}[[render]]\nmax_depth = 2\n"), vec!["bad.toml:6:", "write `[render]`"]),
        ("[[camera]]", CAMERA.replace("[camera]", "[[camera]]"), vec!["bad.toml:1:", "write `[camera]`"]),
        (
            "[lights]",
            format!("{CAMERA}[lights]\nposition = [0.0, 0.0, 9.0]\n"),
            vec!["bad.toml:6:", "write `[[lights]]`"],
        ),
        ("[objects]", format!("{CAMERA}[objects]\ntype = \"sphere\"\n"), vec!["bad.toml:6:", "write `[[objects]]`"]),
        // Fields of view out of range say so, with the value.
        ("fov of 0", format!("{CAMERA}fov = 0.0\n"), vec!["bad.toml:6:", "fov", "between 0 and 180 degrees, not 0"]),
        ("fov of -5", format!("{CAMERA}fov = -5.0\n"), vec!["bad.toml:6:", "not -5"]),
        ("fov of 200", format!("{CAMERA}fov = 200.0\n"), vec!["bad.toml:6:", "not 200"]),
        // Spline circles: the circle that is wrong, by its place.
        (
            "a spline's fourth circle of radius 0",
            with_object(&format!(
                "type = \"spline\"\ncircles = [{}, {}, {}, {}]\n",
                circle_at(0.0, 1.0),
                circle_at(1.0, 1.0),
                circle_at(2.0, 1.0),
                circle_at(3.0, 0.0)
            )),
            vec!["bad.toml:10:", "`circles`", "circle 4", "radius is not positive"],
        ),
        (
            "a spline's repeated circle",
            with_object(&format!(
                "type = \"spline\"\ncircles = [{}, {}, {}, {}]\n",
                circle_at(0.0, 1.0),
                circle_at(1.0, 1.5),
                circle_at(1.0, 1.5),
                circle_at(3.0, 1.0)
            )),
            vec!["`thing`", "circles 2 and 3 are the same circle"],
        ),
        // What f64 cannot hold in one picture: refused by name, as the range it is.
        (
            "objects 1e400 apart in size",
            format!(
                "{TINY_CAMERA}[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1e-300\n{MATERIAL}\
                 [[objects]]\ntype = \"sphere\"\ncentre = [1e100, 0.0, 0.0]\nradius = 1.0\n{MATERIAL}"
            ),
            vec!["bad.toml:", "scene", "run from 1.0e-299 to 1.0e100", "2^400"],
        ),
        (
            "a light beyond the frame of a tiny scene",
            format!(
                "{TINY_CAMERA}[[lights]]\nposition = [0.0, 0.0, 1e100]\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1e-300\n{MATERIAL}"
            ),
            vec!["bad.toml:7:", "light 1", "`position`", "give it as `direction`"],
        ),
        (
            "a circle moved beyond the frame",
            with_object(
                "type = \"evolved\"\nc1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\nc2 = { centre = [0.0, 0.0, 1.0], normal = [0.0, 0.0, 1.0], radius = 1.0, transform = [{ translate = [1e100, 0.0, 0.0] }] }\n",
            ),
            vec!["`thing`", "`c2`", "ill-conditioned", "2^200"],
        ),
        (
            "a point of an object beyond the frame",
            format!(
                "{CAMERA}[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n{MATERIAL}\
                 [[objects]]\nname = \"thing\"\ntype = \"ruled\"\np1 = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\np2 = [[0.0, 1.0, 0.0], [1.0, 1.0, 1e100]]\n{MATERIAL}"
            ),
            vec!["`thing`", "ill-conditioned"],
        ),
        // Lights.
        (
            "a spot light wider inside than out",
            format!(
                "{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\ndirection = [0.0, 0.0, -1.0]\nradius = 50.0\nfalloff = 40.0\n"
            ),
            vec!["bad.toml:9:", "light 1", "`radius`", "0 ≤ radius ≤ falloff ≤ 90"],
        ),
        (
            "spot angles on a point light",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nfalloff = 40.0\n"),
            vec!["bad.toml:8:", "light 1", "`falloff`", "give it `position` and `direction`"],
        ),
        (
            "a light of neither kind",
            format!("{CAMERA}[[lights]]\ncolour = [1.0, 1.0, 1.0]\n"),
            vec!["bad.toml:6:", "light 1", "takes `position`"],
        ),
        (
            "an object's table away from it",
            format!(
                "{CAMERA}[[objects]]\ntype = \"sphere\"\n[[lights]]\nposition = [0.0, 0.0, 9.0]\n[objects.material]\ncolour = [1.0, 0.0, 0.0]\n"
            ),
            vec!["bad.toml:10:", "right after the `[[objects]]` table"],
        ),
        (
            "a bracket never closed in a large file",
            format!("{CAMERA}[render]\nbackground = [0.0, 0.0,\n{}", "0.0,\n".repeat(600_000)),
            vec!["bad.toml:7:14:", "never closed"],
        ),
        (
            "an area light of two shapes",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsphere = 1.0\ndisk = 1.0\n"),
            vec!["bad.toml:9:", "light 1", "`disk`", "not both"],
        ),
        (
            "a disk of light without a normal",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\ndisk = 1.0\n"),
            vec!["bad.toml:8:", "light 1", "`disk`", "needs its `normal`"],
        ),
        (
            "an area light of no size",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsphere = 0.0\n"),
            vec!["bad.toml:8:", "`sphere`", "> 0"],
        ),
        (
            "an area light of no samples",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsphere = 1.0\nsamples = 0\n"),
            vec!["bad.toml:9:", "`samples`", "at least 1"],
        ),
        (
            "an area light of too many samples",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsphere = 1.0\nsamples = 5000\n"),
            vec!["bad.toml:9:", "`samples`", "4096"],
        ),
        (
            "a spot light's direction on an area light",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsphere = 1.0\ndirection = [0.0, 0.0, -1.0]\n"),
            vec!["bad.toml:9:", "`direction`", "not a spot light's"],
        ),
        (
            "samples on a point light",
            format!("{CAMERA}[[lights]]\nposition = [0.0, 0.0, 9.0]\nsamples = 4\n"),
            vec!["bad.toml:8:", "`samples`", "give it `sphere` or `disk`"],
        ),
        (
            "a negative aperture",
            format!("{CAMERA}aperture = -0.1\n"),
            vec!["bad.toml:6:", "camera", "`aperture`", "≥ 0"],
        ),
        (
            "a lens focused at no distance",
            format!("{CAMERA}aperture = 0.1\nfocus_distance = 0.0\n"),
            vec!["bad.toml:7:", "`focus_distance`", "> 0"],
        ),
        (
            "a view width on a perspective camera",
            format!("{CAMERA}view_width = 3.0\n"),
            vec!["bad.toml:6:", "`view_width`", "orthographic"],
        ),
        (
            "a lens on an orthographic camera",
            format!("{CAMERA}projection = \"orthographic\"\naperture = 0.2\n"),
            vec!["bad.toml:7:", "`aperture`", "no lens"],
        ),
        ("an unknown projection", format!("{CAMERA}projection = \"fisheye\"\n"), vec!["bad.toml:6:", "fisheye"]),
        (
            "a shutter closing before it opens",
            format!("{CAMERA}shutter = [0.5, 0.2]\n"),
            vec!["bad.toml:6:", "`shutter`", "open ≤ close"],
        ),
        (
            "time samples without a shutter",
            format!("{CAMERA}time_samples = 8\n"),
            vec!["bad.toml:6:", "`time_samples`", "give `shutter"],
        ),
        (
            "a negative index of refraction",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n")
                .replace("[1.0, 0.0, 0.0] }", "[1.0, 0.0, 0.0], ior = -1.5 }"),
            vec!["`thing`", "≥ 0"],
        ),
        (
            "a light of no direction",
            format!("{CAMERA}[[lights]]\ndirection = [0.0, 0.0, 0.0]\n"),
            vec!["bad.toml:7:", "`direction`", "zero"],
        ),
        // Counts checked before anything is built.
        (
            "objects inline beyond what is read at once",
            format!("objects = [{}]\n{CAMERA}", "{ type = \"sphere\" }, ".repeat(250_000)),
            vec!["bad.toml:1:", "1048576", "write them as `[[objects]]` tables"],
        ),
        (
            "more objects than the limit",
            format!("{CAMERA}{}", "[[objects]]\n".repeat((1 << 20) + 1)),
            vec!["1048577 objects", "1048576"],
        ),
        (
            "objects both inline and as tables",
            format!("objects = [{{ type = \"sphere\" }}]\n{CAMERA}[[objects]]\ntype = \"sphere\"\n"),
            vec!["bad.toml:7:", "duplicate key `objects`"],
        ),
        (
            "control characters in a name",
            format!(
                "{CAMERA}[[objects]]\nname = \"bell\\u0007\\u001b[31m\"\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = -1.0\n{MATERIAL}"
            ),
            vec!["bell\\u{7}\\u{1b}[31m"],
        ),
        (
            "a blade name the algebra lacks",
            with_object("type = \"blade\"\nblade = { e1 = 1.0, e9 = 1.0 }\n"),
            vec!["bad.toml:10:", "`thing`", "`blade`", "`e9` is not a blade"],
        ),
        (
            "a blade named in both bases",
            with_object("type = \"blade\"\nblade = { e4 = 1.0, eo = 1.0 }\n"),
            vec!["bad.toml:10:", "`eo` is in the null basis", "`e4` in the orthonormal one"],
        ),
        (
            "an imaginary point pair",
            with_object("type = \"blade\"\nblade = { e1o = 1.0, e1i = -0.5 }\n"),
            vec!["bad.toml:10:", "imaginary point pair (r² = -1.000e0)"],
        ),
        (
            "a zero blade",
            with_object("type = \"blade\"\nblade = { e1 = 0.0 }\n"),
            vec!["bad.toml:10:", "the blade is zero"],
        ),
        (
            "the point at infinity",
            with_object("type = \"blade\"\nblade = { ei = 2.0 }\n"),
            vec!["bad.toml:10:", "grade-1 blade at infinity"],
        ),
        (
            "not a blade",
            with_object("type = \"blade\"\nblade = { e1 = 1.0, e23 = 1.0 }\n"),
            vec!["bad.toml:10:", "not a blade"],
        ),
        (
            "a line given as a circle",
            with_object("type = \"circle\"\nblade = { e12i = 1.0, e1oi = 1.0 }\n"),
            vec!["bad.toml:10:", "the blade is a line, not a circle"],
        ),
        (
            "a line without a direction",
            with_object("type = \"line\"\npoint = [0.0, 0.0, 0.0]\ndirection = [0.0, 0.0, 0.0]\n"),
            vec!["bad.toml:11:", "`direction`"],
        ),
        (
            "a point pair of one point",
            with_object("type = \"point-pair\"\npoints = [[1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\n"),
            vec!["bad.toml:10:", "`points`"],
        ),
        (
            "a negative mark size",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nsize = -1.0\n"),
            vec!["bad.toml:11:", "`size`: a size must be positive"],
        ),
        (
            "a label on a plane",
            with_object("type = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nlabel = \"P\"\n"),
            vec!["bad.toml:12:", "`label`", "plane-patch"],
        ),
        (
            "a material name the file lacks",
            format!(
                "{CAMERA}[materials.gold]\ncolour = [1.0, 0.8, 0.2]\n[[objects]]\nname = \"thing\"\nmaterial = \"silver\"\ntype = \"point\"\npoint = [0.0, 0.0, 0.0]\n"
            ),
            vec!["bad.toml:10:12:", "`thing`", "no material `silver`", "it has `gold`"],
        ),
        (
            "a named material out of range",
            format!(
                "{CAMERA}[materials.gold]\ncolour = [1.0, 0.8, 0.2]\nkd = -1.0\n[[objects]]\nmaterial = \"gold\"\ntype = \"point\"\npoint = [0.0, 0.0, 0.0]\n"
            ),
            vec!["bad.toml:6:", "material `gold`"],
        ),
        (
            "a material neither a table nor a name",
            format!("{CAMERA}[[objects]]\nmaterial = 3\ntype = \"point\"\npoint = [0.0, 0.0, 0.0]\n"),
            vec!["bad.toml:7:", "a material table", "[materials.NAME]"],
        ),
        (
            "a negative ior",
            format!(
                "{CAMERA}[[objects]]\nname = \"glass\"\ntype = \"point\"\npoint = [0.0, 0.0, 0.0]\nmaterial = {{ colour = [1.0, 1.0, 1.0], ior = -1.5 }}\n"
            ),
            vec!["bad.toml:6:", "`glass`", "`ior`", "about 1.5 for glass"],
        ),
        (
            "a negative absorption",
            format!(
                "{CAMERA}[[objects]]\nname = \"glass\"\ntype = \"point\"\npoint = [0.0, 0.0, 0.0]\nmaterial = {{ colour = [1.0, 1.0, 1.0], ior = 1.5, absorption = [0.1, -1.0, 0.0] }}\n"
            ),
            vec!["bad.toml:6:", "`glass`", "`absorption`", "≥ 0"],
        ),
        (
            "a negative ks in a named material",
            format!("{CAMERA}[materials.chalk]\ncolour = [1.0, 1.0, 1.0]\nks = -1.0\n"),
            vec!["bad.toml:6:", "material `chalk`", "`ks`: must be finite and ≥ 0"],
        ),
        (
            "no time samples",
            format!("{CAMERA}shutter = [0.0, 0.5]\ntime_samples = 0\n"),
            vec!["bad.toml:7:", "camera", "`time_samples`", "1 or more instants"],
        ),
        (
            "a NaN in a motion key",
            with_object(
                "type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, nan]]\n",
            ),
            vec!["bad.toml:11:", "`motion`", "NaN"],
        ),
        (
            "a motion key of seven numbers",
            format!("{CAMERA}motion = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]]\n"),
            vec!["bad.toml:6:", "`motion`", "expected 8 numbers, found 7"],
        ),
        (
            "POV-Ray's Euler angles as a rotate step",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\ntransform = [{ rotate = [0.0, 45.0, 30.0] }]\n"),
            vec![
                "bad.toml:11:25:",
                "`rotate` takes one turn, `{ axis = [x, y, z], degrees = θ }`",
                "POV-Ray's `rotate <x, y, z>` is three turns",
                "`transform = [{ rotate = { axis = [0, 1, 0], degrees = 45 } }, { rotate = { axis = [0, 0, 1], degrees = 30 } }]`",
            ],
        ),
        (
            "POV-Ray's Euler angles in a pose key",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [{ rotate = [90, 0, 0] }]\n"),
            vec![
                "bad.toml:11:22:",
                "POV-Ray's `rotate <x, y, z>`",
                "{ rotate = { axis = [1, 0, 0], degrees = 90 } }]`",
            ],
        ),
        (
            "an include after a table",
            format!("{CAMERA}include = [\"parts.toml\"]\n"),
            vec!["bad.toml:6:1:", "`include` comes before the first table", "`[camera]`", "move it to the top"],
        ),
        (
            "an include in an object",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\ninclude = [\"parts.toml\"]\n"),
            vec!["bad.toml:11:1:", "`include` comes before the first table", "`[[objects]]`"],
        ),
        (
            "a motion key of a number",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [3.0]\n"),
            vec![
                "bad.toml:11:",
                "`motion`",
                "expected a keyframe: a motor of 8 numbers `[s, e12, e13, e23, e1i, e2i, e3i, e123i]`",
                "a pose `{ position = [x, y, z], rotate = { axis = [x, y, z], degrees = θ } }`",
                "`{ transform = [steps] }` or `{ motor = [8 numbers] }`",
            ],
        ),
        (
            "a camera's motion key of a string",
            format!("{CAMERA}motion = [\"left\"]\n"),
            vec![
                "bad.toml:6:",
                "`motion`",
                "{ transform = [steps] }",
                "the camera's pose `{ position = [x, y, z], look_at",
            ],
        ),
        (
            "a motion key of transform steps in an array",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [[{ translate = [1.0, 0.0, 0.0] }]]\n"),
            vec![
                "bad.toml:11:",
                "`motion`",
                "a keyframe written as an array is a motor of 8 numbers",
                "{ transform = [steps] }",
            ],
        ),
        (
            "a motion key with a field no key takes",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [{ translate = [1.0, 0.0, 0.0] }]\n"),
            vec!["bad.toml:11:13:", "unknown field `translate` in a keyframe", "a pose `{ position = [x, y, z]"],
        ),
        (
            "an object's key as a camera pose",
            with_object(
                "type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [{ position = [0.0, 0.0, 1.0], look_at = [0.0, 1.0, 0.0] }]\n",
            ),
            vec!["bad.toml:11:41:", "`look_at` is the camera's", "an object's is a motor of 8 numbers"],
        ),
        (
            "a key both a pose and a motor",
            with_object(
                "type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [[1, 0, 0, 0, 0, 0, 0, 0], { position = [1.0, 0.0, 0.0], motor = [1, 0, 0, 0, 0, 0, 0, 0] }]\n",
            ),
            vec![
                "bad.toml:11:50:",
                "`thing`",
                "`motion`: keyframe 2: `position`",
                "a pose (`position`, `rotate`) or `transform` or `motor`",
            ],
        ),
        (
            "a key's transform step of two kinds",
            with_object(
                "type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = [{ transform = [{ translate = [1.0, 0.0, 0.0], motor = [1, 0, 0, 0, 0, 0, 0, 0] }] }]\n",
            ),
            vec![
                "bad.toml:11:26:",
                "`motion`: keyframe 1: `transform`",
                "exactly one of `rotate`, `translate`, `motor`",
            ],
        ),
        (
            "a camera pose key looking at itself",
            format!(
                "{CAMERA}motion = [[1, 0, 0, 0, 0, 0, 0, 0], {{ position = [0.0, 1.0, 0.0], look_at = [0.0, 1.0, 0.0] }}]\n"
            ),
            vec![
                "bad.toml:6:",
                "camera",
                "`motion`: keyframe 2: `look_at`",
                "the camera position equals the look-at point",
            ],
        ),
        (
            "a camera pose key without a position",
            format!("{CAMERA}motion = [{{ look_at = [0.0, 1.0, 0.0] }}]\n"),
            vec!["bad.toml:6:23:", "`motion`: keyframe 1: `look_at`", "needs `position` as well as `look_at`"],
        ),
        (
            "a camera pose key turned as well",
            format!(
                "{CAMERA}motion = [{{ position = [0.0, 1.0, 0.0], look_at = [0.0, 2.0, 0.0], rotate = {{ axis = [0.0, 0.0, 1.0], degrees = 5.0 }} }}]\n"
            ),
            vec!["bad.toml:6:", "keyframe 1: `rotate`", "leave out `rotate`"],
        ),
        (
            "an up without a look_at in a camera key",
            format!("{CAMERA}motion = [{{ position = [0.0, 1.0, 0.0], up = [0.0, 0.0, 1.0] }}]\n"),
            vec!["bad.toml:6:", "keyframe 1: `up`", "`up` goes with `look_at`"],
        ),
        (
            "a motion without keys",
            with_object("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nmotion = []\n"),
            vec!["bad.toml:11:10:", "`thing`", "`motion`: a motion needs at least one keyframe"],
        ),
        (
            "more shadow rays a hit than the limit",
            format!("{CAMERA}{}", "[[lights]]\nposition = [0.0, 0.0, 5.0]\nsphere = 0.5\nsamples = 4096\n".repeat(17)),
            vec![
                "bad.toml:",
                "light 17",
                "69632 shadow rays a hit (lights and their samples) exceed the limit of 65536",
            ],
        ),
        (
            "a CSG part that bounds no solid",
            with_object(
                "type = \"csg\"\noperation = \"union\"\nobjects = [{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }, { type = \"disk\", centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }]\n",
            ),
            vec!["bad.toml:11:", "`thing`", "`objects`: object 2", "bounds a solid"],
        ),
        (
            "a CSG operation misspelt",
            with_object("type = \"csg\"\noperation = \"minus\"\nobjects = []\n"),
            vec!["bad.toml:10:", "`operation`", "`union`, `intersection`, `difference`"],
        ),
        (
            "a CSG tree of one object",
            with_object(
                "type = \"csg\"\noperation = \"union\"\nobjects = [{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }]\n",
            ),
            vec!["bad.toml:11:", "`objects`", "two or more"],
        ),
        (
            "a CSG part with a bad material",
            with_object(
                "type = \"csg\"\noperation = \"union\"\nobjects = [{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }, { type = \"sphere\", centre = [1.0, 0.0, 0.0], radius = 1.0, material = \"gold\" }]\n",
            ),
            vec!["bad.toml:11:", "object 2", "no material `gold`"],
        ),
        (
            "too many CSG objects",
            with_object(&format!(
                "type = \"csg\"\noperation = \"union\"\nobjects = [{}]\n",
                vec!["{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.0 }"; 65].join(", ")
            )),
            vec!["bad.toml:11:", "65 objects in one CSG tree exceed the limit of 64"],
        ),
        (
            "a capped clip of an open object",
            with_object(
                "type = \"disk\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1.0\nclip = { plane = { point = [0.0, 0.0, 0.0], normal = [1.0, 0.0, 0.0] }, capped = true }\n",
            ),
            vec!["bad.toml:13:", "`clip`", "a capped clip needs a closed object"],
        ),
        (
            "a clip without a region",
            with_object("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nclip = { capped = true }\n"),
            vec!["bad.toml:12:", "`clip`", "a clip takes `plane"],
        ),
        (
            "a label too long",
            with_object(&format!("type = \"point\"\npoint = [0.0, 0.0, 0.0]\nlabel = \"{}\"\n", "x".repeat(65))),
            vec!["bad.toml:11:", "`label`: 65 characters exceed the limit of 64"],
        ),
        (
            "a texture scaled by zero",
            textured("texture = { pattern = \"checker\", colour = [0.0, 0.0, 0.0], scale = [0.0, 1.0] }"),
            vec!["bad.toml:11:", "`thing`", "`scale`", "must be > 0"],
        ),
        (
            "a texture flipped along w",
            textured("texture = { pattern = \"checker\", colour = [0.0, 0.0, 0.0], flip = \"w\" }"),
            vec!["bad.toml:11:", "`w`", "`uv`"],
        ),
        (
            "a texture turned by a string",
            textured("texture = { pattern = \"checker\", colour = [0.0, 0.0, 0.0], rotate = \"left\" }"),
            vec!["bad.toml:11:", "invalid type"],
        ),
        (
            "an unknown pattern",
            textured("texture = { pattern = \"wood\", colour = [0.0, 0.0, 0.0] }"),
            vec!["bad.toml:11:", "`wood`", "`marble`", "`bricks`"],
        ),
        (
            "noise of too many octaves",
            textured("texture = { pattern = \"noise\", colour = [0.0, 0.0, 0.0], octaves = 17 }"),
            vec!["bad.toml:11:", "`thing`", "`octaves`", "1 to 16, not 17"],
        ),
        (
            "a negative seed",
            textured("texture = { pattern = \"noise\", colour = [0.0, 0.0, 0.0], seed = -1 }"),
            vec!["bad.toml:11:", "-1"],
        ),
        (
            "octaves on a checker",
            textured("texture = { pattern = \"checker\", colour = [0.0, 0.0, 0.0], octaves = 3 }"),
            vec!["bad.toml:11:", "`octaves`", "noise's and marble's alone"],
        ),
        (
            "a gradient along w",
            textured("texture = { pattern = \"gradient\", colour = [0.0, 0.0, 0.0], along = \"w\" }"),
            vec!["bad.toml:11:", "`w`"],
        ),
        (
            "negative turbulence",
            textured("texture = { pattern = \"marble\", colour = [0.0, 0.0, 0.0], turbulence = -1.0 }"),
            vec!["bad.toml:11:", "`turbulence`", "≥ 0"],
        ),
        (
            "mortar wider than a brick",
            textured("texture = { pattern = \"bricks\", colour = [0.0, 0.0, 0.0], brick = [1.0, 0.5], mortar = 0.5 }"),
            vec!["bad.toml:11:", "`mortar`", "narrower than a brick"],
        ),
        (
            "a brick of no height",
            textured("texture = { pattern = \"bricks\", colour = [0.0, 0.0, 0.0], brick = [1.0, 0.0] }"),
            vec!["bad.toml:11:", "`brick`", "> 0"],
        ),
        (
            "a texture's strength",
            textured("texture = { pattern = \"noise\", colour = [0.0, 0.0, 0.0], strength = 2.0 }"),
            vec!["bad.toml:11:", "`strength`", "a `bump`'s"],
        ),
        (
            "a bump with a colour",
            textured("bump = { pattern = \"noise\", colour = [0.0, 0.0, 0.0], strength = 2.0 }"),
            vec!["bad.toml:11:", "`colour`", "takes no `colour`"],
        ),
        (
            "a bump of an infinite strength",
            textured("bump = { pattern = \"noise\", strength = inf }"),
            vec!["bad.toml:11:", "inf is not finite"],
        ),
        (
            "a bump image that is not there",
            textured("bump = { image = \"no-such-map.png\", strength = 0.5 }"),
            vec!["bad.toml:11:", "no-such-map.png"],
        ),
    ]
}

// Several cases are evolved surfaces; a build without them rejects those differently (below).
#[cfg(feature = "evolved")]
#[test]
fn bad_scene_files_give_located_errors() {
    println!("| input | error |\n|---|---|");
    let mut failures = Vec::new();
    for (what, text, fragments) in cases() {
        let err = match Scene::parse(&text, "bad.toml") {
            Ok(_) => {
                failures.push(format!("{what}: accepted"));
                continue;
            }
            Err(e) => e.to_string(),
        };
        println!("| {what} | `{}` |", err.replace('\n', " ").replace('|', "\\|"));
        if !err.starts_with("bad.toml:") || err.chars().any(char::is_control) {
            failures.push(format!("{what}: no location, or control characters, in `{err}`"));
        }
        failures
            .extend(fragments.iter().filter(|f| !err.contains(**f)).map(|f| format!("{what}: `{err}` lacks `{f}`")));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
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

/// Inputs at the edges of what a file may give, which earlier releases refused or drew wrong
/// (a camera 1e22 … 1e99 from the origin, an object moved 1e8 by its motor, a blade scaled by
/// 1e-300, points 1e-300 apart, a focal length of 1e-300, a sphere of 1e12 around the camera):
/// each loads, and its one sphere covers the middle of the picture, lit (the blades: the
/// picture of the same blades unscaled).
#[cfg(feature = "evolved")]
#[test]
fn inputs_at_the_edges_of_the_limits_load_and_render() {
    let sphere_at = |d: &str| {
        format!(
            "[camera]\nposition = [{d}, -10.0, 0.0]\nlook_at = [{d}, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
             [[lights]]\nposition = [{d}, -10.0, 5.0]\n\
             [[objects]]\ntype = \"sphere\"\ncentre = [{d}, 0.0, 0.0]\nradius = 3.0\n{MATERIAL}"
        )
    };
    let tiny = "[camera]\nposition = [0.0, -1e-299, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
                [[lights]]\nposition = [0.0, -1e-299, 5e-300]\n";
    let cases: Vec<(&str, String)> = vec![
        ("camera 1e22 from the origin", sphere_at("1e22")),
        ("camera 1e50 from the origin", sphere_at("1e50")),
        ("camera 1e99 from the origin", sphere_at("1e99")),
        (
            "an object moved 1e8 by its motor",
            sphere_at("1e8").replace(
                "centre = [1e8, 0.0, 0.0]",
                "centre = [0.0, 0.0, 0.0]\ntransform = [{ translate = [1e8, 0.0, 0.0] }]",
            ),
        ),
        (
            "a sphere through points 1e-300 apart",
            format!(
                "{tiny}[[objects]]\ntype = \"sphere\"\npoints = [[3e-300, 0.0, 0.0], [-3e-300, 0.0, 0.0], [0.0, 3e-300, 0.0], [0.0, 0.0, 3e-300]]\n{MATERIAL}"
            ),
        ),
        (
            "an evolved surface of blades scaled by 1e-300",
            format!(
                "[camera]\nposition = [1.0, -30.0, 0.0]\nlook_at = [1.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
                 [[lights]]\nposition = [0.0, -20.0, 40.0]\n[[objects]]\ntype = \"evolved\"\n\
                 c1 = {{ blade = [0.36389e-300, -1.66662e-300, -1.81194e-300, -1.36982e-300, -1.52625e-300, 0.1694e-300, 0.84272e-300, 0.87727e-300, 0.17834e-300, 0.23224e-300] }}\n\
                 c2 = {{ blade = [-0.16887e-300, -0.75896e-300, -0.91709e-300, -0.92729e-300, -0.97853e-300, 0.63805e-300, -0.0462e-300, -0.12142e-300, -0.29479e-300, -0.39902e-300] }}\n{MATERIAL}"
            ),
        ),
        ("10 MB of comments", format!("{}{}", sphere_at("0.0"), format!("# {}\n", "x".repeat(998)).repeat(10_000))),
        (
            "a focal length of 1e-300",
            sphere_at("0.0").replace("width = 8\n", "width = 8\nfocal_length = 1e-300\nx_max = 2e-300\n"),
        ),
        (
            "a sphere of 1e12 around the camera",
            format!(
                "[camera]\nposition = [0.0, -1.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
                 [[lights]]\nposition = [0.0, -0.5, 1.0]\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1e12\n{MATERIAL}"
            ),
        ),
    ];
    let mut failures = Vec::new();
    let render = |scene: &Scene| cga_trace::Renderer::new(scene).render(cga_trace::Aov::Shaded, &|| {});
    // A floor given by a point 1e100 along it is the floor given by its point below the camera.
    let floor = |p: &str| {
        format!(
            "[camera]\nposition = [0.0, -10.0, 2.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
             [[lights]]\nposition = [0.0, -10.0, 5.0]\n[[objects]]\ntype = \"plane\"\npoint = {p}\nnormal = [0.0, 0.0, 1.0]\n{MATERIAL}"
        )
    };
    let (far, near) = (floor("[1e100, 3e99, -1.0]"), floor("[0.0, 0.0, -1.0]"));
    let (far, near) = (render(&Scene::parse(&far, "far").unwrap()), render(&Scene::parse(&near, "near").unwrap()));
    assert!(far == near && near.pixels.iter().any(|p| p[0] > 0.1), "a plane given far along it");
    for (what, text) in cases {
        match Scene::parse(&text, "edge.toml") {
            Err(e) => failures.push(format!("{what}: refused: {e}")),
            // A blade and its multiples are one circle: the same picture as unscaled.
            Ok(scene) if what.contains("blades") => {
                let same = Scene::parse(&text.replace("e-300", ""), "edge.toml").unwrap();
                let (a, b) = (render(&scene), render(&same));
                let off = a.pixels.iter().flatten().zip(b.pixels.iter().flatten()).map(|(x, y)| (x - y).abs());
                let off = off.fold(0.0f64, f64::max);
                println!(
                    "{what}: {} lit pixels, {off:.1e} from unscaled",
                    a.pixels.iter().filter(|p| p[0] > 0.1).count()
                );
                if off > 1e-9 || a.pixels.iter().all(|p| p[0] <= 0.1) {
                    failures.push(format!("{what}: not the picture of the unscaled blades"));
                }
            }
            Ok(scene) => {
                let film = render(&scene);
                let [r, g, b] = film.get(4, 4);
                println!("{what}: centre pixel ({r:.3}, {g:.3}, {b:.3})");
                if !(r > 0.1 && r > g && r > b) {
                    failures.push(format!(
                        "{what}: the middle of the picture is ({r:.3}, {g:.3}, {b:.3}), not the red object"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
