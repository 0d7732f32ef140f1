//! Pixel masks and the error metrics over the kept pixels only.
//!
//! A [`PixelMask`] says which pixels an error metric counts. The experiment
//! uses it to leave out **directly visible emitters**: the renderer reports,
//! per pixel, whether any camera ray through the pixel first hits an emitter
//! (`lowdisc_render::first_hit::emitter_coverage`), and
//! [`PixelMask::excluding`] drops those pixels plus every pixel within a
//! border of `b` pixels of one (Chebyshev distance, i.e. a `(2b+1)²` square
//! around each). The emitter's own pixels are bright and nearly noiseless;
//! its outline pixels are partly covered, and a handful of them carry most of
//! the squared error of a whole image, so that without the mask the metric
//! measures how each sampler stratifies a few outline pixels rather than the
//! lighting. The border also covers a pixel filter wider than one pixel
//! (samples of a pixel may land up to the filter radius away) and the
//! emitter's reflection in nearby glossy surfaces; [`DEFAULT_EMITTER_BORDER`]
//! (3 pixels) keeps about 98 % of a 128x128 Cornell box.
//!
//! [`masked_error_metrics`] are the metrics of [`crate::metrics`] with the
//! sums and the count `N` over the kept pixels only (`N = 3 · kept`).

use crate::color::srgb8_encode;
use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;
use crate::metrics::{ErrorMetrics, RELMSE_EPSILON, accumulate, channel_pairs, check_sizes};

/// The border, in pixels, kept clear around directly visible emitters.
pub const DEFAULT_EMITTER_BORDER: u32 = 3;

/// Which pixels of a `width x height` image count (row-major, top row first).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PixelMask {
    width: usize,
    height: usize,
    keep: Vec<bool>,
}

impl PixelMask {
    /// The mask keeping every pixel.
    pub fn all(width: usize, height: usize) -> PixelMask {
        PixelMask {
            width,
            height,
            keep: vec![true; width * height],
        }
    }

    /// The mask keeping the pixels where `keep` is true; an error unless
    /// `keep` has `width * height` entries.
    pub fn from_keep(
        width: usize,
        height: usize,
        keep: Vec<bool>,
    ) -> Result<PixelMask, ImageError> {
        if Some(keep.len()) != width.checked_mul(height) {
            return Err(ImageError::new(
                ErrorKind::SizeMismatch,
                format!(
                    "mask has {} entries for a {width}x{height} image",
                    keep.len()
                ),
            ));
        }
        Ok(PixelMask {
            width,
            height,
            keep,
        })
    }

