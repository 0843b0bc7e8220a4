//! A Python class for each of cga-core's types, one value or an array of N: the algebra's
//! operators (`*` geometric, `^` outer, `|` inner, `&` regressive, `~` reverse), scalars on
//! either side, `+ −` within a type, the unary maps, and array access. Every product runs
//! cga-core's generated code (its registry, `product_table`), on each row of an array in Rust
//! with the GIL released; the result's class is the Rust result's type.

use crate::errors::{GeometryError, ShapeError};
use crate::values::all_finite;
use crate::values::{Algebra, Type, Values};
use cga_core::{ProductKind, UnaryKind, product_table, unary_table};
use numpy::{AllowTypeChange, PyArrayDyn, PyArrayLikeDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::IntoPyObjectExt;
use pyo3::exceptions::{PyIndexError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyInt, PySlice};
use std::collections::HashMap;
use std::sync::{Arc, RwLock};

/// A generated map's code on storage-basis arrays of 32 coefficients: cga-core's own, or
/// another algebra's on its own storage (of at most 32 coefficients, held in the first of the
/// 32 as the classes hold every algebra's values).
pub enum Code<F, D: ?Sized> {
    /// cga-core's.
    Cga(F),
    /// Another algebra's, between the storage arrays.
    Other(Arc<D>),
}

/// A product's code on storage arrays of `N` coefficients.
pub type Binary<const N: usize> = fn(&[f64; N], &[f64; N]) -> [f64; N];

/// A unary map's code on storage arrays of `N` coefficients.
pub type Single<const N: usize> = fn(&[f64; N]) -> [f64; N];

/// Another algebra's product, on storage arrays of 32.
pub type OtherBinary = dyn Fn(&[f64; 32], &[f64; 32]) -> [f64; 32] + Send + Sync;

/// Another algebra's unary map, on storage arrays of 32.
pub type OtherSingle = dyn Fn(&[f64; 32]) -> [f64; 32] + Send + Sync;

/// A generated product of two types: its result type and code.
pub struct Product {
    pub output: &'static str,
    pub code: Code<Binary<32>, OtherBinary>,
}

/// A generated unary map of one type: its result type and code.
pub struct Unary {
    pub output: &'static str,
    pub code: Code<Single<32>, OtherSingle>,
}

/// The first `N` of 32 storage coefficients, and back.
pub fn narrow<const N: usize>(x: &[f64; 32]) -> [f64; N] {
    std::array::from_fn(|k| x[k])
}

pub fn widen<const N: usize>(x: [f64; N]) -> [f64; 32] {
    std::array::from_fn(|k| if k < N { x[k] } else { 0.0 })
}

/// A product of an algebra with `N` storage coefficients, on storage arrays of 32.
pub fn widened<const N: usize>(f: Binary<N>) -> Arc<OtherBinary> {
    const { assert!(N <= 32, "the classes hold at most 32 coefficients") };
    Arc::new(move |a, b| widen(f(&narrow(a), &narrow(b))))
}

/// A unary map of an algebra with `N` storage coefficients, on storage arrays of 32.
pub fn widened_single<const N: usize>(f: Single<N>) -> Arc<OtherSingle> {
    const { assert!(N <= 32, "the classes hold at most 32 coefficients") };
    Arc::new(move |a| widen(f(&narrow(a))))
}

impl Product {
    /// The product of two storage-basis values.
    pub fn eval(&self, a: &[f64; 32], b: &[f64; 32]) -> [f64; 32] {
        match &self.code {
            Code::Cga(f) => f(a, b),
            Code::Other(f) => f(a, b),
        }
    }
}

impl Unary {
    /// The map of a storage-basis value.
    pub fn eval(&self, a: &[f64; 32]) -> [f64; 32] {
        match &self.code {
            Code::Cga(f) => f(a),
            Code::Other(f) => f(a),
        }
    }
}

/// A product's key: algebra, kind and operand types.
pub type ProductKey = (Algebra, ProductKind, &'static str, &'static str);

/// A unary map's key: algebra, kind and operand type.
pub type UnaryKey = (Algebra, UnaryKind, &'static str);

/// An algebra's products and unary maps, keyed.
pub type Tables = (Vec<(ProductKey, Product)>, Vec<(UnaryKey, Unary)>);

/// An algebra's dense type, and its products' code by kind (`None` where it defines none).
pub type Dense = (fn() -> &'static Type, fn(ProductKind) -> Option<Binary<32>>);

/// An algebra's classes as the operators reach them: one entry of [`ALGEBRAS`] each.
pub struct Classes {
    /// The algebra (its Python module).
    pub algebra: Algebra,
    /// Its type of a name, where that is a class.
    pub type_in: fn(&str) -> Option<&'static Type>,
    /// Its values as an object of their type's class.
    pub wrap_in: fn(Python<'_>, Values) -> PyResult<Py<PyAny>>,
    /// The values an object holds, where it is one of its classes.
    pub values_in: for<'a, 'py> fn(&'a Bound<'py, PyAny>) -> Option<&'a Values>,
    /// Adds its classes to a module.
    pub register_in: fn(&Bound<'_, PyModule>) -> PyResult<()>,
    /// Its generated products and unary maps.
    pub tables: fn() -> Tables,
    /// Its dense type and the products on it, where mixed results take that class.
    pub dense: Option<Dense>,
}

/// Every algebra with classes: cga-core's (the package's own), then each in its submodule.
/// An algebra declared with `algebra!` joins with one `python_algebra!` line and one entry here
/// (or, from another crate, through [`add_algebra`]).
static ALGEBRAS: [Classes; 5] = [
    Classes {
        algebra: Algebra::CGA,
        type_in,
        wrap_in,
        values_in,
        register_in,
        tables: || {
            let products = product_table::<f64>()
                .into_iter()
                .map(|e| ((Algebra::CGA, e.kind, e.lhs, e.rhs), Product { output: e.output, code: Code::Cga(e.eval) }));
            let unaries = unary_table::<f64>()
                .into_iter()
                .map(|e| ((Algebra::CGA, e.kind, e.input), Unary { output: e.output, code: Code::Cga(e.eval) }));
            (products.collect(), unaries.collect())
        },
        dense: None,
    },
    pga::CLASSES,
    sta::CLASSES,
    cga2::CLASSES,
    vga::CLASSES,
];

/// Algebras added by another extension module built on this crate ([`add_algebra`]).
static ADDED: RwLock<Vec<&'static Classes>> = RwLock::new(Vec::new());

/// The first answer of `f` on the algebras with classes: the package's, then those added.
fn find_algebra<R>(mut f: impl FnMut(&'static Classes) -> Option<R>) -> Option<R> {
    ALGEBRAS
        .iter()
        .find_map(&mut f)
        .or_else(|| ADDED.read().unwrap_or_else(|e| e.into_inner()).iter().copied().find_map(f))
}

/// Adds an algebra's classes (`python_algebra!`'s `CLASSES`) to the module `m`: the
/// `#[pymodule]` of an extension that binds a user's own algebra calls this. An algebra
/// added twice, or named as one of the package's, is refused.
pub fn add_algebra(m: &Bound<'_, PyModule>, classes: &'static Classes) -> PyResult<()> {
    let mut added = ADDED.write().unwrap_or_else(|e| e.into_inner());
    if ALGEBRAS.iter().chain(added.iter().copied()).any(|c| c.algebra == classes.algebra) {
        return Err(crate::errors::ValueError::new_err(format!(
            "the algebra {} has classes already",
            classes.algebra.0
        )));
    }
    (classes.register_in)(m)?;
    added.push(classes);
    Ok(())
}

/// The classes of `algebra`.
fn classes_of(algebra: Algebra) -> &'static Classes {
    find_algebra(|c| (c.algebra == algebra).then_some(c)).expect("every value's algebra has classes")
}

/// An algebra's generated products and unary maps, by key.
struct Lookup {
    products: HashMap<ProductKey, Product>,
    unaries: HashMap<UnaryKey, Unary>,
}

/// The tables of `algebra`, built on first use.
fn lookup(algebra: Algebra) -> &'static Lookup {
    static BUILT: RwLock<Vec<(Algebra, &'static Lookup)>> = RwLock::new(Vec::new());
    let found = |built: &[(Algebra, &'static Lookup)]| built.iter().find(|b| b.0 == algebra).map(|b| b.1);
    if let Some(l) = found(&BUILT.read().unwrap_or_else(|e| e.into_inner())) {
        return l;
    }
    let mut built = BUILT.write().unwrap_or_else(|e| e.into_inner());
    if let Some(l) = found(&built) {
        return l;
    }
    let (products, unaries) = (classes_of(algebra).tables)();
    // One per algebra, kept for the process's life, as a static table would be.
    let l: &'static Lookup = Box::leak(Box::new(Lookup {
        products: products.into_iter().collect(),
        unaries: unaries.into_iter().collect(),
    }));
    built.push((algebra, l));
    l
}

/// The generated product `key`, where there is one.
fn product_of(key: &ProductKey) -> Option<&'static Product> {
    lookup(key.0).products.get(key)
}

/// The generated unary map `key`, where there is one.
fn unary_of(key: &UnaryKey) -> Option<&'static Unary> {
    lookup(key.0).unaries.get(key)
}

/// The symbol of a product in messages.
fn symbol(kind: ProductKind) -> &'static str {
    match kind {
        ProductKind::Geometric => "*",
        ProductKind::Outer => "^",
        ProductKind::Inner => "|",
        ProductKind::Regressive => "&",
        ProductKind::LeftContraction => "lc",
        ProductKind::RightContraction => "rc",
        ProductKind::Commutator => "commutator",
        ProductKind::ScalarProduct => "scalar_product",
        ProductKind::Sandwich => "sandwich",
    }
}

/// The product `kind` of `a` and `b`, row by row; `None` where the algebra has none between
/// their types (identically zero, so not generated). Values of two algebras are refused.
pub fn product(py: Python<'_>, kind: ProductKind, a: &Values, b: &Values) -> PyResult<Option<Values>> {
    let algebra = a.ty.algebra;
    if b.ty.algebra != algebra {
        return Err(PyTypeError::new_err(format!(
            "{} {} {}: values of two algebras",
            a.ty.describe(),
            symbol(kind),
            b.ty.describe()
        )));
    }
    if let Some((dense, code)) = classes_of(algebra).dense
        && (a.ty.name == "Multivector" || b.ty.name == "Multivector")
    {
        let dense = dense();
        let code = code(kind).ok_or_else(|| {
            PyTypeError::new_err(format!("{}: no {} is defined on the dense type", dense.describe(), symbol(kind)))
        })?;
        let v = Values::zip(a, b, py, dense, code)?;
        return scanned(|| format!("{} {} {}", a.ty.describe(), symbol(kind), b.ty.describe()), v).map(Some);
    }
    let Some(entry) = product_of(&(algebra, kind, a.ty.name, b.ty.name)) else { return Ok(None) };
    let out = type_named(algebra, entry.output).ok_or_else(|| {
        PyTypeError::new_err(format!("{} {} {}: no class for {}", a.ty.name, symbol(kind), b.ty.name, entry.output))
    })?;
    let n = crate::values::broadcast(a, b)?;
    let what = || format!("{} {} {}", a.ty.describe(), symbol(kind), b.ty.describe());
    if let Some((data, finite)) = py.detach(|| crate::kernels::lanes(kind, a, b, n, out)) {
        return finite_result(what, Values { ty: out, data, n, single: a.single && b.single }, finite).map(Some);
    }
    scanned(what, Values::zip(a, b, py, out, |x, y| entry.eval(x, y))?).map(Some)
}

/// `v`, the result of `what`, scanned: refused where a coefficient is not finite.
fn scanned(what: impl FnOnce() -> String, v: Values) -> PyResult<Values> {
    let finite = all_finite(&v.data);
    finite_result(what, v, finite)
}

/// `v`, the result of `what`, refused where `finite` says a coefficient is not: the operands
/// are finite (the classes take no others), so the answer overflowed f64 at their scale.
fn finite_result(what: impl FnOnce() -> String, v: Values, finite: bool) -> PyResult<Values> {
    if finite {
        return Ok(v);
    }
    let row = v.data.iter().position(|x| !x.is_finite()).map_or(0, |i| i / v.k().max(1));
    Err(crate::errors::ValueError::new_err(format!(
        "{}: value {row} of the result is not finite (it overflows f64 at the operands' scale)",
        what()
    )))
}

/// `values[0] ^ values[1] ^ …`, left to right: the chain of `^`, row for row the same
/// numbers. Where every step has a kernel it runs a block of rows at a time, its
/// intermediates in the core's cache (for arrays about half the memory traffic of the steps
/// one by one), and two steps over arrays as one kernel; otherwise it is the operators one
/// by one.
#[pyfunction]
#[pyo3(signature = (*values))]
pub fn wedge(py: Python<'_>, values: Vec<Bound<'_, PyAny>>) -> PyResult<Py<PyAny>> {
    let Some((first, rest)) = values.split_first() else {
        return Err(crate::errors::ValueError::new_err("wedge: give at least one value"));
    };
    let all: Vec<&Values> = values
        .iter()
        .map(|v| any_values_of(v).ok_or_else(|| PyTypeError::new_err("wedge: expected values of cga's classes")))
        .collect::<PyResult<_>>()?;
    let n = crate::values::length(&all.iter().map(|v| v.n).collect::<Vec<_>>())?;
    let mut types = vec![all[0].ty];
    for v in &all[1..] {
        let last = types[types.len() - 1].name;
        let key = (Algebra::CGA, ProductKind::Outer, last, v.ty.name);
        match product_of(&key)
            .filter(|_| all[0].ty.algebra == Algebra::CGA)
            .and_then(|e| type_named(Algebra::CGA, e.output))
        {
            Some(t) => types.push(t),
            None => break,
        }
    }
    if types.len() == all.len()
        && let Some((data, finite)) = py.detach(|| crate::kernels::chain(ProductKind::Outer, &all, &types, n))
    {
        let single = all.iter().all(|v| v.single);
        let v = Values { ty: types[types.len() - 1], data, n, single };
        return wrap(py, finite_result(|| "wedge".to_string(), v, finite)?);
    }
    let mut acc = first.clone();
    for v in rest {
        acc = acc.bitxor(v)?;
    }
    Ok(acc.unbind())
}

/// The products computed on lanes, as `(algebra's module, kind, left class, right class)`
/// (for the tests that compare them with [`registry_product`]).
#[pyfunction(name = "_kernels")]
pub fn kernels() -> Vec<(&'static str, String, &'static str, &'static str)> {
    crate::kernels::KERNELS.iter().map(|(algebra, kind, a, b)| (algebra.0, format!("{kind:?}"), *a, *b)).collect()
}

/// The product `kind` (a [`ProductKind`] name) of `a` and `b` through the registry's
/// storage-basis path alone, never the lanes: the reference the kernels are tested against.
#[pyfunction(name = "_registry_product")]
pub fn registry_product(py: Python<'_>, kind: &str, a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let kind = crate::kernels::KERNELS
        .iter()
        .map(|k| k.1)
        .find(|k| format!("{k:?}") == kind)
        .ok_or_else(|| PyTypeError::new_err(format!("no kernel of kind {kind}")))?;
    let (Some(a), Some(b)) = (any_values_of(a), any_values_of(b)) else {
        return Err(PyTypeError::new_err("_registry_product takes two values of cga's classes"));
    };
    let key = (a.ty.algebra, kind, a.ty.name, b.ty.name);
    let entry = product_of(&key).ok_or_else(|| PyTypeError::new_err("not generated"))?;
    let out = type_named(a.ty.algebra, entry.output).ok_or_else(|| PyTypeError::new_err("no class"))?;
    wrap(py, Values::zip(a, b, py, out, |x, y| entry.eval(x, y))?)
}

/// The unary map `kind` of `a`.
pub fn unary(py: Python<'_>, kind: UnaryKind, a: &Values) -> PyResult<Values> {
    let entry = unary_of(&(a.ty.algebra, kind, a.ty.name))
        .ok_or_else(|| PyTypeError::new_err(format!("{}: no {kind:?} is generated", a.ty.name)))?;
    let out = type_named(a.ty.algebra, entry.output)
        .ok_or_else(|| PyTypeError::new_err(format!("no class for {}", entry.output)))?;
    scanned(|| format!("{kind:?} of {}", a.ty.describe()), a.map(py, out, |x| entry.eval(&x)))
}

/// `⟨A Ã⟩₀` of each value.
pub fn norm_squared(py: Python<'_>, a: &Values) -> PyResult<Vec<f64>> {
    let entry = unary_of(&(a.ty.algebra, UnaryKind::NormSquared, a.ty.name))
        .ok_or_else(|| PyTypeError::new_err(format!("{}: no norm is generated", a.ty.name)))?;
    Ok(py.detach(|| (0..a.n).map(|i| entry.eval(&a.storage(i))[0]).collect()))
}

/// Each value times `s` (a float, or an array of one float a value).
pub fn scaled(a: &Values, s: &[f64]) -> PyResult<Values> {
    if s.len() != 1 && s.len() != a.n {
        return Err(ShapeError::new_err(format!("{} scalars for {} values", s.len(), a.n)));
    }
    let k = a.k();
    let data = a.data.iter().enumerate().map(|(i, x)| x * s[if s.len() == 1 { 0 } else { i / k }]).collect();
    Values::new(a.ty, data, a.n, a.single && s.len() == 1)
}

/// `other` as scalars: a Python number or a 1-D float array; `None` otherwise.
pub fn scalars(other: &Bound<'_, PyAny>) -> Option<Vec<f64>> {
    if other.is_instance_of::<PyFloat>() || other.is_instance_of::<PyInt>() {
        return other.extract::<f64>().ok().map(|s| vec![s]);
    }
    let array = other.extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>().ok()?;
    (array.ndim() == 1).then(|| array.as_array().iter().copied().collect())
}

/// Coefficients from an array-like of shape `(k,)` (one value) or `(n, k)`.
pub fn read(ty: &'static Type, coefficients: &Bound<'_, PyAny>) -> PyResult<Values> {
    let array = coefficients.extract::<PyArrayLikeDyn<'_, f64, AllowTypeChange>>().map_err(|_| {
        ShapeError::new_err(format!(
            "{}: coefficients must be numbers, an array of shape ({k},) or (n, {k})",
            ty.name,
            k = ty.blades.len()
        ))
    })?;
    let k = ty.blades.len();
    let shape = array.shape().to_vec();
    let (n, single) = match shape.as_slice() {
        [x] if *x == k => (1, true),
        [n, x] if *x == k => (*n, false),
        _ => {
            return Err(ShapeError::new_err(format!(
                "{}: coefficients of shape {shape:?}; a {0} has {k} ({}), so give shape ({k},) or (n, {k})",
                ty.name,
                ty.blades.join(", ")
            )));
        }
    };
    Values::new(ty, array.as_array().iter().copied().collect(), n, single)
}

