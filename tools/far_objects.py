#!/usr/bin/env python3
"""Object, meet, embedding and motor reference vectors far from the origin, in 50-digit
arithmetic (mpmath).

Writes tests/data/far_objects.json: four families with the SAME per-case keys and multivector
layout as the clifford golden files the tests read, so that the same Rust comparisons run over
both (tests/tests/geometry/conformal.rs, tests/tests/geometry/versors.rs):

  objects      as tests/golden/objects.json: four points; the normalised line (a, b), circle
               (a, b, c), sphere (a, b, c, d), plane (a, b, c) through them; circle_euc
               (centre, unit normal, radius); sphere_centre (the e1..e3 part of the
               unnormalised centre point S einf S), sphere_radius; sphere_dual;
  line_sphere  as tests/golden/line_sphere.json: centre, radius, line_points, the normalised
               line, the sphere (normalised (up(c) - r^2/2 einf) I5, as clifford's file writes it),
               the meet line & sphere, its square, whether the line hits, and (hits only) the
               two end points;
  conformal    as tests/golden/conformal.json: x, up(x), down(up(x));
  rotors       as tests/golden/rotors.json: axis, angle, translation, the rotor
               cos(th/2) - sin(th/2) a I3, the translator 1 - t einf / 2, the motor T R, a point x,
               moved = M up(x) M~ and moved_euc = down(moved).

Coordinates reach 1e3 and sizes (point separations, radii) are 1e-2 ... 1e2. Inputs are drawn as
f64 (random.Random(SEED), SEED = 20261204) and are exactly what the file holds; the reference
converts them exactly (mpmath.mpf(float)) and computes at mp.dps = 50 with an independent,
minimal G(4,1) (orthonormal e1..e5, e4^2 = +1, e5^2 = -1, blades as bitmasks, as
tools/far_reference.py) in the conventions of tests/golden/README.md: einf = e4 + e5,
eo = (e5 - e4)/2, up(x) = x + x^2/2 einf + eo, I5 = e12345, dual(A) = -A I5, the meet
A & B = dual^-1(dual(A) ^ dual(B)) (clifford's `&`, cga-core's `&`), X.normal() = X / sqrt|X X~|.
Every output is written as a JSON float, the nearest f64 of the 50-digit value.

`python3 tools/far_objects.py --check` instead recomputes every case of the near golden files
(clifford 1.5.1) from their inputs and prints the largest difference per quantity, relative to
the largest coefficient; they agree to ~1e-14 (clifford's float64 rounding), which pins down
every sign convention above (line_sphere.json's sphere itself is 1.3e-13 off its centre and
radius; the meet of that sphere as written agrees to 8e-15).

Run: python3 -m pip install mpmath==1.3.0 && python3 tools/far_objects.py
"""
import json
import os
import random
import re
import sys

import mpmath
from mpmath import mp, mpf, sqrt, cos, sin

mp.dps = 50
SEED = 20261204
CHECK = mpf(10) ** -35
from mp_ga import BLADES, N, NAMES, SIGNATURE, gp, reorder_sign  # noqa: F401

# ---------------------------------------------------------------------------------------------
# Minimal G(4,1): multivectors are dicts blade bitmask -> mpf.






def outer(x, y):
    out = {}
    for a, ca in x.items():
        for b, cb in y.items():
            if a & b == 0:
                out[a | b] = out.get(a | b, 0) + reorder_sign(a, b) * ca * cb
    return out


def add(*xs, weights=None):
    out = {}
    for x, w in zip(xs, weights or [1] * len(xs)):
        for b, c in x.items():
            out[b] = out.get(b, 0) + w * c
    return out


def scale(x, s):
    return {b: s * c for b, c in x.items()}


def grade(x, k):
    return {b: c for b, c in x.items() if bin(b).count("1") == k}


