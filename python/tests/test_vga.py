"""cga.vga, the 3D vector algebra G(3): every generated product (``*``, ``^``, ``&``) of every
pair of its classes against kingdon's ``Algebra(3)``, rotor sandwiches likewise, and rotations
against Rodrigues' formula. The algebra reached the package through the one list of algebras
(one ``small_algebra!`` line), with a storage of 8 coefficients."""

import itertools
from functools import reduce

import numpy as np
import pytest

import cga
from cga import vga
from kingdon_blades import check_products, from_kingdon, to_kingdon

RNG = np.random.default_rng(37)
CLASSES = [vga.Scalar, vga.Vector, vga.Bivector, vga.Pseudoscalar, vga.Rotor, vga.Odd, vga.Multivector]


def random(cls, n=None):
    shape = (len(cls.blades),) if n is None else (n, len(cls.blades))
    return cls(RNG.normal(size=shape))


def blade(name, alg):
    """A blade named by its labels (``e13``, ``s``) as the outer product of its vectors."""
    if name == "s":
        return alg.multivector({"e": 1.0})
    e = alg.blades
    vectors = {"1": e.e1, "2": e.e2, "3": e.e3}
    return reduce(lambda a, b: a ^ b, (vectors[label] for label in name[1:]))


@pytest.mark.parametrize("left,right", list(itertools.product(CLASSES, CLASSES)))
def test_products_are_kingdons(left, right):
    kingdon = pytest.importorskip("kingdon")
    alg = kingdon.Algebra(3)
    check_products(random(left), random(right), alg, blade, 8)


def test_sandwiches_and_reverse_are_kingdons():
    kingdon = pytest.importorskip("kingdon")
    alg = kingdon.Algebra(3)
    r = random(vga.Rotor)
    kr = to_kingdon(r, alg, blade)
    for cls in (vga.Vector, vga.Bivector, vga.Pseudoscalar):
        x = random(cls)
        got = r.sandwich(x)
        want = from_kingdon(kr * to_kingdon(x, alg, blade) * ~kr, type(got), alg, blade, 8)
        assert np.allclose(got.array, want, rtol=1e-12, atol=1e-12), cls.__name__
    assert np.allclose((~r).array, from_kingdon(~kr, vga.Rotor, alg, blade, 8), atol=0)


def test_rotations_are_rodrigues():
    axis, angle = RNG.normal(size=(50, 3)), RNG.uniform(-3, 3, size=50)
    x = RNG.normal(size=(50, 3))
    turned = vga.xyz(vga.rotor(axis, angle).sandwich(vga.vector(x)))
    n = axis / np.linalg.norm(axis, axis=1)[:, None]
    c, s = np.cos(angle)[:, None], np.sin(angle)[:, None]
    want = x * c + np.cross(n, x) * s + n * np.sum(n * x, axis=1)[:, None] * (1 - c)
    assert np.allclose(turned, want, rtol=1e-13, atol=1e-14)
    # a * b = a · b + a ∧ b, and a vector squares to its length².
    a, b = vga.vector(x[0]), vga.vector(x[1])
    assert np.isclose(float((a * a).array[0]), float(x[0] @ x[0]), rtol=1e-15)
    assert np.allclose((a * b).array, (vga.Rotor(np.r_[(a | b).array, (a ^ b).array])).array, atol=1e-15)


def test_arrays_are_row_for_row_and_bad_input_is_refused():
    r, v = random(vga.Rotor, 9), random(vga.Vector, 9)
    moved = r.sandwich(v)
    for i in range(9):
        assert np.array_equal(moved[i].array, r[i].sandwich(v[i]).array)
    assert vga.Rotor.__module__ == "cga.vga"
    assert len(vga.Multivector.blades) == 8 and len(set(vga.Multivector.blades)) == 8
    with pytest.raises(TypeError, match="two algebras"):
        cga.up([1.0, 2, 3]) ^ vga.vector([1.0, 2.0, 3.0])
    with pytest.raises(TypeError, match="two algebras"):
        cga.cga2.point([1.0, 2.0]) * vga.vector([1.0, 2.0, 3.0])
    with pytest.raises(cga.GeometryError):
        vga.rotor([0.0, 0.0, 0.0], 1.0)
    with pytest.raises(cga.ShapeError):
        vga.vector([1.0, 2.0])
    with pytest.raises(cga.ValueError):
        vga.Vector([1.0, np.nan, 0.0])
    assert repr(vga.vector([1.0, 0, 2.0])) == "Vector(e1=1, e3=2)"
