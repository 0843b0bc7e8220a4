//! Triangle meshes read from OBJ and PLY files: the same picture as the shape they were
//! made from — a box from its twelve triangles, a swept surface from the mesh `cga-trace
//! mesh` writes of it (vertex normals shading it as the surface's own) — and texture
//! coordinates, scale and motors applied as the file and the object say.

use cga_trace::integrator::Window;
use cga_trace::mesh::MeshFormat;
use cga_trace::shapes::{MeshShape, Shape};
use cga_trace::{Aov, Film, Renderer, Scene};
use std::path::Path;

fn parse(text: &str, folder: &Path) -> Scene {
    Scene::parse(text, folder.join("scene.toml").to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"))
}

fn render(scene: &Scene) -> Film {
    let c = &scene.camera;
    Renderer::new(scene).render_window(Aov::Shaded, Window::full(c.width, c.height), &|| {})
}

/// `(mean |Δ| over channels, fraction of pixels with a channel off by more than 1/32)`.
fn difference(a: &Film, b: &Film) -> (f64, f64) {
    let channels = a.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs()));
    let mean = channels.sum::<f64>() / (3 * a.pixels.len()) as f64;
    let off = a.pixels.iter().zip(&b.pixels).filter(|(p, q)| (0..3).any(|k| (p[k] - q[k]).abs() > 1.0 / 32.0)).count();
    (mean, off as f64 / a.pixels.len() as f64)
}

const CAMERA: &str = "[camera]\nposition = [5.0, -9.0, 6.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 40.0\nwidth = 96\nheight = 72\n\
    [[lights]]\nposition = [-6.0, -8.0, 10.0]\n";

/// The twelve triangles of the box `[-1, 1]³`, counter-clockwise seen from outside.
const CUBE_OBJ: &str = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n\
    f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

#[test]
fn a_box_of_triangles_renders_as_the_box() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cube.obj"), CUBE_OBJ).unwrap();
    let material = "material = { colour = [0.8, 0.4, 0.2], ks = 0.5, q = 30.0 }";
    let mesh = parse(&format!("{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"cube.obj\"\n{material}\n"), dir.path());
    let cube = parse(
        &format!("{CAMERA}[[objects]]\ntype = \"box\"\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, 1.0]\n{material}\n"),
        dir.path(),
    );
    assert_eq!(mesh.objects.len(), 1, "a mesh is one object");
    let shape = mesh.objects[0].shape.downcast_ref::<MeshShape>().expect("a mesh");
    assert_eq!(shape.triangles().len(), 12, "four-sided faces cut in two");
    assert!(shape.closed(), "every edge shared by two triangles");
    let (mean, off) = difference(&render(&mesh), &render(&cube));
    // Only pixels on the triangles' shared diagonals and the silhouette may differ.
    assert!(mean < 2e-3 && off < 0.01, "mean {mean}, {off} of pixels off");
}

#[test]
fn a_closed_glass_mesh_refracts_as_the_solid_it_bounds() {
    // A glass cube of twelve triangles bends the checker floor behind it as the glass box
    // does: light enters at one triangle and leaves at another. Were the triangles thin
    // sheets, light would pass undeviated and the floor show straight through.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cube.obj"), CUBE_OBJ).unwrap();
    let glass = "material = { colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 0.0, ks = 0.3, q = 60.0, ior = 1.5 }";
    let floor = "[[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, -1.5]\nnormal = [0.0, 0.0, 1.0]\n\
        material = { colour = [0.9, 0.9, 0.9], texture = { pattern = \"checker\", colour = [0.1, 0.1, 0.1], repeat = [2.0, 2.0] } }\n";
    let render_with = |object: &str| {
        render(&parse(&format!("{CAMERA}[render]\nmax_depth = 8\n{floor}[[objects]]\n{object}\n{glass}\n"), dir.path()))
    };
    let cube = render_with("type = \"box\"\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, 1.0]");
    // Also as exporters write it: each face's own normal, so every corner a vertex per face.
    let normals = "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n";
    let faces = ["1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"].iter().enumerate().map(|(n, f)| {
        let corners: Vec<String> = f.split(' ').map(|v| format!("{v}//{}", n + 1)).collect();
        format!("f {}\n", corners.join(" "))
    });
    let faceted = CUBE_OBJ.lines().filter(|l| l.starts_with("v ")).map(|l| format!("{l}\n")).chain([normals.into()]);
    std::fs::write(dir.path().join("faceted.obj"), faceted.chain(faces).collect::<String>()).unwrap();
    let mut mean = 0.0f64;
    for file in ["cube.obj", "faceted.obj"] {
        let (m, off) = difference(&render_with(&format!("type = \"mesh\"\nfile = \"{file}\"")), &cube);
        assert!(m < 3e-3 && off < 0.02, "{file}: mean {m}, {off} of pixels off");
        mean = mean.max(m);
    }
    // The sheets' picture, for scale: the floor seen straight through the cube.
    let open = CUBE_OBJ.replace("f 5 6 7 8\n", "");
    std::fs::write(dir.path().join("open.obj"), open).unwrap();
    let sheets = render_with("type = \"mesh\"\nfile = \"open.obj\"");
    let (apart, _) = difference(&sheets, &cube);
    println!("closed mesh vs box: mean {mean:.2e}; open mesh (sheets) vs box: {apart:.2e}");
    assert!(apart > 10.0 * mean, "sheets {apart} vs solid {mean}");
}

