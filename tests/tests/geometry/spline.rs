//! Splines of circles (the paper's Fig. 3): knots reproduced, the two-circle case
//! reproduced, smoothness at the knots, the exact derivative against extrapolated
//! differences, and the analytic normal (eq. 6–11 with the spline's `Ċ`) against
//! finite-difference normals of the swept surface.

use cga_tests::common;

use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{Circle, InterpolationError, Joining, Pair, Spline, SplineError};
use common::*;

/// A circle near the z axis: centre in [−2, 2]² × [z, z + 1], a normal within about 35° of
/// z, radius in [0.7, 2] — neighbours that sweep a surface.
fn circle_at(rng: &mut Rng, z: f64) -> Circle {
    let centre = [rng.range(-2.0, 2.0), rng.range(-2.0, 2.0), z + rng.range(0.0, 1.0)];
    let normal = [rng.range(-0.7, 0.7), rng.range(-0.7, 0.7), 1.0];
    Circle::from_centre_normal_radius(centre, normal, rng.range(0.7, 2.0)).unwrap()
}

fn controls(rng: &mut Rng, n: usize) -> Vec<Circle> {
    (0..n).map(|k| circle_at(rng, 2.0 * k as f64)).collect()
}

const JOININGS: [(Joining, usize); 5] = [
    (Joining::Linear, 4),
    (Joining::Quadratic, 5),
    (Joining::Cubic, 7),
    (Joining::CATMULL_ROM, 4),
    (Joining::KochanekBartels { tension: 0.3, bias: -0.4, continuity: 0.5 }, 5),
];

