//! Each sampler's numbers over the study's scenes: per scene its paired
//! ratio to the baseline in every compared metric, pooled over the scenes
//! ([`crate::stats::pooled`]), and its error structure per scene and on
//! average.

use serde::Serialize;

use super::{SceneResult, StudyConfig};
use crate::quality::Quality;
use crate::stats::{PairedRatio, PooledRatio, Summary, paired_ratio, pooled_ratio};

/// The value of one metric of a render.
pub type QualityOf = fn(&Quality) -> f64;

/// The compared metrics: name and value of a render.
pub const METRICS: [(&str, QualityOf); 3] = [
    ("masked_mse", |q| q.masked.mse),
    ("blurred_mse", |q| q.blurred_mse),
    ("flip", |q| q.flip),
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

/// The error structure of one sampler over the scenes.
#[derive(Debug, Clone, Serialize)]
pub struct StructureSummary {
    /// Mean, se and interval over the seeds of each scene, in scene order.
    pub scenes: Vec<Summary>,
    /// The mean of the scenes' means.
    pub mean: f64,
    /// The smallest and largest scene mean.
    pub range: [f64; 2],
}

/// One sampler's numbers over the study.
#[derive(Debug, Clone, Serialize)]
pub struct SamplerSummary {
    /// The sampler's name.
    pub sampler: String,
    /// One entry per [`METRICS`] metric.
    pub metrics: Vec<PooledMetric>,
    /// Its error structure.
    pub structure: StructureSummary,
}

/// The summary of every sampler of `config` over `scenes`.
pub fn summarise(config: &StudyConfig, scenes: &[SceneResult]) -> Vec<SamplerSummary> {
    let column = |scene: &SceneResult, k: usize, f: &dyn Fn(&super::StudyRun) -> f64| {
        scene.samplers[k].runs.iter().map(f).collect::<Vec<f64>>()
    };
    let base = config
        .samplers
        .iter()
        .position(|s| *s == config.baseline)
        .unwrap_or(0);
    config
        .samplers
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let metrics = METRICS
                .iter()
                .map(|&(metric, f)| {
                    let ratios: Vec<Option<PairedRatio>> = scenes
                        .iter()
                        .map(|s| {
                            let own = column(s, k, &|r| f(&r.quality));
                            let baseline = column(s, base, &|r| f(&r.quality));
                            paired_ratio(&own, &baseline)
                        })
                        .collect();
                    let defined: Vec<PairedRatio> = ratios.iter().flatten().copied().collect();
                    PooledMetric {
                        metric,
                        pooled: pooled_ratio(&defined),
                        scenes: ratios,
                    }
                })
                .collect();
            let per_scene: Vec<Summary> = scenes
                .iter()
                .map(|s| Summary::of(&column(s, k, &|r| r.structure)))
                .collect();
            let means: Vec<f64> = per_scene.iter().map(|s| s.mean).collect();
            let structure = StructureSummary {
                mean: means.iter().sum::<f64>() / means.len().max(1) as f64,
                range: [
                    means.iter().copied().fold(f64::INFINITY, f64::min),
                    means.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                ],
                scenes: per_scene,
            };
            SamplerSummary {
                sampler: name.as_str().to_string(),
                metrics,
                structure,
            }
        })
        .collect()
}
