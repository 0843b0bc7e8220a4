//! Lenses, area lights, the shutter and glass against their textbook formulas: an
//! orthographic view's constant scale, a thin lens's circle of confusion, a disk light's
//! penumbra, motion blur's coverage (smooth at four samples a pixel, the average of many
//! frames, a still scene's own picture), and a glass ball's focal point (the ball-lens
//! formula).

use cga_trace::integrator::Window;
use cga_trace::ray::Ray;
use cga_trace::{Aov, Film, Renderer, Scene};

fn parse(text: &str) -> Scene {
    Scene::parse(text, "optics.toml").unwrap()
}

fn render(scene: &Scene) -> Film {
    let c = &scene.camera;
    Renderer::new(scene).render_window(Aov::Shaded, Window::full(c.width, c.height), &|| {})
}

/// An object lit by the ambient light alone, brightness 1 (with `ambient = 1`).
const WHITE: &str = "material = { colour = [1.0, 1.0, 1.0], ka = 1.0, kd = 0.0, ks = 0.0 }";

/// Pixels brighter than ½.
fn lit(film: &Film) -> usize {
    film.pixels.iter().filter(|p| p[0] > 0.5).count()
}

#[test]
fn an_orthographic_view_shows_a_sphere_at_its_size_at_any_distance() {
    // 4 units over 100 pixels: a unit sphere is a disk of 25 pixels' radius.
    for y in [0.0, 30.0] {
        let s = parse(&format!(
            "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\nview_width = 4.0\nwidth = 100\nheight = 100\n\
             [render]\nambient = 1.0\n[[objects]]\ntype = \"sphere\"\ncentre = [0.3, {y:?}, -0.2]\nradius = 1.0\n{WHITE}\n"
        ));
        let area = lit(&render(&s)) as f64;
        let want = std::f64::consts::PI * 25.0 * 25.0;
        assert!((area / want - 1.0).abs() < 0.01, "at y = {y}: {area} pixels, π 25² = {want:.0}");
    }
}

/// The intensity-weighted mean squared distance from the centroid, in pixels².
fn spread(film: &Film) -> f64 {
    let w = film.width as usize;
    let (mut sum, mut sx, mut sy, mut sr) = (0.0, 0.0, 0.0, 0.0);
    for (k, p) in film.pixels.iter().enumerate() {
        let (x, y) = ((k % w) as f64, (k / w) as f64);
        (sum, sx, sy, sr) = (sum + p[0], sx + p[0] * x, sy + p[0] * y, sr + p[0] * (x * x + y * y));
    }
    let (mx, my) = (sx / sum, sy / sum);
    sr / sum - mx * mx - my * my
}

#[test]
fn a_thin_lens_blurs_a_point_to_its_circle_of_confusion() {
    // A small sphere at depth D seen through a lens of radius A focused at F blurs by a disk
    // of radius A |D − F| / D on the plane of focus: `A |D − F| / (D F) · w / (2 tan(fov/2))`
    // pixels. A disk of radius c has mean squared radius c²/2, and blurs add their spreads.
    let (aperture, focus, width, fov) = (0.2, 10.0, 128u32, 20.0f64);
    let view = |depth: f64, aperture: f64| {
        let lens = format!("aperture = {aperture:?}\nfocus_distance = {focus:?}\n");
        parse(&format!(
            "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = {fov:?}\nwidth = {width}\nheight = {width}\n{}\
             [render]\nambient = 1.0\nspp = 256\n[[objects]]\ntype = \"sphere\"\ncentre = [0.0, {:?}, 0.0]\nradius = 0.05\n{WHITE}\n",
            if aperture > 0.0 { lens } else { String::new() },
            depth - 10.0
        ))
    };
    for depth in [6.0, 16.0] {
        let sharp = spread(&render(&view(depth, 0.0)));
        let blurred = spread(&render(&view(depth, aperture)));
        let measured = (2.0 * (blurred - sharp)).sqrt();
        let pixels = f64::from(width) / (2.0 * (fov.to_radians() / 2.0).tan());
        let want = aperture * (depth - focus).abs() / (depth * focus) * pixels;
        println!("depth {depth}: circle of confusion {measured:.3} pixels, thin lens {want:.3}");
        assert!((measured / want - 1.0).abs() < 0.03, "depth {depth}: {measured} vs {want}");
    }
    // In focus, the lens leaves the point as sharp as the pinhole.
    let (sharp, lens) = (spread(&render(&view(10.0, 0.0))), spread(&render(&view(10.0, aperture))));
    assert!((lens - sharp).abs() < 0.02 * sharp, "{lens} vs {sharp}");
}

