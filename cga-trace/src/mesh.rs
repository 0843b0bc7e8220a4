//! Meshes of swept surfaces, for other tools: vertices on the circles `C_α` at a grid of
//! `(α, angle)`, analytic vertex normals (eq. 6–11, with `Ċ` exact) and `(α, angle/2π)`
//! texture coordinates, written as Wavefront OBJ, binary PLY (both f64-exact: OBJ with the
//! shortest round-trip decimal, PLY with `double` properties) or binary glTF (`.glb`, whose
//! positions the format holds as f32).
//!
//! The angle is measured from a direction carried from circle to circle (projected into
//! each circle's plane), so the grid does not twist where circles tilt. Each ring closes on
//! itself: its last column repeats the first vertex (same position, texture `u = 1`), so
//! textures wrap and the geometry is closed around.

use crate::frame::Frame;
use crate::limits::{MAX_MESH_SIDE, MAX_MESH_VERTICES};
use crate::scene::Scene;
use crate::shapes::Shape;
use crate::surface::{EvolvedSurface, RuledSurface, SplineSurface};
use cga_core::euclid::{E3, add, cross, dot, perpendicular, scale, sub, unit};
use std::io::Write;
use std::path::Path;

/// A surface swept by circles `C_α`, `α ∈ [0, 1]`, in the scene's frame.
pub trait Swept {
    /// `(centre, unit normal, radius)` of `C_α`.
    fn circle(&self, alpha: f64) -> Option<(E3, E3, f64)>;
    /// The unit surface normal at `x` on `C_α` (eq. 6–11; its sign is the caller's to fix).
    fn normal(&self, alpha: f64, x: E3) -> Option<E3>;
}

impl Swept for EvolvedSurface {
    fn circle(&self, alpha: f64) -> Option<(E3, E3, f64)> {
        let (family, origin) = self.family();
        let (c, n, r) = family.at(alpha).ok()?.centre_normal_radius().ok()?;
        Some((add(c, origin), n, r))
    }

    fn normal(&self, alpha: f64, x: E3) -> Option<E3> {
        let (family, origin) = self.family();
        family.pair().normal_parts(alpha, sub(x, origin)).ok()?.normal_line.direction().ok()
    }
}

impl Swept for SplineSurface {
    fn circle(&self, alpha: f64) -> Option<(E3, E3, f64)> {
        let (c, n, r) = self.spline().at(alpha).ok()?.centre_normal_radius().ok()?;
        Some((add(c, self.origin()), n, r))
    }

    fn normal(&self, alpha: f64, x: E3) -> Option<E3> {
        let parts = self.spline().normal_parts(alpha, sub(x, self.origin())).ok()?;
        parts.normal_line.direction().ok()
    }
}

/// `Resolution` unless `1 ≤ rings ≤ 65536`, `least ≤ segments ≤ 65536` and the grid has at
/// most [`MAX_MESH_VERTICES`] vertices: checked before anything is allocated (`least` is 3 for
/// surfaces swept by circles, 1 for ruled ones).
pub fn check_resolution(rings: usize, segments: usize, least: usize) -> Result<(), MeshError> {
    let vertices = (rings as u128 + 1) * (segments as u128 + 1);
    let ok = (1..=MAX_MESH_SIDE).contains(&rings)
        && (least..=MAX_MESH_SIDE).contains(&segments)
        && vertices <= MAX_MESH_VERTICES as u128;
    ok.then_some(()).ok_or(MeshError::Resolution { rings, segments, least })
}

/// A swept surface of a shape, if it is one.
pub fn swept(shape: &dyn Shape) -> Option<&dyn Swept> {
    if let Some(s) = shape.downcast_ref::<EvolvedSurface>() {
        return Some(s);
    }
    shape.downcast_ref::<SplineSurface>().map(|s| s as &dyn Swept)
}

