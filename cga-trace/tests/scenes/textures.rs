//! Textures on the surfaces' own parameters, and the environment rays see when they leave:
//! each colour read back from a render at a place whose `(u, v)` or direction is known.

use cga_trace::environment::Environment;
use cga_trace::integrator::Window;
use cga_trace::picture::Picture;
use cga_trace::shapes::{Crossing, DiskShape, Shape, TriangleShape};
use cga_trace::texture::Unit;
use cga_trace::{Aov, Film, Renderer, Scene};
use std::path::Path;

fn parse(text: &str) -> Scene {
    // Named as if beside the shipped scenes, so that `maps/…` is found.
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/textures-test.toml");
    Scene::parse(text, file.to_str().unwrap()).unwrap()
}

fn render(scene: &Scene) -> Film {
    let c = &scene.camera;
    Renderer::new(scene).render_window(Aov::Shaded, Window::full(c.width, c.height), &|| {})
}

/// The colour of pixel `(i, j)` counted from the top-left.
fn pixel(film: &Film, i: u32, j: u32) -> [f64; 3] {
    film.pixels[((film.height - 1 - j) * film.width + i) as usize]
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= tolerance)
}

/// Lit by the ambient light alone, at full strength: a pixel shows the texture's colour.
const FLAT: &str = "ka = 1.0, kd = 0.0, ks = 0.0";

#[test]
fn a_floor_checker_has_cells_of_world_units_from_the_planes_point() {
    // Looking straight down (orthographic, 8 units over 80 pixels): the plane through
    // (0.3, 0.2, 0) has u = x − 0.3 and v = y − 0.2, cells 1 unit.
    let s = parse(&format!(
        "[camera]\nposition = [0.0, 0.0, 10.0]\nlook_at = [0.0, 0.0, 0.0]\nup = [0.0, 1.0, 0.0]\nprojection = \"orthographic\"\nview_width = 8.0\nwidth = 80\nheight = 80\n\
         [render]\nambient = 1.0\n[[objects]]\ntype = \"plane\"\npoint = [0.3, 0.2, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\
         material = {{ colour = [1.0, 1.0, 1.0], {FLAT}, texture = {{ pattern = \"checker\", colour = [0.0, 0.0, 0.0] }} }}\n"
    ));
    let film = render(&s);
    // World (x, y) at pixel (i, j) from the top-left: x = −4 + (i + ½)/10, y = 4 − (j + ½)/10.
    for (i, j) in [(10, 10), (40, 40), (47, 33), (3, 77), (79, 0)] {
        let (x, y) = (-4.0 + (f64::from(i) + 0.5) / 10.0, 4.0 - (f64::from(j) + 0.5) / 10.0);
        let odd = ((x - 0.3).floor() + (y - 0.2).floor()).rem_euclid(2.0) == 1.0;
        let want = if odd { [0.0; 3] } else { [1.0; 3] };
        assert_eq!(pixel(&film, i, j), want, "pixel ({i}, {j}) at ({x}, {y})");
    }
}

#[test]
fn an_image_wraps_a_sphere_by_longitude_and_colatitude() {
    // Seen from −y, the sphere's nearest point has longitude −90°: u = ¼, v = ½.
    let s = parse(&format!(
        "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nx_max = 0.5\nwidth = 41\nheight = 41\n\
         [render]\nambient = 1.0\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n\
         material = {{ colour = [1.0, 1.0, 1.0], {FLAT}, texture = {{ image = \"maps/grid.png\" }} }}\n"
    ));
    let picture = Picture::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/maps/grid.png")).unwrap();
    let got = pixel(&render(&s), 20, 20);
    assert!(close(got, picture.at(0.25, 0.5), 1e-12), "{got:?} vs {:?}", picture.at(0.25, 0.5));
}

