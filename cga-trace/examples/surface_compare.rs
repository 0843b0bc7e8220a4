//! Compare surface-intersection methods ray by ray against a dense reference.
use cga_trace::scene::Scene;
use cga_trace::shapes::Shape;
use cga_trace::surface::{EvolvedSurface, Method};
fn main() {
    let scene = Scene::load(std::path::Path::new("cga-trace/scenes/combined.toml")).unwrap();
    let Some(Shape::Evolved(s)) = scene.objects.iter().map(|o| &o.shape).find(|s| matches!(s, Shape::Evolved(_)))
    else {
        panic!()
    };
    let (pair, origin) = s.pair();
    let make = |m| EvolvedSurface::in_frame(origin, pair.c1, pair.c2, m).unwrap();
    let reference = make(Method::Sampling { samples: 4096 });
    let methods = [
        ("sampling64", make(Method::Sampling { samples: 64 })),
        ("hier64x4", make(Method::Hierarchy { leaves: 64, per_leaf: 4 })),
    ];
    let (w, h) = (320u32, 240u32);
    let mut stats = vec![(0, 0, 0, 0.0f64); methods.len()];
    let mut n = 0;
    for j in 0..h {
        for i in 0..w {
            let primary = scene.camera.ray(i as f64 + 0.5, j as f64 + 0.5).unwrap();
            let mut rays = vec![(primary, f64::INFINITY)];
            let r = cga_trace::Renderer::new(&scene);
            if let Some((hit, _)) = r.nearest(&primary, 0.0, f64::INFINITY) {
                let d = primary.dir;
                let n_ = hit.normal;
                let dn = d[0] * n_[0] + d[1] * n_[1] + d[2] * n_[2];
                let refl = [d[0] - 2.0 * dn * n_[0], d[1] - 2.0 * dn * n_[1], d[2] - 2.0 * dn * n_[2]];
                if let Some(rr) = cga_trace::ray::Ray::leaving(hit.point, n_, refl) {
                    rays.push((rr, f64::INFINITY));
                }
                let l = scene.lights[0].position;
                let to = [l[0] - hit.point[0], l[1] - hit.point[1], l[2] - hit.point[2]];
                let dist = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
                if let Some(sr) = cga_trace::ray::Ray::leaving(hit.point, n_, to) {
                    rays.push((sr, dist));
                }
            }
            for (ray, tmax) in rays {
                let want = reference.intersect(&ray, 0.0, tmax);
                n += 1;
                for (k, (name, m)) in methods.iter().enumerate() {
                    let got = m.intersect(&ray, 0.0, tmax);
                    match (want, got) {
                        (Some(a), None) => {
                            stats[k].0 += 1;
                            if stats[k].0 <= 3 {
                                println!("{name} MISS ({i},{j}) want t {} α {:?}", a.t, a.alpha);
                            }
                        }
                        (None, Some(b)) => {
                            stats[k].1 += 1;
                            if stats[k].1 <= 3 {
                                println!("{name} FALSE ({i},{j}) got t {} α {:?}", b.t, b.alpha);
                            }
                        }
                        (Some(a), Some(b)) => {
                            let e = (a.alpha.unwrap() - b.alpha.unwrap()).abs();
                            if (a.t - b.t).abs() > 1e-6 * a.t {
                                stats[k].2 += 1;
                                if stats[k].2 <= 3 {
                                    println!(
                                        "{name} OTHER ({i},{j}) want t {} α {:?} got t {} α {:?}",
                                        a.t, a.alpha, b.t, b.alpha
                                    );
                                }
                            } else {
                                stats[k].3 = stats[k].3.max(e);
                            }
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    for (k, (name, _)) in methods.iter().enumerate() {
        println!(
            "{name}: {n} rays, missed {}, false {}, other root {}, max α err {:.1e}",
            stats[k].0, stats[k].1, stats[k].2, stats[k].3
        );
    }
}
