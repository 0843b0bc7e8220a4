//! Labels written into a rendered picture beside their objects, in a bitmap font of
//! `embedded-graphics` (ISO 8859-1: ASCII and the Latin-1 letters; other characters show as
//! `?`), outlined in black so that they read on any background; opaque where drawn over a
//! transparent one (each pixel of text or outline takes coverage 1).

use crate::camera::Camera;
use crate::film::Film;
use cga_core::euclid::{E3, dot, sub};
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle, iso_8859_1};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text};

/// Characters of a label (longer ones are refused where they are read).
pub const MAX_LABEL_CHARS: usize = 64;

/// A label: its text, the object it names (a sphere about it, in the scene's frame) and
/// its colour (linear RGB, the object's).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The text.
    pub text: String,
    /// The centre of the sphere holding the object, in the scene's frame.
    pub at: E3,
    /// That sphere's radius.
    pub reach: f64,
    /// Linear RGB.
    pub colour: [f64; 3],
}

/// The continuous pixel coordinates `(u, v)` of a frame point seen by `camera` (`v` from
/// the bottom, as the film's rows), and its depth along the view; `None` behind the camera.
/// The inverse of [`Camera::image_point`]: `u = w (x/x_max + ½)` for the image-plane point
/// `f x_c / y_c`.
pub fn project(camera: &Camera, x: E3) -> Option<(f64, f64, f64)> {
    let axes = camera.axes();
    let r = sub(x, camera.position());
    let [xc, depth, zc] = [0, 1, 2].map(|k| dot(r, axes[k]));
    if depth <= 0.0 {
        return None;
    }
    let (w, h) = (f64::from(camera.width), f64::from(camera.height));
    // Where the image plane is met: at `f/depth` of the way for rays through the camera's
    // point (or a thin lens's centre), at `1/k` for an orthographic view's parallel rays.
    let along = match camera.lens {
        crate::camera::Lens::Orthographic { k } => 1.0 / k,
        _ => camera.focal / depth,
    };
    let u = w * (along * xc / camera.x_max + 0.5);
    let v = h * (along * zc / camera.y_max + 0.5);
    Some((u, v, depth))
}

/// The film as a canvas of one colour (top-left origin, as the font draws).
struct Canvas<'a> {
    film: &'a mut Film,
    paint: [f64; 3],
}

impl OriginDimensions for Canvas<'_> {
    fn size(&self) -> Size {
        Size::new(self.film.width, self.film.height)
    }
}

impl DrawTarget for Canvas<'_> {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        let (w, h) = (self.film.width as i32, self.film.height as i32);
        for Pixel(p, c) in pixels {
            if c.is_on() && (0..w).contains(&p.x) && (0..h).contains(&p.y) {
                let at = ((h - 1 - p.y) * w + p.x) as usize;
                self.film.pixels[at] = self.paint;
                // Covered whole, so the paint is its own premultiplied colour.
                if let Some(coverage) = &mut self.film.coverage {
                    coverage[at] = 1.0;
                }
            }
        }
        Ok(())
    }
}

/// The font for a picture `width` pixels wide: 9×15 up to 1600, 10×20 beyond.
fn font(width: u32) -> &'static MonoFont<'static> {
    if width > 1600 { &iso_8859_1::FONT_10X20 } else { &iso_8859_1::FONT_9X15_BOLD }
}

/// Write `labels` into `film` (the whole picture `camera` takes), each to the right of its
/// object's image at the height of its centre, or the nearest line above or below that no
/// earlier label covers; a label whose object is behind the camera is left out. Where the film
/// has coverage, the label's pixels are opaque.
pub fn draw_labels(film: &mut Film, camera: &Camera, labels: &[Label]) {
    let font = font(film.width);
    let (cw, ch) = (font.character_size.width as i32, font.character_size.height as i32);
    let mut placed: Vec<[i32; 4]> = Vec::with_capacity(labels.len());
    for label in labels {
        let Some((u, v, depth)) = project(camera, label.at) else { continue };
        // The object's radius on the picture, in pixels.
        let radius = label.reach * camera.focal / depth / camera.x_max * f64::from(camera.width);
        let x = (u + radius.min(f64::from(camera.width)) + 4.0).round();
        let y = (f64::from(camera.height) - v).round();
        if !(x.abs() < 1e6 && y.abs() < 1e6) {
            continue;
        }
        let (x, y) = (x as i32, y as i32);
        let width = cw * label.text.chars().count() as i32;
        let free = |y: i32| {
            let b = [x, y - ch / 2, x + width, y + ch / 2];
            !placed.iter().any(|p| b[0] < p[2] && p[0] < b[2] && b[1] < p[3] && p[1] < b[3])
        };
        let shifts = (0..12).map(|k| if k % 2 == 0 { k / 2 * ch } else { -(k / 2 + 1) * ch });
        let y = shifts.map(|dy| y + dy).find(|&y| free(y)).unwrap_or(y);
        placed.push([x, y - ch / 2, x + width, y + ch / 2]);
        let at = Point::new(x, y);
        for (paint, offsets) in [([0.0; 3], &OUTLINE[..]), (label.colour, &[(0, 0)][..])] {
            let mut canvas = Canvas { film, paint };
            for &(dx, dy) in offsets {
                let style = MonoTextStyle::new(font, BinaryColor::On);
                let text = Text::with_baseline(&label.text, at + Point::new(dx, dy), style, Baseline::Middle);
                let Ok(_) = text.draw(&mut canvas);
            }
        }
    }
}

/// The eight neighbours a label's black outline is drawn at.
const OUTLINE: [(i32, i32); 8] = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)];