#[test]
fn a_ply_mesh_scaled_and_moved_lands_where_its_motor_puts_it() {
    // The same cube as text PLY, scaled by 0.5 and translated by (0, 0, 1), is
    // the box [-0.5, 0.5]² × [0.5, 1.5].
    let dir = tempfile::tempdir().unwrap();
    let ply = "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n\
        element face 6\nproperty list uchar int vertex_indices\nend_header\n\
        -1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n\
        4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    std::fs::write(dir.path().join("cube.ply"), ply).unwrap();
    let material = "material = { colour = [0.3, 0.6, 0.9], ks = 0.2 }";
    let mesh = parse(
        &format!(
            "{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"cube.ply\"\nscale = 0.5\ntransform = [{{ translate = [0.0, 0.0, 1.0] }}]\n{material}\n"
        ),
        dir.path(),
    );
    let cube = parse(
        &format!("{CAMERA}[[objects]]\ntype = \"box\"\nmin = [-0.5, -0.5, 0.5]\nmax = [0.5, 0.5, 1.5]\n{material}\n"),
        dir.path(),
    );
    let (mean, off) = difference(&render(&mesh), &render(&cube));
    assert!(mean < 2e-3 && off < 0.01, "mean {mean}, {off} of pixels off");
}

#[test]
fn a_swept_surface_exported_and_read_back_is_shaded_as_the_surface() {
    // fig3c's spline surface, written by `Scene::mesh` as OBJ (f64 exact, analytic vertex
    // normals), read back as a mesh and rendered in place of the surface.
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/fig3c.toml");
    let text = std::fs::read_to_string(&shipped).unwrap();
    let mut scene = Scene::parse(&text, shipped.to_str().unwrap()).unwrap();
    scene.resize(Some(160), Some(120)).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let mut file = std::fs::File::create(dir.path().join("surface.obj")).unwrap();
    scene.mesh("surface", 256, 512).unwrap().save(&mut file, MeshFormat::Obj).unwrap();
    drop(file);
    // The file with the surface's table replaced by the mesh (same material).
    let (before, surface) = text.split_once("name = \"surface\"").unwrap();
    let material = surface.lines().find(|l| l.starts_with("material")).unwrap();
    let with = |smooth: bool| {
        let object =
            format!("name = \"surface\"\ntype = \"mesh\"\nfile = \"surface.obj\"\nsmooth = {smooth}\n{material}\n");
        let mut s = parse(&format!("{before}{object}"), dir.path());
        s.resize(Some(160), Some(120)).unwrap();
        render(&s)
    };
    let original = render(&scene);
    let (mean, off) = difference(&with(true), &original);
    assert!(mean < 3e-3 && off < 0.01, "smooth: mean {mean}, {off} of pixels off");
    // Without the file's normals the facets show: the normals are what made it agree.
    let (flat, _) = difference(&with(false), &original);
    assert!(flat > 2.0 * mean, "flat {flat} vs smooth {mean}");
}

