#!/usr/bin/env python3
"""Golden vectors for the operations a CGA user reaches for, computed with clifford 1.5.1.

Writes tests/golden/operations.json: reflections in planes, lines and points, inversion in a
sphere, projections and rejections of points, projection of a line onto a plane, distances,
angles, meets, the parts of a circle (carrier plane, carrier sphere, tangent line), versors
(rotor between directions, motor about a line, screw, motor interpolation and powers through
clifford's general_logarithm, dilator, transversor), a classification set of ~30 blades, and
(appended last, so the earlier families draw the same random numbers) projections of flats
onto flats, meets of two lines and meets of point pairs with every object.

Every case gives its inputs as Euclidean parameters and as the multivectors (32 floats, in the
golden blade order) built from them, and its outputs as clifford's multivector and as the
Euclidean answer. Euclidean answers are closed-form formulas in numpy (float64), never read
back from clifford; clifford's own read-backs (clifford.tools.g3c) are asserted against them
in this script, for every case, to 1e-9 relative, and are recorded where a tool exists.
The objects are built as cga-core builds them (the constructors in the header's
`constructors`), each one checked here against the wedge of conformal points.

Inputs come from numpy.random.RandomState(SEED) (SEED = 20261202), not from clifford's
random_* helpers. The output is deterministic for a given clifford/numpy/numba.

Run (as made):
    python3 -m venv /work/.venv-clifford
    /work/.venv-clifford/bin/pip install clifford==1.5.1   # pulled numba 0.68.1, llvmlite 0.50.0,
                                                          # numpy 2.4.6, scipy 1.17.1, sparse 0.19.3, h5py 3.16.0
    /work/.venv-clifford/bin/python tools/clifford_operations.py
(Python 3.11.7; the first import of clifford compiles with numba, ~15 s.)
"""
import json
import math
import os
import re
import sys
import warnings

import numpy as np

warnings.simplefilter("ignore")  # clifford's deprecation and numba notices

import clifford  # noqa: E402
import numba  # noqa: E402
from clifford.g3c import layout, blades, einf, eo, e1, e2, e3  # noqa: E402
from clifford.tools import g3c as tools  # noqa: E402
from clifford.tools.g3c.rotor_parameterisation import general_logarithm  # noqa: E402

SEED = 20261202
TOL = 1e-9
I5 = blades["e12345"]
I3 = blades["e123"]
E45 = blades["e45"]
NAMES = ["1" if n == "" else n for n in layout.names]
assert clifford.__version__ == "1.5.1", clifford.__version__

rng = np.random.RandomState(SEED)


# ---------------------------------------------------------------------------------------------
# Small helpers: Euclidean vectors are numpy arrays of 3 floats.

def V(x):
    return float(x[0]) * e1 + float(x[1]) * e2 + float(x[2]) * e3


def up(x):
    """up(x) = x + x^2/2 einf + eo (clifford's layout.up, the golden files' convention)."""
    return layout.up(V(x))


def clean(v):
    v = float(v)
    return 0.0 if v == 0 else v


def mvl(X):
    return [clean(v) for v in X.value]


def E(v):
    return [clean(x) for x in np.asarray(v, dtype=float)]


def eu(X):
    return np.array(X.value[1:4])


def weight(X):
    """-X . einf: the weight of a (possibly scaled) conformal point or dual round."""
    return -(X | einf)[()]


def down_w(X):
    """Euclidean point and weight of a vector X = w (up(x) + k einf): for a dual round its centre."""
    w = weight(X)
    return eu(X) / w, w


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def s0(X):
    return X.value[0]


def dual(X):
    """dual(A) = A I5^-1 = -A I5 (the golden convention)."""
    return -X * I5


def undual(X):
    return X * I5


def biggest(X):
    return float(np.max(np.abs(X.value)))


def rel(A, B, what, tol=TOL):
    """The scalar lam with A = lam B, asserted to tol relative to the larger coefficient."""
    a, b = A.value, B.value
    lam = float(np.dot(a, b) / np.dot(b, b))
    err = float(np.max(np.abs(a - lam * b)))
    assert err <= tol * max(np.max(np.abs(a)), np.max(np.abs(b)), 1.0), (what, err, lam)
    return lam


def close(a, b, what, tol=TOL):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    err = float(np.max(np.abs(a - b)))
    assert err <= tol * max(1.0, float(np.max(np.abs(b)))), (what, err, a, b)


def sign_of(lam, what):
    assert abs(abs(lam) - 1) < 1e-9, (what, lam)
    return 1 if lam > 0 else -1


def only_grade(X, k, what):
    """X's grade-k part, after asserting the rest is rounding."""
    Xk = X(k)
    assert biggest(X - Xk) <= TOL * max(biggest(X), 1.0), (what, X)
    return Xk


def perp(n):
    """A unit vector perpendicular to n (deterministic)."""
    n = unit(n)
    a = np.zeros(3)
    a[int(np.argmin(np.abs(n)))] = 1.0
    return unit(np.cross(n, a))


def frame(n):
    """u, v with (u, v, n) right-handed orthonormal: u x v = n."""
    n = unit(n)
    u = perp(n)
    return u, np.cross(n, u)


def rpoint(s=3.0):
    return rng.uniform(-s, s, 3)


def rdir():
    return unit(rng.normal(size=3))


def rradius(lo=0.5, hi=3.0):
    return float(rng.uniform(lo, hi))


# ---------------------------------------------------------------------------------------------
# Constructors, as cga-core has them (cga-core/src/conformal.rs), each checked against the
# wedge of conformal points below (check_constructors).

def line(p, d):
    """Line::from_point_direction: up(p) ^ up(p + d) ^ einf, normalised (directed along d)."""
    return (up(p) ^ up(np.add(p, unit(d))) ^ einf).normal()


def plane_dual(p, n):
    n = unit(n)
    return -(V(n) + float(np.dot(n, p)) * einf)


def plane(p, n):
    """Plane::from_point_normal: undual(-(n + (n.p) einf)) = up(p)^up(p+u)^up(p+v)^einf normalised, u x v = n."""
    return undual(plane_dual(p, n))


def sphere_dual(c, r):
    return (up(c) - 0.5 * r * r * einf) / r


def sphere(c, r):
    """Sphere::from_centre_radius: undual((up(c) - r^2/2 einf) / r)."""
    return undual(sphere_dual(c, r))


def imaginary_sphere_dual(c, r):
    return (up(c) + 0.5 * r * r * einf) / r


def circle(c, n, r):
    """Circle::from_centre_normal_radius: -(S vee P) = up(a)^up(b)^up(c) normalised, a, b, c ccw about n."""
    return -(sphere(c, r) & plane(c, n))


def pair(a, b):
    """up(a) ^ up(b), not normalised (Bivector::from_points)."""
    return up(a) ^ up(b)


def flat_point(x):
    return up(x) ^ einf


def ccw_points(c, n, r):
    """Three points of the circle, counter-clockwise about n: c + r u, c + r v, c - r u."""
    u, v = frame(n)
    return [np.add(c, r * u), np.add(c, r * v), np.add(c, -r * u)]


def sphere_points(c, r, seed_dirs):
    return [np.add(c, r * unit(d)) for d in seed_dirs]


def wedge(points):
    """up(p0) ^ up(p1) ^ ..., with None standing for einf."""
    out = None
    for p in points:
        q = einf if p is None else up(p)
        out = q if out is None else out ^ q
    return out


def defining_points(kind, prm, extra=None):
    """Ordered points (None = einf) whose wedge is a positive multiple of the object's blade."""
    if kind == "point":
        return [prm["x"]]
    if kind == "point_pair":
        return [prm["a"], prm["b"]]
    if kind == "line":
        return [prm["point"], np.add(prm["point"], prm["direction"]), None]
    if kind == "plane":
        u, v = frame(prm["normal"])
        p = np.asarray(prm["point"])
        return [p, p + u, p + v, None]
    if kind == "circle":
        return ccw_points(prm["centre"], prm["normal"], prm["radius"])
    if kind == "sphere":
        pts = sphere_points(prm["centre"], prm["radius"], extra)
        return pts
    raise ValueError(kind)


def build(kind, prm):
    if kind == "point":
        return up(prm["x"])
    if kind == "point_pair":
        return pair(prm["a"], prm["b"])
    if kind == "line":
        return line(prm["point"], prm["direction"])
    if kind == "plane":
        return plane(prm["point"], prm["normal"])
    if kind == "circle":
        return circle(prm["centre"], prm["normal"], prm["radius"])
    if kind == "sphere":
        return sphere(prm["centre"], prm["radius"])
    raise ValueError(kind)


GRADE = {"point": 1, "point_pair": 2, "line": 3, "circle": 3, "plane": 4, "sphere": 4}


def jparams(prm):
    return {k: (E(v) if isinstance(v, (list, np.ndarray)) and np.ndim(v) == 1 else
                [E(w) for w in v] if isinstance(v, list) else clean(v)) for k, v in prm.items()}


def check_constructors():
    for _ in range(10):
        p, d, n, r = rpoint(), rdir(), rdir(), rradius()
        rel(line(p, d), wedge([p, p + d, None]), "line") > 0 or sys.exit("line orientation")
        lam = rel(plane(p, n), wedge(defining_points("plane", {"point": p, "normal": n})), "plane")
        assert lam > 0
        lam = rel(circle(p, n, r), wedge(ccw_points(p, n, r)), "circle")
        assert lam > 0
        dirs = [rdir() for _ in range(4)]
        pts = sphere_points(p, r, dirs)
        lam = rel(sphere(p, r), wedge(pts), "sphere")
        u, v, w = pts[1] - pts[0], pts[2] - pts[0], pts[3] - pts[0]
        # Sphere::through: the wedge is -sphere(c, r) when u . (v x w) > 0.
        assert (lam > 0) == (np.dot(u, np.cross(v, w)) < 0), "sphere orientation rule"
        assert abs(s0(line(p, d) * ~line(p, d)) + 1) < 1e-12
        assert abs(s0(sphere(p, r) * ~sphere(p, r)) + 1) < 1e-12
        assert abs(s0(circle(p, n, r) * ~circle(p, n, r)) + 1) < 1e-12
        # clifford's vee (&) against tools.g3c.meet: (-1)^((5-ga)(5-gb)).
        for ga, gb, A, B in [(4, 4, sphere(p, r), plane(p, n)), (3, 4, line(p, d), sphere(p, r)),
                             (3, 3, line(p, d), circle(p + n, d, r)), (2, 4, pair(p, p + d), plane(p, n))]:
            assert biggest((A & B) - (-1) ** ((5 - ga) * (5 - gb)) * tools.meet(A, B)) < 1e-9 * biggest(A & B)


def vee_meet(A, B):
    """Both clifford meets, with the grade sign rule between them asserted."""
    ga, gb = max(A.grades()), max(B.grades())
    vee, meet = A & B, tools.meet(A, B)
    assert biggest(vee - (-1) ** ((5 - ga) * (5 - gb)) * meet) <= TOL * max(biggest(vee), 1.0)
    return vee, meet


# ---------------------------------------------------------------------------------------------
# Euclidean formulas.

def mirror_point(x, p, n):
    return x - 2 * np.dot(x - p, n) * n


def mirror_dir(v, n):
    return v - 2 * np.dot(v, n) * n


def invert_point(x, c, R):
    d = x - c
    return c + R * R * d / np.dot(d, d)


def half_turn_point(x, q, u):
    return 2 * (q + np.dot(x - q, u) * u) - x


def half_turn_dir(v, u):
    return 2 * np.dot(v, u) * u - v


def rodrigues(v, a, th):
    return v * math.cos(th) + np.cross(a, v) * math.sin(th) + a * np.dot(a, v) * (1 - math.cos(th))


def rot_matrix(a, th):
    return np.array([rodrigues(np.eye(3)[k], unit(a), th) for k in range(3)]).T


def circumcircle(a, b, c):
    """Centre, unit normal (b - a) x (c - a), radius (as cga-core's circumcircle)."""
    u, v = b - a, c - a
    w = np.cross(u, v)
    centre = a + (np.dot(u, u) * np.cross(v, w) + np.dot(v, v) * np.cross(w, u)) / (2 * np.dot(w, w))
    return centre, unit(w), float(np.linalg.norm(centre - a))


