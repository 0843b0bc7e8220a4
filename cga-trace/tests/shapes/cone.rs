//! Cylinders and cones against Euclid: the first crossing is the first point of the ray that
//! the inside test finds (`|u| ≤ h` along the axis and `|x⊥| ≤ r(u)`, `r` linear between the
//! end radii), it lies on the side or a cap, and the normal faces the ray, anywhere in space.

use cga_core::euclid::{E3, add, dot, norm, scale, sub, unit};
use cga_trace::ray::Ray;
use cga_trace::shapes::{ConeShape, Shape};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn the_first_crossing_is_where_the_ray_gets_inside(
        far in prop::sample::select(vec![0.0, 1e3, 1e6]),
        p in prop::array::uniform3(-1.0f64..1.0),
        axis in prop::array::uniform3(-2.0f64..2.0),
        r1 in 0.0f64..1.5,
        r2 in 0.0f64..1.5,
        cylinder in any::<bool>(),
        from in prop::array::uniform3(-1.0f64..1.0),
        aim in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let r2 = if cylinder { r1 } else { r2 };
        prop_assume!(r1.max(r2) > 0.05 && norm(axis) > 0.1);
        let Some(from) = unit(from) else { return Ok(()) };
        let p1 = p.map(|x| x * (1.0 + far));
        let p2 = add(p1, axis);
        let c = ConeShape::new(p1, r1, p2, r2, true).unwrap();
        let (a, len) = (unit(axis).unwrap(), norm(axis));
        let mid = add(p1, scale(axis, 0.5));
        let size = 0.5 * len + r1.max(r2);
        let origin = add(mid, scale(from, 6.0 * size));
        let Some(ray) = Ray::new(origin, sub(add(mid, scale(aim, size)), origin)) else { return Ok(()) };
        let inside = |x: E3| {
            let u = dot(sub(x, p1), a);
            let perp = norm(sub(sub(x, p1), scale(a, u)));
            (0.0..=len).contains(&u) && perp <= r1 + (r2 - r1) * u / len
        };
        let t0 = dot(sub(mid, origin), ray.dir);
        let (lo, step) = (t0 - size, 2.0 * size / 20_000.0);
        let first = (0..20_000).map(|i| lo + step * i as f64).find(|&t| inside(ray.at(t)));
        let slack = 1e-11 * (far + size);
        match (c.hit(&ray, 0.0, f64::INFINITY), first) {
            (Some(h), Some(t)) => {
                prop_assert!(h.t <= t + slack && h.t >= t - step - slack, "ours at {}, the march at {t}", h.t);
                prop_assert!(dot(h.normal, ray.dir) <= 0.0, "the normal faces the ray");
            }
            (None, None) => {}
            // Only a sliver narrower than the march's step may be seen by one alone.
            (Some(h), None) => prop_assert!(
                !(0..20_000).map(|i| lo + step * i as f64).any(|t| (t - h.t).abs() > 2.0 * step && inside(ray.at(t))),
                "missed by the march at {}", h.t
            ),
            (None, Some(t)) => {
                let depth = (0..20_000).map(|i| lo + step * i as f64).filter(|&t| inside(ray.at(t))).count();
                prop_assert!(depth <= 2, "missed at {t}, inside for {depth} steps");
            }
        }
    }
}
