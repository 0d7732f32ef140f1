//! Each sampler's numbers over the study's scenes: per scene its paired
//! ratio to each baseline in every compared metric, pooled over the scenes
//! ([`crate::stats::pooled`]), and its error structure per scene and on
//! average.

use serde::Serialize;

use super::{SceneResult, StudyConfig, StudyRun};
use crate::stats::{PairedRatio, PooledRatio, Summary, paired_ratio, pooled_ratio};

/// The value of one metric of a render.
pub type MetricOf = fn(&StudyRun) -> f64;

/// The compared metrics: name and value of a render (the first is the
/// tables' main metric).
pub const METRICS: [(&str, MetricOf); 4] = [
    ("masked_mse", |r| r.quality.masked.mse),
    ("blurred_mse", |r| r.quality.blurred_mse),
    ("flip", |r| r.quality.flip),
    ("mse", |r| r.mse),
];

/// One metric of one sampler over the scenes.
#[derive(Debug, Clone, Serialize)]
pub struct PooledMetric {
    /// The metric's name ([`METRICS`]).
    pub metric: &'static str,
    /// The paired ratio to the baseline on each scene, in scene order
    /// (`None` where it is undefined: an error of 0).
    pub scenes: Vec<Option<PairedRatio>>,
    /// The scenes' ratios pooled (`None` if no scene has one).
    pub pooled: Option<PooledRatio>,
}

/// The error structure of one sampler over the scenes: the largest of the
/// three Nyquist regions' power ratios of each render, and each region's
/// mean.
#[derive(Debug, Clone, Serialize)]
pub struct StructureSummary {
    /// Mean, se and interval over the seeds of each scene, in scene order.
    pub scenes: Vec<Summary>,
    /// The mean over every render of every scene of the checkerboard,
    /// columns and rows ratios.
    pub regions: [f64; 3],
    /// The mean over every render of every scene of the spectral peak ratio.
    pub peak: f64,
    /// The frequency of the strongest peak of any render.
    pub peak_frequency: [f64; 2],
    /// The mean of the scenes' means.
    pub mean: f64,
    /// The smallest and largest scene mean.
    pub range: [f64; 2],
}

/// One sampler's ratios to one baseline.
#[derive(Debug, Clone, Serialize)]
pub struct BaselineRatios {
    /// The baseline's name.
    pub baseline: String,
    /// One entry per [`METRICS`] metric.
    pub metrics: Vec<PooledMetric>,
}

/// One sampler's numbers over the study.
#[derive(Debug, Clone, Serialize)]
pub struct SamplerSummary {
    /// The sampler's name.
    pub sampler: String,
    /// Its ratios to each baseline, in the order of
    /// [`StudyConfig::baselines`].
    pub ratios: Vec<BaselineRatios>,
    /// Its error structure.
    pub structure: StructureSummary,
}

/// The summary of every sampler of `config` over `scenes`.
pub fn summarise(config: &StudyConfig, scenes: &[SceneResult]) -> Vec<SamplerSummary> {
    config
        .samplers
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let ratios = config
                .baselines
                .iter()
                .map(|b| {
                    let base = config.samplers.iter().position(|s| s == b).unwrap_or(0);
                    BaselineRatios {
                        baseline: b.as_str().to_string(),
                        metrics: METRICS
                            .iter()
                            .map(|&(metric, f)| pooled_metric(scenes, k, base, metric, f))
                            .collect(),
                    }
                })
                .collect();
            let per_scene: Vec<Summary> = scenes
                .iter()
                .map(|s| Summary::of(&column(s, k, &|r| r.structure.max())))
                .collect();
            let means: Vec<f64> = per_scene.iter().map(|s| s.mean).collect();
            let all: Vec<&StudyRun> = scenes.iter().flat_map(|s| &s.samplers[k].runs).collect();
            let region = |f: fn(&StudyRun) -> f64| {
                all.iter().map(|r| f(r)).sum::<f64>() / all.len().max(1) as f64
            };
            let strongest = all
                .iter()
                .map(|r| r.peak)
                .max_by(|a, b| a.ratio.total_cmp(&b.ratio));
            let structure = StructureSummary {
                peak: region(|r| r.peak.ratio),
                peak_frequency: strongest.map_or([f64::NAN; 2], |p| p.frequency),
                regions: [
                    region(|r| r.structure.checkerboard),
                    region(|r| r.structure.columns),
                    region(|r| r.structure.rows),
                ],
                mean: means.iter().sum::<f64>() / means.len().max(1) as f64,
                range: [
                    means.iter().copied().fold(f64::INFINITY, f64::min),
                    means.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                ],
                scenes: per_scene,
            };
            SamplerSummary {
                sampler: name.as_str().to_string(),
                ratios,
                structure,
            }
        })
        .collect()
}

fn column(scene: &SceneResult, k: usize, f: &dyn Fn(&StudyRun) -> f64) -> Vec<f64> {
    scene.samplers[k].runs.iter().map(f).collect()
}

/// Metric `metric` (value `f`) of sampler `k` against sampler `base`:
/// per scene and pooled.
fn pooled_metric(
    scenes: &[SceneResult],
    k: usize,
    base: usize,
    metric: &'static str,
    f: MetricOf,
) -> PooledMetric {
    let ratios: Vec<Option<PairedRatio>> = scenes
        .iter()
        .map(|s| paired_ratio(&column(s, k, &f), &column(s, base, &f)))
        .collect();
    let defined: Vec<PairedRatio> = ratios.iter().flatten().copied().collect();
    PooledMetric {
        metric,
        pooled: pooled_ratio(&defined),
        scenes: ratios,
    }
}
