//! `report.md`: the settings, the summary table, the images, the
//! convergence plot, the threshold sweep and the figure, in Markdown.

use std::fmt::Write as _;

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::results::Results;
use crate::stats::MeanSd;

fn ms(m: MeanSd) -> String {
    format!("{:.4e} ± {:.1e}", m.mean, m.sd)
}

fn table(results: &Results) -> String {
    let mut t = String::from(
        "| sampler | time (s) | MSE | relMSE | RMSE | MAE | sRGB8 MSE | sRGB8 relMSE | sRGB8 RMSE | sRGB8 MAE | relMSE / sobol | slope |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for s in &results.samplers {
        let r = s
            .relmse_ratio_to_sobol
            .map_or("-".into(), |v| format!("{v:.3}"));
        let slope = s
            .convergence_slope
            .map_or("-".into(), |v| format!("{v:.2}"));
        let det = if s.deterministic {
            " (deterministic)"
        } else {
            ""
        };
        let _ = writeln!(
            t,
            "| {}{det} | {:.3} ± {:.3} | {} | {} | {} | {} | {} | {} | {} | {} | {r} | {slope} |",
            s.name,
            s.time_s.mean,
            s.time_s.sd,
            ms(s.mse),
            ms(s.relmse),
            ms(s.rmse),
            ms(s.mae),
            ms(s.srgb8.mse),
            ms(s.srgb8.relmse),
            ms(s.srgb8.rmse),
            ms(s.srgb8.mae)
        );
    }
    t
}

/// The report's Markdown.
pub fn markdown(config: &ExperimentConfig, results: &Results, wall: f64) -> String {
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
        "# lowdisc experiment\n\nScene: {scene}. {w}x{h}, {} spp, {} runs per sampler (seeds 0..{}), max depth {}. \
Reference: {} spp with `{}` (seed {REF_SEED}), {}. Wall time {wall:.1} s.\n\n\
Errors are against the reference; ± is the sample standard deviation over runs. \
A sampler marked deterministic gave bit-identical images in every run: its runs differ only in time. \
relMSE is `(x-r)^2/(r^2+0.01)` averaged over pixels and channels; sRGB8 metrics are on 8-bit codes. \
The slope is the least-squares log-log slope of relMSE against spp (seed 0, spp 1..{}, at {}x{} against a {}-spp reference).\n\n",
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
        config.conv_ref_spp
    );
    md.push_str(&table(results));
    md.push_str(&super::statistics::section(config, results));
    md.push_str("\n## Images\n\nEach render is the seed-0 run; the crop is the central quarter magnified 4x; the heatmap is the per-pixel relative squared error (viridis, scaled to its 99th percentile).\n\n| sampler | render | crop | relative squared error |\n|---|---|---|---|\n");
    md.push_str("| reference | ![](reference.png) | ![](reference_crop.png) | |\n");
    for s in &results.samplers {
        let n = &s.name;
        let _ = writeln!(
            md,
            "| {n} | ![]({n}.png) | ![]({n}_crop.png) | ![]({n}_relse.png) |"
        );
    }
    md.push_str("\n## Convergence\n\n![](convergence.png)\n\n## Threshold sweep (paper's method)\n\n\
`paper-repro` rendered at each threshold (the probability that a generator-matrix column is left unflipped; \
1 is plain Sobol), mean ± sd over the runs' seeds, and the star discrepancy of one pixel's film positions \
(dimensions 0-1, permuted too).\n\n\
![](threshold_sweep.png)\n\n| threshold | relMSE (linear) | relMSE (sRGB8) | star discrepancy |\n|---|---|---|---|\n");
    for p in &results.threshold_sweep {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.5} |",
            p.threshold,
            ms(p.relmse),
            ms(p.srgb8_relmse),
            p.star_discrepancy
        );
    }
    md.push_str("\n## The paper's figure\n\n![](figure.png)\n\n## results.json\n\n\
`{schema, command, version, git_hash, machine: {cpu, cores}, settings, reference: {file, cached, time_s}, \
convergence_reference: {file, cached, time_s}, \
samplers: [{name, description, deterministic, time_s, mse, relmse, rmse, mae, srgb8: {mse, relmse, rmse, mae}, \
relmse_ratio_to_sobol, statistics: [{metric, summary: {n, mean, sd, se, ci95}, ratio_to_baseline: \
{n, ratio, ci95, log_ratio, ratio_of_means, verdict} or null}], \
runs: [{seed, time_s, linear, srgb8, quality: {masked, blurred_mse, flip}}], convergence: [{spp, relmse}], convergence_slope}], \
threshold_sweep: [{threshold, star_discrepancy, relmse, srgb8_relmse}], kept_fraction, wall_time_s}`; \
the other metric summaries are `{mean, sd}`.\n");
    md
}