#[test]
fn a_disk_lights_penumbra_is_as_wide_as_similar_triangles_say() {
    // A disk light of radius R at height H over a floor; an opaque half-plane (a huge disk
    // whose edge runs through x = 0) at height h between. A floor point at x sees the light's
    // points with x_L ≥ −x (H − h)/h: the penumbra runs over |x| ≤ R h / (H − h).
    let (r, height, h) = (1.0, 5.0, 1.0);
    let s = parse(&format!(
        "[camera]\nposition = [0.0, -10.0, 3.0]\nlook_at = [0.0, 0.0, 0.0]\nwidth = 8\nheight = 8\n\
         [render]\nambient = 0.0\n\
         [[lights]]\nposition = [0.0, 0.0, {height:?}]\ndisk = {r:?}\nnormal = [0.0, 0.0, -1.0]\nsamples = 1024\n\
         [[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = {{ colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 1.0, ks = 0.0 }}\n\
         [[objects]]\ntype = \"disk\"\ncentre = [-1000.0, 0.0, {h:?}]\nnormal = [0.0, 0.0, 1.0]\nradius = 1000.0\nmaterial = {{ colour = [0.0, 0.0, 0.0] }}\n"
    ));
    let renderer = Renderer::new(&s);
    // Straight down onto the floor from between it and the blocker (frame coordinates).
    let seen = |x: f64| {
        let origin = s.frame.point([x, 0.0, 0.5 * h]);
        renderer.trace(&Ray::new(origin, [0.0, 0.0, -1.0]).unwrap(), 0)[0]
    };
    // The light's points visible from x, each weighted by n·l, on a fine polar grid.
    let expected = |x: f64| {
        let (mut seen, mut all) = (0.0, 0.0);
        for i in 0..400 {
            for k in 0..400 {
                let (rho, phi) =
                    (r * ((f64::from(i) + 0.5) / 400.0).sqrt(), std::f64::consts::TAU * (f64::from(k) + 0.5) / 400.0);
                let (lx, ly) = (rho * phi.cos(), rho * phi.sin());
                let d = ((lx - x).powi(2) + ly * ly + height * height).sqrt();
                let cos = height / d;
                all += 1.0;
                if lx >= -x * (height - h) / h {
                    seen += cos;
                }
            }
        }
        seen / all
    };
    let edge = r * h / (height - h);
    let mut worst: f64 = 0.0;
    for step in -40..=40 {
        let x = 2.0 * edge * f64::from(step) / 40.0;
        let (got, want) = (seen(x), expected(x));
        worst = worst.max((got - want).abs());
    }
    println!("penumbra over |x| ≤ {edge}: largest difference from the analytic irradiance {worst:.2e}");
    assert!(worst < 5e-3, "{worst}");
    // Dark before the penumbra, fully lit after it.
    assert_eq!(seen(-1.05 * edge), 0.0);
    assert!((seen(1.05 * edge) - expected(1.05 * edge)).abs() < 1e-3);
}

#[test]
fn a_shutter_blurs_a_moving_sphere_over_its_path() {
    // A ball of radius ½ moving from x = −2 to x = 2 during the shutter (an orthographic view,
    // 20 pixels a unit): a point of its path's middle row is covered for the share of the
    // time that the ball is within ½ of it, |[x − ½, x + ½] ∩ [−2, 2]| / 4.
    let text = format!(
        "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\nview_width = 8.0\nwidth = 160\nheight = 20\n\
         shutter = [0.0, 1.0]\n[render]\nambient = 1.0\nspp = 64\n\
         [[objects]]\ntype = \"sphere\"\ncentre = [-2.0, 0.0, 0.0]\nradius = 0.5\n{WHITE}\nmotion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, -2, 0, 0, 0]]\n"
    );
    let mut pipeline = cga_trace::Pipeline::parse(&text, "optics.toml", cga_trace::View::default()).unwrap();
    let scene = pipeline.scene(0.0).unwrap();
    assert!(scene.shutter.is_some(), "a shutter");
    let film = pipeline.render(&scene, &cga_trace::Options::default(), &|| {}).unwrap().film;
    let row = 10 * 160;
    let mut worst: f64 = 0.0;
    for i in 0..160 {
        let x = -4.0 + (f64::from(i) + 0.5) / 20.0;
        let want = ((x + 0.5).min(2.0) - (x - 0.5).max(-2.0)).max(0.0) / 4.0;
        worst = worst.max((film.pixels[row + i as usize][0] - want).abs());
    }
    println!("coverage along the path: largest difference {worst:.3}");
    // A pixel's 64 samples one in each 1/64 of the shutter, and the pixel's width (1/20 of a
    // unit, 1/80 of the path).
    assert!(worst < 1.0 / 64.0 + 1.0 / 80.0 + 1e-3, "{worst}");
}

