//! Flat silhouettes against POV-Ray 3.7: each Euclidean object kind, a few of each in varied
//! poses, rendered by us and by POV-Ray in the same camera at 640×480; the pixels each covers
//! agree on at least 99.5 % (only pixels the edges cross may differ). The kinds that draw CGA
//! objects too (`point`, `point-pair`, `line`, `circle`, `plane-patch`, `blade`), against the
//! Euclidean shapes worked out here from their fields. Needs `povray`:
//!
//! ```text
//! apt-get install -y povray
//! cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
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

/// A point as TOML's `[x, y, z]` and POV-Ray's `<x,y,z>`.
fn toml3(p: [f64; 3]) -> String {
    format!("[{:?}, {:?}, {:?}]", p[0], p[1], p[2])
}
fn pov3(p: [f64; 3]) -> String {
    format!("<{},{},{}>", p[0], p[1], p[2])
}

/// Points (balls), a point pair with its segment (a capped cylinder) and one without.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn points_and_point_pairs() {
    let toml = tables(&[
        "type = \"point\"\npoint = [-4.5, 0.5, 2.5]\nsize = 1.3",
        "type = \"point\"\npoint = [0.5, -3.0, 3.5]\nsize = 0.6",
        "type = \"point-pair\"\npoints = [[-3.0, 1.0, -2.0], [1.5, -1.0, -0.5]]\nsize = 0.9\nsegment = true\ntube = 0.35",
        "type = \"point-pair\"\npoints = [[3.0, 2.0, 1.0], [5.0, -1.5, -2.0]]\nsize = 1.1\nsegment = false",
    ]);
    let pov = "sphere { <-4.5,0.5,2.5>, 1.3 }\nsphere { <0.5,-3,3.5>, 0.6 }\n\
               sphere { <-3,1,-2>, 0.9 }\nsphere { <1.5,-1,-0.5>, 0.9 }\ncylinder { <-3,1,-2>, <1.5,-1,-0.5>, 0.35 }\n\
               sphere { <3,2,1>, 1.1 }\nsphere { <5,-1.5,-2>, 1.1 }\n";
    check("points and point pairs", &toml, pov);
}

/// Lines across the view: nearly level, steep, and receding; POV-Ray's cylinders reach
/// 1000 units each way, far out of the picture.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn lines() {
    use cga_core::euclid::{add, norm, scale};
    let lines = [
        ([0.0, 0.0, -1.5], [1.0, 0.3, 0.15], 0.25),
        ([-2.0, 3.0, 1.0], [0.3, -0.4, 1.0], 0.3),
        ([2.0, 1.0, 2.0], [-1.0, 1.5, -0.6], 0.2),
    ];
    let (mut toml, mut pov) = (String::new(), String::new());
    for (p, d, tube) in lines {
        toml +=
            &tables(&[&format!("type = \"line\"\npoint = {}\ndirection = {}\ntube = {tube:?}", toml3(p), toml3(d))]);
        let d = scale(d, 1000.0 / norm(d));
        pov += &format!("cylinder {{ {}, {}, {tube} }}\n", pov3(add(p, scale(d, -1.0))), pov3(add(p, d)));
    }
    check("lines", &toml, &pov);
}

