//! `report.md`: the answer to the paper's question ([`super::answer`]),
//! the settings, the summary table (the deciding columns:
//! error ratio to `sobol` with its interval, relMSE, time), a details table
//! with every other metric, the images side by side per sampler, the
//! convergence plot, the threshold sweep and the figure, in Markdown.
//! Every sentence that depends on the results is written from them.

use std::fmt::Write as _;

use super::answer::Answer;
use super::charts::slope_text;
use crate::comparison::relmse_ratio;
use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::results::{Results, SamplerResult};
use crate::stats::{MeanSd, PairedRatio, Verdict};

/// Render times whose sd over a sampler's runs exceeds this fraction of
/// their mean get a note.
const TIME_SPREAD_NOTE: f64 = 0.1;

/// An image linked to its full-size file.
fn image(alt: &str, file: &str) -> String {
    format!("[![{alt}]({file})]({file})")
}

fn ms(m: MeanSd) -> String {
    format!("{:.4e} ± {:.1e}", m.mean, m.sd)
}

/// The paired relMSE ratio to `sobol` with its interval (the statistics'
/// `relmse` entry), bold when the interval excludes 1; without one (a
/// single run, or `sobol` itself) the ratio of the means alone.
fn ratio_cell(s: &SamplerResult) -> String {
    match (relmse_ratio(s), s.relmse_ratio_to_sobol) {
        (Some(p), _) => paired_cell(p),
        (None, Some(r)) => format!("{r:.3}"),
        (None, None) => "-".into(),
    }
}

/// A paired ratio with its interval, the ratio bold when the interval
/// excludes 1.
fn paired_cell(p: &PairedRatio) -> String {
    let ratio = format!("{:.3}", p.ratio);
    let ratio = match p.verdict {
        Verdict::NotDistinguishable => ratio,
        _ => format!("**{ratio}**"),
    };
    format!("{ratio} ({:.3} to {:.3})", p.ci95[0], p.ci95[1])
}

fn summary_table(results: &Results) -> String {
    let mut t = String::from(
        "| sampler | relMSE / sobol, paired (95 % interval) | relMSE (linear) | time (s) | convergence slope |\n|---|---|---|---|---|\n",
    );
    for s in &results.samplers {
        let slope = slope_text(s);
        let _ = writeln!(
            t,
            "| {} | {} | {} | {:.3} ± {:.3} | {slope} |",
            s.name,
            ratio_cell(s),
            ms(s.relmse),
            s.time_s.mean,
            s.time_s.sd,
        );
    }
    t
}

fn details_table(results: &Results) -> String {
    let mut t = String::from(
        "| sampler | MSE | RMSE | MAE | sRGB8 MSE | sRGB8 relMSE | sRGB8 RMSE | sRGB8 MAE | identical runs |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for s in &results.samplers {
        let _ = writeln!(
            t,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            s.name,
            ms(s.mse),
            ms(s.rmse),
            ms(s.mae),
            ms(s.srgb8.mse),
            ms(s.srgb8.relmse),
            ms(s.srgb8.rmse),
            ms(s.srgb8.mae),
            if s.deterministic { "yes" } else { "no" }
        );
    }
    t
}

/// The sentences about the results: which samplers gave identical runs,
/// and how much the times vary.
fn notes(results: &Results) -> String {
    let mut out = String::new();
    let same: Vec<&str> = results
        .samplers
        .iter()
        .filter(|s| s.deterministic)
        .map(|s| s.name.as_str())
        .collect();
    if !same.is_empty() {
        let _ = write!(
            out,
            "{} gave bit-identical images in every run (deterministic samplers): their runs differ only in time, so their sd is 0. ",
            same.join(", ")
        );
    }
    let spread = results
        .samplers
        .iter()
        .filter(|s| s.time_s.mean > 0.0)
        .map(|s| (s.time_s.sd / s.time_s.mean, s.name.as_str()))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    out.push_str("Times are wall-clock render times on this machine and change with its load");
    match spread {
        Some((cv, name)) if cv > TIME_SPREAD_NOTE => {
            let _ = write!(
                out,
                "; here they vary by up to {:.0} % between runs ({name}), so only time differences well beyond that mean anything.",
                100.0 * cv
            );
        }
        _ => out.push_str(": compare them within one report only."),
    }
    out
}