/// A picture through `text`'s shutter by its pipeline.
fn shuttered(text: &str) -> (Scene, Film) {
    let mut pipeline = cga_trace::Pipeline::parse(text, "optics.toml", cga_trace::View::default()).unwrap();
    let scene = pipeline.scene(0.0).unwrap();
    assert!(scene.shutter.is_some(), "a shutter");
    let film = pipeline.render(&scene, &cga_trace::Options::default(), &|| {}).unwrap().film;
    (scene, film)
}

#[test]
fn a_shutter_blurs_smoothly_at_four_samples_a_pixel() {
    // A tall bar of width 1 crossing from x = −2 to x = 2 (an orthographic view, 20 pixels a
    // unit, 4 samples a pixel): every row sees the same motion, so a column's mean over the
    // rows is its coverage, |[x − ½, x + ½] ∩ [−2, 2]| / 4, to the noise of 4 · 48 samples.
    // Were every pixel's samples taken at the same 4 instants, the bar would leave 4 copies:
    // a staircase up to 1/8 off that ramp in every row alike.
    let (width, height) = (160, 48);
    let text = format!(
        "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\nview_width = 8.0\nwidth = {width}\nheight = {height}\n\
         shutter = [0.0, 1.0]\n[render]\nambient = 1.0\nspp = 4\n\
         [[objects]]\ntype = \"box\"\nmin = [-2.5, -0.5, -5.0]\nmax = [-1.5, 0.5, 5.0]\n{WHITE}\nmotion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, -2, 0, 0, 0]]\n"
    );
    let (scene, film) = shuttered(&text);
    // The samples of an instant through packets give the bits of one ray at a time.
    let mut pipeline = cga_trace::Pipeline::parse(&text, "optics.toml", cga_trace::View::default()).unwrap();
    for options in [
        cga_trace::Options { packets: false, ..Default::default() },
        cga_trace::Options { avx2: false, ..Default::default() },
    ] {
        assert!(pipeline.render(&scene, &options, &|| {}).unwrap().film.pixels == film.pixels);
    }
    let mut worst: f64 = 0.0;
    for i in 0..width {
        let x = -4.0 + (f64::from(i) + 0.5) / 20.0;
        let want = ((x + 0.5).min(2.0) - (x - 0.5).max(-2.0)).max(0.0) / 4.0;
        let mean = (0..height).map(|j| film.pixels[(j * width + i) as usize][0]).sum::<f64>() / f64::from(height);
        worst = worst.max((mean - want).abs());
    }
    println!("coverage along the path, the mean of {height} rows at 4 samples: largest difference {worst:.3}");
    assert!(worst < 0.06, "{worst}");
}

#[test]
fn a_shutter_gives_the_average_of_many_frames_and_a_still_scene_its_still_picture() {
    // motion.toml's ring and ball at 48 × 36, 16 samples a pixel: through the shutter (256
    // instants), against the mean of 64 frames at the middles of 64 equal parts of the
    // interval, each at 16 samples.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join("motion.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("width = 320", "width = 48")
        .replace("height = 240", "height = 36")
        .replace("spp = 32", "spp = 16");
    let (scene, blurred) = shuttered(&text);
    let mut frames = cga_trace::Pipeline::parse(
        &text.replace("shutter = [0.0, 1.0]\n", ""),
        "motion.toml",
        cga_trace::View::default(),
    )
    .unwrap();
    let mut mean = vec![[0.0; 3]; blurred.pixels.len()];
    for k in 0..64 {
        let at = frames.scene((f64::from(k) + 0.5) / 64.0).unwrap();
        for (m, p) in mean.iter_mut().zip(render(&at).pixels) {
            *m = [0, 1, 2].map(|c| m[c] + p[c] / 64.0);
        }
    }
    let difference = |a: &[[f64; 3]], b: &[[f64; 3]]| {
        a.iter()
            .zip(b)
            .map(|(p, q)| (0..3).map(|c| (p[c].min(1.0) - q[c].min(1.0)).abs()).sum::<f64>() / 3.0)
            .sum::<f64>()
            / a.len() as f64
    };
    let against_frames = difference(&blurred.pixels, &mean);
    let still = render(&frames.scene(0.0).unwrap());
    println!(
        "mean |shutter − mean of 64 frames| {against_frames:.4}; against one frame {:.4}",
        difference(&still.pixels, &mean)
    );
    assert!(against_frames < 0.01 && difference(&still.pixels, &mean) > 5.0 * against_frames, "{against_frames}");
    // Nothing moves: the shutter gives the still picture (sums in another order: to rounding).
    let standing = text.replace("motion = ", "# motion = ");
    let (standing_scene, through) = shuttered(&standing);
    let plain = render(&standing_scene);
    let worst = through
        .pixels
        .iter()
        .flatten()
        .zip(plain.pixels.iter().flatten())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-12, "{worst}");
    assert_eq!(through.to_rgb8(scene.settings.encoding).into_raw(), plain.to_rgb8(scene.settings.encoding).into_raw());
}

