//! Triangle meshes read from other tools: Wavefront OBJ (through `tobj`) and PLY, text or
//! binary (through `ply-rs-bw`), with their vertex normals and texture coordinates where the
//! file has them. Polygons are cut into fans of triangles. The file's size is checked
//! against [`MAX_MESH_FILE_BYTES`] before it is read, which bounds what reading it holds.

use crate::invalid::Invalid;
use crate::limits::MAX_MESH_FILE_BYTES;
use cga_core::euclid::E3;
use std::io::Read;
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
    /// Read `path`: `.obj` or `.ply` by its extension. Every coordinate must be finite and
    /// every index name a vertex.
    pub fn load(path: &Path) -> Result<TriangleMesh, Invalid> {
        let why = |e: &dyn std::fmt::Display| Invalid::Mesh(format!("{}: {e}", path.display()));
        let size = std::fs::metadata(path).map_err(|e| why(&e))?.len();
        if size > MAX_MESH_FILE_BYTES {
            return Err(why(&format!("{size} bytes, more than the limit of {MAX_MESH_FILE_BYTES}")));
        }
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|f| f.take(MAX_MESH_FILE_BYTES).read_to_end(&mut bytes))
            .map_err(|e| why(&e))?;
        let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let mesh = match extension.as_deref() {
            Some("obj") => from_obj(&bytes),
            Some("ply") => from_ply(&bytes),
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
fn from_obj(bytes: &[u8]) -> Result<TriangleMesh, String> {
    let options = tobj::LoadOptions { single_index: true, triangulate: true, ..Default::default() };
    let (models, _) = tobj::load_obj_buf(&mut std::io::Cursor::new(bytes), &options, |_| Ok(Default::default()))
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
/// (`vertex_indices` or `vertex_index`) elements.
fn from_ply(bytes: &[u8]) -> Result<TriangleMesh, String> {
    use ply_rs_bw::ply::{DefaultElement, Property};
    let parser = ply_rs_bw::parser::Parser::<DefaultElement>::new();
    let ply = parser.read_ply(&mut std::io::Cursor::new(bytes)).map_err(|e| format!("not a readable PLY file: {e}"))?;
    let number = |e: &DefaultElement, k: &str| -> Option<f64> {
        Some(match e.get(k)? {
            Property::Char(x) => f64::from(*x),
            Property::UChar(x) => f64::from(*x),
            Property::Short(x) => f64::from(*x),
            Property::UShort(x) => f64::from(*x),
            Property::Int(x) => f64::from(*x),
            Property::UInt(x) => f64::from(*x),
            Property::Float(x) => f64::from(*x),
            Property::Double(x) => *x,
            _ => return None,
        })
    };
    let triple = |e: &DefaultElement, keys: [&str; 3]| -> Option<E3> {
        Some([number(e, keys[0])?, number(e, keys[1])?, number(e, keys[2])?])
    };
    let vertices = ply.payload.get("vertex").ok_or("no `vertex` element")?;
    let positions: Option<Vec<E3>> = vertices.iter().map(|v| triple(v, ["x", "y", "z"])).collect();
    let positions = positions.ok_or("a vertex without numbers `x`, `y`, `z`")?;
    let normals = vertices.iter().map(|v| triple(v, ["nx", "ny", "nz"])).collect();
    let uv = |v: &DefaultElement| Some([number(v, "u").or(number(v, "s"))?, 1.0 - number(v, "v").or(number(v, "t"))?]);
    let uvs = vertices.iter().map(uv).collect();
    let faces = ply.payload.get("face").ok_or("no `face` element")?;
    let mut triangles = Vec::new();
    for (k, face) in faces.iter().enumerate() {
        let list = face.get("vertex_indices").or_else(|| face.get("vertex_index"));
        let indices: Vec<i64> = match list {
            Some(Property::ListChar(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            Some(Property::ListUChar(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            Some(Property::ListShort(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            Some(Property::ListUShort(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            Some(Property::ListInt(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            Some(Property::ListUInt(l)) => l.iter().map(|&i| i64::from(i)).collect(),
            _ => return Err(format!("face {} has no integer list `vertex_indices`", k + 1)),
        };
        let index = |i: i64| u32::try_from(i).map_err(|_| format!("face {} names vertex {i}", k + 1));
        for j in 1..indices.len().saturating_sub(1) {
            triangles.push([index(indices[0])?, index(indices[j])?, index(indices[j + 1])?]);
        }
    }
    Ok(TriangleMesh { positions, normals, uvs, triangles })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_obj_square_becomes_two_triangles_with_its_normals() {
        let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";
        let mesh = from_obj(text.as_bytes()).unwrap();
        assert_eq!(mesh.triangles.len(), 2);
        assert_eq!(mesh.normals.as_ref().map(Vec::len), Some(mesh.positions.len()));
        assert_eq!(mesh.uvs, None);
        mesh.check().unwrap();
    }

    #[test]
    fn a_ply_quad_is_a_fan_and_bad_indices_are_named() {
        let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 7\n";
        let mesh = from_ply(text.as_bytes()).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 7]]);
        assert_eq!(mesh.check().unwrap_err(), "a face names vertex 8 of 4");
    }
}
