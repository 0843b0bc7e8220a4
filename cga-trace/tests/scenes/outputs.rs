//! No input and no existing output is ever lost, through the binary: every way a render or a
//! mesh export can fail leaves the files it names as they were (hashed before and after), an
//! output that is an input — by path, symbolic link or hard link — is refused before anything
//! is written, a link to a device is written through and kept, and a closed or full stderr
//! never turns into a panic.

use crate::common;

use common::snapshot;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// A fresh scratch directory for one test, removed when the test ends, pass or fail.
fn scratch(test: &str) -> tempfile::TempDir {
    tempfile::Builder::new().prefix(&format!("cga-trace-outputs-{test}-")).tempdir().unwrap()
}

fn cga_trace(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cga-trace")).args(args).output().unwrap()
}

/// Runs `args` in `dir`, expecting a one-line error containing `says`, and checks that the
/// directory is exactly as it was (nothing removed, truncated or left behind).
fn fails_and_keeps(dir: &Path, args: &[&str], says: &str) {
    let before = snapshot(dir);
    let out = Command::new(env!("CARGO_BIN_EXE_cga-trace")).current_dir(dir).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
    assert!(stderr.contains(says), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    assert_eq!(snapshot(dir), before, "{args:?} changed the directory");
}

#[test]
fn an_existing_output_survives_every_failure() {
    let scratch_dir = scratch("survives");
    let dir = scratch_dir.path();
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.toml")).unwrap();
    std::fs::write(dir.join("out.png"), b"an earlier render").unwrap();
    std::fs::write(dir.join("broken.toml"), "[camera\n").unwrap();
    std::fs::write(dir.join("out.png.scale.json"), b"an earlier scale").unwrap();
    for (args, says) in [
        (&["render", "broken.toml", "-o", "out.png"][..], "broken.toml:1:"),
        (&["render", "missing.toml", "-o", "out.png"], "missing.toml"),
        (&["render", "scene.toml", "-o", "out.png", "--spp", "0"], "spp"),
        (&["render", "scene.toml", "-o", "out.png", "--crop", "0.5,0.2,0,1"], "--crop"),
        (&["render", "scene.toml", "-o", "out.png", "--fov", "200"], "--fov"),
        (&["render", "scene.toml", "-o", "out.png", "--threads", "0"], "--threads"),
        (&["render", "scene.toml", "-o", "out.png", "--width", "100000", "--height", "100000"], "limit"),
        (&["render", "broken.toml", "-o", "out.png", "--aov", "gaussian"], "broken.toml:1:"),
        (&["render", "scene.toml", "-o", "out.png", "--aov", "gaussian", "--crop", "2,3,0,1"], "--crop"),
    ] {
        fails_and_keeps(dir, args, says);
    }
}

#[test]
fn an_output_that_is_an_input_is_refused() {
    let scratch_dir = scratch("inputs");
    let dir = scratch_dir.path();
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.toml")).unwrap();
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.png")).unwrap();
    std::fs::copy(shipped("fig3b.toml"), dir.join("surface.obj")).unwrap();
    let mut cases = vec![
        (vec!["render", "scene.png", "-o", "scene.png"], "same file as the scene"),
        (vec!["render", "./scene.png", "-o", "scene.png"], "same file as the scene"),
        (vec!["mesh", "surface.obj", "--object", "surface", "-o", "surface.obj"], "same file as the scene"),
    ];
    #[cfg(unix)]
    {
        let link = |target: &str, name: &str| std::os::unix::fs::symlink(target, dir.join(name)).unwrap();
        link("scene.toml", "link.png");
        link("link.png", "link-to-link.png");
        link("scene.toml", "x.png.scale.json");
        link("surface.obj", "mesh-link.obj");
        std::fs::hard_link(dir.join("scene.toml"), dir.join("hard.png")).unwrap();
        cases.extend([
            (vec!["render", "scene.toml", "-o", "link.png"], "same file as the scene"),
            (vec!["render", "scene.toml", "-o", "link-to-link.png"], "same file as the scene"),
            (vec!["render", "scene.toml", "-o", "hard.png"], "same file as the scene"),
            (vec!["render", "scene.toml", "-o", "x.png", "--aov", "gaussian"], "x.png.scale.json"),
            (vec!["mesh", "surface.obj", "--object", "surface", "-o", "mesh-link.obj"], "same file as the scene"),
        ]);
    }
    for (args, says) in cases {
        fails_and_keeps(dir, &args, says);
    }
}

#[cfg(unix)]
#[test]
fn links_are_written_through_and_devices_never_removed() {
    let scratch_dir = scratch("links");
    let dir = scratch_dir.path();
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.toml")).unwrap();
    std::fs::write(dir.join("broken.toml"), "[camera\n").unwrap();
    std::fs::create_dir(dir.join("renders")).unwrap();
    std::fs::write(dir.join("renders/v3.png"), b"version 3").unwrap();
    std::os::unix::fs::symlink("renders/v3.png", dir.join("latest.png")).unwrap();
    std::os::unix::fs::symlink("/dev/full", dir.join("full.png")).unwrap();
    std::os::unix::fs::symlink("/dev/null", dir.join("null.png")).unwrap();
    std::fs::create_dir(dir.join("folder.png")).unwrap();
    // The user's case: a failed render through a link leaves the link and its file.
    fails_and_keeps(dir, &["render", "broken.toml", "-o", "latest.png"], "broken.toml:1:");
    // A device that cannot take the bytes: an error, and the link is still there.
    fails_and_keeps(dir, &["render", "scene.toml", "-o", "full.png", "--width", "16"], "No space left");
    fails_and_keeps(dir, &["render", "scene.toml", "-o", "folder.png", "--width", "16"], "is a directory");
    let run = |out: &str| {
        Command::new(env!("CARGO_BIN_EXE_cga-trace"))
            .current_dir(dir)
            .args(["render", "scene.toml", "-o", out, "--width", "16"])
            .output()
            .unwrap()
    };
    assert!(run("null.png").status.success());
    assert!(std::fs::symlink_metadata(dir.join("null.png")).unwrap().file_type().is_symlink());
    // A render through the link replaces the file it names, and keeps the link.
    assert!(run("latest.png").status.success());
    assert!(std::fs::symlink_metadata(dir.join("latest.png")).unwrap().file_type().is_symlink());
    let image = image::open(dir.join("renders/v3.png")).unwrap();
    assert_eq!((image.width(), image.height()), (16, 12));
    // A named pipe is refused at once (opening it to write would wait for a reader).
    let fifo = dir.join("pipe.png");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    fails_and_keeps(dir, &["render", "scene.toml", "-o", "pipe.png", "--width", "16"], "named pipe");
    // Only the outputs asked for were written: no temporary file is left anywhere.
    let names: Vec<String> = snapshot(dir).into_iter().map(|(n, _)| n).collect();
    assert!(names.iter().all(|n| !n.ends_with(".tmp")), "{names:?}");
}

#[test]
fn a_replaced_output_keeps_its_permissions() {
    let scratch_dir = scratch("mode");
    let dir = scratch_dir.path();
    let out = dir.join("out.png");
    std::fs::write(&out, b"old").unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o640)).unwrap();
    }
    let scene = shipped("primitives.toml");
    assert!(
        cga_trace(&["render", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--width", "8"]).status.success()
    );
    assert!(image::open(&out).is_ok());
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        assert_eq!(std::fs::metadata(&out).unwrap().permissions().mode() & 0o777, 0o640);
        let new = dir.join("new.png");
        assert!(
            cga_trace(&["render", scene.to_str().unwrap(), "-o", new.to_str().unwrap(), "--width", "8"])
                .status
                .success()
        );
        let mode = std::fs::metadata(&new).unwrap().permissions().mode() & 0o777;
        assert_eq!(
            mode & 0o600,
            0o600,
            "a new file is as File::create makes it, not the temporary file's 0600: {mode:o}"
        );
    }
}

