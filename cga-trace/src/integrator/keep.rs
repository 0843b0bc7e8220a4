//! What a pixel keeps of its samples while they are taken ([`Keep`]): their colours
//! ([`Taken`], an opaque picture) or, over a transparent background, their colours with a miss
//! as nothing and how many met something ([`Covered`]); and POV-Ray's contrast between them, in
//! the values a PNG shows ([`Shown`]), which adaptive sampling decides by.

use crate::film::Channels;
use crate::settings::{Settings, ToneMap};

/// What a pixel keeps of its samples as they are taken, and gives once they are: [`Taken`]
/// (colours: an opaque picture) or [`Covered`] (premultiplied colours and coverage: a
/// transparent background). Chosen once a picture, so that an opaque picture's samples do
/// no more than they did before transparency existed.
pub(crate) trait Keep: Copy + Default + Send + Sync {
    /// The pixel's value: `[f64; 3]` colours, or `[f64; 4]` with the coverage.
    type Pixel: Channels;

    /// Whether it keeps the coverage: only then is it found (`Renderer::trace_met`).
    const COVERS: bool;

    /// Adds a sample: its colour (premultiplied by its coverage where `K` keeps that), and the
    /// fraction of its camera rays that met anything (0 or 1 for one ray).
    fn add(&mut self, colour: [f64; 3], coverage: f64);

    /// The mean of the samples taken.
    fn pixel(&self) -> Self::Pixel;

    /// Each of `W` samples' value, as [`Keep::pixel`] of it alone.
    fn samples<const W: usize>(colours: [[f64; 3]; W], coverage: [f64; W]) -> [Self::Pixel; W];

    /// A pixel where the camera forms no ray: the background (nothing, where transparent).
    fn empty(background: [f64; 3]) -> Self::Pixel;

    /// POV-Ray's contrast over the samples taken ([`Taken::contrast`]).
    fn contrast(&self, shown: Shown) -> f64;

    /// POV-Ray's distance between two pixels ([`Taken::distance`]).
    fn distance(a: Self::Pixel, b: Self::Pixel, shown: Shown) -> f64;
}

/// A pixel's samples so far: their sum (in sample order, so the mean has the same bits
/// however they were traced), their number, and each channel's range (linear).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Taken {
    sum: [f64; 3],
    n: u32,
    low: [f64; 3],
    high: [f64; 3],
}

impl Default for Taken {
    fn default() -> Self {
        Taken { sum: [0.0; 3], n: 0, low: [f64::INFINITY; 3], high: [f64::NEG_INFINITY; 3] }
    }
}

impl Taken {
    /// Adds a sample's colour to the sum and the ranges.
    #[inline(always)]
    fn add_colour(&mut self, c: [f64; 3]) {
        self.sum = [self.sum[0] + c[0], self.sum[1] + c[1], self.sum[2] + c[2]];
        self.n += 1;
        let (l, h) = (self.low, self.high);
        self.low = [l[0].min(c[0]), l[1].min(c[1]), l[2].min(c[2])];
        self.high = [h[0].max(c[0]), h[1].max(c[1]), h[2].max(c[2])];
    }

    /// POV-Ray's colour distance over the samples, `Σ_c (max d_c − min d_c)`, of the values
    /// shown, `d` ([`Shown`]: increasing, so it keeps the range's ends; a NaN sample counts as
    /// the most contrast).
    pub(crate) fn contrast(&self, shown: Shown) -> f64 {
        let c: f64 = (0..3).map(|k| shown.value(self.high[k]) - shown.value(self.low[k])).sum();
        if c.is_nan() || self.sum.iter().any(|x| x.is_nan()) { f64::INFINITY } else { c }
    }

    /// POV-Ray's colour distance between two colours as shown, `Σ_c |d_c(a) − d_c(b)|`
    /// (a NaN counts as the most distance).
    pub(crate) fn distance(a: [f64; 3], b: [f64; 3], shown: Shown) -> f64 {
        let d: f64 = (0..3).map(|k| (shown.value(a[k]) - shown.value(b[k])).abs()).sum();
        if d.is_nan() { f64::INFINITY } else { d }
    }

    /// The mean of the samples taken (zero for none).
    pub(crate) fn mean(&self) -> [f64; 3] {
        let n = f64::from(self.n.max(1));
        self.sum.map(|x| x / n)
    }
}

impl Keep for Taken {
    type Pixel = [f64; 3];
    const COVERS: bool = false;

    #[inline(always)]
    fn add(&mut self, colour: [f64; 3], _: f64) {
        self.add_colour(colour);
    }

    #[inline(always)]
    fn pixel(&self) -> [f64; 3] {
        self.mean()
    }

    #[inline(always)]
    fn samples<const W: usize>(colours: [[f64; 3]; W], _: [f64; W]) -> [[f64; 3]; W] {
        colours
    }

    fn empty(background: [f64; 3]) -> [f64; 3] {
        background
    }

    fn contrast(&self, shown: Shown) -> f64 {
        Taken::contrast(self, shown)
    }

    fn distance(a: [f64; 3], b: [f64; 3], shown: Shown) -> f64 {
        Taken::distance(a, b, shown)
    }
}

/// A pixel's samples over a transparent background: their colours, a miss's as nothing (so the
/// mean is premultiplied by the coverage), and the sum of their coverages (how many of them
/// met something, for one camera ray a sample).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Covered {
    taken: Taken,
    coverage: f64,
}

impl Keep for Covered {
    type Pixel = [f64; 4];
    const COVERS: bool = true;

    #[inline(always)]
    fn add(&mut self, colour: [f64; 3], coverage: f64) {
        self.taken.add_colour(colour);
        self.coverage += coverage;
    }

    #[inline(always)]
    fn pixel(&self) -> [f64; 4] {
        let [r, g, b] = self.taken.mean();
        [r, g, b, self.coverage / f64::from(self.taken.n.max(1))]
    }

    #[inline(always)]
    fn samples<const W: usize>(colours: [[f64; 3]; W], coverage: [f64; W]) -> [[f64; 4]; W] {
        core::array::from_fn(|k| {
            let mut one = Covered::default();
            one.add(colours[k], coverage[k]);
            one.pixel()
        })
    }

    fn empty(_: [f64; 3]) -> [f64; 4] {
        [0.0; 4]
    }

    /// The colours' contrast, plus the coverage's range as a fourth channel: 1 where the
    /// samples both met something and missed (an edge against nothing is an edge, whatever
    /// the colour).
    fn contrast(&self, shown: Shown) -> f64 {
        let mixed = self.coverage > 0.0 && self.coverage < f64::from(self.taken.n);
        self.taken.contrast(shown) + if mixed { 1.0 } else { 0.0 }
    }

    /// The colours' distance plus the coverages'.
    fn distance(a: [f64; 4], b: [f64; 4], shown: Shown) -> f64 {
        Taken::distance([a[0], a[1], a[2]], [b[0], b[1], b[2]], shown) + (a[3] - b[3]).abs()
    }
}

/// How a PNG of the picture shows a linear value: times `2^exposure`, tone-mapped, clipped to
/// [0, 1] (before its encoding), which adaptive sampling measures contrast in.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shown {
    scale: f64,
    tone_map: ToneMap,
}

impl Shown {
    pub(crate) fn of(settings: &Settings) -> Self {
        Shown { scale: settings.exposure.exp2(), tone_map: settings.tone_map }
    }

    fn value(self, x: f64) -> f64 {
        self.tone_map.apply(self.scale * x).clamp(0.0, 1.0)
    }
}
