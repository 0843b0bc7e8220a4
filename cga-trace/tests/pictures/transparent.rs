//! Transparent backgrounds (`background = "transparent"`): each pixel's alpha is the fraction
//! of its samples whose camera ray meets something — against the area of a disk in each
//! pixel, under adaptive sampling, through a shutter and a lens — written as PNG (straight
//! colours) and EXR (premultiplied) and read back with the `image` crate; labels opaque,
//! glass opaque, the environment seen only in reflections, and HDR refused.

use cga_trace::film::Output;
use cga_trace::pipeline::Rendered;
use cga_trace::{Aov, Film, Options, Pipeline, View};
use std::path::Path;

/// An object lit by the ambient light alone (with `ambient = 1`): its colour exactly.
const FLAT: &str = "ka = 1.0, kd = 0.0, ks = 0.0";

/// An orthographic view of 10 pixels a unit, `size` pixels square, looking along +y at the
/// origin (so the origin is the corner shared by the middle four pixels).
fn camera(size: u32) -> String {
    format!(
        "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\n\
         view_width = {:?}\nwidth = {size}\nheight = {size}\n",
        f64::from(size) / 10.0
    )
}

/// A sphere of `radius` at the origin in `colour`, with `render` as the `[render]` table.
fn ball(size: u32, radius: f64, colour: [f64; 3], render: &str) -> String {
    format!(
        "{}[render]\nambient = 1.0\n{render}\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = {radius:?}\n\
         material = {{ colour = {colour:?}, {FLAT} }}\n",
        camera(size)
    )
}

/// `text`'s picture with `options` through its pipeline.
fn rendered(text: &str, options: &Options) -> Rendered {
    let mut pipeline = Pipeline::parse(text, "transparent.toml", View::default()).unwrap();
    let scene = pipeline.scene(0.0).unwrap();
    pipeline.render(&scene, options, &|| {}).unwrap()
}

/// `text`'s film.
fn film(text: &str) -> Film {
    rendered(text, &Options::default()).film
}

/// The area of the disk of radius `r` about `(cx, cy)` inside the unit square at `(i, j)`,
/// by the midpoint rule over 20,000 columns of the chord's overlap (error below 1e-6).
fn disk_in_pixel(cx: f64, cy: f64, r: f64, i: u32, j: u32) -> f64 {
    let (x0, y0) = (f64::from(i), f64::from(j));
    let n = 20_000;
    (0..n)
        .map(|k| {
            let x = x0 + (f64::from(k) + 0.5) / f64::from(n);
            let h = (r * r - (x - cx) * (x - cx)).max(0.0).sqrt();
            ((cy + h).min(y0 + 1.0) - (cy - h).max(y0)).max(0.0)
        })
        .sum::<f64>()
        / f64::from(n)
}

/// The coverage of each pixel of a `size`² picture of a sphere of `radius` units at the
/// origin, seen as [`camera`] sees it: a disk of `10 radius` pixels about the middle.
fn analytic(size: u32, radius: f64) -> Vec<f64> {
    let c = f64::from(size) / 2.0;
    (0..size).flat_map(|j| (0..size).map(move |i| disk_in_pixel(c, c, 10.0 * radius, i, j))).collect()
}

/// The largest and RMS differences between `coverage` and `want` over the pixels the disk's
/// edge crosses, and how many those are.
fn edge_error(coverage: &[f64], want: &[f64]) -> (f64, f64, usize) {
    let edge: Vec<f64> =
        coverage.iter().zip(want).filter(|(_, w)| **w > 0.0 && **w < 1.0).map(|(a, w)| (a - w).abs()).collect();
    let rms = (edge.iter().map(|d| d * d).sum::<f64>() / edge.len() as f64).sqrt();
    (edge.iter().copied().fold(0.0, f64::max), rms, edge.len())
}

