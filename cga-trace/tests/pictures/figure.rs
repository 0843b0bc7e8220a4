//! Drawing CGA objects: what each blade is drawn as carries the Euclidean parameters it was
//! built from (centre, radius, direction) to the rounding its coefficients hold, anywhere in
//! space; a [`Figure`] frames its objects and renders the scene file it writes.

use cga_tests::common::dd;

use cga_core::euclid::{E3, add, cross, dot, norm, scale, sub, unit};
use cga_core::{Circle, FlatPoint, Line, Multivector, Plane, Real, Sphere, Vector, ei, up};
use cga_trace::figure::{DrawError, Drawing, Figure, FigureError, Sizes, project};
use cga_trace::{Aov, Renderer, Scene};
use dd::{Dd, dd3 as dd};
use proptest::prelude::*;

/// The marks `Drawing::of` sizes with: none, so that only the parameters are compared.
const MARKS: Sizes = Sizes::ZERO;

/// What a blade built in double-double (so that its f64 coefficients are the object's to
/// their own rounding) is drawn as.
fn drawn(blade: impl Into<Multivector<Dd>>) -> Result<Drawing, String> {
    let coefficients = blade.into().to_storage().map(Dd::hi);
    let kind = cga_core::classify_storage(&coefficients).map_err(|e| e.to_string())?;
    Drawing::of(kind, &MARKS, false).map_err(|e| e.to_string())
}

fn close(got: E3, want: E3, tol: f64) -> bool {
    norm(sub(got, want)) <= tol
}

