//! Stiff and extreme circle pairs: each case is a named test, run in f64 and f32, with the
//! error bound it must meet or the named error it must give; never NaN, never a panic.
//!
//! Errors, per case, over α = 0, 1/16, …, 1:
//! - f64: the endpoints against their exact parameters, and `|⟨C_α C̃_α⟩₀ + 1|`
//!   (geometric error: |Δcentre| / (|centre| + r) + |Δr| / r + normal angle);
//! - f32: the f32 result against the f64 one at every α;
//! - normal: the analytic normal (f64) against a finite-difference normal at interior α.
//!
//! `cargo test --test geometry stability:: -- --nocapture --test-threads 1` prints the table of
//! `docs/STABILITY.md`.

use cga_core::euclid::{E3, cross, dot, norm, sub, unit};
use cga_core::{Circle, InterpolationError, NormalError, Pair, Real, Vector, up};

type Params = (E3, E3, f64);

fn circle<T: Real>((c, n, r): Params) -> Circle<T> {
    let t = |v: E3| v.map(T::from_f64);
    Circle::from_centre_normal_radius(t(c), t(n), T::from_f64(r)).expect("a valid circle")
}

fn params<T: Real>(c: &Circle<T>) -> Result<Params, String> {
    let (centre, normal, r) = c.centre_normal_radius().map_err(|e| format!("{e:?}"))?;
    let f = |v: E3<T>| v.map(|x| x.to_f64());
    Ok((f(centre), f(normal), r.to_f64()))
}

fn angle(a: E3, b: E3) -> f64 {
    norm(cross(a, b)).atan2(dot(a, b).abs())
}

fn geometric_error(got: Params, want: Params) -> f64 {
    let scale = norm(want.0) + want.2;
    norm(sub(got.0, want.0)) / scale + (got.2 - want.2).abs() / want.2 + angle(got.1, want.1)
}

/// What a sweep over α found.
struct Report {
    f64_error: f64,
    f32_error: f64,
    normal_error: f64,
    named: Vec<String>,
}

/// The nearest point of a circle to `x` (Euclidean).
fn nearest_on(p: Params, x: E3) -> Option<E3> {
    let d = sub(x, p.0);
    let in_plane = sub(d, p.1.map(|v| v * dot(d, p.1)));
    unit(in_plane).map(|u| [p.0[0] + p.2 * u[0], p.0[1] + p.2 * u[1], p.0[2] + p.2 * u[2]])
}

/// Sweep through the checked `Pair::new`: a pair it refuses is reported by name.
fn sweep(a: Params, b: Params) -> Report {
    sweep_with(a, b, Pair::new)
}

/// Sweep through `Pair::new_unchecked`: to measure what the check refuses.
fn sweep_unchecked(a: Params, b: Params) -> Report {
    sweep_with(a, b, Pair::new_unchecked)
}

/// How a sweep makes its pair: checked or not.
type MakePair = fn(Circle<f64>, Circle<f64>) -> Result<Pair<Circle<f64>>, InterpolationError>;

fn sweep_with(a: Params, b: Params, make: MakePair) -> Report {
    let mut r = Report { f64_error: 0.0, f32_error: 0.0, normal_error: 0.0, named: Vec::new() };
    let pair64 = match make(circle::<f64>(a), circle::<f64>(b)) {
        Ok(p) => p,
        Err(e) => {
            r.named.push(format!("f64 Pair::new: {}", short(&e)));
            return r;
        }
    };
    // f32: checked, or where refused, unchecked if it can be normalised at all.
    let pair32 = Pair::new(circle::<f32>(a), circle::<f32>(b)).or_else(|e| {
        r.named.push(format!("f32 Pair::new: {}", short(&e)));
        Pair::new_unchecked(circle::<f32>(a), circle::<f32>(b))
    });
    let pair32 = pair32.map_err(|_| r.named.push("f32: the circles cannot even be normalised".into())).ok();
    if pair32.is_none() {
        r.f32_error = f64::INFINITY;
    }
    for (end, want) in [(0.0, a), (1.0, b)] {
        let got = params(&pair64.at(end).expect("endpoint")).expect("endpoint params");
        r.f64_error = r.f64_error.max(geometric_error(got, want));
    }
    for i in 0..=16 {
        let alpha = i as f64 / 16.0;
        let c64 = match pair64.at(alpha) {
            Ok(x) => x,
            Err(e) => {
                r.named.push(format!("α={alpha}: f64 {}", short(&e)));
                continue;
            }
        };
        assert!(c64.to_array().iter().all(|x| x.is_finite()), "NaN");
        r.f64_error = r.f64_error.max(((c64 * c64.reverse()).s + 1.0).abs());
        let p64 = match params(&c64) {
            Ok(p) => p,
            Err(e) => {
                r.named.push(format!("α={alpha}: f64 reads back {e}"));
                continue;
            }
        };
        match pair32.as_ref().map(|p| p.at(alpha as f32)) {
            None => {}
            Some(Err(e)) => r.named.push(format!("α={alpha}: f32 {}", short(&e))),
            Some(Ok(c32)) => {
                assert!(c32.to_array().iter().all(|x| x.is_finite()), "NaN");
                match params(&c32) {
                    Ok(p32) => r.f32_error = r.f32_error.max(geometric_error(p32, p64)),
                    Err(e) => r.named.push(format!("α={alpha}: f32 reads back {e}")),
                }
            }
        }
        if i % 4 == 2 {
            match normal_error(&pair64, alpha, p64) {
                Ok(e) => r.normal_error = r.normal_error.max(e),
                Err(e) => r.named.push(format!("α={alpha}: normal {e}")),
            }
        }
    }
    r
}

