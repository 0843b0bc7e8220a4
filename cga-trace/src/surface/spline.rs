//! A spline surface: the circles of a [`cga_core::Spline`] through `N ≥ 2` control circles
//! (the paper's Fig. 3), one [`EvolvedSurface`] per segment — the two-circle family with its
//! degree-8 polynomial for linear joins, a [`BezierSegment`] with its degree-`(12d − 4)`
//! polynomial otherwise — sharing one local frame, so that neighbouring segments meet on the
//! very same knot circle and leave no crack.

use super::evolved::{EvolvedSurface, distinct};
use super::patches::Patches;
use super::segment::BezierSegment;
use super::unsquared::{Numerators, Unsquared};
use super::{Method, SurfaceError, TwoCircles};
use crate::ray::{Ray, crosses};
use crate::shapes::{Crossing, Shape, facing};
use cga_core::euclid::{E3, sub};
use cga_core::{Circle, Joining, Line, Pair, Spline};

/// One segment, by the family its circles form.
#[derive(Clone, Debug)]
enum Segment {
    /// Between two knots (linear joining): the exact degree-8 polynomial.
    Linear(Box<EvolvedSurface>),
    /// A quadratic or cubic Bézier segment.
    Curved(Box<EvolvedSurface<BezierSegment<f64>>>),
}

/// A Bézier segment's surface with its crossing condition unsquared on the hybrid method's
/// cells ([`Unsquared`]), which decides most rays without the polynomial.
fn curved(surface: EvolvedSurface<BezierSegment<f64>>) -> EvolvedSurface<BezierSegment<f64>> {
    let unsquared = match surface.method() {
        method @ Method::Hybrid { .. } => {
            method.cells().and_then(|cells| Unsquared::new(&surface.circles().circles, cells))
        }
        _ => None,
    };
    surface.with_unsquared(unsquared)
}

impl Segment {
    /// The nearest crossing of a ray in the shared local frame.
    fn intersect_local(&self, local: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        match self {
            Segment::Linear(s) => s.intersect_local(local, t_min, t_max),
            Segment::Curved(s) => s.intersect_local(local, t_min, t_max),
        }
    }

    /// Whether the ray crosses the segment, in the shared local frame.
    fn occludes_local(&self, local: &Ray, t_min: f64, t_max: f64) -> bool {
        match self {
            Segment::Linear(s) => s.occludes_local(local, t_min, t_max),
            Segment::Curved(s) => s.occludes_local(local, t_min, t_max),
        }
    }

    /// The ray's `N` and `D` over the segment, where its cells solve them unsquared.
    fn prepare(&self, local: &Ray) -> Option<Numerators<f64>> {
        match self {
            Segment::Linear(_) => None,
            Segment::Curved(s) => s.prepare(local),
        }
    }

    /// The nearest crossing on one cell, in the shared local frame.
    fn intersect_cell(
        &self,
        local: &Ray,
        cell: usize,
        window: (f64, f64),
        n: Option<&Numerators<f64>>,
    ) -> Option<Crossing> {
        match self {
            Segment::Linear(s) => s.intersect_cell(local, cell, window, n),
            Segment::Curved(s) => s.intersect_cell(local, cell, window, n),
        }
    }

    /// Whether the ray crosses one cell, in the shared local frame.
    fn occludes_cell(&self, local: &Ray, cell: usize, window: (f64, f64), n: Option<&Numerators<f64>>) -> bool {
        match self {
            Segment::Linear(s) => s.occludes_cell(local, cell, window, n),
            Segment::Curved(s) => s.occludes_cell(local, cell, window, n),
        }
    }

    fn circle(&self, alpha: f64) -> Result<(E3, E3, f64), SurfaceError> {
        let circle = match self {
            Segment::Linear(s) => s.circles().at(alpha),
            Segment::Curved(s) => s.circles().at(alpha),
        }?;
        circle.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })
    }

    fn normal(&self, crossing: &Crossing) -> E3 {
        match self {
            Segment::Linear(s) => s.normal(crossing),
            Segment::Curved(s) => s.normal(crossing),
        }
    }

    fn bounds(&self) -> (E3, f64) {
        match self {
            Segment::Linear(s) => s.bounds(),
            Segment::Curved(s) => s.bounds(),
        }
    }

    fn frame_radius(&self) -> f64 {
        match self {
            Segment::Linear(s) => s.frame_radius(),
            Segment::Curved(s) => s.frame_radius(),
        }
    }
}

/// A surface swept by the circles of a spline; `α ∈ [0, 1]` runs over all of it, segment `j`
/// of `m` covering `[j/m, (j+1)/m]`.
#[derive(Clone, Debug)]
pub struct SplineSurface {
    segments: Vec<Segment>,
    /// The spline, in the local frame (for curvature and inspection).
    spline: Spline<Circle>,
    origin: E3,
    radius: f64,
    /// Boxes and slabs over the segments' cells cut along α and by angle, which lead a ray to
    /// the cells it can cross nearest first (for the hybrid method on Bézier segments).
    patches: Option<Patches>,
}

