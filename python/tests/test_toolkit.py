"""The toolkit on the classes against Euclidean formulas: classification, reflections and
inversions, distances and angles, the versors' log, exp and interpolation; arrays row for row
against one value at a time, and what has no answer refused by name."""

import numpy as np
import pytest

import cga

RNG = np.random.default_rng(5)
TOL = 1e-12


def test_classify_reads_each_kind_in_euclidean_terms():
    c = cga.Circle.from_centre_normal_radius([1.0, 2.0, 3.0], [0, 0, 1.0], 2.0).classify()
    assert c["kind"] == "round" and c["grade"] == 3 and c["reality"] == "real"
    assert np.allclose(c["centre"], [1, 2, 3], atol=TOL) and abs(c["radius_squared"] - 4.0) < TOL
    line = cga.Line.through([0, 0, 1.0], [1.0, 0, 1.0]).classify()
    assert line["kind"] == "line" and np.allclose(line["point"], [0, 0, 1], atol=TOL)
    plane = cga.Plane.from_point_normal([0, 0, 2.0], [0, 0, 1.0]).classify()
    assert plane["kind"] == "plane" and abs(abs(plane["offset"]) - 2.0) < TOL
    many = cga.Sphere.from_centre_radius(RNG.normal(size=(4, 3)), 1.5).classify()
    assert [k["kind"] for k in many] == ["round"] * 4


def test_reflections_and_inversion_of_points_are_euclids():
    x = RNG.normal(size=(20, 3))
    X = cga.up(x)
    mirror = cga.Plane.from_point_normal([0, 0, 0.5], [0, 0, 1.0])
    assert np.allclose(cga.down(X.reflect_in(mirror)), x * [1, 1, -1] + [0, 0, 1.0], atol=TOL)
    c, r = np.array([0.3, -0.2, 0.1]), 1.7
    d = x - c
    want = c + r * r * d / np.sum(d * d, axis=1, keepdims=True)
    assert np.allclose(cga.down(X.invert_in(cga.Sphere.from_centre_radius(c, r))), want, rtol=1e-12, atol=TOL)
    assert np.allclose(cga.down(X.reflect_in_point(c)), 2 * c - x, atol=TOL)
    axis = cga.Line.through([0, 0, 0.0], [0, 0, 1.0])
    assert np.allclose(cga.down(X.reflect_in_line(axis)), x * [-1, -1, 1], atol=TOL)
    # A line not through the centre inverts to a circle.
    assert type(cga.Line.through([2.0, 0, 0], [2.0, 1.0, 0]).invert_in(cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0))) is cga.Circle


def test_distances_and_angles_are_euclids():
    p, q, x = RNG.normal(size=(3, 30, 3))
    lines = cga.Line.through(p, q)
    d = (q - p) / np.linalg.norm(q - p, axis=1, keepdims=True)
    want = np.linalg.norm(np.cross(x - p, d), axis=1)
    assert np.allclose(lines.distance_to(x), want, rtol=1e-12, atol=TOL)
    assert abs(lines[3].distance_to(x[3]) - want[3]) < TOL
    plane = cga.Plane.from_point_normal([0, 0, 1.0], [0, 0, 1.0])
    assert np.allclose(plane.signed_distance(x), x[:, 2] - 1.0, atol=TOL)
    sphere = cga.Sphere.from_centre_radius([1.0, 0, 0], 0.5)
    assert np.allclose(sphere.signed_distance(x), np.linalg.norm(x - [1, 0, 0], axis=1) - 0.5, atol=TOL)
    a, b = cga.Line.through([0, 0, 0.0], [1.0, 0, 0]), cga.Line.through([0, 1.0, 1.0], [0, 2.0, 1.0])
    on_a, on_b, dist = a.closest_points(b)
    assert np.allclose(on_a, [0, 0, 0], atol=TOL) and np.allclose(on_b, [0, 0, 1], atol=TOL) and abs(dist - 1) < TOL
    assert abs(a.angle_to(b) - np.pi / 2) < TOL


