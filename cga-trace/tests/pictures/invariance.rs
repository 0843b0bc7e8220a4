//! The same picture wherever the scene sits and whatever its size: every shipped scene,
//! moved along the diagonal by 1e3 … 1e6 and scaled about the origin by 1e-3 and 1e3
//! (attenuation rescaled to match), renders as the original on all three back ends — mean
//! difference ≤ 0.5 of 255 levels, at most 0.1 % of pixels off by more than 8 levels.
//!
//! The scene file itself is transformed (as a user would write the moved scene), so this
//! checks the whole path: parsing, the camera-relative frame, every shape and the shading.

use crate::common;

use cga_core::euclid::E3;
use cga_trace::backend::{Backend, Dense, Plain, Sparse};
use cga_trace::{Aov, Options, Pipeline, Renderer, Scene, View};
use common::{Similarity, floats, scene_of, table, triple};
use toml::{Table, Value};

/// Shipped scenes' samples per pixel at most (the soft shadows, lenses and shutters keep
/// their stratification; a debug build renders them in seconds).
const MAX_SPP: u32 = 4;

fn picture<B: Backend>(scene: &Scene) -> Vec<u8> {
    let film = Renderer::<B>::with_backend(scene).render(Aov::Shaded, &|| {});
    film.to_rgb8(scene.settings.encoding).into_raw()
}

/// A shipped scene's picture, moved by `similarity`, at `width × height` and at most
/// [`MAX_SPP`] samples, through the library's pipeline (and the scene's shutter where it
/// has one).
fn shipped<B: Backend>(name: &str, similarity: Option<&Similarity>, width: u32, height: u32) -> Vec<u8> {
    let mut t = table(name);
    if let Some(s) = similarity {
        s.apply(&mut t);
    }
    // Named by its path, so that the images it names are found beside it.
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
    let view = View { width: Some(width), height: Some(height), ..View::default() };
    let text = toml::to_string(&t).unwrap();
    let mut pipeline = Pipeline::parse(&text, file.to_str().unwrap(), view).unwrap_or_else(|e| panic!("{name}: {e}"));
    let spp = pipeline.scene(0.0).unwrap().settings.spp.min(MAX_SPP);
    pipeline.set_view(View { spp: Some(spp), ..view });
    let scene = pipeline.scene(0.0).unwrap();
    let options = Options { backend: B::KIND, ..Options::default() };
    let rendered = pipeline.render(&scene, &options, &|| {}).unwrap_or_else(|e| panic!("{name}: {e}"));
    rendered.film.to_rgb8(scene.settings.encoding).into_raw()
}

/// `(mean |Δ| in levels, fraction of pixels with a channel off by more than 8 levels)`.
fn difference(a: &[u8], b: &[u8]) -> (f64, f64) {
    let mean = a.iter().zip(b).map(|(x, y)| f64::from(x.abs_diff(*y))).sum::<f64>() / a.len() as f64;
    let off = a.chunks(3).zip(b.chunks(3)).filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > 8)).count();
    (mean, off as f64 / (a.len() / 3) as f64)
}

/// The shipped scenes every back end renders anywhere the same.
const SCENES: [&str; 14] = [
    "primitives.toml",
    "surface.toml",
    "combined.toml",
    "torus.toml",
    "box.toml",
    "cylinder.toml",
    "blades.toml",
    "spot.toml",
    "glass.toml",
    "lens.toml",
    "motion.toml",
    "textures.toml",
    "assembly.toml",
    "contact.toml",
];

fn check<B: Backend>(width: u32, height: u32) {
    check_scenes::<B>(&SCENES, width, height);
}

