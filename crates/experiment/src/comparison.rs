//! Which samplers can be told apart: for each compared metric, every
//! sampler's mean over runs with its standard error and 95 % interval
//! ([`Summary`]) and its paired ratio to the baseline sampler `sobol` with
//! the ratio's interval and verdict ([`PairedRatio`]: the log-ratio mean of
//! the runs with the same seed index, Student-t interval; see
//! [`crate::stats::paired`]).
//!
//! A deterministic sampler (unscrambled `sobol`, `halton`...) gives the same
//! image for every seed, so its own interval has zero width and a ratio to
//! it carries only the other sampler's scatter.

use crate::results::{MetricStats, RunResult, SamplerResult};
use crate::stats::{PairedRatio, Summary, paired_ratio};

/// The baseline of the ratios: pbrt-v3's global Sobol, the paper's baseline.
pub const BASELINE: &str = "sobol";

/// The value of one metric in one run.
pub type MetricOf = fn(&RunResult) -> f64;

/// The compared metrics: name in `results.json` and the value of one run.
pub const METRICS: [(&str, MetricOf); 6] = [
    ("masked_mse", |r| r.quality.masked.mse),
    ("masked_relmse", |r| r.quality.masked.relmse),
    ("blurred_mse", |r| r.quality.blurred_mse),
    ("flip", |r| r.quality.flip),
    ("mse", |r| r.linear.mse),
    ("relmse", |r| r.linear.relmse),
];

fn column(s: &SamplerResult, f: MetricOf) -> Vec<f64> {
    s.runs.iter().map(f).collect()
}

/// Fills every sampler's `statistics` (one entry per [`METRICS`] metric),
/// and its `relmse_ratio_interval` from the paired `relmse` entry.
pub fn fill_statistics(samplers: &mut [SamplerResult]) {
    let base = samplers.iter().position(|s| s.name == BASELINE);
    let baseline: Vec<Vec<f64>> = match base {
        Some(b) => METRICS
            .iter()
            .map(|(_, f)| column(&samplers[b], *f))
            .collect(),
        None => Vec::new(),
    };
    for (k, s) in samplers.iter_mut().enumerate() {
        s.statistics = METRICS
            .iter()
            .enumerate()
            .map(|(m, (metric, f))| {
                let values = column(s, *f);
                let ratio_to_baseline = match base {
                    Some(b) if b != k => paired_ratio(&values, &baseline[m]),
                    _ => None,
                };
                MetricStats {
                    metric,
                    summary: Summary::of(&values),
                    ratio_to_baseline,
                }
            })
            .collect();
        s.relmse_ratio_interval = match relmse_ratio(s) {
            Some(r) => Some(r.ci95),
            None if Some(k) == base => Some([1.0, 1.0]),
            None => None,
        };
    }
}

/// The paired ratio of a sampler's linear relMSE to the baseline's (the
/// `relmse` entry of its `statistics`), if there is one.
pub fn relmse_ratio(s: &SamplerResult) -> Option<&PairedRatio> {
    s.statistics
        .iter()
        .find(|m| m.metric == "relmse")?
        .ratio_to_baseline
        .as_ref()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quality::Quality;
    use crate::results::result;
    use crate::stats::Verdict;
    use lowdisc_image::ErrorStats;

    fn run(seed: u64, mse: f64) -> RunResult {
        let e = ErrorStats {
            mse,
            relmse: 2.0 * mse,
            rmse: mse.sqrt(),
            mae: mse,
        };
        RunResult {
            seed,
            time_s: 0.0,
            linear: e,
            srgb8: e,
            quality: Quality {
                masked: e,
                blurred_mse: 0.5 * mse,
                flip: 0.1,
            },
        }
    }

    #[test]
    fn ratios_pair_runs_by_seed_and_give_verdicts() {
        let seeds = [1.0, 3.0, 2.0, 5.0];
        let mut base = result("sobol", 1.0);
        base.runs = seeds
            .iter()
            .enumerate()
            .map(|(i, m)| run(i as u64, *m))
            .collect();
        let mut better = result("zsobol", 1.0);
        // 0.8x the baseline on every seed, with a little scatter.
        let wiggle = [1.01, 0.99, 1.0, 1.005];
        better.runs = (0..4)
            .map(|i| run(i as u64, 0.8 * seeds[i] * wiggle[i]))
            .collect();
        let mut v = vec![better, base];
        fill_statistics(&mut v);
        let mse = &v[0].statistics[0];
        assert_eq!(mse.metric, "masked_mse");
        let r = mse.ratio_to_baseline.unwrap();
        assert!((r.ratio - 0.8).abs() < 0.01, "{r:?}");
        assert_eq!(r.verdict, Verdict::Better);
        // Same values for FLIP (0.1 everywhere): ratio 1, zero width.
        let flip = v[0].statistics[3].ratio_to_baseline.unwrap();
        assert_eq!(
            (flip.ratio, flip.verdict),
            (1.0, Verdict::NotDistinguishable)
        );
        assert!(
            v[1].statistics
                .iter()
                .all(|m| m.ratio_to_baseline.is_none())
        );
        assert_eq!(v[1].statistics[0].summary.n, 4);
        // The relMSE interval of results.json is the paired one.
        let relmse = relmse_ratio(&v[0]).unwrap();
        assert_eq!(v[0].relmse_ratio_interval, Some(relmse.ci95));
        assert!(relmse.ci95[0] < 0.8 && 0.8 < relmse.ci95[1], "{relmse:?}");
        assert_eq!(v[1].relmse_ratio_interval, Some([1.0, 1.0]));
    }
}
