//! `lowdisc experiment`: the paper's experiment in one command.
//!
//! Renders a scene (default: the built-in scene of [`scene`]) with each
//! sampler `runs` times (seeds `0..runs`), compares every render with a
//! converged reference and writes a report folder:
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
//! The reference (`--ref-spp` samples per pixel with `sobol-owen`, an
//! unbiased randomised sampler, seed [`REF_SEED`]) is cached as PFM in
//! `<parent of --out>/lowdisc-ref-cache/ref-<hash>.pfm`, keyed by an FNV-1a
//! hash of the scene's content (the built-in scene's id, or the scene file's
//! bytes), the environment map's bytes and every render setting; reruns
//! reuse it and say so on stderr. The convergence series (1 to `--conv-max`
//! spp, seed 0) is rendered at `--conv-res` (default: half the resolution
//! per side) against its own reference of `--conv-ref-spp` (default 8 x
//! `--conv-max`) samples, cached the same way, so that the series can reach
//! 1024 spp within the default run's time; the reference's own noise adds at
//! most about 1/8 to the last point's relMSE. Every file is written to a
//! temporary file and renamed into place.

mod reference;
mod report;
mod results;
mod run;
mod scene;
mod stats;
mod sweep;

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;
use lowdisc::catalog::{SamplerConfig, SamplerName};

use crate::parse;

pub use run::run;

/// The seed of the reference render.
pub const REF_SEED: u64 = 0x0005_EED0_F2EF;
/// The sampler of the reference render.
pub const REF_SAMPLER: SamplerName = SamplerName::SobolOwen;
/// The samplers compared by default.
pub const DEFAULT_SAMPLERS: &str = "independent,stratified,halton,sobol,paper,paper-repro,sobol-xor,padded-sobol,sobol-fast-owen,zsobol";

/// The long help of `experiment`.
pub const LONG_ABOUT: &str = "\
Reproduce the paper's experiment: render a scene with each sampler --runs\n\
times (seeds 0..runs), compare with a converged, cached reference, and write\n\
report.md, report.html, results.json and the images to --out.\n\
\n\
Without SCENE a built-in scene is used: rough gold and aluminium spheres,\n\
car-paint-like coated shapes on a diffuse ground under a procedural sky with\n\
a sun (no downloads). Defaults: 256x144, 16 spp, 3 runs, reference 1024 spp;\n\
convergence from 1 to 1024 spp at half the resolution per side against its\n\
own 8192-spp reference. --paper: 1280x720, 16 spp, 10 runs, reference 4096\n\
spp, convergence to 1024 spp at 640x360. --quick: 32x32, 4 spp, 2 runs,\n\
reference 64 spp, convergence up to 8 spp at 32x32 (for tests).";

/// The arguments of `experiment`.
#[derive(Debug, Args)]
pub struct ExperimentArgs {
    /// A pbrt-v4 scene file (omit for the built-in scene).
    scene: Option<PathBuf>,
    /// Samplers to compare, comma-separated.
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = DEFAULT_SAMPLERS)]
    samplers: Vec<String>,
    /// Samples per pixel of every compared render.
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Renders per sampler (seeds 0..runs).
    #[arg(long, value_name = "N")]
    runs: Option<u32>,
    /// Image resolution.
    #[arg(long, value_name = "WxH")]
    res: Option<String>,
    /// Samples per pixel of the reference.
    #[arg(long, value_name = "N")]
    ref_spp: Option<u32>,
    /// Largest spp of the convergence plot (a power of two).
    #[arg(long, value_name = "N")]
    conv_max: Option<u32>,
    /// Resolution of the convergence series [default: half of --res per side].
    #[arg(long, value_name = "WxH")]
    conv_res: Option<String>,
    /// Samples per pixel of the convergence series' reference [default: 8 x --conv-max].
    #[arg(long, value_name = "N")]
    conv_ref_spp: Option<u32>,
    /// Environment map (lat-long 2:1 or equal-area square) replacing the built-in sky.
    #[arg(long, value_name = "FILE")]
    envmap: Option<PathBuf>,
    /// Paper permutation threshold of the paper's samplers (renders and point figure).
    #[arg(long, value_name = "T", default_value_t = SamplerConfig::DEFAULT_THRESHOLD)]
    threshold: f64,
    /// Maximum path depth.
    #[arg(long, value_name = "D", default_value_t = 5)]
    maxdepth: u32,
    /// Worker threads [default: all cores].
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// Output folder (created if missing).
    #[arg(long, value_name = "DIR", default_value = "experiment")]
    out: PathBuf,
    /// The paper's settings: 1280x720, 16 spp, 10 runs, reference 4096 spp.
    #[arg(long, conflicts_with = "quick")]
    paper: bool,
    /// Tiny settings for tests: 32x32, 4 spp, 2 runs, reference 64 spp.
    #[arg(long)]
    quick: bool,
    /// No progress messages.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// A validated `experiment` invocation.