def test_motor_log_exp_and_interpolation():
    r = cga.Rotor.from_axis_angle([0.0, 0.6, 0.8], 1.1)
    m = cga.Motor.from_rotor_translation(r, [1.0, -2.0, 0.5])
    assert np.allclose(cga.Motor.exp(m.log()).array, m.array, atol=TOL)
    assert np.allclose(cga.Rotor.exp(r.log()).array, r.array, atol=TOL)
    one = cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0])
    path = cga.Motor.interpolate(one, m, np.linspace(0, 1, 5))
    assert len(path) == 5 and np.allclose(path[0].array, one.array, atol=TOL) and np.allclose(path[4].array, m.array, atol=TOL)
    # Half way twice is the whole way: M(½)² = M.
    half = cga.Motor.interpolate(one, m, 0.5)
    assert np.allclose((half * half).array, m.array, atol=TOL)


def test_what_has_no_answer_is_refused_by_name():
    centre = cga.Sphere.from_centre_radius([0, 0, 0.0], 1.0)
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga.up([[1.0, 0, 0], [0, 0, 0.0]]).invert_in(centre)
    with pytest.raises(TypeError, match="expected a Plane"):
        cga.up([1.0, 0, 0]).reflect_in(centre)
    with pytest.raises(cga.ValueError):
        cga.Motor.interpolate(cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0]), cga.Motor([1.0, 0, 0, 0, 0, 0, 0, 0]), float("nan"))
    with pytest.raises(cga.ShapeError):
        cga.Line.through([0, 0, 0.0], [1.0, 0, 0]).distance_to([1.0, 2.0])


def test_projections_are_euclids_nearest_points():
    x = RNG.normal(size=(30, 3)) * 3
    c, r = np.array([0.5, -1.0, 2.0]), 1.3
    d = x - c
    sphere = cga.Sphere.from_centre_radius(c, r)
    assert np.allclose(sphere.project(x), c + r * d / np.linalg.norm(d, axis=1, keepdims=True), atol=1e-12)
    n = np.array([1.0, 2.0, 2.0]) / 3
    plane = cga.Plane.from_point_normal(2 * n, n)
    assert np.allclose(plane.project(x), x - (x @ n - 2.0)[:, None] * n, atol=1e-12)
    p, u = np.array([1.0, 0, 0]), np.array([0, 0.6, 0.8])
    line = cga.Line.from_point_direction(p, u)
    assert np.allclose(line.project(x), p + ((x - p) @ u)[:, None] * u, atol=1e-12)
    circle = cga.Circle.from_centre_normal_radius(c, n, r)
    in_plane = d - (d @ n)[:, None] * n
    assert np.allclose(circle.project(x), c + r * in_plane / np.linalg.norm(in_plane, axis=1, keepdims=True), atol=1e-12)
    a, b = np.array([1.0, 1, 1]), np.array([-1.0, 0, 2])
    pair = cga.up(a) ^ cga.up(b)
    nearer = np.where((np.linalg.norm(x - a, axis=1) <= np.linalg.norm(x - b, axis=1))[:, None], a, b)
    assert np.allclose(pair.project(x), nearer, atol=1e-9)
    # Arrays row for row, and one point onto many objects.
    spheres = cga.Sphere.from_centre_radius(x[:5], 0.5)
    assert np.allclose(spheres.project([0, 0, 0.0]), np.array([spheres[i].project([0, 0, 0.0]) for i in range(5)]))
    with pytest.raises(cga.GeometryError, match="row 0"):
        sphere.project([c])


def test_a_line_projects_onto_a_plane_and_along_its_normal_is_refused():
    plane = cga.Plane.from_point_normal([0, 0, 1.0], [0, 0, 1.0])
    line = cga.Line.from_point_direction([1.0, 2.0, 5.0], [1.0, 0, 1.0])
    shadow = line.project_onto_plane(plane)
    assert np.allclose(shadow.point()[2], 1.0, atol=1e-12)
    d = shadow.direction()
    assert np.allclose(np.cross(d, [1.0, 0, 0]), 0, atol=1e-12)
    with pytest.raises(cga.GeometryError):
        cga.Line.from_point_direction([0, 0, 0.0], [0, 0, 1.0]).project_onto_plane(plane)


