//! Writing the report folder: the answer to the paper's question
//! ([`answer`], the report's first section), images ([`images`]: linear EXR, sRGB PNG,
//! crops, error heatmaps), charts ([`charts`]), `results.json` ([`json`]),
//! `report.md` ([`markdown`]) and `report.html` ([`html`], the same
//! content as a web page). Every file goes through a temporary file and a
//! rename.

pub mod answer;
pub mod charts;
pub mod html;
pub mod images;
pub mod json;
pub mod markdown;
pub mod statistics;

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};

use crate::config::ExperimentConfig;
use crate::results::{Images, Results};

fn write_text(path: &Path, text: &str) -> Result<()> {
    lowdisc_image::io::write_bytes_atomically(path, text.as_bytes())
        .with_context(|| format!("cannot write `{}`", path.display()))
}

/// Writes every file of the report folder and returns their paths.
pub fn write_all(
    config: &ExperimentConfig,
    results: &Results,
    images: &Images,
    wall: f64,
) -> Result<Vec<PathBuf>> {
    let dir = &config.out;
    let mut written = Vec::new();
    written.extend(images::save_with_crop(dir, "reference", &images.reference)?);
    let top = images::common_scale(&images.renders, &images.reference)?;
    for (s, image) in results.samplers.iter().zip(&images.renders) {
        written.extend(images::save_with_crop(dir, &s.name, image)?);
        written.push(images::save_error_heatmap(
            dir,
            &s.name,
            image,
            &images.reference,
            top,
        )?);
    }
    written.extend(charts::write_charts(config, results)?);
    let md = markdown::markdown(config, results, wall, top);
    write_text(&dir.join("report.md"), &md)?;
    write_text(&dir.join("report.html"), &html::html(&md))?;
    write_text(
        &dir.join("results.json"),
        &json::json(config, results, wall)?,
    )?;
    let mut files: Vec<PathBuf> = ["report.html", "report.md", "results.json"]
        .map(|f| dir.join(f))
        .into();
    files.append(&mut written);
    Ok(files)
}
