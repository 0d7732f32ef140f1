//! The report's section "Can the samplers be told apart?": for each sampler
//! the masked MSE's mean ± standard error and 95 % interval, and for each
//! compared metric the paired ratio to the baseline with its interval,
//! marked "not distinguishable" when the interval contains 1.

use std::fmt::Write as _;

use crate::comparison::BASELINE;
use crate::config::ExperimentConfig;
use crate::results::MetricStats;
use crate::results::Results;
use crate::stats::{PairedRatio, Verdict};

/// `0.912 [0.88, 0.95]`, with "(n.d.)" when not distinguishable.
fn ratio_cell(r: Option<&PairedRatio>) -> String {
    match r {
        None => "-".into(),
        Some(r) => {
            let mark = match r.verdict {
                Verdict::NotDistinguishable => " (n.d.)",
                _ => "",
            };
            format!("{:.3} [{:.3}, {:.3}]{mark}", r.ratio, r.ci95[0], r.ci95[1])
        }
    }
}

fn find<'a>(stats: &'a [MetricStats], metric: &str) -> Option<&'a MetricStats> {
    stats.iter().find(|m| m.metric == metric)
}

/// The section's Markdown.
pub fn section(config: &ExperimentConfig, results: &Results) -> String {
    let mut md = format!(
        "\n## Can the samplers be told apart?\n\n\
Masked metrics leave out every pixel whose camera rays first hit an emitter (area lights, and the sky of an \
environment light), plus a border of {} pixels: {:.1} % of the pixels are kept. The blurred MSE blurs the error \
image by a Gaussian of σ = {} pixels before squaring (normalised convolution over the kept pixels); FLIP is \
NVIDIA's LDR FLIP at 67 pixels per degree on the 8-bit sRGB images. Mean ± standard error over the {} runs, \
95 % interval from Student's t. Ratios are to `{BASELINE}` from paired seeds (run i of both with seed i): the \
geometric mean of the per-seed ratios with its 95 % t interval on the log scale; **(n.d.)** marks a sampler not \
distinguishable from `{BASELINE}` (the interval contains 1). A deterministic sampler has no scatter over seeds.\n\n\
| sampler | masked MSE (mean ± SE) | 95 % CI | masked MSE / {BASELINE} | verdict | masked relMSE / {BASELINE} | blurred MSE / {BASELINE} | FLIP (mean ± SE) | FLIP / {BASELINE} | MSE / {BASELINE} |\n\
|---|---|---|---|---|---|---|---|---|---|\n",
        config.emitter_border,
        100.0 * results.kept_fraction,
        config.blur_sigma,
        config.runs,
    );
    for s in &results.samplers {
        let st = &s.statistics;
        let ratio = |m: &str| ratio_cell(find(st, m).and_then(|m| m.ratio_to_baseline.as_ref()));
        let (Some(mse), Some(flip)) = (find(st, "masked_mse"), find(st, "flip")) else {
            continue;
        };
        let verdict = match (&mse.ratio_to_baseline, s.name == BASELINE) {
            (_, true) => "baseline".to_string(),
            (Some(r), _) => r.verdict.as_str().to_string(),
            (None, _) => "-".to_string(),
        };
        let (m, f) = (mse.summary, flip.summary);
        let _ = writeln!(
            md,
            "| {} | {:.4e} ± {:.1e} | [{:.4e}, {:.4e}] | {} | {verdict} | {} | {} | {:.4} ± {:.4} | {} | {} |",
            s.name,
            m.mean,
            m.se,
            m.ci95[0],
            m.ci95[1],
            ratio("masked_mse"),
            ratio("masked_relmse"),
            ratio("blurred_mse"),
            f.mean,
            f.se,
            ratio("flip"),
            ratio("mse"),
        );
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::paired_ratio;

    #[test]
    fn cells_say_when_not_distinguishable() {
        let nd = paired_ratio(&[1.0, 4.0], &[2.0, 2.0]).unwrap();
        assert!(ratio_cell(Some(&nd)).ends_with("(n.d.)"));
        let better = paired_ratio(&[0.9, 1.8, 2.71], &[1.0, 2.0, 3.0]).unwrap();
        let cell = ratio_cell(Some(&better));
        assert!(cell.starts_with("0.90") && !cell.contains("n.d."), "{cell}");
        assert_eq!(ratio_cell(None), "-");
    }
}
