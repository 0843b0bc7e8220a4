"""3D projective geometric algebra G(3,0,1) on numpy arrays: cga-algebras' ``pga``, in
bivector.net's and kingdon's conventions (``e0² = 0``, ``e1² = e2² = e3² = 1``).

- A plane ``a x + b y + c z + d = 0`` is ``a e1 + b e2 + c e3 + d e0`` (:func:`plane`).
- A point ``(x, y, z)`` is ``e123 + x e032 + y e013 + z e021`` (:func:`point`; back by
  :func:`position`).
- A line is ``P & Q`` (the join) of two points, ``p ^ q`` (the meet) of two planes.
- A motor ``[s, e01, e02, e03, e12, e31, e23, e0123]`` moves anything by ``M.sandwich(X)``
  (``M X M̃``); :func:`translator`, :func:`rotor` and :func:`screw` make them; :func:`log`,
  :func:`exp`, :func:`sqrt`, :func:`interpolate` and :func:`normalise` are closed forms, screws
  included, run by cga-algebras' Rust on every row (``docs/PGA.md``: klein's and kingdon's
  spellings beside each).

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
    >>> axis = pga.line_through([1, 0, 0], [1, 0, 1])
    >>> half = pga.sqrt(pga.screw(axis, np.pi, 2.0))  # a quarter turn, 1 along +z
    >>> [round(float(c), 12) + 0.0 for c in pga.position(half.sandwich(pga.point([0, 0, 0])))]
    [1.0, -1.0, 1.0]
"""

import numpy as np

from . import _cga
from ._cga import GeometryError, ShapeError

_pga = _cga.pga
_tk = _cga.pga_toolkit
Scalar = _pga.Scalar
Plane = _pga.Plane
Line = _pga.Line
Point = _pga.Point
Pseudoscalar = _pga.Pseudoscalar
Motor = _pga.Motor
#: Any value: the results of mixed grades (a plane times a line), the 16 blades in storage order.
Multivector = _pga.Multivector

__all__ = ["Line", "Motor", "Multivector", "Plane", "Point", "Pseudoscalar", "Scalar", "angle", "direction", "distance",
           "exp", "from_line_pitch", "from_rotor_translator", "interpolate", "line_through", "log", "moment", "normalise",
           "plane", "plane_from_normal_distance", "point", "position", "pow", "project", "rotor", "rotor_translation",
           "screw", "sqrt", "translator"]


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
    """Motors that move by ``+t`` (shape (3,) or (n, 3)): ``1 − ½ (t₁ e01 + t₂ e02 + t₃ e03)``
    (with points ``e123 + x e032 + …``, ``e01`` moves them along −x). klein:
    ``kln::translator(|t|, x, y, z)``. Rust: ``Motor::translator``."""
    return Motor(_tk.translator(t))


def rotor(axis, angle):
    """Motors that turn by ``angle`` (radians, right-handed) about the unit ``axis`` through the
    origin: ``cos(θ/2) − sin(θ/2)(a₁ e23 + a₂ e31 + a₃ e12)``. The axis is normalised; a zero
    axis is refused (``GeometryError``). klein: ``kln::rotor(θ, x, y, z)``. Rust:
    ``Motor::rotor``."""
    return Motor(_tk.rotor(axis, angle))


def screw(line, angle, distance):
    """Motors that turn by ``angle`` (right-handed about the line's direction) about ``line``
    and slide ``distance`` along it: ``exp((−θ + δ I) L̂ / 2)``. klein: ``kln::motor(θ, δ, l)``.
    Rust: ``Motor::screw``."""
    return Motor(_tk.screw(line.array, angle, distance))


def exp(line):
    """``exp(B)`` of bivectors (lines or screw generators, ``B ∧ B ≠ 0`` too), closed form:
    motors. klein: ``kln::exp``; kingdon: ``B.exp()`` (simple ``B`` only). Rust:
    ``Line::exp_motor``."""
    return Motor(_tk.exp(line.array))


def log(motor):
    """The principal logarithm of motors, screws included: ``Line`` values with ``exp(log(M)) =
    M``. klein: ``kln::log``. Rust: ``Motor::log``. A full turn (``−1``) is refused."""
    return Line(_tk.log(motor.array))


def sqrt(motor):
    """The square root of motors, half their screw: ``(1 + M) / ‖1 + M‖`` normalised as a motor.
    klein: ``kln::sqrt``; kingdon: ``M.sqrt()`` (the same for rotations and translations). Rust:
    ``Motor::sqrt``."""
    return Motor(_tk.sqrt(motor.array))


def normalise(motor):
    """Motors scaled to ``M M̃ = 1``, the Study condition (the ``e0123`` part) included. klein:
    ``m.normalize()``; kingdon: ``M.normalized()``. Rust: ``Motor::renormalise``."""
    return Motor(_tk.normalise(motor.array))


def interpolate(a, b, t):
    """The motors a fraction ``t`` of the way from ``a`` to ``b`` along the shorter screw that
    joins them, ``(b ã)ᵗ a`` (``t`` a number or an array of n). klein: ``kln::exp(t *
    kln::log(b * ~a)) * a``; kingdon: ``(B * ~A).sqrt() * A`` at ``t = ½``. Rust:
    ``Motor::interpolate``."""
    return Motor(_tk.interpolate(a.array, b.array, t))


