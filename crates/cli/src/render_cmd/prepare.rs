//! Building a render: the scene (a file or the Cornell box) and its view,
//! the settings resolved from the scene's and then the command line's,
//! the output file and its checks, and the warnings printed once.

use std::collections::HashSet;
use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use lowdisc_render::cornell::{CORNELL_RESOLUTION, cornell_scene};
use lowdisc_render::film::PEAK_BYTES_PER_PIXEL;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::RenderOptions;
use lowdisc_render::scene::Scene;
use lowdisc_render::settings::{Given, Settings, SettingsLayer};
use lowdisc_render::view::{View, ViewSpec};

use super::RenderConfig;
use crate::{default_output, limits};

/// The output must have a known extension and an existing directory.
pub(super) fn check_output(path: &Path) -> Result<()> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if !matches!(ext.as_deref(), Some("exr" | "png" | "pfm" | "hdr")) {
        bail!(
            "output `{}` must end in .exr, .png, .pfm or .hdr",
            path.display()
        );
    }
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !dir.is_dir() {
        bail!("output directory `{}` does not exist", dir.display());
    }
    Ok(())
}

/// Prints each distinct warning once to stderr (nothing with `--quiet`).
pub(super) fn warn_once(seen: &mut HashSet<String>, quiet: bool, warning: &str) {
    if !quiet && seen.insert(warning.to_string()) {
        let prefix = if warning.contains("warning:") {
            ""
        } else {
            "warning: "
        };
        // A stderr that cannot be written (closed, full) loses the warning,
        // not the render.
        let _ = writeln!(std::io::stderr(), "{prefix}{warning}");
    }
}

/// The output file when neither the command line nor the scene names one.
const DEFAULT_OUTPUT: &str = "render.exr";

/// The scene, its view, the render options and the output file, after
/// resolving the scene's settings and then the command line's.
pub(super) fn prepare(
    config: &RenderConfig,
    seen: &mut HashSet<String>,
) -> Result<(Scene, View, RenderOptions, PathBuf)> {
    let (scene, spec, layer, output) = load(config, seen)?;
    let settings = Settings::resolve(&[&layer, &config.settings])?;
    let view = View::new(&spec, settings.resolution)?;
    // Without -o the image goes to out/ (created).
    let output = match &config.output {
        Some(given) => given.clone(),
        None => {
            default_output::create_dir()?;
            default_output::path(output)
        }
    };
    check_output(&output)?;
    if config.is_part() && !crate::split_cmd::is_exr(&output) {
        bail!(
            "output `{}`: a part (--pixel-bounds, --sample-range) is written as .exr",
            output.display()
        );
    }
    // A part allocates its window alone.
    let [w, h] = match settings.render.window {
        Some(b) => [b.width() as u32, b.height() as u32],
        None => settings.resolution,
    };
    let bytes = f64::from(w) * f64::from(h) * PEAK_BYTES_PER_PIXEL as f64;
    limits::check_memory(&format!("a {w}x{h} film"), bytes, config.max_memory)?;
    Ok((scene, view, settings.render, output))
}

/// The scene, its view, the settings it asks for and its output file: a
/// scene file's, or the built-in Cornell box's.
fn load(
    config: &RenderConfig,
    seen: &mut HashSet<String>,
) -> Result<(Scene, ViewSpec, SettingsLayer, PathBuf)> {
    let Some(path) = &config.scene else {
        let (scene, spec) = cornell_scene()?;
        let layer = SettingsLayer {
            resolution: Some(Given::new(CORNELL_RESOLUTION, "the Cornell box")),
            ..SettingsLayer::default()
        };
        return Ok((scene, spec, layer, PathBuf::from(DEFAULT_OUTPUT)));
    };
    let options = LoadOptions {
        envmap_override: config.envmap.clone(),
        approximate: config.approximate,
    };
    let loaded = load_pbrt_scene(path, &options)
        .with_context(|| format!("cannot load scene `{}`", path.display()))?;
    for w in &loaded.warnings {
        warn_once(seen, config.quiet, w);
    }
    let output = loaded
        .settings
        .output
        .as_deref()
        .map_or_else(|| PathBuf::from(DEFAULT_OUTPUT), scene_output);
    Ok((loaded.scene, loaded.view, loaded.settings.layer, output))
}

/// The file name a scene's `Film` filename asks for (written to
/// [`default_output::DIR`]); an extension this command cannot write becomes
/// `.exr`.
fn scene_output(name: &str) -> PathBuf {
    let file = Path::new(name)
        .file_name()
        .map_or_else(|| PathBuf::from(DEFAULT_OUTPUT), PathBuf::from);
    let ext = file
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if matches!(ext.as_deref(), Some("exr" | "png" | "pfm" | "hdr")) {
        file
    } else {
        file.with_extension("exr")
    }
}
