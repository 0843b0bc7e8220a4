#!/usr/bin/env python3
"""`import cga` against kingdon 3.0.0 and clifford 1.5.1, each with numba, on three batched
operations, interleaved rounds, medians of wall time (the Python call included):

- 1e6 conformal points moved by one motor (`M X M̃`),
- 1e5 line–sphere meets (the regressive product),
- 1e5 circles through three points (`A ∧ B ∧ C`): ours as `cga.wedge(A, B, C)` (the chain
  taken a block of rows at a time) and as `A ^ B ^ C` (the operators one by one).

Each library gets its idiomatic batch form: ours an array object (one call, rows in Rust),
kingdon a multivector whose coefficients are numpy arrays with its operators compiled by
numba (`Algebra(4, 1, wrapper=numba.njit)`), clifford its numba-compiled product functions
(`layout.gmt_func`, …) in an `@numba.njit` loop over rows. Each answer is read back in
Euclidean terms and compared (moved points, the meets' `P·P` over `(L·L)(S·S)`, circle radii):
the table says how many digits agree. Compilation (numba's first call) is left out.

    python3 -m venv /tmp/peers
    /tmp/peers/bin/pip install kingdon==3.0.0 clifford==1.5.1 numba ./python
    /tmp/peers/bin/python tools/python_peers.py [ROUNDS]
"""

import statistics
import sys
import time

import numba
import numpy as np

import cga

ROUNDS = int(sys.argv[1]) if len(sys.argv) > 1 else 5
RNG = np.random.default_rng(1)
# PEERS_SHRINK=100 divides the sizes (a quick check of the harness itself).
SHRINK = int(__import__("os").environ.get("PEERS_SHRINK", "1"))
N_POINTS, N_MEETS, N_CIRCLES = 1_000_000 // SHRINK, 100_000 // SHRINK, 100_000 // SHRINK
ANGLE, AXIS, SHIFT = 0.9, np.array([0.3, 0.4, 1.0]) / np.linalg.norm([0.3, 0.4, 1.0]), np.array([1.0, 2.0, 3.0])


def orthonormal_points(x):
    """Conformal points in e1 … e5 (e4² = 1, e5² = −1): x + (½x² − ½) e4 + (½x² + ½) e5."""
    h = 0.5 * np.sum(x * x, axis=1)
    return np.stack([x[:, 0], x[:, 1], x[:, 2], h - 0.5, h + 0.5])


def euclidean(c):
    """Points from e1 … e5 coefficients (5, n): x over the weight −X·ei = e5 − e4."""
    return (c[:3] / (c[4] - c[3])).T


# --- ours -------------------------------------------------------------------------------------

def ours_setup():
    x = RNG.normal(size=(N_POINTS, 3))
    m = cga.Motor.from_rotor_translation(cga.Rotor.from_axis_angle(AXIS, ANGLE), SHIFT)
    X = cga.up(x)
    a, b = RNG.normal(size=(N_MEETS, 3)), RNG.normal(size=(N_MEETS, 3))
    lines, sphere = cga.Line.through(a, b), cga.Sphere.from_centre_radius([0.1, 0.2, 0.3], 1.5)
    pqr = [RNG.normal(size=(N_CIRCLES, 3)) for _ in range(3)]
    p, q, r = (cga.up(v) for v in pqr)
    return x, (a, b), pqr, dict(m=m, X=X, lines=lines, sphere=sphere, p=p, q=q, r=r)


def ours_motor(s):
    return s["m"].sandwich(s["X"])


def ours_meet(s):
    return s["lines"] & s["sphere"]


def ours_circle(s):
    return cga.wedge(s["p"], s["q"], s["r"])


def ours_circle_steps(s):
    return s["p"] ^ s["q"] ^ s["r"]


# --- kingdon ----------------------------------------------------------------------------------

