//! Adaptive anti-aliasing by corners ([`AdaptiveMethod::Corners`], POV-Ray's method 2,
//! `+AM2`): a ray at every pixel corner, each shared by the four pixels that meet there, so a
//! flat picture costs one ray a pixel; a square whose corners differ is cut into four.
//!
//! Every point lies on a grid of `n = 2^L` steps a pixel side (`L = ⌊log₄ spp⌋` cuts), and is
//! traced, lens and light points included, by its place on that grid alone, so any thread
//! count or crop window gives the same bytes. A pixel takes the points its left-hand
//! neighbour traced on their shared edge; one on an edge shared with the row above or below
//! (rows run in parallel) is traced by each pixel that needs it, with the same bits.
//!
//! [`AdaptiveMethod::Corners`]: crate::settings::AdaptiveMethod::Corners

use super::keep::{Keep, Shown};
use super::sampler::SampleKey;
use super::{Aov, RayCounts, Renderer, Window};
use crate::backend::Backend;
use crate::film::{Channels, Film};
use crate::ray::Ray;
use crate::settings::Adaptive;
use rayon::prelude::*;
use std::ops::Range;

/// The bytes of corners a band of rows keeps: as many rows as fit, 1 to 256.
const BAND_BYTES: usize = 64 << 20;

/// A point of the fine grid, in steps of `1/n` pixel from the picture's corner.
type Point = (u32, u32);

