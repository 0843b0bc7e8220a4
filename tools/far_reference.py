#!/usr/bin/env python3
"""Reference vectors far from the origin, in 50-digit arithmetic (mpmath).

Writes tests/data/far_interpolation.json: circle pairs with centres up to 1e3 from the origin
and radii 1e-2 ... 1e2, each circle as its normalised OPNS blade, and the interpolated circle
C_alpha with its centre and radius. The geometric algebra here is an independent, minimal
implementation (orthonormal basis e1..e5, e5^2 = -1, blades as bitmasks), in the conventions
of the golden files (shared/golden/README.md): up(x) = x + x^2/2 einf + eo, einf = e4 + e5,
eo = (e5 - e4)/2, blades normalised so that X X~ = -1, C2 aligned to C1, X = (1-a) C1 + a C2,
C = K^-1 X with K the principal root of -X X~ (Dorst-Valkenburg).

Every value is rounded to f64 only when written: the reference is exact to ~1e-40, far below
what f64 can reach, unlike clifford (float64), which itself loses ~1e-10 at coordinates 1e3.

Run: python3 -m pip install mpmath==1.3.0 && python3 tools/far_reference.py
"""
import json
import os
import random

import mpmath
from mpmath import mp, mpf, sqrt

mp.dps = 50
from mp_ga import BLADES, N, NAMES, SIGNATURE, gp, reorder_sign  # noqa: F401






def grade(x, k):
    return {b: c for b, c in x.items() if bin(b).count("1") == k}


def add(*xs, weights=None):
    out = {}
    for x, w in zip(xs, weights or [1] * len(xs)):
        for b, c in x.items():
            out[b] = out.get(b, 0) + w * c
    return out


def scale(x, s):
    return {b: s * c for b, c in x.items()}


