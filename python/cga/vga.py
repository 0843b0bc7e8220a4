"""The 3D vector algebra G(3) on numpy arrays: cga-algebras' ``vga`` (``e1``, ``e2``, ``e3``
orthonormal, ``eᵢ² = +1``; blades named by their labels in ascending order, ``e12``, ``e123``),
clifford's ``Cl(3)`` and kingdon's ``Algebra(3)``.

- :func:`vector` makes vectors of Euclidean directions (shape (3,) or (n, 3)), :func:`xyz`
  reads them back.
- :func:`rotor` turns by an angle about an axis, ``cos(θ/2) − sin(θ/2) n I``;
  ``R.sandwich(x)`` is ``R x R̃``.

The classes are cga's, on this algebra: one value or an array of n, the operators ``*`` ``^``
``|`` ``&`` ``~`` running the generated Rust code on every row::

    >>> from cga import vga
    >>> turned = vga.rotor([0.0, 0.0, 1.0], 3.141592653589793 / 2).sandwich(vga.vector([1.0, 0.0, 0.0]))
    >>> [round(float(c), 12) + 0.0 for c in vga.xyz(turned)]
    [0.0, 1.0, 0.0]
    >>> type(vga.vector([1.0, 0, 0]) ^ vga.vector([0, 1.0, 0])).__name__
    'Bivector'
"""

import numpy as np

from . import _cga
from .pga import _of, _rows

_vga = _cga.vga
Scalar = _vga.Scalar
Vector = _vga.Vector
Bivector = _vga.Bivector
Pseudoscalar = _vga.Pseudoscalar
Rotor = _vga.Rotor
Odd = _vga.Odd
#: Any value: the results of mixed grades, the 8 blades in storage order.
Multivector = _vga.Multivector

__all__ = ["Bivector", "Multivector", "Odd", "Pseudoscalar", "Rotor", "Scalar", "Vector", "rotor", "vector", "xyz"]


def vector(x):
    """Vectors ``x e1 + y e2 + z e3``: shape (3,) gives one, (n, 3) an array."""
    x = _rows(x, 3, "vector")
    return _of(Vector, {"e1": x[..., 0], "e2": x[..., 1], "e3": x[..., 2]}, x.shape[:-1])


def xyz(v):
    """The components ``(e1, e2, e3)`` of vectors (shape (3,) or (n, 3))."""
    c = dict(zip(Vector.blades, np.moveaxis(v.array, -1, 0)))
    return np.stack([c["e1"], c["e2"], c["e3"]], axis=-1)


def rotor(axis, angle):
    """Rotors that turn by ``angle`` (radians, right-handed) about ``axis`` (normalised; shape
    (3,) or (n, 3), ``angle`` a number or an array of n): ``cos(θ/2) − sin(θ/2) n I``, with
    ``n I = n₁ e23 − n₂ e13 + n₃ e12``. A zero axis is refused (``GeometryError``)."""
    axis = _rows(axis, 3, "rotor")
    norm = np.linalg.norm(axis, axis=-1)
    if np.any(norm == 0):
        raise _cga.GeometryError("rotor: a zero axis has no direction")
    n = axis / norm[..., None]
    half = 0.5 * np.asarray(angle, dtype=float)
    if half.ndim > 1:
        raise _cga.ShapeError(f"rotor: angle of shape {half.shape}; give a number or an array of shape (n,)")
    shape = np.broadcast_shapes(n.shape[:-1], half.shape)
    s = np.sin(half)
    return _of(Rotor, {"s": np.cos(half), "e23": -s * n[..., 0], "e13": s * n[..., 1], "e12": -s * n[..., 2]}, shape)
