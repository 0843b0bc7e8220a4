"""3D projective geometric algebra G(3,0,1) on numpy arrays: cga-algebras' ``pga``, in
bivector.net's and kingdon's conventions (``e0² = 0``, ``e1² = e2² = e3² = 1``).

- A plane ``a x + b y + c z + d = 0`` is ``a e1 + b e2 + c e3 + d e0`` (:func:`plane`).
- A point ``(x, y, z)`` is ``e123 + x e032 + y e013 + z e021`` (:func:`point`; back by
  :func:`position`).
- A line is ``P & Q`` (the join) of two points, ``p ^ q`` (the meet) of two planes.
- A motor ``[s, e01, e02, e03, e12, e31, e23, e0123]`` moves anything by ``M.sandwich(X)``
  (``M X M̃``); :func:`translator` and :func:`rotor` make them.

The classes are cga's, on this algebra: one value or an array of n (``Point(a)``, ``a`` of
shape (n, 4), in the order of ``Point.blades``), the operators ``*`` ``^`` ``|`` ``&`` ``~``
running the generated Rust code on every row::

    >>> from cga import pga
    >>> line = pga.point([0, 0, 0]) & pga.point([1, 0, 0])
    >>> type(line).__name__
    'Line'
    >>> moved = pga.translator([0, 2, 0]).sandwich(pga.point([1, 0, 0]))
    >>> [float(c) for c in pga.position(moved)]
    [1.0, 2.0, 0.0]
"""

import numpy as np

from . import _cga
from ._cga import GeometryError, ShapeError

_pga = _cga.pga
Scalar = _pga.Scalar
Plane = _pga.Plane
Line = _pga.Line
Point = _pga.Point
Pseudoscalar = _pga.Pseudoscalar
Motor = _pga.Motor
#: Any value: the results of mixed grades (a plane times a line), the 16 blades in storage order.
Multivector = _pga.Multivector

__all__ = ["Line", "Motor", "Multivector", "Plane", "Point", "Pseudoscalar", "Scalar", "plane", "point", "position", "rotor",
           "translator"]


def _rows(x, width, name):
    x = np.asarray(x, dtype=float)
    if x.ndim not in (1, 2) or x.shape[-1] != width:
        raise ShapeError(f"{name}: shape {x.shape}; give ({width},) or (n, {width})")
    return x


def _of(cls, parts, shape):
    """A value of ``cls`` from its blades' coefficients by name (the others zero)."""
    columns = [np.broadcast_to(np.asarray(parts.get(b, 0.0), dtype=float), shape) for b in cls.blades]
    return cls(np.stack(columns, axis=-1))


def point(x):
    """Points ``(x, y, z)`` of weight 1, ``e123 + x e032 + y e013 + z e021``: shape (3,) gives
    one, (n, 3) an array."""
    x = _rows(x, 3, "point")
    return _of(Point, {"e123": 1.0, "e032": x[..., 0], "e013": x[..., 1], "e021": x[..., 2]}, x.shape[:-1])


def position(p):
    """The Euclidean positions ``(e032, e013, e021) / e123`` of points: shape (3,) or (n, 3).
    An ideal point (a direction, ``e123 = 0``) has none: ``GeometryError``."""
    c = dict(zip(Point.blades, np.moveaxis(p.array, -1, 0)))
    w = c["e123"]
    if np.any(w == 0):
        raise GeometryError("an ideal point (e123 = 0, a direction) has no position")
    return np.stack([c["e032"] / w, c["e013"] / w, c["e021"] / w], axis=-1)


def plane(a, b, c, d):
    """Planes ``a x + b y + c z + d = 0``: ``a e1 + b e2 + c e3 + d e0`` (numbers or arrays of n)."""
    a, b, c, d = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a, b, c, d)))
    if a.ndim > 1:
        raise ShapeError(f"plane: shape {a.shape}; give numbers or arrays of shape (n,)")
    return _of(Plane, {"e1": a, "e2": b, "e3": c, "e0": d}, a.shape)


def translator(t):
    """Motors that move by ``t`` (shape (3,) or (n, 3)): ``1 − ½ (t₁ e01 + t₂ e02 + t₃ e03)``
    (with points ``e123 + x e032 + …``, ``e01`` moves them along −x)."""
    t = _rows(t, 3, "translator")
    half = -0.5 * t
    parts = {"s": 1.0, "e01": half[..., 0], "e02": half[..., 1], "e03": half[..., 2]}
    return _of(Motor, parts, t.shape[:-1])


def rotor(axis, angle):
    """Motors that turn by ``angle`` (radians, right-handed) about the unit ``axis`` through the
    origin: ``cos(θ/2) − sin(θ/2)(a₁ e23 + a₂ e31 + a₃ e12)``. The axis is normalised; a zero
    axis is refused."""
    axis = _rows(axis, 3, "rotor")
    norm = np.linalg.norm(axis, axis=-1)
    if np.any(norm == 0):
        raise GeometryError("rotor: the axis is zero")
    a = axis / norm[..., None]
    half = 0.5 * np.asarray(angle, dtype=float)
    s = np.sin(half)
    parts = {"s": np.cos(half), "e23": -s * a[..., 0], "e31": -s * a[..., 1], "e12": -s * a[..., 2]}
    return _of(Motor, parts, np.broadcast_shapes(a.shape[:-1], np.shape(half)))
