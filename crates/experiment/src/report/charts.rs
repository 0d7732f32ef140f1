//! The report's charts: the convergence plot, the threshold sweep and the
//! paper's 2x2-pixel point figure.

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_plot::{LineChart, Series};

use crate::config::ExperimentConfig;
use crate::results::Results;

/// Writes `convergence.png`, `threshold_sweep.png` and `figure.png`.
pub fn write_charts(config: &ExperimentConfig, results: &Results) -> Result<()> {
    let mut chart = LineChart::log_log("relMSE vs samples per pixel", "spp", "relMSE (linear)");
    for s in &results.samplers {
        let pts = s
            .convergence
            .iter()
            .map(|c| [f64::from(c.spp), c.relmse])
            .collect();
        let slope = s
            .convergence_slope
            .map_or("-".into(), |v| format!("{v:.2}"));
        chart = chart.with(Series::new(format!("{} (slope {slope})", s.name), pts));
    }
    chart.to_canvas().save(config.out.join("convergence.png"))?;
    let sweep_chart = |title: &str, y: &str, name: String, pts: Vec<[f64; 2]>| {
        let mut c = LineChart::log_log(title, "threshold", y);
        c.x_log = false;
        c.y_log = false;
        c.size = [520, 360];
        c.with(Series::new(name, pts)).to_canvas()
    };
    let sweep = &results.threshold_sweep;
    let error = sweep_chart(
        "paper-repro: relMSE vs threshold",
        "relMSE (linear)",
        format!("{} spp, mean of {} runs", config.spp, config.runs),
        sweep.iter().map(|p| [p.threshold, p.relmse.mean]).collect(),
    );
    let disc = sweep_chart(
        "paper-repro: D* of one pixel",
        "D*",
        format!("{} samples", config.spp),
        sweep
            .iter()
            .map(|p| [p.threshold, p.star_discrepancy])
            .collect(),
    );
    lowdisc_plot::compose::grid(vec![vec![error, disc]])
        .save(config.out.join("threshold_sweep.png"))?;
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
    crate::figure::figure(&panels, 260.0, title)?.save(config.out.join("figure.png"))?;
    Ok(())
}
