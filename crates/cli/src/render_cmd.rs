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

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::integrator::{MAX_DEPTH_LIMIT, PathIntegrator};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{MAX_SPP, MAX_THREADS, Progress, RenderOptions, render};
use lowdisc_render::scene::Scene;
use std::collections::HashSet;

use crate::parse;
use crate::progress::Reporter;

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
}

impl RenderArgs {
    /// Checks every argument and builds the configuration.
    pub fn into_config(self) -> Result<RenderConfig> {
        let sampler = self
            .sampler
            .as_deref()
            .map(parse::sampler_name)
            .transpose()?;
        if let Some(spp) = self.spp {
            if spp == 0 || spp > MAX_SPP {
                bail!("--spp must be between 1 and {MAX_SPP}, got {spp}");
            }
        }
        if let Some(d) = self.maxdepth {
            if d > MAX_DEPTH_LIMIT {
                bail!("--maxdepth must be at most {MAX_DEPTH_LIMIT}, got {d}");
            }
        }
        if let Some(t) = self.threads {
            if t == 0 || t > MAX_THREADS {
                bail!("--threads must be between 1 and {MAX_THREADS}, got {t}");
            }
        }
        let resolution = self.res.as_deref().map(resolution).transpose()?;
        if self.envmap.is_some() && self.scene.is_none() {
            bail!("--envmap applies to scene files; the built-in Cornell box has no environment");
        }
        if let Some(out) = &self.output {
            check_output(out)?;
        }
        if let Some(scene) = &self.scene {
            if !scene.is_file() {
                bail!("scene file `{}` does not exist", scene.display());
            }
        }
        if let Some(env) = &self.envmap {
            if !env.is_file() {
                bail!("--envmap file `{}` does not exist", env.display());
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
            threshold: parse::threshold(self.threshold)?,
            paper_all_dims: self.paper_all_dims,
            stats: self.stats,
            quiet: self.quiet,
        })
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

/// Time spent in each phase.
#[derive(Debug, Default)]
struct Phases {
    load: Duration,
    render: Duration,
    write: Duration,
}

/// Prints each distinct warning once to stderr (nothing with `--quiet`).
fn warn_once(seen: &mut HashSet<String>, quiet: bool, warning: &str) {
    if !quiet && seen.insert(warning.to_string()) {
        if warning.contains("warning:") {
            eprintln!("{warning}");
        } else {
            eprintln!("warning: {warning}");
        }
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
            spp = s.spp.unwrap_or(spp).clamp(1, MAX_SPP);
            max_depth = s.max_depth.unwrap_or(max_depth).min(MAX_DEPTH_LIMIT);
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
        sampler: config.sampler.unwrap_or(sampler),
        seed: config.seed,
        spp: config.spp.unwrap_or(spp),
        integrator: PathIntegrator {
            max_depth: config.max_depth.unwrap_or(max_depth),
            ..PathIntegrator::default()
        },
        threads: config.threads,
        tile_size: 16,
        threshold: config.threshold,
        paper_all_dims: config.paper_all_dims,
    };
    let output = config.output.clone().unwrap_or(output);
    check_output(&output)?;
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
    let total = u64::from(w) * u64::from(h) * u64::from(options.spp);
    let title = format!(
        "rendering {w}x{h}, {} spp with {}",
        options.spp, options.sampler
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
        print_stats(&scene, &out, &phases);
    }
    Ok(())
}

fn print_stats(scene: &Scene, out: &lowdisc_render::render::RenderOutput, phases: &Phases) {
    let s = &out.stats;
    let b = scene.bvh_stats();
    println!("primitives        {}", scene.prim_count());
    println!("lights            {}", scene.lights().len());
    println!("{b}");
    println!("samples           {}", s.samples);
    println!("rays traced       {}", s.rays);
    println!(
        "rays/s            {:.0} ({:.2} M)",
        s.rays_per_second(),
        s.rays_per_second() / 1e6
    );
    println!("nonfinite samples {}", s.nonfinite_samples);
    println!("threads           {}", s.threads);
    let build = b.build_time.as_secs_f64();
    println!(
        "time load         {:.3} s",
        (phases.load.as_secs_f64() - build).max(0.0)
    );
    println!("time build (BVH)  {build:.3} s");
    println!("time render       {:.3} s", phases.render.as_secs_f64());
    println!("time write        {:.3} s", phases.write.as_secs_f64());
}
