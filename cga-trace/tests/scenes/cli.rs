//! The command line as a user meets it: one-line errors without backtraces, the output
//! checked before rendering, formats by extension, crop windows, and help that points at
//! the scene format.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// A fresh scratch directory for one test, removed when the test ends, pass or fail.
fn scratch(test: &str) -> tempfile::TempDir {
    tempfile::Builder::new().prefix(&format!("cga-trace-cli-{test}-")).tempdir().unwrap()
}

/// `cga-trace render ARGS…`, with backtraces asked for (they must not appear).
fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cga-trace")).arg("render").args(args).env("RUST_BACKTRACE", "1").output().unwrap()
}

/// The one line of a failed run.
fn error_line(out: &Output) -> String {
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line, not {stderr:?}");
    assert!(lines[0].starts_with("error: "), "{stderr}");
    assert!(!stderr.contains("backtrace") && !stderr.contains("Stack"), "{stderr}");
    lines[0].to_string()
}

#[test]
fn user_errors_are_one_line_and_come_before_any_rendering() {
    let scratch_dir = scratch("errors");
    let dir = scratch_dir.path();
    let primitives = scene("primitives.toml");
    let p = primitives.to_str().unwrap();
    let jpg = dir.join("x.jpg");
    let e = error_line(&render(&[p, "-o", jpg.to_str().unwrap()]));
    assert!(e.contains("x.jpg") && e.contains("unknown image extension"), "{e}");
    assert!(!jpg.exists(), "nothing written");
    let e = error_line(&render(&[p, "-o", dir.join("no/such/dir/x.png").to_str().unwrap()]));
    assert!(e.contains("cannot write"), "{e}");
    let e = error_line(&render(&[p, "-o", dir.join("x.exr").to_str().unwrap(), "--bit-depth", "16"]));
    assert!(e.contains("16-bit"), "{e}");
    // A missing scene: its cause once, not twice; the output it would have written is gone.
    let out = dir.join("y.png");
    let e = error_line(&render(&["no/such/scene.toml", "-o", out.to_str().unwrap()]));
    assert!(e.contains("no/such/scene.toml") && e.matches("os error").count() == 1, "{e}");
    assert!(!out.exists());
    // A bad scene: located.
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[camera]\nposition = [0.0, 0.0, nan]\nlook_at = [0.0, 1.0, 0.0]\nwidth = 8\nheight = 8\n")
        .unwrap();
    let e = error_line(&render(&[bad.to_str().unwrap(), "-o", out.to_str().unwrap()]));
    assert!(e.contains("bad.toml:2:") && e.contains("NaN"), "{e}");
    // Limits on the command line too.
    let e = error_line(&render(&[p, "-o", out.to_str().unwrap(), "--width", "100000", "--height", "100000"]));
    assert!(e.contains("larger than the limit"), "{e}");
    let e = error_line(&render(&[p, "-o", out.to_str().unwrap(), "--spp", "0"]));
    assert!(e.contains("spp"), "{e}");
    let e = error_line(&render(&[p, "-o", out.to_str().unwrap(), "--crop", "0.5,0.2,0,1"]));
    assert!(e.contains("--crop") && e.contains("x0 < x1"), "{e}");
    // What clap cannot read: one line too (status 2).
    let out2 = render(&[p, "--crop", "0.5,0.2"]);
    let stderr = String::from_utf8_lossy(&out2.stderr);
    assert_eq!((out2.status.code(), stderr.lines().count()), (Some(2), 1), "{stderr}");
    assert!(stderr.contains("four numbers"), "{stderr}");
    // A missing argument is named, with what it goes with.
    for (args, says) in [(&[][..], "<SCENE>"), (&[p, "--frame-range", "0..2"], "--frames <N>")] {
        let out = render(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!((out.status.code(), stderr.lines().count()), (Some(2), 1), "{stderr}");
        assert!(stderr.contains("not provided: ") && stderr.contains(says), "{args:?}: {stderr}");
    }
    // A template is named as one: the scene draws only its instances.
    #[cfg(feature = "evolved")]
    {
        let templated = dir.join("templated.toml");
        let fig3b = std::fs::read_to_string(scene("fig3b.toml")).unwrap();
        let text = fig3b.replacen("name = \"surface\"", "name = \"surface\"\ntemplate = true", 1)
            + "\n[[objects]]\ntype = \"instance\"\nof = \"surface\"\nname = \"copy\"\n";
        std::fs::write(&templated, text).unwrap();
        let t = templated.to_str().unwrap();
        let mesh = Command::new(env!("CARGO_BIN_EXE_cga-trace"))
            .args(["mesh", t, "--object", "surface", "-o", dir.join("m.obj").to_str().unwrap()])
            .output()
            .unwrap();
        let e = error_line(&mesh);
        assert!(e.contains("`surface` is a template") && e.contains("name one of them"), "{e}");
    }
    // The scene file's size is bounded: an endless file is refused, not read forever.
    #[cfg(unix)]
    {
        let e = error_line(&render(&["/dev/zero", "-o", out.to_str().unwrap()]));
        assert!(e.contains("larger than the limit"), "{e}");
    }
}

#[test]
fn help_points_at_the_scene_format() {
    let out = Command::new(env!("CARGO_BIN_EXE_cga-trace")).args(["render", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("docs/SCENES.md#scene-files") && help.contains("--spp") && help.contains("--crop"), "{help}");
}

/// `primitives.toml` rendered 32 pixels wide with `extra` to `dir/name`, and read back.
fn primitives(dir: &Path, name: &str, extra: &[&str]) -> image::DynamicImage {
    let (p, path) = (scene("primitives.toml"), dir.join(name));
    let mut args = vec![p.to_str().unwrap(), "-o", path.to_str().unwrap(), "--width", "32"];
    args.extend_from_slice(extra);
    let out = render(&args);
    assert!(out.status.success(), "{out:?}");
    image::open(&path).unwrap()
}

#[test]
fn formats_follow_the_extension() {
    let scratch_dir = scratch("formats");
    let dir = scratch_dir.path();
    let run = |name: &str, extra: &[&str]| primitives(dir, name, &[&["--encoding", "linear"], extra].concat());
    let png8 = run("a.png", &[]);
    let png16 = run("b.png", &["--bit-depth", "16"]);
    let exr = run("c.exr", &[]);
    let hdr = run("d.hdr", &[]);
    assert_eq!(png8.color(), image::ColorType::Rgb8);
    assert_eq!(png16.color(), image::ColorType::Rgb16);
    assert_eq!((png8.width(), png8.height()), (32, 24));
    // The floating-point files hold the linear values: where they are below 1 (unclipped),
    // they agree with the 16-bit linear PNG to its quantisation (and RGBE's 8-bit mantissa).
    let (exr, hdr, png16) = (exr.to_rgb32f(), hdr.to_rgb32f(), png16.to_rgb16());
    let mut compared = 0;
    for ((e, h), p) in exr.pixels().zip(hdr.pixels()).zip(png16.pixels()) {
        for k in 0..3 {
            let linear = f32::from(p.0[k]) / 65535.0;
            if e.0[k] < 0.99 {
                assert!((e.0[k] - linear).abs() <= 1.0 / 65535.0, "EXR {} against PNG {linear}", e.0[k]);
                // RGBE shares one exponent: 8 bits of mantissa relative to the largest channel.
                let largest = e.0.iter().fold(0f32, |a, b| a.max(*b));
                assert!((h.0[k] - e.0[k]).abs() <= largest / 128.0 + 1e-6, "HDR {} against EXR {}", h.0[k], e.0[k]);
                compared += 1;
            }
        }
    }
    assert!(compared > 1000);
}

#[test]
fn a_transparent_background_writes_alpha_and_hdr_is_refused_by_name() {
    let scratch_dir = scratch("transparent");
    let dir = scratch_dir.path();
    let p = scene("primitives.toml");
    let p = p.to_str().unwrap();
    let run = |name: &str, extra: &[&str]| primitives(dir, name, extra);
    let png = run("t.png", &["--background", "transparent"]);
    assert_eq!(png.color(), image::ColorType::Rgba8);
    let alpha: Vec<u8> = png.to_rgba8().pixels().map(|p| p.0[3]).collect();
    // primitives.toml: the sky above the floor's horizon sees through, the floor is opaque.
    assert!(alpha.contains(&0) && alpha.contains(&255), "{alpha:?}");
    assert_eq!(run("t16.png", &["--background", "transparent", "--bit-depth", "16"]).color(), image::ColorType::Rgba16);
    assert_eq!(run("t.exr", &["--background", "transparent"]).color(), image::ColorType::Rgba32F);
    // A colour from the command line: opaque, the colour where nothing is met.
    let blue = run("b.png", &["--background", "0,0,1", "--encoding", "linear"]).to_rgb8();
    assert_eq!(blue.get_pixel(0, 0).0, [0, 0, 255]);
    // HDR has no alpha: refused before rendering, naming the output and the setting, and an
    // existing file is left as it was.
    let hdr = dir.join("t.hdr");
    std::fs::write(&hdr, b"old").unwrap();
    let e = error_line(&render(&[p, "-o", hdr.to_str().unwrap(), "--background", "transparent"]));
    assert!(e.contains("t.hdr") && e.contains("background = \"transparent\""), "{e}");
    assert_eq!(std::fs::read(&hdr).unwrap(), b"old");
    let bad = render(&[p, "-o", hdr.to_str().unwrap(), "--background", "clear"]);
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!((bad.status.code(), stderr.lines().count()), (Some(2), 1), "{stderr}");
    assert!(stderr.contains("transparent"), "{stderr}");
}

#[test]
fn crops_from_the_command_line_assemble_into_the_frame() {
    let scratch_dir = scratch("crops");
    let dir = scratch_dir.path();
    let p = scene("combined.toml");
    let run = |name: &str, crop: Option<&str>| {
        let path = dir.join(name);
        let mut args = vec![p.to_str().unwrap(), "-o", path.to_str().unwrap(), "--width", "48", "--spp", "4"];
        if let Some(c) = crop {
            args.extend(["--crop", c]);
        }
        assert!(render(&args).status.success());
        image::open(&path).unwrap().to_rgb8()
    };
    let full = run("full.png", None);
    let top = run("top.png", Some("0,1,0,0.5"));
    let bottom = run("bottom.png", Some("0,1,0.5,1"));
    assert_eq!((top.height(), bottom.height()), (18, 18));
    let mut assembled = image::RgbImage::new(48, 36);
    image::imageops::replace(&mut assembled, &top, 0, 0);
    image::imageops::replace(&mut assembled, &bottom, 0, 18);
    assert_eq!(assembled.into_raw(), full.into_raw());
}

#[test]
fn a_camera_without_a_size_takes_the_command_lines_and_a_dark_scene_gets_a_note() {
    let scratch_dir = scratch("sizeless");
    let dir = scratch_dir.path();
    let file = dir.join("sizeless.toml");
    std::fs::write(
        &file,
        "[camera]\nposition = [0.0, -8.0, 0.0]\nlook_at = [0.0, 0.0, 0.0]\n\
         [[objects]]\ntype = \"sphere\"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\nmaterial = { colour = [1.0, 0.0, 0.0] }\n",
    )
    .unwrap();
    let (f, out) = (file.to_str().unwrap(), dir.join("out.png"));
    let o = out.to_str().unwrap();
    let line = error_line(&render(&[f, "-o", o, "--width", "32"]));
    assert!(line.contains("`width` and `height`") && line.contains("--width and --height"), "{line}");
    let run = render(&[f, "-o", o, "--width", "32", "--height", "24"]);
    assert!(run.status.success(), "{run:?}");
    assert_eq!(image::image_dimensions(&out).unwrap(), (32, 24));
    assert!(String::from_utf8_lossy(&run.stderr).contains("note: the scene has no lights"), "{run:?}");
}

#[test]
fn frames_are_numbered_files_and_a_range_renders_only_its_own() {
    let scratch_dir = scratch("frames");
    let dir = scratch_dir.path();
    let scene_file = scene("primitives.toml");
    let (s, out) = (scene_file.to_str().unwrap(), dir.join("anim.png"));
    let o = out.to_str().unwrap();
    let run = render(&[s, "-o", o, "--width", "16", "--frames", "3", "--frame-range", "1..3"]);
    assert!(run.status.success(), "{run:?}");
    let names: std::collections::BTreeSet<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert_eq!(names, ["anim_0001.png", "anim_0002.png"].map(String::from).into());
    let line = error_line(&render(&[s, "-o", o, "--frames", "3", "--frame-range", "2..5"]));
    assert!(line.contains("--frame-range 2..5: the animation has frames 0 to 2"), "{line}");
}

#[test]
fn exposure_scales_linear_values_and_the_filmic_map_keeps_highlights_below_white() {
    let scratch_dir = scratch("exposure");
    let dir = scratch_dir.path();
    let p = scene("primitives.toml");
    let s = p.to_str().unwrap();
    let png = |name: &str, extra: &[&str]| {
        let out = dir.join(name);
        let mut args = vec![s, "-o", out.to_str().unwrap(), "--width", "40", "--encoding", "linear"];
        args.extend_from_slice(extra);
        let run = render(&args);
        assert!(run.status.success(), "{run:?}");
        image::open(&out).unwrap().to_rgb8().into_raw()
    };
    let (plain, brighter) = (png("a.png", &[]), png("b.png", &["--exposure", "1"]));
    // One stop doubles every linear value (to rounding of 8 bits), clipped at white.
    let off = plain.iter().zip(&brighter).filter(|(a, b)| (2 * u32::from(**a)).min(255).abs_diff(u32::from(**b)) > 1);
    assert_eq!(off.count(), 0);
    let darker = png("c.png", &["--exposure", "-1"]);
    // One stop down halves what the plain picture did not clip (a clipped value was over 1).
    let unclipped = plain.iter().zip(&darker).filter(|(a, _)| **a < 255);
    assert!(unclipped.clone().count() > 1000);
    assert!(unclipped.clone().all(|(a, b)| (u32::from(*a) / 2).abs_diff(u32::from(*b)) <= 1));
    // Filmic at +3 stops: what clips without it stays below white.
    let (clipped, filmic) =
        (png("d.png", &["--exposure", "3"]), png("e.png", &["--exposure", "3", "--tone-map", "filmic"]));
    assert!(clipped.iter().filter(|&&v| v == 255).count() > filmic.iter().filter(|&&v| v == 255).count());
    let line = error_line(&render(&[s, "-o", dir.join("f.png").to_str().unwrap(), "--exposure", "100"]));
    assert!(line.contains("--exposure") && line.contains("exposure must lie in [-64, 64] stops"), "{line}");
}

#[test]
fn a_shutter_blurs_what_moves_and_leaves_what_stands() {
    let scratch_dir = scratch("shutter");
    let dir = scratch_dir.path();
    let p = scene("motion.toml");
    let s = p.to_str().unwrap();
    let still = dir.join("still.toml");
    let text = std::fs::read_to_string(&p).unwrap().replace("shutter = [0.0, 1.0]\n", "");
    std::fs::write(&still, text).unwrap();
    let png = |scene: &str, name: &str| {
        let out = dir.join(name);
        let run = render(&[scene, "-o", out.to_str().unwrap(), "--width", "64", "--spp", "8"]);
        assert!(run.status.success(), "{run:?}");
        image::open(&out).unwrap().to_rgb8()
    };
    let (blurred, sharp) = (png(s, "blurred.png"), png(still.to_str().unwrap(), "still.png"));
    // The moving ring and ball differ; the post standing at the right does not.
    let differ = |x0: u32, x1: u32| {
        (x0..x1)
            .flat_map(|x| (0..blurred.height()).map(move |y| (x, y)))
            .filter(|&(x, y)| blurred.get_pixel(x, y) != sharp.get_pixel(x, y))
            .count()
    };
    assert!(differ(0, 40) > 200, "{}", differ(0, 40));
    let post = blurred.width() * 55 / 64;
    assert!(blurred.get_pixel(post, 20).0.iter().zip(sharp.get_pixel(post, 20).0).all(|(a, b)| a.abs_diff(b) <= 2));
}
