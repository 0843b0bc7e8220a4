//! The film: linear RGB pixels, `(0, 0)` bottom-left, and where the background is
//! transparent each pixel's coverage; written as an 8- or 16-bit PNG (with the sRGB transfer
//! curve, or clipped linear values; RGBA with straight colours where there is coverage) or as
//! linear floating point in OpenEXR (RGBA, premultiplied, where there is coverage) or Radiance
//! HDR (no alpha), the format chosen by the file's extension; the encodings, tone maps and the
//! sRGB curve both ways.

use image::{ImageBuffer, ImageFormat, Pixel, Rgb, Rgba};
use rayon::prelude::*;
use std::io::{Seek, Write};
use std::path::Path;
use std::sync::OnceLock;

/// A rendered image in linear RGB, with its coverage where the background is transparent.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major from the bottom row up; premultiplied by `coverage` where there is one.
    pub pixels: Vec<[f64; 3]>,
    /// Each pixel's coverage in [0, 1], the fraction of its samples whose camera ray met
    /// something (an alpha channel), as `pixels`; `None` for an opaque picture.
    pub coverage: Option<Vec<f64>>,
}

/// A pixel as a renderer gives it: linear RGB (an opaque picture), or RGB premultiplied by
/// the pixel's coverage and the coverage (a picture over a transparent background); its
/// values, RGB first, as a slice.
pub trait Channels: Copy + Default + Send + Sync + AsRef<[f64]> + AsMut<[f64]> {
    /// The film of `pixels` (row-major from the bottom row up).
    fn film(width: u32, height: u32, pixels: Vec<Self>) -> Film;
}

impl Channels for [f64; 3] {
    fn film(width: u32, height: u32, pixels: Vec<Self>) -> Film {
        Film { width, height, pixels, coverage: None }
    }
}

impl Channels for [f64; 4] {
    fn film(width: u32, height: u32, pixels: Vec<Self>) -> Film {
        let coverage = Some(pixels.iter().map(|p| p[3]).collect());
        Film { width, height, pixels: pixels.into_iter().map(|[r, g, b, _]| [r, g, b]).collect(), coverage }
    }
}

/// How an image file stores the film.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// PNG, 8 bits a channel, encoded ([`Encoding`]).
    Png8,
    /// PNG, 16 bits a channel, encoded ([`Encoding`]).
    Png16,
    /// OpenEXR, linear 32-bit floats, unclipped.
    Exr,
    /// Radiance RGBE (`.hdr`), linear, unclipped.
    Hdr,
}

/// Why an output file cannot be written as asked.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The extension names no format this renderer writes.
    #[error("`{0}`: unknown image extension (use .png, .exr or .hdr)")]
    Extension(String),
    /// A bit depth other than 8 or 16, or one given for a floating-point format.
    #[error("{bits}-bit output is not possible for {format} (PNG takes 8 or 16; EXR and HDR are floating point)")]
    BitDepth {
        /// Asked for.
        bits: u8,
        /// The format.
        format: &'static str,
    },
    /// A picture with coverage (a transparent background) asked of a format without alpha.
    #[error(
        "`{file}`: {format} has no alpha channel for `background = \"transparent\"`: write .png or .exr, or give the background a colour"
    )]
    NoAlpha {
        /// The output, as given.
        file: String,
        /// The format.
        format: &'static str,
    },
    /// Encoding failed.
    #[error(transparent)]
    Image(#[from] image::ImageError),
}

impl Output {
    /// The format for `path`'s extension (case-insensitive) and, for PNG, `bits` per channel
    /// (8 when not given).
    pub fn for_path(path: &Path, bits: Option<u8>) -> Result<Output, OutputError> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        Ok(match (ext.as_str(), bits) {
            ("png", None | Some(8)) => Output::Png8,
            ("png", Some(16)) => Output::Png16,
            ("exr", None) => Output::Exr,
            ("hdr", None) => Output::Hdr,
            ("png", Some(bits)) => return Err(OutputError::BitDepth { bits, format: "PNG" }),
            ("exr" | "hdr", Some(bits)) => return Err(OutputError::BitDepth { bits, format: "EXR and HDR" }),
            _ => return Err(OutputError::Extension(path.display().to_string())),
        })
    }

    /// Whether the format stores an alpha channel (PNG and EXR do; Radiance HDR does not).
    pub fn has_alpha(self) -> bool {
        self != Output::Hdr
    }

    /// Refuses a picture with coverage (`transparent`) where the format (of `path`) has no
    /// alpha channel, rather than drop it.
    pub fn check_alpha(self, path: &Path, transparent: bool) -> Result<(), OutputError> {
        match transparent && !self.has_alpha() {
            true => Err(OutputError::NoAlpha { file: path.display().to_string(), format: "Radiance HDR (.hdr)" }),
            false => Ok(()),
        }
    }
}

