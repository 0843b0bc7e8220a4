//! One safeguarded Newton iteration for every root finder here: Newton steps with the exact
//! slope, replaced by bisection whenever a step would leave the bracket.

use cga_core::Real;

/// When to stop: `|g|` at the rounding level of `g` where it is evaluated (below `noise`, an
/// upper bound of that level over the bracket, and below the level at the point itself), a
/// step or bracket no larger than `max(absolute, relative · |α|)`, or `iterations` steps.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stop<T> {
    pub noise: T,
    pub absolute: T,
    pub relative: T,
    pub iterations: usize,
}

/// The root of `g` in `[lo, hi]`, where `g(lo)` is positive iff `positive_lo` and `g(hi)` has
/// the other sign, starting from `start` (the midpoint if it lies outside). `g` returns the
/// value and slope; where it cannot be evaluated the current estimate is returned. `noise_at(x)`
/// is `g`'s rounding level at `x`, asked only where `|g(x)| ≤ stop.noise`: a polynomial whose
/// coefficients span many decades is far more accurate near its small coefficients than its
/// largest one says, and stopping at the global level there left roots 1e-6 off in α.
pub(crate) fn safeguarded<T: Real>(
    mut g: impl FnMut(T) -> Option<(T, T)>,
    noise_at: impl Fn(T) -> T,
    (mut lo, mut hi): (T, T),
    positive_lo: bool,
    start: T,
    stop: Stop<T>,
) -> T {
    let half = T::from_f64(0.5);
    let mut x = if start > lo && start < hi { start } else { half * (lo + hi) };
    for _ in 0..stop.iterations {
        let Some((value, slope)) = g(x) else { return x };
        if value.abs() <= stop.noise && value.abs() <= noise_at(x) {
            return x;
        }
        if (value > T::zero()) == positive_lo {
            lo = x;
        } else {
            hi = x;
        }
        let step = x - value / slope;
        let next = if step > lo && step < hi { step } else { half * (lo + hi) };
        let small = stop.absolute.max(stop.relative * next.abs());
        if (next - x).abs() <= small || hi - lo <= stop.absolute {
            return next;
        }
        x = next;
    }
    x
}
