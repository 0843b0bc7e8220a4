//! The evolved surface as a scene object: its local frame, bounds, culling cells and the
//! method that finds its crossings with a ray.

use super::bernstein::Roots;
use super::cells::{CellBits, Cells, Intervals, PAD};
use super::family::{Circles, TwoCircles};
use super::unsquared::{Numerators, Unsquared, Window};
use super::{Family, Finder, Method, SurfaceError};
use crate::ray::{Ray, crosses};
use crate::shapes::{Crossing, Shape, facing};
use cga_core::euclid::{E3, add, cross, dot, norm, sub};
use cga_core::{Circle, Dual, Interpolable, Line, NormalParts, Pair, Sandwich, Translator};

/// A surface swept by a family of circles `C_α`, `α ∈ [0, 1]`: by default those interpolated
/// between two circles ([`TwoCircles`]); one segment of a spline surface
/// ([`BezierSegment`](super::BezierSegment)) is the same object over another family.
#[derive(Clone, Debug)]
pub struct EvolvedSurface<C = TwoCircles<f64>> {
    /// The circles in the local frame, with per-surface constants.
    family: Family<f64, C>,
    /// The local frame's origin, in world coordinates.
    origin: E3,
    /// Bounding-sphere radius about `origin`.
    radius: f64,
    /// A tighter bounding sphere `(centre, radius)`, in world coordinates: the one rays are
    /// culled by (a segment of a spline lies off the frame's origin).
    sphere: (E3, f64),
    /// How rays are intersected.
    method: Method,
    /// Bounding spheres and tubes over α-intervals, for the methods that cull with them.
    cells: Option<Cells>,
    /// The crossing condition unsquared on the same cells, for the families and methods that
    /// use it (a spline segment's, with the hybrid method).
    unsquared: Option<Box<Unsquared<f64>>>,
}

/// Circles whose centres and radii differ by less than this times the radius, and whose
/// normals by less than this in angle, are one circle ([`SurfaceError::SameCircle`]).
const SAME_CIRCLE: f64 = 1e-12;

/// `Err(SameCircle)` if two circles `(centre, unit normal, radius)` are one circle, the same
/// way round or reversed: a family between them sweeps nothing.
pub(super) fn distinct(
    (p1, n1, r1): (E3, E3, f64),
    (p2, n2, r2): (E3, E3, f64),
    between: Option<(usize, usize)>,
) -> Result<(), SurfaceError> {
    let close = SAME_CIRCLE * r1.max(r2);
    if norm(sub(p1, p2)) <= close && (r1 - r2).abs() <= close && norm(cross(n1, n2)) <= SAME_CIRCLE {
        return Err(SurfaceError::SameCircle { between, reversed: dot(n1, n2) < 0.0 });
    }
    Ok(())
}

/// The bounding sphere is sampled this finely, then padded.
const BOUND_SAMPLES: usize = 512;

/// A sphere around sampled circles `(centre, radius)`, centred in their bounding box and padded
/// by [`PAD`] and by the most a circle moves between neighbouring samples (every circle between
/// two samples lies within that of both).
fn tight_sphere(sampled: &[(E3, f64)]) -> (E3, f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (c, r) in sampled {
        for k in 0..3 {
            lo[k] = lo[k].min(c[k] - r);
            hi[k] = hi[k].max(c[k] + r);
        }
    }
    let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
    let step = sampled.windows(2).fold(0.0f64, |m, w| m.max(norm(sub(w[0].0, w[1].0)) + (w[0].1 - w[1].1).abs()));
    let radius = sampled.iter().fold(0.0f64, |m, (c, r)| m.max(norm(sub(*c, centre)) + r));
    (centre, radius * PAD + step)
}

impl EvolvedSurface {
    /// The surface between `c1` (α = 0) and `c2` (α = 1), given in world coordinates and
    /// moved to the frame of [`EvolvedSurface::frame_origin`].
    pub fn new(c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let centre =
            |c: &Circle, which| c.centre_normal_radius().map_err(|reason| SurfaceError::NotACircle { which, reason });
        let ((p1, _, r1), (p2, _, r2)) = (centre(&c1, 1)?, centre(&c2, 2)?);
        let origin = Self::frame_origin((p1, r1), (p2, r2));
        let to_local = Translator::from_vector(origin.map(|x| -x));
        Self::in_frame(origin, to_local.sandwich(c1), to_local.sandwich(c2), method)
    }