impl SplineSurface {
    /// The frame origin for circles of centres `cᵢ` and radii `rᵢ`: `Σ(cᵢ/rᵢ) / Σ(1/rᵢ)`, which
    /// for two circles is their centre of similitude ([`EvolvedSurface::frame_origin`]) and
    /// in general keeps every circle's distance in its own radii, `|cᵢ − o|/rᵢ`, small.
    pub fn frame_origin(circles: &[(E3, f64)]) -> E3 {
        let weight: f64 = circles.iter().map(|(_, r)| 1.0 / r).sum();
        [0, 1, 2].map(|k| circles.iter().map(|(c, r)| c[k] / r).sum::<f64>() / weight)
    }

    /// The surface through `circles` (centre, normal, radius, in the scene's frame), joined as
    /// `joining` says, built in the frame of [`SplineSurface::frame_origin`].
    pub fn new(circles: &[(E3, E3, f64)], joining: Joining, method: Method) -> Result<Self, SurfaceError> {
        // Each circle checked where it is given, before any of them sets the frame.
        for (k, &(c, n, r)) in circles.iter().enumerate() {
            Circle::from_centre_normal_radius(c, n, r)
                .map_err(|reason| SurfaceError::NotACircle { which: k + 1, reason })?;
        }
        let origin = Self::frame_origin(&circles.iter().map(|&(c, _, r)| (c, r)).collect::<Vec<_>>());
        let mut local = Vec::with_capacity(circles.len());
        for (k, &(c, n, r)) in circles.iter().enumerate() {
            local.push(
                Circle::from_centre_normal_radius(sub(c, origin), n, r)
                    .map_err(|reason| SurfaceError::NotACircle { which: k + 1, reason })?,
            );
        }
        if joining == Joining::Linear {
            // Two consecutive circles that are one make a span that sweeps nothing.
            let unit_normal = |&(c, n, r): &(E3, E3, f64)| (c, cga_core::euclid::unit(n).unwrap_or(n), r);
            for (k, pair) in circles.windows(2).enumerate() {
                distinct(unit_normal(&pair[0]), unit_normal(&pair[1]), Some((k + 1, k + 2)))?;
            }
        }
        let spline = Spline::new(&local, joining)?;
        let segments = (0..spline.segments())
            .map(|j| {
                let controls = spline.segment(j);
                Ok(match controls {
                    [a, b] => {
                        let pair = TwoCircles::new(Pair { c1: *a, c2: *b });
                        Segment::Linear(Box::new(EvolvedSurface::of(origin, pair, method)?))
                    }
                    _ => Segment::Curved(Box::new(curved(EvolvedSurface::of(
                        origin,
                        BezierSegment::new(controls),
                        method,
                    )?))),
                })
            })
            .collect::<Result<Vec<_>, SurfaceError>>()?;
        let radius = segments.iter().map(Segment::frame_radius).fold(0.0, f64::max);
        let patches = Self::patches(&segments, method)?;
        Ok(SplineSurface { segments, spline, origin, radius, patches })
    }

    /// The patches over `segments`' cells, for the hybrid method on Bézier segments whose
    /// cells are solved unsquared ([`Patches::cells_for`]). Others solve a cell by building a
    /// polynomial on it: one cell at a time, a shadow ray leaving the surface built it on each
    /// cell around its start, and the scene rays of fig3a (linear segments) took 1.05× their
    /// time through the spheres' merged intervals.
    fn patches(segments: &[Segment], method: Method) -> Result<Option<Patches>, SurfaceError> {
        let curved = segments.iter().all(|s| matches!(s, Segment::Curved(s) if s.solves_unsquared()));
        let Some(cells) = Patches::cells_for(method, segments.len()).filter(|_| curved) else { return Ok(None) };
        Patches::new(segments.len(), cells, |j, alpha| segments[j].circle(alpha)).map(Some)
    }

    /// The same surface intersected by another method.
    pub fn with_method(&self, method: Method) -> Result<Self, SurfaceError> {
        let segments = (self.segments.iter())
            .map(|s| {
                Ok(match s {
                    Segment::Linear(s) => Segment::Linear(Box::new(s.with_method(method)?)),
                    Segment::Curved(s) => Segment::Curved(Box::new(curved(s.with_method(method)?))),
                })
            })
            .collect::<Result<Vec<_>, SurfaceError>>()?;
        let patches = Self::patches(&segments, method)?;
        let (spline, origin, radius) = (self.spline.clone(), self.origin, self.radius);
        Ok(SplineSurface { segments, spline, origin, radius, patches })
    }

    /// The number of segments.
    pub fn segments(&self) -> usize {
        self.segments.len()
    }

    /// The spline, in the local frame whose origin is [`SplineSurface::origin`].
    pub fn spline(&self) -> &Spline<Circle> {
        &self.spline
    }

    /// The local frame's origin.
    pub fn origin(&self) -> E3 {
        self.origin
    }

