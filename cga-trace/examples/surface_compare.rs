//! Evolved-surface methods against a dense reference, ray by ray, on every ray a 320×240
//! render of `combined.toml` casts (primary, reflection and shadow):
//! `cargo run --release -p cga-trace --example surface_compare`.
//! Counts missed hits, false hits, rays where a different root is taken, and the largest
//! α difference where both agree.

use cga_core::euclid::{norm, reflect, sub};
use cga_trace::Renderer;
use cga_trace::ray::Ray;
use cga_trace::scene::Scene;
use cga_trace::shapes::Shape;
use cga_trace::surface::{EvolvedSurface, Method};

/// Missed, false, other root, max α error.
#[derive(Default)]
struct Tally(usize, usize, usize, f64);

fn main() {
    let scene = Scene::load(std::path::Path::new("cga-trace/scenes/combined.toml")).expect("the combined scene");
    let Some(Shape::Evolved(surface)) = scene.objects.iter().map(|o| &o.shape).find(|s| matches!(s, Shape::Evolved(_)))
    else {
        panic!("the combined scene has an evolved surface");
    };
    let (pair, origin) = surface.pair();
    let make = |m| EvolvedSurface::in_frame(origin, pair.c1, pair.c2, m).expect("the same surface");
    let reference = make(Method::Sampling { samples: 4096 });
    let methods = [
        ("sampling 64", make(Method::Sampling { samples: 64 })),
        ("hierarchy 64×4", make(Method::Hierarchy { leaves: 64, per_leaf: 4 })),
    ];
    let renderer = Renderer::new(&scene);
    let mut tallies: Vec<Tally> = methods.iter().map(|_| Tally::default()).collect();
    let mut count = 0;
    for j in 0..scene.camera.height {
        for i in 0..scene.camera.width {
            let primary = scene.camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5).expect("a camera ray");
            let mut rays = vec![(primary, f64::INFINITY)];
            if let Some((hit, _)) = renderer.nearest(&primary, 0.0, f64::INFINITY) {
                rays.extend(
                    Ray::leaving(hit.point, hit.normal, reflect(primary.dir, hit.normal)).map(|r| (r, f64::INFINITY)),
                );
                for light in &scene.lights {
                    let to = sub(light.position, hit.point);
                    rays.extend(Ray::leaving(hit.point, hit.normal, to).map(|r| (r, norm(to))));
                }
            }
            for (ray, t_max) in rays {
                count += 1;
                let want = reference.intersect(&ray, 0.0, t_max);
                for ((name, method), tally) in methods.iter().zip(&mut tallies) {
                    match (want, method.intersect(&ray, 0.0, t_max)) {
                        (Some(a), None) => {
                            tally.0 += 1;
                            println!("{name}: missed, pixel ({i}, {j}), t {}", a.t);
                        }
                        (None, Some(b)) => {
                            tally.1 += 1;
                            println!("{name}: false hit, pixel ({i}, {j}), t {}", b.t);
                        }
                        (Some(a), Some(b)) if (a.t - b.t).abs() > 1e-6 * a.t => {
                            tally.2 += 1;
                            println!("{name}: other root, pixel ({i}, {j}), t {} (reference {})", b.t, a.t);
                        }
                        (Some(a), Some(b)) => {
                            tally.3 = tally.3.max((a.alpha.unwrap_or(0.0) - b.alpha.unwrap_or(0.0)).abs())
                        }
                        (None, None) => {}
                    }
                }
            }
        }
    }
    for ((name, _), t) in methods.iter().zip(&tallies) {
        println!(
            "{name}: {count} rays, missed {}, false {}, other root {}, max α difference {:.1e}",
            t.0, t.1, t.2, t.3
        );
    }
}