def reverse(x):
    return {b: c * (-1 if (bin(b).count("1") * (bin(b).count("1") - 1) // 2) & 1 else 1) for b, c in x.items()}


def scalar(x):
    return x.get(0, mpf(0))


E = [{1 << i: mpf(1)} for i in range(N)]
EINF = add(E[3], E[4])
EO = scale(add(E[4], E[3], weights=[1, -1]), mpf("0.5"))
I5 = {31: mpf(1)}
I3 = {0b111: mpf(1)}


def dual(x):
    """A I5^-1 = -A I5."""
    return scale(gp(x, I5), -1)


def undual(x):
    return gp(x, I5)


def vee(x, y):
    """The regressive product dual^-1(dual(A) ^ dual(B)): clifford's A & B."""
    return undual(outer(dual(x), dual(y)))


def vec(x):
    return add(*[scale(E[i], x[i]) for i in range(3)])


def up(x):
    return add(vec(x), scale(EINF, sum(v * v for v in x) / 2), EO)


def down(p):
    """The Euclidean point of a weighted point: P / w, w = -P . einf = P_e5 - P_e4."""
    w = p.get(16, mpf(0)) - p.get(8, mpf(0))
    return [p.get(1 << i, mpf(0)) / w for i in range(3)]


def normalise(x):
    """clifford's .normal(): X / sqrt|X X~|."""
    return scale(x, 1 / sqrt(abs(scalar(gp(x, reverse(x))))))


def wedge(*xs):
    out = xs[0]
    for x in xs[1:]:
        out = outer(out, x)
    return out


def dense(x):
    return [float(x.get(b, 0)) for b in BLADES]


def M(v):
    """An f64 vector (or float) as exact mpf."""
    return [mpf(float(x)) for x in v] if isinstance(v, (list, tuple)) else mpf(float(v))


def F(v):
    return [float(x) for x in v] if isinstance(v, (list, tuple)) else float(v)


def dist(a, b):
    return sqrt(sum((a[i] - b[i]) ** 2 for i in range(3)))


def check(value, size, what):
    assert abs(value) <= CHECK * max(abs(size), 1), (what, value)


# ---------------------------------------------------------------------------------------------
# The quantities of each golden file, from its inputs (exact mpf).


def circle_euc(c):
    """Centre down(C einf C), unit normal of the carrier plane C ^ einf, radius sqrt(-C^2/(C^einf)^2)."""
    p = grade(gp(gp(c, EINF), c), 1)
    centre = down(p)
    plane = outer(c, EINF)
    radius = sqrt(-scalar(gp(c, c)) / scalar(gp(plane, plane)))
    d = grade(dual(plane), 1)
    n = [-d.get(1 << i, mpf(0)) for i in range(3)]
    length = sqrt(sum(v * v for v in n))
    return centre, [v / length for v in n], radius


def objects_case(points):
    a, b, c, d = [up(p) for p in points]
    line = normalise(wedge(a, b, EINF))
    circle = normalise(wedge(a, b, c))
    sphere = normalise(wedge(a, b, c, d))
    plane = normalise(wedge(a, b, c, EINF))
    centre, normal, radius = circle_euc(circle)
    for p in points[:3]:
        check(dist(p, centre) - radius, radius, "circle radius")
        check(sum((p[i] - centre[i]) * normal[i] for i in range(3)), radius, "circle plane")
    s_centre = grade(gp(gp(sphere, EINF), sphere), 1)
    sd = grade(dual(sphere), 1)
    s_radius = sqrt(scalar(gp(sd, sd)) / scalar(gp(sd, EINF)) ** 2)
    for p in points:
        check(dist(p, down(s_centre)) - s_radius, s_radius, "sphere radius")
    return {
        "line": line, "circle": circle, "sphere": sphere, "plane": plane, "sphere_dual": dual(sphere),
        "circle_euc": {"centre": centre, "normal": normal, "radius": radius},
        "sphere_centre": [s_centre.get(1 << i, mpf(0)) for i in range(3)], "sphere_radius": s_radius,
    }


def sphere_of(centre, r):
    """The sphere of centre c and radius r as clifford's line_sphere.json holds it: the normalised
    (up(c) - r^2/2 einf) I5 = dual^-1 of the dual sphere, i.e. -dual(up(c) - r^2/2 einf) / r."""
    return normalise(undual(add(up(centre), EINF, weights=[1, -r * r / 2])))


def end_points(pair):
    """The two points of a real point pair P, in clifford's order: (P -/+ sqrt(P^2)) (einf . P), up to weight."""
    p2 = scalar(gp(pair, pair))
    root = sqrt(p2)
    ei_p = grade(gp(EINF, pair), 1)  # einf . P (grade 1 part of einf P)
    return [down(grade(gp(add(pair, {0: s * root}), ei_p), 1)) for s in (-1, 1)]


def line_sphere_case(centre, radius, line_points):
    line = normalise(wedge(up(line_points[0]), up(line_points[1]), EINF))
    # The sphere as the file holds it (rounded to f64) is the meet's input, as clifford's file's
    # meet is exact for clifford's float64 sphere: rounding the e4, e5 coefficients (~|c|^2/2r)
    # moves a far sphere by ~eps |c|^2 relative, which no meet should be charged for.
    sphere = {b: mpf(v) for b, v in zip(BLADES, dense(sphere_of(centre, radius))) if v}
    meet = vee(line, sphere)
    sq = scalar(gp(meet, meet))
    out = {"line": line, "sphere": sphere, "meet": meet, "meet_squared": sq, "hits": bool(sq > 0)}
    if sq > 0:
        ends = end_points(meet)
        for x in ends:
            check(outer(up(x), sphere).get(31, mpf(0)), max(abs(v) for v in sphere.values()) * radius, "end point on the sphere")
        out["end_points"] = ends
    return out


def rotor(axis, angle):
    length = sqrt(sum(v * v for v in axis))
    a = [v / length for v in axis]
    return add({0: cos(angle / 2)}, scale(gp(vec(a), I3), -sin(angle / 2)))


def translator(t):
    return add({0: mpf(1)}, scale(gp(vec(t), EINF), mpf(-0.5)))


def rotors_case(axis, angle, t, x):
    r, tr = rotor(axis, angle), translator(t)
    m = gp(tr, r)
    moved = gp(gp(m, up(x)), reverse(m))
    return {"rotor": r, "translator": tr, "motor": m, "moved": moved, "moved_euc": down(moved)}


# ---------------------------------------------------------------------------------------------
# Writing and checking.


def out_value(v):
    if isinstance(v, dict) and all(isinstance(k, int) for k in v):
        return dense(v)
    if isinstance(v, dict):
        return {k: out_value(x) for k, x in v.items()}
    if isinstance(v, list):
        return [out_value(x) for x in v]
    if isinstance(v, bool):
        return v
    return float(v)


def max_abs(v):
    if isinstance(v, list):
        return max([max_abs(x) for x in v] + [0.0])
    return abs(v)


def diff(a, b):
    if isinstance(a, list):
        return max(diff(x, y) for x, y in zip(a, b))
    return abs(a - b)


def M_line(case):
    return normalise(wedge(*[up(M(p)) for p in case["line_points"]], EINF))


def check_against_golden():
    """Recompute the near golden files' quantities from their inputs and compare."""
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "golden")
    load = lambda name: json.load(open(os.path.join(here, name)))["cases"]
    worst = {}

    def note(family, key, got, want):
        if isinstance(want, bool):
            assert got == want, (family, key)
            return
        e = diff(got, want) / max(max_abs(want), 1e-300)
        worst[(family, key)] = max(worst.get((family, key), 0.0), e)

    for case in load("objects.json"):
        got = out_value(objects_case([M(p) for p in case["points"]]))
        for k in ["line", "circle", "sphere", "plane", "sphere_dual", "sphere_radius"]:
            note("objects", k, got[k], case[k])
        for k in ["centre", "radius"]:
            note("objects", "circle_euc." + k, got["circle_euc"][k], case["circle_euc"][k])
        # The normal's sign and the centre point's weight are not fixed by the file.
        g, w = got["circle_euc"]["normal"], case["circle_euc"]["normal"]
        note("objects", "circle_euc.normal (up to sign)", g if sum(x * y for x, y in zip(g, w)) > 0 else [-x for x in g], w)
        g, w = got["sphere_centre"], case["sphere_centre"]
        note("objects", "sphere_centre", g, w)
    for case in load("line_sphere.json"):
        got = out_value(line_sphere_case(M(case["centre"]), M(case["radius"]), [M(p) for p in case["line_points"]]))
        for k in ["line", "sphere", "meet", "meet_squared", "hits"]:
            note("line_sphere", k, got[k], case[k])
        # clifford's sphere is ~1e-13 off its centre and radius; its meet is exact for that sphere.
        sphere = {b: mpf(v) for b, v in zip(BLADES, case["sphere"]) if v}
        note("line_sphere", "meet (clifford's sphere)", dense(vee(M_line(case), sphere)), case["meet"])
        if "end_points" in case:
            note("line_sphere", "end_points", got["end_points"], case["end_points"])
    for case in load("conformal.json"):
        x = M(case["x"])
        note("conformal", "up", dense(up(x)), case["up"])
        note("conformal", "down", F(down(up(x))), case["down"])
    for case in load("rotors.json"):
        got = out_value(rotors_case(M(case["axis"]), M(case["angle"]), M(case["translation"]), M(case["x"])))
        for k in ["rotor", "translator", "motor", "moved_euc"]:
            note("rotors", k, got[k], case[k])
        # clifford's `moved` carries float64 debris (~1e-14) in grades 3 and 5.
        note("rotors", "moved (grade 1)", got["moved"][:6], case["moved"][:6])
    for (family, key), e in sorted(worst.items()):
        print("%-12s %-32s %.1e" % (family, key, e))
    return worst


# ---------------------------------------------------------------------------------------------
# The far cases.

rng = random.Random(SEED)


def direction():
    d = [rng.gauss(0, 1) for _ in range(3)]
    length = sum(v * v for v in d) ** 0.5
    return [v / length for v in d]


def far_point():
    """A point 1 ... 1e3 from the origin (f64)."""
    dist_ = 10 ** rng.uniform(0, 3)
    return [dist_ * v for v in direction()]


def size():
    return 10 ** rng.uniform(-2, 2)


def spread(n):
    """n unit offsets no two closer than 0.8 and, for 3 and 4, well away from collinear / coplanar."""
    while True:
        d = [direction() for _ in range(n)]
        if all(sum((d[i][k] - d[j][k]) ** 2 for k in range(3)) ** 0.5 > 0.8 for i in range(n) for j in range(i)):
            if n < 4:
                return d
            u = [[d[i][k] - d[0][k] for k in range(3)] for i in (1, 2, 3)]
            det = (u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) - u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0])
                   + u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0]))
            if abs(det) > 0.3:
                return d


