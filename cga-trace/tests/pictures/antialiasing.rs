//! Anti-aliasing and crop windows: the error against a many-sample reference falls as the
//! samples per pixel grow; adaptive sampling takes a pixel's first samples or all of them, as
//! their contrast decides, at nearly the error of all of them; the bytes do not depend on the
//! thread count; windows of a frame assemble into it byte for byte, adaptive or not; adaptive
//! sampling by corners (POV-Ray's method 2) traces each corner once and cuts only where
//! corners differ, at nearly the error of all the samples.

use cga_trace::integrator::Window;
use cga_trace::settings::{Adaptive, AdaptiveMethod};
use cga_trace::{Aov, Film, Renderer, Scene};
use std::path::Path;

fn scene(name: &str, w: u32, h: u32, spp: u32) -> Scene {
    let mut scene = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)).unwrap();
    scene.resize(Some(w), Some(h)).unwrap();
    scene.settings.spp = spp;
    scene
}

fn adaptive(name: &str, w: u32, h: u32, spp: u32, threshold: f64) -> Scene {
    let mut s = scene(name, w, h, spp);
    s.settings.adaptive = Some(Adaptive::threshold(threshold));
    s
}

fn corners(name: &str, w: u32, h: u32, spp: u32, threshold: f64) -> Scene {
    let mut s = scene(name, w, h, spp);
    s.settings.adaptive = Some(Adaptive { method: AdaptiveMethod::Corners, ..Adaptive::threshold(threshold) });
    s
}

/// `s` with each sample averaging `m` rays through the lens.
fn blurred(mut s: Scene, m: u32) -> Scene {
    s.settings.blur_samples = m;
    s
}

fn render(scene: &Scene, window: Window, threads: usize) -> Film {
    rendered(scene, window, threads).0
}

/// The film and the primary rays cast.
fn rendered(scene: &Scene, window: Window, threads: usize) -> (Film, u64) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    let renderer = Renderer::new(scene);
    let film = pool.install(|| renderer.render_window(Aov::Shaded, window, &|| {}));
    (film, renderer.counts().primary)
}

/// The error of a picture of `name` at `w × h` against 256 samples a pixel
/// ([`rms`]), with the primary rays it cast.
fn errors(name: &str, w: u32, h: u32) -> impl Fn(&Scene) -> (f64, u64) {
    let full = Window::full(w, h);
    let reference = render(&scene(name, w, h, 256), full.clone(), 2);
    move |s| {
        let (film, rays) = rendered(s, full.clone(), 2);
        (rms(&film, &reference), rays)
    }
}

/// Root-mean-square difference of the clipped linear values.
fn rms(a: &Film, b: &Film) -> f64 {
    let sq: f64 = (a.pixels.iter().flatten().zip(b.pixels.iter().flatten()))
        .map(|(x, y)| (x.clamp(0.0, 1.0) - y.clamp(0.0, 1.0)).powi(2))
        .sum();
    (sq / (3 * a.pixels.len()) as f64).sqrt()
}

#[test]
fn the_error_falls_as_the_samples_per_pixel_grow() {
    let (w, h) = (32, 24);
    let full = Window::full(w, h);
    let reference = render(&scene("combined.toml", w, h, 256), full.clone(), 2);
    let errors: Vec<(u32, f64)> = [1, 4, 16, 64]
        .map(|spp| (spp, rms(&render(&scene("combined.toml", w, h, spp), full.clone(), 2), &reference)))
        .into();
    println!("spp, rms error against 256 spp: {errors:?}");
    for pair in errors.windows(2) {
        assert!(pair[1].1 < pair[0].1, "{errors:?}");
    }
    // Stratified sampling beats the 1/√n of independent samples: 64 samples at least 8×
    // better than one (measured: see the output).
    assert!(errors[3].1 < errors[0].1 / 8.0, "{errors:?}");
}