#[test]
fn a_glass_ball_focuses_parallel_light_where_the_ball_lens_formula_says() {
    // A ball of index n and radius R focuses paraxial rays at f = n R / (2 (n − 1)) from its
    // centre. Parallel rays (an orthographic view) through the ball's middle meet a small
    // marker sphere placed on the axis behind it: nearly all where it sits at the focus, a
    // tenth as many 5 % nearer or farther.
    let (n, radius) = (1.5, 1.0);
    let focal = n * radius / (2.0 * (n - 1.0));
    let seen = |distance: f64| {
        let s = parse(&format!(
            "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nprojection = \"orthographic\"\nview_width = 0.3\nwidth = 80\nheight = 80\n\
             [render]\nambient = 1.0\nmax_depth = 4\n\
             [[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = {radius:?}\n\
             material = {{ colour = [0.0, 0.0, 0.0], ka = 0.0, kd = 0.0, ks = 0.0, ior = {n:?} }}\n\
             [[objects]]\ntype = \"sphere\"\ncentre = [0.0, {distance:?}, 0.0]\nradius = 0.002\n{WHITE}\n"
        ));
        // Through glass at normal incidence, (1 − 0.04)² of the marker's light comes back.
        render(&s).pixels.iter().filter(|p| p[0] > 0.5).count()
    };
    let at = seen(focal);
    let (near, far) = (seen(0.95 * focal), seen(1.05 * focal));
    println!("rays meeting the marker: {near} at 0.95 f, {at} at f = {focal}, {far} at 1.05 f");
    assert!(at > 10 * near && at > 10 * far, "{near} {at} {far}");
    // The best focus within 2 % of f (nearer by the ball's spherical aberration), and f
    // itself within 10 % of the best.
    let scan: Vec<(f64, usize)> =
        (-4..=4).map(|k| focal * (1.0 + 0.005 * f64::from(k))).map(|d| (d, seen(d))).collect();
    let best = scan.iter().map(|s| s.1).max().unwrap();
    assert!(scan.iter().filter(|s| s.1 == best).all(|s| (s.0 / focal - 1.0).abs() <= 0.02), "{scan:?}");
    assert!(at as f64 >= 0.9 * best as f64, "{scan:?}");
}

/// The colour the sky gradient gives the direction `d` (`zenith` up, `nadir` down).
const SKY: &str = "[environment]\nzenith = [0.2, 0.4, 0.9]\nhorizon = [0.9, 0.9, 0.9]\nnadir = [0.9, 0.5, 0.1]\n";

#[test]
fn a_camera_inside_glass_sees_through_it_absorbed_as_beer_lambert_says() {
    // A camera at the centre of an absorbing glass bubble of radius r: every camera ray leaves
    // it at normal incidence, F = ((n − 1)/(n + 1))² = 0.04, through r of glass; its mirror
    // ray crosses the bubble (2r more) and leaves the other way. The sky depends on the
    // direction alone, so a pixel is 0.96 e^(−a r) S(d) + 0.04 · 0.96 e^(−3 a r) S(−d) (the
    // next bounce weighs 0.04², under the cut-off).
    let (r, a): (f64, f64) = (0.1, 1.4);
    let camera =
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.3]\nfov = 70.0\nwidth = 24\nheight = 18\n";
    let glass = format!(
        "[[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = {r:?}\n\
         material = {{ colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 0.0, ks = 0.0, ior = 1.5, absorption = [{a:?}, {a:?}, {a:?}] }}\n"
    );
    let open = parse(&format!("{camera}{SKY}"));
    let bubble = parse(&format!("{camera}[render]\nmax_depth = 4\n{SKY}{glass}"));
    let renderer = Renderer::new(&open);
    let (sky, seen) = (render(&open), render(&bubble));
    let f: f64 = (0.5f64 / 2.5).powi(2);
    for (k, (p, q)) in sky.pixels.iter().zip(&seen.pixels).enumerate() {
        let (i, j) = ((k % 24) as u32, (k / 24) as u32);
        let ray = open.camera.ray(f64::from(i) + 0.5, f64::from(j) + 0.5).unwrap();
        let back = renderer.trace(&Ray::new(ray.origin, ray.dir.map(|x| -x)).unwrap(), 0);
        for c in 0..3 {
            let want = (1.0 - f) * (-a * r).exp() * p[c] + f * (1.0 - f) * (-3.0 * a * r).exp() * back[c];
            assert!((q[c] - want).abs() < 1e-6 * want.max(1.0), "pixel {k} channel {c}: {} against {want}", q[c]);
        }
    }
}