/// The unit square in z = 0 with the OBJ texture coordinates `vt` (its corners' in order
/// from the origin, counter-clockwise), textured by `texture`, seen from above
/// (orthographic, 40 × 40, lit by the ambient term alone): pixel `(i, j)`, `j` down from the
/// top row, covers `x = (i + ½)/40`, `y = 1 − (j + ½)/40`.
fn textured_square(dir: &Path, vt: &str, texture: &str) -> impl Fn(u32, u32) -> [f64; 3] {
    let obj = format!("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n{vt}f 1/1 2/2 3/3 4/4\n");
    std::fs::write(dir.join("square.obj"), obj).unwrap();
    let scene = parse(
        &format!(
            "[camera]\nposition = [0.5, 0.5, 5.0]\nlook_at = [0.5, 0.5, 0.0]\nup = [0.0, 1.0, 0.0]\nprojection = \"orthographic\"\nview_width = 1.0\nwidth = 40\nheight = 40\n\
             [render]\nambient = 1.0\n[[objects]]\ntype = \"mesh\"\nfile = \"square.obj\"\n\
             material = {{ colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0, texture = {texture} }}\n"
        ),
        dir,
    );
    let film = render(&scene);
    // Film rows run up from the bottom.
    move |i, j| film.pixels[((film.height - 1 - j) * film.width + i) as usize]
}

#[test]
fn a_meshs_texture_coordinates_place_its_texture() {
    // Texture coordinates that run u from 0 to 2 along x: a checker of one cell per unit of
    // u changes colour at x = 0.5.
    let dir = tempfile::tempdir().unwrap();
    let vt = "vt 0 0\nvt 2 0\nvt 2 1\nvt 0 1\n";
    let at = textured_square(dir.path(), vt, "{ pattern = \"checker\", colour = [0.0, 0.0, 0.0] }");
    // White for x < ½ (u < 1), black beyond.
    assert_eq!((at(5, 20), at(18, 20), at(21, 20), at(35, 20)), ([1.0; 3], [1.0; 3], [0.0; 3], [0.0; 3]));
}

#[test]
fn an_obj_files_v_counts_up_the_image() {
    // OBJ's v = 1 is the image's top row: an image red above and blue below, on a square
    // whose top edge (y = 1) has v = 1, shows red at the top as other tools show it.
    let dir = tempfile::tempdir().unwrap();
    let image = image::RgbImage::from_fn(4, 4, |_, y| image::Rgb(if y < 2 { [255, 0, 0] } else { [0, 0, 255] }));
    image.save(dir.path().join("halves.png")).unwrap();
    let at = textured_square(dir.path(), "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n", "{ image = \"halves.png\" }");
    let (top, bottom) = (at(20, 4), at(20, 35));
    assert!(top[0] > 0.99 && top[2] < 0.01 && bottom[2] > 0.99 && bottom[0] < 0.01, "top {top:?}, bottom {bottom:?}");
}

#[test]
fn bad_mesh_files_are_named_with_their_reason() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n").unwrap();
    std::fs::write(dir.path().join("mesh.stl"), "solid").unwrap();
    std::fs::write(dir.path().join("flat.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n").unwrap();
    let error = |file: &str| {
        let text = format!(
            "{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"{file}\"\nmaterial = {{ colour = [1.0, 1.0, 1.0] }}\n"
        );
        Scene::parse(&text, dir.path().join("scene.toml").to_str().unwrap()).unwrap_err().to_string()
    };
    for (file, says) in [
        ("bad.obj", "face vertex index out of bounds"),
        ("mesh.stl", "give a mesh as `.obj` or `.ply`"),
        ("missing.obj", "missing.obj"),
        ("flat.obj", "no triangle of the mesh has an area: nothing to see"),
    ] {
        let e = error(file);
        // The `file` field is the object's third line.
        let line = CAMERA.lines().count() + 3;
        assert!(e.contains(says) && e.contains(&format!("scene.toml:{line}:")) && e.contains("`file`"), "{file}: {e}");
    }
}

/// The cube as a binary little-endian PLY: vertices with normals, an element the reader
/// does not keep between them and the faces, and quads.
fn binary_cube_ply() -> Vec<u8> {
    let header = "ply\nformat binary_little_endian 1.0\ncomment made by the test\n\
        element vertex 8\nproperty float x\nproperty float y\nproperty float z\n\
        property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n\
        element edge 2\nproperty int vertex1\nproperty int vertex2\n\
        element face 6\nproperty list uchar int vertex_indices\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    let corners = [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]];
    for c in corners {
        for x in c.iter().chain(&c) {
            bytes.extend((*x as f32).to_le_bytes());
        }
        bytes.push(200);
    }
    for edge in [[0i32, 1], [1, 2]] {
        edge.iter().for_each(|i| bytes.extend(i.to_le_bytes()));
    }
    for face in [[0i32, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]] {
        bytes.push(4);
        face.iter().for_each(|i| bytes.extend(i.to_le_bytes()));
    }
    bytes
}