/// A render (or its error) whose stderr is closed, a pipe nobody reads, or a full device:
/// the status says what happened, and nothing panics (status 101).
#[cfg(unix)]
#[test]
fn a_broken_stderr_never_panics() {
    let scratch_dir = scratch("stderr");
    let dir = scratch_dir.path();
    let scene = shipped("primitives.toml");
    std::fs::write(dir.join("broken.toml"), "[camera\n").unwrap();
    let (good, bad) = (scene.to_str().unwrap().to_string(), dir.join("broken.toml").to_string_lossy().into_owned());
    let out = dir.join("out.png");
    for (scene, status) in [(&good, 0), (&bad, 1)] {
        let args = ["render", scene.as_str(), "-o", out.to_str().unwrap(), "--width", "8", "--threads", "4"];
        // stderr on /dev/full.
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
        let run = Command::new(env!("CARGO_BIN_EXE_cga-trace")).args(args).stderr(full).status().unwrap();
        assert_eq!(run.code(), Some(status), "/dev/full");
        // stderr a pipe whose reader has gone.
        let mut child =
            Command::new(env!("CARGO_BIN_EXE_cga-trace")).args(args).stderr(Stdio::piped()).spawn().unwrap();
        drop(child.stderr.take());
        assert_eq!(child.wait().unwrap().code(), Some(status), "closed pipe");
        // stderr closed altogether.
        let run = Command::new("sh")
            .arg("-c")
            .arg(format!("exec 2>&-; exec '{}' \"$@\"", env!("CARGO_BIN_EXE_cga-trace")))
            .arg("sh")
            .args(args)
            .status()
            .unwrap();
        assert_eq!(run.code(), Some(status), "closed stderr");
    }
}