#[test]
fn a_camera_inside_a_closed_glass_mesh_sees_what_it_sees_inside_the_box() {
    // The same glass cube as twelve triangles and as a box: the camera inside either.
    let dir = tempfile::tempdir().unwrap();
    let cube = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n\
        vn -1 -1 -1\nvn 1 -1 -1\nvn 1 1 -1\nvn -1 1 -1\nvn -1 -1 1\nvn 1 -1 1\nvn 1 1 1\nvn -1 1 1\n\
        f 1//1 4//4 3//3 2//2\nf 5//5 6//6 7//7 8//8\nf 1//1 2//2 6//6 5//5\nf 2//2 3//3 7//7 6//6\nf 3//3 4//4 8//8 7//7\nf 4//4 1//1 5//5 8//8\n";
    std::fs::write(dir.path().join("cube.obj"), cube).unwrap();
    let camera =
        "[camera]\nposition = [0.2, -0.3, 0.1]\nlook_at = [0.5, 1.0, 0.4]\nfov = 80.0\nwidth = 32\nheight = 24\n";
    let glass = "material = { colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 0.0, ks = 0.0, ior = 1.5, absorption = [0.3, 0.2, 0.1] }";
    let scene = |object: &str| {
        let text = format!("{camera}[render]\nmax_depth = 6\n{SKY}[[objects]]\n{object}\n{glass}\n");
        Scene::parse(&text, dir.path().join("scene.toml").to_str().unwrap()).unwrap()
    };
    let text_scene = |dir: &tempfile::TempDir, camera: &str, glass: &str| {
        let text = format!(
            "{camera}[render]\nmax_depth = 6\n{SKY}[[objects]]\ntype = \"mesh\"\nfile = \"cube.obj\"\n{glass}\n"
        );
        Scene::parse(&text, dir.path().join("scene.toml").to_str().unwrap()).unwrap()
    };
    let mesh = scene("type = \"mesh\"\nfile = \"cube.obj\"");
    let solid = scene("type = \"box\"\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, 1.0]");
    let (m, b) = (render(&mesh), render(&solid));
    let plain_cube = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    std::fs::write(dir.path().join("plain.obj"), plain_cube).unwrap();
    let p = render(&scene("type = \"mesh\"\nfile = \"plain.obj\""));
    let flat = p.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |c| (p[c] - q[c]).abs()));
    assert!(flat.fold(0.0, f64::max) < 1e-6, "the cube without normals");
    // Every back end decides the same sides, from inside and from outside.
    let outside = text_scene(&dir, &camera.replace("[0.2, -0.3, 0.1]", "[3.0, -4.0, 2.0]"), glass);
    for scene in [&mesh, &outside] {
        let c = &scene.camera;
        let window = Window::full(c.width, c.height);
        let own = Renderer::new(scene).render_window(Aov::Shaded, window.clone(), &|| {});
        let plain = Renderer::<cga_trace::backend::Plain>::with_backend(scene).render_window(
            Aov::Shaded,
            window.clone(),
            &|| {},
        );
        let dense =
            Renderer::<cga_trace::backend::Dense>::with_backend(scene).render_window(Aov::Shaded, window, &|| {});
        for other in [&plain, &dense] {
            let off = other
                .pixels
                .iter()
                .zip(&own.pixels)
                .filter(|(p, q)| (0..3).any(|k| (p[k] - q[k]).abs() > 1e-6))
                .count();
            assert_eq!(off, 0, "pixels that differ between back ends");
        }
    }
    let worst =
        m.pixels.iter().zip(&b.pixels).flat_map(|(p, q)| (0..3).map(move |c| (p[c] - q[c]).abs())).fold(0.0, f64::max);
    // The vertex normals point out of the corners: the geometric faces decide the side and
    // refraction alike, so the pictures agree but for the rounding of two kinds of shape.
    assert!(worst < 1e-6, "worst {worst}");
    // Against the camera outside every medium (what a ray absorbed outside the glass gives).
    let sky = render(&scene("type = \"sphere\"\ncentre = [0.0, 0.0, 50.0]\nradius = 0.1"));
    let mean = |f: &Film| f.pixels.iter().map(|p| p[0] + p[1] + p[2]).sum::<f64>() / f.pixels.len() as f64;
    assert!(mean(&b) > 0.5 * mean(&sky), "{} against the open sky's {}", mean(&b), mean(&sky));
}

