//! Building a render: the scene (a file or the Cornell box), the options
//! from the scene's settings and then the command line's overrides, the
//! output file and its checks, and the warnings printed once.

use std::collections::HashSet;
use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::film::PEAK_BYTES_PER_PIXEL;
use lowdisc_render::integrator::{MAX_DEPTH_LIMIT, PathIntegrator};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{MAX_SPP, RenderOptions};
use lowdisc_render::scene::Scene;

use super::RenderConfig;
use crate::limits;

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

/// The scene, its render options and the output file, after applying the
/// scene file's settings and then the command line's overrides.
pub(super) fn prepare(
    config: &RenderConfig,
    seen: &mut HashSet<String>,
) -> Result<(Scene, RenderOptions, PathBuf)> {
    let mut sampler = SamplerName::ZSobol;
    let mut spp = 16;
    let mut max_depth = 5;
    let mut output = PathBuf::from("render.exr");
    let scene = match &config.scene {
        None => cornell_box(config.resolution.unwrap_or([512, 512]))?,
        Some(path) => {
            let options = LoadOptions {
                envmap_override: config.envmap.clone(),
            };
            let loaded = load_pbrt_scene(path, &options)
                .with_context(|| format!("cannot load scene `{}`", path.display()))?;
            for w in &loaded.warnings {
                warn_once(seen, config.quiet, w);
            }
            let s = &loaded.settings;
            sampler = s.sampler.unwrap_or(sampler);
            spp = s.spp.unwrap_or(spp);
            max_depth = s.max_depth.unwrap_or(max_depth);
            // The scene's values obey the limits of the flags that override them.
            if config.spp.is_none() && !(1..=MAX_SPP).contains(&spp) {
                bail!(
                    "{}: pixelsamples {spp} must be between 1 and {MAX_SPP} (the --spp limit)",
                    path.display()
                );
            }
            if config.max_depth.is_none() && max_depth > MAX_DEPTH_LIMIT {
                bail!(
                    "{}: maxdepth {max_depth} must be at most {MAX_DEPTH_LIMIT} (the --maxdepth limit)",
                    path.display()
                );
            }
            if let Some(name) = &s.output {
                output = scene_output(name);
            }
            loaded.scene
        }
    };
    let mut scene = scene;
    if let Some(r) = config.resolution {
        scene.set_resolution(r)?;
    }
    let options = RenderOptions {
        sampler: SamplerConfig {
            seed: config.seed,
            spp: config.spp.unwrap_or(spp),
            threshold: config.threshold,
            paper_all_dims: config.paper_all_dims,
            ..SamplerConfig::new(config.sampler.unwrap_or(sampler))
        },
        integrator: PathIntegrator {
            max_depth: config.max_depth.unwrap_or(max_depth),
            layered_exit_weight: config.layered_weight,
            ..PathIntegrator::default()
        },
        threads: config.threads,
        window: config.window,
        samples: config.samples,
        spectral: config.spectral,
    };
    let output = config.output.clone().unwrap_or(output);
    check_output(&output)?;
    if config.is_part() && !crate::split_cmd::is_exr(&output) {
        bail!(
            "output `{}`: a part (--pixel-bounds, --sample-range) is written as .exr",
            output.display()
        );
    }
    // A part allocates its window alone.
    let [w, h] = match config.window {
        Some(b) => [b.width() as u32, b.height() as u32],
        None => scene.film().params.resolution,
    };
    let bytes = f64::from(w) * f64::from(h) * PEAK_BYTES_PER_PIXEL as f64;
    limits::check_memory(&format!("a {w}x{h} film"), bytes, config.max_memory)?;
    Ok((scene, options, output))
}

/// The output a scene's `Film` filename asks for, in the current directory;
/// an extension this command cannot write becomes `.exr`.
fn scene_output(name: &str) -> PathBuf {
    let file = Path::new(name)
        .file_name()
        .map_or_else(|| PathBuf::from("render.exr"), PathBuf::from);
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
