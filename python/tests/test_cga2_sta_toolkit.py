"""cga.cga2's and cga.sta's everyday constructors and read-backs (circle_through, line_through,
centre_radius, ends; boost, rotation, four_velocity, velocity, field, fields) against Euclid and
special relativity, on single values and arrays row for row, with the refusals by row."""

import numpy as np
import pytest

import cga
from cga import cga2, sta

RNG = np.random.default_rng(52)


def circumcentre(a, b, c):
    d = 2 * (a[..., 0] * (b[..., 1] - c[..., 1]) + b[..., 0] * (c[..., 1] - a[..., 1]) + c[..., 0] * (a[..., 1] - b[..., 1]))
    a2, b2, c2 = (np.sum(x * x, axis=-1) for x in (a, b, c))
    x = (a2 * (b[..., 1] - c[..., 1]) + b2 * (c[..., 1] - a[..., 1]) + c2 * (a[..., 1] - b[..., 1])) / d
    y = (a2 * (c[..., 0] - b[..., 0]) + b2 * (a[..., 0] - c[..., 0]) + c2 * (b[..., 0] - a[..., 0])) / d
    return np.stack([x, y], axis=-1)


def test_circles_lines_and_pairs():
    a, b, c = (RNG.uniform(-5, 5, (6, 2)) for _ in range(3))
    centre, radius = cga2.centre_radius(cga2.circle_through(a, b, c))
    want = circumcentre(a, b, c)
    assert np.allclose(centre, want, atol=1e-9) and np.allclose(radius, np.linalg.norm(a - want, axis=1), atol=1e-9)
    one_centre, one_radius = cga2.centre_radius(cga2.circle_through(a[2], b[2], c[2]))
    assert np.array_equal(one_centre, centre[2]) and one_radius == radius[2]
    ends = cga2.ends(cga2.point(a) ^ cga2.point(b))
    assert ends.shape == (6, 2, 2) and np.allclose(ends[:, 0], a, atol=1e-10) and np.allclose(ends[:, 1], b, atol=1e-10)
    line = cga2.line_through(a, b)
    assert np.allclose(((line ^ cga2.point(a + 0.3 * (b - a))).array), 0.0, atol=1e-10)
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga2.circle_through([[0, 0], [0, 0]], [[1, 0], [1, 1]], [[0, 1], [2, 2]])
    with pytest.raises(cga.GeometryError, match="line"):
        cga2.centre_radius(line[0])


def test_boosts_rotations_and_fields():
    n = RNG.normal(size=(5, 3))
    u = n / np.linalg.norm(n, axis=1)[:, None]
    phi = RNG.uniform(-2, 2, 5)
    moved = sta.boost(n, phi).sandwich(sta.Vector([1.0, 0, 0, 0]))
    assert np.allclose(sta.velocity(moved), u * np.tanh(phi)[:, None], atol=1e-13)
    quarter = sta.rotation([0, 0, 1], np.pi / 2).sandwich(sta.Vector([0, 1.0, 0, 0]))
    assert np.allclose(quarter.array, [0, 0, 1, 0], atol=1e-15)
    v = RNG.uniform(-0.5, 0.5, (5, 3))
    w = sta.four_velocity(v)
    assert np.allclose((w * w).array[..., 0], 1.0) and np.allclose(sta.velocity(w), v)
    e, b = RNG.normal(size=(5, 3)), RNG.normal(size=(5, 3))
    e2, b2 = sta.fields(sta.field(e, b))
    assert np.allclose(e2, e, atol=1e-15) and np.allclose(b2, b, atol=1e-15)
    with pytest.raises(cga.GeometryError):
        sta.four_velocity([1.0, 0, 0])


def test_against_kingdon():
    kingdon = pytest.importorskip("kingdon")
    from functools import reduce

    from kingdon_blades import from_kingdon, to_kingdon

    # 2D CGA: kingdon's A ^ B ^ C of its own conformal points, eo = ½(e4 − e3), ei = e3 + e4.
    alg = kingdon.Algebra(3, 1)
    e = alg.blades
    vec = {"1": e.e1, "2": e.e2, "o": 0.5 * (e.e4 - e.e3), "i": e.e3 + e.e4}

    def blade(name, alg):
        if name == "s":
            return alg.multivector({"e": 1.0})
        return reduce(lambda a, b: a ^ b, (vec[label] for label in name[1:]))

    def up(x):
        return x[0] * vec["1"] + x[1] * vec["2"] + 0.5 * (x @ x) * vec["i"] + vec["o"]

    a, b, c = (RNG.uniform(-5, 5, 2) for _ in range(3))
    theirs = from_kingdon(up(a) ^ up(b) ^ up(c), cga2.Circle, alg, blade, 16)
    assert np.allclose(cga2.circle_through(a, b, c).array, theirs, atol=1e-12)
    theirs = from_kingdon(up(a) ^ up(b) ^ vec["i"], cga2.Circle, alg, blade, 16)
    assert np.allclose(cga2.line_through(a, b).array, theirs, atol=1e-12)
    # STA: kingdon's exp of −φ/2 n̂ · (e01, e02, e03) and of θ/2 a · (e23, −e13, e12).
    alg = kingdon.Algebra(1, 3, start_index=0)
    e = alg.blades
    n = RNG.normal(size=3)
    u = n / np.linalg.norm(n)
    boost = (-0.35 * (u[0] * e.e01 + u[1] * e.e02 + u[2] * e.e03)).exp()
    sta_blade = lambda name, alg: alg.multivector({"e": 1.0}) if name == "s" else getattr(alg.blades, name)
    assert np.allclose(sta.boost(n, 0.7).array, from_kingdon(boost, sta.Rotor, alg, sta_blade, 16), atol=1e-14)
    turn = (0.6 * (u[0] * e.e23 - u[1] * e.e13 + u[2] * e.e12)).exp()
    assert np.allclose(sta.rotation(n, 1.2).array, from_kingdon(turn, sta.Rotor, alg, sta_blade, 16), atol=1e-14)
    # And kingdon's sandwich of γ0 by the boost moves it along +n̂.
    moved = boost * e.e0 * ~boost
    assert np.allclose([moved.e1 / moved.e0, moved.e2 / moved.e0, moved.e3 / moved.e0], u * np.tanh(0.7))