    /// The mask dropping every pixel where `excluded` is true and every
    /// pixel within `border` pixels (Chebyshev distance) of one.
    pub fn excluding(
        width: usize,
        height: usize,
        excluded: &[bool],
        border: u32,
    ) -> Result<PixelMask, ImageError> {
        let mut mask = PixelMask::from_keep(width, height, excluded.iter().map(|e| !e).collect())?;
        let b = border as usize;
        // Separable dilation of the excluded set: along rows, then columns.
        let dilate = |get: &dyn Fn(usize) -> bool, len: usize| -> Vec<bool> {
            (0..len)
                .map(|i| (i.saturating_sub(b)..=(i + b).min(len - 1)).any(get))
                .collect()
        };
        if width == 0 || height == 0 {
            return Ok(mask);
        }
        let mut rows = vec![false; width * height];
        for y in 0..height {
            let row = dilate(&|x| excluded[y * width + x], width);
            rows[y * width..(y + 1) * width].copy_from_slice(&row);
        }
        for x in 0..width {
            let col = dilate(&|y| rows[y * width + x], height);
            for (y, e) in col.into_iter().enumerate() {
                mask.keep[y * width + x] = !e;
            }
        }
        Ok(mask)
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Whether pixel `(x, y)` counts (false outside the image).
    pub fn keeps(&self, x: usize, y: usize) -> bool {
        x < self.width && y < self.height && self.keep[y * self.width + x]
    }

    /// The per-pixel flags, row-major.
    pub fn as_slice(&self) -> &[bool] {
        &self.keep
    }

    /// Number of kept pixels.
    pub fn kept(&self) -> usize {
        self.keep.iter().filter(|k| **k).count()
    }

    /// Fraction of the pixels kept (0 for an empty image).
    pub fn kept_fraction(&self) -> f64 {
        self.kept() as f64 / self.keep.len().max(1) as f64
    }

    /// An error unless the mask fits `image` and keeps at least one pixel.
    pub(crate) fn check_fits(&self, image: &RgbImage) -> Result<(), ImageError> {
        if self.width != image.width() || self.height != image.height() {
            return Err(ImageError::new(
                ErrorKind::SizeMismatch,
                format!(
                    "mask is {}x{}, image is {}x{}",
                    self.width,
                    self.height,
                    image.width(),
                    image.height()
                ),
            ));
        }
        if self.kept() == 0 {
            return Err(ImageError::new(
                ErrorKind::InvalidArgument,
                "the mask keeps no pixel",
            ));
        }
        Ok(())
    }
}

/// The metrics of [`crate::error_metrics`] over the pixels `mask` keeps; an
/// error if the sizes differ or the mask keeps nothing.
pub fn masked_error_metrics(
    test: &RgbImage,
    reference: &RgbImage,
    mask: &PixelMask,
) -> Result<ErrorMetrics, ImageError> {
    check_sizes(test, reference)?;
    mask.check_fits(test)?;
    let kept = |i: usize| mask.keep[i / 3];
    let linear = channel_pairs(test.pixels(), reference.pixels())
        .enumerate()
        .filter(|(i, _)| kept(*i))
        .map(|(_, (x, r))| (f64::from(x), f64::from(r)));
    let srgb8 = channel_pairs(test.pixels(), reference.pixels())
        .enumerate()
        .filter(|(i, _)| kept(*i))
        .map(|(_, (x, r))| (f64::from(srgb8_encode(x)), f64::from(srgb8_encode(r))));
    Ok(ErrorMetrics {
        linear: accumulate(linear, RELMSE_EPSILON),
        srgb8: accumulate(srgb8, RELMSE_EPSILON * 255.0 * 255.0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::error_metrics;

    fn noisy(w: usize, h: usize, salt: u32) -> RgbImage {
        RgbImage::from_fn(w, h, |x, y| {
            let v = ((x * 7 + y * 13) as u32 ^ salt) % 17;
            [0.2 + v as f32 * 0.01, 0.5, 0.1 * (x % 3) as f32]
        })
        .unwrap()
    }

    #[test]
    fn full_mask_equals_the_unmasked_metrics() {
        let (t, r) = (noisy(9, 7, 5), noisy(9, 7, 11));
        let m = masked_error_metrics(&t, &r, &PixelMask::all(9, 7)).unwrap();
        assert_eq!(m, error_metrics(&t, &r).unwrap());
    }

    #[test]
    fn excluded_pixels_do_not_influence_the_metrics() {
        let (t, r) = (noisy(8, 8, 1), noisy(8, 8, 2));
        let mut excluded = vec![false; 64];
        excluded[3 * 8 + 4] = true;
        let mask = PixelMask::excluding(8, 8, &excluded, 1).unwrap();
        let before = masked_error_metrics(&t, &r, &mask).unwrap();
        let mut t2 = t.clone();
        for (x, y) in [(4, 3), (3, 2), (5, 4)] {
            t2.set(x, y, [1e6, -5.0, f32::NAN]).unwrap();
        }
        assert_eq!(masked_error_metrics(&t2, &r, &mask).unwrap(), before);
        // A kept pixel does change them.
        t2.set(0, 0, [9.0; 3]).unwrap();
        assert_ne!(masked_error_metrics(&t2, &r, &mask).unwrap(), before);
    }

    #[test]
    fn masked_mse_is_the_mean_over_kept_pixels() {
        // Error 1 on the left half, 3 on the right half; keep only the left.
        let r = RgbImage::filled(4, 2, [0.0; 3]).unwrap();
        let t = RgbImage::from_fn(4, 2, |x, _| [if x < 2 { 1.0 } else { 3.0 }; 3]).unwrap();
        let keep = (0..8).map(|i| i % 4 < 2).collect();
        let mask = PixelMask::from_keep(4, 2, keep).unwrap();
        let m = masked_error_metrics(&t, &r, &mask).unwrap();
        assert_eq!(m.linear.mse, 1.0);
        assert_eq!(error_metrics(&t, &r).unwrap().linear.mse, 5.0);
    }

    #[test]
    fn border_is_a_chebyshev_square() {
        let mut excluded = vec![false; 49];
        excluded[3 * 7 + 3] = true;
        let mask = PixelMask::excluding(7, 7, &excluded, 2).unwrap();
        for y in 0..7 {
            for x in 0..7 {
                let inside = (1..=5).contains(&x) && (1..=5).contains(&y);
                assert_eq!(mask.keeps(x, y), !inside, "({x}, {y})");
            }
        }
        assert_eq!(mask.kept(), 49 - 25);
        // Border 0 drops the pixel itself only; the image edge clips the square.
        assert_eq!(PixelMask::excluding(7, 7, &excluded, 0).unwrap().kept(), 48);
        let mut corner = vec![false; 49];
        corner[0] = true;
        assert_eq!(PixelMask::excluding(7, 7, &corner, 1).unwrap().kept(), 45);
    }

    #[test]
    fn bad_masks_are_errors() {
        assert!(PixelMask::from_keep(3, 3, vec![true; 8]).is_err());
        let img = RgbImage::filled(3, 3, [0.5; 3]).unwrap();
        let none = PixelMask::from_keep(3, 3, vec![false; 9]).unwrap();
        let e = masked_error_metrics(&img, &img, &none).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidArgument);
        let small = PixelMask::all(2, 3);
        assert_eq!(
            masked_error_metrics(&img, &img, &small).unwrap_err().kind(),
            ErrorKind::SizeMismatch
        );
    }
}