def test_a_motor_spline_passes_through_its_poses_smoothly():
    poses = cga.random.motors(5, seed=3)
    at_knots = cga.Motor.spline(poses, np.arange(5.0))
    x = RNG.normal(size=3)
    for k in range(5):
        assert np.allclose(at_knots[k].move_point(x), poses[k].move_point(x), atol=1e-9)
    # C¹: the point's velocity just before and after an inner pose agree.
    h = 1e-6
    path = lambda u: cga.Motor.spline(poses, u).move_point(x)
    for k in (1, 2, 3):
        before = (path(k) - path(k - h)) / h
        after = (path(k + h) - path(k)) / h
        assert np.allclose(before, after, rtol=1e-3, atol=1e-3)
    with pytest.raises(cga.ValueError, match="outside"):
        cga.Motor.spline(poses, 4.5)
    with pytest.raises(cga.GeometryError):
        cga.Motor.spline(poses[0:1], 0.0)


def test_random_objects_are_proper_reproducible_and_checked():
    import cga.random as rnd

    for make, cls in [(rnd.spheres, cga.Sphere), (rnd.planes, cga.Plane), (rnd.lines, cga.Line),
                      (rnd.circles, cga.Circle), (rnd.point_pairs, cga.Bivector), (rnd.rotors, cga.Rotor),
                      (rnd.translators, cga.Translator), (rnd.motors, cga.Motor), (rnd.vectors, cga.Vector)]:
        many = make(50, seed=7)
        assert type(many) is cls and len(many) == 50
        assert np.array_equal(many.array, make(50, seed=7).array)
        assert make(seed=1).single
    assert rnd.points(4, seed=2).shape == (4, 3) and rnd.points(seed=2).shape == (3,)
    radii = rnd.spheres(200, seed=4, scale=2.0).centre_radius()[1]
    assert ((radii >= 0.2) & (radii <= 2.0)).all()
    m = rnd.motors(100, seed=5)
    assert np.allclose((m * ~m).array[:, 0], 1.0, atol=1e-12)
    kinds = {k["kind"] for k in rnd.point_pairs(20, seed=6).classify()}
    assert kinds == {"round"}
    with pytest.raises(cga.ValueError, match="count"):
        rnd.spheres(0)


def _on_sphere(c, r, n):
    d = RNG.normal(size=(n, 3))
    return np.asarray(c) + r * d / np.linalg.norm(d, axis=1)[:, None]


def test_fits_give_back_the_object_the_points_lie_on_far_from_the_origin():
    c, r = np.array([1e5, -2e5, 3e4]), 0.75
    sphere = cga.fit_sphere(_on_sphere(c, r, 30))
    centre, radius = sphere.centre_radius()
    # The points' rounding, ε ρ r, and what a sphere read back from its blade carries, ε ρ² r.
    rho = np.linalg.norm(c) / r
    tol = 64 * 2.2e-16 * rho * (1 + rho) * r
    assert np.linalg.norm(centre - c) < tol and abs(radius - r) < tol
    # Points in a plane through c: the circle, and its plane.
    n = np.array([0.0, 0.6, 0.8])
    u = np.cross(n, [1.0, 0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    t = RNG.uniform(0, 2 * np.pi, 9)
    ring = c + r * (np.cos(t)[:, None] * u + np.sin(t)[:, None] * v)
    cc, cn, cr = cga.fit_circle(ring).centre_normal_radius()
    assert np.linalg.norm(cc - c) < tol and abs(cr - r) < tol and np.allclose(cn, n, atol=1e-9)
    pn, offset = cga.fit_plane(ring).normal_offset()
    # The points' own rounding, ε |c|, tilts a plane of their spread r by up to about ε ρ.
    assert np.allclose(pn, n, atol=64 * 2.2e-16 * rho) and abs(offset - n @ c) < 1e-9 * np.linalg.norm(c)
    line = cga.fit_line(c + np.outer(RNG.uniform(-1, 1, 6), u))
    assert line.distance_to(c) < 1e-9 and abs(abs(line.direction() @ u) - 1) < 1e-12


def test_noisy_points_fit_as_clifford_fits_them():
    """clifford.tools.g3c's fit_sphere (Dorst's eigenvector fit) and ours (the algebraic
    least-squares fit) agree within the noise. (On exact points clifford's can return another
    sphere: it takes the smallest *positive* eigenvalue, and the right one is zero up to
    rounding, of either sign; exact points are checked against Euclid above.)"""
    fitting = pytest.importorskip("clifford.tools.g3c.object_fitting")
    from clifford.g3c import e1, e2, e3, up

    for noise in (1e-6, 1e-3):
        points = _on_sphere([0.5, -1.0, 2.0], 1.5, 40) + RNG.normal(scale=noise, size=(40, 3))
        theirs = fitting.fit_sphere([up(x * e1 + y * e2 + z * e3) for x, y, z in points])
        kind = cga.from_clifford(theirs).classify()
        centre, radius = cga.fit_sphere(points).centre_radius()
        tol = 1e-10 + 10 * noise
        assert kind["kind"] == "round" and kind["grade"] == 4
        assert np.linalg.norm(centre - kind["centre"]) < tol and abs(radius - kind["radius_squared"] ** 0.5) < tol


def test_fits_take_sets_of_points_and_conformal_points_and_refuse_what_holds_no_object():
    sets = np.stack([_on_sphere(RNG.normal(size=3), 1 + k, 12) for k in range(5)])
    many = cga.Sphere.fit(sets)
    assert len(many) == 5
    for k in range(5):
        assert np.array_equal(many[k].array, cga.fit_sphere(sets[k]).array)
    assert np.array_equal(cga.fit_sphere(cga.up(sets[0])).array, cga.fit_sphere(sets[0]).array)
    collinear = np.outer(np.arange(5.0), [1.0, 2.0, 3.0])
    with pytest.raises(cga.GeometryError, match="collinear"):
        cga.fit_circle(collinear)
    square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]], dtype=float)
    with pytest.raises(cga.GeometryError, match="row 1"):
        cga.Plane.fit(np.stack([square, collinear]))
    with pytest.raises(cga.ShapeError):
        cga.fit_sphere(np.zeros((4, 2)))
    with pytest.raises(cga.ValueError, match="finite"):
        cga.fit_line([[0, 0, 0], [1, np.nan, 0]])


