//! Work on large arrays shared between the calling thread and rayon's: the caller starts at
//! once and helpers join as they wake, each taking the next chunk, so a helper that was
//! asleep costs only the chunks it arrives too late for (the caller of a rayon loop would
//! otherwise sit idle while every worker wakes).

use std::sync::Mutex;

/// `f(state, c, chunk)` on every chunk `c` of `out` (`rows` items each, the last shorter),
/// on the calling thread and as many of rayon's as there are chunks to share, each with its
/// own `init()` state.
pub fn share<T: Send, S>(
    out: &mut [T],
    rows: usize,
    init: impl Fn() -> S + Sync,
    f: impl Fn(&mut S, usize, &mut [T]) + Sync,
) {
    let count = out.len().div_ceil(rows.max(1));
    let chunks = Mutex::new(out.chunks_mut(rows.max(1)).enumerate());
    let next = || chunks.lock().unwrap_or_else(|e| e.into_inner()).next();
    let work = || {
        let mut state = init();
        while let Some((c, chunk)) = next() {
            f(&mut state, c, chunk);
        }
    };
    let helpers = rayon::current_num_threads().min(count).saturating_sub(1);
    rayon::in_place_scope(|s| {
        for _ in 0..helpers {
            s.spawn(|_| work());
        }
        work();
    });
}
