//! What the tests that rewrite scene files share: moving and scaling a scene file as a user
//! would write the moved scene, and reading the shipped ones.
#![allow(dead_code)]

use cga_tests::common::dd;

use cga_core::Circle;
use cga_core::euclid::E3;
use cga_trace::Scene;
use cga_trace::camera::Camera;
use cga_trace::format::Role;
use toml::{Table, Value};

/// `x ↦ s x + t` for a scene file: points move, lengths scale, directions stay, and the
/// attenuation `1/(c0 + c1 d + c2 d²)` keeps its values at the scaled distances.
pub struct Similarity {
    pub scale: f64,
    pub shift: f64,
}

impl Similarity {
    pub fn point(&self, v: &mut Value) {
        let x = triple(v);
        *v = Value::Array(x.iter().map(|&x| Value::Float(self.scale * x + self.shift)).collect());
    }

    pub fn length(&self, v: &mut Value) {
        *v = Value::Float(self.scale * v.as_float().expect("a length"));
    }

    pub fn circle(&self, c: &mut Table) {
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

    /// A blade given by its coefficients' null-basis names, moved as its points are:
    /// `X ↦ V X Ṽ` for `V = T D` (a dilation about the origin, then the shift along the
    /// diagonal), in double-double so that the moved coefficients are those of the moved
    /// object to f64's rounding (checked on a point: `up(x) ↦ ∝ up(s x + t)`).
    pub fn blade(&self, b: &mut Value) {
        use cga_core::{Dilator, Motor, Multivector, Real};
        use dd::Dd;
        let names = cga_trace::figure::null_basis_names();
        let d: Multivector<Dd> = Dilator::new([Dd::zero(); 3], Dd::from_f64(self.scale)).expect("a dilator").into();
        let t: Multivector<Dd> = Motor::from_translation([Dd::from_f64(self.shift); 3]).into();
        let v = t * d;
        let moved = |x: Multivector<Dd>| (v * x * v.reverse()).to_storage().map(Dd::hi);
        let p = moved(cga_core::up([1.0, -2.0, 3.0].map(Dd::from_f64)).into());
        let want = [1.0, -2.0, 3.0].map(|x| self.scale * x + self.shift);
        let got = cga_core::down(cga_core::Vector::<f64>::from_storage(&p)).expect("a point");
        assert!((0..3).all(|k| (got[k] - want[k]).abs() <= 1e-9 * (1.0 + want[k].abs())), "{got:?} vs {want:?}");
        let mut storage = [Dd::zero(); 32];
        for (name, value) in b.as_table().expect("a blade table") {
            let k = names.iter().position(|n| n == name).expect("a null-basis blade name");
            storage[k] = Dd::from_f64(value.as_float().or(value.as_integer().map(|i| i as f64)).expect("a number"));
        }
        let x = moved(Multivector::from_storage(&storage));
        let table: Table =
            names.iter().zip(x).filter(|(_, c)| *c != 0.0).map(|(n, c)| (n.to_string(), Value::Float(c))).collect();
        *b = Value::Table(table);
    }

    /// A motor `M` (eight coefficients) as seen after the similarity `S`: `S M S⁻¹`, the
    /// dilation scaling its translation parts, then conjugated by the shift's translator.
    pub fn motor(&self, m: &mut Value) {
        let c = m.as_array().expect("eight numbers");
        let mut k = [0.0; 8];
        for (k, v) in k.iter_mut().zip(c) {
            *k = v.as_float().or_else(|| v.as_integer().map(|i| i as f64)).expect("a number");
        }
        for x in &mut k[4..] {
            *x *= self.scale;
        }
        let t = cga_core::Motor::from_rotor_translator(
            cga_core::Rotor { s: 1.0, e12: 0.0, e13: 0.0, e23: 0.0 },
            cga_core::Translator::from_vector([self.shift; 3]),
        );
        let moved = t * cga_core::Motor::from_array(k) * t.reverse();
        *m = floats(&moved.to_array());
    }

    /// A mesh's or an instance's `transform` F (rotations about points, translations)
    /// conjugated by the scaling `S x = s x`: `S F S⁻¹` rotates about `s p` and translates by
    /// `s t`. A mesh's vertices (its file's, times `scale`) are scaled (`scale` times `s`),
    /// moved by `S F S⁻¹` and then shifted; an instance's F acts after its object's, so it is
    /// conjugated by the shift as well: its points `p` move to `s p + t`.
    fn conjugate_steps(&self, object: &mut Table, mesh: bool) {
        assert!(
            !object.contains_key("motor") && !object.contains_key("motion"),
            "shipped meshes and instances move by `transform`"
        );
        let scaled = |v: &mut Value| {
            *v = Value::Array(triple(v).iter().map(|&x| Value::Float(self.scale * x)).collect());
        };
        let steps = object.entry("transform").or_insert(Value::Array(Vec::new())).as_array_mut().expect("a list");
        for step in steps.iter_mut() {
            if let Some(t) = step.get_mut("translate") {
                scaled(t);
            }
            if let Some(rotate) = step.get_mut("rotate").and_then(Value::as_table_mut) {
                let about = rotate.entry("about").or_insert(floats(&[0.0; 3]));
                if mesh { scaled(about) } else { self.point(about) }
            }
        }
        if mesh {
            let mut shift = Table::new();
            shift.insert("translate".into(), floats(&[self.shift; 3]));
            steps.push(Value::Table(shift));
            let scale = object.entry("scale").or_insert(Value::Float(1.0));
            *scale = Value::Float(self.scale * scale.as_float().expect("a number"));
        }
    }

    pub fn apply(&self, scene: &mut Table) {
        let camera = scene["camera"].as_table_mut().expect("[camera]");
        for key in ["position", "look_at"] {
            if let Some(v) = camera.get_mut(key) {
                self.point(v);
            }
        }
        assert!(!camera.contains_key("motor"), "shipped scenes place the camera by position and look_at");
        for key in ["aperture", "focus_distance", "view_width"] {
            if let Some(v) = camera.get_mut(key) {
                self.length(v);
            }
        }
        if let Some(Value::Table(render)) = scene.get_mut("render")
            && let Some(Value::Array(att)) = render.get_mut("attenuation")
        {
            let [c0, c1, c2] = [0, 1, 2].map(|k| att[k].as_float().expect("a number"));
            *att = vec![Value::Float(c0), Value::Float(c1 / self.scale), Value::Float(c2 / (self.scale * self.scale))];
        }
        // Directional lights stay as they are.
        for light in scene.get_mut("lights").and_then(Value::as_array_mut).into_iter().flatten() {
            if let Some(p) = light.get_mut("position") {
                self.point(p);
            }
            for key in ["sphere", "disk"] {
                if let Some(r) = light.get_mut(key) {
                    self.length(r);
                }
            }
        }
        for (_, m) in scene.get_mut("materials").and_then(Value::as_table_mut).into_iter().flatten() {
            Self::absorbing(self.scale, m);
        }
        for object in scene.get_mut("objects").and_then(Value::as_array_mut).into_iter().flatten() {
            self.object(object.as_table_mut().expect("an object table"));
        }
    }

    /// Absorption is per unit length.
    fn absorbing(scale: f64, m: &mut Value) {
        if let Some(Value::Array(a)) = m.get_mut("absorption") {
            a.iter_mut().for_each(|x| *x = Value::Float(x.as_float().expect("a number") / scale));
        }
    }

    /// One object's table moved, field by field as the format declares its role (a CSG
    /// tree's objects each in turn).
    fn object(&self, object: &mut Table) {
        let absorbing = |m: &mut Value| Self::absorbing(self.scale, m);
        if let Some(m) = object.get_mut("material").filter(|m| m.is_table()) {
            absorbing(m);
        }
        // A plane's texture is laid out in lengths: as many cells per scaled unit.
        if object.get("type").and_then(Value::as_str) == Some("plane")
            && let Some(texture) =
                object.get_mut("material").and_then(|m| m.get_mut("texture")).and_then(Value::as_table_mut)
        {
            let repeat = texture.entry("repeat").or_insert(Value::Array(vec![Value::Float(1.0), Value::Float(1.0)]));
            for r in repeat.as_array_mut().expect("repeat = [u, v]") {
                *r = Value::Float(r.as_float().expect("a number") / self.scale);
            }
        }
        // Each field as the format declares its role.
        let kind = object.get("type").and_then(Value::as_str).unwrap_or("").to_string();
        let fields = cga_trace::format::fields(&kind).unwrap_or_else(|| panic!("no object kind `{kind}`"));
        let mesh = fields.iter().any(|f| f.role == Role::Scale);
        if mesh || kind == "instance" {
            self.conjugate_steps(object, mesh);
        }
        for (key, value) in object.iter_mut() {
            let role = fields.iter().find(|f| f.name == key.as_str()).map(|f| f.role);
            match role.unwrap_or_else(|| panic!("`{key}` is no field of a {kind}")) {
                Role::Point => self.point(value),
                Role::Points => value.as_array_mut().expect("points").iter_mut().for_each(|p| self.point(p)),
                Role::Length => self.length(value),
                Role::Circle => self.circle(value.as_table_mut().expect("a circle table")),
                Role::Circles => value
                    .as_array_mut()
                    .expect("circles")
                    .iter_mut()
                    .for_each(|c| self.circle(c.as_table_mut().expect("a circle"))),
                Role::Line => self.point(value.get_mut("point").expect("point")),
                Role::Bound => {
                    self.point(value.get_mut("centre").expect("centre"));
                    self.length(value.get_mut("radius").expect("radius"));
                }
                // A circle's ten orthonormal coefficients are read as centre and radius.
                Role::Blade if value.is_table() => self.blade(value),
                Role::Motor => self.motor(value),
                Role::Objects => value
                    .as_array_mut()
                    .expect("objects")
                    .iter_mut()
                    .for_each(|o| self.object(o.as_table_mut().expect("an object table"))),
                Role::Clip => {
                    let clip = value.as_table_mut().expect("a clip table");
                    for (region, key, role) in [
                        ("plane", "point", 0),
                        ("sphere", "centre", 0),
                        ("sphere", "radius", 1),
                        ("box", "min", 0),
                        ("box", "max", 0),
                    ] {
                        if let Some(v) = clip.get_mut(region).and_then(|r| r.get_mut(key)) {
                            if role == 0 { self.point(v) } else { self.length(v) }
                        }
                    }
                }
                Role::Motion => value.as_array_mut().expect("motors").iter_mut().for_each(|m| self.motor(m)),
                // Rotations about a point of the object move with it (a mesh's and an
                // instance's steps are conjugated above).
                Role::Transform if !mesh && kind != "instance" => {
                    for step in value.as_array_mut().expect("steps") {
                        assert!(
                            step.get("translate").is_none(),
                            "shipped objects move by rotations about their own points"
                        );
                        if let Some(about) = step.get_mut("rotate").and_then(|r| r.get_mut("about")) {
                            self.point(about);
                        }
                    }
                }
                _ => {}
            }
        }
    }
}

pub fn triple(v: &Value) -> E3 {
    let a = v.as_array().expect("an array of three numbers");
    [0, 1, 2].map(|k| a[k].as_float().or_else(|| a[k].as_integer().map(|i| i as f64)).expect("a number"))
}

pub fn floats(x: &[f64]) -> Value {
    Value::Array(x.iter().map(|&v| Value::Float(v)).collect())
}

/// Centre, normal and radius of a circle given by its ten orthonormal grade-3 coefficients.
pub fn blade_params(blade: &Value) -> (E3, E3, f64) {
    const ORDER: [&str; 10] = ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"];
    let mut dense = cga_core::Multivector::zero();
    for (name, v) in ORDER.iter().zip(blade.as_array().expect("ten numbers")) {
        let k = cga_core::Multivector::<f64>::BLADES.iter().position(|b| b == name).unwrap();
        dense.coeffs[k] = v.as_float().expect("a number");
    }
    Circle::from_dense(&dense).try_normalise().unwrap().centre_normal_radius().unwrap()
}

/// A shipped scene as a TOML table, its blade circles read as centre, normal and radius.
pub fn table(name: &str) -> Table {
    let path = format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut table: Table = std::fs::read_to_string(path).unwrap().parse().unwrap();
    include(&mut table);
    Similarity { scale: 1.0, shift: 0.0 }.apply(&mut table);
    table
}

/// A shipped scene's included files written into it, as the renderer joins them (their
/// materials added, their lights after the scene's own, their objects before), so that a
/// similarity moves them too.
fn include(table: &mut Table) {
    let Some(Value::Array(files)) = table.remove("include") else { return };
    let mut objects = Vec::new();
    for file in files {
        let path = format!("{}/scenes/{}", env!("CARGO_MANIFEST_DIR"), file.as_str().expect("a file name"));
        let mut part: Table = std::fs::read_to_string(path).unwrap().parse().unwrap();
        include(&mut part);
        for (key, value) in part {
            match (key.as_str(), table.get_mut(&key), value) {
                ("objects", _, Value::Array(from)) => objects.extend(from),
                (_, Some(Value::Table(into)), Value::Table(from)) => into.extend(from),
                (_, Some(Value::Array(into)), Value::Array(from)) => into.extend(from),
                (_, None, value) => drop(table.insert(key, value)),
                (_, _, _) => panic!("`{key}` in an included file and the scene differ in kind"),
            }
        }
    }
    if let Some(Value::Array(own)) = table.remove("objects") {
        objects.extend(own);
    }
    if !objects.is_empty() {
        table.insert("objects".into(), Value::Array(objects));
    }
}

/// The scene a table describes, rendered at `width × height`.
pub fn scene_of(table: &Table, name: &str, width: u32, height: u32) -> Scene {
    let text = toml::to_string(table).unwrap();
    // Named by its path, so that the images it names are found beside it.
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
    let mut scene = Scene::parse(&text, file.to_str().unwrap()).unwrap_or_else(|e| panic!("{name}: {e}"));
    let c = scene.camera;
    scene.camera = Camera::new(c.pose, c.focal, c.x_max, c.y_max, width, height).unwrap().with_lens(c.lens).unwrap();
    scene
}

/// Each entry of a directory (recursively) with what it is: a link's target, or a file's
/// content hash.
#[cfg(unix)]
pub fn snapshot(dir: &std::path::Path) -> Vec<(String, String)> {
    use std::hash::{Hash, Hasher};
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let name = path.strip_prefix(dir).unwrap().to_string_lossy().into_owned();
            let meta = std::fs::symlink_metadata(&path).unwrap();
            let state = if meta.file_type().is_symlink() {
                format!("link to {}", std::fs::read_link(&path).unwrap().display())
            } else if meta.is_dir() {
                todo.push(path);
                "directory".into()
            } else if !meta.is_file() {
                // A pipe or device: reading it could wait for ever.
                "special".into()
            } else {
                let mut h = std::collections::hash_map::DefaultHasher::new();
                std::fs::read(&path).unwrap().hash(&mut h);
                format!("file {:x}", h.finish())
            };
            out.push((name, state));
        }
    }
    out.sort();
    out
}
pub mod swept;
