//! Ruled surfaces of interpolated point pairs and lines: exact hits (the cubic and quartic of
//! `cga-trace/src/surface/ruled.rs`) against a dense reference that samples the Plücker form
//! on the interpolated rulings themselves, analytic normals against finite differences of
//! the Euclidean surface, and shadows in the shipped scene.

use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_trace::ray::Ray;
use cga_trace::shapes::{Crossing, Shape};
use cga_trace::surface::{RuledSurface, Rulings};
use cga_trace::{Aov, Renderer, Scene};
use rand::{RngExt, SeedableRng};
use rand_xorshift::XorShiftRng;

use crate::common;

use common::swept::ruling;

/// The reference: `common::swept`'s sampled Plücker form, over every `t > 0`.
fn reference(surface: &RuledSurface, ray: &Ray, n: usize) -> Option<(f64, f64)> {
    common::swept::ruled_reference(surface, ray, n, 0.0, f64::INFINITY)
}

fn surfaces() -> Vec<(&'static str, RuledSurface)> {
    let scene = Scene::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/ruled.toml")).unwrap();
    let mut out: Vec<(&str, RuledSurface)> = Vec::new();
    for (name, object) in [("band (point pairs)", "band"), ("sheet (lines)", "sheet")] {
        let shape = &scene.objects.iter().find(|o| &*o.name == object).unwrap().shape;
        out.push((name, shape.downcast_ref::<RuledSurface>().unwrap().clone()));
    }
    out.push((
        "twisted pairs",
        RuledSurface::point_pairs([0.0; 3], [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[0.0, -1.0, 2.0], [0.0, 1.0, 2.0]])
            .unwrap(),
    ));
    out.push((
        "skew lines",
        RuledSurface::lines(
            [0.0; 3],
            ([-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
            ([0.0; 3], 3.0),
        )
        .unwrap(),
    ));
    out
}

/// Rays per surface (a debug build samples the reference 1,024 times per ray).
const RAYS: usize = 150;

#[test]
fn hits_agree_with_a_dense_reference() {
    compare(RAYS, 1024);
}

/// 5,000 rays per surface against 16,384 samples, with the time per ray of each (the table
/// in docs/SURFACE.md): `cargo test --release -p cga-trace --test shapes ruled_surface:: -- --ignored
/// --nocapture`.
#[test]
#[ignore]
fn hits_agree_with_a_dense_reference_report() {
    compare(5000, 16_384);
}

fn compare(per_surface: usize, samples: usize) {
    use std::time::Instant;
    let mut rng = XorShiftRng::seed_from_u64(3);
    let (mut rays, mut hits, mut worst_alpha) = (0, 0, 0.0f64);
    println!(
        "| surface | rays | hits | missed | false | polynomial ns/ray | reference ns/ray |\n|---|---|---|---|---|---|---|"
    );
    for (name, surface) in surfaces() {
        let (c, r) = surface.bounds();
        let (mut missed, mut false_hits, mut own_hits) = (0, 0, 0);
        let mut test_rays = Vec::new();
        for _ in 0..per_surface {
            // From outside the bound, at a random point inside it.
            let d =
                unit([rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)]).unwrap();
            let target =
                add(c, [rng.random_range(-r..r), rng.random_range(-r..r), rng.random_range(-r..r)].map(|x| 0.6 * x));
            test_rays.push(Ray::new(sub(target, scale(d, 3.0 * r)), d).unwrap());
        }
        let start = Instant::now();
        let wants: Vec<_> = test_rays.iter().map(|ray| reference(&surface, ray, samples)).collect();
        let reference_time = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let gots: Vec<_> = test_rays.iter().map(|ray| surface.intersect(ray, 0.0, f64::INFINITY)).collect();
        let own_time = start.elapsed().as_secs_f64();
        for (want, got) in wants.into_iter().zip(gots) {
            rays += 1;
            match (want, got) {
                (Some((t, alpha)), Some(got)) => {
                    (hits, own_hits) = (hits + 1, own_hits + 1);
                    if (t - got.t).abs() > 1e-9 * t.max(1.0) {
                        // Sampling steps over close root pairs; the polynomial's root must be nearer.
                        assert!(got.t < t, "{name}: t {} against the reference's {t}", got.t);
                    } else {
                        worst_alpha = worst_alpha.max((alpha - got.alpha.unwrap()).abs());
                    }
                }
                (Some(_), None) => missed += 1,
                (None, Some(_)) => false_hits += 1,
                (None, None) => {}
            }
        }
        let per = |s: f64| s * 1e9 / per_surface as f64;
        println!(
            "| {name} | {per_surface} | {own_hits} | {missed} | {false_hits} | {:.0} | {:.0} |",
            per(own_time),
            per(reference_time)
        );
        assert_eq!((missed, false_hits), (0, 0), "{name}");
    }
    println!("{rays} rays, {hits} hits: 0 missed, 0 false; worst α difference {worst_alpha:.1e}");
    assert!(worst_alpha <= 1e-9 && hits > rays / 5, "{worst_alpha:e}, {hits} hits");
}

#[test]
fn normals_match_finite_differences() {
    let mut rng = XorShiftRng::seed_from_u64(4);
    let mut worst = 0.0f64;
    for (name, surface) in surfaces() {
        let o = surface.origin();
        for _ in 0..200 {
            let alpha = rng.random_range(0.05..0.95);
            let Some((_, p, u, (s0, s1))) = ruling(&surface, alpha) else { continue };
            let s = s0 + (s1 - s0) * rng.random_range(0.1..0.9);
            let x = add(p, scale(u, s));
            // ∂x/∂α along the ruling's own parameter (for pairs, the fraction of the segment;
            // for lines, the distance from the closest point to the bound's centre), Richardson.
            let point_at = |a: f64| -> Option<E3> {
                let (_, p, u, (s0, s1)) = ruling(&surface, a)?;
                let f = (s - s0) / (s1 - s0);
                Some(add(p, scale(u, s0 + f * (s1 - s0))))
            };
            let d = |h: f64| Some(scale(sub(point_at(alpha + h)?, point_at(alpha - h)?), 0.5 / h));
            let (Some(d1), Some(d2)) = (d(1e-4), d(5e-5)) else { continue };
            let along = add(scale(d1, -1.0 / 3.0), scale(d2, 4.0 / 3.0));
            let Some(fd) = unit(cross(along, u)) else { continue };
            let n = surface.normal(&Crossing { t: 0.0, point: add(x, o), alpha: Some(alpha), part: 0 });
            let angle = norm(cross(n, fd)).atan2(dot(n, fd).abs());
            worst = worst.max(angle);
            assert!(angle < 1e-7, "{name}: α = {alpha}: {angle:e} rad");
        }
    }
    println!("worst angle to the finite-difference normal: {worst:.1e} rad");
}

#[test]
fn ruled_surfaces_cast_shadows_and_reflect() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/ruled.toml");
    let mut scene = Scene::load(&path).unwrap();
    scene.resize(Some(80), None).unwrap();
    let lit = Renderer::new(&scene).render(Aov::Shaded, &|| {});
    scene.settings.shadows = false;
    let unshadowed = Renderer::new(&scene).render(Aov::Shaded, &|| {});
    scene.settings.shadows = true;
    scene.settings.max_depth = 0;
    let unreflected = Renderer::new(&scene).render(Aov::Shaded, &|| {});
    let differ = |a: &cga_trace::Film, b: &cga_trace::Film| {
        a.pixels
            .iter()
            .zip(&b.pixels)
            .filter(|(x, y)| x.iter().zip(y.iter()).any(|(p, q)| (p - q).abs() > 0.02))
            .count()
    };
    assert!(lit.pixels.iter().flatten().all(|x| x.is_finite()));
    let (shadowed, reflected) = (differ(&lit, &unshadowed), differ(&lit, &unreflected));
    println!("{shadowed} pixels in shadow, {reflected} showing reflections");
    assert!(shadowed > 100 && reflected > 100);
}

