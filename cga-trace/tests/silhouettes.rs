//! Flat silhouettes against POV-Ray 3.7: each Euclidean object kind, a few of each in varied
//! poses, rendered by us and by POV-Ray in the same camera at 640×480; the pixels each covers
//! agree on at least 99.5 % (only pixels the edges cross may differ). Needs `povray`:
//!
//! ```text
//! apt-get install -y povray
//! cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture
//! ```

use cga_trace::{Aov, Renderer, Scene};

const W: usize = 640;
const H: usize = 480;

/// The scene around `objects_toml`: the camera of `benches/povray/*.pov` (at `(0, −14, 5)`,
/// looking at the origin, `x_max = 1.4`), a black background.
const OURS: &str = "[camera]\nposition = [0.0, -14.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nx_max = 1.4\n\
                    width = 640\nheight = 480\n[render]\nbackground = [0.0, 0.0, 0.0]\n";

/// POV-Ray's scene around `objects_pov`: the same camera (`angle = 2 atan(0.7)`, `x_max`'s
/// half width) in our right-handed, z-up world (`sky` z and a `right` along −x turn POV-Ray's
/// left-handed frame into ours, so coordinates carry over one to one), every object flat white
/// by default (ambient 1, no lights), a black background.
const THEIRS: &str = "#version 3.7;\n#include \"transforms.inc\"\n\
    global_settings { ambient_light rgb 1 assumed_gamma 1.0 }\n\
    camera { perspective location <0,-14,5> sky <0,0,1> up <0,0,1> right <-1.3333333,0,0> look_at <0,0,0> angle 69.98432 }\n\
    background { rgb 0 }\n\
    #default { texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } } }\n";

/// `[[objects]]` tables, one per body (its fields, one a line), each with a white material
/// (the mask ignores it; our scene format requires one).
fn tables(bodies: &[&str]) -> String {
    bodies.iter().map(|b| format!("[[objects]]\n{b}\nmaterial = {{ colour = [1.0, 1.0, 1.0] }}\n")).collect()
}

/// How many pixels our render of `objects_toml` (`[[objects]]` tables in our scene format,
/// each with a material: see [`tables`]) covers, and the fraction of all pixels where its mask
/// agrees with POV-Ray's of `objects_pov` (object statements without textures; the macros of
/// `transforms.inc` may place them), both in the common camera at 640×480 ([`OURS`],
/// [`THEIRS`]). Ours covers a pixel where any channel of the normal AOV is positive
/// (`(n + 1)/2`, so any hit), POV-Ray's where a channel is over half (flat white on black, no
/// anti-aliasing).
fn agreement(objects_toml: &str, objects_pov: &str) -> (usize, f64) {
    let scene = Scene::parse(&format!("{OURS}{objects_toml}"), "silhouettes.toml").unwrap();
    let film = Renderer::new(&scene).render(Aov::Normal, &|| {});
    let ours: Vec<bool> = film.pixels.iter().map(|p| p.iter().any(|&x| x > 0.0)).collect();
    assert_eq!(ours.len(), W * H);
    // A directory per call: the tests run in parallel.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.pov"), format!("{THEIRS}{objects_pov}")).unwrap();
    let out = std::process::Command::new("povray")
        .current_dir(dir.path())
        .args(["+Is.pov", "+Os.ppm", "+FP", &format!("+W{W}"), &format!("+H{H}"), "-D", "-A", "-GA"])
        .output()
        .expect("povray runs (apt-get install -y povray)");
    assert!(out.status.success(), "povray failed: {}", String::from_utf8_lossy(&out.stderr));
    let ppm = std::fs::read(dir.path().join("s.ppm")).unwrap();
    // A binary PPM (P6, maxval 255) ends with the pixels, three bytes each; its header may
    // hold comments.
    assert!(ppm.starts_with(b"P6") && ppm.len() > 3 * W * H);
    let theirs: Vec<bool> = ppm[ppm.len() - 3 * W * H..].chunks(3).map(|p| p.iter().any(|&x| x > 127)).collect();
    let covered = ours.iter().filter(|&&x| x).count();
    // The film's rows run bottom to top, the PPM's top to bottom.
    let same = (0..W * H).filter(|&i| ours[i] == theirs[(H - 1 - i / W) * W + i % W]).count();
    (covered, same as f64 / (W * H) as f64)
}