def far_objects():
    cases = []
    for _ in range(32):
        c, s = far_point(), size()
        points = [[c[k] + s * d[k] for k in range(3)] for d in spread(4)]
        case = {"points": points}
        case.update(out_value(objects_case([M(p) for p in points])))
        cases.append(case)
    return cases


def far_line_sphere():
    cases = []
    for i in range(32):
        centre, radius = far_point(), size()
        # Hits and misses alike: the line's distance from the centre 0 ... 0.9 r or 1.1 ... 3 r.
        h = radius * (rng.uniform(0, 0.9) if i % 2 == 0 else rng.uniform(1.1, 3))
        d = direction()
        v = direction()
        w = [d[1] * v[2] - d[2] * v[1], d[2] * v[0] - d[0] * v[2], d[0] * v[1] - d[1] * v[0]]
        lw = sum(x * x for x in w) ** 0.5
        foot = [centre[k] + h * w[k] / lw for k in range(3)]
        t0, t1 = radius * rng.uniform(-3, 3), radius * rng.uniform(-3, 3)
        if abs(t1 - t0) < 0.5 * radius:
            t1 = t0 + radius
        line_points = [[foot[k] + t * d[k] for k in range(3)] for t in (t0, t1)]
        case = {"centre": centre, "radius": radius, "line_points": line_points}
        case.update(out_value(line_sphere_case(M(centre), M(radius), [M(p) for p in line_points])))
        cases.append(case)
    return cases


