//! Swept surfaces as solids: an evolved surface between two coaxial circles, capped by its
//! end disks ([`Body`]), against marching an inside test built from its own circles `C_α`.

use cga_trace::Scene;
use cga_trace::mesh::swept;
use cga_trace::ray::Ray;
use cga_trace::shapes::{Body, DiskShape, Shape};
use std::sync::Arc;

/// The evolved surface between circles of radii 1 (at z = 0) and 0.6 (at z = 2) about the
/// z axis, and the scene's frame its shape lies in.
fn tube() -> (Scene, Arc<dyn Shape>) {
    let text = "[camera]\nposition = [0.0, -9.0, 1.0]\nlook_at = [0.0, 0.0, 1.0]\nwidth = 8\nheight = 6\n\
                [[objects]]\ntype = \"evolved\"\n\
                c1 = { centre = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0], radius = 1.0 }\n\
                c2 = { centre = [0.0, 0.0, 2.0], normal = [0.0, 0.0, 1.0], radius = 0.6 }\n\
                material = { colour = [1.0, 1.0, 1.0] }\n";
    let scene = Scene::parse(text, "tube.toml").unwrap();
    let shape = scene.objects[0].shape.clone();
    (scene, shape)
}

/// The capped tube is the solid of revolution its circles sweep: along 300 random lines, the
/// ends of its spans are where marching an inside test finds a change, within 2e-5 of the
/// tube's size; the first is the body's nearest crossing. The test: a point is inside where
/// it lies between the end planes and nearer the axis than the circle `C_α` at its height
/// (the circles tabulated at 4,097 values of α, linear between them).
#[test]
fn a_capped_evolved_surface_bounds_the_solid_its_circles_sweep() {
    let (scene, surface) = tube();
    let family = swept(&*surface).expect("a swept surface");
    // Everything in the scene's frame (where shapes lie): a shift and a scale of the world.
    let size = scene.frame.length(1.0);
    let axis = family.circle(0.0).unwrap().0;
    let table: Vec<(f64, f64)> = (0..=4096)
        .map(|k| {
            let (c, n, r) = family.circle(k as f64 / 4096.0).unwrap();
            let off_axis = (c[0] - axis[0]).hypot(c[1] - axis[1]);
            assert!(off_axis < 1e-12 && (n[2].abs() - 1.0).abs() < 1e-12, "{c:?} {n:?}");
            (c[2], r)
        })
        .collect();
    assert!(table.windows(2).all(|w| w[1].0 > w[0].0), "heights rise with α");
    let radius_at = |z: f64| {
        let k = table.partition_point(|e| e.0 < z).clamp(1, 4096);
        let (a, b) = (table[k - 1], table[k]);
        a.1 + (b.1 - a.1) * (z - a.0) / (b.0 - a.0)
    };
    let inside = |x: [f64; 3]| {
        table[0].0 < x[2] && x[2] < table[4096].0 && (x[0] - axis[0]).hypot(x[1] - axis[1]) < radius_at(x[2])
    };
    let disk = |(c, n, r): ([f64; 3], [f64; 3], f64)| Arc::new(DiskShape::new(c, n, r).unwrap()) as Arc<dyn Shape>;
    let ends = [family.circle(0.0).unwrap(), family.circle(1.0).unwrap()];
    let body = Body::new(vec![surface.clone(), disk(ends[0]), disk(ends[1])]).unwrap();
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    let mut found = 0;
    for _ in 0..300 {
        let from = scene.frame.point([4.0 * random(), 4.0 * random(), 1.0 + 4.0 * random()]);
        let aim = scene.frame.point([0.8 * random(), 0.8 * random(), 1.0 + random()]);
        let ray = Ray::new(from, [0, 1, 2].map(|k| aim[k] - from[k])).unwrap();
        let spans = body.spans(&ray);
        // March from the ray's origin in steps of 2e-3 of the tube's size, each change
        // bisected.
        let at = |t: f64| inside(ray.at(t));
        let (step, reach) = (2e-3 * size, 12.0 * size);
        let (mut changes, mut was, mut t) = (Vec::new(), at(0.0), 0.0);
        while t < reach {
            if at(t + step) != was {
                let (mut a, mut b) = (t, t + step);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    if at(m) == was {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                changes.push(0.5 * (a + b));
                was = !was;
            }
            t += step;
        }
        let got: Vec<f64> = spans.iter().flat_map(|s| [s.0, s.1]).filter(|&t| t > 0.0).collect();
        assert_eq!(got.len(), changes.len(), "{got:?} {changes:?}");
        for (g, w) in got.iter().zip(&changes) {
            assert!((g - w).abs() < 2e-5 * size, "{got:?} {changes:?}");
        }
        if let Some(&first) = got.first() {
            let c = body.intersect(&ray, 0.0, f64::INFINITY).unwrap();
            assert!((c.t - first).abs() < 1e-9 * size, "{} {first}", c.t);
        }
        found += got.len();
    }
    assert!(found > 200, "{found}");
}