/// The shipped scene `name` with its objects written in the reverse order.
fn reversed(text: &str) -> String {
    let mut parts = text.split("[[objects]]");
    let head = parts.next().unwrap().to_string();
    let objects: Vec<&str> = parts.collect();
    head + &objects.iter().rev().map(|o| format!("[[objects]]{o}\n")).collect::<String>()
}

#[test]
fn touching_surfaces_are_decided_by_the_surfaces_not_their_order() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/contact.toml")).unwrap();
    let small = |t: &str| t.replace("width = 320\nheight = 240", "width = 160\nheight = 120");
    let (scene, back) = (parse(&small(&text)), parse(&small(&reversed(&text))));
    let (a, b) = (render(&scene), render(&back));
    assert!(a.pixels == b.pixels, "the same picture in either order");
    // Every back end agrees on which surface shows.
    let window = Window::full(160, 120);
    let plain = Renderer::<cga_trace::backend::Plain>::with_backend(&back).render_window(Aov::Shaded, window, &|| {});
    let off =
        plain.pixels.iter().zip(&a.pixels).filter(|(p, q)| (0..3).any(|k| (p[k] - q[k]).abs() > 1.0 / 64.0)).count();
    assert!(off <= 2, "{off} pixels differ on plain vectors");
    // The disk on the floor shows, in its own colour, at its centre.
    let (u, v, _) = cga_trace::figure::project(&scene.camera, scene.frame.point([2.2, 0.5, 0.0])).unwrap();
    let p = a.pixels[v as usize * 160 + u as usize];
    assert!(p[2] > 2.0 * p[0] && p[2] > 2.0 * p[1], "the decal's pixel {p:?}");
    // Nothing under the glass box is left black (a ray leaving the box's bottom face below
    // the floor would see the empty background there).
    let dark = a.pixels.iter().filter(|p| p.iter().sum::<f64>() < 0.02).count();
    assert_eq!(dark, 0, "black pixels");
}

#[test]
fn a_light_standing_on_a_surface_is_lit_the_same_on_every_back_end() {
    // A point light on the floor: shadow rays to it end on the floor's plane. Rounding must
    // not decide whether the floor blocks them (speckle on the box's lit face).
    let text = "[camera]\nposition = [0.0, -8.0, 4.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 60.0\nwidth = 96\nheight = 72\n\
        [[lights]]\nposition = [0.0, 0.0, 0.0]\n\
        [[objects]]\ntype = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nmaterial = { colour = [0.8, 0.8, 0.8] }\n\
        [[objects]]\ntype = \"box\"\nmin = [-1.0, 1.0, 0.0]\nmax = [0.0, 2.0, 1.0]\nmaterial = { colour = [0.8, 0.2, 0.2] }\n\
        [[objects]]\ntype = \"sphere\"\ncentre = [1.5, 0.5, 0.0]\nradius = 0.5\nmaterial = { colour = [0.2, 0.8, 0.2] }\n";
    let scene = parse(text);
    let window = Window::full(96, 72);
    let own = render(&scene);
    let plain =
        Renderer::<cga_trace::backend::Plain>::with_backend(&scene).render_window(Aov::Shaded, window.clone(), &|| {});
    let dense = Renderer::<cga_trace::backend::Dense>::with_backend(&scene).render_window(Aov::Shaded, window, &|| {});
    for other in [&plain, &dense] {
        let off = other
            .pixels
            .iter()
            .zip(&own.pixels)
            .filter(|(p, q)| (0..3).any(|k| (p[k] - q[k]).abs() > 1.0 / 16.0))
            .count();
        assert_eq!(off, 0, "pixels that differ between back ends");
    }
    // No speckle on the box's face (its pixels red, as are their neighbours): no pixel there
    // differs from both its left and right neighbours by more than 1/16 the same way.
    let pixel = |i: usize, j: usize| own.pixels[j * 96 + i];
    let on_box = |i: usize, j: usize| (i - 1..=i + 1).all(|x| pixel(x, j)[0] > 2.0 * pixel(x, j)[1]);
    let dot = |i: usize, j: usize| {
        let (l, c, r) = (pixel(i - 1, j)[0], pixel(i, j)[0], pixel(i + 1, j)[0]);
        (c - l).abs() > 1.0 / 16.0 && (c - r).abs() > 1.0 / 16.0 && (c - l).signum() == (c - r).signum()
    };
    let face: Vec<(usize, usize)> =
        (0..72).flat_map(|j| (1..95).map(move |i| (i, j))).filter(|&(i, j)| on_box(i, j)).collect();
    let dots: Vec<_> = face.iter().filter(|&&(i, j)| dot(i, j)).collect();
    assert!(face.len() > 50 && dots.is_empty(), "{} face pixels, dots at {dots:?}", face.len());
}

