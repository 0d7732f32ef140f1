//! The experiment's measures on image arrays: the error metrics of
//! `lowdisc-image` (MSE, relMSE, RMSE, MAE over all pixels or a mask's, the
//! blurred perceptual MSE, FLIP, per-pixel error images) and the paired-seed
//! ratio of `lowdisc-experiment` with its 95 % interval. Images arrive as
//! `height * width * 3` float32 values, row-major, top row first.

use lowdisc_experiment::stats::paired_ratio;
use lowdisc_image::metrics::linear_errors;
use lowdisc_image::{
    ErrorStats, PixelError, PixelMask, RgbImage, blurred_mse, error_image, flip_error,
    masked_error_metrics,
};

use super::{EngineError, Result};

/// An image's values and its `(height, width)`.
#[derive(Debug, Clone, Copy)]
pub struct ImageArg<'a> {
    /// `height * width * 3` values.
    pub values: &'a [f32],
    /// Rows.
    pub height: usize,
    /// Columns.
    pub width: usize,
}

impl ImageArg<'_> {
    /// The image.
    fn image(&self) -> Result<RgbImage> {
        if self.values.len() != self.height * self.width * 3 {
            return Err(EngineError::value(format!(
                "an image of {}x{} pixels needs {} values, got {}",
                self.width,
                self.height,
                self.height * self.width * 3,
                self.values.len()
            )));
        }
        let pixels = self
            .values
            .chunks_exact(3)
            .map(|p| [p[0], p[1], p[2]])
            .collect();
        RgbImage::from_pixels(self.width, self.height, pixels).map_err(image_error)
    }
}

/// The test image, the reference and the mask (one flag per pixel, kept
/// where true), checked.
fn inputs(
    test: ImageArg<'_>,
    reference: ImageArg<'_>,
    mask: Option<&[bool]>,
) -> Result<(RgbImage, RgbImage, Option<PixelMask>)> {
    let (t, r) = (test.image()?, reference.image()?);
    if !t.same_size(&r) {
        return Err(EngineError::value(format!(
            "image is {}x{} pixels, reference {}x{}",
            t.width(),
            t.height(),
            r.width(),
            r.height()
        )));
    }
    let mask = mask
        .map(|m| PixelMask::from_keep(t.width(), t.height(), m.to_vec()))
        .transpose()
        .map_err(image_error)?;
    Ok((t, r, mask))
}

/// MSE, relMSE, RMSE and MAE of linear values over the kept pixels (every
/// pixel without a mask), as the experiment measures them.
pub fn errors(
    test: ImageArg<'_>,
    reference: ImageArg<'_>,
    mask: Option<&[bool]>,
) -> Result<ErrorStats> {
    let (t, r, mask) = inputs(test, reference, mask)?;
    match mask {
        Some(m) => Ok(masked_error_metrics(&t, &r, &m)
            .map_err(image_error)?
            .linear),
        None => linear_errors(&t, &r).map_err(image_error),
    }
}

/// The MSE of the error blurred by a Gaussian of `sigma` pixels (the
/// experiment's perceptual error).
pub fn blurred(
    test: ImageArg<'_>,
    reference: ImageArg<'_>,
    mask: Option<&[bool]>,
    sigma: f64,
) -> Result<f64> {
    let (t, r, mask) = inputs(test, reference, mask)?;
    blurred_mse(&t, &r, mask.as_ref(), sigma).map_err(image_error)
}

/// The mean FLIP error (8-bit sRGB at exposure 1, `pixels_per_degree`).
pub fn flip(
    test: ImageArg<'_>,
    reference: ImageArg<'_>,
    mask: Option<&[bool]>,
    pixels_per_degree: f32,
) -> Result<f64> {
    let (t, r, mask) = inputs(test, reference, mask)?;
    flip_error(&t, &r, mask.as_ref(), pixels_per_degree).map_err(image_error)
}

/// The per-channel error image (`squared`, `relative` or `absolute`), as
/// `height * width * 3` values.
pub fn error_values(test: ImageArg<'_>, reference: ImageArg<'_>, kind: &str) -> Result<Vec<f32>> {
    let kind = match kind {
        "squared" => PixelError::Squared,
        "relative" => PixelError::RelativeSquared,
        "absolute" => PixelError::Absolute,
        other => {
            return Err(EngineError::value(format!(
                "kind must be 'squared', 'relative' or 'absolute', got {other:?}"
            )));
        }
    };
    let (t, r, _) = inputs(test, reference, None)?;
    let image = error_image(&t, &r, kind).map_err(image_error)?;
    Ok(image.into_pixels().into_iter().flatten().collect())
}

