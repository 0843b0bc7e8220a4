#!/usr/bin/env python3
"""Reference answers of clifford 1.5.1's `clifford.tools.g3c` helpers that cga-core now has
its own spellings of (issue 51, point 4): fitting, averaging objects, closest points of a
circle and a line and of two circles, the versor between two orthonormal frames, between two
objects, and the motor between two rounds.

Writes tests/golden/clifford_tools.json. Every input object is built here from Euclidean
parameters by wedging conformal points (recorded both ways), and every output is clifford's
own function's answer on it (a multivector of 32 floats in the golden blade order, or
Euclidean points), or, where clifford raised, the exception's text. Nothing here is checked
against Euclid: the Rust tests (tests/tests/geometry/clifford_tools.rs) do that, and say
where clifford's answer is wrong.

Inputs come from numpy.random.default_rng(SEED) (SEED = 20261206), not from clifford's
random_* helpers. clifford's `iterative_*` helpers are deterministic; none of the functions
called draws random numbers except `closest_point_on_circle_from_line` in one degenerate
branch (a line along the circle's axis), which is given its own seeded generator
(np.random.seed(SEED) before each call).

Run (as made, from the repository root):
    /tmp/peers/bin/python tools/clifford_tools.py
(clifford 1.5.1, numpy, numba; Python 3; the first import compiles with numba, about a minute
in all.)
"""
import json
import os
import sys
import warnings

import numpy as np

warnings.simplefilter("ignore")

import clifford  # noqa: E402
from clifford import tools as ctools  # noqa: E402
from clifford.g3c import layout, blades, einf, e1, e2, e3  # noqa: E402
from clifford.tools import g3c as tools  # noqa: E402
from clifford.tools.g3c import object_fitting as fitting  # noqa: E402

assert clifford.__version__ == "1.5.1", clifford.__version__
SEED = 20261206
NAMES = ["1" if n == "" else n for n in layout.names]
rng = np.random.default_rng(SEED)


def V(x):
    return float(x[0]) * e1 + float(x[1]) * e2 + float(x[2]) * e3


def up(x):
    return layout.up(V(x))


def E(x):
    return [float(v) for v in np.asarray(x, dtype=float)]


def mvl(X):
    return [float(v) for v in X.value]


def down(X):
    """The Euclidean point of a conformal point of any weight (clifford's normalise_n_minus_1
    then the e1, e2, e3 parts)."""
    Y = tools.normalise_n_minus_1(X(1))
    return E(Y.value[1:4])


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def basis_across(n):
    """Unit u, v with u, v, n orthonormal and right-handed."""
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = unit(np.cross(n, a))
    return u, np.cross(n, u)


def circle(c, n, r):
    u, v = basis_across(n)
    return (up(c + r * u) ^ up(c + r * v) ^ up(c - r * u)).normal()


def sphere(c, r):
    return (up(c + r * np.array([1.0, 0, 0])) ^ up(c + r * np.array([0, 1.0, 0]))
            ^ up(c + r * np.array([0, 0, 1.0])) ^ up(c - r * np.array([1.0, 0, 0]))).normal()


def plane(p, n):
    u, v = basis_across(n)
    return (up(p) ^ up(p + u) ^ up(p + v) ^ einf).normal()


def line(p, d):
    return (up(p) ^ up(p + d) ^ einf).normal()


def pair(c, d, r):
    return (up(c + r * d) ^ up(c - r * d)).normal()


def direction():
    return unit(rng.normal(size=3))


def attempt(f):
    try:
        return {"ok": f()}
    except Exception as exc:  # clifford raises ValueError/ZeroDivision on degenerate input
        return {"error": f"{type(exc).__name__}: {exc}"}


