//! Line meets and reflections against the textbook ray formulas (glam).

use cga_core::{Circle, Disk, Hit, Line, Plane, Sphere, Vector};
use glam::DVec3;

use cga_tests::common;

use common::Rng;

/// A point in [−s, s]³.
fn vec(rng: &mut Rng, s: f64) -> DVec3 {
    DVec3::from(rng.e3(-s, s))
}

/// Ray `o + t d` against a sphere: the two `t`, ascending, if real.
fn ray_sphere(o: DVec3, d: DVec3, c: DVec3, r: f64) -> Option<(f64, f64)> {
    let oc = o - c;
    let (b, cc) = (oc.dot(d), oc.length_squared() - r * r);
    let disc = b * b - cc;
    (disc >= 0.0).then(|| (-b - disc.sqrt(), -b + disc.sqrt()))
}

#[test]
fn line_sphere_meets_agree_with_the_quadratic() {
    let mut rng = Rng::new(11);
    let (mut two, mut miss) = (0, 0);
    for _ in 0..2000 {
        let (o, c, r) = (vec(&mut rng, 8.0), vec(&mut rng, 3.0), 0.5 + 3.0 * rng.unit());
        // Aim near the sphere so that hits and misses are both common.
        let d = (c + vec(&mut rng, 1.5 * r) - o).normalize();
        let line = Line::from_point_direction(o.into(), d.into()).unwrap();
        let meet = line.meet_sphere(&Sphere::from_centre_radius(c.into(), r).unwrap());
        match ray_sphere(o, d, c, r) {
            Some((t0, t1)) if t1 - t0 > 1e-6 => {
                assert_eq!(meet.hit, Hit::Two);
                let [a, b] = meet.points(&line).unwrap();
                assert!((DVec3::from(a) - (o + t0 * d)).length() < 1e-9, "first point");
                assert!((DVec3::from(b) - (o + t1 * d)).length() < 1e-9, "second point");
                two += 1;
            }
            None => {
                assert_eq!(meet.hit, Hit::Miss);
                assert_eq!(meet.points(&line), Err(cga_core::GeometryError::Imaginary));
                miss += 1;
            }
            _ => {}
        }
    }
    assert!(two > 500 && miss > 300, "{two} hits, {miss} misses");
}

#[test]
fn a_grazing_line_is_tangent() {
    let sphere = Sphere::from_centre_radius([0.0, 0.0, 0.0], 2.0).unwrap();
    let line = Line::through([-5.0, 2.0, 0.0], [5.0, 2.0, 0.0]).unwrap();
    let meet = line.meet_sphere(&sphere);
    assert_eq!(meet.hit, Hit::Tangent, "P² = {}", meet.square);
    let [a, b] = meet.points(&line).unwrap();
    assert!((DVec3::from(a) - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-9 && a == b);
}

#[test]
fn line_plane_and_disk_meets() {
    let mut rng = Rng::new(5);
    for _ in 0..500 {
        let (o, p, n) = (vec(&mut rng, 5.0), vec(&mut rng, 5.0), vec(&mut rng, 1.0).normalize());
        let d = vec(&mut rng, 1.0).normalize();
        let line = Line::from_point_direction(o.into(), d.into()).unwrap();
        let plane = Plane::from_point_normal(p.into(), n.into()).unwrap();
        let t = (p - o).dot(n) / d.dot(n);
        let x = line.meet_plane(&plane).unwrap();
        assert!((DVec3::from(x) - (o + t * d)).length() < 1e-8 * (1.0 + t.abs()), "plane point");
        let disk = Disk::new(Circle::from_centre_normal_radius(p.into(), n.into(), 1.5).unwrap()).unwrap();
        let inside = ((o + t * d) - p).length() <= 1.5;
        if ((o + t * d) - p).length().abs() - 1.5 > 1e-9 || ((o + t * d) - p).length() < 1.5 - 1e-9 {
            assert_eq!(line.meet_disk(&disk).is_some(), inside);
        }
    }
    let parallel = Line::through([0.0, 0.0, 1.0], [1.0, 0.0, 1.0]).unwrap();
    let floor = Plane::from_point_normal([0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    assert_eq!(parallel.meet_plane(&floor), None);
}

#[test]
fn reflections_follow_the_mirror_law() {
    let mut rng = Rng::new(9);
    for _ in 0..500 {
        let (o, p, n) = (vec(&mut rng, 5.0), vec(&mut rng, 5.0), vec(&mut rng, 1.0).normalize());
        let d = vec(&mut rng, 1.0).normalize();
        if d.dot(n).abs() < 1e-3 {
            continue;
        }
        let line = Line::from_point_direction(o.into(), d.into()).unwrap();
        let plane = Plane::from_point_normal(p.into(), n.into()).unwrap();
        let hit = DVec3::from(line.meet_plane(&plane).unwrap());
        let reflected = line.reflect_in_plane(&plane);
        let want = d - 2.0 * d.dot(n) * n;
        assert!((DVec3::from(reflected.direction().unwrap()) - want).length() < 1e-9, "reflected direction");
        assert!(DVec3::from(reflected.meet_plane(&plane).unwrap()).distance(hit) < 1e-8, "through the hit");
        // L' − L: the normal line at the hit, pointing back to the side the ray came from.
        let normal_line = (reflected - line).normalise().unwrap();
        let nd = DVec3::from(normal_line.direction().unwrap());
        assert!(nd.cross(n).length() < 1e-9 && nd.dot(d) < 0.0, "normal line");
        let on_line = DVec3::from(normal_line.point().unwrap());
        assert!((hit - on_line).cross(nd).length() < 1e-8 * (1.0 + hit.length()), "normal line misses the hit");

        // In a sphere: the mirror is the tangent plane at the hit.
        let (c, r) = (vec(&mut rng, 3.0), 1.0 + rng.unit());
        let Some((t0, _)) = ray_sphere(o, d, c, r) else { continue };
        let at = o + t0 * d;
        let sphere = Sphere::from_centre_radius(c.into(), r).unwrap();
        let m = (at - c).normalize();
        let r_line = line.reflect_in_sphere(&sphere, at.into()).unwrap();
        let want = d - 2.0 * d.dot(m) * m;
        assert!((DVec3::from(r_line.direction().unwrap()) - want).length() < 1e-8, "sphere reflection");
    }
}

#[test]
fn circle_meets_vanish_exactly_where_the_line_touches() {
    let circle = Circle::from_centre_normal_radius([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2.0).unwrap();
    let through_rim = Line::through([3.0, 0.0, 0.0], [4.0, 1.0, 5.0]).unwrap();
    let away = Line::through([0.0, 0.0, 5.0], [1.0, 0.0, 6.0]).unwrap();
    let sq = |l: &Line| {
        let v: Vector = l.meet_circle(&circle);
        (v | v).s
    };
    approx::assert_abs_diff_eq!(sq(&through_rim), 0.0, epsilon = 1e-12);
    assert!(sq(&away).abs() > 1e-3);
}
