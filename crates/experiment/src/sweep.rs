//! The threshold sweep of the paper's method: for each threshold, the star
//! discrepancy of one pixel's film positions and the error of `paper-repro`
//! renders against the reference (mean and sd over the runs' seeds).
//!
//! Threshold 1 leaves every generator-matrix column unflipped, so its row
//! is plain Sobol (a deterministic sampler: its runs are identical).

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{RgbImage, error_metrics};
use lowdisc_render::render::render;
use lowdisc_render::scene::Scene;

use crate::config::ExperimentConfig;
use crate::progress::{Progress, Stage, samples};
use crate::results::SweepPoint;
use crate::run::options;
use crate::stats::MeanSd;

/// The thresholds swept.
pub const THRESHOLDS: [f64; 7] = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0];

/// Star discrepancy of one pixel's `spp` film positions from `paper-repro`
/// (permuting dimensions 0-1 too) at threshold `t`.
fn pixel_discrepancy(spp: u32, t: f64) -> Result<f64> {
    let mut c = SamplerConfig::new(SamplerName::PaperRepro);
    c.threshold = t;
    c.paper_all_dims = true;
    c.spp = spp;
    c.resolution = [1, 1];
    let pts = crate::figure::film_positions(&c)?;
    let set = lowdisc_metrics::PointSet::from_rows(&pts)?;
    Ok(lowdisc_metrics::star_discrepancy(&set)?)
}

/// The sweep over [`THRESHOLDS`].
pub fn threshold_sweep(
    config: &ExperimentConfig,
    scene: &Scene,
    reference: &RgbImage,
    observer: &dyn Progress,
) -> Result<Vec<SweepPoint>> {
    let title = format!(
        "threshold sweep: paper-repro at {} thresholds, {} runs each",
        THRESHOLDS.len(),
        config.runs
    );
    let renders = (THRESHOLDS.len() as u64) * u64::from(config.runs);
    let stage = Stage::begin(
        observer,
        &title,
        renders * samples(config.resolution, config.spp),
    );
    let mut out = Vec::new();
    for t in THRESHOLDS {
        let mut linear = Vec::new();
        let mut srgb8 = Vec::new();
        for seed in 0..u64::from(config.runs) {
            let mut o = options(config, SamplerName::PaperRepro, seed, config.spp);
            o.threshold = t;
            let rendered = render(scene, &o, &stage)?;
            stage.finished_render(rendered.stats.samples);
            let m = error_metrics(&rendered.image, reference)?;
            linear.push(m.linear.relmse);
            srgb8.push(m.srgb8.relmse);
        }
        out.push(SweepPoint {
            threshold: t,
            star_discrepancy: pixel_discrepancy(config.spp, t)?,
            relmse: MeanSd::of(&linear),
            srgb8_relmse: MeanSd::of(&srgb8),
        });
    }
    stage.end();
    Ok(out)
}
