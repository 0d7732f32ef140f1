//! The estimate of a one-machine run's time ([`Estimate`], the observer's
//! [`crate::progress`] vocabulary): the camera
//! samples of its plan's units ([`crate::plan::Plan::samples`]) at the
//! speed of a short calibration render, which measures this machine's
//! samples per second on the scene.
//!
//! The estimate assumes every sample costs the same; samplers differ by a
//! few tens of percent, so it is a guide, not a promise.

use std::time::Instant;

use anyhow::Result;
use lowdisc_render::render::{NoProgress, render};
use lowdisc_render::settings::{Given, SettingsLayer};

use crate::config::{ExperimentConfig, REF_SAMPLER};
use crate::progress::Estimate;
use crate::subject::Subject;

/// Samples per pixel of the calibration render. At 1 spp the start of the
/// worker threads and the first touches of the scene weigh so much that the
/// measured rate on the default scene (287 ksamples/s) was below every
/// stage's own (350-770 ksamples/s); at 4 spp it costs about half a second.
pub const CALIBRATION_SPP: u32 = 4;

/// Renders `subject` once at the experiment's resolution with
/// [`CALIBRATION_SPP`] samples per pixel and estimates the time of
/// `samples` samples from its speed.
pub fn calibrate(config: &ExperimentConfig, subject: &Subject, samples: u64) -> Result<Estimate> {
    let view = subject.view_at(config.resolution)?;
    let from = "the calibration render";
    let options = config.render_options(&SettingsLayer {
        sampler: Some(Given::new(REF_SAMPLER, from)),
        seed: Some(Given::new(0, from)),
        spp: Some(Given::new(CALIBRATION_SPP, from)),
        ..SettingsLayer::default()
    })?;
    let start = Instant::now();
    let out = render(&subject.scene, &view, &options, &NoProgress)?;
    let seconds = start.elapsed().as_secs_f64().max(1e-6);
    let samples_per_second = out.stats.samples as f64 / seconds;
    Ok(Estimate {
        samples,
        samples_per_second,
        seconds: samples as f64 / samples_per_second.max(1e-9),
    })
}
