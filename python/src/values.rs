//! Values of one cga-core type: one, or N of them as an N × k array of coefficients (k the
//! type's blades, in its own order), and the broadcasting of a binary map over two of them.

use crate::errors::{ShapeError, ValueError};
use pyo3::prelude::*;
use std::sync::Mutex;

/// An algebra with classes, named by its Python module (`cga`, `cga.pga`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Algebra(pub &'static str);

impl Algebra {
    /// cga-core's G(4,1), the package's own (`cga`).
    pub const CGA: Algebra = Algebra("cga");
}

/// A generated type as the bindings see it: its name, blades, where each sits in the storage
/// basis (of 32 coefficients; PGA's 16 are the first of them) and its algebra.
#[derive(Debug)]
pub struct Type {
    /// The class name (`Line`).
    pub name: &'static str,
    /// Its blades' names, in its coefficient order.
    pub blades: &'static [&'static str],
    /// Each blade's index in the storage basis.
    pub storage: &'static [usize],
    /// Its algebra.
    pub algebra: Algebra,
}

impl Type {
    /// Its name with its algebra's where that is not cga-core's: `Line`, `pga.Line`.
    pub fn describe(&self) -> String {
        match self.algebra.0.strip_prefix("cga.") {
            Some(module) => format!("{module}.{}", self.name),
            None => self.name.to_string(),
        }
    }
}

/// Rows of a batch above which a map runs on rayon's threads.
const PARALLEL_ROWS: usize = 1 << 14;

/// One value, or N of them.
#[derive(Clone, Debug)]
pub struct Values {
    /// Their type.
    pub ty: &'static Type,
    /// `n × k` coefficients, row by row.
    pub data: Vec<f64>,
    /// How many values.
    pub n: usize,
    /// Whether this is one value (shape `(k,)`) rather than an array of `n` (shape `(n, k)`).
    pub single: bool,
}

impl Values {
    /// Coefficients per value.
    pub fn k(&self) -> usize {
        self.ty.blades.len()
    }

    /// `data` (`n × k`) of type `ty`, refused where a coefficient is not finite.
    pub fn new(ty: &'static Type, data: Vec<f64>, n: usize, single: bool) -> PyResult<Values> {
        let k = ty.blades.len();
        if data.len() != n * k {
            return Err(ShapeError::new_err(format!("{}: {} coefficients for {n} values of {k}", ty.name, data.len())));
        }
        if let Some(i) = data.iter().position(|x| !x.is_finite()) {
            let (row, col) = (i / k.max(1), i % k.max(1));
            return Err(ValueError::new_err(format!(
                "{}: coefficient {} of value {row} is {} (every coefficient must be finite)",
                ty.name, ty.blades[col], data[i]
            )));
        }
        Ok(Values { ty, data, n, single })
    }

    /// Value `i`'s coefficients.
    pub fn row(&self, i: usize) -> &[f64] {
        let k = self.k();
        &self.data[i * k..(i + 1) * k]
    }

    /// Value `i` in the storage basis.
    pub fn storage(&self, i: usize) -> [f64; 32] {
        let mut s = [0.0; 32];
        for (&at, &x) in self.ty.storage.iter().zip(self.row(i)) {
            s[at] = x;
        }
        s
    }

    /// `f` on each value, in the storage basis (on threads for large batches, the GIL released).
    pub fn map(&self, py: Python<'_>, out: &'static Type, f: impl Fn([f64; 32]) -> [f64; 32] + Sync + Send) -> Values {
        let data = py.detach(|| fill(out, self.n, |i| f(self.storage(i))));
        Values { ty: out, data, n: self.n, single: self.single }
    }

    /// `f` on `(a_i, b_i)`, broadcasting one value against many; the result is one value only
    /// where both are.
    pub fn zip(
        a: &Values,
        b: &Values,
        py: Python<'_>,
        out: &'static Type,
        f: impl Fn(&[f64; 32], &[f64; 32]) -> [f64; 32] + Sync + Send,
    ) -> PyResult<Values> {
        let n = broadcast(a, b)?;
        // A value broadcast against many is put in the storage basis once.
        let (one_a, one_b) = ((a.n == 1).then(|| a.storage(0)), (b.n == 1).then(|| b.storage(0)));
        let at = |v: &Values, one: &Option<[f64; 32]>, i: usize| one.unwrap_or_else(|| v.storage(i));
        let data = py.detach(|| fill(out, n, |i| f(&at(a, &one_a, i), &at(b, &one_b, i))));
        Ok(Values { ty: out, data, n, single: a.single && b.single })
    }
}

/// Row `i` of `v`, broadcasting a single value.
pub(crate) fn at(v: &Values, i: usize) -> usize {
    row(v.n, i)
}

/// Row `i` of `n` rows, broadcasting one.
pub(crate) fn row(n: usize, i: usize) -> usize {
    if n == 1 { 0 } else { i }
}