/// Why a mesh cannot be made or written.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// No object of that name.
    #[error("no object named `{0}` in the scene")]
    NoObject(String),
    /// The object is a template, which the scene holds only as its instances.
    #[error(
        "`{0}` is a template (`template = true`): the scene draws only its instances; name one of them, or give the surface without `template`"
    )]
    Template(String),
    /// The object is not a swept surface.
    #[error("`{0}` is not an evolved, spline or ruled surface")]
    NotSwept(String),
    /// Fewer than 1 ring or too few segments, more than [`MAX_MESH_SIDE`] of either, or more
    /// than [`MAX_MESH_VERTICES`] vertices.
    #[error(
        "{rings} rings × {segments} segments: a mesh takes 1 to {MAX_MESH_SIDE} rings, {least} to {MAX_MESH_SIDE} segments and at most {MAX_MESH_VERTICES} vertices, (rings + 1)(segments + 1)"
    )]
    Resolution {
        /// Asked for.
        rings: usize,
        /// Asked for.
        segments: usize,
        /// The fewest segments this kind of surface takes.
        least: usize,
    },
    /// A circle or normal could not be computed at this α.
    #[error("no circle at α = {0}")]
    NoCircle(f64),
    /// The extension names no mesh format.
    #[error("`{0}`: unknown mesh extension (use .obj, .ply or .glb)")]
    Extension(String),
    /// Writing failed.
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// Wavefront OBJ (text, f64 exact).
    Obj,
    /// Binary PLY (f64).
    Ply,
    /// Binary glTF 2.0 (f32).
    Glb,
}

impl MeshFormat {
    /// The format of `path`'s extension (case-insensitive).
    pub fn of(path: &Path) -> Result<Self, MeshError> {
        match path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase().as_str() {
            "obj" => Ok(MeshFormat::Obj),
            "ply" => Ok(MeshFormat::Ply),
            "glb" => Ok(MeshFormat::Glb),
            _ => Err(MeshError::Extension(path.display().to_string())),
        }
    }
}

