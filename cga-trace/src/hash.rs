//! The integer hash that scrambles each pixel's sample sequences: where in the pixel its
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
