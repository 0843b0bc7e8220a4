"""The toolkit on the classes against Euclidean formulas: classification, reflections and
inversions, distances and angles, the versors' log, exp and interpolation; arrays row for row
against one value at a time, and what has no answer refused by name."""

import numpy as np
import pytest

import cga

RNG = np.random.default_rng(5)
TOL = 1e-12


def test_classify_reads_each_kind_in_euclidean_terms():
    c = cga.Circle.from_centre_normal_radius([1.0, 2.0, 3.0], [0, 0, 1.0], 2.0).classify()
    assert c["kind"] == "round" and c["grade"] == 3 and c["reality"] == "real"
    assert np.allclose(c["centre"], [1, 2, 3], atol=TOL) and abs(c["radius_squared"] - 4.0) < TOL
    line = cga.Line.through([0, 0, 1.0], [1.0, 0, 1.0]).classify()
    assert line["kind"] == "line" and np.allclose(line["point"], [0, 0, 1], atol=TOL)
    plane = cga.Plane.from_point_normal([0, 0, 2.0], [0, 0, 1.0]).classify()
    assert plane["kind"] == "plane" and abs(abs(plane["offset"]) - 2.0) < TOL
    many = cga.Sphere.from_centre_radius(RNG.normal(size=(4, 3)), 1.5).classify()
    assert [k["kind"] for k in many] == ["round"] * 4


def test_reflections_and_inversion_of_points_are_euclids():
    x = RNG.normal(size=(20, 3))
    X = cga.up(x)
    mirror = cga.Plane.from_point_normal([0, 0, 0.5], [0, 0, 1.0])
    assert np.allclose(cga.down(X.reflect_in(mirror)), x * [1, 1, -1] + [0, 0, 1.0], atol=TOL)
    c, r = np.array([0.3, -0.2, 0.1]), 1.7
    d = x - c
    want = c + r * r * d / np.sum(d * d, axis=1, keepdims=True)
    assert np.allclose(cga.down(X.invert_in(cga.Sphere.from_centre_radius(c, r))), want, rtol=1e-12, atol=TOL)
    assert np.allclose(cga.down(X.reflect_in_point(c)), 2 * c - x, atol=TOL)
    axis = cga.Line.through([0, 0, 0.0], [0, 0, 1.0])
    assert np.allclose(cga.down(X.reflect_in_line(axis)), x * [-1, -1, 1], atol=TOL)
    # A line not through the centre inverts to a circle.
    assert type(cga.Line.through([2.0, 0, 0], [2.0, 1.0, 0]).invert_in(cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0))) is cga.Circle


def test_distances_and_angles_are_euclids():
    p, q, x = RNG.normal(size=(3, 30, 3))
    lines = cga.Line.through(p, q)
    d = (q - p) / np.linalg.norm(q - p, axis=1, keepdims=True)
    want = np.linalg.norm(np.cross(x - p, d), axis=1)
    assert np.allclose(lines.distance_to(x), want, rtol=1e-12, atol=TOL)
    assert abs(lines[3].distance_to(x[3]) - want[3]) < TOL
    plane = cga.Plane.from_point_normal([0, 0, 1.0], [0, 0, 1.0])
    assert np.allclose(plane.signed_distance(x), x[:, 2] - 1.0, atol=TOL)
    sphere = cga.Sphere.from_centre_radius([1.0, 0, 0], 0.5)
    assert np.allclose(sphere.signed_distance(x), np.linalg.norm(x - [1, 0, 0], axis=1) - 0.5, atol=TOL)
    a, b = cga.Line.through([0, 0, 0.0], [1.0, 0, 0]), cga.Line.through([0, 1.0, 1.0], [0, 2.0, 1.0])
    on_a, on_b, dist = a.closest_points(b)
    assert np.allclose(on_a, [0, 0, 0], atol=TOL) and np.allclose(on_b, [0, 0, 1], atol=TOL) and abs(dist - 1) < TOL
    assert abs(a.angle_to(b) - np.pi / 2) < TOL


def test_motor_log_exp_and_interpolation():
    r = cga.Rotor.from_axis_angle([0.0, 0.6, 0.8], 1.1)
    m = cga.Motor.from_rotor_translation(r, [1.0, -2.0, 0.5])
    assert np.allclose(cga.Motor.exp(m.log()).array, m.array, atol=TOL)
    assert np.allclose(cga.Rotor.exp(r.log()).array, r.array, atol=TOL)
    one = cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0])
    path = cga.Motor.interpolate(one, m, np.linspace(0, 1, 5))
    assert len(path) == 5 and np.allclose(path[0].array, one.array, atol=TOL) and np.allclose(path[4].array, m.array, atol=TOL)
    # Half way twice is the whole way: M(½)² = M.
    half = cga.Motor.interpolate(one, m, 0.5)
    assert np.allclose((half * half).array, m.array, atol=TOL)


def test_what_has_no_answer_is_refused_by_name():
    centre = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga.up([[1.0, 0, 0], [0, 0, 0.0]]).invert_in(centre)
    with pytest.raises(TypeError, match="expected a Plane"):
        cga.up([1.0, 0, 0]).reflect_in(centre)
    with pytest.raises(cga.ValueError):
        cga.Motor.interpolate(cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0]), cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0]), float("nan"))
    with pytest.raises(cga.ShapeError):
        cga.Line.through([0, 0, 0.0], [1.0, 0, 0]).distance_to([1.0, 2.0])
