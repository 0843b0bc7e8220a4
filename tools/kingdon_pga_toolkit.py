#!/usr/bin/env python3
"""Golden vectors for the PGA toolkit (cga_algebras::pga's motors, exp, log, sqrt,
interpolation, normalisation, and the signs of the joins), computed with kingdon 3.0.0.

Writes tests/data/kingdon_pga_toolkit.json, coefficients in kingdon's canonical order (the
BLADES list below, as tools/kingdon_pga.py lists them), seed SEED = 20261206,
random.Random(SEED):

- rotors: unit axis a, angle θ; kingdon's (−θ/2 (a₁ e23 − a₂ e13 + a₃ e12)).exp(), and the
  point x moved by it (R >> P).
- translators: t; (−½ (t₁ e01 + t₂ e02 + t₃ e03)).exp() and the point moved.
- screws: a line through p along unit d, angle θ ∈ (−3, 3), slide δ; L̂ = (P & Q).normalized(),
  the generator B = −θ/2 L̂ + δ/2 I L̂, and M = exp(δ/2 I L̂) exp(−θ/2 L̂) = (1 + δ/2 I L̂)(cos θ/2
  − sin θ/2 L̂) in kingdon's products (its exp() refuses L̂ itself, whose L̂ ∧ L̂ is rounding, not
  zero), the point moved, and the half screw of θ/2, δ/2 (√M; kingdon's M.sqrt() is also
  listed, which agrees for rotations and translations only).
- interpolations: A a screw as above, D another with |θ| < 3, B = D A; at t, the screw of tθ, tδ about L̂_D,
  times A.
- normalised: a perturbed motor M (8 coefficients) and kingdon's M.normalized().
- signs: a point P (weight 1) and a plane p, kingdon's P & p, p & P, P ^ p, p ^ P; two points'
  P & Q and two planes' p ^ q.

Run (as made):
    python3 -m venv /tmp/kvenv && /tmp/kvenv/bin/pip install kingdon==3.0.0
    /tmp/kvenv/bin/python tools/kingdon_pga_toolkit.py
"""
import json
import math
import random
import warnings
from pathlib import Path

import kingdon
from kingdon import Algebra

SEED = 20261206
BLADES = ["e", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e13", "e23",
          "e012", "e013", "e023", "e123", "e0123"]

alg = Algebra(3, 0, 1)
rng = random.Random(SEED)
I = alg.pseudoscalar(e0123=1.0)


def read(x):
    if not hasattr(x, "keys"):  # a plain number
        return [float(x)] + [0.0] * 15
    return [float(getattr(x, k, 0) if k != "e" else x.e) for k in BLADES]


def point(x):
    return alg.trivector(e123=1.0, e023=-x[0], e013=x[1], e012=-x[2])


def plane(c):
    return alg.vector(e1=c[0], e2=c[1], e3=c[2], e0=c[3])


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def vec(lo, hi, n=3):
    return [rng.uniform(lo, hi) for _ in range(n)]


def screw(p, d, theta, delta):
    """kingdon's unit line through p along d, the generator, and the motor."""
    line = (point(p) & point([p[k] + d[k] for k in range(3)])).normalized()
    b = -theta / 2 * line + delta / 2 * (I * line)
    return line, b, turn_slide(line, theta, delta), turn_slide(line, theta / 2, delta / 2)


def turn_slide(line, theta, delta):
    """exp(δ/2 I L̂) exp(−θ/2 L̂) = (1 + δ/2 I L̂)(cos θ/2 − sin θ/2 L̂) in kingdon's products:
    its exp() refuses L̂, whose L̂ ∧ L̂ is rounding, not zero."""
    return (1 + delta / 2 * (I * line)) * (math.cos(theta / 2) - math.sin(theta / 2) * line)