impl<B: Backend> Renderer<'_, B> {
    /// The shaded picture of `window` under adaptive sampling by corners, each sample's value
    /// as `K` keeps it.
    pub(super) fn render_corners<K: Keep>(&self, a: Adaptive, window: Window, on_row: &(dyn Fn() + Sync)) -> Film {
        let levels = Adaptive::levels(self.scene.settings.spp);
        let (width, height) = (window.columns.len(), window.rows.len());
        let mut pixels = vec![K::Pixel::default(); width * height];
        let corners = window.columns.start..window.columns.end + 1;
        let band_rows = (BAND_BYTES / (size_of::<K::Pixel>() * corners.len())).clamp(1, 256);
        for (band, j0) in pixels.chunks_mut(width * band_rows).zip(window.rows.clone().step_by(band_rows)) {
            let rows = (band.len() / width) as u32;
            let grid = self.corner_rows::<K>(levels, corners.clone(), j0..j0 + rows + 1);
            let at = |i: u32, j: u32| grid[(j - j0) as usize * corners.len() + (i - corners.start) as usize];
            band.par_chunks_mut(width).with_max_len(1).zip(j0..j0 + rows).for_each(|(row, j)| {
                let mut cast = RayCounts::default();
                let mut cut = Cut::new(levels);
                for (p, i) in row.iter_mut().zip(window.columns.clone()) {
                    cut.start([at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)], i > window.columns.start);
                    *p = self.square::<K>(a, &mut cut, (i, j), (0, 0), 1 << levels, levels, &mut cast);
                }
                self.count(&cast);
                on_row();
            });
        }
        K::Pixel::film(width as u32, height as u32, pixels)
    }

    /// The values at the pixel corners `columns × rows`, row by row.
    fn corner_rows<K: Keep>(&self, levels: u32, columns: Range<u32>, rows: Range<u32>) -> Vec<K::Pixel> {
        let n = 1 << levels;
        let mut grid = vec![K::Pixel::default(); columns.len() * rows.len()];
        grid.par_chunks_mut(columns.len()).with_max_len(1).zip(rows).for_each(|(row, j)| {
            let mut cast = RayCounts::default();
            let points: Vec<Point> = columns.clone().map(|i| (i * n, j * n)).collect();
            self.trace_points::<K>(levels, &points, row, &mut cast);
            self.count(&cast);
        });
        grid
    }

    /// The value of the square of side `size` (fine steps) at `corner` of pixel `pixel`:
    /// the mean of its corners where they agree or no cut is left, else the mean of its four
    /// quarters' values, its edges' midpoints and centre traced where not yet.
    #[allow(clippy::too_many_arguments)]
    fn square<K: Keep>(
        &self,
        a: Adaptive,
        cut: &mut Cut<K::Pixel>,
        pixel: (u32, u32),
        (x, y): Point,
        size: u32,
        levels: u32,
        cast: &mut RayCounts,
    ) -> K::Pixel {
        let c = [cut.get((x, y)), cut.get((x + size, y)), cut.get((x, y + size)), cut.get((x + size, y + size))];
        if levels == 0 || !differ::<K>(&c, a.threshold, Shown::of(&self.scene.settings)) {
            return mean(c);
        }
        let h = size / 2;
        // The edges' midpoints and the centre not yet traced, on the stack: this runs for
        // every cut square.
        let (mut missing, mut absolute, mut count) = ([(0, 0); 5], [(0, 0); 5], 0);
        for p in [(x + h, y), (x, y + h), (x + h, y + h), (x + size, y + h), (x + h, y + size)] {
            if !cut.has(p) {
                (missing[count], absolute[count]) = (p, (pixel.0 * cut.n + p.0, pixel.1 * cut.n + p.1));
                count += 1;
            }
        }
        let mut values = [K::Pixel::default(); 5];
        self.trace_points::<K>(cut.levels, &absolute[..count], &mut values[..count], cast);
        for (&p, &v) in missing[..count].iter().zip(&values) {
            cut.set(p, v);
        }
        let quarters = [(x, y), (x + h, y), (x, y + h), (x + h, y + h)];
        mean(quarters.map(|q| self.square::<K>(a, cut, pixel, q, h, levels - 1, cast)))
    }

    /// The values at fine-grid points `points` (of a grid of `2^levels` steps a pixel),
    /// four at a time through packets; the background where the camera forms no ray.
    fn trace_points<K: Keep>(&self, levels: u32, points: &[Point], out: &mut [K::Pixel], cast: &mut RayCounts) {
        let scale = 1.0 / f64::from(1u32 << levels);
        let place = |&(x, y): &Point| (f64::from(x) * scale, f64::from(y) * scale, SampleKey::new(x, y, 0, 1));
        let mut done = 0;
        if self.packets {
            for (four, values) in points.chunks_exact(4).zip(out.chunks_exact_mut(4)) {
                let p: [(f64, f64, SampleKey); 4] = core::array::from_fn(|k| place(&four[k]));
                let Some(v) = self.points4::<K>(p.map(|q| q.0), p.map(|q| q.1), p.map(|q| q.2), cast) else { break };
                values.copy_from_slice(&v);
                done += 4;
            }
        }
        let background = K::empty(self.scene.settings.background);
        for (point, value) in points.iter().zip(out.iter_mut()).skip(done) {
            let (u, v, key) = place(point);
            *value =
                self.points::<Ray<B::Carrier>, 1, K>([u], [v], [key], Aov::Shaded, cast).map_or(background, |[x]| x);
        }
    }
}

/// Whether any two of a square's corners differ by more than `threshold` (POV-Ray's colour
/// distance between them, [`Keep::distance`]: all six pairs, as POV-Ray compares them).
fn differ<K: Keep>(c: &[K::Pixel; 4], threshold: f64, shown: Shown) -> bool {
    const PAIRS: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    PAIRS.iter().any(|&(p, q)| K::distance(c[p], c[q], shown) > threshold)
}

/// The mean of four values, channel by channel, summed in order.
fn mean<P: Channels>(values: [P; 4]) -> P {
    let mut m = P::default();
    for (k, x) in m.as_mut().iter_mut().enumerate() {
        *x = (values[0].as_ref()[k] + values[1].as_ref()[k] + values[2].as_ref()[k] + values[3].as_ref()[k]) * 0.25;
    }
    m
}

/// One pixel's points on the fine grid of `n = 2^levels` steps a side, as traced so far: a
/// value and the pixel it was traced for (numbered from 2; 1 is no pixel, 0 nothing
/// traced), so that starting the next pixel clears nothing.
struct Cut<P> {
    levels: u32,
    n: u32,
    values: Vec<(u32, P)>,
    pixel: u32,
}