impl Film {
    /// The linear colour of pixel `(i, j)`.
    pub fn get(&self, i: u32, j: u32) -> [f64; 3] {
        self.pixels[j as usize * self.width as usize + i as usize]
    }

    /// An image of the film, top row first, each channel mapped by `f`.
    fn image<P>(&self, f: impl Fn(f64) -> P + Sync) -> ImageBuffer<Rgb<P>, Vec<P>>
    where
        P: Default + Clone + Send,
        Rgb<P>: Pixel<Subpixel = P>,
    {
        self.image_of(|pixels, _, row: &mut [P]| {
            for (out, pixel) in row.chunks_exact_mut(3).zip(pixels) {
                for (o, &v) in out.iter_mut().zip(pixel) {
                    *o = f(v);
                }
            }
        })
    }

    /// An image of the film with its coverage as alpha, top row first: each pixel's colour
    /// straight (unassociated: divided by its coverage; black where that is 0), each channel
    /// mapped by `f`, the coverage by `alpha`.
    fn image_rgba<P>(
        &self,
        f: impl Fn(f64) -> P + Sync,
        alpha: impl Fn(f64) -> P + Sync,
    ) -> ImageBuffer<Rgba<P>, Vec<P>>
    where
        P: Default + Clone + Send,
        Rgba<P>: Pixel<Subpixel = P>,
    {
        self.image_of(|pixels, coverage, row: &mut [P]| {
            for ((out, pixel), a) in row.chunks_exact_mut(4).zip(pixels).zip(alphas(coverage)) {
                let straight = unpremultiplied(*pixel, a);
                for (o, &v) in out.iter_mut().zip(&straight) {
                    *o = f(v);
                }
                out[3] = alpha(a);
            }
        })
    }

    /// An image whose rows `put(film row, its coverage, subpixels)` writes, top row first.
    fn image_of<Q, P>(&self, put: impl Fn(&[[f64; 3]], Option<&[f64]>, &mut [P]) + Sync) -> ImageBuffer<Q, Vec<P>>
    where
        P: Default + Clone + Send,
        Q: Pixel<Subpixel = P>,
    {
        // Rows in parallel (8-bit encoding of a large frame is otherwise a tenth of a
        // two-thread render); image rows run top-down, the film's bottom-up.
        let (w, h, n) = (self.width as usize, self.height as usize, usize::from(Q::CHANNEL_COUNT));
        let mut data = vec![P::default(); n * w * h];
        data.par_chunks_mut(n * w).enumerate().for_each(|(y, row)| {
            let at = (h - 1 - y) * w..(h - y) * w;
            put(&self.pixels[at.clone()], self.coverage.as_ref().map(|c| &c[at]), row);
        });
        ImageBuffer::from_raw(self.width, self.height, data).expect("n w h subpixels")
    }

    /// The film as a PNG shows it: each linear value times `2^exposure`, then tone-mapped
    /// (still linear; the encoding comes after). Where there is coverage, the straight colours
    /// are developed (a tone map is not linear) and premultiplied again.
    pub fn developed(&self, exposure: f64, tone_map: ToneMap) -> Film {
        let gain = exposure.exp2();
        let develop = |p: &[f64; 3]| p.map(|v| tone_map.apply(v * gain));
        let pixels = match &self.coverage {
            None => self.pixels.iter().map(develop).collect(),
            Some(coverage) => self
                .pixels
                .iter()
                .zip(coverage)
                .map(|(p, &a)| develop(&unpremultiplied(*p, a)).map(|v| v * a))
                .collect(),
        };
        Film { width: self.width, height: self.height, pixels, coverage: self.coverage.clone() }
    }

    /// 8-bit RGBA, top row first: straight colours encoded, the coverage as alpha (1 where the
    /// film has none), as a PNG stores them.
    pub fn to_rgba8(&self, encoding: Encoding) -> image::RgbaImage {
        let alpha = |a: f64| level8(a, Encoding::Linear);
        match encoding {
            Encoding::Srgb => self.image_rgba(srgb8, alpha),
            Encoding::Linear => self.image_rgba(|v| level8(v, encoding), alpha),
        }
    }