    /// The best origin for a pair of circles of centres `cᵢ` and radii `rᵢ`: their internal
    /// centre of similitude `(r₂ c₁ + r₁ c₂) / (r₁ + r₂)`, where each circle's distance from the
    /// origin in its own radii, `ρᵢ = |cᵢ − o| / rᵢ`, is the same, `|c₁ − c₂| / (r₁ + r₂)`, and
    /// the larger of the two as small as it can be (the interpolation's error grows as
    /// `ε (1 + ρ)³`, [`cga_core::Pair::condition`]). For equal radii it is the midpoint; for
    /// radii eight decades apart it sits at the small circle.
    pub fn frame_origin((c1, r1): (E3, f64), (c2, r2): (E3, f64)) -> E3 {
        let w = r1 + r2;
        [0, 1, 2].map(|k| (r2 * c1[k] + r1 * c2[k]) / w)
    }

    /// The surface between circles given in a frame whose origin is `origin` (world
    /// coordinates). Building them there, rather than far out in world coordinates, keeps
    /// their precision. All per-surface work (bounds, cells, polynomial constants) is done here.
    ///
    /// The circles are rebuilt from their centre, normal and radius: a trivector typed with
    /// rounded coefficients is not exactly a blade (`C C̃` then has a 4-vector part), and the
    /// polynomial method relies on `⟨−X X̃⟩₄ = α(1 − α) W` exactly.
    pub fn in_frame(origin: E3, c1: Circle, c2: Circle, method: Method) -> Result<Self, SurfaceError> {
        let parts =
            |c: Circle, which| c.centre_normal_radius().map_err(|reason| SurfaceError::NotACircle { which, reason });
        let ((p1, n1, r1), (p2, n2, r2)) = (parts(c1, 1)?, parts(c2, 2)?);
        distinct((p1, n1, r1), (p2, n2, r2), None)?;
        let blade = |(centre, normal, radius), which| {
            Circle::from_centre_normal_radius(centre, normal, radius)
                .map_err(|reason| SurfaceError::NotACircle { which, reason })
        };
        let pair = Pair::new(blade((p1, n1, r1), 1)?, blade((p2, n2, r2), 2)?)?;
        EvolvedSurface::of(origin, TwoCircles::new(pair), method)
    }

    /// The circles in the local frame (with per-surface constants), and the frame's origin.
    pub fn family(&self) -> (&Family<f64>, E3) {
        (&self.family, self.origin)
    }
}

impl<C: Circles<f64>> EvolvedSurface<C> {
    /// The surface swept by `circles`, given in a frame whose origin is `origin` (world
    /// coordinates): bounding sphere (sampled, padded), and the method's cells. Refused where a
    /// sampled `C_α` is a line (`Unbounded`) or has no real root.
    pub fn of(origin: E3, circles: C, method: Method) -> Result<Self, SurfaceError> {
        let mut sampled = Vec::with_capacity(BOUND_SAMPLES + 1);
        for k in 0..=BOUND_SAMPLES {
            let alpha = k as f64 / BOUND_SAMPLES as f64;
            let (c, _, r) = circles.at(alpha)?.centre_normal_radius().map_err(|_| SurfaceError::Unbounded { alpha })?;
            sampled.push((c, r));
        }
        let radius = sampled.iter().fold(0.0f64, |m, (c, r)| m.max(norm(*c) + r));
        let (centre, tight) = tight_sphere(&sampled);
        let cells = Self::cells(&circles, method)?;
        Ok(EvolvedSurface {
            family: Family::of(circles),
            origin,
            radius: radius * PAD,
            sphere: (add(centre, origin), tight),
            method,
            cells,
            unsquared: None,
        })
    }

    /// The same surface (the same circles, oriented as they are) intersected by another
    /// method.
    pub fn with_method(&self, method: Method) -> Result<Self, SurfaceError> {
        let cells = Self::cells(&self.family.circles, method)?;
        Ok(EvolvedSurface { family: self.family.clone(), method, cells, unsquared: None, ..*self })
    }