/// `values` as a numpy array: `(k,)` for one value, `(n, k)` for an array.
pub fn array<'py>(py: Python<'py>, values: &Values) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let shape = if values.single { vec![values.k()] } else { vec![values.n, values.k()] };
    let flat = numpy::PyArray1::from_slice(py, &values.data);
    flat.reshape(shape)
}

/// Row `index` (negative from the end) or a slice of an array.
pub fn item(values: &Values, index: &Bound<'_, PyAny>) -> PyResult<Values> {
    if values.single {
        return Err(PyTypeError::new_err(format!("a single {} is not an array: it has no items", values.ty.name)));
    }
    if let Ok(slice) = index.cast::<PySlice>() {
        let s = slice.indices(values.n as isize)?;
        let rows: Vec<usize> = (0..s.slicelength).map(|j| (s.start + j as isize * s.step) as usize).collect();
        let data = rows.iter().flat_map(|&i| values.row(i).iter().copied()).collect();
        return Ok(Values { ty: values.ty, data, n: rows.len(), single: false });
    }
    let i: isize = index.extract()?;
    let at = if i < 0 { i + values.n as isize } else { i };
    if at < 0 || at >= values.n as isize {
        return Err(PyIndexError::new_err(format!("index {i} out of range for {} {}s", values.n, values.ty.name)));
    }
    Ok(Values { ty: values.ty, data: values.row(at as usize).to_vec(), n: 1, single: true })
}

