#!/usr/bin/env python3
"""Runs every clifford spelling in docs/COOKBOOK.md with clifford 1.5.1, on the entry's own
inputs, and records what it gives (issue 51, point 5).

Writes tests/golden/cookbook_clifford.json: one case per spelling with the COOKBOOK's text
(`spelling`, run literally by `eval` where it is an expression; `setup` says what the names
in it are), clifford's answer read back to Euclidean numbers (`answer`, or `error` with the
exception's text where it raised), the answer the COOKBOOK's own example states
(`expected`, the same numbers our doctest asserts), and `right`: whether clifford's answer
is the expected one to 1e-9 (up to the sign of a blade, and for points up to their weight).
The Rust test (tests/tests/geometry/cookbook_clifford.rs) computes cga-core's answer to each
task and checks it against `expected`, and against `answer` where `right`.

Spellings that are wrong are listed in the output's `wrong`; the COOKBOOK says so beside
each. Run from the repository root:
    /tmp/peers/bin/python tools/cookbook_clifford.py
"""
import json
import math
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
from clifford.tools.g3c.rotor_parameterisation import general_logarithm  # noqa: E402

assert clifford.__version__ == "1.5.1", clifford.__version__
I5 = blades["e12345"]
TOL = 1e-9


def V(x):
    return float(x[0]) * e1 + float(x[1]) * e2 + float(x[2]) * e3


def up(x):
    return layout.up(V(x))


def down(X):
    X = X(1)
    w = -(X | einf)[()]
    return [float(v) / w for v in X.value[1:4]]


def sphere(c, r):
    c = np.asarray(c, dtype=float)
    return (up(c + [r, 0, 0]) ^ up(c + [0, r, 0]) ^ up(c + [0, 0, r]) ^ up(c - [r, 0, 0])).normal()


def plane(p, n):
    p, n = np.asarray(p, dtype=float), np.asarray(n, dtype=float)
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    return (up(p) ^ up(p + u) ^ up(p + v) ^ einf).normal()


def line(p, d):
    p, d = np.asarray(p, dtype=float), np.asarray(d, dtype=float)
    return (up(p) ^ up(p + d) ^ einf).normal()


def circle(c, n, r):
    c, n = np.asarray(c, dtype=float), np.asarray(n, dtype=float)
    n = n / np.linalg.norm(n)
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    return (up(c + r * u) ^ up(c + r * v) ^ up(c - r * u)).normal()


def centre_radius(S):
    """A sphere blade's centre and radius (clifford.tools.g3c's own read-backs)."""
    return down(tools.get_center_from_sphere(S)), float(tools.get_radius_from_sphere(S))


def circle_centre_radius(C):
    """A circle's centre (C ei C, normalised) and radius (of its carrier sphere)."""
    centre = down(C * einf * C)
    S = tools.circle_to_sphere(C)
    return centre, float(tools.get_radius_from_sphere(S))


def moved(R, x):
    return down(R * up(x) * ~R)


def close(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= TOL * np.maximum(1.0, np.abs(b))))


cases = []


def finite(x):
    """Numbers as floats, NaN and infinities as None (JSON has no NaN)."""
    if isinstance(x, (list, tuple)):
        return [finite(v) for v in x]
    x = float(x)
    return x if math.isfinite(x) else None


def case(task, spelling, setup, run, expected, note="", documented=None):
    """Run `run()` (which evaluates `spelling` and reads the answer back) and record it.
    `documented`: what the COOKBOOK says clifford gives where that differs from the answer
    (`as_documented` then says whether it does)."""
    entry = {"task": task, "spelling": spelling, "setup": setup, "expected": expected}
    try:
        answer = finite(run())
        entry["answer"] = answer
        entry["right"] = bool(close(np.array(answer, dtype=float), expected))
        if documented is not None:
            entry["documented"] = documented
            entry["as_documented"] = bool(close(np.array(answer, dtype=float), documented))
    except Exception as exc:
        entry["error"] = f"{type(exc).__name__}: {exc}"
        entry["right"] = False
    if note:
        entry["note"] = note
    cases.append(entry)


def ev(spelling, **names):
    env = dict(vars(tools))
    env.update(dict(vars(fitting)))
    env.update({"general_logarithm": general_logarithm, "I5": I5, "einf": einf, "np": np,
                "orthoFrames2Versor": ctools.orthoFrames2Versor})
    env.update(names)
    return eval(spelling, env)


