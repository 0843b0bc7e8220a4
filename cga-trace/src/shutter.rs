//! Motion blur: a shutter open over an interval of the motion's time, every sample of a pixel
//! at its own instant. The interval is cut into `N = m · spp` instants; a pixel's `spp`
//! samples lie one in each of `spp` strata of `m` instants (stratified in time), sample `s` in
//! stratum `(s + o) mod spp` at instant `r` of it, with `o` and `r` drawn by a hash of the
//! pixel. Neighbouring pixels so see a motion at different instants, and a moving object blurs
//! smoothly at any `spp` instead of leaving `spp` copies of itself. Each instant places the
//! scene anew by its keyframed motors (the same screw interpolation as `--frames`) and takes
//! the samples that fall on it, so a blurred picture casts the rays a still one of the same
//! `spp` does; what stands is kept from one instant to the next.

use crate::film::Film;
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
    /// The instants it is cut into at least (`time_samples`); `None`: [`Shutter::INSTANTS`].
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
    /// `m · spp` at most [`MAX_TIME_SAMPLES`].
    pub fn per_stratum(&self, spp: u32) -> u32 {
        let spp = spp.max(1);
        let wanted = self.samples.unwrap_or(Self::INSTANTS).div_ceil(spp);
        wanted.min(MAX_TIME_SAMPLES / spp).max(1)
    }

    /// The instants, `N = m · spp`.
    pub fn instants(&self, spp: u32) -> u32 {
        self.per_stratum(spp) * spp.max(1)
    }

    /// The motion's time of instant `k` of `n` for a frame at `time`: the middle of its
    /// `1/n` of the interval, `time + open + (k + ½)(close − open)/n`.
    pub fn time(&self, time: f64, k: u32, n: u32) -> f64 {
        time + self.open + (f64::from(k) + 0.5) * (self.close - self.open) / f64::from(n)
    }

    /// Pixel `(i, j)`'s rotation of its strata, `o ∈ [0, spp)`, and its instant within each,
    /// `r ∈ [0, m)`: hashes of the pixel.
    fn scramble(i: u32, j: u32, spp: u32, m: u32) -> (u32, u32) {
        (hash::pixel(i, j, 0x2545_f491) % spp, hash::pixel(i, j, 0x6c8e_9cf5) % m)
    }

    /// The instant sample `s` of pixel `(i, j)` is taken at, `((s + o) mod spp) · m + r`.
    pub fn instant_of(&self, spp: u32, [i, j, s]: Sample) -> u32 {
        let (spp, m) = (spp.max(1), self.per_stratum(spp));
        let (o, r) = Self::scramble(i, j, spp, m);
        (s + o) % spp * m + r
    }

    /// The picture of the pixels `columns × rows` of a frame at `time` with `spp` samples a
    /// pixel: `picture(t, samples)` renders the scene placed at instant `t` and gives the
    /// colour of each of `samples` (pixel and sample number, [`Shutter::instant_of`] them all
    /// `t`'s), and each pixel is the mean of its samples. Instants that take no sample are
    /// not placed. `on_row` is called `rows.len()` times in all, as the instants go by.
    pub fn expose<E>(
        &self,
        time: f64,
        spp: u32,
        (columns, rows): (Range<u32>, Range<u32>),
        on_row: &(dyn Fn() + Sync),
        mut picture: impl FnMut(f64, &[Sample]) -> Result<Vec<[f64; 3]>, E>,
    ) -> Result<Film, E> {
        let (spp, m) = (spp.max(1), self.per_stratum(spp));
        let n = m * spp;
        let width = columns.len();
        // The pixels by their instant within each stratum, with their rotations.
        let mut classes: Vec<Vec<[u32; 3]>> = vec![Vec::new(); m as usize];
        for j in rows.clone() {
            for i in columns.clone() {
                let (o, r) = Self::scramble(i, j, spp, m);
                classes[r as usize].push([i, j, o]);
            }
        }
        let mut sum = vec![[0.0; 3]; width * rows.len()];
        let mut samples: Vec<Sample> = Vec::new();
        let (mut reported, height) = (0, rows.len() as u64);
        for k in 0..n {
            let (q, r) = (k / m, k % m);
            samples.clear();
            samples.extend(classes[r as usize].iter().map(|&[i, j, o]| [i, j, (q + spp - o) % spp]));
            if !samples.is_empty() {
                let colours = picture(self.time(time, k, n), &samples)?;
                for (&[i, j, _], c) in samples.iter().zip(colours) {
                    let p = &mut sum[(j - rows.start) as usize * width + (i - columns.start) as usize];
                    *p = [p[0] + c[0], p[1] + c[1], p[2] + c[2]];
                }
            }
            let due = height * u64::from(k + 1) / u64::from(n);
            for _ in reported..due {
                on_row();
            }
            reported = due;
        }
        let pixels = sum.into_iter().map(|p| p.map(|c| c / f64::from(spp))).collect();
        Ok(Film { width: width as u32, height: rows.len() as u32, pixels })
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
