//! Rays: a Euclidean origin and unit direction for ordering hits, and what a back end meets
//! objects with — the CGA line they lie on for the CGA back ends.

use cga_core::Line;
use cga_core::euclid::{E3, add, dot, reflect, scale, sub, tolerance, unit};
use cga_core::{Real, Select};

/// A ray `o + t d`, `t > 0`, met by its `carrier`: by default the normalised CGA line from `o`
/// along `d` (the dense back end carries a dense multivector, the plain one nothing).
#[derive(Clone, Copy, Debug)]
pub struct Ray<C = Line> {
    /// Where the ray starts.
    pub origin: E3,
    /// Unit direction.
    pub dir: E3,
    /// The carrier: `up(o) ∧ up(o + d) ∧ ei`, normalised, for the CGA back ends.
    pub carrier: C,
}

impl Ray {
    /// The ray from `origin` along `dir`; `None` for a zero or non-finite direction.
    pub fn new(origin: E3, dir: E3) -> Option<Self> {
        let dir = unit(dir)?;
        origin.iter().all(|x| x.is_finite()).then(|| Ray {
            origin,
            dir,
            carrier: Line::from_point_unit_direction(origin, dir),
        })
    }

    /// The ray from `origin` along `dir`, which the caller knows to be a unit vector and
    /// finite (reflected and light directions): not normalised again.
    pub fn unit(origin: E3, dir: E3) -> Self {
        Ray { origin, dir, carrier: Line::from_point_unit_direction(origin, dir) }
    }

    /// A secondary ray leaving a surface point `x` with unit normal `n` along `dir`, starting
    /// `offset` off the surface ([`leaving_origin`], [`offset`]).
    pub fn leaving(x: E3, n: E3, dir: E3, offset: f64) -> Option<Self> {
        Ray::new(leaving_origin(x, n, dot(n, dir), offset), dir)
    }

    /// The ray from `origin` along the normalised line `line` (which must pass through it).
    pub fn from_line(origin: E3, line: Line) -> Option<Self> {
        Some(Ray { origin, dir: line.direction().ok()?, carrier: line })
    }
}

impl<C> Ray<C> {
    /// `o + t d`.
    pub fn at(&self, t: f64) -> E3 {
        add(self.origin, scale(self.dir, t))
    }

    /// The parameter of a point on the ray, `(x − o) · d`.
    pub fn t_of(&self, x: E3) -> f64 {
        dot(sub(x, self.origin), self.dir)
    }
}

/// Whether the ray parameter `t` lies in the open range `(t_min, t_max)` a ray is searched
/// over: the one test of whether a crossing counts, for every shape, back end and lane
/// ([`Select`]: a `bool` for one ray, a mask for a packet).
#[inline(always)]
pub fn in_range<T: Select>(t: T, t_min: T, t_max: T) -> T::Mask {
    t_min.lt(t) & t.lt(t_max)
}

/// How far off a surface a secondary ray starts when it leaves the crossing `x` of a ray from
/// `origin` with a shape whose crossings lie within `error` of it
/// ([`Shape::crossing_error`](crate::shapes::Shape::crossing_error)): four times that error and
/// the rounding of the coordinates that located the crossing, `64 ε (|x|∞ + |o|∞)`. Every
/// term is the hit's own size, so the same picture comes out at any scale and anywhere in
/// the frame; no global unit enters. Generic, so that a point and a packet's four points
/// (lanes) take the same operations.
#[inline(always)]
pub fn offset<T: Real>(x: E3<T>, origin: E3<T>, error: T) -> T {
    let largest = |v: E3<T>| v.iter().fold(T::zero(), |m, c| m.max(c.abs()));
    T::from_f64(4.0) * (error + tolerance(largest(x) + largest(origin)))
}

/// Where a secondary ray leaving a surface point `x` (unit normal `n`) along a direction `d`
/// starts, `n_dir` being `n · d`: `offset` off the surface on the side it leaves to
/// ([`offset`]), so that rounding in the hit point cannot make it meet the surface it starts
/// on. Lane by lane for a packet ([`Select`]): one ray and four take the same steps.
#[inline(always)]
pub fn leaving_origin<T: Select>(x: E3<T>, n: E3<T>, n_dir: T, offset: T) -> E3<T> {
    let side = T::select(T::zero().le(n_dir), T::one(), -T::one());
    add(x, scale(n, side * offset))
}

/// The mirror bounce of a ray of direction `dir` from `origin` at its hit `x` (unit normal
/// `n`) on an object of crossing error `error`: the reflected direction `r = d − 2(d·n)n` and
/// where the bounce starts, [`leaving_origin`] off the surface by [`offset`]. Lane by lane
/// for a packet ([`Select`]): one ray and four take the same steps.
#[inline(always)]
pub fn mirror<T: Select>(dir: E3<T>, origin: E3<T>, x: E3<T>, n: E3<T>, error: T) -> (E3<T>, E3<T>) {
    let r = reflect(dir, n);
    (leaving_origin(x, n, dot(n, r), offset(x, origin, error)), r)
}

/// Whether the ray passes through the sphere `(centre, radius)` within `(t_min, t_max)`.
pub fn crosses<C>(ray: &Ray<C>, centre: E3, radius: f64, t_min: f64, t_max: f64) -> bool {
    let oc = sub(ray.origin, centre);
    let tc = -dot(oc, ray.dir);
    let miss = add(oc, scale(ray.dir, tc));
    dot(miss, miss) <= radius * radius && tc + radius > t_min && tc - radius < t_max
}
