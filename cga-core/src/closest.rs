//! The closest points of a circle and a line, and of two circles (clifford.tools.g3c's
//! `closest_point_on_circle_from_line`, `iterative_closest_points_circle_line` and
//! `iterative_closest_points_on_circles`), in Euclidean terms and to rounding.
//!
//! The circle of centre `c`, unit normal `n` and radius `r` is `x(θ) = c + r (cos θ u +
//! sin θ v)` for an orthonormal `u, v` across `n`; the squared distance `f(θ)` of `x(θ)` from
//! the other object is minimised over `θ`:
//! - from a line through `p` along unit `d`: `f = |(x − p) × d|²`, a trigonometric
//!   polynomial of degree 2 in `θ` (at most two local minima);
//! - from a circle of centre `c₂`, unit normal `n₂` and radius `r₂`: `f = h² + (ρ − r₂)²`,
//!   `h = (x − c₂)·n₂` the height over its plane and `ρ` the distance from its axis.
//!
//! `f` is sampled at 128 angles; about every sampled local minimum the root of `f′` (exact,
//! on [`Dual`] numbers) is bracketed between the neighbouring samples and bisected to
//! rounding, and the least of those minima is the answer: the global minimum, whatever the
//! configuration (an iteration from one start, as clifford's, can stop in the other
//! minimum). The other closest point is the nearest point of the other object to `x(θ)`.
//!
//! Where the minimum is not unique — a line along the circle's axis, coaxial circles (every
//! point of one at the same distance from the other), or a point of one circle on the
//! other's axis at the minimum — [`Closest::parallel`] is set and the points are one
//! closest pair of many. Where two or more isolated pairs tie (a line crossing the circle
//! twice) one of them is returned.
//!
//! Against clifford 1.5.1 (tests/tests/geometry/clifford_tools.rs, 40 random cases each plus
//! special ones): `closest_point_on_circle_from_line` (Aristidou's construction) is not the
//! closest point on 22 of 40; `iterative_closest_points_circle_line` is right where it
//! answers but raises (`No root exists`) on 4; `iterative_closest_points_on_circles` stops in
//! another minimum on 4, returns points off the circles on 5 (up to 3e-2), and raises
//! (`UnboundLocalError`) on the symmetric pair of docs/COOKBOOK.md. Ours is checked against
//! a Euclidean brute force on all of them.

use crate::conformal::Result;
use crate::euclid::{E3, add, cross, dot, norm, perpendicular, scale, sub};
use crate::measure::{Closest, Nearest as _, distance};
use crate::{Circle, Dual, Line, Real};

/// Samples of `θ` over the full turn.
const SAMPLES: usize = 128;

/// A circle as `(c, u, v, r)`: `x(θ) = c + r (cos θ u + sin θ v)`.
struct Param<T> {
    c: E3<T>,
    u: E3<T>,
    v: E3<T>,
    r: T,
}

impl<T: Real> Param<T> {
    fn of(circle: &Circle<T>) -> Result<Self> {
        let (c, n, r) = circle.centre_normal_radius()?;
        let u = perpendicular(n);
        Ok(Param { c, u, v: cross(n, u), r })
    }

    /// `x(θ) − o` for a point `o`, on any scalar (dual numbers for the derivative).
    fn offset<S: Real>(&self, theta: S, o: E3<T>, lift: impl Fn(T) -> S) -> E3<S> {
        let (cos, sin) = (theta.cos(), theta.sin());
        [0, 1, 2].map(|k| lift(self.c[k] - o[k]) + lift(self.r) * (cos * lift(self.u[k]) + sin * lift(self.v[k])))
    }

    fn at(&self, theta: T) -> E3<T> {
        add(self.c, scale(add(scale(self.u, theta.cos()), scale(self.v, theta.sin())), self.r))
    }
}

/// The `θ` minimising `f` over the full turn, and whether `f` is constant there (to
/// `tol`): every sampled local minimum refined by bisecting `f′` between its neighbours.
fn minimise<T: Real>(f: impl Fn(Dual<T>) -> Dual<T>, tol: T) -> (T, bool) {
    let h = T::from_f64(core::f64::consts::TAU / SAMPLES as f64);
    let angle = |k: usize| T::from_f64(k as f64) * h;
    let value = |t: T| f(Dual::constant(t)).re;
    let slope = |t: T| f(Dual::variable(t)).du;
    let samples: [T; SAMPLES] = core::array::from_fn(|k| value(angle(k)));
    let (mut lo, mut hi) = (samples[0], samples[0]);
    for &s in &samples {
        lo = if s < lo { s } else { lo };
        hi = if s > hi { s } else { hi };
    }
    let flat = hi - lo <= tol;
    let (mut best, mut best_value) = (T::zero(), samples[0]);
    for k in 0..SAMPLES {
        let (before, after) = (samples[(k + SAMPLES - 1) % SAMPLES], samples[(k + 1) % SAMPLES]);
        if !(samples[k] <= before && samples[k] <= after) {
            continue;
        }
        let mut t = angle(k);
        let (mut a, mut b) = (t - h, t + h);
        if slope(a) < T::zero() && slope(b) > T::zero() {
            for _ in 0..200 {
                let m = (a + b) * T::from_f64(0.5);
                if !(m > a && m < b) {
                    break;
                }
                if slope(m) < T::zero() { a = m } else { b = m }
            }
            t = (a + b) * T::from_f64(0.5);
        }
        let v = value(t);
        let (t, v) = if v <= samples[k] { (t, v) } else { (angle(k), samples[k]) };
        if v < best_value {
            (best, best_value) = (t, v);
        }
    }
    (best, flat)
}

