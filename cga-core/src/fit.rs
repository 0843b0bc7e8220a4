//! Objects fitted to points by least squares (clifford.tools.g3c's `fit_sphere`,
//! `fit_circle`, `fit_plane`, `fit_line`).
//!
//! The points are first moved to their centroid `m` and scaled by their RMS distance `s`
//! from it (`u = (x − m)/s`), so that the answer does not depend on where in space they lie
//! or how large they are; their scatter `S = mean(u uᵀ)` (trace 1) is diagonalised once.
//!
//! - A line runs through `m` along the largest axis of `S`; a plane through `m` across its
//!   smallest (total least squares: the sum of squared distances is least).
//! - A sphere is the algebraic (Kåsa) fit: the dual sphere `σ = up(c) − ½ r² ei` minimising
//!   `Σ (up(x) · σ)² = ¼ Σ (r² − |x − c|²)²`. It is linear in `c` and `k = r² − |c|²`, and about
//!   the centroid the normal equations split: `k = mean |u|² = 1` and `S c = ½ mean(u |u|²)`.
//! - A circle is that fit within the fitted plane (in its two in-plane axes).
//!
//! Points that do not hold the object are refused by name: fewer than it needs, all at one
//! place (`CoincidentPoints`), on a line where a plane or circle needs more
//! (`CollinearPoints`), on a plane where a sphere needs more (`CoplanarPoints`): an axis of
//! the scatter within rounding of zero, `λ ≤ 64 ε` of the trace. An input that is not finite
//! is `NonFinite`.
//!
//! Orientation: a plane's normal, a circle's normal and a line's direction are the unit axis
//! whose largest component (the first of equals) is positive.
//!
//! Against clifford 1.5.1 (tests/tests/geometry/clifford_tools.rs): its `fit_sphere` and
//! `fit_circle` agree with these within the noise on noisy points but are wrong on points
//! exactly on the object (they keep only positive eigenvalues, and the exact fit's is zero:
//! another sphere or circle, or NaN), `fit_line` raises there, and `fit_plane` returns a
//! round (or another plane) on 11 of 12 cases. [`Fit`] states a fit's error, which clifford
//! does not.

use crate::conformal::{GeometryError, Result};
use crate::euclid::{E3, add, circle_distance, cross, dot, norm, scale, sub};
use crate::{Circle, Line, Plane, Real, Sphere};

/// The sphere nearest the points in the algebraic sense (at least four, not coplanar).
pub fn fit_sphere<T: Real>(points: &[E3<T>]) -> Result<Sphere<T>> {
    let scatter = Scatter::of(points, 4)?;
    scatter.spans(3)?;
    let g = scatter.moment(|u| u);
    // c = S⁻¹ g in the axes of S, where S is diagonal.
    let c = (0..3).fold([T::zero(); 3], |c, j| {
        let v = scatter.axes[j];
        add(c, scale(v, dot(v, g) / scatter.values[j]))
    });
    let r = (T::one() + dot(c, c)).sqrt();
    Sphere::from_centre_radius(scatter.world(c), scatter.scale * r)
}

/// The circle nearest the points: in their fitted plane, the algebraic fit of their
/// in-plane coordinates (at least three, not collinear).
pub fn fit_circle<T: Real>(points: &[E3<T>]) -> Result<Circle<T>> {
    let scatter = Scatter::of(points, 3)?;
    scatter.spans(2)?;
    let [a, b, n] = scatter.axes;
    // In-plane coordinates p = (u · a, u · b): their scatter is diag(λ₀, λ₁), mean |p|² their sum.
    let in_plane = |u: E3<T>| add(scale(a, dot(u, a)), scale(b, dot(u, b)));
    let g = scatter.moment(in_plane);
    let [l0, l1, _] = scatter.values;
    let c = add(scale(a, dot(a, g) / l0), scale(b, dot(b, g) / l1));
    let r = (l0 + l1 + dot(c, c)).sqrt();
    Circle::from_centre_normal_radius(scatter.world(c), oriented(n), scatter.scale * r)
}

/// The plane through the points' centroid across their least spread (at least three, not
/// collinear).
pub fn fit_plane<T: Real>(points: &[E3<T>]) -> Result<Plane<T>> {
    let scatter = Scatter::of(points, 3)?;
    scatter.spans(2)?;
    Plane::new(scatter.centroid, oriented(scatter.axes[2]))
}

/// The line through the points' centroid along their greatest spread (at least two, not all
/// at one place).
pub fn fit_line<T: Real>(points: &[E3<T>]) -> Result<Line<T>> {
    let scatter = Scatter::of(points, 2)?;
    Line::new(scatter.centroid, oriented(scatter.axes[0]))
}