fn short(e: &InterpolationError) -> String {
    match e {
        InterpolationError::NoRealRoot { .. } => "NoRealRoot".into(),
        InterpolationError::Singular { .. } => "Singular".into(),
        InterpolationError::Degenerate => "Degenerate".into(),
        InterpolationError::NoObjects | InterpolationError::Weights { .. } => format!("{e:?}"),
        InterpolationError::ThroughInfinity { .. } => "ThroughInfinity".into(),
        InterpolationError::IllConditioned { estimate } => format!("IllConditioned {{ estimate: {estimate:.1e} }}"),
    }
}

/// Analytic normal against the finite-difference one at a point of `C_α`; a named refusal
/// (ill-conditioned) is returned as such.
fn normal_error(pair: &Pair<Circle>, alpha: f64, p: Params) -> Result<f64, String> {
    let u = unit(cross(p.1, if p.1[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] })).unwrap();
    let x = [p.0[0] + p.2 * u[0], p.0[1] + p.2 * u[1], p.0[2] + p.2 * u[2]];
    let analytic = match pair.normal(alpha, x) {
        Ok(n) => n,
        Err(NormalError::Degenerate(_)) => return Ok(0.0),
        Err(e @ NormalError::IllConditioned { .. }) => return Err(format!("{e}")),
        Err(e) => panic!("{e}"),
    };
    let h = 1e-6;
    let (Ok(before), Ok(after)) = (pair.at(alpha - h), pair.at(alpha + h)) else { return Ok(f64::NAN) };
    let (Ok(pb), Ok(pa)) = (params(&before), params(&after)) else { return Ok(f64::NAN) };
    let (Some(xb), Some(xa)) = (nearest_on(pb, x), nearest_on(pa, x)) else { return Ok(f64::NAN) };
    let across = sub(xa, xb);
    let fd = cross(cross(p.1, sub(x, p.0)), across);
    Ok(angle(analytic, fd))
}

/// Print the case's row and hold it to its bounds. `bound32 = None`: f32 is not expected to
/// hold the geometry (it must still give finite values or named errors, checked in `sweep`).
fn report(case: &str, r: &Report, bound64: f64, bound32: Option<f64>, check_normal: bool, limit: &str) {
    let mut named = r.named.clone();
    named.dedup_by(|a, b| a.split_once(": ").map(|x| x.1) == b.split_once(": ").map(|x| x.1));
    let named =
        if named.is_empty() { String::new() } else { format!(" Named (first of each kind): {}.", named.join(", ")) };
    let normal = if check_normal { format!("{:.1e}", r.normal_error) } else { "n/a".into() };
    println!("| {case} | {:.1e} | {:.1e} | {normal} | {limit}{named} |", r.f64_error, r.f32_error);
    assert!(r.f64_error <= bound64, "{case}: f64 error {:e} > {bound64:e}", r.f64_error);
    if let Some(b) = bound32 {
        assert!(r.f32_error <= b, "{case}: f32 error {:e} > {b:e}", r.f32_error);
    }
    if check_normal {
        assert!(r.normal_error <= 1e-5, "{case}: normal off by {:e}", r.normal_error);
    }
}

const Z: E3 = [0.0, 0.0, 1.0];

