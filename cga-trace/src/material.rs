//! Materials: a surface's colour and Blinn–Phong coefficients (the paper's eq. 12).

use crate::invalid::Invalid;
use cga_core::Real;
use cga_core::euclid::{dot, norm, scale, unit};
use cga_core::simd::Lane;

/// Surface colour and Blinn–Phong coefficients.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Linear RGB in [0, 1].
    pub colour: [f64; 3],
    /// Ambient coefficient `k_a`.
    pub ka: f64,
    /// Diffuse coefficient `k_d`.
    pub kd: f64,
    /// Specular coefficient `k_s`.
    pub ks: f64,
    /// Specular exponent `q`.
    pub q: f64,
    /// Mirror reflection `k_r`.
    pub kr: f64,
    /// Index of refraction of a dielectric (glass, water); 0 for an opaque surface. A
    /// dielectric reflects by Fresnel's equations and refracts by Snell's law
    /// (`integrator/glass.rs`); its `k_r` is not used.
    pub ior: f64,
    /// What a dielectric absorbs per world unit its light travels inside it (Beer–Lambert:
    /// `exp(−a d)` per channel).
    pub absorption: [f64; 3],
}

impl Material {
    /// `colour` with the default coefficients a scene file gets where it gives none:
    /// `k_a = 0.5`, `k_d = 1`, `k_s = 1`, `q = 100`, `k_r = 0`, opaque.
    pub fn new(colour: [f64; 3]) -> Material {
        Material { colour, ka: 0.5, kd: 1.0, ks: 1.0, q: 100.0, kr: 0.0, ior: 0.0, absorption: [0.0; 3] }
    }

    /// Every value finite and non-negative.
    pub fn check(&self) -> Result<(), Invalid> {
        let bad = |x: &f64| !x.is_finite() || *x < 0.0;
        let scalars = [("ka", self.ka), ("kd", self.kd), ("ks", self.ks), ("q", self.q), ("kr", self.kr)];
        if self.colour.iter().any(bad) {
            return Err(Invalid::of("colour", Invalid::Value("each channel must be finite and ≥ 0")));
        }
        if let Some((field, _)) = scalars.iter().find(|(_, x)| bad(x)) {
            return Err(Invalid::of(field, Invalid::Value("must be finite and ≥ 0")));
        }
        if bad(&self.ior) {
            let why = "must be finite and ≥ 0: 0 for an opaque material, the refractive index (about 1.5 for glass) for a dielectric";
            return Err(Invalid::of("ior", Invalid::Value(why)));
        }
        if self.absorption.iter().any(bad) {
            let why = "each channel must be finite and ≥ 0 (absorption per world unit; 0 for clear glass)";
            return Err(Invalid::of("absorption", Invalid::Value(why)));
        }
        Ok(())
    }

    /// Whether light passes through it (a dielectric: `ior > 0`).
    #[inline]
    pub fn dielectric(&self) -> bool {
        self.ior > 0.0
    }

    /// The specular term `max(c, 0)^q` for `c = n·h`: by repeated squaring ([`power`]) where
    /// `q` is a whole number up to 1,024 (as it nearly always is; far cheaper than `powf` and
    /// within a few ulps of it), by `powf` otherwise.
    #[inline]
    pub fn specular(&self, c: f64) -> f64 {
        if c.is_nan() || c <= 0.0 {
            // `max(c, 0)^q`, NaN included (as `f64::max` takes it): `0^0 = 1`.
            return if self.q == 0.0 { 1.0 } else { 0.0 };
        }
        match self.whole_exponent() {
            Some(n) => power(c, n),
            None => c.powf(self.q),
        }
    }

    /// `q` as a whole number up to 1,024, where it is one (then [`Material::specular`] is
    /// [`power`]`(c, q)` for `c > 0`).
    #[inline]
    pub fn whole_exponent(&self) -> Option<u32> {
        (self.q.fract() == 0.0 && self.q <= 1024.0).then_some(self.q as u32)
    }
}