    /// 16-bit RGBA, top row first, as [`Film::to_rgba8`].
    pub fn to_rgba16(&self, encoding: Encoding) -> ImageBuffer<Rgba<u16>, Vec<u16>> {
        let level = |v: f64, encoding| (encode(v, encoding) * 65535.0 + 0.5) as u16;
        self.image_rgba(|v| level(v, encoding), |a| level(a, Encoding::Linear))
    }

    /// Linear 32-bit floats with the coverage as alpha, top row first: colours premultiplied
    /// (associated alpha), as OpenEXR stores them; NaN and infinities as [`Film::to_rgb32f`].
    pub fn to_rgba32f(&self) -> image::Rgba32FImage {
        self.image_of(|pixels, coverage, row: &mut [f32]| {
            for ((out, pixel), a) in row.chunks_exact_mut(4).zip(pixels).zip(alphas(coverage)) {
                for (o, &v) in out.iter_mut().zip(pixel.iter().chain([&a])) {
                    *o = float32(v);
                }
            }
        })
    }

    /// 8-bit RGB, top row first, encoded.
    pub fn to_rgb8(&self, encoding: Encoding) -> image::RgbImage {
        match encoding {
            Encoding::Srgb => self.image(srgb8),
            Encoding::Linear => self.image(|v| level8(v, encoding)),
        }
    }

    /// 16-bit RGB, top row first, encoded.
    pub fn to_rgb16(&self, encoding: Encoding) -> ImageBuffer<Rgb<u16>, Vec<u16>> {
        self.image(|v| (encode(v, encoding) * 65535.0 + 0.5) as u16)
    }

    /// Linear 32-bit floats, top row first, unclipped (NaN as 0; infinities as the largest
    /// f32, since the formats store no infinity usefully).
    pub fn to_rgb32f(&self) -> image::Rgb32FImage {
        self.image(float32)
    }

    /// Write the film in `output`'s format to `w` (`encoding` applies to PNG only): with its
    /// coverage as alpha where it has one (PNG straight, EXR premultiplied), refused for HDR.
    pub fn write<W: Write + Seek>(&self, w: &mut W, output: Output, encoding: Encoding) -> Result<(), OutputError> {
        let covered = self.coverage.is_some();
        match output {
            Output::Png8 if covered => self.to_rgba8(encoding).write_to(w, ImageFormat::Png)?,
            Output::Png16 if covered => self.to_rgba16(encoding).write_to(w, ImageFormat::Png)?,
            Output::Exr if covered => self.to_rgba32f().write_to(w, ImageFormat::OpenExr)?,
            Output::Png8 => self.to_rgb8(encoding).write_to(w, ImageFormat::Png)?,
            Output::Png16 => self.to_rgb16(encoding).write_to(w, ImageFormat::Png)?,
            Output::Exr => self.to_rgb32f().write_to(w, ImageFormat::OpenExr)?,
            Output::Hdr if covered => output.check_alpha(Path::new("the picture"), true)?,
            Output::Hdr => {
                // Radiance stores no negative values.
                let mut img = self.to_rgb32f();
                img.pixels_mut().flat_map(|p| p.0.iter_mut()).for_each(|v| *v = v.max(0.0));
                img.write_to(w, ImageFormat::Hdr)?
            }
        }
        Ok(())
    }
}

/// How the output PNG encodes linear values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum Encoding {
    /// The sRGB transfer curve (the default).
    #[default]
    Srgb,
    /// Clipped linear values, as the original renderer writes them.
    Linear,
}

/// How a PNG's linear values are brought into [0, 1] before encoding (EXR and HDR keep them
/// as rendered).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
pub enum ToneMap {
    /// Clipped at 1 (the default; what the reference images use).
    #[default]
    None,
    /// The filmic curve of ACES (Narkowicz's fit, `x (2.51 x + 0.03) / (x (2.43 x + 0.59) +
    /// 0.14)`): highlights roll off to white instead of clipping.
    Filmic,
}

impl ToneMap {
    /// One linear channel, tone-mapped (the filmic curve is 0 at 0, increasing, and ≤ 1).
    pub fn apply(self, v: f64) -> f64 {
        match self {
            ToneMap::None => v,
            ToneMap::Filmic => {
                let x = v.max(0.0);
                (x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)).min(1.0)
            }
        }
    }
}

