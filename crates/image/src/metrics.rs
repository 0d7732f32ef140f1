//! Error metrics of a test image against a reference, for the experiment.
//!
//! Every metric averages over all pixels and all three channels
//! (`N = 3 * width * height` terms), accumulating in `f64`:
//!
//! - `mse    = Σ (x - r)² / N`
//! - `relmse = Σ (x - r)² / (r² + ε) / N` with [`RELMSE_EPSILON`] `ε = 0.01`,
//!   the relative MSE of Rousselle et al. and of pbrt/Mitsuba-style
//!   comparisons (ε keeps black reference pixels from dominating)
//! - `rmse   = sqrt(mse)`
//! - `mae    = Σ |x - r| / N`
//!
//! "Linear" metrics use the images' linear radiance as is; non-finite test
//! values make them non-finite (check with [`crate::stats`] first). "sRGB8"
//! metrics use the 8-bit sRGB codes 0..=255 of both images at exposure 1
//! (NaN to 0, clamped, rounded: [`crate::srgb8_encode`]); MSE, RMSE and MAE are
//! in code units, and relMSE divides codes by 255 first so that ε applies on
//! the same 0..1 scale as for linear values, i.e.
//! `(x - r)² / (r² + ε · 255²)` in codes.

use serde::{Deserialize, Serialize};

use crate::color::srgb8_encode;
use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;

/// The ε in the denominator of relMSE, `(x - r)² / (r² + ε)`.
pub const RELMSE_EPSILON: f64 = 1e-2;

/// MSE, relMSE, RMSE and MAE of one comparison.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ErrorStats {
    /// Mean squared error.
    pub mse: f64,
    /// Mean relative squared error, `(x - r)² / (r² + ε)`.
    pub relmse: f64,
    /// Root mean squared error, `sqrt(mse)`.
    pub rmse: f64,
    /// Mean absolute error.
    pub mae: f64,
}

/// The metrics on linear radiance and on 8-bit sRGB.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ErrorMetrics {
    /// On linear radiance values.
    pub linear: ErrorStats,
    /// On 8-bit sRGB codes (0..=255, exposure 1).
    pub srgb8: ErrorStats,
}

pub(crate) fn check_sizes(test: &RgbImage, reference: &RgbImage) -> Result<(), ImageError> {
    if test.same_size(reference) {
        Ok(())
    } else {
        Err(ImageError::new(
            ErrorKind::SizeMismatch,
            format!(
                "test image is {}x{}, reference is {}x{}",
                test.width(),
                test.height(),
                reference.width(),
                reference.height()
            ),
        ))
    }
}

/// Accumulates the four metrics over (test, reference) value pairs.
pub(crate) fn accumulate(pairs: impl Iterator<Item = (f64, f64)>, epsilon: f64) -> ErrorStats {
    let (mut se, mut rel, mut ae, mut n) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    for (x, r) in pairs {
        let d = x - r;
        se += d * d;
        rel += d * d / (r * r + epsilon);
        ae += d.abs();
        n += 1;
    }
    let n = n.max(1) as f64;
    let mse = se / n;
    ErrorStats {
        mse,
        relmse: rel / n,
        rmse: mse.sqrt(),
        mae: ae / n,
    }
}

pub(crate) fn channel_pairs<'a, T: Copy + 'a>(
    test: &'a [[T; 3]],
    reference: &'a [[T; 3]],
) -> impl Iterator<Item = (T, T)> + 'a {
    test.iter()
        .zip(reference)
        .flat_map(|(t, r)| (0..3).map(move |c| (t[c], r[c])))
}

/// The metrics on linear radiance.
pub fn linear_errors(test: &RgbImage, reference: &RgbImage) -> Result<ErrorStats, ImageError> {
    check_sizes(test, reference)?;
    let pairs =
        channel_pairs(test.pixels(), reference.pixels()).map(|(x, r)| (f64::from(x), f64::from(r)));
    Ok(accumulate(pairs, RELMSE_EPSILON))
}

/// The metrics on 8-bit sRGB codes at exposure 1 (see the module docs).
pub fn srgb8_errors(test: &RgbImage, reference: &RgbImage) -> Result<ErrorStats, ImageError> {
    check_sizes(test, reference)?;
    let pairs = channel_pairs(test.pixels(), reference.pixels())
        .map(|(x, r)| (f64::from(srgb8_encode(x)), f64::from(srgb8_encode(r))));
    Ok(accumulate(pairs, RELMSE_EPSILON * 255.0 * 255.0))
}

/// Both sets of metrics; an [`ErrorKind::SizeMismatch`] error when the sizes differ.
pub fn error_metrics(test: &RgbImage, reference: &RgbImage) -> Result<ErrorMetrics, ImageError> {
    Ok(ErrorMetrics {
        linear: linear_errors(test, reference)?,
        srgb8: srgb8_errors(test, reference)?,
    })
}

/// A per-value error, for error images and heatmaps (on linear values).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PixelError {
    /// `(x - r)²`.
    Squared,
    /// `(x - r)² / (r² + ε)` with [`RELMSE_EPSILON`].
    #[default]
    RelativeSquared,
    /// `|x - r|`.
    Absolute,
}

impl PixelError {
    /// The error of one test value `x` against the reference value `r`.
    pub fn eval(self, x: f32, r: f32) -> f32 {
        let (x, r) = (f64::from(x), f64::from(r));
        let d = x - r;
        let e = match self {
            PixelError::Squared => d * d,
            PixelError::RelativeSquared => d * d / (r * r + RELMSE_EPSILON),
            PixelError::Absolute => d.abs(),
        };
        e as f32
    }
}

/// The per-channel error image: channel `c` of pixel `p` is the error of the
/// test value against the reference value.
pub fn error_image(
    test: &RgbImage,
    reference: &RgbImage,
    kind: PixelError,
) -> Result<RgbImage, ImageError> {
    check_sizes(test, reference)?;
    let pixels = test
        .pixels()
        .iter()
        .zip(reference.pixels())
        .map(|(t, r)| [0, 1, 2].map(|c| kind.eval(t[c], r[c])))
        .collect();
    RgbImage::from_pixels(test.width(), test.height(), pixels)
}

/// The per-pixel error, averaged over the three channels, row-major top row
/// first; the mean of these values is the matching metric (MSE, relMSE, MAE).
pub fn pixel_errors(
    test: &RgbImage,
    reference: &RgbImage,
    kind: PixelError,
) -> Result<Vec<f32>, ImageError> {
    check_sizes(test, reference)?;
    Ok(test
        .pixels()
        .iter()
        .zip(reference.pixels())
        .map(|(t, r)| {
            let sum: f64 = (0..3).map(|c| f64::from(kind.eval(t[c], r[c]))).sum();
            (sum / 3.0) as f32
        })
        .collect())
}