def circumsphere(a, b, c, d):
    """Centre, radius, and the orientation of the wedge: +1 when up(a)^..^up(d) ~ +sphere(c, r)."""
    u, v, w = b - a, c - a, d - a
    vol = np.dot(u, np.cross(v, w))
    centre = a + (np.dot(u, u) * np.cross(v, w) + np.dot(v, v) * np.cross(w, u) + np.dot(w, w) * np.cross(u, v)) / (2 * vol)
    return centre, float(np.linalg.norm(centre - a)), (-1 if vol > 0 else 1)


def foot_on_line(x, p, d):
    return p + np.dot(x - p, d) * d


def flat_point_euc(F):
    """F = lam (x ^ einf + eo ^ einf) = lam (sum x_k (e_k4 + e_k5) - e45): (x, lam)."""
    lam = -F[(4, 5)]
    return np.array([F[(1, 4)], F[(2, 4)], F[(3, 4)]]) / lam, lam


def chasles(Rm, t):
    """Screw of x -> Rm x + t: (axis a, angle phi in [0, pi], point q on the axis, slide s)."""
    c = (np.trace(Rm) - 1) / 2
    w = np.array([Rm[2, 1] - Rm[1, 2], Rm[0, 2] - Rm[2, 0], Rm[1, 0] - Rm[0, 1]])
    sn = np.linalg.norm(w) / 2
    phi = math.atan2(sn, c)
    if sn < 1e-12:
        return None, 0.0, np.zeros(3), t
    a = w / (2 * sn)
    s = float(np.dot(t, a))
    tp = t - s * a
    q = 0.5 * (tp + np.cross(a, tp) / math.tan(phi / 2))
    return a, phi, q, s


def screw_apply(y, screw, frac):
    a, phi, q, s = screw
    if a is None:
        return y + frac * s
    return q + rodrigues(y - q, a, frac * phi) + frac * s * a


def motor_euc(axis, angle, t):
    return rot_matrix(axis, angle), np.asarray(t, dtype=float)


def rotor(axis, angle):
    """R = cos(angle/2) - sin(angle/2) a I3 (rotors.json, cga-core Rotor::from_axis_angle)."""
    return math.cos(angle / 2) - math.sin(angle / 2) * V(unit(axis)) * I3


def translator(t):
    """T = 1 + einf t / 2 = 1 - t einf / 2 (clifford's generate_translation_rotor)."""
    return tools.generate_translation_rotor(V(t))


def moved(M, x):
    X = M * up(x) * ~M
    y, w = down_w(X(1))
    return y, w


def rotor4(R):
    return [clean(R[()]), clean(R[(1, 2)]), clean(R[(1, 3)]), clean(R[(2, 3)])]


# ---------------------------------------------------------------------------------------------
# Families.

def sphere_dirs():
    return [rdir() for _ in range(4)]


def random_object(kind):
    """Euclidean parameters of a random object of the kind, and (for spheres) 4 point directions."""
    extra = None
    if kind == "point":
        prm = {"x": rpoint()}
    elif kind == "point_pair":
        prm = {"a": rpoint(), "b": rpoint()}
    elif kind == "line":
        prm = {"point": rpoint(), "direction": rdir()}
    elif kind == "plane":
        prm = {"point": rpoint(), "normal": rdir()}
    elif kind == "circle":
        prm = {"centre": rpoint(), "normal": rdir(), "radius": rradius()}
    elif kind == "sphere":
        prm = {"centre": rpoint(), "radius": rradius()}
        extra = sphere_dirs()
    return prm, extra


def outermorphism_sign(kind, prm, extra, image_points, X, Xp, what):
    """Assert Xp = (positive) * wedge(image points) whenever X = (positive) * wedge(points)."""
    lam0 = rel(X, wedge(defining_points(kind, prm, extra)), what + " object")
    lam1 = rel(Xp, wedge(image_points), what + " image")
    assert (lam0 > 0) == (lam1 > 0), (what, lam0, lam1)


def reflect_in_plane():
    cases = []
    kinds = ["point", "point_pair", "line", "circle", "sphere", "plane"]
    for i in range(24):
        kind = kinds[i % 6]
        k = GRADE[kind]
        p0, n0 = rpoint(2), rdir()
        P = plane(p0, n0)
        pi = plane_dual(p0, n0)
        prm, extra = random_object(kind)
        X = build(kind, prm)
        sandwich = only_grade(P * X * P, k, "reflect sandwich")
        reflected = (-1) ** (k + 1) * sandwich
        # The same with the dual plane (a unit vector): (-1)^k pi X pi.
        close(((-1) ** k * pi * X * pi)(k).value, reflected.value, "dual plane form")
        m = lambda x: mirror_point(np.asarray(x), p0, n0)
        md = lambda v: mirror_dir(np.asarray(v), n0)
        if kind == "point":
            img = {"x": m(prm["x"])}
        elif kind == "point_pair":
            img = {"a": m(prm["a"]), "b": m(prm["b"])}
        elif kind == "line":
            img = {"point": m(prm["point"]), "direction": md(prm["direction"])}
        elif kind == "plane":
            img = {"point": m(prm["point"]), "normal": md(prm["normal"])}
        elif kind == "circle":
            img = {"centre": m(prm["centre"]), "normal": md(prm["normal"]), "radius": prm["radius"]}
        elif kind == "sphere":
            img = {"centre": m(prm["centre"]), "radius": prm["radius"]}
        image_mv = build(kind, img)
        orientation = sign_of(rel(reflected, image_mv, "reflect image"), "reflect")
        ipts = [None if q is None else m(q) for q in defining_points(kind, prm, extra)]
        outermorphism_sign(kind, prm, extra, ipts, X, reflected, "reflect outermorphism")
        cases.append({
            "mirror": {"point": E(p0), "normal": E(n0)}, "mirror_mv": mvl(P), "mirror_dual_mv": mvl(pi),
            "kind": kind, "grade": k, "object": jparams(prm), "object_mv": mvl(X),
            "sandwich": mvl(sandwich), "reflected": mvl(reflected),
            "image": jparams(img), "image_mv": mvl(image_mv), "orientation": orientation,
        })
    return cases


def invert_in_sphere():
    cases = []
    plan = (["point"] * 6 + ["line"] * 3 + ["line_through"] + ["circle"] * 3 + ["circle_through"]
            + ["sphere"] * 2 + ["sphere_around"] + ["sphere_through"] + ["plane"] * 3 + ["plane_through"])
    S_inf_weights = []
    for what in plan:
        c0, R = rpoint(2), rradius(0.8, 2.5)
        S, sigma = sphere(c0, R), sphere_dual(c0, R)
        kind = what.split("_")[0]
        extra = None
        if what == "point":
            prm = {"x": rpoint()}
        elif what == "line":
            prm = {"point": rpoint(), "direction": rdir()}
        elif what == "line_through":
            prm = {"point": c0 + 0.7 * rdir(), "direction": None}
            prm["direction"] = unit(c0 - prm["point"])
            prm["point"] = c0 - 1.3 * prm["direction"]
        elif what == "circle":
            prm = {"centre": rpoint(), "normal": rdir(), "radius": rradius()}
        elif what == "circle_through":
            # A circle through c0, none of its three ccw points at c0.
            n, r = rdir(), rradius()
            u, v = frame(n)
            ang = 0.9
            centre = c0 - r * (math.cos(ang) * u + math.sin(ang) * v)
            prm = {"centre": centre, "normal": n, "radius": r}
        elif what == "sphere":
            prm = {"centre": c0 + rdir() * rng.uniform(3.5, 5), "radius": rradius(0.5, 2.5)}
            extra = sphere_dirs()
        elif what == "sphere_around":
            prm = {"centre": c0 + 0.3 * rdir(), "radius": rradius(1.0, 2.5)}
            extra = sphere_dirs()
        elif what == "sphere_through":
            r = rradius()
            prm = {"centre": c0 + r * rdir(), "radius": r}
            extra = sphere_dirs()
        elif what == "plane":
            n = rdir()
            prm = {"point": c0 + rng.uniform(0.5, 2) * rng.choice([-1, 1]) * n + 0.5 * perp(n), "normal": n}
        elif what == "plane_through":
            n = rdir()
            prm = {"point": c0 + 0.8 * perp(n), "normal": n}
        k = GRADE[kind]
        X = build(kind, prm)
        sandwich = only_grade(S * X * S, k, "invert sandwich")
        inverted = (-1) ** (k + 1) * sandwich
        close(((-1) ** k * sigma * X * sigma)(k).value, inverted.value, "dual sphere form")
        iv = lambda x: invert_point(np.asarray(x), c0, R)
        case = {"sphere": {"centre": E(c0), "radius": R}, "sphere_mv": mvl(S), "sphere_dual_mv": mvl(sigma),
                "kind": kind, "grade": k, "case": what, "object": jparams(prm), "object_mv": mvl(X),
                "sandwich": mvl(sandwich), "inverted": mvl(inverted)}
        if kind == "point":
            x = prm["x"]
            img, image_kind = {"x": iv(x)}, "point"
            w_expect = np.dot(x - c0, x - c0) / R ** 2
        elif what == "line":
            p, d = prm["point"], prm["direction"]
            a1, b1 = iv(p), iv(p + d)
            centre, normal, radius = circumcircle(a1, b1, c0)
            q1 = iv(foot_on_line(c0, p, d))
            close(centre, (c0 + q1) / 2, "line image centre")
            close(radius, np.linalg.norm(q1 - c0) / 2, "line image radius")
            img, image_kind = {"centre": centre, "normal": normal, "radius": radius}, "circle"
        elif what == "line_through":
            img, image_kind = {"point": c0, "direction": prm["direction"]}, "line"
        elif what == "circle":
            pts = [iv(q) for q in ccw_points(prm["centre"], prm["normal"], prm["radius"])]
            centre, normal, radius = circumcircle(*pts)
            img, image_kind = {"centre": centre, "normal": normal, "radius": radius}, "circle"
        elif what == "circle_through":
            pts = [iv(q) for q in ccw_points(prm["centre"], prm["normal"], prm["radius"])]
            dd = unit(pts[1] - pts[0])
            assert np.linalg.norm(np.cross(dd, unit(pts[2] - pts[0]))) < 1e-9
            img, image_kind = {"point": foot_on_line(c0, pts[0], dd), "direction": dd}, "line"
        elif what in ("sphere", "sphere_around"):
            c2, r2 = prm["centre"], prm["radius"]
            s = R * R / (np.dot(c2 - c0, c2 - c0) - r2 * r2)
            img, image_kind = {"centre": c0 + s * (c2 - c0), "radius": abs(s) * r2}, "sphere"
            cc, rr, _ = circumsphere(*[iv(q) for q in sphere_points(c2, r2, extra)])
            close(cc, img["centre"], "sphere image centre")
            close(rr, img["radius"], "sphere image radius")
        elif what == "sphere_through":
            c2, r2 = prm["centre"], prm["radius"]
            mdir = unit(c2 - c0)
            img, image_kind = {"point": c0 + R * R / (2 * r2) * mdir, "normal": mdir}, "plane"
        elif what == "plane":
            p, n = prm["point"], prm["normal"]
            h = np.dot(n, p - c0)
            img, image_kind = {"centre": c0 + R * R / (2 * h) * n, "radius": R * R / (2 * abs(h))}, "sphere"
        elif what == "plane_through":
            img, image_kind = {"point": c0, "normal": prm["normal"]}, "plane"
        image_mv = build(image_kind, img)
        lam = rel(inverted, image_mv, "invert image " + what)
        if kind == "point":
            close(lam, w_expect, "point weight")
            case["weight"] = lam
        else:
            case["orientation"] = sign_of(lam, "invert " + what)
        # Outermorphism: finite points go to up(image) times a positive weight, einf to
        # +(2/R^2) up(c0).
        w_inf = rel(S * einf * S, up(c0), "einf image")
        close(w_inf, 2 / R ** 2, "einf weight")
        S_inf_weights.append(w_inf)
        ipts = [c0 if q is None else iv(q) for q in defining_points(kind, prm, extra)]
        outermorphism_sign(kind, prm, extra, ipts, X, inverted, "invert outermorphism")
        case.update({"image_kind": image_kind, "image": jparams(img), "image_mv": mvl(image_mv)})
        cases.append(case)
    return cases


