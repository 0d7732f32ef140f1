//! `lowdisc paper-claim`: the paper's claim about its permuted Sobol
//! sequence, measured. For each sampler (Sobol, the paper's permutation
//! literal and reproducible at several thresholds, XOR, Owen, fast Owen,
//! Halton, independent), each dimension pair and each point count, the exact
//! star discrepancy and the minimum Euclidean and toroidal distance, as mean
//! and standard deviation over seeds `0..K` (one run for unscrambled Sobol).
//! Writes `claim.md`, `claim.json` and log-log plots (see [`report`]).

use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc::catalog::{SamplerConfig, SamplerName};

use crate::parse;
use crate::progress::Reporter;

mod measure;
mod report;

use measure::{ClaimConfig, measure};

/// The long help of `paper-claim`.
pub const LONG_ABOUT: &str = "\
Measure the paper's claim: does its random permutation of the Sobol\n\
generator matrices keep the star discrepancy close to Sobol's while raising\n\
the minimum distance between points?\n\
\n\
For sobol, paper and paper-repro at each --thresholds value, sobol-xor,\n\
sobol-owen, sobol-fast-owen, halton and independent, for each N in --ns and\n\
each dimension pair in --pairs (the renderer's global Sobol sampler uses\n\
dimensions 0,1 for the film position, 2,3 for the lens, then 4,5, 6,7 ...),\n\
computes the exact star discrepancy D*_N and the minimum Euclidean and\n\
toroidal distance of the first N points (natural order), as mean and sample\n\
standard deviation over the seeds 0..K (one run for unscrambled sobol).\n\
\n\
Writes DIR/claim.md (markdown tables), DIR/claim.json and, per pair,\n\
DIR/dstar_dimsA-B.png, DIR/mindist_dimsA-B.png and\n\
DIR/mindist_toroidal_dimsA-B.png (log-log, one line per sampler).\n\
";

/// The arguments of `paper-claim`.
#[derive(Debug, Args)]
pub struct ClaimArgs {
    /// Output directory (created if missing).
    #[arg(long, short = 'o', value_name = "DIR", default_value = "claim")]
    out: PathBuf,
    /// Seeds 0..K of the randomized samplers.
    #[arg(long, value_name = "K", default_value_t = 8)]
    seeds: u64,
    /// Comma-separated point counts.
    #[arg(long, value_name = "LIST", default_value = "16,64,256,1024,4096")]
    ns: String,
    /// Comma-separated dimension pairs A..B (B = A + 2).
    #[arg(long, value_name = "LIST", default_value = "0..2,2..4,4..6")]
    pairs: String,
    /// Comma-separated thresholds of the paper's permutation.
    #[arg(long, value_name = "LIST", default_value = "0.25,0.5,0.75,0.9")]
    thresholds: String,
    /// Plot format: png or svg.
    #[arg(long, value_name = "EXT", default_value = "png")]
    plot_format: String,
    /// No progress on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// The largest point count accepted.
const MAX_N: u32 = 1 << 16;

impl ClaimArgs {
    /// Checks every option and builds the configuration.
    pub fn into_config(self) -> Result<ClaimConfig> {
        if self.seeds == 0 || self.seeds > 10_000 {
            bail!("--seeds must lie in 1..=10000");
        }
        let ns = self
            .ns
            .split(',')
            .map(|t| match t.trim().parse::<u32>() {
                Ok(n) if (2..=MAX_N).contains(&n) => Ok(n),
                _ => bail!("--ns: `{t}` is not a point count in 2..={MAX_N}"),
            })
            .collect::<Result<Vec<_>>>()?;
        let pairs = self
            .pairs
            .split(',')
            .map(|t| {
                let r = parse::dim_range(t)?;
                if r.len() != 2 {
                    bail!("--pairs: `{t}` must span exactly two dimensions (e.g. 2..4)");
                }
                Ok(r)
            })
            .collect::<Result<Vec<_>>>()?;
        let thresholds = self
            .thresholds
            .split(',')
            .map(|t| {
                let v: f64 = t
                    .trim()
                    .parse()
                    .with_context(|| format!("--thresholds: `{t}` is not a number"))?;
                parse::threshold(v)
            })
            .collect::<Result<Vec<_>>>()?;
        if !matches!(self.plot_format.as_str(), "png" | "svg") {
            bail!("--plot-format must be png or svg");
        }
        let mut samplers = vec![SamplerConfig::new(SamplerName::Sobol)];
        for name in [SamplerName::Paper, SamplerName::PaperRepro] {
            for &t in &thresholds {
                let mut c = SamplerConfig::new(name);
                c.threshold = t;
                samplers.push(c);
            }
        }
        for name in [
            SamplerName::SobolXor,
            SamplerName::SobolOwen,
            SamplerName::SobolFastOwen,
            SamplerName::Halton,
            SamplerName::Independent,
        ] {
            samplers.push(SamplerConfig::new(name));
        }
        Ok(ClaimConfig {
            out: self.out,
            seeds: self.seeds,
            ns,
            pairs,
            samplers,
            plot_format: self.plot_format,
            quiet: self.quiet,
        })
    }
}

/// Runs `paper-claim`: measures, writes the report files, prints their names.
pub fn run(config: &ClaimConfig, mut out: impl Write) -> Result<()> {
    let start = Instant::now();
    let progress = Reporter::new(config.quiet);
    let rows = measure(config, &progress)?;
    progress.end_stage();
    let seconds = start.elapsed().as_secs_f64();
    std::fs::create_dir_all(&config.out)
        .with_context(|| format!("cannot create `{}`", config.out.display()))?;
    let written = report::write_all(config, &rows, seconds)?;
    writeln!(out, "measured {} cells in {seconds:.1} s", rows.len())?;
    for path in written {
        writeln!(out, "wrote {}", path.display())?;
    }
    out.flush()?;
    Ok(())
}
