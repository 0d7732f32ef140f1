//! # lowdisc-experiment: the paper's experiment as a library
//!
//! Renders a scene (default: the built-in scene of [`scene`]) with each
//! sampler `runs` times (seeds `0..runs`), compares every render with a
//! converged reference and writes a report folder. The `lowdisc experiment`
//! command is a thin front end; tests, benches and other programs call
//! [`run()`] with an [`ExperimentConfig`] and a [`Progress`] observer.
//!
//! Modules, in the order a run uses them:
//! - [`config`]: the validated settings of one experiment, and the render
//!   options of one of its renders (through the renderer's one settings
//!   type);
//! - [`scene`]: the built-in scene and its procedural sky;
//! - [`subject`]: the scene to render with its view, loaded and hashed;
//! - [`plan`]: the experiment as independent units (one render each) and
//!   `plan.json`;
//! - [`cut`]: a large render cut into pieces (bands x sample ranges) and
//!   joined again, exactly;
//! - [`estimate`]: the estimate of a one-machine run's time;
//! - [`eta`]: the time left of a stage and of the whole run;
//! - [`reference`](mod@reference): the converged reference renders, cached on disk;
//! - [`run`](mod@run): the one-machine run: every unit rendered in-process;
//! - [`source`]: the units' renders as the assembly reads them, and the
//!   pieces of a cut render joined;
//! - [`units`]: rendering one unit, its files, its lock;
//! - [`assemble`](mod@assemble): the units' renders measured and collected
//!   into results and the report folder (one path for the one-machine and
//!   the planned run);
//! - [`planned`]: the planned run in a folder: plan, and merge;
//! - [`status`]: the progress of a planned run;
//! - [`sweep`]: the threshold sweep of the paper's method;
//! - [`metrics`]: the error metrics of one render and their summary over runs;
//! - [`quality`]: the emitter mask, masked errors, blurred MSE and FLIP of a render;
//! - [`stats`]: mean and sd, mean ± SE with Student-t intervals, paired
//!   ratios with intervals and verdicts, log-log slopes, the cache key's hash;
//! - [`comparison`]: those statistics for every sampler and compared metric;
//! - [`results`]: the numbers measured, as `results.json` holds them;
//! - [`figure`]: the 2x2-pixel point figure's film positions and panels;
//! - [`report`]: images, plots, `report.md`, `report.html`, `results.json`;
//! - [`study`]: the paired comparison repeated over a collection of scenes
//!   and pooled per sampler (`lowdisc study`);
//! - [`progress`]: the observer through which a run reports what it does
//!   (the library never prints).
//!
//! The report folder holds:
//!
//! - `report.md`, `report.html`: the table (mean ± sd of render time and of
//!   MSE, relMSE, RMSE, MAE on linear radiance and on 8-bit sRGB, and the
//!   relMSE ratio to `sobol`, the paper's baseline), the statistics section
//!   (masked, blurred and FLIP errors: mean ± SE, 95 % intervals, paired
//!   ratios to `sobol` with intervals and verdicts), the images with 4x
//!   nearest crops, per-pixel relative-squared-error heatmaps, the
//!   convergence plot, the threshold sweep and the 2x2-pixel point figure;
//! - `results.json`, schema (every number of the report):
//!   `{ schema: 1, command: [args], version, git_hash?, machine: {cpu, cores},
//!   settings: {scene, width, height, spp, runs, ref_spp, ref_sampler, ref_seed,
//!   max_depth, spectral, threshold, conv_max, conv_res: [w, h], conv_seeds,
//!   conv_ref_spp,
//!   unit_samples (the unit budget), ref_ranges: [main, convergence] (the
//!   sample ranges each reference is cut into), samplers: [names]}, reference: {file, cached, time_s}, convergence_reference:
//!   {file, cached, time_s}, samplers: [{ name, description, deterministic,
//!   time_s, mse, relmse, rmse, mae (linear, each {mean, sd}),
//!   srgb8: {mse, relmse, rmse, mae} (each {mean, sd}),
//!   relmse_ratio_to_sobol (number or null), relmse_ratio_interval ([lo, hi]
//!   or null: the 95 % interval of the paired relmse ratio in statistics), statistics: [{metric, summary:
//!   {n, mean, sd, se, ci95: [lo, hi]}, ratio_to_baseline: {n, ratio, ci95,
//!   log_ratio: {summary}, ratio_of_means, verdict} or null}] (metrics
//!   masked_mse, masked_relmse, blurred_mse, flip, mse, relmse; see
//!   [`comparison`]), runs: [{seed, time_s, linear: {mse, relmse, rmse, mae},
//!   srgb8: {...}, quality: {masked: {mse, relmse, rmse, mae}, blurred_mse,
//!   flip}}], convergence: [{spp, relmse (mean over the seeds), relmse_ci95,
//!   relmse_seeds}], convergence_slope (mean of the seeds' fits),
//!   convergence_slope_ci95, convergence_slopes }],
//!   threshold_sweep: [{threshold, star_discrepancy, relmse, srgb8_relmse,
//!   ratio_to_sobol (a paired ratio, or null)}],
//!   kept_fraction, wall_time_s, answer: {claimed_ratio, claimed_spp,
//!   verdict, paper: {sampler, ratio, ci95 or null} or null, best: {...} or
//!   null, line} }`; settings also hold preset (name or null),
//!   emitter_border, blur_sigma and baseline. `answer` is the report's first
//!   section ([`report::answer`]).
//!
//! The reference (`ref_spp` samples per pixel with `sobol-owen`, an
//! unbiased randomised sampler, seed [`REF_SEED`]) is cached as PFM in
//! `<parent of out>/lowdisc-ref-cache/ref-<hash>.pfm`, keyed by an FNV-1a
//! hash of the scene's content (the built-in scene's id, or the scene file's
//! bytes), the environment map's bytes, every render setting and the number
//! of sample ranges it is cut into ([`cut`]: each range's `f64` sums are
//! added in range order, the same in a planned and a one-machine run); reruns
//! reuse it and say so through [`Progress::note`]. The convergence series
//! (1 to `conv_max` spp, seed 0) is rendered at `conv_res` against its own
//! reference of `conv_ref_spp` samples, cached the same way, so that the
//! series can reach 1024 spp within the default run's time; the reference's
//! own noise adds at most about 1/8 to the last point's relMSE. Every file
//! is written to a temporary file and renamed into place.
//!
//! The same run can be cut into independent units ([`plan`]) that any
//! scheduler runs: [`planned::make_plan`] writes `DIR/plan.json`,
//! [`units::run_unit`] runs one unit into `DIR/units/`, [`status`] reports
//! their progress and [`planned::merge`] writes the report of the
//! one-machine run, through the same [`assemble()`] (its `wall_time_s` is
//! the sum of the units' wall times and the merge's own).

pub mod assemble;
pub mod comparison;
pub mod config;
pub mod cut;
pub mod estimate;
pub mod eta;
pub mod figure;
pub mod metrics;
pub mod plan;
pub mod planned;
pub mod progress;
pub mod quality;
pub mod reference;
pub mod report;
pub mod results;
pub mod run;
pub mod scene;
pub mod source;
pub mod stats;
pub mod status;
pub mod study;
pub mod subject;
pub mod sweep;
pub mod units;

pub use assemble::Outcome;
pub use assemble::assemble;
pub use config::{DEFAULT_SAMPLERS, ExperimentConfig, REF_SAMPLER, REF_SEED};
pub use progress::{Done, Estimate, Progress, Silent};
pub use run::run;
