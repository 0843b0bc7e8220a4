//! `type = "mesh"`: the triangles of an .obj or .ply `file` (relative to the scene's folder),
//! scaled by `scale` about the file's origin and shaded by its vertex normals where `smooth`.

use super::kind::{At, Geometry, Kind, flag, read, spec};
use crate::format::Assets;
use crate::format::marks::Parts;
use crate::format::numbers::Num;
use crate::invalid::Invalid;
use crate::limits::MAX_OBJECTS;
use crate::shapes::{MeshShape, Shading, TriangleShape};
use cga_core::euclid::E3;
use std::sync::Arc;

const TAKES: &str =
    "a mesh takes `file` (an .obj or .ply), `scale` (default 1) and `smooth` (its vertex normals, default true)";

pub(crate) const KIND: Kind = Kind { name: "mesh", fields: Mesh::FIELDS, takes: TAKES, read: read::<Mesh> };

spec!(Mesh { file: String => Other, scale: Num => Scale, smooth: bool => Other });

impl Mesh {
    /// Its scale, checked: finite and > 0.
    fn scale(&self) -> Result<f64, Invalid> {
        match &self.scale {
            Some(s) if !(s.get_ref().0 > 0.0 && s.get_ref().0.is_finite()) => {
                Err(Invalid::at("scale", s.span(), Invalid::Value("a mesh's scale must be finite and > 0")))
            }
            s => Ok(s.as_ref().map_or(1.0, |s| s.get_ref().0)),
        }
    }
}

impl Geometry for Mesh {
    /// The sphere holding the file's vertices, scaled.
    fn extent(&self, assets: &Assets) -> Option<(E3, f64)> {
        let (c, r) = assets.mesh_bounds(self.file.as_ref()?).ok()??;
        let s = self.scale().ok()?;
        Some((c.map(|x| x * s), r * s))
    }

    /// Its triangles, scaled, placed, with the file's normals (turned) and texture
    /// coordinates. Triangles without area (in the file, or once placed) are left out: no ray
    /// sees them; a mesh left with none (or with no triangles) is refused.
    fn build(&self, at: &At) -> Result<Parts, Invalid> {
        let file = self.file.as_ref().ok_or(Invalid::Form(TAKES))?;
        let mesh = at.assets.mesh(file)?;
        let s = self.scale()?;
        if mesh.triangles.len() > MAX_OBJECTS {
            let many =
                Invalid::Limit { what: "triangles", found: mesh.triangles.len() as u64, limit: MAX_OBJECTS as u64 };
            return Err(Invalid::at("file", file.span(), many));
        }
        let smooth = flag(&self.smooth, true);
        let place = &at.place;
        let mut triangles = Vec::with_capacity(mesh.triangles.len());
        let mut flat_in_file = 0;
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize].map(|x| x * s));
            if TriangleShape::new([a, b, c]).is_err() {
                flat_in_file += 1;
                continue;
            }
            let corner = |i: u32| i as usize;
            let shading = Shading {
                normals: mesh.normals.as_ref().filter(|_| smooth).map(|n| t.map(|i| place.direction(n[corner(i)]))),
                uvs: mesh.uvs.as_ref().map(|uv| t.map(|i| uv[corner(i)])),
            };
            // A sliver that placing far out makes flat is lost to rounding: no ray sees it.
            let Ok(triangle) = TriangleShape::new([place.point(a)?, place.point(b)?, place.point(c)?]) else {
                continue;
            };
            triangles.push(triangle.with_shading(shading).map_err(|e| Invalid::at("file", file.span(), e.into()))?);
        }
        let closed = at.assets.mesh_is_closed(file)?;
        let Some(shape) = MeshShape::new(triangles, closed) else {
            let why = if flat_in_file == mesh.triangles.len() {
                "no triangle of the mesh has an area: nothing to see"
            } else {
                "no triangle of the mesh has an area f64 can hold at this scale and place"
            };
            return Err(Invalid::at("file", file.span(), Invalid::Value(why)));
        };
        Ok((vec![Arc::new(shape)], None))
    }

    fn triangles(&self, assets: &Assets) -> Option<usize> {
        assets.mesh(self.file.as_ref()?).ok().map(|m| m.triangles.len())
    }

    fn closed(&self, assets: &Assets) -> Result<bool, Invalid> {
        self.file.as_ref().map_or(Ok(false), |file| assets.mesh_is_closed(file))
    }
}
