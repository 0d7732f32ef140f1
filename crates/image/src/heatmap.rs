//! False-colour heatmaps of per-pixel values (errors) with a viridis-like
//! colormap.
//!
//! The colormap interpolates linearly, in sRGB-encoded space, between eleven
//! samples of matplotlib's viridis at t = 0, 0.1, ..., 1 (published values of
//! van der Walt and Smith's colormap, CC0), and returns the colour decoded to
//! linear RGB, so that writing the heatmap as an sRGB PNG shows the intended
//! colours. Dark purple is low, yellow is high; lightness rises monotonically.
//!
//! Normalisation (see [`Normalization`]) maps each value `v` to
//! `t = clamp(v / scale, 0, 1)`, where `scale` is the maximum finite value, a
//! fixed bound, or a quantile of the finite values. A scale of 0 (all values
//! zero) maps everything to `t = 0`. Non-finite values (NaN, ±inf) are drawn in
//! magenta, which the colormap never produces, so they stand out.

use crate::color::srgb_decode;
use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;
use crate::metrics::{PixelError, pixel_errors};

/// sRGB-encoded viridis at t = k / 10 (matplotlib's table, CC0).
const VIRIDIS: [[f32; 3]; 11] = [
    [0.267_004, 0.004_874, 0.329_415],
    [0.282_623, 0.140_926, 0.457_517],
    [0.253_935, 0.265_254, 0.529_983],
    [0.206_756, 0.371_758, 0.553_117],
    [0.163_625, 0.471_133, 0.558_148],
    [0.127_568, 0.566_949, 0.550_556],
    [0.134_692, 0.658_636, 0.517_649],
    [0.266_941, 0.748_751, 0.440_573],
    [0.477_504, 0.821_444, 0.318_195],
    [0.741_388, 0.873_449, 0.149_561],
    [0.993_248, 0.906_157, 0.143_936],
];

/// Linear-RGB colour drawn for non-finite values.
pub const NON_FINITE_COLOR: [f32; 3] = [1.0, 0.0, 1.0];

/// The viridis-like colour of `t` in `[0, 1]` (clamped; NaN gives 0), as
/// linear RGB.
pub fn viridis(t: f32) -> [f32; 3] {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * 10.0;
    let i = (x.floor() as usize).min(9);
    let f = x - i as f32;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    [0, 1, 2].map(|c| srgb_decode(a[c] + f * (b[c] - a[c])))
}

/// How values are scaled to the colormap's `[0, 1]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Normalization {
    /// Divide by the largest finite value.
    Max,
    /// Divide by this bound (must be finite and positive).
    Fixed(f32),
    /// Divide by the given quantile in `(0, 1]` of the finite values (for
    /// example 0.99, so a few fireflies do not wash out the map); the largest
    /// finite value when that quantile is 0.
    Quantile(f32),
}

/// The scale that `normalization` divides by, for these values.
pub fn normalization_scale(
    values: &[f32],
    normalization: Normalization,
) -> Result<f32, ImageError> {
    let invalid = |msg: String| ImageError::new(ErrorKind::InvalidArgument, msg);
    let max = values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(0.0f32, f32::max);
    match normalization {
        Normalization::Max => Ok(max),
        Normalization::Fixed(bound) => {
            if bound.is_finite() && bound > 0.0 {
                Ok(bound)
            } else {
                Err(invalid(format!(
                    "heatmap bound {bound} is not finite and positive"
                )))
            }
        }
        Normalization::Quantile(q) => {
            if !(q > 0.0 && q <= 1.0) {
                return Err(invalid(format!("heatmap quantile {q} is not in (0, 1]")));
            }
            let mut finite: Vec<f32> = values.iter().copied().filter(|v| v.is_finite()).collect();
            if finite.is_empty() {
                return Ok(0.0);
            }
            finite.sort_by(f32::total_cmp);
            let index = ((q * finite.len() as f32).ceil() as usize).clamp(1, finite.len()) - 1;
            let s = finite[index];
            Ok(if s > 0.0 { s } else { max })
        }
    }
}

/// A false-colour image of `values` (row-major, top row first) of the given
/// size, normalised as documented in the module.
pub fn heatmap(
    values: &[f32],
    width: usize,
    height: usize,
    normalization: Normalization,
) -> Result<RgbImage, ImageError> {
    let scale = normalization_scale(values, normalization)?;
    let pixels = values
        .iter()
        .map(|&v| {
            if !v.is_finite() {
                NON_FINITE_COLOR
            } else if scale > 0.0 {
                viridis(v / scale)
            } else {
                viridis(0.0)
            }
        })
        .collect();
    RgbImage::from_pixels(width, height, pixels)
}

/// The heatmap of the per-pixel error of `test` against `reference` (the
/// channel mean of `kind`, see [`pixel_errors`]).
pub fn error_heatmap(
    test: &RgbImage,
    reference: &RgbImage,
    kind: PixelError,
    normalization: Normalization,
) -> Result<RgbImage, ImageError> {
    let values = pixel_errors(test, reference, kind)?;
    heatmap(&values, test.width(), test.height(), normalization)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::{luminance, srgb_encode};

    #[test]
    fn endpoints_and_samples_are_the_table() {
        for (k, sample) in VIRIDIS.iter().enumerate() {
            let c = viridis(k as f32 / 10.0);
            for ch in 0..3 {
                assert!((srgb_encode(c[ch]) - sample[ch]).abs() < 1e-5, "k = {k}");
            }
        }
        assert_eq!(viridis(-3.0), viridis(0.0));
        assert_eq!(viridis(7.0), viridis(1.0));
        assert_eq!(viridis(f32::NAN), viridis(0.0));
    }

    #[test]
    fn lightness_increases_monotonically() {
        let mut last = -1.0;
        for i in 0..=1000 {
            let y = luminance(viridis(i as f32 / 1000.0));
            assert!(
                y > last,
                "luminance not increasing at t = {}",
                i as f32 / 1000.0
            );
            last = y;
        }
    }

    #[test]
    fn normalisations() {
        let v = [0.0, 1.0, 2.0, 4.0, f32::NAN, f32::INFINITY];
        assert_eq!(normalization_scale(&v, Normalization::Max).unwrap(), 4.0);
        assert_eq!(
            normalization_scale(&v, Normalization::Fixed(8.0)).unwrap(),
            8.0
        );
        // Finite values sorted: 0, 1, 2, 4; the 0.5 quantile is the 2nd (ceil(0.5 * 4) = 2).
        assert_eq!(
            normalization_scale(&v, Normalization::Quantile(0.5)).unwrap(),
            1.0
        );
        assert!(normalization_scale(&v, Normalization::Fixed(0.0)).is_err());
        assert!(normalization_scale(&v, Normalization::Quantile(1.5)).is_err());
        let img = heatmap(&v, 3, 2, Normalization::Max).unwrap();
        assert_eq!(img.get(0, 0), Some(viridis(0.0)));
        assert_eq!(img.get(2, 0), Some(viridis(0.5)));
        assert_eq!(img.get(0, 1), Some(viridis(1.0)));
        assert_eq!(img.get(1, 1), Some(NON_FINITE_COLOR));
        assert_eq!(img.get(2, 1), Some(NON_FINITE_COLOR));
        assert!(heatmap(&v, 2, 2, Normalization::Max).is_err());
    }
}