def far_conformal():
    cases = []
    for _ in range(32):
        x = far_point()
        cases.append({"x": x, "up": dense(up(M(x))), "down": F(down(up(M(x))))})
    return cases


def far_rotors():
    cases = []
    for _ in range(32):
        axis, angle = direction(), rng.uniform(-3, 3)
        t, x = far_point(), far_point()
        case = {"axis": axis, "angle": angle, "translation": t, "x": x}
        case.update(out_value(rotors_case(M(axis), M(angle), M(t), M(x))))
        cases.append(case)
    return cases


def compact(text):
    return re.sub(r"\[\s+([-+0-9.eE,\s]+?)\s+\]", lambda m: "[" + ", ".join(s.strip() for s in m.group(1).split(",")) + "]", text)


def main():
    if "--check" in sys.argv:
        worst = check_against_golden()
        loose = {("line_sphere", k) for k in ["sphere", "meet", "meet_squared"]}
        assert max(e for k, e in worst.items() if k not in loose) < 1e-12, "disagrees with clifford's conventions"
        assert max(worst[k] for k in loose) < 1e-12 * 1e3, "clifford's sphere is further off than it was"
        return
    out = {
        "generator": "tools/far_objects.py (mpmath %s, %d digits; an independent minimal G(4,1)); seed %d"
                     % (mpmath.__version__, mp.dps, SEED),
        "blades": NAMES,
        "convention": "as tests/golden (objects.json, line_sphere.json, conformal.json, rotors.json): orthonormal "
                      "e1..e5, e4^2 = +1, e5^2 = -1; einf = e4 + e5, eo = (e5 - e4)/2, up(x) = x + x^2/2 einf + eo; "
                      "I5 = e12345, dual(A) = -A I5; A & B = dual^-1(dual(A) ^ dual(B)); X.normal() = X / sqrt|X X~|; "
                      "R = cos(th/2) - sin(th/2) a I3, T = 1 - t einf/2, M = T R",
        "ranges": "coordinates up to 1e3 (points and centres 1 ... 1e3 from the origin), sizes (point spreads, radii) "
                  "1e-2 ... 1e2",
        "number_format": "inputs: the f64 values used, exactly; outputs: JSON floats, each the nearest f64 of the "
                         "50-digit result",
        "reference_digits": mp.dps,
    }
    for name, fn in [("objects", far_objects), ("line_sphere", far_line_sphere), ("conformal", far_conformal),
                     ("rotors", far_rotors)]:
        out[name] = fn()
        print("%-12s %3d cases" % (name, len(out[name])))
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "far_objects.json")
    with open(path, "w") as f:
        f.write(compact(json.dumps(out, indent=1)))
        f.write("\n")
    print("-> %s (%d bytes)" % (os.path.normpath(path), os.path.getsize(path)))


if __name__ == "__main__":
    main()