def reflect_in_point():
    cases = []
    plan = ["point"] * 14 + ["line"] * 3 + ["sphere"] * 3
    for kind in plan:
        c = rpoint(2)
        F = flat_point(c)
        assert abs(s0(F * F) - 1) < 1e-12
        Vd = dual(F)
        prm, extra = random_object(kind)
        k = GRADE[kind]
        X = build(kind, prm)
        sandwich = only_grade(F * X * F, k, "point reflection")
        reflected = (-1) ** k * sandwich
        close(((-1) ** k * Vd * X * Vd.inv())(k).value, reflected.value, "odd versor form")
        m = lambda x: 2 * c - np.asarray(x)
        if kind == "point":
            img = {"x": m(prm["x"])}
        elif kind == "line":
            img = {"point": m(prm["point"]), "direction": -np.asarray(prm["direction"])}
        else:
            img = {"centre": m(prm["centre"]), "radius": prm["radius"]}
        image_mv = build(kind, img)
        orientation = sign_of(rel(reflected, image_mv, "point reflection image"), "point reflection")
        ipts = [None if q is None else m(q) for q in defining_points(kind, prm, extra)]
        outermorphism_sign(kind, prm, extra, ipts, X, reflected, "point reflection outermorphism")
        cases.append({"centre": E(c), "versor_mv": mvl(F), "odd_versor_mv": mvl(Vd), "kind": kind, "grade": k,
                      "object": jparams(prm), "object_mv": mvl(X), "sandwich": mvl(sandwich),
                      "reflected": mvl(reflected), "image": jparams(img), "image_mv": mvl(image_mv),
                      "orientation": orientation})
    return cases


def reflect_in_line():
    cases = []
    plan = ["point"] * 12 + ["line"] * 3 + ["circle"] * 3 + ["sphere"] * 2
    for kind in plan:
        q, u = rpoint(2), rdir()
        L = line(q, u)
        assert abs(s0(L * L) - 1) < 1e-12
        M = (-math.pi / 2 * L * I5).exp()
        close(M.value, (-L * I5).value, "half-turn motor")
        prm, extra = random_object(kind)
        k = GRADE[kind]
        X = build(kind, prm)
        sandwich = only_grade(L * X * L, k, "line reflection")
        close((M * X * ~M)(k).value, sandwich.value, "half-turn motor sandwich")
        m = lambda x: half_turn_point(np.asarray(x), q, u)
        md = lambda v: half_turn_dir(np.asarray(v), u)
        if kind == "point":
            img = {"x": m(prm["x"])}
        elif kind == "line":
            img = {"point": m(prm["point"]), "direction": md(prm["direction"])}
        elif kind == "circle":
            img = {"centre": m(prm["centre"]), "normal": md(prm["normal"]), "radius": prm["radius"]}
        else:
            img = {"centre": m(prm["centre"]), "radius": prm["radius"]}
        image_mv = build(kind, img)
        orientation = sign_of(rel(sandwich, image_mv, "line reflection image"), "line reflection")
        ipts = [None if p is None else m(p) for p in defining_points(kind, prm, extra)]
        outermorphism_sign(kind, prm, extra, ipts, X, sandwich, "line reflection outermorphism")
        cases.append({"axis": {"point": E(q), "direction": E(u)}, "axis_mv": mvl(L), "motor_mv": mvl(M),
                      "kind": kind, "grade": k, "object": jparams(prm), "object_mv": mvl(X),
                      "reflected": mvl(sandwich), "image": jparams(img), "image_mv": mvl(image_mv),
                      "orientation": orientation})
    return cases


def project_point():
    cases = []
    kinds = ["line", "plane", "sphere", "circle", "point_pair"]
    for i in range(20):
        kind = kinds[i % 5]
        prm, _ = random_object(kind)
        A = build(kind, prm)
        x = rpoint()
        X = up(x)
        case = {"target_kind": kind, "target": jparams(prm), "target_mv": mvl(A), "x": E(x), "x_mv": mvl(X)}
        if kind == "line":
            proj = foot_on_line(x, prm["point"], prm["direction"])
            tool = tools.project_points_to_line([X], A)[0]
            case["tool"] = "project_points_to_line"
        elif kind == "plane":
            n = prm["normal"]
            proj = x - np.dot(x - prm["point"], n) * n
            tool = tools.project_points_to_plane([X], A)[0]
            case["tool"] = "project_points_to_plane"
        elif kind == "sphere":
            c, r = prm["centre"], prm["radius"]
            proj = c + r * unit(x - c)
            tool = tools.project_points_to_sphere([X], A, closest=True)[0]
            far = tools.project_points_to_sphere([X], A, closest=False)[0]
            close(down_w(far)[0], c - r * unit(x - c), "far sphere point")
            case["tool"] = "project_points_to_sphere(closest=True)"
            case["far_point"] = E(c - r * unit(x - c))
        elif kind == "circle":
            c, n, r = prm["centre"], prm["normal"], prm["radius"]
            y = x - np.dot(x - c, n) * n
            proj = c + r * unit(y - c)
            tool = tools.project_points_to_circle([X], A)[0]
            case["tool"] = "project_points_to_circle"
        else:
            a, b = prm["a"], prm["b"]
            proj = a if np.linalg.norm(x - a) <= np.linalg.norm(x - b) else b
            ends = tools.point_pair_to_end_points(A)
            ends_e = [down_w(q)[0] for q in ends]
            tool = ends[int(np.argmin([np.linalg.norm(x - q) for q in ends_e]))]
            case["tool"] = "point_pair_to_end_points, the nearer"
            case["tool_end_points"] = [E(q) for q in ends_e]
        tp, tw = down_w(tool)
        close(tp, proj, "projection " + kind)
        case["projection"] = E(proj)
        case["reject"] = E(x - proj)
        case["distance"] = float(np.linalg.norm(x - proj))
        case["tool_point_mv"] = mvl(tool)
        case["tool_point"] = E(tp)
        if kind in ("line", "plane"):
            Y = (X << A) * A.inv()
            Y1 = only_grade(Y, 1, "flat projection formula")
            centre, w = down_w(Y1)
            close(centre, proj, "formula centre")
            case["formula_mv"] = mvl(Y1)
        cases.append(case)
    return cases


def project_flat():
    cases = []
    for _ in range(20):
        p, d = rpoint(), rdir()
        p0, n = rpoint(2), rdir()
        if abs(np.dot(d, n)) > 0.95:
            d = unit(d + 2 * perp(n))
        L, P = line(p, d), plane(p0, n)
        Y = only_grade((L << P) * P.inv(), 3, "line projection")
        dp = d - np.dot(d, n) * n
        img = {"point": p - np.dot(p - p0, n) * n, "direction": unit(dp)}
        image_mv = line(img["point"], img["direction"])
        lam = rel(Y, image_mv, "projected line")
        close(lam, np.linalg.norm(dp), "projected line weight")
        cases.append({"line": {"point": E(p), "direction": E(d)}, "line_mv": mvl(L),
                      "plane": {"point": E(p0), "normal": E(n)}, "plane_mv": mvl(P),
                      "projected_mv": mvl(Y), "image": jparams(img), "image_mv": mvl(image_mv), "weight": lam})
    return cases


def distances():
    cases = []
    plan = ["point_point"] * 4 + ["point_line"] * 4 + ["point_plane"] * 4 + ["point_sphere"] * 4 + \
        ["line_line_skew"] * 4 + ["line_line_intersecting"] * 2 + ["line_line_parallel"] * 2
    for what in plan:
        if what == "point_point":
            a, b = rpoint(), rpoint()
            A, B = up(a), up(b)
            dist = float(np.linalg.norm(a - b))
            close(tools.euc_dist(A, B), dist, "euc_dist")
            close(-2 * s0(A | B), dist ** 2, "point inner")
            cases.append({"kind": what, "a": E(a), "b": E(b), "a_mv": mvl(A), "b_mv": mvl(B), "distance": dist,
                          "mv_value": clean(-2 * s0(A | B))})
        elif what == "point_line":
            x, p, d = rpoint(), rpoint(), rdir()
            X, L = up(x), line(p, d)
            f = foot_on_line(x, p, d)
            dist = float(np.linalg.norm(x - f))
            close(abs(X ^ L), dist, "|x ^ L|")
            cases.append({"kind": what, "x": E(x), "line": {"point": E(p), "direction": E(d)}, "x_mv": mvl(X),
                          "line_mv": mvl(L), "distance": dist, "foot": E(f), "mv_value": float(abs(X ^ L))})
        elif what == "point_plane":
            x, p, n = rpoint(), rpoint(2), rdir()
            X, P = up(x), plane(p, n)
            sd = float(np.dot(x - p, n))
            val = s0(X | (P * I5))
            close(val, sd, "x . (P I5)")
            cases.append({"kind": what, "x": E(x), "plane": {"point": E(p), "normal": E(n)}, "x_mv": mvl(X),
                          "plane_mv": mvl(P), "distance": sd, "foot": E(x - sd * n), "mv_value": clean(val)})
        elif what == "point_sphere":
            c, r = rpoint(2), rradius()
            x = c + rdir() * rng.uniform(0.2, 2) * r
            X, S = up(x), sphere(c, r)
            sd = float(np.linalg.norm(x - c) - r)
            val = s0(X | dual(S))
            close(val, (r * r - np.dot(x - c, x - c)) / (2 * r), "x . sigma")
            close(math.sqrt(r * r - 2 * r * val) - r, sd, "sphere distance formula")
            cases.append({"kind": what, "x": E(x), "sphere": {"centre": E(c), "radius": r}, "x_mv": mvl(X),
                          "sphere_mv": mvl(S), "distance": sd, "nearest": E(c + r * unit(x - c)), "mv_value": clean(val)})
        else:
            p1, d1 = rpoint(), rdir()
            if what == "line_line_skew":
                p2, d2 = rpoint(), rdir()
            elif what == "line_line_intersecting":
                d2 = rdir()
                p2 = p1 + rng.uniform(-2, 2) * d1 - rng.uniform(1, 2) * d2
            else:
                d2 = d1 * rng.choice([-1.0, 1.0])
                p2 = p1 + rng.uniform(0.5, 2) * perp(d1) + rng.uniform(-2, 2) * d1
            L1, L2 = line(p1, d1), line(p2, d2)
            w = np.cross(d1, d2)
            if what == "line_line_parallel":
                c1 = p1
                c2 = foot_on_line(p1, p2, d2)
                flag = "parallel"
            else:
                # p1 + s d1 - (p2 + t d2) perpendicular to d1 and d2.
                r0 = p1 - p2
                b = np.dot(d1, d2)
                s = (b * np.dot(d2, r0) - np.dot(d1, r0)) / (1 - b * b)
                t = (np.dot(d2, r0) - b * np.dot(d1, r0)) / (1 - b * b)
                c1, c2 = p1 + s * d1, p2 + t * d2
                flag = "skew" if what == "line_line_skew" else "intersecting"
            dist = float(np.linalg.norm(c1 - c2))
            prod = L1 * L2
            close(prod[()], np.dot(d1, d2), "<L1 L2>0")
            quad = prod(4)
            close(quad.value, (np.dot(p2 - p1, w) * (blades["e1234"] + blades["e1235"])).value, "<L1 L2>4")
            case = {"kind": "line_line", "flag": flag, "line1": {"point": E(p1), "direction": E(d1)},
                    "line2": {"point": E(p2), "direction": E(d2)}, "line1_mv": mvl(L1), "line2_mv": mvl(L2),
                    "distance": dist, "closest1": E(c1), "closest2": E(c2),
                    "product_scalar": clean(prod[()]), "product_e123inf": clean(quad[(1, 2, 3, 4)])}
            if flag != "parallel":
                close(abs(quad[(1, 2, 3, 4)]) / np.linalg.norm(w), dist, "distance from <L1 L2>4")
                mid = tools.midpoint_between_lines(L1, L2)
                mp_, _ = down_w(mid)
                close(mp_, (c1 + c2) / 2, "midpoint_between_lines")
                case["tool_midpoint"] = E(mp_)
            cases.append(case)
    return cases


