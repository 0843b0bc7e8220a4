//! Dense references for swept surfaces, written apart from the root finders they check:
//! samples of `f(α) = (C_α ∨ L)²` over the whole surface for evolved and spline surfaces (across
//! the knots, so that a root at a knot is a sign change), of the Plücker form of the ray and
//! the interpolated ruling for ruled ones; sign changes bisected to rounding.

use cga_core::euclid::{E3, circle_distance, dot, norm, sub, unit};
use cga_core::{Circle, Dual, InterpolationError, Line, Spline, ei};
use cga_trace::ray::Ray;
use cga_trace::shapes::{Crossing, Shape};
use cga_trace::surface::bernstein::Bernstein;
use cga_trace::surface::{Circles, EvolvedSurface, Method, RuledSurface, Rulings, SplineSurface};

/// The whole spline as one family over the global α: dense samples run across the knots.
#[derive(Clone, Debug)]
pub struct Whole(pub Spline<Circle>);

impl Circles<f64> for Whole {
    type Polynomial = Bernstein<f64>;
    fn at(&self, alpha: f64) -> Result<Circle, InterpolationError> {
        self.0.at(alpha)
    }
    fn at_dual(&self, alpha: Dual<f64>) -> Result<Circle<Dual<f64>>, InterpolationError> {
        let (c, d) = self.0.with_derivative(alpha.re)?;
        let (c, d) = (c.to_array(), d.to_array());
        Ok(Circle::from_array(std::array::from_fn(|k| Dual { re: c[k], du: d[k] * alpha.du })))
    }
    /// Not used: the reference samples.
    fn polynomial(&self, _: &Line) -> Bernstein<f64> {
        Bernstein::new(&[1.0])
    }
}

/// The ruling at α in the local frame: a point, a unit direction, the range along it.
pub fn ruling(surface: &RuledSurface, alpha: f64) -> Option<(Line, E3, E3, (f64, f64))> {
    match surface.rulings() {
        Rulings::PointPairs(pair) => {
            let b = pair.at(alpha).ok()?;
            let [p, q] = b.end_points().ok()?;
            Some(((b ^ ei()).try_normalise()?, p, unit(sub(q, p))?, (0.0, norm(sub(q, p)))))
        }
        Rulings::Lines { pair, bound } => {
            let l = pair.at(alpha).ok()?;
            let (p, d) = (l.point().ok()?, l.direction().ok()?);
            let pc = sub(p, bound.0);
            let (b, c) = (dot(pc, d), dot(pc, pc) - bound.1 * bound.1);
            let disc = b * b - c;
            (disc > 0.0).then(|| (l, p, d, (-b - disc.sqrt(), -b + disc.sqrt())))
        }
    }
}

/// The ray's closest approach to the ruling at α: `(t along the ray, s along the ruling,
/// distance)`, and whether `s` lies within the ruling's range.
fn approach(surface: &RuledSurface, o: E3, d: E3, alpha: f64) -> Option<(f64, f64, bool)> {
    let (_, p, u, (s0, s1)) = ruling(surface, alpha)?;
    let w0 = sub(o, p);
    let (b, dd, e) = (dot(d, u), dot(d, w0), dot(u, w0));
    let den = 1.0 - b * b;
    let (t, s) = ((b * e - dd) / den, (e - b * dd) / den);
    let x = cga_core::euclid::add(o, cga_core::euclid::scale(d, t));
    let y = cga_core::euclid::add(p, cga_core::euclid::scale(u, s));
    Some((t, norm(sub(x, y)), s >= s0 && s <= s1))
}

/// The reference for a ruled surface: the Plücker form sampled at `n` points, sign changes
/// bisected to rounding, each root's closest approach kept if within the ruling's range and
/// `t_min < t < t_max`: the nearest `(t, α)`.
pub fn ruled_reference(surface: &RuledSurface, ray: &Ray, n: usize, t_min: f64, t_max: f64) -> Option<(f64, f64)> {
    let o = sub(ray.origin, surface.origin());
    let line = Line::from_point_unit_direction(o, ray.dir);
    let f = |alpha: f64| ruling(surface, alpha).map(|(l, ..)| (line * l).e123i);
    let mut best: Option<(f64, f64)> = None;
    let mut prev = (0.0, f(0.0));
    for k in 1..=n {
        let alpha = k as f64 / n as f64;
        let cur = (alpha, f(alpha));
        if let (Some(a), Some(b)) = (prev.1, cur.1)
            && (a > 0.0) != (b > 0.0)
        {
            let (mut lo, mut hi, f_lo) = (prev.0, cur.0, a);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                match f(mid) {
                    Some(v) if (v > 0.0) == (f_lo > 0.0) => lo = mid,
                    _ => hi = mid,
                }
            }
            let alpha = 0.5 * (lo + hi);
            if let Some((t, _, true)) = approach(surface, o, ray.dir, alpha)
                && t > t_min
                && t < t_max
                && best.is_none_or(|x| t < x.0)
            {
                best = Some((t, alpha));
            }
        }
        prev = cur;
    }
    best
}

