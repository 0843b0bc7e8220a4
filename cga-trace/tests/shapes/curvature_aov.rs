//! The curvature AOVs: on a surface of co-spherical circles (a piece of their sphere) every
//! pixel shows K = 1/R² and H = 1/R in world units — also with the scene moved far away and
//! scaled — and the false-colour image carries its scale.

use cga_trace::colour::false_colour;
use cga_trace::{Aov, Renderer, Scene};

/// Two circles on the sphere of radius `r` about `c`, seen from outside, everything scaled
/// by `s` and moved by `c`.
fn scene(c: [f64; 3], s: f64, r: f64) -> Scene {
    let at = |x: [f64; 3]| format!("[{}, {}, {}]", c[0] + s * x[0], c[1] + s * x[1], c[2] + s * x[2]);
    // Circles of the sphere in the planes z = ±0.4 r (normal z) and x = 0.3 r (normal x).
    let (h1, h2) = (0.4 * r, 0.3 * r);
    let text = format!(
        "[camera]\nposition = {}\nlook_at = {}\nwidth = 32\nheight = 24\nfov = 60.0\n\
         [[objects]]\nname = \"s\"\ntype = \"evolved\"\nmaterial = {{ colour = [1.0, 1.0, 1.0] }}\n\
         c1 = {{ centre = {}, normal = [0.0, 0.0, 1.0], radius = {} }}\n\
         c2 = {{ centre = {}, normal = [1.0, 0.0, 0.0], radius = {} }}\n",
        at([3.0 * r, -4.0 * r, 1.0 * r]),
        at([0.0; 3]),
        at([0.0, 0.0, -h1]),
        s * (r * r - h1 * h1).sqrt(),
        at([h2, 0.0, 0.0]),
        s * (r * r - h2 * h2).sqrt(),
    );
    Scene::parse(&text, "sphere.toml").unwrap()
}

#[test]
fn a_piece_of_a_sphere_shows_its_curvature_in_world_units() {
    for (c, s) in [([0.0; 3], 1.0), ([1e4, -2e4, 5e3], 1.0), ([3.0, 1.0, 2.0], 1e-3), ([0.0; 3], 1e3)] {
        let r = 2.0;
        let scene = scene(c, s, r);
        for (aov, want) in [(Aov::Gaussian, 1.0 / (s * r * s * r)), (Aov::Mean, 1.0 / (s * r)), (Aov::Postulate, 0.0)] {
            let film = Renderer::new(&scene).render(aov, &|| {});
            let values: Vec<f64> = film.pixels.iter().filter(|p| p[1] > 0.0).map(|p| p[0] / p[1]).collect();
            assert!(values.len() > 50, "{aov:?}: {} pixels on the surface", values.len());
            // H's sign: positive where the outside of the sphere is seen, negative through
            // the zone's openings, where its inside is.
            let positive = values.iter().filter(|v| **v > 0.0).count();
            let worst = values.iter().map(|v| (v.abs() - want).abs() / want.abs().max(1.0)).fold(0.0, f64::max);
            if aov == Aov::Mean {
                println!("H > 0 at {positive} of {} pixels (the rest see the zone's inside)", values.len());
            }
            assert!(worst < 1e-8, "{aov:?} at {c:?} ×{s}: {worst:e} off {want}");
            let (coloured, scale) = false_colour(&film, aov).unwrap();
            assert_eq!(scale.pixels, values.len());
            assert!(coloured.pixels.iter().flatten().all(|x| x.is_finite()));
        }
    }
}
