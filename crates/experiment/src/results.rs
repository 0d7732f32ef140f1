//! The numbers one experiment measures ([`Results`] and its parts), as the
//! report and `results.json` show them, and the error ratio to the paper's
//! baseline sampler.

use std::path::PathBuf;

use lowdisc_image::RgbImage;
use serde::Serialize;

use crate::metrics::{ErrorStats, MetricSummary};
use crate::quality::Quality;
use crate::stats::{MeanSd, PairedRatio, Summary, ratio};

/// One metric of one sampler: its summary and its ratio to the baseline.
#[derive(Debug, Clone, Serialize)]
pub struct MetricStats {
    /// The metric's name (see `comparison::METRICS`).
    pub metric: &'static str,
    /// Mean, sd, standard error and 95 % interval over the runs.
    pub summary: Summary,
    /// The paired ratio to the baseline sampler `sobol` (none for the baseline itself, when
    /// it is absent, or with fewer than two runs).
    pub ratio_to_baseline: Option<PairedRatio>,
}

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

/// One point of a convergence series, over its seeds.
#[derive(Debug, Clone, Serialize)]
pub struct ConvPoint {
    /// Samples per pixel.
    pub spp: u32,
    /// relMSE on linear radiance, the mean over the seeds.
    pub relmse: f64,
    /// The 95 % interval of that mean (`None` for one seed).
    pub relmse_ci95: Option<[f64; 2]>,
    /// Each seed's relMSE (seeds `0..conv_seeds`).
    pub relmse_seeds: Vec<f64>,
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
    /// The 95 % interval of the paired relMSE ratio to `sobol` (the
    /// `relmse` entry of `statistics`, copied by
    /// `comparison::fill_statistics`; `[1, 1]` for `sobol` itself).
    pub relmse_ratio_interval: Option<[f64; 2]>,
    /// Mean ± SE, 95 % interval and paired ratio to `sobol` of each compared
    /// metric (`comparison`).
    pub statistics: Vec<MetricStats>,
    /// Every run.
    pub runs: Vec<RunResult>,
    /// relMSE against spp, over the convergence seeds.
    pub convergence: Vec<ConvPoint>,
    /// The log-log slope of relMSE against spp: the mean over the seeds of
    /// each seed's least-squares fit.
    pub convergence_slope: Option<f64>,
    /// The 95 % interval of that mean (`None` for one seed).
    pub convergence_slope_ci95: Option<[f64; 2]>,
    /// Each seed's fitted slope.
    pub convergence_slopes: Vec<f64>,
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
    /// The linear relMSE relative to `sobol`'s from paired seeds (run `i`
    /// at this threshold against `sobol`'s run `i`), when `sobol` is among
    /// the samplers and there are at least two runs.
    pub ratio_to_sobol: Option<PairedRatio>,
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

/// Fills every sampler's `relmse_ratio_to_sobol` from the `sobol` entry
/// (its interval comes with the paired statistics).
pub fn fill_ratios(samplers: &mut [SamplerResult]) {
    let base = samplers
        .iter()
        .find(|s| s.name == "sobol")
        .map(|s| s.relmse.mean);
    for s in samplers {
        s.relmse_ratio_to_sobol = ratio(s.relmse.mean, base);
    }
}

/// A sampler result with every metric `relmse` (sd 0) and no runs, for tests.
#[cfg(test)]
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
        relmse_ratio_interval: None,
        statistics: Vec::new(),
        runs: Vec::new(),
        convergence: Vec::new(),
        convergence_slope: None,
        convergence_slope_ci95: None,
        convergence_slopes: Vec::new(),
    }
}

/// The results of a run of `samplers` whose references took 1 s and were
/// not cached, with no threshold sweep, for tests.
#[cfg(test)]
pub(crate) fn results(samplers: Vec<SamplerResult>) -> Results {
    let reference = ReferenceInfo {
        file: "ref.pfm".into(),
        cached: false,
        time_s: 1.0,
    };
    Results {
        samplers,
        reference: reference.clone(),
        convergence_reference: reference,
        threshold_sweep: Vec::new(),
        kept_fraction: 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
}