#[test]
fn a_silhouettes_coverage_is_the_area_of_the_disk_in_each_pixel() {
    // A white ball of radius 1.23 (12.3 pixels) at 64 samples a pixel: inside exactly 1,
    // outside exactly 0, along the edge the disk's area in the pixel to the error of 64
    // stratified samples (measured: largest 0.049, RMS 0.016 over 100 pixels).
    let (size, radius) = (40, 1.23);
    let text = ball(size, radius, [1.0; 3], "spp = 64\nbackground = \"transparent\"");
    let film = film(&text);
    let coverage = film.coverage.as_ref().expect("a transparent picture carries its coverage");
    let want = analytic(size, radius);
    for (k, (a, w)) in coverage.iter().zip(&want).enumerate() {
        if *w == 1.0 || *w == 0.0 {
            assert_eq!(a, w, "pixel {k}: wholly {}", if *w == 1.0 { "inside" } else { "outside" });
        }
        // White lit by 1: the premultiplied colour is the coverage, bit for bit.
        assert_eq!(film.pixels[k], [*a; 3], "pixel {k}: premultiplied");
    }
    let (worst, rms, edge) = edge_error(coverage, &want);
    println!("coverage of {edge} edge pixels against the disk's area: largest {worst:.4}, RMS {rms:.4}");
    assert!(edge > 70, "{edge}");
    assert!(worst < 0.08 && rms < 0.025, "largest {worst}, RMS {rms}");
    assert!(coverage.iter().filter(|a| **a > 0.0 && **a < 1.0).count() > 60, "fractional alpha along the edge");
    // The coverage AOV counts the same rays its own way; packets, AVX2 or not, the same bits.
    let aov = rendered(&text, &Options { aov: Aov::Coverage, ..Options::default() }).film;
    assert!(aov.coverage.is_none(), "an AOV picture is opaque");
    assert!(aov.pixels.iter().zip(coverage).all(|(p, a)| p[0] == *a));
    for options in [Options { packets: false, ..Options::default() }, Options { avx2: false, ..Options::default() }] {
        assert_eq!(rendered(&text, &options).film, film, "{options:?}");
    }
    // The same scene over a colour: no coverage, the colours of old.
    let opaque = self::film(&text.replace("background = \"transparent\"", "background = [0.0, 0.0, 0.0]"));
    assert!(opaque.coverage.is_none());
    assert_eq!(opaque.pixels, film.pixels, "over black, premultiplied colours are the opaque ones");
}

#[test]
fn adaptive_sampling_refines_edges_against_nothing_whatever_their_colour() {
    // A black ball: over a transparent background its edge has no colour contrast, only
    // coverage, and adaptive sampling must still refine it.
    let (size, radius) = (40, 1.23);
    let adaptive = "spp = 64\nadaptive = { threshold = 0.3, min_spp = 4 }";
    let text = ball(size, radius, [0.0; 3], &format!("{adaptive}\nbackground = \"transparent\""));
    let picture = rendered(&text, &Options::default());
    let pixels = u64::from(size * size);
    assert!(picture.counts.primary > 4 * pixels + 60 * 50, "edges refined: {} primary rays", picture.counts.primary);
    let coverage = picture.film.coverage.as_ref().unwrap();
    let (worst, rms, _) = edge_error(coverage, &analytic(size, radius));
    println!("adaptive coverage along the edge: largest {worst:.4}, RMS {rms:.4}");
    assert!(worst < 0.08 && rms < 0.025, "largest {worst}, RMS {rms}");
    // Over black, the same ball shows no contrast at all: every pixel takes its first 4.
    let opaque = rendered(&ball(size, radius, [0.0; 3], adaptive), &Options::default());
    assert_eq!(opaque.counts.primary, 4 * pixels);
}

