"""A user's own algebra reaches Python: python/examples/quaternions declares G(0,2) with
``algebra!`` in its own crate and binds it with ``cga_python::python_algebra!`` (CI installs it
beside the package: ``pip install ./python/examples/quaternions``). Its classes run the
generated code with the package's arrays, operators and checks; the products are Hamilton's
(``i = e1``, ``j = e2``, ``k = e12``) and kingdon's ``Algebra(0, 2)``."""

import numpy as np
import pytest

import cga
import quaternions as q

RNG = np.random.default_rng(41)


def hamilton(a, b):
    """Hamilton's product of quaternions ``(w, x, y, z)`` row by row."""
    w1, x1, y1, z1 = np.moveaxis(a, -1, 0)
    w2, x2, y2, z2 = np.moveaxis(b, -1, 0)
    return np.stack([
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    ], axis=-1)


def test_the_units_obey_hamilton():
    i, j = q.Vector([1.0, 0.0]), q.Vector([0.0, 1.0])
    k = i ^ j
    assert type(k) is q.Bivector and list(k.array) == [1.0]
    for unit in (i, j, k):
        assert np.array_equal((unit * unit).array[0], -1.0)
    assert np.allclose((i * j * k).array, [-1.0, 0.0, 0.0, 0.0], atol=0)


def test_arrays_multiply_as_hamilton_row_for_row():
    a, b = RNG.normal(size=(1000, 4)), RNG.normal(size=(1000, 4))
    got = q.Quaternion(a) * q.Quaternion(b)
    assert type(got) is q.Quaternion and got.array.shape == (1000, 4)
    assert np.allclose(got.array, hamilton(a, b), rtol=1e-14, atol=1e-14)
    one = q.Quaternion(a[3])
    assert np.array_equal((one * q.Quaternion(b)).array[7], (one * q.Quaternion(b[7])).array)
    # Clifford's conjugate is the quaternion's, and q q̄ = |q|².
    assert np.array_equal(one.conjugate().array, a[3] * [1, -1, -1, -1])
    assert np.allclose((one * one.conjugate()).array, [a[3] @ a[3], 0, 0, 0], rtol=1e-15, atol=1e-15)


def test_products_are_kingdons():
    kingdon = pytest.importorskip("kingdon")
    alg = kingdon.Algebra(0, 2)
    e = alg.blades
    basis = {"s": alg.multivector({"e": 1.0}), "e1": e.e1, "e2": e.e2, "e12": e.e12}

    def to_k(v):
        return sum((float(c) * basis[n] for n, c in zip(type(v).blades, v.array)), alg.multivector({"e": 0.0}))

    def coefficients(mv, blades):
        d = dict(zip(mv.keys(), (float(x) for x in mv.values())))
        keys = {"s": 0, "e1": 1, "e2": 2, "e12": 3}
        return np.array([d.get(keys[b], 0.0) for b in blades])

    classes = [q.Scalar, q.Vector, q.Bivector, q.Quaternion, q.Multivector]
    for left in classes:
        for right in classes:
            a, b = left(RNG.normal(size=len(left.blades))), right(RNG.normal(size=len(right.blades)))
            for op in (lambda x, y: x * y, lambda x, y: x ^ y):
                try:
                    got = op(a, b)
                except TypeError as err:
                    assert "identically zero" in str(err)
                    continue
                want = coefficients(op(to_k(a), to_k(b)), type(got).blades)
                assert np.allclose(got.array, want, rtol=1e-13, atol=1e-13), (left.__name__, right.__name__)


def test_bad_input_is_refused_and_algebras_do_not_mix():
    with pytest.raises(cga.ValueError):
        q.Quaternion([1.0, np.nan, 0.0, 0.0])
    with pytest.raises(cga.ShapeError):
        q.Quaternion(np.zeros((3, 5)))
    with pytest.raises(TypeError):
        cga.up([1.0, 2.0, 3.0]) * q.Vector([1.0, 0.0])
    assert q.Quaternion.__module__ == "quaternions"
    assert repr(q.Quaternion([1.0, 0.0, 2.0, 0.0])) == "Quaternion(s=1, e2=2)"
