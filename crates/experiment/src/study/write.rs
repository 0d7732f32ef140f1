//! The study's output folder: `study.md` (the tables), `study.csv` (one
//! row per scope, sampler and metric) and `study.json` (settings, every
//! run's measures and the summaries).
//!
//! `study.csv` columns: `scope` (a scene's name, or `all` for the pooled
//! row), `sampler`, `baseline` (empty for `structure`), `metric`
//! (`masked_mse`, `blurred_mse`, `flip`, `mse`: ratios to the baseline;
//! `structure`: the mean error structure; `spectral_peak`: the mean
//! spectral peak, pooled rows only), `value`,
//! `ci_low`, `ci_high` (the 95 % interval over seeds), `ci_scenes_low`,
//! `ci_scenes_high` (pooled rows: the interval with scenes as a sample),
//! `n` (seeds of a scene row, scenes of a pooled row). Undefined values are
//! empty.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::Result;
use serde_json::json;

use super::summary::METRICS;
use super::{StudyConfig, StudyResults};
use crate::report::json::{git_hash, machine};

/// Writes `study.md`, `study.csv` and `study.json` into `config.out`
/// (created if needed), each atomically; returns their paths.
pub fn write_all(config: &StudyConfig, results: &StudyResults) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(&config.out)?;
    let files = [
        ("study.md", markdown(config, results)),
        ("study.csv", csv(results)),
        ("study.json", json_text(config, results)?),
    ];
    let mut written = Vec::new();
    for (name, text) in files {
        let path = config.out.join(name);
        lowdisc_files::write_bytes(&path, text.as_bytes())?;
        written.push(path);
    }
    Ok(written)
}

fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.3}")
    } else {
        "–".into()
    }
}

fn interval(ci: Option<[f64; 2]>) -> String {
    match ci {
        Some([lo, hi]) if lo.is_finite() && hi.is_finite() => format!("[{lo:.2}, {hi:.2}]"),
        _ => "–".into(),
    }
}

fn settings_line(config: &StudyConfig) -> String {
    format!(
        "{} scenes at {}x{}, {} spp, seeds 0..{}, references of {} spp; ratios to `{}`.{}",
        config.scenes.len(),
        config.resolution[0],
        config.resolution[1],
        config.spp,
        config.runs,
        config.ref_spp,
        config.baselines[0].as_str(),
        if config.baselines.len() > 1 {
            " Masked MSE ratios to the other baselines follow the main tables."
        } else {
            ""
        }
    )
}

/// `study.md`: the pooled table, then per-scene tables of the masked MSE
/// ratio and of the structure.
pub fn markdown(config: &StudyConfig, results: &StudyResults) -> String {
    let mut md = String::from("# Sampler study\n\n");
    let _ = writeln!(md, "{}\n", settings_line(config));
    let _ = writeln!(
        md,
        "Ratios: geometric mean over scenes of each scene's paired ratio (geometric \
         mean over seeds), 95 % intervals over seeds (these scenes) and with the scenes \
         as a sample. Structure: error power near the Nyquist frequencies over white noise's, \
         the largest of the checkerboard, column and row regions (1 = white noise, \
         about 25 = a pure pixel checkerboard or stripes), mean over scenes.\n"
    );
    md.push_str(
        "| sampler | masked MSE ratio | 95 % (seeds) | 95 % (scenes) | scene range \
         | blurred MSE ratio | 95 % (seeds) | FLIP ratio | 95 % (seeds) | structure |\n",
    );
    md.push_str("|---|---|---|---|---|---|---|---|---|---|\n");
    for s in &results.samplers {
        let mut row = format!("| `{}` ", s.sampler);
        for (m, metric) in s.ratios[0].metrics.iter().take(3).enumerate() {
            let p = metric.pooled;
            let _ = write!(
                row,
                "| {} | {} ",
                p.map_or("–".into(), |p| num(p.ratio)),
                interval(p.map(|p| p.ci95))
            );
            if m == 0 {
                let _ = write!(
                    row,
                    "| {} | {} ",
                    interval(p.and_then(|p| p.ci95_scenes)),
                    interval(p.map(|p| p.range))
                );
            }
        }
        let _ = writeln!(row, "| {} |", num(s.structure.mean));
        md.push_str(&row);
    }
    scene_matrix(&mut md, results, "Masked MSE ratio per scene", &|s, k| {
        s.ratios[0].metrics[0].scenes[k].map_or("–".into(), |r| num(r.ratio))
    });
    scene_matrix(
        &mut md,
        results,
        "Structure per scene (mean over seeds)",
        &|s, k| num(s.structure.scenes[k].mean),
    );
    md.push_str(
        "\n## Structure by region and spectral peak (mean over every render)\n\n\
         | sampler | checkerboard (½, ½) | columns (½, 0) | rows (0, ½) \
         | spectral peak | strongest at (f_x, f_y) |\n|---|---|---|---|---|---|\n",
    );
    for s in &results.samplers {
        let [c, x, y] = s.structure.regions;
        let [fx, fy] = s.structure.peak_frequency;
        let _ = writeln!(
            md,
            "| `{}` | {} | {} | {} | {} | ({fx:+.2}, {fy:.2}) |",
            s.sampler,
            num(c),
            num(x),
            num(y),
            num(s.structure.peak)
        );
    }
    for (b, baseline) in config.baselines.iter().enumerate().skip(1) {
        let _ = write!(
            md,
            "\n## Masked MSE ratio to `{}`\n\n| sampler | ratio | 95 % (seeds) \
             | 95 % (scenes) | scene range |\n|---|---|---|---|---|\n",
            baseline.as_str()
        );
        for s in &results.samplers {
            let p = s.ratios[b].metrics[0].pooled;
            let _ = writeln!(
                md,
                "| `{}` | {} | {} | {} | {} |",
                s.sampler,
                p.map_or("–".into(), |p| num(p.ratio)),
                interval(p.map(|p| p.ci95)),
                interval(p.and_then(|p| p.ci95_scenes)),
                interval(p.map(|p| p.range))
            );
        }
    }
    md.push_str("\n## Scenes\n\n| scene | source | pixels kept | reference |\n|---|---|---|---|\n");
    for scene in &results.scenes {
        let _ = writeln!(
            md,
            "| {} | `{}` | {:.3} | `{}`{} |",
            scene.name,
            scene.source,
            scene.kept_fraction,
            scene.reference.file.display(),
            if scene.reference.cached {
                " (cached)"
            } else {
                ""
            }
        );
    }
    let _ = writeln!(md, "\nWall time {:.1} s.", results.wall_time_s);
    md
}

