//! `lowdisc spectrum`: radially averaged power spectra of several samplers'
//! 2-D point sets in one picture (one row per sampler: the points, then the
//! spectrum as a line chart), the numbers saved as CSV beside the picture
//! and, with `--json`, printed as JSON.

use std::io::Write;
use std::ops::Range;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc::catalog::{Order, SamplerConfig};
use lowdisc_experiment::figure::sampler_title;
use lowdisc_metrics::{RadialSpectrum, radial_power_spectrum};
use lowdisc_plot::{LineChart, ScatterGrid, ScatterPanel, Series, compose};
use serde::Serialize;

use crate::{parse, pointfile};

/// The long help of `spectrum` (`lowdisc spectrum --help`).
pub const LONG_ABOUT: &str = "\
Radially averaged power spectra of 2-D point sets, several samplers in one\n\
picture: each sampler is a row with its points (dimensions A, A+1 of the\n\
first N points, natural order) beside its spectrum.\n\
\n\
The periodogram P(k) = |sum_i exp(-2 pi i k.x_i)|^2 / N over integer\n\
frequencies k in [-K, K]^2 is averaged over rings r - 1/2 <= |k| < r + 1/2,\n\
r = 1..K; white noise gives 1 (the dashed line), blue noise less at low r.\n\
\n\
Writes FILE (.png or .svg) and FILE with extension .csv (columns sampler,\n\
radius, power, count); --json also prints the numbers to stdout.\n\
";

/// The arguments of `spectrum`.
#[derive(Debug, Args)]
pub struct SpectrumArgs {
    /// Comma-separated sampler names, one row each.
    #[arg(
        long,
        value_name = "LIST",
        default_value = "independent,sobol,sobol-owen,paper"
    )]
    samplers: String,
    /// Number of points.
    #[arg(long, short = 'n', value_name = "N", default_value_t = 1024)]
    n: u32,
    /// Seed of every random choice.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Paper permutation threshold in [0,1].
    #[arg(long, default_value_t = SamplerConfig::DEFAULT_THRESHOLD, allow_negative_numbers = true)]
    threshold: f64,
    /// The two dimensions A..B (B = A + 2).
    #[arg(
        long,
        value_name = "A..B",
        default_value = "0..2",
        allow_hyphen_values = true
    )]
    dim_range: String,
    /// Largest frequency radius K.
    #[arg(long, value_name = "K", default_value_t = 64)]
    max_frequency: usize,
    /// The picture: FILE.png or FILE.svg.
    #[arg(long, short = 'o', value_name = "FILE")]
    output: PathBuf,
    /// Also print the spectra as JSON on stdout.
    #[arg(long)]
    json: bool,
}

/// A validated `spectrum` invocation.
#[derive(Debug, Clone)]
pub struct SpectrumConfig {
    samplers: Vec<SamplerConfig>,
    n: u32,
    dims: Range<u32>,
    max_frequency: usize,
    output: PathBuf,
    json: bool,
}

/// The most points per sampler.
const MAX_POINTS: u32 = 1 << 16;

impl SpectrumArgs {
    /// Checks every option and builds the configuration.
    pub fn into_config(self) -> Result<SpectrumConfig> {
        let samplers = self
            .samplers
            .split(',')
            .map(|name| parse::sampler_config(name, self.seed, self.threshold, false))
            .collect::<Result<Vec<_>>>()?;
        if self.n < 2 || self.n > MAX_POINTS {
            bail!("--n must lie in 2..={MAX_POINTS}");
        }
        let dims = parse::dim_range(&self.dim_range)?;
        if dims.len() != 2 {
            bail!("--dim-range must span exactly two dimensions (e.g. 2..4)");
        }
        if !(1..=4096).contains(&self.max_frequency) {
            bail!("--max-frequency must lie in 1..=4096");
        }
        lowdisc_plot::Format::from_path(&self.output)?;
        Ok(SpectrumConfig {
            samplers,
            n: self.n,
            dims,
            max_frequency: self.max_frequency,
            output: self.output,
            json: self.json,
        })
    }
}

