"""To and from clifford's and kingdon's multivectors: every class round trips, the
conformal embedding and the products agree with theirs, and what does not fit is refused."""

import numpy as np
import pytest

import cga
from cga import interop

RNG = np.random.default_rng(11)


def random(cls, n=None):
    shape = (len(cls.blades),) if n is None else (n, len(cls.blades))
    return cls(RNG.normal(size=shape))


def close(a, b, ulps=2):
    """Equal within `ulps` units of the last place at the arrays' largest magnitude: a
    conversion rounds at most once or twice; a product computed in another order, by the
    few tens of terms summed (see the calls)."""
    a, b = np.asarray(a), np.asarray(b)
    return np.allclose(a, b, rtol=0, atol=ulps * 2.2e-16 * max(np.abs(a).max(), np.abs(b).max(), 1e-300))


@pytest.mark.parametrize("name", interop.CLASSES)
def test_every_class_round_trips_through_the_orthonormal_basis(name):
    cls = getattr(cga, name)
    for v in (random(cls), random(cls, 7)):
        c = interop.orthonormal(v)
        assert c.shape == v.array.shape[:-1] + (32,)
        back = interop.from_orthonormal(c)
        assert type(back) is cls and close(back.array, v.array)


def test_the_null_basis_in_orthonormal_terms():
    # eo = ½(e5 − e4), ei = e4 + e5, eo ∧ ei = −e45.
    named = lambda v: {b: float(x) for b, x in zip(interop.BLADES, interop.orthonormal(v)) if x != 0}
    assert named(cga.Vector([0, 0, 0, 1.0, 0])) == {"e4": -0.5, "e5": 0.5}
    assert named(cga.Vector([0, 0, 0, 0, 1.0])) == {"e4": 1.0, "e5": 1.0}
    assert named(cga.FlatPoint([0, 0, 0, 1.0])) == {"e45": -1.0}


def test_what_a_class_lacks_is_refused_by_name():
    c = interop.orthonormal(random(cga.Circle))
    with pytest.raises(cga.ValueError, match="a Line has no blades"):
        interop.from_orthonormal(c, cga.Line)
    mixed = interop.orthonormal(cga.up([1.0, 2.0, 3.0])) + interop.orthonormal(random(cga.Rotor))
    with pytest.raises(cga.ValueError, match="no class holds"):
        interop.from_orthonormal(mixed)
    with pytest.raises(cga.ShapeError):
        interop.from_orthonormal(np.zeros(31))


clifford = pytest.importorskip("clifford")


@pytest.mark.parametrize("name", interop.CLASSES)
def test_every_class_round_trips_through_clifford(name):
    cls = getattr(cga, name)
    v, many = random(cls), random(cls, 5)
    mv = cga.to_clifford(v)
    assert isinstance(mv, clifford.MultiVector)
    assert type(cga.from_clifford(mv)) is cls and close(cga.from_clifford(mv, cls).array, v.array)
    arr = cga.to_clifford(many)
    assert len(arr) == 5 and close(cga.from_clifford(arr, cls).array, many.array)


def test_points_and_products_agree_with_cliffords():
    from clifford.g3c import layout, up

    x = RNG.normal(size=(4, 3))
    e1, e2, e3 = (layout.blades[n] for n in ("e1", "e2", "e3"))
    theirs = [up(p[0] * e1 + p[1] * e2 + p[2] * e3) for p in x]
    ours = [cga.up(p) for p in x]
    for a, b in zip(ours, theirs):
        assert close(cga.to_clifford(a).value, b.value)
    circle = ours[0] ^ ours[1] ^ ours[2]
    assert close(cga.to_clifford(circle).value, (theirs[0] ^ theirs[1] ^ theirs[2]).value, ulps=8)
    m = cga.Motor.from_rotor_translation(cga.Rotor.from_axis_angle([0.3, 0.4, 1.0], 0.9), [1.0, 2.0, 3.0])
    M = cga.to_clifford(m)
    assert close(cga.to_clifford(m.sandwich(ours[3])).value, (M * theirs[3] * ~M).value, ulps=8)
    assert close(cga.to_clifford(m * m).value, (M * M).value, ulps=8)


def test_a_layout_of_another_algebra_is_refused():
    layout, _ = clifford.Cl(3)
    with pytest.raises(cga.ValueError, match="signature"):
        cga.to_clifford(cga.up([1.0, 0, 0]), layout)


kingdon = pytest.importorskip("kingdon")


@pytest.mark.parametrize("name", interop.CLASSES)
def test_every_class_round_trips_through_kingdon(name):
    alg = kingdon.Algebra(4, 1)
    cls = getattr(cga, name)
    for v in (random(cls), random(cls, 6)):
        mv = cga.to_kingdon(v, alg)
        assert type(cga.from_kingdon(mv)) is cls and close(cga.from_kingdon(mv, cls).array, v.array)


def test_products_agree_with_kingdons_on_arrays():
    alg = kingdon.Algebra(4, 1)
    p, q, r = (cga.up(RNG.normal(size=(9, 3))) for _ in range(3))
    P, Q, R = (cga.to_kingdon(v, alg) for v in (p, q, r))
    assert close(cga.from_kingdon(P ^ Q ^ R, cga.Circle).array, (p ^ q ^ r).array, ulps=8)
    m = cga.Motor.from_rotor_translation(cga.Rotor.from_axis_angle([0.0, 0.6, 0.8], 0.4), [0.5, -1.0, 2.0])
    M = cga.to_kingdon(m, alg)
    assert close(cga.from_kingdon(M >> P, cga.Vector).array, m.sandwich(p).array, ulps=8)
    with pytest.raises(cga.ValueError, match="signature"):
        cga.to_kingdon(m, kingdon.Algebra(3, 0, 1))