/// `max(n·h, 0)^q` with `h = unit(l + v)` (`lv = l + v`) at one hit or, lane by lane, at a
/// packet's (`m[l]` lane `l`'s material), as [`Material::specular`] computes it for each: the
/// power in lanes where all share a whole `q`, `specular` for the rest, and where `|l + v|`
/// needs rescaling (or there is no `h`) [`unit`](fn@unit)'s own path.
#[inline(always)]
pub fn shine<T: Lane, const N: usize>(m: &[&Material; N], n: [T; 3], lv: [T; 3]) -> T {
    let at = |x: &[T; 3], l: usize| x.map(|c| c.lane(l));
    // `unit(lv)` lane by lane, where it rescales (or there is no `h`).
    let rescaled = |l: usize| unit(at(&lv, l)).map_or(0.0, |h| m[l].specular(cga_core::euclid::dot(at(&n, l), h)));
    if N == 1 {
        // One ray: `unit`'s path straight away (the same bits as the lanes' steps below).
        return T::from_fn(rescaled);
    }
    let inv = T::one() / norm(lv);
    let c = dot(n, scale(lv, inv));
    // The power only where some lane will take it.
    let q = m[0].whole_exponent().filter(|_| m.iter().all(|x| x.q == m[0].q) && T::any(T::zero().lt(c)));
    let powers = q.map(|q| power(c, q));
    T::from_fn(
        #[inline(always)]
        |l| {
            let (inv, c) = (inv.lane(l), c.lane(l));
            match powers {
                _ if !(inv.is_finite() && inv > 0.0) => rescaled(l),
                Some(p) if c > 0.0 => p.lane(l),
                _ => m[l].specular(c),
            }
        },
    )
}

/// The coefficients a light's term takes ([`crate::light::blinn_phong`]): colour, `k_d`
/// and `k_s` of one material, or of four in lanes for a packet.
#[derive(Clone, Copy, Debug)]
pub struct Reflectance<T> {
    /// Linear RGB.
    pub colour: [T; 3],
    /// Diffuse coefficient `k_d`.
    pub kd: T,
    /// Specular coefficient `k_s`.
    pub ks: T,
}

impl<T: Lane> Reflectance<T> {
    /// The materials of a ray's hit or of a packet's, lane `l` being `m[l]`'s.
    #[inline(always)]
    pub fn lanes<const W: usize>(m: &[&Material; W]) -> Self {
        let channel = |k: usize| T::from_fn(|l| m[l].colour[k]);
        Reflectance {
            colour: [channel(0), channel(1), channel(2)],
            kd: T::from_fn(|l| m[l].kd),
            ks: T::from_fn(|l| m[l].ks),
        }
    }
}

/// `c^n` by repeated squaring: `powi`'s own algorithm (compiler-rt's `__powidf2`, the same
/// bits), inlined, and generic so that four lanes take the same steps as one value.
#[inline(always)]
pub fn power<T: Real>(c: T, mut n: u32) -> T {
    let (mut r, mut a) = (T::one(), c);
    loop {
        if n & 1 == 1 {
            r = r * a;
        }
        n /= 2;
        if n == 0 {
            return r;
        }
        a = a * a;
    }
}

/// A material that reflects nothing (for lanes without a hit, and to build others from).
pub const NONE: Material =
    Material { colour: [0.0; 3], ka: 0.0, kd: 0.0, ks: 0.0, q: 0.0, kr: 0.0, ior: 0.0, absorption: [0.0; 3] };

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specular_agrees_with_powf() {
        for q in [0.0, 1.0, 7.0, 100.0, 1024.0, 2.5, 2000.0] {
            let m = Material { ks: 1.0, q, ..NONE };
            for c in [-0.5, 0.0, f64::NAN, 1e-3, 0.3, 0.9, 0.999, 1.0] {
                let want = f64::max(c, 0.0).powf(q);
                let got = m.specular(c);
                assert!((got - want).abs() <= 1e-13 * want.max(f64::MIN_POSITIVE), "q {q}, c {c}: {got} vs {want}");
            }
        }
    }
}
