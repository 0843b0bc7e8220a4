//! Motors `M = T R`: built from rotors and translations, about lines and as screws; their
//! parts, inverse and rigid renormalisation; logarithm, exponential, powers and
//! interpolation.

use super::{VersorError, VersorResult, pseudo_infinity, rigid_tolerance, sinc_terms};
use crate::euclid::{E3, add, norm, scale, sub};
use crate::{Generator, Line, Motor, Real, Rotor, Translator};

impl<T: Real> Translator<T> {
    /// `1 − ½ t ei`: translation by `t`.
    pub fn from_vector(t: E3<T>) -> Self {
        let h = T::from_f64(-0.5);
        Translator { s: T::one(), e1i: h * t[0], e2i: h * t[1], e3i: h * t[2] }
    }

    /// The translation `t` of `1 − ½ t ei` (divided by the scalar part, so any weight reads
    /// the same).
    pub fn vector(&self) -> E3<T> {
        let k = T::from_f64(-2.0) / self.s;
        [self.e1i * k, self.e2i * k, self.e3i * k]
    }
}

impl<T: Real> Motor<T> {
    /// The identity motion, `M = 1`.
    #[inline]
    pub fn identity() -> Self {
        Motor { s: T::one(), ..Motor::zero() }
    }

    /// `T R`: rotate by `R` about the origin, then translate by `T` (clifford's order).
    pub fn from_rotor_translator(r: Rotor<T>, t: Translator<T>) -> Self {
        t * r
    }

    /// `T_t R`: rotate by `R` about the origin, then translate by `t`.
    pub fn from_rotor_translation(r: Rotor<T>, t: E3<T>) -> Self {
        Translator::from_vector(t) * r
    }

    /// The translation by `t`, as a motor.
    pub fn from_translation(t: E3<T>) -> Self {
        Translator::from_vector(t).into()
    }

    /// The rotation by `angle` (right-handed about the line's direction) about `line`:
    /// `M = T_{p − R p} R` for a point `p` of the line and `R` the rotor about its direction,
    /// the same motion as `T_p R T̃_p` and as `exp(−½ θ L*)` for the unit line `L`, written
    /// with Euclidean data so that a line far from the origin costs no digits beyond `|p|`'s.
    /// `ZeroAxis` for a degenerate line.
    pub fn about_line(line: &Line<T>, angle: T) -> VersorResult<Self> {
        Self::screw(line, angle, T::zero())
    }

    /// The screw motion about `line`: a turn by `angle` and an advance of `pitch · angle`
    /// along the line's direction (`pitch` is length per radian; per turn it is `2π pitch`).
    /// `M = T_{p − R p + h θ d} R`. Rotation and advance commute, so the order does not matter.
    pub fn screw(line: &Line<T>, angle: T, pitch: T) -> VersorResult<Self> {
        let d = line.direction().map_err(|_| VersorError::ZeroAxis)?;
        let p = line.point().map_err(|_| VersorError::ZeroAxis)?;
        let r = Rotor::from_axis_angle(d, angle)?;
        let t = add(sub(p, r.rotate(p)), scale(d, pitch * angle));
        Ok(Self::from_rotor_translation(r, t))
    }

    /// The rotation part `R` of a rigid motor `M = T R`: its scalar and `e_jk` parts.
    #[inline]
    pub fn rotor(&self) -> Rotor<T> {
        Rotor { s: self.s, e12: self.e12, e13: self.e13, e23: self.e23 }
    }

    /// The translation `t` of a rigid motor `M = T R` with unit `R`: `M R̃ = T = 1 − ½ t ei`,
    /// so `t = −2 ⟨M R̃⟩_{e_k i}`. Exact in the coefficients: no conformal point is formed.
    pub fn translation(&self) -> E3<T> {
        let t = *self * self.rotor().reverse();
        let m = T::from_f64(-2.0);
        [m * t.e1i, m * t.e2i, m * t.e3i]
    }

    /// The translator part `T = 1 − ½ t ei` of `M = T R` ([`Motor::translation`]).
    pub fn translator(&self) -> Translator<T> {
        Translator::from_vector(self.translation())
    }