def kingdon_setup(x, ab, pqr):
    from kingdon import Algebra

    alg = Algebra(4, 1, wrapper=numba.njit)
    e = alg.blades
    ei, eo = e.e4 + e.e5, 0.5 * (e.e5 - e.e4)
    up = lambda pts: alg.vector(orthonormal_points(pts))
    # M = T R: R = cos(θ/2) − sin(θ/2) a I3, T = 1 − ½ t ei.
    i3 = e.e123
    a_dual = AXIS[0] * e.e1 * i3 + AXIS[1] * e.e2 * i3 + AXIS[2] * e.e3 * i3
    R = np.cos(ANGLE / 2) - np.sin(ANGLE / 2) * a_dual
    t = SHIFT[0] * e.e1 + SHIFT[1] * e.e2 + SHIFT[2] * e.e3
    T = 1 - 0.5 * t * ei
    M = T * R
    a, b = ab
    lines = up(a) ^ up(b) ^ ei
    c, rad = np.array([0.1, 0.2, 0.3]), 1.5
    centre = alg.vector(orthonormal_points(c[None, :])[:, 0])
    sphere = (centre - 0.5 * rad * rad * ei).dual()
    p, q, r = (up(v) for v in pqr)
    return dict(alg=alg, M=M, X=up(x), lines=lines, sphere=sphere, p=p, q=q, r=r, ei=ei)


def kingdon_motor(s):
    return s["M"] >> s["X"]


def kingdon_meet(s):
    return s["lines"] & s["sphere"]


def kingdon_circle(s):
    return s["p"] ^ s["q"] ^ s["r"]


# --- clifford ---------------------------------------------------------------------------------

def clifford_setup(x, ab, pqr):
    from clifford.g3c import blades, layout

    gmt, omt, vee, rev = layout.gmt_func, layout.omt_func, layout.vee_func, layout.adjoint_func
    idx = {n: k for k, n in enumerate(layout.names)}

    def up(pts):
        out = np.zeros((len(pts), 32))
        c = orthonormal_points(pts)
        for k, n in enumerate(["e1", "e2", "e3", "e4", "e5"]):
            out[:, idx[n]] = c[k]
        return out

    @numba.njit
    def sandwich_all(M, Mr, X):
        out = np.empty_like(X)
        for i in range(X.shape[0]):
            out[i] = gmt(gmt(M, X[i]), Mr)
        return out

    @numba.njit
    def meet_all(L, S):
        out = np.empty_like(L)
        for i in range(L.shape[0]):
            out[i] = vee(L[i], S)
        return out

    @numba.njit
    def outer3_all(P, Q, R):
        out = np.empty_like(P)
        for i in range(P.shape[0]):
            out[i] = omt(omt(P[i], Q[i]), R[i])
        return out

    e1, e2, e3, e4, e5 = (blades[n] for n in ["e1", "e2", "e3", "e4", "e5"])
    ei = e4 + e5
    i3 = e1 * e2 * e3
    R = np.cos(ANGLE / 2) - np.sin(ANGLE / 2) * (AXIS[0] * e1 + AXIS[1] * e2 + AXIS[2] * e3) * i3
    T = 1 - 0.5 * (SHIFT[0] * e1 + SHIFT[1] * e2 + SHIFT[2] * e3) * ei
    M = (T * R).value
    a, b = ab
    ei_v = np.zeros(32)
    ei_v[idx["e4"]], ei_v[idx["e5"]] = 1.0, 1.0
    A, B = up(a), up(b)
    lines = np.array([omt(omt(A[i], B[i]), ei_v) for i in range(len(A))])
    c = up(np.array([[0.1, 0.2, 0.3]]))[0]
    sphere_dual = c - 0.5 * 1.5 * 1.5 * ei_v
    sphere = layout.MultiVector(sphere_dual).dual().value
    P, Q, Rr = (up(v) for v in pqr)
    return dict(
        M=M, Mr=rev(M), X=up(x), lines=lines, sphere=sphere, p=P, q=Q, r=Rr, idx=idx,
        sandwich_all=sandwich_all, meet_all=meet_all, outer3_all=outer3_all, gmt=gmt, layout=layout,
    )


def clifford_motor(s):
    return s["sandwich_all"](s["M"], s["Mr"], s["X"])


def clifford_meet(s):
    return s["meet_all"](s["lines"], s["sphere"])


def clifford_circle(s):
    return s["outer3_all"](s["p"], s["q"], s["r"])


# --- the comparison ---------------------------------------------------------------------------

def digits(a, b):
    """Significant digits the two arrays agree to (relative to the larger magnitude)."""
    err = np.max(np.abs(a - b) / np.maximum(np.abs(a), np.abs(b)).clip(1e-300))
    return 16.0 if err == 0 else -np.log10(err)