#[test]
fn adaptive_pixels_take_their_first_samples_or_all_of_them() {
    // combined.toml has no lens and no area light, so a pixel's first 4 samples are those of
    // the same pixel at 4 samples, bit for bit (the same offsets, summed in the same order).
    let (w, h) = (48, 36);
    let full = Window::full(w, h);
    let (four, sixteen) = (
        render(&scene("combined.toml", w, h, 4), full.clone(), 2),
        render(&scene("combined.toml", w, h, 16), full.clone(), 2),
    );
    let kinds = |film: &Film| {
        let (mut first, mut all) = (0, 0);
        for ((p, a), b) in film.pixels.iter().zip(&four.pixels).zip(&sixteen.pixels) {
            if p == a {
                first += 1;
            } else {
                assert_eq!(p, b, "an adaptive pixel is its first 4 samples' mean or all 16's");
                all += 1;
            }
        }
        (first, all)
    };
    let (first, all) = kinds(&render(&adaptive("combined.toml", w, h, 16, 0.3), full.clone(), 2));
    println!("threshold 0.3: {first} pixels took 4 samples, {all} took 16");
    assert!(all > 0 && first > 5 * all, "edges refine, flat pixels stop: {first}, {all}");
    // Nothing exceeds the greatest contrast, 3; at 0 every pixel whose samples differ goes on.
    let (first, all) = kinds(&render(&adaptive("combined.toml", w, h, 16, 3.0), full.clone(), 2));
    assert_eq!((first, all), ((w * h) as usize, 0));
    let zero = render(&adaptive("combined.toml", w, h, 16, 0.0), full, 2);
    let (_, refined) = kinds(&zero);
    let (_, at_point_three) = kinds(&render(&adaptive("combined.toml", w, h, 16, 0.3), Window::full(w, h), 2));
    assert!(refined > at_point_three, "a lower threshold refines more: {refined}, {at_point_three}");
}

#[test]
fn adaptive_sampling_keeps_the_error_of_all_the_samples_for_fewer_rays() {
    let (w, h) = (64, 48);
    let error = errors("combined.toml", w, h);
    let ((e16, rays16), (e64, rays64)) =
        (error(&scene("combined.toml", w, h, 16)), error(&scene("combined.toml", w, h, 64)));
    let (e, rays) = error(&adaptive("combined.toml", w, h, 64, 0.1));
    println!(
        "rms against 256 spp, primary rays: 16 spp {e16:.2e} {rays16}, 64 spp {e64:.2e} {rays64}, adaptive 0.1 {e:.2e} {rays}"
    );
    // Measured: 1.32e-3 with 50,268 rays, against 9.37e-4 with 196,608 and 3.25e-3 with 49,152.
    assert!(e < 1.5 * e64 && 3 * rays < rays64, "nearly the error of 64 samples for under a third of the rays");
    assert!(e < 0.5 * e16, "under half the error of 16 samples a pixel, for about their rays");
}

#[test]
fn adaptive_packets_give_the_bits_of_one_ray_at_a_time() {
    // Packets where all four pixels go on, single rays for the lanes that do where not all do.
    for s in [
        adaptive("combined.toml", 40, 30, 16, 0.2),
        corners("combined.toml", 40, 30, 16, 0.2),
        blurred(adaptive("lens.toml", 40, 30, 16, 0.2), 3),
        blurred(corners("lens.toml", 40, 30, 16, 0.2), 4),
    ] {
        let full = Window::full(40, 30);
        let packets = Renderer::new(&s).render_window(Aov::Shaded, full.clone(), &|| {});
        for other in [Renderer::new(&s).without_packets(), Renderer::new(&s).without_avx2()] {
            assert!(other.render_window(Aov::Shaded, full.clone(), &|| {}).pixels == packets.pixels);
        }
    }
}

#[test]
fn corners_trace_each_corner_once_and_cut_only_where_corners_differ() {
    let (w, h) = (48, 36);
    let full = Window::full(w, h);
    // Nothing exceeds the greatest contrast, 3: one ray a corner, each pixel its corners'
    // mean; with no lens or area light a point's value does not depend on the grid, so any
    // spp gives the same bits.
    let (flat, rays) = rendered(&corners("combined.toml", w, h, 16, 3.0), full.clone(), 2);
    assert_eq!(rays, u64::from((w + 1) * (h + 1)));
    assert!(flat.pixels == rendered(&corners("combined.toml", w, h, 64, 3.0), full.clone(), 2).0.pixels);
    // A lower threshold cuts more squares; spp 16 cuts twice, so at most 5 × 5 points a pixel.
    let counts: Vec<u64> =
        [0.3, 0.1, 0.0].iter().map(|&t| rendered(&corners("combined.toml", w, h, 16, t), full.clone(), 2).1).collect();
    println!("primary rays at thresholds 0.3, 0.1, 0: {counts:?}");
    assert!(rays < counts[0] && counts[0] < counts[1] && counts[1] <= counts[2], "{counts:?}");
    assert!(counts[2] <= u64::from(w * h * 25), "{counts:?}");
}

#[test]
fn corners_keep_the_error_of_all_the_samples_for_fewer_rays() {
    let (w, h) = (64, 48);
    let error = errors("combined.toml", w, h);
    let ((e1, rays1), (e16, rays16)) =
        (error(&scene("combined.toml", w, h, 1)), error(&scene("combined.toml", w, h, 16)));
    let (e, rays) = error(&corners("combined.toml", w, h, 16, 0.1));
    println!(
        "rms against 256 spp, primary rays: 1 spp {e1:.2e} {rays1}, 16 spp {e16:.2e} {rays16}, corners 0.1 {e:.2e} {rays}"
    );
    assert!(e < 1.5 * e16 && 4 * rays < rays16, "nearly the error of 16 samples for under a quarter of the rays");
    assert!(e < 0.5 * e1, "under half the error of one sample a pixel");
}

