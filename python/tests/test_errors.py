"""Bad input is refused by name as a Python exception (a ValueError), never a crash and never
NaN passed off as a result."""

import numpy as np
import pytest

import cga


def test_the_exceptions_are_value_errors():
    for e in (cga.ValueError, cga.ShapeError, cga.GeometryError, cga.SceneError):
        assert issubclass(e, ValueError)


def test_wrong_shapes_are_refused_by_name():
    with pytest.raises(cga.ShapeError, match="Circle"):
        cga.Circle.from_array(np.zeros((4, 9)))
    with pytest.raises(cga.ShapeError, match="x"):
        cga.up([1.0, 2.0])
    with pytest.raises(cga.ShapeError):
        cga.Line.through(np.zeros((3, 3)), np.ones((4, 3)))


def test_nan_and_infinity_are_refused():
    with pytest.raises(cga.ValueError, match="finite"):
        cga.up([np.nan, 0, 0])
    with pytest.raises(cga.ValueError, match="finite"):
        cga.Sphere.from_array([np.inf] + [0.0] * 4)


def test_degenerate_geometry_is_refused_by_row():
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga.Sphere.from_centre_radius(np.zeros((3, 3)), np.array([1.0, 0.0, 2.0]))
    with pytest.raises(cga.GeometryError):
        cga.Circle.through([0, 0, 0.0], [1.0, 0, 0], [2.0, 0, 0])
    with pytest.raises(cga.GeometryError, match="normalise"):
        cga.Sphere.from_array(np.zeros(5)).normalise()


def test_products_the_algebra_lacks_and_foreign_operands():
    s = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    with pytest.raises(TypeError):
        s ^ s  # grade 8: identically zero, not generated
    with pytest.raises(TypeError):
        s * "a string"
    with pytest.raises(TypeError):
        s + cga.up([0, 0, 0.0])