/// The experiment's paired ratio of `errors` to `baseline`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratio {
    /// The geometric mean of the per-seed ratios.
    pub ratio: f64,
    /// Its 95 % interval.
    pub low: f64,
    /// Its 95 % interval's upper end.
    pub high: f64,
    /// Pairs.
    pub n: usize,
    /// `mean(errors) / mean(baseline)`.
    pub ratio_of_means: f64,
    /// `better`, `worse` or `not distinguishable`.
    pub verdict: &'static str,
}

/// The paired-seed ratio of `errors` to `baseline` (entry `i` of both from
/// seed `i`): the log-ratio mean with its Student-t 95 % interval.
pub fn compare(errors: &[f64], baseline: &[f64]) -> Result<Ratio> {
    let r = paired_ratio(errors, baseline).ok_or_else(|| {
        EngineError::value(format!(
            "compare needs two arrays of the same length, at least 2, of finite \
             positive errors; got lengths {} and {}",
            errors.len(),
            baseline.len()
        ))
    })?;
    Ok(Ratio {
        ratio: r.ratio,
        low: r.ci95[0],
        high: r.ci95[1],
        n: r.n,
        ratio_of_means: r.ratio_of_means,
        verdict: r.verdict.as_str(),
    })
}

/// An image error's one-line message.
fn image_error(e: lowdisc_image::ImageError) -> EngineError {
    EngineError::value(e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arg(values: &[f32], height: usize, width: usize) -> ImageArg<'_> {
        ImageArg {
            values,
            height,
            width,
        }
    }

    #[test]
    fn errors_of_a_constant_offset_are_analytic() {
        let r = [0.5f32; 12];
        let t = [0.75f32; 12];
        let e = errors(arg(&t, 2, 2), arg(&r, 2, 2), None).unwrap();
        assert_eq!((e.mse, e.mae), (0.0625, 0.25));
        assert!((e.relmse - 0.0625 / 0.26).abs() < 1e-12, "{e:?}");
        // A mask keeping one pixel whose error is 1: MSE 1.
        let mut t2 = r;
        t2[..3].copy_from_slice(&[1.5; 3]);
        let m = errors(
            arg(&t2, 2, 2),
            arg(&r, 2, 2),
            Some(&[true, false, false, false][..]),
        );
        assert_eq!(m.unwrap().mse, 1.0);
        // Blurring a constant error leaves it.
        let b = blurred(arg(&t, 2, 2), arg(&r, 2, 2), None, 1.0).unwrap();
        assert!((b - 0.0625).abs() < 1e-12, "{b}");
        assert_eq!(
            error_values(arg(&t, 2, 2), arg(&r, 2, 2), "absolute").unwrap(),
            vec![0.25; 12]
        );
    }

    #[test]
    fn bad_shapes_and_kinds_are_refused() {
        let err = |r: Result<ErrorStats>| r.unwrap_err().to_string();
        let v = [0.0f32; 12];
        assert!(err(errors(arg(&v, 2, 2), arg(&v, 1, 4), None)).contains("reference 4x1"));
        assert!(err(errors(arg(&v, 3, 2), arg(&v, 3, 2), None)).contains("needs 18 values"));
        assert!(err(errors(arg(&v, 2, 2), arg(&v, 2, 2), Some(&[true][..]))).contains("mask"));
        let kind = error_values(arg(&v, 2, 2), arg(&v, 2, 2), "cubed").unwrap_err();
        assert!(kind.to_string().contains("'absolute'"));
    }

    #[test]
    fn compare_gives_the_ratio_and_its_interval() {
        let base = [1.0, 2.0, 4.0, 3.0];
        let half: Vec<f64> = base.iter().map(|b| b * 0.5).collect();
        let r = compare(&half, &base).unwrap();
        assert!(
            (r.ratio - 0.5).abs() < 1e-15 && (r.low - 0.5).abs() < 1e-15,
            "{r:?}"
        );
        // Every pair is exactly 0.5: a zero-width interval below 1.
        assert_eq!((r.high, r.verdict), (r.low, "better"));
        assert!(compare(&[1.0], &[1.0]).is_err());
        assert!(compare(&[1.0, 0.0], &[1.0, 1.0]).is_err());
    }
}