#[test]
fn a_spheres_texture_turns_with_its_motor() {
    // Turned a quarter turn about z (and moved), the sphere shows at its nearest point what
    // the unturned one shows a quarter turn on: longitude −90° − 90°, u = 0 (the seam's
    // neighbour: sampled at u = 1 − ε and 0 + ε alike by the wrapping lookup).
    let sphere = |transform: &str| {
        parse(&format!(
            "[camera]\nposition = [2.0, -10.0, 0.0]\nlook_at = [2.0, 0.0, 0.0]\nx_max = 0.5\nwidth = 41\nheight = 41\n\
             [render]\nambient = 1.0\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n{transform}\
             material = {{ colour = [1.0, 1.0, 1.0], {FLAT}, texture = {{ image = \"maps/grid.png\" }} }}\n"
        ))
    };
    let turned = sphere(
        "transform = [{ rotate = { axis = [0.0, 0.0, 1.0], degrees = 90.0 } }, { translate = [2.0, 0.0, 0.0] }]\n",
    );
    let picture = Picture::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/maps/grid.png")).unwrap();
    let got = pixel(&render(&turned), 20, 20);
    assert!(close(got, picture.at(0.0, 0.5), 1e-9), "{got:?} vs {:?}", picture.at(0.0, 0.5));
    // Moved only, it shows what it shows at the origin.
    let moved = pixel(&render(&sphere("transform = [{ translate = [2.0, 0.0, 0.0] }]\n")), 20, 20);
    assert!(close(moved, picture.at(0.25, 0.5), 1e-9), "{moved:?} vs {:?}", picture.at(0.25, 0.5));
}

#[test]
fn stripes_along_alpha_split_an_evolved_cylinder_at_its_middle() {
    // Two coaxial circles of radius 1 at heights −1 and 1: α = (z + 1)/2 (the circle
    // family of a cylinder), so stripes of 2 per unit of α change colour at z = 0.
    let s = parse(&format!(
        "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\nview_width = 4.0\nwidth = 40\nheight = 40\n\
         [render]\nambient = 1.0\n[[objects]]\ntype = \"evolved\"\n\
         c1 = {{ centre = [0.0, 0.0, -1.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }}\nc2 = {{ centre = [0.0, 0.0, 1.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }}\n\
         material = {{ colour = [1.0, 1.0, 1.0], {FLAT}, texture = {{ pattern = \"stripes\", colour = [0.0, 0.0, 0.0], repeat = [2.0, 1.0] }} }}\n"
    ));
    let film = render(&s);
    // Rows from the top: z = 2 − (j + ½)/10; the cylinder spans z ∈ (−1, 1).
    for j in [11, 15, 19] {
        assert_eq!(pixel(&film, 20, j), [0.0; 3], "row {j} (α ≥ ½)");
    }
    for j in [20, 25, 28] {
        assert_eq!(pixel(&film, 20, j), [1.0; 3], "row {j} (α < ½)");
    }
}

#[test]
fn disks_and_triangles_give_their_own_parameters() {
    let disk = DiskShape::new([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 2.0).unwrap();
    let at = |point| Crossing { t: 1.0, point, alpha: None, part: 0 };
    // Half the radius out along the first axis orthonormal to +z (x): angle ½ turn from
    // atan2's −π, r/R = ½.
    let (uv, unit) = disk.uv(&at([2.0, 2.0, 3.0])).unwrap();
    assert_eq!(unit, Unit::Fraction);
    assert!((uv[0] - 0.5).abs() < 1e-15 && (uv[1] - 0.5).abs() < 1e-15, "{uv:?}");
    let triangle = TriangleShape::new([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 4.0, 0.0]]).unwrap();
    let (uv, _) = triangle.uv(&at([0.5, 1.0, 0.0])).unwrap();
    assert!((uv[0] - 0.25).abs() < 1e-15 && (uv[1] - 0.25).abs() < 1e-15, "{uv:?}");
}

