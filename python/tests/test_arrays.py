"""Arrays of values: every operator and constructor on N rows gives, row by row, the bits of
one value at a time, and broadcasts one value against many."""

import numpy as np
import pytest

import cga

RNG = np.random.default_rng(7)


def points(n):
    return RNG.normal(size=(n, 3))


def test_array_products_are_one_at_a_time_bit_for_bit():
    a, b, c = points(50), points(50), points(50)
    circles = cga.up(a) ^ cga.up(b) ^ cga.up(c)
    assert type(circles) is cga.Circle and len(circles) == 50 and circles.array.shape == (50, 10)
    for i in range(50):
        one = cga.up(a[i]) ^ cga.up(b[i]) ^ cga.up(c[i])
        assert np.array_equal(circles[i].array, one.array)


def test_one_against_many_broadcasts():
    lines = cga.Line.through(points(20), points(20))
    sphere = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    pairs = lines & sphere
    assert len(pairs) == 20
    for i in range(20):
        assert np.array_equal(pairs[i].array, (lines[i] & sphere).array)


def test_constructors_broadcast_and_match_one_at_a_time():
    centres, radii = points(30), RNG.uniform(0.1, 2.0, size=30)
    spheres = cga.Sphere.from_centre_radius(centres, radii)
    c, r = spheres.centre_radius()
    assert c.shape == (30, 3) and r.shape == (30,)
    assert np.allclose(c, centres, atol=1e-13) and np.allclose(r, radii, rtol=1e-13)
    assert np.array_equal(spheres[4].array, cga.Sphere.from_centre_radius(centres[4], radii[4]).array)


def test_from_array_indexing_slicing_and_len():
    a = RNG.normal(size=(8, 10))
    circles = cga.Circle.from_array(a)
    assert len(circles) == 8 and np.array_equal(circles.array, a)
    assert np.array_equal(circles[-1].array, a[-1])
    assert np.array_equal(circles[2:6:2].array, a[2:6:2])
    with pytest.raises(IndexError):
        circles[8]
    with pytest.raises(TypeError):
        len(circles[0])


def test_a_large_batch_runs_in_threads_with_the_same_bits():
    n = 40_000
    x = points(n)
    m = cga.Motor.from_rotor_translation(cga.Rotor.from_axis_angle([0.3, 0.4, 1.0], 0.9), [1.0, 2.0, 3.0])
    moved = m.sandwich(cga.up(x))
    for i in (0, 12_345, n - 1):
        assert np.array_equal(moved[i].array, m.sandwich(cga.up(x[i])).array)


def test_motor_moves_many_points():
    m = cga.Motor.from_rotor_translation(cga.Rotor.from_axis_angle([0, 0, 1.0], 0.3), [1.0, 0, 0])
    x = points(100)
    assert np.allclose(m.move_point(x), cga.down(m.sandwich(cga.up(x))), atol=1e-12)


@pytest.mark.parametrize("n", [1, 13, 70_000])
def test_every_lane_kernel_gives_the_registrys_bits(n):
    # The products run on SIMD lanes (and threads, at 70,000 rows) against the generated
    # code through the storage basis, row for row: both operands arrays, and either one a
    # single value broadcast (a tail of rows not filling the lanes included).
    from cga import _cga

    import importlib

    kernels = _cga._kernels()
    assert len(kernels) >= 20 and {k[0] for k in kernels} == {"cga", "cga.pga", "cga.cga2", "cga.vga", "cga.sta"}
    for algebra, kind, left, right in kernels:
        module = importlib.import_module(algebra)
        cls_a, cls_b = getattr(module, left), getattr(module, right)
        a = cls_a(RNG.normal(size=(n, len(cls_a.blades))))
        b = cls_b(RNG.normal(size=(n, len(cls_b.blades))))
        op = {
            "Geometric": lambda x, y: x * y,
            "Outer": lambda x, y: x ^ y,
            "Regressive": lambda x, y: x & y,
            "Sandwich": lambda x, y: x.sandwich(y),
        }[kind]
        for x, y in [(a, b), (a[0], b), (a, b[0])]:
            got, want = op(x, y), _cga._registry_product(kind, x, y)
            assert type(got) is type(want), (algebra, kind, left, right)
            assert np.array_equal(got.array, want.array), (algebra, kind, left, right, n)


def test_threads_share_the_rows_and_each_row_gets_its_own_answer():
    # Rows are shared out in chunks (4096 rows through the storage basis, 8192 on lanes): the
    # rows at chunk edges against the same product of those rows alone.
    from cga import _cga

    n = 70_000
    a, b = cga.Circle(RNG.normal(size=(n, 10))), cga.Sphere(RNG.normal(size=(n, 5)))
    lanes, storage = a & b, _cga._registry_product("Regressive", a, b)
    for i in (0, 4095, 4096, 8191, 8192, 65_535, n - 1):
        one = _cga._registry_product("Regressive", a[i], b[i])
        assert np.array_equal(storage[i].array, one.array) and np.array_equal(lanes[i].array, one.array), i


def test_wedge_is_the_chain_of_outer_products_bit_for_bit():
    rng = np.random.default_rng(11)
    for n in (1, 7, 5000, 100_000):
        p, q, r, s = (cga.up(rng.normal(size=(n, 3))) for _ in range(4))
        assert np.array_equal(cga.wedge(p, q, r).array, (p ^ q ^ r).array)
        assert np.array_equal(cga.wedge(p, q, r, s).array, (p ^ q ^ r ^ s).array)
        assert type(cga.wedge(p, q, r, s)) is cga.Sphere
        pair = p ^ q
        assert np.array_equal(cga.wedge(pair, r, s).array, (pair ^ r ^ s).array)
    # One value against arrays, at any place in the chain.
    one, many = cga.up([1.0, 2.0, 3.0]), cga.up(rng.normal(size=(3000, 3)))
    other = cga.up(rng.normal(size=(3000, 3)))
    assert np.array_equal(cga.wedge(one, many, other).array, (one ^ many ^ other).array)
    assert np.array_equal(cga.wedge(one, cga.up([0, 1.0, 0]), many).array, (one ^ cga.up([0, 1.0, 0]) ^ many).array)
    assert cga.wedge(one, cga.up([0, 1.0, 0]), cga.up([0, 0, 1.0])).single
    # Steps without a kernel are the operators one by one.
    line = cga.Line.through([0, 0, 0.0], [1.0, 0, 0])
    assert np.array_equal(cga.wedge(line, many).array, (line ^ many).array)
    assert cga.wedge(one) is one or np.array_equal(cga.wedge(one).array, one.array)
    with pytest.raises(cga.ValueError):
        cga.wedge()
    with pytest.raises(TypeError):
        cga.wedge(one, 3.0)
    with pytest.raises(cga.ShapeError):
        cga.wedge(cga.up(rng.normal(size=(3, 3))), cga.up(rng.normal(size=(4, 3))), one)