def angles():
    cases = []
    for i in range(21):
        kind = ["line_line", "plane_plane", "line_plane"][i % 3]
        special = i // 3  # 0: parallel, 1: perpendicular, else random
        a, b = rdir(), rdir()
        if special == 0:
            b = a * rng.choice([-1.0, 1.0]) if kind != "line_plane" else perp(a)
        elif special == 1:
            b = perp(a) if kind != "line_plane" else a * rng.choice([-1.0, 1.0])
        pa, pb = rpoint(), rpoint()
        if kind == "line_line":
            A, B = line(pa, a), line(pb, b)
            cos_o = float(np.clip(np.dot(a, b), -1, 1))
            ang, ang_o = math.acos(min(1.0, abs(cos_o))), math.acos(cos_o)
            val = s0(A * B)
            close(val, cos_o, "<L1 L2>0")
            ea, eb = {"point": E(pa), "direction": E(a)}, {"point": E(pb), "direction": E(b)}
            formula = "<L1 L2>_0 = d1 . d2"
        elif kind == "plane_plane":
            A, B = plane(pa, a), plane(pb, b)
            cos_o = float(np.clip(np.dot(a, b), -1, 1))
            ang, ang_o = math.acos(min(1.0, abs(cos_o))), math.acos(cos_o)
            val = s0(A * B)
            close(val, -cos_o, "<P1 P2>0")
            ea, eb = {"point": E(pa), "normal": E(a)}, {"point": E(pb), "normal": E(b)}
            formula = "<P1 P2>_0 = -n1 . n2"
        else:
            A, B = line(pa, a), plane(pb, b)
            sin_o = float(np.clip(np.dot(a, b), -1, 1))
            ang, ang_o = math.asin(abs(sin_o)), math.asin(sin_o)
            F = A & B
            val = F[(4, 5)]
            close(val, -sin_o, "e45 of L & P")
            ea, eb = {"point": E(pa), "direction": E(a)}, {"point": E(pb), "normal": E(b)}
            formula = "the e45 coefficient of the vee L & P (clifford's &, cga-core's &) = -d . n"
        cases.append({"kind": kind, "special": ["parallel", "perpendicular"][special] if special < 2 else "generic",
                      "a": ea, "b": eb, "a_mv": mvl(A), "b_mv": mvl(B), "angle": ang, "angle_oriented": ang_o,
                      "mv_value": clean(val), "mv_formula": formula})
    return cases


def pp_points_euc(M):
    """End points of a point pair from clifford's point_pair_to_end_points, in its order."""
    return [down_w(q)[0] for q in tools.point_pair_to_end_points(M)]


def same_set(a, b, what):
    if np.linalg.norm(a[0] - b[0]) + np.linalg.norm(a[1] - b[1]) > np.linalg.norm(a[0] - b[1]) + np.linalg.norm(a[1] - b[0]):
        a = [a[1], a[0]]
    close(a[0], b[0], what)
    close(a[1], b[1], what)


def meets():
    cases = []

    def pair_case(case, M, hit, pts, order_dir):
        """Common point-pair fields: hit, Euclidean points (ordered along order_dir), clifford's ends."""
        sq = s0(M * M)
        case.update({"square": clean(sq), "hit": hit})
        if hit == "two":
            assert sq > 1e-9 * biggest(M) ** 2, (case, sq)
        elif hit == "miss":
            assert sq < -1e-9 * biggest(M) ** 2, (case, sq)
        else:
            assert abs(sq) < 1e-9 * max(biggest(M) ** 2, 1), (case, sq)
        if pts is None:
            case["points"] = None
            return
        pts = sorted(pts, key=lambda q: float(np.dot(q, order_dir)))
        case["points"] = [E(q) for q in pts]
        if hit == "two":
            tp = pp_points_euc(M)
            same_set(tp, pts, "point pair ends")
            case["tool_points"] = [E(q) for q in tp]

    # line through a circle in its plane: two, tangent, miss
    for hit in ["two", "two", "two", "tangent", "tangent", "miss", "miss"]:
        c, n, r = rpoint(2), rdir(), rradius()
        u, v = frame(n)
        ang = rng.uniform(0, 2 * math.pi)
        w = math.cos(ang) * u + math.sin(ang) * v
        h = {"two": rng.uniform(0, 0.9), "tangent": 1.0, "miss": rng.uniform(1.1, 2)}[hit] * r
        d = np.cross(n, w)
        p = c + h * w + rng.uniform(-2, 2) * d
        L, C = line(p, d), circle(c, n, r)
        SC = tools.circle_to_sphere(C)
        lam = rel(SC, sphere(c, r), "circle_to_sphere")
        vee, meet = vee_meet(L, SC)
        Pi = (C ^ einf).normal()
        in_plane = (((L * Pi.inv()) ^ (C * Pi.inv())) * Pi)(2)
        f = foot_on_line(c, p, d)
        pts = None
        if hit == "two":
            t = math.sqrt(r * r - h * h)
            pts = [f - t * d, f + t * d]
        elif hit == "tangent":
            pts = [f, f]
        case = {"kind": "line_circle", "line": {"point": E(p), "direction": E(d)},
                "circle": {"centre": E(c), "normal": E(n), "radius": r}, "line_mv": mvl(L), "circle_mv": mvl(C),
                "carrier_sphere_mv": mvl(SC), "carrier_sphere_orientation": sign_of(lam, "circle_to_sphere"),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet), "in_plane_mv": mvl(in_plane),
                "in_plane_vs_vee": rel(in_plane, vee, "in-plane meet")}
        pair_case(case, vee, hit, pts, d)
        cases.append(case)

    # sphere ^ sphere: circle ("two" = a real circle), tangent, miss (imaginary circle)
    for hit in ["two", "two", "two", "tangent", "tangent", "miss", "miss"]:
        c1, r1, r2 = rpoint(2), rradius(), rradius()
        m = rdir()
        if hit == "two":
            dd = rng.uniform(abs(r1 - r2) + 0.1, r1 + r2 - 0.1)
        elif hit == "tangent":
            dd = r1 + r2 if rng.rand() < 0.5 or abs(r1 - r2) < 0.3 else abs(r1 - r2)
        else:
            dd = r1 + r2 + rng.uniform(0.2, 1) if rng.rand() < 0.5 else max(abs(r1 - r2) - 0.3, 0.05)
            if dd >= abs(r1 - r2):
                dd = r1 + r2 + 0.5
        c2 = c1 + dd * m
        S1, S2 = sphere(c1, r1), sphere(c2, r2)
        vee, meet = vee_meet(S1, S2)
        dd = float(np.linalg.norm(c2 - c1))
        a = (dd * dd + r1 * r1 - r2 * r2) / (2 * dd)
        h2 = r1 * r1 - a * a
        centre = c1 + a * m
        gc, gn, gr = tools.get_circle_in_euc(meet)
        close(eu(gc), centre, "circle centre")
        close(abs(np.dot(eu(gn), m)), 1.0, "circle normal")
        close(math.copysign(gr * gr, gr), h2, "circle radius^2", tol=1e-8)
        case = {"kind": "sphere_sphere", "sphere1": {"centre": E(c1), "radius": r1},
                "sphere2": {"centre": E(c2), "radius": r2}, "sphere1_mv": mvl(S1), "sphere2_mv": mvl(S2),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet), "hit": hit, "square": clean(s0(vee * vee)),
                "circle": {"centre": E(centre), "normal": E(m), "radius_squared": clean(h2),
                           "radius": math.sqrt(h2) if hit == "two" else (0.0 if hit == "tangent" else None)},
                "tool_circle": {"centre": E(eu(gc)), "normal": E(eu(gn)), "radius": clean(gr)}}
        if hit == "two":
            case["orientation"] = sign_of(rel(vee.normal(), circle(centre, m, math.sqrt(h2)), "s^s circle"), "s^s")
        cases.append(case)

    # circle ^ plane: point pair
    for hit in ["two", "two", "two", "tangent", "tangent", "miss", "miss"]:
        c, n, r = rpoint(2), rdir(), rradius()
        u, v = frame(n)
        ang = rng.uniform(0, 2 * math.pi)
        w = math.cos(ang) * u + math.sin(ang) * v
        beta = {"two": rng.uniform(-0.9, 0.9), "tangent": 1.0, "miss": rng.uniform(1.1, 2)}[hit] * r
        tilt = rng.uniform(-1.2, 1.2)
        nP = unit(math.cos(tilt) * w + math.sin(tilt) * n)
        p0 = c + beta * w + rng.uniform(-1, 1) * np.cross(n, w)
        C, P = circle(c, n, r), plane(p0, nP)
        vee, meet = vee_meet(C, P)
        # Euclidean: the line of the two planes, nearest c, along u_dir.
        u_dir = unit(np.cross(n, nP))
        wv = unit(nP - np.dot(nP, n) * n)
        b = (np.dot(nP, p0) - np.dot(nP, c)) / np.dot(nP, wv)
        f = c + b * wv
        pts = None
        if hit == "two":
            t = math.sqrt(r * r - b * b)
            pts = [f - t * u_dir, f + t * u_dir]
        elif hit == "tangent":
            pts = [f, f]
        case = {"kind": "circle_plane", "circle": {"centre": E(c), "normal": E(n), "radius": r},
                "plane": {"point": E(p0), "normal": E(nP)}, "circle_mv": mvl(C), "plane_mv": mvl(P),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet), "order_direction": E(u_dir)}
        pair_case(case, vee, hit, pts, u_dir)
        cases.append(case)

    # line ^ sphere: point pair (also in line_sphere.json; here in this file's schema)
    for hit in ["two", "two", "tangent", "miss"]:
        c, r = rpoint(2), rradius()
        d = rdir()
        w = perp(d)
        h = {"two": rng.uniform(0, 0.9), "tangent": 1.0, "miss": rng.uniform(1.1, 2)}[hit] * r
        p = c + h * w + rng.uniform(-2, 2) * d
        L, S = line(p, d), sphere(c, r)
        vee, meet = vee_meet(L, S)
        f = foot_on_line(c, p, d)
        pts = None
        if hit == "two":
            t = math.sqrt(r * r - h * h)
            pts = [f - t * d, f + t * d]
        elif hit == "tangent":
            pts = [f, f]
        case = {"kind": "line_sphere", "line": {"point": E(p), "direction": E(d)},
                "sphere": {"centre": E(c), "radius": r}, "line_mv": mvl(L), "sphere_mv": mvl(S),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet)}
        pair_case(case, vee, hit, pts, d)
        cases.append(case)

    # three planes: a point, or parallel (the three normals coplanar)
    for hit in ["one"] * 5 + ["parallel"] * 2:
        ns = [rdir(), rdir(), rdir()]
        if hit == "parallel":
            ns[2] = unit(rng.uniform(-1, 1) * ns[0] + rng.uniform(-1, 1) * ns[1])
        ps = [rpoint(2) for _ in range(3)]
        Ps = [plane(p, n) for p, n in zip(ps, ns)]
        v12, m12 = vee_meet(Ps[0], Ps[1])
        vee, _ = vee_meet(v12, Ps[2])
        meet = tools.meet(m12, Ps[2])
        assert biggest(vee + meet) <= TOL * max(biggest(vee), 1)
        case = {"kind": "three_planes", "planes": [{"point": E(p), "normal": E(n)} for p, n in zip(ps, ns)],
                "planes_mv": [mvl(P) for P in Ps], "vee_mv": mvl(vee), "meet_mv": mvl(meet), "hit": hit}
        if hit == "one":
            x = np.linalg.solve(np.array(ns), np.array([np.dot(n, p) for n, p in zip(ns, ps)]))
            fx, lam = flat_point_euc(vee)
            close(fx, x, "three planes point")
            case.update({"point": E(x), "weight": clean(lam)})
        else:
            assert abs(vee[(4, 5)]) < 1e-9
            case["point"] = None
        cases.append(case)

    # line ^ plane: a point, or parallel
    for hit in ["one"] * 5 + ["parallel"] * 2:
        p, d, p0, n = rpoint(), rdir(), rpoint(2), rdir()
        if hit == "parallel":
            d = perp(n)
            p = p0 + rng.uniform(0.5, 2) * n + rng.uniform(-1, 1) * d
        L, P = line(p, d), plane(p0, n)
        vee, meet = vee_meet(L, P)
        case = {"kind": "line_plane", "line": {"point": E(p), "direction": E(d)},
                "plane": {"point": E(p0), "normal": E(n)}, "line_mv": mvl(L), "plane_mv": mvl(P),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet), "hit": hit}
        if hit == "one":
            t = np.dot(n, p0 - p) / np.dot(n, d)
            x = p + t * d
            fx, lam = flat_point_euc(vee)
            close(fx, x, "line plane point")
            close(lam, np.dot(d, n), "line plane weight")
            tp = tools.intersect_line_and_plane_to_point(L, P)
            close(down_w(tp)[0], x, "intersect_line_and_plane_to_point")
            case.update({"point": E(x), "weight": clean(lam), "tool_point": E(down_w(tp)[0])})
        else:
            assert abs(vee[(4, 5)]) < 1e-9
            case["point"] = None
        cases.append(case)

    # plane ^ plane: a line, or parallel
    for hit in ["one"] * 5 + ["parallel"] * 2:
        p1, n1, p2, n2 = rpoint(2), rdir(), rpoint(2), rdir()
        if hit == "parallel":
            n2 = n1 * rng.choice([-1.0, 1.0])
        P1, P2 = plane(p1, n1), plane(p2, n2)
        vee, meet = vee_meet(P1, P2)
        case = {"kind": "plane_plane", "plane1": {"point": E(p1), "normal": E(n1)},
                "plane2": {"point": E(p2), "normal": E(n2)}, "plane1_mv": mvl(P1), "plane2_mv": mvl(P2),
                "vee_mv": mvl(vee), "meet_mv": mvl(meet), "hit": hit}
        if hit == "one":
            u = np.cross(n1, n2)
            d1, d2 = np.dot(n1, p1), np.dot(n2, p2)
            x = (d1 * np.cross(n2, u) + d2 * np.cross(u, n1)) / np.dot(u, u)
            close([np.dot(n1, x), np.dot(n2, x)], [d1, d2], "plane plane point")
            img = {"point": x, "direction": unit(u)}
            lam = rel(vee, line(x, unit(u)), "plane plane line")
            close(abs(lam), np.linalg.norm(u), "plane plane weight")
            case.update({"line": jparams(img), "line_mv": mvl(line(x, unit(u))), "weight": lam})
        else:
            case["line"] = None  # vee_mv is then a free bivector ^ einf (the line at infinity)
        cases.append(case)

    # sphere ^ plane: a circle ("two" = real), tangent, miss
    for hit in ["two", "two", "two", "tangent", "miss", "miss"]:
        c, r, n = rpoint(2), rradius(), rdir()
        h = {"two": rng.uniform(-0.9, 0.9), "tangent": rng.choice([-1.0, 1.0]), "miss": rng.uniform(1.1, 2)}[hit] * r
        p0 = c + h * n + rng.uniform(-1, 1) * perp(n)
        S, P = sphere(c, r), plane(p0, n)
        vee, meet = vee_meet(S, P)
        hh = np.dot(n, c - p0)
        centre = c - hh * n
        r2 = r * r - hh * hh
        gc, gn, gr = tools.get_circle_in_euc(meet)
        close(eu(gc), centre, "sphere plane centre")
        close(math.copysign(gr * gr, gr), r2, "sphere plane radius^2", tol=1e-8)
        case = {"kind": "sphere_plane", "sphere": {"centre": E(c), "radius": r}, "plane": {"point": E(p0), "normal": E(n)},
                "sphere_mv": mvl(S), "plane_mv": mvl(P), "vee_mv": mvl(vee), "meet_mv": mvl(meet), "hit": hit,
                "square": clean(s0(vee * vee)),
                "circle": {"centre": E(centre), "normal": E(n), "radius_squared": clean(r2),
                           "radius": math.sqrt(r2) if hit == "two" else (0.0 if hit == "tangent" else None)},
                "tool_circle": {"centre": E(eu(gc)), "normal": E(eu(gn)), "radius": clean(gr)}}
        if hit == "two":
            case["orientation"] = sign_of(rel(vee.normal(), circle(centre, n, math.sqrt(r2)), "s^p circle"), "s^p")
        cases.append(case)
    return cases


