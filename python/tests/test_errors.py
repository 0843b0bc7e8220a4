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


def test_a_result_that_overflows_is_refused_by_row_never_passed_off():
    # Finite operands whose product overflows f64: on the lanes (vector ^ vector, the meet of
    # lines and a sphere), through the registry (circle * circle), in a chain (wedge) and on
    # the dense type of another algebra; the error names the operation and the first row.
    x, y = np.zeros((5, 5)), np.zeros((5, 5))
    x[:, 0], y[:, 1] = 1.0, 1.0
    x[3, 0], y[3, 1] = 1e200, 1e200
    with pytest.raises(cga.ValueError, match=r"Vector \^ Vector: value 3 of the result is not finite"):
        cga.Vector(x) ^ cga.Vector(y)
    lines = cga.Line(np.full((40_000, 6), 1e300))
    with pytest.raises(cga.ValueError, match=r"Line & Sphere: value 0 of the result is not finite"):
        lines & cga.Sphere.from_centre_radius([0.0, 0.0, 0.0], 1e10)
    c = cga.Circle(np.full(10, 1e200))
    with pytest.raises(cga.ValueError, match=r"Circle \* Circle: value 0 .* not finite"):
        c * c
    points = cga.up(np.full((3, 3), 1e110))
    with pytest.raises(cga.ValueError, match="wedge: value 0 of the result is not finite"):
        cga.wedge(points, points * 2.0, points * 3.0 + cga.up([0.0, 0.0, 0.0]) * 0.0)
    m = cga.pga.Multivector(np.full(16, 1e200))
    with pytest.raises(cga.ValueError, match=r"pga.Multivector \* pga.Multivector: value 0"):
        m * m
    # Within range the same products are answered.
    assert np.all(np.isfinite((cga.Circle(np.full(10, 1e100)) * cga.Circle(np.full(10, 1e100))).array))