#[test]
fn the_same_bytes_on_any_thread_count() {
    for s in [
        scene("combined.toml", 40, 30, 4),
        adaptive("combined.toml", 40, 30, 16, 0.2),
        corners("combined.toml", 40, 30, 16, 0.2),
        blurred(corners("lens.toml", 40, 30, 16, 0.2), 4),
    ] {
        let one = render(&s, Window::full(40, 30), 1);
        let two = render(&s, Window::full(40, 30), 2);
        assert_eq!(one.to_rgb8(s.settings.encoding).into_raw(), two.to_rgb8(s.settings.encoding).into_raw());
        assert_eq!(one.pixels, two.pixels, "the linear values too, bit for bit");
    }
}

#[test]
fn crop_windows_assemble_into_the_frame_byte_for_byte() {
    let (w, h) = (41, 29);
    crop_windows_assemble(&scene("combined.toml", w, h, 4));
    crop_windows_assemble(&adaptive("combined.toml", w, h, 16, 0.2));
    crop_windows_assemble(&corners("combined.toml", w, h, 16, 0.2));
    crop_windows_assemble(&blurred(corners("lens.toml", w, h, 16, 0.2), 4));
}

#[test]
fn blur_samples_let_corners_take_a_lens_blur_for_what_it_is() {
    // POV-Ray's focal blur with +AM2: each corner the mean of 16 lens rays, so the corners of a
    // blurred region agree and are not cut; one lens ray a corner looks like noise everywhere.
    let (w, h) = (64, 48);
    let error = errors("lens.toml", w, h);
    let (e16, rays16) = error(&scene("lens.toml", w, h, 16));
    let (e32, rays32) = error(&scene("lens.toml", w, h, 32));
    let (e1, rays1) = error(&corners("lens.toml", w, h, 4, 0.3));
    let (e, rays) = error(&blurred(corners("lens.toml", w, h, 4, 0.3), 16));
    println!(
        "rms against 256 spp, primary rays: 16 spp {e16:.2e} {rays16}, 32 spp {e32:.2e} {rays32}, corners 0.3 {e1:.2e} {rays1}, with blur_samples 16 {e:.2e} {rays}"
    );
    assert!(e < e32 && rays < rays32, "{e} against {e32}, {rays} rays against {rays32}");
    assert!(e < 0.5 * e1, "{e} against one lens ray a corner's {e1}");
    // Plain samples: spp 4 with 4 lens rays each cast the rays of 16 samples.
    let (e4, rays4) = error(&blurred(scene("lens.toml", w, h, 4), 4));
    assert_eq!(rays4, rays16);
    assert!(e4 < 1.5 * e16, "{e4} against {e16}");
    // Without a lens there is one ray a sample: the same bits as without blur_samples.
    let pinhole = scene("combined.toml", 24, 18, 4);
    assert!(
        render(&blurred(pinhole.clone(), 8), Window::full(24, 18), 2).pixels
            == render(&pinhole, Window::full(24, 18), 2).pixels
    );
    // Over a transparent background a sample's coverage is the fraction of its rays that met
    // something: strictly between 0 and 1 where the lens blurs an edge against nothing.
    let mut clear = blurred(scene("lens.toml", 32, 24, 1), 8);
    clear.settings.set_background(cga_trace::settings::Background::Transparent);
    let coverage = render(&clear, Window::full(32, 24), 2).coverage.unwrap();
    assert!(coverage.iter().any(|&c| c > 0.0 && c < 1.0), "a blurred edge is partly covered");
    assert!(coverage.iter().all(|&c| (0.0..=1.0).contains(&c)));
}

fn crop_windows_assemble(s: &Scene) {
    let (w, h) = (s.camera.width, s.camera.height);
    let frame = render(s, Window::full(w, h), 2).to_rgb8(s.settings.encoding);
    let mut assembled = image::RgbImage::new(w, h);
    let cuts = [0.0, 0.3, 0.71, 1.0];
    for x in cuts.windows(2) {
        for y in cuts.windows(2) {
            let window = Window::crop(w, h, [x[0], x[1], y[0], y[1]]).unwrap();
            let piece = render(s, window.clone(), 1).to_rgb8(s.settings.encoding);
            // The piece's top-left pixel is column `columns.start`, row `h − rows.end` from the top.
            image::imageops::replace(
                &mut assembled,
                &piece,
                i64::from(window.columns.start),
                i64::from(h - window.rows.end),
            );
        }
    }
    assert_eq!(assembled.into_raw(), frame.into_raw());
}