def circle_parts():
    cases = []
    for _ in range(20):
        c, n, r = rpoint(), rdir(), rradius()
        C = circle(c, n, r)
        Pi = C ^ einf
        Pn = Pi.normal()
        plane_orientation = sign_of(rel(Pn, plane(c, n), "carrier plane"), "carrier plane")
        SC = tools.circle_to_sphere(C)
        close(SC.value, (C * Pn * I5).value, "circle_to_sphere formula")
        sphere_orientation = sign_of(rel(SC, sphere(c, r), "carrier sphere"), "carrier sphere")
        u, v = frame(n)
        phi = rng.uniform(0, 2 * math.pi)
        x = c + r * (math.cos(phi) * u + math.sin(phi) * v)
        X = up(x)
        T = (X << C) ^ einf
        tdir = np.cross(n, (x - c) / r)
        lam = rel(T, line(x, tdir), "tangent line")
        cases.append({"circle": {"centre": E(c), "normal": E(n), "radius": r}, "circle_mv": mvl(C),
                      "carrier_plane_mv": mvl(Pi), "carrier_plane_normalised": mvl(Pn),
                      "carrier_plane": {"point": E(c), "normal": E(n)}, "plane_orientation": plane_orientation,
                      "carrier_sphere_mv": mvl(SC), "carrier_sphere": {"centre": E(c), "radius": r},
                      "sphere_orientation": sphere_orientation,
                      "at": E(x), "at_mv": mvl(X), "tangent_line_mv": mvl(T),
                      "tangent_line": {"point": E(x), "direction": E(tdir)}, "tangent_weight": lam})
    return cases


def versors():
    cases = []
    # rotor between directions
    for i in range(14):
        a = rdir()
        b = a.copy() if i == 0 else rdir()
        if np.dot(a, b) < -0.95:
            b = unit(b + perp(b))
        R = (1 + V(b) * V(a))
        R = R / math.sqrt(2 * (1 + np.dot(a, b)))
        img = eu(R * V(a) * ~R)
        close(img, b, "rotor image")
        ang = math.acos(float(np.clip(np.dot(a, b), -1, 1)))
        axis = unit(np.cross(a, b)) if i else perp(a)
        close(R.value, rotor(axis, ang).value, "rotor axis angle")
        cases.append({"kind": "rotor_between_directions", "a": E(a), "b": E(b), "rotor": rotor4(R),
                      "rotor_mv": mvl(R), "image": E(img), "axis": E(axis), "angle": ang})
    xs_of = lambda: [rpoint() for _ in range(3)]
    # motor about a line
    for _ in range(8):
        p, d, th = rpoint(), rdir(), float(rng.uniform(-3, 3))
        L = line(p, d)
        B = -th / 2 * L * I5
        M = B.exp()
        close(M.value, (translator(p) * rotor(d, th) * ~translator(p)).value, "motor about line")
        xs = xs_of()
        imgs = [p + rodrigues(x - p, d, th) for x in xs]
        for x, y in zip(xs, imgs):
            close(moved(M, x)[0], y, "motor image")
        cases.append({"kind": "motor_about_line", "line": {"point": E(p), "direction": E(d)}, "line_mv": mvl(L),
                      "angle": th, "generator_mv": mvl(B(2)), "motor_mv": mvl(M), "xs": [E(x) for x in xs],
                      "images": [E(y) for y in imgs]})
    # screw: rotation by angle about the line and translation pitch * angle / (2 pi) along it
    for _ in range(6):
        p, d, th, pitch = rpoint(), rdir(), float(rng.uniform(-3, 3)), float(rng.uniform(-2, 2))
        L = line(p, d)
        shift = pitch * th / (2 * math.pi) * d
        B = -th / 2 * L * I5 + 0.5 * (einf * V(shift))
        M = translator(shift) * (-th / 2 * L * I5).exp()
        close(B.exp().value, M.value, "screw exp")
        close(general_logarithm(M).value, B(2).value, "screw log")
        xs = xs_of()
        imgs = [p + rodrigues(x - p, d, th) + shift for x in xs]
        for x, y in zip(xs, imgs):
            close(moved(M, x)[0], y, "screw image")
        cases.append({"kind": "screw", "line": {"point": E(p), "direction": E(d)}, "line_mv": mvl(L), "angle": th,
                      "pitch": pitch, "translation": E(shift), "generator_mv": mvl(B(2)), "motor_mv": mvl(M),
                      "xs": [E(x) for x in xs], "images": [E(y) for y in imgs]})
    # motor interpolation exp(t log(M1 M0~)) M0
    for j in range(6):
        while True:  # relative rotations below 2.6 rad (general_logarithm loses digits towards pi)
            a0, th0, t0 = rdir(), float(rng.uniform(-2.5, 2.5)), rpoint()
            if j == 5:  # same rotation: the relative motion is a pure translation
                a1, th1 = a0, th0
            else:
                a1, th1 = rdir(), float(rng.uniform(-2.5, 2.5))
            t1 = rpoint()
            R0, R1 = rot_matrix(a0, th0), rot_matrix(a1, th1)
            Rrel = R1 @ R0.T
            sc = chasles(Rrel, t1 - Rrel @ t0)
            # and a relative rotor with a positive scalar part: general_logarithm then gives the
            # shortest screw (a negative one would interpolate the long way round).
            if sc[1] < 2.6 and s0(rotor(a1, th1) * ~rotor(a0, th0)) > 0:
                break
        M0, M1 = translator(t0) * rotor(a0, th0), translator(t1) * rotor(a1, th1)
        Mrel = M1 * ~M0
        Lg = general_logarithm(Mrel)
        close(Lg.exp().value, Mrel.value, "log round trip")
        xs = xs_of()
        samples = []
        ts = [0, 0.25, 0.5, 0.75, 1] + [float(rng.uniform(-0.5, 1.5)) for _ in range(2)]
        for tt in ts:
            Mt = (tt * Lg).exp() * M0
            imgs = [screw_apply(R0 @ x + t0, sc, tt) for x in xs]
            for x, y in zip(xs, imgs):
                close(moved(Mt, x)[0], y, "interpolated image")
            samples.append({"t": tt, "motor_mv": mvl(Mt), "images": [E(y) for y in imgs]})
        cases.append({"kind": "motor_interpolate",
                      "m0": {"axis": E(a0), "angle": th0, "translation": E(t0)},
                      "m1": {"axis": E(a1), "angle": th1, "translation": E(t1)},
                      "m0_mv": mvl(M0), "m1_mv": mvl(M1), "relative_mv": mvl(Mrel), "log_mv": mvl(Lg),
                      "screw": {"axis": None if sc[0] is None else E(sc[0]), "angle": sc[1], "point": E(sc[2]),
                                "slide": clean(sc[3]) if sc[0] is not None else E(sc[3])},
                      "xs": [E(x) for x in xs], "samples": samples})
    # motor power exp(t log M)
    for _ in range(6):
        a, th, tv = rdir(), float(rng.uniform(-2.8, 2.8)), rpoint()
        tt = float(rng.uniform(-1, 2))
        M = translator(tv) * rotor(a, th)
        Lg = general_logarithm(M)
        Mt = (tt * Lg).exp()
        sc = chasles(rot_matrix(a, th), tv)
        xs = xs_of()
        imgs = [screw_apply(x, sc, tt) for x in xs]
        for x, y in zip(xs, imgs):
            close(moved(Mt, x)[0], y, "motor power image")
        cases.append({"kind": "motor_pow", "m": {"axis": E(a), "angle": th, "translation": E(tv)}, "m_mv": mvl(M),
                      "log_mv": mvl(Lg), "t": tt, "result_mv": mvl(Mt), "xs": [E(x) for x in xs],
                      "images": [E(y) for y in imgs]})
    # dilator about c by factor s
    for _ in range(6):
        c, s = rpoint(2), float(math.exp(rng.uniform(-1.2, 1.2)))
        D0 = tools.generate_dilation_rotor(s)
        g = math.log(s)
        close(D0.value, (math.cosh(g / 2) - math.sinh(g / 2) * E45).value, "dilator formula")
        close(D0.value, (-g / 2 * E45).exp().value, "dilator exp")
        D = translator(c) * D0 * ~translator(c)
        xs = xs_of()
        imgs, ws = [], []
        for x in xs:
            y, w = moved(D, x)
            close(y, c + s * (x - c), "dilated point")
            close(w, 1 / s, "dilated weight")
            imgs.append(y)
            ws.append(w)
        c2, r2 = rpoint(), rradius()
        S = sphere(c2, r2)
        Sd = D * S * ~D
        img = {"centre": c + s * (c2 - c), "radius": s * r2}
        lam = rel(Sd, sphere(img["centre"], img["radius"]), "dilated sphere")
        cases.append({"kind": "dilator", "centre": E(c), "factor": s, "versor_mv": mvl(D), "origin_versor_mv": mvl(D0),
                      "xs": [E(x) for x in xs], "images": [E(y) for y in imgs], "weights": ws,
                      "sphere": {"centre": E(c2), "radius": r2}, "sphere_mv": mvl(S), "sphere_image_mv": mvl(Sd),
                      "sphere_image": jparams(img), "sphere_weight": lam})
    # transversor 1 + eo t
    for _ in range(6):
        tv = rpoint(0.4)
        K = 1 + eo * V(tv)
        xs = xs_of()
        imgs, ws = [], []
        for x in xs:
            y, w = moved(K, x)
            den = 1 + 2 * np.dot(tv, x) + np.dot(tv, tv) * np.dot(x, x)
            close(y, (x + np.dot(x, x) * tv) / den, "transversor image")
            close(w, den, "transversor weight")
            imgs.append(y)
            ws.append(w)
        cases.append({"kind": "transversor", "t": E(tv), "versor_mv": mvl(K), "xs": [E(x) for x in xs],
                      "images": [E(y) for y in imgs], "weights": ws})
    return cases