# --- fitting ---------------------------------------------------------------------------------
fit = []
for k in range(12):
    sigma = [0.0, 0.01, 0.05][k % 3]
    c, r, n = rng.normal(size=3), rng.uniform(0.5, 2.0), direction()
    m = 40
    z = rng.uniform(-1, 1, m)
    phi = rng.uniform(0, 2 * np.pi, m)
    s = np.sqrt(1 - z * z)
    pts = c + r * np.stack([s * np.cos(phi), s * np.sin(phi), z], axis=1) + sigma * rng.normal(size=(m, 3))
    fit.append({"kind": "sphere", "sigma": sigma, "centre": E(c), "radius": r,
                "points": [E(p) for p in pts],
                "clifford": attempt(lambda: mvl(fitting.fit_sphere([up(p) for p in pts])))})
    u, v = basis_across(n)
    t = rng.uniform(0, 2 * np.pi, m)
    pts = c + r * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v)) + sigma * rng.normal(size=(m, 3))
    fit.append({"kind": "circle", "sigma": sigma, "centre": E(c), "normal": E(n), "radius": r,
                "points": [E(p) for p in pts],
                "clifford": attempt(lambda: mvl(fitting.fit_circle([up(p) for p in pts])))})
    a, b = rng.uniform(-2, 2, m), rng.uniform(-2, 2, m)
    pts = c + np.outer(a, u) + np.outer(b, v) + sigma * rng.normal(size=(m, 3))
    fit.append({"kind": "plane", "sigma": sigma, "point": E(c), "normal": E(n),
                "points": [E(p) for p in pts],
                "clifford": attempt(lambda: mvl(fitting.fit_plane([up(p) for p in pts])))})

# --- averaging -------------------------------------------------------------------------------
average = []
for k in range(30):
    kind = ["circle", "sphere", "plane", "line", "point_pair"][k % 5]
    c, n, r = rng.normal(size=3), direction(), rng.uniform(0.5, 2.0)
    objs = []
    for _ in range(5):
        dc, dn, dr = 0.1 * rng.normal(size=3), 0.1 * rng.normal(size=3), 1 + 0.1 * rng.uniform(-1, 1)
        nn = unit(n + dn)
        objs.append({"circle": lambda: circle(c + dc, nn, r * dr),
                     "sphere": lambda: sphere(c + dc, r * dr),
                     "plane": lambda: plane(c + dc, nn),
                     "line": lambda: line(c + dc, nn),
                     "point_pair": lambda: pair(c + dc, nn, r * dr)}[kind]())
    average.append({"kind": kind, "objects": [mvl(o) for o in objs],
                    "clifford": attempt(lambda: mvl(tools.average_objects(objs)))})

# --- closest points: circle and line, two circles ----------------------------------------------
circle_line = []
for k in range(40):
    c, n, r = rng.normal(size=3), direction(), rng.uniform(0.3, 2.0)
    p, d = rng.normal(size=3), direction()
    u, v = basis_across(n)
    if k % 8 == 1:  # in the circle's plane, crossing it
        p, d = c + 0.3 * r * u, unit(u + 2 * v)
    elif k % 8 == 2:  # parallel to the circle's plane, above it
        p, d = c + 0.5 * n + 0.2 * r * u, v
    elif k % 8 == 3:  # along the circle's axis
        p, d = c + 0.7 * n, n
    elif k % 8 == 4:  # through the circle's centre, slanted
        p, d = c, unit(n + u)
    C, L = circle(c, n, r), line(p, d)
    np.random.seed(SEED)
    aristidou = attempt(lambda: down(tools.closest_point_on_circle_from_line(C, L)))
    iterative = attempt(lambda: [down(P) for P in tools.iterative_closest_points_circle_line(C, L)])
    circle_line.append({"circle": {"centre": E(c), "normal": E(n), "radius": r, "mv": mvl(C)},
                        "line": {"point": E(p), "direction": E(d), "mv": mvl(L)},
                        "closest_point_on_circle_from_line": aristidou,
                        "iterative_closest_points_circle_line": iterative})

circles = []
for k in range(40):
    c1, n1, r1 = rng.normal(size=3), direction(), rng.uniform(0.3, 2.0)
    c2, n2, r2 = rng.normal(size=3), direction(), rng.uniform(0.3, 2.0)
    if k % 8 == 1:  # linked circles
        u, v = basis_across(n1)
        c2, n2, r2 = c1 + r1 * u, v, r1
    elif k % 8 == 2:  # coplanar, disjoint
        u, v = basis_across(n1)
        c2, n2 = c1 + (r1 + r2 + 0.5) * u, n1
    elif k % 8 == 3:  # one above the other, parallel planes, offset axes
        u, v = basis_across(n1)
        c2, n2 = c1 + 0.8 * n1 + 0.3 * u, n1
    C1, C2 = circle(c1, n1, r1), circle(c2, n2, r2)
    iterative = attempt(lambda: [down(P) for P in tools.iterative_closest_points_on_circles(C1, C2)])
    circles.append({"circle1": {"centre": E(c1), "normal": E(n1), "radius": r1, "mv": mvl(C1)},
                    "circle2": {"centre": E(c2), "normal": E(n2), "radius": r2, "mv": mvl(C2)},
                    "iterative_closest_points_on_circles": iterative})