/// A triangle mesh in world coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<E3>,
    /// Unit vertex normals, facing the side the triangles' winding makes front.
    pub normals: Vec<E3>,
    /// `(α, angle / 2π)` (a ruled surface's `(α, fraction)`), `v` counted down an image as
    /// the renderer's textures and glTF count it; OBJ and PLY count it up, so they are
    /// written `1 − v`.
    pub uvs: Vec<[f64; 2]>,
    /// Counter-clockwise seen from the normals' side.
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// `rings + 1` circles at `α = i / rings`, each `segments + 1` vertices around (the last
    /// repeating the first), positions and normals moved out of `frame` to world coordinates.
    pub fn of(surface: &dyn Swept, frame: &Frame, rings: usize, segments: usize) -> Result<Mesh, MeshError> {
        check_resolution(rings, segments, 3)?;
        let mut mesh = Mesh::default();
        let mut across: Option<E3> = None;
        for i in 0..=rings {
            let alpha = i as f64 / rings as f64;
            let (c, n, r) = surface.circle(alpha).ok_or(MeshError::NoCircle(alpha))?;
            // The angle's zero: the previous ring's, carried into this circle's plane.
            let u = across.and_then(|u| unit(sub(u, scale(n, dot(u, n))))).unwrap_or_else(|| perpendicular(n));
            let v = cross(n, u);
            across = Some(u);
            for j in 0..=segments {
                let theta = std::f64::consts::TAU * (j % segments) as f64 / segments as f64;
                let x = add(c, add(scale(u, r * theta.cos()), scale(v, r * theta.sin())));
                let normal = surface.normal(alpha, x).unwrap_or_else(|| unit(sub(x, c)).unwrap_or(n));
                mesh.positions.push(frame.world_point(x));
                mesh.normals.push(normal);
                mesh.uvs.push([alpha, j as f64 / segments as f64]);
            }
        }
        mesh.finish(rings, segments, true);
        Ok(mesh)
    }

    /// Triangulate the `(rings + 1) × (segments + 1)` grid of vertices, and turn each analytic
    /// normal to the side the winding makes front (the sign of eq. 6–11's `N` follows the
    /// circles' orientation, not the mesh's); a zero normal (a singular point) becomes the
    /// grid's own. `closed`: the columns wrap around (the seam's two columns are one, their
    /// neighbours columns 1 and n − 1).
    fn finish(&mut self, rings: usize, segments: usize, closed: bool) {
        let w = segments + 1;
        let at = |i: usize, j: usize| (i * w + j) as u32;
        for i in 0..rings {
            for j in 0..segments {
                self.triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                self.triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
        for i in 0..=rings {
            for j in 0..=segments {
                let p = |i: usize, j: usize| self.positions[i * w + j];
                let (i0, i1) = (i.saturating_sub(1), (i + 1).min(rings));
                let (j0, j1) = match (closed, j) {
                    (true, j) if j == 0 || j == segments => (segments - 1, 1),
                    _ => (j.saturating_sub(1), (j + 1).min(segments)),
                };
                let geometric = cross(sub(p(i1, j), p(i0, j)), sub(p(i, j1), p(i, j0)));
                let k = i * w + j;
                if self.normals[k] == [0.0; 3] {
                    self.normals[k] = unit(geometric).unwrap_or([0.0, 0.0, 1.0]);
                } else if dot(geometric, self.normals[k]) < 0.0 {
                    self.normals[k] = self.normals[k].map(|x| -x);
                }
            }
        }
    }

    /// Write to `out` in `format` (buffer it: OBJ is many small writes).
    pub fn save(&self, out: &mut dyn Write, format: MeshFormat) -> Result<(), MeshError> {
        match format {
            MeshFormat::Obj => self.write_obj(out)?,
            MeshFormat::Ply => self.write_ply(out)?,
            MeshFormat::Glb => self.write_glb(out)?,
        }
        out.flush()?;
        Ok(())
    }

    /// Wavefront OBJ: `v`, `vt`, `vn` in full f64 precision (shortest round-trip decimals),
    /// faces `f a/a/a` (1-based).
    pub fn write_obj(&self, out: &mut dyn Write) -> std::io::Result<()> {
        writeln!(
            out,
            "# cga-trace mesh: vertices on the circles C_α, analytic normals, uv = (α, 1 − angle/2π): v up the image"
        )?;
        for p in &self.positions {
            writeln!(out, "v {:?} {:?} {:?}", p[0], p[1], p[2])?;
        }
        for t in &self.uvs {
            writeln!(out, "vt {:?} {:?}", t[0], 1.0 - t[1])?;
        }
        for n in &self.normals {
            writeln!(out, "vn {:?} {:?} {:?}", n[0], n[1], n[2])?;
        }
        for t in &self.triangles {
            let [a, b, c] = t.map(|k| k + 1);
            writeln!(out, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")?;
        }
        Ok(())
    }

    /// Binary little-endian PLY: vertices with `double` x, y, z, nx, ny, nz, u, v; faces as
    /// `uchar`-counted lists of `uint` indices.
    pub fn write_ply(&self, out: &mut dyn Write) -> std::io::Result<()> {
        write!(
            out,
            "ply\nformat binary_little_endian 1.0\ncomment cga-trace mesh: uv = (alpha, 1 - angle/2pi): v up the image\n\
             element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
             property double nx\nproperty double ny\nproperty double nz\nproperty double u\nproperty double v\n\
             element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
            self.positions.len(),
            self.triangles.len()
        )?;
        for k in 0..self.positions.len() {
            let (p, n, [u, v]) = (self.positions[k], self.normals[k], self.uvs[k]);
            let t = [u, 1.0 - v];
            for x in p.iter().chain(&n).chain(&t) {
                out.write_all(&x.to_le_bytes())?;
            }
        }
        for t in &self.triangles {
            out.write_all(&[3])?;
            for k in t {
                out.write_all(&k.to_le_bytes())?;
            }
        }
        Ok(())
    }

    /// Binary glTF 2.0 (`.glb`): one mesh of one triangle primitive, `POSITION`, `NORMAL`,
    /// `TEXCOORD_0` as f32 (the format's type for them) and `u32` indices, in one buffer.
    pub fn write_glb(&self, out: &mut dyn Write) -> std::io::Result<()> {
        let f32s = |v: &[f64]| v.iter().flat_map(|x| (*x as f32).to_le_bytes()).collect::<Vec<u8>>();
        let positions = f32s(&self.positions.concat());
        let normals = f32s(&self.normals.concat());
        let uvs = f32s(&self.uvs.concat());
        let indices: Vec<u8> = self.triangles.iter().flatten().flat_map(|k| k.to_le_bytes()).collect();
        let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        for p in &self.positions {
            for k in 0..3 {
                (min[k], max[k]) = (min[k].min(p[k] as f32), max[k].max(p[k] as f32));
            }
        }
        let views = [positions.len(), normals.len(), uvs.len(), indices.len()];
        let offsets: Vec<usize> = views.iter().scan(0, |o, len| Some(std::mem::replace(o, *o + len))).collect();
        let n = self.positions.len();
        let json = serde_json::json!({
            "asset": { "version": "2.0", "generator": "cga-trace" },
            "scene": 0,
            "scenes": [{ "nodes": [0] }],
            "nodes": [{ "mesh": 0 }],
            "meshes": [{ "primitives": [{
                "attributes": { "POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2 },
                "indices": 3,
                "mode": 4
            }]}],
            "buffers": [{ "byteLength": offsets[3] + views[3] }],
            "bufferViews": [
                { "buffer": 0, "byteOffset": offsets[0], "byteLength": views[0], "target": 34962 },
                { "buffer": 0, "byteOffset": offsets[1], "byteLength": views[1], "target": 34962 },
                { "buffer": 0, "byteOffset": offsets[2], "byteLength": views[2], "target": 34962 },
                { "buffer": 0, "byteOffset": offsets[3], "byteLength": views[3], "target": 34963 }
            ],
            "accessors": [
                { "bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3", "min": min, "max": max },
                { "bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3" },
                { "bufferView": 2, "componentType": 5126, "count": n, "type": "VEC2" },
                { "bufferView": 3, "componentType": 5125, "count": self.triangles.len() * 3, "type": "SCALAR" }
            ]
        });
        let mut json = serde_json::to_vec(&json).map_err(std::io::Error::other)?;
        json.resize(json.len().next_multiple_of(4), b' ');
        let mut bin = [positions, normals, uvs, indices].concat();
        bin.resize(bin.len().next_multiple_of(4), 0);
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let word = |x: usize| u32::try_from(x).map_err(std::io::Error::other).map(u32::to_le_bytes);
        out.write_all(b"glTF")?;
        out.write_all(&2u32.to_le_bytes())?;
        out.write_all(&word(total)?)?;
        out.write_all(&word(json.len())?)?;
        out.write_all(b"JSON")?;
        out.write_all(&json)?;
        out.write_all(&word(bin.len())?)?;
        out.write_all(b"BIN\0")?;
        out.write_all(&bin)
    }
}

impl Mesh {
    /// A ruled surface: `rings + 1` rulings at `α = i / rings`, each cut into `segments`
    /// (its `segments + 1` vertices at fractions `j / segments` of the ruling's extent), the
    /// analytic normals (the grid's own where the surface is singular, `N = 0`), texture
    /// coordinates `(α, j / segments)`.
    pub fn of_ruled(surface: &RuledSurface, frame: &Frame, rings: usize, segments: usize) -> Result<Mesh, MeshError> {
        check_resolution(rings, segments, 1)?;
        let mut mesh = Mesh::default();
        for i in 0..=rings {
            let alpha = i as f64 / rings as f64;
            for j in 0..=segments {
                let v = j as f64 / segments as f64;
                let (x, n) = surface.point_and_normal(alpha, v).ok_or(MeshError::NoCircle(alpha))?;
                mesh.positions.push(frame.world_point(x));
                // Where the surface is singular (N = 0), the grid's own normal (below).
                mesh.normals.push(n.unwrap_or([0.0; 3]));
                mesh.uvs.push([alpha, v]);
            }
        }
        mesh.finish(rings, segments, false);
        Ok(mesh)
    }
}

impl Scene {
    /// The object named `name`, as a swept surface.
    pub fn swept(&self, name: &str) -> Result<&dyn Swept, MeshError> {
        swept(self.object(name)?.shape.as_ref()).ok_or_else(|| MeshError::NotSwept(name.into()))
    }

    /// The mesh of the object named `name`: an evolved, spline or ruled surface.
    pub fn mesh(&self, name: &str, rings: usize, segments: usize) -> Result<Mesh, MeshError> {
        let shape = self.object(name)?.shape.as_ref();
        match shape.downcast_ref::<RuledSurface>() {
            Some(ruled) => Mesh::of_ruled(ruled, &self.frame, rings, segments),
            None => Mesh::of(self.swept(name)?, &self.frame, rings, segments),
        }
    }

    fn object(&self, name: &str) -> Result<&crate::object::Object, MeshError> {
        match self.objects.iter().find(|o| &*o.name == name) {
            Some(object) => Ok(object),
            None if self.templates.iter().any(|t| t == name) => Err(MeshError::Template(name.into())),
            None => Err(MeshError::NoObject(name.into())),
        }
    }
}