fn same_axis(got: E3, want: E3, tol: f64) -> bool {
    norm(cross(got, want)) <= tol && dot(got, want) > 0.0
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Objects of size `s` (1e-3 … 1e3) at up to `10^far` sizes (and 1e6 radii) from the origin: every
    /// parameter read back within `64 ε (1 + ρ)²` of the object's size, `ρ` its distance over
    /// its size (the coefficients hold `|c|²/r`-sized terms beside `r`-sized ones).
    #[test]
    fn drawings_carry_the_parameters_the_blades_were_built_from(
        size in -3.0f64..3.0,
        far in 0.0f64..6.0,
        at in prop::array::uniform3(-1.0f64..1.0),
        u in prop::array::uniform3(-1.0f64..1.0),
        w in prop::array::uniform3(-1.0f64..1.0),
        r in 0.2f64..1.0,
    ) {
        let (Some(u), Some(w)) = (unit(u), unit(w)) else { return Ok(()) };
        // Beyond about 1e7 of their units from the origin, rounds are refused by name
        // (`Indistinct`), checked below; here every one is drawn.
        if size + far > 6.5 {
            return Ok(());
        }
        let Some(n) = unit(cross(u, w)).filter(|_| norm(cross(u, w)) > 0.1) else { return Ok(()) };
        let s = 10f64.powf(size);
        let c = scale(at, s * 10f64.powf(far));
        let r = r * s;
        let rho = norm(c) / r;
        // A round's `⟨X X⟩₀ ∝ r⁴` sums terms of about `r² |c|²`, so from `ρ = 1/√(192 ε)`
        // (about 3.9e6) on it is zero to the classifier's `64 ε` and reads as a tangent.
        if rho > 1e6 {
            return Ok(());
        }
        let tol = 64.0 * f64::EPSILON * (1.0 + rho).powi(2) * r;
        let msg = |what: &str, d: &Drawing| format!("{what}: {d:?}, c {c:?} r {r:e} tol {tol:e}");

        // A point: a ball at it.
        match drawn(up(dd(c))) {
            Ok(Drawing::Point { at, .. }) => prop_assert!(close(at, c, tol), "point at {at:?} vs {c:?}"),
            d => prop_assert!(false, "point: {d:?}"),
        }
        // A point pair: its two points, in order.
        let (a, b) = (sub(c, scale(u, r)), add(c, scale(u, r)));
        match drawn(up(dd(a)) ^ up(dd(b))) {
            Ok(d @ Drawing::PointPair { points: [p, q], .. }) => {
                prop_assert!(close(p, a, tol) && close(q, b, tol), "{}", msg("pair", &d))
            }
            d => prop_assert!(false, "pair: {d:?}"),
        }
        // A circle through three of its points: centre, normal (oriented), radius.
        let on = |t: f64| add(c, add(scale(u, r * t.cos()), scale(cross(n, u), r * t.sin())));
        let circle: Circle<Dd> = up(dd(on(0.3))) ^ up(dd(on(2.1))) ^ up(dd(on(4.4)));
        match drawn(circle) {
            Ok(d @ Drawing::Circle { centre, normal, radius, dashed: false, .. }) => {
                prop_assert!(close(centre, c, tol), "{}", msg("circle centre", &d));
                prop_assert!(same_axis(normal, n, tol / r), "{}", msg("circle normal", &d));
                prop_assert!((radius - r).abs() <= tol, "{}", msg("circle radius", &d));
            }
            d => prop_assert!(false, "circle: {d:?}"),
        }
        // A sphere, real and imaginary (a dual sphere `c + eo + ½(c² ∓ r²) ei`).
        let sphere = Sphere::from_centre_radius(dd(c), Dd::from_f64(r)).unwrap();
        for (blade, dashed) in [(Multivector::from(sphere), false), (imaginary(c, r).into(), true)] {
            match drawn(blade) {
                Ok(d @ Drawing::Sphere { centre, radius, dashed: got, .. }) => {
                    prop_assert!(got == dashed, "{}", msg("sphere reality", &d));
                    prop_assert!(close(centre, c, tol) && (radius - r).abs() <= tol, "{}", msg("sphere", &d));
                }
                d => prop_assert!(false, "sphere: {d:?}"),
            }
        }
        // Flats: a line through c along u, a plane through c of normal n, a flat point.
        match drawn(Line::new(dd(c), dd(u)).unwrap()) {
            Ok(d @ Drawing::Line { point, direction, .. }) => {
                prop_assert!(same_axis(direction, u, 64.0 * f64::EPSILON), "{}", msg("line direction", &d));
                let off = norm(cross(sub(point, c), u));
                prop_assert!(off <= 64.0 * f64::EPSILON * norm(c).max(r), "{}", msg("line point", &d));
            }
            d => prop_assert!(false, "line: {d:?}"),
        }
        match drawn(Plane::new(dd(c), dd(n)).unwrap()) {
            Ok(d @ Drawing::PlanePatch { centre, normal, .. }) => {
                let s = dot(normal, n).signum();
                prop_assert!(same_axis(scale(normal, s), n, 64.0 * f64::EPSILON), "{}", msg("plane normal", &d));
                // The patch sits about the plane's point nearest the origin.
                prop_assert!(close(centre, scale(n, dot(n, c)), 64.0 * f64::EPSILON * norm(c)), "{}", msg("plane", &d));
            }
            d => prop_assert!(false, "plane: {d:?}"),
        }
        let flat = FlatPoint::from_storage(&(up(dd(c)) ^ ei::<Dd>()).to_storage());
        match drawn(flat) {
            Ok(Drawing::FlatPoint { at, .. }) => prop_assert!(close(at, c, 64.0 * f64::EPSILON * norm(c))),
            d => prop_assert!(false, "flat point: {d:?}"),
        }
    }
}

/// The imaginary dual sphere of centre `c` and radius `r`: `c + eo + ½(c² + r²) ei`.
fn imaginary(c: E3, r: f64) -> Vector<Dd> {
    let [x, y, z] = dd(c);
    let half = Dd::from_f64(0.5);
    Vector { e1: x, e2: y, e3: z, eo: Dd::one(), ei: half * (x * x + y * y + z * z + Dd::from_f64(r * r)) }
}