#[test]
fn a_binary_ply_is_read_an_element_at_a_time() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cube.ply"), binary_cube_ply()).unwrap();
    let mesh = cga_trace::import::TriangleMesh::load(&dir.path().join("cube.ply")).unwrap();
    assert_eq!((mesh.positions.len(), mesh.triangles.len()), (8, 12));
    assert_eq!(mesh.normals.as_ref().unwrap()[6], [1.0, 1.0, 1.0]);
    assert!(mesh.is_closed());
    std::fs::write(dir.path().join("cube.obj"), CUBE_OBJ).unwrap();
    let material = "material = { colour = [0.8, 0.4, 0.2], ks = 0.5, q = 30.0 }";
    let ply = parse(&format!("{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"cube.ply\"\n{material}\n"), dir.path());
    let obj = parse(&format!("{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"cube.obj\"\n{material}\n"), dir.path());
    let (mean, _) = difference(&render(&ply), &render(&obj));
    // The PLY's normals point out of the corners (smooth shading): only shading differs.
    assert!(mean < 0.1, "mean {mean}");
}

#[test]
fn a_ply_header_that_promises_too_much_is_refused_before_reading() {
    let dir = tempfile::tempdir().unwrap();
    let header = |vertices: u64, faces: u64| {
        format!(
            "ply\nformat ascii 1.0\nelement vertex {vertices}\nproperty float x\nproperty float y\nproperty float z\n\
             element face {faces}\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
        )
    };
    for (vertices, faces, says) in [
        (4_000_000_000, 1, "vertices, more than the limit"),
        (3, 2_000_000, "faces, more than the limit"),
        (3_000_000, 1, "the file ends at vertex 5 of 3000000"),
        (3, 5, "the file ends at face 2 of 5"),
    ] {
        std::fs::write(dir.path().join("bomb.ply"), header(vertices, faces)).unwrap();
        let text = format!(
            "{CAMERA}[[objects]]\ntype = \"mesh\"\nfile = \"bomb.ply\"\nmaterial = {{ colour = [1.0, 1.0, 1.0] }}\n"
        );
        let path = dir.path().join("scene.toml");
        let e = Scene::parse(&text, path.to_str().unwrap()).unwrap_err().to_string();
        assert!(e.contains("scene.toml:") && e.contains("bomb.ply") && e.contains(says), "{e}");
    }
}

#[test]
fn a_scenes_files_are_read_once_and_placed_at_every_time() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("cube.obj"), CUBE_OBJ).unwrap();
    let grid = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/maps/grid.png");
    std::fs::copy(grid, dir.path().join("grid.png")).unwrap();
    let text = format!(
        "{CAMERA}[environment]\nimage = \"grid.png\"\n[[objects]]\nname = \"cube\"\ntype = \"mesh\"\nfile = \"cube.obj\"\n\
         motion = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0]]\n\
         material = {{ colour = [1.0, 1.0, 1.0] }}\n"
    );
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let mut source = cga_trace::Source::load(&path).unwrap();
    let first = source.scene(None, 0.0).unwrap();
    // Gone from the disk: the source has them.
    for name in ["cube.obj", "grid.png", "scene.toml"] {
        std::fs::remove_file(dir.path().join(name)).unwrap();
    }
    let last = source.scene(None, 1.0).unwrap();
    let roles: Vec<&str> = last.inputs.iter().map(|i| i.role).collect();
    assert_eq!(roles, ["scene", "mesh", "environment image"]);
    let centre = |s: &Scene| {
        let (c, _) = s.objects[0].shape.bounds().unwrap();
        s.frame.world_point(c)
    };
    let (a, b) = (centre(&first), centre(&last));
    assert!((b[0] - a[0] - 2.0).abs() < 1e-9 && (b[1] - a[1]).abs() < 1e-9, "{a:?} → {b:?}");
}