/// [`agreement`], printed and checked: the objects fill over 5 % of the view, the masks agree
/// on at least 99.5 % of it.
fn check(kind: &str, objects_toml: &str, objects_pov: &str) {
    let (covered, agree) = agreement(objects_toml, objects_pov);
    let differ = ((1.0 - agree) * (W * H) as f64).round();
    println!("{kind}: {covered} pixels covered, {:.3} % agree ({differ} differ)", 100.0 * agree);
    assert!(covered > W * H / 20, "{kind}: only {covered} pixels covered");
    assert!(agree >= 0.995, "{kind}: {:.3} % agree", 100.0 * agree);
}

/// `benches/povray/torus.pov`'s tori (no floor, no sphere): tilted, thin and fat. POV-Ray's
/// torus lies about its y axis; `Reorient_Trans` turns y to the normal.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn torus() {
    let tori = [
        ([-2.5, 1.0, 0.5], [1.0, -0.5, 1.5], 2.0, 0.45),
        ([2.8, 2.0, -1.2], [0.0, 0.0, 1.0], 2.2, 0.08),
        ([2.6, -2.0, -1.0], [0.2, 0.0, 1.0], 1.0, 0.95),
    ];
    let (mut toml, mut pov) = (String::new(), String::new());
    for ([x, y, z], [a, b, c], r, tube) in tori {
        toml += &tables(&[&format!(
            "type = \"torus\"\ncentre = [{x:?}, {y:?}, {z:?}]\nnormal = [{a:?}, {b:?}, {c:?}]\nradius = {r:?}\ntube = {tube:?}"
        )]);
        pov += &format!("torus {{ {r}, {tube} Reorient_Trans(y, <{a},{b},{c}>) translate <{x},{y},{z}> }}\n");
    }
    check("torus", &toml, &pov);
}

/// A large sphere, a small one, and one cut by the view's left edge.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn sphere() {
    let toml = tables(&[
        "type = \"sphere\"\ncentre = [0.0, 2.0, 0.0]\nradius = 3.0",
        "type = \"sphere\"\ncentre = [5.0, -3.0, -1.5]\nradius = 0.6",
        "type = \"sphere\"\ncentre = [-10.0, 1.0, 1.0]\nradius = 2.5",
    ]);
    let pov = "sphere { <0,2,0>, 3 }\nsphere { <5,-3,-1.5>, 0.6 }\nsphere { <-10,1,1>, 2.5 }\n";
    check("sphere", &toml, pov);
}

/// Disks facing the camera, tilted, nearly edge-on, and one crossing the bottom edge.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn disk() {
    let toml = tables(&[
        "type = \"disk\"\ncentre = [-4.0, 1.0, 1.0]\nnormal = [0.0, -1.0, 0.4]\nradius = 2.5",
        "type = \"disk\"\ncentre = [3.0, 0.0, 0.0]\nnormal = [1.0, -0.5, 1.0]\nradius = 2.0",
        "type = \"disk\"\ncentre = [0.0, 3.0, 3.0]\nnormal = [0.1, 0.35, 1.0]\nradius = 3.0",
        "type = \"disk\"\ncentre = [1.0, -4.0, -4.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 2.0",
    ]);
    let pov = "disc { <-4,1,1>, <0,-1,0.4>, 2.5 }\ndisc { <3,0,0>, <1,-0.5,1>, 2 }\n\
               disc { <0,3,3>, <0.1,0.35,1>, 3 }\ndisc { <1,-4,-4>, <0,0,1>, 2 }\n";
    check("disk", &toml, pov);
}

/// A tilted capped cylinder, a thin upright one, and an open tube seen nearly along its axis
/// (from the camera to it runs about `(3, 14, −3.4)`), so the view passes through it: a hole in
/// the mask where the caps would be.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn cylinder() {
    let toml = tables(&[
        "type = \"cylinder\"\np1 = [-4.5, 0.0, -2.0]\np2 = [-2.0, 1.5, 1.5]\nradius = 1.0",
        "type = \"cylinder\"\np1 = [-1.0, 4.0, -3.0]\np2 = [0.5, 3.0, 4.0]\nradius = 0.6",
        "type = \"cylinder\"\np1 = [2.6, -1.5, 2.0]\np2 = [3.2, 1.5, 1.3]\nradius = 1.5\ncaps = false",
    ]);
    let pov = "cylinder { <-4.5,0,-2>, <-2,1.5,1.5>, 1 }\ncylinder { <-1,4,-3>, <0.5,3,4>, 0.6 }\n\
               cylinder { <2.6,-1.5,2>, <3.2,1.5,1.3>, 1.5 open }\n";
    check("cylinder", &toml, pov);
}

