//! `lowdisc discrepancy`: quality metrics of a point set, from a named
//! sequence or a text file, printed as a table or as JSON.
//!
//! The metrics come from `lowdisc-metrics`; this module only picks them,
//! times them and prints them (see [`rows`] for the rows).

use std::io::Write;
use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::Args;
use lowdisc::catalog::{Order, SamplerConfig};
use lowdisc_metrics::PointSet;
use serde::Serialize;

use crate::progress::Reporter;
use crate::{limits, parse, pointfile};

mod rows;

use rows::{Metric, MetricRow};

/// The long help of `discrepancy` (`lowdisc discrepancy --help`).
pub const LONG_ABOUT: &str = "\
Quality metrics of a point set: star discrepancy (exact, or bounds), the\n\
L2-type discrepancies of scipy.stats.qmc.discrepancy, minimum distances.\n\
\n\
Points come from a sequence (--sampler NAME --n N --dims D, words w mapped\n\
to w * 2^-32, natural order) or from --input FILE: one point per line,\n\
coordinates in [0,1] separated by whitespace or commas, '#' comment lines\n\
and blank lines skipped. A bad file (a value outside [0,1], NaN, ragged\n\
rows, no points, unreadable) is an error naming the line.\n\
\n\
--seed seeds both the sampler and the random parts of the bounds\n\
(star-lower, star-bounds). Output: a table (metric, value, method, time)\n\
or, with --json, one JSON object {source, points, dims, results: [...]}\n\
where each result has metric, value (or lower/upper), method and seconds.\n\
";

/// The arguments of `discrepancy`.
#[derive(Debug, Args)]
pub struct DiscrepancyArgs {
    /// Sampler name (see `lowdisc points --help`) [required unless --input].
    #[arg(
        long,
        short = 's',
        value_name = "NAME",
        required_unless_present = "input"
    )]
    sampler: Option<String>,
    /// Read the points from FILE instead of a sampler [required unless --sampler].
    #[arg(long, short = 'i', value_name = "FILE", conflicts_with_all = ["sampler", "n", "dims", "dim_range", "threshold"])]
    input: Option<PathBuf>,
    /// Number of points [default: 256].
    #[arg(long, short = 'n', value_name = "N")]
    n: Option<u32>,
    /// Number of dimensions 0..D [default: 2].
    #[arg(long, value_name = "D", conflicts_with = "dim_range")]
    dims: Option<u32>,
    /// Dimensions A up to but excluding B.
    #[arg(long, value_name = "A..B", allow_hyphen_values = true)]
    dim_range: Option<String>,
    /// Seed of the sampler and of the bounds' random boxes.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Paper permutation threshold in [0,1].
    #[arg(long, allow_negative_numbers = true)]
    threshold: Option<f64>,
    /// The metric.
    #[arg(long, short = 'm', value_enum, default_value = "all")]
    metric: Metric,
    /// Random anchored boxes of the paper's lower bound.
    #[arg(long, default_value_t = 10_000)]
    boxes: usize,
    /// Largest estimated work (elementary operations) accepted by any metric.
    #[arg(long, default_value_t = limits::DEFAULT_MAX_WORK)]
    max_work: f64,
    /// Largest memory (MiB) the point set may take.
    #[arg(long, value_name = "MIB", default_value_t = limits::DEFAULT_MAX_MEMORY_MIB)]
    max_memory: u64,
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
    /// No progress on stderr (shown for sets of 20000 points or more).
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// Where the points come from.
#[derive(Debug, Clone)]
pub enum Source {
    /// A catalog sequence.
    Sampler {
        /// The sampler.
        config: SamplerConfig,
        /// Number of points.
        n: u32,
        /// Dimensions.
        dims: std::ops::Range<u32>,
    },
    /// A point file.
    File(PathBuf),
}

/// A validated `discrepancy` invocation.
#[derive(Debug, Clone)]
pub struct DiscrepancyConfig {
    source: Source,
    metric: Metric,
    options: rows::Options,
    max_memory: u64,
    json: bool,
    quiet: bool,
}

/// Point sets at least this large show their progress on stderr.
const LARGE: usize = 20_000;

impl DiscrepancyArgs {
    /// Checks every option and builds the configuration.
    pub fn into_config(self) -> Result<DiscrepancyConfig> {
        let source = match (self.input, self.sampler) {
            (Some(path), _) => Source::File(path),
            (None, Some(name)) => {
                let threshold = self.threshold.unwrap_or(SamplerConfig::DEFAULT_THRESHOLD);
                let config = parse::sampler_config(&name, self.seed, threshold, false)?;
                let n = self.n.unwrap_or(256);
                if n == 0 {
                    bail!("--n must be at least 1");
                }
                let dims = parse::dims(self.dim_range.as_deref(), self.dims)?;
                Source::Sampler { config, n, dims }
            }
            (None, None) => bail!("give --sampler NAME or --input FILE"),
        };
        limits::check_max_work(self.max_work)?;
        if let Source::Sampler { n, dims, .. } = &source {
            let bytes = lowdisc_metrics::cost::points_memory(*n as usize, dims.len());
            limits::check_memory("the point set", bytes, self.max_memory)?;
        }
        Ok(DiscrepancyConfig {
            source,
            metric: self.metric,
            options: rows::Options {
                boxes: self.boxes,
                seed: self.seed,
                max_work: self.max_work,
            },
            max_memory: self.max_memory,
            json: self.json,
            quiet: self.quiet,
        })
    }
}

/// The JSON document of `discrepancy --json`.
#[derive(Debug, Serialize)]
struct Report<'a> {
    source: String,
    points: usize,
    dims: usize,
    results: &'a [MetricRow],
}

/// Runs `discrepancy`, printing to `out`.
pub fn run(config: &DiscrepancyConfig, mut out: impl Write) -> Result<()> {
    let (points, source) = load(&config.source, config.max_memory)?;
    let progress = Reporter::new(config.quiet || points.len() < LARGE);
    progress.begin_stage(
        &format!(
            "discrepancy of {} points in {} dimensions",
            points.len(),
            points.dims()
        ),
        rows::computations(config.metric),
        "metrics",
    );
    let rows = rows::compute(&points, config.metric, &config.options, &progress)?;
    progress.end_stage();
    if config.json {
        let report = Report {
            source,
            points: points.len(),
            dims: points.dims(),
            results: &rows,
        };
        serde_json::to_writer_pretty(&mut out, &report)?;
        writeln!(out)?;
    } else {
        writeln!(
            out,
            "{} points in {} dimensions from {source}",
            points.len(),
            points.dims()
        )?;
        rows::write_table(&mut out, &rows)?;
    }
    out.flush()?;
    Ok(())
}

/// The point set and a description of its source.
fn load(source: &Source, max_memory: u64) -> Result<(PointSet, String)> {
    match source {
        Source::File(path) => Ok((
            pointfile::read_points(path, max_memory)?,
            format!("file {}", path.display()),
        )),
        Source::Sampler { config, n, dims } => {
            let points = pointfile::sequence_points(config, *n, dims.clone(), Order::Natural)?;
            let mut text = format!(
                "sampler {}, seed {}, dims {}..{}",
                config.name, config.seed, dims.start, dims.end
            );
            if matches!(
                config.name,
                lowdisc::catalog::SamplerName::Paper | lowdisc::catalog::SamplerName::PaperRepro
            ) {
                text.push_str(&format!(", threshold {}", config.threshold));
            }
            Ok((points, text))
        }
    }
}
