//! Triangle meshes read from other tools: Wavefront OBJ (through `tobj`) and PLY, text or
//! binary (through `ply-rs-bw`), with their vertex normals and texture coordinates where the
//! file has them. Polygons are cut into fans of triangles. The file's size is checked
//! against [`MAX_MESH_FILE_BYTES`] before it is read, and it is streamed, a PLY element at a
//! time, so that what reading holds is bounded per vertex and triangle, not per file byte.

use crate::input::open_regular;
use crate::invalid::Invalid;
use crate::limits::{MAX_MESH_FILE_BYTES, MAX_MESH_VERTICES_READ, MAX_OBJECTS};
use cga_core::euclid::E3;
use std::io::{BufRead, Read};
use std::path::Path;

/// A triangle mesh as its file gives it (world units), one index for a vertex's position,
/// normal and texture coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// Vertex positions.
    pub positions: Vec<E3>,
    /// Vertex normals, one per position, where the file gives them.
    pub normals: Option<Vec<E3>>,
    /// Texture coordinates `(u, v)`, one per position, where the file gives them, with `v`
    /// counted down from an image's top row as [`crate::picture::Picture::at`] reads it (the
    /// file's `v`, counted up from the bottom row in OBJ and PLY, as `1 − v`).
    pub uvs: Option<Vec<[f64; 2]>>,
    /// Triangles: three indices into the vertices, counter-clockwise seen from the front.
    pub triangles: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// Read `path` ([`TriangleMesh::read`]).
    pub fn load(path: &Path) -> Result<TriangleMesh, Invalid> {
        let (file, _, size) = open_regular(path).map_err(|e| Invalid::Mesh(format!("{}: {e}", path.display())))?;
        TriangleMesh::read(file, size, path)
    }

    /// Read the mesh in `file` (`size` bytes, at `path`, whose extension says `.obj` or
    /// `.ply`), streamed: the file is never held whole, and a PLY file's vertices and
    /// faces are counted from its header against [`MAX_MESH_VERTICES_READ`] and
    /// [`MAX_OBJECTS`] before any is read, so that reading holds at most 64 bytes a vertex
    /// and 12 a triangle. Every coordinate must be finite and every index name a vertex.
    pub fn read(file: std::fs::File, size: u64, path: &Path) -> Result<TriangleMesh, Invalid> {
        let why = |e: &dyn std::fmt::Display| Invalid::Mesh(format!("{}: {e}", path.display()));
        if size > MAX_MESH_FILE_BYTES {
            return Err(why(&format!("{size} bytes, more than the limit of {MAX_MESH_FILE_BYTES}")));
        }
        let mut reader = std::io::BufReader::new(file.take(MAX_MESH_FILE_BYTES));
        let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let mesh = match extension.as_deref() {
            Some("obj") => from_obj(&mut reader),
            Some("ply") => from_ply(&mut reader, size),
            _ => Err("give a mesh as `.obj` or `.ply`".into()),
        }
        .map_err(|e| why(&e))?;
        mesh.check().map_err(|e| why(&e))?;
        Ok(mesh)
    }

    /// Whether the triangles close a solid: every edge, between vertices at the same place
    /// (a file repeats a corner for each normal or texture coordinate it has there), shared by
    /// exactly two triangles.
    pub fn is_closed(&self) -> bool {
        use std::collections::HashMap;
        let mut places: HashMap<[u64; 3], u32> = HashMap::new();
        let place: Vec<u32> = self
            .positions
            .iter()
            .enumerate()
            .map(|(k, p)| *places.entry(p.map(|x| (x + 0.0).to_bits())).or_insert(k as u32))
            .collect();
        let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
        for t in &self.triangles {
            let t = t.map(|k| place[k as usize]);
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if a != b {
                    *edges.entry((a.min(b), a.max(b))).or_default() += 1;
                }
            }
        }
        !edges.is_empty() && edges.values().all(|&n| n == 2)
    }

    /// Finite coordinates, indices in range, normals and coordinates one per vertex.
    fn check(&self) -> Result<(), String> {
        let n = self.positions.len();
        if let Some(k) = self.positions.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(format!("vertex {} is not finite: {:?}", k + 1, self.positions[k]));
        }
        if let Some(k) = self.normals.iter().flatten().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(format!("normal {} is not finite", k + 1));
        }
        if let Some(k) = self.uvs.iter().flatten().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(format!("texture coordinate {} is not finite", k + 1));
        }
        let counts = [self.normals.as_ref().map(Vec::len), self.uvs.as_ref().map(Vec::len)];
        if counts.into_iter().flatten().any(|m| m != n) {
            return Err(format!("{n} positions but {counts:?} normals and texture coordinates"));
        }
        match self.triangles.iter().flatten().find(|&&i| i as usize >= n) {
            Some(i) => Err(format!("a face names vertex {} of {n}", u64::from(*i) + 1)),
            None if self.triangles.is_empty() => Err("no faces".into()),
            None => Ok(()),
        }
    }

    /// The sphere `(centre, radius)` around its vertices: the centre of their box.
    pub fn bounds(&self) -> Option<(E3, f64)> {
        let first = *self.positions.first()?;
        let (lo, hi) = self.positions.iter().fold((first, first), |(lo, hi), p| {
            ([0, 1, 2].map(|k| lo[k].min(p[k])), [0, 1, 2].map(|k| hi[k].max(p[k])))
        });
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let far = self.positions.iter().map(|p| cga_core::euclid::norm(cga_core::euclid::sub(*p, centre)));
        Some((centre, far.fold(0.0, f64::max)))
    }
}