def pow(motor, t):
    """``Mᵗ = exp(t log M)``: the motors a fraction ``t`` (a number or an array of n) of the way
    along their screws, ``pow(M, 0.5)`` the square root and ``pow(M, 2)`` ``M M``. klein:
    ``kln::exp(t * kln::log(m))``. Rust: ``Motor::pow``. A full turn (``−1``) is refused."""
    return Motor(_tk.pow(motor.array, t))


def from_line_pitch(line, angle, pitch):
    """The screws of ``pitch`` (distance slid per radian turned) turning by ``angle`` about
    ``line``: ``screw(line, angle, pitch · angle)``. klein: ``kln::motor(θ, pitch · θ, l)``.
    Rust: ``Motor::from_line_pitch``."""
    return Motor(_tk.from_line_pitch(line.array, angle, pitch))


def from_rotor_translator(rotor, translator):
    """The motors that apply ``rotor`` first, then ``translator``: the product ``T R``.
    klein: ``kln::motor`` of ``t * r``; kingdon: ``T * R``. Rust: ``Motor::from_rotor_translator``."""
    return translator * rotor


def rotor_translation(motor):
    """Motors split into their rotors and translations ``(R, t)``, ``t`` of shape (3,) or
    (n, 3): ``M = T(t) R`` for the motor made unit, what :func:`from_rotor_translator` would
    be given. A motor without rotation part is refused. Rust: ``Motor::rotor_translation``."""
    both = _tk.rotor_translation(motor.array)
    return Motor(both[..., :8]), both[..., 8:]


def _pair(what, kinds, a, b):
    """The kind ``kinds`` names for the classes of ``a`` and ``b`` (in either order), and their
    arrays in that kind's order."""
    key = (type(a).__name__, type(b).__name__)
    if key not in kinds and key[::-1] in kinds:
        a, b, key = b, a, key[::-1]
    if key not in kinds:
        raise TypeError(f"{what}: no {what} between {key[0]} and {key[1]}")
    return kinds[key], a.array, b.array


_ANGLES = {("Line", "Line"): "line_line", ("Line", "Plane"): "line_plane", ("Plane", "Plane"): "plane_plane"}


def angle(a, b):
    """Angles between lines (``[0, π]`` between their directions, ``atan2(|d₁ × d₂|, d₁ · d₂)``),
    planes (``[0, π]`` between their normals) and a line and a plane (``[0, π/2]``, zero for a
    line parallel to the plane; either order). klein and kingdon: ``acos`` of the unit values'
    inner product, up to its sign. Rust: ``Line::angle_to_line``, ``Line::angle_to_plane``,
    ``Plane::angle_to_plane``. An ideal line or plane is refused."""
    return _tk.angle(*_pair("angle", _ANGLES, a, b))


def line_through(p, q):
    """Lines through ``p`` and ``q`` (shape (3,) or (n, 3)), directed from ``p`` to ``q``: the
    join ``P & Q``. Coincident points are refused. Rust: ``Line::through``."""
    return Line(_tk.line_through(p, q))


def plane_from_normal_distance(n, d):
    """Planes ``n̂ · x = d`` (``n̂ = n / |n|``): ``n̂ · (e1, e2, e3) − d e0``. Rust:
    ``Plane::from_normal_distance``."""
    return Plane(_tk.plane_from_normal_distance(n, d))


def direction(line):
    """The directions ``(e23, e31, e12)`` of lines: ``q − p`` for ``P & Q``. Rust:
    ``Line::direction``."""
    c = dict(zip(Line.blades, np.moveaxis(line.array, -1, 0)))
    return np.stack([c["e23"], c["e31"], c["e12"]], axis=-1)


def moment(line):
    """The moments ``(e01, e02, e03)`` of lines about the origin: ``p × d``. Rust:
    ``Line::moment``."""
    c = dict(zip(Line.blades, np.moveaxis(line.array, -1, 0)))
    return np.stack([c["e01"], c["e02"], c["e03"]], axis=-1)


_DISTANCES = {("Point", "Point"): "point_point", ("Point", "Plane"): "point_plane", ("Point", "Line"): "point_line",
              ("Line", "Line"): "line_line"}


def distance(a, b):
    """Euclidean distances: point–point, point–plane (signed, positive on the normal's side),
    point–line, line–line (also with the arguments the other way round). Rust:
    ``Point::distance_to_point``, ``distance_to_plane``, ``distance_to_line``,
    ``Line::distance_to_line``."""
    return _tk.distance(*_pair("distance", _DISTANCES, a, b))


def project(x, onto):
    """Orthogonal projections, as klein's ``kln::project``: a point onto a plane or a line,
    ``(P · X) ∧ X``; a line onto a plane, ``(L · p) ∧ p``; a line or a plane onto a point, the
    one through it parallel, ``−(X · P) · P`` (keeping the orientation). Computed here from the
    bound products (arrays included), by the formulas of Rust's ``Point::project_onto_plane``,
    ``project_onto_line``, ``Line::project_onto_plane``, ``project_onto_point`` and
    ``Plane::project_onto_point``."""
    kinds = (type(x).__name__, type(onto).__name__)
    if kinds in (("Point", "Plane"), ("Point", "Line"), ("Line", "Plane")):
        return (x | onto) ^ onto
    if kinds in (("Line", "Point"), ("Plane", "Point")):
        return -((x | onto) | onto)
    raise TypeError(f"project: no projection of {kinds[0]} onto {kinds[1]}")
