//! Image utilities: crops, nearest-neighbour upscaling (for the experiment's
//! 4x crops) and simple statistics with a count of non-finite values.

use serde::{Deserialize, Serialize};

use crate::color::REC709_LUMINANCE;
use crate::error::{ErrorKind, ImageError};
use crate::image::{RgbImage, checked_pixel_count};

/// The `w x h` rectangle whose top-left pixel is `(x, y)`; an
/// [`ErrorKind::OutOfBounds`] error when it does not lie inside the image.
pub fn crop(
    image: &RgbImage,
    x: usize,
    y: usize,
    w: usize,
    h: usize,
) -> Result<RgbImage, ImageError> {
    checked_pixel_count(w, h)?;
    let inside = x.checked_add(w).is_some_and(|r| r <= image.width())
        && y.checked_add(h).is_some_and(|b| b <= image.height());
    if !inside {
        return Err(ImageError::new(
            ErrorKind::OutOfBounds,
            format!(
                "crop {w}x{h} at ({x}, {y}) outside a {}x{} image",
                image.width(),
                image.height()
            ),
        ));
    }
    let mut pixels = Vec::with_capacity(w * h);
    for row in y..y + h {
        let start = row * image.width() + x;
        pixels.extend_from_slice(&image.pixels()[start..start + w]);
    }
    RgbImage::from_pixels(w, h, pixels)
}

/// The image enlarged `factor` times in each direction, every pixel becoming
/// a `factor x factor` block.
pub fn upscale_nearest(image: &RgbImage, factor: usize) -> Result<RgbImage, ImageError> {
    if factor == 0 {
        return Err(ImageError::new(
            ErrorKind::InvalidArgument,
            "upscale factor 0",
        ));
    }
    let too_large = || {
        ImageError::new(
            ErrorKind::TooLarge,
            format!("upscale by {factor} overflows"),
        )
    };
    let w = image.width().checked_mul(factor).ok_or_else(too_large)?;
    let h = image.height().checked_mul(factor).ok_or_else(too_large)?;
    checked_pixel_count(w, h)?;
    let src = image.pixels();
    let sw = image.width();
    RgbImage::from_fn(w, h, |x, y| src[(y / factor) * sw + x / factor])
}

/// Summary statistics of an image.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ImageStats {
    /// Mean of each channel over the pixels whose three channels are finite.
    pub mean: [f64; 3],
    /// Rec.709 luminance of `mean`.
    pub mean_luminance: f64,
    /// Smallest finite value of each channel (+inf when none).
    pub min: [f32; 3],
    /// Largest finite value of each channel (-inf when none).
    pub max: [f32; 3],
    /// Number of NaN channel values.
    pub nan_count: usize,
    /// Number of infinite channel values.
    pub inf_count: usize,
    /// Number of negative finite channel values.
    pub negative_count: usize,
    /// Number of pixels whose three channels are finite (used for `mean`).
    pub finite_pixels: usize,
}

impl ImageStats {
    /// True when no channel value is NaN or infinite.
    pub fn all_finite(&self) -> bool {
        self.nan_count == 0 && self.inf_count == 0
    }
}

/// Statistics of an image: means over finite pixels, ranges, and counts of
/// NaN, infinite and negative values.
pub fn stats(image: &RgbImage) -> ImageStats {
    let mut sum = [0.0f64; 3];
    let mut s = ImageStats {
        mean: [0.0; 3],
        mean_luminance: 0.0,
        min: [f32::INFINITY; 3],
        max: [f32::NEG_INFINITY; 3],
        nan_count: 0,
        inf_count: 0,
        negative_count: 0,
        finite_pixels: 0,
    };
    for p in image.pixels() {
        for (c, &v) in p.iter().enumerate() {
            if v.is_nan() {
                s.nan_count += 1;
            } else if v.is_infinite() {
                s.inf_count += 1;
            } else {
                s.min[c] = s.min[c].min(v);
                s.max[c] = s.max[c].max(v);
                if v < 0.0 {
                    s.negative_count += 1;
                }
            }
        }
        if p.iter().all(|v| v.is_finite()) {
            s.finite_pixels += 1;
            for c in 0..3 {
                sum[c] += f64::from(p[c]);
            }
        }
    }
    if s.finite_pixels > 0 {
        s.mean = sum.map(|v| v / s.finite_pixels as f64);
    }
    s.mean_luminance = (0..3)
        .map(|c| f64::from(REC709_LUMINANCE[c]) * s.mean[c])
        .sum();
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp() -> RgbImage {
        RgbImage::from_fn(4, 3, |x, y| [x as f32, y as f32, (10 * y + x) as f32]).unwrap()
    }

    #[test]
    fn crop_takes_the_rectangle() {
        let c = crop(&ramp(), 1, 1, 2, 2).unwrap();
        assert_eq!(
            c.pixels(),
            &[
                [1.0, 1.0, 11.0],
                [2.0, 1.0, 12.0],
                [1.0, 2.0, 21.0],
                [2.0, 2.0, 22.0]
            ]
        );
        assert_eq!(crop(&ramp(), 0, 0, 4, 3).unwrap(), ramp());
        assert_eq!(
            crop(&ramp(), 3, 0, 2, 1).unwrap_err().kind(),
            ErrorKind::OutOfBounds
        );
        assert_eq!(
            crop(&ramp(), usize::MAX, 0, 2, 1).unwrap_err().kind(),
            ErrorKind::OutOfBounds
        );
        assert_eq!(
            crop(&ramp(), 0, 0, 0, 1).unwrap_err().kind(),
            ErrorKind::InvalidArgument
        );
    }

    #[test]
    fn upscale_repeats_blocks() {
        let up = upscale_nearest(&ramp(), 4).unwrap();
        assert_eq!((up.width(), up.height()), (16, 12));
        for y in 0..12 {
            for x in 0..16 {
                assert_eq!(up.get(x, y), ramp().get(x / 4, y / 4));
            }
        }
        assert!(upscale_nearest(&ramp(), 0).is_err());
        assert_eq!(
            upscale_nearest(&ramp(), usize::MAX).unwrap_err().kind(),
            ErrorKind::TooLarge
        );
    }

    #[test]
    fn stats_count_non_finite_and_average_the_rest() {
        let img = RgbImage::from_pixels(
            2,
            2,
            vec![
                [1.0, 2.0, 3.0],
                [3.0, 4.0, -5.0],
                [f32::NAN, 0.0, 0.0],
                [f32::INFINITY, 0.0, f32::NEG_INFINITY],
            ],
        )
        .unwrap();
        let s = stats(&img);
        assert_eq!(
            (s.nan_count, s.inf_count, s.negative_count, s.finite_pixels),
            (1, 2, 1, 2)
        );
        // Means over the two finite pixels: (1+3)/2, (2+4)/2, (3-5)/2.
        assert_eq!(s.mean, [2.0, 3.0, -1.0]);
        // 0.2126*2 + 0.7152*3 + 0.0722*(-1) = 0.4252 + 2.1456 - 0.0722 = 2.4986.
        assert!((s.mean_luminance - 2.4986).abs() < 1e-6);
        assert_eq!(s.min, [1.0, 0.0, -5.0]);
        assert_eq!(s.max, [3.0, 4.0, 3.0]);
        assert!(!s.all_finite());
        assert!(stats(&ramp()).all_finite());
    }
}