/// A colour premultiplied by coverage `a` as a straight one: divided by `a`, black where `a`
/// is 0 (nothing there).
pub fn unpremultiplied(c: [f64; 3], a: f64) -> [f64; 3] {
    if a > 0.0 { c.map(|v| v / a) } else { [0.0; 3] }
}

/// A row's coverage, or 1 for each pixel of an opaque film.
fn alphas(coverage: Option<&[f64]>) -> impl Iterator<Item = f64> + '_ {
    coverage.into_iter().flatten().copied().chain(std::iter::repeat(1.0))
}

/// A linear value as a 32-bit float: NaN as 0, infinities as the largest f32 (the formats
/// store no infinity usefully).
fn float32(v: f64) -> f32 {
    if v.is_nan() { 0.0 } else { (v as f32).clamp(-f32::MAX, f32::MAX) }
}

/// An 8-bit sRGB channel as a linear value (the sRGB transfer curve inverted).
pub fn srgb_to_linear(v: u8) -> f64 {
    let v = f64::from(v) / 255.0;
    if v <= 0.040_45 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
}

/// The 8-bit level of a linear value: `encode` scaled to 255 and rounded.
fn level8(v: f64, encoding: Encoding) -> u8 {
    // `encode` is in [0, 1]: adding ½ and truncating rounds (`f64::round` is a libm call on
    // the baseline target, 4 % of a frame's instructions).
    (encode(v, encoding) * 255.0 + 0.5) as u8
}

/// [`level8`] for sRGB without `powf` per channel (a twentieth of a two-circle surface's
/// render): the level is the number of the 255 thresholds — the least `v` in `[0, 1]` at
/// which each level is reached, found once by bisection on the bits of `v` with `level8`
/// itself — that `v` has reached (`level8` is non-decreasing in `v`, so the two agree bit for
/// bit; test `srgb_levels_from_thresholds_are_encode_s`).
fn srgb8(v: f64) -> u8 {
    static THRESHOLDS: OnceLock<[f64; 255]> = OnceLock::new();
    let thresholds = THRESHOLDS.get_or_init(|| core::array::from_fn(|k| least_reaching(k as u8 + 1)));
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    thresholds.partition_point(|&t| t <= v) as u8
}

/// The least `v ∈ [0, 1]` whose sRGB level is at least `level` (non-negative doubles are
/// ordered as their bits).
fn least_reaching(level: u8) -> f64 {
    let reaches = |bits: u64| level8(f64::from_bits(bits), Encoding::Srgb) >= level;
    let (mut below, mut at) = (0u64, 1f64.to_bits());
    while at - below > 1 {
        let mid = below + (at - below) / 2;
        if reaches(mid) { at = mid } else { below = mid }
    }
    f64::from_bits(at)
}

