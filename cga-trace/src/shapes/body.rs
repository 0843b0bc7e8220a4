//! A solid bounded by several surfaces together: a swept surface and the disks that cap its
//! ends. Its crossing is the nearest of its parts' (tagged with the part, [`Crossing::part`]),
//! and where its line lies inside is read off all of its parts' crossings in turn, by
//! parity ([`spans_by_crossings`]): so it takes part in CSG and capped clips as any closed
//! shape does.

use super::csg::enclosing;
use super::{Crossing, Shape, Spans, spans_by_crossings};
use crate::ray::Ray;
use cga_core::euclid::E3;
use std::sync::Arc;

/// Surfaces that together bound a solid.
#[derive(Clone, Debug)]
pub struct Body {
    parts: Vec<Arc<dyn Shape>>,
    bounds: Option<(E3, f64)>,
    error: f64,
}

impl Body {
    /// The solid that `parts` bound together: the caller knows that they close one (a
    /// swept surface with both end disks); `None` for fewer than two parts or one without
    /// bounds.
    pub fn new(parts: Vec<Arc<dyn Shape>>) -> Option<Self> {
        if parts.len() < 2 || parts.len() > u32::MAX as usize {
            return None;
        }
        let bounds = enclosing(&parts.iter().map(|p| p.bounds()).collect::<Vec<_>>());
        let error = parts.iter().map(|p| p.crossing_error()).fold(0.0, f64::max);
        bounds.map(|b| Body { parts, bounds: Some(b), error })
    }

    /// Its parts, in order.
    pub fn parts(&self) -> &[Arc<dyn Shape>] {
        &self.parts
    }

    /// The part a crossing lies on, and the crossing as that part gave it.
    fn piece(&self, c: &Crossing) -> (&dyn Shape, Crossing) {
        let k = (c.part as usize).min(self.parts.len() - 1);
        (&*self.parts[k], Crossing { part: 0, ..*c })
    }
}

impl Shape for Body {
    /// The nearest of its parts' crossings.
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Crossing> {
        let mut best: Option<Crossing> = None;
        for (k, part) in self.parts.iter().enumerate() {
            let limit = best.map_or(t_max, |b| b.t);
            if let Some(c) = part.intersect(ray, t_min, limit) {
                best = Some(Crossing { part: k as u32, ..c });
            }
        }
        best
    }

    fn normal(&self, ray: &Ray, crossing: &Crossing) -> E3 {
        let (part, c) = self.piece(crossing);
        part.normal(ray, &c)
    }

    fn facet(&self, crossing: &Crossing) -> Option<E3> {
        let (part, c) = self.piece(crossing);
        part.facet(&c)
    }

    fn bounds(&self) -> Option<(E3, f64)> {
        self.bounds
    }

    /// The largest of its parts'.
    fn crossing_error(&self) -> f64 {
        self.error
    }

    fn cull(&self) -> bool {
        true
    }

    fn curvature(&self, crossing: &Crossing) -> Option<cga_core::Curvature> {
        let (part, c) = self.piece(crossing);
        part.curvature(&c)
    }

    fn uv(&self, crossing: &Crossing) -> Option<([f64; 2], super::Unit)> {
        let (part, c) = self.piece(crossing);
        part.uv(&c)
    }

    fn closed(&self) -> bool {
        true
    }

    fn spans(&self, ray: &Ray) -> Spans {
        spans_by_crossings(self, ray)
    }

    /// The part's own crossing nearest `t` within a few of its errors (with a swept
    /// surface's α), else the point at `t` on the first part.
    fn crossing_on(&self, ray: &Ray, t: f64) -> Crossing {
        let reach = 4.0 * self.error + 4.0 * f64::EPSILON * t.abs();
        let near = |k: usize, p: &Arc<dyn Shape>| {
            let c = p.intersect(ray, t - reach, t + reach)?;
            Some(Crossing { part: k as u32, ..c })
        };
        let found = self.parts.iter().enumerate().filter_map(|(k, p)| near(k, p));
        found.min_by(|a, b| (a.t - t).abs().total_cmp(&(b.t - t).abs())).unwrap_or(Crossing {
            t,
            point: ray.at(t),
            alpha: None,
            part: 0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::testing::{ray, stream};
    use crate::shapes::{ConeShape, DiskShape};
    use cga_core::euclid::{sub, unit};

    /// An open cone's side and its two end disks, as a body, bound the capped cone: the
    /// same spans on 2,000 random lines, and crossings that name the part they lie on.
    #[test]
    fn a_side_and_two_disks_bound_the_capped_cone() {
        let (p1, p2) = ([0.2, -0.1, -1.0], [0.0, 0.3, 1.2]);
        let axis = unit(sub(p2, p1)).unwrap();
        let side: Arc<dyn Shape> = Arc::new(ConeShape::new(p1, 1.0, p2, 0.6, false).unwrap());
        let ends: [Arc<dyn Shape>; 2] =
            [Arc::new(DiskShape::new(p1, axis, 1.0).unwrap()), Arc::new(DiskShape::new(p2, axis, 0.6).unwrap())];
        let body = Body::new(vec![side, ends[0].clone(), ends[1].clone()]).unwrap();
        let capped = ConeShape::new(p1, 1.0, p2, 0.6, true).unwrap();
        let mut random = stream(0x9e37_79b9_7f4a_7c15);
        let mut point = |s: f64| [0, 1, 2].map(|_| s * random());
        let mut hits = 0;
        for _ in 0..2_000 {
            let o = point(5.0);
            let r = ray(o, sub(point(1.2), o));
            let (got, want) = (body.spans(&r), capped.spans(&r));
            assert_eq!(got.len(), want.len(), "{got:?} {want:?}");
            for (g, w) in got.iter().zip(&want) {
                assert!((g.0 - w.0).abs() < 1e-9 && (g.1 - w.1).abs() < 1e-9, "{got:?} {want:?}");
            }
            if let Some(&(enter, _)) = got.first() {
                let c = body.crossing_on(&r, enter);
                let on_disk = |k: usize| ends[k].intersect(&r, enter - 1e-9, enter + 1e-9).is_some();
                assert!(c.part == 0 || on_disk(c.part as usize - 1), "{c:?}");
                hits += 1;
            }
        }
        assert!(hits > 500, "{hits}");
    }
}
