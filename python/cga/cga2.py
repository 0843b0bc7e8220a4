"""2D conformal geometric algebra G(3,1) on numpy arrays: cga-algebras' ``cga2``, the plane's
version of cga's own algebra (``e1² = e2² = 1``; the null vectors ``eo`` and ``ei`` with
``eo · ei = −1``, in which the blades are named: ``e1i``, ``e12o``, …).

- A point ``(x, y)`` is ``x e1 + y e2 + ½(x² + y²) ei + eo`` (:func:`point`; back by
  :func:`position`); two points' inner product is ``−½`` their squared distance.
- ``P ^ Q`` is a point pair, ``P ^ Q ^ R`` the circle through three points, ``P ^ Q ^ ei``
  the line through two (:data:`ei`).
- A motor ``[s, e12, e1i, e2i]`` moves anything by ``M.sandwich(X)`` (``M X M̃``);
  :func:`translator` and :func:`rotor` make them.

The classes are cga's, on this algebra: one value or an array of n, the operators ``*`` ``^``
``|`` ``&`` ``~`` running the generated Rust code on every row::

    >>> from cga import cga2
    >>> moved = cga2.translator([1.0, 2.0]).sandwich(cga2.point([0.5, 0.0]))
    >>> [float(c) for c in cga2.position(moved)]
    [1.5, 2.0]
    >>> type(cga2.point([0, 0]) ^ cga2.point([1, 0]) ^ cga2.point([0, 1])).__name__
    'Circle'
    >>> centre, radius = cga2.centre_radius(cga2.circle_through([1, 0], [0, 1], [-1, 0]))
    >>> [round(float(c), 12) + 0.0 for c in centre], round(float(radius), 12)
    ([0.0, 0.0], 1.0)
"""

import numpy as np

from . import _cga
from ._cga import GeometryError
from .pga import _of, _rows

_cga2 = _cga.cga2
_tk = _cga.cga2_toolkit
Scalar = _cga2.Scalar
Vector = _cga2.Vector
PointPair = _cga2.PointPair
Circle = _cga2.Circle
Pseudoscalar = _cga2.Pseudoscalar
Rotor = _cga2.Rotor
Motor = _cga2.Motor
Even = _cga2.Even
#: Any value: the results of mixed grades, the 16 blades in storage order.
Multivector = _cga2.Multivector

__all__ = ["Circle", "Even", "Motor", "Multivector", "PointPair", "Pseudoscalar", "Rotor", "Scalar", "Vector",
           "centre_radius", "circle_through", "ei", "ends", "eo", "line_through", "point", "position", "rotor",
           "translator"]

#: The point at infinity ``ei = e3 + e4`` and the origin ``eo = ½(e4 − e3)``.
ei = _of(Vector, {"ei": 1.0}, ())
eo = _of(Vector, {"eo": 1.0}, ())


def point(x):
    """Points ``(x, y)``, ``x e1 + y e2 + ½(x² + y²) ei + eo``: shape (2,) gives one, (n, 2) an
    array."""
    x = _rows(x, 2, "point")
    half = 0.5 * np.sum(x * x, axis=-1)
    return _of(Vector, {"e1": x[..., 0], "e2": x[..., 1], "ei": half, "eo": 1.0}, x.shape[:-1])


def position(p):
    """The Euclidean positions ``(e1, e2) / w`` of points (shape (2,) or (n, 2)), ``w = −p · ei``
    their weight, the ``eo`` coefficient. A vector of weight 0 (``ei`` itself, a dual line) is
    no point: ``GeometryError``."""
    c = dict(zip(Vector.blades, np.moveaxis(p.array, -1, 0)))
    w = c["eo"]
    if np.any(w == 0):
        raise GeometryError("a vector of weight 0 (no eo: a point at infinity or a dual line) has no position")
    return np.stack([c["e1"] / w, c["e2"] / w], axis=-1)


def translator(t):
    """Motors that move by ``t`` (shape (2,) or (n, 2)): ``1 − ½ t ei``."""
    t = _rows(t, 2, "translator")
    half = -0.5 * t
    return _of(Motor, {"s": 1.0, "e1i": half[..., 0], "e2i": half[..., 1]}, t.shape[:-1])


def rotor(angle):
    """Motors that turn by ``angle`` (radians, counter-clockwise) about the origin:
    ``exp(−½θ e12) = cos(θ/2) − sin(θ/2) e12`` (a number or an array of n)."""
    half = 0.5 * np.asarray(angle, dtype=float)
    if half.ndim > 1:
        raise _cga.ShapeError(f"rotor: shape {half.shape}; give a number or an array of shape (n,)")
    return _of(Motor, {"s": np.cos(half), "e12": -np.sin(half)}, half.shape)


def circle_through(a, b, c):
    """Circles through three points (shape (2,) or (n, 2) each), ``A ∧ B ∧ C``; coincident or
    collinear points are refused (``GeometryError``: use :func:`line_through`). Rust:
    ``cga2::Circle::through``."""
    return Circle(_tk.circle_through(a, b, c))


def line_through(p, q):
    """Lines through two points, ``P ∧ Q ∧ ei``, directed from ``p`` to ``q``. Rust:
    ``cga2::Circle::line_through``."""
    return Circle(_tk.line_through(p, q))


def centre_radius(circle):
    """Centres (shape (2,) or (n, 2)) and radii of circles, from their duals; a line or an
    imaginary circle is refused. Rust: ``cga2::Circle::centre_radius``."""
    out = np.asarray(_tk.centre_radius(circle.array))
    return out[..., :2], out[..., 2]


def ends(pair):
    """The two points of point pairs ``A ∧ B``, in order ``(a, b)``: shape (2, 2) or (n, 2, 2).
    Rust: ``cga2::PointPair::ends``."""
    out = np.asarray(_tk.ends(pair.array))
    return out.reshape(out.shape[:-1] + (2, 2))