#[test]
fn rays_that_leave_see_the_gradient_directly_and_in_a_mirror() {
    let sky = "[environment]\nzenith = [0.0, 0.0, 1.0]\nhorizon = [1.0, 1.0, 1.0]\nnadir = [0.0, 0.0, 0.0]\n";
    // Looking along +y: the middle row sees the horizon; the top row is 10° up (fov 20°,
    // square pixels: the vertical half-angle is 10° too).
    let s = parse(&format!(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nfov = 20.0\nwidth = 21\nheight = 21\n{sky}"
    ));
    let film = render(&s);
    assert!(close(pixel(&film, 10, 10), [1.0; 3], 1e-15));
    let want = Environment::Gradient { zenith: [0.0, 0.0, 1.0], horizon: [1.0; 3], nadir: [0.0; 3] };
    let top = s.camera.ray(10.5, 20.5).unwrap().dir;
    assert!(close(pixel(&film, 10, 0), want.seen(top), 1e-15));
    // A mirror floor seen at 45° reflects the sky 45° up: ½ of the way to the zenith
    // (sin 45° along the gradient), times k_r = 1.
    let s = parse(&format!(
        "[camera]\nposition = [0.0, -5.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\nx_max = 0.01\nwidth = 1\nheight = 1\n{sky}\
         [render]\nambient = 0.0\n[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\
         material = {{ colour = [0.0, 0.0, 0.0], ka = 0.0, kd = 0.0, ks = 0.0, kr = 1.0 }}\n"
    ));
    let w = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(pixel(&render(&s), 0, 0), [1.0 - w, 1.0 - w, 1.0], 1e-12));
}

#[test]
fn an_environment_map_is_seen_at_its_longitude() {
    // Looking along +x with the map turned by 90°: longitude 0 − 90°, u = ¼, at the
    // horizon v = ½; times the strength.
    let s = parse(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [1.0, 0.0, 0.0]\nx_max = 0.01\nwidth = 1\nheight = 1\n\
         [environment]\nimage = \"maps/sky.png\"\nrotate = 90.0\nstrength = 2.0\n",
    );
    let picture = Picture::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/maps/sky.png")).unwrap();
    let want = picture.at(0.25, 0.5).map(|c| 2.0 * c);
    let got = pixel(&render(&s), 0, 0);
    assert!(close(got, want, 1e-12), "{got:?} vs {want:?}");
}

#[test]
fn one_image_under_many_names_is_read_once() {
    let maps = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let ball = |k: usize, name: &str| {
        format!(
            "[[objects]]\ntype = \"sphere\"\ncentre = [{k}.0, 0.0, 0.0]\nradius = 0.4\n\
             material = {{ colour = [1.0, 1.0, 1.0], texture = {{ image = \"{name}\" }} }}\n"
        )
    };
    let names = ["maps/grid.png", "./maps/grid.png", "maps/../maps/grid.png", "../scenes/maps/grid.png"];
    let objects: String = names.iter().enumerate().map(|(k, n)| ball(k, n)).collect();
    let text = format!(
        "[camera]\nposition = [1.5, -8.0, 0.0]\nlook_at = [1.5, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
         [environment]\nimage = \"maps/grid.png\"\n{objects}"
    );
    let scene = Scene::parse(&text, maps.join("scene.toml").to_str().unwrap()).unwrap();
    let roles: Vec<&str> = scene.inputs.iter().map(|i| i.role).collect();
    assert_eq!(roles, ["scene", "environment image", "texture"], "{:?}", scene.inputs);
    let pictures: Vec<_> = scene
        .objects
        .iter()
        .map(|o| match &o.texture.as_ref().unwrap().pattern {
            cga_trace::texture::Pattern::Image(p) => p.clone(),
            _ => unreachable!("an image"),
        })
        .collect();
    assert!(pictures.iter().all(|p| std::sync::Arc::ptr_eq(p, &pictures[0])), "one decoded picture");
}

#[test]
fn an_image_past_the_scenes_pixel_budget_is_refused_before_decoding() {
    let grid = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/maps/grid.png");
    let size = Picture::load(&grid).map(|p| u64::from(p.width) * u64::from(p.height)).unwrap();
    let open = || std::fs::File::open(&grid).unwrap();
    assert!(Picture::read(open(), &grid, size).is_ok());
    let e = Picture::read(open(), &grid, size - 1).unwrap_err().to_string();
    assert!(e.contains("grid.png") && e.contains("limit of 134217728 pixels in all"), "{e}");
}
