//! Anti-aliasing and crop windows: the error against a many-sample reference falls as the
//! samples per pixel grow; the bytes do not depend on the thread count; windows of a frame
//! assemble into it byte for byte.

use cga_trace::integrator::Window;
use cga_trace::{Aov, Film, Renderer, Scene};
use std::path::Path;

fn scene(name: &str, w: u32, h: u32, spp: u32) -> Scene {
    let mut scene = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)).unwrap();
    scene.resize(Some(w), Some(h)).unwrap();
    scene.settings.spp = spp;
    scene
}

fn render(scene: &Scene, window: Window, threads: usize) -> Film {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| Renderer::new(scene).render_window(Aov::Shaded, window, &|| {}))
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
fn the_same_bytes_on_any_thread_count() {
    let s = scene("combined.toml", 40, 30, 4);
    let one = render(&s, Window::full(40, 30), 1);
    let two = render(&s, Window::full(40, 30), 2);
    assert_eq!(one.to_rgb8(s.settings.encoding).into_raw(), two.to_rgb8(s.settings.encoding).into_raw());
    assert_eq!(one.pixels, two.pixels, "the linear values too, bit for bit");
}

#[test]
fn crop_windows_assemble_into_the_frame_byte_for_byte() {
    let (w, h) = (41, 29);
    let s = scene("combined.toml", w, h, 4);
    let frame = render(&s, Window::full(w, h), 2).to_rgb8(s.settings.encoding);
    let mut assembled = image::RgbImage::new(w, h);
    let cuts = [0.0, 0.3, 0.71, 1.0];
    for x in cuts.windows(2) {
        for y in cuts.windows(2) {
            let window = Window::crop(w, h, [x[0], x[1], y[0], y[1]]).unwrap();
            let piece = render(&s, window.clone(), 1).to_rgb8(s.settings.encoding);
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
