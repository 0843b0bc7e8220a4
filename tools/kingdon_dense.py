#!/usr/bin/env python3
"""Golden vectors for the dense types of 2D CGA G(3,1) and the spacetime algebra G(1,3),
computed with kingdon 3.0.0.

Writes tests/data/kingdon_dense.json: per algebra, random multivectors a, b (every blade,
coefficients uniform in [-2, 2] from random.Random(SEED), SEED = 20261202) and kingdon's
geometric and outer products, left and right contractions, regressive product (`a & b`),
dual (`a I⁻¹`) and undual of a. Coefficients are in the orthonormal basis e1..e4 (p vectors
squaring to +1, then q to −1, as kingdon and `algebra!` both order them), blades in canonical
order (grade, then vector indices increasing), read from kingdon by bitmask.

Run (as made):
    python3 -m venv /tmp/kvenv && /tmp/kvenv/bin/pip install kingdon==3.0.0
    /tmp/kvenv/bin/python tools/kingdon_dense.py
"""
import json
import random
from pathlib import Path

import kingdon
from kingdon import Algebra

SEED = 20261202
rng = random.Random(SEED)
out = {"provenance": f"tools/kingdon_dense.py, kingdon {kingdon.__version__}, seed {SEED}"}

for name, (p, q) in [("cga2", (3, 1)), ("sta", (1, 3))]:
    n = p + q
    alg = Algebra(p, q)
    order = sorted(range(1 << n), key=lambda m: (bin(m).count("1"), [i for i in range(n) if m >> i & 1]))

    def make(coeffs):
        return alg.multivector(keys=tuple(order), values=list(coeffs))

    def read(x):
        have = dict(zip(x.keys(), x.values())) if hasattr(x, "keys") else {0: x}
        return [float(have.get(m, 0.0)) for m in order]

    cases = []
    for _ in range(30):
        a = [rng.uniform(-2, 2) for _ in order]
        b = [rng.uniform(-2, 2) for _ in order]
        A, B = make(a), make(b)
        cases.append({
            "a": a, "b": b,
            "gp": read(A * B), "op": read(A ^ B), "lc": read(A.lc(B)), "rc": read(A.rc(B)),
            "rp": read(A & B), "dual": read(A.dual()), "undual": read(A.undual()),
        })
    out[name] = {"signature": [p, q], "cases": cases}

path = Path(__file__).resolve().parent.parent / "tests" / "data" / "kingdon_dense.json"
path.write_text(json.dumps(out) + "\n")
print(f"wrote {path}")
