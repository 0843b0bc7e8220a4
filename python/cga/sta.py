"""Spacetime algebra G(1,3) on numpy arrays: cga-algebras' ``sta`` (``e0² = +1``,
``e1² = e2² = e3² = −1``; blades named by their labels in ascending order, ``e01``, ``e123``).

The classes are cga's, on this algebra: one value or an array of n (``Vector(a)``, ``a`` of
shape (n, 4), in the order of ``Vector.blades``), the operators ``*`` ``^`` ``|`` ``&`` ``~``
running the generated Rust code on every row; ``Multivector`` holds any value::

    >>> from cga import sta
    >>> t, x = sta.Vector([1.0, 0, 0, 0]), sta.Vector([0, 1.0, 0, 0])
    >>> type(t ^ x).__name__, float((t * t).array[0]), float((x * x).array[0])
    ('Bivector', 1.0, -1.0)
"""

from . import _cga

_sta = _cga.sta
Scalar = _sta.Scalar
Vector = _sta.Vector
Bivector = _sta.Bivector
Trivector = _sta.Trivector
Pseudoscalar = _sta.Pseudoscalar
Rotor = _sta.Rotor
Multivector = _sta.Multivector

__all__ = ["Bivector", "Multivector", "Pseudoscalar", "Rotor", "Scalar", "Trivector", "Vector"]