/// Circles by centre, normal and radius (tilted, and nearly edge-on), and one through three
/// points, its circumcircle worked out here: POV-Ray's tori.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn circles() {
    use cga_core::euclid::{add, cross, dot, scale, sub};
    let mut circles =
        vec![([-3.5, 0.5, 1.5], [0.3, -1.0, 0.5], 2.0, 0.3), ([3.0, 2.0, -1.0], [0.0, 0.0, 1.0], 2.5, 0.2)];
    let mut toml = String::new();
    for &(c, n, r, tube) in &circles {
        toml += &tables(&[&format!(
            "type = \"circle\"\ncentre = {}\nnormal = {}\nradius = {r:?}\ntube = {tube:?}",
            toml3(c),
            toml3(n)
        )]);
    }
    // Through a, b, c: the centre a + x u + y v (u = b − a, v = c − a) is as far from each,
    // so x u·u + y u·v = u·u/2 and x u·v + y v·v = v·v/2.
    let (a, b, c, tube) = ([0.5, -2.0, -3.0], [2.5, -1.0, -1.0], [0.0, 0.0, -0.5], 0.35);
    toml +=
        &tables(&[&format!("type = \"circle\"\npoints = [{}, {}, {}]\ntube = {tube:?}", toml3(a), toml3(b), toml3(c))]);
    let (u, v) = (sub(b, a), sub(c, a));
    let (uu, uv, vv) = (dot(u, u), dot(u, v), dot(v, v));
    let det = uu * vv - uv * uv;
    let (x, y) = ((uu * vv - uv * vv) / (2.0 * det), (uu * vv - uv * uu) / (2.0 * det));
    let centre = add(a, add(scale(u, x), scale(v, y)));
    let r = dot(sub(a, centre), sub(a, centre)).sqrt();
    circles.push((centre, cross(u, v), r, tube));
    let pov: String = circles
        .iter()
        .map(|&(c, n, r, tube)| {
            format!("torus {{ {r}, {tube} Reorient_Trans(y, {}) translate {} }}\n", pov3(n), pov3(c))
        })
        .collect();
    check("circles", &toml, &pov);
}

/// Plane patches facing the camera, tilted, crossing the bottom edge, and one through three
/// points: a disk about their centroid, normal to their plane.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn plane_patches() {
    use cga_core::euclid::{cross, sub};
    let (a, b, c) = ([-1.0, 3.0, 3.0], [2.0, 4.0, 3.5], [0.0, 5.0, 2.0]);
    let toml = tables(&[
        "type = \"plane-patch\"\npoint = [-4.0, 1.0, 1.0]\nnormal = [0.0, -1.0, 0.4]\nsize = 2.5",
        "type = \"plane-patch\"\npoint = [3.0, 0.0, 0.0]\nnormal = [1.0, -0.5, 1.0]\nsize = 2.0",
        "type = \"plane-patch\"\npoint = [1.5, -5.0, -4.0]\nnormal = [0.2, 0.1, 1.0]\nsize = 2.2",
        &format!("type = \"plane-patch\"\npoints = [{}, {}, {}]\nsize = 1.5", toml3(a), toml3(b), toml3(c)),
    ]);
    let centroid = [0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0);
    let pov = format!(
        "disc {{ <-4,1,1>, <0,-1,0.4>, 2.5 }}\ndisc {{ <3,0,0>, <1,-0.5,1>, 2 }}\ndisc {{ <1.5,-5,-4>, <0.2,0.1,1>, 2.2 }}\n\
         disc {{ {}, {}, 1.5 }}\n",
        pov3(centroid),
        pov3(cross(sub(b, a), sub(c, a)))
    );
    check("plane patches", &toml, &pov);
}

