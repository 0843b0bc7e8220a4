#!/usr/bin/env python3
"""Golden vectors for the exponential of simple bivectors, computed with kingdon 3.0.0.

Writes tests/data/kingdon_exp.json: per algebra, bivectors b and kingdon's `b.exp()`, with
seeds and inputs from random.Random(SEED), SEED = 20261202:
- g21, G(2,1) (e1² = e2² = 1, e3² = −1): bivectors with coefficients uniform in [-2, 2]
  (every bivector of a 3D algebra is simple; rotations, boosts and null rotations occur);
- sta, G(1,3) (kingdon's start_index=0: e0² = 1, e1² = e2² = e3² = −1): the wedge of two
  vectors with coefficients k/8, k uniform in -8..8 (a simple bivector of any metric; dyadic,
  so that B ∧ B is exactly zero in floating point, which kingdon's exp requires);
- pga, G(3,0,1) (e0² = 0 first, as cga_algebras::pga declares it): the join of two points
  with coordinates k/8, k uniform in -16..16, scaled by k/8, k uniform in 1..8 (dyadic, for
  the same reason), and ideal lines with coefficients uniform in [-2, 2] (e01, e02, e03
  only; their exponential is a translation).
Coefficients are listed in canonical order (grade, then vector index increasing), read from
kingdon by bitmask, with kingdon's blade names (e13, e012, …): tests/tests/algebra/exp_log.rs carries
pga's over to its spellings (e31, e021, e032) with their signs.

Run (as made):
    python3 -m venv /tmp/kvenv && /tmp/kvenv/bin/pip install kingdon==3.0.0
    /tmp/kvenv/bin/python tools/kingdon_exp.py
"""
import json
import random
from pathlib import Path

import kingdon
from kingdon import Algebra

SEED = 20261202
rng = random.Random(SEED)
out = {"provenance": f"tools/kingdon_exp.py, kingdon {kingdon.__version__}, seed {SEED}"}


def canonical(n):
    return sorted(range(1 << n), key=lambda m: (bin(m).count("1"), [i for i in range(n) if m >> i & 1]))


def read(x, order):
    have = dict(zip(x.keys(), x.values())) if hasattr(x, "keys") else {0: x}
    return [float(have.get(m, 0.0)) for m in order]


def cases(alg, n, bivectors):
    order = canonical(n)
    return [{"b": read(b, order), "exp": read(b.exp(), order)} for b in bivectors]


g21 = Algebra(2, 1)
out["g21"] = cases(g21, 3, [g21.bivector([rng.uniform(-2, 2) for _ in range(3)]) for _ in range(20)])

sta = Algebra(1, 3, start_index=0)
vec = lambda: sta.vector([rng.randint(-8, 8) / 8 for _ in range(4)])
out["sta"] = cases(sta, 4, [vec() ^ vec() for _ in range(20)])

pga = Algebra(3, 0, 1)


def point(x, y, z):
    # bivector.net's e123 + x e032 + y e013 + z e021, in kingdon's canonical blades.
    return pga.trivector(e123=1.0, e023=-x, e013=y, e012=-z)


lines = []
for _ in range(16):
    p = point(*[rng.randint(-16, 16) / 8 for _ in range(3)])
    q = point(*[rng.randint(-16, 16) / 8 for _ in range(3)])
    lines.append((p & q) * (rng.randint(1, 8) / 8))
for _ in range(4):
    lines.append(pga.bivector(e01=rng.uniform(-2, 2), e02=rng.uniform(-2, 2), e03=rng.uniform(-2, 2)))
out["pga"] = cases(pga, 4, lines)

path = Path(__file__).resolve().parent.parent / "tests" / "data" / "kingdon_exp.json"
path.write_text(json.dumps(out) + "\n")
print(f"wrote {path}")