    /// The culling cells, for the methods that cull with them.
    fn cells(circles: &C, method: Method) -> Result<Option<Cells>, SurfaceError> {
        method.cells().map(|count| Cells::new(circles, count)).transpose()
    }

    /// The surface deciding most rays on the hybrid method's cells by `unsquared`, the
    /// crossing condition unsquared (built by the families that have one: a spline's
    /// segments), without the polynomial.
    pub(crate) fn with_unsquared(self, unsquared: Option<Unsquared<f64>>) -> Self {
        EvolvedSurface { unsquared: unsquared.map(Box::new), ..self }
    }

    /// The bounding sphere `(centre, radius)` in world coordinates.
    pub fn bounds(&self) -> (E3, f64) {
        self.sphere
    }

    /// The radius of a sphere about the frame's origin that bounds the surface.
    pub fn frame_radius(&self) -> f64 {
        self.radius
    }

    /// The local frame's origin, in world coordinates.
    pub fn origin(&self) -> E3 {
        self.origin
    }

    /// The circles' root finders, in the local frame.
    pub fn circles(&self) -> &Family<f64, C> {
        &self.family
    }

    /// The method in use.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The ray moved to the local frame, if it can reach the bounding sphere in
    /// `(t_min, t_max)`.
    pub fn local_ray<L>(&self, ray: &Ray<L>, t_min: f64, t_max: f64) -> Option<Ray> {
        let (centre, radius) = self.sphere;
        if !crosses(ray, centre, radius, t_min, t_max) {
            return None;
        }
        let o = sub(ray.origin, self.origin);
        Some(Ray { origin: o, dir: ray.dir, carrier: Line::from_point_unit_direction(o, ray.dir) })
    }

    /// Candidate α for a ray in the local frame: what the method's root finder returns over
    /// the α-intervals it reaches, in increasing α per interval.
    pub fn candidates(&self, local: &Ray, t_min: f64, t_max: f64) -> Roots<f64> {
        let (mut placed, rest) = self.candidates_placed(local, t_min, t_max);
        placed.extend(rest);
        placed
    }

    /// [`EvolvedSurface::candidates`] in two lists: those already placed on `f` to rounding
    /// (the unsquared condition's), and the rest (a polynomial's, or samples), which the
    /// crossing kept refines on `f`.
    fn candidates_placed(&self, local: &Ray, t_min: f64, t_max: f64) -> (Roots<f64>, Roots<f64>) {
        match &self.cells {
            Some(cells) => {
                let (intervals, ends) = cells.reach(local, t_min, t_max);
                self.candidates_on(local, (t_min, t_max), &intervals, &ends, None)
            }
            None => {
                let mut out = Roots::new();
                self.family.roots(&local.carrier, self.method.finder(1), 0.0, 1.0, &mut out);
                (Roots::new(), out)
            }
        }
    }

    /// [`EvolvedSurface::candidates_placed`] on the cells' `intervals` a ray reaches, `ends`
    /// marking those whose crossings can lie outside the window; with the ray's `N` and `D`
    /// where they are at hand ([`EvolvedSurface::prepare`]).
    fn candidates_on(
        &self,
        local: &Ray,
        (t_min, t_max): (f64, f64),
        intervals: &Intervals,
        ends: &[u64],
        numerators: Option<&Numerators<f64>>,
    ) -> (Roots<f64>, Roots<f64>) {
        let (mut placed, mut out) = (Roots::new(), Roots::new());
        let line = &local.carrier;
        if let (Some(unsquared), Finder::Polynomial(tolerance)) = (&self.unsquared, self.method.finder(1)) {
            // Most intervals are decided without the squared polynomial; it is built (once)
            // for the rest.
            let window = Window { origin: local.origin, dir: local.dir, t_min, t_max, ends, any: false };
            let (undecided, _) = match numerators {
                Some(n) => unsquared.roots_prepared(n, line, Some(&window), intervals, &mut placed, |_| false),
                None => unsquared.roots_until(line, Some(&window), intervals, &mut placed, |_| false),
            };
            if !undecided.is_empty() {
                self.family.roots_on(line, tolerance, undecided.iter().map(|&(lo, hi, _)| (lo, hi)), &mut out);
            }
        } else if let (true, Finder::Polynomial(tolerance)) = (C::HIGH_DEGREE, self.method.finder(1)) {
            // A high-degree polynomial (a spline segment's) is built once and restricted to
            // each interval: cheaper than building it on each.
            self.family.roots_on(line, tolerance, intervals.iter().map(|&(lo, hi, _)| (lo, hi)), &mut out);
        } else {
            for &(lo, hi, leaves) in intervals {
                self.family.roots(line, self.method.finder(leaves), lo, hi, &mut out);
            }
        }
        (placed, out)
    }

