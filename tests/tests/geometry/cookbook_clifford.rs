//! docs/COOKBOOK.md's clifford spellings, run with clifford 1.5.1 on each entry's own inputs
//! (`golden/cookbook_clifford.json`, `tools/cookbook_clifford.py`), against cga-core's
//! answer to the same task: ours must be the entry's expected answer, and clifford's where
//! the script found it right. The spellings found wrong are the ones the COOKBOOK says are
//! (and every spelling recorded is still in the COOKBOOK, so the two cannot drift apart).

use cga_tests::common;

use cga_core::euclid::norm;
use cga_core::{
    Circle, Dilator, Flat, Line, Meet, Motor, Multivector, Plane, Reflect, Rotor, Sandwich, Sphere, VersorBetween,
    average_objects, down, fit_circle, fit_line, fit_plane, fit_sphere, up,
};
use serde_json::Value;

/// Every number of a (nested) JSON list, in order; `null` (a NaN of clifford's) as NaN.
fn flat(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(items) => items.iter().flat_map(flat).collect(),
        Value::Null => vec![f64::NAN],
        other => vec![other.as_f64().expect("number")],
    }
}

fn points(meet: Meet<f64>) -> Vec<f64> {
    match meet {
        Meet::Points([a, b]) => {
            let mut p = [a, b];
            p.sort_by(|x, y| x[0].total_cmp(&y[0]));
            p.concat()
        }
        Meet::Point(x) => x.to_vec(),
        other => panic!("{other:?}"),
    }
}

