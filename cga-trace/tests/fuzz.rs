//! A fuzzer over the shipped scenes: numbers turned to NaN, ±∞, ±1e308, 0 or negative values;
//! arrays made longer, shorter or of the wrong type; lines removed, duplicated or moved; keys
//! misspelt; bytes garbled. Every mutant must give either a located error (no control
//! characters) or a scene that renders without a NaN, in bounded time, without a panic or
//! an abort; the image sizes it can ask for are bounded by `limits` before allocation.
//!
//! `cargo test` runs 3,000 mutants (a few seconds in a debug build). More:
//! `CGA_FUZZ_CASES=20000 cargo test --release -p cga-trace --test fuzz -- --nocapture`
//! (`CGA_FUZZ_SEED` picks another stream).

use cga_trace::limits::MAX_PIXELS;
use cga_trace::{Aov, Renderer, Scene};
use rand::{RngExt, SeedableRng};
use rand_xorshift::XorShiftRng;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

/// What a number may become.
const NUMBERS: [&str; 16] = [
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "0",
    "0.0",
    "-1.0",
    "-0.0",
    "1e100",
    "1e-300",
    "4294967295",
    "100000000000",
    "-7",
    "\"x\"",
    "[1.0]",
];

/// The shipped scenes, by name.
fn seeds() -> Vec<(String, String)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut seeds: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    seeds.sort();
    seeds
}

/// Byte ranges of the numbers in `text` (outside comments, roughly: good enough to mutate).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut k = 0;
    while k < b.len() {
        let starts = b[k].is_ascii_digit() || (b[k] == b'-' && b.get(k + 1).is_some_and(u8::is_ascii_digit));
        let after_word = k > 0 && (b[k - 1].is_ascii_alphanumeric() || b[k - 1] == b'_');
        if starts && !after_word {
            let start = k;
            k += 1;
            while k < b.len() && (b[k].is_ascii_alphanumeric() || b"+-._".contains(&b[k])) {
                k += 1;
            }
            out.push((start, k));
        } else {
            k += 1;
        }
    }
    out
}

/// One random change of `text`.
fn mutate(text: &str, rng: &mut XorShiftRng) -> String {
    let pick = |rng: &mut XorShiftRng, n: usize| rng.random_range(0..n.max(1));
    let lines: Vec<&str> = text.lines().collect();
    match rng.random_range(0..9) {
        // A number becomes an extreme, non-finite, negative or ill-typed value.
        0..=2 => {
            let spots = numbers(text);
            let (a, b) = spots[pick(rng, spots.len())];
            format!("{}{}{}", &text[..a], NUMBERS[pick(rng, NUMBERS.len())], &text[b..])
        }
        // An array gets longer, shorter, or becomes a string.
        3 => {
            let closes: Vec<usize> = text.match_indices(']').map(|(k, _)| k).collect();
            if closes.is_empty() {
                return text.to_string();
            }
            let k = closes[pick(rng, closes.len())];
            match rng.random_range(0..3) {
                0 => format!("{}, 1.5{}", &text[..k], &text[k..]),
                1 => match text[..k].rfind(',') {
                    Some(c) if !text[c..k].contains('[') => format!("{}{}", &text[..c], &text[k..]),
                    _ => text.to_string(),
                },
                _ => match text[..k].rfind('[') {
                    Some(o) => format!("{}\"ab\"{}", &text[..o], &text[k + 1..]),
                    None => text.to_string(),
                },
            }
        }
        // A line removed, duplicated, or moved.
        4 => {
            let k = pick(rng, lines.len());
            let mut l = lines.clone();
            match rng.random_range(0..3) {
                0 => {
                    l.remove(k);
                }
                1 => l.insert(k, lines[k]),
                _ => {
                    let line = l.remove(k);
                    let to = pick(rng, l.len());
                    l.insert(to, line);
                }
            }
            l.join("\n")
        }
        // A key misspelt.
        5 => {
            let keys: Vec<usize> = text.match_indices(" = ").map(|(k, _)| k).collect();
            if keys.is_empty() {
                return text.to_string();
            }
            let k = keys[pick(rng, keys.len())];
            format!("{}x{}", &text[..k], &text[k..])
        }
        // Bytes garbled.
        _ => {
            let mut bytes = text.as_bytes().to_vec();
            for _ in 0..rng.random_range(1..4) {
                let k = pick(rng, bytes.len());
                bytes[k] = rng.random_range(0..=255u8);
            }
            String::from_utf8_lossy(&bytes).into_owned()
        }
    }
}

