#!/usr/bin/env python3
"""Golden vectors for 3D projective geometric algebra G(3,0,1), computed with kingdon 3.0.0.

Writes tests/data/kingdon_pga.json: for random multivectors a, b (every blade, coefficients
uniform in [-2, 2] from random.Random(SEED), SEED = 20261202) kingdon's geometric product,
outer product, left and right contractions, regressive product (`a & b`), dual and undual of a, and the
join of two points and the meet of two planes given by Euclidean parameters. Coefficients are
listed in canonical order (grade, then basis order, e0 first): s, e0, e1, e2, e3, e01, e02,
e03, e12, e13, e23, e012, e013, e023, e123, e0123, kingdon's own blade names. `cga_algebras::pga`
spells three of them as bivector.net does (e31, e021, e032), and `tests/tests/algebra/pga.rs` carries
the data over with those blades' signs. kingdon takes the pseudoscalar as e0123 and the dual
as the right complement (`e0.dual() = e123`).

Run (as made):
    python3 -m venv /tmp/kvenv && /tmp/kvenv/bin/pip install kingdon==3.0.0
    /tmp/kvenv/bin/python tools/kingdon_pga.py
"""
import json
import random
from pathlib import Path

import kingdon
from kingdon import Algebra

SEED = 20261202
BLADES = ["e", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e13", "e23",
          "e012", "e013", "e023", "e123", "e0123"]

alg = Algebra(3, 0, 1)
rng = random.Random(SEED)


def make(coeffs):
    return alg.multivector({k: c for k, c in zip(BLADES, coeffs) if c != 0.0})


def read(x):
    if not hasattr(x, "keys"):  # a plain number
        return [float(x)] + [0.0] * 15
    return [float(getattr(x, k, 0) if k != "e" else x.e) for k in BLADES]


def point(x, y, z):
    return alg.trivector(e123=1.0, e023=-x, e013=y, e012=-z)


cases = []
for _ in range(40):
    a = [rng.uniform(-2, 2) for _ in BLADES]
    b = [rng.uniform(-2, 2) for _ in BLADES]
    A, B = make(a), make(b)
    cases.append({
        "a": a, "b": b,
        "gp": read(A * B), "op": read(A ^ B), "lc": read(A.lc(B)), "rc": read(A.rc(B)), "rp": read(A & B),
        "dual": read(A.dual()), "undual": read(A.undual()),
    })

joins = []
for _ in range(10):
    p = [rng.uniform(-5, 5) for _ in range(3)]
    q = [rng.uniform(-5, 5) for _ in range(3)]
    joins.append({"p": p, "q": q, "join": read(point(*p) & point(*q))})

meets = []
for _ in range(10):
    m = [rng.uniform(-2, 2) for _ in range(4)]
    n = [rng.uniform(-2, 2) for _ in range(4)]
    plane = lambda c: alg.vector(e1=c[0], e2=c[1], e3=c[2], e0=c[3])
    meets.append({"m": m, "n": n, "meet": read(plane(m) ^ plane(n))})

out = {
    "provenance": f"tools/kingdon_pga.py, kingdon {kingdon.__version__}, seed {SEED}",
    "blades": BLADES,
    "cases": cases,
    "joins": joins,
    "meets": meets,
}
path = Path(__file__).resolve().parent.parent / "tests" / "data" / "kingdon_pga.json"
path.write_text(json.dumps(out, indent=1) + "\n")
print(f"wrote {path}: {len(cases)} cases, {len(joins)} joins, {len(meets)} meets")
