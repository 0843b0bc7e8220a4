//! Rays cast, by kind.

/// Rays cast, by kind: one thread's tally of a row, or the renderer's total
/// ([`Renderer::counts`](super::Renderer::counts)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// From the camera.
    pub primary: u64,
    /// Towards lights.
    pub shadow: u64,
    /// Mirror bounces, and the rays a dielectric reflects and refracts (those cast: a branch
    /// whose weight falls below the cut-off is not).
    pub reflection: u64,
}

impl RayCounts {
    /// Adds `other`'s counts.
    pub fn add(&mut self, other: &RayCounts) {
        self.primary += other.primary;
        self.shadow += other.shadow;
        self.reflection += other.reflection;
    }

    /// `[primary, shadow, reflection]`.
    pub(super) fn to_array(self) -> [u64; 3] {
        [self.primary, self.shadow, self.reflection]
    }
}