/// Raw blades read as cga-core classifies them, against Euclidean objects worked out here
/// from the coefficients: a dual sphere `w (c + eo + ½(|c|² − r²) ei)` (weight 2) is the
/// sphere of centre `(e1, e2, e3)/eo` and `r² = |c|² − 2 ei/eo`; an imaginary one (weight −1.5,
/// `r² < 0`) three dashed great circles of radius `√−r²` about e1, e2, e3, each 24 capped
/// rods (chords from `2πk/24` over 0.6 of their arc, in the basis `u, v = n × u` that
/// `cga_core::euclid::perpendicular` gives for that axis); a flat point
/// `x1 e1i + x2 e2i + x3 e3i + eoi` a cube of half edge `size` at `x`.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn blades() {
    use std::f64::consts::TAU;
    let sphere = |[e1, e2, e3, eo, ei]: [f64; 5]| {
        let c = [e1 / eo, e2 / eo, e3 / eo];
        (c, c.iter().map(|x| x * x).sum::<f64>() - 2.0 * ei / eo)
    };
    let (real, imaginary, tube) = ([-7.0, 2.0, 2.0, 2.0, 5.25], [-4.5, 0.0, -2.25, -1.5, -11.4375], 0.15);
    let (x, size) = ([0.5, -3.0, -2.5], 0.9);
    let blade = |[e1, e2, e3, eo, ei]: [f64; 5]| {
        format!("{{ e1 = {e1:?}, e2 = {e2:?}, e3 = {e3:?}, eo = {eo:?}, ei = {ei:?} }}")
    };
    let toml = tables(&[
        &format!("type = \"blade\"\nblade = {}", blade(real)),
        &format!("type = \"blade\"\nblade = {}\ntube = {tube:?}", blade(imaginary)),
        &format!(
            "type = \"blade\"\nblade = {{ e1i = {:?}, e2i = {:?}, e3i = {:?}, eoi = 1.0 }}\nsize = {size:?}",
            x[0], x[1], x[2]
        ),
    ]);
    let (c, r2) = sphere(real);
    assert!(r2 > 0.0);
    let mut pov = format!("sphere {{ {}, {} }}\n", pov3(c), r2.sqrt());
    pov += &format!("box {{ {}, {} }}\n", pov3(x.map(|x| x - size)), pov3(x.map(|x| x + size)));
    let (c, r2) = sphere(imaginary);
    assert!(r2 < 0.0);
    let r = (-r2).sqrt();
    // (u, v) about e1, e2, e3: `perpendicular` crosses n with the first axis least aligned.
    let bases = [
        ([0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        ([0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]),
        ([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
    ];
    for (u, v) in bases {
        let on = |t: f64| pov3([0, 1, 2].map(|k| c[k] + r * (u[k] * t.cos() + v[k] * t.sin())));
        for k in 0..24 {
            let start = TAU * k as f64 / 24.0;
            pov += &format!("cylinder {{ {}, {}, {tube} }}\n", on(start), on(start + 0.6 * TAU / 24.0));
        }
    }
    check("blades", &toml, &pov);
}

/// Surfaces that touch, in flat colours against POV-Ray (ambient only, no lights): a glass box
/// standing on a floor checkered white and green in unit cells (its bottom face in the
/// floor's plane; the checker seen through it shows the refraction), a blue disk lying on the
/// floor and a red ball standing on it. Each pixel falls in one of eight colour classes (each
/// channel over half or not); the classes agree on at least 99.5 % of the pixels. A ray that
/// leaves the box's bottom face below the floor would see the black sky (the speckle of a
/// contact decided by rounding); the disk must show over the floor, which it shares a plane
/// with. POV-Ray draws the disk over the floor only when it is lifted off it (coincident
/// surfaces are its documented weakness), so its disk is lifted by 1e-4.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn touching_surfaces() {
    let flat = |c: &str| format!("material = {{ colour = {c}, ka = 1.0, kd = 0.0, ks = 0.0 }}");
    let objects = |order: &[usize]| -> String {
        let bodies = [
            "type = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = { colour = [1.0, 1.0, 1.0], \
             ka = 1.0, kd = 0.0, ks = 0.0, texture = { pattern = \"checker\", colour = [0.1, 0.8, 0.1] } }"
                .to_string(),
            "type = \"box\"\nmin = [-2.0, -1.0, 0.0]\nmax = [1.0, 1.5, 2.5]\n\
             material = { colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 0.0, ks = 0.0, ior = 1.5 }"
                .to_string(),
            format!("type = \"disk\"\ncentre = [4.0, -1.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1.5\n{}", flat("[0.1, 0.2, 0.9]")),
            format!("type = \"sphere\"\ncentre = [-5.0, 0.5, 1.2]\nradius = 1.2\n{}", flat("[0.9, 0.2, 0.1]")),
        ];
        order.iter().map(|&k| format!("[[objects]]\n{}\n", bodies[k])).collect()
    };
    // Our checker is green where ⌊x⌋ + ⌊y⌋ is odd; POV-Ray's takes its first colour where
    // ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, and its pattern lifted by ½ reads ⌊z⌋ = −1 on the floor (never
    // a rounding of z = 0 to either side).
    let pov = "plane { z, 0 texture { pigment { checker rgb <0.1,0.8,0.1>, rgb 1 translate 0.5*z } } }\n\
        box { <-2,-1,0>, <1,1.5,2.5> texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy } } interior { ior 1.5 } }\n\
        disc { <4,-1,0.0001>, z, 1.5 texture { pigment { rgb <0.1,0.2,0.9> } } }\n\
        sphere { <-5,0.5,1.2>, 1.2 texture { pigment { rgb <0.9,0.2,0.1> } } }\n";
    let theirs = povray(&format!("{THEIRS}global_settings {{ max_trace_level 8 }}\n{pov}"));
    let class = |p: [f64; 3]| p.map(|x| x > 0.5);
    for order in [[0, 1, 2, 3], [3, 2, 1, 0]] {
        let text = format!("{OURS}ambient = 1.0\nmax_depth = 8\n{}", objects(&order));
        let scene = Scene::parse(&text, "touching.toml").unwrap();
        let film = Renderer::new(&scene).render(Aov::Shaded, &|| {});
        let same = (0..W * H).filter(|&i| class(film.pixels[i]) == class(theirs[(H - 1 - i / W) * W + i % W])).count();
        let agree = same as f64 / (W * H) as f64;
        let blue = film.pixels.iter().filter(|p| class(**p) == [false, false, true]).count();
        println!("touching surfaces, order {order:?}: {:.3} % agree, {blue} disk pixels", 100.0 * agree);
        assert!(blue > 2000, "the disk shows: {blue} pixels");
        assert!(agree >= 0.995, "{:.3} % agree", 100.0 * agree);
    }
}

/// POV-Ray's picture of `pov` at W×H without anti-aliasing: linear colours (gamma 1), rows top
/// to bottom.
fn povray(pov: &str) -> Vec<[f64; 3]> {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.pov"), pov).unwrap();
    let out = std::process::Command::new("povray")
        .current_dir(dir.path())
        .args(["+Is.pov", "+Os.ppm", "+FP", &format!("+W{W}"), &format!("+H{H}"), "-D", "-A", "-GA", "File_Gamma=1.0"])
        .output()
        .expect("povray runs (apt-get install -y povray)");
    assert!(out.status.success(), "povray failed: {}", String::from_utf8_lossy(&out.stderr));
    let ppm = std::fs::read(dir.path().join("s.ppm")).unwrap();
    assert!(ppm.starts_with(b"P6") && ppm.len() > 3 * W * H);
    ppm[ppm.len() - 3 * W * H..].chunks(3).map(|p| [0, 1, 2].map(|k| p[k] as f64 / 255.0)).collect()
}

/// CSG and clips against POV-Ray's `difference`, `intersection`, `union` and `clipped_by`:
/// a sphere bored through along the view (the hole shows the background), a lens of two
/// spheres, a box and a sphere joined, a sphere cut open by a plane (seen into the bowl), and
/// a torus cut by a plane and capped.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn csg() {
    let toml = tables(&[
        "type = \"csg\"\noperation = \"difference\"\nobjects = [{ type = \"sphere\", centre = [-3.0, 0.0, 0.0], radius = 2.2 }, { type = \"cylinder\", p1 = [-3.0, -7.0, 2.5], p2 = [-3.0, 7.0, -2.5], radius = 0.8 }]",
        "type = \"csg\"\noperation = \"intersection\"\nobjects = [{ type = \"sphere\", centre = [2.5, 0.0, 1.5], radius = 1.6 }, { type = \"sphere\", centre = [3.5, 0.0, 1.5], radius = 1.6 }]",
        "type = \"csg\"\noperation = \"union\"\nobjects = [{ type = \"box\", min = [1.5, -1.0, -3.0], max = [4.0, 1.0, -1.5] }, { type = \"sphere\", centre = [4.0, 0.0, -1.5], radius = 1.0 }]",
        "type = \"sphere\"\ncentre = [0.0, 2.0, -2.0]\nradius = 1.5\nclip = { plane = { point = [0.0, 2.0, -2.0], normal = [0.0, 0.0, 1.0] } }",
        "type = \"torus\"\ncentre = [0.0, 0.0, 3.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 1.6\ntube = 0.5\nclip = { plane = { point = [0.3, 0.0, 3.0], normal = [1.0, 0.0, 0.0] }, capped = true }",
    ]);
    let pov = "difference { sphere { <-3,0,0>, 2.2 } cylinder { <-3,-7,2.5>, <-3,7,-2.5>, 0.8 } }\n\
               intersection { sphere { <2.5,0,1.5>, 1.6 } sphere { <3.5,0,1.5>, 1.6 } }\n\
               union { box { <1.5,-1,-3>, <4,1,-1.5> } sphere { <4,0,-1.5>, 1 } }\n\
               sphere { <0,2,-2>, 1.5 clipped_by { plane { z, -2 } } }\n\
               intersection { torus { 1.6, 0.5 Reorient_Trans(y, z) translate <0,0,3> } plane { x, 0.3 } }\n";
    check("csg", &toml, pov);
}

/// A closed torus mesh about z (radii 1.8 and 0.6, `48 × 24` quads) at `centre`, as an .obj
/// file in `dir` and as POV-Ray's `mesh` (with the `inside_vector` CSG needs).
fn torus_mesh(dir: &std::path::Path, name: &str, centre: [f64; 3]) -> (String, String) {
    let (m, n) = (48, 24);
    let corner = |i: usize, j: usize| {
        let (u, v) = (std::f64::consts::TAU * i as f64 / m as f64, std::f64::consts::TAU * j as f64 / n as f64);
        let r = 1.8 + 0.6 * v.cos();
        [centre[0] + r * u.cos(), centre[1] + r * u.sin(), centre[2] + 0.6 * v.sin()]
    };
    let at = |i: usize, j: usize| (i % m) * n + j % n;
    let faces: Vec<[usize; 3]> = (0..m)
        .flat_map(|i| {
            (0..n).flat_map(move |j| {
                [[at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]]
            })
        })
        .collect();
    let corners: Vec<[f64; 3]> = (0..m).flat_map(|i| (0..n).map(move |j| (i, j))).map(|(i, j)| corner(i, j)).collect();
    let mut obj: String = corners.iter().map(|[x, y, z]| format!("v {x:?} {y:?} {z:?}\n")).collect();
    obj += &faces.iter().map(|[a, b, c]| format!("f {} {} {}\n", a + 1, b + 1, c + 1)).collect::<String>();
    let path = dir.join(name);
    std::fs::write(&path, obj).unwrap();
    let v = |k: usize| format!("<{:?},{:?},{:?}>", corners[k][0], corners[k][1], corners[k][2]);
    let triangles: String =
        faces.iter().map(|[a, b, c]| format!("triangle {{ {}, {}, {} }}\n", v(*a), v(*b), v(*c))).collect();
    (path.display().to_string(), format!("mesh {{ {triangles} inside_vector <0.3,0.2,1> }}"))
}

/// CSG of closed meshes against POV-Ray's: a sphere with a torus mesh taken away (notches
/// in its outline), a box cut to a torus mesh, and a torus mesh cut by a plane and capped.
#[test]
#[ignore = "needs povray: apt-get install -y povray; cargo test --release -p cga-trace --test shapes silhouettes:: -- --ignored --nocapture"]
fn csg_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let (a, pov_a) = torus_mesh(dir.path(), "a.obj", [-3.0, 0.0, 0.0]);
    let (b, pov_b) = torus_mesh(dir.path(), "b.obj", [3.0, 0.0, 0.0]);
    let (c, pov_c) = torus_mesh(dir.path(), "c.obj", [0.0, 0.0, 3.2]);
    let toml = tables(&[
        &format!(
            "type = \"csg\"\noperation = \"difference\"\nobjects = [{{ type = \"sphere\", centre = [-3.0, 0.0, 0.0], radius = 2.0 }}, {{ type = \"mesh\", file = {a:?} }}]"
        ),
        &format!(
            "type = \"csg\"\noperation = \"intersection\"\nobjects = [{{ type = \"box\", min = [1.0, -3.0, -0.3], max = [4.6, 3.0, 1.0] }}, {{ type = \"mesh\", file = {b:?} }}]"
        ),
        &format!(
            "type = \"mesh\"\nfile = {c:?}\nclip = {{ plane = {{ point = [0.5, 0.0, 3.2], normal = [1.0, 0.0, 0.0] }}, capped = true }}"
        ),
    ]);
    let pov = format!(
        "difference {{ sphere {{ <-3,0,0>, 2 }} {pov_a} }}\n\
         intersection {{ box {{ <1,-3,-0.3>, <4.6,3,1> }} {pov_b} }}\n\
         intersection {{ {pov_c} plane {{ x, 0.5 }} }}\n"
    );
    check("csg of meshes", &toml, &pov);
}
