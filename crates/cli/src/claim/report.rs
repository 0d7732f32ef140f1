//! The files of `paper-claim`: markdown tables (`claim.md`), the numbers as
//! JSON (`claim.json`) and log-log charts per dimension pair.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::Result;
use lowdisc_plot::{Color, LineChart, Series};
use serde::Serialize;

use lowdisc_experiment::stats::MeanSd;

use super::measure::{ClaimConfig, ClaimRow};

/// The three measured quantities: file stem, title, accessor.
type Quantity = (&'static str, &'static str, fn(&ClaimRow) -> MeanSd);

const QUANTITIES: [Quantity; 3] = [
    ("dstar", "Star discrepancy D*_N (exact)", |r| r.star),
    ("mindist", "Minimum Euclidean distance", |r| r.min_euclidean),
    ("mindist_toroidal", "Minimum toroidal distance", |r| {
        r.min_toroidal
    }),
];

/// `v` with four significant digits: fixed notation, scientific below 1e-4.
pub fn significant(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    if v.abs() < 1e-4 {
        return format!("{v:.3e}");
    }
    let decimals = (3 - v.abs().log10().floor() as i32).max(0) as usize;
    format!("{v:.decimals$}")
}

/// The JSON document.
#[derive(Debug, Serialize)]
struct Document<'a> {
    seeds: u64,
    ns: &'a [u32],
    seconds: f64,
    rows: &'a [ClaimRow],
}

/// Labels in table order (first appearance).
fn labels(rows: &[ClaimRow]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for r in rows {
        if !out.contains(&r.label) {
            out.push(r.label.clone());
        }
    }
    out
}

/// The markdown report.
pub fn markdown(config: &ClaimConfig, rows: &[ClaimRow], seconds: f64) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# The paper's claim, measured: star discrepancy and minimum distance\n\n\
         First N points (natural order) of each sampler in each dimension pair. \
         Randomized samplers: mean ± sample standard deviation over seeds 0..{}; \
         `sobol` is deterministic (one run). D*_N is exact (2-D sweep); distances \
         are exact minima over all pairs. Measured in {seconds:.1} s.\n",
        config.seeds
    );
    let names = labels(rows);
    for pair in &config.pairs {
        let _ = writeln!(md, "## Dimensions {}, {}\n", pair.start, pair.start + 1);
        for (_, title, get) in QUANTITIES {
            let _ = writeln!(md, "### {title}\n");
            let mut header = String::from("| sampler |");
            let mut rule = String::from("|---|");
            for n in &config.ns {
                let _ = write!(header, " N = {n} |");
                rule.push_str("---:|");
            }
            let _ = writeln!(md, "{header}\n{rule}");
            for name in &names {
                let mut line = format!("| {name} |");
                for &n in &config.ns {
                    let cell = rows
                        .iter()
                        .find(|r| &r.label == name && r.n == n && r.dims[0] == pair.start);
                    match cell {
                        Some(r) if r.runs > 1 => {
                            let s = get(r);
                            let _ =
                                write!(line, " {} ± {} |", significant(s.mean), significant(s.sd));
                        }
                        Some(r) => {
                            let _ = write!(line, " {} |", significant(get(r).mean));
                        }
                        None => line.push_str(" - |"),
                    }
                }
                let _ = writeln!(md, "{line}");
            }
            md.push('\n');
        }
    }
    md
}

/// Colour and dash of each label's line, in label order: `paper` and
/// `paper-repro` at the same threshold share a colour (`paper-repro`
/// dashed), every other sampler has its own palette colour.
fn series_styles(rows: &[ClaimRow]) -> Vec<(Color, bool)> {
    let mut thresholds: Vec<u64> = Vec::new();
    let mut others: Vec<String> = Vec::new();
    let mut styles = Vec::new();
    let names = labels(rows);
    for name in &names {
        let row = rows
            .iter()
            .find(|r| &r.label == name)
            .expect("a row per label");
        let style = match row.threshold {
            Some(t) => {
                let bits = t.to_bits();
                let k = thresholds
                    .iter()
                    .position(|&b| b == bits)
                    .unwrap_or_else(|| {
                        thresholds.push(bits);
                        thresholds.len() - 1
                    });
                (k, row.sampler == "paper-repro")
            }
            None => {
                others.push(name.clone());
                (usize::MAX - others.len() + 1, false)
            }
        };
        styles.push(style);
    }
    // Paper thresholds take the colours after the first other sampler (sobol).
    let paper_colours = thresholds.len();
    styles
        .into_iter()
        .map(|(k, dashed)| {
            let index = if k > usize::MAX / 2 {
                let other = usize::MAX - k;
                if other == 0 { 0 } else { other + paper_colours }
            } else {
                1 + k
            };
            (Color::palette(index), dashed)
        })
        .collect()
}

/// A log-log chart of one quantity against N for one pair.
fn chart(
    config: &ClaimConfig,
    rows: &[ClaimRow],
    pair_start: u32,
    quantity: &Quantity,
) -> LineChart {
    let (stem, title, get) = quantity;
    let mut chart = LineChart::log_log(
        format!("{title}, dimensions {}, {}", pair_start, pair_start + 1),
        "number of points N",
        if *stem == "dstar" {
            "D*_N"
        } else {
            "minimum distance"
        },
    );
    chart.size = [960, 640];
    let styles = series_styles(rows);
    for (name, (color, dashed)) in labels(rows).into_iter().zip(styles) {
        let points: Vec<[f64; 2]> = rows
            .iter()
            .filter(|r| r.label == name && r.dims[0] == pair_start)
            .map(|r| [f64::from(r.n), get(r).mean])
            .collect();
        let mut series = Series::new(name, points);
        series.color = Some(color);
        series.dashed = dashed;
        chart = chart.with(series);
    }
    let (lo, hi) = (
        f64::from(*config.ns.iter().min().unwrap_or(&1)),
        f64::from(*config.ns.iter().max().unwrap_or(&1)),
    );
    chart.with(if *stem == "dstar" {
        Series::reference("1/N", vec![[lo, 1.0 / lo], [hi, 1.0 / hi]])
    } else {
        Series::reference("1/sqrt(N)", vec![[lo, lo.powf(-0.5)], [hi, hi.powf(-0.5)]])
    })
}

fn write_file(path: &Path, contents: &str) -> Result<()> {
    Ok(lowdisc_files::write_bytes(path, contents.as_bytes())?)
}

/// Writes `claim.md`, `claim.json` and the charts; returns the paths written.
pub fn write_all(config: &ClaimConfig, rows: &[ClaimRow], seconds: f64) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    let md = config.out.join("claim.md");
    write_file(&md, &markdown(config, rows, seconds))?;
    written.push(md);
    let json = config.out.join("claim.json");
    let doc = Document {
        seeds: config.seeds,
        ns: &config.ns,
        seconds,
        rows,
    };
    write_file(&json, &(serde_json::to_string_pretty(&doc)? + "\n"))?;
    written.push(json);
    for pair in &config.pairs {
        for quantity in &QUANTITIES {
            let path = config.out.join(format!(
                "{}_dims{}-{}.{}",
                quantity.0,
                pair.start,
                pair.start + 1,
                config.plot_format
            ));
            chart(config, rows, pair.start, quantity)
                .to_canvas()
                .save(&path)?;
            written.push(path);
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_significant_digits() {
        assert_eq!(significant(0.000612345), "0.0006123");
        assert_eq!(significant(0.5), "0.5000");
        assert_eq!(significant(12.345), "12.35");
        assert_eq!(significant(0.0), "0");
        assert_eq!(significant(2.3283e-10), "2.328e-10");
    }
}
