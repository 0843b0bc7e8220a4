//! The same picture wherever the scene sits and whatever its size: every shipped scene,
//! moved along the diagonal by 1e3 … 1e6 and scaled about the origin by 1e-3 and 1e3
//! (attenuation rescaled to match), renders as the original on all three back ends — mean
//! difference ≤ 0.5 of 255 levels, at most 0.1 % of pixels off by more than 8 levels.
//!
//! The scene file itself is transformed (as a user would write the moved scene), so this
//! checks the whole path: parsing, the camera-relative frame, every shape and the shading.

use cga_core::Circle;
use cga_core::euclid::E3;
use cga_trace::backend::{Backend, Dense, Plain, Sparse};
use cga_trace::camera::Camera;
use cga_trace::{Aov, Renderer, Scene};
use toml::{Table, Value};

/// `x ↦ s x + t` for a scene file: points move, lengths scale, directions stay, and the
/// attenuation `1/(c0 + c1 d + c2 d²)` keeps its values at the scaled distances.
struct Similarity {
    scale: f64,
    shift: f64,
}

impl Similarity {
    fn point(&self, v: &mut Value) {
        let x = triple(v);
        *v = Value::Array(x.iter().map(|&x| Value::Float(self.scale * x + self.shift)).collect());
    }

    fn length(&self, v: &mut Value) {
        *v = Value::Float(self.scale * v.as_float().expect("a length"));
    }

    fn circle(&self, c: &mut Table) {
        if let Some(Value::Array(points)) = c.get_mut("points") {
            points.iter_mut().for_each(|p| self.point(p));
            return;
        }
        // A circle given as orthonormal blade coefficients is first read as centre, normal,
        // radius (near the origin, where the file's digits are exact enough), then moved.
        if let Some(blade) = c.remove("blade") {
            let (centre, normal, radius) = blade_params(&blade);
            c.insert("centre".into(), floats(&centre));
            c.insert("normal".into(), floats(&normal));
            c.insert("radius".into(), Value::Float(radius));
        }
        self.point(c.get_mut("centre").expect("centre"));
        self.length(c.get_mut("radius").expect("radius"));
    }

    fn apply(&self, scene: &mut Table) {
        let camera = scene["camera"].as_table_mut().expect("[camera]");
        for key in ["position", "look_at"] {
            if let Some(v) = camera.get_mut(key) {
                self.point(v);
            }
        }
        assert!(!camera.contains_key("motor"), "shipped scenes place the camera by position and look_at");
        if let Some(Value::Table(render)) = scene.get_mut("render")
            && let Some(Value::Array(att)) = render.get_mut("attenuation")
        {
            let [c0, c1, c2] = [0, 1, 2].map(|k| att[k].as_float().expect("a number"));
            *att = vec![Value::Float(c0), Value::Float(c1 / self.scale), Value::Float(c2 / (self.scale * self.scale))];
        }
        for light in scene.get_mut("lights").and_then(Value::as_array_mut).into_iter().flatten() {
            self.point(light.get_mut("position").expect("position"));
        }
        for object in scene.get_mut("objects").and_then(Value::as_array_mut).into_iter().flatten() {
            let object = object.as_table_mut().expect("an object table");
            for key in ["centre", "point"] {
                if let Some(v) = object.get_mut(key) {
                    self.point(v);
                }
            }
            if let Some(v) = object.get_mut("radius") {
                self.length(v);
            }
            if let Some(Value::Array(corners)) = object.get_mut("corners") {
                corners.iter_mut().for_each(|c| self.point(c));
            }
            for key in ["c1", "c2"] {
                if let Some(c) = object.get_mut(key).and_then(Value::as_table_mut) {
                    self.circle(c);
                }
            }
            // Spline surfaces' circles; ruled surfaces' point pairs, lines and bound.
            if let Some(Value::Array(circles)) = object.get_mut("circles") {
                circles.iter_mut().filter_map(Value::as_table_mut).for_each(|c| self.circle(c));
            }
            for key in ["p1", "p2", "points"] {
                if let Some(Value::Array(points)) = object.get_mut(key) {
                    points.iter_mut().for_each(|p| self.point(p));
                }
            }
            for key in ["l1", "l2"] {
                if let Some(line) = object.get_mut(key).and_then(Value::as_table_mut) {
                    self.point(line.get_mut("point").expect("point"));
                }
            }
            if let Some(bound) = object.get_mut("bound").and_then(Value::as_table_mut) {
                self.point(bound.get_mut("centre").expect("centre"));
                self.length(bound.get_mut("radius").expect("radius"));
            }
        }
    }
}

