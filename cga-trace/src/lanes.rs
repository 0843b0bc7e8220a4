//! Points in SIMD lanes: `W` points as three coordinates in lanes and back, a lane's value
//! or mask as an array. Below the camera and every back end, which both move points
//! between one ray and a packet of four.

use cga_core::euclid::E3;
use cga_core::simd::Lane;

/// Points (or vectors), one per lane, as three coordinates in lanes.
#[inline(always)]
pub(crate) fn lanes3<T: Lane, const W: usize>(v: [E3; W]) -> E3<T> {
    let at = |k: usize| T::from_fn(|l| v[l][k]);
    [at(0), at(1), at(2)]
}

/// The four lanes of `x` as an array.
#[inline(always)]
pub(crate) fn array<L: Lane>(x: L) -> [f64; 4] {
    [x.lane(0), x.lane(1), x.lane(2), x.lane(3)]
}

/// The mask's four lanes as truth values.
#[inline(always)]
pub(crate) fn mask_array<L: Lane>(m: L::Mask) -> [bool; 4] {
    let at = |l: usize| L::mask_lane(m, l);
    [at(0), at(1), at(2), at(3)]
}

/// Lane `l` of a point in lanes.
#[inline(always)]
pub(crate) fn lane<L: Lane>(x: &E3<L>, l: usize) -> E3 {
    [x[0].lane(l), x[1].lane(l), x[2].lane(l)]
}