#[test]
fn far_from_the_origin() {
    let a = ([1e4, -1e4, 5e3], [0.2, 0.3, 1.0], 1.0);
    let b = ([1e4 + 3.0, -1e4 + 1.0, 5e3 + 2.0], [0.5, -0.2, 1.0], 2.0);
    // Never silently wrong: the checked pair refuses, by name.
    let refused = sweep(a, b);
    assert!(refused.named.iter().any(|n| n.contains("f64 Pair::new: IllConditioned")), "{:?}", refused.named);
    report(
        "centres at \\|c\\| ≈ 1.5e4, radii 1–2 (unchecked)",
        &sweep_unchecked(a, b),
        1e-3,
        None,
        false,
        "f64 error ≈ ε (\\|c\\|/r)³ (measured below); `Pair::new` refuses it: IllConditioned",
    );
    // The remedy: the same pair in a frame centred between the circles.
    let shift = |p: Params| (sub(p.0, [1e4, -1e4, 5e3]), p.1, p.2);
    report(
        "the same, in a local frame",
        &sweep(shift(a), shift(b)),
        1e-12,
        Some(1e-5),
        true,
        "translate to a local origin first: full precision back",
    );
}

/// How precision falls with distance from the origin (unit-size circles), f64.
#[test]
fn precision_against_distance() {
    let mut errors = Vec::new();
    for d in [1e1, 1e2, 1e3, 1e4] {
        let a = ([d, -d, 0.5 * d], [0.2, 0.3, 1.0], 1.0);
        let b = ([d + 3.0, 1.0 - d, 0.5 * d + 2.0], [0.5, -0.2, 1.0], 2.0);
        let e = sweep_unchecked(a, b).f64_error;
        println!("| unit circles at \\|c\\| = {:.1e} | {e:.1e} | | | f64 error against distance |", d * 1.5);
        errors.push(e);
    }
    assert!(errors[0] < 1e-11 && errors[3] < 1e-3);
}

#[test]
fn tiny_radii() {
    let a = ([0.0, 0.0, 0.0], [0.2, 0.3, 1.0], 1e-4);
    let b = ([3e-4, 1e-4, 2e-4], [0.5, -0.2, 1.0], 2e-4);
    report(
        "radii 1e-4, near the origin",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        true,
        "scale-free: errors as for unit circles",
    );
}

#[test]
fn huge_radii() {
    let a = ([1e4, 0.0, 0.0], [0.2, 0.3, 1.0], 1e4);
    let b = ([0.0, 2e4, 1e4], [0.5, -0.2, 1.0], 2e4);
    report(
        "radii 1e4–2e4, centres 1e4",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        true,
        "scale-free: errors as for unit circles",
    );
}

#[test]
fn radii_eight_decades_apart() {
    let a = ([0.0, 0.0, 0.0], [0.2, 0.3, 1.0], 1e-4);
    let b = ([1.0, 2.0, 0.5], [0.5, -0.2, 1.0], 1e4);
    report(
        "radii 1e-4 and 1e4",
        &sweep(a, b),
        1e-8,
        Some(1e-2),
        true,
        "the family jumps from tiny to huge within a few steps of α",
    );
}

#[test]
fn nearly_identical_circles() {
    let a = ([1.0, 2.0, 3.0], [0.2, 0.3, 1.0], 1.5);
    let b = ([1.0 + 1e-9, 2.0, 3.0 - 1e-9], [0.2, 0.3 + 1e-9, 1.0], 1.5 + 1e-9);
    report(
        "circles 1e-9 apart",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        false,
        "Ċ ≈ 1e-9: the analytic normal is defined; a finite difference has no signal left",
    );
}

#[test]
fn opposite_orientation() {
    let a = ([0.0, 0.0, 0.0], Z, 1.0);
    let b = ([0.5, 0.0, 0.2], [0.0, 0.1, -1.0], 1.2);
    report(
        "C2 ≈ −C1 (normals opposite)",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        true,
        "aligned by Pair::new: C2 is negated, no zero crossing",
    );
}

#[test]
fn coplanar_disjoint_circles() {
    let a = ([0.0, 0.0, 0.0], Z, 1.0);
    let b = ([3.0, 0.0, 0.0], Z, 1.0);
    report(
        "coplanar, disjoint, equal radii",
        &sweep(a, b),
        1e-12,
        Some(1e-4),
        true,
        "C_½ is the bisecting line (radius → ∞): read back as AtInfinity",
    );
}

