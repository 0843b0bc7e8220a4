"""Conformal geometric algebra G(4,1) from Rust: typed objects on numpy arrays, and a ray
tracer of CGA scenes.

Every class holds one value or an array of them (``Circle.from_array(a)`` with ``a`` of
shape ``(n, 10)``); the operators ``*`` (geometric), ``^`` (outer), ``|`` (inner), ``&``
(regressive, the meet) and ``~`` (reverse) run the generated Rust code on every row, and the
result's class is the Rust result's type (``cga.wedge(a, b, c)`` is ``a ^ b ^ c`` taken a block of
rows at a time, with the same numbers)::

    >>> import cga
    >>> a, b, c = cga.up([1.0, 0, 0]), cga.up([0, 1.0, 0]), cga.up([-1.0, 0, 0])
    >>> circle = a ^ b ^ c
    >>> type(circle).__name__
    'Circle'
    >>> round(float(circle.centre_normal_radius()[2]), 12)
    1.0

``cga.draw([sphere, circle, line])`` draws objects as what they are (a notebook shows any
object, and any rendered ``Picture``, as a picture), and ``cga.Scene`` renders scenes, read
from files or built in code (:mod:`cga.scene`), to numpy arrays.

``cga.pga`` is 3D projective geometric algebra G(3,0,1), ``cga.sta`` spacetime algebra G(1,3),
``cga.cga2`` the plane's conformal algebra G(3,1) and ``cga.vga`` the 3D vector algebra G(3),
with the same classes and operators (:mod:`cga.pga`, :mod:`cga.sta`, :mod:`cga.cga2`,
:mod:`cga.vga`). ``cga.random`` draws random objects of every class (:mod:`cga.random`); ``cga.fit_sphere``,
``fit_circle``, ``fit_plane`` and ``fit_line`` fit objects to points by least squares
(``fit_sphere_with_error`` … give a ``Fit`` with the points' distances from it), and
``cga.average_objects`` averages objects of one class. ``Rotor.between_frames``,
``Motor.between_frames``, ``Motor.between_circles``, ``Motor.between_spheres`` and
``X.versor_to(Y)`` give the versors between frames and between objects
(``cga.rotor_between_objects`` and ``cga.motor_between_rounds`` as clifford.tools.g3c names
them).

``cga.to_clifford``, ``cga.from_clifford``, ``cga.to_kingdon`` and ``cga.from_kingdon``
convert values and arrays to and from those libraries' multivectors (:mod:`cga.interop`).

Errors are ``cga.ValueError`` (a ``ValueError``) and its kinds ``ShapeError``,
``GeometryError`` and ``SceneError``, with the Rust error's words.
"""

from ._cga import (
    Bivector,
    Circle,
    Dilator,
    Even,
    Fit,
    FlatPoint,
    Generator,
    GeometryError,
    Infinity,
    Line,
    Motor,
    Odd,
    Picture,
    Plane,
    Pseudoscalar,
    Rotor,
    Scalar,
    ScalarQuadvector,
    SceneError,
    ShapeError,
    Sphere,
    Translator,
    Transversor,
    ValueError,
    Vector,
    __version__,
    down,
    draw,
    up,
    wedge,
)

from .scene import Scene

#: A conformal point is a ``Vector``; a point pair a ``Bivector`` (cga-core's aliases).
Point = Vector
PointPair = Bivector

#: Objects fitted to points by least squares, as clifford.tools.g3c names them: points of
#: shape (n, 3) or a ``Vector`` of them give one object, (m, n, 3) give m.
fit_sphere = Sphere.fit
fit_circle = Circle.fit
fit_plane = Plane.fit
fit_line = Line.fit

#: The same fits with their stated error: a ``Fit`` (``object, rms, max, sigma``).
fit_sphere_with_error = Sphere.fit_with_error
fit_circle_with_error = Circle.fit_with_error
fit_plane_with_error = Plane.fit_with_error
fit_line_with_error = Line.fit_with_error


def rotor_between_objects(x1, x2):
    """The even versor taking object ``x1`` to ``x2`` (clifford.tools.g3c's name for
    ``x1.versor_to(x2)``; circles, spheres, point pairs, lines or planes, or arrays of them)."""
    return x1.versor_to(x2)


def motor_between_rounds(x1, x2):
    """The rigid motion lining up two circles (centre and normal) or two spheres (centre),
    clifford.tools.g3c's name for ``Motor.between_circles`` / ``Motor.between_spheres``."""
    if isinstance(x1, Circle) and isinstance(x2, Circle):
        return Motor.between_circles(x1, x2)
    if isinstance(x1, Sphere) and isinstance(x2, Sphere):
        return Motor.between_spheres(x1, x2)
    raise TypeError(f"motor_between_rounds: two Circles or two Spheres, not {type(x1).__name__} "
                    f"and {type(x2).__name__}")


def average_objects(objects):
    """The average of an array of circles, spheres, planes, lines or point pairs, as one object
    (clifford.tools.g3c's name for ``objects.average()``: each normalised and oriented like the
    first, summed, and projected back onto the blades)."""
    return objects.average()

__all__ = [
    "Bivector", "Circle", "Dilator", "Even", "Fit", "FlatPoint", "Generator", "GeometryError", "Infinity",
    "Line", "Motor", "Odd", "Picture", "Plane", "Point", "PointPair", "Pseudoscalar", "Rotor",
    "Scalar", "ScalarQuadvector", "Scene", "SceneError", "ShapeError", "Sphere", "Translator",
    "Transversor", "ValueError", "Vector", "__version__", "average_objects", "down", "draw", "fit_circle",
    "fit_circle_with_error", "fit_line", "fit_line_with_error", "fit_plane", "fit_plane_with_error", "fit_sphere",
    "fit_sphere_with_error", "from_clifford", "from_kingdon", "motor_between_rounds", "rotor_between_objects",
    "cga2", "interop", "pga", "random", "sta", "to_clifford", "to_kingdon", "up", "vga", "wedge",
]


_INTEROP = ("interop", "from_clifford", "from_kingdon", "to_clifford", "to_kingdon")


def __getattr__(name):
    # cga.interop and cga.random need numpy, whose import takes longer than the rest of ours:
    # on first use.
    import importlib

    if name in _INTEROP:
        interop = importlib.import_module(".interop", __name__)
        return interop if name == "interop" else getattr(interop, name)
    if name in ("random", "pga", "sta", "cga2", "vga"):
        return importlib.import_module("." + name, __name__)
    raise AttributeError(f"module 'cga' has no attribute {name!r}")
