#!/usr/bin/env python3
"""Operation reference vectors far from the origin, in 50-digit arithmetic (mpmath).

Writes tests/data/far_operations.json: the Euclidean answers of tests/golden/operations.json
(projections of points, distances, reflections in a plane and inversions in a sphere of points
and spheres, the meets line ^ sphere, sphere ^ sphere and three planes, and the images of points
under interpolated motors) for inputs with coordinates up to 1e3 and radii 1e-2 ... 1e2.

Inputs are drawn as f64 (random.Random(SEED), SEED = 20261203) and are exactly what the file
holds; the reference converts them exactly (mpmath.mpf(float)) and computes with closed-form
Euclidean formulas at mp.dps = 50. Directions and normals are f64 vectors of length 1 to
rounding: the reference normalises them exactly (v / |v| in 50 digits), as a consumer
normalising in f64 does to ~1e-16. Every output is written as a JSON float, the nearest f64 of
the 50-digit value (so exact to the last bit bar the final rounding).

The motor samples also carry the motors themselves (32 floats in the golden blade order),
built exactly from the Euclidean screw with an independent minimal G(4,1) (orthonormal
e1..e5, e5^2 = -1, blades as bitmasks, as tools/far_reference.py), in the golden conventions:
up(x) = x + x^2/2 einf + eo, einf = e4 + e5, eo = (e5 - e4)/2, R = cos(th/2) - sin(th/2) a I3,
T = 1 - t einf / 2, M = T R.

Each family is checked in 50 digits (projections lie on their target, images map back, meet
points lie on both objects, the motors move points where the Euclidean screw does) to 1e-35
relative.

Run: python3 -m pip install mpmath==1.3.0 && python3 tools/far_operations.py
"""
import json
import os
import random
import re

import mpmath
from mpmath import mp, mpf, sqrt, cos, sin, atan2, tan, pi

mp.dps = 50
SEED = 20261203
CHECK = mpf(10) ** -35