impl<P: Copy + Default> Cut<P> {
    fn new(levels: u32) -> Self {
        let n = 1 << levels;
        Cut { levels, n, values: vec![(0, P::default()); ((n + 1) * (n + 1)) as usize], pixel: 1 }
    }

    /// A new pixel, with its corners' values (at `(0, 0)`, `(n, 0)`, `(0, n)`, `(n, n)`);
    /// where it is the last one's right-hand neighbour (`beside`), the points the last one
    /// traced on their shared edge carry over (the same places: the same bits).
    fn start(&mut self, corners: [P; 4], beside: bool) {
        let (last, n) = (self.pixel, self.n);
        self.pixel += 1;
        if beside {
            for y in 1..n {
                let (stamp, v) = self.values[self.index((n, y))];
                if stamp == last {
                    self.set((0, y), v);
                }
            }
        }
        for (p, v) in [(0, 0), (n, 0), (0, n), (n, n)].into_iter().zip(corners) {
            self.set(p, v);
        }
    }

    fn index(&self, (x, y): Point) -> usize {
        (y * (self.n + 1) + x) as usize
    }

    fn has(&self, p: Point) -> bool {
        self.values[self.index(p)].0 == self.pixel
    }

    fn get(&self, p: Point) -> P {
        self.values[self.index(p)].1
    }

    fn set(&mut self, p: Point, v: P) {
        let i = self.index(p);
        self.values[i] = (self.pixel, v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_new_pixel_forgets_the_last_ones_points_without_clearing() {
        let mut cut = Cut::<[f64; 3]>::new(2);
        cut.start([[1.0; 3], [2.0; 3], [3.0; 3], [4.0; 3]], true);
        assert!(cut.has((0, 0)) && cut.has((4, 4)) && !cut.has((2, 2)) && !cut.has((0, 2)));
        cut.set((2, 2), [5.0; 3]);
        cut.set((4, 1), [6.0; 3]);
        assert_eq!((cut.get((4, 0)), cut.get((2, 2))), ([2.0; 3], [5.0; 3]));
        // The right-hand neighbour keeps the shared edge's points, and only those.
        cut.start([[0.0; 3]; 4], true);
        assert!(!cut.has((2, 2)) && cut.has((0, 4)) && !cut.has((4, 1)));
        assert!(cut.has((0, 1)) && cut.get((0, 1)) == [6.0; 3] && !cut.has((0, 2)));
        // A pixel that is not beside the last keeps nothing of it.
        cut.set((4, 3), [7.0; 3]);
        cut.start([[0.0; 3]; 4], false);
        assert!(!cut.has((0, 3)) && !cut.has((0, 1)));
    }

    #[test]
    fn the_deepest_cut_keeps_what_limits_md_says() {
        // docs/LIMITS.md: 6 cuts (spp 4096), (2⁶ + 1)² points of a transparent picture's
        // value and its stamp, 169 KB.
        assert_eq!(Adaptive::levels(crate::limits::MAX_SPP), 6);
        let cut = Cut::<[f64; 4]>::new(6);
        assert_eq!(cut.values.len() * size_of::<(u32, [f64; 4])>(), 169_000);
        assert_eq!([1, 3, 4, 15, 16, 63, 64].map(Adaptive::levels), [0, 0, 1, 1, 2, 2, 3]);
    }

    #[test]
    fn corners_differ_by_any_pair_and_average_in_order() {
        let shown = Shown::of(&crate::settings::Settings::default());
        let flat = [[0.5; 3]; 4];
        assert!(!differ::<super::super::keep::Taken>(&flat, 0.0, shown));
        let mut one = flat;
        one[3] = [0.5, 0.5, 0.6];
        assert!(differ::<super::super::keep::Taken>(&one, 0.05, shown));
        assert!(!differ::<super::super::keep::Taken>(&one, 0.5, shown));
        assert_eq!(mean([[1.0; 3], [2.0; 3], [3.0; 3], [6.0; 3]]), [3.0; 3]);
    }
}