#[test]
fn tangents_and_directions_are_arrows_and_what_has_no_picture_says_why() {
    // A tangent vector at the origin along e3 (a point pair of zero radius), and `e3 ∧ ei`.
    let tangent = cga_core::Bivector { e3o: -1.0, ..cga_core::Bivector::zero() };
    let sizes = Sizes { arrow: 2.0, centre: [5.0, 0.0, 0.0], ..Sizes::ZERO };
    let kind = |b: cga_core::Bivector| b.classify().unwrap();
    assert_eq!(
        Drawing::of(kind(tangent), &sizes, false).unwrap(),
        Drawing::Arrow { at: [0.0; 3], direction: [0.0, 0.0, 2.0], tube: 0.0 }
    );
    let direction = cga_core::Bivector { e3i: 1.0, ..cga_core::Bivector::zero() };
    assert_eq!(
        Drawing::of(kind(direction), &sizes, false).unwrap(),
        Drawing::Arrow { at: [5.0, 0.0, 0.0], direction: [0.0, 0.0, 2.0], tube: 0.0 }
    );
    let infinity = Vector { ei: 1.0, ..Vector::zero() };
    assert_eq!(Drawing::of(infinity.classify().unwrap(), &sizes, false), Err(DrawError::AtInfinity { grade: 1 }));
    assert_eq!(Drawing::of(Vector::zero().classify().unwrap(), &sizes, false), Err(DrawError::Zero));
}

fn example() -> Figure {
    let circle = Circle::from_centre_normal_radius([1e4, 2e4, 0.0], [0.0, 0.3, 1.0], 2.0).unwrap();
    let line = Line::new([1e4, 2e4, -1.0], [1.0, 0.2, 0.0]).unwrap();
    let sphere = Sphere::from_centre_radius([1e4 - 3.0, 2e4 + 1.0, 0.5], 0.8).unwrap();
    Figure::new()
        .add(&circle, "red")
        .label("C")
        .add(&line, "blue")
        .add(&up([1e4 + 3.0, 2e4, 1.0]), "#ffcc00")
        .label("X")
        .add(&sphere, "green")
        .resolution(160, 120)
}

#[test]
fn a_figure_frames_its_objects_and_renders_the_scene_it_writes() {
    let figure = example();
    let scene = figure.build().unwrap();
    // The camera frames every bounded object: their centres project into the picture.
    for x in [[1e4, 2e4, 0.0], [1e4 + 3.0, 2e4, 1.0], [1e4 - 3.0, 2e4 + 1.0, 0.5]] {
        let (u, v, _) = project(&scene.camera, scene.frame.point(x)).expect("in front");
        assert!((0.0..160.0).contains(&u) && (0.0..120.0).contains(&v), "{x:?} at ({u}, {v})");
    }
    assert_eq!(scene.labels.len(), 2);
    // The picture is the scene's, labels written in.
    let mut film = Renderer::new(&scene).render(Aov::Shaded, &|| {});
    let bare = film.clone();
    cga_trace::figure::draw_labels(&mut film, &scene.camera, &scene.labels);
    assert_eq!(figure.film().unwrap(), film);
    assert_ne!(bare, film, "the labels are drawn");
    // Written to disk and read back, the same picture.
    let dir = tempfile::tempdir().unwrap();
    figure.write_scene(dir.path().join("f.toml")).unwrap();
    let loaded = Scene::load(&dir.path().join("f.toml")).unwrap();
    assert_eq!(Renderer::new(&loaded).render(Aov::Shaded, &|| {}), bare);
    figure.render(dir.path().join("f.png")).unwrap();
    let png = image::open(dir.path().join("f.png")).unwrap().to_rgb8();
    assert_eq!(png.dimensions(), (160, 120));
}

