//! The estimate of a one-machine run's time ([`Estimate`], the observer's
//! [`crate::progress`] vocabulary): the camera
//! samples of its plan's units ([`crate::plan::Plan::samples`]) at the
//! speed of a short calibration render, which measures this machine's
//! samples per second on the scene.
//!
//! The calibration renders the whole image, so its speed averages the
//! cheap rows (sky) and the expensive ones, and it counts the rays per
//! sample that [`crate::eta`] uses to weigh the work done. A first render
//! at 1 spp, untimed, starts the worker threads and touches the scene, so
//! that the timed one measures rendering only. The estimate assumes every
//! sampler costs the same per sample; they differ by a few tens of percent,
//! so it is a guide, not a promise: [`crate::eta`] corrects it with the
//! speed measured as the run goes.

use std::time::Instant;

use anyhow::Result;
use lowdisc_render::render::{NoProgress, render};
use lowdisc_render::settings::{Given, SettingsLayer};

use crate::config::{ExperimentConfig, REF_SAMPLER};
use crate::progress::Estimate;
use crate::subject::Subject;

/// Samples per pixel of the timed calibration render. At 1 spp the start
/// of the worker threads and the first touches of the scene weigh so much
/// that the measured rate on the default scene (287 ksamples/s) was below
/// every stage's own (350-770 ksamples/s); at 4 spp it costs about half a
/// second.
pub const CALIBRATION_SPP: u32 = 4;

/// Renders `subject` at the experiment's resolution, once at 1 spp to warm
/// up and once, timed, with [`CALIBRATION_SPP`] samples per pixel, and
/// estimates the time of `samples` samples from its speed.
pub fn calibrate(config: &ExperimentConfig, subject: &Subject, samples: u64) -> Result<Estimate> {
    let view = subject.view_at(config.resolution)?;
    let from = "the calibration render";
    let at = |spp| {
        config.render_options(&SettingsLayer {
            sampler: Some(Given::new(REF_SAMPLER, from)),
            seed: Some(Given::new(0, from)),
            spp: Some(Given::new(spp, from)),
            ..SettingsLayer::default()
        })
    };
    render(&subject.scene, &view, &at(1)?, &NoProgress)?;
    let options = at(CALIBRATION_SPP)?;
    let start = Instant::now();
    let out = render(&subject.scene, &view, &options, &NoProgress)?;
    let seconds = start.elapsed().as_secs_f64().max(1e-6);
    let samples_per_second = out.stats.samples as f64 / seconds;
    Ok(Estimate {
        samples,
        samples_per_second,
        rays_per_sample: out.stats.rays as f64 / out.stats.samples.max(1) as f64,
        seconds: samples as f64 / samples_per_second.max(1e-9),
    })
}