/// The value `v` divided by `√|⟨v ṽ⟩₀|`, refused (by name) where that is zero or not finite.
pub fn normalised(py: Python<'_>, v: &Values) -> PyResult<Values> {
    let ns = norm_squared(py, v)?;
    let mut data = v.data.clone();
    let k = v.k();
    for (i, s) in ns.iter().enumerate() {
        let norm = s.abs().sqrt();
        if !(norm > 0.0 && norm.is_finite()) {
            return Err(GeometryError::new_err(format!(
                "{} {i}: cannot normalise: ⟨A Ã⟩₀ = {s:e} (a zero or null value has no unit)",
                v.ty.name
            )));
        }
        for x in &mut data[i * k..(i + 1) * k] {
            *x /= norm;
        }
    }
    Values::new(v.ty, data, v.n, v.single)
}

/// An algebra's types that are classes, and the code each needs: the invoking module names
/// the algebra's crate module `algebra` (`use cga_core as algebra;`); `$algebra` names it,
/// `$module` is the Python module of its classes, `$repr` how a value reads (`display`: the
/// type's Euclidean `Display`; `coefficients`: its blades).
#[doc(hidden)]
#[macro_export]
macro_rules! __classes {
    (@typed display, $name:ident) => {
        impl $name {
            /// The typed value of row `i` (for what the algebra's crate computes on it).
            pub fn typed(v: &Values, i: usize) -> algebra::$name<f64> {
                algebra::$name::from_storage(&v.storage(i))
            }
        }
    };
    (@typed coefficients, $name:ident) => {};
    (@repr display, $v:expr, $i:expr, $name:ident) => {
        format!("{}", $name::typed($v, $i))
    };
    (@repr coefficients, $v:expr, $i:expr, $name:ident) => {
        $crate::__private::coefficients($v, $i)
    };
    (@basis $name:ident) => {
        (&algebra::$name::<f64>::BLADES[..], &algebra::$name::<f64>::STORAGE_INDEX[..])
    };
    (@basis $name:ident dense) => {
        (&storage_basis().0[..], &storage_basis().1[..])
    };
    ($algebra:expr, $module:literal, $repr:ident; $($name:ident $($dense:ident)?),* $(,)?) => {
        $(
            #[doc = concat!(
                "`", stringify!($name), "` of ", $module, ": one value (coefficients of shape (k,)) or an ",
                "array of n (shape (n, k)), with the algebra's operators."
            )]
            #[pyclass(module = $module, frozen)]
            pub struct $name(pub Values);

            impl $name {
                /// The type.
                pub fn ty() -> &'static Type {
                    static TYPE: std::sync::LazyLock<Type> = std::sync::LazyLock::new(|| {
                        let (blades, storage) = $crate::__classes!(@basis $name $($dense)?);
                        Type { name: stringify!($name), blades, storage, algebra: $algebra }
                    });
                    &TYPE
                }
            }

            $crate::__classes!(@typed $repr, $name);

            #[pymethods]
            impl $name {
                /// A value from its coefficients (shape (k,)), or an array of n (shape (n, k)),
                /// in the order of `blades`.
                #[new]
                fn new(coefficients: &Bound<'_, PyAny>) -> PyResult<Self> {
                    Ok($name($crate::__private::read(Self::ty(), coefficients)?))
                }

                /// The same as the constructor: coefficients of shape (k,) or (n, k).
                #[staticmethod]
                fn from_array(coefficients: &Bound<'_, PyAny>) -> PyResult<Self> {
                    Ok($name($crate::__private::read(Self::ty(), coefficients)?))
                }

                /// The blades' names, in coefficient order.
                #[classattr]
                fn blades() -> Vec<&'static str> {
                    Self::ty().blades.to_vec()
                }

                /// The coefficients: shape (k,) for one value, (n, k) for an array.
                #[getter(array)]
                fn get_array<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
                    $crate::__private::array(py, &self.0)
                }

                /// Whether this holds one value (not an array).
                #[getter]
                fn single(&self) -> bool {
                    self.0.single
                }

                fn __len__(&self) -> PyResult<usize> {
                    if self.0.single {
                        return Err(PyTypeError::new_err(format!("a single {} has no len(): it is not an array", stringify!($name))));
                    }
                    Ok(self.0.n)
                }

                fn __getitem__(&self, index: &Bound<'_, PyAny>) -> PyResult<Self> {
                    Ok($name($crate::__private::item(&self.0, index)?))
                }

                fn __repr__(&self) -> String {
                    let show = |i: usize| $crate::__classes!(@repr $repr, &self.0, i, $name);
                    if self.0.single {
                        show(0)
                    } else {
                        let first: Vec<String> = (0..self.0.n.min(3)).map(show).collect();
                        let more = if self.0.n > 3 { ", …" } else { "" };
                        format!("{} array of {}: [{}{more}]", stringify!($name), self.0.n, first.join(", "))
                    }
                }

                /// Exactly the same type, shape and coefficients.
                fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
                    match $crate::__private::any_values_of(other) {
                        Some(o) => std::ptr::eq(o.ty, self.0.ty) && o.single == self.0.single && o.data == self.0.data,
                        None => false,
                    }
                }

                fn __mul__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::binary(py, ProductKind::Geometric, &self.0, other, false)
                }

                fn __rmul__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::binary(py, ProductKind::Geometric, &self.0, other, true)
                }

                fn __truediv__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    match $crate::__private::scalars(other) {
                        Some(s) => $crate::__private::wrap(py, $crate::__private::scaled(&self.0, &s.iter().map(|x| 1.0 / x).collect::<Vec<_>>())?),
                        None => $crate::__private::not_implemented(py),
                    }
                }

                fn __xor__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::binary(py, ProductKind::Outer, &self.0, other, false)
                }

                fn __or__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::binary(py, ProductKind::Inner, &self.0, other, false)
                }

                fn __and__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::binary(py, ProductKind::Regressive, &self.0, other, false)
                }

                fn __add__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::sum(py, &self.0, other, 1.0)
                }

                fn __sub__(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::sum(py, &self.0, other, -1.0)
                }

                fn __neg__(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::scaled(&self.0, &[-1.0])?)
                }

                /// `~x`: the reverse.
                fn __invert__(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Reverse, &self.0)?)
                }

                /// The reverse `Ã`.
                fn reverse(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Reverse, &self.0)?)
                }

                /// The grade involution `Â`.
                fn involute(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Involute, &self.0)?)
                }

                /// The Clifford conjugate `Ā`.
                fn conjugate(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Conjugate, &self.0)?)
                }

                /// The dual `A I₅⁻¹`.
                fn dual(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Dual, &self.0)?)
                }

                /// The undual `A I₅`.
                fn undual(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Undual, &self.0)?)
                }

                /// The part of grade `k`, `⟨A⟩ₖ`.
                fn grade(&self, py: Python<'_>, k: usize) -> PyResult<Py<PyAny>> {
                    $crate::__private::wrap(py, $crate::__private::unary(py, UnaryKind::Grade(k), &self.0)?)
                }

                /// `⟨A Ã⟩₀`: a float for one value, an array of n for an array.
                fn norm_squared(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    $crate::__private::floats(py, &self.0, $crate::__private::norm_squared(py, &self.0)?)
                }

                /// `√|⟨A Ã⟩₀|`.
                fn norm(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                    let n = $crate::__private::norm_squared(py, &self.0)?.into_iter().map(|s| s.abs().sqrt()).collect();
                    $crate::__private::floats(py, &self.0, n)
                }

                /// The value over `√|⟨A Ã⟩₀|` (clifford's `.normal()`); a zero or null value is
                /// refused (`GeometryError`).
                fn normalise(&self, py: Python<'_>) -> PyResult<Self> {
                    Ok($name($crate::__private::normalised(py, &self.0)?))
                }

                /// The geometric product (`*`).
                fn gp(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::Geometric, &self.0, other)
                }

                /// The outer product (`^`).
                fn wedge(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::Outer, &self.0, other)
                }

                /// The Hestenes inner product (`|`).
                fn inner(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::Inner, &self.0, other)
                }

                /// The left contraction `A ⌋ B`.
                fn lc(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::LeftContraction, &self.0, other)
                }

                /// The right contraction `A ⌊ B`.
                fn rc(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::RightContraction, &self.0, other)
                }

                /// The regressive product, the meet (`&`).
                fn vee(&self, py: Python<'_>, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::Regressive, &self.0, other)
                }

                /// The value drawn (a notebook shows it): PNG bytes, or `None` where it has no
                /// picture (a versor, a zero blade).
                fn _repr_png_<'py>(&self, py: Python<'py>) -> Option<Bound<'py, pyo3::types::PyBytes>> {
                    $crate::__private::png(py, &self.0).map(|b| pyo3::types::PyBytes::new(py, &b))
                }

                /// `V X Ṽ` for this versor and `x`.
                fn sandwich(&self, py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                    $crate::__private::named(py, ProductKind::Sandwich, &self.0, x)
                }
            }
        )*

        /// The type named `name` of this algebra, if it is a class.
        pub fn type_in(name: &str) -> Option<&'static Type> {
            match name {
                $(stringify!($name) => Some($name::ty()),)*
                _ => None,
            }
        }

        /// `values` (of this algebra) as an object of its type's class.
        pub fn wrap_in(py: Python<'_>, values: Values) -> PyResult<Py<PyAny>> {
            match values.ty.name {
                $(stringify!($name) => Bound::new(py, $name(values))?.into_py_any(py),)*
                other => Err(PyTypeError::new_err(format!("no class for {other}"))),
            }
        }

        /// The values `obj` holds, if it is one of this algebra's classes (borrowed: no copy
        /// per operation).
        pub fn values_in<'a>(obj: &'a Bound<'_, PyAny>) -> Option<&'a Values> {
            $(if let Ok(x) = obj.cast::<$name>() {
                return Some(&x.get().0);
            })*
            None
        }

        /// Adds every class to the module.
        pub fn register_in(m: &Bound<'_, PyModule>) -> PyResult<()> {
            $(m.add_class::<$name>()?;)*
            Ok(())
        }
    };
}