/// The scene a figure builds and the one its file reads back to are the same: every kind of
/// blade it draws (with its own size, tube and segment), labels, and a camera given or
/// framing, far from the origin as near it; the same objects, lights, labels and picture.
#[test]
fn a_figure_builds_the_scene_its_file_reads_back_to() {
    let at = |x: E3, shift: f64| add(x, [shift, -2.0 * shift, 0.5 * shift]);
    for shift in [0.0, 3e5] {
        let pair = up(at([1.0, 0.0, 0.0], shift)) ^ up(at([2.0, 1.0, 0.0], shift));
        let tangent = cga_core::Bivector { e3o: -1.0, ..cga_core::Bivector::zero() };
        let direction = cga_core::Bivector { e3i: 1.0, ..cga_core::Bivector::zero() };
        let plane = Plane::new(at([0.0, 0.0, -1.0], shift), [0.0, 0.3, 1.0]).unwrap();
        let flat = FlatPoint::from_storage(&(up(at([0.0, 2.0, 1.0], shift)) ^ ei::<f64>()).to_storage());
        let [x, y, z] = at([0.0, -3.0, 0.0], shift);
        let imaginary = Vector { e1: x, e2: y, e3: z, eo: 1.0, ei: 0.5 * (x * x + y * y + z * z + 0.49) };
        let circle = Circle::from_centre_normal_radius(at([0.0; 3], shift), [0.0, 0.3, 1.0], 2.0).unwrap();
        let figure = Figure::new()
            .add(&circle, "red")
            .label("C")
            .tube(0.05)
            .add(&Line::new(at([0.0, 0.0, -1.0], shift), [1.0, 0.2, 0.0]).unwrap(), "blue")
            .label("L")
            .add(&up(at([3.0, 0.0, 1.0], shift)), "#ffcc00")
            .size(0.2)
            .add(&pair, "green")
            .segment()
            .add(&Sphere::from_centre_radius(at([-3.0, 1.0, 0.5], shift), 0.8).unwrap(), "sky")
            .add(&imaginary, "purple")
            .add(&plane, "grey")
            .size(3.0)
            .label("P")
            .add(&flat, "orange")
            .add(&tangent, "white")
            .add(&direction, "pink")
            .resolution(96, 72);
        for figure in [figure.clone(), figure.camera(at([0.0, -12.0, 6.0], shift), at([0.0; 3], shift))] {
            let built = figure.build().unwrap();
            let read = Scene::parse(&figure.scene().unwrap(), "figure.toml").unwrap();
            assert_eq!(built.objects.len(), read.objects.len());
            assert_eq!(format!("{:?}", built.labels), format!("{:?}", read.labels));
            assert_eq!(format!("{:?}", built.lights), format!("{:?}", read.lights));
            assert_eq!(format!("{:?}", built.camera), format!("{:?}", read.camera));
            assert_eq!(format!("{:?}", built.frame), format!("{:?}", read.frame));
            for (b, r) in built.objects.iter().zip(&read.objects) {
                assert_eq!((&b.name, b.material, b.shape.bounds()), (&r.name, r.material, r.shape.bounds()));
            }
            let shaded = |scene: &Scene| Renderer::new(scene).render(Aov::Shaded, &|| {});
            assert_eq!(shaded(&built), shaded(&read), "shift {shift}");
        }
    }
}

#[test]
fn a_figure_names_the_object_it_cannot_draw() {
    let pair = cga_core::Bivector { e1o: 1.0, e1i: -0.5, ..cga_core::Bivector::zero() };
    let e = Figure::new().add(&up([0.0; 3]), "red").add(&pair, "blue").scene().unwrap_err();
    assert!(matches!(e, FigureError::Blade { index: 2, .. }), "{e}");
    assert!(e.to_string().starts_with("object 2: an imaginary point pair"), "{e}");
    let e = Figure::new().add(&up([0.0; 3]), "reddish").scene().unwrap_err();
    assert_eq!(e.to_string(), "object 1: unknown colour `reddish` (a name such as \"red\", or \"#rrggbb\")");
    // A point 1e8 from the origin: its eo coefficient is within rounding of its ei one
    // (5e15), so f64 cannot tell it from a plane: refused by name, not drawn as a plane.
    let e = Figure::new().add(&up([1e8, 0.0, 0.0]), "red").scene().unwrap_err();
    assert!(e.to_string().contains("cannot tell this round from a flat"), "{e}");
    // Nothing is written when the figure fails.
    let dir = tempfile::tempdir().unwrap();
    assert!(Figure::new().add(&pair, "red").render(dir.path().join("x.png")).is_err());
    assert!(!dir.path().join("x.png").exists());
}