rotors = []
for _ in range(12):
    a, theta, x = unit(vec(-1, 1)), rng.uniform(-3.1, 3.1), vec(-5, 5)
    r = (-theta / 2 * alg.bivector(e23=a[0], e13=-a[1], e12=a[2])).exp()
    rotors.append({"axis": a, "angle": theta, "x": x, "motor": read(r), "moved": read(r >> point(x))})

translators = []
for _ in range(8):
    t, x = vec(-5, 5), vec(-5, 5)
    m = (-0.5 * alg.bivector(e01=t[0], e02=t[1], e03=t[2])).exp()
    translators.append({"t": t, "x": x, "motor": read(m), "moved": read(m >> point(x))})

screws = []
for n in range(16):
    p, d, x = vec(-5, 5), unit(vec(-1, 1)), vec(-5, 5)
    # Far-from-origin lines, tiny turns and pure-ish slides among them.
    if n == 12:
        p = [1e3 + c for c in p]
    theta = [1e-9, 1e-4, 3.0, -2.9][n - 12] if n >= 12 else rng.uniform(-3, 3)
    delta = rng.uniform(-4, 4)
    line, b, m, half = screw(p, d, theta, delta)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ksqrt = m.sqrt()
    screws.append({"p": p, "d": d, "angle": theta, "distance": delta, "x": x, "line": read(line),
                   "generator": read(b), "motor": read(m), "moved": read(m >> point(x)),
                   "half": read(half), "kingdon_sqrt": read(ksqrt)})

interpolations = []
for _ in range(8):
    _, _, a, _ = screw(vec(-3, 3), unit(vec(-1, 1)), rng.uniform(-3, 3), rng.uniform(-3, 3))
    p, dd, theta, delta = vec(-3, 3), unit(vec(-1, 1)), rng.uniform(-3, 3), rng.uniform(-3, 3)
    line, _, d, _ = screw(p, dd, theta, delta)
    b = d * a
    for t in (0.25, 0.5, 0.75):
        mt = turn_slide(line, t * theta, t * delta) * a
        interpolations.append({"a": read(a), "b": read(b), "t": t, "want": read(mt)})

normalised = []
for _ in range(8):
    _, _, m, _ = screw(vec(-3, 3), unit(vec(-1, 1)), rng.uniform(-3, 3), rng.uniform(-3, 3))
    c = [v * rng.uniform(0.5, 2.0) + rng.uniform(-0.05, 0.05) for v in read(m)]
    mm = alg.evenmv(**{k: c[i] for i, k in enumerate(BLADES) if k in
                       ("e", "e01", "e02", "e03", "e12", "e13", "e23", "e0123")})
    normalised.append({"motor": read(mm), "want": read(mm.normalized())})

signs = []
for _ in range(6):
    x, c = vec(-5, 5), vec(-2, 2, 4)
    P, p = point(x), plane(c)
    y, c2 = vec(-5, 5), vec(-2, 2, 4)
    signs.append({"x": x, "plane": c, "y": y, "plane2": c2,
                  "point_vee_plane": read(P & p), "plane_vee_point": read(p & P),
                  "point_wedge_plane": read(P ^ p), "plane_wedge_point": read(p ^ P),
                  "planes_meet": read(p ^ plane(c2)), "points_join": read(P & point(y))})

out = {
    "provenance": f"tools/kingdon_pga_toolkit.py, kingdon {kingdon.__version__}, seed {SEED}",
    "blades": BLADES,
    "rotors": rotors,
    "translators": translators,
    "screws": screws,
    "interpolations": interpolations,
    "normalised": normalised,
    "signs": signs,
}
path = Path(__file__).resolve().parent.parent / "tests" / "data" / "kingdon_pga_toolkit.json"
path.write_text(json.dumps(out, indent=1) + "\n")
print(f"wrote {path}: {len(rotors)} rotors, {len(translators)} translators, {len(screws)} screws, "
      f"{len(interpolations)} interpolations, {len(normalised)} normalised, {len(signs)} signs")
