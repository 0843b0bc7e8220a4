#!/usr/bin/env python3
"""Golden vectors for a ten-dimensional algebra, G(9,1), computed with kingdon 3.0.0.

Writes tests/data/kingdon_g91.json: random vectors a, b, bivectors B and trivectors T (every
blade, coefficients uniform in [-1, 1] from random.Random(SEED), SEED = 20261202), a rotor
R, the product of two unit vectors of e1..e9, and kingdon's a b, a B, B ∧ a, a ⌋ T and
R a R~. Each value is listed on its type's blades only, in the canonical order of `tests/tests/algebra/dimension.rs`
(grade, then vector indices increasing; e1..e9 square to +1, the tenth, kingdon's `eA` and
our `ea`, to −1). kingdon's coefficients are read by bitmask, so no blade name is translated.

Run (as made):
    python3 -m venv /tmp/kvenv && /tmp/kvenv/bin/pip install kingdon==3.0.0
    /tmp/kvenv/bin/python tools/kingdon_g91.py
"""
import json
import random
from pathlib import Path

import kingdon
from kingdon import Algebra

SEED = 20261202
N = 10
alg = Algebra(9, 1)
rng = random.Random(SEED)

ORDER = sorted(range(1 << N), key=lambda m: (bin(m).count("1"), [i for i in range(N) if m >> i & 1]))
GRADE = {k: [m for m in ORDER if bin(m).count("1") == k] for k in range(N + 1)}
TYPES = {
    "vector": GRADE[1],
    "bivector": GRADE[2],
    "trivector": GRADE[3],
    "rotor": GRADE[0] + GRADE[2],
    "odd": GRADE[1] + GRADE[3],
}


def make(kind, coeffs):
    return alg.multivector(keys=tuple(TYPES[kind]), values=list(coeffs))


def read(kind, x):
    have = dict(zip(x.keys(), x.values())) if hasattr(x, "keys") else {0: x}
    extra = [k for k, v in have.items() if k not in TYPES[kind] and abs(float(v)) > 1e-12]
    assert not extra, f"{kind}: kingdon's result has blades {extra} outside the type"
    return [float(have.get(m, 0.0)) for m in TYPES[kind]]


def rand(kind, scale=1.0):
    return [rng.uniform(-scale, scale) for _ in TYPES[kind]]


cases = []
for _ in range(12):
    a, b, B, T = rand("vector"), rand("vector"), rand("bivector"), rand("trivector")
    va, vb, vB, vT = make("vector", a), make("vector", b), make("bivector", B), make("trivector", T)
    # A rotor as the product of two unit vectors of e1..e9 (so R R~ = 1).
    units = []
    for _ in range(2):
        u = [rng.uniform(-1, 1) for _ in range(9)]
        norm = sum(x * x for x in u) ** 0.5
        units.append(make("vector", [x / norm for x in u] + [0.0]))
    rotor = read("rotor", units[0] * units[1])
    cases.append({
        "a": a, "b": b, "B": B, "T": T, "R": rotor,
        "ab": read("rotor", va * vb),
        "aB": read("odd", va * vB),
        "B_wedge_a": read("trivector", vB ^ va),
        "a_lc_T": read("bivector", va.lc(vT)),
        "R_a_Rrev": read("vector", make("rotor", rotor) * va * ~make("rotor", rotor)),
    })

out = {"provenance": f"tools/kingdon_g91.py, kingdon {kingdon.__version__}, seed {SEED}", "cases": cases}
path = Path(__file__).resolve().parent.parent / "tests" / "data" / "kingdon_g91.json"
path.write_text(json.dumps(out) + "\n")
print(f"wrote {path}: {len(cases)} cases")