use cga_core as algebra;

crate::__classes!(
    Algebra::CGA, "cga", display;
    Scalar,
    Infinity,
    Vector,
    Bivector,
    FlatPoint,
    Line,
    Circle,
    Plane,
    Sphere,
    Pseudoscalar,
    ScalarQuadvector,
    Rotor,
    Translator,
    Motor,
    Dilator,
    Transversor,
    Generator,
    Even,
    Odd,
);

/// The type named `name` of `algebra`, if it is a class.
pub fn type_named(algebra: Algebra, name: &str) -> Option<&'static Type> {
    (classes_of(algebra).type_in)(name)
}

/// `values` as an object of its type's class.
pub fn wrap(py: Python<'_>, values: Values) -> PyResult<Py<PyAny>> {
    (classes_of(values.ty.algebra).wrap_in)(py, values)
}

/// The values `obj` holds if it is one of cga-core's classes (what the geometry, figures and
/// scenes take).
pub fn values_of<'a>(obj: &'a Bound<'_, PyAny>) -> Option<&'a Values> {
    values_in(obj)
}

/// The values `obj` holds if it is a class of any algebra (what the operators take).
pub fn any_values_of<'a>(obj: &'a Bound<'_, PyAny>) -> Option<&'a Values> {
    find_algebra(|c| (c.values_in)(obj))
}