def _brute_on_circle(c, n, r, dist):
    """The least of ``dist`` over 20000 points of the circle (centre c, unit normal n, radius r)."""
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    t = np.linspace(0, 2 * np.pi, 20000, endpoint=False)
    xs = c + r * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))
    return dist(xs).min()


def test_closest_points_of_circles_and_lines_are_euclids():
    ring = cga.Circle.from_centre_normal_radius([0, 0, 0.0], [0, 0, 1.0], 1.0)
    above = cga.Line.from_point_direction([3.0, 0, 2.0], [0, 1.0, 0])
    on_c, on_l, dist = ring.closest_points_to_line(above)
    assert np.allclose(on_c, [1, 0, 0], atol=TOL) and np.allclose(on_l, [3, 0, 2], atol=TOL)
    assert abs(dist - np.sqrt(8)) < TOL
    upright = cga.Circle.from_centre_normal_radius([3.0, 0, 0], [0, 1.0, 0], 1.0)
    on_a, on_b, dist = ring.closest_points_to_circle(upright)
    assert np.allclose(on_a, [1, 0, 0], atol=TOL) and np.allclose(on_b, [2, 0, 0], atol=TOL) and abs(dist - 1) < TOL
    # Arrays, row by row, against a brute force over each circle.
    circles, lines = cga.random.circles(20, seed=3), cga.random.lines(20, seed=4)
    c, n, r = circles.centre_normal_radius()
    _, _, d = circles.closest_points_to_line(lines)
    p, u = lines.point(), lines.direction()
    for i in range(20):
        want = _brute_on_circle(c[i], n[i], r[i], lambda x: np.linalg.norm(np.cross(x - p[i], u[i]), axis=1))
        assert want - 1e-6 <= d[i] <= want + 1e-12
    with pytest.raises(TypeError):
        ring.closest_points_to_line(ring)


def test_average_objects():
    a = cga.Circle.from_centre_normal_radius([0, 0, 0.0], [0, 0, 1.0], 1.0)
    both = cga.Circle(np.stack([a.array, (-a).array]))
    mean = cga.average_objects(both)
    assert mean.single and np.allclose(mean.array, a.array, atol=TOL)
    spheres = cga.Sphere.from_centre_radius([[0, 0, 0.0], [0.02, 0, 0], [0, 0.02, 0]], [1.0, 1.0, 1.0])
    c, r = spheres.average().centre_radius()
    assert np.allclose(c, [0.02 / 3, 0.02 / 3, 0], atol=1e-4) and abs(r - 1) < 1e-3
    with pytest.raises(cga.GeometryError):
        cga.Circle(np.zeros((2, 10))).average()