    /// A direction moved by a rigid motor `M = T R` (unit `R`): `R d R̃` (translations do not
    /// move directions).
    pub fn move_direction(&self, d: E3<T>) -> E3<T> {
        self.rotor().rotate(d)
    }

    /// A point moved by a rigid motor `M = T R` (unit `R`): `R x R̃ + t`, the Euclidean part
    /// of `down(M up(x) M̃)` computed without `up(x)`, whose `½|x|²` would cost `ε |x|²` of
    /// the result (an object moved by 1e8 would lose its size) and overflow near 1e154.
    pub fn move_point(&self, x: E3<T>) -> E3<T> {
        add(self.move_direction(x), self.translation())
    }

    /// `M M̃ = a + b e123i` as `(a, b)`: `(1, 0)` exactly for a rigid motor.
    pub fn study(&self) -> (T, T) {
        let q = *self * self.reverse();
        (q.s, q.e123i)
    }

    /// How far `M` is from rigid: the larger of `|a − 1|` and `|b|` relative to the size of
    /// the translation parts, where `M M̃ = a + b e123i` (the Study condition is `a = 1,
    /// b = 0`). Scale-free: a motor moving by 1e6 has the same defect as one moving by 1.
    pub fn rigid_defect(&self) -> T {
        let (a, b) = self.study();
        let size = norm([self.e1i, self.e2i, self.e3i]).max(self.e123i.abs());
        let rel = if b == T::zero() { T::zero() } else { b.abs() / size };
        (a - T::one()).abs().max(rel)
    }

    /// The rigid motor nearest in the Study sense: `M (M M̃)^(−½)`, with
    /// `(a + b e123i)^(−½) = a^(−½) (1 − (b/2a) e123i)` (`e123i` squares to zero and commutes
    /// with motors), so that `M M̃ = 1` again: scalar part 1 and `e123i` part 0, not only a
    /// scale. `NotInvertible` when `a` is not positive and finite.
    pub fn renormalise(self) -> VersorResult<Self> {
        let (a, b) = self.study();
        let k = T::one() / a.sqrt();
        if a <= T::zero() || !k.is_finite() {
            return Err(VersorError::NotInvertible);
        }
        let fix = Motor { s: k, e123i: -k * b / (a + a), ..Motor::zero() };
        Ok(self * fix)
    }

    /// `M⁻¹ = M̃ (M M̃)⁻¹` with `(a + b e123i)⁻¹ = (a − b e123i)/a²` (the generated
    /// `try_inverse` of other types needs `X X̃` to be a scalar, which a motor's is not);
    /// `None` when `a` is zero or the result is not finite. For a rigid motor this is `M̃`.
    pub fn try_inverse(self) -> Option<Self> {
        let inv = self.inverse();
        inv.to_array().iter().all(|x| x.is_finite()).then_some(inv)
    }

    /// [`Motor::try_inverse`] for a motor known to be invertible: non-finite coefficients
    /// otherwise.
    pub fn inverse(self) -> Self {
        let (a, b) = self.study();
        let k = T::one() / (a * a);
        self.reverse() * Motor { s: a * k, e123i: -b * k, ..Motor::zero() }
    }

    /// `exp(B)` for the generator `B` of a rigid motion. With `B² = −φ² + ε e123i` (`e123i`
    /// nilpotent and central here), the series sums to
    /// `exp B = cos φ + (sin φ/2φ) ε e123i + (sin φ/φ) B − ((φ cos φ − sin φ)/2φ³) ε e123i B`.
    /// `exp(−½θ a I3)` is the rotor of [`Rotor::from_axis_angle`]; `exp(−½ t ∧ ei)` the
    /// translator by `t`. Always rigid.
    pub fn exp(b: Generator<T>) -> Self {
        let b = Motor::from(b);
        let sq = b * b;
        let phi = if sq.s < T::zero() { (-sq.s).sqrt() } else { T::zero() };
        let eps = sq.e123i;
        let (c1, dc) = sinc_terms(phi);
        let half_c1 = c1 * T::from_f64(0.5);
        let c2 = dc * eps;
        Motor { s: phi.cos(), e123i: half_c1 * eps, ..Motor::zero() }
            + b.scale(c1)
            + (pseudo_infinity::<T>() * b).scale(c2)
    }