def reverse(x):
    return {b: c * (-1 if (bin(b).count("1") * (bin(b).count("1") - 1) // 2) & 1 else 1) for b, c in x.items()}


def outer(x, y):
    out = {}
    for a, ca in x.items():
        for b, cb in y.items():
            if a & b == 0:
                out[a | b] = out.get(a | b, 0) + reorder_sign(a, b) * ca * cb
    return out


def scalar(x):
    return x.get(0, mpf(0))


E = [{1 << i: mpf(1)} for i in range(N)]
EINF = add(E[3], E[4])
EO = scale(add(E[4], E[3], weights=[1, -1]), mpf("0.5"))


def up(x):
    x2 = sum(v * v for v in x)
    return add(*[scale(E[i], x[i]) for i in range(3)], scale(EINF, x2 / 2), EO)


def normalise(x):
    return scale(x, 1 / sqrt(abs(scalar(gp(x, reverse(x))))))


def circle(c, n, r):
    """Through three points counter-clockwise about n (the orientation of Circle::through)."""
    n = [v / sqrt(sum(w * w for w in n)) for v in n]
    axis = min(range(3), key=lambda k: abs(n[k]))
    e = [mpf(0)] * 3
    e[axis] = mpf(1)
    u = [n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]]
    lu = sqrt(sum(v * v for v in u))
    u = [r * v / lu for v in u]
    v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
    pts = [[c[k] + u[k] for k in range(3)], [c[k] + v[k] for k in range(3)], [c[k] - u[k] for k in range(3)]]
    return normalise(outer(outer(up(pts[0]), up(pts[1])), up(pts[2])))


def interpolate(c1, c2, alpha):
    x = add(c1, c2, weights=[1 - alpha, alpha])
    s_full = scale(gp(x, reverse(x)), -1)
    s, q = scalar(s_full), grade(s_full, 4)
    q2 = scalar(gp(q, q))
    a = sqrt((s + sqrt(s * s - q2)) / 2)
    k = add({0: a}, scale(q, 1 / (2 * a)))
    kstar = add({0: a}, scale(q, -1 / (2 * a)))
    inv = scale(kstar, 1 / scalar(gp(kstar, k)))
    return normalise(grade(gp(inv, x), 3))


def centre_radius(c):
    """Centre down(C einf C) and radius sqrt(-C^2 / (C ^ einf)^2)."""
    p = grade(gp(gp(c, EINF), c), 1)
    weight = -scalar(gp(p, EINF))
    centre = [p.get(1 << i, mpf(0)) / weight for i in range(3)]
    plane = outer(c, EINF)
    r2 = -scalar(gp(c, c)) / scalar(gp(plane, plane))
    return centre, sqrt(r2)


def carrier_normal(c):
    """Unit normal of the plane C ^ einf, from its dual -lambda (n + delta einf)."""
    plane = outer(c, EINF)
    i5 = {31: mpf(1)}
    dual = grade(gp(plane, scale(i5, -1)), 1)
    v = [-dual.get(1 << i, mpf(0)) for i in range(3)]
    length = sqrt(sum(x * x for x in v))
    return [x / length for x in v]


def dense(x):
    return [float(x.get(b, 0)) for b in BLADES]


def main():
    rng = random.Random(20261122)
    cases = []
    for k in range(40):
        distance = 10 ** rng.uniform(0, 3)
        r1, r2 = 10 ** rng.uniform(-2, 2), 10 ** rng.uniform(-2, 2)
        direction = [rng.gauss(0, 1) for _ in range(3)]
        length = sum(v * v for v in direction) ** 0.5
        c1 = [distance * v / length for v in direction]
        gap = max(r1, r2) * rng.uniform(0.5, 3)
        c2 = [c1[i] + gap * rng.uniform(-1, 1) for i in range(3)]
        n1 = [rng.uniform(-1, 1) for _ in range(3)]
        n2 = [rng.uniform(-1, 1) for _ in range(3)]
        # Round the inputs to f64 first.
        c1, c2, n1, n2 = [[float(v) for v in x] for x in (c1, c2, n1, n2)]
        r1, r2 = float(r1), float(r2)
        alpha = round(rng.uniform(0.05, 0.95), 6)
        m = lambda x: [mpf(v) for v in x]
        C1, C2 = circle(m(c1), m(n1), mpf(r1)), circle(m(c2), m(n2), mpf(r2))
        if (scalar(gp(C1, reverse(C1))) < 0) != (scalar(gp(C1, reverse(C2))) < 0):
            C2 = scale(C2, -1)
        # From the exact parameters: what a pipeline from centres, normals and radii should give.
        exact_centre, exact_radius = centre_radius(interpolate(C1, C2, mpf(alpha)))
        # The blades as f64 holds them are the inputs from here on: the reference is exact
        # for those numbers, as clifford's files are for theirs. (Rounded coefficients are not
        # exactly a blade, and interpolation amplifies that: these differ from the above.)
        C1, C2 = [{b: mpf(v) for b, v in zip(BLADES, dense(x)) if v != 0} for x in (C1, C2)]
        s_full = scale(gp(*(lambda x: (x, reverse(x)))(add(C1, C2, weights=[1 - alpha, alpha]))), -1)
        s, q2 = scalar(s_full), scalar(gp(grade(s_full, 4), grade(s_full, 4)))
        if s * s - q2 < 0 or s + sqrt(s * s - q2) <= 0:
            continue  # no real root: not a reference case
        Ca = interpolate(C1, C2, mpf(alpha))
        centre, radius = centre_radius(Ca)
        normal = carrier_normal(Ca)
        cases.append({
            # The fields of shared/golden/interpolation.json, so the same test reads both:
            # the blades rounded to f64 are the inputs; what follows is exact for them.
            "c1": dense(C1), "c2": dense(C2), "alpha": alpha,
            "x_alpha": dense(add(C1, C2, weights=[1 - mpf(alpha), mpf(alpha)])),
            "c_alpha": dense(Ca),
            "c_alpha_euc": {"centre": [float(v) for v in centre], "normal": [float(v) for v in normal],
                            "radius": float(radius)},
            # And the Euclidean parameters the blades were made from (C2 before alignment).
            "params": {"c1": {"centre": c1, "normal": n1, "radius": r1},
                       "c2": {"centre": c2, "normal": n2, "radius": r2},
                       "c_alpha": {"centre": [float(v) for v in exact_centre], "radius": float(exact_radius)}},
        })
    out = {
        "generator": "tools/far_reference.py (mpmath %s, %d digits; an independent minimal G(4,1))" % (mpmath.__version__, mp.dps),
        "blades": NAMES,
        "convention": "as shared/golden: up(x) = x + x^2/2 einf + eo, einf = e4 + e5, eo = (e5 - e4)/2; "
                      "blades normalised (X X~ = -1); C2 aligned to C1; X = (1 - alpha) C1 + alpha C2; C = K^-1 X",
        "ranges": "centres 1 ... 1e3 from the origin, radii 1e-2 ... 1e2",
        "reference_digits": mp.dps,
        "cases": cases,
    }
    path = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "far_interpolation.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print("%d cases -> %s" % (len(cases), path))


if __name__ == "__main__":
    main()
