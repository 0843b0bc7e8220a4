//! The film: linear RGB pixels, `(0, 0)` bottom-left, written to PNG with the sRGB transfer
//! curve (or clipped linear values).

use crate::settings::Encoding;
use std::path::Path;

/// A rendered image in linear RGB.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major from the bottom row up.
    pub pixels: Vec<[f64; 3]>,
}

impl Film {
    /// From rows, bottom row first.
    pub fn from_rows(width: u32, height: u32, rows: Vec<Vec<[f64; 3]>>) -> Self {
        Film { width, height, pixels: rows.into_iter().flatten().collect() }
    }

    /// The linear colour of pixel `(i, j)`.
    pub fn get(&self, i: u32, j: u32) -> [f64; 3] {
        self.pixels[(j * self.width + i) as usize]
    }

    /// 8-bit RGB, top row first, encoded.
    pub fn to_rgb8(&self, encoding: Encoding) -> image::RgbImage {
        image::RgbImage::from_fn(self.width, self.height, |x, y| {
            let c = self.get(x, self.height - 1 - y);
            image::Rgb(c.map(|v| encode(v, encoding)))
        })
    }

    /// Write a PNG.
    pub fn save_png(&self, path: &Path, encoding: Encoding) -> Result<(), image::ImageError> {
        self.to_rgb8(encoding).save_with_format(path, image::ImageFormat::Png)
    }
}

/// One channel to 8 bits: clipped to [0, 1], sRGB-encoded or not, rounded.
pub fn encode(v: f64, encoding: Encoding) -> u8 {
    let v = if v.is_finite() { v.clamp(0.0, 1.0) } else { 0.0 };
    let e = match encoding {
        Encoding::Linear => v,
        Encoding::Srgb if v <= 0.003_130_8 => 12.92 * v,
        Encoding::Srgb => 1.055 * v.powf(1.0 / 2.4) - 0.055,
    };
    (e * 255.0).round() as u8
}