fn triple(v: &Value) -> E3 {
    let a = v.as_array().expect("an array of three numbers");
    [0, 1, 2].map(|k| a[k].as_float().or_else(|| a[k].as_integer().map(|i| i as f64)).expect("a number"))
}

fn floats(x: &[f64]) -> Value {
    Value::Array(x.iter().map(|&v| Value::Float(v)).collect())
}

/// Centre, normal and radius of a circle given by its ten orthonormal grade-3 coefficients.
fn blade_params(blade: &Value) -> (E3, E3, f64) {
    const ORDER: [&str; 10] = ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"];
    let mut dense = cga_core::Multivector::zero();
    for (name, v) in ORDER.iter().zip(blade.as_array().expect("ten numbers")) {
        let k = cga_core::Multivector::<f64>::BLADES.iter().position(|b| b == name).unwrap();
        dense.coeffs[k] = v.as_float().expect("a number");
    }
    Circle::from_dense(&dense).try_normalise().unwrap().centre_normal_radius().unwrap()
}

fn load(name: &str, similarity: Option<&Similarity>, width: u32, height: u32) -> Scene {
    let path = format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut table: Table = std::fs::read_to_string(path).unwrap().parse().unwrap();
    // Every variant, the original included, reads blade circles the same way.
    Similarity { scale: 1.0, shift: 0.0 }.apply(&mut table);
    if let Some(s) = similarity {
        s.apply(&mut table);
    }
    let mut scene = Scene::parse(&toml::to_string(&table).unwrap(), name).unwrap();
    let c = scene.camera;
    scene.camera = Camera::new(c.pose, c.focal, c.x_max, c.y_max, width, height).unwrap();
    scene
}

fn picture<B: Backend>(scene: &Scene) -> Vec<u8> {
    let film = Renderer::<B>::with_backend(scene).render(Aov::Shaded, &|| {});
    film.to_rgb8(scene.settings.encoding).into_raw()
}

/// `(mean |Δ| in levels, fraction of pixels with a channel off by more than 8 levels)`.
fn difference(a: &[u8], b: &[u8]) -> (f64, f64) {
    let mean = a.iter().zip(b).map(|(x, y)| f64::from(x.abs_diff(*y))).sum::<f64>() / a.len() as f64;
    let off = a.chunks(3).zip(b.chunks(3)).filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > 8)).count();
    (mean, off as f64 / (a.len() / 3) as f64)
}

fn check<B: Backend>(width: u32, height: u32) {
    check_scenes::<B>(&["primitives.toml", "surface.toml", "combined.toml"], width, height);
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
        let original = picture::<B>(&load(name, None, width, height));
        for (what, scale, shift) in moves {
            let moved = picture::<B>(&load(name, Some(&Similarity { scale, shift }), width, height));
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

/// The spline and ruled scenes (smaller: a debug build intersects their surfaces slowly).
#[test]
fn spline_and_ruled_pictures_do_not_depend_on_place_or_scale() {
    check_scenes::<Sparse>(&["fig3b.toml", "ruled.toml"], 48, 36);
}

#[test]
fn dense_pictures_do_not_depend_on_place_or_scale() {
    check::<Dense>(48, 36);
}