#[test]
fn through_a_shutter_the_coverage_is_the_share_of_the_time_covered() {
    // A ball of radius ½ moving from x = −2 to x = 2 over the shutter (20 pixels a unit): a
    // pixel of its path's middle row is covered for |[x − ½, x + ½] ∩ [−2, 2]| / 4 of the
    // time. The colour (white, lit by 1) is premultiplied: it equals the coverage.
    let text = "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\n\
                view_width = 8.0\nwidth = 160\nheight = 20\nshutter = [0.0, 1.0]\n\
                [render]\nambient = 1.0\nspp = 64\nbackground = \"transparent\"\n\
                [[objects]]\ntype = \"sphere\"\ncentre = [-2.0, 0.0, 0.0]\nradius = 0.5\n\
                material = { colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0 }\n\
                motion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, -2, 0, 0, 0]]\n";
    let film = film(text);
    let coverage = film.coverage.as_ref().unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..160 {
        let x = -4.0 + (f64::from(i) + 0.5) / 20.0;
        let want = ((x + 0.5).min(2.0) - (x - 0.5).max(-2.0)).max(0.0) / 4.0;
        worst = worst.max((coverage[10 * 160 + i as usize] - want).abs());
    }
    println!("coverage along the path: largest difference {worst:.4}");
    assert!(worst < 1.0 / 64.0 + 1.0 / 80.0 + 1e-3, "{worst}");
    assert!(film.pixels.iter().zip(coverage).all(|(p, a)| p[0] == *a), "premultiplied");
    // The coverage AOV through the same shutter: the same samples at the same instants.
    let aov = rendered(text, &Options { aov: Aov::Coverage, ..Options::default() }).film;
    assert!(aov.pixels.iter().zip(coverage).all(|(p, a)| p[0] == *a));
}

#[test]
fn through_a_lens_the_coverage_is_blurred_as_the_picture_is() {
    // A ball nearer than the plane of focus: its edge blurs over a band of pixels, in the
    // alpha as in the colours, each sample's lens point the same for both.
    let text = "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 20.0\nwidth = 48\nheight = 48\n\
                aperture = 0.3\nfocus_distance = 20.0\n\
                [render]\nambient = 1.0\nspp = 32\nbackground = \"transparent\"\n\
                [[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n\
                material = { colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0 }\n";
    let blurred = film(text);
    let coverage = blurred.coverage.as_ref().unwrap();
    let aov = rendered(text, &Options { aov: Aov::Coverage, ..Options::default() }).film;
    assert!(aov.pixels.iter().zip(coverage).all(|(p, a)| p[0] == *a), "the AOV's coverage");
    let fractional = |c: &[f64]| c.iter().filter(|a| **a > 0.0 && **a < 1.0).count();
    let pinhole = film(&text.replace("aperture = 0.3", "aperture = 0.0"));
    let (wide, sharp) = (fractional(coverage), fractional(pinhole.coverage.as_ref().unwrap()));
    println!("pixels of fractional alpha: {wide} through the lens, {sharp} through a pinhole");
    assert!(wide > 2 * sharp, "{wide} against {sharp}");
}

/// A ball of linear colour (0.8, 0.4, 0.2) at 16 samples a pixel over a transparent
/// background, and its picture.
fn orange() -> (Rendered, [f64; 3]) {
    let colour = [0.8, 0.4, 0.2];
    (rendered(&ball(40, 1.23, colour, "spp = 16\nbackground = \"transparent\""), &Options::default()), colour)
}

/// The film's pixel `(i, j)` (from the bottom) of an image read back (rows from the top).
fn top_down(film: &Film, i: u32, j: u32) -> (u32, u32) {
    (i, film.height - 1 - j)
}

#[test]
fn png_holds_straight_colours_and_the_coverage_as_alpha() {
    let (picture, colour) = orange();
    let film = &picture.film;
    let coverage = film.coverage.as_ref().unwrap();
    let dir = tempfile::tempdir().unwrap();
    for (bits, scale) in [(8u8, 255.0), (16, 65535.0)] {
        let path = dir.path().join(format!("ball{bits}.png"));
        picture.save(&path, Some(bits)).unwrap();
        let read = image::open(&path).unwrap();
        let want_type = if bits == 8 { image::ColorType::Rgba8 } else { image::ColorType::Rgba16 };
        assert_eq!(read.color(), want_type, "{bits}-bit RGBA");
        let read = read.into_rgba16();
        let level = |v: f64| (cga_trace::film::encode(v, cga_trace::Encoding::Srgb) * scale + 0.5).floor();
        let (mut edges, mut misses) = (0, 0);
        for j in 0..film.height {
            for i in 0..film.width {
                let a = coverage[(j * film.width + i) as usize];
                let (x, y) = top_down(film, i, j);
                // 8-bit levels read back as 16-bit ones (times 257).
                let px = read.get_pixel(x, y).0.map(|v| f64::from(v) / if bits == 8 { 257.0 } else { 1.0 });
                assert_eq!(px[3], (a * scale + 0.5).floor(), "({i}, {j}): alpha is the coverage");
                if a == 0.0 {
                    assert_eq!(px, [0.0; 4], "nothing there: transparent black");
                    misses += 1;
                    continue;
                }
                // Straight colours: the ball's own, however little of the pixel it covers
                // (to rounding where the mean is divided by the coverage again).
                for c in 0..3 {
                    assert!((px[c] - level(colour[c])).abs() <= 1.0, "({i}, {j}) channel {c}: {px:?}");
                }
                edges += usize::from(a < 1.0);
            }
        }
        assert!(edges > 60 && misses > 100, "{edges} edge pixels, {misses} empty");
    }
}