/// A fitted object and how far the points lie from it: the stated error of a fit.
///
/// `rms = √(mean dᵢ²)` and `max = max dᵢ` of the points' Euclidean distances `dᵢ` from the
/// fitted object (for a sphere `| |x − c| − r |`, for a circle `√(h² + (ρ − r)²)` with `h`
/// the height over its plane and `ρ` the distance from its axis, for a plane and a line the
/// perpendicular distance). `sigma = rms √(n / (n − p))` estimates the standard deviation
/// of isotropic noise along the object's normal from `n` points and the object's `p`
/// parameters (sphere 4, circle 6, plane 3, line 4); `NaN`-free, and `rms` itself when
/// `n ≤ p` (exact fits, `rms` zero to rounding).
///
/// What it promises: for points on the object with independent noise of standard deviation
/// `σ` per coordinate, `sigma ≈ σ` (`√2 σ` for a circle, whose distance has two normal
/// directions; a line's likewise), and the fitted centre and radius lie within a few
/// `σ/√n` of the true ones (the test
/// `clifford_tools::noisy_fits_state_their_error_and_agree_with_clifford` checks `4 σ √(3/n)` on
/// well-spread points). The algebraic sphere and circle fits are biased by about `σ²/r`
/// in the radius, below that bound while `σ < r/√n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit<X, T> {
    /// The fitted object (as the plain `fit_*` function returns it).
    pub object: X,
    /// The root-mean-square distance of the points from it.
    pub rms: T,
    /// The largest distance of a point from it.
    pub max: T,
    /// `rms √(n / (n − p))`: the noise's standard deviation, estimated.
    pub sigma: T,
}

/// `Fit` of `object` to `points`, by the distance `d` of a point from it and its parameter
/// count `p`.
fn residuals<X, T: Real>(object: X, points: &[E3<T>], p: usize, d: impl Fn(E3<T>) -> T) -> Fit<X, T> {
    let n = points.len();
    let (sum, max) = points.iter().fold((T::zero(), T::zero()), |(s, m), &x| {
        let e = d(x);
        (s + e * e, if e > m { e } else { m })
    });
    let rms = (sum / T::from_f64(n as f64)).sqrt();
    let sigma = if n > p { rms * T::from_f64((n as f64 / (n - p) as f64).sqrt()) } else { rms };
    Fit { object, rms, max, sigma }
}

/// [`fit_sphere`] with its stated error ([`Fit`]): distances `| |x − c| − r |`.
pub fn fit_sphere_with_error<T: Real>(points: &[E3<T>]) -> Result<Fit<Sphere<T>, T>> {
    let sphere = fit_sphere(points)?;
    let (c, r) = sphere.centre_radius()?;
    Ok(residuals(sphere, points, 4, |x| (norm(sub(x, c)) - r).abs()))
}

/// [`fit_circle`] with its stated error ([`Fit`]): distances `√(h² + (ρ − r)²)`.
pub fn fit_circle_with_error<T: Real>(points: &[E3<T>]) -> Result<Fit<Circle<T>, T>> {
    let circle = fit_circle(points)?;
    let parts = circle.centre_normal_radius()?;
    Ok(residuals(circle, points, 6, |x| circle_distance(x, parts) * parts.2))
}

/// [`fit_plane`] with its stated error ([`Fit`]): distances `|(x − p)·n|`.
pub fn fit_plane_with_error<T: Real>(points: &[E3<T>]) -> Result<Fit<Plane<T>, T>> {
    let plane = fit_plane(points)?;
    let (n, offset) = plane.normal_offset()?;
    Ok(residuals(plane, points, 3, |x| (dot(x, n) - offset).abs()))
}

/// [`fit_line`] with its stated error ([`Fit`]): distances `|(x − p) × d|`.
pub fn fit_line_with_error<T: Real>(points: &[E3<T>]) -> Result<Fit<Line<T>, T>> {
    let line = fit_line(points)?;
    let (p, d) = (line.point()?, line.direction()?);
    Ok(residuals(line, points, 4, |x| norm(cross(sub(x, p), d))))
}

/// Points about their centroid in units of their RMS distance from it, with the axes of
/// their scatter, largest first.
struct Scatter<'a, T> {
    points: &'a [E3<T>],
    centroid: E3<T>,
    scale: T,
    /// Eigenvalues of `S = mean(u uᵀ)`, largest first (they sum to 1).
    values: [T; 3],
    /// Their unit eigenvectors.
    axes: [E3<T>; 3],
}

impl<'a, T: Real> Scatter<'a, T> {
    /// At least `needed` finite points, not all at one place.
    fn of(points: &'a [E3<T>], needed: usize) -> Result<Self> {
        if points.len() < needed {
            return Err(GeometryError::Degenerate);
        }
        if !points.iter().flatten().all(|x| x.is_finite()) {
            return Err(GeometryError::NonFinite);
        }
        let n = T::from_f64(points.len() as f64);
        let centroid = scale(points.iter().fold([T::zero(); 3], |s, &x| add(s, x)), T::one() / n);
        let spread = points.iter().map(|&x| dot(sub(x, centroid), sub(x, centroid))).fold(T::zero(), |a, b| a + b);
        let size = (spread / n).sqrt();
        if !(size > T::zero() && size.is_finite()) {
            return Err(if size > T::zero() { GeometryError::Overflow } else { GeometryError::CoincidentPoints });
        }
        let mut s = [[T::zero(); 3]; 3];
        let inverse = T::one() / size;
        for &x in points {
            let u = scale(sub(x, centroid), inverse);
            for (i, row) in s.iter_mut().enumerate() {
                for (j, entry) in row.iter_mut().enumerate() {
                    *entry = *entry + u[i] * u[j] / n;
                }
            }
        }
        let (values, axes) = eigen(s);
        Ok(Scatter { points, centroid, scale: size, values, axes })
    }