/// Adds cga-core's classes to the module and every other algebra's to its submodule
/// (`cga.pga`'s to `pga`).
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    for c in &ALGEBRAS {
        match c.algebra.0.strip_prefix("cga.") {
            None => (c.register_in)(m)?,
            Some(name) => {
                let sub = PyModule::new(m.py(), name)?;
                (c.register_in)(&sub)?;
                m.add_submodule(&sub)?;
            }
        }
    }
    Ok(())
}

/// A value's coefficients by blade: `Motor(s=1, e12=0.5)`, the zero ones left out.
pub fn coefficients(v: &Values, i: usize) -> String {
    let terms: Vec<String> =
        v.ty.blades.iter().zip(v.row(i)).filter(|(_, x)| **x != 0.0).map(|(b, x)| format!("{b}={x}")).collect();
    format!("{}({})", v.ty.name, terms.join(", "))
}

/// An algebra declared with `algebra!` (of at most 32 storage coefficients) as a module of
/// classes: `$module` (the Rust module), `$python` its Python module, the algebra's crate
/// module `$path`, its classes, its dense type and the types whose blades cover the storage
/// basis. Its [`Classes`] are `$module::CLASSES`, for [`ALGEBRAS`].
#[macro_export]
macro_rules! python_algebra {
    ($(#[$doc:meta])* $module:ident, $python:literal, $path:path; $($class:ident),*; dense $dense:ident; covered by $($cover:ident),*) => {
        $(#[$doc])*
        pub mod $module {
            use $crate::__private::*;
            use $path as algebra;

            /// The algebra.
            pub const ALGEBRA: Algebra = Algebra($python);

            $crate::__classes!(ALGEBRA, $python, coefficients; $($class,)* $dense dense);

            /// Its classes, for the operators.
            pub const CLASSES: Classes = Classes {
                algebra: ALGEBRA,
                type_in,
                wrap_in,
                values_in,
                register_in,
                tables,
                dense: Some((Multivector::ty, dense_code)),
            };

            /// The storage basis's blades by index, as the algebra spells them (read from the
            /// sparse types that hold them all), and its indices in order.
            fn storage_basis() -> &'static (Vec<&'static str>, Vec<usize>) {
                static BASIS: std::sync::LazyLock<(Vec<&'static str>, Vec<usize>)> = std::sync::LazyLock::new(|| {
                    let mut names = vec![""; 32];
                    let mut width = 0;
                    $(for (b, &i) in algebra::$cover::<f64>::BLADES.iter().zip(&algebra::$cover::<f64>::STORAGE_INDEX) {
                        names[i] = b;
                        width = width.max(i + 1);
                    })*
                    names.truncate(width);
                    (names, (0..width).collect())
                });
                &BASIS
            }

            /// Its products and unary maps, keyed as the classes look them up.
            fn tables() -> Tables {
                let products = algebra::product_table::<f64>().into_iter().map(|e| {
                    ((ALGEBRA, product_kind(e.kind), e.lhs, e.rhs), Product { output: e.output, code: Code::Other(widened(e.eval)) })
                });
                let unaries = algebra::unary_table::<f64>().into_iter().map(|e| {
                    ((ALGEBRA, unary_kind(e.kind), e.input), Unary { output: e.output, code: Code::Other(widened_single(e.eval)) })
                });
                (products.collect(), unaries.collect())
            }

            /// A product with the dense type, for which no table is generated: both operands
            /// as dense values and the dense type's own product; `None` for the sandwich and
            /// the scalar product, which it does not define.
            fn dense_code(kind: ProductKind) -> Option<Binary<32>> {
                use algebra::{
                    CommutatorProduct, GeometricProduct, InnerProduct, LeftContraction, Multivector as Dense,
                    OuterProduct, RegressiveProduct, RightContraction,
                };
                fn of(x: &[f64; 32]) -> Dense<f64> {
                    Dense::from_storage(&narrow(x))
                }
                fn back(x: Dense<f64>) -> [f64; 32] {
                    widen(x.to_storage())
                }
                Some(match kind {
                    ProductKind::Geometric => |a, b| back(of(a).gp(of(b))),
                    ProductKind::Outer => |a, b| back(of(a).wedge(of(b))),
                    ProductKind::Inner => |a, b| back(of(a).inner(of(b))),
                    ProductKind::LeftContraction => |a, b| back(of(a).lc(of(b))),
                    ProductKind::RightContraction => |a, b| back(of(a).rc(of(b))),
                    ProductKind::Regressive => |a, b| back(of(a).vee(of(b))),
                    ProductKind::Commutator => |a, b| back(of(a).commutator(of(b))),
                    ProductKind::ScalarProduct | ProductKind::Sandwich => return None,
                })
            }

            /// Its product kind as the classes name it (cga-core's).
            fn product_kind(k: algebra::ProductKind) -> ProductKind {
                use algebra::ProductKind as P;
                match k {
                    P::Geometric => ProductKind::Geometric,
                    P::Outer => ProductKind::Outer,
                    P::Inner => ProductKind::Inner,
                    P::LeftContraction => ProductKind::LeftContraction,
                    P::RightContraction => ProductKind::RightContraction,
                    P::Regressive => ProductKind::Regressive,
                    P::Commutator => ProductKind::Commutator,
                    P::ScalarProduct => ProductKind::ScalarProduct,
                    P::Sandwich => ProductKind::Sandwich,
                }
            }

            /// Its unary kind as the classes name it (cga-core's).
            fn unary_kind(k: algebra::UnaryKind) -> UnaryKind {
                use algebra::UnaryKind as U;
                match k {
                    U::Reverse => UnaryKind::Reverse,
                    U::Involute => UnaryKind::Involute,
                    U::Conjugate => UnaryKind::Conjugate,
                    U::Dual => UnaryKind::Dual,
                    U::Undual => UnaryKind::Undual,
                    U::Grade(g) => UnaryKind::Grade(g),
                    U::NormSquared => UnaryKind::NormSquared,
                }
            }
        }
    };
}