#[test]
fn exr_holds_premultiplied_colours_and_the_coverage_as_alpha() {
    let (picture, colour) = orange();
    let film = &picture.film;
    let coverage = film.coverage.as_ref().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ball.exr");
    picture.save(&path, None).unwrap();
    let read = image::open(&path).unwrap();
    assert_eq!(read.color(), image::ColorType::Rgba32F, "an A channel");
    let read = read.into_rgba32f();
    let mut edges = 0;
    for j in 0..film.height {
        for i in 0..film.width {
            let k = (j * film.width + i) as usize;
            let (x, y) = top_down(film, i, j);
            let px = read.get_pixel(x, y).0;
            assert_eq!(px[3], coverage[k] as f32, "({i}, {j}): A is the coverage");
            for c in 0..3 {
                assert_eq!(px[c], film.pixels[k][c] as f32);
                // Premultiplied (associated): the colour times the coverage.
                assert!((f64::from(px[c]) - colour[c] * coverage[k]).abs() < 1e-6, "({i}, {j}): {px:?}");
            }
            edges += usize::from(coverage[k] > 0.0 && coverage[k] < 1.0);
        }
    }
    assert!(edges > 60, "{edges}");
}

#[test]
fn labels_are_opaque_where_drawn() {
    let text = ball(40, 0.8, [0.2, 0.6, 0.9], "spp = 4\nbackground = \"transparent\"")
        .replace("type = \"sphere\"", "type = \"sphere\"\nlabel = \"Ball\"")
        .replace("width = 40\nheight = 40", "width = 96\nheight = 40");
    let labelled = rendered(&text, &Options::default());
    let bare = rendered(&text, &Options { labels: false, ..Options::default() });
    let (with, without) = (labelled.image(Output::Png8), bare.image(Output::Png8));
    let (a, b) = (with.coverage.as_ref().unwrap(), without.coverage.as_ref().unwrap());
    let drawn: Vec<usize> = (0..a.len()).filter(|&k| with.pixels[k] != without.pixels[k] || a[k] != b[k]).collect();
    assert!(drawn.len() > 50, "the label is drawn: {} pixels", drawn.len());
    assert!(drawn.iter().all(|&k| a[k] == 1.0), "every pixel of the label is opaque");
    assert!(drawn.iter().filter(|&&k| b[k] == 0.0).count() > 50, "drawn over nothing");
    // And so in the file.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("label.png");
    labelled.save(&path, None).unwrap();
    let read = image::open(&path).unwrap().into_rgba8();
    for &k in &drawn {
        let (i, j) = ((k % 96) as u32, (k / 96) as u32);
        assert_eq!(read.get_pixel(i, 39 - j).0[3], 255, "({i}, {j})");
    }
}

