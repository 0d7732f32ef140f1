//! The report's charts: the convergence plot, the threshold sweep and the
//! paper's 2x2-pixel point figure.

use std::path::PathBuf;

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_plot::{Color, LineChart, Series};

use super::answer::PAPER_CLAIMED_RATIO;
use crate::config::ExperimentConfig;
use crate::results::{Results, SamplerResult, SweepPoint};
use crate::stats::PairedRatio;
use crate::stats::summary::interval_factor;

/// Writes `convergence.png`, `threshold_sweep.png` and `figure.png` and
/// returns their paths.
pub fn write_charts(config: &ExperimentConfig, results: &Results) -> Result<[PathBuf; 3]> {
    let files =
        ["convergence.png", "threshold_sweep.png", "figure.png"].map(|f| config.out.join(f));
    let mut chart = LineChart::log_log("relMSE vs samples per pixel", "spp", "relMSE (linear)");
    for s in &results.samplers {
        let pts = s
            .convergence
            .iter()
            .map(|c| [f64::from(c.spp), c.relmse])
            .collect();
        let mut series = Series::new(format!("{} (slope {})", s.name, slope_text(s)), pts);
        let bars: Option<Vec<[f64; 2]>> = s.convergence.iter().map(|c| c.relmse_ci95).collect();
        // A log axis has no room for an interval reaching zero or below.
        if let Some(bars) = bars.filter(|b| b.iter().all(|b| b[0] > 0.0)) {
            series = series.with_bars(bars);
        }
        chart = chart.with(series);
    }
    chart.to_canvas().save(&files[0])?;
    let error = sweep_error_chart(config, &results.threshold_sweep);
    let disc = linear_chart(
        "paper-repro: D* of one pixel",
        "D*",
        Series::new(
            format!("{} samples", config.spp),
            results
                .threshold_sweep
                .iter()
                .map(|p| [p.threshold, p.star_discrepancy])
                .collect(),
        ),
    );
    lowdisc_plot::compose::grid(vec![vec![error.to_canvas(), disc.to_canvas()]]).save(&files[1])?;
    // The paper's figure: 2x2 pixels, `spp` samples each.
    let panels: Vec<SamplerConfig> = [
        SamplerName::Sobol,
        SamplerName::Paper,
        SamplerName::PaperRepro,
        SamplerName::ZSobol,
    ]
    .into_iter()
    .map(|name| {
        let mut c = SamplerConfig::new(name);
        c.spp = config.spp;
        c.resolution = [2, 2];
        c.threshold = config.threshold;
        c.paper_all_dims = true;
        c
    })
    .collect();
    let title = format!("2x2 pixels, {} samples per pixel", config.spp);
    crate::figure::figure(&panels, 260.0, title)?.save(&files[2])?;
    Ok(files)
}

/// A sampler's convergence slope with its 95 % interval over the seeds:
/// `-1.52 [-1.60, -1.44]`, `-1.52` for one seed, `-` without a fit.
pub fn slope_text(s: &SamplerResult) -> String {
    match (s.convergence_slope, s.convergence_slope_ci95) {
        (Some(m), Some([lo, hi])) => format!("{m:.2} [{lo:.2}, {hi:.2}]"),
        (Some(m), None) => format!("{m:.2}"),
        (None, _) => "-".into(),
    }
}

/// A chart of `series` against the threshold on linear axes, sized to be
/// read at half the page's width.
fn linear_chart(title: &str, y: &str, series: Series) -> LineChart {
    let mut c = LineChart::log_log(title, "threshold", y);
    c.x_log = false;
    c.y_log = false;
    c.size = [560, 400];
    c.with(series)
}

/// The sweep's error chart: `paper-repro`'s relMSE relative to `sobol`'s
/// from paired seeds with its 95 % interval as error bars, beside a ratio
/// of 1 (`sobol`) and the paper's claimed ratio; without a paired ratio
/// (no `sobol`, or one run) the relMSE with its 95 % interval of the mean.
fn sweep_error_chart(config: &ExperimentConfig, sweep: &[SweepPoint]) -> LineChart {
    let name = format!("{} spp, {} seeds", config.spp, config.runs);
    let ratios: Option<Vec<&PairedRatio>> =
        sweep.iter().map(|p| p.ratio_to_sobol.as_ref()).collect();
    let Some(ratios) = ratios.filter(|r| !r.is_empty()) else {
        let factor = interval_factor(config.runs as usize) / f64::from(config.runs).sqrt();
        let half = |p: &SweepPoint| factor * p.relmse.sd;
        let series = Series::new(
            name,
            sweep.iter().map(|p| [p.threshold, p.relmse.mean]).collect(),
        )
        .with_bars(
            sweep
                .iter()
                .map(|p| [p.relmse.mean - half(p), p.relmse.mean + half(p)])
                .collect(),
        );
        return linear_chart(
            "paper-repro: relMSE vs threshold",
            "relMSE (linear)",
            series,
        );
    };
    let points = sweep
        .iter()
        .zip(&ratios)
        .map(|(p, r)| [p.threshold, r.ratio])
        .collect();
    let series = Series::new(format!("paper-repro, {name}"), points)
        .with_bars(ratios.iter().map(|r| r.ci95).collect());
    let span = [0.0, 1.0];
    linear_chart(
        "paper-repro: relMSE / sobol's vs threshold",
        "relMSE / sobol (paired, 95 %)",
        series,
    )
    .with(Series::level("sobol (1)", 1.0, span, Color::GREY))
    .with(Series::level(
        format!("paper's claim ({PAPER_CLAIMED_RATIO:.2})"),
        PAPER_CLAIMED_RATIO,
        span,
        Color::palette(1),
    ))
}