crate::python_algebra!(
    /// 3D projective geometric algebra G(3,0,1) (cga-algebras' `pga`: bivector.net's and
    /// kingdon's conventions) as classes of `cga.pga`, with the same operators and arrays.
    pga, "cga.pga", cga_algebras::pga; Scalar, Plane, Line, Point, Pseudoscalar, Motor; dense Multivector;
    covered by Scalar, Plane, Line, Point, Pseudoscalar
);

crate::python_algebra!(
    /// Spacetime algebra G(1,3) (cga-algebras' `sta`: `e0² = +1`, `e1² = e2² = e3² = −1`) as
    /// classes of `cga.sta`, with the same operators and arrays.
    sta, "cga.sta", cga_algebras::sta; Scalar, Vector, Bivector, Trivector, Pseudoscalar, Rotor;
    dense Multivector; covered by Scalar, Vector, Bivector, Trivector, Pseudoscalar
);

crate::python_algebra!(
    /// 2D conformal geometric algebra G(3,1) (cga-algebras' `cga2`: points
    /// `x + ½x² ei + eo` of the plane, blades in the null basis `e1, e2, eo, ei`) as classes of
    /// `cga.cga2`, with the same operators and arrays.
    cga2, "cga.cga2", cga_algebras::cga2; Scalar, Vector, PointPair, Circle, Pseudoscalar, Rotor, Motor, Even;
    dense Multivector; covered by Scalar, Vector, PointPair, Circle, Pseudoscalar
);