fn check_scenes<B: Backend>(names: &[&str], width: u32, height: u32) {
    let moves = [
        ("shifted 1e3", 1.0, 1e3),
        ("shifted 1e4", 1.0, 1e4),
        ("shifted 1e5", 1.0, 1e5),
        ("shifted 1e6", 1.0, 1e6),
        ("scaled 1e-3", 1e-3, 0.0),
        ("scaled 1e3", 1e3, 0.0),
    ];
    let mut failures = Vec::new();
    for &name in names {
        let original = shipped::<B>(name, None, width, height);
        for (what, scale, shift) in moves {
            let moved = shipped::<B>(name, Some(&Similarity { scale, shift }), width, height);
            let (mean, off) = difference(&original, &moved);
            println!("{:6} {name:16} {what:12} mean {mean:.4} levels, {:.3} % of pixels > 8", B::NAME, 100.0 * off);
            if mean > 0.5 || off > 1e-3 {
                failures.push(format!("{} {name} {what}: mean {mean:.3}, {:.3} % off", B::NAME, 100.0 * off));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn sparse_pictures_do_not_depend_on_place_or_scale() {
    check::<Sparse>(96, 72);
}

#[test]
fn plain_pictures_do_not_depend_on_place_or_scale() {
    check::<Plain>(96, 72);
}

/// The spline, ruled and cut-away scenes (smaller: a debug build intersects their surfaces
/// slowly).
#[test]
fn spline_and_ruled_pictures_do_not_depend_on_place_or_scale() {
    check_scenes::<Sparse>(&["fig3b.toml", "ruled.toml", "cutaway.toml"], 48, 36);
}

/// The dense back end, slower, in two halves that the test threads share.
#[test]
fn dense_pictures_do_not_depend_on_place_or_scale() {
    check_scenes::<Dense>(&SCENES[..7], 48, 36);
}

#[test]
fn dense_pictures_of_the_other_scenes_do_not_depend_on_place_or_scale() {
    check_scenes::<Dense>(&SCENES[7..], 48, 36);
}

/// Light attenuation off: it has world units, and at the extreme scales its coefficients
/// (`c₁/s`, `c₂/s²`) leave the range a file may give.
fn without_attenuation(t: &mut Table) {
    if let Some(Value::Table(render)) = t.get_mut("render") {
        render.remove("attenuation");
    }
}

/// The camera's look-at point.
fn look_at(t: &Table) -> E3 {
    triple(&t["camera"]["look_at"])
}

/// Every point light moved to `distance` from the look-at point along its direction from it,
/// or (`None`) made a directional light shining the same way.
fn lights_at(t: &mut Table, distance: Option<f64>) {
    let centre = look_at(t);
    for light in t.get_mut("lights").and_then(Value::as_array_mut).into_iter().flatten() {
        let light = light.as_table_mut().unwrap();
        let p = triple(&light["position"]);
        let u = cga_core::euclid::unit(cga_core::euclid::sub(p, centre)).unwrap();
        match distance {
            Some(d) => {
                light.insert("position".into(), floats(&[0, 1, 2].map(|k| centre[k] + d * u[k])));
            }
            None => {
                light.remove("position");
                light.insert("direction".into(), floats(&u.map(|x| -x)));
            }
        }
    }
}

/// Checks `pictures` against `reference` (mean ≤ 0.5 levels, at most `off` of the pixels
/// more than 8 levels away), printing each; the failures.
fn compare(reference: &[u8], pictures: &[(String, Vec<u8>, f64)]) -> Vec<String> {
    let mut failures = Vec::new();
    for (what, picture, allowed) in pictures {
        let (mean, off) = difference(reference, picture);
        println!("{what:48} mean {mean:.4} levels, {:.3} % of pixels > 8", 100.0 * off);
        if mean > 0.5 || off > *allowed {
            failures.push(format!("{what}: mean {mean:.3}, {:.3} % off", 100.0 * off));
        }
    }
    failures
}

/// Lights far away are directions: a scene whose lights sit at 1e4 … 1e90 renders as with
/// those lights made directional, on the sparse and plain back ends (at 1e4 the light's
/// direction still turns by 1e-3 rad across the scene, which moves the sharpest highlights by
/// a pixel here and there).
#[test]
fn far_lights_render_as_directional_lights() {
    let mut failures = Vec::new();
    for name in ["primitives.toml", "combined.toml", "surface.toml"] {
        let mut base = table(name);
        without_attenuation(&mut base);
        let mut directional = base.clone();
        lights_at(&mut directional, None);
        let size = if name == "surface.toml" { (48, 36) } else { (96, 72) };
        let reference_sparse = picture::<Sparse>(&scene_of(&directional, name, size.0, size.1));
        let reference_plain = picture::<Plain>(&scene_of(&directional, name, size.0, size.1));
        let (mut sparse, mut plain) = (Vec::new(), Vec::new());
        for d in [1e4, 1e6, 1e10, 1e20, 1e50, 1e90] {
            let mut far = base.clone();
            lights_at(&mut far, Some(d));
            let scene = scene_of(&far, name, size.0, size.1);
            sparse.push((format!("sparse {name} lights at {d:e}"), picture::<Sparse>(&scene), 1e-3));
            plain.push((format!("plain {name} lights at {d:e}"), picture::<Plain>(&scene), 1e-3));
        }
        failures.extend(compare(&reference_sparse, &sparse));
        failures.extend(compare(&reference_plain, &plain));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Objects far away and smaller than a pixel change nothing near: three unit spheres at
/// 1e4 … 1e90 beyond the look-at point render as the scene without them.
#[test]
fn sub_pixel_objects_far_away_leave_the_picture_alone() {
    let mut failures = Vec::new();
    for name in ["primitives.toml", "combined.toml"] {
        let base = table(name);
        let reference = picture::<Sparse>(&scene_of(&base, name, 96, 72));
        let mut pictures = Vec::new();
        for d in [1e4, 1e6, 1e10, 1e20, 1e50, 1e90] {
            let mut far = base.clone();
            let (centre, eye) = (look_at(&far), triple(&far["camera"]["position"]));
            let u = cga_core::euclid::unit(cga_core::euclid::sub(centre, eye)).unwrap();
            let objects = far.get_mut("objects").and_then(Value::as_array_mut).unwrap();
            for k in 0..3 {
                let at = [0, 1, 2].map(|j| centre[j] + d * u[j] + (k as f64 - 1.0) * 1e-3 * d * [1.0, 0.0, 0.5][j]);
                let sphere = format!(
                    "type = \"sphere\"\ncentre = [{:e}, {:e}, {:e}]\nradius = 1.0\nmaterial = {{ colour = [1.0, 1.0, 1.0] }}\n",
                    at[0], at[1], at[2]
                );
                objects.push(Value::Table(sphere.parse().unwrap()));
            }
            pictures.push((
                format!("{name} + 3 spheres at {d:e}"),
                picture::<Sparse>(&scene_of(&far, name, 96, 72)),
                1e-3,
            ));
        }
        failures.extend(compare(&reference, &pictures));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A triangle whose corners lie 1e100 away, in front of a wall, renders as the plane it
/// spans: it covers the view, with the wall's reflection and a sphere's shadow on it.
#[test]
fn a_triangle_as_large_as_a_file_allows_renders_as_its_plane() {
    let scene = |front: &str| {
        format!(
            "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 48\nheight = 36\n\
             [[lights]]\nposition = [3.0, -8.0, 5.0]\n\
             [[objects]]\ntype = \"plane\"\npoint = [0.0, 20.0, 0.0]\nnormal = [0.0, -1.0, 0.0]\nmaterial = {{ colour = [0.2, 0.9, 0.2] }}\n\
             [[objects]]\n{front}material = {{ colour = [0.9, 0.3, 0.2], kr = 0.3 }}\n\
             [[objects]]\ntype = \"sphere\"\ncentre = [1.0, 0.0, 0.0]\nradius = 2.0\nmaterial = {{ colour = [0.3, 0.3, 0.9] }}\n"
        )
    };
    // The plane y = 5, which corners of 1e100 (exact in f64) span exactly; a tilted one
    // would not be: its corners' coordinates round by 1e83, which moves the plane as far.
    let plane = scene("type = \"plane\"\npoint = [0.0, 5.0, 0.0]\nnormal = [0.0, -1.0, 0.0]\n");
    let triangle =
        scene("type = \"triangle\"\ncorners = [[-1e100, 5.0, -1e100], [1e100, 5.0, -1e100], [0.0, 5.0, 1e100]]\n");
    let (a, b) = (Scene::parse(&plane, "plane").unwrap(), Scene::parse(&triangle, "triangle").unwrap());
    let mut failures = Vec::new();
    // The dense back end's orthonormal basis cannot hold near objects beside ones 1e100 away
    // (its `holds` says so; the command line refuses it).
    assert!(cga_trace::backend::holds::<Dense>(&b).is_err() && cga_trace::backend::holds::<Dense>(&a).is_ok());
    for (name, (pa, pb)) in [
        ("sparse", (picture::<Sparse>(&a), picture::<Sparse>(&b))),
        ("plain", (picture::<Plain>(&a), picture::<Plain>(&b))),
    ] {
        // The wall (green) is hidden behind the plane in front, and nothing is black.
        let green = pb.chunks(3).filter(|p| p[1] > p[0] && p[1] > p[2]).count();
        let black = pb.chunks(3).filter(|p| p.iter().all(|&c| c < 8)).count();
        assert_eq!((green, black), (0, 0), "{name}: the triangle hides the wall");
        failures.extend(compare(&pa, &[(format!("{name}: triangle of 1e100 against its plane"), pb, 1e-3)]));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A camera and a light inside a sphere of radius 1e3 … 1e100 see the lit inner wall, the
/// same colour everywhere (the light at the centre meets the wall head-on: `k_a A + k_d`), on
/// every back end.
#[test]
fn a_camera_inside_a_huge_sphere_sees_the_lit_inner_wall() {
    let expected = (cga_trace::film::encode(0.1 + 0.5, cga_trace::Encoding::Srgb) * 255.0).round();
    for radius in [1e3, 1e6, 1e12, 1e20, 1e50, 1e100] {
        let text = format!(
            "[camera]\nposition = [0.0, -1.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 16\nheight = 12\n\
             [render]\nambient = 0.1\n[[lights]]\nposition = [0.0, -0.5, 1.0]\n\
             [[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = {radius:e}\n\
             material = {{ colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.5, ks = 0.0 }}\n"
        );
        let scene = Scene::parse(&text, "inside").unwrap();
        for (name, picture) in [
            ("sparse", picture::<Sparse>(&scene)),
            ("dense", picture::<Dense>(&scene)),
            ("plain", picture::<Plain>(&scene)),
        ] {
            let (lo, hi) = picture.iter().fold((255u8, 0u8), |(lo, hi), &v| (lo.min(v), hi.max(v)));
            println!("radius {radius:e} {name}: levels {lo} … {hi} (expected {expected})");
            assert!(
                (f64::from(lo) - expected).abs() <= 1.0 && (f64::from(hi) - expected).abs() <= 1.0,
                "radius {radius:e}, {name}: levels {lo} … {hi}, expected {expected}"
            );
        }
    }
}

/// Every scene of the invariance test scaled down to 1e-300 (its lengths then between about
/// 1e-301 and 4e-299, normal numbers) and up by 1e98 (its lengths up to 4e99, within the
/// file's 1e100) renders as the original; attenuation off in all three, since its
/// coefficients could not be written at those scales.
#[test]
fn the_smallest_and_largest_scales_render_the_same_picture() {
    let mut failures = Vec::new();
    let cases: [(&str, u32, u32, bool); 5] = [
        ("primitives.toml", 96, 72, true),
        ("combined.toml", 96, 72, true),
        ("surface.toml", 48, 36, true),
        ("fig3b.toml", 48, 36, false),
        ("ruled.toml", 48, 36, false),
    ];
    for (name, w, h, all_back_ends) in cases {
        let mut base = table(name);
        without_attenuation(&mut base);
        let scaled = |s: f64| {
            let mut t = base.clone();
            Similarity { scale: s, shift: 0.0 }.apply(&mut t);
            scene_of(&t, name, w, h)
        };
        let (original, tiny, huge) = (scene_of(&base, name, w, h), scaled(1e-300), scaled(1e98));
        let run = |f: fn(&Scene) -> Vec<u8>, back_end: &str| {
            let pictures = [(1e-300, &tiny), (1e98, &huge)]
                .map(|(s, scene)| (format!("{back_end} {name} scaled {s:e}"), f(scene), 1e-3));
            compare(&f(&original), &pictures)
        };
        failures.extend(run(picture::<Sparse>, "sparse"));
        if all_back_ends {
            failures.extend(run(picture::<Plain>, "plain"));
            failures.extend(run(picture::<Dense>, "dense"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