/// Curvature of ruled surfaces (exact second derivatives of the rulings) against central
/// differences of the Euclidean surface `x(α, v) = a(α) + v (b(α) − a(α))` (point pairs) or
/// `p(α) + v d(α)` (lines; p the ruling's point nearest the local origin): `K ≤ 0` always.
#[test]
fn curvature_matches_finite_differences() {
    let mut rng = XorShiftRng::seed_from_u64(5);
    let mut worst = 0.0f64;
    for (name, surface) in surfaces() {
        let o = surface.origin();
        let param = |a: f64, v: f64| -> Option<E3> {
            match surface.rulings() {
                Rulings::PointPairs(pair) => {
                    let [p, q] = pair.at(a).ok()?.end_points().ok()?;
                    Some(add(p, scale(sub(q, p), v)))
                }
                Rulings::Lines { pair, .. } => {
                    let l = pair.at(a).ok()?;
                    Some(add(l.point().ok()?, scale(l.direction().ok()?, v)))
                }
            }
        };
        for _ in 0..100 {
            let alpha = rng.random_range(0.1..0.9);
            let v = match surface.rulings() {
                Rulings::PointPairs(_) => rng.random_range(0.1..0.9),
                Rulings::Lines { .. } => rng.random_range(-1.0..1.0),
            };
            let Some(x) = param(alpha, v) else { continue };
            let Some(k) = surface.curvature_at(alpha, add(x, o)) else { continue };
            let fd = |h: f64| -> Option<(f64, f64)> {
                let (p, pa, pm) = (param(alpha, v)?, param(alpha + h, v)?, param(alpha - h, v)?);
                let (va, vm) = (param(alpha, v + h)?, param(alpha, v - h)?);
                let (pp, p_m, m_p, mm) = (
                    param(alpha + h, v + h)?,
                    param(alpha + h, v - h)?,
                    param(alpha - h, v + h)?,
                    param(alpha - h, v - h)?,
                );
                let x_a = scale(sub(pa, pm), 0.5 / h);
                let x_v = scale(sub(va, vm), 0.5 / h);
                let x_aa = scale(add(sub(pa, scale(p, 2.0)), pm), 1.0 / (h * h));
                let x_av = scale(add(sub(pp, p_m), sub(mm, m_p)), 0.25 / (h * h));
                let nu = unit(cross(x_a, x_v))?;
                let (e, f, g) = (dot(x_a, x_a), dot(x_a, x_v), dot(x_v, x_v));
                let (l, m) = (dot(x_aa, nu), dot(x_av, nu));
                let det = e * g - f * f;
                Some((-m * m / det, (g * l - 2.0 * f * m) / (2.0 * det)))
            };
            let (Some(a), Some(b)) = (fd(1e-3), fd(5e-4)) else { continue };
            let (fd_k, fd_h) = ((4.0 * b.0 - a.0) / 3.0, (4.0 * b.1.abs() - a.1.abs()) / 3.0);
            let s = k.k[0].abs().max(k.k[1].abs());
            assert!(k.gaussian <= 1e-12 * s * s, "{name}: K = {} > 0 on a ruled surface", k.gaussian);
            worst = worst.max((k.gaussian - fd_k).abs() / (s * s)).max((k.mean.abs() - fd_h).abs() / s);
        }
    }
    println!("ruled surfaces: K and |H| within {worst:.1e} (of k_max², k_max) of finite differences");
    assert!(worst < 1e-6, "{worst:e}");
}