crate::python_algebra!(
    /// The 3D vector algebra G(3) (cga-algebras' `vga`: `e1, e2, e3` orthonormal) as classes
    /// of `cga.vga`, with the same operators and arrays.
    vga, "cga.vga", cga_algebras::vga; Scalar, Vector, Bivector, Pseudoscalar, Rotor, Odd;
    dense Multivector; covered by Scalar, Vector, Bivector, Pseudoscalar
);

/// Python's `NotImplemented`, so that the other operand may answer.
pub fn not_implemented(py: Python<'_>) -> PyResult<Py<PyAny>> {
    Ok(py.NotImplemented())
}

/// `a op other` (or `other op a` when `reflected`): a product of two values, or a scaling by
/// numbers for the geometric product.
pub fn binary(
    py: Python<'_>,
    kind: ProductKind,
    a: &Values,
    other: &Bound<'_, PyAny>,
    reflected: bool,
) -> PyResult<Py<PyAny>> {
    if kind == ProductKind::Geometric
        && let Some(s) = scalars(other)
    {
        return wrap(py, scaled(a, &s)?);
    }
    let Some(b) = any_values_of(other) else { return not_implemented(py) };
    let (l, r) = if reflected { (b, a) } else { (a, b) };
    match product(py, kind, l, r)? {
        Some(v) => wrap(py, v),
        None => Err(PyTypeError::new_err(format!(
            "{} {} {}: identically zero in this algebra, so not generated",
            l.ty.name,
            symbol(kind),
            r.ty.name
        ))),
    }
}