#[derive(Debug, Clone)]
pub struct ExperimentConfig {
    /// Scene file or `None` for the built-in scene.
    pub scene: Option<PathBuf>,
    /// Samplers, in the order given.
    pub samplers: Vec<SamplerName>,
    /// Samples per pixel.
    pub spp: u32,
    /// Runs per sampler.
    pub runs: u32,
    /// Resolution.
    pub resolution: [u32; 2],
    /// Reference spp.
    pub ref_spp: u32,
    /// Convergence plot cap.
    pub conv_max: u32,
    /// Resolution of the convergence series.
    pub conv_res: [u32; 2],
    /// Reference spp of the convergence series.
    pub conv_ref_spp: u32,
    /// Environment map.
    pub envmap: Option<PathBuf>,
    /// Paper threshold (renders of `paper`/`paper-repro` and the figure).
    pub threshold: f64,
    /// Maximum depth.
    pub max_depth: u32,
    /// Threads.
    pub threads: Option<usize>,
    /// Output folder.
    pub out: PathBuf,
    /// Quiet.
    pub quiet: bool,
}

impl ExperimentArgs {
    /// Checks every argument and builds the configuration.
    pub fn into_config(self) -> Result<ExperimentConfig> {
        let (res, spp, runs, ref_spp, conv_max) = if self.quick {
            ([32, 32], 4, 2, 64, 8)
        } else if self.paper {
            ([1280, 720], 16, 10, 4096, 1024)
        } else {
            ([256, 144], 16, 3, 1024, 1024)
        };
        let mut samplers = Vec::new();
        for name in self.samplers.iter().filter(|s| !s.trim().is_empty()) {
            let s = parse::sampler_name(name)?;
            if !samplers.contains(&s) {
                samplers.push(s);
            }
        }
        if samplers.is_empty() {
            bail!("--samplers needs at least one sampler name");
        }
        let resolution = match self.res.as_deref() {
            Some(text) => {
                let r = parse::resolution(text)?;
                if r[0] > 16_384 || r[1] > 16_384 {
                    bail!("--res `{text}` is too large: each side must be at most 16384 pixels");
                }
                r
            }
            None => res,
        };
        let conv_res = match self.conv_res.as_deref() {
            Some(text) => {
                let r = parse::resolution(text)?;
                if r[0] > 16_384 || r[1] > 16_384 {
                    bail!(
                        "--conv-res `{text}` is too large: each side must be at most 16384 pixels"
                    );
                }
                r
            }
            // --quick keeps one resolution (and so one reference).
            None if self.quick => resolution,
            None => resolution.map(|v| (v / 2).max(1)),
        };
        let spp = self.spp.unwrap_or(spp);
        let runs = self.runs.unwrap_or(runs);
        let ref_spp = self.ref_spp.unwrap_or(ref_spp);
        let conv_max = self.conv_max.unwrap_or(conv_max);
        if spp == 0 || spp > 1 << 16 {
            bail!("--spp must be between 1 and 65536, got {spp}");
        }
        if runs == 0 || runs > 1000 {
            bail!("--runs must be between 1 and 1000, got {runs}");
        }
        if ref_spp == 0 || ref_spp > 1 << 20 {
            bail!("--ref-spp must be between 1 and 1048576, got {ref_spp}");
        }
        if !conv_max.is_power_of_two() || conv_max > 1 << 16 {
            bail!("--conv-max must be a power of two up to 65536, got {conv_max}");
        }
        let conv_ref_spp = match self.conv_ref_spp {
            Some(n) => n,
            None if conv_res == resolution && self.quick => ref_spp,
            None => 8 * conv_max,
        };
        if conv_ref_spp == 0 || conv_ref_spp > 1 << 20 {
            bail!("--conv-ref-spp must be between 1 and 1048576, got {conv_ref_spp}");
        }
        if self.maxdepth > lowdisc_render::integrator::MAX_DEPTH_LIMIT {
            bail!("--maxdepth is too large: {}", self.maxdepth);
        }
        if let Some(t) = self.threads {
            if t == 0 || t > lowdisc_render::render::MAX_THREADS {
                bail!("--threads must be at least 1, got {t}");
            }
        }
        if let Some(e) = &self.envmap {
            if !e.is_file() {
                bail!("--envmap `{}` is not a file", e.display());
            }
        }
        if let Some(s) = &self.scene {
            if !s.is_file() {
                bail!("scene `{}` is not a file", s.display());
            }
        }
        Ok(ExperimentConfig {
            scene: self.scene,
            samplers,
            spp,
            runs,
            resolution,
            ref_spp,
            conv_max,
            conv_res,
            conv_ref_spp,
            envmap: self.envmap,
            threshold: parse::threshold(self.threshold)?,
            max_depth: self.maxdepth,
            threads: self.threads,
            out: self.out,
            quiet: self.quiet,
        })
    }
}
