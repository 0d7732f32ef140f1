//! `lowdisc render`: path-trace a pbrt-v4 scene file or the built-in Cornell
//! box with any of lowdisc's samplers and write EXR or PNG.
//!
//! Arguments become a validated [`RenderConfig`] before any work starts; the
//! render itself runs in the `lowdisc-render` library, which reports progress
//! through a callback that drives [`crate::progress::Reporter`] (a bar on a
//! terminal, lines otherwise, nothing with `--quiet`), which also says where
//! the image went. Warnings go to stderr, each distinct
//! one once (also suppressed by `--quiet`); `--stats` prints the counters and
//! the time per phase to stdout. A scene file's own settings (sampler, spp,
//! maxdepth, resolution, output file) apply unless a flag overrides them.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, anyhow, bail};
use clap::Args;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::film::PEAK_BYTES_PER_PIXEL;
use lowdisc_render::integrator::{MAX_DEPTH_LIMIT, PathIntegrator};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{MAX_SPP, Progress, RenderOptions, render};
use lowdisc_render::scene::Scene;
use std::collections::HashSet;

use crate::progress::Reporter;
use crate::render_stats::{self, Phases};
use crate::{limits, parse};

/// The largest image side `--res` accepts.
pub const MAX_SIDE: u32 = 16_384;
/// The most pixels `--res` accepts (a 16k x 16k image).
pub const MAX_PIXELS: u64 = 1 << 28;

/// The long help of `render`.
pub const LONG_ABOUT: &str = "\
Path-trace a scene and write the image.\n\
\n\
Without SCENE the built-in Cornell box is rendered (the published Cornell\n\
Box Data geometry, RGB reflectances, 35 mm camera). A pbrt-v4 scene file's\n\
Sampler, pixelsamples, maxdepth, Film resolution and filename are used\n\
unless --sampler, --spp, --maxdepth, --res or -o is given; --envmap replaces\n\
the image of every image-based infinite light. Unsupported directives and\n\
parameters are warnings with file:line:column; syntax errors are errors.\n\
\n\
The renderer is a unidirectional path tracer with next-event estimation and\n\
MIS, in RGB. Every random decision comes from the chosen pixel sampler, in a\n\
fixed order of dimensions (film position, lens, then seven per bounce: light\n\
choice, light position, BSDF lobe, BSDF direction, Russian roulette). The\n\
output is bit-identical for the same options whatever --threads is.\n\
\n\
Output: .exr (linear float), .png (8-bit sRGB), .pfm or .hdr, written to a\n\
temporary file and renamed into place.\n\
";

/// The arguments of `render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// A pbrt-v4 scene file (omit for the built-in Cornell box).
    scene: Option<PathBuf>,
    /// Pixel sampler: independent, stratified, halton, halton-owen, sobol,
    /// sobol-xor, sobol-owen, sobol-fast-owen, paper, paper-repro,
    /// padded-sobol, zsobol [default: the scene's, else zsobol].
    #[arg(long, short = 's', value_name = "NAME")]
    sampler: Option<String>,
    /// Samples per pixel [default: the scene's, else 16].
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Seed of every random choice.
    #[arg(long, value_name = "S", default_value_t = 0)]
    seed: u64,
    /// Image resolution [default: the scene's; 512x512 for the Cornell box].
    #[arg(long, value_name = "WxH", allow_hyphen_values = true)]
    res: Option<String>,
    /// Maximum number of bounces (pbrt's maxdepth) [default: the scene's, else 5].
    #[arg(long, value_name = "D")]
    maxdepth: Option<u32>,
    /// Worker threads [default: all cores].
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// Environment map replacing a scene's missing one (scene files only).
    #[arg(long, value_name = "FILE")]
    envmap: Option<PathBuf>,
    /// Output image: .exr, .png, .pfm or .hdr [default: the scene's Film
    /// filename, else render.exr].
    #[arg(long, short = 'o', value_name = "OUT")]
    output: Option<PathBuf>,
    /// Paper permutation threshold in [0,1] (samplers paper and paper-repro):
    /// the probability that a generator-matrix column is left unflipped.
    #[arg(long, value_name = "T", default_value_t = SamplerConfig::DEFAULT_THRESHOLD)]
    threshold: f64,
    /// Let the paper permutation act on the film dimensions 0-1 too;
    /// `--paper-all-dims` alone means true.
    #[arg(long, value_name = "BOOL", default_value_t = false, num_args = 0..=1,
          default_missing_value = "true", require_equals = true, action = clap::ArgAction::Set)]
    paper_all_dims: bool,
    /// Largest memory (MiB) of the film and its image.
    #[arg(long, value_name = "MIB", default_value_t = limits::DEFAULT_MAX_MEMORY_MIB)]
    max_memory: u64,
    /// Print rays traced, rays/s, BVH statistics and time per phase.
    #[arg(long)]
    stats: bool,
    /// No progress bar and no warnings.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// A validated `render` invocation.
#[derive(Debug, Clone)]
pub struct RenderConfig {
    /// Scene file, or `None` for the Cornell box.
    pub scene: Option<PathBuf>,
    /// Resolution override.
    pub resolution: Option<[u32; 2]>,
    /// Sampler override.
    pub sampler: Option<SamplerName>,
    /// Samples-per-pixel override.
    pub spp: Option<u32>,
    /// Maximum-depth override.
    pub max_depth: Option<u32>,
    /// Seed of every random choice.
    pub seed: u64,
    /// Worker threads (`None`: all cores).
    pub threads: Option<usize>,
    /// Environment map replacing the scene's.
    pub envmap: Option<PathBuf>,
    /// Output file override.
    pub output: Option<PathBuf>,
    /// Paper permutation threshold.
    pub threshold: f64,
    /// Paper permutation on the film dimensions too.
    pub paper_all_dims: bool,
    /// Print statistics.
    pub stats: bool,
    /// Suppress progress and warnings.
    pub quiet: bool,
    /// Memory limit (MiB) of the film.
    pub max_memory: u64,
}

