//! [`RgbImage`]: a linear-RGB `f32` image, row-major with the top row first.

use crate::error::{ErrorKind, ImageError};

/// The largest number of pixels an image may have: 2^28 (268,435,456), about
/// 3 GiB of `f32` RGB. Readers refuse larger headers before allocating, so a
/// corrupt or hostile size field can never trigger a huge allocation.
pub const MAX_PIXELS: usize = 1 << 28;

/// Checks that `width x height` is a non-empty size of at most [`MAX_PIXELS`]
/// pixels and returns the pixel count.
pub fn checked_pixel_count(width: usize, height: usize) -> Result<usize, ImageError> {
    if width == 0 || height == 0 {
        return Err(ImageError::new(
            ErrorKind::InvalidArgument,
            format!("image size {width}x{height} is empty"),
        ));
    }
    match width.checked_mul(height) {
        Some(n) if n <= MAX_PIXELS => Ok(n),
        _ => Err(ImageError::new(
            ErrorKind::TooLarge,
            format!("image size {width}x{height} exceeds the limit of {MAX_PIXELS} pixels"),
        )),
    }
}

/// A linear-RGB image of `f32` values: `width x height` pixels stored row-major,
/// top row first, each pixel `[r, g, b]`. Width and height are at least 1 and
/// their product at most [`MAX_PIXELS`].
#[derive(Debug, Clone, PartialEq)]
pub struct RgbImage {
    width: usize,
    height: usize,
    pixels: Vec<[f32; 3]>,
}

impl RgbImage {
    /// A black image of the given size.
    pub fn new(width: usize, height: usize) -> Result<Self, ImageError> {
        Self::filled(width, height, [0.0; 3])
    }

    /// An image of the given size with every pixel set to `value`.
    pub fn filled(width: usize, height: usize, value: [f32; 3]) -> Result<Self, ImageError> {
        let n = checked_pixel_count(width, height)?;
        Ok(RgbImage {
            width,
            height,
            pixels: vec![value; n],
        })
    }

    /// An image from row-major pixels (top row first); the length must be
    /// `width * height`.
    pub fn from_pixels(
        width: usize,
        height: usize,
        pixels: Vec<[f32; 3]>,
    ) -> Result<Self, ImageError> {
        let n = checked_pixel_count(width, height)?;
        if pixels.len() != n {
            return Err(ImageError::new(
                ErrorKind::SizeMismatch,
                format!(
                    "{} pixels given for a {width}x{height} image ({n} pixels)",
                    pixels.len()
                ),
            ));
        }
        Ok(RgbImage {
            width,
            height,
            pixels,
        })
    }

    /// An image whose pixel `(x, y)` is `f(x, y)`.
    pub fn from_fn(
        width: usize,
        height: usize,
        mut f: impl FnMut(usize, usize) -> [f32; 3],
    ) -> Result<Self, ImageError> {
        let n = checked_pixel_count(width, height)?;
        let mut pixels = Vec::with_capacity(n);
        for y in 0..height {
            for x in 0..width {
                pixels.push(f(x, y));
            }
        }
        Ok(RgbImage {
            width,
            height,
            pixels,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Number of pixels, `width * height`.
    pub fn pixel_count(&self) -> usize {
        self.pixels.len()
    }

    /// True when `other` has the same width and height.
    pub fn same_size(&self, other: &RgbImage) -> bool {
        self.width == other.width && self.height == other.height
    }

    /// The pixel at column `x`, row `y` (row 0 is the top), or `None` outside.
    pub fn get(&self, x: usize, y: usize) -> Option<[f32; 3]> {
        self.index(x, y).map(|i| self.pixels[i])
    }

    /// Sets the pixel at column `x`, row `y`; an [`ErrorKind::OutOfBounds`]
    /// error outside the image.
    pub fn set(&mut self, x: usize, y: usize, value: [f32; 3]) -> Result<(), ImageError> {
        match self.index(x, y) {
            Some(i) => {
                self.pixels[i] = value;
                Ok(())
            }
            None => Err(ImageError::new(
                ErrorKind::OutOfBounds,
                format!(
                    "pixel ({x}, {y}) outside a {}x{} image",
                    self.width, self.height
                ),
            )),
        }
    }

    /// All pixels, row-major, top row first.
    pub fn pixels(&self) -> &[[f32; 3]] {
        &self.pixels
    }

    /// All pixels, mutable, row-major, top row first.
    pub fn pixels_mut(&mut self) -> &mut [[f32; 3]] {
        &mut self.pixels
    }

    /// Row `y` (0 is the top), or `None` outside.
    pub fn row(&self, y: usize) -> Option<&[[f32; 3]]> {
        (y < self.height).then(|| &self.pixels[y * self.width..(y + 1) * self.width])
    }

    /// The pixels, consuming the image.
    pub fn into_pixels(self) -> Vec<[f32; 3]> {
        self.pixels
    }

    /// A copy with every channel multiplied by `factor`.
    #[must_use]
    pub fn scaled(&self, factor: f32) -> RgbImage {
        let pixels = self
            .pixels
            .iter()
            .map(|p| [p[0] * factor, p[1] * factor, p[2] * factor])
            .collect();
        RgbImage {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// A copy with `f` applied to every pixel.
    #[must_use]
    pub fn map(&self, f: impl FnMut(&[f32; 3]) -> [f32; 3]) -> RgbImage {
        RgbImage {
            width: self.width,
            height: self.height,
            pixels: self.pixels.iter().map(f).collect(),
        }
    }

    fn index(&self, x: usize, y: usize) -> Option<usize> {
        (x < self.width && y < self.height).then(|| y * self.width + x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn get_set_are_row_major_top_first() {
        let mut img = RgbImage::new(3, 2).unwrap();
        img.set(2, 1, [1.0, 2.0, 3.0]).unwrap();
        assert_eq!(img.pixels()[5], [1.0, 2.0, 3.0]);
        assert_eq!(img.get(2, 1), Some([1.0, 2.0, 3.0]));
        assert_eq!(img.get(3, 0), None);
        assert_eq!(img.get(0, 2), None);
        assert_eq!(
            img.set(3, 0, [0.0; 3]).unwrap_err().kind(),
            ErrorKind::OutOfBounds
        );
        assert_eq!(img.row(1).unwrap()[2], [1.0, 2.0, 3.0]);
        assert!(img.row(2).is_none());
    }

    #[test]
    fn sizes_are_guarded() {
        assert_eq!(
            RgbImage::new(0, 5).unwrap_err().kind(),
            ErrorKind::InvalidArgument
        );
        assert_eq!(
            RgbImage::new(1 << 15, 1 << 14).unwrap_err().kind(),
            ErrorKind::TooLarge
        );
        assert_eq!(
            RgbImage::new(usize::MAX, 2).unwrap_err().kind(),
            ErrorKind::TooLarge
        );
        assert!(checked_pixel_count(1 << 14, 1 << 14).is_ok());
        let err = RgbImage::from_pixels(2, 2, vec![[0.0; 3]; 3]).unwrap_err();
        assert_eq!(err.kind(), ErrorKind::SizeMismatch);
    }

    #[test]
    fn from_fn_visits_in_row_major_order() {
        let img = RgbImage::from_fn(2, 2, |x, y| [x as f32, y as f32, 0.0]).unwrap();
        assert_eq!(
            img.pixels(),
            &[
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [1.0, 1.0, 0.0]
            ]
        );
        assert_eq!(img.scaled(2.0).get(1, 1), Some([2.0, 2.0, 0.0]));
    }
}