fn scene_matrix(
    md: &mut String,
    results: &StudyResults,
    title: &str,
    cell: &dyn Fn(&super::SamplerSummary, usize) -> String,
) {
    let _ = write!(md, "\n## {title}\n\n| sampler |");
    for scene in &results.scenes {
        let _ = write!(md, " {} |", scene.name);
    }
    md.push_str("\n|---|");
    md.push_str(&"---|".repeat(results.scenes.len()));
    md.push('\n');
    for s in &results.samplers {
        let _ = write!(md, "| `{}` |", s.sampler);
        for k in 0..results.scenes.len() {
            let _ = write!(md, " {} |", cell(s, k));
        }
        md.push('\n');
    }
}

fn field(v: Option<f64>) -> String {
    v.filter(|v| v.is_finite())
        .map_or(String::new(), |v| format!("{v}"))
}

/// `study.csv` (columns in the module doc).
pub fn csv(results: &StudyResults) -> String {
    let mut out = String::from(
        "scope,sampler,baseline,metric,value,ci_low,ci_high,ci_scenes_low,ci_scenes_high,n\n",
    );
    for s in &results.samplers {
        let by_baseline = s
            .ratios
            .iter()
            .flat_map(|r| r.metrics.iter().map(move |m| (&r.baseline, m)));
        for (b, m) in by_baseline {
            for (scene, r) in results.scenes.iter().zip(&m.scenes) {
                let _ = writeln!(
                    out,
                    "{},{},{b},{},{},{},{},,,{}",
                    scene.name,
                    s.sampler,
                    m.metric,
                    field(r.map(|r| r.ratio)),
                    field(r.map(|r| r.ci95[0])),
                    field(r.map(|r| r.ci95[1])),
                    r.map_or(String::new(), |r| r.n.to_string())
                );
            }
            let p = m.pooled;
            let _ = writeln!(
                out,
                "all,{},{b},{},{},{},{},{},{},{}",
                s.sampler,
                m.metric,
                field(p.map(|p| p.ratio)),
                field(p.map(|p| p.ci95[0])),
                field(p.map(|p| p.ci95[1])),
                field(p.and_then(|p| p.ci95_scenes).map(|c| c[0])),
                field(p.and_then(|p| p.ci95_scenes).map(|c| c[1])),
                p.map_or(String::new(), |p| p.scenes.to_string())
            );
        }
        for (scene, st) in results.scenes.iter().zip(&s.structure.scenes) {
            let _ = writeln!(
                out,
                "{},{},,structure,{},{},{},,,{}",
                scene.name,
                s.sampler,
                field(Some(st.mean)),
                field(Some(st.ci95[0])),
                field(Some(st.ci95[1])),
                st.n
            );
        }
        let _ = writeln!(
            out,
            "all,{},,structure,{},,,,,{}",
            s.sampler,
            field(Some(s.structure.mean)),
            results.scenes.len()
        );
        let _ = writeln!(
            out,
            "all,{},,spectral_peak,{},,,,,{}",
            s.sampler,
            field(Some(s.structure.peak)),
            results.scenes.len()
        );
    }
    out
}

/// `study.json`: the settings, the machine and every number.
pub fn json_text(config: &StudyConfig, results: &StudyResults) -> Result<String> {
    let scenes: Vec<serde_json::Value> = config
        .scenes
        .iter()
        .map(|s| {
            json!({
                "name": s.name,
                "envmap": s.envmap.as_deref().map(Path::display).map(|d| d.to_string()),
            })
        })
        .collect();
    let value = json!({
        "schema": 1,
        "command": config.command,
        "version": env!("CARGO_PKG_VERSION"),
        "git_hash": git_hash(),
        "machine": machine(),
        "settings": {
            "scenes": scenes,
            "samplers": config.samplers.iter().map(|s| s.as_str()).collect::<Vec<_>>(),
            "baselines": config.baselines.iter().map(|s| s.as_str()).collect::<Vec<_>>(),
            "width": config.resolution[0],
            "height": config.resolution[1],
            "spp": config.spp,
            "runs": config.runs,
            "ref_spp": config.ref_spp,
            "max_depth": config.max_depth,
            "metrics": METRICS.iter().map(|m| m.0).collect::<Vec<_>>(),
            "structure_cutoff": lowdisc_metrics::structure::DEFAULT_CUTOFF,
        },
        "results": results,
    });
    Ok(serde_json::to_string_pretty(&value)? + "\n")
}
