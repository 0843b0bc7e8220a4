//! Fitting spheres, circles, planes and lines to points: exact points give back the object
//! they were taken from (Euclidean formulas), anywhere in space and at any size; noisy points
//! give the least-squares optimum (the normal equations hold, checked in double-double); too
//! few or degenerate points are refused by name.

use cga_tests::common;

use cga_core::Real;
use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{GeometryError, fit_circle, fit_line, fit_plane, fit_sphere};
use common::Rng;
use common::dd::{Dd, dd3};

/// `n` points on the sphere of centre `c` and radius `r`, spread over it (or over a cap of
/// half-angle `cap` about +z).
fn on_sphere(rng: &mut Rng, c: E3, r: f64, n: usize, cap: f64) -> Vec<E3> {
    (0..n)
        .map(|_| {
            let (z, phi) = (rng.range(cap.cos(), 1.0), rng.range(0.0, std::f64::consts::TAU));
            let s = (1.0 - z * z).sqrt();
            add(c, scale([s * phi.cos(), s * phi.sin(), z], r))
        })
        .collect()
}

/// `n` points on the circle of centre `c`, unit normal `nrm` and radius `r`.
fn on_circle(rng: &mut Rng, c: E3, nrm: E3, r: f64, n: usize) -> Vec<E3> {
    let u = unit(cross(nrm, [0.3, 0.5, 0.7])).unwrap();
    let v = cross(nrm, u);
    (0..n)
        .map(|_| {
            let t = rng.range(0.0, std::f64::consts::TAU);
            add(c, add(scale(u, r * t.cos()), scale(v, r * t.sin())))
        })
        .collect()
}

fn noisy(rng: &mut Rng, points: &[E3], sigma: f64) -> Vec<E3> {
    points.iter().map(|&x| add(x, rng.e3(-sigma, sigma))).collect()
}

/// The same answer anywhere: exact points on spheres and circles centred up to 1e6 from the
/// origin, of radius 1e-3 … 1e3 (`ρ = |c|/r` up to 1e6), give back centre and radius to
/// the rounding of the points themselves, `64 ε ρ r`, plus what a sphere or circle read
/// back from its blade carries in the null basis, `ε ρ²` (ARCHITECTURE.md, "Precision
/// anywhere").
#[test]
fn exact_points_give_back_their_sphere_and_circle_anywhere() {
    let mut rng = Rng::new(7);
    for (shift, r) in [(0.0, 1.0), (1e3, 1e-3), (1e6, 1e3), (1e6, 1.0), (-2e5, 30.0), (3e5, 1e-2)] {
        let c = add(rng.e3(-1.0, 1.0), [shift, -0.5 * shift, 0.25 * shift]);
        let rho = norm(c) / r;
        let tol = r * (1e-12 + 64.0 * f64::EPSILON * rho * (1.0 + rho));
        let sphere = fit_sphere(&on_sphere(&mut rng, c, r, 40, std::f64::consts::PI)).unwrap();
        let (fc, fr) = sphere.centre_radius().unwrap();
        assert!(norm(sub(fc, c)) <= tol && (fr - r).abs() <= tol, "sphere {c:?} {r}: {fc:?} {fr}");
        let n = rng.direction();
        let circle = fit_circle(&on_circle(&mut rng, c, n, r, 12)).unwrap();
        let (cc, cn, cr) = circle.centre_normal_radius().unwrap();
        assert!(norm(sub(cc, c)) <= tol && (cr - r).abs() <= tol, "circle {c:?} {r}: {cc:?} {cr}");
        assert!(norm(cross(cn, n)) <= 1e-9, "normal {cn:?} vs {n:?}");
    }
}

/// A cap of 20° still determines its sphere, and four points (the least a sphere needs) give
/// the circumsphere.
#[test]
fn a_cap_and_four_points_give_their_sphere() {
    let mut rng = Rng::new(3);
    let (c, r) = ([1.0, -2.0, 3.0], 5.0);
    let cap = on_sphere(&mut rng, c, r, 200, 20f64.to_radians());
    let (fc, fr) = fit_sphere(&cap).unwrap().centre_radius().unwrap();
    assert!(norm(sub(fc, c)) <= 1e-10 * r && (fr - r).abs() <= 1e-10 * r, "{fc:?} {fr}");
    let four = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0], [1.0, 1.0, 1.0]];
    let (want, radius, _) = cga_core::circumsphere(four[0], four[1], four[2], four[3]).unwrap();
    let (fc, fr) = fit_sphere(&four).unwrap().centre_radius().unwrap();
    assert!(norm(sub(fc, want)) <= 1e-12 && (fr - radius).abs() <= 1e-12, "{fc:?} {fr}");
}