# ## Reflect a point, a sphere or a circle in a plane
P = plane([0, 0, 1], [0, 0, 1]).dual()
case("reflect_point_in_plane", "-P*X*P", "P: the dual of the plane z = 1; X = up((1, 2, 0))",
     lambda: down(ev("-P*X*P", P=P, X=up([1, 2, 0]))), [1.0, 2.0, 2.0])
case("reflect_sphere_in_plane", "-P*X*P", "X: the sphere of centre (0, 0, −1), radius ½ (centre, radius read back)",
     lambda: [*centre_radius(ev("-P*X*P", P=P, X=sphere([0, 0, -1], 0.5)))[0],
              centre_radius(ev("-P*X*P", P=P, X=sphere([0, 0, -1], 0.5)))[1]], [0.0, 0.0, 3.0, 0.5])
case("reflect_circle_in_plane", "-P*X*P", "X: the unit circle at the origin across x (centre read back)",
     lambda: circle_centre_radius(ev("-P*X*P", P=P, X=circle([0, 0, 0], [1, 0, 0], 1.0)))[0], [0.0, 0.0, 2.0])

# ## Invert in a sphere
S1 = sphere([0, 0, 0], 1.0)
case("invert_point_in_sphere", "(S.dual()*X*S.dual()).grade1()", "S: the unit sphere; X = up((2, 0, 0))",
     lambda: down(ev("(S.dual()*X*S.dual()).grade1()", S=S1, X=up([2, 0, 0]))), [0.5, 0.0, 0.0],
     "clifford's MultiVector has no grade1(): the grade-1 part is X(1)")
case("invert_point_in_sphere_corrected", "(S.dual()*X*S.dual())(1)", "as above, with clifford's grade selection",
     lambda: down(ev("(S.dual()*X*S.dual())(1)", S=S1, X=up([2, 0, 0]))), [0.5, 0.0, 0.0])

# ## Project a point onto a line, plane, sphere or circle
X = up([1, 2, 3])
case("project_point_onto_line", "project_points_to_line([X], L)[0]", "X = up((1, 2, 3)); L: the x axis",
     lambda: down(ev("project_points_to_line([X], L)[0]", X=X, L=line([0, 0, 0], [1, 0, 0]))), [1.0, 0.0, 0.0])
case("project_point_onto_plane", "project_points_to_plane([X], P)[0]", "P: the plane z = 0",
     lambda: down(ev("project_points_to_plane([X], P)[0]", X=X, P=plane([0, 0, 0], [0, 0, 1]))), [1.0, 2.0, 0.0])
case("project_point_onto_sphere", "project_points_to_sphere([X], S)[0]", "S: centre (1, 2, 0), radius 1",
     lambda: down(ev("project_points_to_sphere([X], S)[0]", X=X, S=sphere([1, 2, 0], 1.0))), [1.0, 2.0, 1.0])
case("project_point_onto_circle", "project_points_to_circle([X], C)[0]", "C: the unit circle in z = 0",
     lambda: down(ev("project_points_to_circle([X], C)[0]", X=X, C=circle([0, 0, 0], [0, 0, 1], 1.0))),
     [1 / math.sqrt(5), 2 / math.sqrt(5), 0.0])

# ## The rotor between two directions
case("rotor_between_directions", "(1 + b*a).normal()", "a = e1, b = e2; the image of e1",
     lambda: [float(v) for v in (lambda R: (R * e1 * ~R).value[1:4])(ev("(1 + b*a).normal()", a=e1, b=e2))],
     [0.0, 1.0, 0.0])
case("rotor_between_objects_directions", "rotor_between_objects(a, b)", "a = e1, b = e2; the image of e1",
     lambda: [float(v) for v in (lambda R: (R * e1 * ~R).value[1:4])(ev("rotor_between_objects(a, b)", a=e1, b=e2))],
     [0.0, 1.0, 0.0])

# ## Turn about any line
case("turn_about_line", "(-0.5*theta*L*I5).exp()", "L: the line x = 1 along z, θ = π/2; the image of (2, 0, 0)",
     lambda: moved(ev("(-0.5*theta*L*I5).exp()", theta=math.pi / 2, L=line([1, 0, 0], [0, 0, 1])), [2, 0, 0]),
     [1.0, 1.0, 0.0])