    /// The points spread over `dimensions` (2: a plane, 3: space), else `CollinearPoints` or
    /// `CoplanarPoints`, by the axis within rounding of zero.
    fn spans(&self, dimensions: usize) -> Result<()> {
        let flat = |k: usize| k < dimensions && self.values[k] <= T::from_f64(64.0) * T::epsilon();
        match (flat(1), flat(2)) {
            (true, _) => Err(GeometryError::CollinearPoints),
            (_, true) => Err(GeometryError::CoplanarPoints),
            _ => Ok(()),
        }
    }

    /// `½ mean(p |p|²)` of the points' scaled coordinates `u`, each taken through `p = f(u)`.
    fn moment(&self, f: impl Fn(E3<T>) -> E3<T>) -> E3<T> {
        let n = T::from_f64(self.points.len() as f64);
        let inverse = T::one() / self.scale;
        let sum = self.points.iter().fold([T::zero(); 3], |g, &x| {
            let p = f(scale(sub(x, self.centroid), inverse));
            add(g, scale(p, dot(p, p)))
        });
        scale(sum, T::from_f64(0.5) / n)
    }

    /// A scaled point back in world coordinates: `m + s u`.
    fn world(&self, u: E3<T>) -> E3<T> {
        add(self.centroid, scale(u, self.scale))
    }
}

/// `axis` or `−axis`, whichever has its largest component (the first of equals) positive.
fn oriented<T: Real>(axis: E3<T>) -> E3<T> {
    let mut largest = 0;
    for k in 1..3 {
        if axis[k].abs() > axis[largest].abs() {
            largest = k;
        }
    }
    if axis[largest] < T::zero() { scale(axis, -T::one()) } else { axis }
}

/// The eigenvalues of a symmetric 3 × 3 matrix, largest first, and unit eigenvectors, by
/// cyclic Jacobi rotations (each zeroes one off-diagonal entry; converged to rounding
/// within a few sweeps).
fn eigen<T: Real>(mut a: [[T; 3]; 3]) -> ([T; 3], [E3<T>; 3]) {
    let mut v = [[T::one(), T::zero(), T::zero()], [T::zero(), T::one(), T::zero()], [T::zero(), T::zero(), T::one()]];
    for _sweep in 0..32 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        let diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if off <= T::epsilon() * T::epsilon() * diagonal {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == T::zero() {
                continue;
            }
            // The rotation by θ in the (p, q) plane with tan 2θ = 2 a_pq / (a_qq − a_pp).
            let theta = (a[q][q] - a[p][p]) / (T::from_f64(2.0) * a[p][q]);
            let sign = if theta < T::zero() { -T::one() } else { T::one() };
            let t = sign / (theta.abs() + (theta * theta + T::one()).sqrt());
            let c = T::one() / (t * t + T::one()).sqrt();
            let s = t * c;
            // A ← Jᵀ A J (columns, then rows), V ← V J.
            let turn = |x: &mut [T; 3]| {
                let (xp, xq) = (x[p], x[q]);
                x[p] = c * xp - s * xq;
                x[q] = s * xp + c * xq;
            };
            a.iter_mut().for_each(turn);
            let (ap, aq) = (a[p], a[q]);
            a[p] = core::array::from_fn(|k| c * ap[k] - s * aq[k]);
            a[q] = core::array::from_fn(|k| s * ap[k] + c * aq[k]);
            v.iter_mut().for_each(turn);
        }
    }
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| a[j][j].partial_cmp(&a[i][i]).unwrap_or(core::cmp::Ordering::Equal));
    let values = order.map(|j| a[j][j]);
    let axes = order.map(|j| [v[0][j], v[1][j], v[2][j]]);
    (values, axes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Jacobi rotations diagonalise: `A v = λ v` for each pair, the axes orthonormal.
    #[test]
    fn eigen_pairs_hold() {
        let a = [[4.0, 1.0, -2.0], [1.0, 2.0, 0.5], [-2.0, 0.5, 3.0]];
        let (values, axes) = eigen(a);
        assert!(values[0] >= values[1] && values[1] >= values[2]);
        for (l, v) in values.iter().zip(&axes) {
            let av = [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2]);
            assert!(crate::euclid::norm(sub(av, scale(*v, *l))) < 1e-13, "{av:?} vs {l} {v:?}");
            assert!((dot(*v, *v) - 1.0).abs() < 1e-14);
        }
        assert!(dot(axes[0], axes[1]).abs() < 1e-14 && dot(axes[0], axes[2]).abs() < 1e-14);
    }

    /// A diagonal matrix is its own decomposition (no rotation is made).
    #[test]
    fn eigen_of_a_diagonal_matrix() {
        let (values, axes) = eigen([[1.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 2.0]]);
        assert_eq!(values, [3.0, 2.0, 1.0]);
        assert_eq!(axes, [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]);
    }
}