/// cga-core's answer to a task, in the form the script records (see each case's `setup`).
fn ours(task: &str) -> Result<Vec<f64>, Box<dyn std::error::Error>> {
    let mirror: Plane = Plane::new([0.0, 0.0, 1.0], [0.0, 0.0, 1.0])?;
    let unit: Sphere = Sphere::new([0.0; 3], 1.0)?;
    let ring: Circle = Circle::new([0.0; 3], [0.0, 0.0, 1.0], 1.0)?;
    let cb: Circle = Circle::new([0.0, 0.0, 1.0], [0.0, 1.0, 1.0], 2.0)?;
    let floor: Plane = Plane::new([0.0; 3], [0.0, 0.0, 1.0])?;
    let slope: Line = Line::new([0.0, 0.0, 2.0], [1.0, 0.0, 1.0])?;
    let x = up([1.0, 2.0, 3.0]);
    let e1 = [1.0, 0.0, 0.0];
    let m = Motor::from_rotor_translation(Rotor::from_axis_angle([0.0, 0.0, 1.0], 0.5)?, [1.0, 2.0, 3.0]);
    let five = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]];
    let nonzero = |b: bool| vec![if b { 1.0 } else { 0.0 }];
    Ok(match task {
        "reflect_point_in_plane" => down(up([1.0, 2.0, 0.0]).reflect_in(&mirror)?)?.to_vec(),
        "reflect_sphere_in_plane" => {
            let (c, r) = Sphere::new([0.0, 0.0, -1.0], 0.5)?.reflect_in(&mirror)?.centre_radius()?;
            [c.as_slice(), &[r]].concat()
        }
        "reflect_circle_in_plane" => {
            Circle::new([0.0; 3], [1.0, 0.0, 0.0], 1.0)?.reflect_in(&mirror)?.centre_normal_radius()?.0.to_vec()
        }
        "invert_point_in_sphere" | "invert_point_in_sphere_corrected" => {
            down(up([2.0, 0.0, 0.0]).invert_in(&unit)?)?.to_vec()
        }
        "project_point_onto_line" => x.project_onto(&Line::new([0.0; 3], e1)?)?.to_vec(),
        "project_point_onto_plane" => x.project_onto(&floor)?.to_vec(),
        "project_point_onto_sphere" => x.project_onto(&Sphere::new([1.0, 2.0, 0.0], 1.0)?)?.to_vec(),
        "project_point_onto_circle" => x.project_onto(&ring)?.to_vec(),
        "rotor_between_directions" | "rotor_between_objects_directions" => {
            Rotor::between(e1, [0.0, 1.0, 0.0])?.rotate(e1).to_vec()
        }
        "turn_about_line" => Motor::about_line(&Line::new(e1, [0.0, 0.0, 1.0])?, std::f64::consts::FRAC_PI_2)?
            .move_point([2.0, 0.0, 0.0])
            .to_vec(),
        "motor_inverse" => Multivector::from(m * m.inverse()).coeffs.to_vec(),
        "motor_logarithm" => Motor::exp(m.log()?).move_point(e1).to_vec(),
        "interpolate_poses" => {
            let b = Motor::from_rotor_translation(Rotor::from_axis_angle([0.0, 0.0, 1.0], 1.0)?, [2.0, 0.0, 0.0]);
            b.pow(0.5)?.move_point([0.0; 3]).to_vec()
        }
        "dilation_rotor" => down(Dilator::new([0.0; 3], 2.5)?.sandwich(up([2.0, 0.0, 0.0])))?.to_vec(),
        "project_flat_onto_flat" => {
            let Flat::Line(shadow) = slope.project_flat_onto(&floor)? else { panic!("not a line") };
            vec![shadow.distance_to([0.0; 3])?, shadow.distance_to(e1)?]
        }
        "project_perpendicular_flat" => nonzero(
            Line::new([1.0, 2.0, 5.0], [0.0, 0.0, 1.0])?.project_flat_onto(&floor)? == Flat::Point([1.0, 2.0, 0.0]),
        ),
        "reject_flat_from_flat" => nonzero(matches!(slope.reject_flat_from(&floor)?, Flat::Line(_))),
        "line_meets_circle" | "line_meets_circle_corrected" => {
            points(Line::new([-2.0, 0.0, 0.0], e1)?.intersect_circle(&ring)?)
        }
        "spheres_meet" => match unit.intersect_sphere(&Sphere::new(e1, 1.0)?)? {
            Meet::Circle { centre, radius, .. } => [centre.as_slice(), &[radius]].concat(),
            other => panic!("{other:?}"),
        },
        "three_planes_meet" => {
            let p = [e1, [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|n| Plane::new([1.0, 2.0, 3.0], n).unwrap());
            match Plane::intersect_planes(&p[0], &p[1], &p[2])? {
                Meet::Point(x) => vec![norm([x[0] - 1.0, x[1] - 2.0, x[2] - 3.0]), 1.0],
                other => panic!("{other:?}"),
            }
        }
        "lines_meet" => nonzero(matches!(
            Line::new([0.0, 0.0, 1.0], e1)?.intersect_line(&Line::new([0.0; 3], [0.0, 0.0, 1.0])?)?,
            Meet::Point(_)
        )),
        "lines_meet_corrected" => {
            points(Line::new([0.0, 0.0, 1.0], e1)?.intersect_line(&Line::new([0.0; 3], [0.0, 0.0, 1.0])?)?)
        }
        "pair_points_on_sphere" => points(cga_core::Bivector::from_points(e1, [3.0, 0.0, 0.0])?.intersect(&unit)?),
        "distance" => vec![cga_core::distance([0.0; 3], [3.0, 4.0, 0.0])],
        "fit_sphere" => {
            let (c, r) = fit_sphere(&five)?.centre_radius()?;
            [c.as_slice(), &[r]].concat()
        }
        "fit_circle" => vec![fit_circle(&five[..4])?.centre_normal_radius()?.2],
        "fit_plane" => vec![0.0, fit_plane(&five[..4])?.normal_offset()?.0[2].abs()],
        "fit_line" => vec![fit_line(&[[0.0; 3], [1.0, 1.0, 0.0], [2.0, 2.0, 0.0]])?.distance_to([3.0, 3.0, 0.0])?],
        "join_line_point" => vec![Line::new([0.0; 3], e1)?.join_point([0.0, 1.0, 0.0])?.normal_offset()?.0[2].abs()],
        "average_objects" => {
            let (c, _, r) = average_objects(&[ring, cb])?.centre_normal_radius()?;
            [c.as_slice(), &[r]].concat()
        }
        "closest_circle_line" | "closest_circle_line_aristidou" => {
            ring.closest_points_to_line(&Line::new([3.0, 0.0, 2.0], [0.0, 1.0, 0.0])?)?.on_self.to_vec()
        }
        "closest_circles" => {
            let k = ring.closest_points_to_circle(&Circle::new([3.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0)?)?;
            [k.on_self, k.on_other].concat()
        }
        "versor_between_circles" => {
            let v = ring.versor_to(&cb)?;
            let moved = Multivector::from(ring.moved_by(&v));
            let want = Multivector::from(cb.try_normalise().unwrap());
            vec![moved.coeffs.iter().zip(&want.coeffs).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)]
        }
        "motor_between_circles" => {
            Motor::between_circles(&ring, &Circle::new([1.0, 2.0, 3.0], e1, 1.0)?)?.move_point([0.0; 3]).to_vec()
        }
        "frames_versor" => {
            Rotor::from_frame(&[[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])?.rotate(e1).to_vec()
        }
        other => panic!("no answer of ours for the task {other}"),
    })
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1.0))
}