# ## A motor's parts, its inverse, its logarithm
R05 = tools.generate_rotation_rotor(0.5, e1, e2)
M = tools.generate_translation_rotor(V([1, 2, 3])) * R05
case("motor_inverse", "M.inv()", "M: turn 0.5 about z, then shift (1, 2, 3); M M⁻¹'s coefficients",
     lambda: [float(v) for v in (M * ev("M.inv()", M=M)).value], [1.0] + [0.0] * 31)
case("motor_logarithm", "general_logarithm(M)", "exp of the logarithm, the image of (1, 0, 0)",
     lambda: moved(ev("general_logarithm(M)", M=M).exp(), [1, 0, 0]), moved(M, [1, 0, 0]))

def half_screw_origin():
    """The image of the origin under the square root of x ↦ R₁ x + (2, 0, 0), R₁ the turn by 1
    about z: its axis c solves (I − R₁) c = t in the plane, and the half motion turns by ½ about c."""
    def rot(a):
        return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    c = np.linalg.solve(np.eye(2) - rot(1.0), np.array([2.0, 0.0]))
    x = c - rot(0.5) @ c
    return [float(x[0]), float(x[1]), 0.0]


# ## Interpolate two poses
B = tools.generate_translation_rotor(V([2, 0, 0])) * tools.generate_rotation_rotor(1.0, e1, e2)
case("interpolate_poses", "(t*general_logarithm(B*~A)).exp()*A",
     "A = 1, B: turn 1 about z then shift (2, 0, 0), t = ½; the image of the origin (ours: B^½)",
     lambda: moved(ev("(t*general_logarithm(B*~A)).exp()*A", t=0.5, A=e1 * e1, B=B), [0, 0, 0]),
     half_screw_origin())

# ## Dilators
case("dilation_rotor", "generate_dilation_rotor(s)", "s = 2.5 about the origin; the image of (2, 0, 0) by D X D̃ (ours: 5)",
     lambda: moved(ev("generate_dilation_rotor(s)", s=2.5), [2, 0, 0]), [5.0, 0.0, 0.0])

# ## Project a flat onto a flat, and reject it
floor = plane([0, 0, 0], [0, 0, 1])
slope = line([0, 0, 2], [1, 0, 1])
case("project_flat_onto_flat", "(A << B) * B.inv()",
     "A: the line through (0, 0, 2) along (1, 0, 1), B: the floor z = 0; |up(x) ∧ result| (normalised) at "
     "x = (0, 0, 0) and (1, 0, 0), both on our projection (the x axis)",
     lambda: (lambda Lp: [float(np.max(np.abs((up(x) ^ Lp).value))) for x in ([0, 0, 0], [1, 0, 0])])(
         ev("(A << B) * B.inv()", A=slope, B=floor).normal()),
     [0.0, 0.0])
case("project_perpendicular_flat", "(A << B) * B.inv()",
     "A: the line along the floor's normal through (1, 2, 5); 1 if the result is nonzero (ours: the point (1, 2, 0))",
     lambda: float(np.max(np.abs(ev("(A << B) * B.inv()", A=line([1, 2, 5], [0, 0, 1]), B=floor).value)) > 1e-12),
     1.0, "zero: the blade formula cannot express the smaller image", documented=0.0)
case("reject_flat_from_flat", "(A ^ B) * B.inv()",
     "A: the sloping line, B: the floor; 1 if the result is nonzero (ours: a line along the normal)",
     lambda: float(np.max(np.abs(ev("(A ^ B) * B.inv()", A=slope, B=floor).value)) > 1e-12), 1.0,
     "zero for any two flats", documented=0.0)

# ## Where a line meets a circle, two spheres meet, three planes meet
ring = circle([0, 0, 0], [0, 0, 1], 1.0)
across = line([-2, 0, 0], [1, 0, 0])
case("line_meets_circle", "point_pair_to_end_points(meet(L, C))",
     "L: the x axis, C: the unit circle in z = 0; the two points, sorted along x",
     lambda: sorted([down(x) for x in ev("point_pair_to_end_points(meet(L, C))", L=across, C=ring)]),
     [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]], "meet of a coplanar line and circle is 0 (their join is not the whole space)")
