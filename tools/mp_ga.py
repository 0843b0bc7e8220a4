"""G(4,1) at mpmath precision, shared by the reference generators (far_reference.py,
far_operations.py, far_objects.py): multivectors are dicts blade bitmask -> mpf over the
orthonormal basis e1..e5 (e4² = +1, e5² = −1), blades ordered as the golden files order them
(by grade, then lexicographic)."""

N = 5
SIGNATURE = [1, 1, 1, 1, -1]
# The golden files' blade order: by grade, then lexicographic.
BLADES = sorted(range(1 << N), key=lambda b: (bin(b).count("1"), [i for i in range(N) if b >> i & 1]))
NAMES = ["1" if b == 0 else "e" + "".join(str(i + 1) for i in range(N) if b >> i & 1) for b in BLADES]


def reorder_sign(a, b):
    """Sign of moving the factors of blade a past those of blade b into canonical order."""
    a >>= 1
    swaps = 0
    while a:
        swaps += bin(a & b).count("1")
        a >>= 1
    return -1 if swaps & 1 else 1


def gp(x, y):
    """The geometric product of two multivectors."""
    out = {}
    for a, ca in x.items():
        for b, cb in y.items():
            s = reorder_sign(a, b)
            for i in range(N):
                if a & b & (1 << i):
                    s *= SIGNATURE[i]
            out[a ^ b] = out.get(a ^ b, 0) + s * ca * cb
    return out
