//! Images a scene reads — textures and environment maps — as linear RGB: PNG decoded from
//! sRGB, OpenEXR and Radiance HDR as they are; looked up bilinearly at `(u, v)` in [0, 1]²,
//! `u` wrapping around, `v` from the top edge down.

use crate::film::srgb_to_linear;
use crate::input::open_regular;
use crate::invalid::Invalid;
use crate::limits::{MAX_IMAGE_PIXELS, MAX_SCENE_IMAGE_PIXELS};
use std::io::Seek;
use std::path::Path;

/// A linear RGB image.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    /// Pixels across.
    pub width: u32,
    /// Pixels down.
    pub height: u32,
    /// Rows from the top, each left to right.
    pub pixels: Vec<[f32; 3]>,
}

impl Picture {
    /// The image at `path` ([`Picture::read`] with the whole budget of one image).
    pub fn load(path: &Path) -> Result<Picture, Invalid> {
        let (file, _, _) = open_regular(path).map_err(|e| Invalid::Image(format!("{}: {e}", path.display())))?;
        Picture::read(file, path, MAX_IMAGE_PIXELS)
    }

    /// The image in `file` (read from `path`, which messages name): its size checked from
    /// the header, against [`MAX_IMAGE_PIXELS`] and against `budget` (the pixels the scene's
    /// images may still take, [`MAX_SCENE_IMAGE_PIXELS`] in all), before it is decoded.
    /// Decoding holds the file's own pixels and the linear copy, so at most 16 bytes a pixel
    /// for an 8-bit PNG.
    pub fn read(file: std::fs::File, path: &Path, budget: u64) -> Result<Picture, Invalid> {
        let why = |e: &dyn std::fmt::Display| Invalid::Image(format!("{}: {e}", path.display()));
        let mut source = std::io::BufReader::new(file);
        let reader = image::ImageReader::new(&mut source).with_guessed_format().map_err(|e| why(&e))?;
        let format = reader.format();
        let (width, height) = reader.into_dimensions().map_err(|e| why(&e))?;
        let pixels = u64::from(width) * u64::from(height);
        if pixels > MAX_IMAGE_PIXELS || width == 0 || height == 0 {
            return Err(why(&format!("{width} × {height} pixels: give an image of 1 to {MAX_IMAGE_PIXELS} pixels")));
        }
        if pixels > budget {
            return Err(why(&format!(
                "{width} × {height} pixels: the scene's images would hold more than the limit of {MAX_SCENE_IMAGE_PIXELS} pixels in all"
            )));
        }
        source.seek(std::io::SeekFrom::Start(0)).map_err(|e| why(&e))?;
        let reader = image::ImageReader::new(source).with_guessed_format().map_err(|e| why(&e))?;
        let decoded = reader.decode().map_err(|e| why(&e))?;
        let pixels = if format == Some(image::ImageFormat::Png) {
            decoded.into_rgb8().pixels().map(|p| p.0.map(|c| srgb_to_linear(c) as f32)).collect()
        } else {
            decoded.into_rgb32f().pixels().map(|p| p.0).collect()
        };
        Ok(Picture { width, height, pixels })
    }

    /// The colour at `(u, v)`, bilinear between the four nearest pixel centres: `u` wraps
    /// (an environment's longitude, a texture's repeat), `v` is held to the image (0 the top
    /// row, 1 the bottom one).
    pub fn at(&self, u: f64, v: f64) -> [f64; 3] {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let x = (u - u.floor()) * w - 0.5;
        let y = (v.clamp(0.0, 1.0) * h - 0.5).clamp(0.0, h - 1.0);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |x: f64| (x.rem_euclid(w)) as usize;
        let row = |y: f64| (y.min(h - 1.0)) as usize;
        let texel = |x: f64, y: f64| self.pixels[row(y) * self.width as usize + column(x)].map(f64::from);
        let (a, b, c, d) = (texel(x0, y0), texel(x0 + 1.0, y0), texel(x0, y0 + 1.0), texel(x0 + 1.0, y0 + 1.0));
        [0, 1, 2].map(|k| (a[k] * (1.0 - fx) + b[k] * fx) * (1.0 - fy) + (c[k] * (1.0 - fx) + d[k] * fx) * fy)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookups_are_bilinear_and_wrap_in_u() {
        let p = Picture { width: 2, height: 1, pixels: vec![[0.0; 3], [1.0; 3]] };
        assert_eq!(p.at(0.25, 0.5), [0.0; 3]);
        assert_eq!(p.at(0.75, 0.5), [1.0; 3]);
        assert_eq!(p.at(0.5, 0.5), [0.5; 3]);
        // Across the seam: halfway between the last column and the first.
        assert_eq!(p.at(0.0, 0.5), [0.5; 3]);
        assert_eq!(p.at(1.25, 0.0), p.at(0.25, 1.0));
    }
}
