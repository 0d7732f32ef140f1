//! The numbers one experiment measures ([`Results`] and its parts), as the
//! report and `results.json` show them, and the error ratio to the paper's
//! baseline sampler.

use std::path::PathBuf;

use lowdisc_image::{ErrorStats, RgbImage};
use serde::Serialize;

use crate::comparison::MetricStats;
use crate::quality::Quality;
use crate::stats::{MeanSd, ratio};

/// One render's numbers.
#[derive(Debug, Clone, Serialize)]
pub struct RunResult {
    /// Seed.
    pub seed: u64,
    /// Render time in seconds.
    pub time_s: f64,
    /// Errors on linear radiance.
    pub linear: ErrorStats,
    /// Errors on 8-bit sRGB.
    pub srgb8: ErrorStats,
    /// Masked errors, blurred MSE and FLIP.
    pub quality: Quality,
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

/// One point of a convergence series.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ConvPoint {
    /// Samples per pixel.
    pub spp: u32,
    /// relMSE on linear radiance.
    pub relmse: f64,
}

/// Everything measured for one sampler.
#[derive(Debug, Clone, Serialize)]
pub struct SamplerResult {
    /// Command-line name.
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Whether every run gave a bit-identical image (runs differ only in time).
    pub deterministic: bool,
    /// Render time, seconds.
    pub time_s: MeanSd,
    /// Linear MSE.
    pub mse: MeanSd,
    /// Linear relMSE.
    pub relmse: MeanSd,
    /// Linear RMSE.
    pub rmse: MeanSd,
    /// Linear MAE.
    pub mae: MeanSd,
    /// The same on 8-bit sRGB.
    pub srgb8: MetricSummary,
    /// Mean linear relMSE over `sobol`'s.
    pub relmse_ratio_to_sobol: Option<f64>,
    /// Mean ± SE, 95 % interval and paired ratio to `sobol` of each compared
    /// metric ([`crate::comparison`]).
    pub statistics: Vec<MetricStats>,
    /// Every run.
    pub runs: Vec<RunResult>,
    /// relMSE against spp (seed 0).
    pub convergence: Vec<ConvPoint>,
    /// Fitted log-log slope of the convergence series.
    pub convergence_slope: Option<f64>,
}

/// One threshold of the sweep.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SweepPoint {
    /// Threshold.
    pub threshold: f64,
    /// Star discrepancy of dimensions 0-1 of one pixel's samples.
    pub star_discrepancy: f64,
    /// Linear relMSE of `paper-repro` renders at this threshold (over the runs).
    pub relmse: MeanSd,
    /// 8-bit sRGB relMSE of the same renders.
    pub srgb8_relmse: MeanSd,
}

/// The reference render.
#[derive(Debug, Clone, Serialize)]
pub struct ReferenceInfo {
    /// Cache file.
    pub file: PathBuf,
    /// Whether it came from the cache.
    pub cached: bool,
    /// Render time (0 when cached).
    pub time_s: f64,
}

/// All results of one experiment.
#[derive(Debug, Clone, Serialize)]
pub struct Results {
    /// Samplers, in the order given.
    pub samplers: Vec<SamplerResult>,
    /// Reference.
    pub reference: ReferenceInfo,
    /// Reference of the convergence series (at the convergence resolution).
    pub convergence_reference: ReferenceInfo,
    /// Threshold sweep of the paper's method.
    pub threshold_sweep: Vec<SweepPoint>,
    /// Fraction of the pixels the masked metrics keep.
    pub kept_fraction: f64,
}

/// Images kept for the report.
pub struct Images {
    /// Reference.
    pub reference: RgbImage,
    /// Seed-0 render of each sampler.
    pub renders: Vec<RgbImage>,
}

/// Fills every sampler's `relmse_ratio_to_sobol` from the `sobol` entry.
pub fn fill_ratios(samplers: &mut [SamplerResult]) {
    let base = samplers
        .iter()
        .find(|s| s.name == "sobol")
        .map(|s| s.relmse.mean);
    for s in samplers {
        s.relmse_ratio_to_sobol = ratio(s.relmse.mean, base);
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use lowdisc_image::error_metrics;

    /// A sampler result with every summary at `relmse` and no runs.
    pub(crate) fn result(name: &str, relmse: f64) -> SamplerResult {
        let m = MeanSd {
            mean: relmse,
            sd: 0.0,
        };
        SamplerResult {
            name: name.into(),
            description: String::new(),
            deterministic: false,
            time_s: m,
            mse: m,
            relmse: m,
            rmse: m,
            mae: m,
            srgb8: MetricSummary {
                mse: m,
                relmse: m,
                rmse: m,
                mae: m,
            },
            relmse_ratio_to_sobol: None,
            statistics: Vec::new(),
            runs: Vec::new(),
            convergence: Vec::new(),
            convergence_slope: None,
        }
    }

    #[test]
    fn ratios_are_to_sobol_and_absent_without_it() {
        let mut v = vec![
            result("paper", 0.919),
            result("sobol", 1.0),
            result("zsobol", 0.5),
        ];
        fill_ratios(&mut v);
        assert_eq!(v[0].relmse_ratio_to_sobol, Some(0.919));
        assert_eq!(v[1].relmse_ratio_to_sobol, Some(1.0));
        assert_eq!(v[2].relmse_ratio_to_sobol, Some(0.5));
        let mut w = vec![result("paper", 0.919)];
        fill_ratios(&mut w);
        assert_eq!(w[0].relmse_ratio_to_sobol, None);
    }

    #[test]
    fn summary_of_two_hand_computed_runs() {
        // Test images against a reference of 1s: errors 0.5 and 1.5 in every
        // channel of a 1x1 image, then 1.0 everywhere.
        let r = RgbImage::filled(1, 2, [1.0; 3]).unwrap();
        let a = RgbImage::from_pixels(1, 2, vec![[1.5; 3], [2.5; 3]]).unwrap();
        let b = RgbImage::filled(1, 2, [2.0; 3]).unwrap();
        let ea = error_metrics(&a, &r).unwrap().linear;
        let eb = error_metrics(&b, &r).unwrap().linear;
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