/// A swept surface of a scene, by kind.
#[derive(Clone, Copy)]
pub enum Swept<'a> {
    Evolved(&'a EvolvedSurface),
    Spline(&'a SplineSurface),
    Ruled(&'a RuledSurface),
}

/// One way of intersecting a swept surface: its name and the shape.
pub type Variant = (String, Box<dyn Shape>);

impl<'a> Swept<'a> {
    /// The swept surface a scene object's shape is, if it is one.
    pub fn of(shape: &'a dyn Shape) -> Option<Self> {
        (shape.downcast_ref::<EvolvedSurface>().map(Swept::Evolved))
            .or_else(|| shape.downcast_ref::<SplineSurface>().map(Swept::Spline))
            .or_else(|| shape.downcast_ref::<RuledSurface>().map(Swept::Ruled))
    }

    /// What kind it is.
    pub fn kind(&self) -> &'static str {
        match self {
            Swept::Evolved(_) => "evolved",
            Swept::Spline(_) => "spline",
            Swept::Ruled(_) => "ruled",
        }
    }

    /// The shape itself.
    pub fn shape(&self) -> &'a dyn Shape {
        match *self {
            Swept::Evolved(s) => s,
            Swept::Spline(s) => s,
            Swept::Ruled(s) => s,
        }
    }

    /// The methods the docs call exact: the default and the plain polynomial (a ruled
    /// surface has one, its cubic or quartic).
    pub fn exact_methods(&self) -> Vec<Variant> {
        let exact = [("default", Method::default()), ("polynomial", Method::Polynomial { tolerance: 0.0 })];
        match *self {
            Swept::Evolved(s) => exact
                .iter()
                .map(|(n, m)| (n.to_string(), Box::new(s.with_method(*m).unwrap()) as Box<dyn Shape>))
                .collect(),
            Swept::Spline(s) => exact
                .iter()
                .map(|(n, m)| (n.to_string(), Box::new(s.with_method(*m).unwrap()) as Box<dyn Shape>))
                .collect(),
            Swept::Ruled(s) => vec![("polynomial".to_string(), Box::new(s.clone()) as Box<dyn Shape>)],
        }
    }

    /// The dense reference at `n` samples over the whole surface.
    pub fn reference(&self, n: usize) -> Reference<'a> {
        let sampling = Method::Sampling { samples: n };
        match *self {
            Swept::Evolved(s) => Reference::Family(Box::new(s.with_method(sampling).unwrap())),
            Swept::Spline(s) => Reference::Family(Box::new(
                EvolvedSurface::of(s.origin(), Whole(s.spline().clone()), sampling).unwrap(),
            )),
            Swept::Ruled(s) => Reference::Ruled(s, n),
        }
    }

    /// How far `x` (frame coordinates) lies from the surface's curve at α, relative to its
    /// size: in radii of `C_α`, or from the ruling within its range, in the bound's radius.
    pub fn off_curve(&self, alpha: f64, x: E3) -> f64 {
        let circle = |c: Result<Circle, InterpolationError>, origin: E3| {
            c.ok()
                .and_then(|c| c.centre_normal_radius().ok())
                .map_or(f64::INFINITY, |c| circle_distance(sub(x, origin), c))
        };
        match *self {
            Swept::Evolved(s) => circle(s.circles().at(alpha), s.origin()),
            Swept::Spline(s) => circle(s.spline().at(alpha), s.origin()),
            Swept::Ruled(s) => {
                let o = sub(x, s.origin());
                // The ruling's nearest point to x: the approach of a ray from x along any
                // direction is not it; project x on the ruling instead.
                ruling(s, alpha).map_or(f64::INFINITY, |(_, p, u, (s0, s1))| {
                    let along = dot(sub(o, p), u).clamp(s0, s1);
                    norm(sub(o, cga_core::euclid::add(p, cga_core::euclid::scale(u, along)))) / s.bounds().1
                })
            }
        }
    }
}

/// A dense reference, ready to intersect.
pub enum Reference<'a> {
    Family(Box<dyn Shape>),
    Ruled(&'a RuledSurface, usize),
}

impl Reference<'_> {
    /// The nearest crossing with `t_min < t < t_max`: `(t, α)`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64)> {
        match self {
            Reference::Family(s) => s.intersect(ray, t_min, t_max).map(|c: Crossing| (c.t, c.alpha.unwrap())),
            Reference::Ruled(s, n) => {
                let (centre, radius) = s.bounds();
                if !cga_trace::ray::crosses(ray, centre, radius, t_min, t_max) {
                    return None;
                }
                ruled_reference(s, ray, *n, t_min, t_max)
            }
        }
    }
}
