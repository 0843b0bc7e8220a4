"""Versors between frames and between objects, and fits with their stated error, against
clifford 1.5.1's own answers (tests/golden/clifford_tools.json, made by
tools/clifford_tools.py) and against Euclid; arrays row for row against one value at a time,
and what has no answer refused by name."""

import json
import os

import numpy as np
import pytest

import cga
from cga.interop import from_orthonormal, orthonormal

GOLDEN = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "golden", "clifford_tools.json")
CASES = json.load(open(GOLDEN))["cases"]
KINDS = {"circle": cga.Circle, "sphere": cga.Sphere, "plane": cga.Plane, "line": cga.Line,
         "point_pair": cga.Bivector}
RNG = np.random.default_rng(51)


def _up_to_sign(ours, theirs):
    """The largest coefficient difference of ``ours`` (a value) from ``theirs`` (32 orthonormal
    coefficients) or its negative."""
    a, b = orthonormal(ours), np.asarray(theirs)
    return min(np.abs(a - b).max(), np.abs(a + b).max())


def test_rotor_and_motor_between_frames_are_cliffords_and_move_each_axis():
    frm = np.array([c["from"] for c in CASES["frames"]])
    to = np.array([c["to"] for c in CASES["frames"]])
    rotors = cga.Rotor.between_frames(frm, to)
    assert len(rotors) == len(frm)
    for i, case in enumerate(CASES["frames"]):
        one = cga.Rotor.between_frames(frm[i], to[i])
        assert one.single and np.array_equal(one.array, rotors[i].array)
        turn = cga.Motor.from_rotor_translation(one, [0.0, 0.0, 0.0])
        assert np.abs(turn.move_point(frm[i]) - to[i]).max() < 1e-14
        assert _up_to_sign(one, case["orthoFrames2Versor"]["ok"]) < 1e-9
    # With origins: the origin and the axes both land.
    m = cga.Motor.between_frames([1.0, 2.0, 3.0], frm, [-2.0, 0.5, 4.0], to)
    assert np.abs(m.move_point([1.0, 2.0, 3.0]) - [-2.0, 0.5, 4.0]).max() < 1e-14
    tips = m.move_point(np.array([1.0, 2.0, 3.0]) + frm[:, 2])
    assert np.abs(tips - ([-2.0, 0.5, 4.0] + to[:, 2])).max() < 1e-14
    # From the standard basis.
    assert np.array_equal(cga.Rotor.from_frame(to[0]).array, cga.Rotor.between_frames(np.eye(3), to[0]).array)


def test_frames_that_are_not_frames_are_refused_by_name_and_row():
    mirrored = np.diag([1.0, 1.0, -1.0])
    with pytest.raises(cga.GeometryError, match="handed"):
        cga.Rotor.between_frames(np.eye(3), mirrored)
    skewed = np.array([[1.0, 0, 0], [0.1, 1, 0], [0, 0, 1]])
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga.Rotor.from_frame(np.stack([np.eye(3), skewed]))
    with pytest.raises(cga.ShapeError, match="frm"):
        cga.Rotor.between_frames(np.eye(2), np.eye(3))
    with pytest.raises(cga.ValueError, match="finite"):
        cga.Rotor.from_frame(np.full((3, 3), np.nan))
    with pytest.raises(cga.ShapeError, match="2 and 3 rows"):
        cga.Rotor.between_frames(np.stack([np.eye(3)] * 2), np.stack([np.eye(3)] * 3))


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_versor_to_takes_each_object_onto_the_other_as_clifford_does(kind):
    cases = [c for c in CASES["between"] if c["kind"] == kind]
    cls = KINDS[kind]
    x1 = from_orthonormal([c["x1"] for c in cases], cls)
    x2 = from_orthonormal([c["x2"] for c in cases], cls)
    v = x1.versor_to(x2)
    assert isinstance(v, cga.Even) and len(v) == len(cases)
    moved, target = x1.moved_by(v).array, x2.normalise().array
    assert np.abs(moved - target).max() < 1e-12 * np.abs(target).max()
    for i, case in enumerate(cases):
        one = x1[i].versor_to(x2[i])
        assert np.array_equal(one.array, v[i].array)
        vv = (one * ~one).grade(0).array[0]
        assert abs(abs(vv) - 1) < 1e-12
        assert _up_to_sign(one, case["rotor_between_objects"]["ok"]) < 1e-9, i
    assert np.array_equal(cga.rotor_between_objects(x1, x2).array, v.array)


def test_an_object_and_its_opposite_have_no_versor():
    a = cga.Circle.from_centre_normal_radius([0.0, 0, 0], [0, 0, 1.0], 1.0)
    with pytest.raises(cga.GeometryError, match="versor"):
        a.versor_to(-a)
    with pytest.raises(TypeError):
        a.versor_to(cga.Sphere.from_centre_radius([0.0, 0, 0], 1.0))


