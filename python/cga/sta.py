"""Spacetime algebra G(1,3) on numpy arrays: cga-algebras' ``sta`` (``e0² = +1``,
``e1² = e2² = e3² = −1``; blades named by their labels in ascending order, ``e01``, ``e123``).

The classes are cga's, on this algebra: one value or an array of n (``Vector(a)``, ``a`` of
shape (n, 4), in the order of ``Vector.blades``), the operators ``*`` ``^`` ``|`` ``&`` ``~``
running the generated Rust code on every row; ``Multivector`` holds any value::

    >>> from cga import sta
    >>> t, x = sta.Vector([1.0, 0, 0, 0]), sta.Vector([0, 1.0, 0, 0])
    >>> type(t ^ x).__name__, float((t * t).array[0]), float((x * x).array[0])
    ('Bivector', 1.0, -1.0)
    >>> u = sta.boost([1, 0, 0], 0.5).sandwich(t)  # γ0 moving along +x at tanh 0.5
    >>> [round(float(c), 12) + 0.0 for c in sta.velocity(u)]
    [0.46211715726, 0.0, 0.0]
"""

import numpy as np

from . import _cga

_sta = _cga.sta
Scalar = _sta.Scalar
Vector = _sta.Vector
Bivector = _sta.Bivector
Trivector = _sta.Trivector
Pseudoscalar = _sta.Pseudoscalar
Rotor = _sta.Rotor
Multivector = _sta.Multivector

__all__ = ["Bivector", "Multivector", "Pseudoscalar", "Rotor", "Scalar", "Trivector", "Vector", "boost", "field", "fields",
           "four_velocity", "rotation", "velocity"]

_tk = _cga.sta_toolkit


def boost(direction, rapidity):
    """Rotors boosting by ``rapidity`` along ``direction`` (normalised): ``cosh(φ/2) − sinh(φ/2)
    n̂ · (e01, e02, e03)``, taking ``γ0`` to velocity ``tanh φ`` along ``+n̂``. Rust:
    ``sta::Rotor::boost``."""
    return Rotor(_tk.boost(direction, rapidity))


def rotation(axis, angle):
    """Rotors turning by ``angle`` (right-handed) about ``axis``: ``cos(θ/2) + sin(θ/2) a · (e23,
    e31, e12)`` (``γₖ² = −1`` flips G(3)'s sign). Rust: ``sta::Rotor::rotation``."""
    return Rotor(_tk.rotation(axis, angle))


def four_velocity(v):
    """Four-velocities ``γ(1, v)`` of 3-velocities ``|v| < 1`` (``c = 1``). Rust:
    ``sta::Vector::from_velocity``."""
    return Vector(_tk.four_velocity(v))


def velocity(u):
    """3-velocities ``(x, y, z) / t`` of future-pointing timelike vectors. Rust:
    ``sta::Vector::velocity``."""
    return np.asarray(_tk.velocity(u.array))


def field(e, b):
    """Fields ``F = E + I B`` on ``σₖ = γₖ γ0``. Rust: ``sta::Bivector::from_fields``."""
    return Bivector(_tk.field(e, b))


def fields(f):
    """``(E, B)`` of fields: ``Eₖ = ⟨F σₖ⟩₀``, ``Bₖ = −⟨F I σₖ⟩₀``. Rust:
    ``sta::Bivector::fields``."""
    out = np.asarray(_tk.fields(f.array))
    return out[..., :3], out[..., 3:]