#[test]
fn glass_is_opaque_and_the_environment_shows_only_in_reflections() {
    // A mirror ball and a glass ball under a sky: what misses them is transparent (nothing,
    // not the sky), what meets them is opaque, and the mirror shows the sky.
    let text = format!(
        "{}[render]\nambient = 0.0\nspp = 4\nbackground = \"transparent\"\n\
         [environment]\nzenith = [0.2, 0.4, 0.9]\nhorizon = [0.9, 0.9, 0.9]\nnadir = [0.3, 0.2, 0.1]\n\
         [[objects]]\ntype = \"sphere\"\ncentre = [-1.0, 0.0, 0.0]\nradius = 0.8\nmaterial = {{ colour = [0.0, 0.0, 0.0], kr = 1.0, {FLAT} }}\n\
         [[objects]]\ntype = \"sphere\"\ncentre = [1.0, 0.0, 0.0]\nradius = 0.8\nmaterial = {{ colour = [1.0, 1.0, 1.0], ior = 1.5 }}\n",
        camera(40)
    );
    let film = film(&text);
    let coverage = film.coverage.as_ref().unwrap();
    let at = |i: u32, j: u32| (j * 40 + i) as usize;
    for (i, j) in [(0, 0), (20, 39), (39, 20)] {
        assert_eq!((coverage[at(i, j)], film.pixels[at(i, j)]), (0.0, [0.0; 3]), "({i}, {j}) sees through");
    }
    let (mirror, glass) = (at(10, 20), at(30, 20));
    assert_eq!((coverage[mirror], coverage[glass]), (1.0, 1.0), "both balls opaque");
    assert!(film.pixels[mirror].iter().all(|&c| c > 0.05), "the mirror shows the sky: {:?}", film.pixels[mirror]);
    // Over the sky as a background the balls are the same to the bit: only misses change.
    let opaque = self::film(&text.replace("background = \"transparent\"", ""));
    for (k, a) in coverage.iter().enumerate() {
        if *a == 1.0 {
            assert_eq!(film.pixels[k], opaque.pixels[k], "pixel {k}");
        }
    }
}

#[test]
fn formats_without_alpha_are_refused_by_name() {
    let (picture, _) = orange();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ball.hdr");
    std::fs::write(&path, b"old").unwrap();
    let e = picture.save(&path, None).unwrap_err().to_string();
    assert!(e.contains("ball.hdr") && e.contains("background = \"transparent\"") && !e.contains('\n'), "{e}");
    assert_eq!(std::fs::read(&path).unwrap(), b"old", "the file is left as it was");
    // A colour background writes HDR as before.
    let opaque = rendered(&ball(8, 0.3, [1.0; 3], ""), &Options::default());
    opaque.save(&path, None).unwrap();
    // Refused before rendering where the scene is known first.
    let scene = Pipeline::parse(&ball(8, 0.3, [1.0; 3], "background = \"transparent\""), "t.toml", View::default())
        .unwrap()
        .scene(0.0)
        .unwrap();
    let hdr = Output::for_path(&path, None).unwrap();
    assert!(cga_trace::pipeline::check_output(&scene, &Options::default(), hdr, &path).is_err());
    let normals = Options { aov: Aov::Normal, ..Options::default() };
    assert!(cga_trace::pipeline::check_output(&scene, &normals, hdr, Path::new("n.hdr")).is_ok(), "AOVs are opaque");
}

#[test]
fn the_background_reads_as_a_colour_or_transparent_and_nothing_else() {
    let parse = |value: &str| {
        Pipeline::parse(&ball(8, 0.3, [1.0; 3], &format!("background = {value}")), "t.toml", View::default())
    };
    let settings = |value: &str| parse(value).unwrap().scene(0.0).unwrap().settings;
    let s = settings("\"transparent\"");
    assert!(s.transparent && s.background == [0.0; 3]);
    let s = settings("[0.1, 0.2, 0.3]");
    assert!(!s.transparent && s.background == [0.1, 0.2, 0.3]);
    for (value, says) in [
        ("\"clear\"", "\"transparent\""),
        ("[0.1, 0.2]", "expected 3 numbers, found 2"),
        ("[0.1, nan, 0.3]", "element 2: NaN"),
        ("3", "[r, g, b]"),
    ] {
        let e = parse(value).and_then(|mut p| p.scene(0.0)).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains("background") && e.contains(says), "{value}: {e}");
    }
    // The view's background overrides the file's, both ways.
    let mut pipeline = parse("\"transparent\"").unwrap();
    pipeline.set_view(View { background: Some(cga_trace::settings::Background::Colour([0.5; 3])), ..View::default() });
    assert!(!pipeline.scene(0.0).unwrap().settings.transparent);
    pipeline.set_view(View { background: Some(cga_trace::settings::Background::Transparent), ..View::default() });
    assert!(pipeline.scene(0.0).unwrap().settings.transparent);
}