    /// The nearest crossing with `t_min < t < t_max` of a local ray among candidates: those
    /// placed are verified as they are, the others' kept crossing is refined.
    fn nearest_of(
        &self,
        local: &Ray,
        t_min: f64,
        t_max: f64,
        (placed, alphas): (Roots<f64>, Roots<f64>),
    ) -> Option<Crossing> {
        let polish = self.method.finder(1).polishes();
        let ray = (local.origin, local.dir, &local.carrier);
        let first = self.family.nearest(ray, &placed, t_min, t_max, false);
        let t_max = first.map_or(t_max, |(t, _, _)| t);
        let (t, x, alpha) = self.family.nearest(ray, &alphas, t_min, t_max, polish).or(first)?;
        Some(Crossing { t, point: add(x, self.origin), alpha: Some(alpha), part: 0 })
    }

    /// The nearest crossing with `t_min < t < t_max`. Only the ray's origin and direction
    /// are read: the surface builds its line in its own frame, so every back end shares this.
    pub fn intersect<L>(&self, ray: &Ray<L>, t_min: f64, t_max: f64) -> Option<Crossing> {
        self.intersect_local(&self.local_ray(ray, t_min, t_max)?, t_min, t_max)
    }

    /// [`EvolvedSurface::intersect`] for a ray already in the local frame (surfaces sharing a
    /// frame, the segments of a spline, build it once).
    pub fn intersect_local(&self, local: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        self.nearest_of(local, t_min, t_max, self.candidates_placed(local, t_min, t_max))
    }

    /// Whether its crossings are found unsquared on its cells ([`Unsquared`]).
    pub(super) fn solves_unsquared(&self) -> bool {
        self.unsquared.is_some()
    }

    /// The ray's `N` and `D` over the segment, where its crossings are found unsquared: what
    /// [`EvolvedSurface::intersect_cell`] and [`EvolvedSurface::occludes_cell`] share across
    /// the cells of one ray.
    pub(super) fn prepare(&self, local: &Ray) -> Option<Numerators<f64>> {
        self.unsquared.as_ref().map(|u| u.prepare(&local.carrier))
    }

    /// Cell `cell` of the method's cells alone, for the cells a spline's patches lead a ray
    /// to, with its one interval and mark.
    fn one_cell(&self, local: &Ray, cell: usize, (t_min, t_max): (f64, f64)) -> Option<(Intervals, CellBits)> {
        let cells = self.cells.as_ref()?;
        let count = cells.count() as f64;
        let mut ends = CellBits::from_elem(0, cell / 64 + 1);
        if cells.beyond(local, cell, t_min, t_max) {
            ends[cell / 64] |= 1 << (cell % 64);
        }
        let mut intervals = Intervals::new();
        intervals.push((cell as f64 / count, (cell + 1) as f64 / count, 1));
        Some((intervals, ends))
    }

    /// [`EvolvedSurface::intersect_local`] on one of the method's cells (`None` for a method
    /// without cells), with the ray's `N` and `D` from [`EvolvedSurface::prepare`].
    pub(super) fn intersect_cell(
        &self,
        local: &Ray,
        cell: usize,
        (t_min, t_max): (f64, f64),
        numerators: Option<&Numerators<f64>>,
    ) -> Option<Crossing> {
        let (intervals, ends) = self.one_cell(local, cell, (t_min, t_max))?;
        let candidates = self.candidates_on(local, (t_min, t_max), &intervals, &ends, numerators);
        self.nearest_of(local, t_min, t_max, candidates)
    }

