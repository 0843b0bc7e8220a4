//! What a drawing is made of: its shapes, placed in the frame, and where its label goes.

use super::transform::Placement;
use crate::drawing::Drawing;
use crate::invalid::Invalid;
use crate::shapes::{BoxShape, ConeShape, DiskShape, Shape, SphereShape, TorusShape};
use cga_core::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub, unit};
use std::f64::consts::TAU;
use std::sync::Arc;

/// A drawing's shapes, and where its label goes if not beside them all (centre and radius
/// in the frame).
pub(crate) type Parts = (Vec<Arc<dyn Shape>>, Option<(E3, f64)>);

/// Dashes a dashed ring is cut into, and the share of each dash's arc that is drawn.
const DASHES: usize = 24;
const DASH_FILL: f64 = 0.6;

/// A drawing's shapes, placed in the frame by `place`; a line kept over the ball of radius `view`
/// (frame units) about the camera ([`Marks::view`](crate::drawing::Marks::view): where its tube is a quarter
/// of a pixel wide), as a
/// segment about its point nearest `centre` (the scene's, in the frame: where its label
/// goes), and where a label goes when not beside the sphere holding the shapes (a line's
/// beside that point, its tube's radius away).
pub(crate) fn parts(drawing: &Drawing, place: &Placement, centre: E3, view: f64) -> Result<Parts, Invalid> {
    let len = |l: f64| place.length(l);
    let mut out: Vec<Arc<dyn Shape>> = Vec::new();
    let mut anchor = None;
    match *drawing {
        Drawing::Point { at, size } => out.push(Arc::new(SphereShape::new(place.point(at)?, len(size))?)),
        Drawing::PointPair { points, size, segment } => {
            let [a, b] = [place.point(points[0])?, place.point(points[1])?];
            for p in [a, b] {
                out.push(Arc::new(SphereShape::new(p, len(size))?));
            }
            if let Some(tube) = segment {
                out.push(Arc::new(ConeShape::cylinder(a, b, len(tube), true)?));
            }
        }
        Drawing::Line { point, direction, tube } => {
            let (p, d) =
                (place.point(point)?, unit(place.direction(direction)).ok_or(cga_core::GeometryError::ZeroVector)?);
            // The camera is the frame's origin: every point of the line within `view` of
            // it lies within `view + |foot|` of the foot.
            let foot = add(p, scale(d, dot(sub(centre, p), d)));
            let half = view + norm(foot);
            let (a, b) = (sub(foot, scale(d, half)), add(foot, scale(d, half)));
            out.push(Arc::new(ConeShape::cylinder(a, b, len(tube), true)?));
            anchor = Some((foot, len(tube)));
        }
        Drawing::Circle { centre, normal, radius, tube, dashed } => {
            let (c, n, r, t) = (place.point(centre)?, place.direction(normal), len(radius), len(tube));
            if dashed {
                dashes(&mut out, c, n, r, t)?;
            } else {
                out.push(Arc::new(TorusShape::new(c, n, r, t)?));
            }
        }
        Drawing::PlanePatch { centre, normal, size } => {
            out.push(Arc::new(DiskShape::new(place.point(centre)?, place.direction(normal), len(size))?));
        }
        Drawing::Sphere { centre, radius, tube, dashed } => {
            let (c, r) = (place.point(centre)?, len(radius));
            if dashed {
                for n in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
                    dashes(&mut out, c, place.direction(n), r, len(tube))?;
                }
            } else {
                out.push(Arc::new(SphereShape::new(c, r)?));
            }
        }
        Drawing::Arrow { at, direction, tube } => {
            let (a, d, t) = (place.point(at)?, place.direction(direction).map(len), len(tube));
            // A shaft three quarters of the length, a head of three tubes' radius.
            let (neck, tip) = (add(a, scale(d, 0.75)), add(a, d));
            out.push(Arc::new(ConeShape::cylinder(a, neck, t, true)?));
            out.push(Arc::new(ConeShape::new(neck, 3.0 * t, tip, 0.0, true)?));
        }
        Drawing::FlatPoint { at, size } => {
            let (c, axes) = (place.point(at)?, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
            out.push(Arc::new(BoxShape::new([len(size); 3], c, axes.map(|a| place.direction(a)))?));
        }
    }
    Ok((out, anchor))
}

/// A dashed ring: [`DASHES`] straight rods of radius `tube` on the circle of `centre`,
/// `normal` and `radius`, each over [`DASH_FILL`] of its arc.
fn dashes(out: &mut Vec<Arc<dyn Shape>>, centre: E3, normal: E3, radius: f64, tube: f64) -> Result<(), Invalid> {
    let n = unit(normal).ok_or(cga_core::GeometryError::ZeroVector)?;
    let u = unit(perpendicular(n)).ok_or(cga_core::GeometryError::ZeroVector)?;
    let v = cross(n, u);
    let on = |theta: f64| add(centre, add(scale(u, radius * theta.cos()), scale(v, radius * theta.sin())));
    for k in 0..DASHES {
        let start = TAU * k as f64 / DASHES as f64;
        let end = start + DASH_FILL * TAU / DASHES as f64;
        out.push(Arc::new(ConeShape::cylinder(on(start), on(end), tube, true)?));
    }
    Ok(())
}
