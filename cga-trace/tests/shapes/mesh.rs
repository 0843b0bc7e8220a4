//! Meshes of swept surfaces, written as OBJ, PLY and glb and read back with independent
//! reader crates (`tobj`, `ply-rs-bw`, `gltf`): every vertex lies on its circle `C_α` (α from
//! its texture coordinate) — to 1e-9 of the radius for OBJ and PLY (f64), to f32 rounding for
//! glb — and every normal is the analytic one (eq. 6–11) recomputed at the read-back point,
//! and faces the winding's front wherever the grid resolves the surface.

use cga_core::euclid::circle_distance;
use cga_core::euclid::{E3, cross, dot, norm, sub};
use cga_trace::Scene;
use cga_trace::mesh::{Mesh, Swept};
use std::path::Path;

fn scene(name: &str) -> Scene {
    Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)).unwrap()
}

/// A mesh as read back: positions, normals, uvs (`v` counted down an image, as the
/// renderer's textures and glTF count it; OBJ and PLY count it up), triangles.
struct ReadBack {
    positions: Vec<E3>,
    normals: Vec<E3>,
    uvs: Vec<[f64; 2]>,
    triangles: Vec<[usize; 3]>,
}

fn triples(v: &[f64]) -> Vec<E3> {
    v.chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
}

fn read_obj(bytes: &[u8]) -> ReadBack {
    let options = tobj::LoadOptions { single_index: true, triangulate: true, ..Default::default() };
    let (models, _) =
        tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |_| Ok(Default::default())).unwrap();
    let m = &models[0].mesh;
    ReadBack {
        positions: triples(&m.positions),
        normals: triples(&m.normals),
        uvs: m.texcoords.chunks(2).map(|c| [c[0], 1.0 - c[1]]).collect(),
        triangles: m.indices.chunks(3).map(|c| [c[0] as usize, c[1] as usize, c[2] as usize]).collect(),
    }
}

fn read_ply(bytes: &[u8]) -> ReadBack {
    use ply_rs_bw::ply::Property;
    let parser = ply_rs_bw::parser::Parser::<ply_rs_bw::ply::DefaultElement>::new();
    let ply = parser.read_ply(&mut std::io::Cursor::new(bytes)).unwrap();
    let double = |e: &ply_rs_bw::ply::DefaultElement, k: &str| match e.get(k) {
        Some(Property::Double(x)) => *x,
        other => panic!("{k}: {other:?}"),
    };
    let vertices = &ply.payload["vertex"];
    let faces = &ply.payload["face"];
    ReadBack {
        positions: vertices.iter().map(|v| [double(v, "x"), double(v, "y"), double(v, "z")]).collect(),
        normals: vertices.iter().map(|v| [double(v, "nx"), double(v, "ny"), double(v, "nz")]).collect(),
        uvs: vertices.iter().map(|v| [double(v, "u"), 1.0 - double(v, "v")]).collect(),
        triangles: faces
            .iter()
            .map(|f| match f.get("vertex_indices") {
                Some(Property::ListUInt(k)) => [k[0] as usize, k[1] as usize, k[2] as usize],
                other => panic!("{other:?}"),
            })
            .collect(),
    }
}

fn read_glb(bytes: &[u8]) -> ReadBack {
    let (document, buffers, _) = gltf::import_slice(bytes).unwrap();
    let primitive = document.meshes().next().unwrap().primitives().next().unwrap();
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let widen = |p: [f32; 3]| p.map(f64::from);
    let indices: Vec<usize> = reader.read_indices().unwrap().into_u32().map(|k| k as usize).collect();
    ReadBack {
        positions: reader.read_positions().unwrap().map(widen).collect(),
        normals: reader.read_normals().unwrap().map(widen).collect(),
        uvs: reader.read_tex_coords(0).unwrap().into_f32().map(|t| t.map(f64::from)).collect(),
        triangles: indices.chunks(3).map(|c| [c[0], c[1], c[2]]).collect(),
    }
}

/// Worst (distance from C_α in radii, normal angle) over the vertices, and checks of the
/// triangles' winding against the normals.
fn check(back: &ReadBack, surface: &dyn Swept, scene: &Scene, triangles: usize) -> (f64, f64, usize) {
    assert_eq!(back.triangles.len(), triangles);
    let (mut off, mut angle) = (0.0f64, 0.0f64);
    for ((x, n), uv) in back.positions.iter().zip(&back.normals).zip(&back.uvs) {
        let x = scene.frame.point(*x);
        let circle = surface.circle(uv[0]).unwrap();
        off = off.max(circle_distance(x, circle));
        let analytic = surface.normal(uv[0], x).unwrap();
        angle = angle.max(norm(cross(*n, analytic)).atan2(dot(*n, analytic).abs()) + (norm(*n) - 1.0).abs());
    }
    // Every triangle the mesh resolves (its vertex normals within 45° of each other) is wound
    // with its normals in front. Where the surface bends faster than the grid (or folds),
    // no winding can agree with all three.
    let resolved = |n: [E3; 3]| (0..3).all(|i| dot(n[i], n[(i + 1) % 3]) > std::f64::consts::FRAC_1_SQRT_2);
    let (mut unresolved, mut wrong) = (0, 0);
    for t in &back.triangles {
        let [a, b, c] = t.map(|k| back.positions[k]);
        let g = cross(sub(b, a), sub(c, a));
        let n = t.map(|k| back.normals[k]);
        if !resolved(n) {
            unresolved += 1;
        } else if !n.iter().all(|n| dot(g, *n) > 0.0) {
            wrong += 1;
        }
    }
    assert_eq!(wrong, 0, "triangles wound against their normals");
    assert!(unresolved * 50 <= triangles, "{unresolved} of {triangles} triangles unresolved");
    (off, angle, unresolved)
}