# --- versors ---------------------------------------------------------------------------------
frames = []
for k in range(20):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    w, x, y, z = q
    M = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    if k == 1:  # a half turn
        M = np.diag([1.0, -1.0, -1.0])
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    if np.linalg.det(Q) < 0:
        Q[:, 0] *= -1
    A = [Q[:, i] for i in range(3)]
    B = [M @ a for a in A]
    frames.append({"from": [E(a) for a in A], "to": [E(b) for b in B],
                   "orthoFrames2Versor": attempt(lambda: mvl(ctools.orthoFrames2Versor([V(b) for b in B],
                                                                                        [V(a) for a in A])[0]))})

between = []
for k in range(40):
    kind = ["circle", "sphere", "line", "plane", "point_pair"][k % 5]
    make = {"circle": lambda: circle(rng.normal(size=3), direction(), rng.uniform(0.3, 2.0)),
            "sphere": lambda: sphere(rng.normal(size=3), rng.uniform(0.3, 2.0)),
            "line": lambda: line(rng.normal(size=3), direction()),
            "plane": lambda: plane(rng.normal(size=3), direction()),
            "point_pair": lambda: pair(rng.normal(size=3), direction(), rng.uniform(0.3, 2.0))}[kind]
    X1, X2 = make(), make()
    between.append({"kind": kind, "x1": mvl(X1), "x2": mvl(X2),
                    "rotor_between_objects": attempt(lambda: mvl(tools.rotor_between_objects(X1, X2)))})

rounds = []
for k in range(20):
    kind = "circle" if k % 2 == 0 else "sphere"
    same = k % 4 < 2
    r1 = rng.uniform(0.3, 2.0)
    r2 = r1 if same else rng.uniform(0.3, 2.0)
    if kind == "circle":
        X1, X2 = circle(rng.normal(size=3), direction(), r1), circle(rng.normal(size=3), direction(), r2)
    else:
        X1, X2 = sphere(rng.normal(size=3), r1), sphere(rng.normal(size=3), r2)
    rounds.append({"kind": kind, "same_radius": same, "x1": mvl(X1), "x2": mvl(X2),
                   "motor_between_rounds": attempt(lambda: mvl(tools.motor_between_rounds(X1, X2)))})

out = {
    "generator": "tools/clifford_tools.py",
    "clifford": clifford.__version__,
    "numpy": np.__version__,
    "python": sys.version.split()[0],
    "seed": SEED,
    "blades": NAMES,
    "conventions": "Multivectors in clifford.g3c's orthonormal basis (e4² = 1, e5² = −1), the golden blade "
                   "order; objects are wedges of layout.up points, normalised (.normal()). Every output is "
                   "clifford's answer, {\"ok\": value} or {\"error\": text}; Euclidean points by "
                   "normalise_n_minus_1 and the e1, e2, e3 parts.",
    "families": {
        "fit": "object_fitting.fit_sphere / fit_circle / fit_plane of 40 points on a known object plus "
               "isotropic normal noise sigma per coordinate",
        "average": "average_objects of 5 objects near one another (same orientation)",
        "circle_line": "closest_point_on_circle_from_line (Aristidou) and iterative_closest_points_circle_line; "
                       "every 8th case from index 1: in the plane crossing, parallel above, along the axis, "
                       "through the centre",
        "circles": "iterative_closest_points_on_circles; every 8th from 1: linked, coplanar disjoint, stacked",
        "frames": "clifford.tools.orthoFrames2Versor(B, A) for frames A, B = M A of one rotation M "
                  "(index 1 a half turn)",
        "between": "rotor_between_objects(X1, X2) of two random objects of one kind",
        "rounds": "motor_between_rounds(X1, X2), same_radius or not",
    },
    "cases": {"fit": fit, "average": average, "circle_line": circle_line, "circles": circles,
              "frames": frames, "between": between, "rounds": rounds},
}
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "golden", "clifford_tools.json")
with open(path, "w") as f:
    json.dump(out, f, indent=1)
    f.write("\n")
print("wrote", os.path.normpath(path))
