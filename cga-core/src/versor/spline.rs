//! A C¹ spline of motors through several poses: cubic Bézier segments built by de
//! Casteljau's construction from screw interpolations (Shoemake's scheme, on motors).

use super::{VersorError, VersorResult};
use crate::{Generator, Motor, Real};

/// A spline of rigid motions through poses `M_0 … M_{n−1}` (`n ≥ 2`), evaluated at
/// `u ∈ [0, n − 1]` (pose `k` at `u = k`).
///
/// Segment `k` is the cubic Bézier curve with control poses `M_k`, `exp(v_k/3) M_k`,
/// `exp(−v_{k+1}/3) M_{k+1}`, `M_{k+1}`, evaluated by de Casteljau's construction with
/// [`Motor::interpolate`] for each linear step. Its velocity at the ends is `v_k` and
/// `v_{k+1}` exactly (`3 log(P1 P̃0)`), so neighbouring segments join with the same screw
/// velocity (C¹); the knot velocities are Catmull–Rom's,
/// `v_k = ½(log(M_{k+1} M̃_k) + log(M_k M̃_{k−1}))`, one-sided at the ends. Two poses give
/// the constant-velocity screw of [`Motor::interpolate`].
#[derive(Clone, Debug)]
pub struct MotorSpline<T: Real> {
    poses: Vec<Motor<T>>,
    velocities: Vec<Generator<T>>,
}

impl<T: Real> MotorSpline<T> {
    /// The spline through `poses` (rigid motors; each one's sign aligned with the previous
    /// one's so that every step takes the shorter path). `TooFewPoses` below two,
    /// `NotRigid`/`Antipodal` as [`Motor::interpolate`] for a pair of neighbours.
    pub fn new(poses: &[Motor<T>]) -> VersorResult<Self> {
        if poses.len() < 2 {
            return Err(VersorError::TooFewPoses);
        }
        let mut aligned: Vec<Motor<T>> = Vec::with_capacity(poses.len());
        for m in poses {
            let m = match aligned.last() {
                Some(prev) if (*m * prev.reverse()).s < T::zero() => -*m,
                _ => *m,
            };
            aligned.push(m);
        }
        let steps: Vec<Generator<T>> =
            aligned.windows(2).map(|w| Motor::relative_log(&w[0], &w[1])).collect::<VersorResult<_>>()?;
        let half = T::from_f64(0.5);
        let n = aligned.len();
        let velocities = (0..n)
            .map(|k| match k {
                0 => steps[0],
                k if k == n - 1 => steps[n - 2],
                k => (steps[k - 1] + steps[k]).scale(half),
            })
            .collect();
        Ok(MotorSpline { poses: aligned, velocities })
    }

    /// The number of poses.
    pub fn len(&self) -> usize {
        self.poses.len()
    }

    /// Always false: a spline has at least two poses.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The pose at `u`, clamped to `[0, n − 1]`.
    pub fn at(&self, u: T) -> VersorResult<Motor<T>> {
        let last = self.poses.len() - 1;
        let u = u.max(T::zero());
        let u = if u.to_f64() > last as f64 { T::from_f64(last as f64) } else { u };
        let k = (u.to_f64().floor() as usize).min(last - 1);
        let t = u - T::from_f64(k as f64);
        let third = T::from_f64(1.0 / 3.0);
        let p0 = self.poses[k];
        let p3 = self.poses[k + 1];
        let p1 = Motor::exp(self.velocities[k].scale(third)) * p0;
        let p2 = Motor::exp(self.velocities[k + 1].scale(-third)) * p3;
        let lerp = |a: &Motor<T>, b: &Motor<T>| Motor::interpolate(a, b, t);
        let (q0, q1, q2) = (lerp(&p0, &p1)?, lerp(&p1, &p2)?, lerp(&p2, &p3)?);
        let (r0, r1) = (lerp(&q0, &q1)?, lerp(&q1, &q2)?);
        lerp(&r0, &r1)
    }
}