/// A pointed cone (`r2 = 0`) upright, a truncated one tilted, and an open truncated one lying
/// across the view.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn cone() {
    let toml = tables(&[
        "type = \"cone\"\np1 = [0.0, -2.0, -2.0]\nr1 = 1.5\np2 = [0.0, -2.0, 1.5]\nr2 = 0.0",
        "type = \"cone\"\np1 = [3.5, 0.0, -2.0]\nr1 = 1.2\np2 = [3.0, 0.5, 0.5]\nr2 = 0.4",
        "type = \"cone\"\np1 = [-6.0, 2.0, 2.0]\nr1 = 0.5\np2 = [-2.0, -1.0, 3.0]\nr2 = 1.5\ncaps = false",
    ]);
    let pov = "cone { <0,-2,-2>, 1.5, <0,-2,1.5>, 0 }\ncone { <3.5,0,-2>, 1.2, <3,0.5,0.5>, 0.4 }\n\
               cone { <-6,2,2>, 0.5, <-2,-1,3>, 1.5 open }\n";
    check("cone", &toml, pov);
}

/// A box along the axes; one turned by a `transform` list (30° about x, then 40° about z, then
/// moved), POV-Ray's `rotate` step by step; one turned 35° about a tilted axis through a point
/// of it by a `motor` built here, POV-Ray's `Axis_Rotate_Trans` about that point.
///
/// The signs carry over unchanged: both turn right-handedly in the coordinates (POV-Ray's
/// `rotate` is the same matrix; it only looks left-handed on its own screen, and our camera's
/// `right` along −x mirrors that away). The opposite sign puts the turned boxes elsewhere and
/// the masks then disagree.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test silhouettes -- --ignored --nocapture"]
fn boxes() {
    use cga_core::{Motor, Rotor, Translator};
    // Rotate about the origin, then carry the origin to `p`: about `p` when the box is built
    // around the origin.
    let (axis, degrees, p) = ([0.3, 0.2, 1.0], 35.0f64, [4.0, 1.0, -1.0]);
    let r = Rotor::from_axis_angle(axis, degrees.to_radians()).unwrap();
    let m = Motor::from_rotor_translator(r, Translator::from_vector(p));
    let motor = [m.s, m.e12, m.e13, m.e23, m.e1i, m.e2i, m.e3i, m.e123i].map(|x| format!("{x:?}")).join(", ");
    let toml = tables(&[
        "type = \"box\"\nmin = [-6.5, -1.0, -2.0]\nmax = [-3.5, 2.0, 1.0]",
        "type = \"box\"\nmin = [-1.5, -1.0, -0.5]\nmax = [1.5, 1.0, 0.5]\ntransform = [\
             { rotate = { axis = [1.0, 0.0, 0.0], degrees = 30.0 } }, \
             { rotate = { axis = [0.0, 0.0, 1.0], degrees = 40.0 } }, { translate = [0.0, 0.0, 2.5] }]",
        &format!("type = \"box\"\nmin = [-1.5, -2.0, -0.4]\nmax = [1.5, 2.0, 0.4]\nmotor = [{motor}]"),
    ]);
    // POV-Ray's turns, by `s` times our angles.
    let ([a, b, c], [x, y, z]) = (axis, p);
    let pov = |s: f64| {
        format!(
            "box {{ <-6.5,-1,-2>, <-3.5,2,1> }}\n\
             box {{ <-1.5,-1,-0.5>, <1.5,1,0.5> rotate {}*x rotate {}*z translate <0,0,2.5> }}\n\
             box {{ <-1.5,-2,-0.4>, <1.5,2,0.4> Axis_Rotate_Trans(<{a},{b},{c}>, {}) translate <{x},{y},{z}> }}\n",
            s * 30.0,
            s * 40.0,
            s * degrees
        )
    };
    check("box", &toml, &pov(1.0));
    // Not vacuous: turned the other way, the turned boxes' masks part (by ~2 %).
    let (_, agree) = agreement(&toml, &pov(-1.0));
    println!("box, POV-Ray's turns reversed: {:.3} % agree", 100.0 * agree);
    assert!(agree < 0.995, "the turns' signs are not seen");
}
