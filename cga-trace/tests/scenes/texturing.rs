//! Textures on every shape, placed and bumped: each shape's `(u, v)` at known points, a
//! texture changing the picture of every kind of object, an image on a plane reading as
//! drawn seen from the side its normal faces, and bumps that change the shading but neither
//! what is covered nor the geometric normal.

use cga_trace::integrator::Window;
use cga_trace::shapes::{BoxShape, ConeShape, Crossing, Shape, TorusShape};
use cga_trace::texture::Unit;
use cga_trace::{Aov, Film, Renderer, Scene};
use std::path::Path;

fn parse_in(text: &str, folder: &Path) -> Scene {
    let file = folder.join("texturing-test.toml");
    Scene::parse(text, file.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn parse(text: &str) -> Scene {
    parse_in(text, &Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes"))
}

fn render(scene: &Scene, aov: Aov) -> Film {
    let c = &scene.camera;
    Renderer::new(scene).render_window(aov, Window::full(c.width, c.height), &|| {})
}

/// The colour of pixel `(i, j)` counted from the top-left.
fn pixel(film: &Film, i: u32, j: u32) -> [f64; 3] {
    film.pixels[((film.height - 1 - j) * film.width + i) as usize]
}

/// `uv` of `shape` at `point`, checked to be fractions and compared with `want` to 1e-12.
fn assert_uv(shape: &dyn Shape, point: [f64; 3], want: [f64; 2]) {
    let (uv, unit) = shape.uv(&Crossing { t: 1.0, point, alpha: None, part: 0 }).expect("(u, v)");
    assert_eq!(unit, Unit::Fraction);
    assert!((uv[0] - want[0]).abs() < 1e-12 && (uv[1] - want[1]).abs() < 1e-12, "at {point:?}: {uv:?}, not {want:?}");
}

#[test]
fn boxes_give_each_face_its_own_fractions_reading_from_outside() {
    let b = BoxShape::between([-1.0, -2.0, -3.0], [1.0, 2.0, 3.0]).unwrap();
    // +x: up z, right +y.
    assert_uv(&b, [1.0, 1.0, 1.5], [0.75, 0.25]);
    // −y: up z, right +x.
    assert_uv(&b, [0.5, -2.0, -1.5], [0.75, 0.75]);
    // +y: right −x.
    assert_uv(&b, [0.5, 2.0, 0.0], [0.25, 0.5]);
    // −x: right −y.
    assert_uv(&b, [-1.0, 1.0, 0.0], [0.25, 0.5]);
    // Top: up +y, right +x; bottom: up −y, right +x.
    assert_uv(&b, [-0.5, 1.0, 3.0], [0.25, 0.25]);
    assert_uv(&b, [-0.5, 1.0, -3.0], [0.25, 0.75]);
    // Near the top-left corner of +x, seen from outside: near 0, 0.
    assert_uv(&b, [1.0, -1.8, 2.7], [0.05, 0.05]);
}

#[test]
fn cylinders_and_cones_give_the_angle_and_the_place_down_the_axis_and_disks_on_their_caps() {
    let c = ConeShape::cylinder([0.0, 0.0, -1.0], [0.0, 0.0, 3.0], 0.5, true).unwrap();
    // Angle ½ + atan2(y, x)/2π about +z; v from 0 at p2 (z = 3) to 1 at p1 (z = −1).
    assert_uv(&c, [0.0, -0.5, 2.0], [0.25, 0.25]);
    assert_uv(&c, [0.5, 0.0, 1.0], [0.5, 0.5]);
    assert_uv(&c, [0.0, 0.5, -1.0 + 1e-3], [0.75, 1.0 - 0.25e-3]);
    // Caps: the same angle, r/R.
    assert_uv(&c, [0.0, 0.25, 3.0], [0.75, 0.5]);
    assert_uv(&c, [0.25, 0.0, -1.0], [0.5, 0.5]);
    let cone = ConeShape::new([0.0, 0.0, 0.0], 1.0, [0.0, 0.0, 2.0], 0.5, true).unwrap();
    assert_uv(&cone, [0.0, 0.75, 1.0], [0.75, 0.5]);
    assert_uv(&cone, [0.5, 0.0, 0.0], [0.5, 0.5]);
    assert_uv(&cone, [0.25, 0.0, 2.0], [0.5, 0.5]);
}

#[test]
fn tori_give_the_angles_about_the_axis_and_about_the_tube() {
    let t = TorusShape::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0, 0.5).unwrap();
    assert_uv(&t, [2.5, 0.0, 0.0], [0.5, 0.25]);
    assert_uv(&t, [0.0, 2.0, 0.5], [0.75, 0.0]);
    assert_uv(&t, [0.0, -1.5, 0.0], [0.25, 0.75]);
    assert_uv(&t, [2.0, 0.0, -0.5], [0.5, 0.5]);
}

/// A 40 × 40 view of `object` (its fields, then `material = …`) from −y, lit by one light.
fn view(object: &str, material: &str) -> Scene {
    parse(&format!(
        "[camera]\nposition = [0.0, -8.0, 3.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 30.0\nwidth = 40\nheight = 40\n\
         [render]\nambient = 0.3\n[[lights]]\nposition = [-3.0, -6.0, 8.0]\n\
         [[objects]]\nname = \"it\"\n{object}material = {{ colour = [0.9, 0.6, 0.2], ks = 0.3, q = 30.0{material} }}\n"
    ))
}

const OBJECTS: [&str; 5] = [
    "type = \"box\"\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, 1.0]\n",
    "type = \"cylinder\"\np1 = [0.0, 0.0, -1.0]\np2 = [0.0, 0.0, 1.0]\nradius = 1.0\ncaps = true\n",
    "type = \"cone\"\np1 = [0.0, 0.0, -1.0]\nr1 = 1.2\np2 = [0.0, 0.0, 1.0]\nr2 = 0.4\ncaps = true\n",
    "type = \"torus\"\ncentre = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.3, 1.0]\nradius = 1.3\ntube = 0.5\n",
    "type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.2\n",
];

#[test]
fn a_texture_shows_on_boxes_cylinders_cones_and_tori() {
    let textures = [
        "texture = { pattern = \"checker\", colour = [0.1, 0.2, 0.8], repeat = [8.0, 4.0] }",
        "texture = { pattern = \"gradient\", colour = [0.1, 0.2, 0.8], along = \"v\" }",
        "texture = { pattern = \"marble\", colour = [0.1, 0.2, 0.8], scale = [0.2, 0.2], turbulence = 2.0 }",
        "texture = { pattern = \"bricks\", colour = [0.1, 0.2, 0.8], repeat = [4.0, 4.0], rotate = 30.0, mortar = 0.15 }",
        "texture = { image = \"maps/grid.png\", flip = \"u\", offset = [0.1, 0.2] }",
    ];
    for object in OBJECTS {
        let plain = render(&view(object, ""), Aov::Shaded);
        for texture in textures {
            let textured = render(&view(object, &format!(", {texture}")), Aov::Shaded);
            let changed = plain.pixels.iter().zip(&textured.pixels).filter(|(a, b)| a != b).count();
            assert!(changed > 40, "{object} with {texture}: {changed} pixels changed");
        }
    }
}

#[test]
fn an_image_on_a_plane_reads_as_drawn_from_the_side_its_normal_faces() {
    // A 4 × 4 image black but for its top-left pixel.
    let folder = tempfile::tempdir().unwrap();
    let mut image = image::RgbImage::new(4, 4);
    image.put_pixel(0, 0, image::Rgb([255, 255, 255]));
    image.save(folder.path().join("corner.png")).unwrap();
    let material =
        "material = { colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0, texture = { image = \"corner.png\" } }";
    // A floor seen from above (up +y) and a wall seen from in front (up +z), each showing
    // the image's one copy over the unit square from the plane's point.
    for (camera, normal) in [
        ("position = [0.5, 0.5, 10.0]\nlook_at = [0.5, 0.5, 0.0]\nup = [0.0, 1.0, 0.0]", "[0.0, 0.0, 1.0]"),
        ("position = [0.5, -10.0, 0.5]\nlook_at = [0.5, 0.0, 0.5]\nup = [0.0, 0.0, 1.0]", "[0.0, -1.0, 0.0]"),
    ] {
        let s = parse_in(
            &format!(
                "[camera]\n{camera}\nprojection = \"orthographic\"\nview_width = 1.0\nwidth = 40\nheight = 40\n\
                 [render]\nambient = 1.0\n[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = {normal}\n{material}\n"
            ),
            folder.path(),
        );
        let film = render(&s, Aov::Shaded);
        let bright = |i, j| pixel(&film, i, j)[0];
        assert!(bright(4, 4) > 0.5, "the bright corner at the top-left: {}", bright(4, 4));
        for (i, j) in [(35, 4), (4, 35), (35, 35)] {
            assert!(bright(i, j) < 0.1, "({i}, {j}) is dark: {}", bright(i, j));
        }
    }
}

#[test]
fn a_bump_changes_the_shading_but_not_the_coverage_or_the_geometric_normal() {
    let bumps = [
        ", bump = { pattern = \"noise\", strength = 0.8, repeat = [6.0, 6.0], seed = 3 }",
        ", texture = { pattern = \"checker\", colour = [0.1, 0.2, 0.8], repeat = [8.0, 4.0] }, bump = { pattern = \"bricks\", strength = -0.5, repeat = [4.0, 4.0] }",
    ];
    let floor = "type = \"plane\"\npoint = [0.0, 0.0, -1.0]\nnormal = [0.0, 0.0, 1.0]\n";
    for object in OBJECTS.iter().copied().chain([floor]) {
        for bump in bumps {
            let (plain, bumped) = (view(object, ""), view(object, bump));
            let shaded = [render(&plain, Aov::Shaded), render(&bumped, Aov::Shaded)];
            let changed = shaded[0].pixels.iter().zip(&shaded[1].pixels).filter(|(a, b)| a != b).count();
            assert!(changed > 40, "{object}{bump}: {changed} pixels changed");
            let normals = [render(&plain, Aov::Normal), render(&bumped, Aov::Normal)];
            assert_eq!(normals[0].pixels, normals[1].pixels, "{object}{bump}: the geometric normals");
            let covered = |f: &Film| f.pixels.iter().map(|p| *p != [0.0; 3]).collect::<Vec<_>>();
            assert_eq!(covered(&shaded[0]), covered(&shaded[1]), "{object}{bump}: the coverage");
        }
    }
}

#[test]
fn texture_placement_and_patterns_reach_the_picture() {
    // A floor seen from above: a checker turned by 90° shows the checker of swapped repeats
    // read at (−x, y), the one flipped along u.
    let floor = |texture: &str| {
        parse(&format!(
            "[camera]\nposition = [0.0, 0.0, 10.0]\nlook_at = [0.0, 0.0, 0.0]\nup = [0.0, 1.0, 0.0]\nprojection = \"orthographic\"\nview_width = 8.0\nwidth = 80\nheight = 80\n\
             [render]\nambient = 1.0\n[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\
             material = {{ colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0, texture = {{ {texture} }} }}\n"
        ))
    };
    let turned = render(
        &floor("pattern = \"checker\", colour = [0.0, 0.0, 0.0], repeat = [0.5, 2.0], rotate = 90.0"),
        Aov::Shaded,
    );
    let swapped = render(
        &floor("pattern = \"checker\", colour = [0.0, 0.0, 0.0], repeat = [2.0, 0.5], flip = \"u\""),
        Aov::Shaded,
    );
    assert_eq!(turned.pixels, swapped.pixels);
    // Offset by a whole cell along u, a checker swaps its colours.
    let plain = render(&floor("pattern = \"checker\", colour = [0.0, 0.0, 0.0]"), Aov::Shaded);
    let moved = render(&floor("pattern = \"checker\", colour = [0.0, 0.0, 0.0], offset = [1.0, 0.0]"), Aov::Shaded);
    assert!(plain.pixels.iter().zip(&moved.pixels).all(|(a, b)| a[0] + b[0] == 1.0));
}