/// Ours is the expected answer of every task (1e-12), and clifford's where the script
/// found clifford right; the tasks where clifford is wrong are exactly those listed, and
/// the COOKBOOK says so beside each (it names the task's wrong spelling next to a warning).
#[test]
fn cookbook_clifford_spellings_against_ours() {
    let d = common::golden("cookbook_clifford.json");
    let cookbook = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/COOKBOOK.md")).unwrap();
    let mut wrong = Vec::new();
    for case in d["cases"].as_array().unwrap() {
        let task = case["task"].as_str().unwrap();
        let spelling = case["spelling"].as_str().unwrap();
        assert!(cookbook.contains(spelling), "{task}: the spelling `{spelling}` is no longer in docs/COOKBOOK.md");
        let expected = flat(&case["expected"]);
        let got = ours(task).unwrap_or_else(|e| panic!("{task}: {e}"));
        assert!(close(&got, &expected, 1e-12), "{task}: ours {got:?}, expected {expected:?}");
        if case["right"].as_bool().unwrap() {
            let theirs = flat(&case["answer"]);
            assert!(close(&got, &theirs, 1e-9), "{task}: ours {got:?}, clifford's {theirs:?}");
        } else if !case["as_documented"].as_bool().unwrap_or(false) {
            wrong.push(task.to_string());
        }
    }
    let listed: Vec<String> = d["wrong"].as_array().unwrap().iter().map(|t| t.as_str().unwrap().to_string()).collect();
    assert_eq!(wrong, listed);
    assert_eq!(
        listed,
        [
            "invert_point_in_sphere",
            "line_meets_circle",
            "lines_meet",
            "fit_sphere",
            "fit_circle",
            "fit_plane",
            "fit_line",
            "closest_circles"
        ]
    );
    // Each wrong spelling is flagged in the COOKBOOK: the section that shows it says "wrong".
    for task in &listed {
        let case = d["cases"].as_array().unwrap().iter().find(|c| c["task"] == task.as_str()).unwrap();
        let spelling = case["spelling"].as_str().unwrap();
        let at = cookbook.find(spelling).unwrap();
        let paragraph_end = cookbook[at..].find("\n\n").map_or(cookbook.len(), |k| at + k);
        let paragraph_start = cookbook[..at].rfind("\n\n").unwrap_or(0);
        assert!(
            cookbook[paragraph_start..paragraph_end].contains("wrong"),
            "{task}: docs/COOKBOOK.md shows `{spelling}` without saying it is wrong"
        );
    }
}