/// An OBJ file's faces (all its groups), polygons cut into fans; its materials are not read.
fn from_obj(reader: &mut impl BufRead) -> Result<TriangleMesh, String> {
    let options = tobj::LoadOptions { single_index: true, triangulate: true, ..Default::default() };
    let (models, _) = tobj::load_obj_buf(reader, &options, |_| Ok(Default::default()))
        .map_err(|e| format!("not a readable OBJ file: {e}"))?;
    let mut mesh = TriangleMesh::default();
    let (mut normals, mut uvs) = (Some(Vec::new()), Some(Vec::new()));
    for model in models {
        let m = model.mesh;
        let base = u32::try_from(mesh.positions.len()).map_err(|_| "more than 2³² vertices")?;
        let count = m.positions.len() / 3;
        mesh.positions.extend(m.positions.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
        // A group without normals (or coordinates) leaves the whole mesh without them.
        normals = normals.filter(|_| m.normals.len() == 3 * count);
        uvs = uvs.filter(|_| m.texcoords.len() == 2 * count);
        if let Some(n) = normals.as_mut() {
            n.extend(m.normals.chunks_exact(3).map(|p| [p[0], p[1], p[2]]));
        }
        if let Some(t) = uvs.as_mut() {
            t.extend(m.texcoords.chunks_exact(2).map(|p| [p[0], 1.0 - p[1]]));
        }
        mesh.triangles.extend(m.indices.chunks_exact(3).map(|t| [t[0] + base, t[1] + base, t[2] + base]));
    }
    (mesh.normals, mesh.uvs) = (normals.filter(|n| !n.is_empty()), uvs.filter(|t| !t.is_empty()));
    Ok(mesh)
}

/// A PLY file's `vertex` (`x y z`, and `nx ny nz`, `u v` or `s t` where given) and `face`
/// (`vertex_indices` or `vertex_index`) elements, read one element at a time (other elements
/// read and dropped); `size` is the file's length, which bounds what is reserved ahead.
fn from_ply(source: &mut impl BufRead, size: u64) -> Result<TriangleMesh, String> {
    use ply_rs_bw::parser::{Parser, Reader};
    use ply_rs_bw::ply::Encoding;
    let unreadable = |e: &dyn std::fmt::Display| format!("not a readable PLY file: {e}");
    let mut reader = Reader::new(source);
    let header = Parser::<PlyVertex>::new().read_header(&mut reader).map_err(|e| unreadable(&e))?;
    let count = |name: &str| header.elements.get(name).map(|e| e.count);
    let vertices = count("vertex").ok_or("no `vertex` element")?;
    let faces = count("face").ok_or("no `face` element")?;
    if vertices > MAX_MESH_VERTICES_READ {
        return Err(format!("{vertices} vertices, more than the limit of {MAX_MESH_VERTICES_READ}"));
    }
    if faces > MAX_OBJECTS {
        return Err(format!("{faces} faces, more than the limit of {MAX_OBJECTS} shapes in a scene"));
    }
    // A header may promise more than the file holds: reserve no more than its bytes allow
    // (every vertex takes at least 3 bytes).
    let ahead = |n: usize| n.min(usize::try_from(size / 3).unwrap_or(usize::MAX));
    let mut mesh = TriangleMesh {
        positions: Vec::with_capacity(ahead(vertices)),
        triangles: Vec::with_capacity(ahead(faces)),
        ..Default::default()
    };
    let has = |name: &str| header.elements.get("vertex").is_some_and(|v| v.properties.contains_key(name));
    let (mut normals, mut uvs) = (Vec::new(), Vec::new());
    if has("nx") {
        normals.reserve(ahead(vertices));
    }
    if has("u") || has("s") {
        uvs.reserve(ahead(vertices));
    }
    let (mut have_normals, mut have_uvs) = (true, true);
    let (vertex, face, skip) = (Parser::<PlyVertex>::new(), Parser::<PlyFace>::new(), Parser::<Skip>::new());
    let mut line = String::new();
    for (name, def) in &header.elements {
        for k in 0..def.count {
            // One element: its line (ASCII) or its bytes.
            macro_rules! next {
                ($parser:expr) => {
                    match header.encoding {
                        Encoding::Ascii => {
                            line.clear();
                            if reader.get_mut().read_line(&mut line).map_err(|e| unreadable(&e))? == 0 {
                                return Err(format!("the file ends at {name} {} of {}", k + 1, def.count));
                            }
                            $parser.read_ascii_element(&line, def)
                        }
                        Encoding::BinaryLittleEndian => $parser.read_little_endian_element(reader.get_mut(), def),
                        Encoding::BinaryBigEndian => $parser.read_big_endian_element(reader.get_mut(), def),
                    }
                    .map_err(|e| format!("{name} {}: {}", k + 1, unreadable(&e)))?
                };
            }
            match name.as_str() {
                "vertex" => {
                    let v: PlyVertex = next!(vertex);
                    mesh.positions.push(v.position().ok_or("a vertex without numbers `x`, `y`, `z`")?);
                    have_normals &= v.normal.iter().all(Option::is_some);
                    have_uvs &= v.uv.iter().all(Option::is_some);
                    if have_normals {
                        normals.push(v.normal.map(|x| x.unwrap_or(0.0)));
                    }
                    if have_uvs {
                        uvs.push([v.uv[0].unwrap_or(0.0), 1.0 - v.uv[1].unwrap_or(0.0)]);
                    }
                }
                "face" => {
                    let f: PlyFace = next!(face);
                    let indices =
                        f.indices.ok_or_else(|| format!("face {} has no integer list `vertex_indices`", k + 1))?;
                    let index = |i: i64| u32::try_from(i).map_err(|_| format!("face {} names vertex {i}", k + 1));
                    for j in 1..indices.len().saturating_sub(1) {
                        mesh.triangles.push([index(indices[0])?, index(indices[j])?, index(indices[j + 1])?]);
                    }
                    if mesh.triangles.len() > MAX_OBJECTS {
                        return Err(format!("more than {MAX_OBJECTS} triangles, the limit of shapes in a scene"));
                    }
                }
                _ => {
                    let _: Skip = next!(skip);
                }
            }
        }
    }
    mesh.normals = (have_normals && !normals.is_empty()).then_some(normals);
    mesh.uvs = (have_uvs && !uvs.is_empty()).then_some(uvs);
    Ok(mesh)
}

/// A PLY property's number, whatever its type.
fn ply_number(p: &ply_rs_bw::ply::Property) -> Option<f64> {
    use ply_rs_bw::ply::Property;
    Some(match *p {
        Property::Char(x) => f64::from(x),
        Property::UChar(x) => f64::from(x),
        Property::Short(x) => f64::from(x),
        Property::UShort(x) => f64::from(x),
        Property::Int(x) => f64::from(x),
        Property::UInt(x) => f64::from(x),
        Property::Float(x) => f64::from(x),
        Property::Double(x) => x,
        _ => return None,
    })
}

/// The properties of a PLY vertex this reader keeps.
#[derive(Default)]
struct PlyVertex {
    position: [Option<f64>; 3],
    normal: [Option<f64>; 3],
    uv: [Option<f64>; 2],
}

impl PlyVertex {
    fn position(&self) -> Option<E3> {
        Some([self.position[0]?, self.position[1]?, self.position[2]?])
    }
}

impl ply_rs_bw::ply::PropertyAccess for PlyVertex {
    fn new() -> Self {
        PlyVertex::default()
    }

    fn set_property(&mut self, name: &str, property: ply_rs_bw::ply::Property) -> ply_rs_bw::ply::PropertyAccessResult {
        let slot = match name {
            "x" => &mut self.position[0],
            "y" => &mut self.position[1],
            "z" => &mut self.position[2],
            "nx" => &mut self.normal[0],
            "ny" => &mut self.normal[1],
            "nz" => &mut self.normal[2],
            "u" | "s" => &mut self.uv[0],
            "v" | "t" => &mut self.uv[1],
            _ => return ply_rs_bw::ply::PropertyAccessResult::Ignored,
        };
        *slot = ply_number(&property);
        ply_rs_bw::ply::PropertyAccessResult::Set
    }
}

/// A PLY face's vertex indices (`vertex_indices` or `vertex_index`), if an integer list.
#[derive(Default)]
struct PlyFace {
    indices: Option<Vec<i64>>,
}

impl ply_rs_bw::ply::PropertyAccess for PlyFace {
    fn new() -> Self {
        PlyFace::default()
    }

    fn set_property(&mut self, name: &str, property: ply_rs_bw::ply::Property) -> ply_rs_bw::ply::PropertyAccessResult {
        use ply_rs_bw::ply::Property;
        if name != "vertex_indices" && name != "vertex_index" {
            return ply_rs_bw::ply::PropertyAccessResult::Ignored;
        }
        self.indices = match property {
            Property::ListChar(l) => Some(l.into_iter().map(i64::from).collect()),
            Property::ListUChar(l) => Some(l.into_iter().map(i64::from).collect()),
            Property::ListShort(l) => Some(l.into_iter().map(i64::from).collect()),
            Property::ListUShort(l) => Some(l.into_iter().map(i64::from).collect()),
            Property::ListInt(l) => Some(l.into_iter().map(i64::from).collect()),
            Property::ListUInt(l) => Some(l.into_iter().map(i64::from).collect()),
            _ => None,
        };
        ply_rs_bw::ply::PropertyAccessResult::Set
    }
}

/// An element this reader does not keep (read past).
struct Skip;

impl ply_rs_bw::ply::PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_obj_square_becomes_two_triangles_with_its_normals() {
        let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";
        let mesh = from_obj(&mut text.as_bytes()).unwrap();
        assert_eq!(mesh.triangles.len(), 2);
        assert_eq!(mesh.normals.as_ref().map(Vec::len), Some(mesh.positions.len()));
        assert_eq!(mesh.uvs, None);
        mesh.check().unwrap();
    }

    #[test]
    fn a_ply_quad_is_a_fan_and_bad_indices_are_named() {
        let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 7\n";
        let mesh = from_ply(&mut text.as_bytes(), text.len() as u64).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 7]]);
        assert_eq!(mesh.check().unwrap_err(), "a face names vertex 8 of 4");
    }
}