    /// The ray in the local frame (every segment shares it).
    fn local(&self, ray: &Ray) -> Ray {
        let o = sub(ray.origin, self.origin);
        Ray { origin: o, dir: ray.dir, carrier: Line::from_point_unit_direction(o, ray.dir) }
    }

    /// The segment holding `α`, and the parameter within it.
    fn locate(&self, alpha: f64) -> (usize, f64) {
        let m = self.segments.len();
        let u = alpha * m as f64;
        let j = (u.floor().max(0.0) as usize).min(m - 1);
        (j, u - j as f64)
    }
}

impl SplineSurface {
    /// Walks the patches ([`Patches::visit`]), calling `cell(segment, its index, the local ray,
    /// cell, its N and D, t_max)` for each cell reached: the local ray built at the first, and
    /// a segment's `N` and `D` once for each run of its cells (a walk by a knot may go back
    /// and forth between two segments).
    fn walk(
        &self,
        patches: &Patches,
        ray: &Ray,
        (t_min, t_max): (f64, f64),
        mut cell: impl FnMut(&Segment, usize, &Ray, usize, Option<&Numerators<f64>>, f64) -> Option<f64>,
    ) -> Option<f64> {
        let mut local: Option<Ray> = None;
        let mut prepared: Option<(usize, Option<Numerators<f64>>)> = None;
        let origin = sub(ray.origin, self.origin);
        patches.visit((origin, ray.dir), t_min, t_max, |j, i, t_max| {
            let local = local.get_or_insert_with(|| self.local(ray));
            let segment = &self.segments[j];
            if prepared.as_ref().is_none_or(|p| p.0 != j) {
                prepared = Some((j, segment.prepare(local)));
            }
            cell(segment, j, local, i, prepared.as_ref().and_then(|p| p.1.as_ref()), t_max)
        })
    }

    /// The nearest crossing, through the patches: cells solved as the ray reaches them,
    /// nearest first.
    fn intersect_patches(&self, patches: &Patches, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let m = self.segments.len() as f64;
        let mut best = None;
        self.walk(patches, ray, (t_min, t_max), |segment, j, local, i, numerators, t_max| {
            let Some(c) = segment.intersect_cell(local, i, (t_min, t_max), numerators) else { return Some(t_max) };
            best = Some(Crossing { alpha: c.alpha.map(|t| (j as f64 + t) / m), ..c });
            Some(c.t)
        });
        best
    }

    /// Whether the ray crosses the surface, through the patches: the walk stops at the first
    /// cell crossed.
    fn occludes_patches(&self, patches: &Patches, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let walk = self.walk(patches, ray, (t_min, t_max), |segment, _, local, i, numerators, t_max| {
            (!segment.occludes_cell(local, i, (t_min, t_max), numerators)).then_some(t_max)
        });
        walk.is_none()
    }
}

impl Shape for SplineSurface {
    fn intersect(&self, ray: &Ray, t_min: f64, mut t_max: f64) -> Option<Crossing> {
        if let Some(patches) = &self.patches {
            return self.intersect_patches(patches, ray, t_min, t_max);
        }
        let m = self.segments.len() as f64;
        let mut best = None;
        // Every segment shares the frame at `origin`: the ray's line there is built once.
        let mut local: Option<Ray> = None;
        for (j, segment) in self.segments.iter().enumerate() {
            let (centre, radius) = segment.bounds();
            if !crosses(ray, centre, radius, t_min, t_max) {
                continue;
            }
            let local = local.get_or_insert_with(|| self.local(ray));
            if let Some(c) = segment.intersect_local(local, t_min, t_max) {
                t_max = c.t;
                best = Some(Crossing { alpha: c.alpha.map(|t| (j as f64 + t) / m), ..c });
            }
        }
        best
    }

    fn occludes(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        if let Some(patches) = &self.patches {
            return self.occludes_patches(patches, ray, t_min, t_max);
        }
        let mut local: Option<Ray> = None;
        self.segments.iter().any(|segment| {
            let (centre, radius) = segment.bounds();
            crosses(ray, centre, radius, t_min, t_max) && {
                let local = local.get_or_insert_with(|| self.local(ray));
                segment.occludes_local(local, t_min, t_max)
            }
        })
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let (j, t) = self.locate(crossing.alpha.unwrap_or(0.0));
        facing(self.segments[j].normal(&Crossing { alpha: Some(t), ..*crossing }), ray.dir)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        // Every segment lies within its radius about the shared origin.
        Some((self.origin, self.radius))
    }

    fn crossing_error(&self) -> f64 {
        super::swept_error(self.origin, self.radius)
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        self.spline.curvature(crossing.alpha?, sub(crossing.point, self.origin)).ok()
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], crate::shapes::Unit)> {
        let (c, n, _) = self.spline.at(crossing.alpha?).ok()?.centre_normal_radius().ok()?;
        super::swept_uv(crossing, (cga_core::euclid::add(c, self.origin), n))
    }
}
