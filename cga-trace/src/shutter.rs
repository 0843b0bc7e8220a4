//! Motion blur: a shutter open over an interval of the motion's time, every sample of a pixel
//! at its own instant. The interval is cut into `N = m · spp` instants; a pixel's `spp`
//! samples lie one in each of `spp` strata of `m` instants (stratified in time): stratum `q`
//! takes sample `π(q)` at its instant `r`, `π` a permutation of the samples and `r` drawn by
//! hashes of the pixel (so that a sample's time is not tied to where in the pixel it falls). Neighbouring pixels so see a motion at different instants, and a moving object blurs
//! smoothly at any `spp` instead of leaving `spp` copies of itself. Each instant places the
//! scene anew by its keyframed motors (the same screw interpolation as `--frames`) and takes
//! the samples that fall on it, so a blurred picture casts the rays a still one of the same
//! `spp` does; what stands is kept from one instant to the next.

use crate::film::{Channels, Film};
use crate::hash;
use crate::limits::MAX_TIME_SAMPLES;
use std::ops::Range;

/// A shutter open over `[time + open, time + close]` for a frame at `time` (the motion's time
/// runs over 0 … 1 through the keyframes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shutter {
    /// When it opens, relative to the frame's time.
    pub open: f64,
    /// When it closes, relative to the frame's time (at least `open`).
    pub close: f64,
    /// The instants it is cut into (`time_samples`; `None`: [`Shutter::INSTANTS`]), rounded up
    /// to a multiple of the samples a pixel takes ([`Shutter::instants`]).
    pub samples: Option<u32>,
}

/// One sample of one pixel: `[i, j, s]`, pixel `(i, j)`'s sample `s`.
pub type Sample = [u32; 3];

impl Shutter {
    /// The instants a shutter is cut into where the scene gives no `time_samples`: fine
    /// enough that an object crossing a quarter of a 1280-pixel picture moves at most about a
    /// pixel from one to the next.
    pub const INSTANTS: u32 = 256;

    /// Instants per stratum, `m = ⌈samples / spp⌉`, at least 1 and, where `spp` allows, with
    /// `m · spp` at most [`MAX_TIME_SAMPLES`] (so that `m = 1` where `spp` is more than half
    /// of it).
    pub fn per_stratum(&self, spp: u32) -> u32 {
        let spp = spp.max(1);
        let wanted = self.samples.unwrap_or(Self::INSTANTS).div_ceil(spp);
        wanted.min(MAX_TIME_SAMPLES / spp).max(1)
    }

    /// The instants, `N = m · spp`: never fewer than `spp` (each sample its own instant), and
    /// `time_samples` rounded up to a multiple of `spp` where that stays within
    /// [`MAX_TIME_SAMPLES`].
    pub fn instants(&self, spp: u32) -> u32 {
        self.per_stratum(spp) * spp.max(1)
    }

    /// The motion's time of instant `k` of `n` for a frame at `time`: the middle of its
    /// `1/n` of the interval, `time + open + (k + ½)(close − open)/n`.
    pub fn time(&self, time: f64, k: u32, n: u32) -> f64 {
        time + self.open + (f64::from(k) + 0.5) * (self.close - self.open) / f64::from(n)
    }

    /// Pixel `(i, j)`'s instant within each stratum, `r ∈ [0, m)`, and the seed of its
    /// permutation of samples to strata: hashes of the pixel.
    fn scramble(i: u32, j: u32, m: u32) -> (u32, u32) {
        (hash::pixel(i, j, 0x6c8e_9cf5) % m, hash::pixel(i, j, 0x2545_f491))
    }

    /// The sample of pixel `(i, j)` that stratum `q` takes, `π(q)`.
    fn sample_of(i: u32, j: u32, q: u32, spp: u32, seed: u32) -> Sample {
        [i, j, hash::permute(q, spp, seed)]
    }

    /// The instant sample `s` of pixel `(i, j)` is taken at, `q · m + r` with `π(q) = s`.
    pub fn instant_of(&self, spp: u32, [i, j, s]: Sample) -> u32 {
        let (spp, m) = (spp.max(1), self.per_stratum(spp));
        let (r, seed) = Self::scramble(i, j, m);
        let q = (0..spp).find(|&q| Self::sample_of(i, j, q, spp, seed)[2] == s).expect("π is a permutation");
        q * m + r
    }

