//! No input and no existing output is ever lost, through the binary: every way a render or a
//! mesh export can fail leaves the files it names as they were (hashed before and after), an
//! output that is an input — by path, symbolic link or hard link — is refused before anything
//! is written, a link to a device is written through and kept, and a closed or full stderr
//! never turns into a panic.

mod common;

use common::snapshot;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// A fresh scratch directory for one test.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cga-trace-outputs-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
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
    let dir = scratch("survives");
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
        fails_and_keeps(&dir, args, says);
    }
}

#[test]
fn an_output_that_is_an_input_is_refused() {
    let dir = scratch("inputs");
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
        fails_and_keeps(&dir, &args, says);
    }
}

#[cfg(unix)]
#[test]
fn links_are_written_through_and_devices_never_removed() {
    let dir = scratch("links");
    std::fs::copy(shipped("primitives.toml"), dir.join("scene.toml")).unwrap();
    std::fs::write(dir.join("broken.toml"), "[camera\n").unwrap();
    std::fs::create_dir(dir.join("renders")).unwrap();
    std::fs::write(dir.join("renders/v3.png"), b"version 3").unwrap();
    std::os::unix::fs::symlink("renders/v3.png", dir.join("latest.png")).unwrap();
    std::os::unix::fs::symlink("/dev/full", dir.join("full.png")).unwrap();
    std::os::unix::fs::symlink("/dev/null", dir.join("null.png")).unwrap();
    std::fs::create_dir(dir.join("folder.png")).unwrap();
    // The user's case: a failed render through a link leaves the link and its file.
    fails_and_keeps(&dir, &["render", "broken.toml", "-o", "latest.png"], "broken.toml:1:");
    // A device that cannot take the bytes: an error, and the link is still there.
    fails_and_keeps(&dir, &["render", "scene.toml", "-o", "full.png", "--width", "16"], "No space left");
    fails_and_keeps(&dir, &["render", "scene.toml", "-o", "folder.png", "--width", "16"], "is a directory");
    let run = |out: &str| {
        Command::new(env!("CARGO_BIN_EXE_cga-trace"))
            .current_dir(&dir)
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
    fails_and_keeps(&dir, &["render", "scene.toml", "-o", "pipe.png", "--width", "16"], "named pipe");
    // Only the outputs asked for were written: no temporary file is left anywhere.
    let names: Vec<String> = snapshot(&dir).into_iter().map(|(n, _)| n).collect();
    assert!(names.iter().all(|n| !n.ends_with(".tmp")), "{names:?}");
}

#[test]
fn a_replaced_output_keeps_its_permissions() {
    let dir = scratch("mode");
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
    let dir = scratch("stderr");
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
    let dir = scratch("limits");
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
        fails_and_keeps(&dir, args, says);
    }
    // More threads than cores: rendered, with a note that says so.
    let out = Command::new(env!("CARGO_BIN_EXE_cga-trace"))
        .current_dir(&dir)
        .args(["render", "scene.toml", "-o", "a.png", "--width", "8", "--threads", "1024"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 1024 {
        assert!(String::from_utf8_lossy(&out.stderr).contains("threads beyond the cores"), "{out:?}");
    }
}