case("line_meets_circle_corrected", "point_pair_to_end_points(meet(L, circle_to_sphere(C)))",
     "the same line against the circle's carrier sphere (the line lies in the circle's plane)",
     lambda: sorted([down(x) for x in ev("point_pair_to_end_points(meet(L, circle_to_sphere(C)))", L=across, C=ring)]),
     [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
case("spheres_meet", "meet(S1, S2)", "unit spheres at the origin and at (1, 0, 0); the circle's centre and radius",
     lambda: [*circle_centre_radius(ev("meet(S1, S2)", S1=sphere([0, 0, 0], 1.0), S2=sphere([1, 0, 0], 1.0)))[0],
              circle_centre_radius(ev("meet(S1, S2)", S1=sphere([0, 0, 0], 1.0), S2=sphere([1, 0, 0], 1.0)))[1]],
     [0.5, 0.0, 0.0, math.sqrt(0.75)])
planes = [plane([1, 2, 3], n) for n in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
case("three_planes_meet", "meet(meet(P1, P2), P3)",
     "the planes x = 1, y = 2, z = 3; |up((1, 2, 3)) ∧ F| of the normalised flat point F, and whether F ≠ 0",
     lambda: (lambda F: [float(np.max(np.abs((up([1, 2, 3]) ^ F.normal()).value))), float(np.max(np.abs(F.value)) > 0)])(
         ev("meet(meet(P1, P2), P3)", P1=planes[0], P2=planes[1], P3=planes[2])),
     [0.0, 1.0], "a flat point to read by hand")

# ## Where two lines cross
case("lines_meet", "meet(L1, L2)", "L1: along x through (0, 0, 1), L2: the z axis; 1 if the result is nonzero",
     lambda: float(np.max(np.abs(ev("meet(L1, L2)", L1=line([0, 0, 1], [1, 0, 0]), L2=line([0, 0, 0], [0, 0, 1])).value)) > 1e-12),
     1.0, "zero: the meet of two crossing lines (coplanar) vanishes in tools.g3c.meet, as a coplanar line and circle's does")
case("lines_meet_corrected", "midpoint_between_lines(L1, L2)", "as above; the point (ours: (0, 0, 1))",
     lambda: down(ev("midpoint_between_lines(L1, L2)", L1=line([0, 0, 1], [1, 0, 0]), L2=line([0, 0, 0], [0, 0, 1]))),
     [0.0, 0.0, 1.0])
case("pair_points_on_sphere", "point_pair_to_end_points(PP)",
     "PP: up((1, 0, 0)) ^ up((3, 0, 0)); which end lies on the unit sphere (up(x) ^ S == 0 to 1e-9)",
     lambda: [down(x) for x in ev("point_pair_to_end_points(PP)", PP=up([1, 0, 0]) ^ up([3, 0, 0]))
              if np.max(np.abs((layout.up(V(down(x))) ^ S1).value)) < 1e-9],
     [[1.0, 0.0, 0.0]])

# ## Distances
case("distance", "(-2*(X|Y)).value[0]**0.5", "X = up(0), Y = up((3, 4, 0))",
     lambda: float(ev("(-2*(X|Y)).value[0]**0.5", X=up([0, 0, 0]), Y=up([3, 4, 0]))), 5.0)

# ## Fit
pts = [[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0], [0, 0, 1]]
case("fit_sphere", "fit_sphere(points)", "the five points of the entry, as up(x); centre and radius",
     lambda: (lambda c, r: [*c, r])(*centre_radius(ev("fit_sphere(points)", points=[up(p) for p in pts]))),
     [0.0, 0.0, 0.0, 1.0], "exact points: clifford keeps only positive eigenvalues, and the fit's is zero")
case("fit_circle", "fit_circle(points)", "the first four points; radius",
     lambda: circle_centre_radius(ev("fit_circle(points)", points=[up(p) for p in pts[:4]]))[1], 1.0)
case("fit_plane", "fit_plane(points)", "the first four points; the blade's eo part (0 for a plane) and |normal·e3|",
     lambda: (lambda Pl: [float(abs(Pl.value[26] - Pl.value[27])), float(abs((Pl * I5)(1).value[3]) /
                                                                           np.linalg.norm((Pl * I5)(1).value[1:4]))])(
         ev("fit_plane(points)", points=[up(p) for p in pts[:4]])), [0.0, 1.0])
case("fit_line", "fit_line(points)", "(0, 0, 0), (1, 1, 0), (2, 2, 0); the distance of (3, 3, 0) from the fit",
     lambda: float(abs((up([3, 3, 0]) ^ ev("fit_line(points)", points=[up(p) for p in [[0, 0, 0], [1, 1, 0], [2, 2, 0]]])).value).max()),
     0.0)

# ## Joins
case("join_line_point", "(L ^ X).normal()", "L: the x axis, X = up((0, 1, 0)); the plane's |normal·e3|",
     lambda: (lambda Pl: float(abs((Pl * I5)(1).value[3]) / np.linalg.norm((Pl * I5)(1).value[1:4])))(
         ev("(L ^ X).normal()", L=line([0, 0, 0], [1, 0, 0]), X=up([0, 1, 0]))), 1.0)

# ## The new entries (average, closest points, versors between)
ca = circle([0, 0, 0], [0, 0, 1], 1.0)
cb = circle([0, 0, 1], [0, 1, 1], 2.0)
case("average_objects", "average_objects([C1, C2])", "C1: unit circle at the origin in z = 0, C2: centre (0, 0, 1), "
     "normal (0, 1, 1), radius 2; centre and radius (ours: the interpolation at ½)",
     lambda: (lambda c, r: [*c, r])(*circle_centre_radius(ev("average_objects([C1, C2])", C1=ca, C2=cb))),
     (lambda c, r: [*c, r])(*circle_centre_radius(tools.interp_objects_root(ca, cb, 0.5))))
case("closest_circle_line", "iterative_closest_points_circle_line(C, L)",
     "C: the unit circle in z = 0, L: through (3, 0, 2) along y; the point on the circle",
     lambda: down(ev("iterative_closest_points_circle_line(C, L)", C=ca, L=line([3, 0, 2], [0, 1, 0]))[0]), [1.0, 0.0, 0.0])
case("closest_circle_line_aristidou", "closest_point_on_circle_from_line(C, L)", "as above",
     lambda: down(ev("closest_point_on_circle_from_line(C, L)", C=ca, L=line([3, 0, 2], [0, 1, 0]))), [1.0, 0.0, 0.0])
case("closest_circles", "iterative_closest_points_on_circles(C1, C2)",
     "C1: the unit circle in z = 0, C2: centre (3, 0, 0), normal y, radius 1; the two points",
     lambda: [down(x) for x in ev("iterative_closest_points_on_circles(C1, C2)", C1=ca, C2=circle([3, 0, 0], [0, 1, 0], 1.0))],
     [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0]])
case("versor_between_circles", "rotor_between_objects(C1, C2)", "C1, C2 as for average_objects; V C1 Ṽ = C2 (max coefficient error)",
     lambda: (lambda R: float(np.max(np.abs((R * ca * ~R - cb).value))))(ev("rotor_between_objects(C1, C2)", C1=ca, C2=cb)), 0.0)
case("motor_between_circles", "motor_between_rounds(C1, C2)",
     "C1: the unit circle in z = 0, C2: the unit circle at (1, 2, 3) across x; the image of C1's centre",
     lambda: moved(ev("motor_between_rounds(C1, C2)", C1=ca, C2=circle([1, 2, 3], [1, 0, 0], 1.0)), [0, 0, 0]), [1.0, 2.0, 3.0])
case("frames_versor", "orthoFrames2Versor(B, A)[0]", "A: e1, e2, e3; B: e2, −e1, e3 (a quarter turn about z); the image of e1",
     lambda: [float(v) for v in (lambda R: (R * e1 * ~R).value[1:4])(ev("orthoFrames2Versor(B, A)[0]", A=[e1, e2, e3], B=[e2, -e1, e3]))],
     [0.0, 1.0, 0.0])

out = {
    "generator": "tools/cookbook_clifford.py",
    "clifford": clifford.__version__,
    "numpy": np.__version__,
    "python": sys.version.split()[0],
    "blades": ["1" if n == "" else n for n in layout.names],
    "tolerance": TOL,
    "wrong": [c["task"] for c in cases if not c["right"] and not c.get("as_documented", False)],
    "as_documented": [c["task"] for c in cases if c.get("as_documented", False)],
    "cases": cases,
}
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "golden", "cookbook_clifford.json")
with open(path, "w") as f:
    json.dump(out, f, indent=1)
    f.write("\n")
for c in cases:
    verdict = "ok   " if c["right"] else "doc  " if c.get("as_documented") else "WRONG"
    print(verdict, c["task"], c.get("answer", c.get("error")))
print("wrote", os.path.normpath(path))
