//! Writing the report folder: images (linear EXR and sRGB PNG), plots, `results.json`,
//! `report.md` and `report.html` (the same content, HTML with `<img>` tags).
//! Every file goes through a temporary file and a rename.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{
    Normalization, PixelError, RgbImage, crop, upscale_nearest, write_exr, write_png,
};
use lowdisc_plot::{LineChart, Series};
use serde_json::json;

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::results::{Images, Results, SamplerResult};
use crate::stats::MeanSd;

/// Nearest-neighbour magnification of the crops.
const CROP_ZOOM: usize = 4;

fn write_text(path: &Path, text: &str) -> Result<()> {
    lowdisc_image::io::write_bytes_atomically(path, text.as_bytes())
        .with_context(|| format!("cannot write `{}`", path.display()))
}

/// The crop window: a quarter of each side, around the image centre.
fn crop_window(w: usize, h: usize) -> [usize; 4] {
    let cw = (w / 4).max(1);
    let ch = (h / 4).max(1);
    [(w - cw) / 2, (h - ch) / 2, cw, ch]
}

/// `stem.exr` (linear radiance), `stem.png` (sRGB) and `stem_crop.png`.
fn save_with_crop(dir: &Path, stem: &str, image: &RgbImage) -> Result<()> {
    write_exr(dir.join(format!("{stem}.exr")), image)?;
    write_png(dir.join(format!("{stem}.png")), image, 1.0)?;
    let [x, y, w, h] = crop_window(image.width(), image.height());
    let c = upscale_nearest(&crop(image, x, y, w, h)?, CROP_ZOOM)?;
    write_png(dir.join(format!("{stem}_crop.png")), &c, 1.0)?;
    Ok(())
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into())
}

fn git_hash() -> Option<String> {
    let out = std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn plots(config: &ExperimentConfig, results: &Results) -> Result<()> {
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

fn markdown(config: &ExperimentConfig, results: &Results, wall: f64) -> String {
    let [w, h] = config.resolution;
    let mut scene = config.scene.as_ref().map_or(
        "built-in scene (gold, aluminium, car-paint coated shapes, procedural sky)".to_string(),
        |p| format!("`{}`", p.display()),
    );
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
relmse_ratio_to_sobol, runs: [{seed, time_s, linear, srgb8}], convergence: [{spp, relmse}], convergence_slope}], \
threshold_sweep: [{threshold, star_discrepancy, relmse, srgb8_relmse}], wall_time_s}`; every metric summary is `{mean, sd}`.\n");
    md
}

/// Minimal Markdown-to-HTML for the report's own Markdown (headings,
/// paragraphs, pipe tables and images).
fn html(md: &str) -> String {
    let esc = |s: &str| {
        s.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    let cell = |c: &str| {
        let c = c.trim();
        match c.strip_prefix("![](").and_then(|r| r.strip_suffix(')')) {
            Some(src) => format!("<img src=\"{}\" style=\"max-width:320px\">", esc(src)),
            None => esc(c),
        }
    };
    let mut out = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>lowdisc experiment</title>\
<style>body{font-family:sans-serif;max-width:1400px;margin:auto}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 6px;font-size:13px}</style></head><body>\n",
    );
    let mut in_table = false;
    for line in md.lines() {
        if line.starts_with('|') {
            if line.starts_with("|---") {
                continue;
            }
            let cells: Vec<String> = line.trim_matches('|').split('|').map(cell).collect();
            if !in_table {
                out.push_str("<table>\n<tr>");
                cells.iter().for_each(|c| {
                    let _ = write!(out, "<th>{c}</th>");
                });
                out.push_str("</tr>\n");
                in_table = true;
            } else {
                out.push_str("<tr>");
                cells.iter().for_each(|c| {
                    let _ = write!(out, "<td>{c}</td>");
                });
                out.push_str("</tr>\n");
            }
            continue;
        }
        if in_table {
            out.push_str("</table>\n");
            in_table = false;
        }
        if let Some(t) = line.strip_prefix("## ") {
            let _ = writeln!(out, "<h2>{}</h2>", esc(t));
        } else if let Some(t) = line.strip_prefix("# ") {
            let _ = writeln!(out, "<h1>{}</h1>", esc(t));
        } else if !line.is_empty() {
            let _ = writeln!(out, "<p>{}</p>", cell(line));
        }
    }
    if in_table {
        out.push_str("</table>\n");
    }
    out.push_str("</body></html>\n");
    out
}

fn json(config: &ExperimentConfig, results: &Results, wall: f64) -> Result<String> {
    let names: Vec<&str> = config.samplers.iter().map(|s| s.as_str()).collect();
    let value = json!({
        "schema": 1,
        "command": config.command,
        "version": env!("CARGO_PKG_VERSION"),
        "git_hash": git_hash(),
        "machine": {
            "cpu": cpu_model(),
            "cores": std::thread::available_parallelism().map_or(1, |n| n.get()),
        },
        "settings": {
            "scene": config.scene.as_ref().map_or("builtin".to_string(), |p| p.display().to_string()),
            "width": config.resolution[0],
            "height": config.resolution[1],
            "spp": config.spp,
            "runs": config.runs,
            "ref_spp": config.ref_spp,
            "ref_sampler": REF_SAMPLER.as_str(),
            "ref_seed": REF_SEED,
            "max_depth": config.max_depth,
            "threshold": config.threshold,
            "conv_max": config.conv_max,
            "conv_res": config.conv_res,
            "conv_ref_spp": config.conv_ref_spp,
            "samplers": names,
        },
        "reference": results.reference,
        "convergence_reference": results.convergence_reference,
        "samplers": results.samplers,
        "threshold_sweep": results.threshold_sweep,
        "wall_time_s": wall,
    });
    Ok(serde_json::to_string_pretty(&value)?)
}

fn sampler_images(
    dir: &Path,
    s: &SamplerResult,
    image: &RgbImage,
    reference: &RgbImage,
) -> Result<()> {
    save_with_crop(dir, &s.name, image)?;
    let heat = lowdisc_image::heatmap::error_heatmap(
        image,
        reference,
        PixelError::RelativeSquared,
        Normalization::Quantile(0.99),
    )?;
    write_png(dir.join(format!("{}_relse.png", s.name)), &heat, 1.0)?;
    Ok(())
}

/// Writes every file of the report folder.
pub fn write_all(
    config: &ExperimentConfig,
    results: &Results,
    images: &Images,
    wall: f64,
) -> Result<()> {
    let dir = &config.out;
    save_with_crop(dir, "reference", &images.reference)?;
    for (s, image) in results.samplers.iter().zip(&images.renders) {
        sampler_images(dir, s, image, &images.reference)?;
    }
    plots(config, results)?;
    let md = markdown(config, results, wall);
    write_text(&dir.join("report.md"), &md)?;
    write_text(&dir.join("report.html"), &html(&md))?;
    write_text(&dir.join("results.json"), &json(config, results, wall)?)?;
    Ok(())
}
