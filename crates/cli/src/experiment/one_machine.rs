//! `lowdisc experiment` without a subcommand: the paper's experiment in one
//! command.
//!
//! The arguments ([`ExperimentArgs`]) are turned into a
//! [`lowdisc_experiment::ExperimentConfig`] (presets `--quick` and
//! `--paper`, defaults of the convergence series) and handed to
//! [`lowdisc_experiment::run`], which does the work and writes the report
//! folder; the progress it reports is printed on stderr unless `--quiet`.
//! `experiment plan|unit|merge|status` (the same run cut into units) are in
//! [`super::units`].

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc::catalog::SamplerConfig;
use lowdisc::net::Net;
use lowdisc_experiment::{DEFAULT_SAMPLERS, ExperimentConfig};
use lowdisc_render::preset::ScenePreset;

use crate::parse;
use crate::progress::Reporter;

/// Runs per sampler on the built-in scene. Measured there (8 seeds, masked
/// MSE), the paired log-ratio to `sobol` has an sd of 0.015-0.04 for
/// `sobol-xor`, `padded-sobol` and `independent`, so 8 runs (t = 2.36) give
/// a 95 % interval of about ±1.3-3.4 %: a 5 % difference is resolved.
/// Samplers with weak seeds (`sobol-fast-owen`, `zsobol`, and `sobol-owen`
/// on the sun's glints: sd 0.3-0.5) stay unresolved at any affordable count,
/// and the report says so.
const DEFAULT_RUNS: u32 = 8;
/// Resolution of a `--preset` experiment.
const PRESET_RESOLUTION: [u32; 2] = [128, 128];
/// Runs per sampler of a `--preset` experiment.
const PRESET_RUNS: u32 = 16;
/// Seeds of each convergence series: the slope's 95 % interval over 4
/// seeds has t = 3.18. At a quarter of --res per side they cost what one
/// seed at half of it did.
const DEFAULT_CONV_SEEDS: u32 = 4;

/// Reference spp of a `--preset` experiment.
const PRESET_REF_SPP: u32 = 4096;

/// The long help of `experiment`.
pub const LONG_ABOUT: &str = "\
Reproduce the paper's experiment: render a scene with each sampler --runs\n\
times (seeds 0..runs), compare with a converged, cached reference, and write\n\
report.md, report.html, results.json and the images to --out.\n\
\n\
Without SCENE a built-in scene is used: rough gold and aluminium spheres,\n\
car-paint-like coated shapes on a diffuse ground under a procedural sky with\n\
a sun (no downloads). Defaults: 256x144, 16 spp, 8 runs, reference 1024 spp;\n\
convergence from 1 to 1024 spp at a quarter of the resolution per side, 4\n\
seeds, against its own 8192-spp reference (the slope is fitted per seed).\n\
--paper: 1280x720, 16 spp, 10 runs, reference 4096 spp, convergence to 1024\n\
spp at 320x180. --quick: 32x32, 4 spp, 2 runs, reference 64 spp,\n\
convergence up to 8 spp at 32x32, 2 seeds (for tests).\n\
\n\
--preset direct|gi: a built-in Cornell box instead, direct lighting (path\n\
depth 1) or global illumination with depth of field (depth 5); defaults\n\
128x128, 16 spp, 16 runs, reference 4096 spp.\n\
\n\
Besides the metrics over all pixels, every render is measured with directly\n\
visible emitters (and the sky) masked with a border of --emitter-border\n\
pixels, by the MSE of its error blurred by a Gaussian of --blur-sigma pixels,\n\
and by NVIDIA's FLIP. The report gives mean ± standard error, 95 % intervals\n\
(Student t) and the ratio to sobol from paired seeds with its interval, and\n\
says \"not distinguishable\" where the interval contains 1.\n\
\n\
The same run cut into independent units for a cluster: `experiment plan\n\
[these options] --out DIR`, then `experiment unit DIR --index I` for every\n\
unit (any order, any machine), `experiment status DIR`, `experiment merge\n\
DIR` (the same report, results.json and images).";

