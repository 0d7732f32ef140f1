//! # lowdisc-experiment: the paper's experiment as a library
//!
//! Renders a scene (default: the built-in scene of [`scene`]) with each
//! sampler `runs` times (seeds `0..runs`), compares every render with a
//! converged reference and writes a report folder. The `lowdisc experiment`
//! command is a thin front end; tests, benches and other programs call
//! [`run`] with an [`ExperimentConfig`] and a [`Progress`] observer.
//!
//! Modules, in the order a run uses them:
//! - [`config`]: the validated settings of one experiment;
//! - [`scene`]: the built-in scene and its procedural sky;
//! - [`reference`]: the converged reference render, cached on disk;
//! - [`run`](mod@run): the repeated renders of every sampler and their convergence series;
//! - [`sweep`]: the threshold sweep of the paper's method;
//! - [`stats`]: mean and sd, ratios, log-log slopes, the cache key's hash;
//! - [`results`]: the numbers measured, as `results.json` holds them;
//! - [`figure`]: the 2x2-pixel point figure's film positions and panels;
//! - [`report`]: images, plots, `report.md`, `report.html`, `results.json`;
//! - [`progress`]: the observer through which a run reports what it does
//!   (the library never prints).
//!
//! The report folder holds:
//!
//! - `report.md`, `report.html`: the table (mean ± sd of render time and of
//!   MSE, relMSE, RMSE, MAE on linear radiance and on 8-bit sRGB, and the
//!   relMSE ratio to `sobol`, the paper's baseline), the images with 4x
//!   nearest crops, per-pixel relative-squared-error heatmaps, the
//!   convergence plot, the threshold sweep and the 2x2-pixel point figure;
//! - `results.json`, schema (every number of the report):
//!   `{ schema: 1, command: [args], version, git_hash?, machine: {cpu, cores},
//!   settings: {scene, width, height, spp, runs, ref_spp, ref_sampler, ref_seed,
//!   max_depth, threshold, conv_max, conv_res: [w, h], conv_ref_spp, samplers:
//!   [names]}, reference: {file, cached, time_s}, convergence_reference:
//!   {file, cached, time_s}, samplers: [{ name, description, deterministic,
//!   time_s, mse, relmse, rmse, mae (linear, each {mean, sd}),
//!   srgb8: {mse, relmse, rmse, mae} (each {mean, sd}),
//!   relmse_ratio_to_sobol (number or null), runs: [{seed, time_s, linear:
//!   {mse, relmse, rmse, mae}, srgb8: {...}}], convergence: [{spp, relmse}],
//!   convergence_slope }], threshold_sweep: [{threshold, star_discrepancy,
//!   relmse, srgb8_relmse}],
//!   wall_time_s }`.
//!
//! The reference (`ref_spp` samples per pixel with `sobol-owen`, an
//! unbiased randomised sampler, seed [`REF_SEED`]) is cached as PFM in
//! `<parent of out>/lowdisc-ref-cache/ref-<hash>.pfm`, keyed by an FNV-1a
//! hash of the scene's content (the built-in scene's id, or the scene file's
//! bytes), the environment map's bytes and every render setting; reruns
//! reuse it and say so through [`Progress::note`]. The convergence series
//! (1 to `conv_max` spp, seed 0) is rendered at `conv_res` against its own
//! reference of `conv_ref_spp` samples, cached the same way, so that the
//! series can reach 1024 spp within the default run's time; the reference's
//! own noise adds at most about 1/8 to the last point's relMSE. Every file
//! is written to a temporary file and renamed into place.

pub mod config;
pub mod figure;
pub mod progress;
pub mod reference;
pub mod report;
pub mod results;
pub mod run;
pub mod scene;
pub mod stats;
pub mod sweep;

pub use config::{DEFAULT_SAMPLERS, ExperimentConfig, REF_SAMPLER, REF_SEED};
pub use progress::{Progress, Silent};
pub use run::run;