/// One sampler's spectrum, as printed by `--json`.
#[derive(Debug, Serialize)]
struct Entry {
    sampler: String,
    threshold: Option<f64>,
    seed: u64,
    dims: [u32; 2],
    spectrum: RadialSpectrum,
}

/// The CSV file written beside the picture.
pub fn csv_path(output: &Path) -> PathBuf {
    output.with_extension("csv")
}

/// Runs `spectrum`: computes, draws, writes the CSV, prints a summary or JSON.
pub fn run(config: &SpectrumConfig, mut out: impl Write) -> Result<()> {
    let mut entries = Vec::new();
    let mut rows = Vec::new();
    for sampler in &config.samplers {
        let points =
            pointfile::sequence_points(sampler, config.n, config.dims.clone(), Order::Natural)?;
        let spectrum = radial_power_spectrum(&points, config.max_frequency)?;
        let title = sampler_title(sampler);
        let xy: Vec<[f64; 2]> = points.iter().map(|p| [p[0], p[1]]).collect();
        let mut scatter = ScatterGrid::row(vec![ScatterPanel::new(
            format!(
                "{title}: {} points, dims {}, {}",
                config.n,
                config.dims.start,
                config.dims.start + 1
            ),
            xy,
        )]);
        scatter.panel_size = 360.0;
        let scatter = scatter.to_canvas();
        let mut chart = LineChart::log_log(
            format!("{title}: radially averaged power spectrum"),
            "frequency radius |k|",
            "mean periodogram",
        );
        chart.x_log = false;
        chart.size = [600, scatter.height];
        let line: Vec<[f64; 2]> = spectrum
            .radii
            .iter()
            .copied()
            .zip(spectrum.power.iter().copied())
            .map(|(r, p)| [r, p])
            .collect();
        let white = vec![[1.0, 1.0], [config.max_frequency as f64, 1.0]];
        let chart = chart
            .with(Series::new(title.clone(), line))
            .with(Series::reference("white noise (1)", white));
        rows.push(vec![scatter, chart.to_canvas()]);
        entries.push(Entry {
            sampler: sampler_title(sampler),
            threshold: matches!(
                sampler.name,
                lowdisc::catalog::SamplerName::Paper | lowdisc::catalog::SamplerName::PaperRepro
            )
            .then_some(sampler.threshold),
            seed: sampler.seed,
            dims: [config.dims.start, config.dims.start + 1],
            spectrum,
        });
    }
    compose::grid(rows).save(&config.output)?;
    let csv = csv_path(&config.output);
    std::fs::write(&csv, to_csv(&entries))
        .with_context(|| format!("cannot write `{}`", csv.display()))?;
    if config.json {
        serde_json::to_writer_pretty(&mut out, &entries)?;
        writeln!(out)?;
    } else {
        writeln!(
            out,
            "wrote {} and {}",
            config.output.display(),
            csv.display()
        )?;
        writeln!(
            out,
            "{:<18} {:>12} {:>12}",
            "sampler", "mean P r<=8", "mean P all"
        )?;
        for e in &entries {
            let low = mean(&e.spectrum.power[..e.spectrum.power.len().min(8)]);
            writeln!(
                out,
                "{:<18} {:>12.4} {:>12.4}",
                e.sampler,
                low,
                mean(&e.spectrum.power)
            )?;
        }
    }
    out.flush()?;
    Ok(())
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

/// The spectra as CSV: `sampler,radius,power,count`.
fn to_csv(entries: &[Entry]) -> String {
    let mut text = String::from("sampler,radius,power,count\n");
    for e in entries {
        let s = &e.spectrum;
        for ((r, p), c) in s.radii.iter().zip(&s.power).zip(&s.counts) {
            text.push_str(&format!("{},{r},{p},{c}\n", e.sampler));
        }
    }
    text
}
