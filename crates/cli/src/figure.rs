//! `lowdisc figure`: the paper's figure. A 2x2-pixel image sampled with
//! `spp` samples per pixel; the film positions of all four pixels' samples,
//! one panel per sampler, side by side, with pixel edges and the strata of
//! `spp` samples drawn.

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;
use lowdisc::catalog::SamplerConfig;
use lowdisc_experiment::figure::figure;

use crate::{default_output, parse};

/// The image the figure samples: 2x2 pixels, as in the paper.
const RESOLUTION: [u32; 2] = [2, 2];

/// The long help of `figure` (`lowdisc figure --help`).
pub const LONG_ABOUT: &str = "Draw the paper's figure: the film positions of all samples of a 2x2-pixel \
image, one panel per sampler, side by side, with pixel edges (heavy lines) and the strata of \
--spp samples (light lines).\n\n\
Pixels are visited row by row (y, then x) and each pixel's samples in index order, from one \
sampler, which fixes the values of the paper's literal sampler, whose single random stream \
depends on call order.";

/// The arguments of `figure`.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// Output file, .png or .svg [default: out/figure.png, out/ created]
    #[arg(long, short = 'o', value_name = "FILE")]
    output: Option<PathBuf>,
    /// Samplers, one panel each, comma-separated.
    #[arg(
        long,
        value_name = "LIST",
        value_delimiter = ',',
        default_value = "sobol,paper,paper-repro,sobol-owen,zsobol"
    )]
    samplers: Vec<String>,
    /// Samples per pixel.
    #[arg(long, default_value_t = 16)]
    spp: u32,
    /// Seed of every random choice.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Paper permutation threshold in [0,1]: probability a matrix column is left unflipped.
    #[arg(long, default_value_t = SamplerConfig::DEFAULT_THRESHOLD, allow_negative_numbers = true)]
    threshold: f64,
    /// Let the paper permutation act on the plotted dimensions 0-1 (the
    /// paper's figure shows the permuted sequence's 2-D arrangement); with
    /// `--paper-all-dims=false` the paper panels show the renderer's default
    /// sampler, which permutes dimensions >= 2 only and so places samples
    /// exactly as sobol; `--paper-all-dims` alone means true.
    #[arg(long, value_name = "BOOL", default_value_t = true, num_args = 0..=1,
          default_missing_value = "true", require_equals = true, action = clap::ArgAction::Set)]
    paper_all_dims: bool,
}

/// A validated `figure` invocation.
#[derive(Debug, Clone)]
pub struct FigureConfig {
    output: PathBuf,
    /// Whether to create the output's folder (the default `out/`).
    create_dir: bool,
    samplers: Vec<SamplerConfig>,
}

impl FigureArgs {
    /// Checks every option and builds the configuration.
    pub fn into_config(self) -> Result<FigureConfig> {
        let create_dir = self.output.is_none();
        let output = self
            .output
            .unwrap_or_else(|| default_output::path("figure.png"));
        lowdisc_plot::Format::from_path(&output)?;
        if self.spp == 0 {
            bail!("--spp must be at least 1");
        }
        if self.spp > 1 << 16 {
            bail!("--spp must be at most 65536 for a figure");
        }
        let names: Vec<&String> = self
            .samplers
            .iter()
            .filter(|s| !s.trim().is_empty())
            .collect();
        if names.is_empty() {
            bail!("--samplers needs at least one sampler name");
        }
        let samplers = names
            .into_iter()
            .map(|name| {
                let mut config =
                    parse::sampler_config(name, self.seed, self.threshold, self.paper_all_dims)?;
                config.spp = self.spp;
                config.resolution = RESOLUTION;
                Ok(config)
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(FigureConfig {
            output,
            create_dir,
            samplers,
        })
    }
}

/// Runs `figure`: computes every panel, then writes the file.
pub fn run(config: &FigureConfig) -> Result<()> {
    let first = &config.samplers[0];
    let title = format!(
        "{}x{} pixels, {} samples per pixel (seed {})",
        RESOLUTION[0], RESOLUTION[1], first.spp, first.seed
    );
    let canvas = figure(&config.samplers, 300.0, title)?;
    if config.create_dir {
        default_output::create_dir()?;
    }
    canvas.save(&config.output)?;
    default_output::report_written(&config.output);
    Ok(())
}