/// The tolerance on a squared distance among lengths of size `s`: `1024 ε s²`.
fn flat_tolerance<T: Real>(s: T) -> T {
    T::from_f64(1024.0) * T::epsilon() * s * s
}

impl<T: Real> Circle<T> {
    /// The closest points of this circle and a line (on the circle first), and their
    /// distance: the `θ` minimising `f(θ) = |(x(θ) − p) × d|²` (see the [module](self)), and
    /// the foot of `x(θ)` on the line. `parallel` is set for a line along the circle's axis,
    /// where every point of the circle is closest. The read-backs' errors for degenerate
    /// objects.
    ///
    /// ```
    /// use cga_core::{Circle, Line};
    /// let ring: Circle = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0)?;
    /// let above = Line::new([3.0, 0.0, 2.0], [0.0, 1.0, 0.0])?; // over the plane, along y
    /// let k = ring.closest_points_to_line(&above)?;
    /// assert!((k.on_self[0] - 1.0).abs() < 1e-15 && (k.distance - 8f64.sqrt()).abs() < 1e-15);
    /// # Ok::<(), cga_core::GeometryError>(())
    /// ```
    pub fn closest_points_to_line(&self, line: &Line<T>) -> Result<Closest<T>> {
        let circle = Param::of(self)?;
        let (p, d) = (line.point()?, line.direction()?);
        let size = norm(sub(circle.c, p)) + circle.r;
        let f = |t: Dual<T>| {
            let w = circle.offset(t, p, Dual::constant);
            let x = cross(w, d.map(Dual::constant));
            dot(x, x)
        };
        let (theta, flat) = minimise(f, flat_tolerance(size));
        let on_self = circle.at(theta);
        let on_other = line.nearest_point(on_self)?;
        Ok(Closest { on_self, on_other, distance: distance(on_self, on_other), parallel: flat })
    }

    /// The closest points of two circles (on this one first) and their distance: the `θ`
    /// minimising `f(θ) = h² + (ρ − r₂)²` (see the [module](self)), and the nearest point of
    /// the other circle to `x(θ)`. `parallel` is set where the closest pair is not unique
    /// (coaxial circles; a closest point on the other's axis). The read-backs' errors for
    /// degenerate objects.
    ///
    /// ```
    /// use cga_core::Circle;
    /// let a: Circle = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0)?;
    /// let b = Circle::new([3.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0)?; // upright, beside it
    /// let k = a.closest_points_to_circle(&b)?;
    /// assert!((k.on_self[0] - 1.0).abs() < 1e-15 && (k.on_other[0] - 2.0).abs() < 1e-15);
    /// assert!((k.distance - 1.0).abs() < 1e-15);
    /// # Ok::<(), cga_core::GeometryError>(())
    /// ```
    pub fn closest_points_to_circle(&self, other: &Circle<T>) -> Result<Closest<T>> {
        let circle = Param::of(self)?;
        let (c2, n2, r2) = other.centre_normal_radius()?;
        let size = norm(sub(circle.c, c2)) + circle.r + r2;
        let f = |t: Dual<T>| {
            let y = circle.offset(t, c2, Dual::constant);
            let h = dot(y, n2.map(Dual::constant));
            let across = sub(y, scale(n2.map(Dual::constant), h));
            let rho = dot(across, across).sqrt();
            h * h + (rho - Dual::constant(r2)) * (rho - Dual::constant(r2))
        };
        let (theta, flat) = minimise(f, flat_tolerance(size));
        let on_self = circle.at(theta);
        let y = sub(on_self, c2);
        let across = sub(y, scale(n2, dot(y, n2)));
        let rho = norm(across);
        let (direction, on_axis) = if rho > crate::euclid::tolerance(size) {
            (scale(across, T::one() / rho), false)
        } else {
            (perpendicular(n2), true)
        };
        let on_other = add(c2, scale(direction, r2));
        Ok(Closest { on_self, on_other, distance: distance(on_self, on_other), parallel: flat || on_axis })
    }
}

impl<T: Real> Line<T> {
    /// [`Circle::closest_points_to_line`] from the line's side: the point on the line first.
    pub fn closest_points_to_circle(&self, circle: &Circle<T>) -> Result<Closest<T>> {
        let k = circle.closest_points_to_line(self)?;
        Ok(Closest { on_self: k.on_other, on_other: k.on_self, ..k })
    }
}
