//! Adaptive anti-aliasing ([`Adaptive`]): every pixel takes its first `min_spp` samples; a
//! pixel takes the rest where its own samples, or its mean against a neighbour's, differ by
//! more than the threshold — POV-Ray's test between neighbours (`+A`) and pbrt-v2's within a
//! pixel, together, so that an edge is refined on both of its sides and a thin feature that
//! one pixel's first samples miss is found from the pixel next to it.
//!
//! The picture goes by bands of rows: the first samples of the band and of the pixels around
//! it (one more row and column on each side, within the image), then the rest. A pixel's
//! result depends only on its own samples and its neighbours' first ones, all placed by their
//! position: any thread count or crop window gives the same bytes. A pixel whose camera
//! forms no ray shows the background, as in a picture without adaptive sampling. Over a
//! transparent background the coverage counts as a fourth channel ([`Keep::contrast`]), so
//! that an edge against nothing is refined whatever its colour.

use super::keep::{Keep, Shown};
use super::sampler::Stage;
use super::{RayCounts, Renderer, Window};
use crate::backend::Backend;
use crate::film::{Channels, Film};
use crate::ray::Ray;
use crate::settings::Adaptive;
use rayon::prelude::*;
use std::ops::Range;

/// The bytes of first samples a band keeps: its rows are as many as fit, from 16 (a band's two
/// border rows then cost an eighth more first samples) to 256. At most 104 MB, for the widest
/// image's 18 rows of 65,538 pixels at 88 bytes.
const BAND_BYTES: usize = 64 << 20;

/// A pixel's first samples, `None` where the camera forms no ray there.
type First<K> = Option<K>;

impl<B: Backend> Renderer<'_, B> {
    /// The shaded picture of `window` under adaptive sampling `a`, each pixel's samples kept
    /// by `K`.
    pub(super) fn render_adaptive<K: Keep>(&self, a: Adaptive, window: Window, on_row: &(dyn Fn() + Sync)) -> Film {
        let camera = &self.scene.camera;
        let (width, height) = (window.columns.len(), window.rows.len());
        let mut pixels = vec![K::Pixel::default(); width * height];
        let columns = window.columns.start.saturating_sub(1)..(window.columns.end + 1).min(camera.width);
        let band_rows = (BAND_BYTES / (size_of::<First<K>>() * columns.len())).clamp(18, 258) - 2;
        let mut rows = pixels.chunks_mut(width).zip(window.rows.clone()).peekable();
        while rows.peek().is_some() {
            let band: Vec<(&mut [K::Pixel], u32)> = rows.by_ref().take(band_rows).collect();
            let (first_row, last_row) = (band[0].1, band[band.len() - 1].1);
            let around = first_row.saturating_sub(1)..(last_row + 2).min(camera.height);
            let firsts = self.firsts::<K>(a, columns.clone(), around.clone());
            let at =
                |i: u32, j: u32| &firsts[(j - around.start) as usize * columns.len() + (i - columns.start) as usize];
            band.into_par_iter().with_max_len(1).for_each(|(row, j)| {
                let mut cast = RayCounts::default();
                self.rest_of_row(a, row, window.columns.clone(), j, &at, &mut cast);
                self.count(&cast);
                on_row();
            });
        }
        K::Pixel::film(width as u32, height as u32, pixels)
    }

    /// The first `a.min_spp` samples of the pixels `columns × rows`, row by row.
    fn firsts<K: Keep>(&self, a: Adaptive, columns: Range<u32>, rows: Range<u32>) -> Vec<First<K>> {
        let mut firsts = vec![None; columns.len() * rows.len()];
        let n = a.min_spp as usize;
        firsts.par_chunks_mut(columns.len()).with_max_len(1).zip(rows).for_each(|(row, j)| {
            let mut cast = RayCounts::default();
            let mut done = 0;
            if self.packets {
                for (four, i0) in row.chunks_exact_mut(4).zip(columns.clone().step_by(4)) {
                    let mut taken = [K::default(); 4];
                    if self.take4(i0, j, Stage::First(n), &mut taken, &mut cast).is_none() {
                        break;
                    }
                    for (f, t) in four.iter_mut().zip(taken) {
                        *f = Some(t);
                    }
                    done += 4;
                }
            }
            for (f, i) in row.iter_mut().zip(columns.clone()).skip(done) {
                let mut taken = [K::default()];
                *f = self
                    .take::<Ray<B::Carrier>, 1, K>(i, j, super::Aov::Shaded, Stage::First(n), &mut taken, &mut cast)
                    .map(|()| taken[0]);
            }
            self.count(&cast);
        });
        firsts
    }

    /// Row `j` of the window's `columns`: each pixel's first samples, and the rest where
    /// [`Renderer::refines`] says.
    fn rest_of_row<'f, K: Keep + 'f>(
        &self,
        a: Adaptive,
        row: &mut [K::Pixel],
        columns: Range<u32>,
        j: u32,
        at: &impl Fn(u32, u32) -> &'f First<K>,
        cast: &mut RayCounts,
    ) {
        let background = K::empty(self.scene.settings.background);
        let mut done = 0;
        if self.packets {
            for (four, i0) in row.chunks_exact_mut(4).zip(columns.clone().step_by(4)) {
                let firsts: [First<K>; 4] = core::array::from_fn(|k| *at(i0 + k as u32, j));
                let [Some(t0), Some(t1), Some(t2), Some(t3)] = firsts else { break };
                let mut taken = [t0, t1, t2, t3];
                let more = core::array::from_fn(|k| self.refines(a, i0 + k as u32, j, at));
                if self.take4(i0, j, Stage::Rest(a.min_spp as usize, more), &mut taken, cast).is_none() {
                    break;
                }
                for (p, t) in four.iter_mut().zip(taken) {
                    *p = t.pixel();
                }
                done += 4;
            }
        }
        for (p, i) in row.iter_mut().zip(columns).skip(done) {
            let Some(first) = *at(i, j) else {
                *p = background;
                continue;
            };
            let mut taken = [first];
            let more = [self.refines(a, i, j, at)];
            let rest = self.take::<Ray<B::Carrier>, 1, K>(
                i,
                j,
                super::Aov::Shaded,
                Stage::Rest(a.min_spp as usize, more),
                &mut taken,
                cast,
            );
            *p = rest.map_or(background, |()| taken[0].pixel());
        }
    }

    /// Whether pixel `(i, j)` takes the rest of its samples: its first samples' contrast, or
    /// the distance between its mean and a neighbour's (left, right, below, above, within the
    /// image), exceeds the threshold, both in POV-Ray's measure ([`Keep::contrast`]).
    fn refines<'f, K: Keep + 'f>(&self, a: Adaptive, i: u32, j: u32, at: &impl Fn(u32, u32) -> &'f First<K>) -> bool {
        let camera = &self.scene.camera;
        let shown = Shown::of(&self.scene.settings);
        let Some(own) = at(i, j) else { return false };
        if own.contrast(shown) > a.threshold {
            return true;
        }
        let mean = own.pixel();
        let neighbours = [(i.wrapping_sub(1), j), (i + 1, j), (i, j.wrapping_sub(1)), (i, j + 1)];
        neighbours.into_iter().filter(|&(x, y)| x < camera.width && y < camera.height).any(|(x, y)| {
            let other = at(x, y).map_or(K::empty(self.scene.settings.background), |t| t.pixel());
            K::distance(mean, other, shown) > a.threshold
        })
    }
}