    /// Whether the surface crosses the ray with `t_min < t < t_max` (a shadow ray's test):
    /// [`EvolvedSurface::intersect`]`.is_some()`, but where the unsquared condition decides,
    /// interval by interval, stopping at the first crossing verified.
    pub fn occludes<L>(&self, ray: &Ray<L>, t_min: f64, t_max: f64) -> bool {
        self.local_ray(ray, t_min, t_max).is_some_and(|local| self.occludes_local(&local, t_min, t_max))
    }

    /// [`EvolvedSurface::occludes`] for a ray already in the local frame.
    pub fn occludes_local(&self, local: &Ray, t_min: f64, t_max: f64) -> bool {
        match (&self.cells, &self.unsquared, self.method.finder(1)) {
            (Some(cells), Some(unsquared), Finder::Polynomial(tolerance)) => {
                let (intervals, ends) = cells.reach(local, t_min, t_max);
                self.occludes_on(unsquared, tolerance, local, (t_min, t_max), (&intervals, &ends), None)
            }
            _ => self.intersect_local(local, t_min, t_max).is_some(),
        }
    }

    /// [`EvolvedSurface::occludes_local`] on one of the method's cells.
    pub(super) fn occludes_cell(
        &self,
        local: &Ray,
        cell: usize,
        (t_min, t_max): (f64, f64),
        numerators: Option<&Numerators<f64>>,
    ) -> bool {
        match (self.one_cell(local, cell, (t_min, t_max)), &self.unsquared, self.method.finder(1)) {
            (Some((intervals, ends)), Some(unsquared), Finder::Polynomial(tolerance)) => {
                self.occludes_on(unsquared, tolerance, local, (t_min, t_max), (&intervals, &ends), numerators)
            }
            _ => self.intersect_cell(local, cell, (t_min, t_max), numerators).is_some(),
        }
    }

    /// [`EvolvedSurface::occludes_local`] on the cells' `intervals` (`ends` marking those whose
    /// crossings can lie outside the window), by `unsquared` interval by interval until a
    /// crossing is verified, and by the polynomial (refined to `tolerance`) on what it leaves
    /// undecided.
    fn occludes_on(
        &self,
        unsquared: &Unsquared<f64>,
        tolerance: f64,
        local: &Ray,
        (t_min, t_max): (f64, f64),
        (intervals, ends): (&Intervals, &[u64]),
        numerators: Option<&Numerators<f64>>,
    ) -> bool {
        let ray = (local.origin, local.dir, &local.carrier);
        let mut placed = Roots::new();
        let mut found = false;
        let window = Window { origin: local.origin, dir: local.dir, t_min, t_max, ends, any: true };
        let stop = |roots: &[f64]| {
            found = self.family.nearest(ray, roots, t_min, t_max, false).is_some();
            found
        };
        let (undecided, within) = match numerators {
            Some(n) => unsquared.roots_prepared(n, &local.carrier, Some(&window), intervals, &mut placed, stop),
            None => unsquared.roots_until(&local.carrier, Some(&window), intervals, &mut placed, stop),
        };
        if within || found || undecided.is_empty() {
            return within || found;
        }
        let mut out = Roots::new();
        self.family.roots_on(&local.carrier, tolerance, undecided.iter().map(|&(lo, hi, _)| (lo, hi)), &mut out);
        self.family.nearest(ray, &out, t_min, t_max, self.method.finder(1).polishes()).is_some()
    }

    /// The unit normal at a crossing (eq. 6–11, sign not yet turned to the ray). Where the
    /// circles do not move (`Ẋ = 0`, so `N = 0`) the surface has no normal of its own; the
    /// circle's outward radial direction is used there.
    pub fn normal(&self, crossing: &Crossing) -> E3 {
        let x = sub(crossing.point, self.origin);
        let alpha = crossing.alpha.unwrap_or(0.0);
        let circles = &self.family.circles;
        // The crossing was verified on C_α to the surface's own tolerance (1e-6 r), and the
        // circles built in a local frame: eq. 6–11 directly, without `Pair::normal`'s checks
        // for arbitrary callers (which would refuse points that far off the circle).
        let parts = circles.at_dual(Dual::variable(alpha)).ok().map(|c| {
            let (circle, circle_dot) = Circle::split(c);
            NormalParts::new(circle, circle_dot, x)
        });
        (parts.and_then(|p| p.normal_line.direction().ok()))
            .or_else(|| {
                let (c, _, _) = circles.at(alpha).ok()?.centre_normal_radius().ok()?;
                cga_core::euclid::unit(sub(x, c))
            })
            .unwrap_or([0.0, 0.0, 1.0])
    }
}

