"""Random objects, for tests, examples and benchmarks: each function draws ``n`` objects of one
class as an array value (one value where ``n`` is ``None``), every one a proper object of
its kind, from ``seed`` (an ``int``, ``None`` for fresh entropy, or a
``numpy.random.Generator``, which the draw advances).

Positions are normal with standard deviation ``scale`` about the origin; sizes (radii) are
uniform in ``[0.1, 1] · scale``; directions, normals and axes uniform on the unit sphere;
angles uniform in ``(−π, π]``::

    >>> import cga.random
    >>> s = cga.random.spheres(1000, seed=1)
    >>> len(s), type(s).__name__
    (1000, 'Sphere')
    >>> bool((s.centre_radius()[1] >= 0.1).all())
    True
"""

import math

import numpy as np

from . import _cga

__all__ = ["points", "vectors", "spheres", "planes", "lines", "circles", "point_pairs", "rotors",
           "translators", "motors"]


def _rng(seed):
    return seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)


def _rows(n):
    if n is None:
        return 1
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise _cga.ValueError(f"n: expected a count ≥ 1 (or None for one value), not {n!r}")
    return int(n)


def _one(n, x):
    """``x`` (n rows) as one value where ``n`` is None."""
    return x[0] if n is None else x


def _positions(rng, m, scale):
    return rng.normal(0.0, scale, size=(m, 3))


def _units(rng, m):
    """``m`` directions uniform on the unit sphere (normal draws normalised; a draw too short to
    normalise, of probability about 1e-300, is drawn again)."""
    out = np.empty((m, 3))
    todo = np.arange(m)
    while todo.size:
        d = rng.normal(size=(todo.size, 3))
        norm = np.linalg.norm(d, axis=1)
        good = norm > 1e-12
        out[todo[good]] = d[good] / norm[good, None]
        todo = todo[~good]
    return out


def _sizes(rng, m, scale):
    return rng.uniform(0.1, 1.0, size=m) * scale


def points(n=None, seed=None, scale=1.0):
    """Euclidean points, a numpy array of shape ``(n, 3)`` (``(3,)`` for one)."""
    m = _rows(n)
    x = _positions(_rng(seed), m, scale)
    return x[0] if n is None else x


def vectors(n=None, seed=None, scale=1.0):
    """Conformal points ``up(x)`` (a ``Vector``)."""
    return _cga.up(points(n, seed, scale))


def spheres(n=None, seed=None, scale=1.0):
    """Spheres (``Sphere``): centre and radius."""
    rng, m = _rng(seed), _rows(n)
    return _one(n, _cga.Sphere.from_centre_radius(_positions(rng, m, scale), _sizes(rng, m, scale)))


def planes(n=None, seed=None, scale=1.0):
    """Planes (``Plane``): a unit normal and a point, its distance from the origin normal."""
    rng, m = _rng(seed), _rows(n)
    return _one(n, _cga.Plane.from_point_normal(_positions(rng, m, scale), _units(rng, m)))


def lines(n=None, seed=None, scale=1.0):
    """Lines (``Line``): a point and a unit direction."""
    rng, m = _rng(seed), _rows(n)
    return _one(n, _cga.Line.from_point_direction(_positions(rng, m, scale), _units(rng, m)))


def circles(n=None, seed=None, scale=1.0):
    """Circles (``Circle``): centre, unit normal and radius."""
    rng, m = _rng(seed), _rows(n)
    centres, normals, radii = _positions(rng, m, scale), _units(rng, m), _sizes(rng, m, scale)
    return _one(n, _cga.Circle.from_centre_normal_radius(centres, normals, radii))


def point_pairs(n=None, seed=None, scale=1.0):
    """Point pairs ``up(a) ∧ up(b)`` (a ``Bivector``): a centre, and its two points a radius
    apart along a unit direction on either side."""
    rng, m = _rng(seed), _rows(n)
    c, d, r = _positions(rng, m, scale), _units(rng, m), _sizes(rng, m, scale)
    return _one(n, _cga.up(c + r[:, None] * d) ^ _cga.up(c - r[:, None] * d))


def rotors(n=None, seed=None):
    """Rotors (``Rotor``): a unit axis and an angle in ``(−π, π]``."""
    rng, m = _rng(seed), _rows(n)
    axes, angles = _units(rng, m), math.pi - rng.uniform(0.0, 2.0 * math.pi, size=m)
    return _one(n, _cga.Rotor.from_axis_angle(axes, angles))


def translators(n=None, seed=None, scale=1.0):
    """Translators (``Translator``) by normal vectors."""
    rng, m = _rng(seed), _rows(n)
    return _one(n, _cga.Translator.from_vector(_positions(rng, m, scale)))


def motors(n=None, seed=None, scale=1.0):
    """Rigid motions ``T R`` (a ``Motor``): a rotor as :func:`rotors`, then a translation as
    :func:`translators`."""
    rng = _rng(seed)
    m = _rows(n)
    return _one(n, _cga.Motor.from_rotor_translation(rotors(m, rng), _positions(rng, m, scale)))