# ---------------------------------------------------------------------------------------------
# Euclidean vectors: lists of 3 mpf.


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def mul(a, s):
    return [a[i] * s for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return sqrt(dot(a, a))


def unit(a):
    return mul(a, 1 / norm(a))


def M(v):
    """An f64 vector (or float) as exact mpf."""
    return [mpf(float(x)) for x in v] if isinstance(v, (list, tuple)) else mpf(float(v))


def F(v):
    return [float(x) for x in v] if isinstance(v, (list, tuple)) else float(v)


def check(value, scale, what):
    assert abs(value) <= CHECK * max(abs(scale), 1), (what, value)


def rodrigues(v, a, th):
    c, s = cos(th), sin(th)
    return add(add(mul(v, c), mul(cross(a, v), s)), mul(a, dot(a, v) * (1 - c)))


# ---------------------------------------------------------------------------------------------
# Minimal G(4,1), for the motors.

from mp_ga import BLADES, N, NAMES, SIGNATURE, gp, reorder_sign  # noqa: F401






def mvadd(*xs):
    out = {}
    for x in xs:
        for b, c in x.items():
            out[b] = out.get(b, 0) + c
    return out


def mvscale(x, s):
    return {b: s * c for b, c in x.items()}


def reverse(x):
    return {b: c * (-1 if (bin(b).count("1") * (bin(b).count("1") - 1) // 2) & 1 else 1) for b, c in x.items()}


E = [{1 << i: mpf(1)} for i in range(N)]
EINF = mvadd(E[3], E[4])
EO = mvscale(mvadd(E[4], mvscale(E[3], -1)), mpf("0.5"))
I3 = {0b111: mpf(1)}


def vec(x):
    return mvadd(*[mvscale(E[i], x[i]) for i in range(3)])


def up(x):
    return mvadd(vec(x), mvscale(EINF, dot(x, x) / 2), EO)


def down(X):
    """The Euclidean point of a weighted point X: X / w, w = -X . einf = X_e5 - X_e4."""
    w = X.get(16, mpf(0)) - X.get(8, mpf(0))
    return [X.get(1 << i, mpf(0)) / w for i in range(3)]


def rotor(axis, th):
    """cos(th/2) - sin(th/2) a I3, a = axis normalised."""
    a = unit(axis)
    return mvadd({0: cos(th / 2)}, mvscale(gp(vec(a), I3), -sin(th / 2)))


def translator(t):
    """1 - t einf / 2."""
    return mvadd({0: mpf(1)}, mvscale(gp(vec(t), EINF), mpf(-0.5)))


def sandwich(Mv, X):
    return gp(gp(Mv, X), reverse(Mv))


def dense(x):
    return [float(x.get(b, 0)) for b in BLADES]


def rot_matrix(axis, th):
    a = unit(axis)
    cols = [rodrigues([mpf(int(i == k)) for i in range(3)], a, th) for k in range(3)]
    return [[cols[k][i] for k in range(3)] for i in range(3)]


def matvec(R, x):
    return [sum(R[i][k] * x[k] for k in range(3)) for i in range(3)]


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(A):
    return [[A[j][i] for j in range(3)] for i in range(3)]


def chasles(R, t):
    """x -> R x + t as a screw: unit axis a, angle phi in [0, pi), point q on the axis, slide s."""
    c = (R[0][0] + R[1][1] + R[2][2] - 1) / 2
    w = [R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]]
    sn = norm(w) / 2
    phi = atan2(sn, c)
    a = mul(w, 1 / (2 * sn))
    s = dot(t, a)
    tp = sub(t, mul(a, s))
    q = mul(add(tp, mul(cross(a, tp), 1 / tan(phi / 2))), mpf("0.5"))
    return a, phi, q, s


def screw_motor(sc, frac):
    """The motor of the screw by frac: T(frac s a) T(q) R(a, frac phi) T(-q)."""
    a, phi, q, s = sc
    Tq = translator(q)
    return gp(translator(mul(a, frac * s)), gp(gp(Tq, rotor(a, frac * phi)), reverse(Tq)))


def screw_point(y, sc, frac):
    a, phi, q, s = sc
    return add(add(q, rodrigues(sub(y, q), a, frac * phi)), mul(a, frac * s))


# ---------------------------------------------------------------------------------------------

rng = random.Random(SEED)


def far_point():
    d = [rng.gauss(0, 1) for _ in range(3)]
    length = sum(v * v for v in d) ** 0.5
    dist = 10 ** rng.uniform(0, 3)
    return [dist * v / length for v in d]


def direction():
    d = [rng.gauss(0, 1) for _ in range(3)]
    length = sum(v * v for v in d) ** 0.5
    return [v / length for v in d]


def radius():
    return 10 ** rng.uniform(-2, 2)


def near(c, r, lo=0.2, hi=5.0):
    """A point at lo..hi radii from c (f64)."""
    d = direction()
    k = r * rng.uniform(lo, hi)
    return [c[i] + k * d[i] for i in range(3)]


def perp_f(n):
    """An f64 vector perpendicular to n (to rounding), unit to rounding."""
    i = min(range(3), key=lambda k: abs(n[k]))
    e = [0.0, 0.0, 0.0]
    e[i] = 1.0
    p = [n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]]
    length = sum(v * v for v in p) ** 0.5
    return [v / length for v in p]


def project_point():
    cases = []
    for i in range(24):
        kind = ["line", "plane", "sphere", "circle"][i % 4]
        c, r = far_point(), radius()
        x = near(c, r)
        X = M(x)
        if kind == "line":
            d = direction()
            target = {"point": c, "direction": d}
            p, dd = M(c), unit(M(d))
            proj = add(p, mul(dd, dot(sub(X, p), dd)))
            check(dot(sub(X, proj), dd), r, "line foot")
        elif kind == "plane":
            n = direction()
            target = {"point": c, "normal": n}
            p, nn = M(c), unit(M(n))
            proj = sub(X, mul(nn, dot(sub(X, p), nn)))
            check(dot(sub(proj, p), nn), r, "plane foot")
        elif kind == "sphere":
            target = {"centre": c, "radius": r}
            cc, rr = M(c), M(r)
            proj = add(cc, mul(unit(sub(X, cc)), rr))
            check(norm(sub(proj, cc)) - rr, r, "sphere foot")
        else:
            n = direction()
            target = {"centre": c, "normal": n, "radius": r}
            cc, nn, rr = M(c), unit(M(n)), M(r)
            y = sub(X, mul(nn, dot(sub(X, cc), nn)))
            proj = add(cc, mul(unit(sub(y, cc)), rr))
            check(norm(sub(proj, cc)) - rr, r, "circle foot")
            check(dot(sub(proj, cc), nn), r, "circle plane")
        rej = sub(X, proj)
        cases.append({"target_kind": kind, "target": target, "x": x, "projection": F(proj), "reject": F(rej),
                      "distance": F(norm(rej))})
    return cases


def distances():
    cases = []
    for i in range(24):
        kind = ["point_line", "point_plane", "point_sphere", "line_line"][i % 4]
        c, r = far_point(), radius()
        if kind == "point_line":
            d, x = direction(), near(c, r)
            p, dd, X = M(c), unit(M(d)), M(x)
            foot = add(p, mul(dd, dot(sub(X, p), dd)))
            cases.append({"kind": kind, "x": x, "line": {"point": c, "direction": d}, "distance": F(norm(sub(X, foot))),
                          "foot": F(foot)})
        elif kind == "point_plane":
            n, x = direction(), near(c, r)
            p, nn, X = M(c), unit(M(n)), M(x)
            sd = dot(sub(X, p), nn)
            cases.append({"kind": kind, "x": x, "plane": {"point": c, "normal": n}, "distance": F(sd),
                          "foot": F(sub(X, mul(nn, sd)))})
        elif kind == "point_sphere":
            x = near(c, r, 0.1, 3)
            cc, rr, X = M(c), M(r), M(x)
            cases.append({"kind": kind, "x": x, "sphere": {"centre": c, "radius": r},
                          "distance": F(norm(sub(X, cc)) - rr), "nearest": F(add(cc, mul(unit(sub(X, cc)), rr)))})
        else:
            d1, d2 = direction(), direction()
            p2 = near(c, r)
            P1, D1, P2, D2 = M(c), unit(M(d1)), M(p2), unit(M(d2))
            b = dot(D1, D2)
            r0 = sub(P1, P2)
            s = (b * dot(D2, r0) - dot(D1, r0)) / (1 - b * b)
            t = (dot(D2, r0) - b * dot(D1, r0)) / (1 - b * b)
            c1, c2 = add(P1, mul(D1, s)), add(P2, mul(D2, t))
            check(dot(sub(c1, c2), D1), r, "common perpendicular 1")
            check(dot(sub(c1, c2), D2), r, "common perpendicular 2")
            cases.append({"kind": kind, "flag": "skew", "line1": {"point": c, "direction": d1},
                          "line2": {"point": p2, "direction": d2}, "distance": F(norm(sub(c1, c2))),
                          "closest1": F(c1), "closest2": F(c2)})
    return cases


def reflect_in_plane():
    cases = []
    for i in range(20):
        kind = ["point", "sphere"][i % 2]
        p0, r = far_point(), radius()
        n0 = direction()
        P, N_ = M(p0), unit(M(n0))
        m = lambda x: sub(x, mul(N_, 2 * dot(sub(x, P), N_)))
        if kind == "point":
            x = near(p0, r)
            img = m(M(x))
            check(norm(sub(m(img), M(x))), r, "mirror twice")
            cases.append({"mirror": {"point": p0, "normal": n0}, "kind": kind, "object": {"x": x}, "image": {"x": F(img)}})
        else:
            c, rr = near(p0, r), r * rng.uniform(0.1, 2)
            img = m(M(c))
            cases.append({"mirror": {"point": p0, "normal": n0}, "kind": kind, "object": {"centre": c, "radius": rr},
                          "image": {"centre": F(img), "radius": rr}})
    return cases


def circumsphere(a, b, c, d):
    u, v, w = sub(b, a), sub(c, a), sub(d, a)
    vol = dot(u, cross(v, w))
    num = add(add(mul(cross(v, w), dot(u, u)), mul(cross(w, u), dot(v, v))), mul(cross(u, v), dot(w, w)))
    centre = add(a, mul(num, 1 / (2 * vol)))
    return centre, norm(sub(centre, a))


def invert_in_sphere():
    cases = []
    for i in range(20):
        kind = ["point", "sphere"][i % 2]
        c0, R = far_point(), radius()
        C0, RR = M(c0), M(R)
        iv = lambda x: add(C0, mul(sub(x, C0), RR * RR / dot(sub(x, C0), sub(x, C0))))
        if kind == "point":
            x = near(c0, R)
            img = iv(M(x))
            check(norm(sub(iv(img), M(x))), R, "invert twice")
            cases.append({"sphere": {"centre": c0, "radius": R}, "kind": kind, "object": {"x": x},
                          "image_kind": "point", "image": {"x": F(img)}})
        else:
            # A sphere away from c0 (its centre 1.5 ... 5 radii R off, radius below that distance).
            c2 = near(c0, R, 1.5, 5)
            dist = sum((c2[k] - c0[k]) ** 2 for k in range(3)) ** 0.5
            r2 = dist * rng.uniform(0.05, 0.8)
            C2, R2 = M(c2), M(r2)
            s = RR * RR / (dot(sub(C2, C0), sub(C2, C0)) - R2 * R2)
            centre, rad = add(C0, mul(sub(C2, C0), s)), abs(s) * R2
            pts = [iv(add(C2, mul(unit(M(direction())), R2))) for _ in range(4)]
            cc, rr = circumsphere(*pts)
            check(norm(sub(cc, centre)), rad, "inverted sphere centre")
            check(rr - rad, rad, "inverted sphere radius")
            cases.append({"sphere": {"centre": c0, "radius": R}, "kind": kind, "object": {"centre": c2, "radius": r2},
                          "image_kind": "sphere", "image": {"centre": F(centre), "radius": F(rad)}})
    return cases


def meets():
    cases = []
    for hit in ["two"] * 6 + ["miss"] * 4:
        c, r = far_point(), radius()
        d = direction()
        w = perp_f(d)
        h = r * (rng.uniform(0, 0.9) if hit == "two" else rng.uniform(1.1, 3))
        s = r * rng.uniform(-3, 3)
        p = [c[k] + h * w[k] + s * d[k] for k in range(3)]
        P, D, CC, RR = M(p), unit(M(d)), M(c), M(r)
        foot = add(P, mul(D, dot(sub(CC, P), D)))
        h2 = dot(sub(CC, foot), sub(CC, foot))
        assert (h2 < RR * RR) == (hit == "two")
        case = {"kind": "line_sphere", "line": {"point": p, "direction": d}, "sphere": {"centre": c, "radius": r},
                "hit": hit, "margin": F((RR - sqrt(h2)) / RR)}
        if hit == "two":
            t = sqrt(RR * RR - h2)
            pts = [sub(foot, mul(D, t)), add(foot, mul(D, t))]
            for q in pts:
                check(norm(sub(q, CC)) - RR, r, "line sphere point")
            case["points"] = [F(q) for q in pts]
        else:
            case["points"] = None
        cases.append(case)
    for hit in ["two"] * 6 + ["miss"] * 4:
        c1, r1 = far_point(), radius()
        r2 = r1 * 10 ** rng.uniform(-1, 1)
        m = direction()
        if hit == "two":
            dd = abs(r1 - r2) + (r1 + r2 - abs(r1 - r2)) * rng.uniform(0.05, 0.95)
        else:
            dd = (r1 + r2) * rng.uniform(1.1, 2) if rng.random() < 0.5 else abs(r1 - r2) * rng.uniform(0.1, 0.9)
        c2 = [c1[k] + dd * m[k] for k in range(3)]
        C1, C2, R1, R2 = M(c1), M(c2), M(r1), M(r2)
        n = sub(C2, C1)
        dist = norm(n)
        n = mul(n, 1 / dist)
        a = (dist * dist + R1 * R1 - R2 * R2) / (2 * dist)
        rad2 = R1 * R1 - a * a
        assert (rad2 > 0) == (hit == "two")
        centre = add(C1, mul(n, a))
        case = {"kind": "sphere_sphere", "sphere1": {"centre": c1, "radius": r1}, "sphere2": {"centre": c2, "radius": r2},
                "hit": hit, "circle": {"centre": F(centre), "normal": F(n), "radius_squared": F(rad2),
                                       "radius": F(sqrt(rad2)) if rad2 > 0 else None}}
        if hit == "two":
            q = add(centre, mul(unit(cross(n, M(direction()))), sqrt(rad2)))
            check(norm(sub(q, C1)) - R1, r1, "circle on sphere 1")
            check(norm(sub(q, C2)) - R2, r2, "circle on sphere 2")
        cases.append(case)
    for _ in range(10):
        c, r = far_point(), radius()
        ns = [direction() for _ in range(3)]
        ps = [near(c, r) for _ in range(3)]
        NN = [unit(M(n)) for n in ns]
        PP = [M(p) for p in ps]
        rhs = [dot(NN[k], PP[k]) for k in range(3)]
        x = mpmath.lu_solve(mpmath.matrix([[NN[k][j] for j in range(3)] for k in range(3)]), mpmath.matrix(rhs))
        x = [x[k] for k in range(3)]
        for k in range(3):
            check(dot(NN[k], x) - rhs[k], norm(x), "three planes")
        cases.append({"kind": "three_planes", "planes": [{"point": p, "normal": n} for p, n in zip(ps, ns)],
                      "hit": "one", "point": F(x)})
    return cases


def motor_interpolate():
    cases = []
    for _ in range(10):
        while True:
            a0, a1 = direction(), direction()
            th0, th1 = rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5)
            t0 = far_point()
            t1 = [t0[k] + v for k, v in enumerate(mul(direction(), 10 ** rng.uniform(-1, 2)))]
            R0, R1 = rot_matrix(M(a0), M(th0)), rot_matrix(M(a1), M(th1))
            Rrel = matmul(R1, transpose(R0))
            T0, T1 = M(t0), M(t1)
            sc = chasles(Rrel, sub(T1, matvec(Rrel, T0)))
            # The relative rotor's scalar part positive (turn below pi): the principal log is then the
            # shortest screw, the one computed here.
            rel_scalar = gp(rotor(M(a1), M(th1)), reverse(rotor(M(a0), M(th0)))).get(0, 0)
            if 0.05 < sc[1] < 2.6 and rel_scalar > 0:
                break
        xs = [near([0.0, 0.0, 0.0], 10 ** rng.uniform(0, 2.5), 0.5, 1.5) for _ in range(3)]
        M0 = gp(translator(T0), rotor(M(a0), M(th0)))
        M1 = gp(translator(T1), rotor(M(a1), M(th1)))
        samples = []
        for t in [0, 0.25, 0.5, 0.75, 1] + [round(rng.uniform(-0.5, 1.5), 6) for _ in range(2)]:
            Mt = gp(screw_motor(sc, mpf(t)), M0)
            images = []
            for x in xs:
                y = screw_point(add(matvec(R0, M(x)), T0), sc, mpf(t))
                z = down(sandwich(Mt, up(M(x))))
                check(norm(sub(z, y)), norm(y), "motor moves the point as the screw")
                images.append(F(y))
            if t == 1:
                for b in set(Mt) | set(M1):
                    check(Mt.get(b, 0) - M1.get(b, 0), 1, "M(1) = M1")
            samples.append({"t": t, "motor_mv": dense(Mt), "images": images})
        cases.append({"m0": {"axis": a0, "angle": th0, "translation": t0},
                      "m1": {"axis": a1, "angle": th1, "translation": t1},
                      "m0_mv": dense(M0), "m1_mv": dense(M1),
                      "screw": {"axis": F(sc[0]), "angle": F(sc[1]), "point": F(sc[2]), "slide": F(sc[3])},
                      "xs": xs, "samples": samples})
    return cases


FAMILIES = {
    "project_point": "24 cases, target_kind line {point, direction} | plane {point, normal} | sphere {centre, radius} | circle "
                     "{centre, normal, radius}; x; projection (nearest point: foot on the line or plane, c + r (x-c)/|x-c|, the "
                     "circle's c + r (y-c)/|y-c| for y the foot of x on its plane), reject = x - projection, distance = |reject|",
    "distances": "24 cases: point_line {x, line, distance, foot}; point_plane {x, plane, distance = (x-p).n signed, foot}; "
                 "point_sphere {x, sphere, distance = |x-c| - r signed, nearest}; line_line {flag skew, line1, line2, distance, "
                 "closest1 on line1, closest2 on line2}",
    "reflect_in_plane": "20 cases, kind point {x} | sphere {centre, radius}; mirror {point, normal}; image (mirrored point / centre "
                        "x - 2((x-p).n)n, radius kept). Orientation as in operations.json (a mirrored sphere is -sphere(image))",
    "invert_in_sphere": "20 cases, kind point | sphere; sphere {centre c, radius R}; object; image_kind; image (point c + R^2 "
                        "(x-c)/|x-c|^2; sphere (c2, r2), c outside it: centre c + s(c2-c), radius |s| r2, s = R^2/(|c2-c|^2 - r2^2))",
    "meets": "line_sphere {line, sphere, hit two|miss, margin = (r - h)/r for h the line's distance from the centre, points "
             "[2] ordered along the direction or null}; sphere_sphere {sphere1, sphere2, hit two (a real circle)|miss, circle "
             "{centre, normal = (c2-c1)/|c2-c1|, radius_squared (negative for a miss), radius or null}}; three_planes {planes [3] "
             "{point, normal}, hit one, point}",
    "motor_interpolate": "10 cases. m0, m1 {axis, angle, translation}: M = T(translation) R(axis, angle), x -> R x + t; m0_mv, "
                         "m1_mv (exact, rounded); the relative motor M1 M0~ has a positive scalar part (its principal log is the "
                         "shortest screw); screw: the relative motion M1 M0~ as a screw {axis, angle in (0, 2.6), point on "
                         "the axis, slide}; xs (test points); samples [{t, motor_mv = exp(t log(M1 M0~)) M0, images of xs}] for t "
                         "in 0, 0.25, 0.5, 0.75, 1 and two in [-0.5, 1.5]",
}


def compact(text):
    return re.sub(r"\[\s+([-+0-9.eE,\s]+?)\s+\]", lambda m: "[" + ", ".join(s.strip() for s in m.group(1).split(",")) + "]", text)


def main():
    out = {
        "generator": "tools/far_operations.py (mpmath %s, %d digits; closed-form Euclidean formulas; an independent "
                     "minimal G(4,1) for the motors); seed %d" % (mpmath.__version__, mp.dps, SEED),
        "blades": NAMES,
        "convention": "as tests/golden/operations.json: up(x) = x + x^2/2 einf + eo, einf = e4 + e5, eo = (e5 - e4)/2; "
                      "R = cos(th/2) - sin(th/2) a I3, T = 1 - t einf/2, M = T R; directions and normals are normalised "
                      "exactly by the reference",
        "ranges": "centres and points up to 1e3 from the origin, radii 1e-2 ... 1e2, test points near their objects "
                  "(0.1 ... 5 radii)",
        "number_format": "inputs: the f64 values used, exactly; outputs: JSON floats, each the nearest f64 of the "
                         "50-digit result",
        "reference_digits": mp.dps,
        "families": FAMILIES,
    }
    for name, fn in [("project_point", project_point), ("distances", distances), ("reflect_in_plane", reflect_in_plane),
                     ("invert_in_sphere", invert_in_sphere), ("meets", meets), ("motor_interpolate", motor_interpolate)]:
        cases = fn()
        out[name] = cases
        print("%-18s %3d cases, all checked to 1e-35" % (name, len(cases)))
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "far_operations.json")
    with open(path, "w") as f:
        f.write(compact(json.dumps(out, indent=1)))
        f.write("\n")
    print("-> %s (%d bytes)" % (os.path.normpath(path), os.path.getsize(path)))


if __name__ == "__main__":
    main()