/// Largest coefficient difference relative to the largest coefficient.
fn relative(a: &Circle, b: &Circle) -> f64 {
    let (a, b) = (a.to_array(), b.to_array());
    let size = a.iter().chain(&b).fold(0.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(&b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / size
}

#[test]
fn counts_and_parameters_are_checked() {
    let mut rng = Rng::new(1);
    let c = controls(&mut rng, 4);
    assert!(matches!(Spline::new(&c[..1], Joining::Linear), Err(SplineError::Count { found: 1, .. })));
    assert!(matches!(Spline::new(&c[..4], Joining::Quadratic), Err(SplineError::Count { found: 4, .. })));
    assert!(matches!(Spline::new(&c[..3], Joining::Cubic), Err(SplineError::Count { .. })));
    let bad = Joining::KochanekBartels { tension: 2.0, bias: 0.0, continuity: 0.0 };
    assert_eq!(Spline::new(&c, bad), Err(SplineError::Parameters));
    assert!(matches!(
        Spline::new(&[c[0], Circle::zero()], Joining::Linear),
        Err(SplineError::Interpolation(InterpolationError::Degenerate))
    ));
}

#[test]
fn two_controls_linear_is_the_pair() {
    let mut rng = Rng::new(2);
    for _ in 0..50 {
        let c = controls(&mut rng, 2);
        let (spline, pair) = (Spline::new(&c, Joining::Linear).unwrap(), Pair::new(c[0], c[1]).unwrap());
        for k in 0..=10 {
            let alpha = k as f64 / 10.0;
            let (Ok(a), Ok(b)) = (spline.at(alpha), pair.at(alpha)) else { continue };
            assert!(relative(&a, &b) < 1e-15, "α = {alpha}");
        }
    }
}

#[test]
fn the_curve_passes_through_its_knots() {
    let mut rng = Rng::new(3);
    for (joining, n) in JOININGS {
        for _ in 0..20 {
            let c = controls(&mut rng, n);
            let spline = Spline::new(&c, joining).unwrap();
            let m = spline.segments();
            // Linear and Kochanek–Bartels pass through every control; Bézier through every d-th.
            let step = match joining {
                Joining::Quadratic => 2,
                Joining::Cubic => 3,
                _ => 1,
            };
            for (j, knot) in spline.knots().iter().enumerate().step_by(step) {
                let alpha = (j / step) as f64 / m as f64;
                let at = spline.at(alpha).unwrap();
                assert!(relative(&at, knot) < 1e-13, "{joining:?}: knot {j} at α = {alpha}");
            }
        }
    }
}

#[test]
fn the_exact_derivative_matches_extrapolated_differences() {
    let mut rng = Rng::new(4);
    let mut worst = 0.0f64;
    for (joining, n) in JOININGS {
        let mut checked = 0;
        while checked < 40 {
            let spline = Spline::new(&controls(&mut rng, n), joining).unwrap();
            // Away from the knots, where a one-sided segment would be differenced.
            let m = spline.segments() as f64;
            let alpha = (rng.range(0.0, m).floor() + rng.range(0.1, 0.9)) / m;
            let Ok((_, dc)) = spline.with_derivative(alpha) else { continue };
            let Ok(d) = (|h: f64| -> Result<Circle, InterpolationError> {
                Ok((spline.at(alpha + h)? - spline.at(alpha - h)?).scale(0.5 / h))
            })(1e-4)
            .and_then(|a| Ok((a, (spline.at(alpha + 5e-5)? - spline.at(alpha - 5e-5)?).scale(1e4)))) else {
                continue;
            };
            let richardson = d.0.scale(-1.0 / 3.0) + d.1.scale(4.0 / 3.0);
            let e = relative(&dc, &richardson);
            worst = worst.max(e);
            assert!(e < 1e-8, "{joining:?} at α = {alpha}: {e:e}");
            checked += 1;
        }
    }
    println!("worst relative difference of the dual derivative from Richardson: {worst:.1e}");
}

#[test]
fn catmull_rom_is_smooth_at_the_knots_and_a_corner_is_not() {
    let mut rng = Rng::new(5);
    let derivative_jump = |spline: &Spline<Circle>, alpha: f64| {
        let (_, left) = spline.with_derivative(alpha - 1e-12).unwrap();
        let (_, right) = spline.with_derivative(alpha + 1e-12).unwrap();
        relative(&left, &right)
    };
    let (mut smooth, mut corner) = (0.0f64, f64::INFINITY);
    for _ in 0..20 {
        let c = controls(&mut rng, 4);
        let cr = Spline::new(&c, Joining::CATMULL_ROM).unwrap();
        let kinked = Spline::new(&c, Joining::KochanekBartels { tension: 0.0, bias: 0.0, continuity: 0.8 }).unwrap();
        for knot in [1.0 / 3.0, 2.0 / 3.0] {
            smooth = smooth.max(derivative_jump(&cr, knot));
            corner = corner.min(derivative_jump(&kinked, knot));
        }
    }
    println!("derivative jump at interior knots: Catmull–Rom ≤ {smooth:.1e}, continuity 0.8 ≥ {corner:.1e}");
    assert!(smooth < 1e-9, "{smooth:e}");
    assert!(corner > 1e-3, "{corner:e}");
}

/// The point of circle `c` nearest to `x`.
fn nearest_on(c: &Circle, x: E3) -> Option<E3> {
    let (centre, normal, r) = c.centre_normal_radius().ok()?;
    let d = sub(x, centre);
    Some(add(centre, scale(unit(sub(d, scale(normal, dot(d, normal))))?, r)))
}

/// The surface normal by finite differences, with no CGA beyond reading circles back: the
/// circle's tangent at `x` crossed with the velocity of the curve `α ↦ nearest point of C_α
/// to x` (a curve on the surface through `x`), Richardson-extrapolated central differences.
fn finite_difference_normal(spline: &Spline<Circle>, alpha: f64, x: E3) -> Option<E3> {
    let velocity = |h: f64| -> Option<E3> {
        let (a, b) = (nearest_on(&spline.at(alpha + h).ok()?, x)?, nearest_on(&spline.at(alpha - h).ok()?, x)?);
        Some(scale(sub(a, b), 0.5 / h))
    };
    let (v1, v2) = (velocity(1e-4)?, velocity(5e-5)?);
    let across = add(scale(v1, -1.0 / 3.0), scale(v2, 4.0 / 3.0));
    let (centre, normal, _) = spline.at(alpha).ok()?.centre_normal_radius().ok()?;
    unit(cross(cross(normal, sub(x, centre)), across))
}

#[test]
fn analytic_normals_match_finite_differences_on_random_spline_surfaces() {
    let mut rng = Rng::new(6);
    let angle = |a: E3, b: E3| norm(cross(a, b)).atan2(dot(a, b).abs());
    let mut worst = 0.0f64;
    for (joining, n) in JOININGS {
        let mut compared = 0;
        while compared < 200 {
            let spline = Spline::new(&controls(&mut rng, n), joining).unwrap();
            let m = spline.segments() as f64;
            let alpha = (rng.range(0.0, m).floor() + rng.range(0.05, 0.95)) / m;
            let Ok(c) = spline.at(alpha) else { continue };
            let x = on_circle(&c, rng.range(0.0, std::f64::consts::TAU));
            let (Ok(analytic), Some(fd)) = (spline.normal(alpha, x), finite_difference_normal(&spline, alpha, x))
            else {
                continue;
            };
            worst = worst.max(angle(analytic, fd));
            compared += 1;
        }
    }
    println!("1,000 points on random spline surfaces: worst angle to the finite-difference normal {worst:.1e} rad");
    assert!(worst < 1e-7, "{worst:e}");
}
