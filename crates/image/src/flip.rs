//! NVIDIA's FLIP image-difference metric (LDR ꟻLIP, Andersson, Nilsson,
//! Akenine-Möller, Oskarsson, Åström & Fairchild 2020, "FLIP: A Difference
//! Evaluator for Alternating Images", HPG), through the `nv-flip` crate,
//! which compiles NVIDIA's own C++ implementation.
//!
//! FLIP models what a viewer flipping between the two images notices: both
//! are filtered by contrast-sensitivity functions for a viewing geometry of
//! `pixels_per_degree` pixels per degree of visual angle, colour differences
//! (HyAB in a Hunt-adjusted L\*a\*b\*) are combined with edge and point
//! feature differences, and each pixel gets an error in `[0, 1]`; the metric
//! is the mean over pixels. It is defined on LDR sRGB images, so the linear
//! renders are first encoded to 8-bit sRGB at exposure 1
//! ([`crate::to_srgb8`]: NaN to 0, clamped). The largest colour difference,
//! pure green against pure blue, is 1 by construction, which the tests check.
//!
//! **Masks.** FLIP filters the images, not the error, so a pixel left out
//! would still influence its neighbours. [`flip_error`] therefore replaces
//! every excluded pixel of the test image by the reference's (so the two
//! images agree there and the excluded pixel's own error cannot spread), then
//! averages the error map over the kept pixels only.

use nv_flip::{FlipImageRgb8, FlipPool, flip};

use crate::color::to_srgb8;
use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;
use crate::mask::PixelMask;
use crate::metrics::check_sizes;

/// The default viewing geometry: 67.0 pixels per degree, a 0.7 m wide
/// 3840-pixel monitor seen from 0.7 m (FLIP's default).
pub const DEFAULT_PIXELS_PER_DEGREE: f32 = nv_flip::DEFAULT_PIXELS_PER_DEGREE;

fn flip_image(pixels: &[[u8; 3]], width: usize, height: usize) -> FlipImageRgb8 {
    let bytes: Vec<u8> = pixels.iter().flatten().copied().collect();
    FlipImageRgb8::with_data(width as u32, height as u32, &bytes)
}

/// The per-pixel FLIP error map (row-major, each value in `[0, 1]`) of
/// `test` against `reference`, excluded pixels of `mask` first set to the
/// reference (see the module doc).
pub fn flip_error_map(
    test: &RgbImage,
    reference: &RgbImage,
    mask: Option<&PixelMask>,
    pixels_per_degree: f32,
) -> Result<Vec<f32>, ImageError> {
    check_sizes(test, reference)?;
    if let Some(m) = mask {
        m.check_fits(test)?;
    }
    if !(pixels_per_degree > 0.0 && pixels_per_degree.is_finite()) {
        return Err(ImageError::new(
            ErrorKind::InvalidArgument,
            format!("pixels per degree must be positive, got {pixels_per_degree}"),
        ));
    }
    let (w, h) = (test.width(), test.height());
    if w == 0 || h == 0 || w > u32::MAX as usize || h > u32::MAX as usize {
        return Err(ImageError::new(
            ErrorKind::InvalidArgument,
            format!("FLIP needs a non-empty image, got {w}x{h}"),
        ));
    }
    let ref8 = to_srgb8(reference, 1.0);
    let mut test8 = to_srgb8(test, 1.0);
    if let Some(m) = mask {
        for ((t, r), keep) in test8.iter_mut().zip(&ref8).zip(m.as_slice()) {
            if !keep {
                *t = *r;
            }
        }
    }
    let map = flip(
        flip_image(&ref8, w, h),
        flip_image(&test8, w, h),
        pixels_per_degree,
    );
    Ok(map.to_vec())
}

