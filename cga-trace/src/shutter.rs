//! Motion blur: a shutter open over an interval of the motion's time, sampled at instants.
//! Each instant places the scene anew by its keyframed motors (the same screw interpolation
//! as `--frames`) and takes its share of every pixel's samples
//! ([`Renderer::sample_subset`](crate::Renderer::sample_subset)), so that a blurred picture
//! costs what a still one of the same `spp` does, and its instants are stratified over the
//! interval.

use crate::film::Film;

/// A shutter open over `[time + open, time + close]` for a frame at `time` (the motion's time
/// runs over 0 … 1 through the keyframes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shutter {
    /// When it opens, relative to the frame's time.
    pub open: f64,
    /// When it closes, relative to the frame's time (at least `open`).
    pub close: f64,
    /// The instants it is sampled at; `None`: one per pixel sample.
    pub samples: Option<u32>,
}

impl Shutter {
    /// The instants for a frame at `time` with `spp` samples a pixel: `n = min(samples, spp)`
    /// of them (each must take at least one sample), instant `k` at the middle of its
    /// `1/n` of the interval, `time + open + (k + ½)(close − open)/n`, with the share of the
    /// samples it takes (`s ≡ k mod n`, [`Renderer::sample_subset`](crate::Renderer::sample_subset)).
    pub fn instants(&self, time: f64, spp: u32) -> Vec<Instant> {
        let spp = spp.max(1);
        let n = self.samples.unwrap_or(spp).clamp(1, spp);
        let width = self.close - self.open;
        (0..n)
            .map(|k| {
                let taken = (spp - k).div_ceil(n);
                Instant {
                    time: time + self.open + (f64::from(k) + 0.5) * width / f64::from(n),
                    first: k,
                    step: n,
                    weight: f64::from(taken) / f64::from(spp),
                }
            })
            .collect()
    }
}

/// One instant of a shutter: when, which samples it takes, and its weight in the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instant {
    /// The motion's time.
    pub time: f64,
    /// The first sample it takes, and the step between them.
    pub first: u32,
    /// See `first`.
    pub step: u32,
    /// Its samples' share of the pixel's.
    pub weight: f64,
}

impl Shutter {
    /// The picture of a frame at `time` with `spp` samples a pixel: `picture(t, (first,
    /// step))` renders the scene placed at instant `t` taking the samples `first, first +
    /// step, …` (their mean), and the instants' pictures are summed with their weights,
    /// `Σ w_k F_k`. Every picture must have the same size (the same scene's, at another
    /// time).
    pub fn expose<E>(
        &self,
        time: f64,
        spp: u32,
        mut picture: impl FnMut(f64, (u32, u32)) -> Result<Film, E>,
    ) -> Result<Film, E> {
        let mut sum: Option<Film> = None;
        for instant in self.instants(time, spp) {
            let film = picture(instant.time, (instant.first, instant.step))?;
            let out = sum.get_or_insert_with(|| Film {
                width: film.width,
                height: film.height,
                pixels: vec![[0.0; 3]; film.pixels.len()],
            });
            assert_eq!((film.width, film.height), (out.width, out.height), "one scene's pictures");
            for (o, p) in out.pixels.iter_mut().zip(&film.pixels) {
                *o = [0, 1, 2].map(|c| o[c] + instant.weight * p[c]);
            }
        }
        Ok(sum.expect("at least one instant"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn instants_take_every_sample_once() {
        let shutter = Shutter { open: 0.0, close: 1.0, samples: Some(3) };
        let instants = shutter.instants(0.25, 8);
        assert_eq!(instants.iter().map(|i| i.time).collect::<Vec<_>>(), [0.25 + 1.0 / 6.0, 0.75, 0.25 + 5.0 / 6.0]);
        let mut taken: Vec<u32> = instants.iter().flat_map(|i| (i.first..8).step_by(i.step as usize)).collect();
        taken.sort();
        assert_eq!(taken, (0..8).collect::<Vec<_>>());
        let total: f64 = instants.iter().map(|i| i.weight).sum();
        assert!((total - 1.0).abs() < 1e-15);
        // More instants than samples: one per sample.
        assert_eq!(Shutter { open: 0.0, close: 0.5, samples: Some(64) }.instants(0.0, 4).len(), 4);
    }
}