/// A named product's method: as the operator, refusing what is not a value.
pub fn named(py: Python<'_>, kind: ProductKind, a: &Values, other: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    if any_values_of(other).is_none() && !(kind == ProductKind::Geometric && scalars(other).is_some()) {
        return Err(PyTypeError::new_err(format!(
            "{} {}: expected a cga value, got {}",
            a.ty.name,
            symbol(kind),
            other.get_type().name()?
        )));
    }
    binary(py, kind, a, other, false)
}

/// `a + sign · b` for two values of one type.
pub fn sum(py: Python<'_>, a: &Values, other: &Bound<'_, PyAny>, sign: f64) -> PyResult<Py<PyAny>> {
    let Some(b) = any_values_of(other) else { return not_implemented(py) };
    if b.ty.name != a.ty.name || b.ty.algebra != a.ty.algebra {
        return Err(PyTypeError::new_err(format!(
            "{} ± {}: add values of one type (convert one first, e.g. to Even or Odd)",
            a.ty.name, b.ty.name
        )));
    }
    let n = crate::values::broadcast(a, b)?;
    let k = a.k();
    let at = |v: &Values, i: usize, j: usize| if v.n == 1 { v.data[j] } else { v.data[i * k + j] };
    let data = (0..n * k).map(|x| at(a, x / k, x % k) + sign * at(b, x / k, x % k)).collect();
    wrap(py, Values::new(a.ty, data, n, a.single && b.single)?)
}

/// Per-value floats: a Python float for one value, a numpy array for an array.
pub fn floats(py: Python<'_>, v: &Values, x: Vec<f64>) -> PyResult<Py<PyAny>> {
    if v.single { x[0].into_py_any(py) } else { numpy::PyArray1::from_vec(py, x).into_py_any(py) }
}