#[test]
fn counts_the_command_line_sets_are_bounded_before_anything_is_allocated() {
    let scratch_dir = scratch("limits");
    let dir = scratch_dir.path();
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.toml")).unwrap();
    std::fs::copy(shipped("fig3b.toml"), dir.join("surface.toml")).unwrap();
    for (args, says) in [
        (&["render", "scene.toml", "-o", "a.png", "--threads", "0"][..], "give 1 to 1024"),
        (&["render", "scene.toml", "-o", "a.png", "--threads", "1025"], "give 1 to 1024"),
        (&["render", "scene.toml", "-o", "a.png", "--threads", "18446744073709551615"], "give 1 to 1024"),
        (
            &["mesh", "surface.toml", "--object", "surface", "-o", "m.obj", "--rings", "8192", "--segments", "8192"],
            "at most 4194304 vertices",
        ),
        (
            &["mesh", "surface.toml", "--object", "surface", "-o", "m.obj", "--rings", "65536", "--segments", "65534"],
            "at most 4194304 vertices",
        ),
        (&["mesh", "surface.toml", "--object", "surface", "-o", "m.obj", "--rings", "0"], "1 to 65536 rings"),
        (&["mesh", "surface.toml", "--object", "surface", "-o", "m.obj", "--segments", "2"], "3 to 65536 segments"),
    ] {
        fails_and_keeps(dir, args, says);
    }
    // More threads than cores: rendered, with a note that says so.
    let out = Command::new(env!("CARGO_BIN_EXE_cga-trace"))
        .current_dir(dir)
        .args(["render", "scene.toml", "-o", "a.png", "--width", "8", "--threads", "1024"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 1024 {
        assert!(String::from_utf8_lossy(&out.stderr).contains("threads beyond the cores"), "{out:?}");
    }
}

/// A folder with a scene that reads a file of every role: an included file, a texture, an
/// environment image and a mesh (beside a swept surface, for `mesh`).
fn every_role(test: &str) -> tempfile::TempDir {
    let scratch_dir = scratch(test);
    let dir = scratch_dir.path();
    let scenes = shipped("");
    for (from, to) in [
        ("parts/studio.toml", "parts/studio.toml"),
        ("maps/grid.png", "maps/grid.png"),
        ("maps/sky.png", "maps/sky.png"),
        ("meshes/vase.obj", "meshes/vase.obj"),
    ] {
        std::fs::create_dir_all(dir.join(to).parent().unwrap()).unwrap();
        std::fs::copy(scenes.join(from), dir.join(to)).unwrap();
    }
    let surface = std::fs::read_to_string(shipped("fig3b.toml")).unwrap();
    let scene = format!(
        "include = [\"parts/studio.toml\"]\n{surface}\n[environment]\nimage = \"maps/sky.png\"\n\n\
         [[objects]]\nname = \"ball\"\ntype = \"sphere\"\ncentre = [3.0, 0.0, 0.0]\nradius = 0.5\n\
         material = {{ colour = [1.0, 1.0, 1.0], texture = {{ image = \"maps/grid.png\" }} }}\n\n\
         [[objects]]\nname = \"vase\"\ntype = \"mesh\"\nfile = \"meshes/vase.obj\"\nscale = 0.1\n\
         material = {{ colour = [1.0, 1.0, 1.0] }}\n"
    );
    std::fs::write(dir.join("scene.toml"), scene).unwrap();
    scratch_dir
}

#[test]
fn no_input_of_any_role_can_be_an_output() {
    let scratch_dir = every_role("roles");
    let dir = scratch_dir.path();
    fn render(out: &str) -> Vec<&str> {
        vec!["render", "scene.toml", "-o", out, "--width", "16", "--height", "12"]
    }
    fn mesh(out: &str) -> Vec<&str> {
        vec!["mesh", "scene.toml", "--object", "surface", "-o", out, "--rings", "4"]
    }
    // Sanity: the scene renders and meshes with outputs elsewhere.
    for args in [render("fine.png"), mesh("fine.obj")] {
        let out = Command::new(env!("CARGO_BIN_EXE_cga-trace")).current_dir(dir).args(&args).output().unwrap();
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
    let roles = [
        ("parts/studio.toml", "the included file `"),
        ("maps/grid.png", "the texture `"),
        ("maps/sky.png", "the environment image `"),
        ("meshes/vase.obj", "the mesh `"),
    ];
    for (k, (input, role)) in roles.into_iter().enumerate() {
        // The input itself, however spelt: refused (by its role, or as no image or mesh).
        for name in [input.to_string(), format!("./{input}"), format!("parts/../{input}")] {
            fails_and_keeps(dir, &render(&name), "");
            fails_and_keeps(dir, &mesh(&name), "");
        }
        let extension = Path::new(input).extension().unwrap().to_str().unwrap();
        if matches!(extension, "png" | "obj") {
            let args = if extension == "png" { render(input) } else { mesh(input) };
            fails_and_keeps(dir, &args, role);
        }
        // Links to it under an image's and a mesh's name: refused by its role.
        #[cfg(unix)]
        for kind in ["png", "obj"] {
            let (sym, hard) = (format!("sym{k}.{kind}"), format!("hard{k}.{kind}"));
            std::os::unix::fs::symlink(input, dir.join(&sym)).unwrap();
            std::fs::hard_link(dir.join(input), dir.join(&hard)).unwrap();
            for name in [&sym, &hard] {
                let args = if kind == "png" { render(name) } else { mesh(name) };
                fails_and_keeps(dir, &args, role);
            }
        }
        // The scale beside a false-colour image, a link to the input.
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(input, dir.join(format!("x{k}.png.scale.json"))).unwrap();
            let out = format!("x{k}.png");
            let mut args = render(&out);
            args.extend(["--aov", "gaussian"]);
            fails_and_keeps(dir, &args, role);
        }
    }
}

#[cfg(unix)]
#[test]
fn frames_are_never_written_over_each_other() {
    let scratch_dir = scratch("frames");
    let dir = scratch_dir.path();
    std::fs::copy(shipped("motion.toml"), dir.join("scene.toml")).unwrap();
    fn frames(out: &str) -> Vec<&str> {
        vec!["render", "scene.toml", "-o", out, "--frames", "3", "--width", "8", "--height", "6"]
    }
    // A link from one frame to another, existing or not yet written, and a hard link.
    std::os::unix::fs::symlink("a_0001.png", dir.join("a_0000.png")).unwrap();
    fails_and_keeps(dir, &frames("a.png"), "are the same file");
    std::fs::write(dir.join("b_0002.png"), b"frame 2 of another run").unwrap();
    std::os::unix::fs::symlink("b_0002.png", dir.join("b_0000.png")).unwrap();
    fails_and_keeps(dir, &frames("b.png"), "are the same file");
    std::fs::write(dir.join("c_0000.png"), b"frame 0").unwrap();
    std::fs::hard_link(dir.join("c_0000.png"), dir.join("c_0001.png")).unwrap();
    fails_and_keeps(dir, &frames("c.png"), "are the same file");
    // Also when only part of the animation is rendered here.
    let mut some = frames("b.png");
    some.extend(["--frame-range", "0..1"]);
    fails_and_keeps(dir, &some, "are the same file");
    // Links elsewhere are written through.
    std::fs::create_dir(dir.join("out")).unwrap();
    std::os::unix::fs::symlink("out/d_0001.png", dir.join("d_0001.png")).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cga-trace")).current_dir(dir).args(frames("d.png")).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("out/d_0001.png").is_file() && dir.join("d_0002.png").is_file());
}

/// Runs `args` in `dir` and gives its output, or fails if it takes more than `seconds`.
#[cfg(unix)]
fn within(dir: &Path, args: &[&str], seconds: u64) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cga-trace"))
        .current_dir(dir)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed().as_secs() > seconds {
            child.kill().unwrap();
            panic!("{args:?} still running after {seconds} s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[cfg(unix)]
#[test]
fn a_pipe_or_device_named_by_a_scene_is_refused_at_once() {
    let scratch_dir = every_role("pipes");
    let dir = scratch_dir.path();
    assert!(Command::new("mkfifo").arg(dir.join("pipe")).status().unwrap().success());
    let scene = std::fs::read_to_string(dir.join("scene.toml")).unwrap();
    for (input, says) in [
        ("parts/studio.toml", "include `pipe`"),
        ("maps/grid.png", "`image`"),
        ("maps/sky.png", "`image`"),
        ("meshes/vase.obj", "`file`"),
    ] {
        for (name, kind) in [("pipe", "a named pipe"), ("/dev/zero", "a device"), ("parts", "a directory")] {
            let text = scene.replace(input, name);
            std::fs::write(dir.join("named.toml"), text).unwrap();
            let out = within(dir, &["render", "named.toml", "-o", "out.png", "--width", "8", "--height", "6"], 30);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{input} as {name}: {stderr}");
            assert!(stderr.contains("named.toml:") && stderr.contains(kind), "{input} as {name}: {stderr}");
            if name == "pipe" {
                assert!(stderr.contains(says), "{input} as {name}: {stderr}");
            }
        }
    }
}
