"""cga.pga's toolkit (rotor, translator, screw, exp, log, sqrt, pow, interpolate, normalise,
line_through, plane_from_normal_distance, from_line_pitch, rotor_translation, distance, angle,
project) against kingdon 3.0.0's own results (``Algebra(3, 0, 1)``: its products, simple
``exp``, ``sqrt``, ``normalized``, ``proj``, inner products) and against Euclid, on single
values and on arrays row for row; the signs docs/PGA.md states."""

import numpy as np
import pytest

import cga
from cga import pga
from kingdon_blades import named_from_kingdon
from kingdon_blades import named_to_kingdon as to_kingdon

RNG = np.random.default_rng(51)


def from_kingdon(mv, cls):
    return cls(named_from_kingdon(mv, cls))


def close_motor(a, b, tol):
    a, b = np.asarray(a.array), np.asarray(b.array)
    return min(np.max(np.abs(a - b)), np.max(np.abs(a + b))) <= tol * (1 + np.max(np.abs(b)))


@pytest.fixture(scope="module")
def alg():
    kingdon = pytest.importorskip("kingdon")
    return kingdon.Algebra(3, 0, 1)


def random_screws(n):
    p, d = RNG.uniform(-5, 5, (n, 3)), RNG.normal(size=(n, 3))
    lines = pga.line_through(p, p + d)
    return lines, RNG.uniform(-3, 3, n), RNG.uniform(-3, 3, n)


def test_rotor_and_translator_move_as_named():
    x = RNG.uniform(-5, 5, (6, 3))
    t = RNG.uniform(-5, 5, (6, 3))
    assert np.allclose(pga.position(pga.translator(t).sandwich(pga.point(x))), x + t, atol=1e-13)
    quarter = pga.rotor([0, 0, 1], np.pi / 2)
    assert np.allclose(pga.position(quarter.sandwich(pga.point([1, 0, 0]))), [0, 1, 0], atol=1e-15)
    with pytest.raises(cga.GeometryError, match="zero"):
        pga.rotor([0, 0, 0], 1.0)
    with pytest.raises(cga.ValueError):
        pga.translator([np.nan, 0, 0])


def test_screws_exp_log_sqrt_against_kingdon(alg):
    lines, theta, delta = random_screws(8)
    motors = pga.screw(lines, theta, delta)
    I = alg.pseudoscalar(e0123=1.0)
    for i in range(8):
        unit = to_kingdon(lines[i], alg).normalized()
        want = (1 + delta[i] / 2 * (I * unit)) * (np.cos(theta[i] / 2) - np.sin(theta[i] / 2) * unit)
        assert close_motor(motors[i], from_kingdon(want, pga.Motor), 1e-13)
        generator = from_kingdon(-theta[i] / 2 * unit + delta[i] / 2 * (I * unit), pga.Line)
        assert np.allclose(pga.log(motors[i]).array, generator.array, atol=1e-12)
        assert close_motor(pga.exp(generator), motors[i], 1e-13)
        half = (1 + delta[i] / 4 * (I * unit)) * (np.cos(theta[i] / 4) - np.sin(theta[i] / 4) * unit)
        assert close_motor(pga.sqrt(motors[i]), from_kingdon(half, pga.Motor), 1e-13)
    # Arrays row for row, the same bits as one value at a time.
    assert np.array_equal(pga.log(motors).array[3], pga.log(motors[3]).array)
    assert np.array_equal(pga.sqrt(motors).array[5], pga.sqrt(motors[5]).array)


# kingdon warns that it cannot check its input is a Study number; ours are.
@pytest.mark.filterwarnings("ignore:Cannot verify that we really are taking the sqrt")
def test_kingdons_sqrt_agrees_for_rotations_and_translations(alg):
    for m in (pga.rotor(RNG.normal(size=3), 2.0), pga.translator(RNG.normal(size=3))):
        assert close_motor(pga.sqrt(m), from_kingdon(to_kingdon(m, alg).sqrt(), pga.Motor), 1e-14)