/// Noisy points: the fitted sphere is the algebraic least-squares optimum, where the residuals
/// `2 c · x + k − |x|²` (`k = r² − |c|²`) are orthogonal to the columns `[2x, 1]`; checked
/// in double-double about the centroid, relative to the sums' own size.
#[test]
fn noisy_points_give_the_least_squares_sphere() {
    let mut rng = Rng::new(11);
    for shift in [0.0, 1e4] {
        let c = [shift + 0.5, 0.2, -0.1];
        let exact = on_sphere(&mut rng, c, 2.0, 300, 2.0);
        let points = noisy(&mut rng, &exact, 0.05);
        let (fc, fr) = fit_sphere(&points).unwrap().centre_radius().unwrap();
        let m = scale(points.iter().fold([0.0; 3], |s, &x| add(s, x)), 1.0 / points.len() as f64);
        let (dc, k) = (dd3(sub(fc, m)), Dd::from_f64(fr) * Dd::from_f64(fr) - norm2(dd3(sub(fc, m))));
        let (mut gradient, mut size) = ([Dd::from_f64(0.0); 4], 0.0);
        for &x in &points {
            let u = dd3(sub(x, m));
            let residual = Dd::from_f64(2.0) * dot3(dc, u) + k - norm2(u);
            for j in 0..3 {
                gradient[j] = gradient[j] + Dd::from_f64(2.0) * residual * u[j];
            }
            gradient[3] = gradient[3] + residual;
            size += norm2(u).hi() * norm(sub(x, m)).max(1.0);
        }
        let worst = gradient.iter().map(|g| g.hi().abs()).fold(0.0, f64::max);
        assert!(worst <= 1e-12 * size, "shift {shift}: gradient {worst:e} against {size:e}");
        assert!(norm(sub(fc, c)) < 0.05 && (fr - 2.0).abs() < 0.05, "{fc:?} {fr}");
    }
}

/// Noisy points on a plane and along a line: the fitted plane's normal is the scatter's axis
/// of least spread, the line's of greatest (`S n = λ n`), through the centroid; each oriented
/// with its largest component positive.
#[test]
fn noisy_points_give_the_total_least_squares_plane_and_line() {
    let mut rng = Rng::new(5);
    let n = unit([0.2, -0.4, 1.0]).unwrap();
    let u = unit(cross(n, [1.0, 0.0, 0.0])).unwrap();
    let v = cross(n, u);
    let base = [3e5, 1.0, -2.0];
    let flat: Vec<E3> =
        (0..200).map(|_| add(base, add(scale(u, rng.range(-4.0, 4.0)), scale(v, rng.range(-1.0, 1.0))))).collect();
    let flat = noisy(&mut rng, &flat, 0.01);
    let plane = fit_plane(&flat).unwrap();
    let (normal, _) = plane.normal_offset().unwrap();
    assert!(normal[2] > 0.0 && norm(cross(normal, n)) < 0.01, "{normal:?}");
    assert_axis(&flat, normal);
    let line = fit_line(&flat).unwrap();
    let d = line.direction().unwrap();
    assert!(norm(cross(d, u)) < 0.05, "{d:?} vs {u:?}");
    assert!(d.iter().fold(0.0f64, |a, &b| if b.abs() > a.abs() { b } else { a }) > 0.0);
    assert_axis(&flat, d);
    // Both pass through the centroid.
    let m = scale(flat.iter().fold([0.0; 3], |s, &x| add(s, x)), 1.0 / flat.len() as f64);
    assert!(plane.signed_distance(m).unwrap().abs() < 1e-9);
    assert!(line.distance_to(m).unwrap() < 1e-9);
}

/// `axis` is an eigenvector of the points' scatter about their centroid.
fn assert_axis(points: &[E3], axis: E3) {
    let m = scale(points.iter().fold([0.0; 3], |s, &x| add(s, x)), 1.0 / points.len() as f64);
    let s_axis = points.iter().fold([0.0; 3], |s, &x| {
        let d = sub(x, m);
        add(s, scale(d, dot(d, axis)))
    });
    let lambda = dot(s_axis, axis);
    assert!(norm(sub(s_axis, scale(axis, lambda))) <= 1e-9 * norm(s_axis).max(1.0), "{s_axis:?} vs {axis:?}");
}

/// Too few points, or points that do not hold the object, are refused by name.
#[test]
fn degenerate_points_are_refused_by_name() {
    let line: Vec<E3> = (0..5).map(|k| [k as f64, 2.0 * k as f64, 1e6]).collect();
    let square = [[0.0, 0.0, 7.0], [1.0, 0.0, 7.0], [1.0, 1.0, 7.0], [0.0, 1.0, 7.0], [0.5, 0.5, 7.0]];
    assert_eq!(fit_sphere(&square).unwrap_err(), GeometryError::CoplanarPoints);
    assert_eq!(fit_sphere(&line).unwrap_err(), GeometryError::CollinearPoints);
    assert_eq!(fit_circle(&line).unwrap_err(), GeometryError::CollinearPoints);
    assert_eq!(fit_plane(&line).unwrap_err(), GeometryError::CollinearPoints);
    assert_eq!(fit_line(&[[1.0, 2.0, 3.0]; 4]).unwrap_err(), GeometryError::CoincidentPoints);
    assert_eq!(fit_sphere(&square[..3]).unwrap_err(), GeometryError::Degenerate);
    assert_eq!(fit_line(&[[0.0; 3]]).unwrap_err(), GeometryError::Degenerate);
    assert_eq!(fit_plane(&[[0.0; 3], [1.0, f64::NAN, 0.0], [0.0, 1.0, 0.0]]).unwrap_err(), GeometryError::NonFinite);
    assert!(fit_circle(&square).is_ok() && fit_plane(&square).is_ok());
}

fn dot3(a: [Dd; 3], b: [Dd; 3]) -> Dd {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm2(a: [Dd; 3]) -> Dd {
    dot3(a, a)
}
