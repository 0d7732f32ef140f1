//! The error metrics of one render against the reference ([`measure`]:
//! MSE, relMSE, RMSE and MAE on linear radiance and on 8-bit sRGB) and
//! their summary over a sampler's runs ([`MetricSummary`]). A new metric is
//! added here and in [`crate::results`].

use anyhow::Result;
pub use lowdisc_image::{ErrorMetrics, ErrorStats};
use lowdisc_image::{RgbImage, error_metrics};
use serde::Serialize;

use crate::stats::MeanSd;

/// The errors of `image` against `reference` (same size).
pub fn measure(image: &RgbImage, reference: &RgbImage) -> Result<ErrorMetrics> {
    Ok(error_metrics(image, reference)?)
}

/// Mean and sd of the four metrics.
#[derive(Debug, Clone, Serialize)]
pub struct MetricSummary {
    /// MSE.
    pub mse: MeanSd,
    /// relMSE.
    pub relmse: MeanSd,
    /// RMSE.
    pub rmse: MeanSd,
    /// MAE.
    pub mae: MeanSd,
}

impl MetricSummary {
    /// Aggregates one metric family over runs.
    pub fn of(stats: &[ErrorStats]) -> MetricSummary {
        let col = |f: fn(&ErrorStats) -> f64| MeanSd::of(&stats.iter().map(f).collect::<Vec<_>>());
        MetricSummary {
            mse: col(|s| s.mse),
            relmse: col(|s| s.relmse),
            rmse: col(|s| s.rmse),
            mae: col(|s| s.mae),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_of_two_hand_computed_runs() {
        // Test images against a reference of 1s: errors 0.5 and 1.5 in every
        // channel of a 1x1 image, then 1.0 everywhere.
        let r = RgbImage::filled(1, 2, [1.0; 3]).unwrap();
        let a = RgbImage::from_pixels(1, 2, vec![[1.5; 3], [2.5; 3]]).unwrap();
        let b = RgbImage::filled(1, 2, [2.0; 3]).unwrap();
        let ea = measure(&a, &r).unwrap().linear;
        let eb = measure(&b, &r).unwrap().linear;
        // a: MSE (0.25 + 2.25)/2 = 1.25, MAE 1.0; b: MSE 1, MAE 1.
        assert!((ea.mse - 1.25).abs() < 1e-12 && (ea.mae - 1.0).abs() < 1e-12);
        assert!((eb.mse - 1.0).abs() < 1e-12);
        // relMSE of b: 1 / (1 + 0.01).
        assert!((eb.relmse - 1.0 / 1.01).abs() < 1e-9);
        let s = MetricSummary::of(&[ea, eb]);
        assert!((s.mse.mean - 1.125).abs() < 1e-12);
        // sd of {1.25, 1}: |1.25 - 1| / sqrt(2).
        assert!((s.mse.sd - 0.25 / 2f64.sqrt()).abs() < 1e-12);
        assert!((s.mae.mean - 1.0).abs() < 1e-12 && s.mae.sd.abs() < 1e-12);
    }
}
