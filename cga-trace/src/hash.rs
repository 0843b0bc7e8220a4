//! The integer hashes that scramble each pixel's sample sequences: where in the pixel its
//! samples fall, their lens and light points, and the instants a shutter takes them at.

/// A 32-bit integer hash with good avalanche (two multiply–xorshift rounds).
pub(crate) fn hash(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^ (x >> 16)
}

/// A hash of pixel `(i, j)` for one use, `salt` (each use its own, so they are uncorrelated).
pub(crate) fn pixel(i: u32, j: u32, salt: u32) -> u32 {
    hash(i ^ hash(j ^ salt))
}

/// Element `i` of a pseudo-random permutation of `0 .. n` chosen by `seed`: Kensler's
/// hash-based permutation ("Correlated Multi-Jittered Sampling", 2013), cycle-walking to
/// stay below `n`.
pub(crate) fn permute(mut i: u32, n: u32, seed: u32) -> u32 {
    if n <= 1 {
        return 0;
    }
    let mut w = n - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    loop {
        i ^= seed;
        i = i.wrapping_mul(0xe170_893d);
        i ^= seed >> 16;
        i ^= (i & w) >> 4;
        i ^= seed >> 8;
        i = i.wrapping_mul(0x0929_eb3f);
        i ^= seed >> 23;
        i ^= (i & w) >> 1;
        i = i.wrapping_mul(1 | seed >> 27);
        i = i.wrapping_mul(0x6935_fa69);
        i ^= (i & w) >> 11;
        i = i.wrapping_mul(0x74dc_b303);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0x9e50_1cc3);
        i ^= (i & w) >> 2;
        i = i.wrapping_mul(0xc860_a3df);
        i &= w;
        i ^= i >> 5;
        if i < n {
            return (i.wrapping_add(seed)) % n;
        }
    }
}

/// A seeded stream of numbers in [0, 1) (xorshift64), for the tests.
#[cfg(test)]
pub(crate) fn stream(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}