def classify():
    out = []

    def add(kind, X, grade, form, params):
        Xk = only_grade(X, grade, kind)
        out.append({"kind": kind, "grade": grade, "form": form, "mv": mvl(Xk), "params": params,
                    "square": clean(s0(Xk * Xk)), "norm_squared": clean(s0(Xk * ~Xk))})

    x = rpoint()
    add("conformal point", up(x), 1, "direct", {"x": E(x)})
    add("origin (eo)", eo, 1, "direct", {"x": [0.0, 0.0, 0.0]})
    add("infinity (einf)", einf, 1, "direct", {})
    for _ in range(2):
        c, r = rpoint(), rradius()
        add("real sphere", sphere(c, r), 4, "direct", {"centre": E(c), "radius": r, "radius_squared": r * r})
    c, r = rpoint(), rradius()
    add("imaginary sphere", undual(imaginary_sphere_dual(c, r)), 4, "direct",
        {"centre": E(c), "radius_squared": -r * r})
    c, r = rpoint(), rradius()
    add("dual real sphere", sphere_dual(c, r), 1, "dual", {"centre": E(c), "radius": r, "radius_squared": r * r})
    c, r = rpoint(), rradius()
    add("dual imaginary sphere", imaginary_sphere_dual(c, r), 1, "dual", {"centre": E(c), "radius_squared": -r * r})
    for _ in range(2):
        c, n, r = rpoint(), rdir(), rradius()
        add("real circle", circle(c, n, r), 3, "direct", {"centre": E(c), "normal": E(n), "radius": r, "radius_squared": r * r})
    c, n, r = rpoint(), rdir(), rradius()
    Cim = -(undual(imaginary_sphere_dual(c, r)) & plane(c, n))
    add("imaginary circle", Cim, 3, "direct", {"centre": E(c), "normal": E(n), "radius_squared": -r * r})
    c, n, r = rpoint(), rdir(), rradius()
    add("dual real circle", dual(circle(c, n, r)), 2, "dual", {"centre": E(c), "normal": E(n), "radius": r, "radius_squared": r * r})
    a, b = rpoint(), rpoint()
    add("point pair real", pair(a, b), 2, "direct",
        {"a": E(a), "b": E(b), "centre": E((a + b) / 2), "direction": E(unit(b - a)),
         "radius_squared": float(np.dot(b - a, b - a) / 4)})
    c, d, r = rpoint(), rdir(), rradius()
    add("point pair real", line(c, d) & sphere(c, r), 2, "direct",
        {"a": E(c - r * d), "b": E(c + r * d), "centre": E(c), "direction": E(d), "radius_squared": r * r})
    c, d, r = rpoint(), rdir(), rradius()
    add("point pair imaginary", line(c, d) & undual(imaginary_sphere_dual(c, r)), 2, "direct",
        {"centre": E(c), "direction": E(d), "radius_squared": -r * r})
    a, b = rpoint(), rpoint()
    add("dual point pair real", dual(pair(a, b)), 3, "dual", {"a": E(a), "b": E(b)})
    x, u = rpoint(), rdir() * rradius()
    tv = up(x) ^ (V(u) + float(np.dot(x, u)) * einf)
    assert abs(s0(tv * tv)) < 1e-9
    add("tangent vector", tv, 2, "direct", {"point": E(x), "direction": E(u)})
    x, u, v = rpoint(), rdir(), rdir()
    tb = up(x) ^ (V(u) + float(np.dot(x, u)) * einf) ^ (V(v) + float(np.dot(x, v)) * einf)
    assert abs(s0(tb * tb)) < 1e-9
    add("tangent bivector", tb, 3, "direct", {"point": E(x), "normal": E(unit(np.cross(u, v))), "u": E(u), "v": E(v)})
    add("dual tangent vector", dual(tv), 3, "dual", dict(out[-2]["params"]))
    x = rpoint()
    add("tangent trivector (zero-radius sphere)", undual(up(x)), 4, "direct", {"point": E(x), "radius_squared": 0.0})
    for _ in range(2):
        p, d = rpoint(), rdir()
        add("line", line(p, d), 3, "direct", {"point": E(p), "direction": E(d)})
    p, d = rpoint(), rdir()
    add("dual line", dual(line(p, d)), 2, "dual", {"point": E(p), "direction": E(d)})
    for _ in range(2):
        p, n = rpoint(), rdir()
        add("plane", plane(p, n), 4, "direct", {"point": E(p), "normal": E(n), "offset": float(np.dot(n, p))})
    p, n = rpoint(), rdir()
    add("dual plane", plane_dual(p, n), 1, "dual", {"point": E(p), "normal": E(n), "offset": float(np.dot(n, p))})
    x = rpoint()
    add("flat point", flat_point(x), 2, "direct", {"x": E(x)})
    x = rpoint()
    add("dual flat point", dual(flat_point(x)), 3, "dual", {"x": E(x)})
    u = rdir() * rradius()
    add("direction (free vector)", V(u) ^ einf, 2, "direct", {"direction": E(u)})
    u, v = rdir(), rdir()
    add("free bivector", V(u) ^ V(v) ^ einf, 3, "direct", {"u": E(u), "v": E(v), "normal": E(unit(np.cross(u, v)))})
    add("free trivector", I3 ^ einf, 4, "direct", {})
    u = rdir()
    add("dual direction (free vector)", dual(V(u) ^ einf), 3, "dual", {"direction": E(u)})
    return out


# ---------------------------------------------------------------------------------------------

CONVENTION = {
    "basis": "orthonormal e1,e2,e3,e4,e5 with e1^2=e2^2=e3^2=e4^2=+1 and e5^2=-1",
    "null_vectors": "einf = e4 + e5, eo = (e5 - e4)/2 = clifford's layout.eo; clifford.tools.g3c defines no = -eo and ninf = einf "
                    "(so its 'ninf ^ no' = -einf ^ eo = -e45)",
    "up": "up(x) = x + 0.5 x^2 einf + eo, up(x) . einf = -1; a weighted point w up(x) has weight w = -X . einf",
    "pseudoscalar": "I5 = e12345, I5^2 = -1, central (commutes with everything); I3 = e123",
    "dual": "dual(A) = A I5^-1 = -A I5, undual(A) = A I5",
    "vee_and_meet": "vee_mv is clifford's A & B (MultiVector.vee), the product that products.json calls 'vee' and cga-core's & "
                    "computes; meet_mv is clifford.tools.g3c.meet(A, B) = I5((I5 A) ^ (I5 B)) = ((A I5) ^ (B I5)) I5. They are NOT "
                    "the same: vee = (-1)^((5-gA)(5-gB)) meet, so they differ in sign exactly when both co-grades are odd "
                    "(gA, gB in {2, 4}): sphere^sphere, sphere^plane, plane^plane, point pair^plane. Equal for line/circle with "
                    "anything, and for three planes the nested vee(vee) = -meet(meet). (Asserted here for every meet.)",
    "normalise": "lines, planes, circles, spheres made by the constructors below satisfy X X~ = -1 (clifford .normal()); "
                 "point pairs up(a)^up(b) are left unnormalised",
    "versors": "X' = V X V~ for even versors; rotor R = cos(th/2) - sin(th/2) a I3 (right-handed by th about a), translator "
               "T = 1 + einf t/2 = 1 - t einf/2 (clifford generate_translation_rotor), motor M = T R (rotate, then translate)",
    "reflection_signs": "for an odd versor V with V^2 = -1 (a normalised plane P = undual(pi) or sphere S = undual(sigma), both grade 4) "
                        "the map on a blade X of grade k is X' = (-1)^k V X V^-1 = (-1)^(k+1) V X V; with the unit dual vector "
                        "(pi or sigma, pi^2 = sigma^2 = +1) it is (-1)^k pi X pi. So points (k=1) and lines/circles (k=3) take "
                        "+P X P, point pairs (k=2) and planes/spheres (k=4) take -P X P. A line L (L^2 = +1) reflects "
                        "(half-turn) with L X L for every grade; a point c reflects with the flat point F = up(c)^einf "
                        "(F^2 = +1) as (-1)^k F X F",
    "orientation": "every transformed blade equals the wedge of the transformed defining points in the same order (einf -> "
                   "einf for reflections, einf -> +(2/R^2) up(c) for inversion in the sphere (c, R); asserted). Each case "
                   "records 'orientation' (+1/-1) = transformed blade / constructor(Euclidean image parameters)",
}

CONSTRUCTORS = {
    "point": "params {x}: up(x) (unit weight)",
    "point_pair": "params {a, b}: up(a) ^ up(b), unnormalised (cga-core Bivector::from_points)",
    "line": "params {point, direction (unit)}: up(p) ^ up(p + d) ^ einf normalised (cga-core Line::from_point_direction)",
    "plane": "params {point, normal (unit)}: undual(-(n + (n.p) einf)) = up(p)^up(p+u)^up(p+v)^einf normalised with u x v = n "
             "(cga-core Plane::from_point_normal); clifford's get_plane_normal(P) = n, get_plane_origin_distance(P) = n.p",
    "sphere": "params {centre, radius}: undual((up(c) - r^2/2 einf)/r) (cga-core Sphere::from_centre_radius); "
              "up(a)^up(b)^up(c)^up(d) is -sphere when (b-a).((c-a)x(d-a)) > 0",
    "circle": "params {centre, normal (unit), radius}: -(sphere(c, r) & plane(c, n)) = up(a)^up(b)^up(c) normalised for three "
              "points counter-clockwise about n (cga-core Circle::from_centre_normal_radius)",
}

# ---------------------------------------------------------------------------------------------
# Flats onto flats, lines meeting lines, point pairs meeting objects (appended after the
# families above, so their cases and the random stream they draw are unchanged).

def flat_mv(kind, f):
    return {"line": lambda: line(f["point"], f["direction"]), "plane": lambda: plane(f["point"], f["normal"]),
            "point": lambda: flat_point(f["x"])}[kind]()


def on_opns(x, A):
    """up(x) lies on the OPNS blade A: |up(x) ^ A| within 1e-9 of the sizes involved."""
    return biggest(up(x) ^ A) <= TOL * max(biggest(A), 1.0) * max(1.0, float(np.dot(x, x)))