    /// The picture of the pixels `columns × rows` of a frame at `time` with `spp` samples a
    /// pixel: `picture(t, samples)` renders the scene placed at instant `t` and gives the
    /// colour of each of `samples` (pixel and sample number, [`Shutter::instant_of`] them all
    /// `t`'s), and each pixel is the mean of its samples (summed in the order of their
    /// instants, so a scene that does not move gives its still picture to rounding). Instants
    /// that take no sample are not placed. `on_row` is called `rows.len()` times in all, as
    /// the instants go by. Beside the film it holds 4 bytes a pixel, and one instant's
    /// samples and colours, 36 bytes for each pixel the instant takes (every pixel where
    /// `m = 1`). The samples' values are colours (`P = [f64; 3]`), or premultiplied colours
    /// and coverage (`[f64; 4]`, a transparent background: the coverage too is the mean over
    /// the shutter's instants).
    pub fn expose<E, P: Channels>(
        &self,
        time: f64,
        spp: u32,
        (columns, rows): (Range<u32>, Range<u32>),
        on_row: &(dyn Fn() + Sync),
        mut picture: impl FnMut(f64, &[Sample]) -> Result<Vec<P>, E>,
    ) -> Result<Film, E> {
        let (spp, m) = (spp.max(1), self.per_stratum(spp));
        let n = m * spp;
        let width = columns.len();
        // The pixels by their instant within each stratum (4 bytes a pixel: the place in the
        // window; the rest is hashed again).
        let mut classes: Vec<Vec<u32>> = vec![Vec::new(); m as usize];
        for (p, (j, i)) in rows.clone().flat_map(|j| columns.clone().map(move |i| (j, i))).enumerate() {
            classes[Self::scramble(i, j, m).0 as usize].push(p as u32);
        }
        let at = |p: u32| (columns.start + p % width as u32, rows.start + p / width as u32);
        let mut sum = vec![P::default(); width * rows.len()];
        let mut samples: Vec<Sample> = Vec::new();
        let (mut reported, height) = (0, rows.len() as u64);
        for k in 0..n {
            let (q, r) = (k / m, k % m);
            samples.clear();
            samples.extend(classes[r as usize].iter().map(|&p| {
                let (i, j) = at(p);
                Self::sample_of(i, j, q, spp, Self::scramble(i, j, m).1)
            }));
            if !samples.is_empty() {
                let colours = picture(self.time(time, k, n), &samples)?;
                for (&p, c) in classes[r as usize].iter().zip(colours) {
                    for (s, c) in sum[p as usize].as_mut().iter_mut().zip(c.as_ref()) {
                        *s += c;
                    }
                }
            }
            let due = height * u64::from(k + 1) / u64::from(n);
            for _ in reported..due {
                on_row();
            }
            reported = due;
        }
        for p in &mut sum {
            p.as_mut().iter_mut().for_each(|c| *c /= f64::from(spp));
        }
        Ok(P::film(width as u32, rows.len() as u32, sum))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_pixel_takes_every_sample_once_one_in_each_stratum() {
        let shutter = Shutter { open: 0.0, close: 1.0, samples: None };
        assert_eq!((shutter.per_stratum(16), shutter.instants(16)), (16, 256));
        assert_eq!(Shutter { samples: Some(4), ..shutter }.instants(8), 8, "at least one instant a sample");
        assert_eq!(shutter.instants(4096), 4096);
        assert_eq!(Shutter { samples: Some(4096), ..shutter }.instants(3000), 3000);
        let mut seen = Vec::new();
        let film = shutter
            .expose(0.25, 8, (3..7, 1..4), &|| {}, |t, samples| {
                for &sample in samples {
                    let k = shutter.instant_of(8, sample);
                    assert_eq!(shutter.time(0.25, k, 256), t, "{sample:?} at its own instant");
                    seen.push((sample, k));
                }
                Ok::<_, ()>(samples.iter().map(|&[i, j, s]| [f64::from(i), f64::from(j), f64::from(s)]).collect())
            })
            .unwrap();
        assert_eq!(seen.len(), 4 * 3 * 8);
        for j in 1..4 {
            for i in 3..7 {
                let mine: Vec<_> = seen.iter().filter(|(p, _)| p[..2] == [i, j]).collect();
                let mut s: Vec<u32> = mine.iter().map(|(p, _)| p[2]).collect();
                s.sort();
                assert_eq!(s, (0..8).collect::<Vec<_>>(), "pixel ({i}, {j}) takes each sample once");
                let mut strata: Vec<u32> = mine.iter().map(|(_, k)| k / 32).collect();
                strata.sort();
                assert_eq!(strata, (0..8).collect::<Vec<_>>(), "one sample in each stratum of time");
                assert_eq!(film.pixels[((j - 1) * 4 + i - 3) as usize], [f64::from(i), f64::from(j), 3.5]);
            }
        }
        // Neighbours are taken at different instants.
        let first = |i| shutter.instant_of(8, [i, 0, 0]);
        assert!((0..8).map(first).collect::<std::collections::HashSet<_>>().len() > 4);
    }
}
