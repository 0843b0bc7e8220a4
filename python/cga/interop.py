"""Values to and from clifford's g3c ``MultiVector`` and kingdon's ``MultiVector``, in the
orthonormal basis both use: ``e1 … e5`` with ``e4² = 1`` and ``e5² = −1``, blades named by
ascending indices (``e1245``).

Our blades are outer products in the null basis, ``eo = ½(e5 − e4)`` and ``ei = e4 + e5``
(so ``eo·ei = −1``): ``eoi = eo ∧ ei = −e45``, ``e1i = e14 + e15``, and so on. Each class's
coefficients map to the 32 orthonormal ones by one matrix, built here from those two
substitutions, and back by its inverse. Neither clifford nor kingdon is imported until a
conversion to it is asked for.

    >>> import cga
    >>> x = cga.up([1.0, 2.0, 3.0])
    >>> c = cga.interop.orthonormal(x)
    >>> [(name, float(c[i])) for i, name in enumerate(cga.interop.BLADES) if c[i] != 0]
    [('e1', 1.0), ('e2', 2.0), ('e3', 3.0), ('e4', 6.5), ('e5', 7.5)]
    >>> cga.interop.from_orthonormal(c) == x
    True
"""

from itertools import combinations, product

import numpy as np

from . import _cga

#: The 32 orthonormal blades in clifford's order: by grade, then by indices (``""`` is the
#: scalar).
BLADES = [""] + ["e" + "".join(map(str, c)) for k in range(1, 6) for c in combinations(range(1, 6), k)]
_INDEX = {name: i for i, name in enumerate(BLADES)}

#: A coefficient counts as present above this fraction of its value's largest (the
#: conversions' rounding is a few units of 1e-16 of it).
TOLERANCE = 1e-13

#: Each null-basis vector in orthonormal vectors.
_VECTORS = {"1": {1: 1.0}, "2": {2: 1.0}, "3": {3: 1.0}, "o": {4: -0.5, 5: 0.5}, "i": {4: 1.0, 5: 1.0}}

#: The classes a converted value may take, the first that holds its blades (the fewest blades
#: first among those that do).
CLASSES = ["Scalar", "Vector", "Bivector", "FlatPoint", "Line", "Circle", "Plane", "Sphere", "Pseudoscalar",
           "Rotor", "Translator", "Motor", "Dilator", "Transversor", "Generator", "ScalarQuadvector", "Even", "Odd"]


def _blade(name):
    """Our blade ``name`` (``"s"``, ``"e1o"``, …) as {orthonormal blade index: coefficient}."""
    factors = [] if name == "s" else list(name[1:])
    out = {}
    for choice in product(*(_VECTORS[f].items() for f in factors)):
        indices = [i for i, _ in choice]
        if len(set(indices)) < len(indices):
            continue
        # The sign of sorting the indices (each swap of two orthogonal vectors flips it).
        sign = 1.0
        for a in range(len(indices)):
            for b in range(a + 1, len(indices)):
                if indices[a] > indices[b]:
                    sign = -sign
        coefficient = sign * np.prod([c for _, c in choice])
        key = _INDEX["e" + "".join(map(str, sorted(indices))) if indices else ""]
        out[key] = out.get(key, 0.0) + coefficient
    return out


def _matrix(cls):
    """The 32 × k matrix taking a class's coefficients to orthonormal ones."""
    m = np.zeros((32, len(cls.blades)))
    for j, name in enumerate(cls.blades):
        for i, c in _blade(name).items():
            m[i, j] = c
    return m


# Every blade of ours (the even and odd classes hold all 32) and the inverse map, whose
# entries (from e4 = ½ei − eo, e5 = ½ei + eo) are multiples of ¼: exact once rounded to them.
_OURS = list(_cga.Even.blades) + list(_cga.Odd.blades)
_TO = np.concatenate([_matrix(_cga.Even), _matrix(_cga.Odd)], axis=1)
_FROM = np.round(np.linalg.inv(_TO) * 4) / 4


def orthonormal(value):
    """A value's (or array's) 32 orthonormal coefficients in :data:`BLADES` order: shape
    ``(32,)`` or ``(n, 32)``."""
    return np.asarray(value.array) @ _matrix(type(value)).T