/// The number of results of a map over `a` and `b`: their common length, or the other's where
/// one is a single value (or an array of one).
pub fn broadcast(a: &Values, b: &Values) -> PyResult<usize> {
    match (a.n, b.n) {
        (x, y) if x == y => Ok(x),
        (1, y) => Ok(y),
        (x, 1) => Ok(x),
        (x, y) => Err(ShapeError::new_err(format!(
            "{} values and {} values: arrays of different lengths (broadcast only one against many)",
            x, y
        ))),
    }
}

/// Bytes from which an array is asked for huge pages, as numpy asks for its own, and is
/// kept for reuse when freed.
const LARGE: usize = 4 << 20;

/// Freed large arrays, kept for the next results: fresh memory costs a page fault and the
/// kernel's zeroing of each page, which for a batch of products takes longer than the
/// products. At most [`KEPT`] of them, [`KEPT_BYTES`] in all.
static FREED: Mutex<Vec<Vec<f64>>> = Mutex::new(Vec::new());
const KEPT: usize = 4;
const KEPT_BYTES: usize = 256 << 20;

/// An array of `len` coefficients for results that overwrite every one: a freed array of
/// about that size where one is kept (its old values until then), else a new one; a large
/// new one is asked for transparent huge pages (Linux's `madvise`), so that its first
/// writes fault in 2 MiB at a time rather than 4 KiB.
pub fn scratch(len: usize) -> Vec<f64> {
    if len * size_of::<f64>() >= LARGE {
        let mut freed = FREED.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = freed.iter().position(|v| v.capacity() >= len && v.capacity() <= 2 * len) {
            let mut v = freed.swap_remove(i);
            v.resize(len, 0.0);
            v.truncate(len);
            return v;
        }
    }
    // Zeroed by the allocator: fresh pages from the system are zero already, untouched
    // until the results are written, so the advice below still applies to them.
    let v = vec![0.0; len];
    #[cfg(target_os = "linux")]
    if len * size_of::<f64>() >= LARGE {
        let start = v.as_ptr() as usize;
        let (first, end) = (start.next_multiple_of(4096), start + len * size_of::<f64>());
        // SAFETY: the range lies within the vector's own allocation (page-aligned inward),
        // and MADV_HUGEPAGE only advises the kernel: it changes no contents or mapping.
        unsafe { libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE) };
    }
    v
}

impl Drop for Values {
    /// A large array is kept for the next results ([`scratch`]), the oldest let go.
    fn drop(&mut self) {
        let bytes = |v: &Vec<f64>| v.capacity() * size_of::<f64>();
        if (LARGE..=KEPT_BYTES).contains(&bytes(&self.data)) {
            let mut freed = FREED.lock().unwrap_or_else(|e| e.into_inner());
            while freed.len() >= KEPT || freed.iter().map(bytes).sum::<usize>() + bytes(&self.data) > KEPT_BYTES {
                freed.remove(0);
            }
            freed.push(std::mem::take(&mut self.data));
        }
    }
}

/// The coefficients of `out` in `f(0) … f(n − 1)` (storage-basis values), row by row, each
/// written in place (no storage-basis array is kept); on rayon's threads when `n` is large.
fn fill(out: &'static Type, n: usize, f: impl Fn(usize) -> [f64; 32] + Sync + Send) -> Vec<f64> {
    let k = out.blades.len();
    let mut data = scratch(n * k);
    let write = |(i, row): (usize, &mut [f64])| {
        let s = f(i);
        for (x, &at) in row.iter_mut().zip(out.storage) {
            *x = s[at];
        }
    };
    if n >= PARALLEL_ROWS {
        let rows = PARALLEL_ROWS / 4;
        crate::threads::share(
            &mut data,
            rows * k.max(1),
            || (),
            |(), c, block| {
                block.chunks_mut(k.max(1)).enumerate().for_each(|(i, row)| write((c * rows + i, row)));
            },
        );
    } else {
        data.chunks_mut(k).enumerate().for_each(write);
    }
    data
}

/// Whether no coefficient is infinite or NaN (its exponent bits all set), in a loop the
/// compiler vectorises (no early exit).
pub fn all_finite(x: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    x.chunks(256).all(|c| c.iter().fold(0u64, |acc, v| acc | u64::from(v.to_bits() & EXPONENT == EXPONENT)) == 0)
}

/// The common length of arguments of `lens` rows (1 broadcasts).
pub(crate) fn length(lens: &[usize]) -> PyResult<usize> {
    let n = lens.iter().copied().max().unwrap_or(1);
    match lens.iter().find(|&&l| l != 1 && l != n) {
        Some(l) => Err(ShapeError::new_err(format!("arrays of {l} and {n} rows: broadcast only one against many"))),
        None => Ok(n),
    }
}