def project_flats():
    """Every ordered pair of point, line and plane: oblique, and each degenerate relation (perpendicular
    lines, a plane onto a line along its normal, perpendicular planes, a line along a plane's normal)."""
    cases = []
    plan = [("line", "line", "oblique")] * 4 + [("line", "line", "perpendicular")] * 2 + \
        [("plane", "plane", "oblique")] * 3 + [("plane", "plane", "perpendicular")] * 2 + \
        [("plane", "line", "oblique")] * 3 + [("plane", "line", "along_normal")] * 2 + \
        [("line", "plane", "along_normal")] * 2 + [("point", "line", "oblique")] * 2 + \
        [("point", "plane", "oblique")] * 2 + [("line", "point", "oblique")] * 1 + [("plane", "point", "oblique")] * 1
    for ka, kb, rel_ in plan:
        pa, pb, da, db = rpoint(), rpoint(2), rdir(), rdir()
        if rel_ == "perpendicular":
            da = unit(np.cross(db, rdir()))
        if rel_ == "along_normal":
            da = db.copy() * (1 if rng.rand() < 0.5 else -1)
        if rel_ == "oblique" and abs(np.dot(da, db)) < 0.2:
            da = unit(da + db)
        fa = {"line": {"point": pa, "direction": da}, "plane": {"point": pa, "normal": da}, "point": {"x": pa}}[ka]
        fb = {"line": {"point": pb, "direction": db}, "plane": {"point": pb, "normal": db}, "point": {"x": pb}}[kb]
        A, B = flat_mv(ka, fa), flat_mv(kb, fb)
        ga, gb = max(A.grades()), max(B.grades())
        blade = (A << B) * B.inv() if ga <= gb else 0 * A
        # The Euclidean image: closed forms per case (numpy), and clifford's meet where the image
        # is where two flats cross.
        if kb == "point":
            image = {"kind": "point", "x": pb}
        elif ka == "point":
            x = pa - np.dot(pa - pb, db) * db if kb == "plane" else foot_on_line(pa, pb, db)
            image = {"kind": "point", "x": x}
        elif (ka, kb) == ("line", "line"):
            if rel_ == "perpendicular":
                # The foot of the closest points on line b: the common perpendicular's end.
                n = np.cross(da, db)
                t = float(np.dot(np.cross(pb - pa, da), n) / np.dot(n, n))
                close(pb + t * db, foot_on_line(pa, pb, db), "closest point = foot")
                image = {"kind": "point", "x": pb + t * db}
            else:
                image = {"kind": "line", "point": foot_on_line(pa, pb, db), "direction": np.sign(np.dot(da, db)) * db}
        elif (ka, kb) == ("plane", "plane"):
            if rel_ == "perpendicular":
                M = B & A  # clifford's meet of the planes, a line in the plane b
                image = {"kind": "line", "point": None, "direction": None, "mv": M}
            else:
                image = {"kind": "plane", "point": pb, "normal": np.sign(np.dot(da, db)) * db}
        elif (ka, kb) == ("plane", "line"):
            if rel_ == "along_normal":
                Fp = A & B  # clifford's meet: a flat point
                image = {"kind": "point", "x": flat_point_euc(Fp)[0]}
            else:
                image = {"kind": "line", "point": pb, "direction": db}
        else:  # a line along a plane's normal: its foot
            image = {"kind": "point", "x": pa - np.dot(pa - pb, db) * db}
        case = {"kind": "%s_onto_%s" % (ka, kb), "relation": rel_, "a": jparams(fa), "b": jparams(fb),
                "a_mv": mvl(A), "b_mv": mvl(B), "blade_mv": mvl(blade), "blade_zero": bool(biggest(blade) < 1e-12)}
        if image["kind"] == "line" and image["point"] is None:
            Mn = image.pop("mv").normal()
            d = unit(np.cross(da, db))
            # A point on both planes: solve n_a.x = n_a.pa, n_b.x = n_b.pb, d.x = d.pb.
            x0 = np.linalg.solve(np.array([da, db, d]), np.array([np.dot(da, pa), np.dot(db, pb), np.dot(d, pb)]))
            assert on_opns(x0, Mn) and on_opns(x0 + d, Mn), "plane meet"
            image.update({"point": x0, "direction": d})
            case["meet_mv"] = mvl(Mn)
        if image["kind"] == "point":
            assert on_opns(image["x"], B), ("image off b", case["kind"])
        elif image["kind"] == "line":
            Y = line(image["point"], image["direction"])
            assert biggest(Y ^ B) < 1e-9 or kb == "line", "image line not in b"
            if not case["blade_zero"]:
                lam = rel(blade, Y, "projected flat")
                assert lam > 0, ("blade orientation", lam)
                case["weight"] = lam
        else:
            Y = plane(image["point"], image["normal"])
            lam = rel(blade, Y, "projected plane")
            assert lam > 0, ("blade orientation", lam)
            case["weight"] = lam
        case["image"] = dict(kind=image.pop("kind"), **jparams(image))
        cases.append(case)
    return cases


def line_meets():
    """Two lines: crossing (the point on both, checked with clifford's up(x) ^ L = 0), parallel,
    skew, the same line."""
    cases = []
    for what in ["cross"] * 4 + ["parallel"] * 2 + ["skew"] * 2 + ["same"] * 2:
        x, d1, d2 = rpoint(), rdir(), rdir()
        p1, p2 = x + rng.uniform(-2, 2) * d1, x + rng.uniform(-2, 2) * d2
        if what == "parallel":
            d2 = d1 * (1 if rng.rand() < 0.5 else -1)
            p2 = p1 + 0.7 * perp(d1) + rng.uniform(-1, 1) * d1
        if what == "skew":
            p2 = p2 + 0.5 * unit(np.cross(d1, d2))
        if what == "same":
            d2, p2 = -d1, p1 + rng.uniform(-2, 2) * d1
        L1, L2 = line(p1, d1), line(p2, d2)
        case = {"kind": what, "line1": {"point": E(p1), "direction": E(d1)}, "line2": {"point": E(p2), "direction": E(d2)},
                "line1_mv": mvl(L1), "line2_mv": mvl(L2), "vee_mv": mvl(L1 & L2)}
        if what == "cross":
            assert on_opns(x, L1) and on_opns(x, L2), "crossing point"
            case["point"] = E(x)
        cases.append(case)
    return cases


def pair_meets():
    """A point pair against a sphere, plane, line, circle, another pair and a point: 0, 1 or 2 of its
    points on the object, each decided by clifford (up(x) ^ A = 0 for the OPNS object A) and by
    construction. Imaginary pairs (line & sphere missing it) have no real points."""
    cases = []
    for kind in ["sphere", "plane", "line", "circle", "pair", "point"]:
        for on_count in [2, 1, 0]:
            if kind == "point" and on_count == 2:
                continue
            c, n, r = rpoint(2), rdir(), rradius()
            u, v = frame(n)
            if kind == "sphere":
                obj, prm = sphere(c, r), {"centre": c, "radius": r}
                on_pts = [c + r * rdir(), c + r * rdir()]
            elif kind == "plane":
                obj, prm = plane(c, n), {"point": c, "normal": n}
                on_pts = [c + 1.5 * u - 0.5 * v, c - 0.8 * u + 2.0 * v]
            elif kind == "line":
                obj, prm = line(c, n), {"point": c, "direction": n}
                on_pts = [c + 1.3 * n, c - 2.1 * n]
            elif kind == "circle":
                obj, prm = circle(c, n, r), {"centre": c, "normal": n, "radius": r}
                on_pts = [c + r * u, c + r * (0.6 * u + 0.8 * v)]
            elif kind == "pair":
                a0, b0 = rpoint(), rpoint()
                obj, prm = pair(a0, b0), {"a": a0, "b": b0}
                on_pts = [b0, a0]
            else:
                obj, prm = up(c), {"x": c}
                on_pts = [c, c]
            off = [q + 0.37 * unit(rdir()) * r for q in on_pts]
            off = [q if not on_opns(q, obj) else q + 0.5 * n for q in off]
            a = on_pts[0] if on_count >= 1 else off[0]
            b = on_pts[1] if on_count == 2 else off[1]
            P = pair(a, b)
            ends = pp_points_euc(P)
            same_set(ends, [a, b], "pair ends")
            on = [bool(on_opns(q, obj)) for q in ends]
            assert sum(on) == on_count, (kind, on_count, on)
            cases.append({"kind": kind, "pair": {"a": E(a), "b": E(b)}, "pair_mv": mvl(P), "object": jparams(prm),
                          "object_mv": mvl(obj), "ends": [E(q) for q in ends], "on": on})
    # Imaginary pairs: a line missing a sphere.
    for _ in range(2):
        c, r, d = rpoint(2), rradius(), rdir()
        p = c + 1.5 * r * perp(d)
        P = line(p, d) & sphere(c, r)
        assert s0(P * P) < 0
        cases.append({"kind": "imaginary", "pair_mv": mvl(P), "object": jparams({"centre": c, "radius": r}),
                      "object_mv": mvl(sphere(c, r)), "ends": None, "on": [False, False]})
    return cases


