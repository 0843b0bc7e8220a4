//! The benchmarks live beside this file (`products.rs`, `render.rs`, `peers.rs`,
//! `batch_timing.rs`, `pga_timing.rs`, `surface_rays.rs`); this library only holds what they
//! share.

/// A shipped scene file of cga-trace, by name (`primitives`, `surface`, `combined`).
pub fn scene_path(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cga-trace/scenes").join(format!("{name}.toml"))
}

/// The median ns per operation of each of `forms` (each call does `ops` operations, and is
/// run `reps` times a round), in `rounds` interleaved rounds (one round of each in turn) so
/// that a change in the machine's load falls on all of them alike.
pub fn medians_ns(ops: usize, reps: usize, rounds: usize, forms: &mut [&mut dyn FnMut()]) -> Vec<f64> {
    let mut times = vec![Vec::with_capacity(rounds); forms.len()];
    for _ in 0..rounds {
        for (f, t) in forms.iter_mut().zip(&mut times) {
            let start = std::time::Instant::now();
            for _ in 0..reps {
                f();
            }
            t.push(start.elapsed().as_nanos() as f64 / (reps * ops) as f64);
        }
    }
    times
        .into_iter()
        .map(|mut r| {
            r.sort_by(f64::total_cmp);
            r[rounds / 2]
        })
        .collect()
}

/// The six operations of the Versor comparison as [`cga_core::simd::Kernel`]s, for
/// `peers.rs` and `batch_timing.rs`.
pub mod kernels {
    use cga_core::simd::{Kernel, Lane, Over};
    use cga_core::{Circle, Even, Line, Motor, PointPair, Rotor, Sandwich, Sphere, Vector};

    /// A [`Kernel`] named `$name` from `$input` to `$output` computing `$body` over `$x`.
    macro_rules! kernel {
        ($(#[$doc:meta])* $name:ident: $input:ty => $output:ident, |$x:pat_param| $body:expr) => {
            $(#[$doc])*
            #[derive(Default)]
            pub struct $name;
            impl Kernel for $name {
                type Input = $input;
                type Output = $output;
                #[inline(always)]
                fn apply<L: Lane>(&self, $x: Over<$input, L>) -> $output<L> {
                    $body
                }
            }
        };
    }
    kernel!(
        /// `L ∨ S`.
        MeetSphere: (Line, Sphere) => PointPair, |(l, s)| l & s);
    kernel!(
        /// `X₁ ∧ X₂ ∧ X₃`.
        ThreePoints: (Vector, Vector, Vector) => Circle, |(x, y, z)| (x ^ y) ^ z);
    kernel!(
        /// `M X M̃`.
        MotorOnPoint: (Motor, Vector) => Vector, |(m, x)| m.sandwich(x));
    kernel!(
        /// `C₁ C₂`.
        CircleCircle: (Circle, Circle) => Even, |(x, y)| x * y);
    kernel!(
        /// `M₁ M₂`.
        MotorMotor: (Motor, Motor) => Motor, |(x, y)| x * y);
    kernel!(
        /// `R₁ R₂`.
        RotorRotor: (Rotor, Rotor) => Rotor, |(x, y)| x * y);
}