#[test]
fn concentric_coplanar_circles() {
    let a = ([1.0, 1.0, 1.0], Z, 1.0);
    let b = ([1.0, 1.0, 1.0], Z, 0.2);
    report(
        "concentric, coplanar (an annulus)",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        true,
        "the normal is the plane's normal throughout",
    );
}

#[test]
fn concentric_tilted_circles() {
    let a = ([0.0, 0.0, 0.0], Z, 1.0);
    let b = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 1.0);
    report("concentric, planes at 90°", &sweep(a, b), 1e-12, Some(1e-5), true, "stays on the common sphere");
}

#[test]
fn cospherical_circles() {
    // Two circles cut from the sphere of radius 2 about (1, 0, 0) by different planes.
    let (c, r) = ([1.0, 0.0, 0.0], 2.0f64);
    let cut = |n: E3, d: f64| {
        let n = unit(n).unwrap();
        ([c[0] + d * n[0], c[1] + d * n[1], c[2] + d * n[2]], n, (r * r - d * d).sqrt())
    };
    let (a, b) = (cut([0.0, 0.0, 1.0], 0.5), cut([1.0, 1.0, 0.0], -1.2));
    let pair = Pair::new(circle::<f64>(a), circle::<f64>(b)).unwrap();
    // Σ = −X X̃ has no 4-vector part for co-spherical circles: K is a scalar.
    let x = pair.c1 * 0.5 + pair.c2 * 0.5;
    let sigma = cga_core::Interpolable::neg_square(x);
    let quad = sigma.grade4().to_array().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(quad < 1e-12 * sigma.s.abs(), "4-vector part {quad:e}");
    report(
        "co-spherical (Σ has no 4-vector part)",
        &sweep(a, b),
        1e-12,
        Some(1e-5),
        true,
        "K = √s is a scalar; the family stays on the sphere",
    );
}

#[test]
fn through_a_zero_radius_circle() {
    // Real unit circle towards an imaginary circle of radius 0.8i in the same plane.
    let c1 = circle::<f64>(([0.0, 0.0, 0.0], Z, 1.0));
    let mut sigma = up([0.5, 0.0, 0.0]);
    sigma.ei += 0.5 * 0.8 * 0.8;
    let imaginary: Circle = (sigma ^ Vector { e3: 1.0, ..Vector::zero() }).undual();
    assert_eq!(imaginary.centre_normal_radius(), Err(cga_core::GeometryError::Imaginary));
    let pair = Pair::new(c1, imaginary).unwrap();
    let (mut last_radius, mut no_root) = (f64::INFINITY, 0);
    for i in 0..=1000 {
        match pair.at(i as f64 / 1000.0) {
            Ok(c) => {
                let (_, _, r) = c.centre_normal_radius().unwrap();
                assert!(r < last_radius, "the radius shrinks towards zero");
                last_radius = r;
            }
            Err(InterpolationError::NoRealRoot { .. }) => no_root += 1,
            Err(e) => panic!("{e}"),
        }
    }
    println!(
        "| real → imaginary circle | – | – | – | shrinks to radius {last_radius:.1e} at α ≈ 0.53 (steps of 1e-3), then NoRealRoot for {no_root} of 1001 α |"
    );
    assert!(last_radius < 0.05 && no_root > 400);
}

#[test]
fn identical_circles_have_no_normal() {
    // Ċ = 0: Ω = 0, Ẋ = 0, L_T = 0 — the limit where L_T is parallel to (here: vanishes
    // against) L_C. In 1000 random pairs L_T ⟂ L_C held everywhere (tests/tests/geometry/interpolation.rs).
    let c = ([1.0, 0.0, 0.0], Z, 1.0);
    let pair = Pair::new(circle::<f64>(c), circle::<f64>(c)).unwrap();
    let e = pair.normal(0.5, [2.0, 0.0, 0.0]).unwrap_err();
    assert!(matches!(e, NormalError::IllConditioned { estimate } if estimate.is_infinite()), "{e}");
    let pair32 = Pair::new(circle::<f32>(c), circle::<f32>(c)).unwrap();
    assert!(matches!(pair32.normal(0.5, [2.0, 0.0, 0.0]), Err(NormalError::IllConditioned { .. })));
    // Unchecked, the parts show why: Ċ = 0, so Ẋ = 0 and N = 0.
    let parts = pair.normal_parts(0.5, [2.0, 0.0, 0.0]).unwrap();
    assert!(parts.normal_line.direction().is_err());
    println!(
        "| identical circles (Ẋ = 0, L_T = 0) | – | – | – | normal: NormalError::IllConditioned (Δ = 0) in f64 and f32 |"
    );
}