def from_orthonormal(coefficients, cls=None):
    """The value (or array) with these orthonormal coefficients (shape ``(32,)`` or
    ``(n, 32)``, :data:`BLADES` order), of class ``cls``, or else of the first class in
    :data:`CLASSES` that holds every blade with a nonzero coefficient; refused
    (``cga.ValueError``) where ``cls`` lacks one of them."""
    c = np.asarray(coefficients, dtype=float)
    if c.shape[-1:] != (32,) or c.ndim not in (1, 2):
        raise _cga.ShapeError(f"orthonormal coefficients of shape {c.shape}: give (32,) or (n, 32)")
    ours = c @ _FROM.T
    # Present: above the rounding of the conversions, relative to each value's largest.
    rows = np.abs(ours.reshape(-1, 32))
    nonzero = np.any(rows > TOLERANCE * rows.max(axis=1, keepdims=True), axis=0)
    present = {_OURS[i] for i in np.flatnonzero(nonzero)}
    if cls is None:
        holding = [getattr(_cga, n) for n in CLASSES if present <= set(getattr(_cga, n).blades)]
        if not holding:
            raise _cga.ValueError(f"no class holds the blades {sorted(present)} (mixed even and odd grades)")
        cls = min(holding, key=lambda k: len(k.blades))
    keep = [_OURS.index(b) for b in cls.blades]
    dropped = sorted(present - set(cls.blades))
    if dropped:
        raise _cga.ValueError(f"a {cls.__name__} has no blades {dropped}")
    return cls(ours[..., keep])


def _signature_checked(signature, names, library):
    if list(signature) != [1, 1, 1, 1, -1]:
        raise _cga.ValueError(f"{library}'s algebra has signature {list(signature)}: CGA needs [1, 1, 1, 1, -1]")
    missing = set(BLADES) - set(names)
    if missing:
        raise _cga.ValueError(f"{library}'s algebra lacks the blades {sorted(missing)}")


def _clifford_layout(layout):
    if layout is None:
        from clifford.g3c import layout
    _signature_checked(layout.sig, layout.names, "clifford")
    return layout, np.array([_INDEX[n] for n in layout.names])


def to_clifford(value, layout=None):
    """A value as a clifford ``MultiVector`` of ``layout`` (default ``clifford.g3c.layout``),
    an array as a ``clifford.MVArray`` of them."""
    import clifford

    layout, order = _clifford_layout(layout)
    c = orthonormal(value)[..., order]
    if c.ndim == 1:
        return layout.MultiVector(c)
    return clifford.MVArray([layout.MultiVector(row) for row in c])


def from_clifford(mv, cls=None, layout=None):
    """A clifford ``MultiVector`` (or a sequence or ``MVArray`` of them, or an ``(n, 32)``
    array of their ``value`` s in ``layout``'s order) as a value or array of ``cls`` (else
    the class that holds its blades, as :func:`from_orthonormal`)."""
    if hasattr(mv, "layout") and hasattr(mv, "value"):
        layout, values = mv.layout, np.asarray(mv.value)
    elif isinstance(mv, np.ndarray) and mv.dtype != object:
        values = mv
    else:
        rows = list(mv)
        layout = layout or (rows[0].layout if rows else None)
        values = np.array([np.asarray(r.value) for r in rows]).reshape(-1, 32)
    layout, order = _clifford_layout(layout)
    c = np.zeros(values.shape)
    c[..., order] = values
    return from_orthonormal(c, cls)


def _kingdon_checked(alg):
    _signature_checked(alg.signature, BLADES, "kingdon")


def _bits(name):
    """An orthonormal blade's bit mask in kingdon (``e1`` is 1, ``e5`` is 16)."""
    return sum(1 << (int(d) - 1) for d in name[1:])


def to_kingdon(value, alg):
    """A value (or array) as a kingdon ``MultiVector`` of ``alg`` (``Algebra(4, 1)``), an
    array's coefficients as numpy arrays, one a blade (the blades the class reaches only)."""
    _kingdon_checked(alg)
    c = orthonormal(value)
    reached = np.flatnonzero(np.any(_matrix(type(value)) != 0.0, axis=1))
    keys = [_bits(BLADES[i]) for i in reached]
    values = [c[..., i] if c.ndim == 2 else float(c[i]) for i in reached]
    order = np.argsort(keys)
    return alg.multivector(values=[values[i] for i in order], keys=tuple(keys[i] for i in order))


def from_kingdon(mv, cls=None):
    """A kingdon ``MultiVector`` of ``Algebra(4, 1)`` (its coefficients numbers, or arrays
    of one length) as a value or array of ``cls`` (else the class that holds its blades, as
    :func:`from_orthonormal`)."""
    _kingdon_checked(mv.algebra)
    values = [np.asarray(v, dtype=float) for v in mv.values()]
    n = max((v.size for v in values if v.ndim > 0), default=None)
    c = np.zeros((32,) if n is None else (n, 32))
    for key, v in zip(mv.keys(), values):
        name = "e" + "".join(str(b + 1) for b in range(5) if key >> b & 1) if key else ""
        c[..., _INDEX[name]] = v
    return from_orthonormal(c, cls)
