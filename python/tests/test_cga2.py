"""cga.cga2, 2D CGA G(3,1) in the null basis e1, e2, eo, ei: every generated product (``*``, ``^``,
``&``) against
kingdon's ``Algebra(3, 1)`` (``eo = ½(e4 − e3)``, ``ei = e3 + e4`` there, each blade the outer
product of its labels' vectors), sandwiches likewise, and points, circles, lines, translators
and rotors against Euclid."""

import itertools
from functools import reduce

import numpy as np
import pytest

import cga
from cga import cga2
from kingdon_blades import check_products, from_kingdon, to_kingdon

RNG = np.random.default_rng(31)
CLASSES = [cga2.Scalar, cga2.Vector, cga2.PointPair, cga2.Circle, cga2.Pseudoscalar, cga2.Rotor, cga2.Motor,
           cga2.Even, cga2.Multivector]


def random(cls, n=None):
    shape = (len(cls.blades),) if n is None else (n, len(cls.blades))
    return cls(RNG.normal(size=shape))


def vectors(alg):
    """kingdon's vectors for each label: e1 … e4 orthonormal (e4² = −1), eo and ei null."""
    e = alg.blades
    e1, e2, e3, e4 = e.e1, e.e2, e.e3, e.e4
    return {"1": e1, "2": e2, "3": e3, "4": e4, "o": 0.5 * (e4 - e3), "i": e3 + e4}


def blade(name, alg):
    """A blade named by its labels (``e12o``, ``s``) as the outer product of their vectors."""
    if name == "s":
        return alg.multivector({"e": 1.0})
    v = vectors(alg)
    return reduce(lambda a, b: a ^ b, (v[label] for label in name[1:]))


def kingdon_of(value, alg):
    return to_kingdon(value, alg, blade)


def cga2_of(mv, cls, alg):
    return from_kingdon(mv, cls, alg, blade, 16)


@pytest.mark.parametrize("left,right", list(itertools.product(CLASSES, CLASSES)))
def test_products_are_kingdons(left, right):
    kingdon = pytest.importorskip("kingdon")
    alg = kingdon.Algebra(3, 1)
    check_products(random(left), random(right), alg, blade, 16)


def test_sandwiches_are_kingdons():
    kingdon = pytest.importorskip("kingdon")
    alg = kingdon.Algebra(3, 1)
    for versor in (cga2.Motor, cga2.Rotor):
        m = random(versor)
        km = kingdon_of(m, alg)
        for cls in (cga2.Vector, cga2.PointPair, cga2.Circle):
            x = random(cls)
            got = m.sandwich(x)
            want = cga2_of(km * kingdon_of(x, alg) * ~km, type(got), alg)
            assert np.allclose(got.array, want, rtol=1e-12, atol=1e-12), (versor.__name__, cls.__name__)


def test_points_circles_lines_and_motors_are_euclids():
    x, y = RNG.normal(size=(40, 2)), RNG.normal(size=(40, 2))
    p, q = cga2.point(x), cga2.point(y)
    assert np.allclose(cga2.position(p), x, atol=1e-15)
    assert np.allclose(np.asarray((p | p).array).ravel(), 0.0, atol=1e-14)
    assert np.allclose(np.asarray((p | q).array).ravel(), -0.5 * np.sum((x - y) ** 2, axis=1), rtol=1e-13, atol=1e-14)
    t = np.array([0.5, -2.0])
    assert np.allclose(cga2.position(cga2.translator(t).sandwich(p)), x + t, atol=1e-14)
    angle = 0.7
    c, s = np.cos(angle), np.sin(angle)
    turned = cga2.position(cga2.rotor(angle).sandwich(p))
    assert np.allclose(turned, x @ np.array([[c, s], [-s, c]]), atol=1e-14)
    # The circle through three points of the unit circle about (1, 2) holds a fourth; the line
    # through two points holds their midpoint and not a point off it.
    on = lambda a: cga2.point([1.0 + np.cos(a), 2.0 + np.sin(a)])
    circle = on(0.1) ^ on(1.7) ^ on(4.0)
    assert type(circle) is cga2.Circle
    assert np.allclose((on(2.9) ^ circle).array, 0.0, atol=1e-13)
    assert not np.allclose((cga2.point([1.0, 2.0]) ^ circle).array, 0.0, atol=1e-3)
    line = cga2.point([0.0, 0.0]) ^ cga2.point([2.0, 2.0]) ^ cga2.ei
    assert np.allclose((cga2.point([1.0, 1.0]) ^ line).array, 0.0, atol=1e-14)
    assert not np.allclose((cga2.point([1.0, 0.0]) ^ line).array, 0.0, atol=1e-3)


def test_arrays_are_row_for_row_and_bad_input_is_refused():
    m, p = random(cga2.Motor, 7), random(cga2.Vector, 7)
    moved = m.sandwich(p)
    for i in range(7):
        assert np.array_equal(moved[i].array, m[i].sandwich(p[i]).array)
    assert cga2.Motor.__module__ == "cga.cga2"
    with pytest.raises(TypeError, match="two algebras"):
        cga.up([1.0, 2, 3]) ^ cga2.point([1.0, 2.0])
    with pytest.raises(cga.GeometryError):
        cga2.position(cga2.ei)
    with pytest.raises(cga.ShapeError):
        cga2.point([1.0, 2.0, 3.0])
    assert len(set(cga2.Multivector.blades)) == 16