#[test]
fn meshes_read_back_lie_on_the_surface_with_analytic_normals() {
    for (file, object) in
        [("surface.toml", "evolved surface"), ("fig3c.toml", "surface"), ("catmull-rom.toml", "surface")]
    {
        let scene = scene(file);
        let surface = scene.swept(object).unwrap();
        let mesh = Mesh::of(surface, &scene.frame, 96, 40).unwrap();
        let n = mesh.triangles.len();
        let mut bytes = [Vec::new(), Vec::new(), Vec::new()];
        mesh.write_obj(&mut bytes[0]).unwrap();
        mesh.write_ply(&mut bytes[1]).unwrap();
        mesh.write_glb(&mut bytes[2]).unwrap();
        let back = [read_obj(&bytes[0]), read_ply(&bytes[1]), read_glb(&bytes[2])];
        // Each format's own v convention undone, every triangle's corners have the mesh's
        // texture coordinates (corner by corner: a reader may number vertices its own way).
        for (read, tolerance) in back.iter().zip([1e-15, 1e-15, 1e-7]) {
            let corners =
                read.triangles.iter().zip(&mesh.triangles).flat_map(|(a, b)| (0..3).map(move |i| (a[i], b[i])));
            let worst = corners
                .map(|(i, j)| {
                    (read.uvs[i][0] - mesh.uvs[j as usize][0])
                        .abs()
                        .max((read.uvs[i][1] - mesh.uvs[j as usize][1]).abs())
                })
                .fold(0.0f64, f64::max);
            assert!(worst <= tolerance, "{file}: uvs differ by {worst:e}");
        }
        let [obj, ply, glb] = back.map(|b| check(&b, surface, &scene, n));
        println!(
            "{file}: off C_α (radii) / normal angle (rad): OBJ {:.1e} / {:.1e}, PLY {:.1e} / {:.1e}, \
             glb {:.1e} / {:.1e}; {} of {n} triangles bend more than 45° across",
            obj.0, obj.1, ply.0, ply.1, glb.0, glb.1, obj.2
        );
        for (what, (off, angle, _)) in [("OBJ", obj), ("PLY", ply)] {
            assert!(off <= 1e-9 && angle <= 1e-9, "{file} {what}: {off:e} radii, {angle:e} rad");
        }
        // f32: positions to 2⁻²⁴ of the coordinates' size (a few radii here); the normal is
        // recomputed at that rounded position, which moves it by the curvature times the
        // rounding (most where the Catmull–Rom surface folds).
        assert!(glb.0 <= 1e-6 && glb.1 <= 1e-5, "{file} glb: {glb:?}");
        assert_eq!(obj.2, ply.2);
        // Closed around: the last column of every ring is the first.
        let w = 41;
        for ring in mesh.positions.chunks(w) {
            assert_eq!(ring[0], ring[w - 1]);
        }
    }
}

#[test]
fn the_command_line_writes_each_format() {
    // Removed when the test ends, pass or fail.
    let scratch = tempfile::Builder::new().prefix("cga-trace-mesh-").tempdir().unwrap();
    let dir = scratch.path();
    let scene_file = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/fig3b.toml");
    for ext in ["obj", "ply", "glb"] {
        let out = dir.join(format!("m.{ext}"));
        let status = std::process::Command::new(env!("CARGO_BIN_EXE_cga-trace"))
            .args(["mesh", scene_file.to_str().unwrap(), "--object", "surface", "--rings", "8", "--segments", "12"])
            .arg("-o")
            .arg(&out)
            .output()
            .unwrap();
        assert!(status.status.success(), "{status:?}");
        assert!(std::fs::metadata(&out).unwrap().len() > 100);
    }
    // Errors: one line, and nothing left behind.
    let bad = dir.join("m.stl");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cga-trace"))
        .args(["mesh", scene_file.to_str().unwrap(), "--object", "surface", "-o", bad.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown mesh extension"));
    let missing = dir.join("n.obj");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cga-trace"))
        .args(["mesh", scene_file.to_str().unwrap(), "--object", "floor", "-o", missing.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("not an evolved, spline or ruled surface"));
    assert!(!missing.exists());
}

/// A ruled surface's mesh: every vertex on its ruling (α and the fraction along it from the
/// texture coordinates) and the analytic normal there.
#[test]
fn ruled_meshes_read_back_on_their_rulings() {
    let scene = scene("ruled.toml");
    for name in ["band", "sheet"] {
        let mesh = scene.mesh(name, 16, 8).unwrap();
        let mut bytes = Vec::new();
        mesh.write_ply(&mut bytes).unwrap();
        let back = read_ply(&bytes);
        let surface = scene.objects.iter().find(|o| &*o.name == name).unwrap();
        let ruled = surface.shape.downcast_ref::<cga_trace::surface::RuledSurface>().unwrap();
        let (mut off, mut angle, mut singular) = (0.0f64, 0.0f64, 0);
        for ((x, n), uv) in back.positions.iter().zip(&back.normals).zip(&back.uvs) {
            let (want, normal) = ruled.point_and_normal(uv[0], uv[1]).unwrap();
            off = off.max(norm(sub(scene.frame.point(*x), want)));
            match normal {
                Some(normal) => angle = angle.max(norm(cross(*n, normal)).atan2(dot(*n, normal).abs())),
                None => singular += 1,
            }
        }
        println!(
            "{name}: vertices {off:.1e} from their rulings' points, normals within {angle:.1e} rad \
             ({singular} singular vertices given the grid's normal)"
        );
        assert!(singular <= 2, "{name}: {singular} singular vertices");
        assert!(off <= 1e-12 && angle <= 1e-12, "{name}");
    }
}
