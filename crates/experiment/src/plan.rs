//! The work of a run, known before it starts: the camera samples of every
//! stage ([`total_samples`]), and the estimate of the whole run's time
//! ([`Estimate`]) from a short calibration render that measures this
//! machine's samples per second on the scene.
//!
//! The estimate assumes every sample costs the same; samplers differ by a
//! few tens of percent, so it is a guide, not a promise.

use std::time::Instant;

use anyhow::Result;
use lowdisc_render::render::{NoProgress, render};
use lowdisc_render::scene::Scene;

use crate::config::{ExperimentConfig, REF_SAMPLER};
use crate::progress::samples;
use crate::run::options;
use crate::sweep::THRESHOLDS;

/// The estimated work and time of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Camera samples still to render (cached references excluded).
    pub samples: u64,
    /// Samples per second measured by the calibration render.
    pub samples_per_second: f64,
    /// `samples / samples_per_second`.
    pub seconds: f64,
}

/// The camera samples of a run: the references that are not cached, each
/// sampler's runs, the threshold sweep and the convergence series.
pub fn total_samples(config: &ExperimentConfig, reference_cached: [bool; 2]) -> u64 {
    let per_render = samples(config.resolution, config.spp);
    let mut total = u64::from(config.runs) * per_render * config.samplers.len() as u64;
    total += THRESHOLDS.len() as u64 * u64::from(config.runs) * per_render;
    // Spp 1, 2, 4, .. conv_max: 2 conv_max - 1 samples per pixel in all.
    total += config.samplers.len() as u64 * samples(config.conv_res, 2 * config.conv_max - 1);
    if !reference_cached[0] {
        total += samples(config.resolution, config.ref_spp);
    }
    let same = config.conv_res == config.resolution && config.conv_ref_spp == config.ref_spp;
    if !same && !reference_cached[1] {
        total += samples(config.conv_res, config.conv_ref_spp);
    }
    total
}

/// Samples per pixel of the calibration render. At 1 spp the start of the
/// worker threads and the first touches of the scene weigh so much that the
/// measured rate on the default scene (287 ksamples/s) was below every
/// stage's own (350-770 ksamples/s); at 4 spp it costs about half a second.
pub const CALIBRATION_SPP: u32 = 4;

/// Renders `scene` once with [`CALIBRATION_SPP`] samples per pixel and
/// estimates the time of `samples` samples from its speed.
pub fn calibrate(config: &ExperimentConfig, scene: &Scene, samples: u64) -> Result<Estimate> {
    let start = Instant::now();
    let out = render(
        scene,
        &options(config, REF_SAMPLER, 0, CALIBRATION_SPP),
        &NoProgress,
    )?;
    let seconds = start.elapsed().as_secs_f64().max(1e-6);
    let samples_per_second = out.stats.samples as f64 / seconds;
    Ok(Estimate {
        samples,
        samples_per_second,
        seconds: samples as f64 / samples_per_second.max(1e-9),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc::catalog::SamplerName;

    fn config() -> ExperimentConfig {
        ExperimentConfig {
            scene: None,
            samplers: vec![SamplerName::Sobol, SamplerName::Halton],
            spp: 4,
            runs: 3,
            resolution: [10, 10],
            ref_spp: 64,
            conv_max: 8,
            conv_res: [5, 5],
            conv_ref_spp: 32,
            envmap: None,
            threshold: 0.5,
            max_depth: 5,
            threads: None,
            spectral: false,
            out: "out".into(),
            command: Vec::new(),
            preset: None,
            emitter_border: 3,
            blur_sigma: 1.0,
        }
    }

    #[test]
    fn total_counts_every_stage_once() {
        let c = config();
        // Runs: 2 samplers x 3 runs x 400; sweep: 7 x 3 x 400; convergence:
        // 2 x 25 x 15; references: 100 x 64 and 25 x 32.
        let runs = 2 * 3 * 400 + 7 * 3 * 400 + 2 * 25 * 15;
        assert_eq!(total_samples(&c, [true, true]), runs);
        assert_eq!(total_samples(&c, [false, true]), runs + 6400);
        assert_eq!(total_samples(&c, [false, false]), runs + 6400 + 800);
        // One reference serves both when resolution and spp agree.
        let mut same = c.clone();
        same.conv_res = same.resolution;
        same.conv_ref_spp = same.ref_spp;
        let runs_same = 2 * 3 * 400 + 7 * 3 * 400 + 2 * 100 * 15;
        assert_eq!(total_samples(&same, [false, false]), runs_same + 6400);
    }
}