/// The arguments of `experiment`.
#[derive(Debug, Args)]
pub struct ExperimentArgs {
    /// A pbrt-v4 scene file (omit for the built-in scene).
    scene: Option<PathBuf>,
    /// A built-in comparison scene instead: `direct` (Cornell box, path depth
    /// 1) or `gi` (Cornell box, depth 5, depth of field).
    #[arg(long, value_name = "NAME", conflicts_with = "scene")]
    preset: Option<String>,
    /// Border in pixels around directly visible emitters left out of the masked metrics.
    #[arg(long, value_name = "PX", default_value_t = lowdisc_experiment::quality::DEFAULT_EMITTER_BORDER)]
    emitter_border: u32,
    /// Standard deviation in pixels of the Gaussian of the blurred (perceptual) MSE.
    #[arg(long, value_name = "S", default_value_t = lowdisc_experiment::quality::DEFAULT_BLUR_SIGMA)]
    blur_sigma: f64,
    /// Samplers to compare, comma-separated (`--help` lists them all).
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = DEFAULT_SAMPLERS,
          long_help = crate::sampler_help::sampler_list("Samplers to compare, comma-separated, of:", ""))]
    samplers: Vec<String>,
    /// Generator matrices of the compared Sobol samplers (a built-in net:
    /// `sobol`, `onetwo`; or a file); the reference and the other samplers
    /// keep theirs [default: sobol].
    #[arg(long, value_name = "NAME|FILE", long_help = crate::sampler_help::net_help())]
    net: Option<String>,
    /// Samples per pixel of every compared render [default: 16; --quick: 4].
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Renders per sampler, seeds 0..runs [default: 8; --quick: 2; --paper: 10;
    /// --preset: 16].
    #[arg(long, value_name = "N")]
    runs: Option<u32>,
    /// Image resolution [default: 256x144; --quick: 32x32; --paper: 1280x720].
    #[arg(long, value_name = "WxH")]
    res: Option<String>,
    /// Samples per pixel of the reference [default: 1024; --quick: 64; --paper: 4096].
    #[arg(long, value_name = "N")]
    ref_spp: Option<u32>,
    /// Largest spp of the convergence plot, a power of two [default: 1024; --quick: 8].
    #[arg(long, value_name = "N")]
    conv_max: Option<u32>,
    /// Resolution of the convergence series [default: a quarter of --res per side;
    /// --quick: --res].
    #[arg(long, value_name = "WxH")]
    conv_res: Option<String>,
    /// Seeds of each convergence series, 0..N; the log-log slope is fitted per seed and
    /// reported with its 95 % interval over them [default: 4; --quick: 2].
    #[arg(long, value_name = "N")]
    conv_seeds: Option<u32>,
    /// Samples per pixel of the convergence series' reference [default: 8 x --conv-max;
    /// --quick: --ref-spp].
    #[arg(long, value_name = "N")]
    conv_ref_spp: Option<u32>,
    /// Environment map (lat-long 2:1 or equal-area square): replaces the built-in
    /// sky, or every image-based infinite light of a scene file (pbrt-v4 scenes
    /// often ship without their map) [default: none].
    #[arg(long, value_name = "FILE")]
    envmap: Option<PathBuf>,
    /// Render a scene file's pbrt-v4 features that lowdisc lacks (grid media,
    /// curves, measured BSDFs, other integrators, ...) approximately, each with a
    /// warning, instead of refusing the scene.
    #[arg(long)]
    approximate: bool,
    /// Paper permutation threshold of the paper's samplers (renders and point figure).
    #[arg(long, value_name = "T", default_value_t = SamplerConfig::DEFAULT_THRESHOLD)]
    threshold: f64,
    /// Maximum path depth [default: the preset's, else 5].
    #[arg(long, value_name = "D")]
    maxdepth: Option<u32>,
    /// Worker threads [default: all cores].
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// Render spectrally (four sampled wavelengths per sample, as pbrt-v4)
    /// instead of in RGB, the default; the references are cached apart.
    #[arg(long)]
    spectral: bool,
    /// The most camera samples of one unit of work: a reference or a
    /// convergence point with more is rendered in pieces (bands of rows of
    /// tiles; a reference also in sample ranges) whose exact sums are merged,
    /// in a planned run and on one machine alike [default: the larger of a
    /// run's samples and 8388608].
    #[arg(long, value_name = "N")]
    unit_samples: Option<u64>,
    /// Output folder (created if missing).
    #[arg(long, value_name = "DIR", default_value = "experiment")]
    out: PathBuf,
    /// The paper's settings: 1280x720, 16 spp, 10 runs, reference 4096 spp.
    #[arg(long, conflicts_with = "quick")]
    paper: bool,
    /// Tiny settings for tests: 32x32, 4 spp, 2 runs, reference 64 spp.
    #[arg(long)]
    quick: bool,
    /// No progress, estimate or summary on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

impl ExperimentArgs {
    /// Checks every argument and builds the configuration.
    pub fn into_config(self) -> Result<Experiment> {
        let preset = match self.preset.as_deref() {
            None => None,
            Some(name) => Some(ScenePreset::from_name(name).with_context(|| {
                let names: Vec<&str> = ScenePreset::ALL.iter().map(|p| p.name()).collect();
                format!("unknown --preset `{name}`; known: {}", names.join(", "))
            })?),
        };
        let (res, spp, runs, ref_spp, conv_max, conv_seeds) = if self.quick {
            ([32, 32], 4, 2, 64, 8, 2)
        } else if preset.is_some() {
            (
                PRESET_RESOLUTION,
                16,
                PRESET_RUNS,
                PRESET_REF_SPP,
                1024,
                DEFAULT_CONV_SEEDS,
            )
        } else if self.paper {
            ([1280, 720], 16, 10, 4096, 1024, DEFAULT_CONV_SEEDS)
        } else {
            ([256, 144], 16, DEFAULT_RUNS, 1024, 1024, DEFAULT_CONV_SEEDS)
        };
        let mut samplers = Vec::new();
        for name in self.samplers.iter().filter(|s| !s.trim().is_empty()) {
            let s = parse::sampler_name(name)?;
            if !samplers.contains(&s) {
                samplers.push(s);
            }
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
            None => resolution.map(|v| (v / 4).max(1)),
        };
        let spp = self.spp.unwrap_or(spp);
        let runs = self.runs.unwrap_or(runs);
        let ref_spp = self.ref_spp.unwrap_or(ref_spp);
        let conv_max = self.conv_max.unwrap_or(conv_max);
        let conv_seeds = self.conv_seeds.unwrap_or(conv_seeds);
        let conv_ref_spp = match self.conv_ref_spp {
            Some(n) => n,
            None if conv_res == resolution && self.quick => ref_spp,
            None => 8 * conv_max,
        };
        let config = ExperimentConfig {
            scene: self.scene,
            preset,
            emitter_border: self.emitter_border,
            blur_sigma: self.blur_sigma,
            samplers,
            net: self.net.as_deref().map_or(Ok(Net::SOBOL), parse::net)?,
            spp,
            runs,
            resolution,
            ref_spp,
            conv_max,
            conv_res,
            conv_seeds,
            conv_ref_spp,
            envmap: self.envmap,
            approximate: self.approximate,
            threshold: parse::threshold(self.threshold)?,
            max_depth: self
                .maxdepth
                .unwrap_or(preset.map_or(default_max_depth(), |p| p.max_depth())),
            threads: self.threads,
            spectral: self.spectral,
            unit_samples: self.unit_samples,
            out: self.out,
            command: std::env::args().collect(),
        };
        config.validate()?;
        Ok(Experiment {
            config,
            quiet: self.quiet,
        })
    }
}

/// A validated `experiment` invocation.
#[derive(Debug, Clone)]
pub struct Experiment {
    /// What to run.
    config: ExperimentConfig,
    /// No progress, estimate or summary on stderr.
    quiet: bool,
}

impl Experiment {
    /// The experiment's settings.
    pub fn config(&self) -> &ExperimentConfig {
        &self.config
    }

    /// Whether `--quiet` was given.
    pub fn quiet(&self) -> bool {
        self.quiet
    }
}

/// Runs the experiment, printing its progress and a summary unless `--quiet`.
pub fn run(experiment: &Experiment) -> Result<()> {
    let reporter = Reporter::new(experiment.quiet);
    let outcome = lowdisc_experiment::run(&experiment.config, &reporter)?;
    reporter.summary(&outcome.files);
    print_answer(&outcome, std::io::stdout().lock())
}

/// Prints the answer to the paper's question, the command's last line, to
/// `out` (stdout; with `--quiet` too: it is the result, not progress).
pub fn print_answer(
    outcome: &lowdisc_experiment::Outcome,
    mut out: impl std::io::Write,
) -> Result<()> {
    writeln!(out, "{}", outcome.answer)?;
    Ok(())
}

/// The path depth without a preset: the renderer's default.
fn default_max_depth() -> u32 {
    lowdisc_render::render::RenderOptions::default()
        .integrator
        .max_depth
}
