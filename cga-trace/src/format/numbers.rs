//! Numbers as scene files may give them: finite, at most [`MAX_MAGNITUDE`] in size, and
//! arrays of exactly the length a field takes. Checked while the file is read, so that the
//! error points at the offending value and says what is wrong with it, before any geometry
//! is built from it.

use crate::limits::MAX_MAGNITUDE;
use serde::de::{Deserialize, Deserializer, Error, IgnoredAny, SeqAccess, Visitor};
use std::fmt;

/// Why `x` cannot be used, if it cannot.
fn refuse(x: f64) -> Option<String> {
    if x.is_nan() {
        Some("NaN is not a number a scene can use".into())
    } else if x.is_infinite() {
        Some(format!("{x} is not finite"))
    } else if x.abs() > MAX_MAGNITUDE {
        Some(format!("{x:e} is out of range (at most 1e100 in magnitude)"))
    } else {
        None
    }
}

/// One number, checked ([`refuse`]).
pub(crate) fn number<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    let x = f64::deserialize(d)?;
    refuse(x).map_or(Ok(x), |why| Err(D::Error::custom(why)))
}

/// [`number`] for a field that may be missing (with `#[serde(default)]`).
pub(crate) fn some_number<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
    number(d).map(Some)
}

/// [`numbers`] for a field that may be missing (with `#[serde(default)]`).
pub(crate) fn some_numbers<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<Option<[f64; N]>, D::Error> {
    numbers(d).map(Some)
}

/// Exactly `N` numbers, each checked.
pub(crate) fn numbers<'de, D: Deserializer<'de>, const N: usize>(d: D) -> Result<[f64; N], D::Error> {
    struct Exactly<const N: usize>;
    impl<'de, const N: usize> Visitor<'de> for Exactly<N> {
        type Value = [f64; N];
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            write!(f, "an array of {N} numbers")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<[f64; N], A::Error> {
            exactly::<A, f64, N>(seq)
        }
    }
    d.deserialize_seq(Exactly::<N>)
}

/// Exactly `N` numbers from an array being read, each read as a `T` (whose type error says
/// what an element must be) and checked ([`refuse`]).
pub(crate) fn exactly<'de, A, T, const N: usize>(mut seq: A) -> Result<[f64; N], A::Error>
where
    A: SeqAccess<'de>,
    T: Deserialize<'de> + Into<f64>,
{
    let mut out = [0.0; N];
    for (k, slot) in out.iter_mut().enumerate() {
        let x: f64 = seq
            .next_element::<T>()?
            .ok_or_else(|| A::Error::custom(format!("expected {N} numbers, found {k}")))?
            .into();
        if let Some(why) = refuse(x) {
            return Err(A::Error::custom(format!("element {}: {why}", k + 1)));
        }
        *slot = x;
    }
    let mut extra = 0;
    while seq.next_element::<IgnoredAny>()?.is_some() {
        extra += 1;
    }
    if extra > 0 {
        return Err(A::Error::custom(format!("expected {N} numbers, found {}", N + extra)));
    }
    Ok(out)
}

/// A checked number, for the file's own types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Num(pub f64);

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d).map(Num)
    }
}

/// `N` checked numbers (a point, a direction, a colour, a motor).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Nums<const N: usize>(pub [f64; N]);

impl<'de, const N: usize> Deserialize<'de> for Nums<N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        numbers(d).map(Nums)
    }
}

/// A point or direction.
pub(crate) type V3 = Nums<3>;

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Deserialize)]
    struct T {
        v: V3,
        x: Num,
    }

    fn error(text: &str) -> String {
        toml::from_str::<T>(text).err().map(|e| e.to_string()).unwrap_or_default()
    }

    #[test]
    fn bad_numbers_are_named_where_they_are() {
        let t = toml::from_str::<T>("v = [1, 2.5, -3]\nx = 0").unwrap();
        assert_eq!((t.v, t.x), (Nums([1.0, 2.5, -3.0]), Num(0.0)));
        for (text, says) in [
            ("v = [1.0, 2.0, 3.0, 4.0]\nx = 0", "expected 3 numbers, found 4"),
            ("v = [1.0, 2.0]\nx = 0", "expected 3 numbers, found 2"),
            ("v = [1.0, nan, 3.0]\nx = 0", "element 2: NaN"),
            ("v = [1.0, 2.0, 3.0]\nx = -inf", "-inf is not finite"),
            ("v = [1.0, 2.0, 3.0]\nx = 1e308", "out of range"),
            ("v = [1.0, \"a\", 3.0]\nx = 0", "invalid type"),
        ] {
            let e = error(text);
            assert!(e.contains(says), "{text}: {e}");
        }
        // Located at the value: line 2 for x.
        assert!(error("v = [1.0, 2.0, 3.0]\nx = nan").contains("line 2"));
    }
}