def test_motor_between_rounds_is_cliffords_and_rigid():
    for kind, cls in (("circle", cga.Circle), ("sphere", cga.Sphere)):
        cases = [c for c in CASES["rounds"] if c["kind"] == kind]
        a = from_orthonormal([c["x1"] for c in cases], cls)
        b = from_orthonormal([c["x2"] for c in cases], cls)
        m = cga.motor_between_rounds(a, b)
        if kind == "circle":
            (c1, n1, _), (c2, n2, _) = a.centre_normal_radius(), b.centre_normal_radius()
            assert np.abs(m.move_point(c1) - c2).max() < 1e-13
            # A direction moves as the difference of two moved points.
            turned = m.move_point(c1 + n1) - m.move_point(c1)
            assert np.abs(turned - n2).max() < 1e-13
        else:
            (c1, _), (c2, _) = a.centre_radius(), b.centre_radius()
            assert np.abs(m.move_point(c1) - c2).max() < 1e-13
        for i, case in enumerate(cases):
            assert _up_to_sign(m[i], case["motor_between_rounds"]["ok"]) < 1e-9, (kind, i)
            if case["same_radius"]:
                onto = m[i].sandwich(a[i]).array
                assert np.abs(onto - b[i].array).max() < 1e-12 * np.abs(b[i].array).max()
    with pytest.raises(TypeError, match="two Circles"):
        cga.motor_between_rounds(cga.Sphere.from_centre_radius([0.0, 0, 0], 1.0), cga.Circle.from_centre_normal_radius([0.0, 0, 0], [0, 0, 1.0], 1.0))


def _distances(kind, fitted, points):
    """Each point's Euclidean distance from the fitted object, by Euclid."""
    if kind == "sphere":
        c, r = fitted.centre_radius()
        return np.abs(np.linalg.norm(points - c, axis=1) - r)
    if kind == "circle":
        c, n, r = fitted.centre_normal_radius()
        h = (points - c) @ n
        rho = np.linalg.norm((points - c) - np.outer(h, n), axis=1)
        return np.hypot(h, rho - r)
    if kind == "plane":
        n, d = fitted.normal_offset()
        return np.abs(points @ n - d)
    p, u = fitted.point(), fitted.direction()
    return np.linalg.norm(np.cross(points - p, u), axis=1)


PARAMETERS = {"sphere": 4, "circle": 6, "plane": 3, "line": 4}


@pytest.mark.parametrize("kind", sorted(PARAMETERS))
def test_fits_state_their_error_by_euclids_distances(kind):
    cls = KINDS[kind]
    n, noise = 200, 1e-3
    c, r = np.array([3.0, -1.0, 2.0]), 1.5
    t = RNG.uniform(0, 2 * np.pi, n)
    if kind == "sphere":
        d = RNG.normal(size=(n, 3))
        exact = c + r * d / np.linalg.norm(d, axis=1)[:, None]
    elif kind == "circle":
        exact = c + r * np.stack([np.cos(t), np.sin(t), 0 * t], axis=1)
    elif kind == "plane":
        exact = c + np.stack([RNG.uniform(-2, 2, n), RNG.uniform(-2, 2, n), 0 * t], axis=1)
    else:
        exact = c + np.outer(RNG.uniform(-3, 3, n), [0.6, 0.8, 0.0])
    points = exact + RNG.normal(scale=noise, size=(n, 3))
    fit = cls.fit_with_error(points)
    obj, rms, largest, sigma = fit
    assert np.array_equal(obj.array, cls.fit(points).array)
    dist = _distances(kind, obj, points)
    assert abs(rms - np.sqrt(np.mean(dist**2))) < 1e-12 and abs(largest - dist.max()) < 1e-12
    p = PARAMETERS[kind]
    assert abs(sigma - rms * np.sqrt(n / (n - p))) < 1e-15
    # The stated noise: σ along one normal direction, √2 σ for a circle and a line (two).
    per = np.sqrt(2) if kind in ("circle", "line") else 1.0
    assert abs(sigma / (per * noise) - 1) < 0.25
    # Sets of points: row by row, the numbers as arrays.
    many = cls.fit_with_error(np.stack([points, exact]))
    assert len(many.object) == 2 and many.rms.shape == (2,)
    assert np.array_equal(many.object[0].array, obj.array) and many.max[0] == largest
    assert many.rms[1] < 1e-12
    assert cga.fit_sphere_with_error is cga.Sphere.fit_with_error
    assert "Fit(object=" in repr(fit)


def test_a_fit_with_error_refuses_what_fit_refuses():
    collinear = np.outer(np.arange(5.0), [1.0, 2.0, 3.0])
    with pytest.raises(cga.GeometryError, match="collinear"):
        cga.fit_circle_with_error(collinear)
    with pytest.raises(cga.GeometryError, match="row 1"):
        ring = np.array([[1.0, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0.6, 0.8, 0]])
        cga.Circle.fit_with_error(np.stack([ring, collinear]))
    with pytest.raises(cga.ShapeError):
        cga.fit_plane_with_error(np.zeros((4, 2)))