    /// `log M`: the generator `B` with `exp(B) = M`, for a rigid motor (`NotRigid` with the
    /// defect otherwise: [`Motor::renormalise`] first) whose half-angle `φ` is below `π`.
    /// Inverts the closed form of [`Motor::exp`]: `φ = atan2(|⟨M⟩_rot|, ⟨M⟩₀)`, the rotation
    /// part divided by `sin φ / φ`, the translation part with the `e123i` correction removed.
    /// `Antipodal` at `φ = π` (`M = −T`, a full turn about an undetermined axis: `−M`, the
    /// same motion, has a logarithm).
    pub fn log(self) -> VersorResult<Generator<T>> {
        let defect = self.rigid_defect();
        if !super::within(defect, rigid_tolerance::<T>()) {
            return Err(VersorError::NotRigid { defect: defect.to_f64() });
        }
        let phi = norm([self.e12, self.e13, self.e23]).atan2(self.s);
        let (c1, dc) = sinc_terms(phi);
        if c1 <= T::epsilon() {
            return Err(VersorError::Antipodal);
        }
        let br = Motor { e12: self.e12 / c1, e13: self.e13 / c1, e23: self.e23 / c1, ..Motor::zero() };
        let eps = (self.e123i + self.e123i) / c1;
        let c2 = dc * eps;
        let corr = pseudo_infinity::<T>() * br;
        let bt = |m: T, k: T| (m - c2 * k) / c1;
        Ok(Generator {
            e12: br.e12,
            e13: br.e13,
            e23: br.e23,
            e1i: bt(self.e1i, corr.e1i),
            e2i: bt(self.e2i, corr.e2i),
            e3i: bt(self.e3i, corr.e3i),
        })
    }

    /// `M^t = exp(t log M)`: the same screw, `t` times as far (constant velocity in `t`).
    /// It follows `M`'s sign: `M` and `−M` move alike, but their powers differ by a turn of
    /// `π t`; [`Motor::interpolate`] chooses the shorter.
    pub fn pow(self, t: T) -> VersorResult<Self> {
        Ok(Self::exp(self.log()?.scale(t)))
    }

    /// Screw linear interpolation: `exp(t log(M1 M̃0)) M0`, the constant-velocity screw
    /// motion from `M0` (`t = 0`) to `M1` (`t = 1`, up to the sign, the same motion), along
    /// the shorter of the two paths (the relative motor's sign chosen with `⟨M1 M̃0⟩₀ ≥ 0`,
    /// so the relative turn is at most π). `NotRigid` for a drifted end (renormalise it),
    /// `Antipodal` for a relative half turn, where both paths are as short.
    pub fn interpolate(m0: &Self, m1: &Self, t: T) -> VersorResult<Self> {
        Ok(Self::exp(Self::relative_log(m0, m1)?.scale(t)) * *m0)
    }

    /// `log(M1 M̃0)` with the sign of the shorter path: the velocity of [`Motor::interpolate`].
    pub fn relative_log(m0: &Self, m1: &Self) -> VersorResult<Generator<T>> {
        for m in [m0, m1] {
            let defect = m.rigid_defect();
            if !super::within(defect, rigid_tolerance::<T>()) {
                return Err(VersorError::NotRigid { defect: defect.to_f64() });
            }
        }
        let mut delta = *m1 * m0.reverse();
        if delta.s < T::zero() {
            delta = -delta;
        }
        if delta.s <= T::from_f64(64.0) * T::epsilon() {
            return Err(VersorError::Antipodal);
        }
        // The product's rounding is of the factors' sizes, which a near-identity `delta`
        // no longer shows: project it back onto the rigid motors before its logarithm.
        delta.renormalise()?.log()
    }
}