/// The mean FLIP error of `test` against `reference` over the pixels `mask`
/// keeps (every pixel for `None`); see the module doc.
pub fn flip_error(
    test: &RgbImage,
    reference: &RgbImage,
    mask: Option<&PixelMask>,
    pixels_per_degree: f32,
) -> Result<f64, ImageError> {
    let map = flip_error_map(test, reference, mask, pixels_per_degree)?;
    Ok(match mask {
        None => {
            let (w, h) = (test.width() as u32, test.height() as u32);
            f64::from(FlipPool::from_image(&nv_flip::FlipImageFloat::with_data(w, h, &map)).mean())
        }
        Some(m) => {
            let kept = map.iter().zip(m.as_slice()).filter(|(_, k)| **k);
            kept.map(|(v, _)| f64::from(*v)).sum::<f64>() / m.kept() as f64
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const PPD: f32 = DEFAULT_PIXELS_PER_DEGREE;

    fn gradient(w: usize, h: usize) -> RgbImage {
        RgbImage::from_fn(w, h, |x, y| {
            [
                x as f32 / w as f32,
                y as f32 / h as f32,
                0.3 + 0.2 * ((x + y) % 2) as f32,
            ]
        })
        .unwrap()
    }

    /// `image` plus a deterministic per-pixel noise of amplitude `a`.
    fn noisy(image: &RgbImage, a: f32) -> RgbImage {
        let mut s = 12_345u32;
        image.map(|p| {
            p.map(|v| {
                s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                (v + a * ((s >> 8) as f32 / (1 << 24) as f32 - 0.5)).max(0.0)
            })
        })
    }

    #[test]
    fn identical_images_have_zero_flip() {
        let g = gradient(32, 24);
        assert_eq!(flip_error(&g, &g, None, PPD).unwrap(), 0.0);
    }

    /// The paper's normalisation: green against blue is the largest colour
    /// difference and maps to exactly 1; flat images have no feature error.
    #[test]
    fn green_against_blue_is_one() {
        let green = RgbImage::filled(24, 24, [0.0, 1.0, 0.0]).unwrap();
        let blue = RgbImage::filled(24, 24, [0.0, 0.0, 1.0]).unwrap();
        let e = flip_error(&green, &blue, None, PPD).unwrap();
        assert!((e - 1.0).abs() < 1e-3, "{e}");
        let grey = RgbImage::filled(24, 24, [0.2; 3]).unwrap();
        let lighter = RgbImage::filled(24, 24, [0.25; 3]).unwrap();
        let small = flip_error(&grey, &lighter, None, PPD).unwrap();
        assert!(small > 0.0 && small < 0.2, "{small}");
    }

    #[test]
    fn more_noise_gives_more_flip() {
        let g = gradient(48, 48);
        let errors: Vec<f64> = [0.02, 0.1, 0.4]
            .iter()
            .map(|&a| flip_error(&noisy(&g, a), &g, None, PPD).unwrap())
            .collect();
        assert!(
            errors[0] > 0.0 && errors[0] < errors[1] && errors[1] < errors[2],
            "{errors:?}"
        );
        assert!(errors.iter().all(|e| *e <= 1.0));
    }

    #[test]
    fn excluded_pixels_do_not_influence_the_masked_flip() {
        let g = gradient(32, 32);
        let t = noisy(&g, 0.1);
        let mut excluded = vec![false; 32 * 32];
        excluded[16 * 32 + 16] = true;
        let mask = PixelMask::excluding(32, 32, &excluded, 3).unwrap();
        let before = flip_error(&t, &g, Some(&mask), PPD).unwrap();
        let mut bright = t.clone();
        for y in 13..=19 {
            for x in 13..=19 {
                bright.set(x, y, [50.0, 0.0, f32::NAN]).unwrap();
            }
        }
        assert_eq!(flip_error(&bright, &g, Some(&mask), PPD).unwrap(), before);
        assert!(
            flip_error(&bright, &g, None, PPD).unwrap() > flip_error(&t, &g, None, PPD).unwrap()
        );
    }

    #[test]
    fn bad_arguments_are_errors() {
        let g = gradient(8, 8);
        let other = gradient(8, 9);
        assert_eq!(
            flip_error(&g, &other, None, PPD).unwrap_err().kind(),
            ErrorKind::SizeMismatch
        );
        assert!(flip_error(&g, &g, None, 0.0).is_err());
        assert!(flip_error(&g, &g, None, f32::NAN).is_err());
    }
}