/// The report's Markdown; `heat_top` is the error at the top of every
/// heatmap's colour bar.
pub fn markdown(config: &ExperimentConfig, results: &Results, wall: f64, heat_top: f64) -> String {
    let [w, h] = config.resolution;
    let mut scene = config.scene.as_ref().map_or(
        "built-in scene (gold, aluminium, car-paint coated shapes, procedural sky)".to_string(),
        |p| format!("`{}`", p.display()),
    );
    if let Some(p) = config.preset {
        scene = format!("preset `{}`: {}", p.name(), p.description());
    }
    if let Some(e) = &config.envmap {
        let _ = write!(
            scene,
            ", with the environment map `{}` substituted for the scene's own sky",
            e.display()
        );
    }
    let mut md = format!(
        "# Does the paper's permuted Sobol beat Sobol?\n\n{}## Settings\n\nScene: {scene}. {w}x{h}, {} spp, {} runs per sampler (seeds 0..{}), max depth {}. \
Reference: {} spp with `{}` (seed {REF_SEED}), {}. Wall time {wall:.1} s.\n\n\
## Summary\n\n\
The deciding column is the linear relMSE relative to `sobol`'s, the paper's baseline (below 1: fewer errors than Sobol), \
from paired seeds (run i of both with seed i): the geometric mean of the per-seed ratios and its 95 % t interval \
(the `relmse` entry of the statistics below; with one run, the ratio of the means). \
Errors are against the reference; ± is the sample standard deviation over runs. \
relMSE is `(x-r)^2/(r^2+0.01)` averaged over pixels and channels. \
The slope is the least-squares log-log slope of relMSE against spp (spp 1..{}, at {}x{} against a {}-spp reference), \
fitted for each of {} seeds (0..{}): their mean and its 95 % t interval.\n\n",
        Answer::of(config, results).markdown(),
        config.spp,
        config.runs,
        config.runs,
        config.max_depth,
        config.ref_spp,
        REF_SAMPLER.as_str(),
        if results.reference.cached {
            "reused from the cache"
        } else {
            "rendered now and cached"
        },
        config.conv_max,
        config.conv_res[0],
        config.conv_res[1],
        config.conv_ref_spp,
        config.conv_seeds,
        config.conv_seeds
    );
    md.push_str(&summary_table(results));
    let _ = write!(
        md,
        "\n{}\n\n## Details\n\nThe other metrics, mean ± sd over the runs; sRGB8 metrics are on 8-bit codes.\n\n",
        notes(results)
    );
    md.push_str(&details_table(results));
    md.push_str(&super::statistics::section(config, results));
    let _ = write!(
        md,
        "\n## Images\n\nEach row: the seed-0 render, its central quarter magnified {}x, and its per-pixel relative squared error \
(channel mean; viridis on one scale for every sampler, 0 to {heat_top:.3e}, the 99th percentile of all samplers' errors; \
brighter is worse, larger errors show as the top colour). Click an image for its full size.\n\n\
| sampler | render | crop | relative squared error |\n|---|---|---|---|\n",
        super::images::CROP_ZOOM
    );
    let _ = writeln!(
        md,
        "| reference | {} | {} | |",
        image("reference", "reference.png"),
        image("reference crop", "reference_crop.png")
    );
    for s in &results.samplers {
        let n = &s.name;
        let _ = writeln!(
            md,
            "| {n} | {} | {} | {} |",
            image(n, &format!("{n}.png")),
            image(&format!("{n} crop"), &format!("{n}_crop.png")),
            image(&format!("{n} error"), &format!("{n}_relse.png"))
        );
    }
    let _ = write!(
        md,
        "\n## Convergence\n\n{}\n",
        image("convergence", "convergence.png")
    );
    md.push_str("\n## Threshold sweep (paper's method)\n\n\
`paper-repro` rendered at each threshold (the probability that a generator-matrix column is left unflipped; \
1 is plain Sobol), mean ± sd over the runs' seeds, its ratio to `sobol`'s from paired seeds with the 95 % \
interval (plotted as error bars, beside the paper's claimed ratio), and the star discrepancy of one pixel's \
film positions (dimensions 0-1, permuted too).\n\n");
    md.push_str(&image("threshold sweep", "threshold_sweep.png"));
    md.push_str("\n\n| threshold | relMSE (linear) | relMSE / sobol, paired (95 % interval) | relMSE (sRGB8) | star discrepancy |\n|---|---|---|---|---|\n");
    for p in &results.threshold_sweep {
        let ratio = p.ratio_to_sobol.as_ref().map_or("-".into(), paired_cell);
        let _ = writeln!(
            md,
            "| {} | {} | {ratio} | {} | {:.5} |",
            p.threshold,
            ms(p.relmse),
            ms(p.srgb8_relmse),
            p.star_discrepancy
        );
    }
    let _ = write!(
        md,
        "\n## The paper's figure\n\n{}\n",
        image("figure", "figure.png")
    );
    md.push_str("\n## results.json\n\n\
`{schema, command, version, git_hash, machine: {cpu, cores}, settings, reference: {file, cached, time_s}, \
convergence_reference: {file, cached, time_s}, \
samplers: [{name, description, deterministic, time_s, mse, relmse, rmse, mae, srgb8: {mse, relmse, rmse, mae}, \
relmse_ratio_to_sobol, relmse_ratio_interval, statistics: [{metric, summary: {n, mean, sd, se, ci95}, ratio_to_baseline: \
{n, ratio, ci95, log_ratio, ratio_of_means, verdict} or null}], \
runs: [{seed, time_s, linear, srgb8, quality: {masked, blurred_mse, flip}}], convergence: [{spp, relmse, relmse_ci95, relmse_seeds}], convergence_slope, convergence_slope_ci95, convergence_slopes}], \
threshold_sweep: [{threshold, star_discrepancy, relmse, srgb8_relmse, ratio_to_sobol}], kept_fraction, wall_time_s, \
answer: {claimed_ratio, claimed_spp, verdict, paper: {sampler, ratio, ci95}, best: {sampler, ratio, ci95}, line}}`; \
the other metric summaries are `{mean, sd}`.\n");
    md
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::{result, results};

    #[test]
    fn identical_runs_are_named_only_when_there_are_some() {
        let mut a = result("sobol", 1.0);
        let b = result("zsobol", 0.5);
        let none = notes(&results(vec![a.clone(), b.clone()]));
        assert!(
            !none.contains("bit-identical") && !none.contains("deterministic"),
            "{none}"
        );
        a.deterministic = true;
        let one = notes(&results(vec![a, b]));
        assert!(one.starts_with("sobol gave bit-identical images"), "{one}");
    }

    #[test]
    fn a_large_time_spread_gets_its_figure() {
        let mut a = result("sobol", 1.0);
        a.time_s = MeanSd { mean: 2.0, sd: 0.5 };
        let text = notes(&results(vec![a.clone()]));
        assert!(
            text.contains("vary by up to 25 % between runs (sobol)"),
            "{text}"
        );
        a.time_s.sd = 0.1;
        let calm = notes(&results(vec![a]));
        assert!(!calm.contains("vary by up to"), "{calm}");
    }

    #[test]
    fn the_summary_table_leads_with_the_paired_ratio_and_its_interval() {
        let mut a = result("zsobol", 0.5);
        a.relmse_ratio_to_sobol = Some(0.8);
        let one_run = summary_table(&results(vec![a.clone()]));
        assert!(one_run.contains("| zsobol | 0.800 |"), "{one_run}");
        // The paired entry, not the ratio of the means, when there is one.
        let (seeds, base) = ([1.0, 2.0, 4.0], [2.0, 4.0, 8.0]);
        let paired = crate::stats::paired_ratio(&seeds, &base).unwrap();
        a.statistics = vec![crate::results::MetricStats {
            metric: "relmse",
            summary: crate::stats::Summary::of(&seeds),
            ratio_to_baseline: Some(paired),
        }];
        let t = summary_table(&results(vec![a]));
        let header = t.lines().next().unwrap();
        assert!(
            header.starts_with("| sampler | relMSE / sobol, paired (95 % interval) |"),
            "{t}"
        );
        assert!(t.contains("| zsobol | **0.500** (0.500 to 0.500) |"), "{t}");
        // An interval that contains 1 is not bold.
        let (seeds, base) = ([1.0, 2.0, 4.0], [2.0, 1.0, 4.0]);
        a = result("halton", 1.0);
        a.statistics = vec![crate::results::MetricStats {
            metric: "relmse",
            summary: crate::stats::Summary::of(&seeds),
            ratio_to_baseline: crate::stats::paired_ratio(&seeds, &base),
        }];
        let t = summary_table(&results(vec![a]));
        assert!(t.contains("| halton | 1.000 ("), "{t}");
        assert!(!t.contains("**"), "{t}");
    }

    #[test]
    fn the_notes_speak_of_this_run_only() {
        let text = notes(&results(vec![result("sobol", 1.0)]));
        assert!(!text.contains("busy machine"), "{text}");
    }
}
