"""The classes against cga-core's own answers and Euclid: products give the Rust result types,
objects read back what built them, versors move points as stated."""

import math

import numpy as np
import pytest

import cga


def test_points_round_trip_and_square_to_zero():
    x = np.array([1.5, -2.0, 0.25])
    p = cga.up(x)
    assert type(p) is cga.Vector and p.single
    assert np.allclose(cga.down(p), x, rtol=0, atol=1e-15)
    # A conformal point is null: X·X = 0.
    assert abs(float((p | p).array[0])) < 1e-12


def test_products_have_the_rust_result_types():
    a, b, c = cga.up([1.0, 0, 0]), cga.up([0, 1.0, 0]), cga.up([-1.0, 0, 0])
    assert type(a ^ b) is cga.Bivector
    circle = a ^ b ^ c
    assert type(circle) is cga.Circle
    centre, normal, radius = circle.centre_normal_radius()
    assert np.allclose(centre, 0, atol=1e-12) and math.isclose(radius, 1.0, rel_tol=1e-12)
    line = cga.Line.through([0, 0, -3.0], [0, 0, 3.0])
    assert type(line * line) is cga.Motor
    sphere = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    assert type(line & sphere) is cga.Bivector  # the meet: a point pair


def test_reverse_and_dual_are_the_generated_maps():
    r = cga.Rotor.from_axis_angle([0, 0, 1.0], 0.7)
    assert np.allclose((r * ~r).array, [1, 0, 0, 0], atol=1e-15)
    s = cga.Sphere.from_centre_radius([1.0, 2.0, 3.0], 2.0)
    assert s.dual().undual() == s


def test_objects_read_back_what_built_them():
    s = cga.Sphere.from_centre_radius([1.0, -2.0, 0.5], 0.75)
    c, r = s.centre_radius()
    assert np.allclose(c, [1.0, -2.0, 0.5], atol=1e-14) and math.isclose(r, 0.75, rel_tol=1e-14)
    p = cga.Plane.from_point_normal([0, 0, 2.0], [0, 0, 3.0])
    n, d = p.normal_offset()
    assert np.allclose(n, [0, 0, 1]) and math.isclose(d, 2.0, rel_tol=1e-14)
    line = cga.Line.through([1.0, 1.0, 0], [1.0, 1.0, 5.0])
    assert np.allclose(line.point(), [1, 1, 0], atol=1e-14)
    assert np.allclose(np.cross(line.direction(), [0, 0, 1]), 0, atol=1e-14)


def test_a_motor_moves_points_by_its_sandwich():
    turn = cga.Rotor.from_axis_angle([0, 0, 1.0], math.pi / 2)
    m = cga.Motor.from_rotor_translation(turn, [2.0, 0, 0])
    assert np.allclose(m.move_point([1.0, 0, 0]), [2, 1, 0], atol=1e-15)
    moved = cga.down(m.sandwich(cga.up([1.0, 0, 0])))
    assert np.allclose(moved, [2, 1, 0], atol=1e-14)


def test_scalars_on_either_side_and_sums_within_a_type():
    s = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    assert (2.0 * s).array.tolist() == (s * 2.0).array.tolist() == (s + s).array.tolist()
    assert np.allclose((s / 2.0).array, 0.5 * s.array)
    assert np.allclose((s - s).array, 0)
    assert np.allclose((-s).array, -s.array)


def test_normalise_divides_by_the_norm():
    s = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0) * 3.0
    assert math.isclose(abs(s.normalise().norm_squared()), 1.0, rel_tol=1e-14)


def test_repr_reads_in_euclidean_terms():
    c = cga.Circle.from_centre_normal_radius([0, 0, 0.0], [0, 0, 1.0], 1.0)
    assert repr(c).startswith("circle centre")