impl RenderArgs {
    /// Checks every argument and builds the configuration.
    pub fn into_config(self) -> Result<RenderConfig> {
        let sampler = self
            .sampler
            .as_deref()
            .map(parse::sampler_name)
            .transpose()?;
        self.check_ranges()?;
        let resolution = self.res.as_deref().map(resolution).transpose()?;
        if self.envmap.is_some() && self.scene.is_none() {
            bail!("--envmap applies to scene files; the built-in Cornell box has no environment");
        }
        if let Some(out) = &self.output {
            check_output(out)?;
        }
        for (what, file) in [("scene", &self.scene), ("--envmap", &self.envmap)] {
            if let Some(file) = file {
                lowdisc_files::check_input(file, u64::MAX)
                    .with_context(|| format!("{what} file"))?;
            }
        }
        Ok(RenderConfig {
            scene: self.scene,
            resolution,
            sampler,
            spp: self.spp,
            max_depth: self.maxdepth,
            seed: self.seed,
            threads: self.threads,
            envmap: self.envmap,
            output: self.output,
            threshold: self.threshold,
            paper_all_dims: self.paper_all_dims,
            stats: self.stats,
            quiet: self.quiet,
            max_memory: self.max_memory,
        })
    }
}

impl RenderArgs {
    /// Checks `--spp`, `--maxdepth`, `--threads` and `--threshold` with
    /// [`RenderOptions::validate`] (the one definition of their ranges), each
    /// on the default options, so that the error names the flag.
    fn check_ranges(&self) -> Result<()> {
        let base = RenderOptions::default();
        let check =
            |flag: &str, opts: RenderOptions| opts.validate().map_err(|e| anyhow!("{flag}: {e}"));
        let sampler = |spp: u32, threshold: f64| RenderOptions {
            sampler: SamplerConfig {
                spp,
                threshold,
                ..base.sampler
            },
            ..base
        };
        if let Some(spp) = self.spp {
            check("--spp", sampler(spp, base.sampler.threshold))?;
        }
        check("--threshold", sampler(base.sampler.spp, self.threshold))?;
        if let Some(max_depth) = self.maxdepth {
            let integrator = PathIntegrator {
                max_depth,
                ..base.integrator
            };
            check("--maxdepth", RenderOptions { integrator, ..base })?;
        }
        if self.threads.is_some() {
            check(
                "--threads",
                RenderOptions {
                    threads: self.threads,
                    ..base
                },
            )?;
        }
        Ok(())
    }
}

/// `WxH` with both sides in `1..=MAX_SIDE` and at most `MAX_PIXELS` pixels.
fn resolution(text: &str) -> Result<[u32; 2]> {
    let res = parse::resolution(text)?;
    if res[0] > MAX_SIDE || res[1] > MAX_SIDE || u64::from(res[0]) * u64::from(res[1]) > MAX_PIXELS
    {
        bail!("--res `{text}` is too large: each side must be at most {MAX_SIDE} pixels");
    }
    Ok(res)
}

/// The output must have a known extension and an existing directory.
fn check_output(path: &Path) -> Result<()> {
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
fn warn_once(seen: &mut HashSet<String>, quiet: bool, warning: &str) {
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
fn prepare(
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
            ..PathIntegrator::default()
        },
        threads: config.threads,
        tile_size: lowdisc::catalog::DEFAULT_TILE_SIZE,
    };
    let output = config.output.clone().unwrap_or(output);
    check_output(&output)?;
    let [w, h] = scene.film().params.resolution;
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

/// Loads (or builds) the scene, renders it and writes the image.
pub fn run(config: &RenderConfig) -> Result<()> {
    let t0 = Instant::now();
    let mut seen = HashSet::new();
    let (scene, options, output) = prepare(config, &mut seen)?;
    let mut phases = Phases {
        load: t0.elapsed(),
        ..Phases::default()
    };

    let reporter = Reporter::new(config.quiet);
    let [w, h] = scene.film().params.resolution;
    let total = u64::from(w) * u64::from(h) * u64::from(options.sampler.spp);
    let title = format!(
        "rendering {w}x{h}, {} spp with {}",
        options.sampler.spp, options.sampler.name
    );
    reporter.begin_stage(&title, total, "samples");
    let on_progress = |p: Progress| reporter.advance_stage(p.samples_done);
    let t1 = Instant::now();
    let out = render(&scene, &options, &on_progress)?;
    phases.render = t1.elapsed();
    reporter.end_stage();
    for w in &out.warnings {
        warn_once(&mut seen, config.quiet, w);
    }
    let t2 = Instant::now();
    out.film
        .write(&output, scene.film().exposure)
        .with_context(|| format!("cannot write `{}`", output.display()))?;
    phases.write = t2.elapsed();
    reporter.line(&format!("wrote {}", output.display()));
    if config.stats {
        render_stats::print_stats(std::io::stdout().lock(), &scene, &out, &phases)
            .context("cannot print the statistics")?;
    }
    Ok(())
}