/// One channel in `[0, 1]`: clipped (NaN as 0, +∞ as 1: a colour that overflows is as
/// bright as can be), then sRGB-encoded or not.
pub fn encode(v: f64, encoding: Encoding) -> f64 {
    let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
    match encoding {
        Encoding::Linear => v,
        Encoding::Srgb if v <= 0.003_130_8 => 12.92 * v,
        Encoding::Srgb => 1.055 * v.powf(1.0 / 2.4) - 0.055,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_filmic_curve_rolls_highlights_off_without_reordering_values() {
        let f = |v| ToneMap::Filmic.apply(v);
        assert_eq!(f(0.0), 0.0);
        assert_eq!(f(-1.0), 0.0);
        // An overflowing value is as bright as can be, NaN as dark (as the encoding treats them).
        assert_eq!((f(f64::INFINITY), f(f64::NAN)), (1.0, 0.0));
        let values: Vec<f64> = (0..=400).map(|k| f(f64::from(k) * 0.05)).collect();
        assert!(values.windows(2).all(|w| w[0] <= w[1]), "increasing");
        assert!(values.iter().all(|&v| (0.0..=1.0).contains(&v)));
        // Mid grey stays near mid grey; 2 (a clipped highlight) is still below white.
        assert!((f(0.18) - 0.18).abs() < 0.1 && f(2.0) < 0.95, "{} {}", f(0.18), f(2.0));
        assert_eq!(ToneMap::None.apply(3.0), 3.0);
    }

    #[test]
    fn srgb_levels_from_thresholds_are_encode_s() {
        let direct = |v: f64| level8(v, Encoding::Srgb);
        // Every threshold and its neighbours in the bits, where a disagreement would show.
        for level in 1..=255u8 {
            let t = least_reaching(level);
            for bits in t.to_bits().saturating_sub(2)..=t.to_bits() + 2 {
                let v = f64::from_bits(bits);
                assert_eq!(srgb8(v), direct(v), "{v:e} by level {level}");
            }
            assert!(direct(t) >= level && direct(f64::from_bits(t.to_bits() - 1)) < level);
        }
        // A spread of values, and the ones `encode` clips.
        let mut x = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = (x >> 11) as f64 / (1u64 << 53) as f64 * 1.2 - 0.1;
            assert_eq!(srgb8(v), direct(v), "{v:e}");
        }
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -0.0, 0.0, 1.0, 2.0, 0.003_130_8] {
            assert_eq!(srgb8(v), direct(v), "{v:e}");
        }
    }

    #[test]
    fn overflowing_colours_are_white_and_nan_black() {
        let pixels = vec![[f64::INFINITY; 3], [f64::NAN; 3], [0.5, 2.0, -1.0]];
        let film = Film { width: 3, height: 1, pixels, coverage: None };
        let img = film.to_rgb8(Encoding::Linear);
        assert_eq!(img.get_pixel(0, 0).0, [255; 3]);
        assert_eq!(img.get_pixel(1, 0).0, [0; 3]);
        assert_eq!(img.get_pixel(2, 0).0, [128, 255, 0]);
        assert_eq!(film.to_rgb16(Encoding::Linear).get_pixel(2, 0).0, [32768, 65535, 0]);
    }

    #[test]
    fn coverage_is_written_as_alpha_straight_in_png_and_premultiplied_in_exr() {
        // Half of an orange pixel, nothing, and a whole one.
        let orange = [0.8, 0.4, 0.2];
        let pixels = vec![orange.map(|c| c * 0.5), [0.0; 3], orange];
        let film = Film { width: 3, height: 1, pixels, coverage: Some(vec![0.5, 0.0, 1.0]) };
        let png = film.to_rgba8(Encoding::Linear);
        assert_eq!(png.get_pixel(0, 0).0, [204, 102, 51, 128], "straight colour, alpha ½");
        assert_eq!(png.get_pixel(1, 0).0, [0; 4]);
        assert_eq!(png.get_pixel(2, 0).0, [204, 102, 51, 255]);
        assert_eq!(film.to_rgba16(Encoding::Linear).get_pixel(0, 0).0, [52428, 26214, 13107, 32768]);
        let exr = film.to_rgba32f();
        assert_eq!(exr.get_pixel(0, 0).0, [0.4, 0.2, 0.1, 0.5], "premultiplied");
        // Developing acts on the straight colour: the filmic map of 0.8, times ½.
        let developed = film.developed(1.0, ToneMap::Filmic);
        assert_eq!(developed.coverage, film.coverage);
        let want = ToneMap::Filmic.apply(1.6) * 0.5;
        assert!((developed.pixels[0][0] - want).abs() < 1e-15, "{:?}", developed.pixels[0]);
        // An opaque film has no alpha: RGBA of it is opaque.
        let opaque = Film { coverage: None, ..film.clone() };
        assert_eq!(opaque.to_rgba8(Encoding::Linear).get_pixel(0, 0).0[3], 255);
        // Radiance HDR has none: refused, not dropped.
        let mut bytes = std::io::Cursor::new(Vec::new());
        assert!(matches!(film.write(&mut bytes, Output::Hdr, Encoding::Srgb), Err(OutputError::NoAlpha { .. })));
        assert!(opaque.write(&mut bytes, Output::Hdr, Encoding::Srgb).is_ok());
    }

    #[test]
    fn the_extension_picks_the_format() {
        let out = |p: &str, bits| Output::for_path(Path::new(p), bits);
        assert_eq!(out("a.png", None).unwrap(), Output::Png8);
        assert_eq!(out("a.PNG", Some(16)).unwrap(), Output::Png16);
        assert_eq!(out("a.exr", None).unwrap(), Output::Exr);
        assert_eq!(out("a.hdr", None).unwrap(), Output::Hdr);
        assert!(matches!(out("a.jpg", None), Err(OutputError::Extension(_))));
        assert!(matches!(out("a", None), Err(OutputError::Extension(_))));
        assert!(matches!(out("a.exr", Some(16)), Err(OutputError::BitDepth { .. })));
        assert!(matches!(out("a.png", Some(12)), Err(OutputError::BitDepth { .. })));
    }
}