/// Parse and, if accepted, render a shrunken copy; `Err` says what went wrong.
fn check(text: &str) -> Result<&'static str, String> {
    let scene = match catch_unwind(|| Scene::parse(text, "fuzz.toml")) {
        Err(_) => return Err("parse panicked".into()),
        Ok(Err(e)) => {
            let e = e.to_string();
            if !e.starts_with("fuzz.toml:") || e.chars().any(char::is_control) {
                return Err(format!("unlocated or unescaped error: {e:?}"));
            }
            return Ok("error");
        }
        Ok(Ok(scene)) => scene,
    };
    let mut scene = scene;
    let c = scene.camera;
    if u64::from(c.width) * u64::from(c.height) > MAX_PIXELS {
        return Err(format!("{} × {} accepted", c.width, c.height));
    }
    // Bounded work per mutant: at most 12 pixels wide, 3 bounces, 2 samples.
    if c.width > 12 {
        scene.resize(Some(12), None).map_err(|e| format!("resize: {e}"))?;
    }
    if scene.camera.height > 12 {
        scene.resize(None, Some(12)).map_err(|e| format!("resize: {e}"))?;
    }
    scene.settings.max_depth = scene.settings.max_depth.min(3);
    scene.settings.spp = scene.settings.spp.min(2);
    let start = Instant::now();
    let film = catch_unwind(AssertUnwindSafe(|| Renderer::new(&scene).render(Aov::Shaded, &|| {})))
        .map_err(|_| "render panicked".to_string())?;
    if start.elapsed() > Duration::from_secs(60) {
        return Err(format!("rendering took {:?}", start.elapsed()));
    }
    if film.pixels.iter().flatten().any(|x| x.is_nan()) {
        return Err("NaN in the image".into());
    }
    Ok("rendered")
}

#[test]
fn mutated_scenes_error_or_render_cleanly() {
    let cases: usize = std::env::var("CGA_FUZZ_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(3000);
    let seed: u64 = std::env::var("CGA_FUZZ_SEED").ok().and_then(|n| n.parse().ok()).unwrap_or(12);
    let mut rng = XorShiftRng::seed_from_u64(seed);
    let seeds = seeds();
    let (mut errors, mut rendered) = (0, 0);
    let mut failures = Vec::new();
    // Panics are caught and reported with their input; the hook's message would interleave.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    for case in 0..cases {
        let (name, text) = &seeds[case % seeds.len()];
        let mut mutant = text.clone();
        for _ in 0..rng.random_range(1..4) {
            mutant = mutate(&mutant, &mut rng);
        }
        match check(&mutant) {
            Ok("error") => errors += 1,
            Ok(_) => rendered += 1,
            Err(why) => failures.push(format!("case {case} (from {name}): {why}\n{mutant}")),
        }
    }
    std::panic::set_hook(hook);
    println!("{cases} mutants: {errors} located errors, {rendered} rendered cleanly, {} failures", failures.len());
    assert!(failures.is_empty(), "{}", failures.join("\n----\n"));
    // Memory stayed bounded: the peak resident set of this process (Linux reports it).
    if let Some(peak) = peak_resident_kib() {
        println!("peak resident memory: {} MiB", peak / 1024);
        assert!(peak < 2 << 20, "peak resident memory {peak} KiB");
    }
    // Both outcomes are exercised, so the test cannot pass vacuously.
    assert!(errors > cases / 10 && rendered > cases / 10, "{errors} errors, {rendered} renders");
}

/// The process's peak resident set in KiB (`VmHWM`), where the system reports it.
fn peak_resident_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}
