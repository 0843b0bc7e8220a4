//! Dilators (uniform scaling about a point) and transversors (translations conjugated by
//! the inversion in the unit sphere).

use super::{VersorError, VersorResult};
use crate::euclid::E3;
use crate::{Dilator, Real, Transversor};

impl<T: Real> Dilator<T> {
    /// Scaling by `factor` about `centre`: `x ↦ c + s (x − c)` and radii times `s`.
    /// `D = cosh(λ/2) + sinh(λ/2) (c ∧ ei + eo ∧ ei)` with `λ = ln s`, i.e. the translated
    /// `T_c (cosh + sinh E0) T̃_c` (`E0 = eo ∧ ei`, `T_c E0 T̃_c = up(c) ∧ ei`), written with
    /// `cosh(λ/2) = (s + 1)/(2√s)`, `sinh(λ/2) = (s − 1)/(2√s)`: `D D̃ = 1`. On a point,
    /// `D eo D̃ = (cosh − sinh)² eo` and `D ei D̃ = (cosh + sinh)² ei`, so distances from `c`
    /// grow by `s` (not `1/s`: the sign of `E0` decides, and is tested). `Factor` unless `s`
    /// is positive and finite.
    pub fn new(centre: E3<T>, factor: T) -> VersorResult<Self> {
        let root = factor.sqrt();
        let k = T::one() / (root + root);
        if factor <= T::zero() || !factor.is_finite() || !k.is_finite() || !centre.iter().all(|x| x.is_finite()) {
            return Err(VersorError::Factor);
        }
        let (ch, sh) = ((factor + T::one()) * k, (factor - T::one()) * k);
        Ok(Dilator { s: ch, e1i: sh * centre[0], e2i: sh * centre[1], e3i: sh * centre[2], eoi: sh })
    }

    /// The factor `s = (cosh + sinh)/(cosh − sinh)` of a dilator.
    pub fn factor(&self) -> T {
        (self.s + self.eoi) / (self.s - self.eoi)
    }
}

impl<T: Real> Transversor<T> {
    /// The transversion `x ↦ (x + |x|² t)/(1 + 2 t·x + |t|²|x|²)`: the translation by `t`
    /// seen through the inversion in the unit sphere (`ι T_t ι`, which keeps the origin and
    /// moves the point at infinity). As a versor `K = 1 + eo t` (`eo t = eo ∧ t`), the image
    /// of `T_t = 1 − ½ t ei` under the inversion's `ei ↦ −2 eo`; the sign is tested against
    /// the Euclidean map.
    pub fn from_vector(t: E3<T>) -> Self {
        // eo t = −t ∧ eo = −Σ t_k e_k ∧ eo.
        Transversor { s: T::one(), e1o: -t[0], e2o: -t[1], e3o: -t[2] }
    }
}
