//! The torus against Euclid: its crossings lie at distance `ρ` from the core circle (the
//! distance of a point from a circle, `√((|p − (p·n)n| − R)² + (p·n)²)`, computed here and
//! nowhere in the renderer), the first crossing is the first the ray's march over that
//! distance finds, and the normal is the distance's gradient, anywhere in space.

use cga_core::euclid::{E3, add, dot, scale, sub, unit};

use cga_trace::ray::Ray;
use cga_trace::shapes::{Shape, TorusShape};
use proptest::prelude::*;

/// Signed distance of `x` from the tube: distance from the core circle minus `ρ`.
fn tube_distance(x: E3, c: E3, n: E3, r: f64, rho: f64) -> f64 {
    let p = sub(x, c);
    let h = dot(p, n);
    let radial = sub(p, scale(n, h));
    let d = dot(radial, radial).sqrt() - r;
    (d * d + h * h).sqrt() - rho
}

fn unit_of(v: E3) -> Option<E3> {
    unit(v).filter(|u| u.iter().all(|x| x.is_finite()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn crossings_are_on_the_tube_first_and_with_its_normal(
        far in prop::sample::select(vec![0.0, 1e3, 1e6]),
        c in prop::array::uniform3(-1.0f64..1.0),
        n in prop::array::uniform3(-1.0f64..1.0),
        r in 0.5f64..3.0,
        thickness in 0.02f64..1.4,
        from in prop::array::uniform3(-1.0f64..1.0),
        aim in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let (Some(n), Some(from)) = (unit_of(n), unit_of(from)) else { return Ok(()) };
        let c = c.map(|x| x * (1.0 + far));
        let rho = thickness * r;
        let k = r + rho;
        let torus = TorusShape::new(c, n, r, rho).unwrap();
        let origin = add(c, scale(from, 6.0 * k));
        let target = add(c, scale(aim, k));
        let Some(ray) = Ray::new(origin, sub(target, origin)) else { return Ok(()) };
        let hit = torus.hit(&ray, 0.0, f64::INFINITY);
        // March the distance over the bounding sphere's chord, 20 000 steps.
        let t0 = dot(sub(c, origin), ray.dir);
        let (lo, step) = (t0 - k, 2.0 * k / 20_000.0);
        let g = |t: f64| tube_distance(ray.at(t), c, n, r, rho);
        let first = (0..20_000).map(|i| lo + step * i as f64).find(|&t| g(t) <= 0.0);
        let deepest = (0..20_000).map(|i| g(lo + step * i as f64)).fold(f64::INFINITY, f64::min);
        let scale_of = far + k;
        match (hit, first) {
            (Some(h), Some(t)) => {
                prop_assert!(h.t <= t + 1e-12 * scale_of && h.t >= t - step - 1e-12 * scale_of,
                    "ours at {}, the march at {t} (step {step})", h.t);
                let off = tube_distance(h.point, c, n, r, rho);
                let tol = 64.0 * f64::EPSILON * (scale_of + k * k / rho) * 8.0;
                prop_assert!(off.abs() <= tol, "{off:e} off the tube (tolerance {tol:e})");
                // The gradient of the distance, by central differences.
                let e = 1e-6 * k;
                let grad: E3 = core::array::from_fn(|i| {
                    let mut a = h.point;
                    let mut b = h.point;
                    a[i] += e;
                    b[i] -= e;
                    (tube_distance(a, c, n, r, rho) - tube_distance(b, c, n, r, rho)) / (2.0 * e)
                });
                let along = dot(unit(grad).unwrap(), h.normal).abs();
                prop_assert!(along >= 1.0 - 1e-6 * (1.0 + far / k), "normal off the gradient: cos {along}");
                prop_assert!(dot(h.normal, ray.dir) <= 0.0, "the normal faces the ray");
            }
            (None, None) => {}
            // Only a graze narrower than the march's step may be seen by one and not the other.
            (Some(h), None) => prop_assert!(deepest > -step, "missed by the march at {}: deepest {deepest:e}", h.t),
            (None, Some(t)) => prop_assert!(deepest > -step, "missed at {t}: deepest {deepest:e}"),
        }
    }
}

/// A tube about a circle made from three points, and its four crossings along a diameter.
#[test]
fn a_tube_about_a_circle_through_three_points() {
    let circle = cga_core::Circle::through([1.0, 0.0, 5.0], [0.0, 1.0, 5.0], [-1.0, 0.0, 5.0]).unwrap();
    let torus = TorusShape::about(&circle, 0.25).unwrap();
    assert!((torus.radius - 1.0).abs() <= 1e-15 && (torus.centre[2] - 5.0).abs() <= 1e-15);
    let ray = Ray::new([-3.0, 0.0, 5.0], [1.0, 0.0, 0.0]).unwrap();
    let first = torus.intersect(&ray, 0.0, f64::INFINITY).unwrap();
    assert!((first.t - 1.75).abs() <= 1e-14, "{first:?}");
    let third = torus.intersect(&ray, 3.0, f64::INFINITY).unwrap();
    assert!((third.t - 3.75).abs() <= 1e-14, "{third:?}");
}