#[test]
fn an_orthographic_view_across_a_glass_box_starts_each_ray_where_it_is() {
    // An orthographic view from the middle of a glass cube [−1, 1]³ along +y, 4 wide: rays
    // starting inside the cube leave it at normal incidence after 1 unit of glass (and their
    // mirror rays after 3), rays starting beside it see the sky as it is.
    let a: f64 = 0.7;
    let text = format!(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [0.0, 1.0, 0.0]\nprojection = \"orthographic\"\nview_width = 4.0\nwidth = 40\nheight = 30\n\
         [render]\nmax_depth = 4\n{SKY}[[objects]]\ntype = \"box\"\nmin = [-1.0, -1.0, -1.0]\nmax = [1.0, 1.0, 1.0]\n\
         material = {{ colour = [1.0, 1.0, 1.0], ka = 0.0, kd = 0.0, ks = 0.0, ior = 1.5, absorption = [{a:?}, {a:?}, {a:?}] }}\n"
    );
    let film = render(&parse(&text));
    let horizon = [0.9, 0.9, 0.9];
    let f: f64 = 0.04;
    let inside = (1.0 - f) * (-a).exp() + f * (1.0 - f) * (-3.0 * a).exp();
    for (k, p) in film.pixels.iter().enumerate() {
        let (i, j) = (k % 40, k / 40);
        // The pixel's ray starts at (x, 0, z) on the view's plane.
        let (x, z) = (-2.0 + 4.0 * (i as f64 + 0.5) / 40.0, -1.5 + 3.0 * (j as f64 + 0.5) / 30.0);
        let want = if x.abs() < 1.0 && z.abs() < 1.0 { inside } else { 1.0 };
        for c in 0..3 {
            assert!(
                (p[c] - want * horizon[c]).abs() < 1e-9,
                "pixel ({i}, {j}) at x {x:.2}, z {z:.2}: {p:?}, want {}",
                want * horizon[c]
            );
        }
    }
}