def test_interpolate_and_normalise_against_kingdon(alg):
    lines, theta, delta = random_screws(4)
    a = pga.screw(lines, theta, delta)
    b = pga.screw(lines[::-1], theta[::-1] / 2, delta)
    mid = pga.interpolate(a, b, 0.5)
    for i in range(4):
        ka, kb = to_kingdon(a[i], alg), to_kingdon(b[i], alg)
        # kingdon's sqrt of b ã, normalised as a motor (kingdon's own normalized()).
        d = kb * ~ka
        if d.e < 0:
            d = -d
        half = pga.sqrt(from_kingdon(d, pga.Motor))
        want = from_kingdon(to_kingdon(half, alg) * ka, pga.Motor)
        assert close_motor(mid[i], want, 1e-12)
        assert close_motor(pga.interpolate(a[i], b[i], 0.0), a[i], 1e-14)
        assert close_motor(pga.interpolate(a[i], b[i], 1.0), b[i], 1e-12)
    wobbly = pga.Motor(a.array * 1.7 + 0.01)
    for i in range(4):
        want = from_kingdon(to_kingdon(wobbly[i], alg).normalized(), pga.Motor)
        assert np.allclose(pga.normalise(wobbly[i]).array, want.array, atol=1e-14)


def test_constructors_distances_projections(alg):
    p, q = RNG.uniform(-5, 5, (5, 3)), RNG.uniform(-5, 5, (5, 3))
    lines = pga.line_through(p, q)
    assert np.allclose(pga.direction(lines), q - p, atol=1e-13)
    assert np.allclose(pga.moment(lines), np.cross(p, q - p), atol=1e-12)
    with pytest.raises(cga.GeometryError, match="row 1"):
        pga.line_through([[0, 0, 0], [1, 1, 1]], [[1, 0, 0], [1, 1, 1]])
    plane = pga.plane_from_normal_distance([0, 0, 2], 3.0)
    assert np.allclose(plane.array, pga.plane(0, 0, 1, -3).array)
    x = pga.point(p)
    assert np.allclose(pga.distance(x, pga.point(q)), np.linalg.norm(p - q, axis=1), atol=1e-13)
    assert np.allclose(pga.distance(x, plane), p[:, 2] - 3, atol=1e-13)
    assert np.allclose(pga.distance(plane, x), p[:, 2] - 3, atol=1e-13)
    zaxis = pga.line_through([0, 0, 0], [0, 0, 1])
    assert np.allclose(pga.distance(x, zaxis), np.linalg.norm(p[:, :2], axis=1), atol=1e-13)
    xline = pga.line_through([0, 0, 4], [1, 0, 4])
    assert np.isclose(pga.distance(zaxis, xline), 0.0, atol=1e-15)
    assert np.isclose(pga.distance(pga.line_through([0, 1, 4], [1, 1, 4]), zaxis), 1.0)
    # Projections: kingdon's proj for a point and a line onto a plane.
    on = pga.project(x[0], plane)
    assert np.allclose(pga.position(on), [*p[0, :2], 3.0])
    kp = from_kingdon(to_kingdon(x[0], alg).proj(to_kingdon(plane, alg)), pga.Point)
    assert np.allclose(pga.position(kp), pga.position(on))
    tilted = lines[0]
    mine = pga.project(tilted, plane)
    theirs = from_kingdon(to_kingdon(tilted, alg).proj(to_kingdon(plane, alg)), pga.Line)
    scale = np.linalg.norm(pga.direction(mine)) / np.linalg.norm(pga.direction(theirs))
    assert np.allclose(mine.array, scale * theirs.array, atol=1e-12), "same line, same orientation"
    through = pga.project(tilted, x[1])
    assert np.isclose(pga.distance(x[1], through), 0.0, atol=1e-12)
    d = pga.direction(through)
    assert np.allclose(d / np.linalg.norm(d), (q[0] - p[0]) / np.linalg.norm(q[0] - p[0]))


def test_the_signs_docs_state(alg):
    x, c = RNG.uniform(-5, 5, 3), RNG.uniform(-2, 2, 4)
    dist = c[:3] @ x + c[3]
    P, p = pga.point(x), pga.plane(*c)
    assert np.isclose(float((p & P).array[0]), dist) and np.isclose(float((P & p).array[0]), -dist)
    kp, kP = to_kingdon(p, alg), to_kingdon(P, alg)
    assert np.isclose(float((kp & kP).e), dist) and np.isclose(float((kP & kp).e), -dist)
    assert np.isclose(float((p ^ P).array[0]), dist) and np.isclose(float((kp ^ kP).e0123), dist)


