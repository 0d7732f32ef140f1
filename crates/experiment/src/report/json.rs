//! `results.json`: every number of the report with the settings, the
//! command line and the machine (schema in the crate's top doc).

use anyhow::Result;
use serde_json::json;

use super::answer::Answer;
use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::plan::{Target, reference_cut};
use crate::results::Results;

/// The CPU's model name from `/proc/cpuinfo` (`unknown` elsewhere).
fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into())
}

/// The machine a run was measured on: its CPU model and core count.
pub(crate) fn machine() -> serde_json::Value {
    json!({
        "cpu": cpu_model(),
        "cores": std::thread::available_parallelism().map_or(1, |n| n.get()),
    })
}

/// The short hash of the source tree's commit, when git can tell.
pub(crate) fn git_hash() -> Option<String> {
    let out = std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// The pretty-printed JSON document.
pub fn json(config: &ExperimentConfig, results: &Results, wall: f64) -> Result<String> {
    let names: Vec<&str> = config.samplers.iter().map(|s| s.as_str()).collect();
    let ref_ranges = [Target::Main, Target::Convergence].map(|t| reference_cut(config, t).ranges);
    let value = json!({
        "schema": 1,
        "command": config.command,
        "version": env!("CARGO_PKG_VERSION"),
        "git_hash": git_hash(),
        "machine": machine(),
        "settings": {
            "scene": config.scene.as_ref().map_or("builtin".to_string(), |p| p.display().to_string()),
            "preset": config.preset.map(|p| p.name()),
            "emitter_border": config.emitter_border,
            "blur_sigma": config.blur_sigma,
            "baseline": crate::comparison::BASELINE,
            "width": config.resolution[0],
            "height": config.resolution[1],
            "spp": config.spp,
            "runs": config.runs,
            "ref_spp": config.ref_spp,
            "ref_sampler": REF_SAMPLER.as_str(),
            "ref_seed": REF_SEED,
            "max_depth": config.max_depth,
            "spectral": config.spectral,
            "threshold": config.threshold,
            "conv_max": config.conv_max,
            "conv_res": config.conv_res,
            "conv_seeds": config.conv_seeds,
            "conv_ref_spp": config.conv_ref_spp,
            "unit_samples": config.unit_budget(),
            "ref_ranges": ref_ranges,
            "samplers": names,
        },
        "reference": results.reference,
        "convergence_reference": results.convergence_reference,
        "samplers": results.samplers,
        "threshold_sweep": results.threshold_sweep,
        "kept_fraction": results.kept_fraction,
        "wall_time_s": wall,
        "answer": Answer::of(config, results).json(),
    });
    Ok(serde_json::to_string_pretty(&value)?)
}
