//! The Nao's camera: table coordinates (inches) to image pixels.
//!
//! Section 4.3.2: "the Nao's camera was directed straight at the center of
//! the table. The field of view covered the majority of the table with small
//! portions on the left and right being out of sight", the image is 320 by
//! 240 pixels with "the top left corner to be (0, 0)", and the table is
//! 25" × 19". The thesis gives no strip width; this model (a decision,
//! listed in the report) sees the table's whole depth and the middle 23" of
//! its width, leaving a 1" strip out of view on each side:
//!
//! `px = (X − 1) · 320 / 23`, `py = Y · 240 / 19`,
//!
//! with table `X` from the left wall and `Y` from the far wall (the Nao sits
//! at the near edge, `Y = 19`, so the bottom of the image is in front of it).
//! A pixel is the integer part; a bug whose centre maps outside `[0, 320) ×
//! [0, 240)` is not seen.

use serde::{Deserialize, Serialize};

/// Image width in pixels.
pub const IMAGE_WIDTH: u32 = 320;
/// Image height in pixels.
pub const IMAGE_HEIGHT: u32 = 240;
/// Every pixel is a state: 76,800.
pub const NUM_STATES: u32 = IMAGE_WIDTH * IMAGE_HEIGHT;

/// A pixel of the image, `(x, y)` with `(0, 0)` top left.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Pixel {
    pub x: u16,
    pub y: u16,
}

impl Pixel {
    /// The pixel `(x, y)`.
    pub const fn new(x: u16, y: u16) -> Pixel {
        Pixel { x, y }
    }

    /// The state when no bug is seen: `(0, 0)`.
    pub const NONE_SEEN: Pixel = Pixel::new(0, 0);

    /// As floats, for distances and the classifiers.
    pub fn as_f64(self) -> [f64; 2] {
        [f64::from(self.x), f64::from(self.y)]
    }
}

/// The camera's view of the table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    /// Left edge of the view on the table, inches from the left wall.
    pub view_x0: f64,
    /// Right edge of the view, inches.
    pub view_x1: f64,
    /// Far edge of the view, inches from the far wall.
    pub view_y0: f64,
    /// Near edge of the view, inches.
    pub view_y1: f64,
}

impl Camera {
    /// The decision above: 1" strips out of view left and right, the whole depth in view.
    pub const fn thesis() -> Camera {
        Camera { view_x0: 1.0, view_x1: 24.0, view_y0: 0.0, view_y1: 19.0 }
    }

    /// Pixels per inch across.
    pub fn px_per_inch_x(&self) -> f64 {
        f64::from(IMAGE_WIDTH) / (self.view_x1 - self.view_x0)
    }

    /// Pixels per inch in depth.
    pub fn px_per_inch_y(&self) -> f64 {
        f64::from(IMAGE_HEIGHT) / (self.view_y1 - self.view_y0)
    }

    /// Continuous image coordinates of a table point (may lie outside the image).
    pub fn project(&self, x: f64, y: f64) -> (f64, f64) {
        ((x - self.view_x0) * self.px_per_inch_x(), (y - self.view_y0) * self.px_per_inch_y())
    }

    /// The table point at continuous image coordinates.
    pub fn unproject(&self, px: f64, py: f64) -> (f64, f64) {
        (self.view_x0 + px / self.px_per_inch_x(), self.view_y0 + py / self.px_per_inch_y())
    }

    /// The pixel a table point falls in, or `None` outside the view.
    pub fn pixel(&self, x: f64, y: f64) -> Option<Pixel> {
        let (px, py) = self.project(x, y);
        if px >= 0.0 && py >= 0.0 && px < f64::from(IMAGE_WIDTH) && py < f64::from(IMAGE_HEIGHT) {
            Some(Pixel::new(px as u16, py as u16))
        } else {
            None
        }
    }

    /// The table point at the centre of a pixel.
    pub fn pixel_centre(&self, p: Pixel) -> (f64, f64) {
        self.unproject(f64::from(p.x) + 0.5, f64::from(p.y) + 0.5)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn corners_and_strips() {
        let c = Camera::thesis();
        assert_eq!(c.pixel(1.0, 0.0), Some(Pixel::new(0, 0)));
        assert_eq!(c.pixel(23.999, 18.999), Some(Pixel::new(319, 239)));
        // The 1" strips at both sides are out of view, the whole depth is in view.
        assert_eq!(c.pixel(0.5, 10.0), None);
        assert_eq!(c.pixel(24.5, 10.0), None);
        assert!(c.pixel(12.5, 0.01).is_some() && c.pixel(12.5, 18.99).is_some());
        // The table's centre is the image's centre.
        assert_eq!(c.pixel(12.5, 9.5), Some(Pixel::new(160, 120)));
        assert!((c.px_per_inch_x() - 320.0 / 23.0).abs() < 1e-12);
        assert!((c.px_per_inch_y() - 240.0 / 19.0).abs() < 1e-12);
    }

    proptest! {
        #[test]
        fn pixel_centres_map_back_to_their_pixel(x in 0u16..320, y in 0u16..240) {
            let c = Camera::thesis();
            let (tx, ty) = c.pixel_centre(Pixel::new(x, y));
            prop_assert_eq!(c.pixel(tx, ty), Some(Pixel::new(x, y)));
            let (px, py) = c.project(tx, ty);
            prop_assert!((px - f64::from(x) - 0.5).abs() < 1e-9 && (py - f64::from(y) - 0.5).abs() < 1e-9);
        }
    }
}
