"""Values of cga's smaller algebras against kingdon's: each blade built in kingdon as the outer
product of its labels' vectors, and kingdon's answers read back in a class's blades. Each
test module gives ``blade(name, alg)`` for its algebra's labels."""

from functools import reduce

import numpy as np


def dense(mv, width):
    """kingdon's value as ``width`` coefficients over its own basis (binary keys)."""
    out = np.zeros(width)
    for k, c in zip(mv.keys(), mv.values()):
        out[k] = float(c)
    return out


def to_kingdon(value, alg, blade):
    return reduce(lambda a, b: a + b, (float(c) * blade(name, alg) for name, c in zip(type(value).blades, value.array)))


def from_kingdon(mv, cls, alg, blade, width):
    """The coefficients of ``cls``'s blades giving kingdon's value (which must lie in their span)."""
    basis = np.stack([dense(blade(name, alg), width) for name in cls.blades], axis=1)
    want = dense(mv, width)
    c, *_ = np.linalg.lstsq(basis, want, rcond=None)
    assert np.allclose(basis @ c, want, atol=1e-12), (cls.__name__, want)
    return c


# `|` is left out: kingdon's inner product keeps scalars, ours (Hestenes') does not.
OPS = [("*", lambda a, b: a * b), ("^", lambda a, b: a ^ b), ("&", lambda a, b: a & b)]


def check_products(a, b, alg, blade, width):
    """``a * b``, ``a ^ b`` and ``a & b`` against kingdon's, to 1e-12."""
    for symbol, op in OPS:
        expected = op(to_kingdon(a, alg, blade), to_kingdon(b, alg, blade))
        try:
            got = op(a, b)
        except TypeError as e:
            # Not generated: identically zero in the algebra, so kingdon's is zero too.
            assert "identically zero" in str(e)
            assert np.allclose(dense(expected, width), 0.0, atol=1e-12), (symbol, expected)
            continue
        want = from_kingdon(expected, type(got), alg, blade, width)
        assert np.allclose(got.array, want, rtol=1e-12, atol=1e-12), (type(a).__name__, symbol, type(b).__name__)


# By blade name, for the algebras whose blades are spelled out of ascending order (PGA's
# `e31`, `e021`): each name is kingdon's ascending blade times a sign.


def canonical(name):
    """A blade spelled as pga spells it (``e31``, ``e021``) as kingdon's ascending name and the
    sign between them (a swap of two labels flips it)."""
    if name == "s":
        return "e", 1.0
    labels = list(name[1:])
    sign = 1.0
    for i in range(len(labels)):
        for j in range(len(labels) - 1 - i):
            if labels[j] > labels[j + 1]:
                labels[j], labels[j + 1] = labels[j + 1], labels[j]
                sign = -sign
    return "e" + "".join(labels), sign


def named_to_kingdon(value, alg):
    """One value as kingdon's multivector, blade by name."""
    parts = {}
    for name, c in zip(type(value).blades, value.array):
        key, sign = canonical(name)
        parts[key] = sign * float(c)
    return alg.multivector(parts)


def named_from_kingdon(mv, cls):
    """The coefficients of ``cls``'s blades in kingdon's value (any other blade must be zero)."""
    have = {mv.algebra.bin2canon[k]: float(v) for k, v in zip(mv.keys(), mv.values())}
    out = []
    for name in cls.blades:
        key, sign = canonical(name)
        out.append(sign * have.pop(key, 0.0))
    assert all(abs(v) < 1e-12 for v in have.values()), have
    return np.array(out)
