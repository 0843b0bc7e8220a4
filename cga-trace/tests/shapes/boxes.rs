//! The box against Euclid: a turned box's first crossing is the first point of the ray that
//! the inside test (|(x − c)·a_k| ≤ h_k on every axis) finds, and its normal is its face's
//! axis, anywhere in space.

use cga_core::euclid::{E3, add, cross, dot, scale, sub, unit};
use cga_trace::ray::Ray;
use cga_trace::shapes::{BoxShape, Shape};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn the_first_crossing_is_where_the_ray_gets_inside(
        far in prop::sample::select(vec![0.0, 1e3, 1e6]),
        c in prop::array::uniform3(-1.0f64..1.0),
        u in prop::array::uniform3(-1.0f64..1.0),
        v in prop::array::uniform3(-1.0f64..1.0),
        half in prop::array::uniform3(0.05f64..2.0),
        from in prop::array::uniform3(-1.0f64..1.0),
        aim in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let (Some(a), Some(from)) = (unit(u), unit(from)) else { return Ok(()) };
        let Some(b) = unit(sub(v, scale(a, dot(v, a)))) else { return Ok(()) };
        let axes = [a, b, cross(a, b)];
        let c = c.map(|x| x * (1.0 + far));
        let b = BoxShape::new(half, c, axes).unwrap();
        let size = dot(half, half).sqrt();
        let origin = add(c, scale(from, 6.0 * size));
        let Some(ray) = Ray::new(origin, sub(add(c, scale(aim, size)), origin)) else { return Ok(()) };
        let inside = |x: E3| (0..3).all(|k| dot(sub(x, c), axes[k]).abs() <= half[k]);
        let t0 = dot(sub(c, origin), ray.dir);
        let (lo, step) = (t0 - size, 2.0 * size / 20_000.0);
        let first = (0..20_000).map(|i| lo + step * i as f64).find(|&t| inside(ray.at(t)));
        let slack = 1e-12 * (far + size);
        match (b.hit(&ray, 0.0, f64::INFINITY), first) {
            (Some(h), Some(t)) => {
                prop_assert!(h.t <= t + slack && h.t >= t - step - slack, "ours at {}, the march at {t}", h.t);
                let on_face = (0..3).any(|k| {
                    (dot(sub(h.point, c), axes[k]).abs() - half[k]).abs() <= slack
                        && dot(h.normal, axes[k]).abs() >= 1.0 - 1e-12
                });
                prop_assert!(on_face, "the crossing is on a face, the normal its axis");
                prop_assert!(dot(h.normal, ray.dir) <= 0.0);
            }
            (None, None) => {}
            // Only a corner narrower than the march's step may be seen by one alone.
            (Some(h), None) => prop_assert!(
                (0..20_000).map(|i| lo + step * i as f64).all(|t| (t - h.t).abs() > 2.0 * step || !inside(ray.at(t))),
                "missed by the march at {}", h.t
            ),
            (None, Some(t)) => prop_assert!(false, "missed at {t}"),
        }
    }
}