impl<C: Circles<f64> + Send + Sync + 'static> Shape for EvolvedSurface<C> {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        EvolvedSurface::intersect(self, ray, t_min, t_max)
    }

    fn occludes(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        EvolvedSurface::occludes(self, ray, t_min, t_max)
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        facing(EvolvedSurface::normal(self, crossing), ray.dir)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        Some(EvolvedSurface::bounds(self))
    }

    fn crossing_error(&self) -> f64 {
        super::swept_error(self.origin, self.radius)
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        self.family.circles.curvature(crossing.alpha?, sub(crossing.point, self.origin))
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], crate::shapes::Unit)> {
        let (family, origin) = (&self.family.circles, self.origin);
        let circle = family.at(crossing.alpha?).ok()?.centre_normal_radius().ok()?;
        super::swept_uv(crossing, (add(circle.0, origin), circle.1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::BezierSegment;
    use cga_core::euclid::{perpendicular, scale};
    use cga_core::{Joining, Spline};

    /// Every point of every circle lies within the surface's bounding sphere: the farthest
    /// point from its centre of 20,000 random `C_α` (not the samples the bound was built from)
    /// of a twisted pair of circles and of each segment of a Catmull–Rom spline off the frame's
    /// origin (a bound 5 % smaller fails).
    #[test]
    fn the_bounding_sphere_holds_every_circle() {
        let circle = |c, n, r| Circle::from_centre_normal_radius(c, n, r).unwrap();
        let pair = EvolvedSurface::new(
            circle([5.0, 1.0, 0.0], [0.0, 0.0, 1.0], 1.0),
            circle([5.3, 1.0, 1.5], [1.0, 0.2, 0.3], 0.6),
            Method::default(),
        )
        .unwrap();
        let controls = [
            circle([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0),
            circle([1.2, 0.0, 1.8], [0.4, 0.0, 1.0], 0.9),
            circle([-0.3, 0.3, 3.6], [-0.4, 0.2, 1.0], 1.7),
            circle([0.4, 0.0, 5.6], [0.0, 0.3, 1.0], 0.8),
        ];
        let spline = Spline::new(&controls, Joining::CATMULL_ROM).unwrap();
        let origin = [0.1, -0.2, 2.5];
        let segments: Vec<EvolvedSurface<BezierSegment<f64>>> = (0..spline.segments())
            .map(|j| {
                let local: Vec<Circle> = (spline.segment(j).iter())
                    .map(|c| Translator::from_vector(origin.map(|x| -x)).sandwich(*c))
                    .collect();
                EvolvedSurface::of(origin, BezierSegment::new(&local), Method::default()).unwrap()
            })
            .collect();
        let mut random = crate::hash::stream(0x9e37_79b9_7f4a_7c15);
        let mut check = |at: &dyn Fn(f64) -> (E3, E3, f64), (centre, radius): (E3, f64), origin: E3| {
            for _ in 0..20_000 {
                let (c, n, r) = at(random());
                // The circle's point farthest from the sphere's centre.
                let w = sub(add(c, origin), centre);
                let across = sub(w, scale(n, dot(w, n)));
                let out = if norm(across) > 0.0 { scale(across, 1.0 / norm(across)) } else { perpendicular(n) };
                let x = add(add(c, origin), scale(out, r));
                assert!(norm(sub(x, centre)) <= radius, "{x:?} outside ({centre:?}, {radius})");
            }
        };
        let (family, o) = pair.family();
        check(&|a| family.circles.at(a).unwrap().centre_normal_radius().unwrap(), pair.bounds(), o);
        for s in &segments {
            check(&|a| s.circles().circles.at(a).unwrap().centre_normal_radius().unwrap(), s.bounds(), s.origin());
        }
    }
}