FAMILIES = {
    "reflect_in_plane": "24 cases, kinds point, point_pair, line, circle, sphere, plane. mirror {point, normal}, mirror_mv P "
                        "(plane constructor), mirror_dual_mv pi = dual(P) = -(n + (n.p) einf); kind, grade k; object (params of "
                        "the kind, see constructors), object_mv X; sandwich = <P X P>_k (raw); reflected = (-1)^(k+1) P X P = "
                        "(-1)^k pi X pi, the blade of the mirrored defining points; image = the mirrored Euclidean parameters "
                        "(points x - 2((x-p).n)n, directions and normals v - 2(v.n)n, radius kept); image_mv = constructor(image); "
                        "orientation = reflected / image_mv (+1 point, point pair, line; -1 circle, sphere, plane: a mirror "
                        "reverses handedness). how: plain multivector formula (clifford has no reflection tool)",
    "invert_in_sphere": "22 cases. sphere {centre c, radius R}, sphere_mv S (sphere constructor, S^2 = -1), sphere_dual_mv sigma; "
                        "kind, grade k, case (point, line, line_through [through c], circle, circle_through, sphere, sphere_around "
                        "[c inside], sphere_through, plane, plane_through); object, object_mv X; sandwich = <S X S>_k; inverted = "
                        "(-1)^(k+1) S X S = (-1)^k sigma X sigma; image_kind and image (Euclidean: point c + R^2 (x-c)/|x-c|^2; "
                        "line -> circle through c [normal of the circle through the images of p, p+d and c in that order], "
                        "circle -> circle [through the images of its three ccw points, in order], sphere (c2, r2) -> sphere centre "
                        "c + s(c2-c), radius |s| r2, s = R^2/(|c2-c|^2 - r2^2); sphere through c -> plane, normal (c2-c)/|c2-c|, "
                        "through c + R^2/(2 r2) normal; plane (n, h = n.(p-c) != 0) -> sphere centre c + R^2 n/(2h), radius "
                        "R^2/(2|h|); flats through c -> themselves); image_mv = constructor(image); points: weight = inverted / "
                        "up(image) = |x-c|^2/R^2; others: orientation = inverted / image_mv (+1/-1). how: plain formula",
    "reflect_in_point": "20 cases (14 points, 3 lines, 3 spheres). centre c; versor_mv F = up(c) ^ einf (F^2 = 1); odd_versor_mv "
                        "dual(F); kind, grade k, object, object_mv; sandwich = <F X F>_k; reflected = (-1)^k F X F = (-1)^k V X V^-1 "
                        "for V = dual(F); image (x -> 2c - x, directions -> -d); image_mv; orientation (+1 line, -1 sphere)",
    "reflect_in_line": "20 cases (12 points, 3 lines, 3 circles, 2 spheres). axis {point q, direction u}, axis_mv L (L^2 = 1); "
                       "motor_mv = exp(-pi/2 L I5) = -L I5 (the half-turn motor, M X M~ = L X L); kind, grade, object, object_mv; "
                       "reflected = L X L (no sign, any grade); image (x -> 2(q + ((x-q).u)u) - x, directions v -> 2(v.u)u - v); "
                       "image_mv; orientation (+1: a half-turn is proper)",
    "project_point": "20 cases, target_kind line, plane, sphere, circle, point_pair. target (params), target_mv, x, x_mv; projection = "
                     "Euclidean nearest point of the target (line: foot; plane: x - ((x-p).n)n; sphere: c + r (x-c)/|x-c|; circle: "
                     "c + r (y-c)/|y-c| with y the foot of x on its plane; point pair: the nearer end); reject = x - projection; "
                     "distance = |reject|; tool = the clifford.tools.g3c function used, tool_point_mv its (normalised) conformal "
                     "point, tool_point its Euclidean point (asserted = projection). line/plane also formula_mv = <(x _| A) A^-1>_1, "
                     "a dual sphere centred at the projection. sphere also far_point (the antipode, closest=False). point_pair "
                     "also tool_end_points (point_pair_to_end_points order)",
    "project_flat": "20 cases. line {point, direction}, line_mv L, plane {point, normal}, plane_mv P; projected_mv = <(L _| P) P^-1>_3 "
                    "(raw, left contraction); image {point: foot of the line's point on the plane, direction: unit(d - (d.n)n)}; "
                    "image_mv = line(image); weight = projected_mv / image_mv = |d - (d.n)n| = cos(angle to the plane) > 0",
    "distances": "kinds: point_point {a, b, a_mv, b_mv, distance, mv_value = -2 A.B = distance^2}; point_line {x, line, x_mv, line_mv, "
                 "distance, foot, mv_value = |up(x) ^ L| = distance}; point_plane {x, plane, x_mv, plane_mv, distance = (x-p).n signed "
                 "(positive on the normal's side), foot, mv_value = up(x) . (P I5) = distance}; point_sphere {x, sphere, x_mv, "
                 "sphere_mv, distance = |x-c| - r signed, nearest, mv_value = up(x) . dual(S) = (r^2 - |x-c|^2)/(2r)}; line_line "
                 "{flag skew|intersecting|parallel, line1, line2, line1_mv, line2_mv, distance, closest1 (on line1), closest2 (on "
                 "line2; parallel: closest1 = line1.point and closest2 its foot on line2), product_scalar = <L1 L2>_0 = d1.d2, "
                 "product_e123inf = the e1234 (= e1235) coefficient of <L1 L2>_4 = (p2-p1).(d1 x d2) (so distance = "
                 "|product_e123inf| / |d1 x d2| when not parallel), tool_midpoint = clifford midpoint_between_lines (not parallel)}",
    "angles": "21 cases, kind line_line | plane_plane | line_plane, special parallel | perpendicular | generic. a, b (params), a_mv, "
              "b_mv; angle unoriented in [0, pi/2] (line_line acos|d1.d2|, plane_plane acos|n1.n2|, line_plane asin|d.n|); "
              "angle_oriented (acos(d1.d2) in [0, pi], acos(n1.n2) in [0, pi], asin(d.n) in [-pi/2, pi/2]); mv_value and "
              "mv_formula: <L1 L2>_0 = d1.d2, <P1 P2>_0 = -n1.n2, e45 coefficient of L & P = -d.n",
    "meets": "kinds line_circle (the line in the circle's plane), sphere_sphere, circle_plane, line_sphere, three_planes, line_plane, "
             "plane_plane, sphere_plane. Inputs (params) and their _mv; vee_mv = A & B (cga-core's &) and meet_mv = "
             "tools.g3c.meet(A, B) (see convention.vee_and_meet); hit. Point-pair kinds (line_circle, circle_plane, line_sphere): "
             "hit two|tangent|miss from the construction, square = <P P>_0 of vee_mv (>0 two, ~0 tangent, <0 miss), points "
             "(Euclidean, closed form; ordered along the line's direction, for circle_plane along order_direction = "
             "unit(n_circle x n_plane); a tangent gives the touching point twice; null for a miss), tool_points (clifford "
             "point_pair_to_end_points of vee_mv, in its order; hit two only). line_circle: vee_mv = L & S_C with S_C = "
             "carrier_sphere_mv = tools.circle_to_sphere(C) (= carrier_sphere_orientation * sphere(c, r)); in_plane_mv = "
             "<((L Pi^-1) ^ (C Pi^-1)) Pi>_2 with Pi = (C ^ einf) normalised, the meet inside the plane, = in_plane_vs_vee * "
             "vee_mv (L & C itself vanishes for coplanar blades). Circle kinds (sphere_sphere, sphere_plane): hit two (a real "
             "circle)|tangent|miss (an imaginary circle), square, circle {centre, normal (sphere_sphere: (c2-c1)/|c2-c1|; "
             "sphere_plane: the plane's), radius_squared (signed; negative for a miss), radius (null for a miss)}, tool_circle = "
             "clifford get_circle_in_euc of meet_mv (radius negative when imaginary, normal sign its own), orientation (hit "
             "two) = normalised vee_mv / circle(centre, normal, radius). three_planes: planes [3], planes_mv, vee_mv = "
             "(P1 & P2) & P3, meet_mv = meet(meet(P1, P2), P3), hit one|parallel, point, weight = lam of vee_mv = lam (x ^ "
             "einf + eo ^ einf) (x_k = -vee[e_k4]/vee[e45]). line_plane: hit one|parallel, point, weight (lam = d.n), "
             "tool_point (intersect_line_and_plane_to_point). plane_plane: hit one|parallel, line {point nearest the origin, "
             "direction unit(n1 x n2)}, line_mv, weight = vee_mv / line_mv (= +-|n1 x n2|)",
    "circle_parts": "20 cases. circle (params), circle_mv C; carrier_plane_mv = C ^ einf (raw), carrier_plane_normalised, carrier_plane "
                    "{point = centre, normal}, plane_orientation = normalised(C ^ einf) / plane(c, n); carrier_sphere_mv = "
                    "tools.circle_to_sphere(C) = C Pi I5 (Pi normalised), carrier_sphere {centre, radius}, sphere_orientation = "
                    "carrier_sphere_mv / sphere(c, r); at (a point on the circle), at_mv; tangent_line_mv = (up(at) _| C) ^ einf, "
                    "tangent_line {point = at, direction = n x (at - c)/r, the counter-clockwise tangent}, tangent_weight = "
                    "tangent_line_mv / line(tangent_line)",
    "versors": "kinds: rotor_between_directions {a, b unit; rotor [s, e12, e13, e23] = (1 + b a)/sqrt(2(1 + a.b)), the shortest "
               "rotation, = cos(angle/2) - sin(angle/2) axis I3; rotor_mv; image = R a R~ (= b); axis unit(a x b) (any perpendicular "
               "when a = b); angle}; motor_about_line {line, line_mv L, angle th, generator_mv B = -th/2 L I5, motor_mv = exp(B) "
               "(right-handed by th about the line's direction), xs, images (Rodrigues about the line)}; screw {line, line_mv, "
               "angle, pitch, translation = pitch*angle/(2 pi) * direction (pitch = advance per full turn), generator_mv = -th/2 L "
               "I5 + einf t/2 = general_logarithm(motor), motor_mv = T(translation) exp(-th/2 L I5), xs, images}; "
               "motor_interpolate {m0, m1 {axis, angle, translation}: M = T(translation) R(axis, angle), i.e. x -> R x + t; m0_mv, "
               "m1_mv, relative_mv = M1 M0~ (its scalar part > 0: the relative turn is below pi, so the principal log "
               "is the shortest screw), log_mv = clifford general_logarithm(relative_mv), screw = the Euclidean Chasles "
               "decomposition of the relative motion {axis, angle in [0, pi), point on the axis, slide along it} (axis null and "
               "slide a vector when it is a pure translation), xs, samples [{t, motor_mv = exp(t log_mv) M0 (clifford mv.exp), "
               "images = the screw by t*angle and t*slide applied to M0's images}]}; motor_pow {m, m_mv, log_mv, t, result_mv = "
               "exp(t log M), xs, images}; dilator {centre c, factor s, origin_versor_mv D0 = clifford generate_dilation_rotor(s) "
               "= cosh(g/2) - sinh(g/2) e45 = exp(-g/2 e45), g = ln s (e45 = einf ^ eo); versor_mv D = T(c) D0 T(c)~; xs, images "
               "(c + s(x - c)), weights (D up(x) D~ = weight up(image), weight = 1/s); sphere, sphere_mv, sphere_image_mv = D S D~, "
               "sphere_image {centre c + s(c2 - c), radius s r}, sphere_weight = sphere_image_mv / sphere(sphere_image) (= 1: a dilator keeps a normalised sphere normalised)}; "
               "transversor {t, versor_mv K = 1 + eo t (= 1 + eo ^ t), xs, images = (x + |x|^2 t)/(1 + 2 t.x + |t|^2 |x|^2), weights "
               "= 1 + 2 t.x + |t|^2|x|^2 (K up(x) K~ = weight up(image))}",
    "classify": "~33 blades: kind (label known by construction), grade, form (direct = OPNS, dual = IPNS), mv, params (Euclidean, per "
                "kind: centre/radius/radius_squared, normal, direction, point, a/b ends), square = <X X>_0, norm_squared = <X X~>_0. "
                "Imaginary rounds: dual (up(c) + r^2/2 einf)/r (radius_squared = -r^2); imaginary circle = -(imaginary sphere & "
                "plane(c, n)); point pairs as line(c, d) & sphere; tangent vector up(x) ^ (u + (x.u) einf) (the limit of up(x) ^ "
                "up(x + e u)/e, square 0); tangent bivector likewise with u and v; tangent trivector = undual(up(x)) (the zero-"
                "radius sphere); flat point up(x) ^ einf; direction (free vector) u ^ einf; free bivector u ^ v ^ einf; free "
                "trivector e123 ^ einf; dual forms = dual(X) = -X I5",
    "project_flats": "24 cases, kind A_onto_B for A, B in point (the flat point up(x) ^ einf), line, plane; relation oblique, "
                     "perpendicular (lines, planes), along_normal (a plane onto a line along its normal, a line along a plane's "
                     "normal). a, b {point, direction | point, normal | x}, a_mv, b_mv; blade_mv = (A _| B) B^-1 where grade A <= "
                     "grade B (else 0), blade_zero; image {kind point {x} | line {point, direction} | plane {point, normal}}: the set "
                     "the orthogonal projection onto B maps A to, in closed form (numpy), directed as blade_mv (weight = blade_mv / "
                     "image's constructor > 0) where that is nonzero; where it is zero: perpendicular lines give the closest point on "
                     "b, a plane onto a line along its normal the flat point of clifford's meet A & B, perpendicular planes their line "
                     "along n_a x n_b (checked on clifford's meet B & A), a plane onto a line not along its normal the line b as given; "
                     "every image point is checked on B with clifford (up(x) ^ B = 0)",
    "line_meets": "10 cases, kind cross (the crossing point, checked on both lines with clifford's up(x) ^ L = 0), parallel, skew, "
                  "same (the second line given opposite); line1, line2 {point, direction}, line1_mv, line2_mv, vee_mv = L1 & L2",
    "pair_meets": "19 cases, kind sphere, plane, line, circle, pair, point (0, 1 or 2 of the pair's points on the object, by "
                  "construction) and imaginary (line & sphere missing it); pair {a, b}, pair_mv = up(a) ^ up(b), object (its "
                  "parameters), object_mv, ends = clifford's point_pair_to_end_points in its order, on = [up(end) ^ object = 0 "
                  "(clifford), for each end], asserted against the construction",
}


def compact(text):
    """Put each list of plain numbers on one line (the file stays json.dump(indent=1) otherwise)."""
    return re.sub(r"\[\s+([-+0-9.eE,\s]+?)\s+\]", lambda m: "[" + ", ".join(s.strip() for s in m.group(1).split(",")) + "]", text)


def main():
    check_constructors()
    out = {
        "generator": "tools/clifford_operations.py: clifford %s (pygae), numba %s, numpy %s; seed %d"
                     % (clifford.__version__, numba.__version__, np.__version__, SEED),
        "blades": NAMES,
        "convention": CONVENTION,
        "constructors": CONSTRUCTORS,
        "families": FAMILIES,
        "tolerance": "every case's clifford multivector answer agrees with its Euclidean answer to 1e-9 relative (asserted)",
    }
    for name, fn in [("reflect_in_plane", reflect_in_plane), ("invert_in_sphere", invert_in_sphere),
                     ("reflect_in_point", reflect_in_point), ("reflect_in_line", reflect_in_line),
                     ("project_point", project_point), ("project_flat", project_flat), ("distances", distances),
                     ("angles", angles), ("meets", meets), ("circle_parts", circle_parts), ("versors", versors),
                     ("classify", classify), ("project_flats", project_flats), ("line_meets", line_meets),
                     ("pair_meets", pair_meets)]:
        cases = fn()
        out[name] = cases
        kinds = {}
        for c in cases:
            key = c.get("kind") or c.get("target_kind") or "case"
            kinds[key] = kinds.get(key, 0) + 1
        print("%-18s %3d cases, all checked  %s" % (name, len(cases), ", ".join("%s %d" % kv for kv in kinds.items())))
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "golden", "operations.json")
    with open(path, "w") as f:
        f.write(compact(json.dumps(out, indent=1)))
        f.write("\n")
    print("-> %s (%d bytes)" % (os.path.normpath(path), os.path.getsize(path)))


if __name__ == "__main__":
    main()
