//! The measurements of `paper-claim`: for each sampler, dimension pair and
//! point count, the star discrepancy and the minimum distances over seeds.

use std::ops::Range;
use std::path::PathBuf;

use anyhow::Result;
use lowdisc::catalog::{Order, SamplerConfig, SamplerName};
use lowdisc_experiment::figure::sampler_title;
use lowdisc_experiment::stats::MeanSd;
use lowdisc_metrics::{DistanceMetric, min_distance, star_discrepancy};
use serde::Serialize;

use crate::pointfile;
use crate::progress::Reporter;

/// A validated `paper-claim` invocation.
#[derive(Debug, Clone)]
pub struct ClaimConfig {
    /// Output directory.
    pub out: PathBuf,
    /// Number of seeds of randomized samplers.
    pub seeds: u64,
    /// Point counts.
    pub ns: Vec<u32>,
    /// Dimension pairs.
    pub pairs: Vec<Range<u32>>,
    /// The samplers, in table order.
    pub samplers: Vec<SamplerConfig>,
    /// Plot file extension.
    pub plot_format: String,
    /// No progress on stderr.
    pub quiet: bool,
}

/// One measured cell: a sampler, a dimension pair, a point count.
#[derive(Debug, Clone, Serialize)]
pub struct ClaimRow {
    /// Display label (`paper (t = 0.5)`).
    pub label: String,
    /// Catalog name.
    pub sampler: String,
    /// Paper threshold, for the paper's samplers.
    pub threshold: Option<f64>,
    /// The two dimensions.
    pub dims: [u32; 2],
    /// Number of points.
    pub n: u32,
    /// Number of seeds measured.
    pub runs: u64,
    /// Exact star discrepancy.
    pub star: MeanSd,
    /// Minimum Euclidean distance.
    pub min_euclidean: MeanSd,
    /// Minimum toroidal distance.
    pub min_toroidal: MeanSd,
}

/// The seeds measured for `sampler`: one run for unscrambled Sobol.
fn runs_of(config: &ClaimConfig, sampler: &SamplerConfig) -> u64 {
    if sampler.name == SamplerName::Sobol {
        1
    } else {
        config.seeds
    }
}

/// Measures every cell (sampler, pair, n), counting the points measured on
/// `progress`.
pub fn measure(config: &ClaimConfig, progress: &Reporter) -> Result<Vec<ClaimRow>> {
    let points_per_pair: u64 = config
        .samplers
        .iter()
        .map(|s| runs_of(config, s) * config.ns.iter().map(|&n| u64::from(n)).sum::<u64>())
        .sum();
    let cells = config.pairs.len() * config.samplers.len() * config.ns.len();
    progress.begin_stage(
        &format!("paper-claim: {cells} cells"),
        points_per_pair * config.pairs.len() as u64,
        "points",
    );
    let mut rows = Vec::new();
    for pair in &config.pairs {
        for sampler in &config.samplers {
            let is_paper = matches!(sampler.name, SamplerName::Paper | SamplerName::PaperRepro);
            let runs = runs_of(config, sampler);
            for &n in &config.ns {
                let (mut star, mut euc, mut tor) = (Vec::new(), Vec::new(), Vec::new());
                for seed in 0..runs {
                    let mut c = *sampler;
                    c.seed = seed;
                    let points = pointfile::sequence_points(&c, n, pair.clone(), Order::Natural)?;
                    star.push(star_discrepancy(&points)?);
                    euc.push(min_distance(&points, DistanceMetric::Euclidean)?);
                    tor.push(min_distance(&points, DistanceMetric::Toroidal)?);
                    progress.add(u64::from(n));
                }
                rows.push(ClaimRow {
                    label: sampler_title(sampler),
                    sampler: sampler.name.to_string(),
                    threshold: is_paper.then_some(sampler.threshold),
                    dims: [pair.start, pair.start + 1],
                    n,
                    runs,
                    star: MeanSd::of(&star),
                    min_euclidean: MeanSd::of(&euc),
                    min_toroidal: MeanSd::of(&tor),
                });
            }
        }
    }
    Ok(rows)
}