#[test]
fn a_shutter_places_only_what_moves_and_renders_as_if_each_instant_were_loaded_anew() {
    // Twelve spheres that stand (enough for a hierarchy), a ball that moves, a standing
    // template's moving instance and a moving object's standing instance.
    let mut text = String::from(
        "[camera]\nposition = [0.0, -12.0, 2.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 50.0\nwidth = 48\nheight = 32\n\
         shutter = [0.0, 1.0]\ntime_samples = 5\n[render]\nspp = 10\n\
         [[lights]]\nposition = [-4.0, -6.0, 10.0]\n",
    );
    for k in 0..12 {
        let (x, z) = (f64::from(k % 4) * 1.5 - 2.25, f64::from(k / 4) - 1.0);
        text += &format!(
            "[[objects]]\nname = \"still {k}\"\ntype = \"sphere\"\ncentre = [{x:?}, 1.0, {z:?}]\nradius = 0.4\n{WHITE}\n"
        );
    }
    text += "[[objects]]\nname = \"ball\"\ntype = \"sphere\"\ncentre = [-2.0, -1.0, 0.0]\nradius = 0.5\n\
             material = { colour = [0.9, 0.3, 0.2] }\nmotion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, -2, 0, 0, 0]]\n\
             [[objects]]\nname = \"pin\"\ntemplate = true\ntype = \"cylinder\"\np1 = [0.0, 0.0, 0.0]\np2 = [0.0, 0.0, 1.0]\nradius = 0.1\n\
             material = { colour = [0.2, 0.9, 0.3] }\n\
             [[objects]]\nname = \"moving pin\"\ntype = \"instance\"\nof = \"pin\"\ntransform = [{ translate = [2.0, -1.0, -1.0] }]\n\
             motion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, 0, 0, -1, 0]]\n\
             [[objects]]\nname = \"ball copy\"\ntype = \"instance\"\nof = \"ball\"\ntransform = [{ translate = [0.0, 0.0, 1.5] }]\n";
    let mut pipeline = cga_trace::Pipeline::parse(&text, "shutter.toml", cga_trace::View::default()).unwrap();
    // Placed once, nothing is kept (one still picture keeps nothing); from the second time on,
    // what stands is.
    let _ = pipeline.scene(0.1).unwrap();
    let (a, b) = (pipeline.scene(0.2).unwrap(), pipeline.scene(0.7).unwrap());
    let moving: Vec<(&str, bool)> = b.objects.iter().map(|o| (&*o.name, o.moving)).collect();
    let still = |name: &str| !name.contains("ball") && name != "moving pin";
    assert!(moving.iter().all(|&(name, m)| m != still(name)), "{moving:?}");
    // What stands is the very object built at the instant before; what moves is built anew.
    for (x, y) in a.objects.iter().zip(&b.objects) {
        assert_eq!(std::sync::Arc::ptr_eq(&x.shape, &y.shape), !x.moving, "{}", x.name);
    }
    let scene = pipeline.scene(0.0).unwrap();
    let kept = pipeline.render(&scene, &cga_trace::Options::default(), &|| {}).unwrap().film;
    // The same picture with every instant loaded, built and its hierarchy made anew.
    let c = &scene.camera;
    let anew = scene
        .shutter
        .unwrap()
        .expose(0.0, scene.settings.spp, (0..c.width, 0..c.height), &|| {}, |t, samples| {
            let mut fresh = cga_trace::Pipeline::parse(&text, "shutter.toml", cga_trace::View::default()).unwrap();
            let at = fresh.scene(t).unwrap();
            Ok::<_, ()>(Renderer::new(&at).render_samples(Aov::Shaded, samples))
        })
        .unwrap();
    assert!(kept.pixels == anew.pixels, "the kept objects change the picture");
    // The ball and its copy blur: the picture differs from the still start.
    assert!(kept.pixels != render(&scene).pixels);
}

/// Light passes through a glass CSG body as through the solid it bounds: a glass ball in
/// front of a checkered wall, and the same ball as the union of itself with a smaller ball
/// inside (whose surface is no boundary of the union), render the same picture, the wall
/// seen through the ball.
#[test]
fn glass_through_a_csg_body_is_glass_through_its_solid() {
    let scene = |ball: &str| {
        parse(&format!(
            "[camera]\nposition = [0.0, -10.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\nfov = 20.0\nwidth = 48\nheight = 48\n\
             [render]\nambient = 0.3\n[[lights]]\nposition = [-3.0, -8.0, 6.0]\n\
             [[objects]]\ntype = \"plane\"\npoint = [0.0, 4.0, 0.0]\nnormal = [0.0, -1.0, 0.0]\n\
             material = {{ colour = [0.9, 0.2, 0.1], texture = {{ pattern = \"checker\", colour = [0.1, 0.3, 0.9] }} }}\n\
             [[objects]]\n{ball}\nmaterial = {{ colour = [0.0, 0.0, 0.0], ka = 0.0, kd = 0.0, ks = 1.0, q = 300.0, ior = 1.5 }}\n"
        ))
    };
    let plain = render(&scene("type = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.2"));
    let union = render(&scene(
        "type = \"csg\"\noperation = \"union\"\nobjects = [{ type = \"sphere\", centre = [0.0, 0.0, 0.0], radius = 1.2 }, \
         { type = \"sphere\", centre = [0.2, 0.0, 0.1], radius = 0.5 }]",
    ));
    let largest = plain.pixels.iter().zip(&union.pixels).flat_map(|(a, b)| (0..3).map(move |k| (a[k] - b[k]).abs()));
    let largest = largest.fold(0.0, f64::max);
    assert!(largest < 1e-6, "the union differs by {largest}");
    // The wall seen through the ball, bent: not the ball's own black.
    let centre = plain.pixels[24 * 48 + 24];
    assert!(centre.iter().sum::<f64>() > 0.1, "{centre:?}");
}