def test_pow_pitch_and_rotor_translation(alg):
    lines, theta, delta = random_screws(6)
    motors = pga.screw(lines, theta, delta)
    t = RNG.uniform(-1.5, 1.5, 6)
    powered = pga.pow(motors, t)
    I = alg.pseudoscalar(e0123=1.0)
    for i in range(6):
        # kingdon's closed form of the screw a fraction t of the way: angle tθ, slide tδ.
        unit = to_kingdon(lines[i], alg).normalized()
        a, s = t[i] * theta[i], t[i] * delta[i]
        want = (1 + s / 2 * (I * unit)) * (np.cos(a / 2) - np.sin(a / 2) * unit)
        assert close_motor(powered[i], from_kingdon(want, pga.Motor), 1e-12)
        assert close_motor(pga.pow(motors[i], 2.0), motors[i] * motors[i], 1e-12)
        assert close_motor(pga.pow(motors[i], 0.5), pga.sqrt(motors[i]), 1e-13)
    assert np.array_equal(powered.array[2], pga.pow(motors[2], t[2]).array)
    pitch = RNG.uniform(-2, 2, 6)
    assert np.allclose(pga.from_line_pitch(lines, theta, pitch).array, pga.screw(lines, theta, pitch * theta).array)
    r, moved = pga.rotor_translation(motors)
    assert moved.shape == (6, 3)
    for i in range(6):
        assert close_motor(pga.from_rotor_translator(r[i], pga.translator(moved[i])), pga.normalise(motors[i]), 1e-12)
        assert np.allclose(pga.position(r[i].sandwich(pga.point([0, 0, 0]))), 0.0, atol=1e-12)
    with pytest.raises(cga.GeometryError):
        pga.rotor_translation(pga.Motor([0.0, 1.0, 0, 0, 0, 0, 0, 0]))


def test_angles_against_euclid_and_kingdon(alg):
    p, d1, d2 = RNG.uniform(-5, 5, (8, 3)), RNG.normal(size=(8, 3)), RNG.normal(size=(8, 3))
    a, b = pga.line_through(p, p + d1), pga.line_through(p + 1, p + 1 + d2)
    unit = lambda v: v / np.linalg.norm(v, axis=-1, keepdims=True)
    between = np.arccos(np.clip(np.sum(unit(d1) * unit(d2), axis=-1), -1, 1))
    assert np.allclose(pga.angle(a, b), between, atol=1e-13)
    n1, n2 = RNG.normal(size=(8, 3)), RNG.normal(size=(8, 3))
    p1, p2 = pga.plane(*n1.T, 1.0), pga.plane(*n2.T, -2.0)
    planes = np.arccos(np.clip(np.sum(unit(n1) * unit(n2), axis=-1), -1, 1))
    assert np.allclose(pga.angle(p1, p2), planes, atol=1e-13)
    tilt = np.arcsin(np.abs(np.sum(unit(d1) * unit(n1), axis=-1)))
    assert np.allclose(pga.angle(a, p1), tilt, atol=1e-13)
    assert np.allclose(pga.angle(p1, a), tilt, atol=1e-13)
    for i in range(8):
        # kingdon: the unit values' inner product is the cosine, up to its sign.
        ka, kb = to_kingdon(a[i], alg).normalized(), to_kingdon(b[i], alg).normalized()
        assert np.isclose(abs((ka | kb).e), abs(np.cos(between[i])), atol=1e-12)
        kp, kq = to_kingdon(p1[i], alg).normalized(), to_kingdon(p2[i], alg).normalized()
        assert np.isclose((kp | kq).e, np.cos(planes[i]), atol=1e-12)
    assert isinstance(pga.angle(a[0], b[0]), float)
    with pytest.raises(TypeError, match="no angle"):
        pga.angle(pga.point([0, 0, 0]), p1)
