"""The exceptions of ``cga``, every one a ``ValueError`` (a bad value, never a crash), named by
what went wrong, with the Rust error's words. Defined here, in Python, so that every extension
built on the package (``cga._cga``, and a user's algebra bound with ``python_algebra!``) raises
the same classes."""

import builtins


class ValueError(builtins.ValueError):
    """A value the operation cannot take (a base of every cga error)."""

    __module__ = "cga"


class ShapeError(ValueError):
    """An array of the wrong shape, or two arrays of different lengths."""

    __module__ = "cga"


class GeometryError(ValueError):
    """Geometry that makes no object: a zero radius, collinear points, a null blade."""

    __module__ = "cga"


class SceneError(ValueError):
    """A scene file or a picture's options that cannot be rendered."""

    __module__ = "cga"