def main():
    x, ab, pqr, ours = ours_setup()
    peers = {"kingdon": kingdon_setup(x, ab, pqr), "clifford": clifford_setup(x, ab, pqr)}
    rows = [
        ("1e6 points by one motor", ours_motor, {"kingdon": kingdon_motor, "clifford": clifford_motor}),
        ("1e5 line–sphere meets", ours_meet, {"kingdon": kingdon_meet, "clifford": clifford_meet}),
        ("1e5 circles through three points", ours_circle, {"kingdon": kingdon_circle, "clifford": clifford_circle}),
        ("1e5 circles, ours as `p ^ q ^ r`", ours_circle_steps, {"kingdon": kingdon_circle, "clifford": clifford_circle}),
    ]
    # Answers, read back in Euclidean terms.
    moved = cga.down(ours_motor(ours))
    k_moved = euclidean(np.array(kingdon_motor(peers["kingdon"]).values()))
    c = clifford_motor(peers["clifford"])
    idx = peers["clifford"]["idx"]
    c_moved = euclidean(np.stack([c[:, idx[n]] for n in ["e1", "e2", "e3", "e4", "e5"]]))
    agree = {"1e6 points by one motor": (digits(moved, k_moved), digits(moved, c_moved))}
    # Meets: P·P over (L·L)(S·S), which no sign or scale convention changes.
    ratio_ours = (lambda P, L, S: np.asarray((P | P).array).ravel() / (np.asarray((L | L).array).ravel() * float((S | S).array[0])))(
        ours_meet(ours), ours["lines"], ours["sphere"]
    )
    ks = peers["kingdon"]
    kp = kingdon_meet(ks)
    ratio_k = np.asarray((kp | kp).e) / (np.asarray((ks["lines"] | ks["lines"]).e) * (ks["sphere"] | ks["sphere"]).e)
    cs = peers["clifford"]
    L = cs["layout"]
    cp = clifford_meet(cs)
    sq = lambda v: np.array([(L.MultiVector(r) | L.MultiVector(r))[()] for r in v])
    ratio_c = sq(cp) / (sq(cs["lines"]) * (L.MultiVector(cs["sphere"]) | L.MultiVector(cs["sphere"]))[()])
    agree["1e5 line–sphere meets"] = (digits(ratio_ours, ratio_k), digits(ratio_ours, ratio_c))
    # Circles: C·C over (C ∧ ei)², minus the radius² (scale free).
    r_ours = ours_circle(ours).centre_normal_radius()[2]
    kc = kingdon_circle(ks)
    kci = kc ^ ks["ei"]
    r_k = np.sqrt(np.abs(np.asarray((kc | kc).e) / np.asarray((kci | kci).e)))
    cc = clifford_circle(cs)
    ei_mv = L.MultiVector(np.eye(32)[idx["e4"]] + np.eye(32)[idx["e5"]])
    r_c = np.array([np.sqrt(abs((L.MultiVector(v) | L.MultiVector(v))[()] / ((L.MultiVector(v) ^ ei_mv) | (L.MultiVector(v) ^ ei_mv))[()])) for v in cc[:2000]])
    agree["1e5 circles through three points"] = (digits(r_ours, r_k), digits(r_ours[:2000], r_c))
    r_steps = ours_circle_steps(ours).centre_normal_radius()[2]
    agree["1e5 circles, ours as `p ^ q ^ r`"] = (digits(r_steps, r_k), digits(r_steps[:2000], r_c))

    times = {name: {lib: [] for lib in ["ours", "kingdon", "clifford"]} for name, _, _ in rows}
    for _ in range(ROUNDS):
        for name, ours_f, peer_fs in rows:
            for lib, f, state in [("ours", ours_f, ours)] + [(p, peer_fs[p], peers[p]) for p in peers]:
                t = time.perf_counter()
                f(state)
                times[name][lib].append(time.perf_counter() - t)
    print(f"{ROUNDS} interleaved rounds, medians of wall time; digits: how far the answers agree with ours")
    print("| operation | ours | kingdon + numba | clifford + numba | kingdon / ours | clifford / ours | digits (kingdon, clifford) |")
    print("|---|---|---|---|---|---|---|")
    for name, _, _ in rows:
        med = {lib: statistics.median(v) for lib, v in times[name].items()}
        dk, dc = agree[name]
        print(
            f"| {name} | {med['ours'] * 1e3:.1f} ms | {med['kingdon'] * 1e3:.1f} ms | {med['clifford'] * 1e3:.1f} ms | "
            f"{med['kingdon'] / med['ours']:.1f}× | {med['clifford'] / med['ours']:.1f}× | {dk:.1f}, {dc:.1f} |"
        )


if __name__ == "__main__":
    main()
